//! Surfaces of revolution: a profile polyline rotated about an axis (the Granada notes,
//! "Superficies de revolución": `S(u, v) = (x(u)·cos v, x(u)·sin v, z(u))` for the z axis).

use std::f64::consts::TAU;

use glam::{DQuat, DVec3};

use super::SurfaceError;
use super::builder::{SoupBuilder, ensure_fits};
use super::lattice::{CellFaces, Lattice};
use super::polyline::{checked_direction, checked_point, checked_polyline, checked_steps};
use crate::soup::PolygonSoup;
use crate::support::allocation::try_vec_with_capacity;

/// A profile point closer to the axis than this fraction of the profile's size is a pole: it
/// becomes one vertex on the axis instead of a ring of coincident vertices.
const POLE_TOLERANCE: f64 = 1e-9;

/// How far the profile turns about the axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Turn {
    /// A full 360° turn; the last column is welded to the first (no seam duplicates).
    Full,
    /// A partial turn by this angle in radians, in `(0, 2π)`: an open surface.
    Partial(f64),
}

/// How the open ends of the profile are closed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Caps {
    /// Leave them open.
    #[default]
    None,
    /// One planar polygon per end: the ring itself for a full turn, or the sector bounded by the
    /// arc and the axis point for a partial turn.
    Polygon,
    /// A fan of triangles from a new vertex on the axis.
    Fan,
}

/// Parameters of a surface of revolution.
#[derive(Clone, Copy, Debug)]
pub struct Revolution<'a> {
    /// The profile polyline (at least 2 points, 3 when closed), anywhere in space.
    pub profile: &'a [[f64; 3]],
    /// Join the profile's last point back to its first: a closed profile off the axis revolves
    /// into a closed torus-like surface, and has no ends to cap.
    pub closed_profile: bool,
    /// A point on the axis.
    pub axis_origin: [f64; 3],
    /// The axis direction (need not be unit length). Rotation is right-handed about it.
    pub axis_direction: [f64; 3],
    /// Full or partial turn.
    pub turn: Turn,
    /// Angular steps (at least 3 for a full turn, 1 for a partial one).
    pub steps: u32,
    /// Whether and how to close the profile's ends that are not on the axis.
    pub caps: Caps,
    /// Quads or triangles for the swept cells.
    pub faces: CellFaces,
}

/// Revolves `profile` about the axis.
///
/// Profile points on the axis become poles (one vertex, triangles around it, never a degenerate
/// face). Faces are oriented along `∂S/∂θ × P'(u)`: a profile running in the axis direction gives
/// faces looking away from the axis, so a profile from the "south" pole to the "north" pole of a
/// sphere gives an outward-oriented closed mesh. A profile crossing the axis in its middle gives
/// a pinch vertex shared by two cones (allowed; the half-edge kernel reports it).
///
/// # Errors
/// Fewer than 2 profile points (3 when closed), non-finite or coincident consecutive points, a zero or
/// non-finite axis, an angle outside `(0, 2π)`, too few steps, a profile segment lying on the
/// axis, or an output too large for `u32` indices.
pub fn revolution_surface(rev: &Revolution<'_>) -> Result<PolygonSoup, SurfaceError> {
    let closed = rev.closed_profile;
    let profile = checked_polyline("profile", rev.profile, if closed { 3 } else { 2 }, closed)?;
    let origin = checked_point("axis_origin", rev.axis_origin)?;
    let axis = checked_direction("axis_direction", rev.axis_direction)?.normalize();
    let (angle, full) = match rev.turn {
        Turn::Full => (TAU, true),
        Turn::Partial(radians) if radians.is_finite() && radians > 0.0 && radians < TAU => {
            (radians, false)
        }
        Turn::Partial(radians) if radians.is_nan() => {
            return Err(SurfaceError::NonFiniteParameter { what: "turn" });
        }
        Turn::Partial(radians) => return Err(SurfaceError::AngleOutOfRange { radians }),
    };
    let steps = checked_steps("steps", rev.steps, if full { 3 } else { 1 })? as usize;

    // Split each profile point into its axial foot and its radial offset; snap poles onto the axis.
    let extent = profile
        .iter()
        .map(|p| (*p - profile[0]).length())
        .fold(0.0, f64::max);
    let foot = |p: DVec3| origin + axis * (p - origin).dot(axis);
    let is_pole: Vec<bool> = profile
        .iter()
        .map(|&p| (p - foot(p)).length() <= POLE_TOLERANCE * extent.max((p - origin).length()))
        .collect();
    let segments = if closed {
        profile.len()
    } else {
        profile.len() - 1
    };
    if let Some(segment) = (0..segments).find(|&i| is_pole[i] && is_pole[(i + 1) % profile.len()]) {
        return Err(SurfaceError::SegmentOnAxis { segment });
    }

    let columns = if full { steps } else { steps + 1 };
    let ring_points = is_pole.iter().filter(|&&pole| !pole).count();
    let caps: Vec<usize> = [0, profile.len() - 1]
        .into_iter()
        .filter(|&i| rev.caps != Caps::None && !closed && !is_pole[i])
        .collect();
    let vertices = ring_points
        .checked_mul(columns)
        .and_then(|v| v.checked_add(profile.len() + caps.len()));
    let corners = segments
        .checked_mul(steps)
        .and_then(|cells| cells.checked_add(caps.len() * steps))
        .and_then(|cells| cells.checked_mul(6));
    ensure_fits(vertices, corners)?;

    let mut out = SoupBuilder::with_capacity(vertices.unwrap_or(0), 0, corners.unwrap_or(0))?;
    let mut rotations: Vec<DQuat> = try_vec_with_capacity(columns, "columns")?;
    rotations.extend(
        (0..columns)
            .map(|column| DQuat::from_axis_angle(axis, angle * column as f64 / steps as f64)),
    );
    let mut ids = try_vec_with_capacity(profile.len() * columns, "vertices")?;
    for (i, &p) in profile.iter().enumerate() {
        if is_pole[i] {
            let pole = out.vertex(foot(p));
            ids.extend(std::iter::repeat_n(pole, columns));
        } else {
            // Column 0 is the profile itself, exactly, so seams and caps meet the input.
            ids.push(out.vertex(p));
            ids.extend(
                rotations[1..]
                    .iter()
                    .map(|q| out.vertex(origin + *q * (p - origin))),
            );
        }
    }
    // u runs around the axis, v along the profile.
    let lattice = Lattice {
        ids: &ids,
        columns,
        rows: profile.len(),
        wrap_u: full,
        wrap_v: closed,
    };
    out.ensure_finite()?;
    lattice
        .push_faces(&mut out, rev.faces)
        .map_err(|cell| SurfaceError::SegmentOnAxis { segment: cell.v })?;

    for end in caps {
        let ring = &ids[end * columns..(end + 1) * columns];
        // The side faces use the first ring in increasing column order and the last ring in
        // decreasing order; each cap walks its ring the other way so every edge pairs up.
        let reversed = end == 0;
        push_cap(&mut out, ring, foot(profile[end]), full, reversed, rev.caps);
    }
    out.finish()
}

/// Closes one ring (or arc, for a partial turn) with a polygon or a fan around `centre`.
fn push_cap(
    out: &mut SoupBuilder,
    ring: &[u32],
    centre: DVec3,
    full: bool,
    reversed: bool,
    caps: Caps,
) {
    let mut walk: Vec<u32> = ring.to_vec();
    if reversed {
        walk.reverse();
    }
    match caps {
        Caps::None => {}
        Caps::Polygon if full => out.face(&walk),
        Caps::Polygon => {
            let hub = out.vertex(centre);
            walk.insert(0, hub);
            out.face(&walk);
        }
        Caps::Fan => {
            let hub = out.vertex(centre);
            let spokes = if full { walk.len() } else { walk.len() - 1 };
            for k in 0..spokes {
                out.face(&[hub, walk[k], walk[(k + 1) % walk.len()]]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn revolve(
        profile: &[[f64; 3]],
        turn: Turn,
        steps: u32,
        caps: Caps,
    ) -> Result<PolygonSoup, SurfaceError> {
        revolution_surface(&Revolution {
            profile,
            closed_profile: false,
            axis_origin: [0.0, 0.0, 0.0],
            axis_direction: [0.0, 0.0, 1.0],
            turn,
            steps,
            caps,
            faces: CellFaces::Quads,
        })
    }

    #[test]
    fn poles_are_single_vertices_with_triangle_fans() {
        let diamond = [[0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
        let soup = revolve(&diamond, Turn::Full, 8, Caps::None).unwrap();
        assert_eq!(soup.positions.len(), 2 + 8);
        assert_eq!(soup.n_faces(), 16);
        assert!(soup.face_sizes.iter().all(|&s| s == 3));
    }

    #[test]
    fn seed_formula_rotates_towards_positive_y() {
        let profile = [[1.0, 0.0, 0.0], [1.0, 0.0, 1.0]];
        let soup = revolve(
            &profile,
            Turn::Partial(std::f64::consts::FRAC_PI_2),
            1,
            Caps::None,
        )
        .unwrap();
        let rotated = soup.positions[1];
        assert!(rotated[0].abs() < 1e-15 && (rotated[1] - 1.0).abs() < 1e-15);
    }

    #[test]
    fn caps_close_an_open_cylinder() {
        let profile = [[1.0, 0.0, 0.0], [1.0, 0.0, 1.0]];
        let polygon = revolve(&profile, Turn::Full, 6, Caps::Polygon).unwrap();
        assert_eq!((polygon.positions.len(), polygon.n_faces()), (12, 8));
        let fan = revolve(&profile, Turn::Full, 6, Caps::Fan).unwrap();
        assert_eq!((fan.positions.len(), fan.n_faces()), (14, 18));
        let sector = revolve(&profile, Turn::Partial(1.0), 4, Caps::Polygon).unwrap();
        assert_eq!(sector.face_sizes.iter().filter(|&&s| s == 6).count(), 2);
    }

    #[test]
    fn bad_parameters_are_typed_errors() {
        let profile = [[1.0, 0.0, 0.0], [1.0, 0.0, 1.0]];
        assert_eq!(
            revolve(&profile, Turn::Full, 2, Caps::None),
            Err(SurfaceError::TooFewSteps {
                what: "steps",
                min: 3,
                got: 2
            })
        );
        assert_eq!(
            revolve(&profile, Turn::Partial(1.0), 0, Caps::None),
            Err(SurfaceError::TooFewSteps {
                what: "steps",
                min: 1,
                got: 0
            })
        );
        assert_eq!(
            revolve(&profile, Turn::Partial(TAU), 4, Caps::None),
            Err(SurfaceError::AngleOutOfRange { radians: TAU })
        );
        assert_eq!(
            revolve(&profile, Turn::Partial(-1.0), 4, Caps::None),
            Err(SurfaceError::AngleOutOfRange { radians: -1.0 })
        );
        assert_eq!(
            revolve(&profile, Turn::Partial(f64::NAN), 4, Caps::None),
            Err(SurfaceError::NonFiniteParameter { what: "turn" })
        );
        assert_eq!(
            revolve(&profile[..1], Turn::Full, 4, Caps::None),
            Err(SurfaceError::TooFewPoints {
                what: "profile",
                min: 2,
                got: 1
            })
        );
        let on_axis = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]];
        assert_eq!(
            revolve(&on_axis, Turn::Full, 4, Caps::None),
            Err(SurfaceError::SegmentOnAxis { segment: 0 })
        );
        let zero_axis = Revolution {
            profile: &profile,
            closed_profile: false,
            axis_origin: [0.0; 3],
            axis_direction: [0.0; 3],
            turn: Turn::Full,
            steps: 4,
            caps: Caps::None,
            faces: CellFaces::Quads,
        };
        assert_eq!(
            revolution_surface(&zero_axis),
            Err(SurfaceError::ZeroVector {
                what: "axis_direction"
            })
        );
    }
}
