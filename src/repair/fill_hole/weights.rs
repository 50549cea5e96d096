//! Liepa's minimum-weight triangulation of a hole's boundary loop: among all triangulations
//! of the loop (no new vertex), the one whose largest turn ([`Turns`]: a new triangle's tilt
//! from the loop's mean normal, its angle to a new triangle beside it, its angle to a face
//! across the rim beyond the mean plane's) is smallest, ties broken by the smallest sum of
//! angles between new triangles (the least bent patch). O(n³) time and O(n²) memory for `n`
//! corners, so it serves loops up to [`super::EXACT_CORNERS_MAX`] corners only.

use super::geometry::{angle_between, triangle_normal};
use super::turns::Turns;

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
/// `is_joined` says exists already (a second edge between two vertices) or a triangle that
/// `is_forbidden` rules out.
///
/// `side_normals[i]` is the unit normal of the face across the side from corner `i` to
/// `i + 1` (a zero vector when unknown: the angle there is not counted).
pub(super) fn minimum_weight_triangles(
    points: &[[f64; 3]],
    side_normals: &[[f64; 3]],
    turns: &Turns,
    is_joined: &dyn Fn(usize, usize) -> bool,
    is_forbidden: &dyn Fn([u32; 3]) -> bool,
) -> Option<Vec<[u32; 3]>> {
    let n = points.len();
    let at = |i: usize, j: usize| i * n + j;
    let mut weight = vec![Weight::INFINITE; n * n];
    let mut apex = vec![usize::MAX; n * n];
    let mut normal = vec![[0.0f64; 3]; n * n];
    for i in 0..n - 1 {
        weight[at(i, i + 1)] = Weight::ZERO;
    }
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
                if left.max_angle == f64::INFINITY
                    || right.max_angle == f64::INFINITY
                    || is_forbidden([i as u32, k as u32, j as u32])
                {
                    continue;
                }
                let (nt, _) = triangle_normal(points[i], points[k], points[j]);
                let mut angle = turns.tilt(nt);
                let mut bend = 0.0;
                for (a, b) in [(i, k), (k, j)] {
                    if b == a + 1 {
                        angle = angle.max(turns.rim(nt, side_normals[a]));
                    } else {
                        angle = angle.max(turns.between(nt, normal[at(a, b)]));
                        bend += angle_between(nt, normal[at(a, b)]);
                    }
                }
                if span == n - 1 {
                    angle = angle.max(turns.rim(nt, side_normals[n - 1]));
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
