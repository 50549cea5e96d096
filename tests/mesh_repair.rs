//! Repair on the shared broken models: every face kept, a valid mesh, and the surface cut only
//! where it must be — fans around a non-manifold edge's ends get vertices of their own.

use halfwing::io::read_path;
use halfwing::mesh::Mesh;
use halfwing::soup::BuildPolicy;

mod shared_data;

fn broken(name: &str) -> halfwing::soup::PolygonSoup {
    read_path(shared_data::root().join("meshes/broken").join(name)).expect("the shared model reads")
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
