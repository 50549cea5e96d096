//! The Voronoi diagram as a DCEL, dual to the Delaunay triangulation.

use std::sync::OnceLock;

use super::dcel::HalfEdges;
use super::delaunay::{Delaunay, Dimension, INVALID, entry};
use super::error::VoronoiError;
use super::expansion::Exact;
use super::ids::{SiteId, VoronoiHalfedgeId, VoronoiVertexId};
use super::incremental::prev_edge;
use super::parallel::{map_each, seamed_run_length};
use super::predicates::{incircle_in, normalising_scale_of_box};
use crate::geom::exact_orientation::{integers, smallest_unit};
use crate::support::disjoint_sets;
use crate::support::large_arrays;

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
/// * Cells are named by [`SiteId`], vertices by [`VoronoiVertexId`], half-edges by
///   [`VoronoiHalfedgeId`]; a query given an id out of range answers with the invalid id.
/// * Half-edge `h` bounds the cell of [`Voronoi::site`]`(h)`, which lies on its **left**; its twin
///   bounds the cell of [`Voronoi::opposite_site`]`(h)`. Every edge is the perpendicular bisector
///   piece between those two sites, dual to the Delaunay edge joining them.
/// * `next` circulates **counter-clockwise** around the cell. An unbounded cell's cycle passes
///   through infinity: the half-edge running out to infinity ([`Voronoi::target`] invalid) is
///   followed by the one coming back ([`Voronoi::origin`] invalid).
/// * Cocircular sites give one vertex of degree > 3 (Delaunay triangles with the same
///   circumcircle, decided exactly with the in-circle predicate, are merged). Adjacent triangles
///   whose circumcentres round to the same floating-point point are merged too, so no edge has
///   zero length in the output.
/// * A vertex's coordinates are its circumcentre's, each rounded to the nearest double. Sites
///   collinear but for far less than an ulp can have a circumcentre beyond the range of `f64`
///   (past `1.8e308`): a coordinate that overflows is infinite, with the sign of the exact
///   coordinate, never NaN. Such a vertex is still a vertex of the diagram (test it with
///   `is_finite`); its edges lie on the bisectors of their two sites ([`Voronoi::site`],
///   [`Voronoi::opposite_site`]), and clipping, nearest-site queries and Lloyd relaxation
///   place cells from the sites and triangles, not from these positions.
/// * Cells are indexed by site; duplicates (see [`Delaunay::representative`]) have no cell of
///   their own.
///
/// Construction places the vertices; the half-edge arrays are derived from the triangles on
/// first use (by any half-edge query), since clipping, nearest-site queries and Lloyd relaxation
/// read the cells straight from the triangles and never need them.
#[derive(Clone, Debug)]
pub struct Voronoi {
    pub(crate) delaunay: Delaunay,
    pub(crate) vertices: Vec<[f64; 2]>,
    pub(crate) triangle_vertex: Vec<u32>,
    /// The half-edge arrays, built on first use (see [`HalfEdges`]).
    half_edges: OnceLock<HalfEdges>,
}

impl Voronoi {
    /// The Voronoi diagram of `sites` (see [`Delaunay::new`] for the accepted input).
    pub fn new(sites: &[[f64; 2]]) -> Result<Self, VoronoiError> {
        Ok(Self::from_delaunay(Delaunay::new(sites)?))
    }

    /// The dual of an existing triangulation.
    pub fn from_delaunay(delaunay: Delaunay) -> Self {
        let unscale = delaunay.scale.recip();
        Self::from_delaunay_by(delaunay, |v, t| v.circumcircle(t, unscale))
    }

    /// The dual of `delaunay`, the circumcentre of triangle `t` and the L1 length of its offset
    /// from the triangle's first corner (at least the circumradius) given by `circumcircle(v,
    /// t)` (see [`Voronoi::circumcircle`]).
    pub(crate) fn from_delaunay_by(
        delaunay: Delaunay,
        circumcircle: impl Fn(&Voronoi, u32) -> ([f64; 2], f64) + Sync,
    ) -> Self {
        let mut v = Voronoi {
            vertices: Vec::new(),
            triangle_vertex: Vec::new(),
            half_edges: OnceLock::new(),
            delaunay,
        };
        match v.delaunay.dimension() {
            Dimension::Plane => v.place_vertices(circumcircle),
            // Without triangles the half-edge arrays are tiny and are the only description.
            Dimension::Line => {
                let slabs = HalfEdges::parallel(&v.delaunay);
                v.half_edges = OnceLock::from(slabs);
            }
            Dimension::Empty | Dimension::Point => {
                let nothing = HalfEdges::empty(v.delaunay.n_sites());
                v.half_edges = OnceLock::from(nothing);
            }
        }
        v
    }

    /// Groups triangles with one circumcircle and places one vertex per group.
    fn place_vertices(&mut self, circumcircle: impl Fn(&Voronoi, u32) -> ([f64; 2], f64) + Sync) {
        let d = &self.delaunay;
        let n_tri = d.n_triangles();
        // Union-find over triangles: adjacent triangles share a Voronoi vertex when their fourth
        // point is exactly cocircular, and also when their circumcentres round to the same point
        // (so that no edge has zero length in the floating-point output either). Each edge is
        // decided once, from the triangle with the larger index, as soon as both centres are
        // known: in the same pass for neighbours in the same run of triangles (whose centres are
        // still in cache), after the pass for the others, which are listed for it.
        // `e` lies in the triangle whose circumcircle is (`here`, `radius`).
        let same_vertex = |e: u32, here: [f64; 2], radius: f64, there: [f64; 2]| {
            here == there
                || (may_be_cocircular(here, there, radius) && {
                    let [a, b, c] = d.triangle_points(e / 3);
                    let apex = d.corner_point(prev_edge(d.twins[e as usize]));
                    incircle_in(a, b, c, apex, &d.set_bounds) == 0.0
                })
        };
        // A few long runs: enough to share the work among threads, few edges between runs.
        let run_len = seamed_run_length(n_tri);
        let mut centres = large_arrays::zeroed::<[f64; 2]>(n_tri);
        // Union-find over triangles, parents as triangle ids. Neighbours in one run are joined
        // in that run's own part of the array, so runs are independent.
        let mut group = large_arrays::zeroed::<u32>(n_tri);
        let runs = map_each(
            centres
                .chunks_mut(run_len)
                .zip(group.chunks_mut(run_len))
                .collect(),
            |k, (run, run_group): (&mut [[f64; 2]], &mut [u32])| {
                let first = (k * run_len) as u32;
                // Each triangle its own group (and vertex) to begin with.
                run_group
                    .iter_mut()
                    .zip(first..)
                    .for_each(|(slot, t)| *slot = t);
                let (mut any_merged, mut later) = (false, Vec::new());
                for i in 0..run.len() {
                    let t = first + i as u32;
                    let (here, radius) = circumcircle(self, t);
                    run[i] = here;
                    for e in 3 * t..3 * t + 3 {
                        let twin = d.twins[e as usize];
                        let neighbour = twin / 3;
                        if twin == INVALID || neighbour > t {
                            continue;
                        }
                        if neighbour < first {
                            later.push(e);
                        } else if same_vertex(e, here, radius, run[(neighbour - first) as usize]) {
                            disjoint_sets::join(run_group, first, t, neighbour);
                            any_merged = true;
                        }
                    }
                }
                (any_merged, later)
            },
        );
        // The edges between runs, now that every centre is known: about a quarter of all edges
        // (triangles are numbered by their newest corner, and the insertion rounds scatter the
        // older ones), so they are decided in parallel too.
        let (merged_in_runs, later): (Vec<bool>, Vec<_>) = runs.into_iter().unzip();
        let centres_known = &centres;
        let merged_between = map_each(later, |_, edges: Vec<u32>| {
            let merged = edges.into_iter().filter(|&e| {
                let twin = d.twins[e as usize];
                let (here, radius) = circumcircle(self, e / 3);
                same_vertex(e, here, radius, centres_known[(twin / 3) as usize])
            });
            merged.collect::<Vec<u32>>()
        });
        if !merged_in_runs.contains(&true) && merged_between.iter().all(Vec::is_empty) {
            // No cocircular or coincident pair (the usual case): one vertex per triangle.
            self.triangle_vertex = group;
            self.vertices = centres;
            return;
        }
        for &e in merged_between.iter().flatten() {
            disjoint_sets::join(&mut group, 0, e / 3, d.twins[e as usize] / 3);
        }
        // The groups become vertex numbers in place, and the roots' centres move to the front.
        let n_vertices =
            disjoint_sets::number_sets(&mut group, |_| false, |t, slot| centres[slot] = centres[t]);
        self.triangle_vertex = group;
        self.vertices = large_arrays::fit(centres, n_vertices);
    }

    /// Were any triangles merged into one Voronoi vertex? (Not for non-degenerate input.)
    #[inline(always)]
    pub(crate) fn any_merged(&self) -> bool {
        self.vertices.len() < self.triangle_vertex.len()
    }

    /// Is Delaunay half-edge `e` merged away (both its sides one Voronoi vertex, so no Voronoi
    /// edge)? Decided from the vertex numbers, so that no edge of the diagram joins a vertex to
    /// itself even where a group was joined through other edges.
    #[inline(always)]
    pub(crate) fn is_merged(&self, e: u32) -> bool {
        self.any_merged() && {
            let twin = self.delaunay.twins[e as usize];
            twin != INVALID
                && self.triangle_vertex[(e / 3) as usize]
                    == self.triangle_vertex[(twin / 3) as usize]
        }
    }

    /// The half-edge arrays, built on first use.
    pub(crate) fn half_edges(&self) -> &HalfEdges {
        self.half_edges.get_or_init(|| {
            HalfEdges::planar(
                &self.delaunay,
                &self.triangle_vertex,
                self.vertices.len(),
                |e| self.is_merged(e),
            )
        })
    }

    /// Circumcentre of Delaunay triangle `t`, computed relative to its first corner in the
    /// scaled frame and mapped back, and the L1 length of that offset (at least the
    /// circumradius). `unscale` is `1 / scale`: both are powers of two, so multiplying by it
    /// rounds exactly as dividing by `scale` would, and is several times cheaper.
    #[inline(always)]
    fn circumcircle(&self, t: u32, unscale: f64) -> ([f64; 2], f64) {
        let d = &self.delaunay;
        let [a, b, c] = d.triangle_points(t);
        let (centre, [ux, uy]) = match fast_circumcentre_offset(a, b, c) {
            Some(u) if !loses_a_coordinate(a, u) => ([a[0] + u[0], a[1] + u[1]], u),
            _ => {
                let split = SplitCentre::of(a, b, c);
                (split.centre(), split.from_first)
            }
        };
        (centre.map(|x| x * unscale), (ux.abs() + uy.abs()) * unscale)
    }

    /// The underlying Delaunay triangulation.
    pub fn delaunay(&self) -> &Delaunay {
        &self.delaunay
    }

    /// Number of Voronoi vertices.
    pub fn n_vertices(&self) -> usize {
        self.vertices.len()
    }

    /// Positions of all Voronoi vertices: infinite in a coordinate whose circumcentre lies
    /// beyond the range of `f64` (see [`Voronoi`]).
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// An outgoing half-edge of vertex `v`.
    pub fn vertex_edge(&self, v: VoronoiVertexId) -> VoronoiHalfedgeId {
        VoronoiHalfedgeId(entry(&self.half_edges().vertex_edge, v.0))
    }

    /// Number of half-edges (twice the number of edges).
    pub fn n_halfedges(&self) -> usize {
        self.half_edges().origin.len()
    }

    /// Start vertex of `h`, invalid when it comes from infinity (or `h` is invalid).
    pub fn origin(&self, h: VoronoiHalfedgeId) -> VoronoiVertexId {
        VoronoiVertexId(entry(&self.half_edges().origin, h.0))
    }

    /// End vertex of `h`, invalid when it runs to infinity.
    pub fn target(&self, h: VoronoiHalfedgeId) -> VoronoiVertexId {
        self.origin(h.twin())
    }

    /// The opposite half-edge (`h ^ 1`, see [`VoronoiHalfedgeId::twin`]).
    pub fn twin(&self, h: VoronoiHalfedgeId) -> VoronoiHalfedgeId {
        h.twin()
    }

    /// Next half-edge counter-clockwise around the same cell.
    pub fn next(&self, h: VoronoiHalfedgeId) -> VoronoiHalfedgeId {
        VoronoiHalfedgeId(entry(&self.half_edges().next, h.0))
    }

    /// Previous half-edge around the same cell.
    pub fn prev(&self, h: VoronoiHalfedgeId) -> VoronoiHalfedgeId {
        VoronoiHalfedgeId(entry(&self.half_edges().prev, h.0))
    }

    /// The site whose cell `h` bounds (on its left).
    pub fn site(&self, h: VoronoiHalfedgeId) -> SiteId {
        SiteId(entry(&self.half_edges().site, h.0))
    }

    /// The site across `h`.
    pub fn opposite_site(&self, h: VoronoiHalfedgeId) -> SiteId {
        self.site(h.twin())
    }

    /// A half-edge of the cell of `site` (invalid for duplicates, out-of-range sites, and when
    /// the diagram has no edges). For an unbounded cell it is the edge coming in from infinity.
    pub fn cell_edge(&self, site: SiteId) -> VoronoiHalfedgeId {
        VoronoiHalfedgeId(entry(&self.half_edges().cell_edge, site.0))
    }

    /// Half-edges of the cell of `site`, counter-clockwise (in-ray first for unbounded cells).
    pub fn cell_halfedges(&self, site: SiteId) -> Vec<VoronoiHalfedgeId> {
        let start = self.cell_edge(site).0;
        let mut out = Vec::new();
        if start == INVALID {
            return out;
        }
        let links = self.half_edges();
        let mut h = start;
        loop {
            out.push(VoronoiHalfedgeId(h));
            h = links.next[h as usize];
            if h == start || out.len() > links.origin.len() {
                break;
            }
        }
        out
    }

    /// Is the cell of `site` bounded?
    pub fn is_bounded(&self, site: SiteId) -> bool {
        let h = self.cell_edge(site);
        h.is_valid() && self.origin(h).is_valid()
    }

    /// Sites whose cells share an edge with the cell of `site` (Delaunay neighbours not merged
    /// away by cocircularity), counter-clockwise.
    pub fn neighbours(&self, site: SiteId) -> Vec<SiteId> {
        self.cell_halfedges(site)
            .into_iter()
            .map(|h| self.opposite_site(h))
            .collect()
    }

    /// The half-edge of the cell of `a` separating it from the cell of `b`, if they share an edge.
    pub fn edge_between(&self, a: SiteId, b: SiteId) -> Option<VoronoiHalfedgeId> {
        let delaunay = &self.delaunay;
        let (a, b) = (
            delaunay.representative_of(a)?,
            delaunay.representative_of(b)?,
        );
        self.cell_halfedges(a)
            .into_iter()
            .find(|&h| self.opposite_site(h) == b)
    }

    /// Sites equidistant from vertex `v` (all corners of its merged Delaunay triangles),
    /// counter-clockwise.
    pub fn vertex_sites(&self, v: VoronoiVertexId) -> Vec<SiteId> {
        let start = self.vertex_edge(v).0;
        let mut out = Vec::new();
        if start == INVALID {
            return out;
        }
        let links = self.half_edges();
        let mut h = start;
        loop {
            out.push(SiteId(links.site[h as usize]));
            // Next outgoing half-edge around v: twin of the previous edge of this cell.
            h = links.prev[h as usize] ^ 1;
            if h == start || out.len() > links.origin.len() {
                break;
            }
        }
        out
    }

    /// Geometry of the edge of half-edge `h`, `None` for an invalid half-edge.
    pub fn edge_geometry(&self, h: VoronoiHalfedgeId) -> Option<EdgeGeometry> {
        if h.index() >= self.n_halfedges() {
            return None;
        }
        Some(self.geometry(h.0))
    }

    pub(crate) fn geometry(&self, h: u32) -> EdgeGeometry {
        let links = self.half_edges();
        self.geometry_of(EdgeEnds {
            from: links.origin[h as usize],
            to: links.origin[(h ^ 1) as usize],
            left: links.site[h as usize],
            right: links.site[(h ^ 1) as usize],
        })
    }

    /// Geometry of the edge with ends `ends` (see [`EdgeEnds`]).
    pub(crate) fn geometry_of(&self, ends: EdgeEnds) -> EdgeGeometry {
        let (o, t) = (ends.from, ends.to);
        if o != INVALID && t != INVALID {
            return EdgeGeometry::Segment {
                from: self.vertices[o as usize],
                to: self.vertices[t as usize],
            };
        }
        let (midpoint, along) = self.bisector(ends);
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
                point: midpoint,
                direction: along,
            },
        }
    }

    /// The bisector of the edge's two sites, computed from the sites alone: their midpoint, and
    /// the direction along it with the left site on the left, `rot90(right − left)`.
    pub(crate) fn bisector(&self, ends: EdgeEnds) -> ([f64; 2], [f64; 2]) {
        let sites = self.delaunay.sites();
        let (a, b) = (sites[ends.left as usize], sites[ends.right as usize]);
        (
            [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])],
            [a[1] - b[1], b[0] - a[0]],
        )
    }
}

/// A Voronoi edge, oriented, by its end vertices ([`INVALID`] at infinity) and the sites on its
/// left and right: what its geometry and clipping need, whether or not half-edges exist.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EdgeEnds {
    pub from: u32,
    pub to: u32,
    pub left: u32,
    pub right: u32,
}

/// The circumcentre of triangle `abc` minus `a`, to within about 1e-10 of its length:
/// [`fast_circumcentre_offset`], or for a flat triangle the exact offset rounded once.
#[cfg(test)]
fn circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    fast_circumcentre_offset(a, b, c)
        .unwrap_or_else(|| exactly_rounded_circumcentre_offset(a, b, c))
}

/// The circumcentre of triangle `abc` minus `a`, to within about 1e-10 of its length, or `None`
/// for a flat triangle.
///
/// The usual formula `(cy·|b|² − by·|c|², bx·|c|² − cx·|b|²) / 2(bx·cy − by·cx)` (with `b`, `c`
/// taken relative to `a`) is used when a bound on its rounding errors says it is that accurate:
/// every rounding, the differences `b − a`, `c − a` included, is at most a few ulps of the
/// magnitudes of the products, so when the results are no more than [`CANCELLATION_LIMIT`]
/// times smaller than those magnitudes the relative error stays below ~1e-10. Flatter triangles
/// (a small fraction; their centres are far away and sensitive) are left to exact arithmetic
/// ([`SplitCentre`]).
///
/// The differences are first brought near 1 by a power of two (exact, short of underflow: sums
/// below [`SMALLEST_BOUNDED_SIZE`] go to exact arithmetic too), so that products of three of
/// them neither underflow (sites of a frame normalised for a far site, `1e154` beside the unit
/// square, are `1e-154` apart) nor overflow (a frame kept wide so that sites near `1e-300` keep
/// their low bits beside one at `1e301`).
#[inline(always)]
fn fast_circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    let (unit, unit_inverse) = unit_of_differences([bx, by, cx, cy]);
    let [bx, by, cx, cy] = [bx, by, cx, cy].map(|x| x * unit);
    let (bl, cl) = (bx * bx + by * by, cx * cx + cy * cy);
    let det = bx * cy - by * cx;
    let (ux, uy) = (cy * bl - by * cl, bx * cl - cx * bl);
    let det_size = (bx * cy).abs() + (by * cx).abs();
    let u_size = (cy * bl).abs() + (by * cl).abs() + (bx * cl).abs() + (cx * bl).abs();
    let accurate = det_size >= SMALLEST_BOUNDED_SIZE
        && u_size >= SMALLEST_BOUNDED_SIZE
        && det.abs() * CANCELLATION_LIMIT >= det_size
        && (ux.abs() + uy.abs()) * CANCELLATION_LIMIT >= u_size
        && (ux.is_finite() && uy.is_finite());
    let inverse = 0.5 / det;
    // `unit_inverse` is exact, so this rounds as dividing by `unit` would, several times faster.
    accurate.then(|| [ux * inverse, uy * inverse].map(|x| x * unit_inverse))
}

/// [`normalising_scale_of_box`] of a box reaching `largest` (not negative) in every direction,
/// and its inverse, both powers of two. For a normal `largest` both come straight from its
/// exponent bits: this runs once per Delaunay triangle.
#[inline(always)]
fn unit_scale_of(largest: f64) -> (f64, f64) {
    const EXPONENT_SHIFT: u32 = 52;
    // For a biased exponent `b` of 1 to 2045, 2^-e and 2^e (e = b - 1023) are both normal.
    let biased = largest.to_bits() >> EXPONENT_SHIFT;
    if (1..=2045).contains(&biased) {
        (
            f64::from_bits((2046 - biased) << EXPONENT_SHIFT),
            f64::from_bits(biased << EXPONENT_SHIFT),
        )
    } else {
        let unit = normalising_scale_of_box([[-largest, -largest], [largest, largest]]);
        (unit, unit.recip())
    }
}

/// The power of two that brings the largest of `differences` near 1, and its inverse.
#[inline(always)]
fn unit_of_differences([bx, by, cx, cy]: [f64; 4]) -> (f64, f64) {
    unit_scale_of(bx.abs().max(by.abs()).max(cx.abs()).max(cy.abs()))
}

/// The circumcentre of triangle `abc` minus `a`, each coordinate rounded from the exact value
/// (not only the offset's length accurate, as [`fast_circumcentre_offset`] gives it: a triangle
/// 1e15 times wider than tall has a centre whose short coordinate matters).
pub(crate) fn exactly_rounded_circumcentre_offset(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
) -> [f64; 2] {
    let (unit, _) = unit_of_differences([b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]]);
    exact_circumcentre_offset(a, b, c, unit).map(|x| x / unit)
}

/// Does the centre `a + offset` have a coordinate far smaller than the rounding of the fast
/// formula there? That rounding scales with the offset's length and with `a`'s coordinate, not
/// with the centre's: a centre 5e-288 above a region's side, 2e-59 from its corners, came out on
/// the side. Such a centre is placed by [`SplitCentre`] instead; elsewhere (all but a sliver of
/// the plane along the axes) the fast formula stays within a few hundred ulps.
#[inline(always)]
fn loses_a_coordinate(a: [f64; 2], offset: [f64; 2]) -> bool {
    const SHORT: f64 = 1.0 / 256.0;
    let reach = offset[0].abs() + offset[1].abs();
    (0..2).any(|k| (a[k] + offset[k]).abs() < SHORT * (reach + a[k].abs()))
}

/// A circumcentre as `base + offset`, coordinate by coordinate: `base[k]` is the coordinate of
/// the triangle's corner nearest to the centre along axis `k`, and `offset[k]` the centre's
/// offset from it, rounded once from its exact value, so that their sum is within about an ulp
/// of the centre's coordinate. From the first corner alone a short coordinate can be lost: with
/// that corner 1e109 away along x and 5e96 along y, and the two others 5e-13 apart along y
/// beside the centre, its y came out 0 instead of 536.
pub(crate) struct SplitCentre {
    pub base: [f64; 2],
    /// Which corner (0, 1 or 2, from `a`) each coordinate of `base` is taken from.
    pub corner: [usize; 2],
    pub offset: [f64; 2],
    /// The centre minus the first corner, each coordinate rounded once.
    pub from_first: [f64; 2],
}

impl SplitCentre {
    pub(crate) fn of(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> SplitCentre {
        let from_first = exactly_rounded_circumcentre_offset(a, b, c);
        let approximate = [0, 1].map(|k| a[k] + from_first[k]);
        let rotations = [[a, b, c], [b, c, a], [c, a, b]];
        let (mut base, mut corner, mut offset) = (a, [0; 2], from_first);
        for k in 0..2 {
            let gap = |r: usize| (rotations[r][0][k] - approximate[k]).abs();
            corner[k] = (1..3).fold(0, |best, r| if gap(r) < gap(best) { r } else { best });
            if corner[k] != 0 {
                let [p, q, r] = rotations[corner[k]];
                base[k] = p[k];
                offset[k] = exactly_rounded_circumcentre_offset(p, q, r)[k];
            }
        }
        SplitCentre {
            base,
            corner,
            offset,
            from_first,
        }
    }

    /// The centre, each coordinate rounded from `base + offset`.
    pub(crate) fn centre(&self) -> [f64; 2] {
        [0, 1].map(|k| self.base[k] + self.offset[k])
    }
}

/// Can two adjacent triangles be exactly cocircular, given their floating-point circumcentres
/// `here` and `there` and `radius`, at least the circumradius of one of them (L1 length)?
///
/// Cocircular triangles have the same exact centre. [`circumcentre_offset`] places each within
/// ~1.5e-10 of the radius of it, and moving it from its corner to absolute coordinates rounds by
/// at most half an ulp per coordinate; centres farther apart than 1e-8 radii (a margin of about
/// 50, measured in the L1 norm, which never underflows to zero for tiny sites) plus an ulp of
/// their magnitudes cannot be. Only the rest go to the exact in-circle test, which decides.
#[inline]
fn may_be_cocircular(here: [f64; 2], there: [f64; 2], radius: f64) -> bool {
    let apart = (here[0] - there[0]).abs() + (here[1] - there[1]).abs();
    let magnitude = here[0].abs() + here[1].abs() + there[0].abs() + there[1].abs();
    apart <= 1e-8 * radius + f64::EPSILON * magnitude
}

/// How much cancellation [`circumcentre_offset`] accepts in floating point: about 1e-10 relative
/// error from a few ulps (2.2e-16 each) amplified by this factor.
const CANCELLATION_LIMIT: f64 = 1.0e5;

/// The rounding bound of [`fast_circumcentre_offset`] holds for sums of products at least this
/// large (about 2^-900): a difference scaled into the subnormals, or a product there, is off by
/// up to 2^-1074, which is negligible only beside them. Two sites 1e-286 apart beside one at
/// 1e15 have scaled differences near 1e-313: a determinant made of them lost every digit, and
/// the centre, 8e27 away, came out infinite.
const SMALLEST_BOUNDED_SIZE: f64 = 1.0e-271;

/// Below this, a product of three scaled differences can underflow (`2^-300` cubed is
/// `2^-900`, and the products' error terms lie 2^-106 below that).
const UNDERFLOWING_TERM: f64 = 4.909093465297727e-91; // 2^-300

/// [`circumcentre_offset`] in exact arithmetic on the differences times `unit` (a power of two),
/// each coordinate rounded once at the end (the division adds half an ulp).
#[cold]
fn exact_circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2], unit: f64) -> [f64; 2] {
    let difference = |p: f64, q: f64| {
        let Exact(terms) = Exact::difference(p, q);
        Exact(terms.into_iter().map(|t| t * unit).collect())
    };
    let (bx, by) = (difference(b[0], a[0]), difference(b[1], a[1]));
    let (cx, cy) = (difference(c[0], a[0]), difference(c[1], a[1]));
    // Products of three terms this small underflow (a difference of 1e-287 beside one of 2e-59
    // lost the centre's short coordinate): integers take them.
    let smallest = [&bx, &by, &cx, &cy]
        .iter()
        .flat_map(|Exact(terms)| terms.iter())
        .filter(|t| **t != 0.0)
        .fold(f64::INFINITY, |m, t| m.min(t.abs()));
    if smallest < UNDERFLOWING_TERM {
        return wide_circumcentre_offset(a, b, c).map(|x| x * unit);
    }
    let bl = bx.times(&bx).plus(&by.times(&by)).compressed();
    let cl = cx.times(&cx).plus(&cy.times(&cy)).compressed();
    let det = bx.times(&cy).minus(&by.times(&cx)).value();
    let ux = cy.times(&bl).minus(&by.times(&cl)).value();
    let uy = bx.times(&cl).minus(&cx.times(&bl)).value();
    // A Delaunay triangle is never flat (exact orientation), so `det` is exactly nonzero; a zero
    // or non-finite value here is an under- or overflow of the expansions.
    let offset = [ux / (2.0 * det), uy / (2.0 * det)];
    if det != 0.0 && offset.iter().all(|x| x.is_finite()) {
        offset
    } else {
        wide_circumcentre_offset(a, b, c).map(|x| x * unit)
    }
}

/// [`circumcentre_offset`] in integers of any size, for corners whose coordinates span more
/// binary orders of magnitude than expansions hold (sites near `1e-300` and `1e300` in one
/// triangle): numerators and denominator exactly, one division of their leading bits.
#[cold]
fn wide_circumcentre_offset(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    let values = [a[0], a[1], b[0], b[1], c[0], c[1]];
    // `integers` multiplies every value by the power of two of the smallest unit among them.
    let unit = i64::from(smallest_unit(&values));
    let [ax, ay, bx, by, cx, cy] = integers(values);
    let (bx, by, cx, cy) = (bx.sub(&ax), by.sub(&ay), cx.sub(&ax), cy.sub(&ay));
    let bl = bx.mul(&bx).add(&by.mul(&by));
    let cl = cx.mul(&cx).add(&cy.mul(&cy));
    let det = bx.mul(&cy).sub(&by.mul(&cx));
    let ux = cy.mul(&bl).sub(&by.mul(&cl));
    let uy = bx.mul(&cl).sub(&cx.mul(&bl));
    // Degree three over degree two, halved: the result is in units of 2^unit.
    [ux, uy].map(|u| u.ratio(&det, unit - 1))
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
        let expect = exact_circumcentre_offset([0.0, 0.0], [1e6, 1.0], [1e6, 1.0 + 1e-6], 1.0);
        assert!(
            (x - expect[0]).abs() + (y - expect[1]).abs() <= 1e-10 * expect[0].hypot(expect[1])
        );
    }

    #[test]
    fn a_centre_from_differences_scaled_into_the_subnormals_is_exact() {
        // Two sites 1e-286 apart near 1e-271 and one at 1e15: scaled so that 1e15 is near 1, the
        // short differences are subnormal. The centre lies at (3.6e15, 8.0e27).
        let sites = [
            [1.0000000000000491e-271, -3.924186530907457e-284],
            [1.000000000000048e-271, -3.924186530907452e-284],
            [1000000000000049.8, -392.4186530907462],
        ];
        let exact = wide_circumcentre_offset(sites[0], sites[1], sites[2]);
        assert!((exact[1] - 8.021986944739589e27).abs() <= 1e-15 * exact[1]);
        for r in 0..3 {
            let [a, b, c] = [0, 1, 2].map(|k| sites[(r + k) % 3]);
            let [x, y] = circumcentre_offset(a, b, c);
            let expect = wide_circumcentre_offset(a, b, c);
            assert!(
                (x - expect[0]).abs() + (y - expect[1]).abs() <= 1e-10 * expect[1].abs(),
                "rotation {r}: {x:e}, {y:e} against {expect:?}"
            );
        }
    }

    #[test]
    fn a_flat_triangles_centre_keeps_its_short_coordinate() {
        // Two sites 5e-13 apart on a vertical line at 1e15 and one 1e109 away: the centre lies on
        // their horizontal bisector, y = 536.26932490503235, but 5e108 from every corner. Taken
        // from the far corner, whose y is 5e96, its y came out 0.
        let far = [1.000000000000049e109, 5.362693249050314e96];
        let (b, c) = (
            [1000000000000051.5, 536.2693249050326],
            [1000000000000051.5, 536.2693249050321],
        );
        let midpoint = 0.5 * (b[1] + c[1]);
        let from_far = exactly_rounded_circumcentre_offset(far, b, c);
        assert_eq!(far[1] + from_far[1], 0.0);
        for [p, q, r] in [[far, b, c], [b, c, far], [c, far, b]] {
            let [x, y] = SplitCentre::of(p, q, r).centre();
            assert!(
                (y - midpoint).abs() <= 2.0 * f64::EPSILON * midpoint,
                "y = {y}"
            );
            assert!(
                (x - 5.000000000000245e108).abs() <= 4.0 * f64::EPSILON * x,
                "x = {x}"
            );
        }
    }

    #[test]
    fn a_centre_keeps_a_coordinate_whose_products_underflow() {
        // The bisector of (0, 0) and (0, 1e-287) is y = 5e-288; with (2e-59, 1e-59) the centre
        // is (1.25e-59, 5e-288). Cubes of the scaled differences underflowed in the expansions
        // (and the fast formula's rounding is 1e-75 there): y came out 0, on a region's side.
        let corners = [[0.0, 0.0], [2e-59, 1e-59], [0.0, 1e-287]];
        for [p, q, r] in [corners, [corners[1], corners[2], corners[0]]] {
            let [x, y] = SplitCentre::of(p, q, r).centre();
            assert!((y - 5e-288).abs() <= 1e-12 * 5e-288, "y = {y:e}");
            assert!((x - 1.25e-59).abs() <= 1e-12 * 1.25e-59, "x = {x:e}");
        }
    }

    #[test]
    fn unit_scale_matches_the_box_scale_and_inverts_exactly() {
        let magnitudes = [
            0.0,
            f64::from_bits(1),
            3e-310,
            f64::MIN_POSITIVE,
            1e-300,
            0.75,
            1.0,
            3.0,
            1e300,
            f64::MAX,
            f64::INFINITY,
        ];
        for largest in magnitudes {
            let (unit, inverse) = unit_scale_of(largest);
            let expected = normalising_scale_of_box([[-largest, -largest], [largest, largest]]);
            assert_eq!(unit.to_bits(), expected.to_bits(), "largest = {largest:e}");
            assert_eq!(
                inverse.to_bits(),
                expected.recip().to_bits(),
                "largest = {largest:e}"
            );
            assert_eq!(unit * inverse, 1.0, "largest = {largest:e}");
        }
    }

    #[test]
    fn cocircular_filter_never_rejects_equal_centres() {
        let centre = [0.25, -3.0];
        assert!(may_be_cocircular(centre, centre, 3.75));
        assert!(!may_be_cocircular(centre, [0.26, -3.0], 3.75));
        // Centres one ulp apart far from the origin, for a tiny circle: rounding, not geometry.
        let far = [1e6, 1e6];
        assert!(may_be_cocircular(far, [1e6 + 1.2e-10, 1e6], 1e-12));
        // Tiny magnitudes: the L1 test does not underflow to "apart".
        let tiny = [1e-300, 2e-300];
        assert!(may_be_cocircular(tiny, tiny, 1e-301));
    }
}
