//! Polygon triangulation in O(n log n) whatever the polygon's shape: render buffers and the
//! half-edge kernel's face triangulation both use it.
//!
//! A polygon is projected onto the coordinate plane across the largest component of its Newell
//! normal (non-planar polygons included), where it runs counter-clockwise whenever it is simple;
//! the projection only drops a coordinate, so it rounds nothing. A polygon whose fan
//! from its first corner has only proper counter-clockwise triangles (convex polygons, the usual
//! mesh faces) is that fan. Otherwise corners that enclose nothing (repeated places, spike tips)
//! are cut off in triangles of no area, a plane sweep cuts the rest into pieces monotone in the
//! sweep direction, and each piece is triangulated in linear time. Every decision is an exact
//! predicate on an infinitesimally perturbed copy of the projected corners, so collinear and
//! repeated corners are decided consistently; a corner in the middle of a straight side stays
//! in proper triangles (no T-junction cracks). The result is deterministic: same input, same
//! triangles.
//!
//! Any polygon of `n ≥ 3` corners yields exactly `n − 2` triangles, and they always triangulate
//! it as a ring of corners (each cuts an ear off what is left), so a mesh can be split along
//! them whatever the geometry. Geometrically, the triangles of a simple polygon — collinear
//! corners, repeated places and spikes allowed — are never inverted, so they cover it exactly
//! once. A polygon that touches itself (a repaired face that names a vertex twice, a hole joined
//! to the outside by a slit) is triangulated as a perturbed copy that pulls the touching parts
//! apart where ranking the corners at each shared place can do it (see `touching_corners`).
//! Where it cannot — two sides lying on one another with a corner on one of them only — the
//! copy may cross itself; the sweep is then tried in the three other axis directions, and when
//! none gives triangles without an inverted one, the outcome is reported as self-intersecting
//! (like a polygon that does cross itself) with the triangles that invert least.

mod degenerate_corners;
mod monotone_split;
mod monotone_triangulation;
mod perturbed;
mod pieces;
mod plane;
mod sweep_status;
mod touching_corners;

use robust::{Coord, orient2d};

use degenerate_corners::DegenerateCorners;
use monotone_split::MonotoneSplit;
use monotone_triangulation::MonotoneTriangulator;
use perturbed::PerturbedPoints;
use pieces::Pieces;
use touching_corners::PerturbationRanks;

/// Why a polygon's triangles may not cover it exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FallbackReason {
    /// A corner has a NaN or infinite coordinate: the triangles are a fan from the first corner.
    NonFinite,
    /// The polygon has no area to speak of (all corners collinear or coincident, or lobes of
    /// opposite windings cancelling out), so it has no plane to be projected on: the triangles
    /// are a fan from the first corner.
    ZeroArea,
    /// Some triangle is inverted: the polygon crosses itself, or touches itself where the
    /// triangulation could not follow. Of the triangulations tried (the sweep in each axis
    /// direction, fans), the one that inverts least area is kept.
    SelfIntersecting,
}

/// What happened to one polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PolygonOutcome {
    /// `n − 2` triangles, none inverted: together they cover each point as many times as the
    /// polygon winds around it (a simple polygon exactly once).
    Exact,
    /// Fewer than 3 corners: no triangle.
    TooFewCorners,
    /// `n − 2` triangles, some of which may overlap or be inverted.
    Fallback(FallbackReason),
}

/// Reusable polygon triangulator: keeps its scratch buffers between polygons so a mesh is
/// triangulated without allocations per face.
#[derive(Debug, Default)]
pub struct PolygonTriangulator {
    projected: Vec<Coord<f64>>,
    degenerate: DegenerateCorners,
    /// The corners left once those enclosing nothing are cut off, in order.
    ring: Vec<u32>,
    ring_points: Vec<Coord<f64>>,
    ranks: PerturbationRanks,
    split: MonotoneSplit,
    diagonals: Vec<(u32, u32)>,
    pieces: Pieces,
    monotone: MonotoneTriangulator,
    ring_triangles: Vec<[u32; 3]>,
    /// Quarter turns `ring_points` have been turned by since the cut.
    turned: u32,
    candidate: Vec<[u32; 3]>,
    best: Vec<[u32; 3]>,
}

/// One way to triangulate a polygon (see [`PolygonTriangulator::triangulate_choosing`]).
#[derive(Clone, Copy, Debug)]
enum Candidate {
    /// A fan from this corner over every corner.
    Fan(u32),
    /// The degenerate-corner cut, then the sweep after turning the plane by this many quarter
    /// turns (a sweep in another direction: other monotone pieces).
    Sweep(u32),
    /// The degenerate-corner cut, then a fan over the corners left.
    RingFan,
}

impl PolygonTriangulator {
    /// A triangulator with empty scratch buffers.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends the triangles of the polygon `corners` to `out`, as local corner indices in the
    /// polygon's own winding. O(n log n).
    pub fn triangulate(&mut self, corners: &[[f64; 3]], out: &mut Vec<[u32; 3]>) -> PolygonOutcome {
        self.triangulate_choosing(corners, &[], out, |_| true)
            .expect("every triangulation is accepted")
    }

    /// Like [`triangulate`](Self::triangulate), but only a triangulation that `accept` takes
    /// will do: the one `triangulate` gives if taken, else the first exact one taken of a few
    /// others that each cost O(n log n) — sweeps in the three other axis directions, fans from
    /// the corners `fan_apexes` — else the one taken that inverts least; `None` (and `out`
    /// unchanged) when `accept` takes none.
    pub(crate) fn triangulate_choosing(
        &mut self,
        corners: &[[f64; 3]],
        fan_apexes: &[u32],
        out: &mut Vec<[u32; 3]>,
        mut accept: impl FnMut(&[[u32; 3]]) -> bool,
    ) -> Option<PolygonOutcome> {
        let n = corners.len();
        if n < 3 {
            return Some(PolygonOutcome::TooFewCorners);
        }
        if n == 3 {
            return accept(&[[0, 1, 2]]).then(|| {
                out.push([0, 1, 2]);
                PolygonOutcome::Exact
            });
        }
        let no_plane = if corners.iter().flatten().any(|c| !c.is_finite()) {
            Some(FallbackReason::NonFinite)
        } else if !plane::project_on_dominant_plane(corners, &mut self.projected) {
            Some(FallbackReason::ZeroArea)
        } else {
            None
        };
        if let Some(reason) = no_plane {
            // No geometry to go by: any fan is as good as any other.
            for apex in std::iter::once(0).chain(fan_apexes.iter().copied()) {
                self.candidate.clear();
                push_fan(
                    (0..n as u32).map(|k| (k + apex) % n as u32),
                    &mut self.candidate,
                );
                if accept(&self.candidate) {
                    out.extend_from_slice(&self.candidate);
                    return Some(PolygonOutcome::Fallback(reason));
                }
            }
            return None;
        }
        let candidates = std::iter::once(Candidate::Fan(0))
            .chain((0..4).map(Candidate::Sweep))
            .chain(fan_apexes.iter().map(|&apex| Candidate::Fan(apex)))
            .chain(std::iter::once(Candidate::RingFan));
        let mut least_inverted = f64::INFINITY;
        let mut cut_done = false;
        for candidate in candidates {
            if !cut_done && matches!(candidate, Candidate::Sweep(_) | Candidate::RingFan) {
                self.cut_degenerate_corners();
                cut_done = true;
            }
            self.candidate.clear();
            match candidate {
                Candidate::Fan(apex) => push_fan(
                    (0..n as u32).map(|k| (k + apex) % n as u32),
                    &mut self.candidate,
                ),
                Candidate::Sweep(quarter_turns) => self.sweep(quarter_turns),
                Candidate::RingFan => {
                    self.candidate.extend_from_slice(&self.ring_triangles);
                    push_fan(self.ring.iter().copied(), &mut self.candidate);
                }
            }
            let inverted = inverted_area(&self.projected, &self.candidate);
            // A fan is taken as exact only with every triangle proper: a fan of no-area
            // triangles along a straight side would leave a T-junction crack.
            let exact = match candidate {
                Candidate::Fan(_) => self
                    .candidate
                    .iter()
                    .all(|&t| orient(&self.projected, t) > 0.0),
                _ => inverted == 0.0,
            };
            if (exact || inverted < least_inverted) && accept(&self.candidate) {
                if exact {
                    out.extend_from_slice(&self.candidate);
                    return Some(PolygonOutcome::Exact);
                }
                least_inverted = inverted;
                std::mem::swap(&mut self.best, &mut self.candidate);
            }
        }
        (least_inverted < f64::INFINITY).then(|| {
            out.extend_from_slice(&self.best);
            PolygonOutcome::Fallback(FallbackReason::SelfIntersecting)
        })
    }

    /// Cuts off the corners that enclose nothing: their triangles go to `ring_triangles`, the
    /// corners left to `ring` (and their projections to `ring_points`).
    fn cut_degenerate_corners(&mut self) {
        self.ring_triangles.clear();
        self.degenerate
            .cut(&self.projected, &mut self.ring_triangles, &mut self.ring);
        self.ring_points.clear();
        self.ring_points
            .extend(self.ring.iter().map(|&c| self.projected[c as usize]));
        self.turned = 0;
    }

    /// Sets `candidate` to the cut's triangles and those of the sweep over the ring turned by
    /// `quarter_turns`.
    fn sweep(&mut self, quarter_turns: u32) {
        self.candidate.extend_from_slice(&self.ring_triangles);
        while self.turned != quarter_turns % 4 {
            // (x, y) -> (-y, x): exact, and orientations do not change.
            for p in &mut self.ring_points {
                *p = Coord { x: -p.y, y: p.x };
            }
            self.turned = (self.turned + 1) % 4;
        }
        let m = self.ring.len() as u32;
        if m == 3 {
            self.candidate
                .push([self.ring[0], self.ring[1], self.ring[2]]);
            return;
        }
        self.ranks.compute(&self.ring_points);
        let points = PerturbedPoints::new(&self.ring_points, &self.ranks.ranks);
        self.diagonals.clear();
        self.split
            .monotone_diagonals(points, m, &mut self.diagonals);
        self.pieces.cut(m, &self.diagonals);
        let first = self.candidate.len();
        for range in &self.pieces.ranges {
            self.monotone.triangulate(
                points,
                &self.pieces.corners[range.clone()],
                &mut self.candidate,
            );
        }
        let ring = &self.ring;
        for t in &mut self.candidate[first..] {
            *t = t.map(|k| ring[k as usize]);
        }
    }
}

/// Triangulates one polygon: local corner triangles and what happened.
pub fn triangulate_polygon(corners: &[[f64; 3]]) -> (Vec<[u32; 3]>, PolygonOutcome) {
    let mut triangles = Vec::with_capacity(corners.len().saturating_sub(2));
    let outcome = PolygonTriangulator::new().triangulate(corners, &mut triangles);
    (triangles, outcome)
}

/// Fan from the first corner of `ring`.
fn push_fan(ring: impl Iterator<Item = u32>, out: &mut Vec<[u32; 3]>) {
    let mut ring = ring;
    let Some(apex) = ring.next() else { return };
    let Some(mut last) = ring.next() else { return };
    for corner in ring {
        out.push([apex, last, corner]);
        last = corner;
    }
}

/// Twice the signed area of a triangle of projected corners (exact sign).
fn orient(points: &[Coord<f64>], [a, b, c]: [u32; 3]) -> f64 {
    orient2d(points[a as usize], points[b as usize], points[c as usize])
}

/// Twice the area of the inverted triangles of `triangles`.
fn inverted_area(points: &[Coord<f64>], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|&t| (-orient(points, t)).max(0.0))
        .sum()
}
