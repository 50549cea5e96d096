//! Construction from an indexed face list: the classic construction ("Creación a partir de malla
//! indexada" in the Granada notes), on the shared face-list analysis of [`crate::soup`].
//!
//! The construction reads the faces in order and, for every consecutive corner pair `(a, b)`, either
//! finds the edge `(b, a)` already made (the face becomes its inverse face, `Ci`) or appends a
//! new edge `a → b` (the face becomes its direct face, `Cd`); then it fills the wings. The
//! "does `(b, a)` exist" lookup is the expensive part; here every corner meets its edge in the
//! edge buckets of [`crate::soup`] (shared with the half-edge builder, with the same
//! [`BuildPolicy`] handling), so the construction runs in one linear pass. Edges are numbered in
//! the order the construction creates them, so the result is exactly its table.

use std::collections::HashMap;

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, FaceId, Side, VertexId};
use super::record::EdgeRecord;
use super::structure::Winged;
use crate::soup::{
    BuildError, BuildPolicy, DegenerateFaces, Diagnostic, EdgeBuckets, EdgeVisit, FaceList,
    FaceTable, Pinched, Unreached, Walked, build_splitting_pinched, face_edges, walk_faces,
};
use crate::support::large_arrays;
use crate::support::rare_hits::rare_hits;

impl Winged {
    /// Builds the structure from an indexed face list under `policy`, with the same analysis,
    /// policies and [`Diagnostic`] as [`Mesh::from_face_list`](crate::mesh::Mesh::from_face_list)
    /// (see [`BuildPolicy`]): refused input gives a [`BuildError`] carrying the diagnostic.
    ///
    /// Input vertex `i` is vertex `i` (repair's copies follow, see
    /// [`Diagnostic::vertex_copies`]); face `f` is input face `f` unless faces were skipped.
    /// Edges are numbered in order of first appearance walking the faces in order (face 0's
    /// corners first); an edge points the way its first face walks it, so that face is its left
    /// face (Granada's `Cd`) and the second face its right face (`Ci`). A face stores the edge
    /// leaving its first corner, so its loop starts where the input's face started. A vertex
    /// stores, by preference: the lowest-numbered edge whose side leaving it is a hole (boundary
    /// vertices, so that the ring starts at the gap), else the lowest-numbered edge starting at
    /// it (the edge of its first corner in face order), else the lowest-numbered edge ending at
    /// it (only after [`Winged::from_face_list_with_edge_order`] reverses edges).
    /// Unreferenced vertices are kept, without edges, and reported as isolated; vertices where
    /// several fans of faces touch are kept and reported as non-manifold.
    ///
    /// These rules are both kernels': [`Mesh::from_face_list`](crate::mesh::Mesh::from_face_list)
    /// numbers edges, starts faces and chooses vertex half-edges the same way, so
    /// [`Winged::to_mesh`] of this structure is the mesh it builds from the same list, array for
    /// array, and [`Winged::from_mesh`] of that mesh is this structure, record for record.
    pub fn from_face_list(
        list: &FaceList<'_>,
        policy: BuildPolicy,
    ) -> Result<(Self, Diagnostic), BuildError> {
        build_splitting_pinched(|route| {
            let Walked {
                walked,
                table,
                positions,
                deleted_vertices,
                diagnostic,
            } = walk_faces(list, policy, route, WingedFaces::walk)?;
            // Every corner walks one side of an edge; when they cover both sides of every edge
            // there is no hole, and the passes over all edges for holes are skipped.
            let has_holes = 2 * walked.edges.len() > table.n_corners();
            let mut w = walked.into_winged(positions, has_holes);
            if has_holes {
                w.link_boundary_loops();
            }
            w.may_have_pinched_vertices = !w.non_manifold_vertices().is_empty();
            for &v in &deleted_vertices {
                w.vertex_alive[v as usize] = false;
                w.n_live_vertices -= 1;
            }
            Ok((w, diagnostic))
        })
    }

    /// Builds the structure from an indexed face list, numbering and directing the edges as
    /// `edge_order` lists them (`edge_order[i] = [start, end]` of edge `i`).
    ///
    /// This reproduces tables whose edge numbering was made by hand (as textbook
    /// tables are). `edge_order` must list every edge of the faces exactly once, in either
    /// direction; the face that walks an edge `start → end` becomes its left face. The faces
    /// are built under [`BuildPolicy::Strict`] (a hand-made numbering names the input's own
    /// edges); refused input gives [`WingedError::InvalidFaceList`] with the diagnostic.
    pub fn from_face_list_with_edge_order(
        list: &FaceList<'_>,
        edge_order: &[[u32; 2]],
    ) -> Result<Self, WingedError> {
        let (mut w, _) = Self::from_face_list(list, BuildPolicy::Strict)?;
        w.renumber_edges(edge_order)?;
        w.choose_vertex_edges();
        Ok(w)
    }

    /// Applies a caller's edge numbering and directions (see
    /// [`Winged::from_face_list_with_edge_order`]).
    fn renumber_edges(&mut self, edge_order: &[[u32; 2]]) -> Result<(), WingedError> {
        let mismatch = |reason: String| WingedError::EdgeOrderMismatch { reason };
        if edge_order.len() != self.edges.len() {
            return Err(mismatch(format!(
                "{} edges listed, the faces have {}",
                edge_order.len(),
                self.edges.len()
            )));
        }
        let undirected = |a: u32, b: u32| (a.min(b), a.max(b));
        let old_of_key: HashMap<(u32, u32), u32> = self
            .edges
            .iter()
            .enumerate()
            .map(|(old, r)| (undirected(r.start.0, r.end.0), old as u32))
            .collect();
        let mut new_of_old = vec![EdgeId::INVALID; self.edges.len()];
        let mut reversed = vec![false; self.edges.len()];
        for (new, &[a, b]) in edge_order.iter().enumerate() {
            let old = *old_of_key
                .get(&undirected(a, b))
                .ok_or_else(|| mismatch(format!("({a}, {b}) is not an edge of the faces")))?
                as usize;
            if new_of_old[old].is_valid() {
                return Err(mismatch(format!("({a}, {b}) is listed twice")));
            }
            new_of_old[old] = EdgeId(new as u32);
            reversed[old] = self.edges[old].start.0 != a;
        }

        let remap = |e: EdgeId| {
            if e.is_valid() {
                new_of_old[e.index()]
            } else {
                e
            }
        };
        let mut edges =
            vec![EdgeRecord::unlinked(VertexId::INVALID, VertexId::INVALID); self.edges.len()];
        for (old, mut r) in self.edges.iter().copied().enumerate() {
            if reversed[old] {
                r.reverse();
            }
            for wing in [
                &mut r.left_prev,
                &mut r.left_next,
                &mut r.right_prev,
                &mut r.right_next,
            ] {
                *wing = remap(*wing);
            }
            edges[new_of_old[old].index()] = r;
        }
        self.edges = edges;
        for e in &mut self.face_edge {
            *e = remap(*e);
        }
        Ok(())
    }

    /// Links the hole side of every boundary edge into its boundary loop, so boundary walks work
    /// like face walks. Runs on a fresh build, where holes are always on the right side.
    fn link_boundary_loops(&mut self) {
        let bound = self.walk_bound();
        for e in 0..self.edges.len() as u32 {
            if self.edges[e as usize].right_face.is_valid() {
                continue;
            }
            // The hole walks e from end to start, arriving at `a = start`. Its successor is the
            // next boundary edge met rotating about `a` through the faces of e's fan: step to
            // the previous edge of the face (arriving at `a`) and cross it, until its other
            // side is a hole. Rotating within the fan keeps non-manifold vertices (two fans
            // touching) correct: each fan's gap is closed by its own boundary edges.
            let hole = EdgeUse::new(EdgeId(e), Side::Right);
            let mut around = EdgeUse::new(EdgeId(e), Side::Left);
            for _ in 0..bound {
                let Some(arriving) = self.use_prev(around) else {
                    break;
                };
                let leaving = arriving.twin();
                if !self.face_of(leaving).is_valid() {
                    self.link(hole, leaving);
                    break;
                }
                around = leaving;
            }
        }
    }

    /// Chooses every vertex's stored edge by the rule documented on
    /// [`Winged::from_face_list`], in one pass over the edges.
    pub(crate) fn choose_vertex_edges(&mut self) {
        let mut choice = VertexEdgeChoice::new(self.positions.len());
        for (e, r) in self.edges.iter().enumerate() {
            if !r.is_deleted() {
                choice.offer_holes(e, r);
                choice.offer_ends(e, r);
            }
        }
        self.vertex_edge = choice.chosen;
    }
}

/// The vertex edge rule of [`Winged::from_face_list`], fed edge by edge: a better kind of edge
/// replaces the one chosen so far, an equal kind does not, so offering each kind in increasing
/// edge order keeps the lowest-numbered edge of the best kind.
struct VertexEdgeChoice {
    chosen: Vec<EdgeId>,
    kind: Vec<u8>,
}

impl VertexEdgeChoice {
    const NONE: u8 = 0;
    const ENDS_HERE: u8 = 1;
    const STARTS_HERE: u8 = 2;
    const BORDERS_HOLE: u8 = 3;

    fn new(n_vertices: usize) -> Self {
        VertexEdgeChoice {
            chosen: vec![EdgeId::INVALID; n_vertices],
            kind: vec![Self::NONE; n_vertices],
        }
    }

    #[inline]
    fn offer(&mut self, v: VertexId, e: usize, kind: u8) {
        if self.kind[v.index()] < kind {
            self.kind[v.index()] = kind;
            self.chosen[v.index()] = EdgeId(e as u32);
        }
    }

    /// Offers edge `e` to the vertices it starts and ends at.
    #[inline]
    fn offer_ends(&mut self, e: usize, r: &EdgeRecord) {
        self.offer(r.start, e, Self::STARTS_HERE);
        self.offer(r.end, e, Self::ENDS_HERE);
    }

    /// Offers edge `e` to the vertices its hole sides leave from.
    fn offer_holes(&mut self, e: usize, r: &EdgeRecord) {
        for side in [Side::Left, Side::Right] {
            if !r.face(side).is_valid() {
                self.offer(r.tail(side), e, Self::BORDERS_HOLE);
            }
        }
    }
}

impl Pinched for Winged {
    fn has_pinched_vertices(&self) -> bool {
        self.may_have_pinched_vertices
    }
}

impl Unreached for WingedFaces {
    /// A vertex of a walked face was offered the edges that start and end at it.
    fn unreached_vertices(&self) -> Vec<u32> {
        let kind = &self.vertex_edges.kind;
        rare_hits(kind, 0, |&k| k == VertexEdgeChoice::NONE)
    }
}

/// The edge records and face edges of the construction's loop, before holes and vertices are linked.
struct WingedFaces {
    edges: Vec<EdgeRecord>,
    face_edge: Vec<EdgeId>,
    /// The vertex edges by start and end, offered as the edges are made (holes are known only
    /// after the walk).
    vertex_edges: VertexEdgeChoice,
}

impl WingedFaces {
    /// The construction's loop: creates the edge records in its order and fills faces and wings of the
    /// face sides, in one pass over the faces, each corner meeting its edge in `buckets`, each
    /// face's area checked into `degenerate` when given. `None` on an edge defect (see
    /// [`EdgeVisit::Defective`]).
    fn walk(
        table: &FaceTable<'_>,
        buckets: &mut EdgeBuckets,
        positions: &[[f64; 3]],
        mut degenerate: Option<&mut DegenerateFaces<'_>>,
    ) -> Option<WingedFaces> {
        // At most one edge per corner, and at least one per two; fitted to the count afterwards.
        let mut edges: Vec<EdgeRecord> =
            large_arrays::with_capacity_written(table.n_corners(), table.n_corners() / 2);
        let mut face_edge = large_arrays::with_capacity_written(table.n_faces(), table.n_faces());
        let mut loop_edges: Vec<EdgeId> = Vec::new();
        let mut vertex_edges = VertexEdgeChoice::new(positions.len());
        let mut buckets = buckets.visitor();
        for (f, corners) in table.faces().enumerate() {
            let face = FaceId(f as u32);
            buckets.prefetch_ahead_of(table, f);
            if let Some(degenerate) = degenerate.as_deref_mut() {
                degenerate.check(table, f, corners);
            }
            loop_edges.clear();
            for (a, b) in face_edges(corners) {
                // Edge ids stay below the corner count, so they fit an edge's value.
                let e = match buckets.visit(a, b, edges.len() as u32) {
                    EdgeVisit::Opened => {
                        // First face to walk this edge: a new edge, walked forward (the slide's
                        // Cd).
                        let mut r = EdgeRecord::unlinked(VertexId(a), VertexId(b));
                        r.left_face = face;
                        vertex_edges.offer_ends(edges.len(), &r);
                        edges.push(r);
                        edges.len() - 1
                    }
                    EdgeVisit::Paired(e) => {
                        // The edge exists: this face walks it backward (the slide's Ci).
                        edges[e as usize].right_face = face;
                        e as usize
                    }
                    EdgeVisit::Defective => return None,
                };
                loop_edges.push(EdgeId(e as u32));
            }
            // "Recorrer aristas y rellenar enlaces": the face's edges are still in cache.
            let mut prev = loop_edges[loop_edges.len() - 1];
            let following = loop_edges.iter().skip(1).chain(&loop_edges[..1]);
            for ((&e, &next), &corner) in loop_edges.iter().zip(following).zip(corners) {
                let r = &mut edges[e.index()];
                let side = if r.left_face == face && r.start.0 == corner {
                    Side::Left
                } else {
                    Side::Right
                };
                r.set_prev(side, prev);
                r.set_next(side, next);
                prev = e;
            }
            face_edge.push(loop_edges[0]);
        }
        Some(WingedFaces {
            edges,
            face_edge,
            vertex_edges,
        })
    }

    /// The structure of the walked faces over vertices at `positions` (its holes not yet linked
    /// into loops).
    fn into_winged(self, positions: Vec<[f64; 3]>, has_holes: bool) -> Winged {
        let WingedFaces {
            edges,
            face_edge,
            mut vertex_edges,
        } = self;
        if has_holes {
            // Hole sides come first in the vertex edge rule; ends were offered by the walk.
            for (e, r) in edges.iter().enumerate() {
                vertex_edges.offer_holes(e, r);
            }
        }
        let (n_faces, n_vertices) = (face_edge.len(), positions.len());
        let n_edges = edges.len();
        let edges = large_arrays::fit(edges, n_edges);
        let face_edge = large_arrays::fit(face_edge, n_faces);
        Winged {
            positions,
            vertex_edge: vertex_edges.chosen,
            vertex_alive: vec![true; n_vertices],
            face_edge,
            face_alive: vec![true; n_faces],
            n_live_vertices: n_vertices as u32,
            n_live_edges: edges.len() as u32,
            n_live_faces: n_faces as u32,
            edges,
            point_faces: Vec::new(),
            // Decided by the caller once the rings are complete.
            may_have_pinched_vertices: true,
        }
    }
}
