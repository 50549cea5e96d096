//! Integers of any size, for the exact orientation signs of points whose coordinates span more
//! binary orders of magnitude than the adaptive floating-point predicates can take in one call.
//!
//! Only what a determinant needs: sums, differences, products and the sign. Every `f64` is an
//! integer times a power of two, so the coordinates of one call become integers once multiplied
//! by the power of two of their smallest unit ([`WideInteger::from_dyadic`]).

use crate::voronoi::predicates::pow2;
use std::cmp::Ordering;

/// A signed integer as sign and magnitude; the magnitude is little-endian 32-bit limbs with no
/// trailing zero limb (zero has none, and is never negative).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct WideInteger {
    negative: bool,
    limbs: Vec<u32>,
}

impl WideInteger {
    /// `±mantissa · 2^shift`, negative when `negative` (and `mantissa` is not 0).
    pub(crate) fn from_dyadic(negative: bool, mantissa: u64, shift: u32) -> Self {
        let whole_limbs = (shift / 32) as usize;
        let bits = shift % 32;
        let mut limbs = vec![0; whole_limbs];
        // The mantissa shifted by `bits` needs at most 96 bits: three limbs.
        let shifted = u128::from(mantissa) << bits;
        limbs.extend([
            shifted as u32,
            (shifted >> 32) as u32,
            (shifted >> 64) as u32,
        ]);
        let mut number = WideInteger { negative, limbs };
        number.normalise();
        number
    }

    /// -1, 0 or 1 as the number is negative, zero or positive.
    pub(crate) fn signum(&self) -> i32 {
        match (self.limbs.is_empty(), self.negative) {
            (true, _) => 0,
            (false, true) => -1,
            (false, false) => 1,
        }
    }

    /// `self + other`.
    pub(crate) fn add(&self, other: &WideInteger) -> WideInteger {
        if self.negative == other.negative {
            let mut sum = WideInteger {
                negative: self.negative,
                limbs: add_magnitudes(&self.limbs, &other.limbs),
            };
            sum.normalise();
            return sum;
        }
        // Opposite signs: the larger magnitude keeps its sign.
        let (larger, smaller) = match compare_magnitudes(&self.limbs, &other.limbs) {
            Ordering::Equal => return WideInteger::default(),
            Ordering::Greater => (self, other),
            Ordering::Less => (other, self),
        };
        let mut difference = WideInteger {
            negative: larger.negative,
            limbs: subtract_magnitudes(&larger.limbs, &smaller.limbs),
        };
        difference.normalise();
        difference
    }

    /// `self - other`.
    pub(crate) fn sub(&self, other: &WideInteger) -> WideInteger {
        self.add(&other.negated())
    }

    /// `self · other`.
    pub(crate) fn mul(&self, other: &WideInteger) -> WideInteger {
        if self.limbs.is_empty() || other.limbs.is_empty() {
            return WideInteger::default();
        }
        let mut limbs = vec![0u32; self.limbs.len() + other.limbs.len()];
        for (i, &a) in self.limbs.iter().enumerate() {
            let mut carry = 0u64;
            for (j, &b) in other.limbs.iter().enumerate() {
                // a·b + limb + carry < 2^64: (2^32 - 1)^2 + 2 (2^32 - 1) = 2^64 - 1.
                let total = u64::from(a) * u64::from(b) + u64::from(limbs[i + j]) + carry;
                limbs[i + j] = total as u32;
                carry = total >> 32;
            }
            limbs[i + other.limbs.len()] = carry as u32;
        }
        let mut product = WideInteger {
            negative: self.negative != other.negative,
            limbs,
        };
        product.normalise();
        product
    }

    /// The number as `(m, e)` with `self ≈ m · 2^e`: `m` holds its top 65 to 96 bits, so the
    /// relative error is below `2^-52` once rounded to a double; `(0.0, 0)` for zero.
    pub(crate) fn to_float_parts(&self) -> (f64, i64) {
        let n = self.limbs.len();
        let take = n.min(3);
        let top = self.limbs[n - take..]
            .iter()
            .rev()
            .fold(0u128, |top, &limb| (top << 32) | u128::from(limb));
        let magnitude = top as f64;
        let exponent = 32 * (n - take) as i64;
        (if self.negative { -magnitude } else { magnitude }, exponent)
    }

    /// `self / denominator · 2^exponent` as a double: the quotient of the two numbers' leading
    /// bits (each within `2^-64` of its own value), scaled by powers of two in steps that stay
    /// representable, so within about two ulps of the exact value (0 or infinity beyond
    /// doubles). `denominator` is not zero.
    pub(crate) fn ratio(&self, denominator: &WideInteger, exponent: i64) -> f64 {
        let (mantissa, own_exponent) = self.to_float_parts();
        let (divisor, divisor_exponent) = denominator.to_float_parts();
        let mut value = mantissa / divisor;
        let mut shift = own_exponent - divisor_exponent + exponent;
        while shift != 0 && value != 0.0 && value.is_finite() {
            let step = shift.clamp(-1000, 1000);
            value *= pow2(step as i32);
            shift -= step;
        }
        value
    }

    /// `|self|`.
    pub(crate) fn abs(&self) -> WideInteger {
        WideInteger {
            negative: false,
            limbs: self.limbs.clone(),
        }
    }

    fn negated(&self) -> WideInteger {
        WideInteger {
            negative: !self.negative && !self.limbs.is_empty(),
            limbs: self.limbs.clone(),
        }
    }

    /// Drops trailing zero limbs; zero is not negative.
    fn normalise(&mut self) {
        while self.limbs.last() == Some(&0) {
            self.limbs.pop();
        }
        if self.limbs.is_empty() {
            self.negative = false;
        }
    }
}

fn compare_magnitudes(a: &[u32], b: &[u32]) -> Ordering {
    // Normalised magnitudes: the longer one is larger.
    a.len()
        .cmp(&b.len())
        .then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_magnitudes(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    let mut sum = Vec::with_capacity(long.len() + 1);
    let mut carry = 0u64;
    for (i, &limb) in long.iter().enumerate() {
        let total = u64::from(limb) + u64::from(short.get(i).copied().unwrap_or(0)) + carry;
        sum.push(total as u32);
        carry = total >> 32;
    }
    sum.push(carry as u32);
    sum
}

/// `a - b` for magnitudes with `a >= b`.
fn subtract_magnitudes(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut difference = Vec::with_capacity(a.len());
    let mut borrow = 0i64;
    for (i, &limb) in a.iter().enumerate() {
        let mut total = i64::from(limb) - i64::from(b.get(i).copied().unwrap_or(0)) - borrow;
        borrow = i64::from(total < 0);
        total += borrow << 32;
        difference.push(total as u32);
    }
    debug_assert_eq!(borrow, 0, "the larger magnitude comes first");
    difference
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wide(value: i128) -> WideInteger {
        let magnitude = value.unsigned_abs();
        let low = WideInteger::from_dyadic(value < 0, magnitude as u64, 0);
        let high = WideInteger::from_dyadic(value < 0, (magnitude >> 64) as u64, 64);
        low.add(&high)
    }

    fn value(number: &WideInteger) -> i128 {
        let magnitude = number
            .limbs
            .iter()
            .rev()
            .fold(0i128, |total, &limb| (total << 32) | i128::from(limb));
        if number.negative {
            -magnitude
        } else {
            magnitude
        }
    }

    #[test]
    fn arithmetic_agrees_with_i128_across_signs_and_carries() {
        let samples: [i128; 12] = [
            0,
            1,
            -1,
            u32::MAX as i128,
            -(u32::MAX as i128) - 1,
            1 << 32,
            u64::MAX as i128,
            -(u64::MAX as i128),
            (1 << 62) + 12345,
            -(1 << 61) + 7,
            0x1234_5678_9abc_def0,
            -0x0fed_cba9_8765_4321,
        ];
        for &a in &samples {
            for &b in &samples {
                let (x, y) = (wide(a), wide(b));
                assert_eq!(value(&x.add(&y)), a + b, "{a} + {b}");
                assert_eq!(value(&x.sub(&y)), a - b, "{a} - {b}");
                assert_eq!(x.sub(&y).signum(), (a - b).signum() as i32, "{a} - {b}");
                if let Some(product) = a.checked_mul(b) {
                    assert_eq!(value(&x.mul(&y)), product, "{a} * {b}");
                }
            }
        }
    }

    #[test]
    fn zero_is_never_negative_and_shifts_reach_any_size() {
        let x = WideInteger::from_dyadic(true, 5, 0);
        assert_eq!(x.sub(&x), WideInteger::default());
        assert_eq!(WideInteger::from_dyadic(true, 0, 77).signum(), 0);
        // 2^2000 - 2^2000 + 1 = 1, through magnitudes of 63 limbs.
        let big = WideInteger::from_dyadic(false, 1, 2000);
        let one = WideInteger::from_dyadic(false, 1, 0);
        assert_eq!(big.add(&one).sub(&big), one);
        // (2^1000 + 1)(2^1000 - 1) = 2^2000 - 1 > 0, and less than 2^2000.
        let p = WideInteger::from_dyadic(false, 1, 1000);
        let square_less_one = p.add(&one).mul(&p.sub(&one));
        assert_eq!(square_less_one.signum(), 1);
        assert_eq!(square_less_one.sub(&big).signum(), -1);
        assert_eq!(square_less_one.add(&one), big);
    }
}
