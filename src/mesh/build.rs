//! Bulk construction from an indexed face list.
//!
//! [`soup::resolve`](crate::soup::resolve) pairs the directed edges by bucketing and applies the
//! policy; this module turns the pairing into half-edges in three linear passes:
//! 1. number the edges in corner order (a corner opens a new edge unless its partner came
//!    first), so each face's half-edges sit close together in memory;
//! 2. fill origin/next/prev/face face by face, plus the origin of each boundary twin;
//! 3. link boundary half-edges into loops through each vertex's outgoing boundary half-edge
//!    (walking the fan only at vertices with several boundary gaps).

use std::borrow::Cow;

use crate::large_arrays::{self, filled, zeroed};
use crate::soup::{
    BOUNDARY, BuildError, BuildPolicy, Diagnostic, FaceList, FaceTable, degenerate_faces, resolve,
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
        // The mesh's copy of the input positions needs nothing from the checks and the pairing:
        // with two threads it is made beside them. Repair, the rare path that adds positions,
        // brings its own array and the copy goes unused.
        let (resolved, input_positions) = join(
            || resolve(list, policy),
            || large_arrays::copied(list.positions),
        );
        let resolved = resolved?;
        let mut diagnostic = resolved.diagnostic;
        let (table, partner) = (&resolved.table, resolved.pairing.partner);
        // Positions the degenerate-face check reads while the mesh takes its own array.
        let repaired_positions;
        let (positions, mesh_positions): (&[[f64; 3]], _) = match resolved.positions {
            Cow::Borrowed(input) => (input, input_positions),
            Cow::Owned(repaired) => {
                drop(input_positions);
                repaired_positions = repaired;
                let copy = large_arrays::copied(&repaired_positions);
                (&repaired_positions, copy)
            }
        };
        // The geometric check reads only the table and the positions: with two threads it runs
        // beside the connectivity passes.
        let (mut mesh, degenerate) = join(
            || Mesh::from_pairing(table, partner, mesh_positions),
            || degenerate_faces(table, positions),
        );
        diagnostic.non_manifold_vertices =
            mesh.non_manifold_vertices().iter().map(|v| v.0).collect();
        mesh.may_have_pinched_vertices = !diagnostic.non_manifold_vertices.is_empty();
        diagnostic.isolated_vertices = mesh.isolated_vertices();
        diagnostic.degenerate_faces = degenerate;
        Ok((mesh, diagnostic))
    }

    /// Builds the connectivity of a resolved table: `partner[c]` is the corner sharing corner
    /// `c`'s edge the other way, or [`BOUNDARY`]. The partner array is turned into the corner →
    /// half-edge map in place (saving an allocation as large as the index list).
    fn from_pairing(table: &FaceTable<'_>, partner: Vec<u32>, positions: Vec<[f64; 3]>) -> Mesh {
        let corners = table.corners();

        // Pass 1: half-edge of every corner. A corner opens edge `e` (half-edge 2e) unless its
        // partner came first, in which case it takes the partner's twin. n_corners < 2^31, so
        // ids stay below u32::MAX.
        let mut corner_halfedge = partner;
        let mut is_boundary_corner = Vec::new();
        let mut n_edges: u32 = 0;
        for c in 0..corner_halfedge.len() {
            let p = corner_halfedge[c];
            corner_halfedge[c] = if p == BOUNDARY {
                is_boundary_corner.push(c as u32);
                n_edges += 1;
                2 * n_edges - 2
            } else if p as usize > c {
                n_edges += 1;
                2 * n_edges - 2
            } else {
                corner_halfedge[p as usize] ^ 1
            };
        }
        let boundary_corners = is_boundary_corner;

        // Pass 2: face loops. Zeroed allocations are cheap; every slot gets written below.
        let n_halfedges = 2 * n_edges as usize;
        let mut origin = zeroed(n_halfedges);
        let mut next = zeroed(n_halfedges);
        let mut prev = zeroed(n_halfedges);
        let mut face = zeroed(n_halfedges);
        let mut vertex_halfedge = filled(positions.len(), INVALID_INDEX);
        let mut face_halfedge = zeroed(table.n_faces());
        let mut boundary = Vec::with_capacity(boundary_corners.len());
        let mut next_boundary = boundary_corners.iter().copied().peekable();
        for (f, first_corner) in face_halfedge.iter_mut().enumerate() {
            let range = table.face_range(f);
            let first = corner_halfedge[range.start];
            *first_corner = first;
            let mut previous = corner_halfedge[range.end - 1];
            for c in range.clone() {
                let h = corner_halfedge[c];
                let next_c = if c + 1 == range.end {
                    range.start
                } else {
                    c + 1
                };
                let (hu, vertex) = (h as usize, corners[c]);
                origin[hu] = vertex;
                face[hu] = f as u32;
                next[hu] = corner_halfedge[next_c];
                prev[hu] = previous;
                previous = h;
                vertex_halfedge[vertex as usize] = h;
                if next_boundary.next_if_eq(&(c as u32)).is_some() {
                    origin[hu ^ 1] = corners[next_c];
                    face[hu ^ 1] = INVALID_INDEX;
                    boundary.push(h ^ 1);
                }
            }
        }

        let mut mesh = Mesh {
            origin,
            next,
            prev,
            face,
            vertex_halfedge,
            positions,
            face_halfedge,
            deleted: Deletions::default(),
            may_have_pinched_vertices: true,
            attributes: Default::default(),
        };
        mesh.link_boundary(&boundary);
        mesh
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

/// Runs `a` and `b`, in parallel when the `parallel` feature and the thread pool allow.
fn join<A: Send, B: Send>(a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
    #[cfg(feature = "parallel")]
    {
        rayon::join(a, b)
    }
    #[cfg(not(feature = "parallel"))]
    {
        (a(), b())
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
}
