//! Triangulating a polygon monotone in the sweep direction in linear time (Garey, Johnson,
//! Preparata and Tarjan; de Berg et al., *Computational Geometry*, ch. 3): its two chains from
//! the top corner to the bottom one are merged in sweep order, and each corner cuts off the
//! triangles it sees of the chain of waiting corners kept on a stack.
//!
//! Every triangle cut off is an ear of what is left, whatever the geometric tests answer, so a
//! piece that is not monotone after all (the polygon crosses itself) still gets a triangulation
//! of its `k` corners into `k − 2` triangles, some of them inverted.

use super::perturbed::PerturbedPoints;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Chain {
    /// From the top corner forward (counter-clockwise) to the bottom one: the west chain.
    Forward,
    /// From the top corner backward to the bottom one: the east chain.
    Backward,
}

/// Scratch buffers for [`MonotoneTriangulator::triangulate`].
#[derive(Debug, Default)]
pub(super) struct MonotoneTriangulator {
    merged: Vec<(u32, Chain)>,
    stack: Vec<(u32, Chain)>,
}

impl MonotoneTriangulator {
    /// Appends the triangles of the piece `corners` (corners of `points`, in increasing order
    /// round the piece, at least 3) to `out`, each as its corners in increasing order.
    pub(super) fn triangulate(
        &mut self,
        points: PerturbedPoints<'_>,
        corners: &[u32],
        out: &mut Vec<[u32; 3]>,
    ) {
        let k = corners.len();
        let mut emit = |a: u32, b: u32, c: u32| {
            let mut t = [a, b, c];
            t.sort_unstable();
            out.push(t);
        };
        if k == 3 {
            emit(corners[0], corners[1], corners[2]);
            return;
        }
        let at = |i: usize| corners[i % k];
        let order = |i: &usize, j: &usize| points.sweep_order(at(*i), at(*j));
        let top = (0..k).min_by(order).expect("k ≥ 3");
        let bottom = (0..k).max_by(order).expect("k ≥ 3");

        // Merge the two chains (top and bottom excluded) in sweep order; each keeps its own
        // order whatever the comparisons say, which is all the ear cutting below relies on.
        self.merged.clear();
        self.merged.push((at(top), Chain::Forward));
        let forward_len = (bottom + k - top) % k - 1;
        let backward_len = k - 2 - forward_len;
        let (mut f, mut b) = (0, 0);
        while f < forward_len || b < backward_len {
            let forward = at(top + 1 + f);
            let backward = at(top + k - 1 - b);
            let take_forward =
                b == backward_len || (f < forward_len && points.above(forward, backward));
            if take_forward {
                self.merged.push((forward, Chain::Forward));
                f += 1;
            } else {
                self.merged.push((backward, Chain::Backward));
                b += 1;
            }
        }
        self.merged.push((at(bottom), Chain::Forward));

        self.stack.clear();
        self.stack.extend_from_slice(&self.merged[..2]);
        for j in 2..k - 1 {
            let (u, chain) = self.merged[j];
            let &(top_corner, top_chain) = self.stack.last().expect("two corners");
            if chain != top_chain {
                // `u` is next to the bottom of the stack: it sees the whole chain.
                for pair in self.stack.windows(2) {
                    emit(u, pair[0].0, pair[1].0);
                }
                self.stack.clear();
                self.stack.push((top_corner, top_chain));
            } else {
                // `u` is next to the top: cut off the corners it sees round a convex turn.
                let mut last = self.stack.pop().expect("two corners");
                while let Some(&before) = self.stack.last() {
                    let convex = match chain {
                        Chain::Forward => is_convex(points, before.0, last.0, u),
                        Chain::Backward => is_convex(points, u, last.0, before.0),
                    };
                    if !convex {
                        break;
                    }
                    emit(u, last.0, before.0);
                    last = self.stack.pop().expect("just looked at");
                }
                self.stack.push(last);
            }
            self.stack.push((u, chain));
        }
        let bottom_corner = self.merged[k - 1].0;
        for pair in self.stack.windows(2) {
            emit(bottom_corner, pair[0].0, pair[1].0);
        }
    }
}

/// Whether the turn `a → b → c` (in the polygon's order) is convex, so that the triangle `abc`
/// can be cut off. A corner in the middle of a straight side is kept, so that it ends up in
/// proper triangles rather than in one of no area (a T-junction crack); keeping it changes no
/// later decision, since the turns beside it are those of the side. Other collinear turns — a
/// spike's tip, repeated places — are decided by the perturbation, like the sweep decided them.
fn is_convex(points: PerturbedPoints<'_>, a: u32, b: u32, c: u32) -> bool {
    let turn = points.exact_orient(a, b, c);
    if turn != 0.0 {
        turn > 0.0
    } else {
        !points.is_straight(a, b, c) && points.ccw(a, b, c)
    }
}
