//! Stress test of the two bulk builders: random indexed face lists (non-manifold and
//! inconsistently oriented edges, repeated and degenerate faces, out-of-range indices, NaN and
//! infinite coordinates) under every policy. The half-edge and winged-edge kernels agree: both
//! build or both refuse, with the same counts and the same diagnostic; the winged structure
//! converts to the very mesh the half-edge builder made; both pass their checks.

mod stress;

use halfwing::mesh::Mesh;
use halfwing::soup::{BuildPolicy, FaceList};
use halfwing::winged::Winged;
use proptest::test_runner::TestRng;
use stress::{Rng, run, run_long};

#[path = "../fuzz/fuzz_targets/face_list.rs"]
mod face_list;

/// Bytes for the fuzzers' face-list decoder: few vertices, so that edges collide.
fn random_face_list_bytes(rng: &mut TestRng) -> Vec<u8> {
    let len = rng.random_range(0..160);
    (0..len).map(|_| rng.random::<u8>()).collect()
}

/// Panics unless the meshes are equal, naming what differs; positions compare bit for bit (NaN
/// coordinates are kept by the builders and equal to themselves here).
fn assert_same_mesh(found: &Mesh, expected: &Mesh, policy: BuildPolicy) {
    let arrays = [
        ("origin", Mesh::halfedge_origins as fn(&Mesh) -> &[u32]),
        ("next", Mesh::halfedge_nexts),
        ("prev", Mesh::halfedge_prevs),
        ("face", Mesh::halfedge_faces),
        ("vertex_halfedge", Mesh::vertex_halfedges),
        ("face_halfedge", Mesh::face_halfedges),
    ];
    for (name, array) in arrays {
        assert_eq!(
            array(found),
            array(expected),
            "{policy:?}: winged → mesh: {name}"
        );
    }
    let bits = |mesh: &Mesh| -> Vec<[u64; 3]> {
        mesh.positions()
            .iter()
            .map(|p| p.map(f64::to_bits))
            .collect()
    };
    assert_eq!(
        bits(found),
        bits(expected),
        "{policy:?}: winged → mesh: positions"
    );
    if found.positions().iter().flatten().all(|x| !x.is_nan()) {
        assert!(found == expected, "{policy:?}: winged → mesh differs");
    }
}

fn case(rng: &mut TestRng) {
    let decoded = face_list::decode(&random_face_list_bytes(rng));
    let list = FaceList::polygons(&decoded.positions, &decoded.sizes, &decoded.indices);
    for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
        match (
            Mesh::from_face_list(&list, policy),
            Winged::from_face_list(&list, policy),
        ) {
            (Ok((mesh, mesh_diagnostic)), Ok((winged, winged_diagnostic))) => {
                assert_eq!(mesh_diagnostic, winged_diagnostic, "{policy:?}");
                mesh.check().expect("the half-edge mesh passes its check");
                winged
                    .check()
                    .expect("the winged structure passes its check");
                assert_eq!(
                    mesh.n_vertices(),
                    winged.n_vertices() as usize,
                    "{policy:?}"
                );
                assert_eq!(mesh.n_edges(), winged.n_edges() as usize, "{policy:?}");
                assert_eq!(mesh.n_faces(), winged.n_faces() as usize, "{policy:?}");
                let converted = winged.to_mesh().expect("a built structure converts");
                assert_same_mesh(&converted, &mesh, policy);
            }
            (Err(mesh_error), Err(winged_error)) => {
                assert_eq!(
                    mesh_error.to_string(),
                    winged_error.to_string(),
                    "{policy:?}: the kernels refuse differently"
                );
            }
            (mesh, winged) => panic!(
                "{policy:?}: one kernel builds, the other refuses: {:?} / {:?}",
                mesh.map(|_| ()),
                winged.map(|_| ())
            ),
        }
    }
}

#[test]
fn both_kernels_build_random_face_lists_alike() {
    run("build", 100_000, case);
}

#[test]
#[ignore = "long run: cargo test --test stress_build -- --ignored"]
fn both_kernels_build_random_face_lists_alike_long() {
    run_long("build", case);
}
