//! Incremental construction with `Mesh::add_face`: face by face it must reach the topology the
//! bulk build gives, and every refusal must leave the mesh exactly as it was.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, EditError, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::soup::PolygonSoup;
use mesh_support::grid;
use proptest::prelude::*;

/// A vertex cycle rotated to start at its smallest vertex, so equal loops compare equal.
fn canonical(cycle: Vec<u32>) -> Vec<u32> {
    let start = (0..cycle.len()).min_by_key(|&i| cycle[i]).unwrap_or(0);
    cycle[start..]
        .iter()
        .chain(&cycle[..start])
        .copied()
        .collect()
}

fn face_cycles(mesh: &Mesh) -> Vec<Vec<u32>> {
    let mut cycles: Vec<Vec<u32>> = (0..mesh.n_face_slots() as u32)
        .map(FaceId)
        .filter(|&f| !mesh.is_face_deleted(f))
        .map(|f| canonical(mesh.face_vertices(f).map(|v| v.0).collect()))
        .collect();
    cycles.sort();
    cycles
}

fn boundary_cycles(mesh: &Mesh) -> Vec<Vec<u32>> {
    let mut cycles: Vec<Vec<u32>> = mesh
        .boundary_loops()
        .into_iter()
        .map(|h| canonical(mesh.halfedge_loop(h).map(|g| mesh.origin(g).0).collect()))
        .collect();
    cycles.sort();
    cycles
}

fn faces_of(soup: &PolygonSoup) -> Vec<Vec<VertexId>> {
    let mut start = 0usize;
    soup.face_sizes
        .iter()
        .map(|&size| {
            let face = soup.indices[start..start + size as usize]
                .iter()
                .map(|&v| VertexId(v))
                .collect();
            start += size as usize;
            face
        })
        .collect()
}

/// Adds `soup`'s vertices, then its faces in `order`.
fn incremental(soup: &PolygonSoup, order: &[usize]) -> Result<Mesh, EditError> {
    let mut mesh = Mesh::new();
    for &p in &soup.positions {
        mesh.add_vertex(p).unwrap();
    }
    let faces = faces_of(soup);
    for &f in order {
        mesh.add_face(&faces[f])?;
        assert_eq!(mesh.check(), Ok(()), "after adding face {f}");
    }
    Ok(mesh)
}

fn assert_same_topology(incremental: &Mesh, bulk: &Mesh) {
    assert_eq!(incremental.check(), Ok(()));
    assert_eq!(
        (
            incremental.n_vertices(),
            incremental.n_edges(),
            incremental.n_faces()
        ),
        (bulk.n_vertices(), bulk.n_edges(), bulk.n_faces())
    );
    assert_eq!(face_cycles(incremental), face_cycles(bulk));
    assert_eq!(boundary_cycles(incremental), boundary_cycles(bulk));
    for v in 0..bulk.n_vertex_slots() as u32 {
        assert_eq!(incremental.valence(VertexId(v)), bulk.valence(VertexId(v)));
        assert_eq!(
            incremental.is_boundary_vertex(VertexId(v)),
            bulk.is_boundary_vertex(VertexId(v))
        );
    }
}

fn bulk(soup: &PolygonSoup) -> Mesh {
    Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
        .unwrap()
        .0
}

#[test]
fn faces_in_file_order_rebuild_the_seed_mesh_and_real_models() {
    let paths = [
        "closed/cgal_tetrahedron.off",
        "open/cgal_open_cube.off",
        "polygonal/gc_dodecahedron_poly.obj",
        "open/gc_cat_head.obj",
    ];
    for path in paths {
        let soup = mesh_support::load(&mesh_support::data_dir().join(path));
        let order: Vec<usize> = (0..soup.n_faces()).collect();
        let built = incremental(&soup, &order).unwrap_or_else(|e| panic!("{path}: {e}"));
        let reference = bulk(&soup);
        assert_same_topology(&built, &reference);
        // In file order, face ids agree with the bulk build's too.
        for f in 0..reference.n_face_slots() as u32 {
            assert_eq!(
                canonical(built.face_vertices(FaceId(f)).map(|v| v.0).collect()),
                canonical(reference.face_vertices(FaceId(f)).map(|v| v.0).collect())
            );
        }
    }
}

#[test]
fn each_refusal_names_its_reason() {
    let soup = grid(2, 1, false, false); // two quads: vertices 0 1 2 / 3 4 5
    let mut mesh = incremental(&soup, &[0]).unwrap();
    let before = mesh.clone();
    let v = VertexId;
    let cases: [(&[VertexId], &str); 5] = [
        (&[v(0), v(1)], "at least 3"),
        (&[v(1), v(2), v(2), v(5)], "repeated"),
        (&[v(0), v(1), v(4)], "complex edge"),
        (&[v(1), v(2), v(5), v(99)], "out of range"),
        (&[v(1), v(4), v(2)], "complex edge"),
    ];
    for (face, needle) in cases {
        let error = mesh.add_face(face).unwrap_err();
        assert!(error.to_string().contains(needle), "{face:?}: {error}");
        assert_eq!(mesh, before);
    }
    // A vertex with every side taken: close a fan of four triangles around vertex 4 of a
    // 2 × 2 grid, then try to add one more face at it.
    let soup = grid(2, 2, false, true);
    let order: Vec<usize> = (0..soup.n_faces()).collect();
    let mut full = incremental(&soup, &order).unwrap();
    let before = full.clone();
    let error = full.add_face(&[v(4), v(0), v(8)]).unwrap_err();
    assert!(error.to_string().contains("interior vertex"), "{error}");
    assert_eq!(full, before);
}

#[test]
fn a_face_between_two_fans_relinks_the_patch() {
    // Two triangles touching at vertex 0 only (a pinched vertex), then the triangle that joins
    // them along both of its sides at 0: the patch between them must move to another gap.
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
    ];
    let mut mesh = Mesh::new();
    for p in positions {
        mesh.add_vertex(p).unwrap();
    }
    let v = VertexId;
    mesh.add_face(&[v(0), v(1), v(2)]).unwrap();
    mesh.add_face(&[v(0), v(3), v(4)]).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.valence(v(0)), 4, "both fans are on the one-ring walk");
    mesh.add_face(&[v(0), v(2), v(3)]).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(boundary_cycles(&mesh), vec![vec![0, 4, 3, 2, 1]]);
    let boundary: Vec<HalfedgeId> = mesh.boundary_loops();
    assert_eq!(boundary.len(), 1);
}

#[test]
fn a_face_closing_one_fan_of_a_vertex_with_several_is_refused() {
    // Three triangles touching at vertex 0 only, added face by face, so the one-ring walk links
    // their fans. The triangle 0-6-5 is the back of 0-5-6: it would close that fan into a pillow
    // and leave the other two fans no gap to move to, so no one-ring walk could reach them.
    let mut mesh = Mesh::new();
    for i in 0..7 {
        let angle = f64::from(i) * 0.8;
        mesh.add_vertex([angle.cos(), angle.sin(), 0.0]).unwrap();
    }
    let v = VertexId;
    for face in [[0, 1, 2], [0, 3, 4], [0, 5, 6]] {
        mesh.add_face(&face.map(v)).unwrap();
    }
    assert_eq!(
        mesh.valence(v(0)),
        6,
        "the three fans are on the one-ring walk"
    );
    let before = mesh.clone();
    let error = mesh.add_face(&[v(0), v(6), v(5)]).unwrap_err();
    assert!(error.to_string().contains("complex vertex"), "{error}");
    assert_eq!(mesh, before);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Grids (open or closed, triangles or quads), faces added in a random order.
    #[test]
    fn random_face_orders_reach_the_bulk_topology(
        columns in 3u32..7,
        rows in 3u32..7,
        closed in any::<bool>(),
        triangles in any::<bool>(),
        seed in any::<u64>(),
    ) {
        let soup = grid(columns, rows, closed, triangles);
        let mut order: Vec<usize> = (0..soup.n_faces()).collect();
        let mut state = seed | 1;
        for i in (1..order.len()).rev() {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            order.swap(i, (state % (i as u64 + 1)) as usize);
        }
        let built = incremental(&soup, &order).unwrap();
        assert_same_topology(&built, &bulk(&soup));
    }

    /// Random faces thrown at a partly built grid: each is either added (and the mesh stays
    /// valid) or refused (and the mesh is unchanged).
    #[test]
    fn refusals_leave_the_mesh_unchanged(
        prefix in 0usize..18,
        attempts in proptest::collection::vec(proptest::collection::vec(0u32..20, 0..6), 1..24),
    ) {
        let soup = grid(3, 3, false, true);
        let order: Vec<usize> = (0..prefix).collect();
        let mut mesh = incremental(&soup, &order).unwrap();
        for attempt in attempts {
            let face: Vec<VertexId> = attempt.into_iter().map(VertexId).collect();
            let before = mesh.clone();
            match mesh.add_face(&face) {
                Ok(f) => {
                    prop_assert_eq!(mesh.check(), Ok(()));
                    prop_assert_eq!(mesh.face_vertices(f).collect::<Vec<_>>(), face);
                    prop_assert_eq!(mesh.n_faces(), before.n_faces() + 1);
                }
                Err(_) => prop_assert_eq!(&mesh, &before),
            }
        }
    }
}
