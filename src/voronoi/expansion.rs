//! Exact floating-point arithmetic on sums of doubles (Shewchuk's expansions): error-free
//! two-sum, two-difference and two-product, and the exact sign or a faithful value of a sum of
//! many terms. Used where a floating-point filter cannot decide (distance comparisons) or cannot
//! guarantee accuracy (circumcentres of nearly flat triangles).

/// `a - b` as a non-overlapping pair `(rounded, error)`.
#[inline]
pub(crate) fn two_diff(a: f64, b: f64) -> (f64, f64) {
    let x = a - b;
    let b_virtual = a - x;
    let a_virtual = x + b_virtual;
    (x, (a - a_virtual) + (b_virtual - b))
}

/// `a + b` as a non-overlapping pair `(rounded, error)`.
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let b_virtual = x - a;
    let a_virtual = x - b_virtual;
    (x, (a - a_virtual) + (b - b_virtual))
}

/// `a · b` as `(rounded, error)`, exact through a fused multiply-add.
#[inline]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let x = a * b;
    (x, a.mul_add(b, -x))
}

/// The exact sum of `terms` as a non-overlapping expansion, smallest component first, zeros
/// dropped (Shewchuk's grow-expansion with zero elimination, one term at a time).
pub(crate) fn nonoverlapping(terms: &[f64]) -> Vec<f64> {
    let mut expansion: Vec<f64> = Vec::with_capacity(terms.len());
    let mut grown = Vec::with_capacity(terms.len());
    for &t in terms {
        let mut carry = t;
        grown.clear();
        for &e in &expansion {
            let (sum, err) = two_sum(carry, e);
            if err != 0.0 {
                grown.push(err);
            }
            carry = sum;
        }
        if carry != 0.0 {
            grown.push(carry);
        }
        std::mem::swap(&mut expansion, &mut grown);
    }
    expansion
}

/// Exact sign (−1, 0 or 1) of the sum of `terms`.
pub(crate) fn sign_of_sum(terms: &[f64]) -> f64 {
    // The last component of a non-overlapping expansion dominates the others.
    nonoverlapping(terms).last().map_or(0.0, |&x| x.signum())
}

/// The sum of `terms` to within about one ulp: the exact expansion, added up from its smallest
/// component, so every rounding is far below the largest one.
pub(crate) fn faithful_sum(terms: &[f64]) -> f64 {
    nonoverlapping(terms).iter().sum()
}

/// A real number held exactly as an unevaluated sum of doubles. Products and differences stay
/// exact (they only grow the list); [`Exact::value`] rounds once at the end.
#[derive(Clone, Debug, Default)]
pub(crate) struct Exact(pub(crate) Vec<f64>);

impl Exact {
    /// `a - b`, exactly.
    pub(crate) fn difference(a: f64, b: f64) -> Self {
        let (h, l) = two_diff(a, b);
        Exact(vec![h, l])
    }

    /// `self · other`, exactly: every pair of terms as a two-product.
    pub(crate) fn times(&self, other: &Exact) -> Exact {
        let mut terms = Vec::with_capacity(2 * self.0.len() * other.0.len());
        for &x in &self.0 {
            for &y in &other.0 {
                let (h, l) = two_product(x, y);
                terms.push(h);
                terms.push(l);
            }
        }
        Exact(terms)
    }

    /// `self + other`, exactly.
    pub(crate) fn plus(&self, other: &Exact) -> Exact {
        Exact([&self.0[..], &other.0[..]].concat())
    }

    /// `self - other`, exactly.
    pub(crate) fn minus(&self, other: &Exact) -> Exact {
        Exact(
            self.0
                .iter()
                .copied()
                .chain(other.0.iter().map(|&t| -t))
                .collect(),
        )
    }

    /// The value, faithfully rounded (see [`faithful_sum`]).
    pub(crate) fn value(&self) -> f64 {
        faithful_sum(&self.0)
    }

    /// The same number with its terms compressed to a non-overlapping expansion, so that further
    /// products do not multiply the term count needlessly.
    pub(crate) fn compressed(self) -> Exact {
        Exact(nonoverlapping(&self.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faithful_sum_survives_total_cancellation() {
        let big = 1e300;
        assert_eq!(
            faithful_sum(&[big, 1.0, -big, 2.0f64.powi(-60)]),
            1.0 + 2.0f64.powi(-60)
        );
        assert_eq!(sign_of_sum(&[0.1, -0.1]), 0.0);
    }

    #[test]
    fn products_and_differences_are_exact() {
        // (1 + 2^-52)^2 - 1 = 2^-51 + 2^-104: lost entirely by plain doubles after the square.
        let x = Exact(vec![1.0, f64::EPSILON]);
        let value = x.times(&x).minus(&Exact(vec![1.0])).value();
        assert_eq!(value, 2.0 * f64::EPSILON + f64::EPSILON * f64::EPSILON);
        assert_eq!(
            Exact::difference(0.3, 0.1).plus(&Exact(vec![-0.2])).value(),
            {
                // 0.3 - 0.1 - 0.2 in exact arithmetic on the doubles nearest each decimal.
                faithful_sum(&[0.3, -0.1, -0.2])
            }
        );
    }
}
