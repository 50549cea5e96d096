//! The C ABI: a thin layer over the Rust API that holds no algorithm.
//!
//! Conventions (see `include/halfwing.h` for the C view):
//! - every exported function goes through the guards of `boundary/guard.rs`: panics are caught,
//!   pointers are checked, errors become an [`hw_status`] and a thread-local message;
//! - outputs (`out_*`) are written only when the call returns `HW_OK`;
//! - objects are created by `_new`/`_build`/`_from_*` and released by `_free`; `_free(NULL)` is a
//!   no-op and freeing twice is refused while the freed address is held back (see
//!   `boundary/handle.rs`).
//!
//! Each exported item's documentation ends with `\ingroup <topic>`: the topic of the C reference
//! (Doxygen, `scripts/docs.sh`) that lists it. The topics are defined in `cbindgen.toml`.

#![allow(non_camel_case_types)]

// One directory per kernel, in the header's order; `boundary` is the plumbing they share; the
// tools that work on any kernel's mesh or on a face list follow, one file each.
pub mod boundary;

pub mod mesh;

pub mod winged;

pub mod voronoi;

pub mod doctor;

pub mod self_intersections;

pub mod repair;

pub mod repair_mesh;

pub mod surfaces;

pub mod render;

pub use boundary::error::{HW_MAX_MESSAGE_SIZE, hw_last_error_message};
pub use boundary::handle::HW_FREED_ADDRESSES_KEPT;
pub use boundary::status::*;
pub use boundary::threads::*;
pub use boundary::version::*;
pub use doctor::*;
pub use mesh::*;
pub use render::*;
pub use repair::*;
pub use surfaces::*;
pub use voronoi::*;
pub use winged::*;
