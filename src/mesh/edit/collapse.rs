//! Half-edge collapse with the link condition (triangle meshes).

use super::{EditError, refuse};
use crate::mesh::{HalfedgeId, Mesh, VertexId};

const COLLAPSE: &str = "edge collapse";

impl Mesh {
    /// `Ok(())` when [`Mesh::collapse_halfedge`] would succeed on `h`: the faces beside the edge
    /// are triangles, and the link condition holds — the only vertices adjacent to both ends are
    /// the opposite corners of those triangles, an interior edge does not join two boundary
    /// vertices, and no triangle beside the edge has its two other edges on the boundary.
    pub fn can_collapse_halfedge(&self, h: HalfedgeId) -> Result<(), EditError> {
        self.check_halfedge(h)?;
        let o = h.twin();
        let (v0, v1) = (self.origin(h), self.target(h));
        let mut opposite = [VertexId::INVALID; 2];
        for (side, g) in [h, o].into_iter().enumerate() {
            if self.is_boundary_halfedge(g) {
                continue;
            }
            if self.face_degree(self.face(g)) != 3 {
                return refuse(COLLAPSE, "a face beside the edge is not a triangle");
            }
            let (g1, g2) = (self.next(g), self.prev(g));
            if self.is_boundary_halfedge(g1.twin()) && self.is_boundary_halfedge(g2.twin()) {
                return refuse(
                    COLLAPSE,
                    "a triangle beside the edge would fold onto the boundary",
                );
            }
            opposite[side] = self.target(g1);
        }
        if opposite[0] == opposite[1] {
            return refuse(
                COLLAPSE,
                "the edge is a boundary edge of a lone triangle or its sides close up",
            );
        }
        let beside = [self.face(h), self.face(o)];
        let shares_other_face = self
            .vertex_faces(v0)
            .any(|f| !beside.contains(&f) && self.face_vertices(f).any(|w| w == v1));
        if shares_other_face {
            return refuse(
                COLLAPSE,
                "another face holds both ends (it would name a vertex twice)",
            );
        }
        if self.may_have_pinched_vertices && self.fan_misses_halfedges(v0) {
            return refuse(COLLAPSE, "the vertex to remove has several fans");
        }
        let interior_edge = !self.is_boundary_halfedge(h) && !self.is_boundary_halfedge(o);
        if interior_edge && self.is_boundary_vertex(v0) && self.is_boundary_vertex(v1) {
            return refuse(COLLAPSE, "an interior edge joins two boundary vertices");
        }
        // `v0`'s fan walk sees all its neighbours (it has one fan, checked above), but `v1` and
        // its neighbours may have fans the builder kept apart, where a fan walk misses edges.
        let around_v1: Vec<VertexId> = self
            .halfedges_leaving_every_fan(v1)
            .into_iter()
            .map(|g| self.target(g))
            .collect();
        let shared = self
            .vertex_vertices(v0)
            .any(|w| w != v1 && !opposite.contains(&w) && around_v1.contains(&w));
        if shared {
            return refuse(
                COLLAPSE,
                "the link condition fails (the ends share another neighbour)",
            );
        }
        // The edge part of the link condition: when the two opposite corners are joined by an
        // edge whose faces hold one end each (a tetrahedron), the collapse would leave the same
        // triangle twice.
        if let [c, d] = opposite
            && c.is_valid()
            && d.is_valid()
            && let Some(cd) = self
                .halfedges_leaving_every_fan(c)
                .into_iter()
                .find(|&g| self.target(g) == d)
        {
            let holds = |g: HalfedgeId, v: VertexId| {
                !self.is_boundary_halfedge(g) && self.face_vertices(self.face(g)).any(|w| w == v)
            };
            let (g, t) = (cd, cd.twin());
            if (holds(g, v0) && holds(t, v1)) || (holds(g, v1) && holds(t, v0)) {
                return refuse(
                    COLLAPSE,
                    "the link condition fails (the opposite corners' edge would be doubled)",
                );
            }
        }
        Ok(())
    }

    /// Collapses half-edge `h`: its origin is removed and merged into its target, which keeps
    /// its position; the triangles beside the edge vanish with one of their other edges each.
    /// Deleted elements are marked (see [`Mesh::garbage_collect`]). Returns the kept vertex.
    /// Refused, with the mesh unchanged, when [`Mesh::can_collapse_halfedge`] fails: that
    /// includes a face other than the two beside the edge holding both ends (polygon meshes), and
    /// an origin with several fans that its circulator does not link (found by a linear scan, run
    /// only while the mesh may have such vertices: after a build that reported some, until a
    /// [`Mesh::garbage_collect`] finds none).
    pub fn collapse_halfedge(&mut self, h: HalfedgeId) -> Result<VertexId, EditError> {
        self.can_collapse_halfedge(h)?;
        let kept = self.target(h);
        let (before_h, after_twin) = (self.prev(h), self.next(h.twin()));
        self.remove_collapsed_edge(h);
        for g in [before_h, after_twin] {
            if self.next(self.next(g)) == g {
                self.remove_two_sided_loop(g);
            }
        }
        Ok(kept)
    }

    /// `true` when some live half-edge leaves `v` outside the fan of its stored half-edge (a scan
    /// of all half-edges: only needed while the mesh may have pinched vertices).
    pub(super) fn fan_misses_halfedges(&self, v: VertexId) -> bool {
        self.scan_halfedges_leaving(v).count() != self.outgoing_halfedges(v).count()
    }

    /// Removes edge `h` (from `gone` to `kept`), moving `gone`'s half-edges to `kept`.
    fn remove_collapsed_edge(&mut self, h: HalfedgeId) {
        let o = h.twin();
        let (hn, hp, on, op) = (self.next(h), self.prev(h), self.next(o), self.prev(o));
        let (fh, fo) = (self.face(h), self.face(o));
        let (gone, kept) = (self.origin(h), self.target(h));
        let leaving_gone: Vec<HalfedgeId> = self.outgoing_halfedges(gone).collect();
        for g in leaving_gone {
            self.origin[g.index()] = kept.0;
        }
        self.link(hp, hn);
        self.link(op, on);
        if fh.is_valid() {
            self.face_halfedge[fh.index()] = hn.0;
        }
        if fo.is_valid() {
            self.face_halfedge[fo.index()] = on.0;
        }
        if self.vertex_halfedge(kept) == o {
            self.vertex_halfedge[kept.index()] = hn.0;
        }
        self.adjust_outgoing_halfedge_in_fan(kept, hn);
        self.mark_vertex_deleted(gone);
        self.mark_edge_deleted(h);
    }

    /// Removes the two-sided face loop `h → next(h) → h` left by a collapse: `h`'s edge goes and
    /// `next(h)` takes its place in the face across.
    fn remove_two_sided_loop(&mut self, h: HalfedgeId) {
        let h1 = self.next(h);
        let (o0, o1) = (h.twin(), h1.twin());
        let (v0, v1) = (self.origin(h1), self.target(h1));
        let (fh, fo) = (self.face(h), self.face(o0));
        let (o0_next, o0_prev) = (self.next(o0), self.prev(o0));
        self.link(h1, o0_next);
        self.link(o0_prev, h1);
        self.face[h1.index()] = fo.0;
        self.copy_halfedge_attributes(o0, h1);
        // `h`'s edge is gone: an end that stored one of its half-edges takes `h1`'s instead.
        for (v, removed, in_fan) in [(v0, o0, h1), (v1, h, o1)] {
            if self.vertex_halfedge(v) == removed {
                self.vertex_halfedge[v.index()] = in_fan.0;
            }
            self.adjust_outgoing_halfedge_in_fan(v, in_fan);
        }
        if fo.is_valid() && self.face_halfedge(fo) == o0 {
            self.face_halfedge[fo.index()] = h1.0;
        }
        if fh.is_valid() {
            self.mark_face_deleted(fh);
        }
        self.mark_edge_deleted(h);
    }
}
