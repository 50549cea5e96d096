//! Edge flip in a pair of triangles.

use super::{EditError, refuse};
use crate::mesh::{EdgeId, Mesh};

const FLIP: &str = "edge flip";

impl Mesh {
    /// `Ok(())` when [`Mesh::flip_edge`] would succeed on `e`.
    pub fn can_flip_edge(&self, e: EdgeId) -> Result<(), EditError> {
        self.check_edge(e)?;
        let (h0, h1) = (e.halfedge(0), e.halfedge(1));
        if self.is_boundary_edge(e) {
            return refuse(FLIP, "boundary edge");
        }
        if self.face_degree(self.face(h0)) != 3 || self.face_degree(self.face(h1)) != 3 {
            return refuse(FLIP, "a face beside the edge is not a triangle");
        }
        let (c, d) = (self.target(self.next(h0)), self.target(self.next(h1)));
        if c == d {
            return refuse(FLIP, "the two opposite corners are the same vertex");
        }
        if self.find_halfedge(c, d).is_some() || self.find_halfedge(d, c).is_some() {
            return refuse(FLIP, "the opposite corners are already joined by an edge");
        }
        Ok(())
    }

    /// Replaces edge `e` between triangles `(a, b, c)` and `(b, a, d)` by the other diagonal
    /// `c–d`, giving triangles `(d, c, a)` and `(c, d, b)`; ids of the edge and faces are kept
    /// (`halfedge(e, 0)` now runs `d → c`). Refused on boundary edges, non-triangles, and when
    /// `c` and `d` are equal or already adjacent.
    pub fn flip_edge(&mut self, e: EdgeId) -> Result<(), EditError> {
        self.can_flip_edge(e)?;
        let (h0, h1) = (e.halfedge(0), e.halfedge(1));
        let (a1, b1) = (self.next(h0), self.next(h1)); // b → c, a → d
        let (a2, b2) = (self.next(a1), self.next(b1)); // c → a, d → b
        let (a, b) = (self.origin(h0), self.origin(h1));
        let (c, d) = (self.origin(a2), self.origin(b2));
        let (f0, f1) = (self.face(h0), self.face(h1));

        self.origin[h0.index()] = d.0;
        self.origin[h1.index()] = c.0;
        // f0: h0 (d→c), a2 (c→a), b1 (a→d); f1: h1 (c→d), b2 (d→b), a1 (b→c).
        self.link(h0, a2);
        self.link(a2, b1);
        self.link(b1, h0);
        self.link(h1, b2);
        self.link(b2, a1);
        self.link(a1, h1);
        self.face[b1.index()] = f0.0;
        self.face[a1.index()] = f1.0;
        self.face_halfedge[f0.index()] = h0.0;
        self.face_halfedge[f1.index()] = h1.0;
        // The new diagonal's ends take the corners of d (from f1) and c (from f0).
        self.copy_halfedge_attributes(b2, h0);
        self.copy_halfedge_attributes(a2, h1);
        if self.vertex_halfedge[a.index()] == h0.0 {
            self.vertex_halfedge[a.index()] = b1.0;
        }
        if self.vertex_halfedge[b.index()] == h1.0 {
            self.vertex_halfedge[b.index()] = a1.0;
        }
        Ok(())
    }
}
