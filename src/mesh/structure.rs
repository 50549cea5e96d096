//! The half-edge mesh's struct-of-arrays storage.

use super::ElementKind;
use super::attributes::Attributes;
use super::edit::EditError;
use super::ids::{EdgeId, FaceId, HalfedgeId, INVALID_INDEX, VertexId};

/// A half-edge polygon mesh (general polygons), stored as struct-of-arrays of `u32` indices.
///
/// Conventions:
/// - Half-edges come in pairs: `twin(h) = h ^ 1`, `edge(h) = h >> 1`.
/// - Each half-edge stores its `origin` vertex, `next` and `prev` half-edge around its face, and
///   its `face`. Faces run counter-clockwise seen from outside.
/// - Boundary half-edges are real half-edges with `face = INVALID`, linked by `next`/`prev` into
///   loops that run clockwise seen from outside (the rows with face ∅ in Baumgart's half-edge table).
/// - Each vertex stores one outgoing half-edge — the boundary one when the vertex is on a
///   boundary, `INVALID` when the vertex is isolated — and its position.
/// - Each face stores one of its half-edges.
/// - Deleted elements are only marked until `garbage_collect`; counts exclude them.
///
/// Memory: 16 bytes per half-edge, 28 per vertex, 4 per face (≈ 66 bytes per triangle of a
/// closed triangle mesh).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub(super) origin: Vec<u32>,
    pub(super) next: Vec<u32>,
    pub(super) prev: Vec<u32>,
    pub(super) face: Vec<u32>,
    pub(super) vertex_halfedge: Vec<u32>,
    pub(super) positions: Vec<[f64; 3]>,
    pub(super) face_halfedge: Vec<u32>,
    pub(super) deleted: Deletions,
    /// `false` only when no vertex can have a fan that its circulator misses (known after a build
    /// or a garbage collection: the builder keeps the fans of a pinched vertex apart). Edits never
    /// make such a vertex: a vertex that deleting faces pinches keeps its fans linked in one
    /// cycle, which its circulator walks whole. Operators that must see a vertex's every
    /// half-edge check the slow way while it is set.
    pub(super) may_have_pinched_vertices: bool,
    /// Named per-element columns, corner normals and texture coordinates (see
    /// [`attributes`](super::attributes)); empty sets cost nothing.
    pub(super) attributes: Attributes,
}

/// Deletion marks. The flag vectors stay empty until something is deleted, so a freshly built
/// mesh pays nothing for them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct Deletions {
    pub(super) vertices: Vec<bool>,
    pub(super) edges: Vec<bool>,
    pub(super) faces: Vec<bool>,
    pub(super) n_vertices: usize,
    pub(super) n_edges: usize,
    pub(super) n_faces: usize,
}

impl Mesh {
    /// An empty mesh.
    pub fn new() -> Self {
        Mesh::default()
    }

    /// Whether some vertex may have a fan its circulator misses (see the field's docs);
    /// `false` is a guarantee.
    pub(crate) fn may_have_pinched_vertices(&self) -> bool {
        self.may_have_pinched_vertices
    }

    /// Number of live (not deleted) vertices, isolated ones included.
    pub fn n_vertices(&self) -> usize {
        self.vertex_halfedge.len() - self.deleted.n_vertices
    }

    /// Number of live edges.
    pub fn n_edges(&self) -> usize {
        self.origin.len() / 2 - self.deleted.n_edges
    }

    /// Number of live half-edges (twice the edges).
    pub fn n_halfedges(&self) -> usize {
        2 * self.n_edges()
    }

    /// Number of live faces.
    pub fn n_faces(&self) -> usize {
        self.face_halfedge.len() - self.deleted.n_faces
    }

    /// Size of the vertex arrays, deleted slots included: valid vertex ids are below this.
    pub fn n_vertex_slots(&self) -> usize {
        self.vertex_halfedge.len()
    }

    /// Size of the half-edge arrays, deleted slots included.
    pub fn n_halfedge_slots(&self) -> usize {
        self.origin.len()
    }

    /// Size of the edge arrays (half the half-edge arrays), deleted slots included.
    pub fn n_edge_slots(&self) -> usize {
        self.origin.len() / 2
    }

    /// Size of the face arrays, deleted slots included.
    pub fn n_face_slots(&self) -> usize {
        self.face_halfedge.len()
    }

    /// `true` when vertex `v` is marked deleted (out-of-range ids are not).
    pub fn is_vertex_deleted(&self, v: VertexId) -> bool {
        self.deleted
            .vertices
            .get(v.index())
            .copied()
            .unwrap_or(false)
    }

    /// `true` when edge `e` (and so both its half-edges) is marked deleted.
    pub fn is_edge_deleted(&self, e: EdgeId) -> bool {
        self.deleted.edges.get(e.index()).copied().unwrap_or(false)
    }

    /// `true` when half-edge `h`'s edge is marked deleted.
    pub fn is_halfedge_deleted(&self, h: HalfedgeId) -> bool {
        self.is_edge_deleted(h.edge())
    }

    /// `true` when face `f` is marked deleted.
    pub fn is_face_deleted(&self, f: FaceId) -> bool {
        self.deleted.faces.get(f.index()).copied().unwrap_or(false)
    }

    /// `true` when element `idx` of `kind` is marked deleted (out-of-range ids are not).
    pub fn is_deleted_of(&self, kind: ElementKind, idx: u32) -> bool {
        match kind {
            ElementKind::Vertex => self.is_vertex_deleted(VertexId(idx)),
            ElementKind::Halfedge => self.is_halfedge_deleted(HalfedgeId(idx)),
            ElementKind::Edge => self.is_edge_deleted(EdgeId(idx)),
            ElementKind::Face => self.is_face_deleted(FaceId(idx)),
        }
    }

    /// `true` when some element is marked deleted (so the arrays have holes).
    pub fn has_deleted_elements(&self) -> bool {
        self.deleted.n_vertices + self.deleted.n_edges + self.deleted.n_faces > 0
    }

    // Zero-copy views of the raw arrays, indexed by element id; `u32::MAX` means none. They
    // include deleted slots (see the `is_*_deleted` queries).

    /// Origin vertex of every half-edge.
    pub fn halfedge_origins(&self) -> &[u32] {
        &self.origin
    }

    /// Next half-edge (around the face or boundary loop) of every half-edge.
    pub fn halfedge_nexts(&self) -> &[u32] {
        &self.next
    }

    /// Previous half-edge of every half-edge.
    pub fn halfedge_prevs(&self) -> &[u32] {
        &self.prev
    }

    /// Face of every half-edge (`u32::MAX` on the boundary).
    pub fn halfedge_faces(&self) -> &[u32] {
        &self.face
    }

    /// Outgoing half-edge of every vertex (the boundary one on a boundary; `u32::MAX` if
    /// isolated).
    pub fn vertex_halfedges(&self) -> &[u32] {
        &self.vertex_halfedge
    }

    /// One half-edge of every face.
    pub fn face_halfedges(&self) -> &[u32] {
        &self.face_halfedge
    }

    /// Deletion mark of every vertex slot; empty while no vertex was ever deleted.
    pub fn vertex_deletion_marks(&self) -> &[bool] {
        &self.deleted.vertices
    }

    /// Deletion mark of every edge slot; empty while no edge was ever deleted.
    pub fn edge_deletion_marks(&self) -> &[bool] {
        &self.deleted.edges
    }

    /// Deletion mark of every face slot; empty while no face was ever deleted.
    pub fn face_deletion_marks(&self) -> &[bool] {
        &self.deleted.faces
    }

    /// Vertex positions.
    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// Moves `v` (connectivity stays as it is). Refuses a deleted or out-of-range vertex and
    /// non-finite coordinates.
    pub fn set_position(&mut self, v: VertexId, position: [f64; 3]) -> Result<(), EditError> {
        let v = self.check_vertex(v)?;
        require_finite(position, v.0)?;
        self.positions[v.index()] = position;
        Ok(())
    }

    /// Adds an isolated vertex (its attributes are zero). Refuses non-finite coordinates, and
    /// a vertex count reaching `u32::MAX` ([`EditError::Full`], for `operation`).
    pub fn add_vertex(&mut self, position: [f64; 3]) -> Result<VertexId, EditError> {
        const OPERATION: &str = "vertex addition";
        let id = u32::try_from(self.vertex_halfedge.len())
            .ok()
            .filter(|&id| id != INVALID_INDEX)
            .ok_or(EditError::Full {
                operation: OPERATION,
            })?;
        require_finite(position, id)?;
        self.vertex_halfedge.push(INVALID_INDEX);
        self.positions.push(position);
        if !self.deleted.vertices.is_empty() {
            self.deleted.vertices.push(false);
        }
        self.grow_attributes();
        Ok(VertexId(id))
    }
}

/// Refuses a position with a NaN or infinite coordinate for `vertex` (see
/// [`EditError::NonFinitePosition`]).
fn require_finite(position: [f64; 3], vertex: u32) -> Result<(), EditError> {
    if position.iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(EditError::NonFinitePosition { vertex })
    }
}
