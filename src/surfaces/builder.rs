//! Accumulates a [`PolygonSoup`] while checking that every index fits in `u32`.

use glam::DVec3;

use super::SurfaceError;
use crate::soup::PolygonSoup;
use crate::support::allocation::{OutOfMemory, try_vec_with_capacity};

/// Largest vertex count a generator may produce: `u32::MAX` is the invalid index.
const MAX_VERTICES: usize = u32::MAX as usize - 1;

/// Refuses, before anything is allocated, a surface whose vertex or corner count (given as
/// overflow-checked products) does not fit the `u32` index space.
pub(crate) fn ensure_fits(
    vertices: Option<usize>,
    corners: Option<usize>,
) -> Result<(), SurfaceError> {
    match (vertices, corners) {
        (Some(v), Some(c)) if v <= MAX_VERTICES && c <= u32::MAX as usize => Ok(()),
        _ => Err(SurfaceError::TooLarge),
    }
}

/// Collects positions and faces; generators size their output with [`ensure_fits`] first, so
/// pushing never overflows an index.
#[derive(Debug, Default)]
pub(crate) struct SoupBuilder {
    soup: PolygonSoup,
    /// A vertex position overflowed (finite parameters whose sums or products do not fit).
    overflowed: bool,
}

impl SoupBuilder {
    /// An empty builder with room for the expected sizes, or the refusal of that memory.
    pub(crate) fn with_capacity(
        vertices: usize,
        faces: usize,
        corners: usize,
    ) -> Result<Self, OutOfMemory> {
        let soup = PolygonSoup {
            positions: try_vec_with_capacity(vertices, "vertices")?,
            face_sizes: try_vec_with_capacity(faces, "faces")?,
            indices: try_vec_with_capacity(corners, "corners")?,
            ..PolygonSoup::default()
        };
        Ok(SoupBuilder {
            soup,
            overflowed: false,
        })
    }

    /// Adds a vertex and returns its index.
    pub(crate) fn vertex(&mut self, position: DVec3) -> u32 {
        let id = self.soup.positions.len() as u32;
        self.overflowed |= !position.is_finite();
        self.soup.positions.push(position.to_array());
        id
    }

    /// Adds a polygon given by its vertex indices in CCW order seen from outside.
    pub(crate) fn face(&mut self, corners: &[u32]) {
        self.soup.face_sizes.push(corners.len() as u32);
        self.soup.indices.extend_from_slice(corners);
    }

    /// The finished soup, or the refusal of one whose coordinates overflowed: non-finite
    /// coordinates never leave a generator.
    pub(crate) fn finish(self) -> Result<PolygonSoup, SurfaceError> {
        self.ensure_finite()?;
        Ok(self.soup)
    }

    /// Refuses the vertices so far when a coordinate overflowed, before faces on them are
    /// judged (an overflowed cell would look collapsed).
    pub(crate) fn ensure_finite(&self) -> Result<(), SurfaceError> {
        if self.overflowed {
            return Err(SurfaceError::CoordinatesOverflow);
        }
        Ok(())
    }
}
