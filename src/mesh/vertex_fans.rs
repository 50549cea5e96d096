//! Vertex-level topology found after a build: isolated vertices and vertices with several fans.

use std::ops::Range;

use super::Mesh;
use super::ids::{HalfedgeId, INVALID_INDEX, VertexId};
use crate::cycles::for_each_cycle_length;
use crate::rare_hits::rare_hits;

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
        let n_vertices = self.vertex_capacity();
        let walked_in = |vertices: Range<usize>| {
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
        for h in 0..self.halfedge_capacity() {
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
        let (prev, vertex_halfedge) = (&self.prev, &self.vertex_halfedge);
        let check_deleted = self.has_deleted_elements();
        let starts = vertices
            .filter(|&v| {
                vertex_halfedge[v] != INVALID_INDEX
                    && !(check_deleted && self.is_vertex_deleted(VertexId(v as u32)))
            })
            .map(|v| (v, vertex_halfedge[v]));
        let step = |h: u32| Some(prev[h as usize] ^ 1);
        for_each_cycle_length(starts, self.halfedge_capacity(), step, visit);
    }
}

/// The vertices whose entry of `vertex_halfedge` is [`INVALID_INDEX`], ascending.
pub(super) fn vertices_without_halfedge(vertex_halfedge: &[u32]) -> Vec<u32> {
    rare_hits(vertex_halfedge, 0, |&h| h == INVALID_INDEX)
}
