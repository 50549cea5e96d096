//! Exact geometric predicates (Shewchuk's adaptive arithmetic through the `robust` crate) and the
//! power-of-two rescaling that keeps them exact for very large and very small coordinates.

use robust::Coord;

#[inline(always)]
fn coord(p: [f64; 2]) -> Coord<f64> {
    Coord { x: p[0], y: p[1] }
}

/// Orientation of the triangle `a, b, c`: positive when counter-clockwise (`c` left of `a → b`),
/// negative when clockwise, exactly zero when collinear.
#[inline(always)]
pub fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    robust::orient2d(coord(a), coord(b), coord(c))
}

/// In-circle test: for a counter-clockwise triangle `a, b, c`, positive when `d` lies strictly
/// inside its circumcircle, negative when strictly outside, exactly zero when the four points are
/// cocircular. (For a clockwise triangle the sign flips.)
#[inline(always)]
pub fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    robust::incircle(coord(a), coord(b), coord(c), coord(d))
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
