//! Editing operators: direct cases, and random edit sequences that must keep every invariant,
//! leave the mesh untouched when refused, and survive compaction.

mod mesh_support;
#[path = "../benches/common/polygons.rs"]
mod polygons;

use halfwing::mesh::{BuildPolicy, EdgeId, EditError, FaceId, HalfedgeId, Mesh, VertexId};
use halfwing::soup::FaceList;
use halfwing::winged::Winged;
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
    let diagonal = (0..mesh.n_edge_slots() as u32)
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
    let boundary = (0..mesh.n_edge_slots() as u32)
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
    assert_eq!(mesh.n_vertex_slots(), v);
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
        for h in (0..built.n_halfedge_slots() as u32).map(HalfedgeId) {
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
    let edge = |i: u32, mesh: &Mesh| EdgeId(i % mesh.n_edge_slots().max(1) as u32);
    let face = |i: u32, mesh: &Mesh| FaceId(i % mesh.n_face_slots().max(1) as u32);
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
            let h = HalfedgeId(h % mesh.n_halfedge_slots().max(1) as u32);
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
    let positions = polygons::comb(teeth);
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

/// A quad 0-1-2-3 closed into a pillow by triangles 0-2-1 and 0-3-2: its diagonal 0-2 is an
/// edge already. The quad's corners start at `start`.
fn pillow(start: u32) -> Mesh {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let quad = (0..4).map(|k| (start + k) % 4);
    let indices: Vec<u32> = quad.chain([0, 2, 1, 0, 3, 2]).collect();
    let list = FaceList::polygons(&positions, &[4, 3, 3], &indices);
    Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0
}

/// Whether an edge joins `u` and `v` (either way round).
fn joined(mesh: &Mesh, u: VertexId, v: VertexId) -> bool {
    mesh.find_halfedge(u, v).is_some() || mesh.find_halfedge(v, u).is_some()
}

/// Before: the quad was cut along the render triangulation's diagonal or refused when that was
/// the pillow's edge 0-2 (from 2 of the 4 start corners). Now the other diagonal is cut.
#[test]
fn triangulating_a_face_avoids_a_diagonal_that_is_an_edge_already() {
    for start in 0..4 {
        let mut mesh = pillow(start);
        let faces = mesh.triangulate_face(FaceId(0)).unwrap();
        assert_eq!(faces.len(), 2, "start {start}");
        assert_eq!(mesh.check(), Ok(()), "start {start}");
        assert!(joined(&mesh, VertexId(1), VertexId(3)), "start {start}");
        assert_eq!(mesh.n_edges(), 6, "start {start}");
    }
}

/// A face that goes round a path of two struts, made with Euler operators and converted: its
/// loop is `v0 → v1 → v2 → v1 → v0`, visiting `v1` twice.
fn strut_face() -> Mesh {
    let mut w = Winged::new();
    let (v0, f) = w.mvfs([0.0, 0.0, 0.0]).unwrap();
    let (_, v1) = w.mev(f, v0, [1.0, 0.0, 0.0]).unwrap();
    w.mev(f, v1, [1.0, 1.0, 0.0]).unwrap();
    let mesh = w.to_mesh().unwrap();
    assert_eq!(mesh.face_degree(FaceId(0)), 4);
    mesh
}

/// Before: the face was cut from one corner of `v1` to the other, an edge from `v1` to itself
/// (which `Mesh::check` then took for two edges joining the same vertices).
#[test]
fn triangulating_a_face_joins_no_vertex_to_itself() {
    let mut mesh = strut_face();
    mesh.triangulate_face(FaceId(0)).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert!(joined(&mesh, VertexId(0), VertexId(2)));
}

/// Before: accepted, giving an edge from `v1` to itself.
#[test]
fn splitting_a_face_between_two_corners_of_one_vertex_is_refused() {
    let mut mesh = strut_face();
    let before = mesh.clone();
    let into_v1: Vec<HalfedgeId> = mesh
        .face_loop(FaceId(0))
        .filter(|&h| mesh.target(h) == VertexId(1))
        .collect();
    let error = mesh.split_face(into_v1[0], into_v1[1]).unwrap_err();
    assert!(error.to_string().contains("one vertex"), "{error}");
    assert_eq!(mesh, before);
}

/// Splitting the pillow's quad along its edge 0-2 is refused, the mesh unchanged.
#[test]
fn splitting_along_an_existing_edge_is_refused() {
    let mut mesh = pillow(0);
    let before = mesh.clone();
    let into: Vec<HalfedgeId> = mesh.face_loop(FaceId(0)).collect();
    let at = |v: u32| {
        *into
            .iter()
            .find(|&&h| mesh.target(h) == VertexId(v))
            .unwrap()
    };
    let error = mesh.split_face(at(0), at(2)).unwrap_err();
    assert!(error.to_string().contains("already joined"), "{error}");
    assert_eq!(mesh, before);
}

/// Faces of trees of struts and the faces cut off them (random Euler operators), converted:
/// loops that visit vertices several times. Triangulating any of them keeps every invariant or
/// is refused with the mesh unchanged.
#[test]
fn triangulating_faces_that_visit_vertices_twice_keeps_the_mesh_valid() {
    let mut state = 12_345u64;
    let mut below = |n: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as usize
    };
    let (mut cut, mut refused) = (0, 0);
    for _ in 0..300 {
        let mut w = Winged::new();
        let (v0, _) = w.mvfs([0.0, 0.0, 0.0]).unwrap();
        let mut vertices = vec![v0];
        for _ in 0..3 + below(8) {
            let f = halfwing::winged::FaceId(below(w.n_face_slots() as usize) as u32);
            let v = vertices[below(vertices.len())];
            if below(2) == 0 {
                let at = [below(9) as f64 - 4.0, below(9) as f64 - 4.0, 0.0];
                if let Ok((_, new)) = w.mev(f, v, at) {
                    vertices.push(new);
                }
            } else {
                let _ = w.mef(f, v, vertices[below(vertices.len())]);
            }
        }
        // MEF may join two vertices joined already: no mesh has such a second edge.
        let Ok(mesh) = w.to_mesh() else { continue };
        for f in (0..mesh.n_face_slots() as u32).map(FaceId) {
            let mut edited = mesh.clone();
            match edited.triangulate_face(f) {
                Ok(_) => {
                    assert_eq!(edited.check(), Ok(()));
                    cut += 1;
                }
                Err(_) => {
                    assert_eq!(edited, mesh);
                    refused += 1;
                }
            }
        }
    }
    // Both ways are taken (a tree's face of no area is tried as fans only, which often fail).
    assert!(cut > 0 && refused > 0, "{cut} cut, {refused} refused");
}
