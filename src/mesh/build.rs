//! Bulk construction from an indexed face list.
//!
//! The faces are walked once, in order, and each corner meets its edge in
//! [`EdgeBuckets`](crate::soup::EdgeBuckets): the first corner on an edge opens edge `e`
//! (half-edge `2e`, its twin `2e + 1` starts out as a boundary half-edge), the second takes the
//! twin. Each face's loop is written as soon as its corners are known, so half-edges are
//! numbered in corner order and each face's half-edges sit close together in memory; the face's
//! area is checked in the walk or in a pass of its own, on a second thread when there is one
//! (degenerate faces are reported; `soup::front` chooses where). Boundary half-edges are then
//! linked into loops through each vertex's outgoing boundary half-edge (walking the fan only at
//! vertices with several boundary gaps).
//!
//! Well-formed input (no face a policy has to act on) is built directly, and the walk itself
//! finds edge defects; only input that needs a decision goes through
//! [`soup::resolve`](crate::soup::resolve) first, and is then built the same way.

use std::mem::MaybeUninit;

use crate::soup::{
    BuildError, BuildPolicy, DegenerateFaces, Diagnostic, EdgeBuckets, EdgeVisit, EdgeVisitor,
    FaceList, FaceTable, Pinched, Unreached, Walked, build_splitting_pinched, face_edges,
    walk_faces,
};
use crate::support::large_arrays::{filled, fit, with_capacity_written};
use crate::support::rare_hits::rare_hits;

use super::Mesh;
use super::ids::{INVALID_INDEX, VertexId};
use super::structure::Deletions;
use super::vertex_fans::vertices_without_halfedge;

impl Mesh {
    /// Builds a mesh from an indexed face list under `policy` (see [`BuildPolicy`]).
    ///
    /// Returns the mesh and the diagnostic of everything found (non-manifold vertices, isolated
    /// vertices and degenerate faces are kept and reported under every policy), or a
    /// [`BuildError`] carrying the diagnostic. An empty list gives an empty mesh (with its
    /// vertices, all isolated); input vertex `i` is mesh vertex `i`; face `f` is input face `f`
    /// unless faces were skipped (see [`Diagnostic::skipped_faces`]).
    pub fn from_face_list(
        list: &FaceList<'_>,
        policy: BuildPolicy,
    ) -> Result<(Mesh, Diagnostic), BuildError> {
        build_splitting_pinched(|route| {
            let Walked {
                walked,
                table,
                positions,
                deleted_vertices,
                diagnostic,
            } = walk_faces(list, policy, route, FaceLoops::walk)?;
            let mut mesh = walked.into_mesh(&table, positions);
            for &v in &deleted_vertices {
                mesh.mark_vertex_deleted(VertexId(v));
            }
            Ok((mesh, diagnostic))
        })
    }

    /// Makes each boundary vertex's half-edge a boundary one and links the boundary half-edges
    /// into loops: a boundary half-edge's next is the boundary half-edge leaving its target from
    /// the same fan.
    fn link_boundary(&mut self, boundary: &[u32]) {
        let mut several_gaps = Vec::new();
        for &b in boundary {
            let v = self.origin[b as usize] as usize;
            let current = self.vertex_halfedge[v];
            if self.face[current as usize] != INVALID_INDEX {
                self.vertex_halfedge[v] = b;
            } else {
                several_gaps.push(v as u32);
            }
        }
        several_gaps.sort_unstable();
        several_gaps.dedup();
        for &b in boundary {
            let target = self.origin[(b ^ 1) as usize];
            let out = if several_gaps.binary_search(&target).is_ok() {
                self.fan_end(b)
            } else {
                self.vertex_halfedge[target as usize]
            };
            self.next[b as usize] = out;
            self.prev[out as usize] = b;
        }
    }

    /// The boundary half-edge that closes the fan entered by boundary half-edge `b`: rotate
    /// counter-clockwise (`twin(prev(h))`) from `twin(b)` until the face is the outside. Faces are
    /// linked already, and a fan has at most as many half-edges as the mesh.
    fn fan_end(&self, b: u32) -> u32 {
        let mut h = b ^ 1;
        for _ in 0..self.origin.len() {
            let rotated = self.prev[h as usize] ^ 1;
            if self.face[rotated as usize] == INVALID_INDEX {
                return rotated;
            }
            h = rotated;
        }
        unreachable!("a fan opened by a boundary half-edge is closed by one")
    }
}

/// The half-edge arrays while the faces are walked, with room for one edge per corner (the most
/// there can be) and trimmed afterwards. The room is not zeroed: the walk writes every entry the
/// mesh keeps, and pages of room never written are never touched. Fresh pages come zeroed from
/// the kernel anyway, but memory the allocator reuses would have to be cleared, all of the room,
/// which on a closed mesh is twice what is used (with glibc serving every block from a reused
/// heap, the 1M-triangle torus built in 59 ms with zeroed room, 31 ms without).
struct FaceLoops {
    origin: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    face: Vec<u32>,
    vertex_halfedge: Vec<u32>,
    face_halfedge: Vec<u32>,
    n_edges: u32,
}

/// Room for `capacity` entries of a half-edge or face array, none written yet (see
/// [`FaceLoops`]), of which the walk is sure to write the first `written`. Debug builds fill it
/// with [`UNWRITTEN`], so that tests catch an entry the walk failed to write.
fn unwritten_room(capacity: usize, written: usize) -> Vec<u32> {
    let mut room = with_capacity_written(capacity, written);
    if cfg!(debug_assertions) {
        room.spare_capacity_mut().fill(MaybeUninit::new(UNWRITTEN));
    }
    room
}

/// A value no walk writes: not a vertex (ids stay below `MAX_VERTICES`), half-edge or face id,
/// nor [`INVALID_INDEX`].
const UNWRITTEN: u32 = u32::MAX - 1;

impl FaceLoops {
    /// The connectivity walk (see the module documentation) over a well-formed table whose
    /// vertices are at `positions`, checking each face's area into `degenerate` when given.
    /// `None` when an edge is walked by more than two faces or twice in one direction.
    ///
    /// The corners meet their edges in the buckets, which numbers their half-edges
    /// ([`EdgeNumbering`]), and the half-edges are written into the loops ([`LoopWriter`]),
    /// corner by corner, on one thread: with two, the other checks the face areas beside the
    /// walk (`soup::front`). Splitting the walk itself, the numbering running chunks of faces
    /// ahead on one thread while the other wrote, was slower on every model measured once the
    /// arrays of small pages were faulted in at once (`large_arrays::populate`; cold memory,
    /// both threads, best of 150 or 30 builds, five rounds taking turns: armadillo, 86k faces,
    /// 7.8-8.4 ms split against 7.0-8.0 on one thread, the bunny 5.3-6.0 against 5.2-5.6,
    /// nefertiti 7.6-8.1 against 6.7-7.6; before it, the 1M-triangle torus 25.9-37.3 against
    /// 25.6-29.8, the 1M-quad torus 36.2-47.8 against 30.8-41.0).
    fn walk(
        table: &FaceTable<'_>,
        buckets: &mut EdgeBuckets,
        positions: &[[f64; 3]],
        degenerate: Option<&mut DegenerateFaces<'_>>,
    ) -> Option<FaceLoops> {
        // Every corner opens or pairs an edge, so there are at least half as many edges as
        // corners: the walk writes at least the first `n_corners` half-edges.
        let (capacity, written) = (2 * table.n_corners(), table.n_corners());
        let mut loops = FaceLoops {
            origin: unwritten_room(capacity, written),
            next: unwritten_room(capacity, written),
            prev: unwritten_room(capacity, written),
            face: unwritten_room(capacity, written),
            vertex_halfedge: filled(positions.len(), INVALID_INDEX),
            face_halfedge: unwritten_room(table.n_faces(), table.n_faces()),
            n_edges: 0,
        };
        // The numbering gives edges below its count, which the walk's one call per corner keeps
        // within the writer's room, so the writer stores without bounds checks (see
        // `EdgeNumbering` and `LoopWriter`).
        let numbering = EdgeNumbering {
            edges: buckets.first_visitor(),
            n_edges: 0,
        };
        // Every array cut to the counts its unchecked stores rely on (see `LoopWriter`). The
        // vertex count is the buckets', so a vertex below it is one of `vertex_halfedge` too
        // (slicing it to that count fails otherwise).
        let (n_edges, n_vertices, n_faces) =
            (capacity / 2, numbering.edges.n_vertices(), table.n_faces());
        // The area check reads positions of vertices below that count unchecked (see
        // `LoopWriter::check_area`).
        assert!(
            degenerate
                .as_ref()
                .is_none_or(|d| n_vertices <= d.n_positions()),
            "a position for every vertex of the buckets"
        );
        let writer = LoopWriter {
            origin: &mut loops.origin.spare_capacity_mut().as_chunks_mut().0[..n_edges],
            face: &mut loops.face.spare_capacity_mut().as_chunks_mut().0[..n_edges],
            next: &mut loops.next.spare_capacity_mut()[..2 * n_edges],
            prev: &mut loops.prev.spare_capacity_mut()[..2 * n_edges],
            vertex_halfedge: &mut loops.vertex_halfedge[..n_vertices],
            face_halfedge: &mut loops.face_halfedge.spare_capacity_mut()[..n_faces],
            degenerate,
        };
        loops.n_edges = walk_corners(table, numbering, writer)?;
        // SAFETY: the walk went through every face of the table (see `LoopWriter`).
        unsafe { loops.claim_written(n_faces) };
        Some(loops)
    }

    /// Takes as written the entries of the walk's `self.n_edges` edges and of its `n_faces`
    /// faces.
    ///
    /// # Safety
    /// A walk through all `n_faces` faces with a [`LoopWriter`] over this room opened the
    /// `self.n_edges` edges: opening edge `e` wrote its `origin` and `face` pairs and the `next`
    /// and `prev` of its twin `2e + 1`; closing each face wrote `next` and `prev` of each of its
    /// half-edges (`2e` among them) and its `face_halfedge`.
    unsafe fn claim_written(&mut self, n_faces: usize) {
        let n_halfedges = 2 * self.n_edges as usize;
        // SAFETY: as the caller promises, within the room each array was allocated with.
        unsafe {
            for halfedge_array in [
                &mut self.origin,
                &mut self.next,
                &mut self.prev,
                &mut self.face,
            ] {
                halfedge_array.set_len(n_halfedges);
            }
            self.face_halfedge.set_len(n_faces);
        }
        debug_assert!(
            [
                &self.origin,
                &self.next,
                &self.prev,
                &self.face,
                &self.face_halfedge
            ]
            .iter()
            .all(|array| !array.contains(&UNWRITTEN)),
            "the walk left an entry unwritten"
        );
    }

    /// The mesh of the walked faces of `table`, with boundary loops.
    fn into_mesh(self, table: &FaceTable<'_>, positions: Vec<[f64; 3]>) -> Mesh {
        let n_halfedges = 2 * self.n_edges as usize;
        let (n_vertices, n_faces) = (positions.len(), self.face_halfedge.len());
        // The arrays were allocated with room to spare (see `large_arrays`); the mesh keeps
        // exactly what it uses.
        let mut mesh = Mesh {
            origin: fit(self.origin, n_halfedges),
            next: fit(self.next, n_halfedges),
            prev: fit(self.prev, n_halfedges),
            face: fit(self.face, n_halfedges),
            vertex_halfedge: fit(self.vertex_halfedge, n_vertices),
            positions: fit(positions, n_vertices),
            face_halfedge: fit(self.face_halfedge, n_faces),
            deleted: Deletions::default(),
            may_have_pinched_vertices: true,
            attributes: Default::default(),
        };
        // Every corner has a half-edge with a face; the other half-edges are boundary twins.
        if n_halfedges > table.n_corners() {
            let boundary = boundary_twins(&mesh.face);
            mesh.link_boundary(&boundary);
        }
        mesh.may_have_pinched_vertices = !mesh.non_manifold_vertices().is_empty();
        mesh
    }
}

impl Pinched for Mesh {
    fn has_pinched_vertices(&self) -> bool {
        self.may_have_pinched_vertices
    }
}

impl Unreached for FaceLoops {
    /// Every vertex of a walked face has a half-edge: the first face walked around it opened the
    /// edge leaving it.
    fn unreached_vertices(&self) -> Vec<u32> {
        vertices_without_halfedge(&self.vertex_halfedge)
    }
}

/// The twins without a face (odd half-edges: every edge's first half-edge has one), ascending,
/// from the walk's `face` array, found by runs (1M-triangle open grid, 2,832 boundary half-edges,
/// cold, one thread, six rounds of 40 builds: the fastest 31.4-32.5 ms with a filter over every
/// twin, 30.7-30.9 ms so).
fn boundary_twins(face: &[u32]) -> Vec<u32> {
    let by_edge = face.as_chunks::<2>().0;
    let mut twins = rare_hits(by_edge, 0, |&[_, twin]| twin == INVALID_INDEX);
    for e in &mut twins {
        *e = 2 * *e + 1;
    }
    twins
}

/// Are all of `corners` below `n_vertices`? A face's vertices checked at once, so that its corners
/// meet their edges and are written without a check each (see `EdgeVisitor::visit_unchecked`);
/// the table was checked when its buckets were made, so the walks never find one that is not.
#[inline(always)]
fn all_below(corners: &[u32], n_vertices: usize) -> bool {
    (corners.iter().fold(0, |largest, &v| largest.max(v)) as usize) < n_vertices
}

/// The walk, corner by corner: each corner's edge is met in the buckets and its
/// half-edge written at once (the bucket loads of one corner then overlap the stores of the
/// last; numbered a chunk of faces at a time and then written, the walk was about 5% slower).
fn walk_corners(
    table: &FaceTable<'_>,
    numbering: EdgeNumbering<'_>,
    writer: LoopWriter<'_, '_>,
) -> Option<u32> {
    let n_vertices = writer.vertex_halfedge.len();
    let mut walk = CornerWalk { numbering, writer };
    let mut polygon = Vec::new();
    table.try_for_each_face(
        #[inline(always)]
        |f, corners| {
            let f32 = f as u32;
            walk.numbering.edges.prefetch_ahead_of(table, f);
            if !all_below(corners, n_vertices) {
                return None;
            }
            // SAFETY: the face's vertices were just checked.
            unsafe { walk.writer.check_area(table, f, corners) };
            // SAFETY (every `walk.corner`): the face's vertices were just checked, and the walk
            // calls it once per corner of the table.
            match *corners {
                [a, b, c] => {
                    let triangle = unsafe {
                        [
                            walk.corner(a, b, f32)?,
                            walk.corner(b, c, f32)?,
                            walk.corner(c, a, f32)?,
                        ]
                    };
                    // SAFETY: `f` is a face of the table, whose faces the writer has room for, with
                    // half-edges of the numbering's edges, below the table's corner count, the
                    // writer's room (see `CornerWalk::corner`).
                    unsafe { walk.writer.close_face(f, &triangle) };
                }
                [a, b, c, d] => {
                    let quad = unsafe {
                        [
                            walk.corner(a, b, f32)?,
                            walk.corner(b, c, f32)?,
                            walk.corner(c, d, f32)?,
                            walk.corner(d, a, f32)?,
                        ]
                    };
                    // SAFETY: as for a triangle.
                    unsafe { walk.writer.close_face(f, &quad) };
                }
                _ => {
                    polygon.clear();
                    for (a, b) in face_edges(corners) {
                        polygon.push(unsafe { walk.corner(a, b, f32)? });
                    }
                    // SAFETY: as for a triangle.
                    unsafe { walk.writer.close_face(f, &polygon) };
                }
            }
            Some(())
        },
    )?;
    Some(walk.numbering.n_edges)
}

/// Both halves of the walk (numbering and writing), owned by its loop so that their fields
/// stay in registers.
struct CornerWalk<'b, 'a, 'd> {
    numbering: EdgeNumbering<'b>,
    writer: LoopWriter<'a, 'd>,
}

impl CornerWalk<'_, '_, '_> {
    /// The half-edge of the corner of face `f` running `a → b`, numbered and written.
    ///
    /// # Safety
    /// `a` and `b` are below the vertex count (of the buckets and of the writer's
    /// `vertex_halfedge`: `FaceLoops::walk` makes them the same), and as for
    /// [`EdgeNumbering::corner`], the walk makes at most one call per corner of its table.
    #[inline(always)]
    unsafe fn corner(&mut self, a: u32, b: u32, f: u32) -> Option<u32> {
        // SAFETY: as the caller promises; the numbering's edges are then below the table's
        // corner count, the writer's room (`FaceLoops::walk`).
        Some(unsafe {
            match self.numbering.corner(a, b)? {
                CornerEdge::Opened(e) => self.writer.open_edge(e, a, b, f),
                CornerEdge::Paired(e) => self.writer.pair_edge(e, f),
            }
        })
    }
}

/// The walk's first half: the corners meet their edges in the buckets, in corner order. The
/// first corner on an edge opens edge `e` and takes half-edge `2e`; the second, running the
/// other way, takes the twin `2e + 1`. Every edge it gives is below `n_edges`: its visitor is
/// its buckets' first, so the only values an edge can carry are those it stored, each the edge
/// count of its time. And `n_edges` grows by one at most per call, so that a walk calling it once
/// per corner of a table gets edges below the table's corner count, the writer's room.
struct EdgeNumbering<'b> {
    edges: EdgeVisitor<'b>,
    n_edges: u32,
}

/// The edge a corner met, and how.
#[derive(Clone, Copy)]
enum CornerEdge {
    /// The corner opened the edge: its half-edge is the edge's first.
    Opened(u32),
    /// An earlier corner opened the edge: this one has the twin.
    Paired(u32),
}

impl CornerEdge {
    /// The corner's half-edge.
    #[inline(always)]
    fn halfedge(self) -> u32 {
        match self {
            CornerEdge::Opened(e) => 2 * e,
            CornerEdge::Paired(e) => 2 * e + 1,
        }
    }
}

impl EdgeNumbering<'_> {
    /// The edge of the next corner, running `a → b`; `None` when the edge was walked this way
    /// already or by two faces. (Edge ids stay below the corner count, at most `MAX_CORNERS`,
    /// so they fit an edge's value.)
    ///
    /// # Safety
    /// `a` and `b` are below the buckets' vertex count (a walk checks a face's corners with
    /// [`all_below`]); counting this one, the numbering has had at most as many calls as its
    /// table has corners (a walk calls it once per corner; see [`EdgeNumbering`]).
    #[inline(always)]
    unsafe fn corner(&mut self, a: u32, b: u32) -> Option<CornerEdge> {
        // SAFETY: as the caller promises.
        match unsafe { self.edges.visit_unchecked(a, b, self.n_edges) } {
            EdgeVisit::Opened => {
                self.n_edges += 1;
                Some(CornerEdge::Opened(self.n_edges - 1))
            }
            EdgeVisit::Paired(e) => Some(CornerEdge::Paired(e)),
            EdgeVisit::Defective => None,
        }
    }
}

/// The walk's second half: numbered half-edges written into [`FaceLoops`]' room, through
/// slices kept on the writer's stack so their addresses and lengths stay in registers; origins
/// and faces by edge, as pairs. Opening an edge writes its pairs and its twin's links (a
/// boundary twin keeps [`INVALID_INDEX`] until the boundary is linked); closing a face writes
/// its half-edges' links and its `face_halfedge`: once every face is closed, every entry of the
/// opened edges is written ([`FaceLoops::claim_written`]).
///
/// `origin` and `face` have one entry per edge of the room, `next` and `prev` two
/// (`FaceLoops::walk` makes them so). The arrays are written without bounds checks, for edges
/// below the room's count, which [`EdgeNumbering`] guarantees, and vertices and faces the walks
/// check a face at a time (see [`all_below`]): the checks per store, and their lengths, took
/// registers the walk spilled. With the buckets' unchecked visits, against checked ones (cold,
/// one thread, best of 40 or 30 builds, rounds taking turns): 1M-triangle torus 29.4-30.3 →
/// 28.2-28.8 ms in eight rounds, open grid 30.2-30.8 → 28.7-29.6 in six, 1M-quad torus
/// 41.2-43.2 → 41.1-43.5 (no change) in six.
struct LoopWriter<'a, 'd> {
    origin: &'a mut [[MaybeUninit<u32>; 2]],
    face: &'a mut [[MaybeUninit<u32>; 2]],
    next: &'a mut [MaybeUninit<u32>],
    prev: &'a mut [MaybeUninit<u32>],
    vertex_halfedge: &'a mut [u32],
    face_halfedge: &'a mut [MaybeUninit<u32>],
    degenerate: Option<&'a mut DegenerateFaces<'d>>,
}

impl LoopWriter<'_, '_> {
    /// Checks the area of table face `f` (vertices `corners`) when asked to: before the face's
    /// topology, so that the position loads overlap the walk's bucket misses.
    ///
    /// # Safety
    /// Every one of `corners` is below the vertex count (`self.vertex_halfedge.len()`).
    #[inline(always)]
    unsafe fn check_area(&mut self, table: &FaceTable<'_>, f: usize, corners: &[u32]) {
        if let Some(degenerate) = self.degenerate.as_deref_mut() {
            // SAFETY: the vertex count is at most the positions' (`FaceLoops::walk` asserts it).
            unsafe { degenerate.check_in_range(table, f, corners) };
        }
    }

    /// The corner of face `f` running `a → b` opened edge `e`: writes and gives its first
    /// half-edge (its twin stays a boundary half-edge until a second corner pairs with it),
    /// which becomes `a`'s half-edge unless `a` has one already: a vertex keeps its first
    /// corner's (the rule [`Winged::from_face_list`](crate::winged::Winged::from_face_list)
    /// documents for both kernels). Only opening corners set a vertex's half-edge, and that
    /// is enough: the first face walked around a vertex opens the edge leaving it, whose other
    /// face comes later (setting it at every corner, the 1M-triangle torus built in 30.1-31.2
    /// against 29.3-30.3 ms, the 1M-quad torus in 42.3-47.8 against 41.5-43.6: cold, one
    /// thread, six rounds taking turns).
    ///
    /// # Safety
    /// `e` is below the room's edge count (`self.origin.len()`), `a` below the vertex count
    /// (`self.vertex_halfedge.len()`).
    #[inline(always)]
    unsafe fn open_edge(&mut self, e: u32, a: u32, b: u32, f: u32) -> u32 {
        let h = CornerEdge::Opened(e).halfedge();
        // SAFETY: `e` is an edge of the room, whose half-edges are `h` and `h + 1`.
        unsafe {
            *self.origin.get_unchecked_mut(e as usize) = [MaybeUninit::new(a), MaybeUninit::new(b)];
            *self.face.get_unchecked_mut(e as usize) =
                [MaybeUninit::new(f), MaybeUninit::new(INVALID_INDEX)];
            self.next
                .get_unchecked_mut(h as usize + 1)
                .write(INVALID_INDEX);
            self.prev
                .get_unchecked_mut(h as usize + 1)
                .write(INVALID_INDEX);
        }
        // SAFETY: `a` is a vertex.
        unsafe {
            let first = self.vertex_halfedge.get_unchecked_mut(a as usize);
            *first = (*first).min(h);
        }
        h
    }

    /// The corner of face `f` paired with edge `e`: writes and gives its twin.
    ///
    /// # Safety
    /// As for [`LoopWriter::open_edge`].
    #[inline(always)]
    unsafe fn pair_edge(&mut self, e: u32, f: u32) -> u32 {
        // SAFETY: `e` is an edge of the room.
        unsafe { self.face.get_unchecked_mut(e as usize)[1].write(f) };
        CornerEdge::Paired(e).halfedge()
    }

    /// Links the half-edges of table face `f` (in corner order) into its loop, the first being
    /// the face's half-edge.
    ///
    /// # Safety
    /// `f` is a face of the table (below `self.face_halfedge.len()`), and every one of
    /// `halfedges` is a half-edge of the room (below `self.next.len()`).
    #[inline(always)]
    unsafe fn close_face(&mut self, f: usize, halfedges: &[u32]) {
        let mut previous = halfedges[halfedges.len() - 1];
        for &h in halfedges {
            // SAFETY: `previous` and `h` are half-edges of the room.
            unsafe {
                self.next.get_unchecked_mut(previous as usize).write(h);
                self.prev.get_unchecked_mut(h as usize).write(previous);
            }
            previous = h;
        }
        // SAFETY: `f` is a face of the table.
        unsafe { self.face_halfedge.get_unchecked_mut(f).write(halfedges[0]) };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{FaceId, HalfedgeId, VertexId};

    #[test]
    fn two_triangles_have_one_interior_edge_and_a_boundary_loop_of_four() {
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let indices = [0, 1, 2, 0, 2, 3];
        let (mesh, diagnostic) = Mesh::from_face_list(
            &FaceList::triangles(&positions, &indices),
            BuildPolicy::Strict,
        )
        .unwrap();
        assert!(diagnostic.is_clean(), "{diagnostic}");
        assert_eq!(
            (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
            (4, 5, 2)
        );
        let boundary: Vec<_> = (0..mesh.n_halfedge_slots() as u32)
            .map(HalfedgeId)
            .filter(|&h| mesh.face(h) == FaceId::INVALID)
            .collect();
        assert_eq!(boundary.len(), 4);
        for &b in &boundary {
            assert_eq!(mesh.face(mesh.next(b)), FaceId::INVALID);
            assert_eq!(mesh.origin(mesh.next(b)), mesh.target(b));
            assert!(mesh.is_boundary_halfedge(mesh.vertex_halfedge(mesh.origin(b))));
        }
        assert_eq!(mesh.check(), Ok(()));
        assert_eq!(mesh.valence(VertexId(0)), 3);
    }

    /// The degenerate faces are found in the walk or in a pass of their own (with one thread: in
    /// the walk when the vertex order follows the faces, before it otherwise; with two: beside
    /// it). Every way gives the same diagnostic and the same mesh, on the fast path and through
    /// resolve.
    #[cfg(feature = "parallel")]
    #[test]
    fn degenerate_faces_are_the_same_found_in_the_walk_or_beside_it() {
        // A strip of quads split into triangles, with collapsed and needle triangles among them
        // and, for the resolve path, one repeated face; faces in strip order, and with the two
        // halves of the strip interleaved so that consecutive faces are far apart.
        let mut positions = Vec::new();
        for i in 0..1001 {
            positions.push([f64::from(i), 0.0, 0.0]);
            positions.push([f64::from(i), 1.0, 0.0]);
        }
        positions[41] = positions[40];
        positions[1601] = [800.0, 1e-17, 0.0];
        let mut in_order = Vec::new();
        for i in 0..1000u32 {
            let (a, b, c, d) = (2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
            in_order.extend([a, b, c, a, c, d]);
        }
        let (first_half, second_half) = in_order.split_at(in_order.len() / 2);
        let interleaved: Vec<u32> = first_half
            .chunks(3)
            .zip(second_half.chunks(3))
            .flat_map(|(f, g)| f.iter().chain(g).copied())
            .collect();
        let in_pool = |threads: usize, indices: &[u32], policy: BuildPolicy| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| {
                    Mesh::from_face_list(&FaceList::triangles(&positions, indices), policy).unwrap()
                })
        };
        for (indices, follows) in [(&in_order, true), (&interleaved, false)] {
            let table = FaceTable::new(&FaceList::triangles(&positions, indices)).unwrap();
            assert_eq!(table.vertices_follow_faces(), follows);
            let mut repeated = indices.clone();
            repeated.extend_from_slice(&indices[..3]);
            for (indices, policy) in [
                (indices, BuildPolicy::Strict),
                (&repeated, BuildPolicy::Skip),
            ] {
                let (alone, alone_diagnostic) = in_pool(1, indices, policy);
                let (beside, beside_diagnostic) = in_pool(2, indices, policy);
                assert!(
                    alone_diagnostic.degenerate_faces.len() >= 3,
                    "{alone_diagnostic}"
                );
                assert_eq!(alone_diagnostic, beside_diagnostic);
                assert_eq!(alone.halfedge_nexts(), beside.halfedge_nexts());
                assert_eq!(alone.positions(), beside.positions());
            }
        }
    }

    /// With two threads the positions are copied beside the bucket count and the areas checked
    /// beside the walk: the mesh, the diagnostic and the refusals are those of one thread, for
    /// triangles, quads and hexagons, with a hole, with an edge defect in the last face, and in
    /// a vertex order that follows the faces (areas checked in the walk on one thread) or not
    /// (in a pass of their own).
    #[cfg(feature = "parallel")]
    #[test]
    fn two_threads_build_what_one_thread_builds() {
        let n = 120u32;
        let at = |i: u32, j: u32| i * (n + 1) + j;
        let positions: Vec<[f64; 3]> = (0..=n)
            .flat_map(|i| (0..=n).map(move |j| (f64::from(i), f64::from(j))))
            .map(|(x, y)| [x, y, 0.1 * (x * 0.3).sin() * (y * 0.2).cos()])
            .collect();
        let (mut sizes, mut indices) = (Vec::new(), Vec::new());
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                match j % 5 {
                    _ if (i, j) == (60, 60) => {}
                    0 => {
                        // A hexagon over this cell and the next.
                        sizes.push(6);
                        indices.extend([a, b, c, at(i + 1, j + 2), at(i, j + 2), d]);
                    }
                    1 => {}
                    3 => {
                        sizes.extend([3, 3]);
                        indices.extend([a, b, c, a, c, d]);
                    }
                    _ => {
                        sizes.push(4);
                        indices.extend([a, b, c, d]);
                    }
                }
            }
        }
        // The grid's own vertex order, and the vertices renumbered by a stride prime to their
        // count (121^2 = 11^4), which scatters them.
        let n_vertices = positions.len() as u32;
        for renumber in [|v: u32, _| v, |v: u32, n: u32| v * 7919 % n] {
            let indices: Vec<u32> = indices.iter().map(|&v| renumber(v, n_vertices)).collect();
            let mut renumbered = positions.clone();
            for (v, &position) in positions.iter().enumerate() {
                renumbered[renumber(v as u32, n_vertices) as usize] = position;
            }
            let list = FaceList::polygons(&renumbered, &sizes, &indices);
            let follows = FaceTable::new(&list).unwrap().vertices_follow_faces();
            assert_eq!(follows, renumber(1, n_vertices) == 1);
            let mut defective = (sizes.clone(), indices.clone());
            defective.0.push(4);
            defective.1.extend_from_slice(&indices[indices.len() - 4..]);
            let in_pool = |threads: usize, (sizes, indices): &(Vec<u32>, Vec<u32>), policy| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(|| {
                        let list = FaceList::polygons(&renumbered, sizes, indices);
                        Mesh::from_face_list(&list, policy)
                    })
            };
            let clean = (sizes.clone(), indices);
            let (one, diagnostic) = in_pool(1, &clean, BuildPolicy::Strict).unwrap();
            assert_eq!(one.check(), Ok(()));
            assert_eq!(one.n_faces(), clean.0.len());
            assert!(diagnostic.is_clean(), "{diagnostic}");
            assert!(in_pool(2, &clean, BuildPolicy::Strict).unwrap() == (one, diagnostic));
            for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
                let (alone, beside) = (
                    in_pool(1, &defective, policy),
                    in_pool(2, &defective, policy),
                );
                assert_eq!(alone.is_err(), policy == BuildPolicy::Strict);
                assert!(
                    alone == beside,
                    "{policy:?} (vertices follow faces: {follows})"
                );
            }
        }
    }
}
