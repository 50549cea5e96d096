//! Borrowed and owned indexed face lists.

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
