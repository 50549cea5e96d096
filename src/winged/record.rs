//! The edge record: Baumgart's winged edge.

use super::ids::{EdgeId, FaceId, Side, VertexId};

/// One record per undirected edge: its two vertices, the face on each side, and the four wings.
///
/// See the [module documentation](super) for how the fields map onto the naming conventions of
/// the literature. A deleted edge has `start == VertexId::INVALID`.
///
/// `repr(C)` (eight `u32`s in field order) so the C API can hand out a read-only view of the
/// record array without copying.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct EdgeRecord {
    /// First vertex (VSTART, Vi, vert_origin).
    pub start: VertexId,
    /// Second vertex (VEND, Vf, vert_destination).
    pub end: VertexId,
    /// Face whose loop walks `start → end` (FCW, Cd, face_left); invalid on a boundary.
    pub left_face: FaceId,
    /// Face whose loop walks `end → start` (FCCW, Ci, face_right); invalid on a boundary.
    pub right_face: FaceId,
    /// Edge before this one in the left face's loop (EPCW, Ada, edge_left_cw).
    pub left_prev: EdgeId,
    /// Edge after this one in the left face's loop (ENCW, Ads, edge_left_ccw).
    pub left_next: EdgeId,
    /// Edge before this one in the right face's loop (EPCCW, Aia, edge_right_cw).
    pub right_prev: EdgeId,
    /// Edge after this one in the right face's loop (ENCCW, Ais, edge_right_ccw).
    pub right_next: EdgeId,
}

impl EdgeRecord {
    /// A record for `start → end` with no faces and no wings yet.
    pub(crate) const fn unlinked(start: VertexId, end: VertexId) -> Self {
        EdgeRecord {
            start,
            end,
            left_face: FaceId::INVALID,
            right_face: FaceId::INVALID,
            left_prev: EdgeId::INVALID,
            left_next: EdgeId::INVALID,
            right_prev: EdgeId::INVALID,
            right_next: EdgeId::INVALID,
        }
    }

    /// Whether the record has been deleted by an Euler operator.
    #[inline]
    pub const fn is_deleted(&self) -> bool {
        !self.start.is_valid()
    }

    /// The face on `side`.
    #[inline]
    pub const fn face(&self, side: Side) -> FaceId {
        match side {
            Side::Left => self.left_face,
            Side::Right => self.right_face,
        }
    }

    /// The wing before this edge in the loop on `side`.
    #[inline]
    pub const fn prev(&self, side: Side) -> EdgeId {
        match side {
            Side::Left => self.left_prev,
            Side::Right => self.right_prev,
        }
    }

    /// The wing after this edge in the loop on `side`.
    #[inline]
    pub const fn next(&self, side: Side) -> EdgeId {
        match side {
            Side::Left => self.left_next,
            Side::Right => self.right_next,
        }
    }

    /// The vertex the loop on `side` leaves from.
    #[inline]
    pub const fn tail(&self, side: Side) -> VertexId {
        match side {
            Side::Left => self.start,
            Side::Right => self.end,
        }
    }

    /// The vertex the loop on `side` arrives at.
    #[inline]
    pub const fn head(&self, side: Side) -> VertexId {
        match side {
            Side::Left => self.end,
            Side::Right => self.start,
        }
    }

    /// The side whose loop leaves `v`, if `v` is an endpoint. This is the orientation test: it
    /// looks at vertices, not faces, so it also works where both sides carry the same face (a
    /// dangling edge made by MEV) or both are holes.
    #[inline]
    pub fn side_leaving(&self, v: VertexId) -> Option<Side> {
        if self.start == v {
            Some(Side::Left)
        } else if self.end == v {
            Some(Side::Right)
        } else {
            None
        }
    }

    /// The side whose loop arrives at `v`, if `v` is an endpoint.
    #[inline]
    pub fn side_arriving(&self, v: VertexId) -> Option<Side> {
        self.side_leaving(v).map(Side::opposite)
    }

    /// Sets the face on `side`.
    #[inline]
    pub(crate) fn set_face(&mut self, side: Side, face: FaceId) {
        match side {
            Side::Left => self.left_face = face,
            Side::Right => self.right_face = face,
        }
    }

    /// Sets the wing before this edge on `side`.
    #[inline]
    pub(crate) fn set_prev(&mut self, side: Side, edge: EdgeId) {
        match side {
            Side::Left => self.left_prev = edge,
            Side::Right => self.right_prev = edge,
        }
    }

    /// Sets the wing after this edge on `side`.
    #[inline]
    pub(crate) fn set_next(&mut self, side: Side, edge: EdgeId) {
        match side {
            Side::Left => self.left_next = edge,
            Side::Right => self.right_next = edge,
        }
    }

    /// Reverses the edge's direction: swaps the endpoints and with them the two sides, so every
    /// loop still sees the same wings.
    pub(crate) fn reverse(&mut self) {
        std::mem::swap(&mut self.start, &mut self.end);
        std::mem::swap(&mut self.left_face, &mut self.right_face);
        std::mem::swap(&mut self.left_prev, &mut self.right_prev);
        std::mem::swap(&mut self.left_next, &mut self.right_next);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sides_are_told_apart_by_vertex() {
        let mut r = EdgeRecord::unlinked(VertexId(3), VertexId(8));
        r.left_face = FaceId(1);
        r.left_next = EdgeId(5);
        assert_eq!(r.side_leaving(VertexId(3)), Some(Side::Left));
        assert_eq!(r.side_leaving(VertexId(8)), Some(Side::Right));
        assert_eq!(r.side_arriving(VertexId(8)), Some(Side::Left));
        assert_eq!(r.side_leaving(VertexId(4)), None);
        assert_eq!(
            (r.tail(Side::Right), r.head(Side::Right)),
            (VertexId(8), VertexId(3))
        );

        r.reverse();
        assert_eq!((r.start, r.end), (VertexId(8), VertexId(3)));
        assert_eq!((r.right_face, r.right_next), (FaceId(1), EdgeId(5)));
        assert_eq!(r.face(Side::Left), FaceId::INVALID);
    }
}
