//! How attributes follow the editing operators (the rules are listed in the module docs): the
//! operators call these hooks at the points where elements appear, move or merge.

use crate::mesh::ids::{FaceId, HalfedgeId, VertexId};
use crate::mesh::{EdgeId, Mesh};

impl Mesh {
    /// Grows every column to its kind's capacity (after elements were appended).
    pub(in crate::mesh) fn grow_attributes(&mut self) {
        let (v, h, e, f) = (
            self.n_vertex_slots(),
            self.n_halfedge_slots(),
            self.n_edge_slots(),
            self.n_face_slots(),
        );
        let attributes = &mut self.attributes;
        attributes.vertex.resize(v);
        attributes.halfedge.resize(h);
        attributes.edge.resize(e);
        attributes.face.resize(f);
    }

    pub(in crate::mesh) fn blend_vertex_attributes(
        &mut self,
        a: VertexId,
        b: VertexId,
        t: f64,
        to: VertexId,
    ) {
        self.attributes
            .vertex
            .blend(a.index(), b.index(), t, to.index());
    }

    /// Sets vertex `to`'s attributes to the mean of those of `from` (a vertex added inside
    /// their triangle, as hole refinement adds them).
    pub(crate) fn interpolate_vertex_attributes(&mut self, from: [VertexId; 3], to: VertexId) {
        let [a, b, c] = from;
        self.blend_vertex_attributes(a, b, 0.5, to);
        self.blend_vertex_attributes(to, c, 1.0 / 3.0, to);
    }

    pub(in crate::mesh) fn copy_halfedge_attributes(&mut self, from: HalfedgeId, to: HalfedgeId) {
        self.attributes.halfedge.copy(from.index(), to.index());
    }

    pub(in crate::mesh) fn blend_halfedge_attributes(
        &mut self,
        a: HalfedgeId,
        b: HalfedgeId,
        t: f64,
        to: HalfedgeId,
    ) {
        self.attributes
            .halfedge
            .blend(a.index(), b.index(), t, to.index());
    }

    pub(in crate::mesh) fn reset_halfedge_attributes(&mut self, h: HalfedgeId) {
        self.attributes.halfedge.reset(h.index());
    }

    pub(in crate::mesh) fn copy_edge_attributes(&mut self, from: EdgeId, to: EdgeId) {
        self.attributes.edge.copy(from.index(), to.index());
    }

    pub(in crate::mesh) fn copy_face_attributes(&mut self, from: FaceId, to: FaceId) {
        self.attributes.face.copy(from.index(), to.index());
    }

    /// Compacts every column with the maps of a garbage collection.
    pub(in crate::mesh) fn compact_attributes(
        &mut self,
        vertices: &[u32],
        halfedges: &[u32],
        edges: &[u32],
        faces: &[u32],
    ) {
        let attributes = &mut self.attributes;
        attributes.vertex.compact(vertices);
        attributes.halfedge.compact(halfedges);
        attributes.edge.compact(edges);
        attributes.face.compact(faces);
    }
}
