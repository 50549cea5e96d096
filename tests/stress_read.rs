//! Stress test of the OBJ, OFF and PLY readers: random bytes, and files written from random
//! soups then mutated (bytes flipped, inserted, deleted, lines repeated, truncated). Any bytes
//! give a soup or an error; a soup read is consistent and survives a write and a second read.

mod stress;

use halfwing::io::{MeshFormat, PlyEncoding, write_obj, write_off, write_ply};
use halfwing::soup::PolygonSoup;
use proptest::test_runner::TestRng;
use stress::{Rng, choose, run, run_long};

#[path = "../fuzz/fuzz_targets/common.rs"]
mod reader_check;

const FORMATS: [MeshFormat; 3] = [MeshFormat::Obj, MeshFormat::Off, MeshFormat::Ply];

/// A valid soup of a few polygons, some coordinates extreme.
fn random_soup(rng: &mut TestRng) -> PolygonSoup {
    let n = rng.random_range(1..12usize);
    let coordinate = |rng: &mut TestRng| match rng.random_range(0..6) {
        0 => 0.0,
        1 => rng.random_range(-1e300..1e300),
        2 => rng.random_range(-1e-300..1e-300),
        _ => rng.random_range(-10.0..10.0),
    };
    let positions = (0..n)
        .map(|_| [coordinate(rng), coordinate(rng), coordinate(rng)])
        .collect();
    let (mut face_sizes, mut indices) = (Vec::new(), Vec::new());
    for _ in 0..rng.random_range(0..8) {
        let size = rng.random_range(3..6u32);
        face_sizes.push(size);
        indices.extend((0..size).map(|_| rng.random_range(0..n as u32)));
    }
    PolygonSoup {
        positions,
        face_sizes,
        indices,
        ..PolygonSoup::default()
    }
}

/// Bytes of `format`: written from a random soup (in a random PLY encoding), or random.
fn random_file(rng: &mut TestRng, format: MeshFormat) -> Vec<u8> {
    let mut bytes = Vec::new();
    if rng.random_bool(0.1) {
        bytes.extend((0..rng.random_range(0..200)).map(|_| rng.random::<u8>()));
        return bytes;
    }
    let soup = random_soup(rng);
    let encoding = *choose(
        rng,
        &[
            PlyEncoding::Ascii,
            PlyEncoding::BinaryLittleEndian,
            PlyEncoding::BinaryBigEndian,
        ],
    );
    match format {
        MeshFormat::Obj => write_obj(&mut bytes, &soup),
        MeshFormat::Off => write_off(&mut bytes, &soup),
        MeshFormat::Ply => write_ply(&mut bytes, &soup, encoding),
    }
    .expect("a valid soup is written");
    bytes
}

/// A few random mutations of `bytes`, biased to characters the parsers care about.
fn mutate(rng: &mut TestRng, bytes: &mut Vec<u8>) {
    const INTERESTING: &[u8] = b"0123456789-+.eE /\n\r\t#fvnNaAiI\0\xff";
    for _ in 0..rng.random_range(0..6) {
        let at = rng.random_range(0..=bytes.len());
        match rng.random_range(0..6) {
            0 if at < bytes.len() => bytes[at] ^= 1 << rng.random_range(0..8),
            1 => bytes.insert(at, *choose(rng, INTERESTING)),
            2 if at < bytes.len() => {
                bytes.remove(at);
            }
            3 => bytes.truncate(at),
            4 => {
                let end = (at + rng.random_range(1..40)).min(bytes.len());
                let copy = bytes[at..end].to_vec();
                bytes.splice(at..at, copy);
            }
            _ => {
                let digits = format!("{}", rng.random::<u32>() as i64 - i64::from(u32::MAX / 2));
                bytes.splice(at..at, digits.into_bytes());
            }
        }
    }
}

fn case(rng: &mut TestRng) {
    let format = *choose(rng, &FORMATS);
    let mut bytes = random_file(rng, format);
    mutate(rng, &mut bytes);
    reader_check::check(format, &bytes);
}

#[test]
fn readers_take_random_and_mutated_files() {
    run("read", 500_000, case);
}

#[test]
#[ignore = "long run: cargo test --test stress_read -- --ignored"]
fn readers_take_random_and_mutated_files_long() {
    run_long("read", case);
}
