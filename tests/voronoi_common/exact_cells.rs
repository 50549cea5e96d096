//! Which clipped Voronoi cells have an interior, decided without rounding: the region is cut by
//! the half-planes nearer to a site than to each of its neighbours, with every line in integers
//! of any size (the doubles' common power of two taken out) and every corner of the cut polygon
//! kept as the pair of lines that meet there, so that no coordinate is ever rounded.

use std::cmp::Ordering;

/// A signed integer of any size: magnitude in 32-bit limbs, least significant first, without
/// trailing zero limbs (zero has none and is not negative).
#[derive(Clone, Debug)]
struct Integer {
    negative: bool,
    limbs: Vec<u32>,
}

impl Integer {
    fn new(negative: bool, mut limbs: Vec<u32>) -> Integer {
        while limbs.last() == Some(&0) {
            limbs.pop();
        }
        let negative = negative && !limbs.is_empty();
        Integer { negative, limbs }
    }

    /// `(-1)^negative · mantissa · 2^shift`.
    fn from_dyadic(negative: bool, mantissa: u64, shift: u32) -> Integer {
        let mut limbs = vec![0u32; (shift / 32) as usize];
        let wide = (mantissa as u128) << (shift % 32);
        limbs.extend((0..4).map(|k| (wide >> (32 * k)) as u32));
        Integer::new(negative, limbs)
    }

    fn signum(&self) -> i32 {
        match (self.limbs.is_empty(), self.negative) {
            (true, _) => 0,
            (false, true) => -1,
            (false, false) => 1,
        }
    }

    fn add(&self, other: &Integer) -> Integer {
        if self.negative == other.negative {
            return Integer::new(self.negative, add_magnitudes(&self.limbs, &other.limbs));
        }
        match compare_magnitudes(&self.limbs, &other.limbs) {
            Ordering::Less => Integer::new(
                other.negative,
                subtract_magnitudes(&other.limbs, &self.limbs),
            ),
            _ => Integer::new(
                self.negative,
                subtract_magnitudes(&self.limbs, &other.limbs),
            ),
        }
    }

    fn negated(&self) -> Integer {
        Integer::new(!self.negative, self.limbs.clone())
    }

    fn sub(&self, other: &Integer) -> Integer {
        self.add(&other.negated())
    }

    fn mul(&self, other: &Integer) -> Integer {
        let mut limbs = vec![0u32; self.limbs.len() + other.limbs.len()];
        for (i, &a) in self.limbs.iter().enumerate() {
            let mut carry = 0u64;
            for (j, &b) in other.limbs.iter().enumerate() {
                let t = limbs[i + j] as u64 + a as u64 * b as u64 + carry;
                limbs[i + j] = t as u32;
                carry = t >> 32;
            }
            limbs[i + other.limbs.len()] = carry as u32;
        }
        Integer::new(self.negative != other.negative, limbs)
    }

    /// `log2 |self|` (`-inf` for zero), from its two leading limbs.
    fn log2(&self) -> f64 {
        let n = self.limbs.len();
        let leading = self.limbs[n.saturating_sub(2)..]
            .iter()
            .rev()
            .fold(0.0, |value, &limb| value * 4294967296.0 + limb as f64);
        leading.log2() + 32.0 * n.saturating_sub(2) as f64
    }
}

fn compare_magnitudes(a: &[u32], b: &[u32]) -> Ordering {
    a.len()
        .cmp(&b.len())
        .then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_magnitudes(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(a.len().max(b.len()) + 1);
    let mut carry = 0u64;
    for k in 0..a.len().max(b.len()) {
        let t = *a.get(k).unwrap_or(&0) as u64 + *b.get(k).unwrap_or(&0) as u64 + carry;
        out.push(t as u32);
        carry = t >> 32;
    }
    out.push(carry as u32);
    out
}

/// `a - b` for `|a| >= |b|`.
fn subtract_magnitudes(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(a.len());
    let mut borrow = 0i64;
    for (k, &x) in a.iter().enumerate() {
        let mut t = x as i64 - *b.get(k).unwrap_or(&0) as i64 - borrow;
        borrow = 0;
        if t < 0 {
            t += 1 << 32;
            borrow = 1;
        }
        out.push(t as u32);
    }
    out
}

/// The open half-plane `a·x + b·y + c > 0`.
#[derive(Clone, Debug)]
struct Line {
    a: Integer,
    b: Integer,
    c: Integer,
}

/// The sign of `line` at the point where `first` and `second` meet (0 where they are parallel).
fn side(line: &Line, first: &Line, second: &Line) -> i32 {
    let x = first.b.mul(&second.c).sub(&second.b.mul(&first.c));
    let y = first.c.mul(&second.a).sub(&second.c.mul(&first.a));
    let w = first.a.mul(&second.b).sub(&second.a.mul(&first.b));
    let value = line.a.mul(&x).add(&line.b.mul(&y)).add(&line.c.mul(&w));
    value.signum() * w.signum()
}

/// Points of one problem as integers: every coordinate times the same power of two.
pub struct ExactPlane {
    sites: Vec<[Integer; 2]>,
    corners: Vec<[Integer; 2]>,
    /// Every integer is its double divided by `2^unit`.
    unit: i32,
}

/// A finite `x` as `±mantissa · 2^exponent`.
fn dyadic(x: f64) -> (bool, u64, i32) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    let (mantissa, exponent) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    (bits >> 63 == 1, mantissa, exponent)
}

impl ExactPlane {
    /// The sites and the corners (counter-clockwise) of a convex region.
    pub fn new(sites: &[[f64; 2]], corners: &[[f64; 2]]) -> ExactPlane {
        let unit = sites
            .iter()
            .chain(corners)
            .flatten()
            .map(|&x| dyadic(x))
            .filter(|&(_, mantissa, _)| mantissa != 0)
            .map(|(_, _, exponent)| exponent)
            .min()
            .unwrap_or(0);
        let integer = |x: f64| {
            let (negative, mantissa, exponent) = dyadic(x);
            let shift = if mantissa == 0 { 0 } else { exponent - unit };
            Integer::from_dyadic(negative, mantissa, shift as u32)
        };
        let points = |list: &[[f64; 2]]| list.iter().map(|p| p.map(integer)).collect();
        ExactPlane {
            sites: points(sites),
            corners: points(corners),
            unit,
        }
    }

    /// `log2 |orient2d(a, b, c)|` of sites `a`, `b`, `c` from the exact determinant (the
    /// predicate's value only has the right sign: it may be scaled, or rounded to a subnormal).
    pub fn log2_orientation(&self, [a, b, c]: [usize; 3]) -> f64 {
        let [[ax, ay], [bx, by], [cx, cy]] = [a, b, c].map(|k| &self.sites[k]);
        let determinant = bx
            .sub(ax)
            .mul(&cy.sub(ay))
            .sub(&by.sub(ay).mul(&cx.sub(ax)));
        determinant.log2() + 2.0 * self.unit as f64
    }

    /// Does the part of the region strictly nearer to `site` than to every site of `others`
    /// have an interior? (With the site's Delaunay neighbours as `others`, that part is its
    /// clipped cell.)
    pub fn cell_has_interior(&self, site: usize, others: impl IntoIterator<Item = usize>) -> bool {
        let m = self.corners.len();
        let mut lines: Vec<Line> = (0..m)
            .map(|i| {
                let ([px, py], [qx, qy]) = (&self.corners[i], &self.corners[(i + 1) % m]);
                Line {
                    a: py.sub(qy),
                    b: qx.sub(px),
                    c: px.mul(qy).sub(&py.mul(qx)),
                }
            })
            .collect();
        // The polygon as its sides' lines, counter-clockwise: corner `k` is where side `k - 1`
        // meets side `k`.
        let mut polygon: Vec<usize> = (0..m).collect();
        let [sx, sy] = &self.sites[site];
        for other in others {
            let [tx, ty] = &self.sites[other];
            let squared = |x: &Integer, y: &Integer| x.mul(x).add(&y.mul(y));
            let two = Integer::from_dyadic(false, 2, 0);
            lines.push(Line {
                a: two.mul(&sx.sub(tx)),
                b: two.mul(&sy.sub(ty)),
                c: squared(tx, ty).sub(&squared(sx, sy)),
            });
            let cut = lines.len() - 1;
            let n = polygon.len();
            let signs: Vec<i32> = (0..n)
                .map(|k| {
                    let (before, after) = (polygon[(k + n - 1) % n], polygon[k]);
                    side(&lines[cut], &lines[before], &lines[after])
                })
                .collect();
            if signs.iter().all(|&s| s <= 0) {
                return false;
            }
            if signs.iter().all(|&s| s > 0) {
                continue;
            }
            let mut kept = Vec::with_capacity(n + 1);
            for k in 0..n {
                let (start, end) = (signs[k] > 0, signs[(k + 1) % n] > 0);
                if start || end {
                    kept.push(polygon[k]);
                }
                if start && !end {
                    kept.push(cut);
                }
            }
            polygon = kept;
        }
        true
    }
}
