//! The Delaunay triangulation of a set of 2D sites: exact, with duplicates merged and reported.

use std::sync::OnceLock;

use super::error::VoronoiError;
use super::ids::{DelaunayHalfedgeId, SiteId};
use super::incremental::{GhostTriangulation, Triangle, next_edge, prev_edge};
use super::parallel::{map_each, map_indexed, run_length};
use super::predicates::{SetBounds, exact_normalising_scale, orient2d};
use super::spatial_sort::{bounding_box, brio_hilbert_order};
use crate::support::allocation::ensure_room;
use crate::support::id_set::IdSet;
use crate::support::large_arrays;
use crate::support::prefetch::prefetch;

/// "None" in the raw index arrays ([`Delaunay::twins`], [`LabelImage::labels`](super::LabelImage),
/// …): no half-edge, no twin, no site. The typed ids say it with their own `INVALID`.
pub const INVALID: u32 = u32::MAX;

/// Largest number of sites. Triangulation half-edges (`< 6n`), Voronoi half-edges (`< 6n`) and
/// clipped-cell corners (`< 6n` plus the region's corners and boundary crossings) are all `u32`
/// indices below [`INVALID`]; `8n` leaves room for all of them.
pub const MAX_SITES: usize = (u32::MAX as usize - 16) / 8;
// Compile-time check of that headroom.
const _: () = assert!((MAX_SITES as u64) * 8 < INVALID as u64);

/// Dimension of the triangulated site set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    /// No sites.
    Empty,
    /// One distinct site (possibly repeated).
    Point,
    /// Two or more distinct sites, all on one line: no triangles, edges join neighbours along it.
    Line,
    /// Sites span the plane: at least one triangle.
    Plane,
}

/// A Delaunay triangulation as a compact half-edge structure over triangles.
///
/// * Vertices are **sites** ([`SiteId`], the input index, `0..n_sites()`); a duplicated site is
///   represented by the smallest index of its group ([`Delaunay::representative`]); other copies
///   have no incident half-edge.
/// * Triangle `t` owns half-edges ([`DelaunayHalfedgeId`]) `3t, 3t+1, 3t+2`, counter-clockwise;
///   half-edge `e` starts at
///   [`Delaunay::origin`]`(e)` and ends at the origin of `next(e)`, with its triangle on its left.
/// * [`Delaunay::twin`] is the opposite half-edge, invalid on the convex hull.
/// * [`Delaunay::vertex_edge`] is an outgoing half-edge of each vertex — the outgoing hull edge for
///   hull vertices, so that circulating counter-clockwise with `twin(prev(e))` visits every
///   incident triangle and stops at the invalid id.
/// * Where four or more sites are cocircular the split into triangles is arbitrary (but exact and
///   deterministic); the Voronoi diagram merges those triangles into one vertex.
///
/// For 1-dimensional input (all sites collinear) there are no triangles and the Delaunay edges
/// join consecutive sites of [`Delaunay::hull`], which then lists the distinct sites in order
/// along the line. For a single distinct site the hull is that site; for none it is empty.
///
/// The whole arrays ([`Delaunay::triangles`], [`Delaunay::twins`], [`Delaunay::hull`],
/// [`Delaunay::representative`]) are raw `u32` indices, [`INVALID`] for none, shaped for
/// buffers and the C API's zero-copy views; the per-element queries take and return typed ids.
#[derive(Clone, Debug)]
pub struct Delaunay {
    pub(crate) sites: Vec<[f64; 2]>,
    /// Sites multiplied by `scale` (a power of two) for exact predicates, in site order, made
    /// on first use (queries and rasters; the construction reads them through `ranked`).
    scaled: OnceLock<Vec<[f64; 2]>>,
    pub(crate) scale: f64,
    /// Error bounds of the predicates over the scaled sites.
    pub(crate) set_bounds: SetBounds,
    pub(crate) representative: Vec<u32>,
    pub(crate) n_unique: usize,
    pub(crate) triangles: Vec<u32>,
    pub(crate) twins: Vec<u32>,
    pub(crate) vertex_edge: Vec<u32>,
    pub(crate) hull: Vec<u32>,
    pub(crate) dimension: Dimension,
    /// Scaled coordinates in insertion order, and the insertion rank of every triangle corner:
    /// passes over the triangles read coordinates through these, sequentially in memory.
    pub(crate) ranked: Vec<[f64; 2]>,
    pub(crate) corner_ranks: Vec<u32>,
    /// The vertex edge of every site that has one, in increasing order: per-site passes that
    /// start at a site's vertex edge visit sites in this order to read the triangles
    /// sequentially (the site of `e` is `triangles[e]`).
    pub(crate) cell_starts: Vec<u32>,
}

/// Refuses sites a triangulation cannot take: too many for its 32-bit indices, or a NaN or
/// infinite coordinate (naming the first such site).
pub(crate) fn check_sites(sites: &[[f64; 2]]) -> Result<(), VoronoiError> {
    if sites.len() > MAX_SITES {
        return Err(VoronoiError::TooManySites {
            count: sites.len(),
            max: MAX_SITES,
        });
    }
    match sites
        .iter()
        .enumerate()
        .find(|(_, p)| !(p[0].is_finite() && p[1].is_finite()))
    {
        // Below `MAX_SITES`, so the index fits.
        Some((site, &[x, y])) => Err(VoronoiError::NonFiniteSite {
            site: SiteId(site as u32),
            x,
            y,
        }),
        None => Ok(()),
    }
}

impl Delaunay {
    /// Triangulates `sites`. NaN or infinite coordinates are refused; duplicates are merged.
    ///
    /// Construction: exact predicates (`robust`), biased randomised insertion order along a
    /// Hilbert curve, walking point location from the previous insertion, Bowyer–Watson cavities.
    pub fn new(sites: &[[f64; 2]]) -> Result<Self, VoronoiError> {
        check_sites(sites)?;
        let n = sites.len();
        // The triangulation's arrays (about two triangles per site, three corners each, in
        // several arrays), the copies of the sites in input and insertion order, and those of
        // the Voronoi diagram usually made from it, take under this per site.
        const BYTES_PER_SITE: u64 = 320;
        ensure_room(n as u64 * BYTES_PER_SITE, n, "sites")?;
        // One pass over the sites gives the scale and, scaled (a power of two is monotone, so
        // it maps the box), the scaled sites' box.
        let site_box = bounding_box(sites);
        let scale = exact_normalising_scale(sites, site_box);
        let mut representative: Vec<u32> = (0..n as u32).collect();
        let bounds = site_box.map(|corner| corner.map(|x| x * scale));
        let order = brio_hilbert_order(sites, scale, bounds);

        let mut result = Delaunay {
            sites: sites.to_vec(),
            scaled: OnceLock::new(),
            scale,
            set_bounds: SetBounds::NONE,
            representative: Vec::new(),
            n_unique: 0,
            triangles: Vec::new(),
            twins: Vec::new(),
            vertex_edge: vec![INVALID; n],
            hull: Vec::new(),
            dimension: Dimension::Empty,
            cell_starts: Vec::new(),
            ranked: Vec::new(),
            corner_ranks: Vec::new(),
        };
        // The triangulation is built on vertices numbered by insertion rank, with coordinates
        // stored in that (space-filling-curve) order: walks and cavities then touch memory
        // sequentially instead of jumping across the input. Ranks map back to sites at the end.
        let sorted = map_indexed(n, |k| result.scaled_point(order[k]));
        let mut rank_representative: Vec<u32> = (0..n as u32).collect();
        match find_initial_triangle(&sorted, &mut rank_representative) {
            Seed::Empty => {}
            Seed::Degenerate => result.build_collinear(&mut representative),
            Seed::Triangle { a, b, c } => {
                result.set_bounds = SetBounds::of(&sorted, bounds);
                let mut tri = GhostTriangulation::new(&sorted, [a, b, c], n, result.set_bounds);
                // Sites skipped while looking for the seed triangle come first, then the rest.
                for k in (0..n as u32).filter(|&k| k != c) {
                    if k == a || k == b || rank_representative[k as usize] != k {
                        continue;
                    }
                    if let Some(existing) = tri.insert(k) {
                        rank_representative[k as usize] = existing;
                    }
                }
                for (k, &r) in rank_representative.iter().enumerate() {
                    representative[order[k] as usize] = order[r as usize];
                }
                result.finish_planar(&tri.triangles, &order);
                result.ranked = sorted;
            }
        }
        result.canonicalise_representatives(representative);
        Ok(result)
    }

    /// Copies the real triangles out of the ghost triangulation and walks the hull.
    /// `to_site` maps the builder's vertex numbers (insertion ranks) to site indices.
    fn finish_planar(&mut self, built: &[Triangle], to_site: &[u32]) {
        let n_all = built.len();
        // Real triangles are renumbered by their newest corner (a counting sort on insertion
        // rank): slot reuse during construction scatters neighbours across the array, and every
        // later pass (Voronoi vertices, links, clipping) walks neighbours, so the output order is
        // made spatially coherent once here. The key is the rank in steps of 64 (consecutive
        // sites along the curve), so that the counts stay in cache (62 KB instead of 4 MB at 1M
        // sites; count and index passes there, median of 18: 22.1 -> 15.6 ms). Within a step,
        // triangles keep their order in the construction array.
        const RANK_STEP_LOG2: u32 = 6;
        let n_keys = (to_site.len() >> RANK_STEP_LOG2) + 1;
        let mut start = vec![0u32; n_keys + 1];
        let newest = |t: &Triangle| {
            (t.corners[0].max(t.corners[1]).max(t.corners[2]) >> RANK_STEP_LOG2) as usize
        };
        let mut some_ghost = INVALID;
        for (t, triangle) in built.iter().enumerate() {
            if triangle.is_ghost() {
                some_ghost = t as u32;
            } else {
                start[newest(triangle) + 1] += 1;
            }
        }
        for k in 1..start.len() {
            start[k] += start[k - 1];
        }
        let count = start[n_keys] as usize;
        let mut new_index = vec![INVALID; n_all];
        let mut old_index = large_arrays::zeroed::<u32>(count);
        for (t, (slot, triangle)) in new_index.iter_mut().zip(built).enumerate() {
            if !triangle.is_ghost() {
                let key = newest(triangle);
                *slot = start[key];
                old_index[start[key] as usize] = t as u32;
                start[key] += 1;
            }
        }
        // Filled in the new order (writes sequential, reads scattered: cheaper than the reverse).
        let mut triangles = large_arrays::zeroed::<u32>(3 * count);
        let mut corner_ranks = large_arrays::zeroed::<u32>(3 * count);
        let mut twins = large_arrays::zeroed::<u32>(3 * count);
        // The gather below asks for its records ahead when they are unlikely to be in cache
        // already: not for a construction array that fits in a core's cache (10k sites: this
        // fill 3.29M -> 2.12M instructions).
        const PREFETCH_MIN_BYTES: usize = 1 << 20;
        let prefetching = size_of_val(built) >= PREFETCH_MIN_BYTES;
        // Runs of output triangles are independent: filled in parallel.
        let run = run_length(count);
        let runs: Vec<_> = triangles
            .chunks_mut(3 * run)
            .zip(corner_ranks.chunks_mut(3 * run))
            .zip(twins.chunks_mut(3 * run))
            .zip(old_index.chunks(run))
            .collect();
        map_each(runs, |_, (((sites, ranks), opposites), olds)| {
            for (j, (((sites, ranks), opposites), &old)) in sites
                .chunks_exact_mut(3)
                .zip(ranks.chunks_exact_mut(3))
                .zip(opposites.chunks_exact_mut(3))
                .zip(olds)
                .enumerate()
            {
                // A gather through `old_index`: each triangle is asked for 16 ahead, and the new
                // numbers of its neighbours 8 ahead, once its record has arrived (1M sites:
                // this fill 32.6 -> 22.4 ms, best of 12).
                if prefetching {
                    if let Some(&ahead) = olds.get(j + 16) {
                        prefetch(&built[ahead as usize]);
                    }
                    if let Some(&near) = olds.get(j + 8) {
                        for o in built[near as usize].twins {
                            prefetch(&new_index[(o / 3) as usize]);
                        }
                    }
                }
                let triangle = &built[old as usize];
                for k in 0..3 {
                    let rank = triangle.corners[k];
                    ranks[k] = rank;
                    sites[k] = to_site[rank as usize];
                    let o = triangle.twins[k];
                    let no = new_index[(o / 3) as usize];
                    opposites[k] = if no == INVALID {
                        INVALID
                    } else {
                        3 * no + o % 3
                    };
                }
            }
        });
        // Hull, counter-clockwise: ghost (u, v, ∞) sits on real hull edge v → u; the next ghost
        // is across its edge ∞ → u (edge 2).
        let mut hull = Vec::new();
        let mut hull_edges = Vec::new();
        let start = some_ghost;
        let mut g = start;
        loop {
            let ghost = &built[g as usize];
            hull.push(to_site[ghost.corners[1] as usize]);
            let real = ghost.twins[0];
            hull_edges.push(3 * new_index[(real / 3) as usize] + real % 3);
            g = ghost.twins[2] / 3;
            if g == start || hull.len() > n_all {
                break;
            }
        }
        // Vertex edges: the last outgoing edge, then the outgoing hull edge for hull vertices.
        // Found by rank, whose order follows the triangles', then mapped to sites in one pass.
        let mut rank_edge = vec![INVALID; to_site.len()];
        for (e, &r) in corner_ranks.iter().enumerate() {
            rank_edge[r as usize] = e as u32;
        }
        for &e in &hull_edges {
            rank_edge[corner_ranks[e as usize] as usize] = e;
        }
        // The same edges, in increasing order, are where the per-site passes start.
        let mut starts = IdSet::new(corner_ranks.len());
        for (&e, &site) in rank_edge.iter().zip(to_site) {
            if e != INVALID {
                self.vertex_edge[site as usize] = e;
                starts.insert(e);
            }
        }
        self.cell_starts = starts.into_sorted(to_site.len());
        self.triangles = triangles;
        self.corner_ranks = corner_ranks;
        self.twins = twins;
        self.hull = hull;
        self.dimension = Dimension::Plane;
    }

    /// All distinct sites are collinear (or there is only one): order them along the line.
    fn build_collinear(&mut self, representative: &mut [u32]) {
        let mut order: Vec<u32> = (0..self.sites.len() as u32).collect();
        // Lexicographic order is the order along any line.
        let pts = self.scaled();
        order.sort_unstable_by(|&i, &j| {
            pts[i as usize]
                .partial_cmp(&pts[j as usize])
                .unwrap_or(std::cmp::Ordering::Equal)
                .then(i.cmp(&j))
        });
        let mut chain: Vec<u32> = Vec::new();
        for &s in &order {
            match chain.last() {
                Some(&last) if pts[last as usize] == pts[s as usize] => {
                    representative[s as usize] = last
                }
                _ => chain.push(s),
            }
        }
        self.dimension = if chain.len() == 1 {
            Dimension::Point
        } else {
            Dimension::Line
        };
        self.hull = chain;
    }

    /// Makes the smallest index of every duplicate group its representative and renames vertices.
    fn canonicalise_representatives(&mut self, mut representative: Vec<u32>) {
        let n = representative.len();
        let mut smallest: Vec<u32> = (0..n as u32).collect();
        for (i, &r) in representative.iter().enumerate() {
            smallest[r as usize] = smallest[r as usize].min(i as u32);
        }
        let renamed = (0..n).any(|r| representative[r] == r as u32 && smallest[r] != r as u32);
        for r in representative.iter_mut() {
            *r = smallest[*r as usize];
        }
        if renamed {
            for v in self.triangles.iter_mut().chain(self.hull.iter_mut()) {
                *v = smallest[*v as usize];
            }
            let mut vertex_edge = vec![INVALID; n];
            for (old, &e) in self.vertex_edge.iter().enumerate() {
                if e != INVALID {
                    vertex_edge[smallest[old] as usize] = e;
                }
            }
            self.vertex_edge = vertex_edge;
        }
        self.n_unique = (0..n).filter(|&i| representative[i] == i as u32).count();
        self.representative = representative;
    }

    /// Number of input sites (duplicates included).
    pub fn n_sites(&self) -> usize {
        self.sites.len()
    }

    /// Number of distinct sites.
    pub fn n_unique_sites(&self) -> usize {
        self.n_unique
    }

    /// The input sites, as given.
    pub fn sites(&self) -> &[[f64; 2]] {
        &self.sites
    }

    /// The same triangulation over `sites`: the sites moved to other coordinates (clipping's
    /// local frame), read only by constructions, never by predicates.
    pub(crate) fn with_sites(&self, sites: Vec<[f64; 2]>) -> Delaunay {
        Delaunay {
            sites,
            scaled: OnceLock::new(),
            ..self.clone()
        }
    }

    /// Dimension of the site set.
    pub fn dimension(&self) -> Dimension {
        self.dimension
    }

    /// Site → representative map, raw: `representative()[i] == i` for distinct sites; a
    /// duplicate maps to the smallest index with the same coordinates.
    pub fn representative(&self) -> &[u32] {
        &self.representative
    }

    /// The site representing `site` (itself unless it duplicates a smaller index), `None` when
    /// `site` is out of range.
    pub fn representative_of(&self, site: SiteId) -> Option<SiteId> {
        self.representative.get(site.index()).copied().map(SiteId)
    }

    /// `(duplicate, representative)` pairs for every site that was merged into another.
    pub fn duplicates(&self) -> impl Iterator<Item = (SiteId, SiteId)> + '_ {
        self.representative
            .iter()
            .enumerate()
            .filter(|&(i, &r)| r != i as u32)
            .map(|(i, &r)| (SiteId(i as u32), SiteId(r)))
    }

    /// Number of triangles.
    pub fn n_triangles(&self) -> usize {
        self.triangles.len() / 3
    }

    /// The sites of all triangles, raw, three per triangle, counter-clockwise: entry `e` is the
    /// origin of half-edge `e`.
    pub fn triangles(&self) -> &[u32] {
        &self.triangles
    }

    /// Opposite half-edge of every half-edge, raw ([`INVALID`] on the hull).
    pub fn twins(&self) -> &[u32] {
        &self.twins
    }

    /// Start site of half-edge `e` (invalid for an invalid half-edge; so for all accessors).
    pub fn origin(&self, e: DelaunayHalfedgeId) -> SiteId {
        SiteId(entry(&self.triangles, e.0))
    }

    /// Opposite half-edge of `e`, invalid for a hull edge.
    pub fn twin(&self, e: DelaunayHalfedgeId) -> DelaunayHalfedgeId {
        DelaunayHalfedgeId(entry(&self.twins, e.0))
    }

    /// Next half-edge counter-clockwise in the same triangle.
    pub fn next(&self, e: DelaunayHalfedgeId) -> DelaunayHalfedgeId {
        DelaunayHalfedgeId(if e.index() < self.triangles.len() {
            next_edge(e.0)
        } else {
            INVALID
        })
    }

    /// Previous half-edge in the same triangle.
    pub fn prev(&self, e: DelaunayHalfedgeId) -> DelaunayHalfedgeId {
        DelaunayHalfedgeId(if e.index() < self.triangles.len() {
            prev_edge(e.0)
        } else {
            INVALID
        })
    }

    /// An outgoing half-edge of site `v` (the hull one for hull vertices), invalid for
    /// duplicates and when there are no triangles.
    pub fn vertex_edge(&self, v: SiteId) -> DelaunayHalfedgeId {
        DelaunayHalfedgeId(entry(&self.vertex_edge, v.0))
    }

    /// Convex hull, counter-clockwise, as raw site indices. Collinear sites on hull edges are
    /// kept as hull vertices. See the type documentation for lower dimensions.
    pub fn hull(&self) -> &[u32] {
        &self.hull
    }

    /// Every undirected Delaunay edge once, as `(a, b)` site pairs.
    pub fn edges(&self) -> Vec<(SiteId, SiteId)> {
        let pair = |a: u32, b: u32| (SiteId(a), SiteId(b));
        match self.dimension {
            Dimension::Plane => (0..self.triangles.len() as u32)
                .filter(|&e| {
                    let t = self.twins[e as usize];
                    t == INVALID || e < t
                })
                .map(|e| {
                    pair(
                        self.triangles[e as usize],
                        self.triangles[next_edge(e) as usize],
                    )
                })
                .collect(),
            Dimension::Line => self.hull.windows(2).map(|w| pair(w[0], w[1])).collect(),
            Dimension::Empty | Dimension::Point => Vec::new(),
        }
    }

    /// Outgoing half-edges of `v`, counter-clockwise (starting at the hull edge for hull vertices).
    pub fn outgoing(&self, v: SiteId) -> OutgoingEdges<'_> {
        let start = self.vertex_edge(v).0;
        OutgoingEdges {
            delaunay: self,
            start,
            current: start,
        }
    }

    /// The triangulation as a polygon soup (z = 0), one triangle per face, positions for every
    /// input site (duplicates are unreferenced vertices), ready for the half-edge mesh builder.
    pub fn to_polygon_soup(&self) -> crate::soup::PolygonSoup {
        crate::soup::PolygonSoup {
            positions: self.sites.iter().map(|p| [p[0], p[1], 0.0]).collect(),
            face_sizes: vec![3; self.n_triangles()],
            indices: self.triangles.clone(),
            corner_normals: None,
            corner_uvs: None,
        }
    }

    /// Scaled coordinates of the start of half-edge `e` (read in triangle order, coherently).
    #[inline(always)]
    pub(crate) fn corner_point(&self, e: u32) -> [f64; 2] {
        self.ranked[self.corner_ranks[e as usize] as usize]
    }

    /// Scaled coordinates of the corners of triangle `t`, counter-clockwise (an array `map`
    /// here was left as a call by the compiler).
    #[inline(always)]
    pub(crate) fn triangle_points(&self, t: u32) -> [[f64; 2]; 3] {
        let base = 3 * t;
        [
            self.corner_point(base),
            self.corner_point(base + 1),
            self.corner_point(base + 2),
        ]
    }

    /// Scaled coordinates of site `v`, as the exact predicates see it.
    #[inline(always)]
    pub(crate) fn scaled_point(&self, v: u32) -> [f64; 2] {
        let p = self.sites[v as usize];
        [p[0] * self.scale, p[1] * self.scale]
    }

    /// Every site multiplied by `scale`, in site order.
    pub(crate) fn scaled(&self) -> &[[f64; 2]] {
        self.scaled
            .get_or_init(|| map_indexed(self.sites.len(), |v| self.scaled_point(v as u32)))
    }

    /// Exact orientation in the triangulation's own (scaled) coordinates.
    #[cfg(test)]
    pub(crate) fn orient(&self, a: u32, b: u32, c: u32) -> f64 {
        orient2d(
            self.scaled_point(a),
            self.scaled_point(b),
            self.scaled_point(c),
        )
    }
}

/// Counter-clockwise circulator over the outgoing half-edges of a vertex.
pub struct OutgoingEdges<'a> {
    delaunay: &'a Delaunay,
    start: u32,
    current: u32,
}

impl Iterator for OutgoingEdges<'_> {
    type Item = DelaunayHalfedgeId;

    fn next(&mut self) -> Option<DelaunayHalfedgeId> {
        if self.current == INVALID {
            return None;
        }
        let e = self.current;
        let back = self.delaunay.twins[prev_edge(e) as usize];
        self.current = if back == INVALID || back == self.start {
            INVALID
        } else {
            back
        };
        Some(DelaunayHalfedgeId(e))
    }
}

/// `array[i]`, or [`INVALID`] when `i` is out of range (the queries' answer to a bad id).
#[inline]
pub(crate) fn entry(array: &[u32], i: u32) -> u32 {
    array.get(i as usize).copied().unwrap_or(INVALID)
}

enum Seed {
    Empty,
    Degenerate,
    /// Corners counter-clockwise; `c` is the last of the points looked at.
    Triangle {
        a: u32,
        b: u32,
        c: u32,
    },
}

/// First non-degenerate triangle of `points` taken in order (the insertion order); duplicates
/// of the first two sites met on the way are recorded.
fn find_initial_triangle(points: &[[f64; 2]], representative: &mut [u32]) -> Seed {
    let Some(&pa) = points.first() else {
        return Seed::Empty;
    };
    let a = 0;
    let mut b = None;
    for (s, &ps) in (0..).zip(points).skip(1) {
        match b {
            None if ps == pa => representative[s as usize] = a,
            None => b = Some(s),
            Some(b) => {
                let o = orient2d(pa, points[b as usize], ps);
                if o > 0.0 {
                    return Seed::Triangle { a, b, c: s };
                }
                if o < 0.0 {
                    return Seed::Triangle { a: b, b: a, c: s };
                }
            }
        }
    }
    // No seed triangle: the duplicates recorded so far are redone by the collinear builder.
    representative
        .iter_mut()
        .enumerate()
        .for_each(|(i, r)| *r = i as u32);
    Seed::Degenerate
}
