//! Triangulation of non-convex, degenerate and self-intersecting polygons, and of whole meshes.

use glam::{DQuat, DVec3};
use halfwing::render::*;
use halfwing::soup::FaceList;
use halfwing::surfaces::{CellFaces, Torus, cube, torus};
use proptest::prelude::*;

fn planar(points: &[[f64; 2]]) -> Vec<[f64; 3]> {
    points.iter().map(|p| [p[0], p[1], 0.0]).collect()
}

/// Newell normal: twice the polygon's vector area.
fn newell(corners: &[[f64; 3]]) -> DVec3 {
    let p: Vec<DVec3> = corners.iter().map(|c| DVec3::from_array(*c)).collect();
    (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum()
}

/// Checks n − 2 triangles of distinct corners, none inverted, every corner used, and triangle
/// areas adding up to the polygon's area.
fn assert_exact_triangulation(corners: &[[f64; 3]]) -> Vec<[u32; 3]> {
    let (triangles, outcome) = triangulate_polygon(corners);
    assert_eq!(outcome, PolygonOutcome::Exact);
    assert_eq!(triangles.len(), corners.len() - 2);
    let normal = newell(corners);
    let unit = normal.normalize();
    let mut total = 0.0;
    let mut used = vec![false; corners.len()];
    for t in &triangles {
        assert!(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "{t:?}");
        let p = t.map(|k| DVec3::from_array(corners[k as usize]));
        let signed = (p[1] - p[0]).cross(p[2] - p[0]).dot(unit) / 2.0;
        assert!(
            signed >= -1e-12 * normal.length(),
            "inverted triangle {t:?}: {signed}"
        );
        total += signed;
        t.iter().for_each(|&k| used[k as usize] = true);
    }
    assert!(used.iter().all(|&u| u), "a corner is missing");
    let area = normal.length() / 2.0;
    assert!(
        (total - area).abs() <= 1e-9 * area,
        "triangles cover {total}, polygon has {area}"
    );
    triangles
}

fn l_shape() -> Vec<[f64; 3]> {
    planar(&[
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ])
}

fn star(points: usize, outer: f64, inner: f64) -> Vec<[f64; 3]> {
    (0..2 * points)
        .map(|i| {
            let r = if i % 2 == 0 { outer } else { inner };
            let (s, c) = (std::f64::consts::PI * i as f64 / points as f64).sin_cos();
            [r * c, r * s, 0.0]
        })
        .collect()
}

/// A comb with `teeth` narrow teeth standing on a bar: deeply non-convex.
fn comb(teeth: usize) -> Vec<[f64; 3]> {
    // Along the bar, then up and down every tooth from right to left.
    let mut p = vec![[0.0, 0.0], [2.0 * teeth as f64 - 1.0, 0.0]];
    for t in (0..teeth).rev() {
        let x = 2.0 * t as f64;
        p.push([x + 1.0, 5.0]);
        p.push([x, 5.0]);
        if t > 0 {
            p.push([x, 1.0]);
            p.push([x - 1.0, 1.0]);
        }
    }
    planar(&p)
}

#[test]
fn l_shape_star_and_comb_are_covered_exactly() {
    assert_exact_triangulation(&l_shape());
    assert_exact_triangulation(&star(5, 1.0, 0.4));
    assert_exact_triangulation(&star(40, 3.0, 0.1));
    let c = comb(6);
    assert_eq!(c.len(), 4 * 6);
    assert_exact_triangulation(&c);
}

#[test]
fn clockwise_and_tilted_polygons_keep_their_winding() {
    let mut reversed = l_shape();
    reversed.reverse();
    assert_exact_triangulation(&reversed);
    let rotation = DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 2.1);
    let tilted: Vec<[f64; 3]> = comb(4)
        .iter()
        .map(|p| (rotation * DVec3::from_array(*p) + DVec3::new(10.0, -3.0, 7.0)).to_array())
        .collect();
    assert_exact_triangulation(&tilted);
}

#[test]
fn collinear_and_repeated_corners_stay_in_the_triangulation() {
    // A square with a T-junction corner on every side and one corner repeated.
    let square = planar(&[
        [0.0, 0.0],
        [1.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [2.0, 2.0],
        [2.0, 2.0],
        [1.0, 2.0],
        [0.0, 2.0],
        [0.0, 1.0],
    ]);
    let (triangles, outcome) = triangulate_polygon(&square);
    assert_eq!(outcome, PolygonOutcome::Exact);
    assert_eq!(triangles.len(), square.len() - 2);
    let area: f64 = triangles
        .iter()
        .map(|t| {
            let p = t.map(|k| DVec3::from_array(square[k as usize]));
            (p[1] - p[0]).cross(p[2] - p[0]).z / 2.0
        })
        .sum();
    assert!((area - 4.0).abs() < 1e-12);
    let without_repeat: Vec<[f64; 3]> = square
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != 5)
        .map(|(_, p)| *p)
        .collect();
    assert_exact_triangulation(&without_repeat);
}

#[test]
fn degenerate_polygons_fall_back_to_a_reported_fan() {
    let collinear = planar(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]);
    assert_eq!(
        triangulate_polygon(&collinear),
        (
            vec![[0, 1, 2], [0, 2, 3]],
            PolygonOutcome::Fallback(FallbackReason::ZeroArea)
        )
    );
    let bowtie = planar(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
    assert_eq!(
        triangulate_polygon(&bowtie).1,
        PolygonOutcome::Fallback(FallbackReason::ZeroArea)
    );
    let mut nan = l_shape();
    nan[3][1] = f64::NAN;
    let (triangles, outcome) = triangulate_polygon(&nan);
    assert_eq!(
        (triangles.len(), outcome),
        (4, PolygonOutcome::Fallback(FallbackReason::NonFinite))
    );
    assert_eq!(
        triangulate_polygon(&nan[..2]),
        (vec![], PolygonOutcome::TooFewCorners)
    );
}

#[test]
fn overflowing_coordinates_fan_instead_of_panicking() {
    let huge: Vec<[f64; 3]> = l_shape()
        .iter()
        .map(|p| [p[0] * 1e300, p[1] * 1e300, 0.0])
        .collect();
    let (triangles, outcome) = triangulate_polygon(&huge);
    assert_eq!(triangles.len(), 4);
    assert_eq!(outcome, PolygonOutcome::Fallback(FallbackReason::ZeroArea));
}

#[test]
fn self_intersecting_polygons_still_give_n_minus_2_triangles() {
    // A figure eight with lobes of different sizes: non-zero area, no triangulation without an inverted triangle.
    let eight = planar(&[
        [0.0, 0.0],
        [3.0, 3.0],
        [3.0, 0.0],
        [0.0, 3.0],
        [-1.0, 4.0],
        [-1.0, -1.0],
    ]);
    let (triangles, outcome) = triangulate_polygon(&eight);
    assert_eq!(triangles.len(), 4);
    assert_eq!(
        outcome,
        PolygonOutcome::Fallback(FallbackReason::SelfIntersecting)
    );
}

#[test]
fn same_polygon_same_triangles() {
    let c = comb(5);
    assert_eq!(triangulate_polygon(&c), triangulate_polygon(&c));
}

#[test]
fn meshes_become_index_buffers_with_source_faces() {
    let soup = cube(1.0).unwrap();
    let buffer = triangulate_faces(&soup.as_face_list()).unwrap();
    assert_eq!(buffer.n_triangles(), 12);
    assert_eq!(buffer.indices.len(), 36);
    assert_eq!(
        buffer.source_faces,
        (0..6).flat_map(|f| [f, f]).collect::<Vec<u32>>()
    );
    assert!(buffer.fallbacks.is_empty() && buffer.skipped_faces.is_empty());
    for (k, &corner) in buffer.corners.iter().enumerate() {
        assert_eq!(soup.indices[corner as usize], buffer.indices[k]);
    }
    let t = torus(&Torus {
        major_radius: 2.0,
        minor_radius: 0.5,
        major_steps: 12,
        minor_steps: 8,
        faces: CellFaces::Quads,
    })
    .unwrap();
    assert_eq!(
        triangulate_faces(&t.as_face_list()).unwrap().n_triangles(),
        2 * 96
    );
}

#[test]
fn mixed_and_degenerate_faces_are_reported_per_face() {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [2.0, 0.0, 0.0],
    ];
    let sizes = [3, 2, 4, 4];
    let indices = [0, 1, 2, 0, 1, 0, 1, 2, 3, 0, 1, 4, 1];
    let buffer = triangulate_faces(&FaceList::polygons(&positions, &sizes, &indices)).unwrap();
    assert_eq!(buffer.source_faces, vec![0, 2, 2, 3, 3]);
    assert_eq!(buffer.skipped_faces, vec![1]);
    assert_eq!(buffer.fallbacks, vec![(3, FallbackReason::ZeroArea)]);
}

#[test]
fn malformed_face_lists_are_typed_errors() {
    let positions = [[0.0; 3]; 3];
    let bad_index = FaceList::triangles(&positions, &[0, 1, 3]);
    assert_eq!(
        triangulate_faces(&bad_index),
        Err(TriangulateError::IndexOutOfRange {
            face: 0,
            corner: 2,
            vertex: 3,
            vertices: 3
        })
    );
    let ragged = FaceList::triangles(&positions, &[0, 1, 2, 0]);
    assert_eq!(
        triangulate_faces(&ragged),
        Err(TriangulateError::UniformSizeMismatch { size: 3, got: 4 })
    );
    let short = FaceList::polygons(&positions, &[3, 3], &[0, 1, 2]);
    assert_eq!(
        triangulate_faces(&short),
        Err(TriangulateError::CornerCountMismatch {
            expected: 6,
            got: 3
        })
    );
}

proptest! {
    /// Polygons through random radii at sorted random angles, with every angular gap below π,
    /// are star-shaped about the origin, hence simple: they must always be triangulated exactly.
    #[test]
    fn random_star_shaped_polygons_are_triangulated_exactly(
        mut angles in prop::collection::vec(0.0f64..std::f64::consts::TAU, 3..40),
        radii in prop::collection::vec(0.05f64..10.0, 40),
    ) {
        angles.sort_by(f64::total_cmp);
        angles.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
        prop_assume!(angles.len() >= 3);
        let wrap_gap = std::f64::consts::TAU - (angles.last().unwrap() - angles[0]);
        let widest_gap = angles.windows(2).map(|w| w[1] - w[0]).fold(wrap_gap, f64::max);
        prop_assume!(widest_gap < std::f64::consts::PI - 1e-3 && wrap_gap > 1e-3);
        let polygon: Vec<[f64; 3]> = angles.iter().zip(&radii).map(|(a, r)| [r * a.cos(), r * a.sin(), 0.0]).collect();
        prop_assume!(newell(&polygon).length() > 1e-6);
        assert_exact_triangulation(&polygon);
    }
}
