//! Ranking the corners for the perturbation so that where the polygon touches itself at one
//! place (several corners there, as in a repaired face that named a vertex twice), the perturbed
//! copy pulls the touching parts apart instead of across each other.
//!
//! The perturbation moves a corner of lower rank further along `(1, δ)`, δ infinitesimal, so
//! the corners at one place end up in a row, in rank order from east to west. Each has two
//! arms, its sides to its neighbours. Of two arms pointing into the upper half-plane (as seen
//! from that row), one from a corner east of the other, they cross exactly when the eastern
//! one points further west (its angle counter-clockwise from east is larger); likewise below,
//! with angles clockwise from east; an arm above never meets one below. So a corner may go east
//! of another when its arms above span angles no larger than the other's, and its arms below
//! too. Where the polygon only touches itself, its paths through the place do not interleave
//! round it, so the spans of the corners on each side follow one another, and merging the two
//! sides' orders gives a row that separates them. Where no row does (a path lying in the notch
//! of another, or paths that cross), the order is still total, only not separating.

use std::cmp::Ordering;

use robust::{Coord, orient2d};

/// The arms of one corner at a place shared with other corners: on each side, the neighbours
/// its arms point to, first the one nearer east (counter-clockwise from east above, clockwise
/// below); the same neighbour twice for one arm, none for no arm.
#[derive(Clone, Copy, Debug)]
struct Arms {
    corner: u32,
    above: Option<(Coord<f64>, Coord<f64>)>,
    below: Option<(Coord<f64>, Coord<f64>)>,
}

/// Scratch buffers for [`PerturbationRanks::compute`].
#[derive(Debug, Default)]
pub(super) struct PerturbationRanks {
    order: Vec<u32>,
    arms: Vec<Arms>,
    /// Indices into `arms` of the corners with arms above, and below, each east to west.
    above: Vec<u32>,
    below: Vec<u32>,
    placed: Vec<bool>,
    row: Vec<u32>,
    /// The rank of every corner.
    pub(super) ranks: Vec<u32>,
}

impl PerturbationRanks {
    /// Ranks the corners of the ring `points` (no side of zero length): by place (x, then y)
    /// and, at one place, east to west as the module docs say. O(n log n).
    pub(super) fn compute(&mut self, points: &[Coord<f64>]) {
        let n = points.len();
        let place = |i: u32| points[i as usize];
        self.order.clear();
        self.order.extend(0..n as u32);
        self.order.sort_unstable_by(|&a, &b| {
            let (pa, pb) = (place(a), place(b));
            pa.x.partial_cmp(&pb.x)
                .unwrap_or(Ordering::Equal)
                .then(pa.y.partial_cmp(&pb.y).unwrap_or(Ordering::Equal))
                .then(a.cmp(&b))
        });
        self.placed.clear();
        self.placed.resize(n, false);
        let mut start = 0;
        while start < n {
            let here = place(self.order[start]);
            let len = self.order[start..]
                .iter()
                .take_while(|&&i| place(i).x == here.x && place(i).y == here.y)
                .count();
            if len > 1 {
                self.order_east_to_west(points, start..start + len);
            }
            start += len;
        }
        self.ranks.clear();
        self.ranks.resize(n, 0);
        for (rank, &i) in self.order.iter().enumerate() {
            self.ranks[i as usize] = rank as u32;
        }
    }

    /// Reorders the corners `self.order[run]`, all at one place, from east to west.
    fn order_east_to_west(&mut self, points: &[Coord<f64>], run: std::ops::Range<usize>) {
        let n = points.len() as u32;
        let apex = points[self.order[run.start] as usize];
        let ccw = |p: Coord<f64>, q: Coord<f64>| {
            0.0.partial_cmp(&orient2d(apex, p, q))
                .unwrap_or(Ordering::Equal)
        };
        let cw = |p: Coord<f64>, q: Coord<f64>| ccw(q, p);
        let span = |arms: &[Coord<f64>], from_east: &dyn Fn(_, _) -> Ordering| match *arms {
            [] => None,
            [only] => Some((only, only)),
            [a, b, ..] if from_east(a, b) == Ordering::Greater => Some((b, a)),
            [a, b, ..] => Some((a, b)),
        };
        self.arms.clear();
        for &corner in &self.order[run.clone()] {
            let ends = [
                points[((corner + n - 1) % n) as usize],
                points[((corner + 1) % n) as usize],
            ];
            let (up, down): (Vec<Coord<f64>>, Vec<Coord<f64>>) =
                ends.iter().partition(|&&end| is_above(apex, end));
            self.arms.push(Arms {
                corner,
                above: span(&up, &ccw),
                below: span(&down, &cw),
            });
        }
        // Spans compare by their ends nearer east, then farther; where they are the same (two
        // sides lying on one another), by the spans on the other side.
        let by_span = |a: Option<(Coord<f64>, Coord<f64>)>,
                       b: Option<(Coord<f64>, Coord<f64>)>,
                       from_east: &dyn Fn(_, _) -> Ordering| match (a, b) {
            (Some(a), Some(b)) => from_east(a.0, b.0).then(from_east(a.1, b.1)),
            (a, b) => a.is_some().cmp(&b.is_some()),
        };
        let arms = &self.arms;
        self.above.clear();
        self.above
            .extend((0..arms.len() as u32).filter(|&k| arms[k as usize].above.is_some()));
        self.above.sort_unstable_by(|&a, &b| {
            let (a, b) = (&arms[a as usize], &arms[b as usize]);
            by_span(a.above, b.above, &ccw)
                .then_with(|| by_span(a.below, b.below, &cw))
                .then(a.corner.cmp(&b.corner))
        });
        self.below.clear();
        self.below
            .extend((0..arms.len() as u32).filter(|&k| arms[k as usize].below.is_some()));
        self.below.sort_unstable_by(|&a, &b| {
            let (a, b) = (&arms[a as usize], &arms[b as usize]);
            by_span(a.below, b.below, &cw)
                .then_with(|| by_span(a.above, b.above, &ccw))
                .then(a.corner.cmp(&b.corner))
        });

        // Merge the two sides' orders. A corner with arms on one side only goes as soon as it
        // heads that side; one with arms on both sides waits until it heads both (if two such
        // head the sides, the paths cross and either will do).
        self.row.clear();
        let (mut i, mut j) = (0, 0);
        loop {
            let placed = |k: u32| self.placed[arms[k as usize].corner as usize];
            while i < self.above.len() && placed(self.above[i]) {
                i += 1;
            }
            while j < self.below.len() && placed(self.below[j]) {
                j += 1;
            }
            let both =
                |k: u32| arms[k as usize].above.is_some() && arms[k as usize].below.is_some();
            let next = match (self.above.get(i).copied(), self.below.get(j).copied()) {
                (None, None) => break,
                (Some(up), _) if !both(up) => up,
                (_, Some(down)) if !both(down) => down,
                (Some(up), _) => up,
                (None, Some(down)) => down,
            };
            let corner = arms[next as usize].corner;
            self.placed[corner as usize] = true;
            self.row.push(corner);
        }
        self.order[run].copy_from_slice(&self.row);
    }
}

/// `true` when the direction from `apex` to `towards` lies in the upper half-plane as seen from
/// `(1, δ)`: above, or level and to the west.
fn is_above(apex: Coord<f64>, towards: Coord<f64>) -> bool {
    towards.y > apex.y || (towards.y == apex.y && towards.x < apex.x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ranks(xy: &[[f64; 2]]) -> Vec<u32> {
        let points: Vec<Coord<f64>> = xy.iter().map(|p| Coord { x: p[0], y: p[1] }).collect();
        let mut ranks = PerturbationRanks::default();
        ranks.compute(&points);
        ranks.ranks
    }

    #[test]
    fn the_two_sides_of_a_slit_are_ranked_apart() {
        // A square with a square hole joined to its bottom side by a slit at x = 8: the slit's
        // ends, (8, 0) and (8, 8), are each visited twice. Going down the slit, corners 1 and 2
        // lie on its east side; coming up, corners 14 and 15 on its west side.
        let r = ranks(&[
            [11.0, 8.0],
            [8.0, 8.0],
            [8.0, 0.0],
            [40.0, 0.0],
            [40.0, 40.0],
            [0.0, 40.0],
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 11.0],
            [2.0, 14.0],
            [5.0, 14.0],
            [5.0, 11.0],
            [2.0, 11.0],
            [2.0, 0.0],
            [8.0, 0.0],
            [8.0, 8.0],
            [8.0, 11.0],
            [11.0, 11.0],
        ]);
        assert!(r[2] < r[14] && r[1] < r[15], "{r:?}");
        // The second slit, at x = 2: down on the east side (12, 13), up on the west (7, 8).
        assert!(r[13] < r[7] && r[12] < r[8], "{r:?}");
        // Places in order of x, then y.
        assert!(r[6] < r[7] && r[5] < r[7] && r[7] < r[8] && r[16] < r[17] && r[0] < r[17]);
    }
}
