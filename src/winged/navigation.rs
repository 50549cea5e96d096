//! Navigation: one step from an edge use (its tail, head, face, next and previous use), where
//! the orientation test lives, and the checked accessors for uses.

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, FaceId, Side, VertexId};
use super::record::EdgeRecord;
use super::structure::Winged;

impl Winged {
    /// The record of a use's edge (unchecked id: callers hold live ids).
    #[inline]
    pub(crate) fn rec(&self, e: EdgeId) -> &EdgeRecord {
        &self.edges[e.index()]
    }

    /// The vertex a use leaves.
    pub fn use_tail(&self, u: EdgeUse) -> Result<VertexId, WingedError> {
        Ok(self.edge(u.edge)?.tail(u.side))
    }

    /// The vertex a use arrives at.
    pub fn use_head(&self, u: EdgeUse) -> Result<VertexId, WingedError> {
        Ok(self.edge(u.edge)?.head(u.side))
    }

    /// The face (or hole: invalid) whose loop contains the use.
    pub fn use_face(&self, u: EdgeUse) -> Result<FaceId, WingedError> {
        Ok(self.edge(u.edge)?.face(u.side))
    }

    /// [`Winged::use_tail`] for a use the caller knows is live.
    #[inline]
    pub(crate) fn tail_of(&self, u: EdgeUse) -> VertexId {
        self.rec(u.edge).tail(u.side)
    }

    /// [`Winged::use_head`] for a use the caller knows is live.
    #[inline]
    pub(crate) fn head_of(&self, u: EdgeUse) -> VertexId {
        self.rec(u.edge).head(u.side)
    }

    /// [`Winged::use_face`] for a use the caller knows is live.
    #[inline]
    pub(crate) fn face_of(&self, u: EdgeUse) -> FaceId {
        self.rec(u.edge).face(u.side)
    }

    /// The next use in the same loop: the wing after `u.edge` on `u.side`, walked the way that
    /// leaves the vertex `u` arrives at. Returns `None` only on a corrupted structure.
    #[inline]
    pub fn use_next(&self, u: EdgeUse) -> Option<EdgeUse> {
        let r = self.edges.get(u.edge.index())?;
        let n = r.next(u.side);
        let side = self.edges.get(n.index())?.side_leaving(r.head(u.side))?;
        Some(EdgeUse::new(n, side))
    }

    /// The previous use in the same loop (the wing before, walked into the vertex `u` leaves).
    #[inline]
    pub fn use_prev(&self, u: EdgeUse) -> Option<EdgeUse> {
        let r = self.edges.get(u.edge.index())?;
        let p = r.prev(u.side);
        let side = self.edges.get(p.index())?.side_arriving(r.tail(u.side))?;
        Some(EdgeUse::new(p, side))
    }

    /// Links `a → b` in their loop (sets `a`'s next wing and `b`'s previous wing).
    #[inline]
    pub(crate) fn link(&mut self, a: EdgeUse, b: EdgeUse) {
        self.edges[a.edge.index()].set_next(a.side, b.edge);
        self.edges[b.edge.index()].set_prev(b.side, a.edge);
    }

    /// The use of `f`'s stored edge that belongs to `f`'s loop (the loop's first use).
    pub(crate) fn face_first_use(&self, f: FaceId) -> Option<EdgeUse> {
        let e = self.face_edge[f.index()];
        let r = self.edges.get(e.index())?;
        if r.left_face == f {
            Some(EdgeUse::new(e, Side::Left))
        } else if r.right_face == f {
            Some(EdgeUse::new(e, Side::Right))
        } else {
            None
        }
    }

    /// The use of `v`'s stored edge that leaves `v` (the ring's first use).
    pub(crate) fn vertex_first_use(&self, v: VertexId) -> Option<EdgeUse> {
        let e = self.vertex_edge[v.index()];
        let side = self.edges.get(e.index())?.side_leaving(v)?;
        Some(EdgeUse::new(e, side))
    }

    /// An upper bound on any loop or ring length; walks stop there on a corrupted structure.
    #[inline]
    pub(crate) fn walk_bound(&self) -> usize {
        2 * self.edges.len() + 1
    }
}
