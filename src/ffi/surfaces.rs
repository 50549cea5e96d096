//! Surface generators (sweeps, revolutions, ruled surfaces) and primitives, returning new meshes.
//!
//! Every generator checks every parameter: a bad one gives `HW_ERR_INVALID_INPUT` with a message
//! naming it (a NaN coordinate, too few points, a segment on the axis...), and `*out_mesh` is left
//! alone. Faces are counter-clockwise seen from outside.

use crate::mesh::Mesh;
use crate::soup::{BuildPolicy, PolygonSoup};
use crate::surfaces::{
    Caps, CellFaces, Grid, Revolution, Ruling, SurfaceError, Sweep, Torus, Turn, cube,
    cylindrical_surface, grid, icosphere, revolution_surface, ruled_surface, tetrahedron, torus,
};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::into_handle;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, arg_ref, arg_slice, guard};
use crate::ffi::mesh::lifecycle::hw_mesh;

/// How the cells of a parametric surface become faces.
/// \ingroup surfaces
pub type hw_cell_faces = u32;
/// One quadrilateral per cell (a triangle where a pole collapses a side).
/// \ingroup surfaces
pub const HW_CELL_FACES_QUADS: hw_cell_faces = 0;
/// Two triangles per cell.
/// \ingroup surfaces
pub const HW_CELL_FACES_TRIANGLES: hw_cell_faces = 1;

/// How hw_surface_revolution() closes the profile's ends that are off the axis.
/// \ingroup surfaces
pub type hw_caps = u32;
/// Leave them open.
/// \ingroup surfaces
pub const HW_CAPS_NONE: hw_caps = 0;
/// One planar polygon per end.
/// \ingroup surfaces
pub const HW_CAPS_POLYGON: hw_caps = 1;
/// A fan of triangles from a new vertex on the axis.
/// \ingroup surfaces
pub const HW_CAPS_FAN: hw_caps = 2;

impl From<SurfaceError> for FfiError {
    fn from(error: SurfaceError) -> Self {
        match error {
            SurfaceError::OutOfMemory(refusal) => refusal.into(),
            _ => FfiError::invalid_input(error.to_string()),
        }
    }
}

fn cell_faces(raw: hw_cell_faces) -> Result<CellFaces, FfiError> {
    match raw {
        HW_CELL_FACES_QUADS => Ok(CellFaces::Quads),
        HW_CELL_FACES_TRIANGLES => Ok(CellFaces::Triangles),
        other => Err(FfiError::invalid_input(format!(
            "unknown cell faces {other}"
        ))),
    }
}

fn caps_arg(raw: hw_caps) -> Result<Caps, FfiError> {
    match raw {
        HW_CAPS_NONE => Ok(Caps::None),
        HW_CAPS_POLYGON => Ok(Caps::Polygon),
        HW_CAPS_FAN => Ok(Caps::Fan),
        other => Err(FfiError::invalid_input(format!("unknown caps {other}"))),
    }
}

/// Borrows a polyline of `n_points` points (x y z each).
///
/// # Safety
/// `points` must be NULL (only with 0 points) or hold `3 * n_points` doubles.
unsafe fn polyline_arg<'a>(
    points: *const f64,
    n_points: usize,
    name: &str,
) -> Result<&'a [[f64; 3]], FfiError> {
    // SAFETY: forwarded from the caller; `[f64; 3]` has the alignment of `f64`.
    unsafe { arg_slice(points.cast::<[f64; 3]>(), n_points, name) }
}

/// Reads a 3-vector argument.
///
/// # Safety
/// `v` must be NULL or hold 3 doubles.
unsafe fn vector_arg(v: *const f64, name: &str) -> Result<[f64; 3], FfiError> {
    // SAFETY: forwarded from the caller; `[f64; 3]` has the alignment of `f64`.
    unsafe { arg_ref(v.cast::<[f64; 3]>(), name) }.copied()
}

/// Builds the mesh of a generated soup and hands it to the caller.
///
/// # Safety
/// The pointer inside `out` must be writable.
unsafe fn give_mesh(
    out: Out<*mut hw_mesh>,
    soup: Result<PolygonSoup, SurfaceError>,
) -> Result<(), FfiError> {
    let soup = soup?;
    let (mesh, _) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)?;
    // SAFETY: checked non-NULL when `out` was made; writable per the caller.
    unsafe { out.write(into_handle(hw_mesh { mesh })) };
    Ok(())
}

/// The regular tetrahedron of the winged-edge literature's worked example, with its exact
/// coordinates and faces.
///
/// # Safety
/// `out_mesh` must be writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_tetrahedron(out_mesh: *mut *mut hw_mesh) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, Ok(tetrahedron())) }
    })
}

/// An axis-aligned cube of six quads centred at the origin, `side` long (positive, finite).
///
/// # Safety
/// `out_mesh` must be writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_cube(side: f64, out_mesh: *mut *mut hw_mesh) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, cube(side)) }
    })
}

/// A sphere of triangles centred at the origin: an icosahedron subdivided `level` times (each
/// level splits every triangle in four), projected onto the sphere of `radius`.
///
/// # Safety
/// `out_mesh` must be writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_icosphere(
    radius: f64,
    level: u32,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, icosphere(radius, level)) }
    })
}

/// A closed torus about the z axis: `major_steps` segments around the axis (≥ 3) and
/// `minor_steps` around the tube (≥ 3); `minor_radius` below `major_radius`.
///
/// # Safety
/// `out_mesh` must be writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_torus(
    major_radius: f64,
    minor_radius: f64,
    major_steps: u32,
    minor_steps: u32,
    faces: hw_cell_faces,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        let shape = Torus {
            major_radius,
            minor_radius,
            major_steps,
            minor_steps,
            faces: cell_faces(faces)?,
        };
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, torus(&shape)) }
    })
}

/// A flat grid in the plane z = 0 centred at the origin, facing +z: `cells_x` by `cells_y` cells
/// (≥ 1 each) over `width` by `height`. Open, one boundary loop.
///
/// # Safety
/// `out_mesh` must be writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_grid(
    width: f64,
    height: f64,
    cells_x: u32,
    cells_y: u32,
    faces: hw_cell_faces,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        let shape = Grid {
            width,
            height,
            cells_x,
            cells_y,
            faces: cell_faces(faces)?,
        };
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, grid(&shape)) }
    })
}

/// A cylindrical surface: the polyline `profile` (`n_points` points, x y z each; closed joins the
/// last point to the first) swept along the vector `direction` (3 doubles) in `steps` rows (≥ 1).
/// Faces follow `P'(u) × direction`.
///
/// # Safety
/// `profile` must hold `3 * n_points` doubles; `direction` 3 doubles; `out_mesh` writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_sweep(
    profile: *const f64,
    n_points: usize,
    closed: bool,
    direction: *const f64,
    steps: u32,
    faces: hw_cell_faces,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let (profile, direction) = unsafe {
            (
                polyline_arg(profile, n_points, "profile")?,
                vector_arg(direction, "direction")?,
            )
        };
        let sweep = Sweep {
            profile,
            closed_profile: closed,
            direction,
            steps,
            faces: cell_faces(faces)?,
        };
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, cylindrical_surface(&sweep)) }
    })
}

/// A surface of revolution: `profile` (`n_points` points) turned about the axis through
/// `axis_origin` along `axis_direction` (3 doubles each), right-handed. `full_turn` welds the
/// last column to the first; otherwise the turn is `angle` radians, in (0, 2π). `steps` angular
/// steps (≥ 3 for a full turn, ≥ 1 otherwise). Profile points on the axis become poles; `caps`
/// closes the ends that are off it.
///
/// # Safety
/// `profile` must hold `3 * n_points` doubles; `axis_origin` and `axis_direction` 3 doubles
/// each; `out_mesh` writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_revolution(
    profile: *const f64,
    n_points: usize,
    closed: bool,
    axis_origin: *const f64,
    axis_direction: *const f64,
    full_turn: bool,
    angle: f64,
    steps: u32,
    caps: hw_caps,
    faces: hw_cell_faces,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let (profile, axis_origin, axis_direction) = unsafe {
            (
                polyline_arg(profile, n_points, "profile")?,
                vector_arg(axis_origin, "axis_origin")?,
                vector_arg(axis_direction, "axis_direction")?,
            )
        };
        let revolution = Revolution {
            profile,
            closed_profile: closed,
            axis_origin,
            axis_direction,
            turn: if full_turn {
                Turn::Full
            } else {
                Turn::Partial(angle)
            },
            steps,
            caps: caps_arg(caps)?,
            faces: cell_faces(faces)?,
        };
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, revolution_surface(&revolution)) }
    })
}

/// A ruled surface joining `first[i]` to `second[i]` (both `n_points` points, x y z each) with
/// straight rulings, `steps` rows (≥ 1) between them; `closed` joins the curves' ends.
///
/// # Safety
/// `first` and `second` must hold `3 * n_points` doubles each; `out_mesh` writable.
/// \ingroup surfaces
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_surface_ruled(
    first: *const f64,
    second: *const f64,
    n_points: usize,
    closed: bool,
    steps: u32,
    faces: hw_cell_faces,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let (first, second) = unsafe {
            (
                polyline_arg(first, n_points, "first")?,
                polyline_arg(second, n_points, "second")?,
            )
        };
        let ruling = Ruling {
            first,
            second,
            closed,
            steps,
            faces: cell_faces(faces)?,
        };
        // SAFETY: forwarded from the caller.
        unsafe { give_mesh(out, ruled_surface(&ruling)) }
    })
}
