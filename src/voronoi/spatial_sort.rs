//! Insertion order for incremental Delaunay construction: a biased randomised insertion order
//! (BRIO, Amenta–Choi–Rote 2003) whose rounds are each sorted along a Hilbert curve.
//!
//! The Hilbert order keeps consecutive insertions close together, so the walking point location
//! of the next site starts next to its target; the rounds (a random half of the sites in the last
//! round, a quarter in the one before, ...) keep the expected work linear even for adversarial
//! inputs such as points on a parabola, where a pure space-filling-curve order degrades. The
//! randomness is a fixed hash of the site index, so results are reproducible.

/// Bits per axis of the Hilbert grid (the sort key packs `2 × 14` Hilbert bits and 4 round bits
/// into 32 bits; ties inside one of the `2^28` cells keep index order).
const HILBERT_BITS: u32 = 14;
/// Most BRIO rounds the key can express.
const MAX_ROUNDS: u32 = 16;
/// Sites in the first round when there are enough of them.
const FIRST_ROUND_SIZE: usize = 64;

/// Returns the indices of `points` (all finite) in BRIO-Hilbert insertion order.
pub fn brio_hilbert_order(points: &[[f64; 2]]) -> Vec<u32> {
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    let side = (1u32 << HILBERT_BITS) as f64;
    // Same scale on both axes keeps the curve's locality isotropic.
    let extent = (max[0] - min[0]).max(max[1] - min[1]);
    let to_grid = if extent > 0.0 && extent.is_finite() {
        (side - 1.0) / extent
    } else {
        0.0
    };
    let rounds = round_count(n);
    let mut keyed: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let gx = ((p[0] - min[0]) * to_grid) as u32;
            let gy = ((p[1] - min[1]) * to_grid) as u32;
            let h = hilbert_index(gx, gy);
            let round = brio_round(i as u64, rounds);
            let key = (round << (2 * HILBERT_BITS)) | h;
            (u64::from(key) << 32) | i as u64
        })
        .collect();
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
fn hilbert_index(mut x: u32, mut y: u32) -> u32 {
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

/// Stable LSD radix sort on the high 32 bits (three passes of 11 bits).
fn radix_sort_by_high_word(keys: &mut Vec<u64>) {
    const BITS: u32 = 11;
    const BUCKETS: usize = 1 << BITS;
    let mut scratch = vec![0u64; keys.len()];
    for pass in 0..3 {
        let shift = 32 + pass * BITS;
        let mut counts = [0usize; BUCKETS];
        for &k in keys.iter() {
            counts[((k >> shift) as usize) & (BUCKETS - 1)] += 1;
        }
        let mut total = 0;
        for c in counts.iter_mut() {
            let here = *c;
            *c = total;
            total += here;
        }
        for &k in keys.iter() {
            let bucket = ((k >> shift) as usize) & (BUCKETS - 1);
            scratch[counts[bucket]] = k;
            counts[bucket] += 1;
        }
        std::mem::swap(keys, &mut scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_is_a_permutation() {
        let pts: Vec<[f64; 2]> = (0..1000)
            .map(|i| [(i * 37 % 101) as f64, (i * 59 % 103) as f64])
            .collect();
        let mut order = brio_hilbert_order(&pts);
        order.sort_unstable();
        assert_eq!(order, (0..1000).collect::<Vec<u32>>());
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

    #[test]
    fn radix_sort_sorts_by_high_word_stably() {
        let mut keys: Vec<u64> = (0..5000u64)
            .map(|i| ((i * 7919 % 4099) << 32) | i)
            .collect();
        radix_sort_by_high_word(&mut keys);
        for w in keys.windows(2) {
            assert!(w[0] >> 32 < w[1] >> 32 || (w[0] >> 32 == w[1] >> 32 && w[0] < w[1]));
        }
    }
}
