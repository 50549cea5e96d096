//! The half-edge arrays (DCEL links) of a Voronoi diagram, derived from its Delaunay dual.
//!
//! They are built on first use ([`super::Voronoi`] keeps them in a `OnceLock`): clipping and the
//! other bulk operations read the cells straight from the triangles, so a caller who only wants
//! clipped cells never pays for six arrays of `6n` entries.

use super::delaunay::{Delaunay, INVALID};
use super::ids::SiteId;
use super::incremental::{next_edge, prev_edge};
use super::parallel::map_indexed;

/// Per half-edge `origin`, `next`, `prev` and `site`; per site one half-edge of its cell; per
/// vertex one outgoing half-edge. Conventions are those of [`super::Voronoi`].
#[derive(Clone, Debug, Default)]
pub(crate) struct HalfEdges {
    pub origin: Vec<u32>,
    pub next: Vec<u32>,
    pub prev: Vec<u32>,
    pub site: Vec<u32>,
    pub cell_edge: Vec<u32>,
    pub vertex_edge: Vec<u32>,
}

impl HalfEdges {
    /// The diagram of a planar triangulation: a pair of half-edges per Delaunay edge not merged
    /// away (`merged(e)` says both sides of Delaunay half-edge `e` are one Voronoi vertex).
    pub fn planar(
        d: &Delaunay,
        triangle_vertex: &[u32],
        n_vertices: usize,
        merged: impl Fn(u32) -> bool,
    ) -> Self {
        // The even half-edge of a pair is dual to the Delaunay half-edge `e` (cell of
        // origin(e)), the odd one to its twin (or the hull's outer side).
        let mut dual = vec![INVALID; d.triangles.len()];
        let mut origin = Vec::new();
        let mut site = Vec::new();
        for e in 0..d.triangles.len() as u32 {
            let t = d.twins[e as usize];
            if merged(e) || (t != INVALID && t < e) {
                continue;
            }
            let h = origin.len() as u32;
            let here = triangle_vertex[(e / 3) as usize];
            let there = if t == INVALID {
                INVALID
            } else {
                triangle_vertex[(t / 3) as usize]
            };
            origin.push(there);
            site.push(d.triangles[e as usize]);
            origin.push(here);
            site.push(d.triangles[next_edge(e) as usize]);
            dual[e as usize] = h;
            // The outer side of a hull edge is simply the pair `dual[e] ^ 1`.
            if t != INVALID {
                dual[t as usize] = h + 1;
            }
        }
        // Links, one Delaunay half-edge at a time (memory-coherent, no per-site circulation):
        // after dual(e) comes the dual of the next kept edge counter-clockwise around origin(e),
        // or, past the hull, the ray out to infinity; after that ray, the cell's in-ray.
        let mut next = vec![INVALID; origin.len()];
        for e in 0..d.triangles.len() as u32 {
            let h = dual[e as usize];
            if h == INVALID {
                continue;
            }
            let mut cur = e;
            next[h as usize] = loop {
                let p = prev_edge(cur);
                let t = d.twins[p as usize];
                if t == INVALID {
                    let out_ray = dual[p as usize] ^ 1;
                    let a = d.triangles[e as usize];
                    next[out_ray as usize] = dual[d.vertex_edge[a as usize] as usize];
                    break out_ray;
                }
                if !merged(t) {
                    break dual[t as usize];
                }
                cur = t;
            };
        }
        // A cell starts at the dual of its site's vertex edge: the outgoing hull edge for hull
        // sites, whose dual is the in-ray. (One read per site instead of a write per half-edge.)
        let cell_edge = map_indexed(d.n_sites(), |site| {
            if d.vertex_edge[site] == INVALID {
                return INVALID;
            }
            d.outgoing(SiteId(site as u32))
                .map(|e| dual[e.index()])
                .find(|&h| h != INVALID)
                .unwrap_or(INVALID)
        });
        Self::linked(origin, site, next, cell_edge, n_vertices)
    }

    /// All sites on a line: the cells are slabs between parallel bisectors.
    pub fn parallel(d: &Delaunay) -> Self {
        let chain = &d.hull;
        let m = chain.len() - 1;
        let origin = vec![INVALID; 2 * m];
        let mut site = Vec::with_capacity(2 * m);
        for w in chain.windows(2) {
            site.push(w[0]);
            site.push(w[1]);
        }
        let mut cell_edge = vec![INVALID; d.n_sites()];
        let mut next = vec![INVALID; 2 * m];
        for k in 0..m {
            // Cell of chain[k+1] holds 2k+1 (towards chain[k]) and 2k+2 (towards chain[k+2]).
            let left_of_next = 2 * k as u32 + 1;
            let right_of_next = if k + 1 < m {
                2 * k as u32 + 2
            } else {
                left_of_next
            };
            next[left_of_next as usize] = right_of_next;
            next[right_of_next as usize] = left_of_next;
            cell_edge[chain[k + 1] as usize] = left_of_next;
        }
        next[0] = 0;
        cell_edge[chain[0] as usize] = 0;
        Self::linked(origin, site, next, cell_edge, 0)
    }

    /// No edges at all (no site, or one distinct site).
    pub fn empty(n_sites: usize) -> Self {
        HalfEdges {
            cell_edge: vec![INVALID; n_sites],
            ..HalfEdges::default()
        }
    }

    /// Completes the structure with `prev` (inverse of `next`) and the vertices' half-edges.
    fn linked(
        origin: Vec<u32>,
        site: Vec<u32>,
        next: Vec<u32>,
        cell_edge: Vec<u32>,
        n_vertices: usize,
    ) -> Self {
        let mut prev = vec![INVALID; next.len()];
        for (h, &n) in next.iter().enumerate() {
            if n != INVALID {
                prev[n as usize] = h as u32;
            }
        }
        let mut vertex_edge = vec![INVALID; n_vertices];
        for (h, &o) in origin.iter().enumerate() {
            if o != INVALID {
                vertex_edge[o as usize] = h as u32;
            }
        }
        HalfEdges {
            origin,
            next,
            prev,
            site,
            cell_edge,
            vertex_edge,
        }
    }
}
