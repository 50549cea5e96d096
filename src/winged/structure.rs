//! The `Winged` container: vertex, edge and face records and the checked accessors.

use super::error::WingedError;
use super::ids::{EdgeId, FaceId, VertexId};
use super::record::EdgeRecord;

/// A winged-edge (Baumgart) polygon mesh.
///
/// Vertices hold a position (`f64` xyz) and one incident edge; faces hold one edge of their
/// loop; edges hold everything else (see [`EdgeRecord`] and the [module docs](super)). Faces are
/// general polygons, counter-clockwise seen from outside. Elements deleted by the Euler
/// operators keep their ids (the records are marked) until [`Winged::garbage_collect`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Winged {
    pub(crate) positions: Vec<[f64; 3]>,
    pub(crate) vertex_edge: Vec<EdgeId>,
    pub(crate) vertex_alive: Vec<bool>,
    pub(crate) face_edge: Vec<EdgeId>,
    pub(crate) face_alive: Vec<bool>,
    pub(crate) edges: Vec<EdgeRecord>,
    /// Faces without edges (made by MVFS, or left by KEV of a solid's last edge) and the one
    /// vertex each of them holds. Such "point solids" are rare, so a short list suffices.
    pub(crate) point_faces: Vec<(FaceId, VertexId)>,
    /// `false` only when no vertex can have edges outside its ring (a pinched vertex: fans of
    /// faces touching at it, which the builders keep as separate rings). Set by the builders and
    /// [`Winged::from_mesh`] when the input has such a vertex, recomputed by
    /// [`Winged::garbage_collect`]. The Euler operators never make one (they insert an edge into
    /// a ring or remove one from it, never split a ring), so a structure built by them alone
    /// keeps it `false`. Operators that must see every edge of a vertex scan the edges while it
    /// is set.
    pub(crate) may_have_pinched_vertices: bool,
    pub(crate) n_live_vertices: u32,
    pub(crate) n_live_edges: u32,
    pub(crate) n_live_faces: u32,
}

impl Winged {
    /// An empty structure (build one with the Euler operators or a builder).
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of live vertices.
    pub fn n_vertices(&self) -> u32 {
        self.n_live_vertices
    }

    /// Number of live edges.
    pub fn n_edges(&self) -> u32 {
        self.n_live_edges
    }

    /// Number of live faces.
    pub fn n_faces(&self) -> u32 {
        self.n_live_faces
    }

    /// Size of the vertex id space (live and deleted vertices).
    pub fn n_vertex_slots(&self) -> u32 {
        self.positions.len() as u32
    }

    /// Size of the edge id space (live and deleted edges).
    pub fn n_edge_slots(&self) -> u32 {
        self.edges.len() as u32
    }

    /// Size of the face id space (live and deleted faces).
    pub fn n_face_slots(&self) -> u32 {
        self.face_edge.len() as u32
    }

    /// Bytes held by the structure's arrays (their lengths, deleted slots included): 32 per edge
    /// record, 29 per vertex (position, stored edge, live flag), 5 per face (stored edge, live
    /// flag), plus the point faces.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        self.edges.len() * size_of::<EdgeRecord>()
            + self.positions.len() * (size_of::<[f64; 3]>() + size_of::<EdgeId>() + 1)
            + self.face_edge.len() * (size_of::<EdgeId>() + 1)
            + self.point_faces.len() * size_of::<(FaceId, VertexId)>()
    }

    /// V − E + F over the live elements (2 per closed genus-0 solid).
    pub fn euler_characteristic(&self) -> i64 {
        i64::from(self.n_live_vertices) - i64::from(self.n_live_edges)
            + i64::from(self.n_live_faces)
    }

    /// Whether `v` names a live vertex.
    pub fn is_vertex(&self, v: VertexId) -> bool {
        self.vertex_alive.get(v.index()).copied().unwrap_or(false)
    }

    /// Whether `e` names a live edge.
    pub fn is_edge(&self, e: EdgeId) -> bool {
        self.edges.get(e.index()).is_some_and(|r| !r.is_deleted())
    }

    /// Whether `f` names a live face.
    pub fn is_face(&self, f: FaceId) -> bool {
        self.face_alive.get(f.index()).copied().unwrap_or(false)
    }

    /// Ids of the live vertices, in increasing order.
    pub fn vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        (0..self.n_vertex_slots())
            .map(VertexId)
            .filter(|&v| self.is_vertex(v))
    }

    /// Ids of the live edges, in increasing order.
    pub fn edges(&self) -> impl Iterator<Item = EdgeId> + '_ {
        (0..self.n_edge_slots())
            .map(EdgeId)
            .filter(|&e| self.is_edge(e))
    }

    /// Ids of the live faces, in increasing order.
    pub fn faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        (0..self.n_face_slots())
            .map(FaceId)
            .filter(|&f| self.is_face(f))
    }

    pub(crate) fn require_vertex(&self, v: VertexId) -> Result<(), WingedError> {
        if self.is_vertex(v) {
            Ok(())
        } else {
            Err(WingedError::InvalidVertex(v))
        }
    }

    pub(crate) fn require_edge(&self, e: EdgeId) -> Result<(), WingedError> {
        if self.is_edge(e) {
            Ok(())
        } else {
            Err(WingedError::InvalidEdge(e))
        }
    }

    pub(crate) fn require_face(&self, f: FaceId) -> Result<(), WingedError> {
        if self.is_face(f) {
            Ok(())
        } else {
            Err(WingedError::InvalidFace(f))
        }
    }

    /// The record of edge `e`: endpoints, faces and wings.
    pub fn edge(&self, e: EdgeId) -> Result<&EdgeRecord, WingedError> {
        self.require_edge(e)?;
        Ok(&self.edges[e.index()])
    }

    /// The two faces of `e` as `[left, right]` (either may be invalid: a boundary side).
    pub fn edge_faces(&self, e: EdgeId) -> Result<[FaceId; 2], WingedError> {
        let r = self.edge(e)?;
        Ok([r.left_face, r.right_face])
    }

    /// The four wings of `e` as `[left_prev, left_next, right_prev, right_next]`
    /// (Baumgart: EPCW, ENCW, EPCCW, ENCCW; Granada: Ada, Ads, Aia, Ais).
    pub fn edge_wings(&self, e: EdgeId) -> Result<[EdgeId; 4], WingedError> {
        let r = self.edge(e)?;
        Ok([r.left_prev, r.left_next, r.right_prev, r.right_next])
    }

    /// Position of `v`.
    pub fn position(&self, v: VertexId) -> Result<[f64; 3], WingedError> {
        self.require_vertex(v)?;
        Ok(self.positions[v.index()])
    }

    /// Moves `v`. Refuses non-finite coordinates.
    pub fn set_position(&mut self, v: VertexId, p: [f64; 3]) -> Result<(), WingedError> {
        self.require_vertex(v)?;
        if !p.iter().all(|c| c.is_finite()) {
            return Err(WingedError::NonFinitePosition { vertex: v.0 });
        }
        self.positions[v.index()] = p;
        Ok(())
    }

    /// All vertex positions, indexed by vertex id (deleted vertices keep their last position).
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// The edge record array, indexed by edge id (deleted edges have an invalid `start`).
    pub fn edge_records(&self) -> &[EdgeRecord] {
        &self.edges
    }

    /// The stored edge of every vertex, indexed by vertex id (see [`Winged::vertex_edge`]).
    pub fn vertex_edges_stored(&self) -> &[EdgeId] {
        &self.vertex_edge
    }

    /// The stored edge of every face, indexed by face id (see [`Winged::face_edge`]).
    pub fn face_edges_stored(&self) -> &[EdgeId] {
        &self.face_edge
    }

    /// The edge `v` stores (invalid for a vertex without edges). For a boundary vertex the
    /// builders store an edge whose side leaving `v` is a hole, so the ring starts at the gap.
    pub fn vertex_edge(&self, v: VertexId) -> Result<EdgeId, WingedError> {
        self.require_vertex(v)?;
        Ok(self.vertex_edge[v.index()])
    }

    /// The edge `f` stores: its loop starts with this edge (invalid for a point face of MVFS).
    pub fn face_edge(&self, f: FaceId) -> Result<EdgeId, WingedError> {
        self.require_face(f)?;
        Ok(self.face_edge[f.index()])
    }

    /// Chooses which incident edge `v` stores (where its ring starts).
    pub fn set_vertex_edge(&mut self, v: VertexId, e: EdgeId) -> Result<(), WingedError> {
        self.require_vertex(v)?;
        if self.edge(e)?.side_leaving(v).is_none() {
            return Err(WingedError::NotIncident {
                edge: e,
                what: "vertex",
            });
        }
        self.vertex_edge[v.index()] = e;
        Ok(())
    }

    /// Chooses which edge of its loop `f` stores (where its loop starts).
    pub fn set_face_edge(&mut self, f: FaceId, e: EdgeId) -> Result<(), WingedError> {
        self.require_face(f)?;
        let r = self.edge(e)?;
        if r.left_face != f && r.right_face != f {
            return Err(WingedError::NotIncident {
                edge: e,
                what: "face",
            });
        }
        self.face_edge[f.index()] = e;
        Ok(())
    }

    /// The vertex of a face that has no edges (a point face), if `f` is one.
    pub fn point_face_vertex(&self, f: FaceId) -> Option<VertexId> {
        self.point_faces
            .iter()
            .find(|&&(pf, _)| pf == f)
            .map(|&(_, v)| v)
    }
}
