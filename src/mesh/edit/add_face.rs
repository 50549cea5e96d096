//! Adding one face to an existing mesh (OpenMesh's and pmp's `add_face`).

use super::{EditError, refuse};
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

const ADD_FACE: &str = "add face";

/// What [`Mesh::add_face`] found before touching the mesh.
struct Plan {
    /// The half-edge from corner `i` to corner `i + 1`, if it exists already.
    existing: Vec<Option<HalfedgeId>>,
    /// `next` links that reopen gaps at vertices where two existing sides meet but are not
    /// consecutive on the boundary (moving the patch between them elsewhere around the vertex).
    relinks: Vec<(HalfedgeId, HalfedgeId)>,
}

impl Mesh {
    /// Adds the face with corners `vertices` (counter-clockwise seen from outside, at least 3,
    /// all distinct, live) and returns its id. Sides that exist already as boundary half-edges
    /// are used; the others are new edges. Vertices keep a boundary outgoing half-edge. The
    /// face, its new edges and its corners have zero attributes; its loop starts at the first
    /// corner ([`Mesh::face_vertices`] lists `vertices` in order).
    ///
    /// Refused, with the mesh unchanged, when: fewer than 3 corners; a corner repeats; an id is
    /// invalid or deleted; a side exists with a face on this side already (a complex edge); a
    /// corner is an interior vertex (no gap left for the face), or its one-ring cannot be
    /// relinked to fit the face between two of its existing sides (a complex vertex); a corner
    /// has several fans the one-ring walk does not link (as a build with non-manifold vertices
    /// leaves them; checked by a linear scan, only while the mesh may have such vertices); or
    /// 32-bit ids run out.
    pub fn add_face(&mut self, vertices: &[VertexId]) -> Result<FaceId, EditError> {
        let plan = self.plan_face(vertices)?;
        Ok(self.link_face(vertices, plan))
    }

    /// Checks every precondition of [`Mesh::add_face`] and finds the sides that exist and the
    /// relinking needed, without changing anything.
    fn plan_face(&self, vertices: &[VertexId]) -> Result<Plan, EditError> {
        let n = vertices.len();
        if n < 3 {
            return refuse(ADD_FACE, "a face needs at least 3 corners");
        }
        for &v in vertices {
            self.check_vertex(v)?;
        }
        let repeats = (0..n).any(|i| vertices[i + 1..].contains(&vertices[i]));
        if repeats {
            return refuse(ADD_FACE, "a corner is repeated");
        }
        let new_edges = n as u64;
        if self.origin.len() as u64 + 2 * new_edges >= u64::from(u32::MAX)
            || self.face_halfedge.len() as u64 + 1 >= u64::from(u32::MAX)
        {
            return Err(EditError::Full {
                operation: ADD_FACE,
            });
        }

        let mut existing = Vec::with_capacity(n);
        for (i, &v) in vertices.iter().enumerate() {
            let h = self.vertex_halfedge(v);
            if h.is_valid() && !self.is_boundary_halfedge(h) {
                return refuse(ADD_FACE, "a corner is an interior vertex (complex vertex)");
            }
            if self.may_have_pinched_vertices && h.is_valid() && self.fan_misses_halfedges(v) {
                return refuse(
                    ADD_FACE,
                    "a corner has several fans that its one-ring does not link",
                );
            }
            let side = self.find_halfedge(v, vertices[(i + 1) % n]);
            if side.is_some_and(|h| !self.is_boundary_halfedge(h)) {
                return refuse(
                    ADD_FACE,
                    "a side has a face on this side already (complex edge)",
                );
            }
            existing.push(side);
        }

        let mut relinks = Vec::new();
        for i in 0..n {
            let (Some(inner_prev), Some(inner_next)) = (existing[i], existing[(i + 1) % n]) else {
                continue;
            };
            if self.next(inner_prev) == inner_next {
                continue;
            }
            // The patch of faces between the two sides must move to another gap of the vertex:
            // find a boundary half-edge coming into it, walking round from `inner_next` away
            // from the patch. The walk meets the patch only after `inner_prev`; a gap found
            // there would take the patch into itself, leaving it a fan of its own that the
            // vertex's one-ring does not reach.
            let mut boundary_prev = inner_next.twin();
            let mut steps = 0usize;
            loop {
                boundary_prev = self.next(boundary_prev).twin();
                steps += 1;
                if steps > self.n_halfedge_slots() {
                    return refuse(ADD_FACE, "a corner's one-ring does not close");
                }
                if boundary_prev == inner_prev {
                    return refuse(
                        ADD_FACE,
                        "a corner's one-ring cannot be relinked around the face (complex vertex)",
                    );
                }
                if self.is_boundary_halfedge(boundary_prev) {
                    break;
                }
            }
            let boundary_next = self.next(boundary_prev);
            let (patch_start, patch_end) = (self.next(inner_prev), self.prev(inner_next));
            relinks.extend([
                (boundary_prev, patch_start),
                (patch_end, boundary_next),
                (inner_prev, inner_next),
            ]);
        }
        Ok(Plan { existing, relinks })
    }

    /// Creates the missing edges and the face and links everything (preconditions checked).
    fn link_face(&mut self, vertices: &[VertexId], plan: Plan) -> FaceId {
        let n = vertices.len();
        let is_new: Vec<bool> = plan.existing.iter().map(Option::is_none).collect();
        let mut sides = Vec::with_capacity(n);
        for (i, side) in plan.existing.iter().enumerate() {
            sides.push(match *side {
                Some(h) => h,
                None => {
                    let h = self
                        .push_edge(ADD_FACE)
                        .expect("capacity checked in plan_face");
                    self.origin[h.index()] = vertices[i].0;
                    self.origin[h.twin().index()] = vertices[(i + 1) % n].0;
                    h
                }
            });
        }
        let f = self
            .push_face(sides[0], ADD_FACE)
            .expect("capacity checked in plan_face");

        let mut links = plan.relinks;
        let mut needs_adjust = Vec::new();
        for i in 0..n {
            let j = (i + 1) % n;
            let v = vertices[j];
            let (inner_prev, inner_next) = (sides[i], sides[j]);
            let (outer_prev, outer_next) = (inner_next.twin(), inner_prev.twin());
            match (is_new[i], is_new[j]) {
                (true, false) => {
                    // The new side comes in beside an existing boundary half-edge leaving `v`.
                    links.push((self.prev(inner_next), outer_next));
                    self.vertex_halfedge[v.index()] = outer_next.0;
                }
                (false, true) => {
                    links.push((outer_prev, self.next(inner_prev)));
                    self.vertex_halfedge[v.index()] = self.next(inner_prev).0;
                }
                (true, true) => {
                    let current = self.vertex_halfedge(v);
                    if current.is_valid() {
                        // `v` has a gap already: the new sides open a second one beside it.
                        links.push((self.prev(current), outer_next));
                        links.push((outer_prev, current));
                    } else {
                        self.vertex_halfedge[v.index()] = outer_next.0;
                        links.push((outer_prev, outer_next));
                    }
                }
                (false, false) => {
                    needs_adjust.push((v, self.vertex_halfedge(v) == inner_next));
                }
            }
            if is_new[i] || is_new[j] {
                links.push((inner_prev, inner_next));
            }
            self.face[inner_prev.index()] = f.0;
        }
        for (a, b) in links {
            self.link(a, b);
        }
        for (v, stored_side_taken) in needs_adjust {
            if stored_side_taken {
                self.adjust_outgoing_halfedge(v);
            }
        }
        for &h in &sides {
            self.reset_halfedge_attributes(h);
        }
        f
    }
}
