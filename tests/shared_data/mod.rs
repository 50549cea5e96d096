//! Where the integration tests find the shared, read-only data set: `HALFWING_DATA` when set,
//! else `../shared/data` beside the repository (as DESIGN.md says).

use std::path::{Path, PathBuf};

/// The data set's root folder (the one holding `MANIFEST.md`).
pub fn root() -> PathBuf {
    std::env::var_os("HALFWING_DATA")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data"))
}
