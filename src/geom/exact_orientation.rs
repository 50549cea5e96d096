//! Exact orientation signs of 3D points, and of their projections on a coordinate plane, for
//! any finite coordinates.
//!
//! Shewchuk's adaptive predicates (the `robust` crate) are exact only while no intermediate
//! product overflows or underflows: a degree-three determinant of coordinates near `1e300` or
//! `1e-300` breaks them. So the points of one decision are first brought into the range where
//! they are exact, by a power of two (exact, and it changes no sign); when their coordinates span
//! more binary orders of magnitude than that range holds, the determinants are evaluated with
//! [`WideInteger`]s instead, which is slow but never happens on real models.

use robust::{Coord, Coord3D};

use super::wide_integer::WideInteger;

/// A point in space.
pub(crate) type Point = [f64; 3];

/// The sign of a determinant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sign {
    Negative,
    Zero,
    Positive,
}

impl Sign {
    fn of(value: f64) -> Sign {
        if value > 0.0 {
            Sign::Positive
        } else if value < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    fn of_integer(signum: i32) -> Sign {
        Sign::of(f64::from(signum))
    }
}

/// Largest magnitude, as a binary exponent, of the nonzero coordinates the adaptive predicates
/// take, and the negation of the smallest. Within `[2^-250, 2^251)`, every coordinate is a
/// multiple of `2^-302`, so every product of three coordinate differences (the orientation
/// determinant's terms, and the pieces the adaptive arithmetic splits them into) is zero or at
/// least `2^-906`, far from underflow, and below `2^760`, far from overflow (the bounds are
/// `-288` and `336`).
const ADAPTIVE_EXPONENT_LIMIT: i32 = 250;

/// The binary exponents (`floor(log2 |x|)`) of the smallest and the largest nonzero magnitude
/// among some coordinates; empty when they are all zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct ExponentRange {
    lowest: i32,
    highest: i32,
}

impl ExponentRange {
    /// The range of no coordinate (or only zeros).
    pub(crate) const EMPTY: ExponentRange = ExponentRange {
        lowest: i32::MAX,
        highest: i32::MIN,
    };

    /// The range of `coordinates`, which are finite.
    pub(crate) fn of(coordinates: impl IntoIterator<Item = f64>) -> ExponentRange {
        coordinates
            .into_iter()
            .fold(ExponentRange::EMPTY, |range, x| match binary_exponent(x) {
                Some(e) => range.union(ExponentRange {
                    lowest: e,
                    highest: e,
                }),
                None => range,
            })
    }

    /// The range of the coordinates of both.
    #[inline]
    pub(crate) fn union(self, other: ExponentRange) -> ExponentRange {
        ExponentRange {
            lowest: self.lowest.min(other.lowest),
            highest: self.highest.max(other.highest),
        }
    }
}

/// `floor(log2 |x|)` for finite nonzero `x` (subnormals included), `None` for zero.
pub(crate) fn binary_exponent(x: f64) -> Option<i32> {
    let magnitude = x.to_bits() & !(1 << 63);
    if magnitude == 0 {
        return None;
    }
    let biased = (magnitude >> 52) as i32;
    if biased > 0 {
        Some(biased - 1023)
    } else {
        // Subnormal: |x| = magnitude · 2^-1074.
        Some(63 - magnitude.leading_zeros() as i32 - 1074)
    }
}

/// How one decision's orientation signs are evaluated exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ExactOrientation {
    /// Shewchuk's adaptive arithmetic: the points are within its exact range.
    Adaptive,
    /// Integer arithmetic of any size: the coordinates span too many orders of magnitude.
    Wide,
}

impl ExactOrientation {
    /// The arithmetic for a decision on points whose coordinates have the exponent range
    /// `range`, and the power of two, if any, by which to multiply them first (with
    /// [`times_power_of_two`]) to bring them into the adaptive arithmetic's exact range.
    #[inline]
    pub(crate) fn for_range(range: ExponentRange) -> (ExactOrientation, Option<i32>) {
        Self::for_range_within(range, ADAPTIVE_EXPONENT_LIMIT)
    }

    /// [`ExactOrientation::for_range`] for determinants whose exact range is `[2^-limit,
    /// 2^limit]` (of higher degree than the orientation's: the in-circle test's is smaller).
    #[inline]
    pub(crate) fn for_range_within(
        range: ExponentRange,
        limit: i32,
    ) -> (ExactOrientation, Option<i32>) {
        if range.lowest >= -limit && range.highest <= limit {
            return (ExactOrientation::Adaptive, None);
        }
        // i64: the empty range's sentinels are handled above, the others are within ±1100.
        let (lowest, highest) = (i64::from(range.lowest), i64::from(range.highest));
        if highest - lowest > 2 * i64::from(limit) {
            return (ExactOrientation::Wide, None);
        }
        // Centres the range: lowest + shift >= -limit and highest + shift <= limit.
        let shift = -(lowest + highest).div_euclid(2) as i32;
        (ExactOrientation::Adaptive, Some(shift))
    }

    /// [`ExactOrientation::for_range`] for `points`, which it multiplies by the power of two.
    #[inline]
    pub(crate) fn for_points(points: &mut [Point], range: ExponentRange) -> ExactOrientation {
        let (arithmetic, shift) = ExactOrientation::for_range(range);
        if let Some(shift) = shift {
            scale_points(points, shift);
        }
        arithmetic
    }

    /// The sign of `robust::orient3d(a, b, c, d)`: positive when `d` lies below the plane
    /// through `a`, `b`, `c` (which run counter-clockwise seen from above it), zero when the four
    /// points are coplanar.
    #[inline]
    pub(crate) fn orient3d(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        match self {
            ExactOrientation::Adaptive => {
                let coord = |p: Point| Coord3D {
                    x: p[0],
                    y: p[1],
                    z: p[2],
                };
                Sign::of(robust::orient3d(coord(a), coord(b), coord(c), coord(d)))
            }
            ExactOrientation::Wide => wide_orient3d(a, b, c, d),
        }
    }

    /// The sign of `robust::orient2d(a, b, c)`: positive when `a`, `b`, `c` turn
    /// counter-clockwise, zero when they are collinear.
    #[inline]
    pub(crate) fn orient2d(self, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
        match self {
            ExactOrientation::Adaptive => {
                let coord = |p: [f64; 2]| Coord { x: p[0], y: p[1] };
                Sign::of(robust::orient2d(coord(a), coord(b), coord(c)))
            }
            ExactOrientation::Wide => wide_orient2d(a, b, c),
        }
    }
}

/// Whether three finite points lie exactly on one line (two or all of them equal included):
/// the exact signs of the triangle's projections on the three coordinate planes are all zero.
pub(crate) fn are_collinear(a: Point, b: Point, c: Point) -> bool {
    let mut points = [a, b, c];
    let range = ExponentRange::of(points.iter().flatten().copied());
    let arithmetic = ExactOrientation::for_points(&mut points, range);
    let [a, b, c] = points;
    [(0, 1), (1, 2), (2, 0)]
        .into_iter()
        .all(|(i, j)| arithmetic.orient2d([a[i], a[j]], [b[i], b[j]], [c[i], c[j]]) == Sign::Zero)
}

/// Multiplies `points` by `2^shift` (exactly, within the adaptive range).
pub(crate) fn scale_points(points: &mut [Point], shift: i32) {
    for p in points {
        *p = p.map(|x| times_power_of_two(x, shift));
    }
}

/// `x · 2^shift`, exact when the result is a normal number: two factors, as `2^shift` itself
/// may not be representable.
pub(crate) fn times_power_of_two(x: f64, shift: i32) -> f64 {
    let half = shift / 2;
    x * power_of_two(half) * power_of_two(shift - half)
}

/// `2^e` for `|e| <= 1022`.
fn power_of_two(e: i32) -> f64 {
    f64::from_bits(((1023 + e) as u64) << 52)
}

/// `robust::orient3d`'s determinant, in integers.
fn wide_orient3d(a: Point, b: Point, c: Point, d: Point) -> Sign {
    let [ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz] = integers([
        a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2],
    ]);
    let (adx, ady, adz) = (ax.sub(&dx), ay.sub(&dy), az.sub(&dz));
    let (bdx, bdy, bdz) = (bx.sub(&dx), by.sub(&dy), bz.sub(&dz));
    let (cdx, cdy, cdz) = (cx.sub(&dx), cy.sub(&dy), cz.sub(&dz));
    let bc = bdx.mul(&cdy).sub(&cdx.mul(&bdy));
    let ca = cdx.mul(&ady).sub(&adx.mul(&cdy));
    let ab = adx.mul(&bdy).sub(&bdx.mul(&ady));
    let determinant = adz.mul(&bc).add(&bdz.mul(&ca)).add(&cdz.mul(&ab));
    Sign::of_integer(determinant.signum())
}

/// `robust::orient2d`'s determinant, in integers.
fn wide_orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    let [ax, ay, bx, by, cx, cy] = integers([a[0], a[1], b[0], b[1], c[0], c[1]]);
    let left = ax.sub(&cx).mul(&by.sub(&cy));
    let right = ay.sub(&cy).mul(&bx.sub(&cx));
    Sign::of_integer(left.sub(&right).signum())
}

/// The finite `values` as integers, all multiplied by one power of two (the smallest unit among
/// them), so that their differences and products keep the signs of the values'.
pub(crate) fn integers<const N: usize>(values: [f64; N]) -> [WideInteger; N] {
    let unit = smallest_unit(&values);
    values.map(|x| integer_in_unit(x, unit))
}

/// [`integers`] of any number of values.
pub(crate) fn integer_list(values: &[f64]) -> Vec<WideInteger> {
    let unit = smallest_unit(values);
    values.iter().map(|&x| integer_in_unit(x, unit)).collect()
}

/// The exponent of the smallest unit among the non-zero `values` (0 when there are none).
pub(crate) fn smallest_unit(values: &[f64]) -> i32 {
    values
        .iter()
        .map(|&x| dyadic(x))
        .filter(|&(_, mantissa, _)| mantissa != 0)
        .map(|(_, _, exponent)| exponent)
        .min()
        .unwrap_or(0)
}

/// `x` as an integer multiple of `2^unit` (`unit` at most its own exponent).
fn integer_in_unit(x: f64, unit: i32) -> WideInteger {
    let (negative, mantissa, exponent) = dyadic(x);
    // Exponents of finite doubles lie in [-1074, 971]: the shift is below 2^12.
    let shift = if mantissa == 0 { 0 } else { exponent - unit };
    WideInteger::from_dyadic(negative, mantissa, shift as u32)
}

/// A finite `x` as `±mantissa · 2^exponent` with an odd mantissa (or zero).
pub(crate) fn dyadic(x: f64) -> (bool, u64, i32) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    let (mantissa, exponent) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    if mantissa == 0 {
        return (false, 0, 0);
    }
    let zeros = mantissa.trailing_zeros();
    (negative, mantissa >> zeros, exponent + zeros as i32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (xorshift), for reproducible samples.
    struct Samples(u64);

    impl Samples {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }

        /// A coordinate in [-8, 8) on a grid of quarters, or (one time in two) one of five
        /// values, so that ties and coplanarity happen.
        fn coordinate(&mut self) -> f64 {
            let n = self.next();
            if n.is_multiple_of(2) {
                (n / 2 % 64) as f64 / 4.0 - 8.0
            } else {
                (n / 2 % 5) as f64 - 2.0
            }
        }

        fn point(&mut self) -> Point {
            [self.coordinate(), self.coordinate(), self.coordinate()]
        }
    }

    #[test]
    fn binary_exponents_cover_normal_and_subnormal_numbers() {
        assert_eq!(binary_exponent(0.0), None);
        assert_eq!(binary_exponent(-0.0), None);
        assert_eq!(binary_exponent(1.0), Some(0));
        assert_eq!(binary_exponent(-3.0), Some(1));
        assert_eq!(binary_exponent(0.75), Some(-1));
        assert_eq!(binary_exponent(f64::MAX), Some(1023));
        assert_eq!(binary_exponent(f64::MIN_POSITIVE), Some(-1022));
        assert_eq!(binary_exponent(f64::MIN_POSITIVE / 2.0), Some(-1023));
        assert_eq!(binary_exponent(f64::from_bits(1)), Some(-1074));
    }

    #[test]
    fn wide_and_adaptive_arithmetic_agree_where_both_are_exact() {
        let mut samples = Samples(0x9e37_79b9_7f4a_7c15);
        let (mut zeros, mut total) = (0, 0);
        for _ in 0..4000 {
            let [a, b, c, d] = [(); 4].map(|_| samples.point());
            let adaptive = ExactOrientation::Adaptive.orient3d(a, b, c, d);
            assert_eq!(
                adaptive,
                wide_orient3d(a, b, c, d),
                "{a:?} {b:?} {c:?} {d:?}"
            );
            let [p, q, r] = [a, b, c].map(|p| [p[0], p[1]]);
            assert_eq!(
                ExactOrientation::Adaptive.orient2d(p, q, r),
                wide_orient2d(p, q, r)
            );
            zeros += usize::from(adaptive == Sign::Zero);
            total += 1;
        }
        assert!(zeros > 0 && zeros < total, "{zeros} coplanar of {total}");
    }

    /// A tetrahedron whose volume's sign depends on a term of degree three in tiny differences,
    /// at every scale from subnormal to near overflow, and mixed with huge coordinates.
    #[test]
    fn signs_survive_any_scale_and_any_spread_of_magnitudes() {
        let tetrahedron = |s: f64| {
            [
                [0.0, 0.0, 0.0],
                [s, 0.0, 0.0],
                [0.0, s, 0.0],
                [s / 3.0, s / 3.0, s * 2f64.powi(-40)],
            ]
        };
        for exponent in [-1000, -600, -300, -10, 0, 10, 300, 600, 1000, 1020] {
            let s = times_power_of_two(1.0, exponent);
            let points = tetrahedron(s);
            let range = ExponentRange::of(points.iter().flatten().copied());
            let mut scaled = points;
            let arithmetic = ExactOrientation::for_points(&mut scaled, range);
            let [a, b, c, d] = scaled;
            let sign = arithmetic.orient3d(a, b, c, d);
            assert_eq!(
                sign,
                wide_orient3d(points[0], points[1], points[2], points[3])
            );
            assert_ne!(sign, Sign::Zero, "scale 2^{exponent}");
            // Lifted to the plane z = 0 exactly: coplanar at every scale.
            let mut flat = [points[0], points[1], points[2], [s / 3.0, s / 3.0, 0.0]];
            let range = ExponentRange::of(flat.iter().flatten().copied());
            let arithmetic = ExactOrientation::for_points(&mut flat, range);
            let [a, b, c, d] = flat;
            assert_eq!(arithmetic.orient3d(a, b, c, d), Sign::Zero);
        }
        // 1e300 beside 1e-300 in one decision: too wide a spread for any scaling.
        let (big, tiny) = (1e300, 1e-300);
        let points = [
            [big, 0.0, 0.0],
            [0.0, tiny, 0.0],
            [0.0, 0.0, tiny],
            [0.0, 0.0, 0.0],
        ];
        let range = ExponentRange::of(points.iter().flatten().copied());
        let mut unscaled = points;
        let arithmetic = ExactOrientation::for_points(&mut unscaled, range);
        assert_eq!(arithmetic, ExactOrientation::Wide);
        assert_eq!(unscaled, points);
        let [a, b, c, d] = points;
        // The determinant is big · tiny · tiny > 0 in exact arithmetic, 0 in floating point.
        assert_eq!(arithmetic.orient3d(a, b, c, d), Sign::Positive);
        let flipped = ExactOrientation::Wide.orient3d(b, a, c, d);
        assert_eq!(flipped, Sign::Negative);
    }

    #[test]
    fn scaling_keeps_every_sign_of_a_uniformly_scaled_configuration() {
        let mut samples = Samples(0x2545_f491_4f6c_dd1d);
        for _ in 0..500 {
            let points = [(); 4].map(|_| samples.point());
            let exact = wide_orient3d(points[0], points[1], points[2], points[3]);
            for exponent in [-1060, -700, 700, 1010] {
                let mut scaled = points.map(|p| p.map(|x| times_power_of_two(x, exponent)));
                let range = ExponentRange::of(scaled.iter().flatten().copied());
                let arithmetic = ExactOrientation::for_points(&mut scaled, range);
                let [a, b, c, d] = scaled;
                assert_eq!(
                    arithmetic.orient3d(a, b, c, d),
                    exact,
                    "{points:?} 2^{exponent}"
                );
            }
        }
    }
}
