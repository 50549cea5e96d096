//! Stress test of the winged-edge kernel's Euler operators: random sequences of MVFS, MEV, MEF,
//! KEV, KEF, KVFS and garbage collection, on vertices and faces drawn mostly from the live ones
//! (so that most operations apply) and now and then from anywhere. After every operation the
//! structure passes its check; a refused operation leaves it unchanged.

mod stress;

use halfwing::winged::{EdgeId, FaceId, VertexId, Winged};
use proptest::test_runner::TestRng;
use stress::{Rng, choose, index_below, run, run_long};

fn live_or_any<T: Copy>(rng: &mut TestRng, live: &[T], any: impl Fn(u32) -> T, cap: u32) -> T {
    if live.is_empty() || rng.random_bool(0.1) {
        any(index_below(rng, cap as usize + 1))
    } else {
        *choose(rng, live)
    }
}

fn position(rng: &mut TestRng) -> [f64; 3] {
    [rng.random(), rng.random(), rng.random()]
}

fn case(rng: &mut TestRng) {
    let mut w = Winged::new();
    for step in 0..rng.random_range(1..80) {
        let before = w.clone();
        let faces: Vec<FaceId> = w.faces().collect();
        let edges: Vec<EdgeId> = w.edges().collect();
        let vertices: Vec<VertexId> = w.vertices().collect();
        let face = live_or_any(rng, &faces, FaceId, w.n_face_slots());
        // A vertex of `face` when it has any, so that MEV and MEF mostly apply.
        let on_face: Vec<VertexId> = w
            .face_vertices(face)
            .map(|vs| vs.collect())
            .unwrap_or_default();
        let vertex = |rng: &mut TestRng| {
            if !on_face.is_empty() && rng.random_bool(0.8) {
                *choose(rng, &on_face)
            } else {
                live_or_any(rng, &vertices, VertexId, w.n_vertex_slots())
            }
        };
        let (v1, v2) = (vertex(rng), vertex(rng));
        let edge = live_or_any(rng, &edges, EdgeId, w.n_edge_slots());
        let (operation, done) = match rng.random_range(0..10) {
            0 => ("mvfs", w.mvfs(position(rng)).is_ok()),
            1..=3 => ("mev", w.mev(face, v1, position(rng)).is_ok()),
            4 | 5 => ("mef", w.mef(face, v1, v2).is_ok()),
            6 => {
                let end = if rng.random_bool(0.5) {
                    v1
                } else {
                    w.edge(edge)
                        .map_or(v1, |r| if rng.random_bool(0.5) { r.start } else { r.end })
                };
                ("kev", w.kev(edge, end).is_ok())
            }
            7 => {
                let kill = w
                    .edge_faces(edge)
                    .map_or(face, |sides| *choose(rng, &sides));
                ("kef", w.kef(edge, kill).is_ok())
            }
            8 => ("kvfs", w.kvfs(face).is_ok()),
            _ => {
                w.garbage_collect();
                ("garbage collect", true)
            }
        };
        if let Err(error) = w.check() {
            panic!("step {step}: {operation} broke the structure: {error}");
        }
        if !done {
            assert!(
                w == before,
                "step {step}: a refused {operation} changed the structure"
            );
        }
    }
}

#[test]
fn random_euler_sequences_keep_the_structure_valid() {
    run("winged_euler", 100_000, case);
}

#[test]
#[ignore = "long run: cargo test --test stress_winged_euler -- --ignored"]
fn random_euler_sequences_keep_the_structure_valid_long() {
    run_long("winged_euler", case);
}
