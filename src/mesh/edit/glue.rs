//! Gluing pairs of boundary half-edges into interior edges: the kernel half of stitching
//! borders (which pairs may be glued is decided in `crate::repair`).

use crate::mesh::Mesh;
use crate::mesh::ids::{HalfedgeId, INVALID_INDEX, VertexId};

impl Mesh {
    /// Glues each pair `[a, b]` of live boundary half-edges, `a` from `u` to `v` and `b` from
    /// `v'` to `u'`: the faces beside them become neighbours across `a`'s edge, whose boundary
    /// slot `a` takes over the face half-edge of `b`'s edge (its origin, links, face and
    /// half-edge attributes), and `b`'s edge is deleted. Then every vertex `x` with
    /// `kept[x] != x` is merged into `kept[x]` (its half-edges leave `kept[x]`; it is deleted).
    ///
    /// The caller guarantees what makes the result valid: every half-edge in at most one pair,
    /// `kept` identifying exactly the ends the pairs join (`kept[u'] == kept[u]`,
    /// `kept[v'] == kept[v]`, each kept vertex its own), and a result whose vertices stay
    /// manifold, whose edges join distinct vertex pairs and whose faces repeat no vertex.
    pub(crate) fn glue_boundary_pairs(&mut self, pairs: &[[HalfedgeId; 2]], kept: &[u32]) {
        // The boundary loops first, while both half-edges of each pair are still in them.
        for &[a, b] in pairs {
            let (before_a, after_a) = (self.prev(a), self.next(a));
            let (before_b, after_b) = (self.prev(b), self.next(b));
            match (after_a == b, after_b == a) {
                (true, true) => {}
                (true, false) => self.link(before_a, after_b),
                (false, true) => self.link(before_b, after_a),
                (false, false) => {
                    self.link(before_a, after_b);
                    self.link(before_b, after_a);
                }
            }
        }
        for &[a, b] in pairs {
            let moved = b.twin();
            let (i, j) = (a.index(), moved.index());
            self.origin[i] = self.origin[j];
            self.face[i] = self.face[j];
            let (before, after) = (self.prev(moved), self.next(moved));
            self.link(before, a);
            self.link(a, after);
            let f = self.face[i] as usize;
            if self.face_halfedge[f] == moved.0 {
                self.face_halfedge[f] = a.0;
            }
            self.copy_halfedge_attributes(moved, a);
            self.mark_edge_deleted(b);
        }
        // Merged vertices, then the stored half-edge of every vertex the pairs touch: a
        // boundary one where its fan still has one.
        let mut touched = vec![false; self.vertex_halfedge.len()];
        for h in 0..self.origin.len() {
            if self.is_halfedge_deleted(HalfedgeId(h as u32)) {
                continue;
            }
            let v = kept[self.origin[h] as usize];
            self.origin[h] = v;
        }
        for &[a, b] in pairs {
            for h in [a, b] {
                for v in [self.origin[h.index()], self.origin[h.twin().index()]] {
                    touched[kept[v as usize] as usize] = true;
                }
            }
        }
        for (v, &k) in kept.iter().enumerate() {
            if k as usize != v {
                touched[v] = false;
                self.mark_vertex_deleted(VertexId(v as u32));
            } else if touched[v] {
                self.vertex_halfedge[v] = INVALID_INDEX;
            }
        }
        for h in 0..self.origin.len() as u32 {
            let h = HalfedgeId(h);
            if self.is_halfedge_deleted(h) {
                continue;
            }
            let v = self.origin[h.index()] as usize;
            if touched[v]
                && (self.vertex_halfedge[v] == INVALID_INDEX || self.is_boundary_halfedge(h))
            {
                self.vertex_halfedge[v] = h.0;
            }
        }
    }
}
