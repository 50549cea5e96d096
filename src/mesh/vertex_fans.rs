//! Vertex-level topology found after a build: isolated vertices and vertices with several fans.

use std::ops::Range;

use super::Mesh;
use super::ids::{HalfedgeId, INVALID_INDEX, VertexId};
use crate::support::cycles::{for_each_cycle_length, total_cycle_length_interleaved};
use crate::support::order::mostly_nearby;
use crate::support::rare_hits::rare_hits;

impl Mesh {
    /// Live vertices with no half-edge, ascending.
    pub fn isolated_vertices(&self) -> Vec<u32> {
        let mut isolated = vertices_without_halfedge(&self.vertex_halfedge);
        isolated.retain(|&v| !self.is_vertex_deleted(VertexId(v)));
        isolated
    }

    /// Vertices whose outgoing half-edges form more than one fan (the circulator from
    /// [`Mesh::vertex_halfedge`] misses some of them), ascending.
    ///
    /// Fast path: every half-edge leaves exactly one vertex, so if the fans walked from each
    /// vertex's half-edge add up to all live half-edges, no vertex has a second fan. Only
    /// otherwise are per-vertex out-degrees counted.
    pub fn non_manifold_vertices(&self) -> Vec<VertexId> {
        // This runs after every build, over every half-edge.
        let n_vertices = self.n_vertex_slots();
        let interleaved = !self.fans_follow_vertices();
        let walked_in = |vertices: Range<usize>| {
            if interleaved {
                let starts = self.fan_starts(vertices).map(|(_, h)| h);
                return total_cycle_length_interleaved::<_, FANS_SIDE_BY_SIDE>(
                    starts,
                    self.n_halfedge_slots(),
                    |h| self.fan_step(h),
                );
            }
            let mut walked = 0;
            self.for_each_fan_size(vertices, |_, size| walked += size);
            walked
        };
        #[cfg(feature = "parallel")]
        let walked: usize = {
            use rayon::prelude::*;
            const CHUNK: usize = 1 << 14;
            (0..n_vertices.div_ceil(CHUNK))
                .into_par_iter()
                .map(|chunk| walked_in(chunk * CHUNK..n_vertices.min((chunk + 1) * CHUNK)))
                .sum()
        };
        #[cfg(not(feature = "parallel"))]
        let walked: usize = walked_in(0..n_vertices);
        if walked == self.n_halfedges() {
            return Vec::new();
        }
        let mut out_degree = vec![0u32; n_vertices];
        for h in 0..self.n_halfedge_slots() {
            if !self.is_halfedge_deleted(HalfedgeId(h as u32)) {
                let v = self.origin[h] as usize;
                out_degree[v] = out_degree[v].saturating_add(1);
            }
        }
        let mut pinched = Vec::new();
        self.for_each_fan_size(0..n_vertices, |v, size| {
            if size != out_degree[v] as usize {
                pinched.push(VertexId(v as u32));
            }
        });
        pinched
    }

    /// Calls `visit(v, size)` for each live vertex `v` of `vertices` with a half-edge, `size`
    /// being the number of half-edges of the fan walked from it (`h = twin(prev(h))` on the raw
    /// arrays, bounded by the half-edge count like the circulators).
    fn for_each_fan_size(&self, vertices: Range<usize>, visit: impl FnMut(usize, usize)) {
        let step = |h: u32| Some(self.fan_step(h));
        let starts = self.fan_starts(vertices);
        for_each_cycle_length(starts, self.n_halfedge_slots(), step, visit);
    }

    /// The next half-edge of `h`'s fan, on the raw arrays: `twin(prev(h))`.
    #[inline(always)]
    fn fan_step(&self, h: u32) -> u32 {
        self.prev[h as usize] ^ 1
    }

    /// The live vertices of `vertices` with a half-edge, and that half-edge: where their fans
    /// are walked from.
    fn fan_starts(&self, vertices: Range<usize>) -> impl Iterator<Item = (usize, u32)> + '_ {
        let check_deleted = self.has_deleted_elements();
        vertices
            .map(|v| (v, self.vertex_halfedge[v]))
            .filter(move |&(v, h)| {
                h != INVALID_INDEX && !(check_deleted && self.is_vertex_deleted(VertexId(v as u32)))
            })
    }

    /// Do consecutive vertices mostly have their half-edges near each other in memory (generated
    /// meshes, meshes in a cache-friendly order; see [`mostly_nearby`])? Then their fans are
    /// best walked one after another, otherwise [`FANS_SIDE_BY_SIDE`] at a time.
    fn fans_follow_vertices(&self) -> bool {
        const NEARBY_HALFEDGES: u32 = 1024;
        mostly_nearby(self.n_vertex_slots(), NEARBY_HALFEDGES, |v| {
            Some(self.vertex_halfedge[v]).filter(|&h| h != INVALID_INDEX)
        })
    }
}

/// Fans walked side by side when the vertices' half-edges are scattered (scanned models): each
/// step is then a cache miss, and eight walks overlap theirs (one thread, a mesh built once and
/// checked 30 times, the fastest: armadillo, 86k faces, 1.00 → 0.48 ms; nefertiti, 100k, 1.00 →
/// 0.53 ms; in a first version, two side by side gave armadillo 1.01 ms, four 0.48, eight 0.43).
/// Where they are near each other the walks one by one are faster (1M-triangle torus: 2.2 ms,
/// against 3.3 eight side by side), their ends predicted and their loads in cache.
const FANS_SIDE_BY_SIDE: usize = 8;

/// The vertices whose entry of `vertex_halfedge` is [`INVALID_INDEX`], ascending.
pub(super) fn vertices_without_halfedge(vertex_halfedge: &[u32]) -> Vec<u32> {
    rare_hits(vertex_halfedge, 0, |&h| h == INVALID_INDEX)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildPolicy, FaceList};

    /// Two triangulated grids touching at one corner vertex, and a third whose middle vertex is
    /// shared with a fourth: the direct build finds the pinched vertices whether the vertices'
    /// half-edges follow their order (fans walked one by one) or are scattered (side by side),
    /// and builds again splitting them (Skip) or refuses (Strict). Either way the diagnostic
    /// lists them, and no vertex of the mesh has a half-edge its circulation misses.
    #[test]
    fn pinched_vertices_are_found_with_fans_walked_one_by_one_or_side_by_side() {
        let n = 30u32;
        let per_grid = (n + 1) * (n + 1);
        let (mut positions, mut indices) = (Vec::new(), Vec::new());
        for g in 0..4 {
            let at = |i: u32, j: u32| g * per_grid + i * (n + 1) + j;
            for i in 0..=n {
                for j in 0..=n {
                    positions.push([f64::from(i), f64::from(j), f64::from(g)]);
                }
            }
            for i in 0..n {
                for j in 0..n {
                    let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                    indices.extend([a, b, c, a, c, d]);
                }
            }
        }
        // Grid 1's first corner is grid 0's last; grid 3's middle vertex is grid 2's.
        let middle = (n / 2) * (n + 1) + n / 2;
        let pinched = [per_grid - 1, 2 * per_grid + middle];
        for v in &mut indices {
            if *v == per_grid {
                *v = pinched[0];
            } else if *v == 3 * per_grid + middle {
                *v = pinched[1];
            }
        }
        let n_vertices = positions.len() as u32;
        for (stride, scattered) in [(1, false), (7919, true)] {
            let renumber = |v: u32| v * stride % n_vertices;
            let indices: Vec<u32> = indices.iter().map(|&v| renumber(v)).collect();
            let mut renumbered = vec![[0.0; 3]; positions.len()];
            for (v, &p) in positions.iter().enumerate() {
                renumbered[renumber(v as u32) as usize] = p;
            }
            let list = FaceList::triangles(&renumbered, &indices);
            let mut expected = pinched.map(renumber).to_vec();
            expected.sort_unstable();
            let refusal = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap_err();
            assert_eq!(refusal.diagnostic().non_manifold_vertices, expected);

            let (mesh, diagnostic) = Mesh::from_face_list(&list, BuildPolicy::Skip).unwrap();
            assert_eq!(mesh.fans_follow_vertices(), !scattered);
            assert!(mesh.non_manifold_vertices().is_empty());
            assert!(!mesh.may_have_pinched_vertices());
            assert_eq!(diagnostic.non_manifold_vertices, expected);
            assert_eq!(diagnostic.vertex_copies, expected);
            assert!(diagnostic.skipped_faces.is_empty());
            let mut out_degree = vec![0; mesh.n_vertex_slots()];
            for &v in mesh.halfedge_origins() {
                out_degree[v as usize] += 1;
            }
            for v in 0..mesh.n_vertex_slots() as u32 {
                assert_eq!(
                    mesh.valence(VertexId(v)),
                    out_degree[v as usize],
                    "vertex {v}"
                );
            }
            // The vertices left without faces by the sharing are isolated.
            let mut isolated = [per_grid, 3 * per_grid + middle].map(renumber).to_vec();
            isolated.sort_unstable();
            assert_eq!(diagnostic.isolated_vertices, isolated);
        }
    }
}
