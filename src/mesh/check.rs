//! Validation of every structural invariant, with bounded walks.

use std::fmt;

use super::Mesh;
use super::ids::{EdgeId, FaceId, HalfedgeId, INVALID_INDEX, VertexId};

/// A structural invariant of [`Mesh`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Invariant {
    /// The per-half-edge arrays have one even length; per-vertex and per-face arrays agree;
    /// deletion counts match the marks; attribute columns have one entry per element slot.
    ArrayLengths,
    /// A live half-edge's origin, next, prev and face are in range and live.
    HalfedgeReferences,
    /// `next(prev(h)) == h` and `prev(next(h)) == h`.
    NextPrevInverse,
    /// `face(next(h)) == face(h)`: a loop stays on one face (or on the outside).
    LoopOnOneFace,
    /// `origin(next(h)) == target(h)`, where `target(h) = origin(twin(h))`.
    LoopConnected,
    /// An edge has a face on at least one side.
    EdgeHasFace,
    /// `face_halfedge(f)` is a live half-edge of `f`.
    FaceHalfedge,
    /// Walking `next` from `face_halfedge(f)` returns to it within the half-edge count.
    FaceLoopClosed,
    /// The face loops together hold every half-edge that has a face.
    FaceLoopsCoverHalfedges,
    /// `vertex_halfedge(v)` is a live half-edge leaving `v`, or invalid for an isolated vertex.
    VertexHalfedge,
    /// A vertex with a boundary half-edge leaving it stores a boundary half-edge.
    VertexHalfedgeOnBoundary,
    /// A vertex stored as isolated has no half-edge leaving it.
    IsolatedVertexHasNoHalfedge,
    /// Walking `twin(prev(h))` around a vertex returns to `vertex_halfedge(v)` within the
    /// half-edge count.
    VertexFanClosed,
    /// No two edges join the same two vertices (nor an edge a vertex to itself).
    EdgesDistinct,
}

impl fmt::Display for Invariant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Invariant::ArrayLengths => "array lengths agree",
            Invariant::HalfedgeReferences => "half-edge references are in range and live",
            Invariant::NextPrevInverse => "next(prev(h)) == h and prev(next(h)) == h",
            Invariant::LoopOnOneFace => "face(next(h)) == face(h)",
            Invariant::LoopConnected => "origin(next(h)) == target(h)",
            Invariant::EdgeHasFace => "every edge has a face on one side",
            Invariant::FaceHalfedge => "face_halfedge(f) is a live half-edge of f",
            Invariant::FaceLoopClosed => "face loop closes",
            Invariant::FaceLoopsCoverHalfedges => "face loops hold every half-edge with a face",
            Invariant::VertexHalfedge => "vertex_halfedge(v) leaves v",
            Invariant::VertexHalfedgeOnBoundary => "a boundary vertex stores a boundary half-edge",
            Invariant::IsolatedVertexHasNoHalfedge => "an isolated vertex has no half-edge",
            Invariant::VertexFanClosed => "vertex fan closes",
            Invariant::EdgesDistinct => "no two edges join the same two vertices",
        })
    }
}

/// The element where an invariant was found broken.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Element {
    /// The mesh as a whole.
    Mesh,
    /// A vertex.
    Vertex(VertexId),
    /// A half-edge.
    Halfedge(HalfedgeId),
    /// An edge.
    Edge(EdgeId),
    /// A face.
    Face(FaceId),
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Element::Mesh => f.write_str("the mesh"),
            Element::Vertex(v) => write!(f, "{v}"),
            Element::Halfedge(h) => write!(f, "{h}"),
            Element::Edge(e) => write!(f, "{e}"),
            Element::Face(face) => write!(f, "{face}"),
        }
    }
}

/// The first broken invariant [`Mesh::check`] found, and where.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("invariant \"{invariant}\" broken at {element}")]
pub struct InvariantError {
    /// The broken invariant.
    pub invariant: Invariant,
    /// The element it was found broken at.
    pub element: Element,
}

fn fail<T>(invariant: Invariant, element: Element) -> Result<T, InvariantError> {
    Err(InvariantError { invariant, element })
}

impl Mesh {
    /// Checks every structural invariant (see [`Invariant`]) in linear time; every walk is
    /// bounded, so a corrupt structure gives an error, never an endless loop or a panic.
    pub fn check(&self) -> Result<(), InvariantError> {
        self.check_lengths()?;
        self.check_halfedges()?;
        self.check_faces()?;
        self.check_vertices()?;
        self.check_edges_distinct()
    }

    /// Half-edges grouped by origin (a counting sort), then each vertex's targets stamped: a
    /// target met twice is a second edge between the two vertices. Linear in the elements.
    fn check_edges_distinct(&self) -> Result<(), InvariantError> {
        let n_v = self.vertex_halfedge.len();
        let live =
            || (0..self.origin.len() as u32).filter(|&h| !self.is_halfedge_deleted(HalfedgeId(h)));
        let mut start = vec![0u32; n_v + 1];
        for h in live() {
            start[self.origin[h as usize] as usize + 1] += 1;
        }
        for v in 0..n_v {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut by_origin = vec![0u32; start[n_v] as usize];
        for h in live() {
            let slot = &mut fill[self.origin[h as usize] as usize];
            by_origin[*slot as usize] = h;
            *slot += 1;
        }
        let mut stamp = vec![INVALID_INDEX; n_v];
        for v in 0..n_v {
            for &h in &by_origin[start[v] as usize..start[v + 1] as usize] {
                let target = self.origin[h as usize ^ 1] as usize;
                if stamp[target] == v as u32 {
                    return fail(
                        Invariant::EdgesDistinct,
                        Element::Edge(HalfedgeId(h).edge()),
                    );
                }
                stamp[target] = v as u32;
            }
        }
        Ok(())
    }

    fn check_lengths(&self) -> Result<(), InvariantError> {
        let n_h = self.origin.len();
        let counted = |marks: &[bool]| marks.iter().filter(|&&m| m).count();
        let marks_fit = |marks: &[bool], len: usize| marks.is_empty() || marks.len() == len;
        let ok = n_h.is_multiple_of(2)
            && u32::try_from(n_h).is_ok_and(|n| n != INVALID_INDEX)
            && [self.next.len(), self.prev.len(), self.face.len()]
                .iter()
                .all(|&len| len == n_h)
            && self.positions.len() == self.vertex_halfedge.len()
            && marks_fit(&self.deleted.vertices, self.vertex_halfedge.len())
            && marks_fit(&self.deleted.edges, n_h / 2)
            && marks_fit(&self.deleted.faces, self.face_halfedge.len())
            && counted(&self.deleted.vertices) == self.deleted.n_vertices
            && counted(&self.deleted.edges) == self.deleted.n_edges
            && counted(&self.deleted.faces) == self.deleted.n_faces
            && self.attributes.fit([
                self.vertex_halfedge.len(),
                n_h,
                n_h / 2,
                self.face_halfedge.len(),
            ]);
        if ok {
            Ok(())
        } else {
            fail(Invariant::ArrayLengths, Element::Mesh)
        }
    }

    fn live_halfedge(&self, h: u32) -> bool {
        (h as usize) < self.origin.len() && !self.is_halfedge_deleted(HalfedgeId(h))
    }

    fn check_halfedges(&self) -> Result<(), InvariantError> {
        for h in 0..self.origin.len() as u32 {
            let id = HalfedgeId(h);
            if self.is_halfedge_deleted(id) {
                continue;
            }
            let hu = h as usize;
            let (origin, next, prev, face) =
                (self.origin[hu], self.next[hu], self.prev[hu], self.face[hu]);
            let face_ok = face == INVALID_INDEX
                || ((face as usize) < self.face_halfedge.len()
                    && !self.is_face_deleted(FaceId(face)));
            let origin_ok = (origin as usize) < self.vertex_halfedge.len()
                && !self.is_vertex_deleted(VertexId(origin));
            if !(origin_ok && face_ok && self.live_halfedge(next) && self.live_halfedge(prev)) {
                return fail(Invariant::HalfedgeReferences, Element::Halfedge(id));
            }
            if self.prev[next as usize] != h || self.next[prev as usize] != h {
                return fail(Invariant::NextPrevInverse, Element::Halfedge(id));
            }
            if self.face[next as usize] != face {
                return fail(Invariant::LoopOnOneFace, Element::Halfedge(id));
            }
            if self.origin[next as usize] != self.origin[hu ^ 1] {
                return fail(Invariant::LoopConnected, Element::Halfedge(id));
            }
            if h % 2 == 0 && face == INVALID_INDEX && self.face[hu ^ 1] == INVALID_INDEX {
                return fail(Invariant::EdgeHasFace, Element::Edge(id.edge()));
            }
        }
        Ok(())
    }

    fn check_faces(&self) -> Result<(), InvariantError> {
        let mut in_loops = 0usize;
        for f in 0..self.face_halfedge.len() as u32 {
            let id = FaceId(f);
            if self.is_face_deleted(id) {
                continue;
            }
            let h = self.face_halfedge[f as usize];
            if !self.live_halfedge(h) || self.face[h as usize] != f {
                return fail(Invariant::FaceHalfedge, Element::Face(id));
            }
            let mut walk = self.face_loop(id);
            for g in walk.by_ref() {
                if self.face[g.index()] != f {
                    return fail(Invariant::LoopOnOneFace, Element::Halfedge(g));
                }
                in_loops += 1;
            }
            if walk.was_cut_short() {
                return fail(Invariant::FaceLoopClosed, Element::Face(id));
            }
        }
        let with_face = (0..self.origin.len())
            .filter(|&h| {
                self.face[h] != INVALID_INDEX && !self.is_halfedge_deleted(HalfedgeId(h as u32))
            })
            .count();
        if in_loops != with_face {
            return fail(Invariant::FaceLoopsCoverHalfedges, Element::Mesh);
        }
        Ok(())
    }

    fn check_vertices(&self) -> Result<(), InvariantError> {
        // Per vertex: does some live half-edge leave it, and does a boundary one?
        let mut leaves = vec![0u8; self.vertex_halfedge.len()];
        const ANY: u8 = 1;
        const BOUNDARY: u8 = 2;
        for h in 0..self.origin.len() {
            if !self.is_halfedge_deleted(HalfedgeId(h as u32)) {
                let flag = if self.face[h] == INVALID_INDEX {
                    ANY | BOUNDARY
                } else {
                    ANY
                };
                leaves[self.origin[h] as usize] |= flag;
            }
        }
        for v in 0..self.vertex_halfedge.len() as u32 {
            let id = VertexId(v);
            if self.is_vertex_deleted(id) {
                continue;
            }
            let h = self.vertex_halfedge[v as usize];
            if h == INVALID_INDEX {
                if leaves[v as usize] & ANY != 0 {
                    return fail(Invariant::IsolatedVertexHasNoHalfedge, Element::Vertex(id));
                }
                continue;
            }
            if !self.live_halfedge(h) || self.origin[h as usize] != v {
                return fail(Invariant::VertexHalfedge, Element::Vertex(id));
            }
            if leaves[v as usize] & BOUNDARY != 0 && self.face[h as usize] != INVALID_INDEX {
                return fail(Invariant::VertexHalfedgeOnBoundary, Element::Vertex(id));
            }
            let mut walk = self.outgoing_halfedges(id);
            if let Some(g) = walk.by_ref().find(|g| self.origin[g.index()] != v) {
                return fail(Invariant::VertexHalfedge, Element::Halfedge(g));
            }
            if walk.was_cut_short() {
                return fail(Invariant::VertexFanClosed, Element::Vertex(id));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildPolicy, FaceList};

    /// Two triangles sharing edge 0-2, plus one isolated vertex.
    fn square() -> Mesh {
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [5.0; 3],
        ];
        let list = FaceList::triangles(&positions, &[0, 1, 2, 0, 2, 3]);
        Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0
    }

    fn broken(corrupt: impl FnOnce(&mut Mesh)) -> InvariantError {
        let mut mesh = square();
        assert_eq!(mesh.check(), Ok(()));
        corrupt(&mut mesh);
        mesh.check().unwrap_err()
    }

    /// Before: two edges between the same vertices passed the check (triangulate_face could
    /// make them).
    #[test]
    fn a_second_edge_between_two_vertices_is_found() {
        // Two triangles apart, 0-1-2 and 3-4-5; then vertices 3 and 5 renamed 0 and 2: edge
        // 3-5 becomes a second edge 0-2, each vertex keeping a fan of its own.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let list = FaceList::triangles(&positions, &[0, 1, 2, 3, 5, 4]);
        let mut mesh = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0;
        assert_eq!(mesh.check(), Ok(()));
        for origin in &mut mesh.origin {
            *origin = match *origin {
                3 => 0,
                5 => 2,
                v => v,
            };
        }
        mesh.vertex_halfedge[3] = INVALID_INDEX;
        mesh.vertex_halfedge[5] = INVALID_INDEX;
        let error = mesh.check().unwrap_err();
        assert_eq!(error.invariant, Invariant::EdgesDistinct, "{error}");
    }

    #[test]
    fn each_corruption_names_its_invariant() {
        let error = broken(|m| {
            m.next.pop();
        });
        assert_eq!(
            error,
            InvariantError {
                invariant: Invariant::ArrayLengths,
                element: Element::Mesh
            }
        );

        let error = broken(|m| m.next[0] = 999);
        assert_eq!(error.invariant, Invariant::HalfedgeReferences);
        assert_eq!(error.element, Element::Halfedge(HalfedgeId(0)));

        let error = broken(|m| m.prev.swap(0, 2));
        assert_eq!(error.invariant, Invariant::NextPrevInverse);

        let error = broken(|m| m.face[0] = 1);
        assert!(
            matches!(error.invariant, Invariant::LoopOnOneFace),
            "{error}"
        );

        let error = broken(|m| m.origin[0] = 3);
        assert!(
            matches!(error.invariant, Invariant::LoopConnected),
            "{error}"
        );

        let error = broken(|m| m.face_halfedge[1] = m.face_halfedge[0]);
        assert_eq!(
            error,
            InvariantError {
                invariant: Invariant::FaceHalfedge,
                element: Element::Face(FaceId(1))
            }
        );

        let error = broken(|m| {
            let v = m.origin[0] as usize;
            let interior = (0..m.origin.len())
                .find(|&h| m.origin[h] as usize == v && m.face[h] != INVALID_INDEX);
            m.vertex_halfedge[v] = interior.unwrap() as u32;
        });
        assert_eq!(error.invariant, Invariant::VertexHalfedgeOnBoundary);

        let error = broken(|m| m.vertex_halfedge[0] = INVALID_INDEX);
        assert_eq!(error.invariant, Invariant::IsolatedVertexHasNoHalfedge);

        let error = broken(|m| m.vertex_halfedge[4] = 0);
        assert_eq!(error.invariant, Invariant::VertexHalfedge);
        assert!(error.to_string().contains("vertex 4"), "{error}");
    }

    #[test]
    fn a_loop_that_never_closes_ends_the_walk() {
        // A face loop that cycles without passing its start: 3-cycle reached from a 4th half-edge
        // is impossible with next/prev inverse, so corrupt both to make the walk cycle.
        let mut mesh = square();
        let start = mesh.face_halfedge[0] as usize;
        let second = mesh.next[start] as usize;
        let third = mesh.next[second] as usize;
        mesh.next[third] = second as u32;
        let walk = mesh.face_loop(FaceId(0));
        assert!(walk.clone().count() <= mesh.n_halfedge_slots());
        let mut walk = walk;
        walk.by_ref().for_each(drop);
        assert!(walk.was_cut_short());
        assert!(mesh.check().is_err());
    }
}
