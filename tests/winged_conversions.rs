//! Conversions between the winged-edge and half-edge kernels on the test data set: both
//! builders give the same structure (every array, every record) on every model that builds,
//! under every policy; indexed → winged → half-edge → indexed reproduces the faces exactly; and
//! half-edge → winged → half-edge reproduces the mesh array for array.

use std::fmt::Debug;
use std::path::PathBuf;

use halfwing::mesh::{self, Mesh};
use halfwing::soup::{BuildPolicy, PolygonSoup};
use halfwing::winged::{EdgeId, FaceId, VertexId, Winged, WingedError};

mod test_data;

/// The meshes of the test data set under `dirs` that read, positions and faces only, in file
/// name order. Fails when the data set is missing (see `test_data`).
fn models_in(dirs: &[&str]) -> Vec<(PathBuf, PolygonSoup)> {
    let root = test_data::root().join("meshes");
    assert!(
        root.is_dir(),
        "test data not found at {} (set HALFWING_DATA)",
        root.display()
    );
    let mut models = Vec::new();
    for dir in dirs {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .unwrap_or_else(|e| panic!("{}: {e}", root.join(dir).display()))
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
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
            models.push((path, soup));
        }
    }
    models
}

/// Every mesh of the test data set that reads, broken ones included.
fn every_model() -> Vec<(PathBuf, PolygonSoup)> {
    models_in(&["closed", "open", "polygonal", "broken"])
}

/// The manifold models (built strictly, no non-manifold vertex) of closed/, open/ and
/// polygonal/, positions and faces only.
fn manifold_models() -> Vec<(PathBuf, PolygonSoup)> {
    let models: Vec<_> = models_in(&["closed", "open", "polygonal"])
        .into_iter()
        .filter(|(_, soup)| {
            Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
                .is_ok_and(|(_, d)| d.non_manifold_vertices.is_empty())
        })
        .collect();
    assert!(models.len() >= 30, "only {} manifold models", models.len());
    models
}

const POLICIES: [BuildPolicy; 3] = [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair];

/// Panics naming the first index where two arrays of one structure differ.
fn assert_same_array<T: PartialEq + Debug>(name: &str, found: &[T], expected: &[T], what: &str) {
    if let Some(i) = (0..found.len().min(expected.len())).find(|&i| found[i] != expected[i]) {
        panic!(
            "{what}: {name}[{i}] is {:?}, expected {:?}",
            found[i], expected[i]
        );
    }
    assert_eq!(found.len(), expected.len(), "{what}: length of {name}");
}

/// Panics unless the two meshes are equal, naming the first differing array entry when they
/// differ in one: the half-edge arrays, the stored half-edges, the positions, the corner
/// attributes, then everything else (deletions, named attributes, flags).
fn assert_same_mesh(found: &Mesh, expected: &Mesh, what: &str) {
    let halfedge_arrays = [
        ("origin", Mesh::halfedge_origins as fn(&Mesh) -> &[u32]),
        ("next", Mesh::halfedge_nexts),
        ("prev", Mesh::halfedge_prevs),
        ("face", Mesh::halfedge_faces),
        ("vertex_halfedge", Mesh::vertex_halfedges),
        ("face_halfedge", Mesh::face_halfedges),
    ];
    for (name, array) in halfedge_arrays {
        assert_same_array(name, array(found), array(expected), what);
    }
    assert_same_array("positions", found.positions(), expected.positions(), what);
    assert_eq!(
        found.corner_normals(),
        expected.corner_normals(),
        "{what}: corner normals"
    );
    assert_eq!(
        found.corner_uvs(),
        expected.corner_uvs(),
        "{what}: corner uvs"
    );
    assert!(found == expected, "{what}: the meshes differ");
}

/// Panics unless the two structures are equal, naming the first differing record when they
/// differ in one: edge records, stored vertex and face edges, positions, then everything else
/// (live flags and counts, point faces).
fn assert_same_winged(found: &Winged, expected: &Winged, what: &str) {
    assert_same_array(
        "edge records",
        found.edge_records(),
        expected.edge_records(),
        what,
    );
    assert_same_array(
        "vertex edges",
        found.vertex_edges_stored(),
        expected.vertex_edges_stored(),
        what,
    );
    assert_same_array(
        "face edges",
        found.face_edges_stored(),
        expected.face_edges_stored(),
        what,
    );
    assert_same_array("positions", found.positions(), expected.positions(), what);
    assert!(found == expected, "{what}: the structures differ");
}

/// Whatever mesh the builders make of a model (refused, skipped, repaired, non-manifold
/// vertices kept or split), they make the same one: the winged build converted to a mesh is
/// the half-edge build, every array of it, and the half-edge build converted to a winged
/// structure is the winged build, every record of it; both refuse the same input with the same
/// diagnostic.
/// One geometry module computes both kernels' normals: the face normals are the same bit for
/// bit, and the vertex normals (unit face normals summed around the vertex, in another order)
/// agree to rounding.
fn assert_same_normals(mesh: &Mesh, winged: &Winged, what: &str) {
    let faces = halfwing::geom::face_normals(mesh);
    assert_same_array("face normals", &winged.face_normals(), &faces, what);
    let vertices =
        halfwing::geom::vertex_normals(mesh, halfwing::geom::VertexNormalWeighting::Uniform);
    for (v, (found, expected)) in winged.vertex_normals().iter().zip(&vertices).enumerate() {
        let distance = (0..3)
            .map(|k| (found[k] - expected[k]).abs())
            .fold(0.0, f64::max);
        assert!(
            distance <= 1e-12,
            "{what}: vertex {v}: {found:?} against {expected:?}"
        );
    }
}

#[test]
fn both_builders_give_the_same_structure_on_every_model() {
    let mut compared = 0;
    for (path, soup) in every_model() {
        let list = soup.as_face_list();
        for policy in POLICIES {
            let what = format!("{} {policy:?}", path.display());
            match (
                Mesh::from_face_list(&list, policy),
                Winged::from_face_list(&list, policy),
            ) {
                (Ok((mesh, mesh_diagnostic)), Ok((winged, winged_diagnostic))) => {
                    assert_eq!(mesh_diagnostic, winged_diagnostic, "{what}");
                    let converted = winged.to_mesh().unwrap_or_else(|e| panic!("{what}: {e}"));
                    assert_same_mesh(&converted, &mesh, &what);
                    assert_same_winged(&Winged::from_mesh(&mesh), &winged, &what);
                    assert_same_normals(&mesh, &winged, &what);
                    compared += 1;
                }
                (Err(mesh_error), Err(winged_error)) => {
                    assert_eq!(mesh_error, winged_error, "{what}")
                }
                (mesh, winged) => panic!(
                    "{what}: the half-edge build {}, the winged build {}",
                    if mesh.is_ok() { "succeeds" } else { "fails" },
                    if winged.is_ok() { "succeeds" } else { "fails" },
                ),
            }
        }
    }
    assert!(compared >= 150, "only {compared} builds compared");
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
fn point_faces_do_not_convert_and_deleted_elements_are_left_out_of_the_round_trip() {
    let mut w = Winged::new();
    let (v0, f0) = w.mvfs([0.0; 3]).unwrap();
    assert!(matches!(w.to_mesh(), Err(WingedError::NotConvertible(_))));
    // A triangle made operator by operator, then an extra dangling edge killed again.
    let (_, v1) = w.mev(f0, v0, [1.0, 0.0, 0.0]).unwrap();
    let (_, v2) = w.mev(f0, v1, [0.0, 1.0, 0.0]).unwrap();
    w.mef(f0, v2, v0).unwrap();
    let (spare, tip) = w.mev(f0, v1, [2.0, 2.0, 0.0]).unwrap();
    w.kev(spare, tip).unwrap();
    assert!(w.n_edge_slots() > w.n_edges());
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
    for (path, soup) in models_in(&["broken"]) {
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

/// A vertex with a non-finite coordinate is held deleted by both builders (its faces left out):
/// the winged structure converts to the builder's mesh with that vertex deleted at its own id,
/// not to a compacted mesh whose later vertices moved down by one.
#[test]
fn non_finite_vertices_keep_their_ids_through_the_conversion() {
    let positions = [
        [0.0, 0.0, 0.0],
        [f64::NAN, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let list = halfwing::soup::FaceList::polygons(&positions, &[3, 4], &[0, 1, 2, 0, 2, 3, 4]);
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, _) = Mesh::from_face_list(&list, policy).unwrap();
        let (w, _) = Winged::from_face_list(&list, policy).unwrap();
        assert!(mesh.is_vertex_deleted(mesh::VertexId(1)), "{policy:?}");
        let converted = w.to_mesh().unwrap();
        assert_eq!(converted.halfedge_origins(), mesh.halfedge_origins());
        assert_eq!(converted, mesh, "{policy:?}");
        assert_eq!(converted.n_vertices(), 4);
        assert_eq!(converted.n_vertex_slots(), 5);
    }
}

/// Elements an Euler operator deleted stay in the converted mesh, deleted at their ids, until
/// either structure is compacted; compacting before or after the conversion agrees.
#[test]
fn deleted_elements_stay_deleted_through_the_conversion() {
    let mut w = Winged::new();
    let (v0, f0) = w.mvfs([0.0; 3]).unwrap();
    let (_, v1) = w.mev(f0, v0, [1.0, 0.0, 0.0]).unwrap();
    let (_, v2) = w.mev(f0, v1, [0.0, 1.0, 0.0]).unwrap();
    w.mef(f0, v2, v0).unwrap();
    let (spare, tip) = w.mev(f0, v1, [2.0, 2.0, 0.0]).unwrap();
    w.kev(spare, tip).unwrap();
    let mut mesh = w.to_mesh().unwrap();
    mesh.check().unwrap();
    assert!(mesh.is_vertex_deleted(mesh::VertexId(tip.0)));
    assert!(mesh.is_edge_deleted(mesh::EdgeId(spare.0)));
    mesh.garbage_collect();
    let mut compacted = w.clone();
    compacted.garbage_collect();
    assert_eq!(mesh, compacted.to_mesh().unwrap());
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
            prop_assert_eq!(&mesh, &built);
            let back = Winged::from_mesh(&mesh);
            prop_assert!(back.check().is_ok());
            prop_assert_eq!(back, w);
        }
    }
}
