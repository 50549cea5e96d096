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
//! Half-edge `e` belongs to triangle `e / 3`; `next(e) = 3(e/3) + (e+1) % 3`; triangles are
//! counter-clockwise; `origin[e]` is the start vertex, [`GHOST`] for the vertex at infinity.

use super::predicates::{incircle, orient2d};

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
    if e % 3 == 0 { e + 2 } else { e - 1 }
}

/// A triangulation under construction (or finished), ghosts included.
pub(crate) struct GhostTriangulation<'a> {
    points: &'a [[f64; 2]],
    /// Start vertex of each half-edge.
    pub origin: Vec<u32>,
    /// Opposite half-edge of each half-edge.
    pub twin: Vec<u32>,
    last: u32,
    cavity: Vec<u32>,
    boundary: Vec<(u32, u32, u32)>,
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
    /// Starts from the counter-clockwise triangle `a, b, c` (`orient2d > 0`) and its three ghosts.
    pub fn new(points: &'a [[f64; 2]], a: u32, b: u32, c: u32, capacity: usize) -> Self {
        let mut tri = GhostTriangulation {
            points,
            origin: Vec::with_capacity(capacity),
            twin: Vec::with_capacity(capacity),
            last: 0,
            cavity: Vec::new(),
            boundary: Vec::new(),
            stack: Vec::new(),
        };
        #[rustfmt::skip]
        tri.origin.extend_from_slice(&[
            a, b, c,          // 0: the real triangle
            b, a, GHOST,      // 1: ghost of a→b
            c, b, GHOST,      // 2: ghost of b→c
            a, c, GHOST,      // 3: ghost of c→a
        ]);
        tri.twin
            .extend_from_slice(&[3, 6, 9, 0, 11, 7, 1, 5, 10, 2, 8, 4]);
        tri
    }

    #[inline(always)]
    fn point(&self, v: u32) -> [f64; 2] {
        self.points[v as usize]
    }

    /// The finite edge `(u, v)` of ghost triangle `t` (the ghost lies left of `u → v`), or `None`
    /// for a real triangle.
    #[inline(always)]
    fn ghost_edge(&self, t: u32) -> Option<u32> {
        let base = 3 * t;
        let o = &self.origin[base as usize..base as usize + 3];
        if o[2] == GHOST {
            Some(base)
        } else if o[0] == GHOST {
            Some(base + 1)
        } else if o[1] == GHOST {
            Some(base + 2)
        } else {
            None
        }
    }

    /// Does ghost edge `u → v` conflict with `p` (outside the hull across it, or on its interior)?
    #[inline(always)]
    fn ghost_conflict(&self, u: u32, v: u32, p: [f64; 2]) -> bool {
        let (pu, pv) = (self.point(u), self.point(v));
        let o = orient2d(pu, pv, p);
        o > 0.0 || (o == 0.0 && strictly_between(pu, pv, p))
    }

    #[inline(always)]
    fn in_conflict(&self, t: u32, p: [f64; 2]) -> bool {
        match self.ghost_edge(t) {
            Some(e) => self.ghost_conflict(
                self.origin[e as usize],
                self.origin[next_edge(e) as usize],
                p,
            ),
            None => {
                let base = 3 * t as usize;
                let o = &self.origin[base..base + 3];
                incircle(self.point(o[0]), self.point(o[1]), self.point(o[2]), p) > 0.0
            }
        }
    }

    /// Visibility walk from the last created triangle; exact orientations throughout.
    fn locate(&self, p: [f64; 2]) -> Location {
        let n_triangles = self.origin.len() / 3;
        let mut t = self.last;
        // A visibility walk in a Delaunay triangulation always terminates; the bound only turns
        // an impossible cycle into a (slow, correct) exhaustive search instead of a hang.
        let mut steps = 0usize;
        'walk: while steps <= 4 * n_triangles + 16 {
            steps += 1;
            if let Some(e) = self.ghost_edge(t) {
                let (u, v) = (self.origin[e as usize], self.origin[next_edge(e) as usize]);
                if self.ghost_conflict(u, v, p) {
                    return Location::Conflict(t);
                }
                t = self.twin[e as usize] / 3;
                continue;
            }
            let base = 3 * t;
            for e in base..base + 3 {
                let (u, v) = (self.origin[e as usize], self.origin[next_edge(e) as usize]);
                if orient2d(self.point(u), self.point(v), p) < 0.0 {
                    t = self.twin[e as usize] / 3;
                    continue 'walk;
                }
            }
            return self.inside_real_triangle(t, p);
        }
        self.locate_exhaustively(p)
    }

    /// `p` lies in the closed real triangle `t`: a duplicate of one of its corners or in conflict.
    fn inside_real_triangle(&self, t: u32, p: [f64; 2]) -> Location {
        let base = 3 * t as usize;
        for &v in &self.origin[base..base + 3] {
            if self.point(v) == p {
                return Location::Duplicate(v);
            }
        }
        Location::Conflict(t)
    }

    fn locate_exhaustively(&self, p: [f64; 2]) -> Location {
        let n_triangles = (self.origin.len() / 3) as u32;
        for t in 0..n_triangles {
            match self.ghost_edge(t) {
                Some(_) => {
                    if self.in_conflict(t, p) {
                        return Location::Conflict(t);
                    }
                }
                None => {
                    let base = 3 * t;
                    let inside = (base..base + 3).all(|e| {
                        let (u, v) = (self.origin[e as usize], self.origin[next_edge(e) as usize]);
                        orient2d(self.point(u), self.point(v), p) >= 0.0
                    });
                    if inside {
                        return self.inside_real_triangle(t, p);
                    }
                }
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
            let o = self.twin[e as usize];
            let neighbour = o / 3;
            if self.in_conflict(neighbour, p) {
                self.cavity.push(neighbour);
                let o1 = next_edge(o);
                self.stack.push(next_edge(o1));
                self.stack.push(o1);
            } else {
                let u = self.origin[e as usize];
                let v = self.origin[next_edge(e) as usize];
                self.boundary.push((o, u, v));
            }
        }
        let k = self.boundary.len();
        debug_assert_eq!(k, self.cavity.len() + 2);
        // The fan needs two more triangles than the cavity had.
        for _ in 0..2 {
            self.cavity.push((self.origin.len() / 3) as u32);
            self.origin.extend_from_slice(&[0, 0, 0]);
            self.twin.extend_from_slice(&[0, 0, 0]);
        }
        for i in 0..k {
            let t = self.cavity[i];
            let (o, u, v) = self.boundary[i];
            debug_assert_eq!(
                v,
                self.boundary[(i + 1) % k].1,
                "cavity boundary is one loop"
            );
            let next_t = self.cavity[if i + 1 == k { 0 } else { i + 1 }];
            let prev_t = self.cavity[if i == 0 { k - 1 } else { i - 1 }];
            let b = 3 * t as usize;
            self.origin[b] = u;
            self.origin[b + 1] = v;
            self.origin[b + 2] = s;
            self.twin[b] = o;
            self.twin[o as usize] = b as u32;
            self.twin[b + 1] = 3 * next_t + 2;
            self.twin[b + 2] = 3 * prev_t + 1;
        }
        self.last = self.cavity[0];
        None
    }
}

/// `p`, collinear with `a` and `b`, lies strictly between them (exact: compares coordinates).
#[inline]
pub(crate) fn strictly_between(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    let axis = if a[0] != b[0] { 0 } else { 1 };
    (a[axis] < p[axis] && p[axis] < b[axis]) || (b[axis] < p[axis] && p[axis] < a[axis])
}
