//! Pinching a boundary loop: splitting a loop that passes twice through one point into two loops
//! that meet there (the kernel half of filling such a hole, decided in `crate::repair`).

use crate::mesh::Mesh;
use crate::mesh::ids::{HalfedgeId, VertexId};

/// What [`Mesh::pinch_boundary_loop`] changed, for [`Mesh::unpinch_boundary_loop`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Pinch {
    /// The boundary half-edges into the two passes through the point.
    into: [HalfedgeId; 2],
    /// When the second pass was through another vertex: that vertex, welded away, and the
    /// half-edges of its fan, which now leave the first pass's vertex.
    welded: Option<(VertexId, Vec<HalfedgeId>)>,
}

impl Pinch {
    /// The boundary half-edges into the two passes through the point: the first stays in the
    /// loop left, the second is in the loop split off.
    pub(crate) fn boundary_halfedges(&self) -> [HalfedgeId; 2] {
        self.into
    }

    /// The vertex welded into the first pass's vertex, if the passes were through two.
    pub(crate) fn welded_vertex(&self) -> Option<VertexId> {
        self.welded.as_ref().map(|(v, _)| *v)
    }
}

impl Mesh {
    /// Splits the boundary loop holding the live boundary half-edges `first` and `second` into
    /// two loops meeting at `first`'s target `v`: one from `next(first)` to `second`, one from
    /// `next(second)` to `first`. When `second`'s target `w` is another vertex, the fan between
    /// `second` and `next(second)` moves to `v` and `w` is deleted.
    ///
    /// The caller guarantees what makes the result valid: both half-edges in one boundary loop,
    /// `w == v` or `w` a vertex of that one fan at the position of `v`, with no edge from `v` and
    /// one from `w` to the same vertex. O(size of the fan moved).
    pub(crate) fn pinch_boundary_loop(&mut self, first: HalfedgeId, second: HalfedgeId) -> Pinch {
        let (v, w) = (self.target(first), self.target(second));
        let (after_first, after_second) = (self.next(first), self.next(second));
        let welded = (w != v).then(|| {
            // The fan of `w`, from its boundary half-edge round to the twin of `second`.
            let mut fan = vec![after_second];
            let mut h = self.next(after_second.twin());
            while h != after_second {
                fan.push(h);
                h = self.next(h.twin());
            }
            for &h in &fan {
                self.origin[h.index()] = v.0;
            }
            self.mark_vertex_deleted(w);
            (w, fan)
        });
        self.link(first, after_second);
        self.link(second, after_first);
        Pinch {
            into: [first, second],
            welded,
        }
    }

    /// Undoes [`Mesh::pinch_boundary_loop`], given the loops it made are still as it left them.
    pub(crate) fn unpinch_boundary_loop(&mut self, pinch: Pinch) {
        let [first, second] = pinch.into;
        let (after_first, after_second) = (self.next(first), self.next(second));
        self.link(first, after_second);
        self.link(second, after_first);
        if let Some((w, fan)) = pinch.welded {
            for &h in &fan {
                self.origin[h.index()] = w.0;
            }
            self.deleted.vertices[w.index()] = false;
            self.deleted.n_vertices -= 1;
            // `fan[0]` is the boundary half-edge that left `w` (the vertex invariant).
            self.vertex_halfedge[w.index()] = fan[0].0;
        }
    }
}
