//! The boundary of each Voronoi cell as a sequence of sides, read straight from the Delaunay
//! triangles when there are any (so bulk operations need no half-edge arrays), otherwise from
//! the half-edges.
//!
//! Every Voronoi edge has a *key* that both of its sides share, and an orientation of its own:
//! * planar diagrams: the key is the Delaunay half-edge `e` the edge is dual to, the one of the
//!   pair with the smaller index (a hull edge's only one); oriented with the cell of `origin(e)`
//!   on its left, from the vertex of the twin's triangle (or infinity) to that of `e`'s triangle;
//! * otherwise: the key is the edge index `h / 2`, oriented like the even half-edge `h`.
//!
//! In both cases keys increase with the half-edge numbering of [`super::Voronoi`], and a cell's
//! sides come in the order of its half-edge cycle, starting at its [`super::Voronoi::cell_edge`].

use super::delaunay::{Dimension, INVALID};
use super::diagram::{EdgeEnds, Voronoi};
use super::ids::SiteId;
use super::incremental::{next_edge, prev_edge};
use crate::support::id_set::IdSet;

/// A Voronoi edge seen from one of its cells (which lies on the side's left).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Side {
    /// Start vertex along the cell's boundary ([`INVALID`] at infinity).
    pub from: u32,
    /// End vertex ([`INVALID`] at infinity).
    pub to: u32,
    /// The edge's key.
    pub edge: u32,
    /// Does the side run against the edge's own orientation?
    pub reversed: bool,
}

impl Voronoi {
    /// Every cell with sides once, as a handle for [`Voronoi::handle_sides`], in an order that
    /// reads memory coherently.
    pub(crate) fn cell_handles(&self) -> &[u32] {
        let d = &self.delaunay;
        if d.dimension() == Dimension::Plane {
            &d.cell_starts
        } else {
            &d.hull
        }
    }

    /// Replaces `out` with the sides of the cell of `handle` (see [`Voronoi::cell_handles`]),
    /// counter-clockwise; returns its site.
    pub(crate) fn handle_sides(&self, handle: u32, out: &mut Vec<Side>) -> u32 {
        out.clear();
        self.visit_handle_sides(handle, |side| {
            out.push(side);
            true
        })
        .0
    }

    /// Hands the sides of the cell of `handle` to `visit`, counter-clockwise, until it returns
    /// `false`; returns the cell's site and whether every side was visited.
    #[inline(always)]
    pub(crate) fn visit_handle_sides(
        &self,
        handle: u32,
        visit: impl FnMut(Side) -> bool,
    ) -> (u32, bool) {
        if self.delaunay.dimension() == Dimension::Plane {
            let all = self.visit_triangle_sides(handle, false, visit);
            (self.delaunay.triangles[handle as usize], all)
        } else {
            (handle, self.visit_half_edge_sides(handle, visit))
        }
    }

    /// The site of the cell of `handle` and the sites whose bisectors bound it exactly: those
    /// across its sides and across the edges merged away (between Voronoi vertices that coincide
    /// once rounded, an edge has no length in floating point, but its sites still cut the cell).
    pub(crate) fn handle_neighbours(&self, handle: u32) -> (u32, Vec<u32>) {
        let mut neighbours = Vec::new();
        let mut push_other = |site: u32, side: Side| {
            let ends = self.edge_ends(side.edge);
            neighbours.push(if ends.left == site {
                ends.right
            } else {
                ends.left
            });
            true
        };
        let site = if self.delaunay.dimension() == Dimension::Plane {
            let site = self.delaunay.triangles[handle as usize];
            self.visit_triangle_sides(handle, true, |side| push_other(site, side));
            site
        } else {
            self.visit_half_edge_sides(handle, |side| push_other(handle, side));
            handle
        };
        (site, neighbours)
    }

    /// Circulates counter-clockwise over the Delaunay edges leaving a site, from its vertex edge
    /// `first` (the outgoing hull edge for a hull site): each one not merged away is dual to a
    /// side (every one, with `merged_too`); past the hull the cell closes with the ray out
    /// across the incoming hull edge. Hands every side to `visit` in order until it returns
    /// `false`; returns whether all were visited.
    #[inline(always)]
    fn visit_triangle_sides(
        &self,
        first: u32,
        merged_too: bool,
        mut visit: impl FnMut(Side) -> bool,
    ) -> bool {
        let d = &self.delaunay;
        let vertex = |e: u32| self.triangle_vertex[(e / 3) as usize];
        let mut e = first;
        loop {
            if merged_too || !self.is_merged(e) {
                let twin = d.twins[e as usize];
                let side = if twin == INVALID {
                    Side {
                        from: INVALID,
                        to: vertex(e),
                        edge: e,
                        reversed: false,
                    }
                } else {
                    Side {
                        from: vertex(twin),
                        to: vertex(e),
                        edge: e.min(twin),
                        reversed: twin < e,
                    }
                };
                if !visit(side) {
                    return false;
                }
            }
            let incoming = prev_edge(e);
            let back = d.twins[incoming as usize];
            if back == INVALID {
                return visit(Side {
                    from: vertex(e),
                    to: INVALID,
                    edge: incoming,
                    reversed: true,
                });
            }
            if back == first {
                return true;
            }
            e = back;
        }
    }

    fn visit_half_edge_sides(&self, site: u32, mut visit: impl FnMut(Side) -> bool) -> bool {
        let links = self.half_edges();
        let start = self.cell_edge(SiteId(site)).0;
        if start == INVALID {
            return true;
        }
        let mut h = start;
        loop {
            let side = Side {
                from: links.origin[h as usize],
                to: links.origin[(h ^ 1) as usize],
                edge: h >> 1,
                reversed: h & 1 == 1,
            };
            if !visit(side) {
                return false;
            }
            h = links.next[h as usize];
            if h == start {
                return true;
            }
        }
    }

    /// The ends and sites of the edge with key `edge`, in its own orientation.
    pub(crate) fn edge_ends(&self, edge: u32) -> EdgeEnds {
        if self.delaunay.dimension() == Dimension::Plane {
            let d = &self.delaunay;
            let twin = d.twins[edge as usize];
            EdgeEnds {
                from: if twin == INVALID {
                    INVALID
                } else {
                    self.triangle_vertex[(twin / 3) as usize]
                },
                to: self.triangle_vertex[(edge / 3) as usize],
                left: d.triangles[edge as usize],
                right: d.triangles[next_edge(edge) as usize],
            }
        } else {
            let links = self.half_edges();
            let h = 2 * edge as usize;
            EdgeEnds {
                from: links.origin[h],
                to: links.origin[h + 1],
                left: links.site[h],
                right: links.site[h + 1],
            }
        }
    }

    /// The third sites of the Delaunay triangles at the ends of the edge with key `edge`, at
    /// its `from` and `to` ends ([`INVALID`] at infinity, and for every edge of a diagram
    /// without triangles, whose edges have no vertices). Past an end, its third site is nearer
    /// than the edge's own two.
    pub(crate) fn edge_third_sites(&self, edge: u32) -> [u32; 2] {
        if self.delaunay.dimension() != Dimension::Plane {
            return [INVALID; 2];
        }
        let d = &self.delaunay;
        let third = |e: u32| {
            if e == INVALID {
                INVALID
            } else {
                d.triangles[prev_edge(e) as usize]
            }
        };
        [third(d.twins[edge as usize]), third(edge)]
    }

    /// The keys, in increasing order, of every edge with an end that is not placed: at
    /// infinity, or a vertex for which `is_placed` fails. `unplaced` lists those vertices.
    pub(crate) fn edges_with_unplaced_end(
        &self,
        is_placed: impl Fn(u32) -> bool,
        unplaced: &[u32],
    ) -> Vec<u32> {
        let placed = |v: u32| v != INVALID && is_placed(v);
        if self.delaunay.dimension() != Dimension::Plane {
            let n_edges = (self.n_halfedges() / 2) as u32;
            return (0..n_edges)
                .filter(|&k| {
                    let ends = self.edge_ends(k);
                    !(placed(ends.from) && placed(ends.to))
                })
                .collect();
        }
        // The edges around unplaced vertices, and the rays: the hull edges, one leaving each
        // hull site. Marked in a bit set, which lists them in order without sorting.
        let d = &self.delaunay;
        let mut marked = IdSet::new(d.triangles.len());
        for &s in &d.hull {
            marked.insert(d.vertex_edge[s as usize]);
        }
        let mut around_triangle = |t: u32| {
            for e in 3 * t..3 * t + 3 {
                if !self.is_merged(e) {
                    marked.insert(e.min(d.twins[e as usize]));
                }
            }
        };
        if !self.any_merged() {
            // One vertex per triangle, numbered alike.
            unplaced.iter().for_each(|&t| around_triangle(t));
        } else {
            (0..self.triangle_vertex.len() as u32)
                .filter(|&t| !placed(self.triangle_vertex[t as usize]))
                .for_each(around_triangle);
        }
        marked.into_sorted(0)
    }
}
