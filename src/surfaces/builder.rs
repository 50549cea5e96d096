//! Accumulates a [`PolygonSoup`] while checking that every index fits in `u32`.

use glam::DVec3;

use super::SurfaceError;
use crate::allocation::{OutOfMemory, try_vec_with_capacity};
use crate::soup::PolygonSoup;

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
        Ok(SoupBuilder { soup })
    }

    /// Adds a vertex and returns its index.
    pub(crate) fn vertex(&mut self, position: DVec3) -> u32 {
        let id = self.soup.positions.len() as u32;
        self.soup.positions.push(position.to_array());
        id
    }

    /// Adds a polygon given by its vertex indices in CCW order seen from outside.
    pub(crate) fn face(&mut self, corners: &[u32]) {
        self.soup.face_sizes.push(corners.len() as u32);
        self.soup.indices.extend_from_slice(corners);
    }

    /// The finished soup.
    pub(crate) fn finish(self) -> PolygonSoup {
        self.soup
    }
}
