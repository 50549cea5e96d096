//! Shared driver of the randomized stress tests (`tests/stress_*.rs`): every case draws from
//! its own seeded generator, the number of cases comes from `HALFWING_STRESS_CASES` (from the
//! seed `HALFWING_STRESS_FIRST_SEED`, so that a long run splits across processes), one case is
//! replayed with `HALFWING_STRESS_SEED`, and a failing case names its seed (see
//! docs/testing.md).
#![allow(dead_code)]

use std::panic::{AssertUnwindSafe, catch_unwind};

pub use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};

/// Seeds of the long runs (`--ignored`) start here, past those of the bounded runs.
const LONG_RUN_FIRST_SEED: u64 = 1 << 32;

/// The generator of case `seed`.
pub fn generator(seed: u64) -> TestRng {
    let mut bytes = [0u8; 32];
    for (k, chunk) in bytes.chunks_exact_mut(8).enumerate() {
        chunk.copy_from_slice(
            &(seed ^ (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)).to_le_bytes(),
        );
    }
    TestRng::from_seed(RngAlgorithm::ChaCha, &bytes)
}

fn variable(name: &str) -> Option<u64> {
    let value = std::env::var(name).ok()?;
    Some(
        value
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={value:?} is not a count")),
    )
}

/// Runs `case` on `bounded` seeds (in `cargo test`), or on `HALFWING_STRESS_CASES` of them
/// (from `HALFWING_STRESS_FIRST_SEED`, if set), or on the one seed `HALFWING_STRESS_SEED`. A
/// failing case panics naming its seed. Returns the number of cases run.
pub fn run(target: &str, bounded: u64, case: impl Fn(&mut TestRng)) -> u64 {
    run_from(target, 0, bounded, case)
}

/// [`run`] for the long runs of `--ignored` tests: a million cases unless
/// `HALFWING_STRESS_CASES` says otherwise, on seeds that the bounded runs do not use.
pub fn run_long(target: &str, case: impl Fn(&mut TestRng)) -> u64 {
    run_from(target, LONG_RUN_FIRST_SEED, 1_000_000, case)
}

fn run_from(target: &str, first: u64, default_cases: u64, case: impl Fn(&mut TestRng)) -> u64 {
    let seeds = match variable("HALFWING_STRESS_SEED") {
        Some(seed) => seed..seed + 1,
        None => {
            let first = variable("HALFWING_STRESS_FIRST_SEED").unwrap_or(first);
            first..first + variable("HALFWING_STRESS_CASES").unwrap_or(default_cases)
        }
    };
    let count = seeds.end - seeds.start;
    // With HALFWING_STRESS_KEEP_GOING set, every case runs and all failing seeds are listed.
    let keep_going = std::env::var_os("HALFWING_STRESS_KEEP_GOING").is_some();
    let mut failed = Vec::new();
    for seed in seeds {
        let outcome = catch_unwind(AssertUnwindSafe(|| case(&mut generator(seed))));
        if let Err(cause) = outcome {
            let message = cause
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| cause.downcast_ref::<&str>().copied())
                .unwrap_or("(no message)");
            if keep_going {
                // Named at once too: a run of hours can be stopped with what it found so far.
                eprintln!("{target}: case {seed} failed: {message}");
                failed.push(seed);
                continue;
            }
            panic!(
                "{target}: case {seed} failed: {message}\n\
                 replay it with HALFWING_STRESS_SEED={seed} cargo test --test stress_{target} -- \
                 --include-ignored"
            );
        }
    }
    assert!(
        failed.is_empty(),
        "{target}: {} of {count} cases failed, seeds {failed:?}",
        failed.len()
    );
    println!("{target}: {count} cases passed");
    count
}

/// One of `items`, uniformly.
pub fn choose<'a, T>(rng: &mut TestRng, items: &'a [T]) -> &'a T {
    &items[rng.random_range(0..items.len())]
}

/// An index below `count` (0 when `count` is 0): ids drawn past the live range on purpose
/// exercise the refusal paths.
pub fn index_below(rng: &mut TestRng, count: usize) -> u32 {
    rng.random_range(0..count.max(1)) as u32
}
