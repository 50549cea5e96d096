//! Exact geometric predicates (Shewchuk's adaptive arithmetic through the `robust` crate) and the
//! power-of-two rescaling that keeps them exact for very large and very small coordinates.

use robust::Coord;

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

/// Orientation of the triangle `a, b, c`: positive when counter-clockwise (`c` left of `a → b`),
/// negative when clockwise, exactly zero when collinear.
///
/// Evaluation: the floating-point determinant when its error bound decides the sign; otherwise
/// the same determinant when the coordinate differences lie on a coarse power-of-two lattice that
/// makes it exact (integer grids: their many exact zeros would all need the slow path); otherwise
/// Shewchuk's adaptive exact arithmetic.
#[inline(always)]
pub fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (acx, acy, bcx, bcy) = (a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]);
    let left = acx * bcy;
    let right = acy * bcx;
    let det = left - right;
    if (det).abs() > ORIENT_BOUND * (left.abs() + right.abs()) {
        return det;
    }
    orient2d_slow(a, b, c, det)
}

#[cold]
fn orient2d_slow(a: [f64; 2], b: [f64; 2], c: [f64; 2], det: f64) -> f64 {
    if on_small_lattice([(a[0], c[0]), (a[1], c[1]), (b[0], c[0]), (b[1], c[1])], 25) {
        return det;
    }
    robust::orient2d(coord(a), coord(b), coord(c))
}

/// In-circle test: for a counter-clockwise triangle `a, b, c`, positive when `d` lies strictly
/// inside its circumcircle, negative when strictly outside, exactly zero when the four points are
/// cocircular. (For a clockwise triangle the sign flips.) Evaluated like [`orient2d`].
#[inline(always)]
pub fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    incircle_in_set(a, b, c, d, f64::INFINITY)
}

/// [`incircle`] for four points of a set whose [`incircle_set_bound`] is `set_bound`: a
/// determinant above that bound is decided before the per-call error bound is computed (a third
/// of the filter's instructions, and most calls of a construction need no more).
#[inline(always)]
pub fn incircle_in_set(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2], set_bound: f64) -> f64 {
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
    if det.abs() > set_bound {
        return det;
    }
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    if det.abs() > INCIRCLE_BOUND * permanent {
        return det;
    }
    incircle_slow(a, b, c, d, det)
}

/// An error bound of the floating-point in-circle determinant that holds for any four points
/// inside the box `[min, max]`: Shewchuk's bound is `INCIRCLE_BOUND` times the determinant's
/// permanent, and when no coordinate difference exceeds `w` in magnitude the permanent is at most
/// `12 w^4` (each of its three terms is two products of differences, `<= 2 w^2`, times a squared
/// length, `<= 2 w^2`). `w` is the box's larger side, rounded up, and the bound is rounded up
/// once more for its own evaluation, which is monotone in `w` as the permanent's is in the
/// differences.
pub fn incircle_set_bound([min, max]: [[f64; 2]; 2]) -> f64 {
    let w = (max[0] - min[0]).max(max[1] - min[1]) * (1.0 + 4.0 * f64::EPSILON);
    let bound = INCIRCLE_BOUND * 12.0 * (w * w) * (w * w) * (1.0 + 64.0 * f64::EPSILON);
    // An empty or unbounded box: no set bound, every call takes the per-call filter.
    if bound.is_finite() {
        bound
    } else {
        f64::INFINITY
    }
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
    if on_small_lattice(diffs, 12) {
        return det;
    }
    robust::incircle(coord(a), coord(b), coord(c), coord(d))
}

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
        // Exactness of the subtraction (Dekker/Knuth two-difference error term is zero).
        let y_virtual = x - d;
        let x_virtual = d + y_virtual;
        inexact |= (x - x_virtual) + (y_virtual - y) != 0.0;
        let size = d.abs();
        largest = if size > largest { size } else { largest };
    }
    if inexact {
        return false;
    }
    if largest == 0.0 {
        return true;
    }
    // u = 2^(e + 1 - bits) where 2^e <= largest < 2^(e+1).
    let biased_exponent = ((largest.to_bits() >> 52) & 0x7ff) as i32;
    let unit_exponent = biased_exponent - 1023 + 1 - bits;
    if !(-240..=240).contains(&unit_exponent) || biased_exponent == 0 {
        return false;
    }
    // 2^-unit_exponent, a normal number (the range check above), built from its bits: `pow2`
    // would call the software `powi`.
    let inverse_unit = f64::from_bits(((1023 - unit_exponent) as u64) << 52);
    // Every `units` is below 2^bits ≤ 2^25 in magnitude (exact: a power-of-two multiple of
    // `d`), so adding and subtracting 1.5·2^52 rounds it to the nearest integer exactly: it is an
    // integer when that changes nothing (`trunc` is a library call on baseline x86-64).
    const ROUND: f64 = 6_755_399_441_055_744.0;
    let mut off_lattice = false;
    for d in diffs {
        let units = d * inverse_unit;
        off_lattice |= (units + ROUND) - ROUND != units;
    }
    !off_lattice
}

/// The power of two by which sites are multiplied before any predicate is evaluated, so that
/// the largest coordinate magnitude lies in `[1, 2)`.
///
/// The adaptive predicates are exact only when no intermediate product overflows or underflows;
/// the in-circle determinant is of degree four, so inputs near `1e+200` or `1e-300` would break
/// it. Scaling by a power of two is exact (barring underflow of individual coordinates) and does
/// not change any orientation or in-circle sign.
pub fn normalising_scale(points: &[[f64; 2]]) -> f64 {
    let max_abs = points
        .iter()
        .flat_map(|p| [p[0].abs(), p[1].abs()])
        .fold(0.0_f64, f64::max);
    if max_abs == 0.0 || !max_abs.is_finite() {
        return 1.0;
    }
    // Exponent of max_abs without relying on bit tricks: frexp-like via log2 then correction.
    let mut exponent = max_abs.log2().floor() as i32;
    // Guard against log2 rounding at exact powers of two.
    if pow2(exponent) > max_abs {
        exponent -= 1;
    } else if pow2(exponent + 1) <= max_abs {
        exponent += 1;
    }
    // Keep the scale itself representable; subnormal inputs are brought as close as possible.
    pow2((-exponent).clamp(f64::MIN_EXP - 1, f64::MAX_EXP - 1))
}

/// `2^e` for any exponent a finite f64 can represent (including subnormal results).
pub fn pow2(e: i32) -> f64 {
    // powi is exact for powers of two as long as intermediate results stay representable; split
    // the exponent so that neither half overflows or underflows on its own.
    let half = e / 2;
    2.0_f64.powi(half) * 2.0_f64.powi(e - half)
}

#[cfg(test)]
mod tests {
    use super::super::spatial_sort;
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

    #[test]
    fn set_bound_agrees_with_adaptive_arithmetic() {
        // Points near one circle (rounded, so cocircular only up to an ulp or so: determinants
        // on both sides of the set bound), and random points, in boxes of several sizes.
        let mut state = 7_u64;
        let mut random = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let coord = |p: [f64; 2]| Coord { x: p[0], y: p[1] };
        for scale in [1.0, 0.75, 2.0_f64.powi(-20)] {
            let mut pts: Vec<[f64; 2]> = (0..40)
                .map(|_| {
                    let t = random() * std::f64::consts::TAU;
                    [scale * (0.5 + 0.5 * t.cos()), scale * (0.5 + 0.5 * t.sin())]
                })
                .collect();
            pts.extend((0..20).map(|_| [scale * random(), scale * random()]));
            let bound = incircle_set_bound(spatial_sort::bounding_box(&pts));
            assert!(bound > 0.0 && bound.is_finite());
            let (mut decided_by_set, mut total) = (0, 0);
            for a in pts.iter().step_by(3) {
                for b in pts.iter().skip(1).step_by(4) {
                    for c in pts.iter().skip(2).step_by(5) {
                        for &d in &pts {
                            let exact = robust::incircle(coord(*a), coord(*b), coord(*c), coord(d));
                            let mine = incircle_in_set(*a, *b, *c, d, bound);
                            assert_eq!((mine > 0.0, mine < 0.0), (exact > 0.0, exact < 0.0));
                            total += 1;
                            decided_by_set += usize::from(mine.abs() > bound);
                        }
                    }
                }
            }
            // The set bound decides most calls, and not all (the near-circle quadruples).
            assert!(
                decided_by_set > total / 2 && decided_by_set < total,
                "{decided_by_set}/{total}"
            );
        }
        let empty = spatial_sort::bounding_box(&[]);
        assert_eq!(incircle_set_bound(empty), f64::INFINITY);
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
