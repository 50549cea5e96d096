//! Errors of the Voronoi / Delaunay module.

use thiserror::Error;

use super::ids::SiteId;

/// Why a Delaunay triangulation, Voronoi diagram or one of their queries was refused.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum VoronoiError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// A site coordinate is NaN or infinite.
    #[error("{site} has a non-finite coordinate ({x}, {y})")]
    NonFiniteSite {
        /// The offending site.
        site: SiteId,
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
    },
    /// More sites than the 32-bit indices of the triangulation can address.
    #[error("{count} sites exceed the maximum of {max}")]
    TooManySites {
        /// Number of sites given.
        count: usize,
        /// Largest supported number of sites.
        max: usize,
    },
    /// The clip polygon has fewer than three vertices, a non-finite vertex or zero area.
    #[error("clip region is degenerate: {0}")]
    DegenerateClip(&'static str),
    /// The clip polygon is not convex (or not simple).
    #[error("clip polygon is not convex (vertex {vertex})")]
    NonConvexClip {
        /// A vertex at which the polygon turns the wrong way.
        vertex: usize,
    },
    /// A site index is out of range.
    #[error("{site} out of range (0..{count})")]
    InvalidSite {
        /// The site given.
        site: SiteId,
        /// Number of sites.
        count: usize,
    },
    /// A Lloyd relaxation tolerance is negative, NaN or infinite.
    #[error("tolerance {0} is not a finite distance of at least 0")]
    InvalidTolerance(f64),
    /// A query point or parameter is NaN or infinite.
    #[error("non-finite query argument")]
    NonFiniteQuery,
    /// A raster size is zero or its pixel count overflows.
    #[error("invalid raster size {width}x{height}")]
    InvalidRasterSize {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
}
