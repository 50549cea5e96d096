//! Editing operators. Each checks its preconditions first and returns [`EditError`] without
//! touching the mesh when one fails, so a refused operation leaves the mesh as it was.
//! Deletions only mark elements; [`Mesh::garbage_collect`](super::Mesh::garbage_collect)
//! compacts the arrays and returns the old-to-new index maps.

mod add_face;
mod collapse;
mod delete;
mod flip;
mod glue;
mod pinch;
mod split;
mod triangulate;

pub(crate) use pinch::Pinch;
pub(crate) use triangulate::{JoinedCorners, chords_of};

use super::Mesh;
use super::circulators::Step;
use super::ids::{FaceId, HalfedgeId, INVALID_INDEX, VertexId};
use super::navigation::HandleError;

/// Why an editing operator refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum EditError {
    /// An argument names no live element.
    #[error(transparent)]
    Handle(#[from] HandleError),
    /// The operation's precondition does not hold; the mesh is unchanged.
    #[error("{operation} refused: {reason}")]
    Refused {
        /// The operator.
        operation: &'static str,
        /// The failed precondition.
        reason: &'static str,
    },
    /// A position has a NaN or infinite coordinate: such coordinates never enter a mesh.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinitePosition {
        /// The vertex moved, or the id the added vertex would have had.
        vertex: u32,
    },
    /// The mesh would need more elements than 32-bit ids can name.
    #[error("{operation} refused: the mesh is full (32-bit ids exhausted)")]
    Full {
        /// The operator.
        operation: &'static str,
    },
}

pub(super) fn refuse<T>(operation: &'static str, reason: &'static str) -> Result<T, EditError> {
    Err(EditError::Refused { operation, reason })
}

impl Mesh {
    /// The half-edge from `from` to `to`, searched in `from`'s fan; `None` when there is none.
    pub fn find_halfedge(&self, from: VertexId, to: VertexId) -> Option<HalfedgeId> {
        self.outgoing_halfedges(from)
            .find(|&h| self.target(h) == to)
    }

    /// Whether an edge joins `u` and `v`, in any of their fans. Every edge has a half-edge leaving
    /// each end, so looking round `u` is enough: its fans' walks.
    pub(super) fn are_joined(&self, u: VertexId, v: VertexId) -> bool {
        self.halfedges_leaving_every_fan(u)
            .into_iter()
            .any(|h| self.target(h) == v)
    }

    /// Every live half-edge leaving `v`, whatever its fan: a scan of all half-edges. The fan walk
    /// sees one fan only, and a vertex whose fans the builder kept apart has several; operators
    /// scan only while the mesh may have such vertices.
    pub(super) fn scan_halfedges_leaving(
        &self,
        v: VertexId,
    ) -> impl Iterator<Item = HalfedgeId> + '_ {
        (0..self.n_halfedge_slots() as u32)
            .map(HalfedgeId)
            .inspect(|_| super::pinched_fans::note_halfedges_visited(1))
            .filter(move |&h| self.origin(h) == v && !self.is_halfedge_deleted(h))
    }

    /// Appends a pair of half-edges (fields to be set by the caller; attributes zero); returns the
    /// even one.
    pub(super) fn push_edge(&mut self, operation: &'static str) -> Result<HalfedgeId, EditError> {
        let h = self.origin.len();
        if h as u64 + 2 >= u64::from(INVALID_INDEX) {
            return Err(EditError::Full { operation });
        }
        for array in [
            &mut self.origin,
            &mut self.next,
            &mut self.prev,
            &mut self.face,
        ] {
            array.extend([INVALID_INDEX; 2]);
        }
        if !self.deleted.edges.is_empty() {
            self.deleted.edges.push(false);
        }
        self.grow_attributes();
        Ok(HalfedgeId(h as u32))
    }

    /// Appends a face whose loop starts at `h` (face ids of the loop set by the caller; attributes
    /// zero).
    pub(super) fn push_face(
        &mut self,
        h: HalfedgeId,
        operation: &'static str,
    ) -> Result<FaceId, EditError> {
        let f = self.face_halfedge.len();
        if f as u64 + 1 >= u64::from(INVALID_INDEX) {
            return Err(EditError::Full { operation });
        }
        self.face_halfedge.push(h.0);
        if !self.deleted.faces.is_empty() {
            self.deleted.faces.push(false);
        }
        self.grow_attributes();
        Ok(FaceId(f as u32))
    }

    /// Links `a → b` (sets `next(a)` and `prev(b)`).
    #[inline]
    pub(super) fn link(&mut self, a: HalfedgeId, b: HalfedgeId) {
        self.next[a.index()] = b.0;
        self.prev[b.index()] = a.0;
    }

    /// Makes `v`'s half-edge a boundary one if `v`'s fan has one (the vertex invariant).
    pub(super) fn adjust_outgoing_halfedge(&mut self, v: VertexId) {
        self.adjust_outgoing_halfedge_in_fan(v, self.vertex_halfedge(v));
    }

    /// After an edit that changed only the fan of `in_fan` (a live half-edge leaving `v`): makes
    /// `v`'s half-edge a boundary one of that fan if `v` stores none and the fan has one. The fan
    /// is named rather than walked from `v`'s half-edge because at a vertex whose fans the
    /// builder kept apart, `v` may store a half-edge of another fan.
    pub(super) fn adjust_outgoing_halfedge_in_fan(&mut self, v: VertexId, in_fan: HalfedgeId) {
        if self.is_boundary_halfedge(self.vertex_halfedge(v)) {
            return;
        }
        if let Some(h) = self
            .walk(in_fan, Step::Ring)
            .find(|&h| self.is_boundary_halfedge(h))
        {
            self.vertex_halfedge[v.index()] = h.0;
        }
    }

    pub(super) fn mark_face_deleted(&mut self, f: FaceId) {
        if self.deleted.faces.is_empty() {
            self.deleted.faces = vec![false; self.face_halfedge.len()];
        }
        if !std::mem::replace(&mut self.deleted.faces[f.index()], true) {
            self.deleted.n_faces += 1;
        }
    }

    pub(super) fn mark_edge_deleted(&mut self, h: HalfedgeId) {
        if self.deleted.edges.is_empty() {
            self.deleted.edges = vec![false; self.origin.len() / 2];
        }
        if !std::mem::replace(&mut self.deleted.edges[h.edge().index()], true) {
            self.deleted.n_edges += 1;
        }
    }

    pub(super) fn mark_vertex_deleted(&mut self, v: VertexId) {
        if self.deleted.vertices.is_empty() {
            self.deleted.vertices = vec![false; self.vertex_halfedge.len()];
        }
        if !std::mem::replace(&mut self.deleted.vertices[v.index()], true) {
            self.deleted.n_vertices += 1;
        }
        self.vertex_halfedge[v.index()] = INVALID_INDEX;
    }
}
