//! Filled and outlined polygons from a list of 2D or 3D polygons — the cells of a Voronoi
//! diagram, or any set of regions. Each polygon owns its corners (neighbours do not share
//! vertices), so each can get its own colour from [`PolygonBuffer::vertex_polygons`].

use crate::geom::newell_vector;
use crate::soup::{FaceList, FaceSizes};
use crate::support::allocation::ensure_room;

use super::error::RenderError;
use super::line_buffer::push_point;
use super::triangulate::corner_ranges;
use super::{Bounds, FallbackReason, LineBuffer, triangulate_faces};

/// Polygons given corner after corner: polygon `i` has `sizes[i]` consecutive corners of
/// `corners`, counter-clockwise seen from the side it is looked at (from +z for 2D polygons).
#[derive(Clone, Copy, Debug)]
pub struct PolygonList<'a> {
    /// Corner positions, polygon after polygon.
    pub corners: &'a [[f64; 3]],
    /// Corners per polygon; they must add up to `corners.len()`.
    pub sizes: &'a [u32],
}

/// Fill triangles and outlines of a polygon list.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonBuffer {
    /// x y z per corner (z = 0 for 2D input): the fill's vertex array.
    pub positions: Vec<f32>,
    /// Unit nx ny nz per corner: its polygon's Newell normal (+z for counter-clockwise 2D
    /// polygons; zero for polygons without area), so fills can be lit like a mesh.
    pub normals: Vec<f32>,
    /// Per corner, the polygon it belongs to (for per-polygon colours).
    pub vertex_polygons: Vec<u32>,
    /// Three corner indices per fill triangle (non-convex polygons work too).
    pub triangles: Vec<u32>,
    /// Per triangle, its polygon.
    pub triangle_polygons: Vec<u32>,
    /// Every polygon's sides; the source of each segment is its polygon.
    pub outline: LineBuffer,
    /// Polygons whose triangles may not cover them exactly.
    pub fallbacks: Vec<(u32, FallbackReason)>,
    /// Box around the corners.
    pub bounds: Bounds,
}

/// Triangulates and outlines every polygon.
///
/// # Errors
/// [`RenderError::Polygons`] when the sizes do not add up to the number of corners or the
/// triangles would not fit `u32` indices; [`RenderError::TooFewCorners`] for a polygon of fewer
/// than 3 corners and [`RenderError::NonFiniteCorner`] for a NaN or infinite corner, both naming
/// the first such polygon.
pub fn polygon_buffer(polygons: &PolygonList<'_>) -> Result<PolygonBuffer, RenderError> {
    check_polygons(polygons)?;
    build_polygon_buffer(polygons)
}

/// Refuses what a caller's polygon list must not hold: sizes that do not add up, polygons that
/// cannot have an area, and corners that are not points.
fn check_polygons(polygons: &PolygonList<'_>) -> Result<(), RenderError> {
    let ranges = corner_ranges(FaceSizes::PerFace(polygons.sizes), polygons.corners.len())?;
    for (polygon, range) in ranges.into_iter().enumerate() {
        if range.len() < 3 {
            return Err(RenderError::TooFewCorners {
                polygon,
                corners: polygons.sizes[polygon],
            });
        }
        let ring = &polygons.corners[range];
        if let Some(corner) = ring.iter().position(|p| p.iter().any(|c| !c.is_finite())) {
            return Err(RenderError::NonFiniteCorner {
                polygon,
                corner,
                point: ring[corner],
            });
        }
    }
    Ok(())
}

/// [`polygon_buffer`] without the checks, for lists that may hold empty polygons on purpose (a
/// Voronoi diagram's cells, one per site). Polygons of fewer than 3 corners get no fill (a
/// 2-corner polygon is still outlined as a segment there and back, which is what it is).
pub(super) fn build_polygon_buffer(
    polygons: &PolygonList<'_>,
) -> Result<PolygonBuffer, RenderError> {
    let n = polygons.corners.len();
    // Per corner, at most: its triangle corners and their polygons (16 bytes), its vertex
    // (position, normal, polygon: 52) and the triangulation's work (12).
    const BYTES_PER_CORNER: u64 = 80;
    ensure_room(n as u64 * BYTES_PER_CORNER, n, "corners")?;
    let identity: Vec<u32> =
        (0..u32::try_from(n).map_err(|_| super::TriangulateError::TooLarge)?).collect();
    let triangulated = triangulate_faces(&FaceList::polygons(
        polygons.corners,
        polygons.sizes,
        &identity,
    ))?;

    let mut buffer = PolygonBuffer {
        triangles: triangulated.indices,
        triangle_polygons: triangulated.source_faces,
        fallbacks: triangulated.fallbacks,
        positions: Vec::with_capacity(3 * n),
        normals: Vec::with_capacity(3 * n),
        vertex_polygons: Vec::with_capacity(n),
        ..PolygonBuffer::default()
    };
    let mut start = 0usize;
    for (polygon, &size) in polygons.sizes.iter().enumerate() {
        let ring = &polygons.corners[start..start + size as usize];
        let normal = unit(newell_vector(ring.iter().copied()));
        for (k, &corner) in ring.iter().enumerate() {
            push_point(&mut buffer.positions, corner);
            push_point(&mut buffer.normals, normal);
            buffer.vertex_polygons.push(polygon as u32);
            if ring.len() >= 2 {
                buffer
                    .outline
                    .push(corner, ring[(k + 1) % ring.len()], polygon as u32);
            }
        }
        start += size as usize;
    }
    buffer.bounds = Bounds::of_points(&buffer.positions);
    Ok(buffer)
}

/// `v` scaled to unit length, or zero when it has none (or is not finite).
fn unit(v: [f64; 3]) -> [f64; 3] {
    let length = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    if length > 0.0 && length.is_finite() {
        v.map(|c| c / length)
    } else {
        [0.0; 3]
    }
}

/// [`polygon_buffer`] for polygons in the plane z = 0, given by x y.
///
/// # Errors
/// As [`polygon_buffer`].
pub fn polygon_buffer_2d(
    corners: &[[f64; 2]],
    sizes: &[u32],
) -> Result<PolygonBuffer, RenderError> {
    polygon_buffer(&PolygonList {
        corners: &lift_to_plane(corners),
        sizes,
    })
}

/// Points of the plane z = 0 from their x y.
pub(super) fn lift_to_plane(corners: &[[f64; 2]]) -> Vec<[f64; 3]> {
    corners.iter().map(|&[x, y]| [x, y, 0.0]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::TriangulateError;

    #[test]
    fn two_cells_fill_and_outline() {
        // A square and an L-shaped hexagon beside it.
        let corners = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [1.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [2.0, 1.0],
            [2.0, 2.0],
            [1.0, 2.0],
        ];
        let buffer = polygon_buffer_2d(&corners, &[4, 6]).unwrap();
        assert_eq!(buffer.positions.len(), 30);
        assert!(buffer.positions.chunks_exact(3).all(|p| p[2] == 0.0));
        assert!(buffer.normals.chunks_exact(3).all(|n| n == [0.0, 0.0, 1.0]));
        assert_eq!(buffer.vertex_polygons, vec![0, 0, 0, 0, 1, 1, 1, 1, 1, 1]);
        assert_eq!(buffer.triangle_polygons, vec![0, 0, 1, 1, 1, 1]);
        assert!(buffer.fallbacks.is_empty());
        // Each triangle uses corners of its own polygon only.
        for (t, &polygon) in buffer
            .triangles
            .chunks_exact(3)
            .zip(&buffer.triangle_polygons)
        {
            assert!(
                t.iter()
                    .all(|&c| buffer.vertex_polygons[c as usize] == polygon)
            );
        }
        assert_eq!(buffer.outline.n_segments(), 10);
        // The hexagon's last side closes it: from (1, 2) back to (1, 0).
        assert_eq!(
            &buffer.outline.positions[54..60],
            &[1.0, 2.0, 0.0, 1.0, 0.0, 0.0]
        );
        assert_eq!(buffer.bounds.max, [3.0, 2.0, 0.0]);
    }

    #[test]
    fn degenerate_polygons_and_non_finite_corners_are_refused() {
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 0.0]];
        assert_eq!(
            polygon_buffer_2d(&corners, &[3, 2]),
            Err(RenderError::TooFewCorners {
                polygon: 1,
                corners: 2
            })
        );
        assert_eq!(
            polygon_buffer_2d(&corners, &[0, 5]),
            Err(RenderError::TooFewCorners {
                polygon: 0,
                corners: 0
            })
        );
        let mut with_nan = corners;
        with_nan[4][1] = f64::NAN;
        match polygon_buffer_2d(&with_nan, &[5]) {
            Err(RenderError::NonFiniteCorner {
                polygon: 0,
                corner: 4,
                ..
            }) => {}
            other => panic!("NaN corner accepted: {other:?}"),
        }
        let mut with_infinity = corners;
        with_infinity[0][0] = f64::INFINITY;
        assert!(matches!(
            polygon_buffer_2d(&with_infinity, &[5]),
            Err(RenderError::NonFiniteCorner { corner: 0, .. })
        ));
    }

    #[test]
    fn sizes_must_match_the_corners() {
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
        assert_eq!(
            polygon_buffer_2d(&corners, &[4]),
            Err(RenderError::Polygons(
                TriangulateError::CornerCountMismatch {
                    expected: 4,
                    got: 3
                }
            ))
        );
    }
}
