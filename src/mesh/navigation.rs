//! Navigation: the fast accessors for trusted ids and their checked `try_*` twins.
//!
//! The fast accessors index the arrays directly: an id out of range panics (like slice
//! indexing) and a deleted id returns stale data. Use them on ids that come from the mesh itself.
//! The `try_*` accessors accept any id and return [`HandleError`] for invalid, out-of-range or
//! deleted ones; the C API uses them.

use super::Mesh;
use super::ids::{EdgeId, FaceId, HalfedgeId, INVALID_INDEX, VertexId};

/// Which kind of element an id names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ElementKind {
    /// A vertex.
    Vertex,
    /// A half-edge.
    Halfedge,
    /// An edge.
    Edge,
    /// A face.
    Face,
}

impl std::fmt::Display for ElementKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ElementKind::Vertex => "vertex",
            ElementKind::Halfedge => "half-edge",
            ElementKind::Edge => "edge",
            ElementKind::Face => "face",
        })
    }
}

/// An id a mesh cannot resolve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum HandleError {
    /// The id is `INVALID` or beyond the element arrays.
    #[error("{kind} id {index} is out of range")]
    OutOfRange {
        /// Element kind.
        kind: ElementKind,
        /// The raw id.
        index: u32,
    },
    /// The element is marked deleted.
    #[error("{kind} {index} is deleted")]
    Deleted {
        /// Element kind.
        kind: ElementKind,
        /// The raw id.
        index: u32,
    },
}

impl Mesh {
    /// The vertex half-edge `h` leaves.
    #[inline]
    pub fn origin(&self, h: HalfedgeId) -> VertexId {
        VertexId(self.origin[h.index()])
    }

    /// The vertex half-edge `h` points to (`origin(twin(h))`).
    #[inline]
    pub fn target(&self, h: HalfedgeId) -> VertexId {
        VertexId(self.origin[h.twin().index()])
    }

    /// The opposite half-edge (`h ^ 1`); never fails for an in-range `h`.
    #[inline]
    pub fn twin(&self, h: HalfedgeId) -> HalfedgeId {
        h.twin()
    }

    /// The next half-edge around `h`'s face (counter-clockwise), or along its boundary loop.
    #[inline]
    pub fn next(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId(self.next[h.index()])
    }

    /// The previous half-edge around `h`'s face or boundary loop.
    #[inline]
    pub fn prev(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId(self.prev[h.index()])
    }

    /// The face to the left of `h`; [`FaceId::INVALID`] for a boundary half-edge.
    #[inline]
    pub fn face(&self, h: HalfedgeId) -> FaceId {
        FaceId(self.face[h.index()])
    }

    /// The edge of `h` (`h >> 1`).
    #[inline]
    pub fn edge(&self, h: HalfedgeId) -> EdgeId {
        h.edge()
    }

    /// A half-edge leaving `v`: the boundary one when `v` is on a boundary; `INVALID` when `v`
    /// is isolated. Circulators around `v` start here.
    #[inline]
    pub fn vertex_halfedge(&self, v: VertexId) -> HalfedgeId {
        HalfedgeId(self.vertex_halfedge[v.index()])
    }

    /// A half-edge of face `f`; face circulators start here.
    #[inline]
    pub fn face_halfedge(&self, f: FaceId) -> HalfedgeId {
        HalfedgeId(self.face_halfedge[f.index()])
    }

    /// Half-edge `side` (0 or 1) of edge `e`.
    #[inline]
    pub fn edge_halfedge(&self, e: EdgeId, side: u32) -> HalfedgeId {
        e.halfedge(side)
    }

    /// Position of `v`.
    #[inline]
    pub fn position(&self, v: VertexId) -> [f64; 3] {
        self.positions[v.index()]
    }

    /// `true` when `h` has no face.
    #[inline]
    pub fn is_boundary_halfedge(&self, h: HalfedgeId) -> bool {
        self.face[h.index()] == INVALID_INDEX
    }

    /// `true` when either side of `e` has no face.
    #[inline]
    pub fn is_boundary_edge(&self, e: EdgeId) -> bool {
        let h = e.halfedge(0);
        self.is_boundary_halfedge(h) || self.is_boundary_halfedge(h.twin())
    }

    /// `true` when `v` is on a boundary or isolated (its half-edge is a boundary one or none).
    #[inline]
    pub fn is_boundary_vertex(&self, v: VertexId) -> bool {
        let h = self.vertex_halfedge[v.index()];
        h == INVALID_INDEX || self.face[h as usize] == INVALID_INDEX
    }

    /// `true` when one of `f`'s edges is a boundary edge.
    pub fn is_boundary_face(&self, f: FaceId) -> bool {
        self.face_loop(f)
            .any(|h| self.is_boundary_halfedge(h.twin()))
    }

    /// Number of edges at `v` (outgoing half-edges of its fan; 0 when isolated).
    pub fn valence(&self, v: VertexId) -> usize {
        self.outgoing_halfedges(v).count()
    }

    /// Number of sides (corners) of `f`.
    pub fn face_degree(&self, f: FaceId) -> usize {
        self.face_loop(f).count()
    }

    // --- checked access -------------------------------------------------------------------

    /// `v` if it names a live vertex.
    pub fn check_vertex(&self, v: VertexId) -> Result<VertexId, HandleError> {
        resolve(
            ElementKind::Vertex,
            v.0,
            self.n_vertex_slots(),
            self.is_vertex_deleted(v),
        )
        .map(|_| v)
    }

    /// `h` if it names a live half-edge.
    pub fn check_halfedge(&self, h: HalfedgeId) -> Result<HalfedgeId, HandleError> {
        resolve(
            ElementKind::Halfedge,
            h.0,
            self.n_halfedge_slots(),
            self.is_halfedge_deleted(h),
        )
        .map(|_| h)
    }

    /// `e` if it names a live edge.
    pub fn check_edge(&self, e: EdgeId) -> Result<EdgeId, HandleError> {
        resolve(
            ElementKind::Edge,
            e.0,
            self.n_edge_slots(),
            self.is_edge_deleted(e),
        )
        .map(|_| e)
    }

    /// `f` if it names a live face.
    pub fn check_face(&self, f: FaceId) -> Result<FaceId, HandleError> {
        resolve(
            ElementKind::Face,
            f.0,
            self.n_face_slots(),
            self.is_face_deleted(f),
        )
        .map(|_| f)
    }

    /// Checked [`Mesh::origin`].
    pub fn try_origin(&self, h: HalfedgeId) -> Result<VertexId, HandleError> {
        self.check_halfedge(h).map(|h| self.origin(h))
    }

    /// Checked [`Mesh::target`].
    pub fn try_target(&self, h: HalfedgeId) -> Result<VertexId, HandleError> {
        self.check_halfedge(h).map(|h| self.target(h))
    }

    /// Checked [`Mesh::twin`].
    pub fn try_twin(&self, h: HalfedgeId) -> Result<HalfedgeId, HandleError> {
        self.check_halfedge(h).map(HalfedgeId::twin)
    }

    /// Checked [`Mesh::next`].
    pub fn try_next(&self, h: HalfedgeId) -> Result<HalfedgeId, HandleError> {
        self.check_halfedge(h).map(|h| self.next(h))
    }

    /// Checked [`Mesh::prev`].
    pub fn try_prev(&self, h: HalfedgeId) -> Result<HalfedgeId, HandleError> {
        self.check_halfedge(h).map(|h| self.prev(h))
    }

    /// Checked [`Mesh::face`] (`Ok(FaceId::INVALID)` for a boundary half-edge).
    pub fn try_face(&self, h: HalfedgeId) -> Result<FaceId, HandleError> {
        self.check_halfedge(h).map(|h| self.face(h))
    }

    /// Checked [`Mesh::edge`].
    pub fn try_edge(&self, h: HalfedgeId) -> Result<EdgeId, HandleError> {
        self.check_halfedge(h).map(HalfedgeId::edge)
    }

    /// Checked [`Mesh::vertex_halfedge`] (`Ok(HalfedgeId::INVALID)` for an isolated vertex).
    pub fn try_vertex_halfedge(&self, v: VertexId) -> Result<HalfedgeId, HandleError> {
        self.check_vertex(v).map(|v| self.vertex_halfedge(v))
    }

    /// Checked [`Mesh::face_halfedge`].
    pub fn try_face_halfedge(&self, f: FaceId) -> Result<HalfedgeId, HandleError> {
        self.check_face(f).map(|f| self.face_halfedge(f))
    }

    /// Checked [`Mesh::edge_halfedge`].
    pub fn try_edge_halfedge(&self, e: EdgeId, side: u32) -> Result<HalfedgeId, HandleError> {
        self.check_edge(e).map(|e| e.halfedge(side))
    }

    /// Checked [`Mesh::position`].
    pub fn try_position(&self, v: VertexId) -> Result<[f64; 3], HandleError> {
        self.check_vertex(v).map(|v| self.position(v))
    }

    /// Checked [`Mesh::is_boundary_halfedge`].
    pub fn try_is_boundary_halfedge(&self, h: HalfedgeId) -> Result<bool, HandleError> {
        self.check_halfedge(h).map(|h| self.is_boundary_halfedge(h))
    }

    /// Checked [`Mesh::is_boundary_edge`].
    pub fn try_is_boundary_edge(&self, e: EdgeId) -> Result<bool, HandleError> {
        self.check_edge(e).map(|e| self.is_boundary_edge(e))
    }

    /// Checked [`Mesh::is_boundary_vertex`].
    pub fn try_is_boundary_vertex(&self, v: VertexId) -> Result<bool, HandleError> {
        self.check_vertex(v).map(|v| self.is_boundary_vertex(v))
    }

    /// Checked [`Mesh::is_boundary_face`].
    pub fn try_is_boundary_face(&self, f: FaceId) -> Result<bool, HandleError> {
        self.check_face(f).map(|f| self.is_boundary_face(f))
    }

    /// Checked [`Mesh::valence`].
    pub fn try_valence(&self, v: VertexId) -> Result<usize, HandleError> {
        self.check_vertex(v).map(|v| self.valence(v))
    }

    /// Checked [`Mesh::face_degree`].
    pub fn try_face_degree(&self, f: FaceId) -> Result<usize, HandleError> {
        self.check_face(f).map(|f| self.face_degree(f))
    }
}

fn resolve(
    kind: ElementKind,
    index: u32,
    capacity: usize,
    deleted: bool,
) -> Result<(), HandleError> {
    if index == INVALID_INDEX || index as usize >= capacity {
        Err(HandleError::OutOfRange { kind, index })
    } else if deleted {
        Err(HandleError::Deleted { kind, index })
    } else {
        Ok(())
    }
}
