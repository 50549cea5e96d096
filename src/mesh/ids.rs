//! Typed element ids.
//!
//! Every element of a [`Mesh`](super::Mesh) is a `u32` index into its struct-of-arrays storage;
//! `u32::MAX` ([`INVALID_INDEX`]) means "none". The four newtypes keep kinds apart at compile time.
//! Half-edges come in pairs: the twin of half-edge `h` is `h ^ 1` and its edge is `h >> 1`, so
//! edge `e` owns half-edges `2e` and `2e + 1`.

pub use crate::support::ids::INVALID_INDEX;
use crate::support::ids::typed_id;

typed_id!(
    /// A vertex of a half-edge mesh.
    VertexId,
    "vertex"
);
typed_id!(
    /// A half-edge (a directed edge side). Its twin is `h ^ 1`, its edge `h >> 1`.
    HalfedgeId,
    "half-edge"
);
typed_id!(
    /// An undirected edge: the pair of half-edges `2e` and `2e + 1`.
    EdgeId,
    "edge"
);
typed_id!(
    /// A face (polygon) of a half-edge mesh.
    FaceId,
    "face"
);

impl HalfedgeId {
    /// The opposite half-edge of the same edge (`h ^ 1`).
    #[inline]
    pub const fn twin(self) -> Self {
        Self(self.0 ^ 1)
    }

    /// The edge this half-edge belongs to (`h >> 1`).
    #[inline]
    pub const fn edge(self) -> EdgeId {
        EdgeId(self.0 >> 1)
    }
}

impl EdgeId {
    /// One of the edge's two half-edges: `side` 0 gives `2e`, 1 gives `2e + 1`.
    /// The result is invalid when the edge id is too large to have half-edges.
    #[inline]
    pub const fn halfedge(self, side: u32) -> HalfedgeId {
        if self.0 < INVALID_INDEX / 2 {
            HalfedgeId((self.0 << 1) | (side & 1))
        } else {
            HalfedgeId::INVALID
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn twin_and_edge_follow_the_pairing_rule() {
        let h = HalfedgeId::new(7);
        assert_eq!(h.twin(), HalfedgeId::new(6));
        assert_eq!(h.twin().twin(), h);
        assert_eq!(h.edge(), EdgeId::new(3));
        assert_eq!(EdgeId::new(3).halfedge(0), HalfedgeId::new(6));
        assert_eq!(EdgeId::new(3).halfedge(1), h);
    }

    #[test]
    fn invalid_ids_are_recognised_and_do_not_overflow() {
        assert!(!VertexId::INVALID.is_valid());
        assert!(VertexId::new(0).is_valid());
        assert_eq!(FaceId::default(), FaceId::INVALID);
        assert_eq!(EdgeId::INVALID.halfedge(0), HalfedgeId::INVALID);
        assert_eq!(EdgeId::new(u32::MAX / 2).halfedge(1), HalfedgeId::INVALID);
        assert_eq!(
            format!("{:?}", HalfedgeId::INVALID),
            "half-edge 4294967295 (the invalid id)"
        );
        assert_eq!(format!("{}", VertexId::new(4)), "vertex 4");
    }
}
