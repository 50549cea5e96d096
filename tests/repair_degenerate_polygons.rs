//! `remove_degenerate_faces` on polygons (more than 3 corners): a zero-length edge collapses and
//! the polygons beside it lose a corner (the surface stays closed), pinched and flat polygons are
//! removed, a tolerance catches nearly degenerate ones, and the pipeline reports them like
//! triangles.

use halfwing::mesh::{BuildPolicy, HalfedgeId, Mesh};
use halfwing::repair::{
    FaceFate, Removal, RepairOptions, Tolerance, remove_degenerate_faces, repair_mesh,
};
use halfwing::soup::PolygonSoup;

fn polygons(positions: Vec<[f64; 3]>, faces: &[&[u32]]) -> PolygonSoup {
    PolygonSoup {
        positions,
        face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
        indices: faces.iter().flat_map(|f| f.iter().copied()).collect(),
        corner_normals: None,
        corner_uvs: None,
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
    (0..mesh.halfedge_capacity() as u32)
        .map(HalfedgeId)
        .filter(|&h| !mesh.is_halfedge_deleted(h) && mesh.is_boundary_halfedge(h))
        .count()
}

/// A cube of quads whose top edge 1–2 holds vertex 8 at vertex 1's position (offset by
/// `offset` along the edge): the top and the side across that edge are pentagons.
fn cube_with_extra_corner(offset: f64) -> PolygonSoup {
    let mut positions = vec![
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    positions.push([1.0, offset, 1.0]);
    polygons(
        positions,
        &[
            &[0, 1, 8, 2, 3],
            &[4, 7, 6, 5],
            &[0, 4, 5, 1],
            &[1, 5, 6, 2, 8],
            &[2, 6, 7, 3],
            &[3, 7, 4, 0],
        ],
    )
}

#[test]
fn a_zero_length_edge_between_polygons_collapses_and_the_cube_stays_closed() {
    let soup = cube_with_extra_corner(0.0);
    let mut mesh = built(&soup);
    assert_eq!(boundary_edges(&mesh), 0);
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.merged_vertices, vec![[8, 1]]);
    assert_eq!(report.removed_vertices, vec![8]);
    assert!(report.removed_faces.is_empty());
    assert_eq!(mesh.n_vertices(), 8);
    assert_eq!(boundary_edges(&mesh), 0);
    assert_eq!(
        faces(&mesh),
        vec![
            vec![0, 1, 2, 3],
            vec![4, 7, 6, 5],
            vec![0, 4, 5, 1],
            vec![1, 5, 6, 2],
            vec![2, 6, 7, 3],
            vec![0, 3, 7, 4],
        ]
    );
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn a_short_edge_between_polygons_needs_the_tolerance() {
    let soup = cube_with_extra_corner(1e-9);
    let mut exact = built(&soup);
    assert!(
        remove_degenerate_faces(&mut exact, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    let mut mended = built(&soup);
    let report = remove_degenerate_faces(&mut mended, Tolerance::Absolute(1e-6)).unwrap();
    mended.check().unwrap();
    assert_eq!(report.merged_vertices, vec![[8, 1]]);
    assert!(report.removed_faces.is_empty());
    assert_eq!(mended.n_faces(), 6);
    assert_eq!(boundary_edges(&mended), 0);
}

#[test]
fn a_flat_polygon_is_removed_and_its_neighbour_kept() {
    // Face 0: four corners on the x axis (zero area); face 1 a triangle on its edge 1–0.
    let soup = polygons(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [0.5, 1.0, 0.0],
        ],
        &[&[0, 1, 2, 3], &[1, 0, 4]],
    );
    let mut mesh = built(&soup);
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    mesh.check().unwrap();
    assert_eq!(report.removed_faces, vec![0]);
    assert!(report.merged_vertices.is_empty());
    assert_eq!(report.maps.faces, vec![u32::MAX, 0]);
    assert_eq!(faces(&mesh), vec![vec![0, 4, 1]]);
}

#[test]
fn a_nearly_flat_polygon_needs_the_tolerance() {
    let soup = polygons(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 1e-9, 0.0],
            [3.0, 0.0, 0.0],
            [2.0, -1e-9, 0.0],
        ],
        &[&[0, 1, 2, 3]],
    );
    let mut mesh = built(&soup);
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
    let report = remove_degenerate_faces(&mut mesh, Tolerance::Absolute(1e-6)).unwrap();
    assert_eq!(report.removed_faces, vec![0]);
    assert_eq!(mesh.n_faces(), 0);
    mesh.check().unwrap();
}

#[test]
fn a_pinched_polygon_is_removed() {
    // A hexagon whose corners 2 and 5 are at one position: two lobes touching at a point.
    let soup = polygons(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [2.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
            [1.0, 1.0, 0.0],
        ],
        &[&[0, 1, 2, 3, 4, 5]],
    );
    let mut mesh = built(&soup);
    let report = remove_degenerate_faces(&mut mesh, Tolerance::EXACT).unwrap();
    assert_eq!(report.removed_faces, vec![0]);
    mesh.check().unwrap();
    // A hexagon without repeats stays.
    let mut clean = soup.clone();
    clean.positions[5] = [0.5, 1.0, 0.0];
    let mut mesh = built(&clean);
    assert!(
        remove_degenerate_faces(&mut mesh, Tolerance::EXACT)
            .unwrap()
            .is_empty()
    );
}

/// The pipeline reports a polygon's collapsed corner as a merged vertex and a flat polygon as a
/// removed face, as it does for triangles.
#[test]
fn the_pipeline_reports_degenerate_polygons_like_triangles() {
    let (mesh, fates) =
        repair_mesh(&cube_with_extra_corner(0.0), &RepairOptions::default()).unwrap();
    mesh.check().unwrap();
    assert_eq!(mesh.n_vertices(), 8);
    assert_eq!(mesh.n_faces(), 6);
    let counts = fates.counts();
    assert_eq!(counts.merged_vertices, 1);
    assert_eq!(counts.removed_faces, 0);

    let flat = polygons(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [0.5, 1.0, 0.0],
        ],
        &[&[0, 1, 2, 3], &[1, 0, 4]],
    );
    let (mesh, fates) = repair_mesh(&flat, &RepairOptions::default()).unwrap();
    mesh.check().unwrap();
    assert_eq!(mesh.n_faces(), 1);
    assert_eq!(fates.faces[0], FaceFate::Removed(Removal::Degenerate));
}
