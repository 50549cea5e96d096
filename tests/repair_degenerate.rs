//! The mesh repairs of degenerate triangles and T-vertices (`remove_degenerate_faces`,
//! `remove_t_vertices`): constructed cases with the exact elements each must change, bad input
//! (refused, mesh unchanged), every face degenerate, empty meshes, every test model, and their
//! properties: the mesh stays valid, counts follow the report, a second run changes nothing,
//! clean input is left as it is.

mod mesh_support;

use halfwing::mesh::{BuildPolicy, HalfedgeId, Mesh};
use halfwing::repair::{
    RepairError, RepairOptions, Tolerance, remove_degenerate_faces, remove_t_vertices, repair_mesh,
    stitch_borders,
};
use halfwing::soup::PolygonSoup;
use mesh_support::grid;
use mesh_support::soups::{lattice_soup, test_models};
use proptest::prelude::*;

/// A soup of triangles on `positions`, each corner's uv its corner index.
fn triangles(positions: Vec<[f64; 3]>, indices: Vec<u32>) -> PolygonSoup {
    PolygonSoup {
        positions,
        face_sizes: vec![3; indices.len() / 3],
        corner_uvs: Some((0..indices.len()).map(|c| [c as f64, 0.0]).collect()),
        indices,
        corner_normals: None,
    }
}

fn built(soup: &PolygonSoup) -> Mesh {
    Mesh::from_soup(soup, BuildPolicy::Strict).unwrap().0
}

/// The faces of `mesh` as vertex lists, each starting at its lowest vertex.
fn faces(mesh: &Mesh) -> Vec<Vec<u32>> {
    let soup = mesh.to_soup();
    let mut first = 0;
    soup.face_sizes
        .iter()
        .map(|&size| {
            let mut face = soup.indices[first..first + size as usize].to_vec();
            first += size as usize;
            let lowest = (0..face.len()).min_by_key(|&i| face[i]).unwrap();
            face.rotate_left(lowest);
            face
        })
        .collect()
}

fn boundary_edges(mesh: &Mesh) -> usize {
    (0..mesh.n_halfedge_slots() as u32)
        .map(HalfedgeId)
        .filter(|&h| !mesh.is_halfedge_deleted(h) && mesh.is_boundary_halfedge(h))
        .count()
}

/// Whether some triangle of `soup` has its corners exactly on one line (checked with
/// rationals-free reasoning on small-integer lattices: the cross product is exact there).
fn has_collinear_triangle(soup: &PolygonSoup) -> bool {
    let mut first = 0;
    soup.face_sizes.iter().any(|&size| {
        let corners = &soup.indices[first..first + size as usize];
        first += size as usize;
        if let &[a, b, c] = corners {
            let [a, b, c] = [a, b, c].map(|v| soup.positions[v as usize]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let cross = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            cross == [0.0; 3]
        } else {
            false
        }
    })
}

/// An octahedron whose vertex 6 is a second copy of vertex 0's position, taking the place of
/// vertex 0 in the faces around it but one, joined to 0 by a zero-length edge: closed, with two
/// triangles of zero area.
fn octahedron_with_zero_length_edge() -> PolygonSoup {
    let positions = vec![
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, -1.0],
        [0.0, 0.0, 1.0],
    ];
    // Top fan around the apex, split between 0 and 6: 0–1–2, 0–2–3 keep 0; 6–3–4, 6–4–1 use 6;
    // the two slivers 0–3–6 and 0–6–1 close the gap.
    let indices = vec![
        0, 1, 2, 0, 2, 3, 6, 3, 4, 6, 4, 1, 0, 3, 6, 0, 6, 1, 5, 2, 1, 5, 3, 2, 5, 4, 3, 5, 1, 4,
    ];
    triangles(positions, indices)
}

#[test]
fn a_zero_length_edge_collapses_into_its_lower_end_and_the_surface_stays_closed() {
    let soup = octahedron_with_zero_length_edge();
    let mut mesh = built(&soup);
    assert_eq!(boundary_edges(&mesh), 0);
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.merged_vertices, vec![[6, 0]]);
    assert_eq!(report.removed_vertices, vec![6]);
    assert_eq!(report.removed_faces, vec![4, 5]);
    assert!(report.flipped_faces.is_empty());
    assert_eq!(mesh.n_vertices(), 6);
    assert_eq!(mesh.n_faces(), 8);
    assert_eq!(boundary_edges(&mesh), 0);
    // The faces that named 6 now name 0; each kept corner keeps its uv.
    let result = mesh.to_soup();
    assert_eq!(
        faces(&mesh),
        vec![
            vec![0, 1, 2],
            vec![0, 2, 3],
            vec![0, 3, 4],
            vec![0, 4, 1],
            vec![1, 5, 2],
            vec![2, 5, 3],
            vec![3, 5, 4],
            vec![1, 4, 5],
        ]
    );
    let uvs = result.corner_uvs.unwrap();
    let mut kept_uvs: Vec<f64> = uvs.iter().map(|uv| uv[0]).collect();
    kept_uvs.sort_by(f64::total_cmp);
    let expected: Vec<f64> = (0..30)
        .filter(|c| !(12..18).contains(c))
        .map(f64::from)
        .collect();
    assert_eq!(kept_uvs, expected);
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

/// A cap 0–1–2 (2 in the middle of 0–1) and the triangle 1–0–3 across its long edge.
fn cap_and_neighbour() -> PolygonSoup {
    triangles(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, -1.0, 0.0],
        ],
        vec![0, 1, 2, 1, 0, 3],
    )
}

#[test]
fn a_cap_is_flipped_with_the_triangle_across_its_long_edge() {
    let mut mesh = built(&cap_and_neighbour());
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.flipped_faces, vec![[0, 1]]);
    assert!(report.removed_faces.is_empty());
    assert!(report.merged_vertices.is_empty());
    // d c a and c d b: 3 2 0 and 2 3 1.
    assert_eq!(faces(&mesh), vec![vec![0, 3, 2], vec![1, 2, 3]]);
    assert!(!has_collinear_triangle(&mesh.to_soup()));
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn a_cap_on_the_boundary_is_removed_and_its_vertices_stay() {
    let mut mesh = built(&triangles(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
        ],
        vec![0, 2, 1, 2, 3, 1, 0, 3, 2],
    ));
    // Face 0 (0 2 1) has its long edge 1–0 on the boundary: no flip, removed.
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.removed_faces, vec![0]);
    assert!(report.flipped_faces.is_empty());
    assert_eq!(report.maps.faces, vec![u32::MAX, 0, 1]);
    assert_eq!(mesh.n_vertices(), 4);
    assert_eq!(faces(&mesh), vec![vec![1, 2, 3], vec![0, 3, 2]]);
}

#[test]
fn a_tolerance_mends_nearly_degenerate_triangles_only() {
    let mut soup = cap_and_neighbour();
    soup.positions[2] = [1.0, 1e-4, 0.0];
    let mut exact = built(&soup);
    assert!(
        remove_degenerate_faces(&mut exact, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    let mut near = built(&soup);
    assert!(
        remove_degenerate_faces(&mut near, Tolerance::Absolute(5e-5))
            .unwrap()
            .is_empty()
    );
    let report = remove_degenerate_faces(&mut near, Tolerance::Absolute(1e-3)).unwrap();
    assert_eq!(report.flipped_faces, vec![[0, 1]]);
    near.check().unwrap();
    // Relative: 1e-3 of the diagonal (√5) is above the height 1e-4.
    let mut relative = built(&soup);
    let report = remove_degenerate_faces(&mut relative, Tolerance::Relative(1e-3)).unwrap();
    assert_eq!(report.flipped_faces, vec![[0, 1]]);
    // A short edge within the tolerance collapses: 2 at 1e-4 from 0.
    soup.positions[2] = [1e-4, 0.0, 0.0];
    let mut short = built(&soup);
    let report = remove_degenerate_faces(&mut short, Tolerance::Absolute(1e-3)).unwrap();
    short.check().unwrap();
    assert_eq!(report.merged_vertices, vec![[2, 0]]);
    assert_eq!(report.removed_faces, vec![0]);
    assert_eq!(faces(&short), vec![vec![0, 2, 1]]);
}

#[test]
fn bad_tolerances_are_refused_and_leave_the_mesh_unchanged() {
    let original = built(&octahedron_with_zero_length_edge());
    for tolerance in [
        Tolerance::Absolute(-1.0),
        Tolerance::Absolute(f64::NAN),
        Tolerance::Absolute(f64::INFINITY),
        Tolerance::Relative(-0.5),
        Tolerance::Relative(2.0),
        Tolerance::Relative(f64::NAN),
    ] {
        let mut mesh = original.clone();
        let error = remove_degenerate_faces(&mut mesh, tolerance).unwrap_err();
        assert!(matches!(error, RepairError::BadTolerance { .. }), "{error}");
        assert_eq!(mesh, original);
        let error = remove_t_vertices(&mut mesh, tolerance).unwrap_err();
        assert!(matches!(error, RepairError::BadTolerance { .. }), "{error}");
        assert_eq!(mesh, original);
    }
}

#[test]
fn a_huge_tolerance_makes_every_face_degenerate_and_leaves_a_valid_mesh() {
    for soup in [
        grid(6, 5, true, true),
        grid(4, 4, false, true),
        octahedron_with_zero_length_edge(),
    ] {
        let mut mesh = built(&soup);
        let report = remove_degenerate_faces(&mut mesh, Tolerance::Absolute(1e300)).unwrap();
        mesh.check().unwrap();
        assert_eq!(mesh.n_faces(), soup.n_faces() - report.removed_faces.len());
        assert_eq!(
            mesh.n_vertices(),
            soup.positions.len() - report.removed_vertices.len()
        );
        // Every triangle was degenerate under that tolerance: none is left.
        assert_eq!(mesh.n_faces(), 0);
        let again = remove_degenerate_faces(&mut mesh, Tolerance::Absolute(1e300)).unwrap();
        assert!(again.is_empty());
    }
}

#[test]
fn a_closed_surface_with_every_vertex_on_one_line_is_emptied_validly() {
    // A tetrahedron squashed onto the x axis: every face has zero area.
    let soup = triangles(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
        ],
        vec![0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3],
    );
    let mut mesh = built(&soup);
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert!(!has_collinear_triangle(&mesh.to_soup()));
    assert_eq!(report.removed_faces.len() + mesh.n_faces(), 4);
    assert_eq!(mesh.n_faces(), 0);
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn empty_meshes_change_nothing() {
    let mut mesh = Mesh::new();
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::Relative(0.5))
            .unwrap()
            .is_empty()
    );
    assert!(
        remove_t_vertices(&mut mesh, Tolerance::Relative(0.5))
            .unwrap()
            .is_empty()
    );
    assert_eq!(mesh, Mesh::new());
}

/// Triangle 0 2 1 below the edge 0–1, and above it two triangles meeting at 3, the middle of
/// 0–1 (`lift` above it), and at 4: a T-junction at 3. Triangles at 5 (left) and 6 (right) join
/// the sides so that the surface is a disk with a crack 0–1–3.
fn t_junction(lift: f64) -> PolygonSoup {
    triangles(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, -1.0, 0.0],
            [1.0, lift, 0.0],
            [1.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
        ],
        vec![
            0, 2, 1, 0, 3, 4, 3, 1, 4, 2, 0, 5, 5, 0, 4, 1, 2, 6, 4, 1, 6,
        ],
    )
}

#[test]
fn a_t_vertex_splits_the_edge_under_it_and_stitching_closes_the_crack() {
    let mut mesh = built(&t_junction(0.0));
    assert_eq!(boundary_edges(&mesh), 7);
    let report = remove_t_vertices(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.vertex_copies, vec![3]);
    assert_eq!(mesh.n_vertices(), 8);
    assert_eq!(mesh.position(halfwing::mesh::VertexId(7)), [1.0, 0.0, 0.0]);
    // The triangle below gains the corner 7 between 1 and 0.
    assert_eq!(faces(&mesh)[0], vec![0, 2, 1, 7]);
    assert_eq!(boundary_edges(&mesh), 8);
    let stitched = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(stitched.stitched_halfedges.len(), 2);
    assert_eq!(stitched.merged_vertices, vec![[7, 3]]);
    assert_eq!(boundary_edges(&mesh), 4);
    assert_eq!(faces(&mesh)[0], vec![0, 2, 1, 3]);
    assert!(
        remove_t_vertices(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn t_vertices_near_an_edge_need_the_tolerance() {
    let soup = t_junction(1e-7);
    let mut exact = built(&soup);
    assert!(
        remove_t_vertices(&mut exact, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    let mut near = built(&soup);
    let report = remove_t_vertices(&mut near, Tolerance::Absolute(1e-6)).unwrap();
    assert_eq!(report.vertex_copies, vec![3]);
    near.check().unwrap();
    // The new vertex is at the T-vertex's position, so exact stitching closes the crack.
    let stitched = stitch_borders(&mut near, Tolerance::EXACT).unwrap();
    assert_eq!(stitched.stitched_halfedges.len(), 2);
}

#[test]
fn several_t_vertices_split_one_edge_in_order_along_it() {
    // Below: triangle 0 2 1 on the edge 0–1 (length 4); above, a fan around 6 whose lower side
    // runs 0, 5, 3, 4, 1 (vertex ids out of order along the edge); triangles at 7 and 8 join
    // the sides.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [2.0, -1.0, 0.0],
        [2.0, 0.0, 0.0],
        [3.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [2.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [5.0, 0.0, 0.0],
    ];
    let indices = vec![
        0, 2, 1, 0, 5, 6, 5, 3, 6, 3, 4, 6, 4, 1, 6, 2, 0, 7, 7, 0, 6, 1, 2, 8, 6, 1, 8,
    ];
    let mut mesh = built(&triangles(positions, indices));
    let report = remove_t_vertices(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    // Split along 1 → 0 (the boundary half-edge beside the triangle runs 0 → 1, split from 0).
    assert_eq!(report.vertex_copies, vec![5, 3, 4]);
    assert_eq!(faces(&mesh)[0].len(), 6);
    let stitched = stitch_borders(&mut mesh, Tolerance::EXACT).unwrap();
    assert_eq!(stitched.stitched_halfedges.len(), 4);
    mesh.check().unwrap();
    assert_eq!(mesh.n_vertices(), 9);
    assert_eq!(boundary_edges(&mesh), 4);
}

#[test]
fn the_pipeline_mends_degenerate_faces_and_closes_t_junctions() {
    let soup = t_junction(0.0);
    let (mesh, fates) = repair_mesh(&soup, &RepairOptions::default()).unwrap();
    mesh.check().unwrap();
    assert_eq!(fates.split_edges, 1);
    assert_eq!(fates.stitched_edges, 2);
    assert_eq!(fates.counts().added_vertices, 0);
    assert_eq!(boundary_edges(&mesh), 4);
    assert_eq!(mesh.n_vertices(), 7);
    // Turned off, the crack stays.
    let options = RepairOptions {
        t_vertex_tolerance: None,
        ..RepairOptions::default()
    };
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    assert_eq!(fates.split_edges, 0);
    assert_eq!(boundary_edges(&mesh), 7);

    // Exact duplicates merge before the build: a zero-length edge reaches the degenerate step
    // only with a tolerance. The cap of `octahedron_with_cap` reaches it as it is.
    let soup = octahedron_with_cap();
    let (mesh, fates) = repair_mesh(&soup, &RepairOptions::default()).unwrap();
    mesh.check().unwrap();
    assert_eq!(fates.flipped_edges, 1);
    assert_eq!(fates.counts().removed_faces, 0);
    assert_eq!(mesh.n_faces(), 10);
    assert_eq!(boundary_edges(&mesh), 0);
    assert!(!has_collinear_triangle(&mesh.to_soup()));
    let options = RepairOptions {
        degenerate_tolerance: None,
        ..RepairOptions::default()
    };
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    assert_eq!(fates.flipped_edges, 0);
    assert!(has_collinear_triangle(&mesh.to_soup()));

    // A tolerance makes a short edge degenerate: the sliver next to it collapses.
    let mut soup = octahedron_with_zero_length_edge();
    soup.positions[6] = [0.0, 1e-9, 1.0];
    let options = RepairOptions {
        degenerate_tolerance: Some(Tolerance::Absolute(1e-6)),
        ..RepairOptions::default()
    };
    let (mesh, fates) = repair_mesh(&soup, &options).unwrap();
    mesh.check().unwrap();
    let counts = fates.counts();
    assert_eq!(counts.merged_vertices, 1);
    assert_eq!(fates.removed_faces_by_reason(), vec![("degenerate", 2)]);
    assert_eq!(mesh.n_faces(), 8);
    assert_eq!(boundary_edges(&mesh), 0);
}

/// An octahedron whose face 0 1 2 is split at 7, the middle of 1–2, into 0 1 7 and 0 7 2, with
/// the zero-area cap 7 1 2 closing the crack against the face 5 2 1 below: closed.
fn octahedron_with_cap() -> PolygonSoup {
    let mut soup = octahedron_with_zero_length_edge();
    soup.positions[6] = [0.5, 0.5, 0.0];
    triangles(
        soup.positions,
        vec![
            0, 1, 6, 0, 6, 2, 6, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, 5, 2, 1, 5, 3, 2, 5, 4, 3, 5, 1,
            4,
        ],
    )
}

#[test]
fn every_test_model_stays_valid_and_a_second_run_changes_nothing() {
    for (_, path, soup) in test_models() {
        let Ok((mut mesh, _)) = Mesh::from_soup(&soup, BuildPolicy::Repair) else {
            continue;
        };
        let (faces_before, vertices_before) = (mesh.n_faces(), mesh.n_vertices());
        let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
        mesh.check().unwrap_or_else(|e| panic!("{path}: {e}"));
        assert_eq!(mesh.n_faces(), faces_before - report.removed_faces.len());
        assert_eq!(
            mesh.n_vertices(),
            vertices_before - report.removed_vertices.len()
        );
        assert!(
            remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
                .unwrap()
                .is_empty(),
            "{path}"
        );
        let vertices_before = mesh.n_vertices();
        let report = remove_t_vertices(&mut mesh, Tolerance::EXACT).unwrap();
        mesh.check().unwrap_or_else(|e| panic!("{path}: {e}"));
        assert_eq!(
            mesh.n_vertices(),
            vertices_before + report.vertex_copies.len()
        );
        assert!(
            remove_t_vertices(&mut mesh, Tolerance::EXACT)
                .unwrap()
                .is_empty(),
            "{path}"
        );
    }
}

#[test]
fn clean_meshes_are_unchanged() {
    for soup in [
        grid(8, 6, true, true),
        grid(5, 5, false, true),
        grid(5, 5, false, false),
    ] {
        let mut mesh = built(&soup);
        let before = mesh.clone();
        assert!(
            remove_degenerate_faces(&mut mesh, Tolerance::Relative(1e-6))
                .unwrap()
                .is_empty()
        );
        assert!(
            remove_t_vertices(&mut mesh, Tolerance::Relative(1e-6))
                .unwrap()
                .is_empty()
        );
        assert_eq!(mesh, before);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// On random lattice meshes (zero-area triangles and T-junctions are frequent there): the
    /// mesh stays valid, its counts follow the report, no exactly degenerate triangle is left,
    /// and a second run changes nothing.
    #[test]
    fn repairs_keep_meshes_valid_and_are_idempotent(soup in lattice_soup(12)) {
        let Ok((mut mesh, _)) = Mesh::from_soup(&soup, BuildPolicy::Repair) else {
            return Ok(());
        };
        let (faces_before, vertices_before) = (mesh.n_faces(), mesh.n_vertices());
        let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
        prop_assert!(mesh.check().is_ok());
        prop_assert_eq!(mesh.n_faces(), faces_before - report.removed_faces.len());
        prop_assert_eq!(mesh.n_vertices(), vertices_before - report.removed_vertices.len());
        prop_assert!(!has_collinear_triangle(&mesh.to_soup()));
        prop_assert!(remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap().is_empty());

        let vertices_before = mesh.n_vertices();
        let report = remove_t_vertices(&mut mesh, Tolerance::EXACT).unwrap();
        prop_assert!(mesh.check().is_ok());
        prop_assert_eq!(mesh.n_vertices(), vertices_before + report.vertex_copies.len());
        prop_assert!(remove_t_vertices(&mut mesh, Tolerance::EXACT).unwrap().is_empty());

        let (repaired, fates) = repair_mesh(&soup, &RepairOptions::default()).unwrap();
        prop_assert!(repaired.check().is_ok());
        let counts = fates.counts();
        prop_assert_eq!(counts.kept_faces + counts.removed_faces, soup.n_faces());
        prop_assert_eq!(counts.kept_vertices + counts.added_vertices, repaired.n_vertices());
    }
}
