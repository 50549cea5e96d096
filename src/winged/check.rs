//! The structure validator: every invariant, with every walk bounded.

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, Side};
use super::structure::Winged;

fn broken(element: String, reason: &'static str) -> WingedError {
    WingedError::InvariantViolated { element, reason }
}

impl Winged {
    /// Validates every invariant of the structure:
    ///
    /// - array lengths agree and the live counts match the live records;
    /// - every live edge joins two different live vertices, each side has a live face or a hole
    ///   (invalid), and each side's wings are live edges through which the loop continues: the
    ///   next wing leaves the vertex this side arrives at, the previous wing arrives at the vertex
    ///   it leaves, `prev(next(u)) == u`, `next(prev(u)) == u`, and the loop's face is the same;
    /// - every live face's stored edge has it on a side, and its loop closes and contains every
    ///   side that names the face (one loop per face); a face without edges is a recorded point
    ///   face whose vertex has no edges;
    /// - every live vertex's stored edge is incident, its ring closes, every ring use leaves it;
    ///   a vertex without a stored edge has no edges.
    ///
    /// Every walk is bounded by `2 × edges + 1` steps.
    pub fn check(&self) -> Result<(), WingedError> {
        self.check_sizes()?;
        self.check_edges()?;
        self.check_faces()?;
        self.check_vertices()
    }

    fn check_sizes(&self) -> Result<(), WingedError> {
        let nv = self.positions.len();
        let nf = self.face_edge.len();
        if self.vertex_edge.len() != nv
            || self.vertex_alive.len() != nv
            || self.face_alive.len() != nf
        {
            return Err(broken(
                "arrays".into(),
                "per-element arrays differ in length",
            ));
        }
        let live_v = self.vertex_alive.iter().filter(|&&a| a).count();
        let live_f = self.face_alive.iter().filter(|&&a| a).count();
        let live_e = self.edges.iter().filter(|r| !r.is_deleted()).count();
        if live_v != self.n_live_vertices as usize
            || live_f != self.n_live_faces as usize
            || live_e != self.n_live_edges as usize
        {
            return Err(broken(
                "counts".into(),
                "live counts disagree with the records",
            ));
        }
        Ok(())
    }

    fn check_edges(&self) -> Result<(), WingedError> {
        for e in self.edges() {
            let r = self.rec(e);
            let name = |side: Option<Side>| match side {
                None => e.to_string(),
                Some(s) => format!("{e} ({s:?} side)"),
            };
            if !self.is_vertex(r.start) || !self.is_vertex(r.end) {
                return Err(broken(name(None), "endpoint is not a live vertex"));
            }
            if r.start == r.end {
                return Err(broken(name(None), "edge joins a vertex to itself"));
            }
            for side in [Side::Left, Side::Right] {
                let u = EdgeUse::new(e, side);
                let f = r.face(side);
                if f.is_valid() && !self.is_face(f) {
                    return Err(broken(name(Some(side)), "face is neither live nor a hole"));
                }
                if !self.is_edge(r.next(side)) || !self.is_edge(r.prev(side)) {
                    return Err(broken(name(Some(side)), "wing is not a live edge"));
                }
                let next = self
                    .use_next(u)
                    .ok_or_else(|| broken(name(Some(side)), "next wing does not leave the head"))?;
                let prev = self.use_prev(u).ok_or_else(|| {
                    broken(name(Some(side)), "previous wing does not reach the tail")
                })?;
                if self.use_prev(next) != Some(u) || self.use_next(prev) != Some(u) {
                    return Err(broken(name(Some(side)), "wings are not mutual"));
                }
                if self.face_of(next) != f || self.face_of(prev) != f {
                    return Err(broken(name(Some(side)), "loop changes face"));
                }
            }
        }
        Ok(())
    }

    fn check_faces(&self) -> Result<(), WingedError> {
        let mut sides_of_face = vec![0usize; self.face_edge.len()];
        for e in self.edges() {
            let r = self.rec(e);
            for f in [r.left_face, r.right_face] {
                if f.is_valid() {
                    sides_of_face[f.index()] += 1;
                }
            }
        }
        for &(f, v) in &self.point_faces {
            if !self.is_face(f) || self.face_edge[f.index()].is_valid() {
                return Err(broken(
                    f.to_string(),
                    "point face is not a live edgeless face",
                ));
            }
            if !self.is_vertex(v) || self.vertex_edge[v.index()].is_valid() {
                return Err(broken(v.to_string(), "point face vertex has edges"));
            }
        }
        for f in self.faces() {
            let name = || f.to_string();
            if !self.face_edge[f.index()].is_valid() {
                if self.point_face_vertex(f).is_none() || sides_of_face[f.index()] != 0 {
                    return Err(broken(name(), "face without an edge is not a point face"));
                }
                continue;
            }
            let start = self
                .face_first_use(f)
                .ok_or_else(|| broken(name(), "stored edge does not border it"))?;
            let length = self
                .closed_walk_length(start, |u| self.use_next(u))
                .ok_or_else(|| broken(name(), "loop does not close"))?;
            if length != sides_of_face[f.index()] {
                return Err(broken(name(), "loop misses some sides naming the face"));
            }
        }
        Ok(())
    }

    fn check_vertices(&self) -> Result<(), WingedError> {
        let mut degree = vec![0usize; self.positions.len()];
        for e in self.edges() {
            let r = self.rec(e);
            degree[r.start.index()] += 1;
            degree[r.end.index()] += 1;
        }
        for v in self.vertices() {
            let name = || v.to_string();
            let e: EdgeId = self.vertex_edge[v.index()];
            if !e.is_valid() {
                if degree[v.index()] != 0 {
                    return Err(broken(name(), "vertex with edges stores none"));
                }
                continue;
            }
            let start = self
                .vertex_first_use(v)
                .ok_or_else(|| broken(name(), "stored edge is not incident"))?;
            let mut leaves_v = true;
            let length = self.closed_walk_length(start, |u| {
                let after = self.use_prev(u).map(EdgeUse::twin);
                leaves_v &= after.is_some_and(|a| self.tail_of(a) == v);
                after
            });
            if length.is_none() || !leaves_v {
                return Err(broken(name(), "ring does not close around the vertex"));
            }
        }
        Ok(())
    }

    /// Steps from `start` until it comes back; the number of steps, or `None` if a step fails
    /// or the walk exceeds the bound.
    fn closed_walk_length(
        &self,
        start: EdgeUse,
        mut step: impl FnMut(EdgeUse) -> Option<EdgeUse>,
    ) -> Option<usize> {
        let mut here = start;
        for length in 1..=self.walk_bound() {
            here = step(here)?;
            if here == start {
                return Some(length);
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildPolicy, FaceList};
    use crate::winged::{FaceId, VertexId};

    /// A tetrahedron, faces counter-clockwise from outside.
    fn tetrahedron() -> Winged {
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let idx = [0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2];
        Winged::from_face_list(&FaceList::triangles(&p, &idx), BuildPolicy::Strict)
            .unwrap()
            .0
    }

    fn reason(w: &Winged) -> &'static str {
        match w.check() {
            Err(WingedError::InvariantViolated { reason, .. }) => reason,
            other => panic!("corruption not detected: {other:?}"),
        }
    }

    #[test]
    fn a_sound_structure_passes() {
        tetrahedron().check().unwrap();
    }

    #[test]
    fn corruptions_are_detected() {
        let mut w = tetrahedron();
        w.edges[0].left_next = w.edges[0].left_prev;
        assert!(!reason(&w).is_empty());

        let mut w = tetrahedron();
        w.edges[1].left_next = EdgeId(99);
        assert_eq!(reason(&w), "wing is not a live edge");

        let mut w = tetrahedron();
        w.edges[2].right_face = FaceId(0);
        assert!(!reason(&w).is_empty());

        let mut w = tetrahedron();
        let far = w
            .edges()
            .find(|&e| w.rec(e).side_leaving(VertexId(0)).is_none())
            .unwrap();
        w.vertex_edge[0] = far;
        assert!(!reason(&w).is_empty());

        let mut w = tetrahedron();
        w.n_live_edges += 1;
        assert_eq!(reason(&w), "live counts disagree with the records");

        let mut w = tetrahedron();
        w.edges[3].end = w.edges[3].start;
        assert!(!reason(&w).is_empty());

        let mut w = tetrahedron();
        w.face_edge[1] = EdgeId::INVALID;
        assert_eq!(reason(&w), "face without an edge is not a point face");
    }
}
