//! Benchmark inputs shared by the Voronoi benchmarks.

/// Deterministic uniform points in the unit square: the 64-bit LCG of `c_tests/points2d.hpp`, so
/// the CGAL benchmark generates the very same sites from the same seed.
pub fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut state = seed;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(|_| [next(), next()]).collect()
}
