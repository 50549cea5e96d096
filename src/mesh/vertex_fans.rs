//! Vertex-level topology found after a build: isolated vertices and vertices with several fans.

use super::Mesh;
use super::ids::{HalfedgeId, INVALID_INDEX, VertexId};

impl Mesh {
    /// Live vertices with no half-edge, ascending.
    pub fn isolated_vertices(&self) -> Vec<u32> {
        (0..self.vertex_capacity() as u32)
            .filter(|&v| {
                self.vertex_halfedge[v as usize] == INVALID_INDEX
                    && !self.is_vertex_deleted(VertexId(v))
            })
            .collect()
    }

    /// Vertices whose outgoing half-edges form more than one fan (the circulator from
    /// [`Mesh::vertex_halfedge`] misses some of them), ascending.
    ///
    /// Fast path: every half-edge leaves exactly one vertex, so if the fans walked from each
    /// vertex's half-edge add up to all live half-edges, no vertex has a second fan. Only
    /// otherwise are per-vertex out-degrees counted.
    pub fn non_manifold_vertices(&self) -> Vec<VertexId> {
        // The fan walk on the raw arrays (`h = twin(prev(h))`): this runs after every build, over
        // every half-edge. Bounded by the half-edge count, like the circulators.
        let (prev, vertex_halfedge) = (&self.prev, &self.vertex_halfedge);
        let max_steps = self.halfedge_capacity();
        let check_deleted = self.has_deleted_elements();
        let fan_size = |v: usize| -> usize {
            let start = vertex_halfedge[v];
            if start == INVALID_INDEX
                || (check_deleted && self.is_vertex_deleted(VertexId(v as u32)))
            {
                return 0;
            }
            let (mut h, mut steps) = (start, 0);
            loop {
                steps += 1;
                h = prev[h as usize] ^ 1;
                if h == start || steps >= max_steps {
                    return steps;
                }
            }
        };
        #[cfg(feature = "parallel")]
        let walked: usize = {
            use rayon::prelude::*;
            (0..self.vertex_capacity())
                .into_par_iter()
                .with_min_len(8192)
                .map(fan_size)
                .sum()
        };
        #[cfg(not(feature = "parallel"))]
        let walked: usize = (0..self.vertex_capacity()).map(fan_size).sum();
        if walked == self.n_halfedges() {
            return Vec::new();
        }
        let mut out_degree = vec![0u32; self.vertex_capacity()];
        for h in 0..self.halfedge_capacity() {
            if !self.is_halfedge_deleted(HalfedgeId(h as u32)) {
                let v = self.origin[h] as usize;
                out_degree[v] = out_degree[v].saturating_add(1);
            }
        }
        (0..self.vertex_capacity())
            .filter(|&v| fan_size(v) != out_degree[v] as usize)
            .map(|v| VertexId(v as u32))
            .collect()
    }
}
