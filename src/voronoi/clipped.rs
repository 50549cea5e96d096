//! Voronoi cells clipped to a convex region: closed polygons that share their vertices.

use super::cell_sides::Side;
use super::clip_frame::FrameMap;
use super::clip_region::{ClipPolygon, polygon_area_centroid};
use super::crossing_order::{
    bisector_crossing, bisector_meets, bisector_meets_edge, bisector_piece_sides,
    circumcentre_side, compare_crossings, crosses_edge, crossing_nearer_than,
};
use super::delaunay::INVALID;
use super::diagram::{EdgeEnds, EdgeGeometry, Voronoi};
use super::error::VoronoiError;
use super::exact_cell::{cell_has_interior, exact_cell_corners};
use super::ids::SiteId;
use super::parallel::{map_each, run_length};
use super::predicates::{normalising_scale_of_box, orient2d};
use crate::soup::PolygonSoup;
use crate::support::large_arrays;
use std::cmp::Ordering;

/// Every cell of a Voronoi diagram clipped to a convex polygon.
///
/// The cells tile the clip polygon without gaps or overlaps: a Voronoi vertex inside the region,
/// a point where a Voronoi edge crosses the region's boundary, and a corner of the region each
/// exist once in [`ClippedCells::positions`] and are shared by every cell that touches them. A
/// Voronoi vertex on a side in floating point, or computed just outside a side that it lies on
/// or inside exactly, is a point of that side; an edge from it that runs inside along that side
/// keeps its piece there. Each edge is clipped once for both of its cells, so neighbours always
/// agree. Cells are counter-clockwise and indexed by site; a site whose cell misses the region
/// (possible for sites outside it) and every duplicate site have an empty polygon.
///
/// A cell is the part of the region nearest to its site, and it is listed when that part has an
/// interior, however thin (decided exactly): a cell that meets the region only along its
/// boundary (in a segment or a point) is empty, and every other cell has at least three
/// positions. Where a cell is narrower than the spacing of doubles there (sites an ulp apart far
/// from the origin, or far closer together than the region is wide), it keeps its own positions,
/// in their exact order along the region's boundary, but some of them may coincide once rounded:
/// such a cell has zero area in floating point. Where rounding collapses such a cell altogether
/// (its sides rounded onto the region's boundary or onto one another, or its corners into one
/// line beside an edge that missed the region only within rounding), it is rebuilt from its
/// exact polygon: its corners, each within two ulps of its exact place, are positions of its own,
/// after all the shared ones, and its neighbours meet one another there within rounding.
///
/// A cell narrower than the rounding of its own corners (vertices near 1e23 in a region near
/// 1e73, strips 1e-13 tall ending at vertices near 1e31) has corners whose order only rounding
/// decides, and can come out clockwise; its signed area `A` is then within the rounding of its
/// corners: `2|A| ≤ 4nε·X·D` for `n` corners whose largest coordinate magnitude is `X` and
/// largest offset from the first corner is `D` (`ε` is [`f64::EPSILON`]). Every other cell is
/// counter-clockwise.
#[derive(Clone, Debug)]
pub struct ClippedCells {
    positions: Vec<[f64; 2]>,
    ranges: Vec<[u32; 2]>,
    indices: Vec<u32>,
    clip: ClipPolygon,
}

/// A point on the clip boundary: edge index, parameter in `[0, 1]` along it (and in `[-1, 0]`
/// from its end, which keeps the offset of a point near the end of a long edge), what lies
/// there, and its rank in the order along the edge (see [`Builder::order_crossings`]).
#[derive(Clone, Copy, Debug)]
struct Perimeter {
    edge: u32,
    t: f64,
    from_end: f64,
    kind: PerimeterKind,
    rank: u32,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum PerimeterKind {
    /// The corner at the start of the edge (`t = 0`).
    Corner,
    /// Where the bisector of these two sites crosses the edge, strictly after its start corner
    /// even where `t` rounds to 0, and ordered exactly among crossings of close `t`.
    Bisector([u32; 2]),
    /// A Voronoi vertex lying on the edge (in floating point).
    Vertex,
}

/// Crossings on one edge whose parameters lie within this of each other (in a chain) are ordered
/// exactly: their rounded parameters may be equal or in the wrong order.
const EXACT_ORDER_BAND: f64 = 1.0e-6;

/// The sites and the region's corners in the input's own coordinates, where the exact order of
/// crossings is decided (clipping may run in a local frame; see `clip_frame`), and the map from
/// them into the frame.
#[derive(Clone, Copy)]
struct InputPlaces<'a> {
    sites: &'a [[f64; 2]],
    corners: &'a [[f64; 2]],
    frame: FrameMap,
}

/// What clipping leaves of a Voronoi edge.
#[derive(Clone, Copy, Debug)]
enum ClippedEdge {
    /// The `[start, end]` positions of its piece inside the region.
    Piece([u32; 2]),
    /// Nothing of positive length in floating point, though the edge passes the region within
    /// rounding: a cell beside it that comes out empty may be a sliver narrower than rounding,
    /// which is decided exactly (see [`Voronoi::exact_cell`]).
    NearMiss,
    /// Nothing, with room to spare.
    Miss,
}

impl ClippedEdge {
    /// The piece's positions, [`INVALID`] for a miss.
    fn piece(self) -> [u32; 2] {
        match self {
            ClippedEdge::Piece(piece) => piece,
            _ => [INVALID; 2],
        }
    }
}

/// Positions under construction: `[corners][Voronoi vertices inside][boundary crossings]`.
struct Builder<'a> {
    clip: &'a ClipPolygon,
    input: InputPlaces<'a>,
    reach: Reach,
    positions: Vec<[f64; 2]>,
    first_crossing: usize,
    crossings: Vec<Perimeter>,
}

/// The clip region's centroid and the distance from it to the farthest corner: a disc that holds
/// the region, for telling the Voronoi vertices that are far from it.
#[derive(Clone, Copy, Debug)]
struct Reach {
    centre: [f64; 2],
    radius: f64,
}

impl Reach {
    /// Ends farther than this many radii from the centre are moved (see
    /// [`Voronoi::near_geometry`]); ends nearer are exact enough where they are.
    const FAR: f64 = 4.0;
    /// How many radii beyond the centre's projection a moved end lands: outside the region.
    const MOVED: f64 = 2.0;

    fn of(clip: &ClipPolygon) -> Reach {
        let centre = clip.centroid();
        let radius = clip
            .vertices()
            .iter()
            .map(|p| (p[0] - centre[0]).hypot(p[1] - centre[1]))
            .fold(0.0, f64::max);
        Reach { centre, radius }
    }

    fn is_far(&self, p: [f64; 2]) -> bool {
        self.distance(p) > Self::FAR * self.radius
    }

    /// Is `p` at most as far from the centre as `q`? (Squared distances, unless one overflows.)
    fn is_nearer(&self, p: [f64; 2], q: [f64; 2]) -> bool {
        let squared = |p: [f64; 2]| {
            let d = [p[0] - self.centre[0], p[1] - self.centre[1]];
            d[0] * d[0] + d[1] * d[1]
        };
        let (from_p, from_q) = (squared(p), squared(q));
        if from_p.is_finite() && from_q.is_finite() {
            from_p <= from_q
        } else {
            self.distance(p) <= self.distance(q)
        }
    }

    /// The distance from the centre to `p`.
    fn distance(&self, p: [f64; 2]) -> f64 {
        (p[0] - self.centre[0]).hypot(p[1] - self.centre[1])
    }
}

impl Perimeter {
    /// The order of two points of the same edge by their rounded parameters.
    fn along(&self, other: &Perimeter) -> Ordering {
        self.t
            .total_cmp(&other.t)
            .then(self.from_end.total_cmp(&other.from_end))
    }
}

impl Builder<'_> {
    /// Where position `p` sits on the perimeter, if it is a corner or a crossing.
    fn perimeter(&self, p: u32) -> Option<Perimeter> {
        let m = self.clip.vertices().len();
        let p = p as usize;
        if p < m {
            Some(Perimeter {
                edge: p as u32,
                t: 0.0,
                from_end: -1.0,
                kind: PerimeterKind::Corner,
                rank: 0,
            })
        } else if p >= self.first_crossing {
            Some(self.crossings[p - self.first_crossing])
        } else {
            None
        }
    }

    /// Adds the point of clip edge `edge` at parameters `[t, t − 1]` along it (see
    /// [`ClipPolygon::edge_parameters`]): where the bisector of `sites` crosses it, or a Voronoi
    /// vertex (`sites` is `None`). A crossing goes onto a corner only when it lies exactly
    /// there: one whose parameter merely rounds to a corner is kept as a point of its own at the
    /// corner's position (see [`ClippedCells`]).
    fn crossing(&mut self, edge: usize, [t, from_end]: [f64; 2], sites: Option<[u32; 2]>) -> u32 {
        let m = self.clip.vertices().len();
        let (t, from_end) = (t.clamp(0.0, 1.0), from_end.clamp(-1.0, 0.0));
        // A bisector lies on a corner when it meets it exactly; a vertex when its offset from
        // it is zero (a vertex 7e10 before the end of a side 5e75 long has `t` = 1 too).
        let at_corner = |corner: usize, offset: f64| match sites {
            None => offset == 0.0,
            Some([p, q]) => {
                let sites = self.input.sites;
                bisector_meets(
                    self.input.corners[corner],
                    [sites[p as usize], sites[q as usize]],
                )
            }
        };
        if t == 0.0 && at_corner(edge, t) {
            return edge as u32;
        }
        if t == 1.0 && at_corner((edge + 1) % m, from_end) {
            return ((edge + 1) % m) as u32;
        }
        self.positions.push(self.edge_point(edge, t, from_end));
        self.crossings.push(Perimeter {
            edge: edge as u32,
            t,
            from_end,
            kind: sites.map_or(PerimeterKind::Vertex, PerimeterKind::Bisector),
            rank: 0,
        });
        (self.positions.len() - 1) as u32
    }

    /// The point at parameter `t` along clip edge `edge` (`from_end` from its end): the corners
    /// themselves at the ends (`a + e` may round off a corner far smaller than the edge),
    /// placed from the nearer corner, and monotone in `(t, from_end)`.
    fn edge_point(&self, edge: usize, t: f64, from_end: f64) -> [f64; 2] {
        let corners = self.clip.vertices();
        let e = self.clip.edge_vector(edge);
        if t <= 0.5 {
            let a = corners[edge];
            if t == 0.0 {
                a
            } else {
                [a[0] + t * e[0], a[1] + t * e[1]]
            }
        } else {
            let b = corners[(edge + 1) % corners.len()];
            if from_end == 0.0 {
                b
            } else {
                [b[0] + from_end * e[0], b[1] + from_end * e[1]]
            }
        }
    }

    /// Ranks the crossings along each edge. They are sorted by parameter; runs of crossings
    /// within [`EXACT_ORDER_BAND`] of each other, where rounding may have swapped or merged
    /// them, are sorted again by the exact order of their bisectors, and their parameters and
    /// positions made monotone in that order, so that no cell between two of them is clockwise.
    /// Crossings at the same place share a rank. O(k log k) for k crossings; the exact
    /// arithmetic runs only inside such runs.
    fn order_crossings(&mut self) {
        let keys: Vec<(u32, f64)> = self.crossings.iter().map(|c| (c.edge, c.t)).collect();
        let mut order: Vec<u32> = (0..keys.len() as u32).collect();
        let key = |i: u32| keys[i as usize];
        order.sort_unstable_by(|&i, &j| {
            let ((e, t), (f, u)) = (key(i), key(j));
            e.cmp(&f).then(t.total_cmp(&u)).then_with(|| {
                let crossings = &self.crossings;
                crossings[i as usize].along(&crossings[j as usize])
            })
        });
        let mut ranks = vec![0u32; order.len()];
        let mut start = 0;
        while start < order.len() {
            let (edge, _) = key(order[start]);
            let mut end = start + 1;
            while end < order.len() && {
                let ((e, t), (_, previous)) = (key(order[end]), key(order[end - 1]));
                e == edge && t - previous <= EXACT_ORDER_BAND
            } {
                end += 1;
            }
            let run = &mut order[start..end];
            let exact = run.len() > 1 && self.sort_exactly(edge as usize, run);
            for k in 0..run.len() {
                let (i, rank) = (run[k] as usize, (start + k + 1) as u32);
                ranks[i] = rank;
                if k > 0 {
                    let previous = run[k - 1] as usize;
                    let same_place = if exact {
                        self.exact_order(edge as usize, previous, i) == Ordering::Equal
                    } else {
                        self.crossings[previous].along(&self.crossings[i]) == Ordering::Equal
                    };
                    if same_place {
                        ranks[i] = ranks[previous];
                    }
                }
            }
            if exact {
                self.make_monotone(run);
            }
            start = end;
        }
        for (crossing, rank) in self.crossings.iter_mut().zip(ranks) {
            crossing.rank = rank;
        }
    }

    /// Sorts `run` (crossings of edge `edge`) by the exact order of their bisectors; `false`
    /// (and `run` left as it is) when one is not a bisector crossing or is parallel to the edge.
    #[cold]
    fn sort_exactly(&self, edge: usize, run: &mut [u32]) -> bool {
        let ends = self.input_edge(edge);
        let all_cross = run.iter().all(|&i| {
            self.input_sites(i as usize)
                .is_some_and(|sites| crosses_edge(ends, sites))
        });
        if all_cross {
            run.sort_by(|&i, &j| self.exact_order(edge, i as usize, j as usize));
        }
        all_cross
    }

    /// The exact order of crossings `i` and `j` of edge `edge`, both bisector crossings that
    /// are not parallel to it.
    fn exact_order(&self, edge: usize, i: usize, j: usize) -> Ordering {
        let (first, second) = (self.input_sites(i), self.input_sites(j));
        first
            .zip(second)
            .and_then(|(first, second)| compare_crossings(self.input_edge(edge), first, second))
            .unwrap_or(Ordering::Equal)
    }

    /// Parameters and positions of `run` (crossings of one edge in their exact order) made
    /// non-decreasing: a crossing rounded before one that precedes it takes that one's place.
    fn make_monotone(&mut self, run: &[u32]) {
        let mut highest: Option<usize> = None;
        for &i in run {
            let i = i as usize;
            match highest {
                Some(h) if self.crossings[i].along(&self.crossings[h]) == Ordering::Less => {
                    let (t, from_end) = (self.crossings[h].t, self.crossings[h].from_end);
                    self.crossings[i].t = t;
                    self.crossings[i].from_end = from_end;
                    self.positions[self.first_crossing + i] =
                        self.positions[self.first_crossing + h];
                }
                _ => highest = Some(i),
            }
        }
    }

    /// The parameters along side `side` where the bisector of `sites` crosses it, when that
    /// crossing lies on the side and goes the way `entering` says along the clipped edge (run
    /// against the bisector's own direction when `reversed`). `None` for a side chosen only by
    /// rounding: one the bisector crosses beyond its corners, or the other way.
    fn crossing_on_side(
        &self,
        side: usize,
        sites: [u32; 2],
        entering: bool,
        reversed: bool,
    ) -> Option<[f64; 2]> {
        let sites = sites.map(|s| self.input.sites[s as usize]);
        let edge = self.input_edge(side);
        let crossing = bisector_crossing(edge, sites)?;
        let [t, from_end] = crossing.parameters;
        // A crossing within the rounding of its parameters (3e-12, relative) of a corner may lie
        // beyond it: one 2 units past a corner at 6e63 rounds onto it.
        let on_edge = if t.abs().min(from_end.abs()) <= 1e-11 {
            bisector_meets_edge(edge, sites)
        } else {
            (0.0..=1.0).contains(&t)
        };
        (on_edge && (crossing.goes_in != reversed) == entering).then_some(crossing.parameters)
    }

    /// Does the point at `parameters` along side `side` coincide with `point` within the
    /// rounding of `base + s·dir`, where the floating-point clipping put the crossing?
    fn meets_point(
        &self,
        side: usize,
        [t, from_end]: [f64; 2],
        point: [f64; 2],
        [base, dir]: [[f64; 2]; 2],
        s: f64,
    ) -> bool {
        const ROUNDINGS: f64 = 64.0;
        let x = self.edge_point(side, t.clamp(0.0, 1.0), from_end.clamp(-1.0, 0.0));
        let magnitude = [base, [s * dir[0], s * dir[1]], point]
            .iter()
            .flatten()
            .fold(0.0_f64, |m, c| m.max(c.abs()));
        let apart = (x[0] - point[0]).abs().max((x[1] - point[1]).abs());
        apart <= ROUNDINGS * f64::EPSILON * magnitude
    }

    /// The sides across which the bisector of `sites` enters and leaves the region (see
    /// [`bisector_piece_sides`]), decided exactly: for an edge whose floating-point clipping
    /// chose a side only by rounding, or found no piece where the crossings lie within rounding
    /// of each other (the bisector passing a corner, or crossing the region, within far less
    /// than an ulp).
    #[cold]
    fn exact_piece_sides(&self, sites: [u32; 2], reversed: bool) -> Option<[usize; 2]> {
        bisector_piece_sides(
            self.input.corners,
            sites.map(|s| self.input.sites[s as usize]),
            reversed,
        )
    }

    /// Do the parameters `lo ≥ hi` of crossings along `base + s·dir` with sides `sides` (entry
    /// and exit, `usize::MAX` for none) lie within rounding of each other? That is within
    /// [`EXACT_ORDER_BAND`] of each other, relative to the larger of them and to how far
    /// parameters reach to get across the region from `base` (the edge functions at `base` are
    /// rounded relative to its distance from the region, however near to `base` the crossings
    /// are), or within the rounding of where the line crosses those sides.
    fn within_rounding(
        &self,
        [lo, hi]: [f64; 2],
        [base, dir]: [[f64; 2]; 2],
        sides: [usize; 2],
    ) -> bool {
        let reach = self.reach.distance(base) + self.reach.radius;
        let extent = reach / dir[0].hypot(dir[1]);
        let gap = lo - hi;
        if gap <= EXACT_ORDER_BAND * lo.abs().max(hi.abs()).max(extent) {
            return true;
        }
        // Where the line meets a side at an angle whose sine is `sin`, rounding a position
        // near the region by `δ` moves the crossing by `δ / sin` along it: a bisector within
        // 1e-12 of parallel to a side, rounded to ulps of 3.5, crosses it anywhere along 1e-4
        // of the region. (The sine from the side's largest coordinate, not its length: at most
        // √2 too large, and no square root for the many clean misses.)
        let rounding = 8.0 * f64::EPSILON * (base[0].abs().max(base[1].abs()) + reach);
        let moved = |side: usize| {
            if side == usize::MAX {
                return 0.0;
            }
            let e = self.clip.edge_vector(side);
            rounding * e[0].abs().max(e[1].abs()) / (e[0] * dir[1] - e[1] * dir[0]).abs()
        };
        gap <= moved(sides[0]) + moved(sides[1])
    }

    /// The two sites of crossing `i` in the input's coordinates, if it is a bisector crossing.
    fn input_sites(&self, i: usize) -> Option<[[f64; 2]; 2]> {
        match self.crossings[i].kind {
            PerimeterKind::Bisector(sites) => Some(sites.map(|s| self.input.sites[s as usize])),
            _ => None,
        }
    }

    /// The corners that edge `edge` runs between, in the input's coordinates.
    fn input_edge(&self, edge: usize) -> [[f64; 2]; 2] {
        let m = self.input.corners.len();
        [edge, (edge + 1) % m].map(|k| self.input.corners[k])
    }

    /// Which side of side `side`'s line the Voronoi vertex of the sites `triangle` lies on,
    /// decided exactly: `Greater` inside (see [`circumcentre_side`]).
    fn vertex_side(&self, side: usize, triangle: [u32; 3]) -> Option<Ordering> {
        let sites = triangle.map(|s| self.input.sites[s as usize]);
        circumcentre_side(self.input_edge(side), sites)
    }

    /// Does position `p` lie on side `side` (a crossing of it, or one of its two corners)?
    fn lies_on_side(&self, p: u32, side: usize) -> bool {
        let m = self.clip.vertices().len();
        self.perimeter(p).is_some_and(|at| {
            let edge = at.edge as usize;
            edge == side || (at.kind == PerimeterKind::Corner && (edge + m - 1) % m == side)
        })
    }

    /// Is `to` at or after `from`, both on the same edge?
    fn is_at_or_after(&self, from: Perimeter, to: Perimeter) -> bool {
        match (from.kind, to.kind) {
            (_, PerimeterKind::Corner) => from.kind == PerimeterKind::Corner,
            (PerimeterKind::Corner, _) => true,
            _ => to.rank >= from.rank,
        }
    }

    /// Corners met going counter-clockwise along the boundary strictly after `from` and strictly
    /// before `to` (both on the perimeter).
    fn corners_between(&self, from: Perimeter, to: Perimeter, out: &mut Vec<u32>) {
        let m = self.clip.vertices().len() as u32;
        let steps = if from.edge == to.edge && self.is_at_or_after(from, to) {
            0
        } else {
            let mut s = (to.edge + m - from.edge) % m;
            if s == 0 {
                s = m;
            }
            // Corner `to.edge` is `to` itself when `to` is that corner.
            if to.kind == PerimeterKind::Corner {
                s - 1
            } else {
                s
            }
        };
        for k in 1..=steps {
            out.push((from.edge + k) % m);
        }
    }
}

impl Voronoi {
    /// Clips every cell to `clip` (see [`ClippedCells`]).
    pub fn clip(&self, clip: &ClipPolygon) -> ClippedCells {
        let region_owner = || self.owner_of(clip.centroid());
        let input = InputPlaces {
            sites: self.delaunay.sites(),
            corners: clip.vertices(),
            frame: FrameMap::IDENTITY,
        };
        let Some(local) = self.local_clip_frame(clip) else {
            return self.clip_in_own_frame(clip, input, region_owner);
        };
        let input = InputPlaces {
            frame: local.map,
            ..input
        };
        let mut cells = local
            .diagram
            .clip_in_own_frame(&local.clip, input, region_owner);
        local.to_diagram(&mut cells.positions, clip.vertices());
        cells.clip = clip.clone();
        cells
    }

    /// [`Voronoi::clip`] in the diagram's coordinates; `input` has the sites and corners in the
    /// input's coordinates (the same as the diagram's, or those it is a local frame of);
    /// `region_owner` gives the site whose cell holds the whole region when no edge reaches it.
    fn clip_in_own_frame(
        &self,
        clip: &ClipPolygon,
        input: InputPlaces,
        region_owner: impl Fn() -> u32,
    ) -> ClippedCells {
        let m = clip.vertices().len();
        // Room for the corners, the vertices and the crossings, which are usually O(√n) (the
        // boundary's share of the cells): growing the array later would copy all of it.
        let n = self.vertices.len();
        let mut positions = large_arrays::with_capacity(m + n + n / 16 + 64);
        positions.extend_from_slice(clip.vertices());
        let mut b = Builder {
            clip,
            input,
            reach: Reach::of(clip),
            positions,
            first_crossing: 0,
            crossings: Vec::new(),
        };
        let (vertex_position, unplaced) = self.place_vertices_in(&mut b);
        // An edge with both ends placed is its own piece. Only the others, which may add boundary
        // crossings, are clipped, each once for both of its cells, in the order of their keys.
        let placed = |v: u32| vertex_position[v as usize] != INVALID;
        let keys = self.edges_with_unplaced_end(placed, &unplaced);
        let clipped: Vec<(u32, ClippedEdge)> = keys
            .into_iter()
            .map(|key| (key, self.clip_edge(key, &vertex_position, &mut b)))
            .collect();
        b.order_crossings();
        // A side with both ends placed is its own piece.
        let placed_piece = |side: Side| -> Option<[u32; 2]> {
            if side.from == INVALID || side.to == INVALID {
                return None;
            }
            let from = vertex_position[side.from as usize];
            let to = vertex_position[side.to as usize];
            (from != INVALID && to != INVALID).then_some([from, to])
        };
        // The side's piece (`[INVALID; 2]` for none), and whether it missed the region only
        // within rounding.
        let piece = |side: Side| -> ([u32; 2], bool) {
            if let Some(p) = placed_piece(side) {
                return (p, false);
            }
            let edge = clipped
                .binary_search_by_key(&side.edge, |&(key, _)| key)
                .map_or(ClippedEdge::Miss, |i| clipped[i].1);
            let [start, end] = edge.piece();
            let piece = if side.reversed {
                [end, start]
            } else {
                [start, end]
            };
            (piece, matches!(edge, ClippedEdge::NearMiss))
        };
        let n_sites = self.delaunay.n_sites();
        let mut ranges = large_arrays::zeroed::<[u32; 2]>(n_sites);
        // Cells in the order of the triangles (spatially coherent): consecutive cells share cache
        // lines. Cells are independent once the clipped edges exist: runs of them are assembled
        // in parallel into local lists, then concatenated in order.
        let order = self.cell_handles();
        let assemble_run = |_, run: &[u32]| {
            let mut local = large_arrays::with_capacity(7 * run.len());
            let mut spans = Vec::with_capacity(run.len());
            let mut rebuilt = Vec::new();
            let (mut sides, mut cell_pieces) = (Vec::new(), Vec::new());
            for &handle in run {
                let first = local.len();
                // Most cells have every vertex inside: their pieces join end to start, so the
                // polygon is the pieces' starts in order, written out as the sides are visited.
                let (s, all_placed) = self.visit_handle_sides(handle, |side| {
                    placed_piece(side)
                        .map(|[from, _]| local.push(from))
                        .is_some()
                });
                // One or two corners: Voronoi vertices that coincide once rounded.
                let merged = all_placed && (1..3).contains(&(local.len() - first));
                let has_sides = if all_placed && !merged {
                    local.len() > first
                } else {
                    local.truncate(first);
                    self.handle_sides(handle, &mut sides);
                    cell_pieces.clear();
                    let mut near_miss = merged;
                    cell_pieces.extend(sides.iter().map(|&side| {
                        let (piece, near) = piece(side);
                        near_miss |= near;
                        piece
                    }));
                    cell_pieces.retain(|p: &[u32; 2]| p[0] != INVALID);
                    assemble_cell(&cell_pieces, &b, &mut local);
                    let cell = &local[first..];
                    if cell.len() < 3 || near_miss && corners_in_a_line(cell, &b) {
                        // Fewer than three corners: the cell meets the region only along its
                        // boundary, in a segment or a point (see `ClippedCells`), unless rounding
                        // collapsed it. So may corners in a line beside an edge that missed the
                        // region within rounding: with that edge's piece, a sliver along a side
                        // lost its extent (a bisector running 1e-25 inside the side).
                        local.truncate(first);
                        if near_miss && let Some(corners) = self.exact_cell(handle, &b) {
                            rebuilt.push((s, corners));
                        }
                    } else if !area_beyond_rounding(cell, &b)
                        && !self.has_exact_interior(handle, &b)
                    {
                        // Corners in a line that are the rounding of no interior.
                        local.truncate(first);
                    }
                    !sides.is_empty()
                };
                if has_sides {
                    spans.push([s, first as u32, (local.len() - first) as u32]);
                }
            }
            (local, spans, rebuilt)
        };
        let runs = map_each(
            order.chunks(run_length(order.len())).collect(),
            assemble_run,
        );
        // A single run's list is the whole output; several are concatenated.
        let single = runs.len() == 1;
        let mut indices = if single {
            Vec::new()
        } else {
            large_arrays::with_capacity(runs.iter().map(|(l, _, _)| l.len()).sum())
        };
        let mut rebuilt = Vec::new();
        for (local, spans, run_rebuilt) in runs {
            rebuilt.extend(run_rebuilt);
            let offset = indices.len() as u32;
            if single {
                let len = local.len();
                indices = large_arrays::fit(local, len);
            } else {
                indices.extend_from_slice(&local);
            }
            for [s, first, len] in spans {
                ranges[s as usize] = [offset + first, len];
            }
        }
        // No edge reaches the region: it lies inside one cell.
        if indices.is_empty() {
            let owner = region_owner();
            if owner != INVALID {
                ranges[owner as usize] = [0, m as u32];
                indices.extend(0..m as u32);
            }
        }
        // Cells that rounding collapsed, from their exact polygons, with positions of their own.
        for (site, corners) in rebuilt {
            ranges[site as usize] = [indices.len() as u32, corners.len() as u32];
            for p in corners {
                indices.push(b.positions.len() as u32);
                b.positions.push(p);
            }
        }
        ClippedCells {
            positions: b.positions,
            ranges,
            indices,
            clip: clip.clone(),
        }
    }

    /// The corners of the cell of `handle`, rounded from their exact places, when it has an
    /// interior: for a cell whose floating-point pieces collapsed onto fewer than three
    /// positions (see [`ClippedEdge::NearMiss`]).
    #[cold]
    fn exact_cell(&self, handle: u32, b: &Builder) -> Option<Vec<[f64; 2]>> {
        let (site, neighbours) = self.input_neighbours(handle, b);
        exact_cell_corners(site, &neighbours, b.input.corners, b.input.frame)
    }

    /// Does the cell of `handle` have an interior, decided exactly? For an assembled cell whose
    /// area lies within the rounding of its corners (see [`area_beyond_rounding`]): corners in a
    /// line, or a cell pinched to a corner of the region whose corners rounded apart.
    #[cold]
    fn has_exact_interior(&self, handle: u32, b: &Builder) -> bool {
        let (site, neighbours) = self.input_neighbours(handle, b);
        cell_has_interior(site, &neighbours, b.input.corners)
    }

    /// The site of the cell of `handle` and the sites that bound it exactly (see
    /// [`Voronoi::handle_neighbours`]), in the input's coordinates.
    fn input_neighbours(&self, handle: u32, b: &Builder) -> ([f64; 2], Vec<[f64; 2]>) {
        let (site, neighbours) = self.handle_neighbours(handle);
        let place = |s: u32| b.input.sites[s as usize];
        (place(site), neighbours.into_iter().map(place).collect())
    }

    /// Gives every Voronoi vertex inside the region (closed test; the same test decides every
    /// edge) a position, and returns the vertex → position map ([`INVALID`] outside) and the
    /// list of vertices outside. Those exactly on the boundary become perimeter points (or the
    /// corner they sit on), so that the walk along the boundary knows where they are.
    fn place_vertices_in(&self, b: &mut Builder) -> (Vec<u32>, Vec<u32>) {
        let clip = b.clip;
        let m = clip.vertices().len();
        let (mut on_boundary, mut outside, mut just_outside) = (Vec::new(), Vec::new(), Vec::new());
        // Outside by less than this (a millionth of the region's depth) is within the rounding
        // of a vertex: see `rounded_out_vertices`.
        let depth = (0..m).map(|i| clip.edge_function(i, b.reach.centre));
        let rounding_band = EXACT_ORDER_BAND * depth.fold(0.0, f64::max);
        let mut vertex_position = large_arrays::with_capacity(self.vertices.len());
        vertex_position.extend(self.vertices.iter().enumerate().map(|(v, &p)| {
            let lowest = clip.lowest_edge_function(p);
            if lowest > 0.0 {
                b.positions.push(p);
                (b.positions.len() - 1) as u32
            } else {
                if lowest == 0.0 {
                    on_boundary.push(v);
                } else {
                    outside.push(v as u32);
                    if -lowest <= rounding_band {
                        just_outside.push(v as u32);
                    }
                }
                INVALID
            }
        }));
        b.first_crossing = b.positions.len();
        for &v in &on_boundary {
            let p = self.vertices[v];
            let zero = |i: usize| clip.edge_function(i % m, p) == 0.0;
            let i = (0..m).find(|&i| zero(i)).unwrap_or(0);
            vertex_position[v] = if zero(i + 1) {
                ((i + 1) % m) as u32
            } else if zero(i + m - 1) {
                i as u32
            } else {
                b.crossing(i, clip.edge_parameters(i, p), None)
            };
        }
        if !just_outside.is_empty() {
            for (v, side) in self.rounded_out_vertices(&just_outside, b) {
                let p = self.vertices[v as usize];
                vertex_position[v as usize] = b.crossing(side, clip.edge_parameters(side, p), None);
            }
            outside.retain(|&v| vertex_position[v as usize] == INVALID);
        }
        (vertex_position, outside)
    }

    /// The vertices of `just_outside` (outside the region by less than the rounding of a
    /// vertex) that lie inside it or on its boundary exactly, each with the side it is nearest:
    /// it is placed there, on the boundary. (A circumcentre of sites near 0.1 lies 2.8e-17
    /// inside the side at x = -0.4 and rounds 2 ulps outside it: its edges were clipped as if
    /// they entered the region there, at crossings beyond the vertex, and a cell beside it
    /// walked round the whole region.)
    #[cold]
    fn rounded_out_vertices(&self, just_outside: &[u32], b: &Builder) -> Vec<(u32, usize)> {
        let clip = b.clip;
        let m = clip.vertices().len();
        let triangles = self.a_triangle_of_each(just_outside.iter().copied());
        just_outside
            .iter()
            .zip(triangles)
            .filter_map(|(&v, t)| {
                let p = self.vertices[v as usize];
                let triangle = [0, 1, 2].map(|k| self.delaunay.triangles[3 * t as usize + k]);
                let functions = (0..m).map(|i| (clip.edge_function(i, p), i));
                let inside_exactly = functions
                    .clone()
                    .filter(|&(f, _)| f < 0.0)
                    .all(|(_, i)| b.vertex_side(i, triangle) >= Some(Ordering::Equal));
                let (_, side) = functions.min_by(|x, y| x.0.total_cmp(&y.0))?;
                inside_exactly.then_some((v, side))
            })
            .collect()
    }

    /// A Delaunay triangle of each of `vertices` (one of those merged into it).
    #[cold]
    fn a_triangle_of_each(&self, vertices: impl Iterator<Item = u32>) -> Vec<u32> {
        if !self.any_merged() {
            // One vertex per triangle, numbered alike.
            return vertices.collect();
        }
        let mut triangle = vec![INVALID; self.vertices.len()];
        for (t, &v) in self.triangle_vertex.iter().enumerate().rev() {
            triangle[v as usize] = t as u32;
        }
        vertices.map(|v| triangle[v as usize]).collect()
    }

    /// The site owning point `p`; used when no edge crosses the region, i.e. the whole region
    /// lies in one cell.
    fn owner_of(&self, p: [f64; 2]) -> u32 {
        self.nearest_site(p, None)
            .ok()
            .flatten()
            .map_or(INVALID, |site| site.0)
    }

    /// Clips the edge with key `key` to the region.
    fn clip_edge(&self, key: u32, vertex_position: &[u32], b: &mut Builder) -> ClippedEdge {
        let ends = self.edge_ends(key);
        let clip = b.clip;
        let m = clip.vertices().len();
        let (o, t) = (ends.from, ends.to);
        let sites = Some([ends.left, ends.right]);
        // Parametrise as base + s·dir with s in [lo, hi]; the finite end (if any) is at s = 0.
        // An in-ray (from infinity) is clipped as the ray from its finite end, and a segment
        // from its end nearer the region, then reversed where that runs against the edge.
        let position = |v: u32| vertex_position.get(v as usize).copied().unwrap_or(INVALID);
        let (at_o, at_t) = (position(o), position(t));
        if at_o != INVALID && at_t != INVALID {
            return ClippedEdge::Piece([at_o, at_t]);
        }
        // A placed end is clipped from its position: a vertex that rounding put just outside the
        // region but lies on or inside its side exactly is placed on that side (see
        // `rounded_out_vertices`).
        let placed_at = |at: u32, p: [f64; 2]| match at {
            INVALID => p,
            i => b.positions[i as usize],
        };
        let geometry = match self.near_geometry(ends, b.reach) {
            EdgeGeometry::Segment { from, to } => EdgeGeometry::Segment {
                from: placed_at(at_o, from),
                to: placed_at(at_t, to),
            },
            EdgeGeometry::Ray { origin, direction } => EdgeGeometry::Ray {
                origin: placed_at(if o == INVALID { at_t } else { at_o }, origin),
                direction,
            },
            line => line,
        };
        let (base, dir, far, mut lo, mut hi, reversed) = match geometry {
            EdgeGeometry::Segment { from, to } => {
                // From the end nearer the region: a crossing's parameter is rounded relative to
                // its distance from the base, which for a far end (a circumcentre of nearly
                // collinear sites) is the whole edge, an ulp of which can be the whole cell.
                let reversed = !b.reach.is_nearer(from, to);
                let (base, far) = if reversed { (to, from) } else { (from, to) };
                (
                    base,
                    [far[0] - base[0], far[1] - base[1]],
                    Some(far),
                    0.0,
                    1.0,
                    reversed,
                )
            }
            EdgeGeometry::Ray { origin, direction } => (
                origin,
                unit_direction(direction),
                None,
                0.0,
                f64::INFINITY,
                o == INVALID,
            ),
            EdgeGeometry::Line { point, direction } => (
                point,
                unit_direction(direction),
                None,
                f64::NEG_INFINITY,
                f64::INFINITY,
                false,
            ),
        };
        // The positions of the vertices at `s = 0` and (for a segment) at `s = 1`.
        let (base_at, far_at) = if reversed { (at_t, at_o) } else { (at_o, at_t) };
        // An end outside the region is cut off by a side it lies outside of, even where the
        // crossing's parameter rounds onto the end's own (a vertex outside by far less than an
        // ulp of the edge).
        let needs_entry = base_at == INVALID;
        let needs_exit = far.is_some() && far_at == INVALID;
        let (mut enter, mut exit) = (usize::MAX, usize::MAX);
        // An end placed on a side lies on it, whatever the rounding of its position says.
        let placed_on = |at: u32, i: usize| at != INVALID && b.lies_on_side(at, i);
        for i in 0..m {
            let f0 = if placed_on(base_at, i) {
                0.0
            } else {
                clip.edge_function(i, base)
            };
            // For segments use the end's own edge function so the test agrees with the vertex's.
            let f1 = far.map(|to| {
                if placed_on(far_at, i) {
                    0.0
                } else {
                    clip.edge_function(i, to)
                }
            });
            let rate = match f1 {
                Some(f1) => f1 - f0,
                None => clip.edge_rate(i, dir),
            };
            if rate == 0.0 {
                if f0 < 0.0 {
                    // Parallel to side `i` and outside it: near when its distance is lost in
                    // the rounding of the edge functions at `base`.
                    let largest = (0..m).map(|k| clip.edge_function(k, base).abs());
                    let near = -f0 <= EXACT_ORDER_BAND * largest.fold(0.0, f64::max);
                    return if near {
                        ClippedEdge::NearMiss
                    } else {
                        ClippedEdge::Miss
                    };
                }
                continue;
            }
            let s = -f0 / rate;
            if rate > 0.0 {
                if s > lo || (s == lo && needs_entry && enter == usize::MAX && f0 < 0.0) {
                    lo = s;
                    enter = i;
                }
            } else if s < hi
                || (s == hi && needs_exit && exit == usize::MAX && f1.is_some_and(|f1| f1 < 0.0))
            {
                hi = s;
                exit = i;
            }
        }
        let sides = [ends.left, ends.right];
        let (cut_at_start, cut_at_end) = (enter != usize::MAX, exit != usize::MAX);
        let found_piece = lo.partial_cmp(&hi) == Some(Ordering::Less);
        if !found_piece && !b.within_rounding([lo, hi], [base, dir], [enter, exit]) {
            return ClippedEdge::Miss;
        }
        // Each crossing from the sites, where it lies on its side and goes the right way.
        let on_side =
            |side: usize, entering: bool| b.crossing_on_side(side, sides, entering, reversed);
        let (mut entry, mut exit_at) = (
            cut_at_start.then(|| on_side(enter, true)).flatten(),
            cut_at_end.then(|| on_side(exit, false)).flatten(),
        );
        let chosen_by_rounding =
            (cut_at_start && entry.is_none()) || (cut_at_end && exit_at.is_none());
        let at = |s: f64| [base[0] + s * dir[0], base[1] + s * dir[1]];
        if chosen_by_rounding && cut_at_start != cut_at_end {
            // One end at a vertex inside, and a side its bisector does not cross exactly: a
            // bisector far steeper than the rounding of the vertex (sites near 1 beside one at
            // 1e28) leaves by the side it crosses exactly, where that crossing lies within the
            // rounding of the floating-point one. The cells between the two sides' corners
            // depend on it.
            let (entering, s) = if cut_at_start {
                (true, lo)
            } else {
                (false, hi)
            };
            let exact = b
                .exact_piece_sides(sides, reversed)
                .and_then(|[enter, exit]| {
                    let side = if entering { enter } else { exit };
                    let parameters = on_side(side, entering)?;
                    b.meets_point(side, parameters, at(s), [base, dir], s)
                        .then_some((side, parameters))
                });
            if let Some((side, parameters)) = exact {
                if entering {
                    (enter, entry) = (side, Some(parameters));
                } else {
                    (exit, exit_at) = (side, Some(parameters));
                }
            }
        }
        if cut_at_start && cut_at_end {
            if !found_piece || chosen_by_rounding {
                // Both ends on the boundary: the sides are decided exactly.
                let Some([exact_enter, exact_exit]) = b.exact_piece_sides(sides, reversed) else {
                    return ClippedEdge::NearMiss;
                };
                (enter, entry) = (exact_enter, on_side(exact_enter, true));
                (exit, exit_at) = (exact_exit, on_side(exact_exit, false));
                if entry.is_none() || exit_at.is_none() {
                    return ClippedEdge::NearMiss;
                }
            }
            // Both crossings are placed from the sites, and kept where they lie on the edge
            // exactly: the rounding of an end can take an edge across the region when its
            // bisector crosses it beyond that end (a segment 1e-12 long between vertices rounded
            // to ulps of 1e15 crossing a corner, or a ray whose vertex lies 1e300 out in a local
            // frame, moved along a bisector rounded to ulps of that).
            let off_edge = |side: usize, parameters: Option<[f64; 2]>| {
                parameters.is_some() && !self.crosses_on_edge(key, ends, side, b)
            };
            if off_edge(enter, entry) || off_edge(exit, exit_at) {
                return ClippedEdge::NearMiss;
            }
        } else if !found_piece {
            // One end at a vertex inside the region, and the crossing's parameter rounded onto
            // the vertex's: the piece from the crossing, placed from the sites, to the vertex is
            // kept when the crossing lies on its side and where the edge put it, within the
            // rounding of that computation (an edge crossing a side steeply, next to a vertex
            // far closer to the side than an ulp of the edge). An edge running along a side
            // within rounding has a crossing anywhere along it, and is left as missing; so is
            // one leaving a vertex on the boundary through the side the vertex lies on, unless
            // it runs inside along that side (see `runs_inside_along`): its crossing is the
            // vertex. One reaching a vertex on another side crosses the region (a region 1e-86
            // tall, whose height rounds away against 3).
            let (side, crossing, vertex) = if cut_at_start {
                (enter, entry, far_at)
            } else {
                (exit, exit_at, base_at)
            };
            let s = if cut_at_start { lo } else { hi };
            // The vertex's end of the edge: `to` when it is the far end of an edge run forwards.
            let vertex_end = usize::from(cut_at_start != reversed);
            let kept = vertex != INVALID
                && crossing.is_some_and(|parameters| {
                    let vertex_at = b.positions[vertex as usize];
                    if b.lies_on_side(vertex, side) {
                        // Along the side, and far enough from the vertex that their order
                        // there is their rounded order.
                        let vertex_t = clip.edge_parameters(side, vertex_at)[0];
                        (parameters[0] - vertex_t).abs() > EXACT_ORDER_BAND
                            && self.runs_inside_along(key, ends, vertex_end, side, b)
                    } else {
                        b.meets_point(side, parameters, vertex_at, [base, dir], s)
                    }
                });
            if !kept {
                return ClippedEdge::NearMiss;
            }
        }
        // A side chosen by rounding beside an end at a vertex (an edge running along a side
        // within rounding) keeps the floating-point crossing, which agrees with where the test
        // of the vertices put that end.
        let start = if cut_at_start {
            let parameters = entry.unwrap_or_else(|| clip.edge_parameters(enter, at(lo)));
            b.crossing(enter, parameters, sites)
        } else {
            // No entering constraint: the start is the finite end of the edge, inside. (A line
            // or ray whose rates all round to zero has no such end: the edge is dropped rather
            // than indexed past the vertices.)
            base_at
        };
        // Without an exit constraint a segment's far end is inside (a ray always exits).
        let end = if cut_at_end {
            let parameters = exit_at.unwrap_or_else(|| clip.edge_parameters(exit, at(hi)));
            b.crossing(exit, parameters, sites)
        } else {
            far_at
        };
        // A piece whose ends rounded onto one point, or onto an end the region holds only in
        // floating point.
        if start == INVALID || end == INVALID || start == end {
            return ClippedEdge::NearMiss;
        }
        ClippedEdge::Piece(if reversed { [end, start] } else { [start, end] })
    }
}

impl Voronoi {
    /// Does the edge with key `key` and ends `ends`, leaving its vertex at end `vertex_end`
    /// (placed on side `side`) through that side, run inside the region along it, decided
    /// exactly? Yes when the vertex lies strictly inside the side and the bisector crosses the
    /// side on the edge: the piece from the vertex to that crossing bounds a sliver along the
    /// side (a ray running 2e-26 inside a side 3.4e-13 long, from a vertex rounded onto it, for
    /// 92 % of its length). No when the vertex lies on the side: the edge leaves the region
    /// there, and its crossing is the vertex.
    #[cold]
    fn runs_inside_along(
        &self,
        key: u32,
        ends: EdgeEnds,
        vertex_end: usize,
        side: usize,
        b: &Builder,
    ) -> bool {
        let third = self.edge_third_sites(key)[vertex_end];
        if third == INVALID {
            return false;
        }
        b.vertex_side(side, [ends.left, ends.right, third]) == Some(Ordering::Greater)
            && self.crosses_on_edge(key, ends, side, b)
    }

    /// Does the edge with key `key` and ends `ends` cross side `side` of the region (where its
    /// bisector does) between its ends or at one of them, decided exactly (see
    /// [`crossing_nearer_than`])?
    #[cold]
    fn crosses_on_edge(&self, key: u32, ends: EdgeEnds, side: usize, b: &Builder) -> bool {
        let place = |s: u32| b.input.sites[s as usize];
        let sites = [place(ends.left), place(ends.right)];
        self.edge_third_sites(key).iter().all(|&third| {
            third == INVALID
                || crossing_nearer_than(b.input_edge(side), sites, place(third))
                    != Some(Ordering::Greater)
        })
    }

    /// The geometry of the edge with ends `ends`, its ends far from the region (see [`Reach`])
    /// moved along the bisector of its two sites to just beyond the region.
    ///
    /// A far Voronoi vertex is the circumcentre of a flat triangle (nearly collinear sites), up
    /// to 1e16 away and rounded there to a few units, so the line through it can pass the region
    /// by as much as the region is wide: cells of sites inside came out empty and their
    /// neighbours overlapped. The bisector computed from the sites carries only their own
    /// rounding. A moved end stays outside the region, which is all the clipping reads of an end
    /// that is not placed, so the edge keeps the same part of the region, now in the right place.
    fn near_geometry(&self, ends: EdgeEnds, reach: Reach) -> EdgeGeometry {
        let geometry = self.geometry_of(ends);
        let (mid, along) = self.bisector(ends);
        let length = along[0].hypot(along[1]);
        if !(length.is_finite() && length > 0.0 && reach.radius.is_finite()) {
            return geometry;
        }
        let unit = [along[0] / length, along[1] / length];
        let param = |p: [f64; 2]| (p[0] - mid[0]) * unit[0] + (p[1] - mid[1]) * unit[1];
        let centre = param(reach.centre);
        let band = Reach::MOVED * reach.radius;
        let moved = |p: [f64; 2]| {
            if !reach.is_far(p) {
                return p;
            }
            let s = centre + (param(p) - centre).clamp(-band, band);
            [mid[0] + s * unit[0], mid[1] + s * unit[1]]
        };
        match geometry {
            EdgeGeometry::Segment { from, to } => EdgeGeometry::Segment {
                from: moved(from),
                to: moved(to),
            },
            EdgeGeometry::Ray { origin, direction } => EdgeGeometry::Ray {
                origin: moved(origin),
                direction,
            },
            line @ EdgeGeometry::Line { .. } => line,
        }
    }
}

/// Do the positions of the assembled cell `cell` (at least three) lie on one line, exactly?
fn corners_in_a_line(cell: &[u32], b: &Builder) -> bool {
    let at = |i: &u32| b.positions[*i as usize];
    let first = at(&cell[0]);
    let Some(second) = cell.iter().map(at).find(|&p| p != first) else {
        return true;
    };
    cell.iter().all(|i| orient2d(first, second, at(i)) == 0.0)
}

/// Is the signed area of the assembled cell `cell` (at least three positions) larger than the
/// rounding of its corners can make it?
fn area_beyond_rounding(cell: &[u32], b: &Builder) -> bool {
    let points = cell.iter().map(|&i| b.positions[i as usize]);
    let origin = b.positions[cell[0] as usize];
    let (mut twice_area, mut previous) = (0.0_f64, origin);
    let (mut largest_offset, mut largest_coordinate) = (0.0_f64, 0.0_f64);
    for p in points.skip(1) {
        let (u, w) = (
            [0, 1].map(|k| previous[k] - origin[k]),
            [0, 1].map(|k| p[k] - origin[k]),
        );
        twice_area += u[0] * w[1] - u[1] * w[0];
        largest_offset = largest_offset.max(w[0].abs()).max(w[1].abs());
        largest_coordinate = largest_coordinate.max(p[0].abs()).max(p[1].abs());
        previous = p;
    }
    // The region's own reach too: in a local frame (see `clip_frame`) a Voronoi vertex near
    // the origin carries the rounding of its offset from sites a region's width away.
    let reach = b.reach.centre[0].abs().max(b.reach.centre[1].abs()) + b.reach.radius;
    largest_coordinate = largest_coordinate
        .max(origin[0].abs())
        .max(origin[1].abs())
        .max(reach);
    // Each corner lies within an ulp of its exact place: an area of zero can round to up to
    // about (corners × ulp × extent); four times that, for the sums.
    let rounding = 4.0 * cell.len() as f64 * f64::EPSILON * largest_coordinate * largest_offset;
    twice_area.abs() > rounding
}

/// Appends to `out` the corners of a cell given its clipped pieces in order (`[start, end]`
/// positions): each piece's start and, where a piece ends on the region's boundary, the region's
/// corners up to where the next piece starts.
fn assemble_cell(pieces: &[[u32; 2]], b: &Builder, out: &mut Vec<u32>) {
    let Some(&[first_start, _]) = pieces.first() else {
        return;
    };
    for (i, &[start, end]) in pieces.iter().enumerate() {
        out.push(start);
        // The next piece's start, without a division per corner for the wrap-around.
        let next_start = pieces.get(i + 1).map_or(first_start, |p| p[0]);
        // A piece ending on the boundary is followed by the boundary up to where the next
        // piece starts (nothing when the next piece starts right there).
        if end != next_start
            && let (Some(exit), Some(entry)) = (b.perimeter(end), b.perimeter(next_start))
        {
            out.push(end);
            b.corners_between(exit, entry, out);
        }
    }
}

impl ClippedCells {
    /// All vertex positions: the corners of the region first, then Voronoi vertices inside it,
    /// then boundary crossings, then the corners of cells rebuilt from their exact polygons (see
    /// [`ClippedCells`]).
    pub fn positions(&self) -> &[[f64; 2]] {
        &self.positions
    }

    /// `[start, length]` of every site's cell in [`ClippedCells::indices`]: the cell of site `s`
    /// is `indices[start..start + length]`.
    pub fn cell_ranges(&self) -> &[[u32; 2]] {
        &self.ranges
    }

    /// Number of sites (cells, empty ones included).
    pub fn n_cells(&self) -> usize {
        self.ranges.len()
    }

    /// Position indices of all cells (in an internal, spatially coherent order; see
    /// [`ClippedCells::cell_ranges`]).
    pub fn indices(&self) -> &[u32] {
        &self.indices
    }

    /// The clip region.
    pub fn clip_region(&self) -> &ClipPolygon {
        &self.clip
    }

    /// Position indices of the cell of `site`, counter-clockwise (empty when the cell misses the
    /// region or the site is a duplicate).
    pub fn cell(&self, site: SiteId) -> Result<&[u32], VoronoiError> {
        let Some(&[start, len]) = self.ranges.get(site.index()) else {
            return Err(VoronoiError::InvalidSite {
                site,
                count: self.ranges.len(),
            });
        };
        Ok(&self.indices[start as usize..(start + len) as usize])
    }

    /// The polygon of the cell of `site`.
    pub fn cell_polygon(&self, site: SiteId) -> Result<Vec<[f64; 2]>, VoronoiError> {
        Ok(self
            .cell(site)?
            .iter()
            .map(|&i| self.positions[i as usize])
            .collect())
    }

    /// Area of the cell of `site` (0 for an empty cell).
    pub fn cell_area(&self, site: SiteId) -> Result<f64, VoronoiError> {
        Ok(polygon_area_centroid(&self.cell_polygon(site)?).0)
    }

    /// Centroid of the cell of `site`, `None` for an empty cell.
    pub fn cell_centroid(&self, site: SiteId) -> Result<Option<[f64; 2]>, VoronoiError> {
        let poly = self.cell_polygon(site)?;
        Ok(if poly.is_empty() {
            None
        } else {
            Some(polygon_area_centroid(&poly).1)
        })
    }

    /// The cells as a polygon soup (z = 0) with shared vertices, so the half-edge builder gets a
    /// connected mesh, plus the site of every face (empty cells are left out).
    pub fn to_polygon_soup(&self) -> (PolygonSoup, Vec<SiteId>) {
        let mut soup = PolygonSoup {
            positions: self.positions.iter().map(|p| [p[0], p[1], 0.0]).collect(),
            ..PolygonSoup::default()
        };
        let mut face_site = Vec::new();
        for (s, &[start, len]) in self.ranges.iter().enumerate() {
            let cell = &self.indices[start as usize..(start + len) as usize];
            if cell.len() >= 3 {
                soup.face_sizes.push(cell.len() as u32);
                soup.indices.extend_from_slice(cell);
                face_site.push(SiteId(s as u32));
            }
        }
        (soup, face_site)
    }
}

/// `direction` times the power of two that brings its larger component near 1: the rates of the
/// edge functions along a ray then neither underflow (a ray between sites `1e-299` apart, in a
/// region `1e301` wide, got a subnormal rate and an infinite crossing) nor overflow.
fn unit_direction(direction: [f64; 2]) -> [f64; 2] {
    let largest = direction[0].abs().max(direction[1].abs());
    let unit = normalising_scale_of_box([[-largest, 0.0], [largest, 0.0]]);
    direction.map(|x| x * unit)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every cell counter-clockwise (in floating point: zero area allowed) and made of at least
    /// three positions or none, and the areas summing to the region's.
    fn check_tiling(cells: &ClippedCells, clip: &ClipPolygon) {
        let mut total = 0.0;
        for site in (0..cells.n_cells() as u32).map(SiteId) {
            let cell = cells.cell(site).unwrap();
            assert!(cell.is_empty() || cell.len() >= 3, "{site}: {cell:?}");
            let area = cells.cell_area(site).unwrap();
            assert!(area >= 0.0, "{site} clockwise: {area}");
            total += area;
        }
        assert!(
            (total - clip.area()).abs() <= 1e-9 * clip.area(),
            "{total} vs {}",
            clip.area()
        );
    }

    #[test]
    fn parallel_cells_far_narrower_than_an_ulp_stay_counter_clockwise() {
        // Collinear sites a few units apart on the diagonal and one 1e117 out along it: the
        // cells of the near sites are parallel strips crossing the region's corner 1e100 times
        // narrower than an ulp there, whose crossings rounded out of order (one cell covered
        // the region twice, others came out clockwise).
        let sites = [
            [45.0, -45.0],
            [-18.0, 18.0],
            [3.0, -3.0],
            [12.0, -12.0],
            [-57.0, 57.0],
            [-4.500000000000001e117, 4.500000000000001e117],
        ];
        let clip = ClipPolygon::rectangle(
            [-4.9500000000000014e117, -4.5000000000000016e116],
            [4.5000000000000016e116, 4.9500000000000014e117],
        )
        .unwrap();
        let cells = Voronoi::new(&sites).unwrap().clip(&clip);
        check_tiling(&cells, &clip);
        for site in (0..sites.len() as u32).map(SiteId) {
            assert!(cells.cell(site).unwrap().len() >= 3, "{site}");
        }
    }

    #[test]
    fn a_sliver_that_rounding_collapses_is_rebuilt_exactly() {
        // The bisector of the first two sites runs 2e-294 above the region's bottom side y = 1:
        // the tiny site's part of the region is a strip that thin, whose Voronoi vertex with
        // the third site rounds onto that side. Its cell came out empty.
        let sites = [[0.0, 2.0], [1e-294, 4e-294], [2.0, 1.0]];
        let clip = ClipPolygon::rectangle([0.0, 1.0], [2.0, 2.0]).unwrap();
        let cells = Voronoi::new(&sites).unwrap().clip(&clip);
        check_tiling(&cells, &clip);
        let sliver = cells.cell_polygon(SiteId(1)).unwrap();
        assert!(sliver.len() >= 3, "{sliver:?}");
        // Its corners lie on the bottom side, from the left corner to where the strip ends.
        for p in &sliver {
            assert_eq!(p[1], 1.0, "{sliver:?}");
            assert!((0.0..=2.0).contains(&p[0]), "{sliver:?}");
        }
        assert!(sliver.contains(&[0.0, 1.0]), "{sliver:?}");
    }

    #[test]
    fn an_edge_ending_just_outside_the_region_is_cut_at_its_side() {
        // The Voronoi vertex of the first three sites lies 5e-67 below the region's bottom
        // side, an ulp of its edges' parameters being 1e-16: the crossings of both its edges
        // with the side rounded onto the vertex itself, no side cut the edges off, and they were
        // dropped; the first site's cell lost its triangle down to the side.
        let sites = [
            [1.0, 1.0],
            [2.0, 0.0],
            [3e-66, 2e-66],
            [1.0, 2.0],
            [3.0, 1.0],
        ];
        let clip = ClipPolygon::rectangle([3e-66, 2e-66], [3.0, 2.0]).unwrap();
        let cells = Voronoi::new(&sites).unwrap().clip(&clip);
        check_tiling(&cells, &clip);
        assert_eq!(cells.cell_area(SiteId(0)).unwrap(), 2.0);
    }

    #[test]
    fn a_cell_meeting_the_region_along_its_side_only_is_empty() {
        // The bisector of the two sites above the region is its top side: the upper site's
        // cell meets the region in that segment only.
        let sites = [[0.5, 0.5], [0.5, 1.5], [0.25, -1.0]];
        let clip = ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap();
        let cells = Voronoi::new(&sites).unwrap().clip(&clip);
        check_tiling(&cells, &clip);
        assert!(cells.cell(SiteId(1)).unwrap().is_empty());
    }
}
