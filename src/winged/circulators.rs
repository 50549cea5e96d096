//! Ordered adjacency queries: face loops and vertex rings, with the orientation test done once
//! per step (see [`Winged::use_next`]).

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, FaceId, VertexId};
use super::structure::Winged;
use crate::support::cycles::for_each_cycle_length;

/// How a [`Walk`] steps from one use to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Along a loop: `use_next`.
    Loop,
    /// Counter-clockwise about the tail vertex: `twin(use_prev(u))` (Baumgart's
    /// `e = e->prev->sym`).
    Ring,
}

/// A bounded walk over edge uses: a face loop or a vertex ring.
///
/// Yields each use once, starting with the stored one, and stops on returning to it. On a
/// corrupted structure it stops after `2 × edges + 1` steps instead of looping forever
/// ([`Winged::check`] reports the corruption).
#[derive(Clone, Debug)]
pub struct Walk<'a> {
    winged: &'a Winged,
    start: Option<EdgeUse>,
    current: Option<EdgeUse>,
    step: Step,
    remaining: usize,
}

impl Iterator for Walk<'_> {
    type Item = EdgeUse;

    fn next(&mut self) -> Option<EdgeUse> {
        let here = self.current?;
        if self.remaining == 0 {
            self.current = None;
            return None;
        }
        self.remaining -= 1;
        let after = match self.step {
            Step::Loop => self.winged.use_next(here),
            Step::Ring => self.winged.use_prev(here).map(EdgeUse::twin),
        };
        self.current = after.filter(|&u| Some(u) != self.start);
        Some(here)
    }
}

impl std::iter::FusedIterator for Walk<'_> {}

/// Where a [`Walk`] stands: enough to pause it and resume it later with
/// [`Winged::resume_walk`] (the C circulators keep this on the caller's stack).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WalkState {
    /// The use the walk started from (it ends on coming back to it).
    pub start: Option<EdgeUse>,
    /// The use the walk yields next; `None` when it is over.
    pub current: Option<EdgeUse>,
    /// How it steps.
    pub step: Step,
    /// Steps left before the bound stops it.
    pub remaining: usize,
}

impl Walk<'_> {
    /// The walk's state, to resume it later.
    pub fn state(&self) -> WalkState {
        WalkState {
            start: self.start,
            current: self.current,
            step: self.step,
            remaining: self.remaining,
        }
    }
}

impl Winged {
    fn walk(&self, start: Option<EdgeUse>, step: Step) -> Walk<'_> {
        Walk {
            winged: self,
            start,
            current: start,
            step,
            remaining: self.walk_bound(),
        }
    }

    /// Resumes a walk paused with [`Walk::state`]. A state naming an edge that is not live
    /// ends the walk at once (the structure changed since it was paused).
    pub fn resume_walk(&self, state: WalkState) -> Walk<'_> {
        let live = |u: Option<EdgeUse>| u.is_none_or(|u| self.is_edge(u.edge));
        let usable = live(state.start) && live(state.current);
        Walk {
            winged: self,
            start: state.start,
            current: if usable { state.current } else { None },
            step: state.step,
            remaining: state.remaining.min(self.walk_bound()),
        }
    }

    /// The uses of `f`'s loop in order (counter-clockwise seen from outside), starting with the
    /// stored edge. Each use says which side of its edge `f` is on. Empty for a point face.
    pub fn face_loop(&self, f: FaceId) -> Result<Walk<'_>, WingedError> {
        self.require_face(f)?;
        Ok(self.walk(self.face_first_use(f), Step::Loop))
    }

    /// The uses leaving `v`, counter-clockwise about `v` seen from outside, starting with the
    /// stored edge. Holes are passed through like faces, so a boundary vertex's ring is complete
    /// (its first use is the one bordering the hole). At a non-manifold vertex this is the fan
    /// containing the stored edge.
    pub fn vertex_ring(&self, v: VertexId) -> Result<Walk<'_>, WingedError> {
        self.require_vertex(v)?;
        Ok(self.walk(self.vertex_first_use(v), Step::Ring))
    }

    /// The loop of the hole on the side of boundary edge `e` that has no face, or `None` if
    /// both sides of `e` are faces.
    pub fn boundary_loop(&self, e: EdgeId) -> Result<Option<Walk<'_>>, WingedError> {
        let r = self.edge(e)?;
        let side = [super::Side::Left, super::Side::Right]
            .into_iter()
            .find(|&s| !r.face(s).is_valid());
        Ok(side.map(|s| self.walk(Some(EdgeUse::new(e, s)), Step::Loop)))
    }

    /// The edges of `f` in loop order.
    pub fn face_edges(&self, f: FaceId) -> Result<impl Iterator<Item = EdgeId> + '_, WingedError> {
        Ok(self.face_loop(f)?.map(|u| u.edge))
    }

    /// The vertices of `f` in loop order, starting with the tail of the stored edge's use (the
    /// first corner of the face as it was built). A point face yields its one vertex.
    pub fn face_vertices(
        &self,
        f: FaceId,
    ) -> Result<impl Iterator<Item = VertexId> + '_, WingedError> {
        let point = self.point_face_vertex(f);
        Ok(point
            .into_iter()
            .chain(self.face_loop(f)?.map(|u| self.tail_of(u))))
    }

    /// The faces across each edge of `f`, in loop order, leaving out holes. A face that shares
    /// several edges with `f` appears once per shared edge.
    pub fn face_neighbors(
        &self,
        f: FaceId,
    ) -> Result<impl Iterator<Item = FaceId> + '_, WingedError> {
        Ok(self
            .face_loop(f)?
            .map(|u| self.face_of(u.twin()))
            .filter(|g| g.is_valid()))
    }

    /// The edges at `v`, counter-clockwise.
    pub fn vertex_edges(
        &self,
        v: VertexId,
    ) -> Result<impl Iterator<Item = EdgeId> + '_, WingedError> {
        Ok(self.vertex_ring(v)?.map(|u| u.edge))
    }

    /// The neighbours of `v` (other ends of its edges), counter-clockwise.
    pub fn vertex_neighbors(
        &self,
        v: VertexId,
    ) -> Result<impl Iterator<Item = VertexId> + '_, WingedError> {
        Ok(self.vertex_ring(v)?.map(|u| self.head_of(u)))
    }

    /// The faces around `v`, counter-clockwise, leaving out holes (each face follows the edge
    /// that leaves `v` along it).
    pub fn vertex_faces(
        &self,
        v: VertexId,
    ) -> Result<impl Iterator<Item = FaceId> + '_, WingedError> {
        Ok(self
            .vertex_ring(v)?
            .map(|u| self.face_of(u))
            .filter(|f| f.is_valid()))
    }

    /// Number of edges at `v` in its ring.
    pub fn valence(&self, v: VertexId) -> Result<usize, WingedError> {
        Ok(self.vertex_ring(v)?.count())
    }

    /// Whether `e` has a hole on one side.
    pub fn is_boundary_edge(&self, e: EdgeId) -> Result<bool, WingedError> {
        let r = self.edge(e)?;
        Ok(!r.left_face.is_valid() || !r.right_face.is_valid())
    }

    /// Whether `v` lies on a boundary (its ring passes through a hole).
    pub fn is_boundary_vertex(&self, v: VertexId) -> Result<bool, WingedError> {
        Ok(self.vertex_ring(v)?.any(|u| !self.face_of(u).is_valid()))
    }

    /// Number of edges at every vertex, indexed by vertex id (counted from the edge records, so
    /// it includes every fan of a non-manifold vertex).
    pub fn degrees(&self) -> Vec<u32> {
        let mut degree = vec![0u32; self.positions.len()];
        for e in self.edges() {
            let r = self.rec(e);
            degree[r.start.index()] += 1;
            degree[r.end.index()] += 1;
        }
        degree
    }

    /// The vertices where two or more fans of faces meet (their ring, which follows one fan,
    /// misses some of their edges), in increasing order. The structure holds them, but walks
    /// around them see one fan at a time.
    pub fn non_manifold_vertices(&self) -> Vec<VertexId> {
        // Every edge has two ends: when the rings add up to twice the edges, none missed any
        // (the usual case, decided without counting degrees).
        let mut walked = 0;
        self.for_each_ring_size(|_, size| walked += size);
        if walked == 2 * self.n_edges() as usize {
            return Vec::new();
        }
        let mut ring_size = vec![0; self.positions.len()];
        self.for_each_ring_size(|v, size| ring_size[v] = size);
        let degree = self.degrees();
        self.vertices()
            .filter(|&v| ring_size[v.index()] != degree[v.index()] as usize)
            .collect()
    }

    /// Calls `visit(v, size)` for each live vertex `v` with a stored edge, `size` being its
    /// [`Winged::valence`] (the ring walked from that edge, bounded like every walk).
    fn for_each_ring_size(&self, visit: impl FnMut(usize, usize)) {
        let starts = self
            .vertices()
            .filter_map(|v| Some((v.index(), self.vertex_first_use(v)?)));
        let step = |u: EdgeUse| self.use_prev(u).map(EdgeUse::twin);
        for_each_cycle_length(starts, self.walk_bound(), step, visit);
    }
}
