//! Zero-area faces, which every builder reports: checked during its face walk when the walk runs
//! alone, or in a pass of their own beside it when a second thread is free.

use super::FaceTable;
use crate::geom::{is_degenerate_polygon, is_degenerate_quad, is_degenerate_triangle};

/// The degenerate faces of a table as input face indices, ascending, found face by face.
pub(crate) struct DegenerateFaces<'p> {
    positions: &'p [[f64; 3]],
    faces: Vec<u32>,
}

impl<'p> DegenerateFaces<'p> {
    /// None found yet, for the faces of a table whose vertices are at `positions`.
    pub(crate) fn new(positions: &'p [[f64; 3]]) -> Self {
        DegenerateFaces {
            positions,
            faces: Vec::new(),
        }
    }

    /// Checks table face `f`, whose vertices are `corners` (faces are checked in order).
    #[inline(always)]
    pub(crate) fn check(&mut self, table: &FaceTable<'_>, f: usize, corners: &[u32]) {
        if is_degenerate_face(corners, self.positions) {
            self.faces.push(table.input_face(f));
        }
    }

    /// The degenerate faces of all of `table`.
    pub(crate) fn of_table(table: &FaceTable<'_>, positions: &'p [[f64; 3]]) -> Vec<u32> {
        let mut found = DegenerateFaces::new(positions);
        for (f, corners) in table.faces().enumerate() {
            found.check(table, f, corners);
        }
        found.faces
    }

    /// The faces found.
    pub(crate) fn into_faces(self) -> Vec<u32> {
        self.faces
    }
}

/// `true` when the face with corners `face` has negligible area (see
/// [`is_degenerate_polygon`]; non-finite positions are not degenerate but non-finite, reported
/// apart); triangles and quads unrolled.
#[inline(always)]
fn is_degenerate_face(face: &[u32], positions: &[[f64; 3]]) -> bool {
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
