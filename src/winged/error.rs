//! Errors of the winged-edge kernel.

use super::ids::{EdgeId, FaceId, VertexId};
use crate::soup::BuildError;

/// Everything that can go wrong building, querying or editing a [`Winged`](super::Winged).
///
/// Bad input is always reported with the offending face, edge or vertex index; on any error the
/// structure is left exactly as it was.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum WingedError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    // --- face-list input ---
    /// The face list was refused by the shared analysis (see [`BuildError`]: it carries the
    /// [`Diagnostic`](crate::soup::Diagnostic) of everything found).
    #[error(transparent)]
    InvalidFaceList(#[from] BuildError),
    /// A vertex position is NaN or infinite (a new position given to an editing call).
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinitePosition {
        /// The vertex.
        vertex: u32,
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
    #[error("{0} does not exist")]
    InvalidVertex(VertexId),
    /// The edge id is out of range or deleted.
    #[error("{0} does not exist")]
    InvalidEdge(EdgeId),
    /// The face id is out of range, deleted or invalid.
    #[error("{0} does not exist")]
    InvalidFace(FaceId),
    /// The edge is not incident to the element it was paired with.
    #[error("{edge} is not incident to the given {what}")]
    NotIncident {
        /// The edge.
        edge: EdgeId,
        /// "vertex" or "face".
        what: &'static str,
    },

    // --- Euler operator preconditions ---
    /// The vertex does not lie on the face's loop.
    #[error("{vertex} is not on the loop of {face}")]
    VertexNotOnFace {
        /// The vertex.
        vertex: VertexId,
        /// The face.
        face: FaceId,
    },
    /// The vertex occurs more than once on the face's loop, so the corner is ambiguous.
    #[error("{vertex} occurs more than once on the loop of {face}")]
    AmbiguousCorner {
        /// The vertex.
        vertex: VertexId,
        /// The face.
        face: FaceId,
    },
    /// An edge would join a vertex to itself.
    #[error("an edge cannot join {0} to itself")]
    SelfLoop(VertexId),
    /// KEV needs a vertex whose only edge is the one being killed.
    #[error("{vertex} has other edges than {edge}")]
    VertexNotDangling {
        /// The vertex.
        vertex: VertexId,
        /// The edge.
        edge: EdgeId,
    },
    /// KEV of a solid's last edge would leave a point face on a vertex that has edges in
    /// another fan (a pinched vertex); a point face's vertex has no edges.
    #[error("killing {edge} would leave a point face on {vertex}, which has edges in another fan")]
    PointFaceAtSharedVertex {
        /// The edge.
        edge: EdgeId,
        /// The vertex at the edge's other end.
        vertex: VertexId,
    },
    /// KEF needs two different real faces on the edge's sides.
    #[error("{0} does not separate two different faces")]
    EdgeNotBetweenTwoFaces(EdgeId),

    /// KVFS needs a face without edges (a solid reduced to one vertex).
    #[error("{0} has edges; only a point face can be killed with its solid")]
    NotAPointFace(FaceId),

    // --- conversion ---
    /// The structure holds something the half-edge mesh cannot (a face without edges).
    #[error("cannot convert to a half-edge mesh: {0}")]
    NotConvertible(String),

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_elements_as_c_sees_them() {
        // Before: "vertex VertexId(1) does not exist".
        assert_eq!(
            WingedError::InvalidVertex(VertexId(1)).to_string(),
            "vertex 1 does not exist"
        );
        assert_eq!(
            WingedError::VertexNotDangling {
                vertex: VertexId(2),
                edge: EdgeId(5)
            }
            .to_string(),
            "vertex 2 has other edges than edge 5"
        );
        assert_eq!(
            WingedError::InvalidFace(FaceId::INVALID).to_string(),
            "face 4294967295 (the invalid id) does not exist"
        );
    }
}
