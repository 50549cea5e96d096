//! Conversions between the winged-edge and half-edge kernels on every manifold model of the
//! shared data set: indexed → winged → half-edge → indexed reproduces the faces exactly, and
//! half-edge → winged → half-edge reproduces the mesh array for array.

use std::path::{Path, PathBuf};

use halfwing::mesh::{self, Mesh};
use halfwing::soup::{BuildPolicy, PolygonSoup};
use halfwing::winged::{EdgeId, FaceId, VertexId, Winged, WingedError};

/// The manifold models (built strictly, no non-manifold vertex) of closed/, open/ and
/// polygonal/, positions and faces only.
fn manifold_models() -> Vec<(PathBuf, PolygonSoup)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/meshes");
    let mut models = Vec::new();
    for dir in ["closed", "open", "polygonal"] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
            .unwrap_or_default();
        files.sort();
        for path in files {
            let Ok(soup) = halfwing::io::read_path(&path) else {
                continue;
            };
            let soup = PolygonSoup {
                corner_normals: None,
                corner_uvs: None,
                ..soup
            };
            let manifold = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
                .is_ok_and(|(_, d)| d.non_manifold_vertices.is_empty());
            if manifold {
                models.push((path, soup));
            }
        }
    }
    if root.exists() {
        assert!(models.len() >= 30, "only {} manifold models", models.len());
    }
    models
}

#[test]
fn indexed_to_winged_to_half_edge_to_indexed_reproduces_the_faces() {
    for (path, input) in manifold_models() {
        let (w, _) = Winged::from_soup(&input, BuildPolicy::Strict).unwrap();
        let mesh = w.to_mesh().unwrap_or_else(|e| panic!("{path:?}: {e}"));
        mesh.check().unwrap();
        let output = mesh.to_soup();
        assert_eq!(output.positions, input.positions, "{path:?}");
        assert_eq!(output.face_sizes, input.face_sizes, "{path:?}");
        assert_eq!(output.indices, input.indices, "{path:?}");
    }
}

#[test]
fn half_edge_to_winged_to_half_edge_is_the_identity() {
    for (path, input) in manifold_models() {
        let (mesh, _) = Mesh::from_face_list(&input.as_face_list(), BuildPolicy::Strict).unwrap();
        let w = Winged::from_mesh(&mesh);
        w.check().unwrap_or_else(|e| panic!("{path:?}: {e}"));
        assert_eq!(w.to_soup(), input, "{path:?}");
        assert_eq!(w.to_mesh().unwrap(), mesh, "{path:?}");
        // Both kernels number edges in corner order, so the builds agree record for record.
        let (built, _) = Winged::from_soup(&input, BuildPolicy::Strict).unwrap();
        assert_eq!(built.edge_records(), w.edge_records(), "{path:?}");
    }
}

#[test]
fn rings_and_loops_agree_with_the_half_edge_circulators() {
    for (path, input) in manifold_models() {
        let (mesh, _) = Mesh::from_face_list(&input.as_face_list(), BuildPolicy::Strict).unwrap();
        let w = Winged::from_mesh(&mesh);
        for v in 0..mesh.n_vertices() as u32 {
            let ring: Vec<u32> = w
                .vertex_neighbors(VertexId(v))
                .unwrap()
                .map(|x| x.0)
                .collect();
            let expected: Vec<u32> = mesh
                .vertex_vertices(mesh::VertexId(v))
                .map(|x| x.0)
                .collect();
            assert_eq!(ring, expected, "{path:?} vertex {v}");
            let faces: Vec<u32> = w.vertex_faces(VertexId(v)).unwrap().map(|x| x.0).collect();
            let expected: Vec<u32> = mesh.vertex_faces(mesh::VertexId(v)).map(|x| x.0).collect();
            assert_eq!(faces, expected, "{path:?} vertex {v}");
        }
        for f in 0..mesh.n_faces() as u32 {
            let corners: Vec<u32> = w.face_vertices(FaceId(f)).unwrap().map(|x| x.0).collect();
            let expected: Vec<u32> = mesh.face_vertices(mesh::FaceId(f)).map(|x| x.0).collect();
            assert_eq!(corners, expected, "{path:?} face {f}");
        }
    }
}

#[test]
fn point_faces_do_not_convert_and_deleted_elements_are_compacted() {
    let mut w = Winged::new();
    let (v0, f0) = w.mvfs([0.0; 3]).unwrap();
    assert!(matches!(w.to_mesh(), Err(WingedError::NotConvertible(_))));
    // A triangle made operator by operator, then an extra dangling edge killed again.
    let (_, v1) = w.mev(f0, v0, [1.0, 0.0, 0.0]).unwrap();
    let (_, v2) = w.mev(f0, v1, [0.0, 1.0, 0.0]).unwrap();
    w.mef(f0, v2, v0).unwrap();
    let (spare, tip) = w.mev(f0, v1, [2.0, 2.0, 0.0]).unwrap();
    w.kev(spare, tip).unwrap();
    assert!(w.edge_capacity() > w.n_edges());
    let mesh = w.to_mesh().unwrap();
    mesh.check().unwrap();
    assert_eq!(
        (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
        (3, 3, 2)
    );
    let back = Winged::from_mesh(&mesh);
    back.check().unwrap();
    assert!(back.edges().all(|e| e != EdgeId::INVALID));
    assert_eq!(back.to_soup(), w.to_soup());
}

/// Repaired broken models hold what the strict models do not (non-manifold vertices, cut
/// edges, several boundary gaps at one vertex): the conversions stay exact there too.
#[test]
fn repaired_broken_models_convert_both_ways() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/meshes/broken");
    let mut files: Vec<PathBuf> = std::fs::read_dir(root)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.sort();
    for path in files {
        let Ok(soup) = halfwing::io::read_path(&path) else {
            continue;
        };
        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
            let Ok((mesh, _)) = Mesh::from_face_list(&soup.as_face_list(), policy) else {
                continue;
            };
            let w = Winged::from_mesh(&mesh);
            w.check()
                .unwrap_or_else(|e| panic!("{path:?} {policy:?}: {e}"));
            assert_eq!(w.to_mesh().unwrap(), mesh, "{path:?} {policy:?}");
            let (built, _) = Winged::from_face_list(&soup.as_face_list(), policy).unwrap();
            assert_eq!(
                built.edge_records(),
                w.edge_records(),
                "{path:?} {policy:?}"
            );
        }
    }
}

mod random {
    use super::*;
    use proptest::prelude::*;

    /// A `cols × rows` triangle grid with the squares in `holes` left out (so boundaries,
    /// inner holes and pinched vertices where two holes touch at a corner).
    fn grid(cols: u32, rows: u32, holes: &[u32]) -> PolygonSoup {
        let mut soup = PolygonSoup::default();
        for j in 0..=rows {
            for i in 0..=cols {
                soup.positions.push([f64::from(i), f64::from(j), 0.0]);
            }
        }
        let at = |i: u32, j: u32| j * (cols + 1) + i;
        for j in 0..rows {
            for i in 0..cols {
                if holes.contains(&(j * cols + i)) {
                    continue;
                }
                soup.indices
                    .extend([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                soup.indices
                    .extend([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                soup.face_sizes.extend([3, 3]);
            }
        }
        soup
    }

    proptest! {
        #[test]
        fn grids_with_holes_convert_both_ways(
            cols in 1u32..7,
            rows in 1u32..7,
            holes in proptest::collection::vec(0u32..49, 0..10),
        ) {
            // Holes touching at a corner pinch vertices: Skip splits them in both kernels alike.
            let soup = grid(cols, rows, &holes);
            let (w, _) = Winged::from_soup(&soup, BuildPolicy::Skip).unwrap();
            let mesh = w.to_mesh().unwrap();
            let (built, _) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Skip).unwrap();
            prop_assert_eq!(mesh.to_soup(), built.to_soup());
            let back = Winged::from_mesh(&mesh);
            prop_assert!(back.check().is_ok());
            prop_assert_eq!(back, w);
        }
    }
}
