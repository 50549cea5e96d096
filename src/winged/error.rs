//! Errors of the winged-edge kernel.

use super::ids::{EdgeId, FaceId, VertexId};

/// Everything that can go wrong building, querying or editing a [`Winged`](super::Winged).
///
/// Bad input is always reported with the offending face, edge or vertex index; on any error the
/// structure is left exactly as it was.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum WingedError {
    // --- face-list input ---
    /// A face has fewer than three corners.
    #[error("face {face} has {size} corners; a polygon needs at least 3")]
    FaceTooSmall {
        /// The face.
        face: u32,
        /// Its corner count.
        size: u32,
    },
    /// The face sizes do not add up to the number of corner indices.
    #[error("the face sizes add up to {expected} corners but {actual} indices were given")]
    CornerCountMismatch {
        /// Sum of the face sizes.
        expected: u64,
        /// Length of the index array.
        actual: u64,
    },
    /// A corner refers to a vertex that does not exist.
    #[error("face {face} refers to vertex {vertex}, but there are only {n_vertices} vertices")]
    IndexOutOfRange {
        /// The face.
        face: u32,
        /// The bad vertex index.
        vertex: u32,
        /// Number of vertices.
        n_vertices: u32,
    },
    /// A face visits the same vertex twice.
    #[error("face {face} visits vertex {vertex} more than once")]
    RepeatedVertex {
        /// The face.
        face: u32,
        /// The repeated vertex.
        vertex: u32,
    },
    /// A vertex position is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinitePosition {
        /// The vertex.
        vertex: u32,
    },
    /// More than two faces share an edge.
    #[error("edge ({a}, {b}) is shared by {} faces: {faces:?}", faces.len())]
    NonManifoldEdge {
        /// One endpoint.
        a: u32,
        /// The other endpoint.
        b: u32,
        /// Every face using the edge.
        faces: Vec<u32>,
    },
    /// Two faces walk their shared edge in the same direction.
    #[error("faces {faces:?} both walk edge {a} -> {b}; their orientations disagree")]
    InconsistentOrientation {
        /// Start of the edge as both faces walk it.
        a: u32,
        /// End of the edge as both faces walk it.
        b: u32,
        /// The two faces.
        faces: [u32; 2],
    },
    /// An element count does not fit the `u32` ids (`u32::MAX` is reserved for "invalid").
    #[error("too many {what}: {count} does not fit a 32-bit id")]
    TooManyElements {
        /// Which elements.
        what: &'static str,
        /// How many there would be.
        count: u64,
    },
    /// An explicit edge order does not list exactly the edges of the faces.
    #[error("the explicit edge order is not a permutation of the mesh edges: {reason}")]
    EdgeOrderMismatch {
        /// What is wrong with it.
        reason: String,
    },

    // --- handles ---
    /// The vertex id is out of range or deleted.
    #[error("vertex {0:?} does not exist")]
    InvalidVertex(VertexId),
    /// The edge id is out of range or deleted.
    #[error("edge {0:?} does not exist")]
    InvalidEdge(EdgeId),
    /// The face id is out of range, deleted or invalid.
    #[error("face {0:?} does not exist")]
    InvalidFace(FaceId),
    /// The edge is not incident to the element it was paired with.
    #[error("edge {edge:?} is not incident to the given {what}")]
    NotIncident {
        /// The edge.
        edge: EdgeId,
        /// "vertex" or "face".
        what: &'static str,
    },

    // --- Euler operator preconditions ---
    /// The vertex does not lie on the face's loop.
    #[error("vertex {vertex:?} is not on the loop of face {face:?}")]
    VertexNotOnFace {
        /// The vertex.
        vertex: VertexId,
        /// The face.
        face: FaceId,
    },
    /// The vertex occurs more than once on the face's loop, so the corner is ambiguous.
    #[error("vertex {vertex:?} occurs more than once on the loop of face {face:?}")]
    AmbiguousCorner {
        /// The vertex.
        vertex: VertexId,
        /// The face.
        face: FaceId,
    },
    /// An edge would join a vertex to itself.
    #[error("an edge cannot join vertex {0:?} to itself")]
    SelfLoop(VertexId),
    /// KEV needs a vertex whose only edge is the one being killed.
    #[error("vertex {vertex:?} has other edges than {edge:?}")]
    VertexNotDangling {
        /// The vertex.
        vertex: VertexId,
        /// The edge.
        edge: EdgeId,
    },
    /// KEF needs two different real faces on the edge's sides.
    #[error("edge {0:?} does not separate two different faces")]
    EdgeNotBetweenTwoFaces(EdgeId),

    /// KVFS needs a face without edges (a solid reduced to one vertex).
    #[error("face {0:?} has edges; only a point face can be killed with its solid")]
    NotAPointFace(FaceId),

    // --- validation ---
    /// [`Winged::check`](super::Winged::check) found a broken invariant.
    #[error("invariant broken at {element}: {reason}")]
    InvariantViolated {
        /// The element, e.g. "edge 12 (left side)".
        element: String,
        /// Which invariant.
        reason: &'static str,
    },
}
