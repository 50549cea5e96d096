//! Deleting faces, edges and vertices (marking; see `garbage_collect`).

use super::EditError;
use crate::mesh::{EdgeId, FaceId, HalfedgeId, Mesh, VertexId};

impl Mesh {
    /// Deletes face `f`: its sides become boundary; edges left with no face on either side are
    /// deleted and the boundary loops relinked around them; vertices left with no edge are
    /// deleted too when `delete_isolated_vertices`, else kept isolated. Vertices keep a boundary
    /// outgoing half-edge.
    pub fn delete_face(
        &mut self,
        f: FaceId,
        delete_isolated_vertices: bool,
    ) -> Result<(), EditError> {
        self.check_face(f)?;
        let sides: Vec<HalfedgeId> = self.face_loop(f).collect();
        let mut dead_edges = Vec::new();
        let mut vertices = Vec::with_capacity(sides.len());
        for &h in &sides {
            self.face[h.idx()] = u32::MAX;
            if self.is_boundary_halfedge(h.twin()) {
                dead_edges.push(h.edge());
            }
            vertices.push(self.target(h));
        }
        self.mark_face_deleted(f);
        self.may_have_pinched_vertices = true;
        for e in dead_edges {
            self.remove_faceless_edge(e, delete_isolated_vertices);
        }
        for v in vertices {
            if !self.is_vertex_deleted(v) && self.vertex_halfedge(v).is_valid() {
                self.adjust_outgoing_halfedge(v);
            }
        }
        Ok(())
    }

    /// Unlinks and deletes an edge whose two sides are boundary, merging or splitting the
    /// boundary loops through it (as pmp's `delete_face` does).
    fn remove_faceless_edge(&mut self, e: EdgeId, delete_isolated_vertices: bool) {
        let (h0, h1) = (e.halfedge(0), e.halfedge(1));
        let (v0, v1) = (self.target(h0), self.target(h1));
        let (next0, prev0, next1, prev1) =
            (self.next(h0), self.prev(h0), self.next(h1), self.prev(h1));
        self.link(prev0, next1);
        self.link(prev1, next0);
        self.mark_edge_deleted(h0);
        for (v, leaving, following) in [(v0, h1, next0), (v1, h0, next1)] {
            if self.vertex_halfedge(v) == leaving {
                if following == leaving {
                    // `v` had this edge only.
                    if delete_isolated_vertices {
                        self.mark_vertex_deleted(v);
                    } else {
                        self.vertex_halfedge[v.idx()] = u32::MAX;
                    }
                } else {
                    self.vertex_halfedge[v.idx()] = following.0;
                }
            }
        }
    }

    /// Deletes edge `e` and the faces beside it (see [`Mesh::delete_face`]).
    pub fn delete_edge(
        &mut self,
        e: EdgeId,
        delete_isolated_vertices: bool,
    ) -> Result<(), EditError> {
        self.check_edge(e)?;
        for side in 0..2 {
            let f = self.face(e.halfedge(side));
            if f.is_valid() {
                self.delete_face(f, delete_isolated_vertices)?;
            }
        }
        Ok(())
    }

    /// Deletes vertex `v`, the faces around it (its fan) and so its edges; `v` itself is deleted
    /// even when isolated.
    pub fn delete_vertex(&mut self, v: VertexId) -> Result<(), EditError> {
        self.check_vertex(v)?;
        let faces: Vec<FaceId> = self.vertex_faces(v).collect();
        for f in faces {
            self.delete_face(f, true)?;
        }
        if !self.is_vertex_deleted(v) {
            self.mark_vertex_deleted(v);
        }
        Ok(())
    }
}
