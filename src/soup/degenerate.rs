//! Zero-area faces of a resolved face table, reported by every builder.

use super::FaceTable;
use crate::geom::{is_degenerate_polygon, is_degenerate_triangle};

/// Input indices of the faces whose area is negligible (non-finite positions are not degenerate
/// but non-finite, reported apart).
pub fn degenerate_faces(table: &FaceTable<'_>, positions: &[[f64; 3]]) -> Vec<u32> {
    let is_degenerate = |f: usize| is_degenerate_face(table.face(f), positions);
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        (0..table.n_faces())
            .into_par_iter()
            .with_min_len(4096)
            .filter(|&f| is_degenerate(f))
            .map(|f| table.input_face(f))
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..table.n_faces())
            .filter(|&f| is_degenerate(f))
            .map(|f| table.input_face(f))
            .collect()
    }
}

/// `true` when the face with corners `face` has negligible area (see
/// [`is_degenerate_polygon`]); triangles and quads unrolled.
#[inline(always)]
pub(crate) fn is_degenerate_face(face: &[u32], positions: &[[f64; 3]]) -> bool {
    match *face {
        [a, b, c] => is_degenerate_triangle(
            positions[a as usize],
            positions[b as usize],
            positions[c as usize],
        ),
        [a, b, c, d] => is_degenerate_polygon([a, b, c, d].map(|v| positions[v as usize])),
        ref face => is_degenerate_polygon(face.iter().map(|&v| positions[v as usize])),
    }
}
