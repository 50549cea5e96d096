//! The 2D Voronoi diagram and its Delaunay dual.
//!
//! * [`Delaunay`]: exact Delaunay triangulation of `f64` sites (duplicates merged and reported,
//!   collinear and tiny inputs supported, NaN/inf refused).
//!
//! Predicates are exact (Shewchuk's adaptive arithmetic via the `robust` crate, applied to sites
//! rescaled by a power of two); constructions (circumcentres, clip points) are floating point.

mod delaunay;
mod error;
mod incremental;
pub mod predicates;
mod spatial_sort;

pub use delaunay::{Delaunay, Dimension, INVALID, MAX_SITES, OutgoingEdges};
pub use error::VoronoiError;

#[cfg(test)]
mod tests;
