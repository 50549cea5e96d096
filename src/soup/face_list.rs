//! Borrowed and owned indexed face lists.

use super::table::{MAX_CORNERS, MAX_VERTICES};
use crate::support::allocation::{OutOfMemory, ensure_room};

/// How the polygons of a face list are sized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaceSizes<'a> {
    /// Every face has this many corners (3 for a triangle list, 4 for quads).
    Uniform(u32),
    /// Face `f` has `sizes[f]` corners; its indices follow those of face `f - 1`.
    PerFace(&'a [u32]),
}

/// A borrowed indexed face list: positions, polygon sizes and vertex indices (corners).
///
/// Nothing is assumed valid: builders check sizes, indices and coordinates and report every
/// problem by face, edge and vertex index.
#[derive(Clone, Copy, Debug)]
pub struct FaceList<'a> {
    /// Vertex positions.
    pub positions: &'a [[f64; 3]],
    /// Polygon sizes.
    pub sizes: FaceSizes<'a>,
    /// Vertex indices of every corner, face after face.
    pub indices: &'a [u32],
}

impl<'a> FaceList<'a> {
    /// A triangle list: `indices.len() / 3` triangles.
    pub fn triangles(positions: &'a [[f64; 3]], indices: &'a [u32]) -> Self {
        FaceList {
            positions,
            sizes: FaceSizes::Uniform(3),
            indices,
        }
    }

    /// A polygon list with one size per face.
    pub fn polygons(positions: &'a [[f64; 3]], sizes: &'a [u32], indices: &'a [u32]) -> Self {
        FaceList {
            positions,
            sizes: FaceSizes::PerFace(sizes),
            indices,
        }
    }

    /// Makes sure the memory that building or examining this list needs at most can be had
    /// (see [`ensure_room`]), before anything the size of the list is allocated. Lists beyond
    /// the 32-bit limits are left to the list check, which refuses them without allocating.
    pub(crate) fn ensure_working_room(&self) -> Result<(), OutOfMemory> {
        // The most the arrays of either kernel's build, its repair and the doctor take: per
        // corner, up to two half-edges in four arrays (32 bytes), its edge bucket (8) and its
        // pairing (4); per vertex, the structure's copy of the position (24), its bucket start
        // and half-edge (8); per face, its offset and half-edge (8). The repair's copies of
        // vertices and the doctor's findings are bounded by these counts too.
        const BYTES_PER_CORNER: u64 = 48;
        const BYTES_PER_VERTEX: u64 = 40;
        const BYTES_PER_FACE: u64 = 16;
        let (n_vertices, n_corners) = (self.positions.len() as u64, self.indices.len() as u64);
        let n_faces = match self.sizes {
            FaceSizes::Uniform(0) => 0,
            FaceSizes::Uniform(size) => n_corners / u64::from(size),
            FaceSizes::PerFace(sizes) => sizes.len() as u64,
        };
        if n_vertices > MAX_VERTICES || n_corners > MAX_CORNERS || n_faces >= u64::from(u32::MAX) {
            return Ok(());
        }
        let parts = [
            (n_corners * BYTES_PER_CORNER, n_corners, "corners"),
            (n_vertices * BYTES_PER_VERTEX, n_vertices, "vertices"),
            (n_faces * BYTES_PER_FACE, n_faces, "faces"),
        ];
        let bytes = parts.iter().map(|&(bytes, ..)| bytes).sum();
        // The message names the count that asks for the most.
        let (_, count, what) = parts.into_iter().max().expect("three parts");
        ensure_room(bytes, count as usize, what)
    }
}

/// An owned indexed face list, as the readers produce it, with optional per-corner attributes
/// (aligned with `indices`: corner `i` has `corner_normals[i]` and `corner_uvs[i]`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonSoup {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Corners per face.
    pub face_sizes: Vec<u32>,
    /// Vertex index of every corner, face after face.
    pub indices: Vec<u32>,
    /// Per-corner normals, when the file had them.
    pub corner_normals: Option<Vec<[f64; 3]>>,
    /// Per-corner texture coordinates, when the file had them.
    pub corner_uvs: Option<Vec<[f64; 2]>>,
}

impl PolygonSoup {
    /// The borrowed view builders take.
    pub fn as_face_list(&self) -> FaceList<'_> {
        FaceList::polygons(&self.positions, &self.face_sizes, &self.indices)
    }

    /// Number of faces.
    pub fn n_faces(&self) -> usize {
        self.face_sizes.len()
    }
}
