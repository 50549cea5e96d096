//! Tori of revolution about the z axis.

use std::f64::consts::TAU;

use glam::DVec3;

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::lattice::{CellFaces, Lattice};
use super::polyline::{checked_length, checked_steps};
use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

/// Parameters of a torus centred at the origin with the z axis as its axis.
#[derive(Clone, Copy, Debug)]
pub struct Torus {
    /// Distance from the centre to the centre of the tube.
    pub major_radius: f64,
    /// Radius of the tube; smaller than `major_radius`.
    pub minor_radius: f64,
    /// Segments around the z axis (at least 3).
    pub major_steps: u32,
    /// Segments around the tube (at least 3).
    pub minor_steps: u32,
    /// Quads or triangles.
    pub faces: CellFaces,
}

/// Builds a closed genus-1 torus, CCW from outside: `major_steps·minor_steps` vertices.
///
/// # Errors
/// Radii not finite or not positive, a minor radius not below the major one, fewer than 3 steps
/// either way, or an output too large for `u32` indices.
pub fn torus(t: &Torus) -> Result<PolygonSoup, SurfaceError> {
    let major = checked_length("major_radius", t.major_radius)?;
    let minor = checked_length("minor_radius", t.minor_radius)?;
    if minor >= major {
        return Err(SurfaceError::SelfIntersectingTorus { major, minor });
    }
    let columns = checked_steps("major_steps", t.major_steps, 3)? as usize;
    let rows = checked_steps("minor_steps", t.minor_steps, 3)? as usize;
    let vertices = columns.checked_mul(rows);
    ensure_fits(vertices, vertices.and_then(|v| v.checked_mul(6)))?;

    let mut out =
        SoupBuilder::with_capacity(columns * rows, columns * rows * 2, columns * rows * 6)?;
    let mut ids = try_vec_with_capacity(columns * rows, "vertices")?;
    for row in 0..rows {
        let (sin_v, cos_v) = (TAU * row as f64 / rows as f64).sin_cos();
        for column in 0..columns {
            let (sin_u, cos_u) = (TAU * column as f64 / columns as f64).sin_cos();
            let ring = major + minor * cos_v;
            ids.push(out.vertex(DVec3::new(ring * cos_u, ring * sin_u, minor * sin_v)));
        }
    }
    // u around z and v around the tube make ∂S/∂u × ∂S/∂v point out of the tube.
    let lattice = Lattice {
        ids: &ids,
        columns,
        rows,
        wrap_u: true,
        wrap_v: true,
    };
    out.ensure_finite()?;
    lattice
        .push_faces(&mut out, t.faces)
        .expect("torus lattice nodes are all distinct, so no cell collapses");
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn make(
        major: f64,
        minor: f64,
        steps: u32,
        faces: CellFaces,
    ) -> Result<PolygonSoup, SurfaceError> {
        torus(&Torus {
            major_radius: major,
            minor_radius: minor,
            major_steps: steps,
            minor_steps: steps,
            faces,
        })
    }

    #[test]
    fn quads_and_triangles_share_the_vertices() {
        let quads = make(2.0, 0.5, 8, CellFaces::Quads).unwrap();
        let triangles = make(2.0, 0.5, 8, CellFaces::Triangles).unwrap();
        assert_eq!(quads.positions, triangles.positions);
        assert_eq!(
            (quads.positions.len(), quads.n_faces(), triangles.n_faces()),
            (64, 64, 128)
        );
    }

    #[test]
    fn rejects_bad_parameters() {
        assert_eq!(
            make(1.0, 1.0, 8, CellFaces::Quads),
            Err(SurfaceError::SelfIntersectingTorus {
                major: 1.0,
                minor: 1.0
            })
        );
        assert_eq!(
            make(1.0, 0.5, 2, CellFaces::Quads),
            Err(SurfaceError::TooFewSteps {
                what: "major_steps",
                min: 3,
                got: 2
            })
        );
        assert_eq!(
            make(f64::INFINITY, 0.5, 8, CellFaces::Quads),
            Err(SurfaceError::NonFiniteParameter {
                what: "major_radius"
            })
        );
    }
}
