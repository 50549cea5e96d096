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
        for &h in &sides {
            self.face[h.index()] = u32::MAX;
            if self.is_boundary_halfedge(h.twin()) {
                dead_edges.push(h.edge());
            }
        }
        self.mark_face_deleted(f);
        for e in dead_edges {
            self.remove_faceless_edge(e, delete_isolated_vertices);
        }
        for (i, &leaving) in sides.iter().enumerate() {
            let arriving = sides[(i + sides.len() - 1) % sides.len()];
            self.store_boundary_halfedge_of_corner(arriving, leaving);
        }
        Ok(())
    }

    /// After its face is deleted, makes the corner between the face's sides `arriving` and
    /// `leaving` store a boundary half-edge. The half-edge is taken from the face, not found by
    /// walking the corner's fan: at a vertex whose fans the builder kept apart, the fan of the
    /// stored half-edge may not be the one that gained the boundary.
    fn store_boundary_halfedge_of_corner(&mut self, arriving: HalfedgeId, leaving: HalfedgeId) {
        let v = self.origin(leaving);
        let stored = self.vertex_halfedge(v);
        if self.is_vertex_deleted(v) || !stored.is_valid() || self.is_boundary_halfedge(stored) {
            return;
        }
        // A live side of the deleted face is a boundary half-edge now, and the boundary half-edge
        // after one that arrives at `v` leaves `v`. With both sides gone the corner's fan is gone
        // and `remove_faceless_edge` chose what `v` stores.
        let boundary = if !self.is_edge_deleted(leaving.edge()) {
            leaving
        } else if !self.is_edge_deleted(arriving.edge()) {
            self.next(arriving)
        } else {
            return;
        };
        self.vertex_halfedge[v.index()] = boundary.0;
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
                    // `v` had this edge only in this fan, but a vertex whose fans the builder
                    // kept apart has edges in other fans, which the fan walk does not reach.
                    if let Some(other) = self.halfedge_in_another_fan(v) {
                        self.vertex_halfedge[v.index()] = other.0;
                    } else if delete_isolated_vertices {
                        self.mark_vertex_deleted(v);
                    } else {
                        self.vertex_halfedge[v.index()] = u32::MAX;
                    }
                } else {
                    self.vertex_halfedge[v.index()] = following.0;
                }
            }
        }
    }

    /// A live half-edge leaving `v`, a boundary one if there is one, or `None`. It scans all
    /// half-edges, so it runs only while the mesh may have vertices whose fans the builder kept
    /// apart; elsewhere a vertex's one fan holds all its edges.
    fn halfedge_in_another_fan(&self, v: VertexId) -> Option<HalfedgeId> {
        if !self.may_have_pinched_vertices {
            return None;
        }
        let mut found = None;
        for h in self.scan_halfedges_leaving(v) {
            if self.is_boundary_halfedge(h) {
                return Some(h);
            }
            found.get_or_insert(h);
        }
        found
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

    /// Deletes vertex `v`, the faces around it (all its fans) and so its edges; `v` itself is
    /// deleted even when isolated.
    pub fn delete_vertex(&mut self, v: VertexId) -> Result<(), EditError> {
        self.check_vertex(v)?;
        // The circulator sees one fan; once its faces are gone, `v` stores a half-edge of the next
        // fan, if the builder kept several apart. Every round deletes at least one face.
        while !self.is_vertex_deleted(v) && self.vertex_halfedge(v).is_valid() {
            let faces: Vec<FaceId> = self.vertex_faces(v).collect();
            if faces.is_empty() {
                break;
            }
            for f in faces {
                self.delete_face(f, true)?;
            }
        }
        if !self.is_vertex_deleted(v) {
            self.mark_vertex_deleted(v);
        }
        Ok(())
    }
}
