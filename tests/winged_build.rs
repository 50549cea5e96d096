//! Building from face lists: round trips, boundaries, queries and bad input.

use halfwing::soup::{BuildError, BuildPolicy, Diagnostic, EdgeReport, FaceList, PolygonSoup};
use halfwing::winged::{EdgeId, FaceId, Side, VertexId, Winged, WingedError};
use proptest::prelude::*;

mod test_data;

fn soup(positions: Vec<[f64; 3]>, faces: &[&[u32]]) -> PolygonSoup {
    PolygonSoup {
        positions,
        face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
        indices: faces.concat(),
        corner_normals: None,
        corner_uvs: None,
    }
}

/// A `cols × rows` grid of unit squares in the z = 0 plane, split into triangles, with the
/// squares listed in `holes` left out.
fn grid(cols: u32, rows: u32, holes: &[u32]) -> PolygonSoup {
    let mut positions = Vec::new();
    for j in 0..=rows {
        for i in 0..=cols {
            positions.push([f64::from(i), f64::from(j), 0.0]);
        }
    }
    let at = |i: u32, j: u32| j * (cols + 1) + i;
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            if holes.contains(&(j * cols + i)) {
                continue;
            }
            faces.push(vec![at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            faces.push(vec![at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let faces: Vec<&[u32]> = faces.iter().map(|f| f.as_slice()).collect();
    soup(positions, &faces)
}

/// Builds `input` under Skip, which leaves no face out of a well-formed list but splits the
/// vertices where several fans touch: the structure's face list is the input's, up to those
/// copies.
fn assert_round_trip(input: &PolygonSoup) -> Winged {
    let (w, diagnostic) = Winged::from_soup(input, BuildPolicy::Skip).expect("builds");
    w.check().expect("valid");
    assert!(diagnostic.skipped_faces.is_empty());
    let output = w.to_soup();
    let n = input.positions.len();
    let original = |v: u32| match (v as usize).checked_sub(n) {
        Some(copy) => diagnostic.vertex_copies[copy],
        None => v,
    };
    assert_eq!(output.positions[..n], input.positions);
    assert_eq!(output.face_sizes, input.face_sizes);
    let indices: Vec<u32> = output.indices.iter().map(|&v| original(v)).collect();
    assert_eq!(indices, input.indices);
    assert!(w.non_manifold_vertices().is_empty());
    w
}

/// Every vertex ring meets all the vertex's edges except at the reported non-manifold
/// vertices, and each side with a face is met once by the face loops.
fn assert_walks_cover_everything(w: &Winged) {
    let degree = w.degrees();
    let pinched = w.non_manifold_vertices();
    for v in w.vertices() {
        let complete = w.valence(v).unwrap() == degree[v.index()] as usize;
        assert_eq!(complete, !pinched.contains(&v), "vertex {v:?}");
    }
    let face_sides: usize = w.faces().map(|f| w.face_loop(f).unwrap().count()).sum();
    let boundary = w
        .edges()
        .filter(|&e| w.is_boundary_edge(e).unwrap())
        .count();
    assert_eq!(face_sides, 2 * w.n_edges() as usize - boundary);
}

#[test]
fn quads_round_trip_and_close() {
    let cube = soup(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 1.0],
        ],
        &[
            &[0, 3, 2, 1],
            &[4, 5, 6, 7],
            &[0, 1, 5, 4],
            &[1, 2, 6, 5],
            &[2, 3, 7, 6],
            &[3, 0, 4, 7],
        ],
    );
    let w = assert_round_trip(&cube);
    assert_eq!((w.n_vertices(), w.n_edges(), w.n_faces()), (8, 12, 6));
    assert_eq!(w.euler_characteristic(), 2);
    assert_walks_cover_everything(&w);
    // Around vertex 0, counter-clockwise seen from outside (from below-left-front).
    let ring: Vec<u32> = w
        .vertex_neighbors(VertexId(0))
        .unwrap()
        .map(|v| v.0)
        .collect();
    assert_eq!(ring.len(), 3);
    let faces: Vec<u32> = w.vertex_faces(VertexId(0)).unwrap().map(|f| f.0).collect();
    for (k, &n) in ring.iter().enumerate() {
        // The face after the edge to `n` contains `n` and the next neighbour.
        let f = FaceId(faces[k]);
        let next = ring[(k + 1) % 3];
        let verts: Vec<u32> = w.face_vertices(f).unwrap().map(|v| v.0).collect();
        assert!(
            verts.contains(&n) && verts.contains(&next),
            "face {f:?} {verts:?}"
        );
    }
    for f in w.faces() {
        assert_eq!(w.face_neighbors(f).unwrap().count(), 4);
    }
}

#[test]
fn open_grid_links_its_boundary_loop() {
    let input = grid(3, 2, &[]);
    let w = assert_round_trip(&input);
    assert_walks_cover_everything(&w);
    let boundary: Vec<EdgeId> = w
        .edges()
        .filter(|&e| w.is_boundary_edge(e).unwrap())
        .collect();
    assert_eq!(boundary.len(), 10);
    let hole: Vec<_> = w.boundary_loop(boundary[0]).unwrap().unwrap().collect();
    assert_eq!(hole.len(), 10, "one loop through every boundary edge");
    assert!(hole.iter().all(|&u| !w.use_face(u).unwrap().is_valid()));
    // The hole runs clockwise seen from +z (opposite to the faces): from (0,0) to (0,1) first.
    let tails: Vec<[f64; 3]> = hole
        .iter()
        .map(|&u| w.position(w.use_tail(u).unwrap()).unwrap())
        .collect();
    let area2: f64 = (0..tails.len())
        .map(|k| {
            let (p, q) = (tails[k], tails[(k + 1) % tails.len()]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum();
    assert_eq!(area2, -12.0);
    // A boundary vertex's ring starts at the hole, so its faces come out in order.
    let corner = VertexId(0);
    assert!(w.is_boundary_vertex(corner).unwrap());
    let first = w.vertex_ring(corner).unwrap().next().unwrap();
    assert!(!w.use_face(first).unwrap().is_valid());
    assert_eq!(
        w.vertex_faces(corner).unwrap().collect::<Vec<_>>(),
        [FaceId(0), FaceId(1)]
    );
    assert!(!w.is_boundary_vertex(VertexId(5)).unwrap());
    assert_eq!(w.valence(VertexId(5)).unwrap(), 6);
}

#[test]
fn grid_with_inner_hole_has_two_boundary_loops() {
    let w = assert_round_trip(&grid(3, 3, &[4]));
    assert_walks_cover_everything(&w);
    let mut seen = std::collections::HashSet::new();
    let mut loops = Vec::new();
    for e in w.edges() {
        if let Some(walk) = w.boundary_loop(e).unwrap()
            && seen.insert(e)
        {
            let uses: Vec<_> = walk.collect();
            seen.extend(uses.iter().map(|u| u.edge));
            loops.push(uses.len());
        }
    }
    loops.sort();
    assert_eq!(loops, [4, 12]);
}

#[test]
fn fans_touching_at_a_vertex_are_split_with_separate_boundary_loops() {
    // Two triangles sharing only vertex 0 (a non-manifold vertex): Strict refuses it, Skip gives
    // the second triangle a copy of it (vertex 5).
    let input = soup(
        vec![
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [-1.0, -1.0, 0.0],
        ],
        &[&[0, 1, 2], &[0, 3, 4]],
    );
    let refusal = Winged::from_soup(&input, BuildPolicy::Strict).unwrap_err();
    assert_eq!(refusal.diagnostic().non_manifold_vertices, [0]);
    let w = assert_round_trip(&input);
    for e in w.edges() {
        assert_eq!(w.boundary_loop(e).unwrap().unwrap().count(), 3);
    }
    assert_eq!(w.valence(VertexId(0)).unwrap(), 2);
    assert_eq!(w.valence(VertexId(5)).unwrap(), 2);
}

#[test]
fn mixed_polygons_and_unreferenced_vertices_round_trip() {
    let input = soup(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [3.0, 0.5, 0.0],
            [9.0; 3],
        ],
        &[&[0, 1, 2, 3], &[1, 4, 2]],
    );
    let w = assert_round_trip(&input);
    assert_eq!(w.vertex_edge(VertexId(5)).unwrap(), EdgeId::INVALID);
    assert_eq!(w.valence(VertexId(5)).unwrap(), 0);
    assert_eq!(w.face_normal(FaceId(0)).unwrap(), [0.0, 0.0, 1.0]);
    assert_eq!(
        w.face_neighbors(FaceId(0)).unwrap().collect::<Vec<_>>(),
        [FaceId(1)]
    );
}

#[test]
fn uniform_triangle_lists_build() {
    let g = grid(2, 2, &[]);
    let (w, diagnostic) = Winged::from_face_list(
        &FaceList::triangles(&g.positions, &g.indices),
        BuildPolicy::Strict,
    )
    .unwrap();
    assert!(diagnostic.is_clean(), "{diagnostic}");
    w.check().unwrap();
    assert_eq!(w.to_soup().indices, g.indices);
}

// --- bad input -------------------------------------------------------------------------------

fn build_err(positions: &[[f64; 3]], faces: &[&[u32]]) -> BuildError {
    Winged::from_soup(&soup(positions.to_vec(), faces), BuildPolicy::Strict)
        .expect_err("must be refused")
}

const SQUARE: [[f64; 3]; 5] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.5, 0.5, 1.0],
];

/// The shared diagnostic names every defect by index, exactly as for the half-edge kernel.
#[test]
fn bad_input_gets_the_shared_diagnostic() {
    let invalid = |e: BuildError| match e {
        BuildError::InvalidInput(d) => *d,
        other => panic!("expected invalid input, got {other:?}"),
    };
    let non_manifold = |e: BuildError| match e {
        BuildError::NonManifold(d) => *d,
        other => panic!("expected non-manifold, got {other:?}"),
    };
    let d = invalid(build_err(
        &SQUARE,
        &[&[0, 1, 7], &[0, 1, 2], &[0, 2, 1, 2], &[0, 1]],
    ));
    assert_eq!(d.faces_out_of_range, [0]);
    assert_eq!(d.faces_repeated_vertex, [2]);
    assert_eq!(d.faces_too_small, [3]);

    let d = non_manifold(build_err(&SQUARE, &[&[0, 1, 4], &[1, 0, 2], &[0, 1, 3]]));
    let book = EdgeReport {
        vertices: [0, 1],
        faces: vec![0, 1, 2],
    };
    assert_eq!(d.non_manifold_edges, [book]);
    let d = non_manifold(build_err(&SQUARE, &[&[0, 1, 2], &[0, 1, 3]]));
    let flipped = EdgeReport {
        vertices: [0, 1],
        faces: vec![0, 1],
    };
    assert_eq!(d.inconsistent_edges, [flipped]);

    let mut nan = SQUARE;
    nan[3][1] = f64::NAN;
    nan[4][0] = f64::INFINITY;
    assert_eq!(
        invalid(build_err(&nan, &[&[0, 1, 2]])).non_finite_vertices,
        [3, 4]
    );

    // Sizes and indices that disagree, including sizes whose sum overflows 32 bits.
    let idx = [0, 1, 2];
    let sizes = [u32::MAX, u32::MAX, 3];
    let list_problem = |list: FaceList<'_>| {
        invalid(Winged::from_face_list(&list, BuildPolicy::Repair).unwrap_err()).list_problem
    };
    assert!(list_problem(FaceList::polygons(&SQUARE, &sizes, &idx)).is_some());
    assert!(list_problem(FaceList::triangles(&SQUARE, &[0, 1, 2, 3])).is_some());
    let d = invalid(
        Winged::from_face_list(
            &FaceList::polygons(&SQUARE, &[3, 0], &idx),
            BuildPolicy::Strict,
        )
        .unwrap_err(),
    );
    assert_eq!(d.faces_too_small, [1]);
}

/// Skip and repair build what strict refuses, with the same meaning as for the half-edge
/// kernel: the same faces survive, the same vertices are copied, and the two kernels agree.
#[test]
fn skip_and_repair_match_the_half_edge_kernel() {
    let faces: &[&[u32]] = &[&[0, 1, 4], &[1, 0, 2], &[0, 1, 3], &[1, 2, 4], &[0, 3, 2]];
    let input = soup(SQUARE.to_vec(), faces);
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (w, diagnostic) = Winged::from_soup(&input, policy).unwrap();
        let (mesh, mesh_diagnostic) =
            halfwing::mesh::Mesh::from_face_list(&input.as_face_list(), policy).unwrap();
        assert_eq!(diagnostic, mesh_diagnostic, "{policy:?}");
        w.check().unwrap();
        assert_eq!(w.to_soup(), mesh.to_soup(), "{policy:?}");
        assert_eq!(w.n_vertices() as usize, mesh.n_vertices());
        assert_eq!(w.n_edges() as usize, mesh.n_edges());
    }
    let (_, skipped) = Winged::from_soup(&input, BuildPolicy::Skip).unwrap();
    assert_eq!(skipped.skipped_faces, [2]);
    let (_, repaired) = Winged::from_soup(&input, BuildPolicy::Repair).unwrap();
    assert!(!repaired.vertex_copies.is_empty());
}

#[test]
fn long_polygons_with_a_repeat_are_refused() {
    let positions: Vec<[f64; 3]> = (0..100).map(|i| [f64::from(i), 0.0, 0.0]).collect();
    let mut face: Vec<u32> = (0..100).collect();
    face[70] = 3;
    assert_eq!(
        build_err(&positions, &[&face])
            .diagnostic()
            .faces_repeated_vertex,
        [0]
    );
}

#[test]
fn edge_order_builds_refuse_bad_faces_with_the_diagnostic() {
    let list = FaceList::triangles(&SQUARE, &[0, 1, 9]);
    match Winged::from_face_list_with_edge_order(&list, &[[0, 1], [1, 9], [9, 0]]) {
        Err(WingedError::InvalidFaceList(e)) => assert_eq!(e.diagnostic().faces_out_of_range, [0]),
        other => panic!("expected the shared diagnostic, got {other:?}"),
    }
}

#[test]
fn explicit_edge_order_must_be_a_permutation() {
    let tri = soup(SQUARE[..3].to_vec(), &[&[0, 1, 2]]);
    let list = tri.as_face_list();
    let err =
        |order: &[[u32; 2]]| Winged::from_face_list_with_edge_order(&list, order).unwrap_err();
    assert!(matches!(
        err(&[[0, 1], [1, 2]]),
        WingedError::EdgeOrderMismatch { .. }
    ));
    assert!(matches!(
        err(&[[0, 1], [1, 2], [1, 0]]),
        WingedError::EdgeOrderMismatch { .. }
    ));
    assert!(matches!(
        err(&[[0, 1], [1, 2], [0, 3]]),
        WingedError::EdgeOrderMismatch { .. }
    ));
    // Reversed directions are accepted: the face then lies on the edges' right sides.
    let w = Winged::from_face_list_with_edge_order(&list, &[[0, 2], [2, 1], [1, 0]]).unwrap();
    w.check().unwrap();
    for e in w.edges() {
        assert_eq!(w.edge_faces(e).unwrap(), [FaceId::INVALID, FaceId(0)]);
    }
    assert_eq!(w.to_soup().indices, [0, 1, 2]);
}

#[test]
fn invalid_handles_are_errors() {
    let (w, _) = Winged::from_soup(&grid(1, 1, &[]), BuildPolicy::Strict).unwrap();
    assert_eq!(
        w.edge(EdgeId(99)).unwrap_err(),
        WingedError::InvalidEdge(EdgeId(99))
    );
    assert!(w.face_loop(FaceId::INVALID).is_err());
    assert!(w.vertex_ring(VertexId(4)).is_err());
    assert!(w.position(VertexId::INVALID).is_err());
    assert!(w.face_normal(FaceId(2)).is_err());
    let stray = halfwing::winged::EdgeUse::new(EdgeId(1000), Side::Right);
    assert!(w.use_tail(stray).is_err() && w.use_head(stray).is_err() && w.use_face(stray).is_err());
    assert_eq!((w.use_next(stray), w.use_prev(stray)), (None, None));
    let mut w = w;
    assert!(matches!(
        w.set_vertex_edge(VertexId(1), EdgeId(1)),
        Err(WingedError::NotIncident { .. }) | Ok(())
    ));
    let far = w
        .edges()
        .find(|&e| w.edge(e).unwrap().side_leaving(VertexId(0)).is_none())
        .unwrap();
    assert_eq!(
        w.set_vertex_edge(VertexId(0), far),
        Err(WingedError::NotIncident {
            edge: far,
            what: "vertex"
        })
    );
    assert!(w.set_position(VertexId(0), [f64::NAN, 0.0, 0.0]).is_err());
}

// --- the test models -------------------------------------------------------------------------

/// Every model file of the test data's `meshes/<dir>`, read with the crate's reader (files the
/// reader refuses are left out: the readers have their own tests).
fn models(dir: &str) -> Vec<(std::path::PathBuf, PolygonSoup)> {
    let root = test_data::root().join("meshes").join(dir);
    let mut files: Vec<_> = std::fs::read_dir(&root)
        .unwrap_or_else(|e| panic!("{} (set HALFWING_DATA): {e}", root.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    files.sort();
    files
        .into_iter()
        .filter_map(|path| halfwing::io::read_path(&path).ok().map(|soup| (path, soup)))
        .collect()
}

/// Positions and faces only (the readers also keep per-corner normals and uvs, which a
/// winged-edge structure has no place for).
fn geometry(soup: PolygonSoup) -> PolygonSoup {
    PolygonSoup {
        corner_normals: None,
        corner_uvs: None,
        ..soup
    }
}

#[test]
fn manifold_models_round_trip() {
    let mut built = 0;
    for dir in ["closed", "open", "polygonal"] {
        for (path, input) in models(dir) {
            let input = geometry(input);
            let Ok((_, diagnostic)) = Winged::from_soup(&input, BuildPolicy::Strict) else {
                continue; // not manifold: left to the broken-model test
            };
            if !diagnostic.non_manifold_vertices.is_empty() {
                continue;
            }
            let w = assert_round_trip(&input);
            assert_walks_cover_everything(&w);
            if dir == "closed" {
                assert!(
                    w.edges().all(|e| !w.is_boundary_edge(e).unwrap()),
                    "{path:?}"
                );
            }
            built += 1;
        }
    }
    assert!(built >= 30, "only {built} manifold models built");
}

/// Every policy either refuses a broken model with a diagnostic or builds a valid structure
/// that agrees with the half-edge kernel's on the same input.
#[test]
fn broken_models_never_panic() {
    for (path, input) in models("broken") {
        for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
            let winged = Winged::from_soup(&input, policy);
            let mesh = halfwing::mesh::Mesh::from_face_list(&input.as_face_list(), policy);
            match (winged, mesh) {
                (Ok((w, d)), Ok((m, md))) => {
                    w.check()
                        .unwrap_or_else(|e| panic!("{path:?} {policy:?}: {e}"));
                    assert_eq!(d, md, "{path:?} {policy:?}");
                    assert_eq!(w.to_soup(), geometry(m.to_soup()), "{path:?} {policy:?}");
                }
                (Err(e), Err(me)) => assert_eq!(e, me, "{path:?} {policy:?}"),
                (w, m) => panic!("{path:?} {policy:?}: kernels disagree: {w:?} / {m:?}"),
            }
        }
    }
}

// --- random input ----------------------------------------------------------------------------

proptest! {
    #[test]
    fn random_grids_with_holes_round_trip(cols in 1u32..6, rows in 1u32..6, holes in proptest::collection::vec(0u32..36, 0..6)) {
        let input = grid(cols, rows, &holes);
        let w = assert_round_trip(&input);
        assert_walks_cover_everything(&w);
        for v in w.vertices() {
            let ring: Vec<_> = w.vertex_ring(v).unwrap().collect();
            prop_assert!(ring.iter().all(|&u| w.use_tail(u).unwrap() == v));
        }
    }

    #[test]
    fn random_face_lists_never_panic(
        n_vertices in 0usize..8,
        sizes in proptest::collection::vec(0u32..6, 0..8),
        indices in proptest::collection::vec(0u32..10, 0..40),
    ) {
        let positions: Vec<[f64; 3]> = (0..n_vertices).map(|i| [i as f64, (i * i) as f64, 0.0]).collect();
        let list = FaceList::polygons(&positions, &sizes, &indices);
        if let Ok((w, _)) = Winged::from_face_list(&list, BuildPolicy::Strict) {
            prop_assert!(w.check().is_ok());
            let back = w.to_soup();
            prop_assert_eq!(&back.indices, &indices);
            prop_assert_eq!(&back.face_sizes, &sizes);
        }
    }
}

#[test]
fn large_meshes_report_every_defect() {
    let mut input = grid(160, 160, &[]);
    assert_round_trip(&input);
    // Two defects far apart: a face walking the last grid edge (last -> last - 1) again, and
    // one walking grid edge 0 -> 1 again. Both are reported, in vertex order.
    let n = input.positions.len() as u32;
    let last = n - 1;
    input
        .positions
        .extend([[0.5, -1.0, 0.0], [160.5, 161.0, 1.0]]);
    input.face_sizes.extend([3, 3]);
    input.indices.extend([last, last - 1, n + 1, 0, 1, n]);
    let d: Diagnostic = match Winged::from_soup(&input, BuildPolicy::Strict).unwrap_err() {
        BuildError::NonManifold(d) => *d,
        other => panic!("{other:?}"),
    };
    let edges: Vec<[u32; 2]> = d.inconsistent_edges.iter().map(|r| r.vertices).collect();
    assert_eq!(edges, [[0, 1], [last - 1, last]]);
    assert_eq!(d.inconsistent_edges[1].faces, [51199, 51200]);
}
