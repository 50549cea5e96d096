//! The C ABI: a thin layer over the Rust API that holds no algorithm.
//!
//! Conventions (see `include/halfwing.h` for the C view):
//! - every exported function goes through the guards of `boundary.rs`: panics are caught, pointers are checked,
//!   errors become an [`hw_status`] and a thread-local message;
//! - outputs (`out_*`) are written only when the call returns `HW_OK`;
//! - objects are created by `_new`/`_build`/`_from_*` and released by `_free`; `_free(NULL)` is a
//!   no-op and freeing twice is refused while the freed address is held back (see `handle.rs`).
//!
//! Each exported item's documentation ends with `\ingroup <topic>`: the topic of the C reference
//! (Doxygen, `scripts/docs.sh`) that lists it. The topics are defined in `cbindgen.toml`.

#![allow(non_camel_case_types)]

pub mod attributes;
pub(crate) mod boundary;
pub mod circulator;
pub mod delaunay;
pub mod diagnostic;
pub mod doctor;
pub mod edit;
pub mod elements;
pub(crate) mod error;
pub(crate) mod face_list;
pub(crate) mod handle;
pub mod io;
pub mod mesh;
pub mod nav;
pub mod navigation;
pub mod normals;
pub mod points2d;
pub mod positions;
mod quiet_panics;
pub mod render;
pub mod repair;
pub mod repair_mesh;
pub mod self_intersections;
pub mod status;
pub mod surfaces;
pub mod threads;
pub mod topology;
pub mod version;
pub mod views;
pub mod visit;
pub mod voronoi;
pub mod voronoi_cells;
pub mod voronoi_images;
pub mod voronoi_lloyd;
pub mod winged;
pub mod winged_circulator;
pub mod winged_euler;

pub use attributes::*;
pub use circulator::*;
pub use delaunay::*;
pub use diagnostic::*;
pub use doctor::*;
pub use edit::*;
pub use elements::*;
pub use error::{HW_MAX_MESSAGE_SIZE, hw_last_error_message};
pub use handle::HW_FREED_ADDRESSES_KEPT;
pub use io::*;
pub use mesh::*;
pub use nav::*;
pub use navigation::*;
pub use normals::*;
pub use points2d::*;
pub use positions::*;
pub use render::*;
pub use repair::*;
pub use status::*;
pub use surfaces::*;
pub use threads::*;
pub use topology::*;
pub use version::*;
pub use views::*;
pub use visit::*;
pub use voronoi::*;
pub use voronoi_cells::*;
pub use voronoi_images::*;
pub use voronoi_lloyd::*;
pub use winged::*;
pub use winged_circulator::*;
pub use winged_euler::*;
