//! Liepa's minimum-weight triangulation of a hole's boundary loop: among all triangulations
//! of the loop (no new vertex), the one whose largest angle between normals — of two new
//! triangles, of a new triangle and the face across a boundary side, or of a new triangle and
//! the loop's mean (Newell) normal — is smallest, ties broken by the smallest sum of angles
//! between new triangles (the least bent patch). O(n³) time and O(n²) memory for `n` corners,
//! so it serves loops up to [`super::EXACT_CORNERS_MAX`] corners only.

use super::geometry::{angle_between, triangle_normal, unit};
use crate::geom::newell_vector;

/// A triangulation's weight: the largest angle (radians) between neighbouring normals, then the
/// sum of the angles between neighbouring new triangles (how much the patch bends).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub(super) struct Weight {
    pub max_angle: f64,
    pub bend: f64,
}

impl Weight {
    const ZERO: Weight = Weight {
        max_angle: 0.0,
        bend: 0.0,
    };
    const INFINITE: Weight = Weight {
        max_angle: f64::INFINITY,
        bend: f64::INFINITY,
    };

    fn join(self, other: Weight) -> Weight {
        Weight {
            max_angle: self.max_angle.max(other.max_angle),
            bend: self.bend + other.bend,
        }
    }

    fn less(self, other: Weight) -> bool {
        self.max_angle < other.max_angle
            || (self.max_angle == other.max_angle && self.bend < other.bend)
    }
}

/// The triangles `(i, k, j)`, `i < k < j`, of the minimum-weight triangulation of the loop
/// `points` (corners in loop order), or `None` when every triangulation needs a diagonal that
/// `is_joined` says exists already (a second edge between two vertices).
///
/// `side_normals[i]` is the unit normal of the face across the side from corner `i` to
/// `i + 1` (a zero vector when unknown: the angle there is not counted).
pub(super) fn minimum_weight_triangles(
    points: &[[f64; 3]],
    side_normals: &[[f64; 3]],
    is_joined: &dyn Fn(usize, usize) -> bool,
) -> Option<Vec<[u32; 3]>> {
    let n = points.len();
    let mean_normal = unit(newell_vector(points.iter().copied()));
    let at = |i: usize, j: usize| i * n + j;
    let mut weight = vec![Weight::INFINITE; n * n];
    let mut apex = vec![usize::MAX; n * n];
    let mut normal = vec![[0.0f64; 3]; n * n];
    for i in 0..n - 1 {
        weight[at(i, i + 1)] = Weight::ZERO;
    }
    // The neighbour across a range's side: the face outside for a boundary side, otherwise the
    // triangle chosen below it.
    let below = |normal: &[[f64; 3]], i: usize, j: usize| -> Option<[f64; 3]> {
        if j == i + 1 {
            let s = side_normals[i];
            (s != [0.0; 3]).then_some(s)
        } else {
            Some(normal[at(i, j)])
        }
    };
    for span in 2..n {
        for i in 0..n - span {
            let j = i + span;
            if span < n - 1 && is_joined(i, j) {
                continue;
            }
            let mut best = Weight::INFINITE;
            let mut best_k = usize::MAX;
            let mut best_normal = [0.0; 3];
            for k in i + 1..j {
                let (left, right) = (weight[at(i, k)], weight[at(k, j)]);
                if left.max_angle == f64::INFINITY || right.max_angle == f64::INFINITY {
                    continue;
                }
                let (nt, _) = triangle_normal(points[i], points[k], points[j]);
                // Turning from the hole's mean normal counts too: it keeps ears along a
                // curved rim from standing up along the rim's bend.
                let mut angle: f64 = if mean_normal == [0.0; 3] {
                    0.0
                } else {
                    angle_between(nt, mean_normal)
                };
                let mut bend = 0.0;
                for (a, b) in [(i, k), (k, j)] {
                    if let Some(nb) = below(&normal, a, b) {
                        let turn = angle_between(nt, nb);
                        angle = angle.max(turn);
                        if b > a + 1 {
                            bend += turn;
                        }
                    }
                }
                if span == n - 1 && side_normals[n - 1] != [0.0; 3] {
                    angle = angle.max(angle_between(nt, side_normals[n - 1]));
                }
                let w = left.join(right).join(Weight {
                    max_angle: angle,
                    bend,
                });
                if w.less(best) {
                    (best, best_k, best_normal) = (w, k, nt);
                }
            }
            weight[at(i, j)] = best;
            apex[at(i, j)] = best_k;
            normal[at(i, j)] = best_normal;
        }
    }
    if apex[at(0, n - 1)] == usize::MAX {
        return None;
    }
    let mut triangles = Vec::with_capacity(n - 2);
    let mut ranges = vec![(0, n - 1)];
    while let Some((i, j)) = ranges.pop() {
        if j <= i + 1 {
            continue;
        }
        let k = apex[at(i, j)];
        triangles.push([i as u32, k as u32, j as u32]);
        ranges.push((k, j));
        ranges.push((i, k));
    }
    Some(triangles)
}
