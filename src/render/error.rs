//! Why render buffers could not be built.

use thiserror::Error;

use super::TriangulateError;

/// A refused render-buffer request; every variant names the offending input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum RenderError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// A per-corner attribute array does not have one entry per half-edge slot.
    #[error("{what}: {got} entries given, the mesh has {expected} half-edge slots")]
    CornerAttributeLength {
        /// Which attribute.
        what: &'static str,
        /// Half-edge slots of the mesh.
        expected: usize,
        /// Entries given.
        got: usize,
    },
    /// The crease angle is NaN, infinite or negative.
    #[error("crease angle {0} is not a finite angle of at least 0 radians")]
    BadCreaseAngle(f64),
    /// A vertex lies beyond single precision (±3.4e38), which every render buffer holds.
    #[error(
        "vertex {vertex} at {position:?} is beyond the single-precision range (3.4e38) of the render buffers"
    )]
    BeyondSinglePrecision {
        /// The first such vertex.
        vertex: u32,
        /// Its position.
        position: [f64; 3],
    },
    /// The normal glyph length is NaN, infinite, zero or negative.
    #[error("normal glyph length {0} is not a positive finite length")]
    BadGlyphLength(f64),
    /// A diagnostic names a vertex the mesh does not have: it belongs to another mesh.
    #[error("the diagnostic names vertex {vertex} but the mesh has {vertices} vertex slots")]
    DiagnosticMismatch {
        /// The vertex named.
        vertex: u32,
        /// Vertex slots of the mesh.
        vertices: usize,
    },
    /// A polygon of a polygon list has fewer than 3 corners: it has no area to fill.
    #[error("polygon {polygon} has {corners} corners; a polygon needs at least 3")]
    TooFewCorners {
        /// Index of the polygon in the list.
        polygon: usize,
        /// Its corner count.
        corners: u32,
    },
    /// A corner of a polygon list has a NaN or infinite coordinate.
    #[error("polygon {polygon} corner {corner} has a non-finite coordinate {point:?}")]
    NonFiniteCorner {
        /// Index of the polygon in the list.
        polygon: usize,
        /// Index of the corner within the polygon.
        corner: usize,
        /// The corner's coordinates.
        point: [f64; 3],
    },
    /// A doctor's report names a face or vertex the face list does not have: it is the report
    /// of another list.
    #[error("the report names {what} {id}, but the face list has {count}")]
    ReportMismatch {
        /// "face" or "vertex".
        what: &'static str,
        /// The id named.
        id: u32,
        /// How many the list has.
        count: usize,
    },
    /// The face list's sizes and indices do not fit together.
    #[error("malformed face list: {0}")]
    MalformedFaceList(String),
    /// The polygons could not be triangulated (sizes or indices do not fit).
    #[error(transparent)]
    Polygons(#[from] TriangulateError),
}
