//! Checks shared by the generators that take polylines and vectors as input.

use glam::DVec3;

use super::SurfaceError;

/// Converts a polyline to vectors, refusing non-finite points, too few points and consecutive
/// duplicates (including last-to-first when `closed`), which would give zero-length edges.
pub(crate) fn checked_polyline(
    what: &'static str,
    points: &[[f64; 3]],
    min_points: usize,
    closed: bool,
) -> Result<Vec<DVec3>, SurfaceError> {
    if points.len() < min_points {
        return Err(SurfaceError::TooFewPoints {
            what,
            min: min_points,
            got: points.len(),
        });
    }
    let mut out = Vec::with_capacity(points.len());
    for (index, p) in points.iter().enumerate() {
        let v = DVec3::from_array(*p);
        if !v.is_finite() {
            return Err(SurfaceError::NonFinitePoint { what, index });
        }
        out.push(v);
    }
    for first in 0..out.len() {
        let second = first + 1;
        if second < out.len() {
            if out[first] == out[second] {
                return Err(SurfaceError::CoincidentPoints {
                    what,
                    first,
                    second,
                });
            }
        } else if closed && out[first] == out[0] {
            return Err(SurfaceError::CoincidentPoints {
                what,
                first,
                second: 0,
            });
        }
    }
    Ok(out)
}

/// A finite, non-zero vector parameter.
pub(crate) fn checked_direction(what: &'static str, v: [f64; 3]) -> Result<DVec3, SurfaceError> {
    let v = DVec3::from_array(v);
    if !v.is_finite() {
        return Err(SurfaceError::NonFiniteParameter { what });
    }
    if v == DVec3::ZERO {
        return Err(SurfaceError::ZeroVector { what });
    }
    Ok(v)
}

/// A finite point parameter.
pub(crate) fn checked_point(what: &'static str, p: [f64; 3]) -> Result<DVec3, SurfaceError> {
    let p = DVec3::from_array(p);
    if !p.is_finite() {
        return Err(SurfaceError::NonFiniteParameter { what });
    }
    Ok(p)
}

/// A finite, strictly positive length parameter.
pub(crate) fn checked_length(what: &'static str, value: f64) -> Result<f64, SurfaceError> {
    if !value.is_finite() {
        return Err(SurfaceError::NonFiniteParameter { what });
    }
    if value <= 0.0 {
        return Err(SurfaceError::NonPositive { what, value });
    }
    Ok(value)
}

/// A step count of at least `min`.
pub(crate) fn checked_steps(what: &'static str, got: u32, min: u32) -> Result<u32, SurfaceError> {
    if got < min {
        return Err(SurfaceError::TooFewSteps { what, min, got });
    }
    Ok(got)
}
