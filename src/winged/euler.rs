//! Baumgart's Euler operators: MVFS, MEV, MEF and their inverses KVFS, KEV, KEF.
//!
//! Each operator changes V, E and F so that V − E + F is unchanged (MVFS adds a solid:
//! +1 vertex, +1 face). Every precondition is checked before anything is touched, so a refused
//! operator leaves the structure exactly as it was.

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, FaceId, Side, VertexId};
use super::record::EdgeRecord;
use super::structure::Winged;

/// Largest element count a `u32` id can name (`u32::MAX` is the invalid id).
const MAX_ELEMENTS: u64 = u32::MAX as u64 - 1;

impl Winged {
    /// **Make vertex, face, solid**: a new solid made of one vertex at `position` and one face
    /// with no edges (a *point face*). Returns the vertex and the face.
    pub fn mvfs(&mut self, position: [f64; 3]) -> Result<(VertexId, FaceId), WingedError> {
        require_finite(position, self.n_vertex_slots())?;
        self.require_room(1, 0, 1)?;
        let v = self.push_vertex(position);
        let f = self.push_face(EdgeId::INVALID);
        self.point_faces.push((f, v));
        Ok((v, f))
    }

    /// **Make edge, vertex**: a new vertex at `position` joined to `vertex` by a new edge
    /// `vertex → new vertex` lying inside `face` (both sides of the new edge are `face`).
    ///
    /// `vertex` must occur exactly once on `face`'s loop (or be the vertex of a point face); the
    /// new edge is inserted there. Returns the new edge and vertex.
    pub fn mev(
        &mut self,
        face: FaceId,
        vertex: VertexId,
        position: [f64; 3],
    ) -> Result<(EdgeId, VertexId), WingedError> {
        self.require_face(face)?;
        self.require_vertex(vertex)?;
        require_finite(position, self.n_vertex_slots())?;
        let is_point_face = match self.point_face_vertex(face) {
            Some(v) if v == vertex => true,
            Some(_) => return Err(WingedError::VertexNotOnFace { vertex, face }),
            None => false,
        };
        let arriving = if is_point_face {
            None
        } else {
            Some(self.corner(face, vertex)?)
        };
        self.require_room(1, 1, 0)?;

        let w = self.push_vertex(position);
        let mut r = EdgeRecord::unlinked(vertex, w);
        r.left_face = face;
        r.right_face = face;
        let e = self.push_edge(r);
        let (down, up) = (EdgeUse::new(e, Side::Left), EdgeUse::new(e, Side::Right));
        self.link(down, up); // turn round at the new vertex
        self.vertex_edge[w.index()] = e;
        match arriving {
            Some(arriving) => {
                let leaving = self.use_next(arriving).ok_or_else(corrupted)?;
                self.link(arriving, down);
                self.link(up, leaving);
            }
            None => {
                self.link(up, down);
                self.point_faces.retain(|&(f, _)| f != face);
                self.face_edge[face.index()] = e;
                self.vertex_edge[vertex.index()] = e;
            }
        }
        Ok((e, w))
    }

    /// **Make edge, face**: splits `face` with a new edge `v1 → v2`. The new face is the
    /// left side of the new edge (the part of the loop from `v2` back to `v1`); `face` keeps the
    /// part from `v1` to `v2`. Returns the new edge and face.
    ///
    /// `v1` and `v2` must differ and each occur exactly once on `face`'s loop.
    pub fn mef(
        &mut self,
        face: FaceId,
        v1: VertexId,
        v2: VertexId,
    ) -> Result<(EdgeId, FaceId), WingedError> {
        self.require_face(face)?;
        self.require_vertex(v1)?;
        self.require_vertex(v2)?;
        if v1 == v2 {
            return Err(WingedError::SelfLoop(v1));
        }
        let a_in = self.corner(face, v1)?;
        let b_in = self.corner(face, v2)?;
        self.require_room(0, 1, 1)?;
        let a_out = self.use_next(a_in).ok_or_else(corrupted)?;
        let b_out = self.use_next(b_in).ok_or_else(corrupted)?;

        let e = self.push_edge(EdgeRecord::unlinked(v1, v2));
        let g = self.push_face(e);
        self.set_loop_face(b_out, a_in, g)?;
        let (forward, backward) = (EdgeUse::new(e, Side::Left), EdgeUse::new(e, Side::Right));
        let r = &mut self.edges[e.index()];
        r.left_face = g;
        r.right_face = face;
        self.link(a_in, forward);
        self.link(forward, b_out);
        self.link(b_in, backward);
        self.link(backward, a_out);
        if self.face_first_use(face).is_none() {
            self.face_edge[face.index()] = e;
        }
        Ok((e, g))
    }

    /// **Kill edge, vertex**: removes `vertex` and its only edge `edge` (the inverse of MEV).
    /// When `edge` was the solid's last edge, its face becomes a point face on the other vertex.
    ///
    /// Refused with [`WingedError::VertexNotDangling`] when `vertex` has another edge, in its
    /// ring or in another fan of a pinched vertex; and with
    /// [`WingedError::PointFaceAtSharedVertex`] when `edge` is its solid's last edge but the
    /// other vertex has edges in another fan (a point face's vertex has no edges).
    pub fn kev(&mut self, edge: EdgeId, vertex: VertexId) -> Result<(), WingedError> {
        self.require_vertex(vertex)?;
        let r = *self.edge(edge)?;
        let side = r.side_leaving(vertex).ok_or(WingedError::NotIncident {
            edge,
            what: "vertex",
        })?;
        // `vertex` dangles when its loop comes in along `edge` and turns straight back (its ring
        // is `edge` alone) and it has no edge outside that ring.
        if r.prev(side) != edge || self.has_edge_outside_ring(vertex, edge) {
            return Err(WingedError::VertexNotDangling { vertex, edge });
        }
        let leaving = EdgeUse::new(edge, side);
        let other = r.head(side);
        let face = r.face(side);
        let last_edge = r.next(side) == edge;
        // The last edge's other end is in the same position: its ring is `edge` alone.
        if last_edge && self.has_edge_outside_ring(other, edge) {
            return Err(WingedError::PointFaceAtSharedVertex {
                edge,
                vertex: other,
            });
        }
        if last_edge {
            // The edge is its solid's only edge: leave a point face behind.
            self.vertex_edge[other.index()] = EdgeId::INVALID;
            if face.is_valid() {
                self.face_edge[face.index()] = EdgeId::INVALID;
                self.point_faces.push((face, other));
            }
        } else {
            let before = self.use_prev(leaving.twin()).ok_or_else(corrupted)?;
            let after = self.use_next(leaving).ok_or_else(corrupted)?;
            self.link(before, after);
            if face.is_valid() && self.face_edge[face.index()] == edge {
                self.face_edge[face.index()] = after.edge;
            }
            if self.vertex_edge[other.index()] == edge {
                self.vertex_edge[other.index()] = after.edge;
            }
        }
        self.delete_edge(edge);
        self.delete_vertex(vertex);
        Ok(())
    }

    /// **Kill edge, face**: removes `edge` and merges the face `kill` on one of its sides into
    /// the face on the other side (the inverse of MEF). The two sides must be different faces.
    pub fn kef(&mut self, edge: EdgeId, kill: FaceId) -> Result<(), WingedError> {
        let r = *self.edge(edge)?;
        self.require_face(kill)?;
        if r.left_face == r.right_face || !r.left_face.is_valid() || !r.right_face.is_valid() {
            return Err(WingedError::EdgeNotBetweenTwoFaces(edge));
        }
        let kill_side = if r.left_face == kill {
            Side::Left
        } else if r.right_face == kill {
            Side::Right
        } else {
            return Err(WingedError::NotIncident { edge, what: "face" });
        };
        let keep = r.face(kill_side.opposite());
        let (in_kill, in_keep) = (
            EdgeUse::new(edge, kill_side),
            EdgeUse::new(edge, kill_side.opposite()),
        );
        let kill_after = self.use_next(in_kill).ok_or_else(corrupted)?;
        let kill_before = self.use_prev(in_kill).ok_or_else(corrupted)?;
        let keep_after = self.use_next(in_keep).ok_or_else(corrupted)?;
        let keep_before = self.use_prev(in_keep).ok_or_else(corrupted)?;

        self.set_loop_face(kill_after, kill_before, keep)?;
        self.link(keep_before, kill_after);
        self.link(kill_before, keep_after);
        if self.face_edge[keep.index()] == edge {
            self.face_edge[keep.index()] = keep_after.edge;
        }
        for (vertex, replacement) in [
            (r.head(kill_side), kill_after),
            (r.tail(kill_side), keep_after),
        ] {
            if self.vertex_edge[vertex.index()] == edge {
                self.vertex_edge[vertex.index()] = replacement.edge;
            }
        }
        self.delete_edge(edge);
        self.face_alive[kill.index()] = false;
        self.face_edge[kill.index()] = EdgeId::INVALID;
        self.n_live_faces -= 1;
        Ok(())
    }

    /// **Kill vertex, face, solid**: removes a point solid (the inverse of MVFS): `face` must be
    /// a point face, whose one vertex goes with it.
    pub fn kvfs(&mut self, face: FaceId) -> Result<(), WingedError> {
        self.require_face(face)?;
        let vertex = self
            .point_face_vertex(face)
            .ok_or(WingedError::NotAPointFace(face))?;
        self.point_faces.retain(|&(f, _)| f != face);
        self.face_alive[face.index()] = false;
        self.n_live_faces -= 1;
        self.delete_vertex(vertex);
        Ok(())
    }

    /// Whether `vertex`, whose ring is `edge` alone, has other edges (in other fans: only a
    /// pinched vertex can). Its stored edge is one of them unless it is `edge`; otherwise the
    /// edges are scanned, and only while the structure may have pinched vertices.
    fn has_edge_outside_ring(&self, vertex: VertexId, edge: EdgeId) -> bool {
        if self.vertex_edge[vertex.index()] != edge {
            return true;
        }
        self.may_have_pinched_vertices
            && self.edges().any(|e| {
                let r = self.rec(e);
                e != edge && (r.start == vertex || r.end == vertex)
            })
    }

    /// The one use of `face`'s loop that arrives at `vertex`.
    fn corner(&self, face: FaceId, vertex: VertexId) -> Result<EdgeUse, WingedError> {
        let mut found = None;
        for u in self.face_loop(face)? {
            if self.head_of(u) == vertex {
                if found.is_some() {
                    return Err(WingedError::AmbiguousCorner { vertex, face });
                }
                found = Some(u);
            }
        }
        found.ok_or(WingedError::VertexNotOnFace { vertex, face })
    }

    /// Gives every use from `first` to `last` (following the loop) the face `face`.
    fn set_loop_face(
        &mut self,
        first: EdgeUse,
        last: EdgeUse,
        face: FaceId,
    ) -> Result<(), WingedError> {
        let mut u = first;
        for _ in 0..self.walk_bound() {
            let after = self.use_next(u);
            self.edges[u.edge.index()].set_face(u.side, face);
            if u == last {
                return Ok(());
            }
            u = after.ok_or_else(corrupted)?;
        }
        Err(corrupted())
    }

    /// Refuses when adding the given numbers of elements would overflow the `u32` ids.
    fn require_room(&self, vertices: u64, edges: u64, faces: u64) -> Result<(), WingedError> {
        for (what, have, add) in [
            ("vertices", self.positions.len(), vertices),
            ("edges", self.edges.len(), edges),
            ("faces", self.face_edge.len(), faces),
        ] {
            let count = have as u64 + add;
            if count > MAX_ELEMENTS {
                return Err(WingedError::TooManyElements { what, count });
            }
        }
        Ok(())
    }

    fn push_vertex(&mut self, position: [f64; 3]) -> VertexId {
        let v = VertexId(self.positions.len() as u32);
        self.positions.push(position);
        self.vertex_edge.push(EdgeId::INVALID);
        self.vertex_alive.push(true);
        self.n_live_vertices += 1;
        v
    }

    fn push_face(&mut self, edge: EdgeId) -> FaceId {
        let f = FaceId(self.face_edge.len() as u32);
        self.face_edge.push(edge);
        self.face_alive.push(true);
        self.n_live_faces += 1;
        f
    }

    fn push_edge(&mut self, record: EdgeRecord) -> EdgeId {
        let e = EdgeId(self.edges.len() as u32);
        self.edges.push(record);
        self.n_live_edges += 1;
        e
    }

    fn delete_edge(&mut self, e: EdgeId) {
        self.edges[e.index()] = EdgeRecord::unlinked(VertexId::INVALID, VertexId::INVALID);
        self.n_live_edges -= 1;
    }

    fn delete_vertex(&mut self, v: VertexId) {
        self.vertex_alive[v.index()] = false;
        self.vertex_edge[v.index()] = EdgeId::INVALID;
        self.n_live_vertices -= 1;
    }
}

fn require_finite(position: [f64; 3], next_vertex: u32) -> Result<(), WingedError> {
    if position.iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(WingedError::NonFinitePosition {
            vertex: next_vertex,
        })
    }
}

/// A walk failed on a structure that passed every precondition: only a corrupted structure
/// (one [`Winged::check`] rejects) gets here.
fn corrupted() -> WingedError {
    WingedError::InvariantViolated {
        element: "loop".into(),
        reason: "a wing does not continue its loop",
    }
}
