//! Ruled surfaces between two polylines with the same number of points:
//! `S(u, v) = (1 − v)·C₁(u) + v·C₂(u)`, `v ∈ [0, 1]` ("Superficies regladas" in the Granada notes).

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::lattice::{CellFaces, Lattice};
use super::polyline::{checked_polyline, checked_steps};
use crate::soup::PolygonSoup;
use crate::support::allocation::try_filled;

/// Parameters of a ruled surface.
#[derive(Clone, Copy, Debug)]
pub struct Ruling<'a> {
    /// The curve `C₁` at `v = 0`.
    pub first: &'a [[f64; 3]],
    /// The curve `C₂` at `v = 1`, with as many points as `first`.
    pub second: &'a [[f64; 3]],
    /// Join both curves' last points back to their first (gives a band without side boundaries).
    pub closed: bool,
    /// Rows of faces between the curves (at least 1).
    pub steps: u32,
    /// Quads or triangles.
    pub faces: CellFaces,
}

/// Builds the ruled surface joining `first[i]` to `second[i]` with straight rulings.
///
/// Faces are oriented along `C₁'(u) × (C₂ − C₁)`. Where a ruling has zero length
/// (`first[i] == second[i]`) its points are one vertex, and the cells beside it are triangles.
///
/// # Errors
/// Different point counts, too few points (2, or 3 when closed), non-finite or coincident
/// consecutive points, `steps < 1`, a cell collapsing to a line (two adjacent zero-length
/// rulings), or an output too large for `u32` indices.
pub fn ruled_surface(ruling: &Ruling<'_>) -> Result<PolygonSoup, SurfaceError> {
    if ruling.first.len() != ruling.second.len() {
        return Err(SurfaceError::MismatchedPolylines {
            first: ruling.first.len(),
            second: ruling.second.len(),
        });
    }
    let min_points = if ruling.closed { 3 } else { 2 };
    let first = checked_polyline("first polyline", ruling.first, min_points, ruling.closed)?;
    let second = checked_polyline("second polyline", ruling.second, min_points, ruling.closed)?;
    let steps = checked_steps("steps", ruling.steps, 1)? as usize;

    let n = first.len();
    let rows = steps + 1;
    let vertices = n.checked_mul(rows);
    let corners = n.checked_mul(steps).and_then(|cells| cells.checked_mul(6));
    ensure_fits(vertices, corners)?;
    let mut out = SoupBuilder::with_capacity(n * rows, 0, n * steps * 6)?;
    let mut ids = try_filled(n * rows, 0u32, "vertices")?;
    for i in 0..n {
        let (a, b) = (first[i], second[i]);
        if a == b {
            let apex = out.vertex(a);
            (0..rows).for_each(|row| ids[row * n + i] = apex);
        } else {
            for row in 0..rows {
                let t = row as f64 / steps as f64;
                // Exact endpoints at both curves, so the input points appear verbatim.
                let p = if row == steps { b } else { a.lerp(b, t) };
                ids[row * n + i] = out.vertex(p);
            }
        }
    }
    let lattice = Lattice {
        ids: &ids,
        columns: n,
        rows,
        wrap_u: ruling.closed,
        wrap_v: false,
    };
    out.ensure_finite()?;
    lattice
        .push_faces(&mut out, ruling.faces)
        .map_err(|cell| SurfaceError::DegenerateCell { segment: cell.u })?;
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rule(
        first: &[[f64; 3]],
        second: &[[f64; 3]],
        closed: bool,
        steps: u32,
    ) -> Result<PolygonSoup, SurfaceError> {
        ruled_surface(&Ruling {
            first,
            second,
            closed,
            steps,
            faces: CellFaces::Quads,
        })
    }

    #[test]
    fn interpolates_rows_between_the_curves() {
        let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let b = [[0.0, 2.0, 1.0], [1.0, 2.0, 0.0], [2.0, 2.0, -1.0]];
        let soup = rule(&a, &b, false, 2).unwrap();
        assert_eq!((soup.positions.len(), soup.n_faces()), (9, 4));
        assert_eq!(
            soup.positions[1],
            [0.0, 1.0, 0.5],
            "vertices go ruling by ruling"
        );
        assert_eq!(soup.positions[8], b[2]);
    }

    #[test]
    fn zero_length_rulings_weld_into_one_vertex() {
        let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let b = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
        let soup = rule(&a, &b, false, 3).unwrap();
        assert_eq!(soup.positions.len(), 1 + 4 + 1);
        assert_eq!(soup.n_faces(), 6);
        assert!(soup.face_sizes.iter().all(|&s| s == 3));
        let flat = rule(&a, &a, false, 1);
        assert_eq!(flat, Err(SurfaceError::DegenerateCell { segment: 0 }));
    }

    #[test]
    fn bad_parameters_are_typed_errors() {
        let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
        let b = [[0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0]];
        assert_eq!(
            rule(&a, &b, false, 1),
            Err(SurfaceError::MismatchedPolylines {
                first: 2,
                second: 3
            })
        );
        assert_eq!(
            rule(&a, &b[..2], false, 0),
            Err(SurfaceError::TooFewSteps {
                what: "steps",
                min: 1,
                got: 0
            })
        );
        assert_eq!(
            rule(&a, &b[..2], true, 1),
            Err(SurfaceError::TooFewPoints {
                what: "first polyline",
                min: 3,
                got: 2
            })
        );
        let inf = [[0.0, 1.0, 0.0], [f64::INFINITY, 1.0, 0.0]];
        assert_eq!(
            rule(&a, &inf, false, 1),
            Err(SurfaceError::NonFinitePoint {
                what: "second polyline",
                index: 1
            })
        );
    }
}
