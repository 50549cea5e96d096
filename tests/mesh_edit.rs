//! Editing operators: direct cases, and random edit sequences that must keep every invariant,
//! leave the mesh untouched when refused, and survive compaction.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, EdgeId, EditError, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::soup::FaceList;
use mesh_support::grid;
use proptest::prelude::*;

fn build(soup: &halfwing::soup::PolygonSoup) -> Mesh {
    Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
        .unwrap()
        .0
}

fn euler(mesh: &Mesh) -> i64 {
    mesh.n_vertices() as i64 - mesh.n_edges() as i64 + mesh.n_faces() as i64
}

fn square() -> Mesh {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    Mesh::from_face_list(
        &FaceList::triangles(&positions, &[0, 1, 2, 0, 2, 3]),
        BuildPolicy::Strict,
    )
    .unwrap()
    .0
}

#[test]
fn flipping_the_diagonal_of_a_square() {
    let mut mesh = square();
    let diagonal = (0..mesh.edge_capacity() as u32)
        .map(EdgeId)
        .find(|&e| !mesh.is_boundary_edge(e))
        .unwrap();
    mesh.flip_edge(diagonal).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    let ends = [
        mesh.origin(diagonal.halfedge(0)),
        mesh.target(diagonal.halfedge(0)),
    ];
    assert!(
        ends.contains(&VertexId(1)) && ends.contains(&VertexId(3)),
        "{ends:?}"
    );
    // Boundary edges cannot flip; the mesh is untouched.
    let before = mesh.clone();
    let boundary = (0..mesh.edge_capacity() as u32)
        .map(EdgeId)
        .find(|&e| mesh.is_boundary_edge(e))
        .unwrap();
    assert!(matches!(
        mesh.flip_edge(boundary),
        Err(EditError::Refused { .. })
    ));
    assert!(matches!(
        mesh.flip_edge(EdgeId(99)),
        Err(EditError::Handle(_))
    ));
    assert_eq!(mesh, before);
}

#[test]
fn splitting_and_triangulating_a_quad_face() {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let list = FaceList::polygons(&positions, &[4], &[0, 1, 2, 3]);
    let mut mesh = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0;
    let mut pentagon = mesh.clone();
    let w = pentagon.split_edge(EdgeId(0), [0.5, 0.0, 0.0]).unwrap();
    assert_eq!(pentagon.check(), Ok(()));
    assert_eq!(pentagon.face_degree(FaceId(0)), 5);
    assert_eq!(pentagon.valence(w), 2);
    let faces = pentagon.triangulate_face(FaceId(0)).unwrap();
    assert_eq!(faces.len(), 3);
    assert!(faces.iter().all(|&f| pentagon.face_degree(f) == 3));
    assert_eq!(pentagon.check(), Ok(()));

    let h0 = mesh.face_halfedge(FaceId(0));
    let h2 = mesh.next(mesh.next(h0));
    assert!(mesh.split_face(h0, mesh.next(h0)).is_err());
    let diagonal = mesh.split_face(h0, h2).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!((mesh.n_faces(), mesh.n_edges()), (2, 5));
    assert_eq!(mesh.face_degree(mesh.face(diagonal)), 3);
    assert_eq!(mesh.face_degree(mesh.face(diagonal.twin())), 3);
}

#[test]
fn deleting_faces_and_collecting_garbage() {
    let mut mesh = build(&grid(3, 3, false, false));
    mesh.delete_face(FaceId(4), false).unwrap(); // the middle quad: a hole
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.boundary_loops().len(), 2);
    mesh.delete_face(FaceId(0), true).unwrap(); // a corner quad: its corner vertex goes
    assert_eq!(mesh.check(), Ok(()));
    assert!(mesh.is_vertex_deleted(VertexId(0)));
    assert!(mesh.try_face_halfedge(FaceId(0)).is_err());
    let (v, e, f) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    let maps = mesh.garbage_collect();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(
        (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
        (v, e, f)
    );
    assert_eq!(mesh.vertex_capacity(), v);
    assert_eq!(maps.vertices[0], u32::MAX);
    assert_eq!(maps.vertices[1], 0);
    assert_eq!(maps.faces[..2], [u32::MAX, 0]);
    assert!(!mesh.has_deleted_elements());
}

#[test]
fn collapsing_an_interior_edge_of_a_triangle_grid() {
    let mut mesh = build(&grid(4, 4, false, true));
    let (v, e, f) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    // The edge from the grid's vertex (1, 1) to (2, 1): interior, with two triangles beside it.
    let h = mesh.find_halfedge(VertexId(6), VertexId(7)).unwrap();
    let kept = mesh.collapse_halfedge(h).unwrap();
    assert_eq!(kept, VertexId(7));
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(
        (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
        (v - 1, e - 3, f - 2)
    );
    assert!(mesh.is_vertex_deleted(VertexId(6)));
    // The diagonal of the corner quad at (3, 0) joins boundary vertices 3 and 9 across the
    // interior: collapsing it would pinch the surface, so it is refused and nothing changes.
    let before = mesh.clone();
    let h = mesh.find_halfedge(VertexId(3), VertexId(9)).unwrap();
    assert!(!mesh.is_boundary_edge(h.edge()));
    assert!(matches!(
        mesh.collapse_halfedge(h),
        Err(EditError::Refused { .. })
    ));
    assert_eq!(mesh, before);
    mesh.garbage_collect();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(euler(&mesh), 1);
}

/// Vertices on a circle, alternating in height.
fn circle(n_vertices: u32) -> Vec<[f64; 3]> {
    (0..n_vertices)
        .map(|i| {
            let angle = f64::from(i) * 0.7;
            [angle.cos(), angle.sin(), f64::from(i % 2)]
        })
        .collect()
}

/// Adds `indices` (triangles) face by face over `n_vertices` vertices on a circle, vertex 0
/// ending with several open fans: `add_face` links them through the vertex's boundary
/// half-edges, so its circulation crosses from fan to fan.
fn pinched_at_vertex_0(n_vertices: u32, indices: &[u32]) -> Mesh {
    let mut mesh = Mesh::new();
    for p in circle(n_vertices) {
        mesh.add_vertex(p).unwrap();
    }
    for face in indices.chunks(3) {
        let face: Vec<VertexId> = face.iter().map(|&v| VertexId(v)).collect();
        mesh.add_face(&face).unwrap();
    }
    assert_eq!(mesh.check(), Ok(()));
    let degree = mesh.halfedge_origins().iter().filter(|&&v| v == 0).count();
    assert_eq!(
        mesh.valence(VertexId(0)),
        degree,
        "one cycle through every fan"
    );
    mesh
}

/// Two triangles touching at vertex 0 only (a bow tie).
fn bow_tie() -> Mesh {
    pinched_at_vertex_0(5, &[0, 1, 2, 0, 3, 4])
}

#[test]
fn deleting_a_face_at_a_pinched_vertex_keeps_the_vertex_for_its_other_fan() {
    for delete_isolated_vertices in [false, true] {
        let mut mesh = bow_tie();
        mesh.delete_face(FaceId(0), delete_isolated_vertices)
            .unwrap();
        assert_eq!(mesh.check(), Ok(()));
        assert!(!mesh.is_vertex_deleted(VertexId(0)));
        assert_eq!(
            mesh.vertex_faces(VertexId(0)).collect::<Vec<_>>(),
            [FaceId(1)]
        );
        assert!(mesh.is_boundary_halfedge(mesh.vertex_halfedge(VertexId(0))));
    }
}

#[test]
fn deleting_a_pinched_vertex_deletes_the_faces_of_all_its_fans() {
    let mut mesh = bow_tie();
    mesh.delete_vertex(VertexId(0)).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!((mesh.n_faces(), mesh.n_edges()), (0, 0));
    assert!(mesh.is_vertex_deleted(VertexId(0)));
}

#[test]
fn fans_that_cannot_be_linked_are_built_apart_and_edited_apart() {
    // Vertex 0 is the apex of two cones (closed fans, bases open), then the centre of a closed
    // disk and the corner of a lone triangle: no boundary half-edge can link a closed fan to
    // another, so the builder gives the second fan a copy of the vertex (Strict refuses), and
    // edits at either vertex keep every invariant.
    let cones = [0, 1, 2, 0, 2, 3, 0, 3, 1, 0, 4, 5, 0, 5, 6, 0, 6, 4];
    let disk_and_triangle = [0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1, 0, 6, 7];
    for (n_vertices, indices) in [(7, &cones[..]), (8, &disk_and_triangle[..])] {
        let positions = circle(n_vertices);
        let list = FaceList::triangles(&positions, indices);
        let refusal = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap_err();
        assert_eq!(refusal.diagnostic().non_manifold_vertices, [0]);
        let (built, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Skip).unwrap();
        assert_eq!(diagnostic.vertex_copies, [0]);
        let copy = VertexId(n_vertices);
        for face in (0..built.n_faces() as u32).map(FaceId) {
            let mut mesh = built.clone();
            mesh.delete_face(face, false).unwrap();
            assert_eq!(mesh.check(), Ok(()));
            for v in [VertexId(0), copy] {
                let left = mesh.vertex_faces(v).count();
                if 0 < left && left < built.vertex_faces(v).count() {
                    assert!(mesh.is_boundary_halfedge(mesh.vertex_halfedge(v)));
                }
            }
        }
        for h in (0..built.halfedge_capacity() as u32).map(HalfedgeId) {
            let mut mesh = built.clone();
            let _ = mesh.collapse_halfedge(h);
            assert_eq!(mesh.check(), Ok(()));
        }
    }
}

#[test]
fn collapsing_is_refused_when_the_ends_share_a_pinched_neighbour() {
    // Vertex 0 is the apex of a tetrahedron with its face 0-4-5 open, and the corner of a lone
    // triangle 0-1-2. Collapsing the hole's edge 4 -> 5 would close the tetrahedron into a pillow
    // of two triangles (the ends share neighbour 0 besides the opposite corner 3), whichever of
    // vertex 0's fans its stored half-edge is in.
    let open_tetrahedron = [0, 3, 4, 0, 5, 3, 3, 5, 4];
    let lone_triangle = [0, 1, 2];
    for indices in [
        [lone_triangle.as_slice(), &open_tetrahedron].concat(),
        [open_tetrahedron.as_slice(), &lone_triangle].concat(),
    ] {
        let mut mesh = pinched_at_vertex_0(6, &indices);
        let before = mesh.clone();
        let hole_edge = mesh.find_halfedge(VertexId(4), VertexId(5)).unwrap();
        let error = mesh.collapse_halfedge(hole_edge).unwrap_err();
        assert!(error.to_string().contains("link condition"), "{error}");
        assert_eq!(mesh, before);
    }
}

#[derive(Clone, Debug)]
enum Edit {
    Flip(u32),
    SplitEdge(u32),
    SplitFace(u32, u32, u32),
    Triangulate(u32),
    DeleteFace(u32, bool),
    Collapse(u32),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        any::<u32>().prop_map(Edit::Flip),
        any::<u32>().prop_map(Edit::SplitEdge),
        (any::<u32>(), 0u32..6, 2u32..6).prop_map(|(f, i, j)| Edit::SplitFace(f, i, j)),
        any::<u32>().prop_map(Edit::Triangulate),
        (any::<u32>(), any::<bool>()).prop_map(|(f, d)| Edit::DeleteFace(f, d)),
        any::<u32>().prop_map(Edit::Collapse),
    ]
}

/// Applies `edit` with ids taken modulo the capacities; returns whether it succeeded.
fn apply(mesh: &mut Mesh, edit: &Edit) -> bool {
    let edge = |i: u32, mesh: &Mesh| EdgeId(i % mesh.edge_capacity().max(1) as u32);
    let face = |i: u32, mesh: &Mesh| FaceId(i % mesh.face_capacity().max(1) as u32);
    match *edit {
        Edit::Flip(e) => mesh.flip_edge(edge(e, mesh)).is_ok(),
        Edit::SplitEdge(e) => {
            let e = edge(e, mesh);
            let Ok(a) = mesh.try_origin(e.halfedge(0)) else {
                return false;
            };
            let (pa, pb) = (mesh.position(a), mesh.position(mesh.target(e.halfedge(0))));
            mesh.split_edge(
                e,
                [
                    0.5 * (pa[0] + pb[0]),
                    0.5 * (pa[1] + pb[1]),
                    0.5 * (pa[2] + pb[2]),
                ],
            )
            .is_ok()
        }
        Edit::SplitFace(f, i, j) => {
            let f = face(f, mesh);
            let Ok(start) = mesh.try_face_halfedge(f) else {
                return false;
            };
            let h0 = mesh.halfedge_loop(start).nth(i as usize).unwrap_or(start);
            let h1 = mesh.halfedge_loop(h0).nth(j as usize).unwrap_or(h0);
            mesh.split_face(h0, h1).is_ok()
        }
        Edit::Triangulate(f) => mesh.triangulate_face(face(f, mesh)).is_ok(),
        Edit::DeleteFace(f, isolated) => mesh.delete_face(face(f, mesh), isolated).is_ok(),
        Edit::Collapse(h) => {
            let h = HalfedgeId(h % mesh.halfedge_capacity().max(1) as u32);
            mesh.collapse_halfedge(h).is_ok()
        }
    }
}

proptest! {
    #[test]
    fn random_edits_keep_every_invariant(
        columns in 3u32..7, rows in 3u32..7, closed: bool, triangles: bool,
        edits in prop::collection::vec(edit(), 1..40),
    ) {
        let mut mesh = build(&grid(columns, rows, closed, triangles));
        let mut euler_expected = Some(euler(&mesh));
        for edit in &edits {
            let before = mesh.clone();
            let done = apply(&mut mesh, edit);
            prop_assert_eq!(mesh.check(), Ok(()), "after {:?}", edit);
            if !done {
                prop_assert_eq!(&mesh, &before, "refused {:?} changed the mesh", edit);
            }
            if matches!(edit, Edit::DeleteFace(..)) {
                euler_expected = None;
            }
            if let Some(expected) = euler_expected {
                prop_assert_eq!(euler(&mesh), expected, "after {:?}", edit);
            }
        }
        let counts = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
        mesh.garbage_collect();
        prop_assert_eq!(mesh.check(), Ok(()));
        prop_assert_eq!((mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()), counts);
        // Deleting faces can pinch a vertex (its fans linked through its boundary half-edges);
        // a build splits it instead, one vertex per fan.
        let (rebuilt, diagnostic) =
            Mesh::from_face_list(&mesh.to_soup().as_face_list(), BuildPolicy::Skip).unwrap();
        prop_assert_eq!(rebuilt.check(), Ok(()));
        prop_assert!(diagnostic.skipped_faces.is_empty());
        let (v, e, f) = counts;
        prop_assert_eq!(
            (rebuilt.n_vertices(), rebuilt.n_edges(), rebuilt.n_faces()),
            (v + diagnostic.vertex_copies.len(), e, f)
        );
    }
}

/// Twice the signed area, in the xy plane, of a triangular face.
fn signed_area(mesh: &Mesh, f: FaceId) -> f64 {
    let [a, b, c]: [[f64; 3]; 3] = mesh
        .face_vertices(f)
        .map(|v| mesh.position(v))
        .collect::<Vec<_>>()
        .try_into()
        .unwrap();
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Before: a fan from the first free corner folded the L-shaped hexagon from 4 of its 6 start
/// corners (a triangle of signed area -0.5).
#[test]
fn triangulating_a_non_convex_face_folds_nothing_from_any_start_corner() {
    let l_shape = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]];
    for start in 0..6 {
        let positions: Vec<[f64; 3]> = (0..6)
            .map(|k| {
                let [x, y] = l_shape[(start + k) % 6];
                [f64::from(x), f64::from(y), 0.0]
            })
            .collect();
        let indices: Vec<u32> = (0..6).collect();
        let (mut mesh, _) = Mesh::from_face_list(
            &FaceList::polygons(&positions, &[6], &indices),
            BuildPolicy::Strict,
        )
        .unwrap();
        let faces = mesh.triangulate_face(FaceId(0)).unwrap();
        assert_eq!(faces.len(), 4);
        assert_eq!(mesh.check(), Ok(()));
        let areas: Vec<f64> = faces.iter().map(|&f| signed_area(&mesh, f)).collect();
        assert!(areas.iter().all(|&a| a > 0.0), "start {start}: {areas:?}");
        assert_eq!(areas.iter().sum::<f64>(), 6.0, "start {start}");
    }
}

/// A comb of 1,000 teeth (4,002 corners: a bar [0, 1000] x [0, 1] with teeth of width 0.5 and
/// height 1) is covered exactly, without a folded triangle.
#[test]
fn triangulating_a_comb_covers_it_exactly() {
    let teeth = 1_000u32;
    let mut positions = vec![[0.0, 0.0, 0.0], [f64::from(teeth), 0.0, 0.0]];
    for t in (0..teeth).rev() {
        let x = f64::from(t);
        positions.extend(
            [[x + 1.0, 1.0], [x + 0.5, 1.0], [x + 0.5, 2.0], [x, 2.0]].map(|[x, y]| [x, y, 0.0]),
        );
    }
    let n = positions.len() as u32;
    let indices: Vec<u32> = (0..n).collect();
    let (mut mesh, _) = Mesh::from_face_list(
        &FaceList::polygons(&positions, &[n], &indices),
        BuildPolicy::Strict,
    )
    .unwrap();
    let faces = mesh.triangulate_face(FaceId(0)).unwrap();
    assert_eq!(faces.len(), n as usize - 2);
    assert_eq!(mesh.check(), Ok(()));
    assert!(faces.iter().all(|&f| signed_area(&mesh, f) > 0.0));
    let area: f64 = faces.iter().map(|&f| signed_area(&mesh, f)).sum();
    assert_eq!(area, 3.0 * f64::from(teeth));
}
