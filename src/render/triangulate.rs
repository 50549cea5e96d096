//! Triangle index buffers of polygon face lists, from the shared polygon triangulation
//! ([`PolygonTriangulator`]).

use thiserror::Error;

use crate::geom::{FallbackReason, PolygonOutcome, PolygonTriangulator};
use crate::soup::{FaceList, FaceSizes};

/// Why a face list could not be triangulated.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum TriangulateError {
    /// The face sizes do not add up to the number of corner indices.
    #[error("face sizes account for {expected} corners but {got} indices were given")]
    CornerCountMismatch {
        /// Corners the sizes describe.
        expected: usize,
        /// Indices given.
        got: usize,
    },
    /// A uniform face size does not divide the number of corner indices.
    #[error("{got} indices do not make whole faces of {size} corners")]
    UniformSizeMismatch {
        /// The uniform face size.
        size: u32,
        /// Indices given.
        got: usize,
    },
    /// A corner refers to a vertex that does not exist.
    #[error(
        "face {face} corner {corner} refers to vertex {vertex}, but there are {vertices} vertices"
    )]
    IndexOutOfRange {
        /// Face index.
        face: usize,
        /// Corner within the face.
        corner: usize,
        /// The bad vertex index.
        vertex: u32,
        /// Number of vertices.
        vertices: usize,
    },
    /// The triangle list would need more than `u32::MAX` entries.
    #[error("the triangulation would need more than 2^32 - 1 indices")]
    TooLarge,
}

/// A triangle index buffer for a polygon mesh, ready for `glBufferData(GL_ELEMENT_ARRAY_BUFFER)`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TriangleBuffer {
    /// Vertex indices, three per triangle, in each face's winding.
    pub indices: Vec<u32>,
    /// Global corner indices (positions in the face list's `indices`), three per triangle, for
    /// per-corner attributes such as split normals and uvs.
    pub corners: Vec<u32>,
    /// The face each triangle comes from.
    pub source_faces: Vec<u32>,
    /// Faces that fell back to a fan (entirely or partly), with the reason.
    pub fallbacks: Vec<(u32, FallbackReason)>,
    /// Faces with fewer than 3 corners, which produce no triangle.
    pub skipped_faces: Vec<u32>,
}

impl TriangleBuffer {
    /// Number of triangles.
    pub fn n_triangles(&self) -> usize {
        self.source_faces.len()
    }
}

/// Triangulates every face of a face list. Triangles keep their face's winding, come face by
/// face in face order, and every face of `n ≥ 3` corners gives `n − 2` of them.
///
/// # Errors
/// Sizes that do not match the index count, an index out of range, or more than `u32::MAX`
/// output indices. Degenerate faces are not errors: they are fanned and listed in `fallbacks`.
pub fn triangulate_faces(faces: &FaceList<'_>) -> Result<TriangleBuffer, TriangulateError> {
    let ranges = face_ranges(faces)?;
    let vertices = faces.positions.len();
    let mut total = 0usize;
    for (face, range) in ranges.iter().enumerate() {
        for (corner, &vertex) in faces.indices[range.clone()].iter().enumerate() {
            if vertex as usize >= vertices {
                return Err(TriangulateError::IndexOutOfRange {
                    face,
                    corner,
                    vertex,
                    vertices,
                });
            }
        }
        total += range.len().saturating_sub(2) * 3;
    }
    if total > u32::MAX as usize || ranges.len() > u32::MAX as usize {
        return Err(TriangulateError::TooLarge);
    }

    let mut buffer = TriangleBuffer {
        indices: Vec::with_capacity(total),
        corners: Vec::with_capacity(total),
        source_faces: Vec::with_capacity(total / 3),
        ..TriangleBuffer::default()
    };
    let mut triangulator = PolygonTriangulator::new();
    let mut corners = Vec::new();
    let mut local = Vec::new();
    for (face, range) in ranges.into_iter().enumerate() {
        let face_id = face as u32;
        let first_corner = range.start as u32;
        let ring = &faces.indices[range];
        corners.clear();
        corners.extend(ring.iter().map(|&v| faces.positions[v as usize]));
        local.clear();
        match triangulator.triangulate(&corners, &mut local) {
            PolygonOutcome::Exact => {}
            PolygonOutcome::TooFewCorners => buffer.skipped_faces.push(face_id),
            PolygonOutcome::Fallback(reason) => buffer.fallbacks.push((face_id, reason)),
        }
        for triangle in &local {
            for &k in triangle {
                buffer.indices.push(ring[k as usize]);
                buffer.corners.push(first_corner + k);
            }
            buffer.source_faces.push(face_id);
        }
    }
    Ok(buffer)
}

/// The corner range of every face, checked against the index count.
fn face_ranges(faces: &FaceList<'_>) -> Result<Vec<std::ops::Range<usize>>, TriangulateError> {
    corner_ranges(faces.sizes, faces.indices.len())
}

/// The corner range of every face of the given sizes, checked against the `got` corners there are.
pub(super) fn corner_ranges(
    sizes: FaceSizes<'_>,
    got: usize,
) -> Result<Vec<std::ops::Range<usize>>, TriangulateError> {
    match sizes {
        FaceSizes::Uniform(0) if got == 0 => Ok(Vec::new()),
        FaceSizes::Uniform(size) if size > 0 && got.is_multiple_of(size as usize) => {
            let size = size as usize;
            Ok((0..got / size).map(|f| f * size..(f + 1) * size).collect())
        }
        FaceSizes::Uniform(size) => Err(TriangulateError::UniformSizeMismatch { size, got }),
        FaceSizes::PerFace(sizes) => {
            let mut ranges = Vec::with_capacity(sizes.len());
            let mut start = 0usize;
            for &size in sizes {
                let end = start.saturating_add(size as usize);
                ranges.push(start..end);
                start = end;
            }
            if start != got {
                return Err(TriangulateError::CornerCountMismatch {
                    expected: start,
                    got,
                });
            }
            Ok(ranges)
        }
    }
}
