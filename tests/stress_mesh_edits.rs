//! Stress test of the half-edge kernel's edits: random sequences of flip, split edge, split
//! face, collapse, triangulate, delete face, add face and garbage collection on grids and on
//! randomly built (often non-manifold) meshes. After every edit the mesh passes `check()`, and a
//! refused edit leaves it unchanged.

mod stress;

use halfwing::mesh::{BuildPolicy, EdgeId, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::soup::FaceList;
use halfwing::surfaces::{CellFaces, Grid, grid};
use proptest::test_runner::TestRng;
use stress::{Rng, index_below, run, run_long};

#[path = "../fuzz/fuzz_targets/face_list.rs"]
mod face_list;

/// A grid of quads or triangles, or a random face list (NaN-free) built with repairs.
fn start_mesh(rng: &mut TestRng) -> Mesh {
    if rng.random_bool(0.5) {
        let soup = grid(&Grid {
            width: 3.0,
            height: 2.0,
            cells_x: rng.random_range(1..5),
            cells_y: rng.random_range(1..5),
            faces: if rng.random_bool(0.5) {
                CellFaces::Quads
            } else {
                CellFaces::Triangles
            },
        })
        .expect("a valid grid");
        return Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
            .expect("a grid builds")
            .0;
    }
    loop {
        let bytes: Vec<u8> = (0..rng.random_range(8..160))
            .map(|_| rng.random())
            .collect();
        let decoded = face_list::decode(&bytes);
        // NaN would make a mesh unequal to itself, and the refusal check compares meshes (the
        // build target takes NaN).
        let positions: Vec<[f64; 3]> = decoded
            .positions
            .iter()
            .map(|p| p.map(|x| if x.is_nan() { 0.0 } else { x }))
            .collect();
        let list = FaceList::polygons(&positions, &decoded.sizes, &decoded.indices);
        if let Ok((mesh, _)) = Mesh::from_face_list(&list, BuildPolicy::Repair) {
            return mesh;
        }
    }
}

fn case(rng: &mut TestRng) {
    let mut mesh = start_mesh(rng);
    mesh.check().expect("a built mesh passes its check");
    for step in 0..rng.random_range(1..64) {
        let before = mesh.clone();
        let h = HalfedgeId(index_below(rng, mesh.n_halfedge_slots() + 1));
        let e = EdgeId(index_below(rng, mesh.n_edge_slots() + 1));
        let f = FaceId(index_below(rng, mesh.n_face_slots() + 1));
        let (operation, done) = match rng.random_range(0..8) {
            0 => ("flip", mesh.flip_edge(e).is_ok()),
            1 => {
                let t: f64 = rng.random();
                ("split edge", mesh.split_edge(e, [t, 1.0 - t, 0.5]).is_ok())
            }
            2 => {
                let other = HalfedgeId(index_below(rng, mesh.n_halfedge_slots()));
                ("split face", mesh.split_face(h, other).is_ok())
            }
            3 => ("triangulate", mesh.triangulate_face(f).is_ok()),
            4 => ("collapse", mesh.collapse_halfedge(h).is_ok()),
            5 => {
                let isolated = rng.random_bool(0.5);
                ("delete face", mesh.delete_face(f, isolated).is_ok())
            }
            6 => {
                let n = rng.random_range(0..6);
                let corners: Vec<VertexId> = (0..n)
                    .map(|_| VertexId(index_below(rng, mesh.n_vertex_slots() + 1)))
                    .collect();
                ("add face", mesh.add_face(&corners).is_ok())
            }
            _ => {
                mesh.garbage_collect();
                ("garbage collect", true)
            }
        };
        if let Err(error) = mesh.check() {
            panic!("step {step}: {operation} broke the mesh: {error}");
        }
        if !done {
            assert!(
                mesh == before,
                "step {step}: a refused {operation} changed the mesh"
            );
        }
    }
}

#[test]
fn random_edit_sequences_keep_the_mesh_valid() {
    run("mesh_edits", 100_000, case);
}

#[test]
#[ignore = "long run: cargo test --test stress_mesh_edits -- --ignored"]
fn random_edit_sequences_keep_the_mesh_valid_long() {
    run_long("mesh_edits", case);
}
