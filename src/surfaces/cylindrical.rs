//! Cylindrical surfaces: a polyline swept linearly along a vector, `S(u, v) = P(u) + v·r`,
//! `v ∈ [0, 1]` ("Superficies cilíndricas" in the Granada notes).

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::lattice::{CellFaces, Lattice};
use super::polyline::{checked_direction, checked_polyline, checked_steps};
use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

/// Relative size below which a segment counts as parallel to the sweep: `|s × r| ≤ tol·|s|·|r|`.
const PARALLEL_TOLERANCE: f64 = 1e-12;

/// Parameters of a cylindrical (swept) surface.
#[derive(Clone, Copy, Debug)]
pub struct Sweep<'a> {
    /// The polyline `P(u)` to sweep.
    pub profile: &'a [[f64; 3]],
    /// Join the profile's last point back to its first (a closed curve sweeps a tube).
    pub closed_profile: bool,
    /// The sweep vector `r`: the last row of vertices is the profile moved by `r`.
    pub direction: [f64; 3],
    /// Number of rows of faces along `r` (at least 1).
    pub steps: u32,
    /// Quads or triangles.
    pub faces: CellFaces,
}

/// Sweeps `profile` along `direction`.
///
/// Faces are oriented along `P'(u) × r`: a closed profile running counter-clockwise around `r`
/// (seen from its tip) gives outward-facing faces. The result is open: two boundary loops for a
/// closed profile (a tube, Euler characteristic 0), one for an open profile (a disc, χ = 1).
///
/// # Errors
/// Too few points (2, or 3 for a closed profile), non-finite or coincident consecutive points,
/// a zero or non-finite direction, `steps < 1`, a segment parallel to the direction, or an output
/// too large for `u32` indices.
pub fn cylindrical_surface(sweep: &Sweep<'_>) -> Result<PolygonSoup, SurfaceError> {
    let min_points = if sweep.closed_profile { 3 } else { 2 };
    let profile = checked_polyline("profile", sweep.profile, min_points, sweep.closed_profile)?;
    let direction = checked_direction("direction", sweep.direction)?;
    let steps = checked_steps("steps", sweep.steps, 1)? as usize;
    let segments = if sweep.closed_profile {
        profile.len()
    } else {
        profile.len() - 1
    };
    for segment in 0..segments {
        let along = profile[(segment + 1) % profile.len()] - profile[segment];
        let scale = along.length() * direction.length();
        if along.cross(direction).length() <= PARALLEL_TOLERANCE * scale {
            return Err(SurfaceError::SegmentParallelToSweep { segment });
        }
    }

    let rows = steps + 1;
    let vertices = profile.len().checked_mul(rows);
    let corners = segments
        .checked_mul(steps)
        .and_then(|cells| cells.checked_mul(6));
    ensure_fits(vertices, corners)?;
    let mut out = SoupBuilder::with_capacity(
        profile.len() * rows,
        segments * steps * 2,
        segments * steps * 6,
    )?;
    let mut ids = try_vec_with_capacity(profile.len() * rows, "vertices")?;
    for row in 0..rows {
        let offset = direction * (row as f64 / steps as f64);
        for &p in &profile {
            ids.push(out.vertex(p + offset));
        }
    }
    let lattice = Lattice {
        ids: &ids,
        columns: profile.len(),
        rows,
        wrap_u: sweep.closed_profile,
        wrap_v: false,
    };
    // Every node has its own vertex and no segment is parallel to r, so no cell collapses.
    out.ensure_finite()?;
    lattice
        .push_faces(&mut out, sweep.faces)
        .map_err(|cell| SurfaceError::SegmentParallelToSweep { segment: cell.u })?;
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];

    fn sweep(
        profile: &[[f64; 3]],
        closed: bool,
        direction: [f64; 3],
        steps: u32,
    ) -> Result<PolygonSoup, SurfaceError> {
        cylindrical_surface(&Sweep {
            profile,
            closed_profile: closed,
            direction,
            steps,
            faces: CellFaces::Quads,
        })
    }

    #[test]
    fn closed_square_sweeps_a_tube_of_quads() {
        let soup = sweep(&SQUARE, true, [0.0, 0.0, 2.0], 3).unwrap();
        assert_eq!(soup.positions.len(), 16);
        assert_eq!(soup.n_faces(), 12);
        assert!(soup.face_sizes.iter().all(|&s| s == 4));
        assert_eq!(soup.positions[15], [0.0, 1.0, 2.0]);
    }

    #[test]
    fn faces_point_along_tangent_cross_direction() {
        let soup = sweep(&SQUARE, true, [0.0, 0.0, 1.0], 1).unwrap();
        // First face spans the segment from (0,0,0) to (1,0,0): its outside is -y.
        let p: Vec<glam::DVec3> = soup.indices[..4]
            .iter()
            .map(|&i| glam::DVec3::from_array(soup.positions[i as usize]))
            .collect();
        let normal = (p[1] - p[0]).cross(p[2] - p[0]);
        assert!(normal.y < 0.0 && normal.x.abs() < 1e-12 && normal.z.abs() < 1e-12);
    }

    #[test]
    fn bad_parameters_are_typed_errors() {
        assert_eq!(
            sweep(&SQUARE[..1], false, [0.0, 0.0, 1.0], 1),
            Err(SurfaceError::TooFewPoints {
                what: "profile",
                min: 2,
                got: 1
            })
        );
        assert_eq!(
            sweep(&SQUARE[..2], true, [0.0, 0.0, 1.0], 1),
            Err(SurfaceError::TooFewPoints {
                what: "profile",
                min: 3,
                got: 2
            })
        );
        assert_eq!(
            sweep(&SQUARE, true, [0.0, 0.0, 0.0], 1),
            Err(SurfaceError::ZeroVector { what: "direction" })
        );
        assert_eq!(
            sweep(&SQUARE, true, [f64::NAN, 0.0, 1.0], 1),
            Err(SurfaceError::NonFiniteParameter { what: "direction" })
        );
        assert_eq!(
            sweep(&SQUARE, true, [0.0, 0.0, 1.0], 0),
            Err(SurfaceError::TooFewSteps {
                what: "steps",
                min: 1,
                got: 0
            })
        );
        assert_eq!(
            sweep(&SQUARE, true, [1.0, 0.0, 0.0], 1),
            Err(SurfaceError::SegmentParallelToSweep { segment: 0 })
        );
        let nan = [[0.0, 0.0, 0.0], [f64::NAN, 0.0, 0.0]];
        assert_eq!(
            sweep(&nan, false, [0.0, 0.0, 1.0], 1),
            Err(SurfaceError::NonFinitePoint {
                what: "profile",
                index: 1
            })
        );
        let repeated = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
        assert_eq!(
            sweep(&repeated, true, [0.0, 0.0, 1.0], 1),
            Err(SurfaceError::CoincidentPoints {
                what: "profile",
                first: 2,
                second: 0
            })
        );
    }
}
