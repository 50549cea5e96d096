//! A small seeded generator for unit tests: the same numbers on every machine, no dependency.

/// Xorshift64: a stream of 64-bit values from `seed` (not zero).
pub(crate) fn xorshift(seed: u64) -> impl FnMut() -> u64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

/// Doubles uniform in `[0, 1)` from [`xorshift`].
pub(crate) fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut bits = xorshift(seed);
    move || (bits() >> 11) as f64 / (1u64 << 53) as f64
}
