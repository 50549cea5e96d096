//! Diagonals that cut a counter-clockwise polygon into pieces monotone in the sweep direction
//! (Lee and Preparata's plane sweep, as in de Berg et al., *Computational Geometry*, ch. 3): a
//! sweep line moves down over the corners; each corner where the boundary turns back up inside
//! the polygon (a split corner) or down (a merge corner) gets a diagonal to the last corner seen
//! in the stretch of polygon beside it. O(n log n).

use super::perturbed::PerturbedPoints;
use super::sweep_status::SweepStatus;

/// What the boundary does at a corner, seen by a sweep line moving down.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CornerKind {
    /// Both neighbours below, convex: a piece begins.
    Start,
    /// Both neighbours below, reflex: the polygon below divides.
    Split,
    /// Both neighbours above, convex: a piece ends.
    End,
    /// Both neighbours above, reflex: two parts of the polygon join.
    Merge,
    /// The previous neighbour above, the next below: the polygon is east of the corner.
    WestSide,
    /// The previous neighbour below, the next above: the polygon is west of the corner.
    EastSide,
}

/// Scratch buffers for [`monotone_diagonals`].
#[derive(Debug, Default)]
pub(super) struct MonotoneSplit {
    order: Vec<u32>,
    kind: Vec<CornerKind>,
    /// Per status edge (named by its upper corner): the lowest corner seen so far in the stretch
    /// of polygon east of it.
    helper: Vec<u32>,
    status: SweepStatus,
}

impl MonotoneSplit {
    /// Appends to `diagonals` the pairs of corners (of the ring `0..n`, counter-clockwise about
    /// `points`) that cut it into monotone pieces. When the polygon crosses itself the pairs are
    /// still corners of the ring, but may cross or repeat sides; the caller keeps those it can use.
    pub(super) fn monotone_diagonals(
        &mut self,
        points: PerturbedPoints<'_>,
        n: u32,
        diagonals: &mut Vec<(u32, u32)>,
    ) {
        let prev = |v: u32| if v == 0 { n - 1 } else { v - 1 };
        let next = |v: u32| if v + 1 == n { 0 } else { v + 1 };
        self.order.clear();
        self.order.extend(0..n);
        self.order
            .sort_unstable_by(|&a, &b| points.sweep_order(a, b));
        self.kind.clear();
        self.kind.extend((0..n).map(|v| {
            let (p, q) = (prev(v), next(v));
            match (points.above(v, p), points.above(v, q)) {
                (true, true) if points.ccw(p, v, q) => CornerKind::Start,
                (true, true) => CornerKind::Split,
                (false, false) if points.ccw(p, v, q) => CornerKind::End,
                (false, false) => CornerKind::Merge,
                (false, true) => CornerKind::WestSide,
                (true, false) => CornerKind::EastSide,
            }
        }));
        self.helper.clear();
        self.helper.resize(n as usize, 0);
        self.status.reset(n as usize);

        for k in 0..n as usize {
            let v = self.order[k];
            // The status edge from `e` down to `next(e)` lies west of `v`.
            let is_west = |e: u32| points.ccw(e, next(e), v);
            match self.kind[v as usize] {
                CornerKind::Start => {
                    let after = self.status.last_west_of(is_west);
                    self.insert(after, v);
                }
                CornerKind::Split => {
                    let after = self.status.last_west_of(is_west);
                    if let Some(west) = after {
                        diagonals.push((v, self.helper[west as usize]));
                        self.helper[west as usize] = v;
                    }
                    self.insert(after, v);
                }
                CornerKind::End => self.close(prev(v), v, diagonals),
                CornerKind::Merge => {
                    self.close(prev(v), v, diagonals);
                    if let Some(west) = self.status.last_west_of(is_west) {
                        self.join_merge_helper(west, v, diagonals);
                        self.helper[west as usize] = v;
                    }
                }
                CornerKind::WestSide => {
                    self.close(prev(v), v, diagonals);
                    let after = self.status.last_west_of(is_west);
                    self.insert(after, v);
                }
                CornerKind::EastSide => {
                    if let Some(west) = self.status.last_west_of(is_west) {
                        self.join_merge_helper(west, v, diagonals);
                        self.helper[west as usize] = v;
                    }
                }
            }
        }
    }

    /// Puts the edge below `v` in the status, east of `after`, with `v` as its helper.
    fn insert(&mut self, after: Option<u32>, v: u32) {
        self.status.insert_after(after, v);
        self.helper[v as usize] = v;
    }

    /// The edge from `upper` down to `v` leaves the status at `v`, joining a merge corner still
    /// waiting east of it.
    fn close(&mut self, upper: u32, v: u32, diagonals: &mut Vec<(u32, u32)>) {
        self.join_merge_helper(upper, v, diagonals);
        self.status.remove(upper);
    }

    /// A merge corner helping `edge` gets its diagonal down to `v`.
    fn join_merge_helper(&self, edge: u32, v: u32, diagonals: &mut Vec<(u32, u32)>) {
        let helper = self.helper[edge as usize];
        if self.kind[helper as usize] == CornerKind::Merge {
            diagonals.push((v, helper));
        }
    }
}
