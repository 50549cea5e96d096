//! Repair on the broken test models: every face kept, a valid mesh, and the surface cut only
//! where it must be — fans around a non-manifold edge's ends get vertices of their own.

use halfwing::io::read_path;
use halfwing::mesh::Mesh;
use halfwing::soup::BuildPolicy;

mod test_data;

fn broken(name: &str) -> halfwing::soup::PolygonSoup {
    read_path(test_data::root().join("meshes/broken").join(name)).expect("the test model reads")
}

fn repaired(name: &str) -> Mesh {
    let soup = broken(name);
    let (mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair)
        .expect("repair keeps every face");
    mesh.check()
        .expect("a repaired mesh satisfies every invariant");
    assert_eq!(mesh.n_faces(), soup.n_faces(), "{name}: no face is dropped");
    assert!(
        !diagnostic.vertex_copies.is_empty(),
        "{name}: repair copied vertices"
    );
    mesh
}

#[test]
fn two_cubes_sharing_an_edge_become_two_closed_cubes() {
    let mesh = repaired("cgal_cubes.off");
    assert_eq!(mesh.boundary_loops().len(), 0);
    assert_eq!(mesh.connected_components().count, 2);
    // Each closed cube of triangles: V - E + F = 2.
    let euler = mesh.n_vertices() as i64 - mesh.n_edges() as i64 + mesh.n_faces() as i64;
    assert_eq!(euler, 4);
}

#[test]
fn three_triangles_on_one_edge_come_apart() {
    let mesh = repaired("gc_fan3.obj");
    assert_eq!(mesh.connected_components().count, 3);
    assert_eq!(mesh.boundary_loops().len(), 3);
}

#[test]
fn joined_tetrahedra_and_the_truck_keep_every_face() {
    for name in [
        "tm_joined_tetrahedra.obj",
        "igl_truck.obj",
        "gc_moebius.obj",
    ] {
        repaired(name);
    }
}

#[test]
fn every_vertex_repair_copies_is_used_by_a_face() {
    // Five faces of a box, the quad 0-1-5-4 given twice: repair copies vertices in several
    // steps (fans around the problem edges, then rounds for the faces still refused), and a copy
    // a later step took its corners off must not stay behind as an isolated vertex.
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
        [1.0, 1.0, 1.0],
    ];
    let indices = [
        0, 2, 3, 1, 0, 1, 5, 4, 4, 5, 7, 6, 0, 1, 5, 4, 0, 4, 6, 2, 2, 6, 7, 3,
    ];
    let list = halfwing::soup::FaceList::polygons(&positions, &[4; 6], &indices);
    let (mesh, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Repair).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.n_faces(), 6);
    assert!(!diagnostic.vertex_copies.is_empty());
    assert_eq!(diagnostic.isolated_vertices, Vec::<u32>::new());
    assert_eq!(mesh.isolated_vertices(), Vec::<u32>::new());
}

/// A clean closed surface facing inward comes out facing outward under Repair, and Strict and
/// Skip keep it as it is. Before: a list with no defect took the direct route, which never
/// turned closed components outward.
#[test]
fn a_clean_inside_out_tetrahedron_is_turned_outward() {
    use halfwing::soup::FaceList;
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    // Every face clockwise seen from outside.
    let inward = [0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0];
    let list = FaceList::triangles(&positions, &inward);
    let (mesh, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Repair).unwrap();
    mesh.check().unwrap();
    assert_eq!(diagnostic.reoriented_faces, vec![0, 1, 2, 3]);
    // The first face now runs 0, 2, 1: its normal points away from the opposite vertex 3.
    let normal = halfwing::geom::face_normals(&mesh)[0];
    assert!(normal[2] < 0.0, "{normal:?}");
    for policy in [BuildPolicy::Strict, BuildPolicy::Skip] {
        let (mesh, diagnostic) = Mesh::from_face_list(&list, policy).unwrap();
        assert!(diagnostic.reoriented_faces.is_empty());
        assert!(halfwing::geom::face_normals(&mesh)[0][2] > 0.0);
    }
}
