//! # halfwing
//!
//! A half-edge polygon-mesh kernel, a winged-edge (Baumgart) kernel and a 2D Voronoi diagram with
//! its Delaunay dual, with the topology checks, repairs, normals, surface generation and rendering
//! buffers that real mesh work needs. The Rust API is first-class; [`ffi`] is a thin C ABI over it
//! (see `include/halfwing.h`).

pub mod doctor;
pub mod geom;
pub mod io;
pub mod mesh;
pub mod render;
pub mod repair;
pub mod soup;
pub mod surfaces;
pub mod voronoi;
pub mod winged;

pub mod ffi;

// The README's Rust examples run as doctests (its C, C++ and shell blocks are tagged, so not run).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeExamples;

mod support;

pub use support::allocation::OutOfMemory;

/// The crate version, as `Cargo.toml` states it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
