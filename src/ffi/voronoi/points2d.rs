//! 2D point files (`.xy`, `.cin`, `.node`, `.poly`, `.txt`, `.json`): the points a Voronoi
//! diagram is built from, read into an owned array.

use std::ffi::c_char;

use crate::io::read_points2d;

use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, arg_ref, guard, guard_void, write_tuple_view};
use crate::ffi::mesh::io::path_arg;

/// The points of a 2D point file, in file order. Opaque; read with hw_points2d_read(), look at
/// with hw_points2d_view(), release with hw_points2d_free().
/// \ingroup voronoi
pub struct hw_points2d {
    pub(crate) points: Vec<[f64; 2]>,
}

/// Reads a 2D point file, the format by the path's extension: `.xy` and `.cin` (a point per line),
/// `.node` and `.poly` (Triangle's format: a header `count 2 ...`, then `index x y ...` lines),
/// `.txt` (a count line, then a point per line), `.json` (a flat or nested array of
/// coordinates). A malformed file gives `HW_ERR_PARSE`, the message naming the file, the line and
/// the problem; an unreadable one `HW_ERR_IO`; an unknown extension `HW_ERR_INVALID_INPUT`.
/// Non-finite coordinates are read as values (hw_voronoi_build() refuses them).
///
/// # Safety
/// `path` must be NULL or NUL-terminated; `out_points` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_points2d_read(
    path: *const c_char,
    out_points: *mut *mut hw_points2d,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_points, "out_points")?;
        // SAFETY: forwarded from the caller.
        let points = read_points2d(unsafe { path_arg(path) }?)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_points2d { points })) };
        Ok(())
    })
}

/// A zero-copy view of the points: `*out_xy` (`2 * *out_n_points` doubles, x then y of each
/// point, in the form hw_voronoi_build() takes; NULL when there are none). Lives as long as the
/// points.
///
/// # Safety
/// `points` must be NULL or live; `out_xy` and `out_n_points` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_points2d_view(
    points: *const hw_points2d,
    out_xy: *mut *const f64,
    out_n_points: *mut usize,
) -> hw_status {
    guard(|| {
        let (data, len) = (
            Out::new(out_xy, "out_xy")?,
            Out::new(out_n_points, "out_n_points")?,
        );
        // SAFETY: forwarded from the caller.
        let points = &unsafe { arg_ref(points, "points") }?.points;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(data, len, points) };
        Ok(())
    })
}

/// Releases points. NULL is a no-op; a second free is refused (within the limits the ownership
/// conventions at the top of the header state).
///
/// # Safety
/// `points` must be NULL or points from this library, not in use by another thread.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_points2d_free(points: *mut hw_points2d) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(points, "hw_points2d") });
}
