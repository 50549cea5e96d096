//! Edge split (a new vertex on an edge) and face split (a new edge across a face).

use super::{EditError, refuse};
use crate::mesh::{EdgeId, HalfedgeId, Mesh, VertexId};

const SPLIT_EDGE: &str = "edge split";
const SPLIT_FACE: &str = "face split";

impl Mesh {
    /// Inserts a new vertex at `position` on edge `e` = `a → b` (its `halfedge(e, 0)`), making
    /// `a → w → b`: each face beside the edge gains one corner (call
    /// [`Mesh::triangulate_face`] to keep a triangle mesh triangular). `halfedge(e, 0)` becomes
    /// `a → w`; the new edge holds `w → b` and `b → w`. Returns `w`.
    pub fn split_edge(&mut self, e: EdgeId, position: [f64; 3]) -> Result<VertexId, EditError> {
        self.check_edge(e)?;
        if self.origin.len() as u64 + 2 >= u64::from(u32::MAX) {
            return Err(EditError::Full {
                operation: SPLIT_EDGE,
            });
        }
        let w = self.add_vertex(position).ok_or(EditError::Full {
            operation: SPLIT_EDGE,
        })?;
        let (h0, h1) = (e.halfedge(0), e.halfedge(1));
        let b = self.target(h0);
        let n = self.push_edge(SPLIT_EDGE)?; // n: w → b beside h0; twin(n): b → w beside h1
        let (h0_next, h1_prev) = (self.next(h0), self.prev(h1));
        self.origin[n.idx()] = w.0;
        self.origin[n.twin().idx()] = b.0;
        self.origin[h1.idx()] = w.0;
        self.face[n.idx()] = self.face[h0.idx()];
        self.face[n.twin().idx()] = self.face[h1.idx()];
        self.link(h0, n);
        self.link(n, h0_next);
        self.link(h1_prev, n.twin());
        self.link(n.twin(), h1);
        self.vertex_halfedge[w.idx()] = if self.is_boundary_halfedge(h1) {
            h1.0
        } else {
            n.0
        };
        if self.vertex_halfedge[b.idx()] == h1.0 {
            self.vertex_halfedge[b.idx()] = n.twin().0;
        }
        Ok(w)
    }

    /// Splits the face of `h0` and `h1` (two half-edges of one face) with a new edge from
    /// `target(h0)` to `target(h1)`. The original face keeps the side holding `h0` (from the new
    /// half-edge `target(h0) → target(h1)` on); a new face takes the side holding `h1`. Returns
    /// the new half-edge in the original face. Refused when the half-edges are not in one face,
    /// when a side would have fewer than 3 corners, or when the two vertices are already joined.
    pub fn split_face(&mut self, h0: HalfedgeId, h1: HalfedgeId) -> Result<HalfedgeId, EditError> {
        self.check_halfedge(h0)?;
        self.check_halfedge(h1)?;
        let f = self.face(h0);
        if !f.is_valid() || self.face(h1) != f {
            return refuse(SPLIT_FACE, "the half-edges are not in one face");
        }
        if h0 == h1 || self.next(h0) == h1 || self.next(h1) == h0 {
            return refuse(SPLIT_FACE, "a side would have fewer than 3 corners");
        }
        let (v0, v1) = (self.target(h0), self.target(h1));
        if self.find_halfedge(v0, v1).is_some() || self.find_halfedge(v1, v0).is_some() {
            return refuse(SPLIT_FACE, "the two corners are already joined by an edge");
        }
        if self.face_halfedge.len() as u64 + 1 >= u64::from(u32::MAX) {
            return Err(EditError::Full {
                operation: SPLIT_FACE,
            });
        }
        let a = self.push_edge(SPLIT_FACE)?; // a: v0 → v1 stays in f; twin(a): v1 → v0 in the new face
        let b = a.twin();
        let (h0_next, h1_next) = (self.next(h0), self.next(h1));
        self.origin[a.idx()] = v0.0;
        self.origin[b.idx()] = v1.0;
        self.link(h0, a);
        self.link(a, h1_next);
        self.link(h1, b);
        self.link(b, h0_next);
        self.face[a.idx()] = f.0;
        self.face_halfedge[f.idx()] = a.0;
        let g = self.push_face(b, SPLIT_FACE)?;
        let side: Vec<HalfedgeId> = self.halfedge_loop(b).collect();
        for h in side {
            self.face[h.idx()] = g.0;
        }
        Ok(a)
    }
}
