//! The one error type every surface generator returns.

use thiserror::Error;

/// Why a surface could not be generated. Every variant names the offending input so a caller
/// (or the C API's last-error message) can point at it.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SurfaceError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// A point of an input polyline has a NaN or infinite coordinate.
    #[error("{what}: point {index} has a non-finite coordinate")]
    NonFinitePoint {
        /// Which input polyline.
        what: &'static str,
        /// Index of the point in that polyline.
        index: usize,
    },
    /// A scalar or vector parameter is NaN or infinite.
    #[error("parameter `{what}` is not finite")]
    NonFiniteParameter {
        /// Parameter name.
        what: &'static str,
    },
    /// A length parameter (radius, side, width) is zero or negative.
    #[error("parameter `{what}` must be positive, got {value}")]
    NonPositive {
        /// Parameter name.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// A polyline has too few points for the requested surface.
    #[error("{what} needs at least {min} points, got {got}")]
    TooFewPoints {
        /// Which input polyline.
        what: &'static str,
        /// The minimum accepted.
        min: usize,
        /// The number given.
        got: usize,
    },
    /// A step or subdivision count is below its minimum.
    #[error("`{what}` must be at least {min}, got {got}")]
    TooFewSteps {
        /// Parameter name.
        what: &'static str,
        /// The minimum accepted.
        min: u32,
        /// The value given.
        got: u32,
    },
    /// A subdivision level is above the supported maximum.
    #[error("`{what}` must be at most {max}, got {got}")]
    TooManySteps {
        /// Parameter name.
        what: &'static str,
        /// The maximum accepted.
        max: u32,
        /// The value given.
        got: u32,
    },
    /// A direction or axis vector has zero length.
    #[error("vector `{what}` has zero length")]
    ZeroVector {
        /// Parameter name.
        what: &'static str,
    },
    /// Two consecutive points of a polyline coincide (this would give zero-length edges).
    #[error("{what}: consecutive points {first} and {second} coincide")]
    CoincidentPoints {
        /// Which input polyline.
        what: &'static str,
        /// Index of the first point.
        first: usize,
        /// Index of the second point (0 when closing a closed polyline).
        second: usize,
    },
    /// The two polylines of a ruled surface have different numbers of points.
    #[error("ruled surface polylines differ in length: {first} and {second} points")]
    MismatchedPolylines {
        /// Points in the first polyline.
        first: usize,
        /// Points in the second polyline.
        second: usize,
    },
    /// A profile segment lies on the axis of revolution, so it would sweep zero-area faces.
    #[error("profile segment {segment} (points {segment} and {next}) lies on the axis of revolution", next = segment + 1)]
    SegmentOnAxis {
        /// Index of the segment's first point.
        segment: usize,
    },
    /// A polyline segment is parallel to the sweep direction, so it would sweep zero-area faces.
    #[error("segment {segment} of the profile is parallel to the sweep direction")]
    SegmentParallelToSweep {
        /// Index of the segment's first point.
        segment: usize,
    },
    /// A strip cell of a ruled surface collapses to a line or a point.
    #[error("ruled surface cell between points {segment} and {next} collapses to a line", next = segment + 1)]
    DegenerateCell {
        /// Index of the cell's first point along the polylines.
        segment: usize,
    },
    /// A partial revolution angle is outside `(0, 2π)`.
    #[error("revolution angle {radians} is outside (0, 2π); use a full turn for 2π")]
    AngleOutOfRange {
        /// The angle given, in radians.
        radians: f64,
    },
    /// A torus whose tube radius reaches the axis would intersect itself.
    #[error("torus minor radius {minor} must be smaller than major radius {major}")]
    SelfIntersectingTorus {
        /// Distance from the centre to the tube centre.
        major: f64,
        /// Tube radius.
        minor: f64,
    },
    /// Finite parameters whose surface has coordinates beyond the range of doubles (a profile
    /// near the largest double swept further out).
    #[error("the surface's coordinates overflow the range of double-precision numbers")]
    CoordinatesOverflow,
    /// The surface would need more vertices or corners than `u32` indices can address.
    #[error("the surface would need more than 2^32 - 1 vertices or corners")]
    TooLarge,
}
