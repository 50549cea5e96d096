//! Fuzzes the 2D point reader in every format: any bytes must give points or an error naming a
//! line within the input, never a panic; the first byte chooses the format.
#![no_main]

use halfwing::io::{IoError, PointFormat, read_points2d_bytes};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&choice, bytes)) = data.split_first() else {
        return;
    };
    let format = [
        PointFormat::Xy,
        PointFormat::Triangle,
        PointFormat::Counted,
        PointFormat::Json,
    ][usize::from(choice % 4)];
    match read_points2d_bytes(format, bytes) {
        // Every point takes at least one byte of its own.
        Ok(points) => assert!(points.len() <= bytes.len()),
        Err(IoError::PointParse { line, .. }) => {
            let lines = bytes.iter().filter(|&&b| b == b'\n' || b == b'\r').count() as u64;
            assert!(line >= 1 && line <= lines + 1, "line {line} of {lines}");
        }
        Err(IoError::OutOfMemory(_)) => {}
        Err(other) => panic!("unexpected error: {other}"),
    }
});
