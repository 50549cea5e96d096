//! Exact comparison of distances from a query point to two sites under the L2, L1 and L∞
//! metrics: a floating-point filter, then exact expansion arithmetic (Shewchuk's two-sum and an
//! FMA-based two-product) when the filter cannot decide, on the points brought into its exact
//! range by a power of two, or integers of any size when their magnitudes span more than that.

use std::cmp::Ordering;

use super::expansion::{sign_of_sum, two_diff, two_product};
use crate::geom::exact_orientation::{ExactOrientation, ExponentRange, integers};
use crate::geom::wide_integer::WideInteger;

/// A distance function on the plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Metric {
    /// Euclidean distance.
    Euclidean,
    /// L1 (taxicab) distance `|dx| + |dy|`.
    Manhattan,
    /// L∞ distance `max(|dx|, |dy|)`.
    Chebyshev,
}

impl Metric {
    /// Floating-point distance (squared for [`Metric::Euclidean`]), monotone in the true one.
    #[inline(always)]
    pub fn approx(self, q: [f64; 2], a: [f64; 2]) -> f64 {
        let (dx, dy) = ((q[0] - a[0]).abs(), (q[1] - a[1]).abs());
        match self {
            Metric::Euclidean => dx * dx + dy * dy,
            Metric::Manhattan => dx + dy,
            Metric::Chebyshev => dx.max(dy),
        }
    }

    /// Exactly compares the distances from `q` to `a` and to `b`, for any finite points.
    pub fn compare(self, q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Ordering {
        let (da, db) = (self.approx(q, a), self.approx(q, b));
        // Relative error of `approx` is below 4 ulps for all three metrics while nothing
        // overflows and the sum is far above underflow (whose absolute error, below 2^-1073,
        // is then negligible against the bound).
        let bound = 8.0 * f64::EPSILON * (da + db);
        if (da - db).abs() > bound && bound.is_finite() && da + db >= FILTER_FLOOR {
            return da.partial_cmp(&db).unwrap_or(Ordering::Equal);
        }
        let mut points = [q, a, b].map(|p| [p[0], p[1], 0.0]);
        let range = ExponentRange::of(points.iter().flat_map(|p| [p[0], p[1]]));
        match ExactOrientation::for_points(&mut points, range) {
            ExactOrientation::Adaptive => {
                let [q, a, b] = points.map(|p| [p[0], p[1]]);
                self.compare_with_expansions(q, a, b)
            }
            ExactOrientation::Wide => self.compare_with_integers(q, a, b),
        }
    }

    /// [`Metric::compare`] in expansion arithmetic, exact while no product of two coordinate
    /// differences under- or overflows (coordinates within the adaptive predicates' range).
    fn compare_with_expansions(self, q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Ordering {
        let mut terms = Vec::with_capacity(24);
        match self {
            Metric::Euclidean => {
                for (p, sign) in [(a, 1.0), (b, -1.0)] {
                    for k in 0..2 {
                        let (h, l) = two_diff(q[k], p[k]);
                        // (h + l)^2 = h^2 + 2hl + l^2, each product split exactly.
                        for (x, y) in [(h, h), (2.0 * h, l), (l, l)] {
                            let (ph, pl) = two_product(x, y);
                            terms.push(sign * ph);
                            terms.push(sign * pl);
                        }
                    }
                }
            }
            Metric::Manhattan => {
                for (p, sign) in [(a, 1.0), (b, -1.0)] {
                    for k in 0..2 {
                        let (h, l) = abs_expansion(two_diff(q[k], p[k]));
                        terms.push(sign * h);
                        terms.push(sign * l);
                    }
                }
            }
            Metric::Chebyshev => {
                let largest = |p: [f64; 2]| {
                    let x = abs_expansion(two_diff(q[0], p[0]));
                    let y = abs_expansion(two_diff(q[1], p[1]));
                    if sign_of_sum(&[x.0, x.1, -y.0, -y.1]) >= 0.0 {
                        x
                    } else {
                        y
                    }
                };
                let (x, y) = (largest(a), largest(b));
                terms.extend_from_slice(&[x.0, x.1, -y.0, -y.1]);
            }
        }
        sign_of_sum(&terms)
            .partial_cmp(&0.0)
            .unwrap_or(Ordering::Equal)
    }

    /// [`Metric::compare`] in integers of any size: for points whose coordinates span more
    /// binary orders of magnitude than expansion arithmetic holds without underflow.
    fn compare_with_integers(self, q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Ordering {
        let [qx, qy, ax, ay, bx, by] = integers([q[0], q[1], a[0], a[1], b[0], b[1]]);
        let distance = |x: &WideInteger, y: &WideInteger| {
            let (dx, dy) = (qx.sub(x), qy.sub(y));
            match self {
                Metric::Euclidean => dx.mul(&dx).add(&dy.mul(&dy)),
                Metric::Manhattan => dx.abs().add(&dy.abs()),
                Metric::Chebyshev => {
                    let (dx, dy) = (dx.abs(), dy.abs());
                    if dx.sub(&dy).signum() >= 0 { dx } else { dy }
                }
            }
        };
        distance(&ax, &ay).sub(&distance(&bx, &by)).signum().cmp(&0)
    }
}

/// Smallest sum of the two floating-point distances that the filter of [`Metric::compare`]
/// decides: far enough above underflow that its absolute rounding errors do not count.
const FILTER_FLOOR: f64 = 1.0e-270;

/// Absolute value of the two-term expansion `h + l` (its sign is the sign of `h`).
fn abs_expansion((h, l): (f64, f64)) -> (f64, f64) {
    if h < 0.0 { (-h, -l) } else { (h, l) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ties_are_detected_exactly() {
        let (q, a, b) = (
            [0.5, 0.25],
            [0.5 + 0.125, 0.25 - 0.5],
            [0.5 - 0.125, 0.25 + 0.5],
        );
        for m in [Metric::Euclidean, Metric::Manhattan, Metric::Chebyshev] {
            assert_eq!(m.compare(q, a, b), Ordering::Equal, "mirror images, {m:?}");
        }
        assert_eq!(
            Metric::Manhattan.compare([0.0, 0.0], [1.0, 2.0], [3.0, 0.0]),
            Ordering::Equal
        );
        assert_eq!(
            Metric::Chebyshev.compare([0.0, 0.0], [1.0, 3.0], [3.0, -2.0]),
            Ordering::Equal
        );
        assert_eq!(
            Metric::Euclidean.compare([0.0, 0.0], [3.0, 4.0], [5.0, 0.0]),
            Ordering::Equal
        );
    }

    #[test]
    fn one_ulp_differences_are_resolved() {
        let q = [0.0, 0.0];
        let a = [1.0, 0.0];
        let b = [1.0 + f64::EPSILON, 0.0];
        for m in [Metric::Euclidean, Metric::Manhattan, Metric::Chebyshev] {
            assert_eq!(m.compare(q, a, b), Ordering::Less, "{m:?}");
            assert_eq!(m.compare(q, b, a), Ordering::Greater, "{m:?}");
        }
        // Differences that round away in f64 squares: 1e8 + 1e-8 style.
        let q = [1e8, 0.0];
        let a = [1e-8, 0.0];
        let b = [0.0, 1e-8];
        assert_eq!(Metric::Euclidean.compare(q, a, b), Ordering::Less);
    }

    #[test]
    fn sign_of_sum_is_exact() {
        assert_eq!(sign_of_sum(&[1e300, 1.0, -1e300]), 1.0);
        assert_eq!(sign_of_sum(&[1e-300, -1e-300]), 0.0);
        assert_eq!(sign_of_sum(&[]), 0.0);
        assert_eq!(
            sign_of_sum(&[0.1, 0.2, -0.3]),
            (0.1f64 + 0.2 - 0.3).signum()
        );
    }
}
