//! Where the tests and benchmarks find the test data set: `HALFWING_DATA` when set (a fuller set
//! laid out the same way), else the copy in the repository (`tests/data`, see its MANIFEST.md).

use std::path::{Path, PathBuf};

/// The data set's root folder (the one holding `MANIFEST.md`).
pub fn root() -> PathBuf {
    std::env::var_os("HALFWING_DATA")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data"))
}
