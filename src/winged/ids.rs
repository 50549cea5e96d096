//! Typed element ids, edge sides and edge uses.

use crate::support::ids::typed_id;

typed_id!(
    /// A vertex of a [`Winged`](super::Winged) structure.
    VertexId,
    "vertex"
);
typed_id!(
    /// An edge of a [`Winged`](super::Winged) structure (one record per undirected edge).
    EdgeId,
    "edge"
);
typed_id!(
    /// A face of a [`Winged`](super::Winged) structure. `FaceId::INVALID` on an edge side means
    /// "boundary": that side belongs to a hole.
    FaceId,
    "face"
);

/// One of the two sides of an edge `start → end`.
///
/// The **left** side is the one whose loop runs `start → end`; the **right** side's loop runs
/// `end → start`. With faces counter-clockwise seen from outside (the crate's convention), the
/// left face lies on the left of the edge seen from outside looking from `start` to `end`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// The side traversed `start → end` (Baumgart: CW, Granada: "derecho", Wikipedia: left).
    Left,
    /// The side traversed `end → start` (Baumgart: CCW, Granada: "invertido", Wikipedia: right).
    Right,
}

impl Side {
    /// The other side.
    #[inline]
    pub const fn opposite(self) -> Side {
        match self {
            Side::Left => Side::Right,
            Side::Right => Side::Left,
        }
    }
}

/// One traversal of an edge: the edge as the loop on one of its sides walks it.
///
/// This is what a half-edge is in a half-edge structure. The winged-edge records store wings as
/// plain edges; an `EdgeUse` carries the side as well, which is the answer to the per-edge
/// orientation test ("is this face on the edge's left or right?") that every walk needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct EdgeUse {
    /// The edge.
    pub edge: EdgeId,
    /// The side whose loop this traversal belongs to.
    pub side: Side,
}

impl EdgeUse {
    /// The traversal of `edge` by the loop on `side`.
    #[inline]
    pub const fn new(edge: EdgeId, side: Side) -> Self {
        EdgeUse { edge, side }
    }

    /// The same edge walked the other way (by the loop on the other side).
    #[inline]
    pub const fn twin(self) -> Self {
        EdgeUse {
            edge: self.edge,
            side: self.side.opposite(),
        }
    }
}
