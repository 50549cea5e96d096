//! Exact predicates on an infinitesimally perturbed copy of the projected corners (Edelsbrunner
//! and Mücke's *simulation of simplicity*): the corner of rank `r` moves by
//! `(ε^(2^2r), ε^(2^(2r+1)))`, so no two corners share a height and no three are collinear, and
//! every answer is the one that copy gives. The sweep and the monotone pieces ask only these
//! questions, so their decisions agree with one another even on repeated and collinear corners.

use std::cmp::Ordering;

use robust::{Coord, orient2d};

/// The projected corners, answered about as their perturbed copy.
#[derive(Clone, Copy)]
pub(super) struct PerturbedPoints<'a> {
    points: &'a [Coord<f64>],
    /// Each corner's rank: the lower, the larger its move.
    ranks: &'a [u32],
}

impl<'a> PerturbedPoints<'a> {
    /// The corners `points` (finite, without negative zeros), perturbed by their `ranks` (a
    /// permutation of their indices).
    pub(super) fn new(points: &'a [Coord<f64>], ranks: &'a [u32]) -> Self {
        Self { points, ranks }
    }

    fn rank(&self, i: u32) -> u32 {
        self.ranks[i as usize]
    }

    fn at(&self, i: u32) -> Coord<f64> {
        self.points[i as usize]
    }

    /// `true` when corner `a` comes before `b` in the sweep, from top to bottom: it is higher, or
    /// as high with a lower rank (the lower rank moves up more).
    pub(super) fn above(&self, a: u32, b: u32) -> bool {
        match self.at(a).y.partial_cmp(&self.at(b).y) {
            Some(Ordering::Greater) => true,
            Some(Ordering::Less) => false,
            _ => self.rank(a) < self.rank(b),
        }
    }

    /// The sweep order: `Less` when `a` is above `b`.
    pub(super) fn sweep_order(&self, a: u32, b: u32) -> Ordering {
        if a == b {
            Ordering::Equal
        } else if self.above(a, b) {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    /// Twice the signed area of the corners `a`, `b`, `c` themselves, unperturbed (exact sign).
    pub(super) fn exact_orient(&self, a: u32, b: u32, c: u32) -> f64 {
        orient2d(self.at(a), self.at(b), self.at(c))
    }

    /// `true` when `a`, `b`, `c` themselves lie on a line with `b` strictly between the other
    /// two: `b` is a corner in the middle of a straight side.
    pub(super) fn is_straight(&self, a: u32, b: u32, c: u32) -> bool {
        self.exact_orient(a, b, c) == 0.0 && lies_between(self.at(a), self.at(b), self.at(c))
    }

    /// `true` when the perturbed corners `a`, `b`, `c` (three different corners) turn
    /// counter-clockwise. Never undecided: when the exact orientation is zero, the sign is that
    /// of the first non-zero term of the perturbation's expansion.
    pub(super) fn ccw(&self, a: u32, b: u32, c: u32) -> bool {
        let exact = orient2d(self.at(a), self.at(b), self.at(c));
        if exact != 0.0 {
            return exact > 0.0;
        }
        // Sort by rank (i before j before k), counting swaps: an odd permutation flips the sign.
        let (mut i, mut j, mut k) = (a, b, c);
        let mut flipped = false;
        if self.rank(i) > self.rank(j) {
            std::mem::swap(&mut i, &mut j);
            flipped = !flipped;
        }
        if self.rank(j) > self.rank(k) {
            std::mem::swap(&mut j, &mut k);
            flipped = !flipped;
        }
        if self.rank(i) > self.rank(j) {
            std::mem::swap(&mut i, &mut j);
            flipped = !flipped;
        }
        let (pi, pj, pk) = (self.at(i), self.at(j), self.at(k));
        // det[[x, y, 1]] of (i, j, k); its coefficients in the perturbations of x_i, y_i, x_j and
        // y_i·x_j, in decreasing order of size. Signs of differences come from comparisons, so
        // they are exact.
        let positive = [
            pj.y.partial_cmp(&pk.y),
            pk.x.partial_cmp(&pj.x),
            pk.y.partial_cmp(&pi.y),
        ]
        .into_iter()
        .find(|&order| order != Some(Ordering::Equal))
            == Some(Some(Ordering::Greater));
        positive != flipped
    }
}

/// For `a`, `b`, `c` on one line: `true` when `b` lies strictly between `a` and `c`, that is,
/// when the signs of their offsets from `b` are opposite and not zero, coordinate by coordinate
/// (comparisons, so exact).
pub(super) fn lies_between(a: Coord<f64>, b: Coord<f64>, c: Coord<f64>) -> bool {
    let side = |p: Coord<f64>| (p.x.partial_cmp(&b.x), p.y.partial_cmp(&b.y));
    let reverse = |o: Option<Ordering>| o.map(Ordering::reverse);
    let (from_a, from_c) = (side(a), side(c));
    from_a != (Some(Ordering::Equal), Some(Ordering::Equal))
        && from_a == (reverse(from_c.0), reverse(from_c.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(xy: &[[f64; 2]]) -> Vec<Coord<f64>> {
        xy.iter().map(|p| Coord { x: p[0], y: p[1] }).collect()
    }

    const RANKS: [u32; 8] = [0, 1, 2, 3, 4, 5, 6, 7];

    #[test]
    fn exact_turns_are_kept_and_swapping_two_corners_flips_the_answer() {
        let p = points(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [2.0, 0.0], [0.0, 0.0]]);
        let s = PerturbedPoints::new(&p, &RANKS);
        assert!(s.ccw(0, 1, 2));
        assert!(!s.ccw(0, 2, 1));
        // Collinear (0, 1, 3) and coincident (0, 4) corners still get an answer, and every
        // permutation agrees with it.
        for (a, b, c) in [(0, 1, 3), (0, 4, 1), (4, 0, 2), (0, 4, 3)] {
            let even = [s.ccw(a, b, c), s.ccw(b, c, a), s.ccw(c, a, b)];
            let odd = [s.ccw(b, a, c), s.ccw(a, c, b), s.ccw(c, b, a)];
            assert!(even.iter().all(|&x| x == even[0]), "{a} {b} {c}");
            assert!(odd.iter().all(|&x| x != even[0]), "{a} {b} {c}");
        }
    }

    #[test]
    fn degenerate_answers_follow_the_perturbation() {
        // Corner i moves by (η_2i, η_2i+1), each η far smaller than the one before. Three
        // coincident corners 0, 1, 2: corner 0 moves most, to (η0, η1), corner 1 to (η2, η3),
        // corner 2 hardly at all; orient ≈ η0·η3 − η1·η2 < 0, since η1·η2 ≫ η0·η3.
        let p = points(&[[5.0, 5.0]; 3]);
        assert!(!PerturbedPoints::new(&p, &RANKS).ccw(0, 1, 2));
        // Collinear corners along y = 0: corner 0 rises most (by η1), so 0 → 1 → 2 bends left.
        let p = points(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]);
        let s = PerturbedPoints::new(&p, &RANKS);
        assert!(s.ccw(0, 1, 2) && !s.ccw(2, 1, 0));
        // Along x = 0: corner 0 moves right most (by η0), corner 1 by η2 ≪ η0 / 2, so corner 1
        // lies left of the chord from 0 to 2 and 0 → 1 → 2 bends right.
        let p = points(&[[0.0, 0.0], [0.0, 1.0], [0.0, 2.0]]);
        assert!(!PerturbedPoints::new(&p, &RANKS).ccw(0, 1, 2));
        // As high as each other: the lower index is above.
        let p = points(&[[0.0, 1.0], [1.0, 1.0], [0.0, 0.0]]);
        let s = PerturbedPoints::new(&p, &RANKS);
        assert!(s.above(0, 1) && !s.above(1, 0) && s.above(1, 2));
        assert_eq!(s.sweep_order(1, 0), Ordering::Greater);
    }
}
