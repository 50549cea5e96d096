//! Bulk construction from an indexed face list.
//!
//! The faces are walked once, in order, and each corner meets its edge in
//! [`EdgeBuckets`](crate::soup::EdgeBuckets): the first corner on an edge opens edge `e`
//! (half-edge `2e`, its twin `2e + 1` starts out as a boundary half-edge), the second takes the
//! twin. Each face's loop is written as soon as its corners are known, so half-edges are numbered
//! in corner order and each face's half-edges sit close together in memory; the face's area is
//! checked in the walk or in a pass of its own (degenerate faces are reported; `soup::front`
//! chooses where). Boundary half-edges are then linked into loops through each vertex's outgoing
//! boundary half-edge (walking the fan only at vertices with several boundary gaps).
//!
//! Well-formed input (no face a policy has to act on) is built directly, and the walk itself
//! finds edge defects; only input that needs a decision goes through
//! [`soup::resolve`](crate::soup::resolve) first, and is then built the same way.

use crate::large_arrays::{filled, fit, zeroed};
use crate::soup::{
    BuildError, BuildPolicy, DegenerateFaces, Diagnostic, EdgeBuckets, EdgeVisit, EdgeVisitor,
    FaceList, FaceTable, Walked, face_edges, walk_faces,
};

use super::Mesh;
use super::connectivity::Deletions;
use super::ids::INVALID_INDEX;

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
        let Walked {
            walked,
            table,
            positions,
            diagnostic,
        } = walk_faces(list, policy, FaceLoops::walk)?;
        Ok(walked.into_mesh(&table, positions, diagnostic))
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

/// The half-edge arrays while the faces are walked, sized for one edge per corner (the most
/// there can be) and trimmed afterwards: pages never written are never touched.
struct FaceLoops {
    origin: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    face: Vec<u32>,
    vertex_halfedge: Vec<u32>,
    face_halfedge: Vec<u32>,
    n_edges: u32,
}

impl FaceLoops {
    /// The connectivity walk (see the module documentation) over a well-formed table whose
    /// vertices are at `positions`, checking each face's area into `degenerate` when given.
    /// `None` when an edge is walked by more than two faces or twice in one direction.
    fn walk(
        table: &FaceTable<'_>,
        mut buckets: EdgeBuckets,
        positions: &[[f64; 3]],
        mut degenerate: Option<&mut DegenerateFaces<'_>>,
    ) -> Option<FaceLoops> {
        let capacity = 2 * table.n_corners();
        let mut loops = FaceLoops {
            origin: zeroed(capacity),
            next: zeroed(capacity),
            prev: zeroed(capacity),
            face: zeroed(capacity),
            vertex_halfedge: filled(positions.len(), INVALID_INDEX),
            face_halfedge: zeroed(table.n_faces()),
            n_edges: 0,
        };
        // Every array cut to one of two lengths the compiler can see are shared, so the walk's
        // bounds checks need two registers, not one per array.
        let (n_edges, n_vertices) = (capacity / 2, positions.len());
        let mut writer = LoopWriter {
            edges: buckets.visitor(),
            origin: &mut loops.origin.as_chunks_mut().0[..n_edges],
            face: &mut loops.face.as_chunks_mut().0[..n_edges],
            next: &mut loops.next[..2 * n_edges],
            prev: &mut loops.prev[..2 * n_edges],
            vertex_halfedge: &mut loops.vertex_halfedge[..n_vertices],
            n_edges: 0,
        };
        let mut polygon = Vec::new();
        let faces = table.faces().zip(&mut loops.face_halfedge);
        for (f, (corners, face_halfedge)) in faces.enumerate() {
            let f32 = f as u32;
            writer.edges.prefetch_ahead_of(table, f);
            // Before the topology: the position loads overlap the walk's bucket misses.
            if let Some(degenerate) = degenerate.as_deref_mut() {
                degenerate.check(table, f, corners);
            }
            *face_halfedge = match *corners {
                // Triangles and quads, the usual faces, written out with their loops in
                // registers: measurably faster than the generic loop.
                [a, b, c] => {
                    let triangle = [
                        writer.corner(a, b, f32)?,
                        writer.corner(b, c, f32)?,
                        writer.corner(c, a, f32)?,
                    ];
                    writer.close_face(triangle)
                }
                [a, b, c, d] => {
                    let quad = [
                        writer.corner(a, b, f32)?,
                        writer.corner(b, c, f32)?,
                        writer.corner(c, d, f32)?,
                        writer.corner(d, a, f32)?,
                    ];
                    writer.close_face(quad)
                }
                _ => {
                    polygon.clear();
                    for (a, b) in face_edges(corners) {
                        polygon.push(writer.corner(a, b, f32)?);
                    }
                    writer.close_face(&polygon)
                }
            };
        }
        loops.n_edges = writer.n_edges;
        Some(loops)
    }

    /// The mesh of the walked faces of `table`, with boundary loops, and `diagnostic` completed
    /// with what the mesh shows: non-manifold and isolated vertices.
    fn into_mesh(
        self,
        table: &FaceTable<'_>,
        positions: Vec<[f64; 3]>,
        mut diagnostic: Diagnostic,
    ) -> (Mesh, Diagnostic) {
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
            let boundary: Vec<u32> = (1..n_halfedges as u32)
                .step_by(2)
                .filter(|&h| mesh.face[h as usize] == INVALID_INDEX)
                .collect();
            mesh.link_boundary(&boundary);
        }
        diagnostic.non_manifold_vertices =
            mesh.non_manifold_vertices().iter().map(|v| v.0).collect();
        mesh.may_have_pinched_vertices = !diagnostic.non_manifold_vertices.is_empty();
        diagnostic.isolated_vertices = mesh.isolated_vertices();
        (mesh, diagnostic)
    }
}

/// The walk's view of [`FaceLoops`]' arrays and the edge buckets: slices on the walk's stack,
/// so their addresses and lengths stay in registers; origins and faces by edge, as pairs.
struct LoopWriter<'a> {
    edges: EdgeVisitor<'a>,
    origin: &'a mut [[u32; 2]],
    face: &'a mut [[u32; 2]],
    next: &'a mut [u32],
    prev: &'a mut [u32],
    vertex_halfedge: &'a mut [u32],
    n_edges: u32,
}

impl LoopWriter<'_> {
    /// The half-edge of the corner of face `f` running `a → b`: a new edge's first half-edge,
    /// or the twin of the edge's first corner when that ran `b → a`. `None` when the edge was
    /// walked this way already or by two faces. (Edge ids stay below the corner count, at most
    /// `MAX_CORNERS`, so they fit an edge's value.)
    // Inlined into the walk: it is the whole per-corner work.
    #[inline(always)]
    fn corner(&mut self, a: u32, b: u32, f: u32) -> Option<u32> {
        let h = match self.edges.visit(a, b, self.n_edges) {
            EdgeVisit::Opened => {
                let e = self.n_edges;
                self.n_edges += 1;
                self.origin[e as usize] = [a, b];
                self.face[e as usize] = [f, INVALID_INDEX];
                2 * e
            }
            EdgeVisit::Paired(e) => {
                self.face[e as usize][1] = f;
                2 * e + 1
            }
            EdgeVisit::Defective => return None,
        };
        self.vertex_halfedge[a as usize] = h;
        Some(h)
    }

    /// Links a face's half-edges (in corner order) into its loop; returns the first.
    #[inline(always)]
    fn close_face(&mut self, halfedges: impl AsRef<[u32]>) -> u32 {
        let halfedges = halfedges.as_ref();
        let mut previous = halfedges[halfedges.len() - 1];
        for &h in halfedges {
            self.next[previous as usize] = h;
            self.prev[h as usize] = previous;
            previous = h;
        }
        halfedges[0]
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
        let boundary: Vec<_> = (0..mesh.halfedge_capacity() as u32)
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
}
