//! Every class of bad input gets a clear status, a complete diagnostic, and never a panic.

use halfwing::mesh::{
    BuildError, BuildPolicy, EdgeId, FaceId, HalfedgeId, HandleError, Mesh, VertexId,
};
use halfwing::soup::{FaceList, FaceSizes, ListProblem};

const SQUARE: [[f64; 3]; 5] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.5, 0.5, 1.0],
];

fn polygons(
    sizes: &[u32],
    indices: &[u32],
    policy: BuildPolicy,
) -> Result<(Mesh, halfwing::soup::Diagnostic), BuildError> {
    Mesh::from_face_list(&FaceList::polygons(&SQUARE, sizes, indices), policy)
}

#[test]
fn empty_input_is_an_empty_mesh() {
    let (mesh, diagnostic) =
        Mesh::from_face_list(&FaceList::triangles(&[], &[]), BuildPolicy::Strict).unwrap();
    assert_eq!(
        (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
        (0, 0, 0)
    );
    assert!(diagnostic.is_clean());
    assert_eq!(mesh.check(), Ok(()));
    assert!(mesh.to_soup().indices.is_empty());

    let (mesh, diagnostic) = polygons(&[], &[], BuildPolicy::Strict).unwrap();
    assert_eq!(mesh.n_vertices(), 5);
    assert_eq!(diagnostic.isolated_vertices, vec![0, 1, 2, 3, 4]);
    assert_eq!(mesh.valence(VertexId(0)), 0);
    assert!(mesh.is_boundary_vertex(VertexId(0)));
}

#[test]
fn faces_with_one_or_two_corners_are_refused_or_skipped() {
    for sizes in [[1u32, 3], [2, 3], [0, 3]] {
        let indices: Vec<u32> = [0u32, 1, 0, 1, 2]
            .iter()
            .copied()
            .skip(2 - sizes[0] as usize)
            .collect();
        let error = polygons(&sizes, &indices, BuildPolicy::Strict).unwrap_err();
        assert!(matches!(error, BuildError::InvalidInput(_)));
        assert_eq!(error.diagnostic().faces_too_small, vec![0]);
        // Repair keeps every face it can, so it accepts all Skip accepts.
        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
            let (mesh, diagnostic) = polygons(&sizes, &indices, policy).unwrap();
            assert_eq!(mesh.n_faces(), 1);
            assert_eq!(diagnostic.faces_too_small, vec![0]);
            assert_eq!(diagnostic.skipped_faces, vec![0]);
            assert_eq!(mesh.check(), Ok(()));
        }
    }
}

#[test]
fn out_of_range_indices_are_named() {
    let indices = [0, 1, 2, 0, 2, 5, 0, 2, u32::MAX];
    let error = polygons(&[3, 3, 3], &indices, BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_out_of_range, vec![1, 2]);
    assert!(error.to_string().contains("out-of-range"), "{error}");
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, diagnostic) = polygons(&[3, 3, 3], &indices, policy).unwrap();
        assert_eq!(mesh.n_faces(), 1);
        assert_eq!(diagnostic.faces_out_of_range, vec![1, 2]);
        assert_eq!(diagnostic.skipped_faces, vec![1, 2]);
    }
}

#[test]
fn repeated_vertices_are_refused_skipped_or_repaired() {
    // Face 0 repeats 1 consecutively; face 1 names 0 twice apart (a pinched pentagon).
    let sizes = [4, 5];
    let indices = [0, 1, 1, 2, 0, 2, 3, 0, 4];
    let error = polygons(&sizes, &indices, BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().faces_repeated_vertex, vec![0, 1]);
    let (mesh, diagnostic) = polygons(&sizes, &indices, BuildPolicy::Skip).unwrap();
    assert_eq!(mesh.n_faces(), 0);
    assert_eq!(diagnostic.skipped_faces, vec![0, 1]);
    let (mesh, diagnostic) = polygons(&sizes, &indices, BuildPolicy::Repair).unwrap();
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.n_faces(), 2);
    assert_eq!(mesh.face_degree(FaceId(0)), 3);
    assert_eq!(mesh.face_degree(FaceId(1)), 5);
    assert_eq!(diagnostic.vertex_copies, vec![0]);
    assert_eq!(mesh.position(VertexId(5)), SQUARE[0]);
}

#[test]
fn non_finite_coordinates_are_reported() {
    let mut positions = SQUARE;
    positions[2] = [f64::NAN, 0.0, f64::INFINITY];
    let list = FaceList::triangles(&positions, &[0, 1, 2, 0, 2, 3]);
    let error = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().non_finite_vertices, vec![2]);
    // Non-finite coordinates never enter a mesh: the faces on them are left out, the vertex
    // is there as a deleted one.
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, diagnostic) = Mesh::from_face_list(&list, policy).unwrap();
        assert_eq!(mesh.n_faces(), 0);
        assert_eq!(diagnostic.non_finite_vertices, vec![2]);
        assert_eq!(diagnostic.skipped_faces, vec![0, 1]);
        assert!(mesh.is_vertex_deleted(VertexId(2)));
        assert_eq!(mesh.n_vertices(), 4);
        assert_eq!(mesh.check(), Ok(()));
    }
}

#[test]
fn counts_beyond_32_bits_are_refused_without_allocating() {
    let sizes = [u32::MAX, u32::MAX, u32::MAX];
    let error = polygons(&sizes, &[0, 1, 2], BuildPolicy::Repair).unwrap_err();
    assert_eq!(
        error.diagnostic().list_problem,
        Some(ListProblem::CornerCountMismatch {
            expected: 3 * u64::from(u32::MAX),
            actual: 3
        })
    );
    let list = FaceList {
        positions: &SQUARE,
        sizes: FaceSizes::Uniform(u32::MAX),
        indices: &[0, 1, 2],
    };
    let error = Mesh::from_face_list(&list, BuildPolicy::Skip).unwrap_err();
    assert!(matches!(
        error.diagnostic().list_problem,
        Some(ListProblem::RaggedUniform { .. })
    ));
    assert!(error.to_string().contains("do not split"), "{error}");
}

#[test]
fn non_manifold_edges_follow_the_policy() {
    // Three triangles on edge 0-1 ("a book"), the third one reusing direction 0→1.
    let indices = [0, 1, 2, 1, 0, 3, 0, 1, 4];
    let error = polygons(&[3, 3, 3], &indices, BuildPolicy::Strict).unwrap_err();
    assert!(matches!(error, BuildError::NonManifold(_)));
    let edge = &error.diagnostic().non_manifold_edges[0];
    assert_eq!(
        (edge.vertices, edge.faces.as_slice()),
        ([0, 1], &[0, 1, 2][..])
    );

    let (mesh, diagnostic) = polygons(&[3, 3, 3], &indices, BuildPolicy::Skip).unwrap();
    assert_eq!(diagnostic.skipped_faces, vec![2]);
    assert_eq!(mesh.n_faces(), 2);
    assert_eq!(mesh.check(), Ok(()));

    let (mesh, diagnostic) = polygons(&[3, 3, 3], &indices, BuildPolicy::Repair).unwrap();
    assert_eq!(mesh.n_faces(), 3);
    assert_eq!(diagnostic.vertex_copies, vec![0, 1]);
    assert_eq!(diagnostic.non_manifold_edges.len(), 1);
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(
        mesh.face_vertices(FaceId(2)).collect::<Vec<_>>(),
        [VertexId(5), VertexId(6), VertexId(4)]
    );
}

#[test]
fn inconsistent_orientation_follows_the_policy() {
    let indices = [0, 1, 2, 0, 2, 3, 2, 3, 4];
    let error = polygons(&[3, 3, 3], &indices, BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().inconsistent_edges[0].vertices, [2, 3]);
    assert_eq!(error.diagnostic().inconsistent_edges[0].faces, vec![1, 2]);
    let (mesh, diagnostic) = polygons(&[3, 3, 3], &indices, BuildPolicy::Skip).unwrap();
    assert_eq!(
        (mesh.n_faces(), diagnostic.skipped_faces.as_slice()),
        (2, &[2][..])
    );
    // Repair reverses the odd face out instead of cutting the surface.
    let (mesh, diagnostic) = polygons(&[3, 3, 3], &indices, BuildPolicy::Repair).unwrap();
    assert_eq!(mesh.n_faces(), 3);
    assert_eq!(diagnostic.reoriented_faces, vec![2]);
    assert!(diagnostic.vertex_copies.is_empty());
    assert_eq!(mesh.n_edges(), 7);
    assert_eq!(mesh.check(), Ok(()));
}

#[test]
fn non_manifold_vertices_are_refused_or_split() {
    // Two triangles touching only at vertex 0 (a bow tie).
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [-1.0, -1.0, 0.0],
    ];
    let list = FaceList::triangles(&positions, &[0, 1, 2, 0, 3, 4]);
    let error = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap_err();
    assert!(matches!(error, BuildError::NonManifold(_)));
    assert_eq!(error.diagnostic().non_manifold_vertices, vec![0]);
    for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
        let (mesh, diagnostic) = Mesh::from_face_list(&list, policy).unwrap();
        assert_eq!(diagnostic.non_manifold_vertices, vec![0]);
        assert_eq!(
            diagnostic.vertex_copies,
            vec![0],
            "the second fan gets vertex 5"
        );
        assert_eq!(mesh.check(), Ok(()));
        assert_eq!(mesh.valence(VertexId(0)) + mesh.valence(VertexId(5)), 4);
        assert_eq!(mesh.position(VertexId(5)), positions[0]);
        let loops = mesh.boundary_loops();
        assert_eq!(loops.len(), 2);
        assert!(loops.iter().all(|&h| mesh.halfedge_loop(h).count() == 3));
    }

    // Two closed tetrahedra sharing one apex (an hourglass): no boundary to link the fans.
    let mut positions = positions.to_vec();
    positions.extend([[0.0, 0.0, 1.0], [2.0, 2.0, 2.0]]);
    let tetrahedra = [
        0, 2, 1, 0, 1, 5, 1, 2, 5, 2, 0, 5, 0, 3, 4, 0, 4, 6, 4, 3, 6, 3, 0, 6,
    ];
    let list = FaceList::triangles(&positions, &tetrahedra);
    let error = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap_err();
    assert_eq!(error.diagnostic().non_manifold_vertices, vec![0]);
    let (mesh, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Skip).unwrap();
    assert_eq!(diagnostic.non_manifold_vertices, vec![0]);
    assert_eq!(diagnostic.vertex_copies, vec![0]);
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.valence(VertexId(0)), 3);
    assert_eq!(mesh.valence(VertexId(7)), 3);
    assert!(mesh.boundary_loops().is_empty());
    assert_eq!(mesh.connected_components().count, 2);
}

#[test]
fn degenerate_and_isolated_elements_are_reported() {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [9.0, 9.0, 9.0],
    ];
    let list = FaceList::triangles(&positions, &[0, 1, 2, 0, 2, 3]);
    let (_, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
    assert_eq!(diagnostic.degenerate_faces, vec![0]);
    assert_eq!(diagnostic.isolated_vertices, vec![4]);
    assert!(diagnostic.summary().contains("degenerate"));
}

#[test]
fn invalid_ids_give_errors_not_panics() {
    let (mesh, _) = polygons(&[3], &[0, 1, 2], BuildPolicy::Strict).unwrap();
    assert!(matches!(
        mesh.try_next(HalfedgeId::INVALID),
        Err(HandleError::OutOfRange { .. })
    ));
    assert!(mesh.try_next(HalfedgeId(6)).is_err());
    assert!(mesh.try_origin(HalfedgeId(5)).is_ok());
    assert!(mesh.try_vertex_halfedge(VertexId(5)).is_err());
    assert!(mesh.try_face_halfedge(FaceId(1)).is_err());
    assert!(mesh.try_edge_halfedge(EdgeId(3), 0).is_err());
    assert!(mesh.try_valence(VertexId(u32::MAX)).is_err());
    assert_eq!(mesh.try_is_boundary_face(FaceId(0)), Ok(true));
    assert_eq!(mesh.outgoing_halfedges(VertexId(99)).count(), 0);
    assert_eq!(mesh.face_loop(FaceId(99)).count(), 0);
    assert_eq!(mesh.halfedge_loop(HalfedgeId::INVALID).count(), 0);
}
