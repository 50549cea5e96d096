//! Insertion order for incremental Delaunay construction: a biased randomised insertion order
//! (BRIO, Amenta–Choi–Rote 2003) whose rounds are each sorted along a Hilbert curve.
//!
//! The Hilbert order keeps consecutive insertions close together, so the walking point location
//! of the next site starts next to its target; the rounds (a random half of the sites in the last
//! round, a quarter in the one before, ...) keep the expected work linear even for adversarial
//! inputs such as points on a parabola, where a pure space-filling-curve order degrades. The
//! randomness is a fixed hash of the site index, so results are reproducible.

use super::parallel::map_indexed;
use crate::support::radix_sort::radix_sort_by_high_word;

/// Bits per axis of the Hilbert grid (the sort key packs `2 × 14` Hilbert bits and 4 round bits
/// into 32 bits; ties inside one of the `2^28` cells keep index order).
const HILBERT_BITS: u32 = 14;
/// Most BRIO rounds the key can express.
const MAX_ROUNDS: u32 = 16;
/// Sites in the first round when there are enough of them.
const FIRST_ROUND_SIZE: usize = 64;

/// The smallest and largest coordinate of `points` on each axis (infinities when empty).
pub fn bounding_box(points: &[[f64; 2]]) -> [[f64; 2]; 2] {
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    [min, max]
}

/// Returns the indices of `points` (all finite) in BRIO-Hilbert insertion order, the order of
/// the points multiplied by `scale` (a power of two), whose [`bounding_box`] is `bounds`.
pub fn brio_hilbert_order(points: &[[f64; 2]], scale: f64, bounds: [[f64; 2]; 2]) -> Vec<u32> {
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let [min, max] = bounds;
    let side = (1u32 << HILBERT_BITS) as f64;
    // Same scale on both axes keeps the curve's locality isotropic.
    let extent = (max[0] - min[0]).max(max[1] - min[1]);
    let to_grid = if extent > 0.0 && extent.is_finite() {
        (side - 1.0) / extent
    } else {
        0.0
    };
    let rounds = round_count(n);
    let mut keyed: Vec<u64> = map_indexed(n, |i| {
        let p = [points[i][0] * scale, points[i][1] * scale];
        let gx = ((p[0] - min[0]) * to_grid) as u32;
        let gy = ((p[1] - min[1]) * to_grid) as u32;
        let h = hilbert_index(gx, gy);
        let round = brio_round(i as u64, rounds);
        let key = (round << (2 * HILBERT_BITS)) | h;
        (u64::from(key) << 32) | i as u64
    });
    radix_sort_by_high_word(&mut keyed);
    keyed.into_iter().map(|k| k as u32).collect()
}

/// Number of BRIO rounds for `n` sites: enough that the first round has about
/// [`FIRST_ROUND_SIZE`] sites.
fn round_count(n: usize) -> u32 {
    let mut rounds = 1;
    while rounds < MAX_ROUNDS && (n >> rounds) >= FIRST_ROUND_SIZE {
        rounds += 1;
    }
    rounds
}

/// The round (0 = first) of site `index`: a site falls in the last round with probability 1/2,
/// the one before with 1/4, and so on (trailing zeros of a hash are geometric).
fn brio_round(index: u64, rounds: u32) -> u32 {
    // splitmix64 finaliser: a well-mixed, deterministic hash of the index.
    let mut z = index.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    let depth = z.trailing_zeros().min(rounds - 1);
    rounds - 1 - depth
}

/// Position of grid cell `(x, y)` along the Hilbert curve filling the `2^HILBERT_BITS` square.
///
/// Reads the coordinates from the most significant bit down, [`HILBERT_LEVELS_PER_STEP`] levels
/// at a time, through [`HILBERT_STEPS`]: one table load per step instead of data-dependent
/// reflections and swaps per level.
#[inline]
fn hilbert_index(x: u32, y: u32) -> u32 {
    const STEP: u32 = HILBERT_LEVELS_PER_STEP;
    const MASK: u32 = (1 << STEP) - 1;
    let mut state = 0;
    let mut d = 0u32;
    let mut shift = HILBERT_BITS;
    while shift > 0 {
        shift -= STEP;
        let input = ((x >> shift) & MASK) << STEP | ((y >> shift) & MASK);
        let entry = HILBERT_STEPS[(state << (2 * STEP) | input) as usize];
        d = d << (2 * STEP) | u32::from(entry >> 2);
        state = u32::from(entry & 3);
    }
    d
}

/// Curve levels decoded by one table lookup in [`hilbert_index`] (divides [`HILBERT_BITS`]).
const HILBERT_LEVELS_PER_STEP: u32 = 2;
const _: () = assert!(HILBERT_BITS.is_multiple_of(HILBERT_LEVELS_PER_STEP));

/// The Hilbert curve as a state machine, [`HILBERT_LEVELS_PER_STEP`] levels per transition.
///
/// Inside a sub-square the curve is the whole curve seen through one of four symmetries of the
/// square: the identity, the transpose, the anti-transpose, or the half-turn — a pair of flags
/// (swap the axes, mirror both). The state is that pair. One level reads a bit of each
/// coordinate, maps it through the state to the quadrant `(rx, ry)` of the canonical curve,
/// emits the quadrant's position `3·rx ⊕ ry`, and, in the lower quadrants (`ry = 0`), composes
/// the state with a transpose (an anti-transpose when `rx = 1`). Entry
/// `state · 4^L + (x bits · 2^L + y bits)` holds the `2L` emitted bits, then the next state.
const HILBERT_STEPS: [u8; 4 << (2 * HILBERT_LEVELS_PER_STEP)] = {
    const STEP: u32 = HILBERT_LEVELS_PER_STEP;
    let mut table = [0u8; 4 << (2 * STEP)];
    let mut entry = 0;
    while entry < table.len() {
        let (mut swap, mut mirror) = (entry >> (2 * STEP + 1) & 1, entry >> (2 * STEP) & 1);
        let mut digits = 0;
        let mut level = STEP;
        while level > 0 {
            level -= 1;
            let (bx, by) = (entry >> (STEP + level) & 1, entry >> level & 1);
            let (mx, my) = (bx ^ mirror, by ^ mirror);
            let (rx, ry) = if swap == 1 { (my, mx) } else { (mx, my) };
            digits = digits << 2 | ((3 * rx) ^ ry);
            if ry == 0 {
                mirror ^= rx;
                swap ^= 1;
            }
        }
        table[entry] = (digits << 2 | swap << 1 | mirror) as u8;
        entry += 1;
    }
    table
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_is_a_permutation() {
        let pts: Vec<[f64; 2]> = (0..1000)
            .map(|i| [(i * 37 % 101) as f64, (i * 59 % 103) as f64])
            .collect();
        let mut order = brio_hilbert_order(&pts, 1.0, bounding_box(&pts));
        order.sort_unstable();
        assert_eq!(order, (0..1000).collect::<Vec<u32>>());
    }

    /// The curve by its definition, one level at a time, reflecting and swapping coordinates.
    fn hilbert_index_by_reflections(mut x: u32, mut y: u32) -> u32 {
        let n = 1u32 << HILBERT_BITS;
        let mut d = 0u32;
        let mut s = n >> 1;
        while s > 0 {
            let rx = u32::from(x & s != 0);
            let ry = u32::from(y & s != 0);
            d += s * s * ((3 * rx) ^ ry);
            if ry == 0 {
                if rx == 1 {
                    x = n - 1 - x;
                    y = n - 1 - y;
                }
                std::mem::swap(&mut x, &mut y);
            }
            s >>= 1;
        }
        d
    }

    #[test]
    fn state_machine_agrees_with_reflections() {
        let side = 1u32 << HILBERT_BITS;
        let mut state = 12345u64;
        for _ in 0..200_000 {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            let (x, y) = ((state >> 20) as u32 % side, (state >> 40) as u32 % side);
            assert_eq!(hilbert_index(x, y), hilbert_index_by_reflections(x, y));
        }
        for (x, y) in [(0, 0), (side - 1, 0), (0, side - 1), (side - 1, side - 1)] {
            assert_eq!(hilbert_index(x, y), hilbert_index_by_reflections(x, y));
        }
    }

    #[test]
    fn hilbert_curve_visits_neighbouring_cells_consecutively() {
        // Inverting by search on a small corner: consecutive indices are 4-neighbours.
        let mut cells: Vec<(u32, u32, u32)> = Vec::new();
        for x in 0..16 {
            for y in 0..16 {
                cells.push((hilbert_index(x, y), x, y));
            }
        }
        cells.sort_unstable();
        let first_256: Vec<_> = cells.iter().take_while(|c| c.0 < 256).collect();
        assert_eq!(
            first_256.len(),
            256,
            "the first 256 curve cells fill the 16x16 corner"
        );
        for w in first_256.windows(2) {
            let dist = w[0].1.abs_diff(w[1].1) + w[0].2.abs_diff(w[1].2);
            assert_eq!(dist, 1);
        }
    }

    #[test]
    fn rounds_grow_geometrically() {
        let rounds = round_count(1 << 20);
        let mut sizes = vec![0usize; rounds as usize];
        for i in 0..(1u64 << 20) {
            sizes[brio_round(i, rounds) as usize] += 1;
        }
        let last = *sizes.last().unwrap() as f64;
        assert!(
            (last / (1u64 << 20) as f64 - 0.5).abs() < 0.01,
            "last round holds half"
        );
        assert!(sizes[0] >= FIRST_ROUND_SIZE / 2);
    }
}
