//! Flat rectangular grids.

use glam::DVec3;

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::lattice::{CellFaces, Lattice};
use super::polyline::{checked_length, checked_steps};
use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

/// Parameters of a grid in the plane z = 0, centred at the origin.
#[derive(Clone, Copy, Debug)]
pub struct Grid {
    /// Extent along x.
    pub width: f64,
    /// Extent along y.
    pub height: f64,
    /// Cells along x (at least 1).
    pub cells_x: u32,
    /// Cells along y (at least 1).
    pub cells_y: u32,
    /// Quads or triangles.
    pub faces: CellFaces,
}

/// Builds an open grid facing +z: `(cells_x + 1)·(cells_y + 1)` vertices, row by row from
/// `(−width/2, −height/2)`, one boundary loop, Euler characteristic 1.
///
/// # Errors
/// Extents not finite or not positive, zero cells, or an output too large for `u32` indices.
pub fn grid(g: &Grid) -> Result<PolygonSoup, SurfaceError> {
    let width = checked_length("width", g.width)?;
    let height = checked_length("height", g.height)?;
    let cells_x = checked_steps("cells_x", g.cells_x, 1)? as usize;
    let cells_y = checked_steps("cells_y", g.cells_y, 1)? as usize;
    let (columns, rows) = (cells_x + 1, cells_y + 1);
    let corners = cells_x.checked_mul(cells_y).and_then(|c| c.checked_mul(6));
    ensure_fits(columns.checked_mul(rows), corners)?;

    let mut out =
        SoupBuilder::with_capacity(columns * rows, cells_x * cells_y * 2, cells_x * cells_y * 6)?;
    let mut ids = try_vec_with_capacity(columns * rows, "vertices")?;
    for row in 0..rows {
        let y = height * (row as f64 / cells_y as f64 - 0.5);
        for column in 0..columns {
            let x = width * (column as f64 / cells_x as f64 - 0.5);
            ids.push(out.vertex(DVec3::new(x, y, 0.0)));
        }
    }
    let lattice = Lattice {
        ids: &ids,
        columns,
        rows,
        wrap_u: false,
        wrap_v: false,
    };
    out.ensure_finite()?;
    lattice
        .push_faces(&mut out, g.faces)
        .expect("grid lattice nodes are all distinct, so no cell collapses");
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_the_requested_rectangle() {
        let g = grid(&Grid {
            width: 4.0,
            height: 2.0,
            cells_x: 4,
            cells_y: 2,
            faces: CellFaces::Quads,
        })
        .unwrap();
        assert_eq!((g.positions.len(), g.n_faces()), (15, 8));
        assert_eq!(g.positions[0], [-2.0, -1.0, 0.0]);
        assert_eq!(g.positions[14], [2.0, 1.0, 0.0]);
    }

    #[test]
    fn rejects_bad_parameters() {
        let bad = Grid {
            width: 1.0,
            height: 1.0,
            cells_x: 0,
            cells_y: 1,
            faces: CellFaces::Quads,
        };
        assert_eq!(
            grid(&bad),
            Err(SurfaceError::TooFewSteps {
                what: "cells_x",
                min: 1,
                got: 0
            })
        );
        let bad = Grid { width: -1.0, ..bad };
        assert_eq!(
            grid(&bad),
            Err(SurfaceError::NonPositive {
                what: "width",
                value: -1.0
            })
        );
    }
}
