//! The Voronoi diagram as a DCEL, dual to the Delaunay triangulation.

use super::delaunay::{Delaunay, Dimension, INVALID};
use super::error::VoronoiError;
use super::expansion::Exact;
use super::incremental::{next_edge, prev_edge};
use super::parallel::map_indexed;
use super::predicates::incircle;

/// Geometry of an undirected Voronoi edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EdgeGeometry {
    /// Both ends are Voronoi vertices.
    Segment {
        /// Start point (origin of the half-edge asked about).
        from: [f64; 2],
        /// End point.
        to: [f64; 2],
    },
    /// One end at infinity: the points `origin + t·direction`, `t ≥ 0`.
    Ray {
        /// The finite end (a Voronoi vertex).
        origin: [f64; 2],
        /// Unit-free direction towards infinity (perpendicular to the hull edge, pointing out).
        direction: [f64; 2],
    },
    /// Both ends at infinity (collinear sites): the points `point + t·direction`, `t ∈ ℝ`,
    /// `direction` oriented like the half-edge asked about.
    Line {
        /// The midpoint of the two sites.
        point: [f64; 2],
        /// Direction, with the half-edge's cell on its left.
        direction: [f64; 2],
    },
}

/// A Voronoi diagram: one cell (face) per distinct site, vertices at circumcentres, half-edges in
/// twin pairs (`twin(h) = h ^ 1`).
///
/// Conventions:
/// * Half-edge `h` bounds the cell of [`Voronoi::site`]`(h)`, which lies on its **left**; its twin
///   bounds the cell of [`Voronoi::opposite_site`]`(h)`. Every edge is the perpendicular bisector
///   piece between those two sites, dual to the Delaunay edge joining them.
/// * `next` circulates **counter-clockwise** around the cell. An unbounded cell's cycle passes
///   through infinity: the half-edge running out to infinity ([`Voronoi::origin`] of its twin is
///   [`INVALID`]) is followed by the one coming back (its own origin is [`INVALID`]).
/// * Cocircular sites give one vertex of degree > 3 (Delaunay triangles with the same
///   circumcircle, decided exactly with the in-circle predicate, are merged). Adjacent triangles
///   whose circumcentres round to the same floating-point point are merged too, so no edge has
///   zero length in the output.
/// * Cells are indexed by site; duplicates (see [`Delaunay::representative`]) have no cell of
///   their own.
#[derive(Clone, Debug)]
pub struct Voronoi {
    pub(crate) delaunay: Delaunay,
    pub(crate) vertices: Vec<[f64; 2]>,
    pub(crate) vertex_edge: Vec<u32>,
    pub(crate) triangle_vertex: Vec<u32>,
    pub(crate) origin: Vec<u32>,
    pub(crate) next: Vec<u32>,
    pub(crate) prev: Vec<u32>,
    pub(crate) site: Vec<u32>,
    pub(crate) cell_edge: Vec<u32>,
}

impl Voronoi {
    /// The Voronoi diagram of `sites` (see [`Delaunay::new`] for the accepted input).
    pub fn new(sites: &[[f64; 2]]) -> Result<Self, VoronoiError> {
        Ok(Self::from_delaunay(Delaunay::new(sites)?))
    }

    /// The dual of an existing triangulation.
    pub fn from_delaunay(delaunay: Delaunay) -> Self {
        let n = delaunay.n_sites();
        let mut v = Voronoi {
            vertices: Vec::new(),
            vertex_edge: Vec::new(),
            triangle_vertex: Vec::new(),
            origin: Vec::new(),
            next: Vec::new(),
            prev: Vec::new(),
            site: Vec::new(),
            cell_edge: vec![INVALID; n],
            delaunay,
        };
        match v.delaunay.dimension() {
            Dimension::Plane => v.build_planar(),
            Dimension::Line => v.build_parallel(),
            Dimension::Empty | Dimension::Point => {}
        }
        v
    }

    /// Groups triangles with one circumcircle, places vertices, and links the half-edges.
    fn build_planar(&mut self) {
        let d = &self.delaunay;
        let n_tri = d.n_triangles();
        let centres: Vec<[f64; 2]> = map_indexed(n_tri, |t| self.circumcentre(t as u32));
        // Union-find over triangles: adjacent triangles share a Voronoi vertex when their fourth
        // point is exactly cocircular, and also when their circumcentres round to the same point
        // (so that no edge has zero length in the floating-point output either).
        // Each edge is decided once, from its half-edge with the larger twin, in parallel; the
        // rare merges then mark the twin too and are joined in order.
        let mut internal: Vec<bool> = map_indexed(d.triangles.len(), |e| {
            let t = d.twins[e];
            if t == INVALID || (t as usize) < e {
                return false;
            }
            let (here, there) = (centres[e / 3], centres[(t / 3) as usize]);
            here == there
                || (may_be_cocircular(here, there, d.corner_point(e as u32), d.scale) && {
                    let base = 3 * (e as u32 / 3);
                    let [a, b, c] = [base, base + 1, base + 2].map(|k| d.corner_point(k));
                    incircle(a, b, c, d.corner_point(prev_edge(t))) == 0.0
                })
        });
        let merged: Vec<u32> = (0..internal.len() as u32)
            .filter(|&e| internal[e as usize])
            .collect();
        for &e in &merged {
            internal[d.twins[e as usize] as usize] = true;
        }
        let any_merge = !merged.is_empty();
        let mut parent: Vec<u32> = if any_merge {
            (0..n_tri as u32).collect()
        } else {
            Vec::new()
        };
        if any_merge {
            for &e in &merged {
                let t = d.twins[e as usize];
                let (ra, rb) = (find(&mut parent, e / 3), find(&mut parent, t / 3));
                if ra != rb {
                    parent[ra.max(rb) as usize] = ra.min(rb);
                }
            }
        }
        let (triangle_vertex, vertices) = if any_merge {
            let mut triangle_vertex = vec![INVALID; n_tri];
            let mut vertices = Vec::with_capacity(n_tri);
            for t in 0..n_tri as u32 {
                let root = find(&mut parent, t);
                if triangle_vertex[root as usize] == INVALID {
                    triangle_vertex[root as usize] = vertices.len() as u32;
                    vertices.push(centres[root as usize]);
                }
                triangle_vertex[t as usize] = triangle_vertex[root as usize];
            }
            (triangle_vertex, vertices)
        } else {
            // No cocircular or coincident pair (the usual case): one vertex per triangle.
            ((0..n_tri as u32).collect(), centres)
        };
        // Half-edges: a pair per kept Delaunay edge; the even one is dual to the Delaunay
        // half-edge `e` (cell of origin(e)), the odd one to its twin (or the hull's outer side).
        let mut dual = vec![INVALID; d.triangles.len()];
        let n_half = internal.iter().filter(|&&i| !i).count() * 2; // upper bound, exact below
        let mut origin = Vec::with_capacity(n_half);
        let mut site = Vec::with_capacity(n_half);
        for e in 0..d.triangles.len() as u32 {
            let t = d.twins[e as usize];
            if internal[e as usize] || (t != INVALID && t < e) {
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
            site.push(d.origin(e));
            origin.push(here);
            site.push(d.origin(next_edge(e)));
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
                    let a = d.origin(e);
                    next[out_ray as usize] = dual[d.vertex_edge[a as usize] as usize];
                    break out_ray;
                }
                if !internal[t as usize] {
                    break dual[t as usize];
                }
                cur = t;
            };
        }
        // A cell starts at the dual of its site's vertex edge: the outgoing hull edge for hull
        // sites, whose dual is the in-ray. (One read per site instead of a write per half-edge.)
        self.cell_edge = map_indexed(d.n_sites(), |site| {
            if d.vertex_edge[site] == INVALID {
                return INVALID;
            }
            d.outgoing(site as u32)
                .map(|e| dual[e as usize])
                .find(|&h| h != INVALID)
                .unwrap_or(INVALID)
        });
        self.vertices = vertices;
        self.triangle_vertex = triangle_vertex;
        self.origin = origin;
        self.site = site;
        self.finish_links(next);
    }

    /// All sites on a line: the cells are slabs between parallel bisectors.
    fn build_parallel(&mut self) {
        let chain = self.delaunay.hull.clone();
        let m = chain.len() - 1;
        self.origin = vec![INVALID; 2 * m];
        self.site = Vec::with_capacity(2 * m);
        for w in chain.windows(2) {
            self.site.push(w[0]);
            self.site.push(w[1]);
        }
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
            self.cell_edge[chain[k + 1] as usize] = left_of_next;
        }
        next[0] = 0;
        self.cell_edge[chain[0] as usize] = 0;
        self.finish_links(next);
    }

    fn finish_links(&mut self, next: Vec<u32>) {
        let mut prev = vec![INVALID; next.len()];
        for (h, &n) in next.iter().enumerate() {
            if n != INVALID {
                prev[n as usize] = h as u32;
            }
        }
        let mut vertex_edge = vec![INVALID; self.vertices.len()];
        for (h, &o) in self.origin.iter().enumerate() {
            if o != INVALID {
                vertex_edge[o as usize] = h as u32;
            }
        }
        self.next = next;
        self.prev = prev;
        self.vertex_edge = vertex_edge;
    }

    /// Circumcentre of Delaunay triangle `t`, computed relative to its first corner in the
    /// scaled frame and mapped back (dividing by a power of two is exact).
    fn circumcentre(&self, t: u32) -> [f64; 2] {
        let d = &self.delaunay;
        let base = 3 * t;
        let [a, b, c] = [base, base + 1, base + 2].map(|k| d.corner_point(k));
        let [ux, uy] = circumcentre_offset(a, b, c);
        [(a[0] + ux) / d.scale, (a[1] + uy) / d.scale]
    }

    /// The underlying Delaunay triangulation.
    pub fn delaunay(&self) -> &Delaunay {
        &self.delaunay
    }

    /// Number of Voronoi vertices.
    pub fn n_vertices(&self) -> usize {
        self.vertices.len()
    }

    /// Positions of all Voronoi vertices.
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// An outgoing half-edge of vertex `v`.
    pub fn vertex_edge(&self, v: u32) -> u32 {
        self.vertex_edge.get(v as usize).copied().unwrap_or(INVALID)
    }

    /// Number of half-edges (twice the number of edges).
    pub fn n_halfedges(&self) -> usize {
        self.origin.len()
    }

    /// Start vertex of `h`, [`INVALID`] when it comes from infinity (or `h` is invalid).
    pub fn origin(&self, h: u32) -> u32 {
        self.origin.get(h as usize).copied().unwrap_or(INVALID)
    }

    /// End vertex of `h`, [`INVALID`] when it runs to infinity.
    pub fn target(&self, h: u32) -> u32 {
        self.origin(h ^ 1)
    }

    /// The opposite half-edge (`h ^ 1`).
    pub fn twin(&self, h: u32) -> u32 {
        h ^ 1
    }

    /// Next half-edge counter-clockwise around the same cell.
    pub fn next(&self, h: u32) -> u32 {
        self.next.get(h as usize).copied().unwrap_or(INVALID)
    }

    /// Previous half-edge around the same cell.
    pub fn prev(&self, h: u32) -> u32 {
        self.prev.get(h as usize).copied().unwrap_or(INVALID)
    }

    /// The site whose cell `h` bounds (on its left).
    pub fn site(&self, h: u32) -> u32 {
        self.site.get(h as usize).copied().unwrap_or(INVALID)
    }

    /// The site across `h`.
    pub fn opposite_site(&self, h: u32) -> u32 {
        self.site(h ^ 1)
    }

    /// A half-edge of the cell of `site` ([`INVALID`] for duplicates, out-of-range sites, and when
    /// the diagram has no edges). For an unbounded cell it is the edge coming in from infinity.
    pub fn cell_edge(&self, site: u32) -> u32 {
        self.cell_edge
            .get(site as usize)
            .copied()
            .unwrap_or(INVALID)
    }

    /// Half-edges of the cell of `site`, counter-clockwise (in-ray first for unbounded cells).
    pub fn cell_halfedges(&self, site: u32) -> Vec<u32> {
        let start = self.cell_edge(site);
        let mut out = Vec::new();
        if start == INVALID {
            return out;
        }
        let mut h = start;
        loop {
            out.push(h);
            h = self.next[h as usize];
            if h == start || out.len() > self.origin.len() {
                break;
            }
        }
        out
    }

    /// Is the cell of `site` bounded?
    pub fn is_bounded(&self, site: u32) -> bool {
        let h = self.cell_edge(site);
        h != INVALID && self.origin[h as usize] != INVALID
    }

    /// Sites whose cells share an edge with the cell of `site` (Delaunay neighbours not merged
    /// away by cocircularity), counter-clockwise.
    pub fn neighbours(&self, site: u32) -> Vec<u32> {
        self.cell_halfedges(site)
            .into_iter()
            .map(|h| self.opposite_site(h))
            .collect()
    }

    /// The half-edge of the cell of `a` separating it from the cell of `b`, if they share an edge.
    pub fn edge_between(&self, a: u32, b: u32) -> Option<u32> {
        let (a, b) = (self.canonical(a)?, self.canonical(b)?);
        self.cell_halfedges(a)
            .into_iter()
            .find(|&h| self.opposite_site(h) == b)
    }

    fn canonical(&self, s: u32) -> Option<u32> {
        self.delaunay.representative.get(s as usize).copied()
    }

    /// Sites equidistant from vertex `v` (all corners of its merged Delaunay triangles),
    /// counter-clockwise.
    pub fn vertex_sites(&self, v: u32) -> Vec<u32> {
        let start = self.vertex_edge(v);
        let mut out = Vec::new();
        if start == INVALID {
            return out;
        }
        let mut h = start;
        loop {
            out.push(self.site[h as usize]);
            // Next outgoing half-edge around v: twin of the previous edge of this cell.
            h = self.prev[h as usize] ^ 1;
            if h == start || out.len() > self.origin.len() {
                break;
            }
        }
        out
    }

    /// Geometry of the edge of half-edge `h`, `None` for an invalid half-edge.
    pub fn edge_geometry(&self, h: u32) -> Option<EdgeGeometry> {
        if h as usize >= self.origin.len() {
            return None;
        }
        Some(self.geometry(h))
    }

    pub(crate) fn geometry(&self, h: u32) -> EdgeGeometry {
        let (o, t) = (self.origin(h), self.target(h));
        if o != INVALID && t != INVALID {
            return EdgeGeometry::Segment {
                from: self.vertices[o as usize],
                to: self.vertices[t as usize],
            };
        }
        let sites = self.delaunay.sites();
        let (a, b) = (
            sites[self.site(h) as usize],
            sites[self.opposite_site(h) as usize],
        );
        // Left site a: moving along the bisector with a on the left is direction rot90(b - a).
        let along = [a[1] - b[1], b[0] - a[0]];
        match (o == INVALID, t == INVALID) {
            (true, false) => EdgeGeometry::Ray {
                origin: self.vertices[t as usize],
                direction: [-along[0], -along[1]],
            },
            (false, true) => EdgeGeometry::Ray {
                origin: self.vertices[o as usize],
                direction: along,
            },
            _ => EdgeGeometry::Line {
                point: [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])],
                direction: along,
            },
        }
    }
}

/// The circumcentre of triangle `abc` minus `a`, to within about 1e-10 of its length.
///
/// The usual formula `(cy·|b|² − by·|c|², bx·|c|² − cx·|b|²) / 2(bx·cy − by·cx)` (with `b`, `c`
/// taken relative to `a`) is used when a bound on its rounding errors says it is that accurate:
/// every rounding, the differences `b − a`, `c − a` included, is at most a few ulps of the
/// magnitudes of the products, so when the results are no more than [`CANCELLATION_LIMIT`]
/// times smaller than those magnitudes the relative error stays below ~1e-10. Flatter triangles
/// (a small fraction; their centres are far away and sensitive) are computed exactly and
/// rounded once.
#[inline]
fn circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    let (bl, cl) = (bx * bx + by * by, cx * cx + cy * cy);
    let det = bx * cy - by * cx;
    let (ux, uy) = (cy * bl - by * cl, bx * cl - cx * bl);
    let det_size = (bx * cy).abs() + (by * cx).abs();
    let u_size = (cy * bl).abs() + (by * cl).abs() + (bx * cl).abs() + (cx * bl).abs();
    if det.abs() * CANCELLATION_LIMIT >= det_size
        && (ux.abs() + uy.abs()) * CANCELLATION_LIMIT >= u_size
    {
        let inverse = 0.5 / det;
        [ux * inverse, uy * inverse]
    } else {
        exact_circumcentre_offset(a, b, c)
    }
}

/// Can two adjacent triangles be exactly cocircular, given their floating-point circumcentres
/// `here` and `there` and a shared corner (`scaled_corner` in the frame multiplied by `scale`)?
///
/// Cocircular triangles have the same exact centre, and [`circumcentre_offset`] places each
/// within ~1.5e-10 of the radius of it, so centres farther apart than 1e-8 radii (a margin of
/// about 50, measured in the L1 norm, which never underflows to zero for tiny sites) cannot be;
/// only the rest go to the exact in-circle test, which decides.
#[inline]
fn may_be_cocircular(here: [f64; 2], there: [f64; 2], scaled_corner: [f64; 2], scale: f64) -> bool {
    let corner = [scaled_corner[0] / scale, scaled_corner[1] / scale];
    let apart = (here[0] - there[0]).abs() + (here[1] - there[1]).abs();
    let radius = (here[0] - corner[0]).abs() + (here[1] - corner[1]).abs();
    apart <= 1e-8 * radius
}

/// How much cancellation [`circumcentre_offset`] accepts in floating point: about 1e-10 relative
/// error from a few ulps (2.2e-16 each) amplified by this factor.
const CANCELLATION_LIMIT: f64 = 1.0e5;

/// [`circumcentre_offset`] in exact arithmetic, each coordinate rounded once at the end (the
/// division adds half an ulp).
#[cold]
fn exact_circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    let (bx, by) = (Exact::difference(b[0], a[0]), Exact::difference(b[1], a[1]));
    let (cx, cy) = (Exact::difference(c[0], a[0]), Exact::difference(c[1], a[1]));
    let bl = bx.times(&bx).plus(&by.times(&by)).compressed();
    let cl = cx.times(&cx).plus(&cy.times(&cy)).compressed();
    let det = bx.times(&cy).minus(&by.times(&cx)).value();
    let ux = cy.times(&bl).minus(&by.times(&cl)).value();
    let uy = bx.times(&cl).minus(&cx.times(&bl)).value();
    // A Delaunay triangle is never flat (exact orientation), so `det` is not zero.
    [ux / (2.0 * det), uy / (2.0 * det)]
}

/// Union-find root with path halving.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let grand = parent[parent[x as usize] as usize];
        parent[x as usize] = grand;
        x = grand;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circumcentres_of_flat_triangles_stay_accurate() {
        // (0, 0), (1, 0), (2, h): the centre is (0.5, (2 + h²) / 2h) exactly; the fast formula
        // would lose about log10(1/h) digits to cancellation.
        for h in [1e-3, 1e-9, 1e-12, 3e-15] {
            let [x, y] = circumcentre_offset([0.0, 0.0], [1.0, 0.0], [2.0, h]);
            let exact_y = 1.0 / h + 0.5 * h;
            assert!((x - 0.5).abs() <= 1e-12, "h = {h}: x = {x}");
            assert!((y - exact_y).abs() <= 1e-12 * exact_y, "h = {h}: y = {y}");
        }
        // A corner far from the two others: the numerators cancel instead of the determinant.
        let [x, y] = circumcentre_offset([0.0, 0.0], [1e6, 1.0], [1e6, 1.0 + 1e-6]);
        let expect = exact_circumcentre_offset([0.0, 0.0], [1e6, 1.0], [1e6, 1.0 + 1e-6]);
        assert!(
            (x - expect[0]).abs() + (y - expect[1]).abs() <= 1e-10 * expect[0].hypot(expect[1])
        );
    }

    #[test]
    fn cocircular_filter_never_rejects_equal_centres() {
        let centre = [0.25, -3.0];
        assert!(may_be_cocircular(centre, centre, [2.0, 2.0], 2.0));
        assert!(!may_be_cocircular(centre, [0.26, -3.0], [2.0, 2.0], 2.0));
        // Tiny magnitudes: the L1 test does not underflow to "apart".
        let tiny = [1e-300, 2e-300];
        assert!(may_be_cocircular(tiny, tiny, [0.5, 0.5], 1e300));
    }
}
