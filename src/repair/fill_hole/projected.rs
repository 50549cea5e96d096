//! Triangulating a long hole in O(n log n): its ring of corners is projected onto its best-fit
//! plane (across its Newell normal) and triangulated there by the crate's polygon sweep; when
//! the projection is a simple polygon no triangle is inverted in it, so none faces against the
//! others. Edge flips then bring the triangles closer to the surface a non-planar hole spans.

use std::collections::HashMap;

use robust::{Coord, orient2d};

use super::geometry::{cross, dot, sub, triangle_normal, unit};
use super::turns::Turns;
use crate::geom::{PolygonOutcome, PolygonTriangulator, newell_vector};
use crate::mesh::{JoinedCorners, chords_of};

/// Flips tried per corner at most: each flip lowers the largest turn ([`Turns`]) of the two
/// triangles (their tilts, the angle between them, their angles to their four neighbours), and
/// the cap keeps the pass linear.
const FLIPS_PER_CORNER: usize = 8;

/// Why the projection cannot be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ProjectionRefusal {
    /// The ring has no area (Newell vector zero or not finite).
    NoPlane,
    /// The projected ring crosses or touches itself.
    NotSimple,
    /// Every triangulation tried needs a diagonal joining two vertices an edge joins already.
    Joined,
}

/// The triangles (corner indices, in the ring's winding) of the ring `points`, or why none.
pub(super) fn projected_triangles(
    points: &[[f64; 3]],
    rim_normals: &[[f64; 3]],
    joined: &JoinedCorners,
) -> Result<Vec<[u32; 3]>, ProjectionRefusal> {
    let n = points.len();
    let normal = unit(newell_vector(points.iter().copied()));
    let turns = Turns::new(normal);
    if normal == [0.0; 3] {
        return Err(ProjectionRefusal::NoPlane);
    }
    // An orthonormal frame (u, v, normal): the projected ring winds counter-clockwise.
    let helper = if normal[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = unit(cross(helper, normal));
    let v = cross(normal, u);
    let origin = points[0];
    let flat: Vec<[f64; 3]> = points
        .iter()
        .map(|&p| {
            let d = sub(p, origin);
            [dot(d, u), dot(d, v), 0.0]
        })
        .collect();
    let mut triangles = Vec::with_capacity(n - 2);
    let mut chords = Vec::with_capacity(n - 3);
    let outcome = PolygonTriangulator::new().triangulate_choosing(
        &flat,
        &joined.free_corners(2),
        &mut triangles,
        |candidate| {
            chords_of(candidate, n as u32, &mut chords);
            joined.allows(&chords)
        },
    );
    match outcome {
        None => return Err(ProjectionRefusal::Joined),
        Some(PolygonOutcome::Exact) => {}
        Some(_) => return Err(ProjectionRefusal::NotSimple),
    }
    // The sweep (a fan, for a convex projection) puts its thin ears wherever its start falls;
    // a strip puts two where the ring bends least out of the mean plane. Tilts equal up to
    // rounding (a planar hole's are all zero) go to the triangles with the smaller boxes.
    let rank = |triangles: &[[u32; 3]]| {
        let tilt = triangles
            .iter()
            .map(|t| turns.tilt(triangle_normal_at(points, *t)))
            .fold(0.0, f64::max);
        (tilt, box_spread(points, triangles))
    };
    let mut best = rank(&triangles);
    for start in (0..STRIP_STARTS).map(|k| (k * n / STRIP_STARTS) as u32) {
        let strip = strip_triangles(n as u32, start);
        let candidate = rank(&strip);
        let better = candidate.0 < best.0 - TILT_TIE
            || (candidate.0 <= best.0 + TILT_TIE && candidate.1 < best.1);
        if better && is_proper_in_projection(points, &flat, &strip) && {
            chords_of(&strip, n as u32, &mut chords);
            joined.allows(&chords)
        } {
            (triangles, best) = (strip, candidate);
        }
    }
    Flips::new(points, &flat, rim_normals, turns, triangles).run(joined)
}

/// Corners at which [`projected_triangles`] tries a strip, evenly spread round the ring.
const STRIP_STARTS: usize = 16;

/// Largest tilts (radians) closer than this are equal for [`projected_triangles`]: rounding
/// leaves a planar hole's triangles tilted by about 1e-8.
const TILT_TIE: f64 = 1e-6;

/// The sum over `triangles` of the area of the largest side of each one's bounding box. The
/// crossing test meets every face whose box a new triangle's box overlaps: a fan over a convex
/// ring has triangles whose boxes hold O(n) of its corners, a strip's hold O(1), and the sums
/// tell them apart (O(n) times the ring's area against O(1) times it).
fn box_spread(points: &[[f64; 3]], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let corners = t.map(|k| points[k as usize]);
            let mut extents = [0, 1, 2].map(|axis| {
                let (lo, hi) = corners
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                        (lo.min(p[axis]), hi.max(p[axis]))
                    });
                hi - lo
            });
            extents.sort_unstable_by(f64::total_cmp);
            extents[1] * extents[2]
        })
        .sum()
}

/// The zigzag strip over a ring of `n` corners from corner `start`: an ear there, then
/// triangles alternately on either side until the strip closes opposite (the other ear). In the
/// ring's winding.
fn strip_triangles(n: u32, start: u32) -> Vec<[u32; 3]> {
    let next = |k: u32| (k + 1) % n;
    let previous = |k: u32| (k + n - 1) % n;
    let (mut a, mut b) = (next(start), previous(start));
    let mut triangles = Vec::with_capacity(n as usize - 2);
    triangles.push([start, a, b]);
    while next(a) != b {
        triangles.push([a, next(a), b]);
        a = next(a);
        if next(a) == b {
            break;
        }
        triangles.push([previous(b), b, a]);
        b = previous(b);
    }
    triangles
}

/// The unit normal of triangle `t` of `points`.
fn triangle_normal_at(points: &[[f64; 3]], t: [u32; 3]) -> [f64; 3] {
    let [a, b, c] = t.map(|k| points[k as usize]);
    triangle_normal(a, b, c).0
}

/// Whether every triangle is counter-clockwise in the projection `flat` and not degenerate: a
/// triangulation of a ring whose projection is simple then covers it once.
fn is_proper_in_projection(points: &[[f64; 3]], flat: &[[f64; 3]], triangles: &[[u32; 3]]) -> bool {
    let coord = |k: u32| Coord {
        x: flat[k as usize][0],
        y: flat[k as usize][1],
    };
    triangles.iter().all(|&[a, b, c]| {
        orient2d(coord(a), coord(b), coord(c)) > 0.0
            && !super::folds::is_degenerate(
                points[a as usize],
                points[b as usize],
                points[c as usize],
            )
    })
}

/// A triangulation of the ring being improved by flips.
struct Flips<'a> {
    points: &'a [[f64; 3]],
    flat: &'a [[f64; 3]],
    rim_normals: &'a [[f64; 3]],
    turns: Turns,
    triangles: Vec<[u32; 3]>,
    normals: Vec<[f64; 3]>,
    /// Directed side `(u, v)` → the triangle holding it.
    sides: HashMap<(u32, u32), usize>,
}

impl<'a> Flips<'a> {
    fn new(
        points: &'a [[f64; 3]],
        flat: &'a [[f64; 3]],
        rim_normals: &'a [[f64; 3]],
        turns: Turns,
        triangles: Vec<[u32; 3]>,
    ) -> Self {
        let mut sides = HashMap::with_capacity(3 * triangles.len());
        let mut normals = Vec::with_capacity(triangles.len());
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                sides.insert((tri[k], tri[(k + 1) % 3]), t);
            }
            normals.push(
                triangle_normal(
                    points[tri[0] as usize],
                    points[tri[1] as usize],
                    points[tri[2] as usize],
                )
                .0,
            );
        }
        Flips {
            points,
            flat,
            rim_normals,
            turns,
            triangles,
            normals,
            sides,
        }
    }

    fn is_rim_side(&self, a: u32, b: u32) -> bool {
        let n = self.points.len() as u32;
        b == (a + 1) % n
    }

    /// The largest turn of a triangle with unit normal `normal` whose other sides are `sides`:
    /// its tilt, and its turn to the faces across those sides (the rim face or the triangle
    /// holding the side the other way round).
    fn worst(&self, normal: [f64; 3], sides: [(u32, u32); 2]) -> f64 {
        sides
            .iter()
            .map(|&(a, b)| {
                if self.is_rim_side(a, b) {
                    self.turns.rim(normal, self.rim_normals[a as usize])
                } else {
                    self.turns
                        .between(normal, self.normals[self.sides[&(b, a)]])
                }
            })
            .fold(self.turns.tilt(normal), f64::max)
    }

    fn flat_orient(&self, a: u32, b: u32, c: u32) -> f64 {
        let p = |k: u32| {
            let q = self.flat[k as usize];
            Coord { x: q[0], y: q[1] }
        };
        orient2d(p(a), p(b), p(c))
    }

    /// The corner of triangle `t` after side `(a, b)`.
    fn apex(&self, t: usize, a: u32) -> u32 {
        let tri = self.triangles[t];
        let k = tri
            .iter()
            .position(|&c| c == a)
            .expect("a corner of the triangle");
        tri[(k + 2) % 3]
    }

    /// Flips the chord `(a, c)` when that keeps both triangles proper in the projection, cuts
    /// no joined vertices and lowers the largest angle around the two triangles.
    fn try_flip(&mut self, a: u32, c: u32, joined: &JoinedCorners) -> bool {
        let (Some(&t1), Some(&t2)) = (self.sides.get(&(a, c)), self.sides.get(&(c, a))) else {
            return false;
        };
        // t1 = a c b, t2 = c a d; the quad is a d c b, the new chord b d.
        let (b, d) = (self.apex(t1, a), self.apex(t2, c));
        if self.sides.contains_key(&(b, d))
            || self.sides.contains_key(&(d, b))
            || !joined.may_join(b, d)
            || self.flat_orient(a, d, b) <= 0.0
            || self.flat_orient(d, c, b) <= 0.0
        {
            return false;
        }
        let p = |k: u32| self.points[k as usize];
        let before = (self.turns.between(self.normals[t1], self.normals[t2]))
            .max(self.worst(self.normals[t1], [(c, b), (b, a)]))
            .max(self.worst(self.normals[t2], [(a, d), (d, c)]));
        let (n1, _) = triangle_normal(p(a), p(d), p(b));
        let (n2, _) = triangle_normal(p(d), p(c), p(b));
        if super::folds::is_degenerate(p(a), p(d), p(b))
            || super::folds::is_degenerate(p(d), p(c), p(b))
        {
            return false;
        }
        let after = (self.turns.between(n1, n2))
            .max(self.worst(n1, [(a, d), (b, a)]))
            .max(self.worst(n2, [(d, c), (c, b)]));
        // The largest tilt never rises: a flip that trades a bend between triangles for a
        // steeper triangle would undo the choice of ears.
        let tilts = |m1, m2| self.turns.tilt(m1).max(self.turns.tilt(m2));
        if after >= before * (1.0 - 1e-9)
            || tilts(n1, n2) > tilts(self.normals[t1], self.normals[t2])
        {
            return false;
        }
        for side in [(a, c), (c, a), (c, b), (b, a), (a, d), (d, c)] {
            self.sides.remove(&side);
        }
        self.triangles[t1] = [a, d, b];
        self.triangles[t2] = [d, c, b];
        self.normals[t1] = n1;
        self.normals[t2] = n2;
        for (t, tri) in [(t1, [a, d, b]), (t2, [d, c, b])] {
            for k in 0..3 {
                self.sides.insert((tri[k], tri[(k + 1) % 3]), t);
            }
        }
        true
    }

    fn run(mut self, joined: &JoinedCorners) -> Result<Vec<[u32; 3]>, ProjectionRefusal> {
        let mut budget = FLIPS_PER_CORNER * self.points.len();
        let mut stack: Vec<(u32, u32)> = self
            .sides
            .keys()
            .filter(|&&(a, c)| a < c && !self.is_rim_side(a, c) && !self.is_rim_side(c, a))
            .copied()
            .collect();
        stack.sort_unstable();
        while let Some((a, c)) = stack.pop() {
            if budget == 0 {
                break;
            }
            let t1 = self.sides.get(&(a, c)).copied();
            if t1.is_none() || !self.try_flip(a, c, joined) {
                continue;
            }
            budget -= 1;
            let t1 = t1.expect("checked");
            let [_, d, b] = self.triangles[t1];
            for (x, y) in [(a, d), (d, c), (c, b), (b, a)] {
                if !self.is_rim_side(x, y) && !self.is_rim_side(y, x) {
                    stack.push((x, y));
                }
            }
        }
        Ok(self.triangles)
    }
}
