//! The side of the plane of a triangle on which points lie, for several points against one
//! triangle: the orientation determinant expanded along the point's row, so that the triangle's
//! minors are computed once, with a floating-point filter whose error bound is proven below, and
//! the exact predicate when the filter cannot decide.

use super::exact_orientation::{ExactOrientation, Point, Sign};

/// Relative error bound of [`TrianglePlane::side`]'s floating-point determinant (see there).
const FILTER_BOUND: f64 = 10.0 * (f64::EPSILON / 2.0);

/// A triangle and the minors of its edge vectors from its first corner.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TrianglePlane<'t> {
    corners: &'t [Point; 3],
    /// `(t1 - t0) × (t2 - t0)`, in floating point.
    normal: [f64; 3],
    /// For each component of `normal`, the sum of the magnitudes of its two products.
    magnitudes: [f64; 3],
}

impl<'t> TrianglePlane<'t> {
    #[inline(always)]
    pub(crate) fn new(corners: &'t [Point; 3]) -> TrianglePlane<'t> {
        let [t0, t1, t2] = *corners;
        let u = [t1[0] - t0[0], t1[1] - t0[1], t1[2] - t0[2]];
        let v = [t2[0] - t0[0], t2[1] - t0[1], t2[2] - t0[2]];
        let mut normal = [0.0; 3];
        let mut magnitudes = [0.0; 3];
        for (k, (i, j)) in [(1, 2), (2, 0), (0, 1)].into_iter().enumerate() {
            let (plus, minus) = (u[i] * v[j], u[j] * v[i]);
            normal[k] = plus - minus;
            magnitudes[k] = plus.abs() + minus.abs();
        }
        TrianglePlane {
            corners,
            normal,
            magnitudes,
        }
    }

    /// The sign of `arithmetic.orient3d(t0, t1, t2, p)` for the triangle's corners `t0, t1, t2`.
    ///
    /// That determinant is `-D` for `D = w · n`, `w = p - t0` and `n = (t1 - t0) × (t2 - t0)`.
    /// With `ε = 2^-53` and every value normal (which the adaptive arithmetic's range ensures:
    /// products of up to three coordinate differences stay far from underflow and overflow),
    /// each computed difference carries a relative error of at most `ε`, each computed
    /// component `n_k` differs from the exact one by at most `γ4 Q_k` (`Q_k` the sum of the
    /// magnitudes of its two exact products, `γn = nε / (1 - nε)`), and the computed sum of the
    /// three `w_k n_k` carries at most `γ4` more on each term: the computed `D` is within
    /// `γ4 (2 + γ4) Σ |W_k| Q_k ≈ 8ε Σ |W_k| Q_k` of the exact one. The computed permanent
    /// `Σ |w_k| q_k` falls short of `Σ |W_k| Q_k` by a factor of at most `1 - γ8`, so ten `ε`
    /// times it bounds the error: beyond it, the computed sign is the exact sign.
    #[inline(always)]
    pub(crate) fn side(&self, arithmetic: ExactOrientation, p: Point) -> Sign {
        if arithmetic == ExactOrientation::Adaptive {
            let t0 = self.corners[0];
            let w = [p[0] - t0[0], p[1] - t0[1], p[2] - t0[2]];
            let n = self.normal;
            let m = self.magnitudes;
            let along_normal = (w[0] * n[0] + w[1] * n[1]) + w[2] * n[2];
            let permanent = (w[0].abs() * m[0] + w[1].abs() * m[1]) + w[2].abs() * m[2];
            let bound = FILTER_BOUND * permanent;
            if along_normal > bound {
                return Sign::Negative;
            }
            if -along_normal > bound {
                return Sign::Positive;
            }
        }
        self.exact_side(arithmetic, p)
    }

    /// [`TrianglePlane::side`] when the filter cannot decide: near the plane, or in integer
    /// arithmetic.
    #[cold]
    #[inline(never)]
    fn exact_side(&self, arithmetic: ExactOrientation, p: Point) -> Sign {
        let [t0, t1, t2] = *self.corners;
        arithmetic.orient3d(t0, t1, t2, p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on, and within a few ulps of, the planes of random triangles (where the filter
    /// must give up), and far from them (where it decides): always the exact predicate's sign.
    #[test]
    fn sides_agree_with_the_exact_predicate_near_and_far_from_the_plane() {
        let mut uniform = crate::support::test_random::uniform(0x9e37_79b9_7f4a_7c15);
        let mut next = move || 2.0 * uniform() - 1.0;
        let mut zeros = 0;
        for _ in 0..20_000 {
            // Few significant bits: the point on the plane is computed exactly.
            let mut grid = |steps: f64| (next() * steps).round() / steps;
            let t = [(); 3].map(|_| [grid(1024.0), grid(1024.0), grid(1024.0)]);
            let plane = TrianglePlane::new(&t);
            let (s, r) = (grid(16.0), grid(16.0));
            // On the plane, then nudged by a few ulps, or moved well off it.
            let on = [0, 1, 2].map(|k| t[0][k] + s * (t[1][k] - t[0][k]) + r * (t[2][k] - t[0][k]));
            let nudge = (next() * 4.0).round();
            let near = on.map(|x| x + nudge * f64::EPSILON * x.abs());
            let far = [on[0] + next(), on[1] + next(), on[2] + next()];
            for p in [on, near, far, t[0], t[1], t[2]] {
                let exact = ExactOrientation::Adaptive.orient3d(t[0], t[1], t[2], p);
                assert_eq!(
                    plane.side(ExactOrientation::Adaptive, p),
                    exact,
                    "{t:?} {p:?}"
                );
                assert_eq!(plane.side(ExactOrientation::Wide, p), exact);
                zeros += usize::from(exact == Sign::Zero);
            }
        }
        // The corners and the points on the plane, at least.
        assert!(zeros >= 4 * 20_000, "{zeros}");
    }
}
