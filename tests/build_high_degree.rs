//! Builds around a vertex or an edge that many faces share: a star of triangles on one edge, a
//! star of triangles touching only at one vertex, and a manifold fan around one vertex, with the
//! shared vertices numbered first and last. Each build of both kernels under every policy, and
//! the diagnosis, must stay within [`BOUND`]: a build quadratic in the faces around one vertex
//! (as bucketing edges by their smaller vertex and scanning the bucket was) takes minutes.

use std::time::{Duration, Instant};

use halfwing::mesh::{Mesh, VertexId};
use halfwing::soup::{BuildError, BuildPolicy, Diagnostic, EdgeReport, FaceList};
use halfwing::winged::{self, Winged};

#[path = "../benches/common/stars.rs"]
mod stars;
use stars::{Star, star};

/// Faces around the shared vertex or edge.
const K: u32 = 1 << 17;

/// A guard against quadratic work, not a speed measurement (that is `cargo bench --bench
/// high_degree`): each build takes 20-115 ms in the test profile, and took 19-29 s when the
/// buckets were scanned, so a bound of 10 s only fails on a complexity regression.
const BOUND: Duration = Duration::from_secs(10);

/// `run()` timed against [`BOUND`]; a second try when the first takes longer (the machine may
/// have been busy), and the test fails when that one does too.
fn timed<T>(what: &str, run: impl Fn() -> T) -> T {
    let start = Instant::now();
    let result = run();
    let first = start.elapsed();
    if first <= BOUND {
        return result;
    }
    let start = Instant::now();
    let result = run();
    let second = start.elapsed();
    assert!(second <= BOUND, "{what}: {first:?}, then {second:?}");
    result
}

/// Both kernels' builds of `list` under `policy`, timed, with the mesh checked, and the
/// diagnostic (or the refusal's), the same from both.
fn build_both(
    list: &FaceList<'_>,
    policy: BuildPolicy,
    case: &str,
) -> Result<(Mesh, Winged, Diagnostic), BuildError> {
    let mesh = timed(&format!("{case}, half-edge, {policy:?}"), || {
        Mesh::from_face_list(list, policy)
    });
    let winged = timed(&format!("{case}, winged, {policy:?}"), || {
        Winged::from_face_list(list, policy)
    });
    match (mesh, winged) {
        (Ok((mesh, diagnostic)), Ok((winged, winged_diagnostic))) => {
            assert_eq!(diagnostic, winged_diagnostic, "{case}, {policy:?}");
            assert_eq!(mesh.check(), Ok(()), "{case}, {policy:?}");
            winged.check().unwrap();
            Ok((mesh, winged, diagnostic))
        }
        (Err(error), Err(winged_error)) => {
            assert_eq!(error, winged_error, "{case}, {policy:?}");
            Err(error)
        }
        (mesh, winged) => panic!(
            "{case}, {policy:?}: the kernels disagree: {:?} against {:?}",
            mesh.map(|_| ()),
            winged.map(|_| ())
        ),
    }
}

/// The diagnosis of `list`, timed.
fn diagnose(list: &FaceList<'_>, case: &str) -> Diagnostic {
    timed(&format!("{case}, diagnosis"), || {
        Mesh::diagnose(list).unwrap()
    })
}

#[test]
fn a_star_of_triangles_on_one_edge_is_refused_or_skipped_in_linear_time() {
    for hub_last in [false, true] {
        let (positions, indices, renumber) = star(Star::AtEdge, K, hub_last);
        let list = FaceList::triangles(&positions, &indices);
        let case = format!("star on an edge (hub last: {hub_last})");
        let mut edge = [renumber(0), renumber(1)];
        edge.sort_unstable();
        let report = EdgeReport {
            vertices: edge,
            faces: (0..K).collect(),
        };

        let Err(BuildError::NonManifold(refused)) = build_both(&list, BuildPolicy::Strict, &case)
        else {
            panic!("{case}: a star on an edge is refused");
        };
        assert_eq!(
            refused.non_manifold_edges,
            std::slice::from_ref(&report),
            "{case}"
        );

        // Every face walks the edge the same way: only the first is kept.
        let (mesh, winged, skipped) = build_both(&list, BuildPolicy::Skip, &case).unwrap();
        assert_eq!((mesh.n_faces(), winged.n_faces()), (1, 1), "{case}");
        assert_eq!(skipped.skipped_faces, (1..K).collect::<Vec<_>>(), "{case}");
        assert_eq!(
            skipped.non_manifold_edges,
            std::slice::from_ref(&report),
            "{case}"
        );
        assert_eq!(
            diagnose(&list, &case).non_manifold_edges,
            [report],
            "{case}"
        );
    }
}

#[test]
fn a_star_of_triangles_at_one_vertex_builds_in_linear_time() {
    for hub_last in [false, true] {
        let (positions, indices, renumber) = star(Star::AtVertex, K, hub_last);
        let list = FaceList::triangles(&positions, &indices);
        let case = format!("star at a vertex (hub last: {hub_last})");
        let hub = renumber(0);
        for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
            // Every face is kept, and the hub reported; a strict build may refuse it instead.
            let diagnostic = match build_both(&list, policy, &case) {
                Ok((mesh, winged, diagnostic)) => {
                    let n_faces = (mesh.n_faces(), winged.n_faces());
                    assert_eq!(n_faces, (K as usize, K), "{case}, {policy:?}");
                    diagnostic
                }
                Err(BuildError::NonManifold(refused)) if policy == BuildPolicy::Strict => *refused,
                Err(error) => panic!("{case}, {policy:?}: {error}"),
            };
            assert_eq!(
                diagnostic.non_manifold_vertices,
                [hub],
                "{case}, {policy:?}"
            );
            assert!(
                diagnostic.non_manifold_edges.is_empty() && diagnostic.skipped_faces.is_empty(),
                "{case}, {policy:?}"
            );
        }
        let diagnostic = diagnose(&list, &case);
        assert_eq!(diagnostic.non_manifold_vertices, [hub], "{case}");
    }
}

#[test]
fn a_manifold_fan_of_triangles_around_one_vertex_builds_in_linear_time() {
    for hub_last in [false, true] {
        let (positions, indices, renumber) = star(Star::ManifoldFan, K, hub_last);
        let list = FaceList::triangles(&positions, &indices);
        let case = format!("manifold fan (hub last: {hub_last})");
        let hub = renumber(0);
        for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
            let (mesh, winged, diagnostic) = build_both(&list, policy, &case).unwrap();
            assert!(diagnostic.is_clean(), "{case}, {policy:?}: {diagnostic}");
            assert_eq!(mesh.valence(VertexId(hub)), K as usize + 1, "{case}");
            assert_eq!(winged.valence(winged::VertexId(hub)), Ok(K as usize + 1));
        }
        assert!(diagnose(&list, &case).is_clean(), "{case}");
    }
}

/// Repair gives every face on the edge but the first copies of its two vertices (the faces all
/// walk it the same way, so none can share it).
#[test]
fn repairing_a_star_of_triangles_on_one_edge_takes_linear_time() {
    for hub_last in [false, true] {
        let (positions, indices, renumber) = star(Star::AtEdge, K, hub_last);
        let list = FaceList::triangles(&positions, &indices);
        let case = format!("star on an edge (hub last: {hub_last})");
        let (mesh, winged, repaired) = build_both(&list, BuildPolicy::Repair, &case).unwrap();
        assert_eq!(
            (mesh.n_faces(), winged.n_faces()),
            (K as usize, K),
            "{case}"
        );
        assert_eq!(mesh.n_edges(), 3 * K as usize, "{case}");
        let mut copied = repaired.vertex_copies.clone();
        copied.sort_unstable();
        let mut hubs = [renumber(0), renumber(1)];
        hubs.sort_unstable();
        let expected: Vec<u32> = hubs
            .iter()
            .flat_map(|&v| std::iter::repeat_n(v, K as usize - 1))
            .collect();
        assert_eq!(copied, expected, "{case}");
        assert!(repaired.non_manifold_vertices.is_empty(), "{case}");
    }
}

/// `K` copies of one triangle: before, Repair was quadratic in them (64k copies took 5.3 s,
/// 10^6 did not finish in 15 minutes). Skip keeps the first and lists the rest as skipped;
/// Repair keeps them all, each copy but the first on copies of the three vertices (as for any
/// faces that cannot share an edge); the diagnosis names the three edges with every face.
#[test]
fn repeated_copies_of_one_triangle_build_in_linear_time() {
    let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let indices: Vec<u32> = (0..K).flat_map(|_| [0, 1, 2]).collect();
    let list = FaceList::triangles(&positions, &indices);
    let case = "copies of one triangle";
    assert!(build_both(&list, BuildPolicy::Strict, case).is_err());
    let (mesh, winged, skipped) = build_both(&list, BuildPolicy::Skip, case).unwrap();
    assert_eq!((mesh.n_faces(), winged.n_faces()), (1, 1));
    assert_eq!(skipped.skipped_faces, (1..K).collect::<Vec<_>>());
    let (mesh, winged, repaired) = build_both(&list, BuildPolicy::Repair, case).unwrap();
    assert_eq!((mesh.n_faces(), winged.n_faces()), (K as usize, K));
    assert_eq!(mesh.n_vertices(), 3 * K as usize);
    assert_eq!(repaired.vertex_copies.len(), 3 * (K as usize - 1));
    let diagnosis = diagnose(&list, case);
    assert_eq!(diagnosis.non_manifold_edges.len(), 3);
    assert!(
        diagnosis
            .non_manifold_edges
            .iter()
            .all(|e| e.faces.len() == K as usize)
    );
}
