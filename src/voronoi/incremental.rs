//! Incremental Bowyer–Watson construction with a vertex at infinity ("ghost" triangles).
//!
//! Every hull edge `b → a` of a real triangle is paired with a ghost triangle `(a, b, ∞)`, so
//! every half-edge has a twin and insertion outside the hull is the same operation as inside:
//! find one triangle in conflict with the new site (walking from the last one created), grow the
//! conflict region through its neighbours, and re-triangulate the cavity as a fan around the site.
//! A real triangle conflicts with `p` when `p` is strictly inside its circumcircle (exact
//! in-circle test); a ghost `(a, b, ∞)` conflicts when `p` is strictly left of `a → b` (outside
//! the hull), or on that line strictly between `a` and `b`. Cocircular sites are therefore never in
//! conflict, and the result is *a* Delaunay triangulation; the Voronoi layer merges the triangles
//! that share a circumcircle.
//!
//! Half-edge `e` is edge `e % 3` of triangle `e / 3`, running from corner `e % 3` to the next
//! corner; `next(e) = 3(e/3) + (e+1) % 3`; triangles are counter-clockwise. A ghost keeps the
//! vertex at infinity ([`GHOST`]) as its corner 2, so its finite edge is its edge 0 and one load
//! tells a ghost from a real triangle.
//!
//! Corners and twins of a triangle are stored side by side ([`Triangle`]): walking to a neighbour
//! and testing it reads one record, usually one cache line, instead of two arrays.

use super::predicates::{SetBounds, incircle_in, orient2d_in};
use crate::support::large_arrays;

/// The vertex at infinity.
pub(crate) const GHOST: u32 = u32::MAX;

/// Next half-edge of the same triangle (counter-clockwise).
#[inline(always)]
pub(crate) fn next_edge(e: u32) -> u32 {
    if e % 3 == 2 { e - 2 } else { e + 1 }
}

/// Previous half-edge of the same triangle.
#[inline(always)]
pub(crate) fn prev_edge(e: u32) -> u32 {
    if e.is_multiple_of(3) { e + 2 } else { e - 1 }
}

/// One triangle: its corners counter-clockwise and, for each edge `k` (corner `k` to corner
/// `k + 1`), the opposite half-edge.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Triangle {
    pub corners: [u32; 3],
    pub twins: [u32; 3],
}

impl Triangle {
    /// Is this a ghost (corner 2 at infinity)?
    #[inline(always)]
    pub fn is_ghost(&self) -> bool {
        self.corners[2] == GHOST
    }
}

/// A triangulation under construction (or finished), ghosts included.
pub(crate) struct GhostTriangulation<'a> {
    points: &'a [[f64; 2]],
    /// Error bounds of the predicates over `points`.
    bounds: SetBounds,
    /// Triangle `t` owns half-edges `3t..3t + 3`.
    pub triangles: Vec<Triangle>,
    last: u32,
    cavity: Vec<u32>,
    boundary: Vec<CavityEdge>,
    stack: Vec<u32>,
}

/// Where a site falls in the current triangulation.
enum Location {
    /// A triangle (real or ghost) in conflict with the site.
    Conflict(u32),
    /// The site coincides with this existing vertex.
    Duplicate(u32),
}

impl<'a> GhostTriangulation<'a> {
    /// Starts from the counter-clockwise triangle `a, b, c` (`orient2d > 0`) and its three
    /// ghosts, with room for `n_sites` vertices (`2n - 2` triangles, ghosts included).
    /// `bounds` are the predicates' error bounds over `points`.
    pub fn new(
        points: &'a [[f64; 2]],
        [a, b, c]: [u32; 3],
        n_sites: usize,
        bounds: SetBounds,
    ) -> Self {
        let mut triangles = large_arrays::with_capacity(2 * n_sites + 4);
        let triangle = |corners, twins| Triangle { corners, twins };
        triangles.extend_from_slice(&[
            triangle([a, b, c], [3, 6, 9]),      // 0: the real triangle
            triangle([b, a, GHOST], [0, 11, 7]), // 1: ghost of a→b
            triangle([c, b, GHOST], [1, 5, 10]), // 2: ghost of b→c
            triangle([a, c, GHOST], [2, 8, 4]),  // 3: ghost of c→a
        ]);
        GhostTriangulation {
            points,
            bounds,
            triangles,
            last: 0,
            cavity: Vec::new(),
            boundary: Vec::new(),
            stack: Vec::new(),
        }
    }

    #[inline(always)]
    fn point(&self, v: u32) -> [f64; 2] {
        self.points[v as usize]
    }

    /// Exact orientation of three of the points.
    #[inline(always)]
    fn orient(&self, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
        orient2d_in(a, b, c, &self.bounds)
    }

    /// The opposite of half-edge `e`.
    #[inline(always)]
    fn twin(&self, e: u32) -> u32 {
        self.triangles[(e / 3) as usize].twins[(e % 3) as usize]
    }

    /// Does ghost edge `u → v` conflict with `p` (outside the hull across it, or on its interior)?
    #[inline(always)]
    fn ghost_conflict(&self, u: u32, v: u32, p: [f64; 2]) -> bool {
        let (pu, pv) = (self.point(u), self.point(v));
        let o = self.orient(pu, pv, p);
        o > 0.0 || (o == 0.0 && strictly_between(pu, pv, p))
    }

    #[inline(always)]
    fn in_conflict(&self, t: u32, p: [f64; 2]) -> bool {
        let [a, b, c] = self.triangles[t as usize].corners;
        if c == GHOST {
            self.ghost_conflict(a, b, p)
        } else {
            let (pa, pb, pc) = (self.point(a), self.point(b), self.point(c));
            incircle_in(pa, pb, pc, p, &self.bounds) > 0.0
        }
    }

    /// Visibility walk from the last created triangle; exact orientations throughout. The edge
    /// the walk came in through is not tested again: `p` is strictly on its inner side.
    fn locate(&self, p: [f64; 2]) -> Location {
        let n_triangles = self.triangles.len();
        let mut t = self.last;
        let mut entry = 3;
        // A visibility walk in a Delaunay triangulation always terminates; the bound only turns
        // an impossible cycle into a (slow, correct) exhaustive search instead of a hang.
        let mut steps = 0usize;
        'walk: while steps <= 4 * n_triangles + 16 {
            steps += 1;
            let triangle = &self.triangles[t as usize];
            let [a, b, c] = triangle.corners;
            if c == GHOST {
                if self.ghost_conflict(a, b, p) {
                    return Location::Conflict(t);
                }
                let o = triangle.twins[0];
                (t, entry) = (o / 3, (o % 3) as usize);
                continue;
            }
            let corners = [self.point(a), self.point(b), self.point(c)];
            for k in 0..3 {
                if k != entry && self.orient(corners[k], corners[(k + 1) % 3], p) < 0.0 {
                    let o = triangle.twins[k];
                    (t, entry) = (o / 3, (o % 3) as usize);
                    continue 'walk;
                }
            }
            return self.inside_real_triangle(t, p);
        }
        self.locate_exhaustively(p)
    }

    /// `p` lies in the closed real triangle `t`: a duplicate of one of its corners or in conflict.
    fn inside_real_triangle(&self, t: u32, p: [f64; 2]) -> Location {
        for v in self.triangles[t as usize].corners {
            if self.point(v) == p {
                return Location::Duplicate(v);
            }
        }
        Location::Conflict(t)
    }

    fn locate_exhaustively(&self, p: [f64; 2]) -> Location {
        for (t, triangle) in (0..).zip(&self.triangles) {
            if triangle.is_ghost() {
                if self.in_conflict(t, p) {
                    return Location::Conflict(t);
                }
                continue;
            }
            let corners = triangle.corners.map(|v| self.point(v));
            if (0..3).all(|k| self.orient(corners[k], corners[(k + 1) % 3], p) >= 0.0) {
                return self.inside_real_triangle(t, p);
            }
        }
        unreachable!("every point lies in a real triangle or conflicts with a ghost")
    }

    /// Inserts site `s`; returns the existing vertex it duplicates, if any.
    pub fn insert(&mut self, s: u32) -> Option<u32> {
        let p = self.point(s);
        let start = match self.locate(p) {
            Location::Duplicate(v) => return Some(v),
            Location::Conflict(t) => t,
        };
        self.cavity.clear();
        self.boundary.clear();
        self.stack.clear();
        self.cavity.push(start);
        let base = 3 * start;
        self.stack.extend_from_slice(&[base + 2, base + 1, base]);
        // Depth-first growth; visiting each triangle's edges counter-clockwise yields the cavity
        // boundary as one counter-clockwise loop (the cavity is a disk with no interior vertex).
        while let Some(e) = self.stack.pop() {
            let o = self.twin(e);
            let neighbour = o / 3;
            if self.in_conflict(neighbour, p) {
                self.cavity.push(neighbour);
                let o1 = next_edge(o);
                self.stack.push(next_edge(o1));
                self.stack.push(o1);
            } else {
                let corners = &self.triangles[(e / 3) as usize].corners;
                let k = (e % 3) as usize;
                self.boundary
                    .push(CavityEdge::new(o, corners[k], corners[(k + 1) % 3]));
            }
        }
        let k = self.boundary.len();
        debug_assert_eq!(k, self.cavity.len() + 2);
        // The fan needs two more triangles than the cavity had.
        for _ in 0..2 {
            self.cavity.push(self.triangles.len() as u32);
            self.triangles.push(Triangle::default());
        }
        if self.boundary.iter().all(|edge| edge.rotation == 0) {
            self.fill_fan::<false>(s);
        } else {
            self.fill_fan::<true>(s);
        }
        self.last = self.cavity[0];
        None
    }

    /// Re-triangulates the cavity as a fan around site `s`: fan triangle `i` is `(u, v, s)` for
    /// boundary edge `i` = `(u, v)`, stored rotated so that a vertex at infinity lands in corner
    /// 2 (its logical edge `j` is half-edge `edge(i, j)`). Without `ROTATED` no boundary edge
    /// touches the vertex at infinity, as for every site inside the hull, and the rotations
    /// compile away (10% of the insertion's instructions at 10k sites).
    #[inline(always)]
    fn fill_fan<const ROTATED: bool>(&mut self, s: u32) {
        let (cavity, boundary) = (&self.cavity, &self.boundary);
        let k = boundary.len();
        let rotation = |i: usize| if ROTATED { boundary[i].rotation } else { 0 };
        let edge = |i: usize, j: u32| 3 * cavity[i] + add_mod3(j, rotation(i));
        for i in 0..k {
            let CavityEdge {
                outside, from, to, ..
            } = boundary[i];
            debug_assert_eq!(
                to,
                boundary[(i + 1) % k].from,
                "cavity boundary is one loop"
            );
            let next = if i + 1 == k { 0 } else { i + 1 };
            let prev = if i == 0 { k - 1 } else { i - 1 };
            self.triangles[cavity[i] as usize] = Triangle {
                corners: rotated([from, to, s], rotation(i)),
                twins: rotated([outside, edge(next, 2), edge(prev, 1)], rotation(i)),
            };
            self.triangles[(outside / 3) as usize].twins[(outside % 3) as usize] = edge(i, 0);
        }
    }
}

/// An edge of the cavity's boundary, `from → to` counter-clockwise, and the half-edge `outside`
/// across it; `rotation` places the fan triangle `(from, to, new site)` built on it so that a
/// vertex at infinity lands in corner 2 (see [`rotated`]).
#[derive(Clone, Copy, Debug)]
struct CavityEdge {
    outside: u32,
    from: u32,
    to: u32,
    rotation: u32,
}

impl CavityEdge {
    #[inline(always)]
    fn new(outside: u32, from: u32, to: u32) -> Self {
        let rotation = if from == GHOST {
            2
        } else if to == GHOST {
            1
        } else {
            0
        };
        CavityEdge {
            outside,
            from,
            to,
            rotation,
        }
    }
}

/// `items` with item `j` moved to slot `(j + rotation) mod 3`.
#[inline(always)]
fn rotated(items: [u32; 3], rotation: u32) -> [u32; 3] {
    let [a, b, c] = items;
    match rotation {
        0 => [a, b, c],
        1 => [c, a, b],
        _ => [b, c, a],
    }
}

/// `(j + r) mod 3` for `j, r < 3`, without a division.
#[inline(always)]
fn add_mod3(j: u32, r: u32) -> u32 {
    let x = j + r;
    if x >= 3 { x - 3 } else { x }
}

/// `p`, collinear with `a` and `b`, lies strictly between them (exact: compares coordinates).
#[inline]
pub(crate) fn strictly_between(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    let axis = if a[0] != b[0] { 0 } else { 1 };
    (a[axis] < p[axis] && p[axis] < b[axis]) || (b[axis] < p[axis] && p[axis] < a[axis])
}
