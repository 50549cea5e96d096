//! The 2D Voronoi diagram and its Delaunay dual.
//!
//! * [`Delaunay`]: exact Delaunay triangulation of `f64` sites (duplicates merged and reported,
//!   collinear and tiny inputs supported, NaN/inf refused), convex hull, nearest-site queries.
//! * Typed ids: [`SiteId`] (cells and triangulation vertices), [`VoronoiVertexId`],
//!   [`VoronoiHalfedgeId`], [`DelaunayHalfedgeId`].
//! * [`Voronoi`]: the dual diagram as a DCEL — vertices at circumcentres (cocircular sites give one
//!   vertex of degree > 3), half-edges that know their two sites, unbounded edges as rays.
//! * [`ClipPolygon`] / [`ClippedCells`]: every cell clipped to a rectangle or convex polygon,
//!   tiling it with shared vertices; exported as a polygon soup for the half-edge mesh kernel.
//! * [`lloyd_relaxation`], [`Delaunay::label_image`] (L2, L1, L∞ rasters), [`to_svg`].
//!
//! Predicates are exact (Shewchuk's adaptive arithmetic via the `robust` crate, applied to sites
//! rescaled by a power of two so that magnitudes from `1e-300` to `1e+300` stay exact, provided
//! coordinates differences do not underflow); constructions (circumcentres, clip points,
//! areas) are floating point.

mod cell_sides;
mod clip_frame;
mod clip_region;
mod clipped;
mod crossing_order;
mod dcel;
mod delaunay;
mod diagram;
mod error;
mod exact_cell;
mod exact_distance;
mod expansion;
mod ids;
mod incremental;
mod lloyd;
mod nearest;
mod parallel;
pub mod predicates;
mod raster;
mod spatial_sort;
mod svg;

pub use clip_region::{ClipPolygon, polygon_area_centroid};
pub use clipped::ClippedCells;
pub use delaunay::{Delaunay, Dimension, INVALID, MAX_SITES, OutgoingEdges};
pub use diagram::{EdgeGeometry, Voronoi};
pub use error::VoronoiError;
pub use exact_distance::Metric;
pub use ids::{DelaunayHalfedgeId, SiteId, VoronoiHalfedgeId, VoronoiVertexId};
pub use lloyd::{LloydOptions, LloydResult, lloyd_relaxation};
pub use raster::LabelImage;
pub use svg::{SvgOptions, to_svg};

#[cfg(test)]
mod tests;
