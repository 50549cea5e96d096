//! Zero-area faces, which every builder reports (checked during its face walk).

use crate::geom::{is_degenerate_polygon, is_degenerate_quad, is_degenerate_triangle};

/// `true` when the face with corners `face` has negligible area (see
/// [`is_degenerate_polygon`]; non-finite positions are not degenerate but non-finite, reported
/// apart); triangles and quads unrolled.
#[inline(always)]
pub(crate) fn is_degenerate_face(face: &[u32], positions: &[[f64; 3]]) -> bool {
    match *face {
        [a, b, c] => is_degenerate_triangle(
            positions[a as usize],
            positions[b as usize],
            positions[c as usize],
        ),
        [a, b, c, d] => is_degenerate_quad(
            positions[a as usize],
            positions[b as usize],
            positions[c as usize],
            positions[d as usize],
        ),
        ref face => is_degenerate_polygon(face.iter().map(|&v| positions[v as usize])),
    }
}
