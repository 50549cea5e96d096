//! Exact geometric predicates (Shewchuk's adaptive arithmetic through the `robust` crate), error
//! bounds shared by all points of one set (for the crate's constructions), and the power-of-two
//! rescaling that keeps them exact for very large and very small coordinates.

use robust::Coord;

use super::spatial_sort::bounding_box;
use crate::geom::exact_orientation::{
    ExactOrientation, ExponentRange, Sign, binary_exponent, dyadic, integers, times_power_of_two,
};
use crate::geom::wide_integer::WideInteger;

#[inline(always)]
fn coord(p: [f64; 2]) -> Coord<f64> {
    Coord { x: p[0], y: p[1] }
}

/// Shewchuk's machine epsilon (half an ulp of 1).
const HALF_EPSILON: f64 = f64::EPSILON * 0.5;
/// Error bound of the floating-point orientation determinant (Shewchuk's `ccwerrboundA`).
const ORIENT_BOUND: f64 = (3.0 + 16.0 * HALF_EPSILON) * HALF_EPSILON;
/// Error bound of the floating-point in-circle determinant (Shewchuk's `iccerrboundA`).
const INCIRCLE_BOUND: f64 = (10.0 + 96.0 * HALF_EPSILON) * HALF_EPSILON;

/// Error bounds of the floating-point orientation and in-circle determinants that hold for any
/// points of one set, from its bounding box, so that most calls of a construction are decided
/// before their own error bound is computed (a third of the in-circle filter's instructions).
/// Negative when every determinant of the set is exact: all its points on a small lattice, as
/// integer grids are, whose many exact zeros would otherwise all take the slow path.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SetBounds {
    orient: f64,
    incircle: f64,
}

impl SetBounds {
    /// Nothing known of the set: every call computes its own bound.
    pub(crate) const NONE: SetBounds = SetBounds {
        orient: f64::INFINITY,
        incircle: f64::INFINITY,
    };

    /// The bounds for `points`, whose bounding box is `[min, max]`.
    ///
    /// Shewchuk's bounds are `ORIENT_BOUND` and `INCIRCLE_BOUND` times the determinants'
    /// permanents, and when no coordinate difference exceeds `w` in magnitude these are at most
    /// `2 w^2` (two products of differences) and `12 w^4` (three terms, each two products of
    /// differences, `<= 2 w^2`, times a squared length, `<= 2 w^2`). `w` is the box's larger
    /// side, rounded up, and each bound is rounded up once more for its own evaluation, which is
    /// monotone in `w` as the permanents are in the differences.
    pub(crate) fn of(points: &[[f64; 2]], [min, max]: [[f64; 2]; 2]) -> Self {
        let w = (max[0] - min[0]).max(max[1] - min[1]);
        if !w.is_finite() {
            return Self::NONE;
        }
        if set_on_small_lattice(points, min, w, INCIRCLE_LATTICE_BITS) {
            return SetBounds {
                orient: -1.0,
                incircle: -1.0,
            };
        }
        if w < SMALLEST_BOUNDED_SIDE {
            return Self::NONE;
        }
        let w = w * (1.0 + 4.0 * f64::EPSILON);
        let rounding = 1.0 + 64.0 * f64::EPSILON;
        SetBounds {
            orient: ORIENT_BOUND * 2.0 * (w * w) * rounding,
            incircle: INCIRCLE_BOUND * 12.0 * (w * w) * (w * w) * rounding,
        }
    }
}

/// Orientation of the triangle `a, b, c`: positive when counter-clockwise (`c` left of `a → b`),
/// negative when clockwise, exactly zero when collinear.
///
/// Evaluation: the floating-point determinant when its error bound decides the sign; otherwise
/// the same determinant when the coordinate differences lie on a coarse power-of-two lattice that
/// makes it exact (integer grids: their many exact zeros would all need the slow path); otherwise
/// Shewchuk's adaptive exact arithmetic.
#[inline(always)]
pub fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    orient2d_in(a, b, c, &SetBounds::NONE)
}

/// [`orient2d`] for three points of the set of `set`.
#[inline(always)]
pub(crate) fn orient2d_in(a: [f64; 2], b: [f64; 2], c: [f64; 2], set: &SetBounds) -> f64 {
    let (acx, acy, bcx, bcy) = (a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]);
    let left = acx * bcy;
    let right = acy * bcx;
    let det = left - right;
    if det.abs() > set.orient
        || (det.abs() > ORIENT_BOUND * (left.abs() + right.abs()) && det.abs() > UNDERFLOW_GUARD)
    {
        return det;
    }
    orient2d_slow(a, b, c, det)
}

#[cold]
fn orient2d_slow(a: [f64; 2], b: [f64; 2], c: [f64; 2], det: f64) -> f64 {
    if det.abs() > UNDERFLOW_GUARD
        && on_small_lattice([(a[0], c[0]), (a[1], c[1]), (b[0], c[0]), (b[1], c[1])], 25)
    {
        return det;
    }
    let range = ExponentRange::of([a, b, c].iter().flat_map(|p| [p[0], p[1]]));
    let sign = match ExactOrientation::for_range(range) {
        (ExactOrientation::Adaptive, None) => {
            return robust::orient2d(coord(a), coord(b), coord(c));
        }
        (ExactOrientation::Adaptive, Some(shift)) => {
            let [a, b, c] = [a, b, c].map(|p| p.map(|x| times_power_of_two(x, shift)));
            sign_of(robust::orient2d(coord(a), coord(b), coord(c)))
        }
        (ExactOrientation::Wide, _) => match ExactOrientation::Wide.orient2d(a, b, c) {
            Sign::Negative => -1.0,
            Sign::Zero => 0.0,
            Sign::Positive => 1.0,
        },
    };
    with_exact_sign(det, sign)
}

/// -1, 0 or 1 as `x` is negative, zero or positive (`f64::signum` gives 1 for zero).
fn sign_of(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// The floating-point determinant `approximate` when it has the exact `sign` (-1, 0 or 1),
/// otherwise the smallest normal number of that sign: callers that weigh by the determinant get
/// its size where it is meaningful, and every caller gets the exact sign.
fn with_exact_sign(approximate: f64, sign: f64) -> f64 {
    if sign == 0.0 {
        0.0
    } else if sign_of(approximate) == sign && approximate.is_finite() {
        approximate
    } else {
        sign * f64::MIN_POSITIVE
    }
}

/// In-circle test: for a counter-clockwise triangle `a, b, c`, positive when `d` lies strictly
/// inside its circumcircle, negative when strictly outside, exactly zero when the four points are
/// cocircular. (For a clockwise triangle the sign flips.) Evaluated like [`orient2d`].
#[inline(always)]
pub fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    incircle_in(a, b, c, d, &SetBounds::NONE)
}

/// [`incircle`] for four points of the set of `set`.
#[inline(always)]
pub(crate) fn incircle_in(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
    set: &SetBounds,
) -> f64 {
    let (adx, ady) = (a[0] - d[0], a[1] - d[1]);
    let (bdx, bdy) = (b[0] - d[0], b[1] - d[1]);
    let (cdx, cdy) = (c[0] - d[0], c[1] - d[1]);
    let (bdxcdy, cdxbdy) = (bdx * cdy, cdx * bdy);
    let (cdxady, adxcdy) = (cdx * ady, adx * cdy);
    let (adxbdy, bdxady) = (adx * bdy, bdx * ady);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    if det.abs() > set.incircle {
        return det;
    }
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    if det.abs() > INCIRCLE_BOUND * permanent && det.abs() > UNDERFLOW_GUARD {
        return det;
    }
    incircle_slow(a, b, c, d, det)
}

#[cold]
fn incircle_slow(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2], det: f64) -> f64 {
    let diffs = [
        (a[0], d[0]),
        (a[1], d[1]),
        (b[0], d[0]),
        (b[1], d[1]),
        (c[0], d[0]),
        (c[1], d[1]),
    ];
    if det.abs() > UNDERFLOW_GUARD && on_small_lattice(diffs, INCIRCLE_LATTICE_BITS) {
        return det;
    }
    let range = ExponentRange::of([a, b, c, d].iter().flat_map(|p| [p[0], p[1]]));
    match ExactOrientation::for_range_within(range, INCIRCLE_EXPONENT_LIMIT) {
        (ExactOrientation::Adaptive, None) => {
            robust::incircle(coord(a), coord(b), coord(c), coord(d))
        }
        (ExactOrientation::Adaptive, Some(shift)) => {
            let [a, b, c, d] = [a, b, c, d].map(|p| p.map(|x| times_power_of_two(x, shift)));
            let sign = sign_of(robust::incircle(coord(a), coord(b), coord(c), coord(d)));
            with_exact_sign(det, sign)
        }
        (ExactOrientation::Wide, _) => with_exact_sign(det, wide_incircle(a, b, c, d)),
    }
}

/// Largest binary exponent (and negated smallest) of the nonzero coordinates that the adaptive
/// in-circle test takes: every coordinate is then a multiple of `2^-172`, so its degree-four
/// products (and the pieces the adaptive arithmetic splits them into) stay above `2^-700`, far
/// from underflow, and below `2^500`, far from overflow.
const INCIRCLE_EXPONENT_LIMIT: i32 = 120;

/// Smallest side of a set's box for which [`SetBounds`] hold: the in-circle bound, of degree
/// four in it, stays above [`UNDERFLOW_GUARD`].
const SMALLEST_BOUNDED_SIDE: f64 = 1.0e-60;

/// Smallest floating-point determinant whose sign the filters take as it is: its products'
/// underflow errors (below `2^-1074` each) cannot flip it.
const UNDERFLOW_GUARD: f64 = 1.0e-290;

/// The in-circle determinant's sign (as -1, 0 or 1) in integers of any size, for points whose
/// coordinates span more binary orders of magnitude than the adaptive test holds.
fn wide_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    let [ax, ay, bx, by, cx, cy, dx, dy] =
        integers([a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]]);
    let (adx, ady, bdx, bdy) = (ax.sub(&dx), ay.sub(&dy), bx.sub(&dx), by.sub(&dy));
    let (cdx, cdy) = (cx.sub(&dx), cy.sub(&dy));
    let lift = |x: &WideInteger, y: &WideInteger| x.mul(x).add(&y.mul(y));
    let cross = |x1: &WideInteger, y1: &WideInteger, x2: &WideInteger, y2: &WideInteger| {
        x1.mul(y2).sub(&x2.mul(y1))
    };
    let determinant = lift(&adx, &ady)
        .mul(&cross(&bdx, &bdy, &cdx, &cdy))
        .add(&lift(&bdx, &bdy).mul(&cross(&cdx, &cdy, &adx, &ady)))
        .add(&lift(&cdx, &cdy).mul(&cross(&adx, &ady, &bdx, &bdy)));
    f64::from(determinant.signum())
}

/// Lattice span (in units, as a power of two) that keeps the in-circle determinant exact.
const INCIRCLE_LATTICE_BITS: i32 = 12;

/// True when every difference `x - y` is computed exactly and all of them are integer multiples
/// of one power of two `u` with magnitude below `2^bits · u` (and `u` far from underflow). Then
/// the floating-point orientation (`bits = 25`) or in-circle (`bits = 12`) determinant is exact:
/// every product and sum stays below `2^53` units of its lattice.
fn on_small_lattice<const N: usize>(pairs: [(f64, f64); N], bits: i32) -> bool {
    // Straight-line over all pairs (no early exits), which the compiler unrolls: the slow path
    // is frequent on integer grids, where many determinants are exactly zero.
    let diffs = pairs.map(|(x, y)| x - y);
    let (mut inexact, mut largest) = (false, 0.0_f64);
    for (&(x, y), &d) in pairs.iter().zip(&diffs) {
        inexact |= !is_exact_difference(x, y, d);
        let size = d.abs();
        largest = if size > largest { size } else { largest };
    }
    if inexact {
        return false;
    }
    if largest == 0.0 {
        return true;
    }
    let Some(inverse_unit) = inverse_lattice_unit(largest, bits) else {
        return false;
    };
    let mut off_lattice = false;
    for d in diffs {
        off_lattice |= !is_integer(d * inverse_unit);
    }
    !off_lattice
}

/// [`on_small_lattice`] for the differences of any two of `points`, whose bounding box has
/// lower corner `min` and larger side `w`: every `p - min` exact and on the lattice of unit
/// `u` for `w` makes every difference of two points exact (an integer below `2^bits` times `u`
/// is representable) and on that lattice.
fn set_on_small_lattice(points: &[[f64; 2]], min: [f64; 2], w: f64, bits: i32) -> bool {
    if w == 0.0 {
        return true;
    }
    let Some(inverse_unit) = inverse_lattice_unit(w, bits) else {
        return false;
    };
    // Stops at the first point off the lattice: the first one, for almost any non-grid input.
    points.iter().all(|p| {
        (0..2).all(|k| {
            let d = p[k] - min[k];
            is_exact_difference(p[k], min[k], d) && is_integer(d * inverse_unit)
        })
    })
}

/// Is `d = x - y`, as computed, exact? (The Dekker/Knuth two-difference error term is zero.)
#[inline(always)]
fn is_exact_difference(x: f64, y: f64, d: f64) -> bool {
    let y_virtual = x - d;
    let x_virtual = d + y_virtual;
    (x - x_virtual) + (y_virtual - y) == 0.0
}

/// `1 / u` for the lattice unit `u = 2^(e + 1 - bits)`, where `2^e <= largest < 2^(e+1)`, so
/// that magnitudes up to `largest` are below `2^bits` units; `None` when `u` would be too close
/// to underflow or overflow for the determinants (or `largest` is subnormal).
#[inline(always)]
fn inverse_lattice_unit(largest: f64, bits: i32) -> Option<f64> {
    let biased_exponent = ((largest.to_bits() >> 52) & 0x7ff) as i32;
    let unit_exponent = biased_exponent - 1023 + 1 - bits;
    if !(-240..=240).contains(&unit_exponent) || biased_exponent == 0 {
        return None;
    }
    // 2^-unit_exponent, a normal number (the range check above), built from its bits: `pow2`
    // would call the software `powi`.
    Some(f64::from_bits(((1023 - unit_exponent) as u64) << 52))
}

/// Is `units`, of magnitude below `2^25`, an integer? Adding and subtracting `1.5 · 2^52` rounds
/// it to the nearest integer exactly, so it is one when that changes nothing (`trunc` is a
/// library call on baseline x86-64).
#[inline(always)]
fn is_integer(units: f64) -> bool {
    const ROUND: f64 = 6_755_399_441_055_744.0;
    (units + ROUND) - ROUND == units
}

/// The power of two by which sites are multiplied before any predicate is evaluated, so that
/// the largest coordinate magnitude lies in `[1, 2)`.
///
/// The adaptive predicates are exact only when no intermediate product overflows or underflows;
/// the in-circle determinant is of degree four, so inputs near `1e+200` or `1e-300` would break
/// it. Scaling by a power of two is exact (barring underflow of individual coordinates) and does
/// not change any orientation or in-circle sign.
pub fn normalising_scale(points: &[[f64; 2]]) -> f64 {
    normalising_scale_of_box(bounding_box(points))
}

/// [`normalising_scale`] of points whose [`bounding_box`] is `[min, max]` (the largest magnitude
/// is at a corner).
pub(crate) fn normalising_scale_of_box([min, max]: [[f64; 2]; 2]) -> f64 {
    let max_abs = [min[0], min[1], max[0], max[1]]
        .iter()
        .fold(0.0_f64, |m, c| m.max(c.abs()));
    if max_abs == 0.0 || !max_abs.is_finite() {
        return 1.0;
    }
    // The exponent read off the bits: `log2`, `floor` and `powi` are library calls, and this
    // runs once per Voronoi vertex and per clipped ray (1M sites: 6% of the clipped diagram).
    let Some(exponent) = binary_exponent(max_abs) else {
        return 1.0;
    };
    pow2((-exponent).clamp(f64::MIN_EXP - 1, f64::MAX_EXP - 1))
}

/// [`normalising_scale_of_box`] for `points` (whose box is `site_box`), raised where needed so
/// that multiplying any of them by it is exact: no low bit of a tiny coordinate is lost below
/// the smallest subnormal when the largest one is brought near 1. (The exact predicates take
/// any finite coordinates; only the scaling itself could merge distinct sites.)
pub(crate) fn exact_normalising_scale(points: &[[f64; 2]], site_box: [[f64; 2]; 2]) -> f64 {
    let scale = normalising_scale_of_box(site_box);
    if scale >= 1.0 {
        return scale;
    }
    let Some(shift) = binary_exponent(scale) else {
        return scale;
    };
    let lowest_bit = points
        .iter()
        .flatten()
        .map(|&x| dyadic(x))
        .filter(|&(_, mantissa, _)| mantissa != 0)
        .map(|(_, _, exponent)| exponent)
        .min();
    match lowest_bit {
        Some(lowest) if lowest + shift < SMALLEST_EXPONENT => pow2(SMALLEST_EXPONENT - lowest),
        _ => scale,
    }
}

/// Binary exponent of the smallest positive double (the lowest bit of a subnormal).
const SMALLEST_EXPONENT: i32 = -1074;

/// `2^e` for any exponent a finite f64 can represent (including subnormal results).
pub fn pow2(e: i32) -> f64 {
    // Built from its bits (`powi` is a software loop): a normal number's biased exponent, or a
    // subnormal's single mantissa bit; beyond the range, infinity or zero, as rounding gives.
    const MIN_NORMAL: i32 = f64::MIN_EXP - 1;
    const MAX: i32 = f64::MAX_EXP - 1;
    if e > MAX {
        f64::INFINITY
    } else if e >= MIN_NORMAL {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else if e >= SMALLEST_EXPONENT {
        f64::from_bits(1 << (e - SMALLEST_EXPONENT))
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orient_sign_convention_is_counter_clockwise_positive() {
        assert!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]) > 0.0);
        assert!(orient2d([0.0, 0.0], [0.0, 1.0], [1.0, 0.0]) < 0.0);
        assert_eq!(orient2d([0.0, 0.0], [1.0, 1.0], [3.0, 3.0]), 0.0);
    }

    #[test]
    fn incircle_sign_convention_positive_inside_for_ccw_triangle() {
        let (a, b, c) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
        assert!(
            incircle(a, b, c, [0.5, 0.5]) > 0.0,
            "centre-ish point is inside"
        );
        assert!(incircle(a, b, c, [2.0, 2.0]) < 0.0, "far point is outside");
        assert_eq!(
            incircle(a, b, c, [1.0, 1.0]),
            0.0,
            "square corner is cocircular"
        );
        // Clockwise order flips the sign.
        assert!(incircle(a, c, b, [0.5, 0.5]) < 0.0);
    }

    #[test]
    fn incircle_is_exact_near_degeneracy() {
        // A point displaced from the circle by one ulp must not be reported as cocircular.
        let d = [1.0, 1.0 + f64::EPSILON];
        assert!(incircle([0.0, 0.0], [1.0, 0.0], [0.0, 1.0], d) < 0.0);
    }

    /// Orientation and in-circle signs of `pts`'s triples and quadruples under `set` against
    /// the adaptive arithmetic; returns how many in-circle calls the set bound decided, of all.
    fn check_set(pts: &[[f64; 2]], set: &SetBounds) -> (usize, usize) {
        let coord = |p: [f64; 2]| Coord { x: p[0], y: p[1] };
        let same_sign = |x: f64, y: f64| (x > 0.0, x < 0.0) == (y > 0.0, y < 0.0);
        let (mut decided_by_set, mut total) = (0, 0);
        for &a in pts.iter().step_by(3) {
            for &b in pts.iter().skip(1).step_by(4) {
                for &c in pts.iter().skip(2).step_by(5) {
                    let o = robust::orient2d(coord(a), coord(b), coord(c));
                    assert!(same_sign(orient2d_in(a, b, c, set), o));
                    for &d in pts {
                        let exact = robust::incircle(coord(a), coord(b), coord(c), coord(d));
                        let mine = incircle_in(a, b, c, d, set);
                        assert!(same_sign(mine, exact), "{a:?} {b:?} {c:?} {d:?}");
                        total += 1;
                        decided_by_set += usize::from(mine.abs() > set.incircle);
                    }
                }
            }
        }
        (decided_by_set, total)
    }

    #[test]
    fn set_bounds_agree_with_adaptive_arithmetic() {
        // Points near one circle (rounded, so cocircular only up to an ulp or so: determinants
        // on both sides of the set bound), and random points, in boxes of several sizes.
        let mut state = 7_u64;
        let mut random = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for scale in [1.0, 0.75, 2.0_f64.powi(-20)] {
            let mut pts: Vec<[f64; 2]> = (0..40)
                .map(|_| {
                    let t = random() * std::f64::consts::TAU;
                    [scale * (0.5 + 0.5 * t.cos()), scale * (0.5 + 0.5 * t.sin())]
                })
                .collect();
            pts.extend((0..20).map(|_| [scale * random(), scale * random()]));
            let set = SetBounds::of(&pts, bounding_box(&pts));
            assert!(set.incircle > 0.0 && set.incircle.is_finite() && set.orient > 0.0);
            let (decided_by_set, total) = check_set(&pts, &set);
            // The set bound decides most calls, and not all (the near-circle quadruples).
            assert!(
                decided_by_set > total / 2 && decided_by_set < total,
                "{decided_by_set}/{total}"
            );
        }
        let empty = SetBounds::of(&[], bounding_box(&[]));
        assert_eq!(empty.incircle, f64::INFINITY);
    }

    #[test]
    fn lattice_sets_are_exact() {
        // An integer grid, offset and scaled by powers of two: every determinant exact, the
        // many zeros included.
        for (unit, offset) in [(1.0, 0.0), (0.25, -3.0), (2.0_f64.powi(-30), 1.5)] {
            let mut pts: Vec<[f64; 2]> = (0..49)
                .map(|i| {
                    [
                        offset + (i % 7) as f64 * unit,
                        offset + (i / 7) as f64 * unit,
                    ]
                })
                .collect();
            let set = SetBounds::of(&pts, bounding_box(&pts));
            assert!(set.incircle < 0.0 && set.orient < 0.0, "unit {unit}");
            let (decided_by_set, total) = check_set(&pts, &set);
            assert_eq!(decided_by_set, total);
            // Off the lattice by one point, or too wide a lattice: the usual bounds.
            pts.push([offset + 0.1 * unit, offset]);
            assert!(SetBounds::of(&pts, bounding_box(&pts)).incircle > 0.0);
            pts.pop();
            pts.push([offset + 5000.0 * unit, offset]);
            let wide = SetBounds::of(&pts, bounding_box(&pts));
            assert!(wide.incircle > 0.0);
            check_set(&pts, &wide);
        }
        // One distinct point: every determinant is zero, exactly.
        let same = [[0.3, 0.7]; 4];
        let set = SetBounds::of(&same, bounding_box(&same));
        assert!(set.incircle < 0.0);
        check_set(&same, &set);
    }

    #[test]
    fn lattice_shortcut_agrees_with_adaptive_arithmetic() {
        // Integer grids (exact zeros) and near-lattice perturbations.
        let pts: Vec<[f64; 2]> = (0..36)
            .map(|i| [(i % 6) as f64 * 0.25, (i / 6) as f64 * 0.25])
            .collect();
        let coord = |p: [f64; 2]| Coord { x: p[0], y: p[1] };
        for (i, &a) in pts.iter().enumerate().step_by(5) {
            for &b in pts.iter().skip(i % 3).step_by(4) {
                for &c in pts.iter().skip(1).step_by(7) {
                    let o = robust::orient2d(coord(a), coord(b), coord(c));
                    assert_eq!(orient2d(a, b, c).signum(), o.signum());
                    assert_eq!(orient2d(a, b, c) == 0.0, o == 0.0);
                    for &d in pts.iter().step_by(3) {
                        let r = robust::incircle(coord(a), coord(b), coord(c), coord(d));
                        let mine = incircle(a, b, c, d);
                        assert_eq!((mine > 0.0, mine < 0.0), (r > 0.0, r < 0.0));
                    }
                }
            }
        }
        // Differences that are not exact must not take the shortcut.
        let big = 9007199254740992.0; // 2^53
        assert!(!on_small_lattice([(big, 1.0), (0.0, 0.0)], 25));
        assert!(on_small_lattice([(3.0, 1.0), (0.5, 0.0)], 25));
        assert!(!on_small_lattice([(3.0, 1.0), (0.1, 0.0)], 25));
    }

    #[test]
    fn pow2_is_the_exact_power_of_two_or_its_rounding() {
        for e in -1100..1100 {
            // Halves of the exponent keep each factor representable; the product rounds once.
            let reference = 2.0_f64.powi(e / 2) * 2.0_f64.powi(e - e / 2);
            assert_eq!(pow2(e).to_bits(), reference.to_bits(), "2^{e}");
        }
        assert_eq!(pow2(i32::MAX), f64::INFINITY);
        assert_eq!(pow2(i32::MIN), 0.0);
    }

    #[test]
    fn normalising_scale_of_box_brings_every_magnitude_to_unit_range() {
        let smallest = f64::from_bits(1);
        for largest in [
            smallest,
            3.0 * smallest,
            1e-310,
            1e-300,
            0.75,
            1.0,
            1.5,
            2.0,
            1e300,
        ] {
            let scale = normalising_scale_of_box([[-largest, 0.0], [0.0, 0.0]]);
            let scaled = largest * scale;
            // Subnormal magnitudes cannot reach 1: the scale stops at the largest power of two.
            if scale < f64::MAX / 2.0 {
                assert!((1.0..2.0).contains(&scaled), "{largest:e} -> {scaled:e}");
            } else {
                assert_eq!(scale, pow2(1023));
            }
        }
        // The scale stays a normal number: the largest finite magnitude is brought below 4.
        assert_eq!(normalising_scale_of_box([[f64::MAX, 0.0]; 2]), pow2(-1022));
        assert_eq!(normalising_scale_of_box([[0.0; 2]; 2]), 1.0);
    }

    #[test]
    fn normalising_scale_brings_magnitude_to_unit_range() {
        for m in [1e-300, 2.5e-310, 3.0e-7, 1.0, 1.5, 2.0, 7.0e150, 1e200] {
            let s = normalising_scale(&[[m, -m / 3.0]]);
            let scaled = m * s;
            assert!(s.is_finite());
            if m > 1e-307 {
                assert!(
                    (1.0..2.0).contains(&scaled),
                    "{m} scaled by {s} gives {scaled}"
                );
            } else {
                assert!(
                    scaled > 1e-4,
                    "subnormal {m} only partly rescaled: {scaled}"
                );
            }
        }
        assert_eq!(normalising_scale(&[]), 1.0);
        assert_eq!(normalising_scale(&[[0.0, 0.0]]), 1.0);
    }
}
