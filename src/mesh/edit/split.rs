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
        let w = self.add_vertex(position).map_err(|error| match error {
            EditError::Full { .. } => EditError::Full {
                operation: SPLIT_EDGE,
            },
            other => other,
        })?;
        let (h0, h1) = (e.halfedge(0), e.halfedge(1));
        let (a, b) = (self.origin(h0), self.target(h0));
        let t = segment_parameter(self.position(a), self.position(b), position);
        let n = self.push_edge(SPLIT_EDGE)?; // n: w → b beside h0; twin(n): b → w beside h1
        let (h0_next, h1_prev) = (self.next(h0), self.prev(h1));
        self.origin[n.index()] = w.0;
        self.origin[n.twin().index()] = b.0;
        self.origin[h1.index()] = w.0;
        self.face[n.index()] = self.face[h0.index()];
        self.face[n.twin().index()] = self.face[h1.index()];
        self.link(h0, n);
        self.link(n, h0_next);
        self.link(h1_prev, n.twin());
        self.link(n.twin(), h1);
        self.vertex_halfedge[w.index()] = if self.is_boundary_halfedge(h1) {
            h1.0
        } else {
            n.0
        };
        if self.vertex_halfedge[b.index()] == h1.0 {
            self.vertex_halfedge[b.index()] = n.twin().0;
        }
        // Corners: beside h0, n is the new corner at w; beside h1, the corner at b moves from h1
        // to twin(n) and h1 becomes the new corner at w.
        self.blend_vertex_attributes(a, b, t, w);
        self.copy_edge_attributes(e, n.edge());
        self.blend_halfedge_attributes(h0, h0_next, t, n);
        self.copy_halfedge_attributes(h1, n.twin());
        self.blend_halfedge_attributes(self.next(h1), n.twin(), t, h1);
        Ok(w)
    }

    /// Splits the face of `h0` and `h1` (two half-edges of one face) with a new edge from
    /// `target(h0)` to `target(h1)`. The original face keeps the side holding `h0` (from the new
    /// half-edge `target(h0) → target(h1)` on); a new face takes the side holding `h1`. Returns
    /// the new half-edge in the original face. Refused when the half-edges are not in one face,
    /// when a side would have fewer than 3 corners, when the two corners are one vertex, or when
    /// an edge already joins the two vertices (in any of their fans): a second edge between them
    /// would make the mesh non-manifold.
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
        if v0 == v1 {
            return refuse(SPLIT_FACE, "the two corners are one vertex");
        }
        if self.are_joined(v0, v1) {
            return refuse(SPLIT_FACE, "the two corners are already joined by an edge");
        }
        if self.face_halfedge.len() as u64 + 1 >= u64::from(u32::MAX) {
            return Err(EditError::Full {
                operation: SPLIT_FACE,
            });
        }
        self.cut_face(h0, h1)
    }

    /// [`Mesh::split_face`] once its preconditions hold (the caller checked them).
    pub(super) fn cut_face(
        &mut self,
        h0: HalfedgeId,
        h1: HalfedgeId,
    ) -> Result<HalfedgeId, EditError> {
        let f = self.face(h0);
        let (v0, v1) = (self.target(h0), self.target(h1));
        let a = self.push_edge(SPLIT_FACE)?; // a: v0 → v1 stays in f; twin(a): v1 → v0 in the new face
        let b = a.twin();
        let (h0_next, h1_next) = (self.next(h0), self.next(h1));
        self.origin[a.index()] = v0.0;
        self.origin[b.index()] = v1.0;
        self.link(h0, a);
        self.link(a, h1_next);
        self.link(h1, b);
        self.link(b, h0_next);
        self.face[a.index()] = f.0;
        self.face_halfedge[f.index()] = a.0;
        let g = self.push_face(b, SPLIT_FACE)?;
        // The corners at v0 and v1 now have a half-edge on each side of the new edge.
        self.copy_face_attributes(f, g);
        self.copy_halfedge_attributes(h0_next, a);
        self.copy_halfedge_attributes(h1_next, b);
        let side: Vec<HalfedgeId> = self.halfedge_loop(b).collect();
        for h in side {
            self.face[h.index()] = g.0;
        }
        Ok(a)
    }
}

/// Where `p` projects on the segment `a`–`b`, as a fraction of the way from `a` (clamped to
/// `[0, 1]`); the middle when the segment has no length or the numbers are not finite.
fn segment_parameter(a: [f64; 3], b: [f64; 3], p: [f64; 3]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let length_squared = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let t = (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / length_squared;
    if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    }
}
