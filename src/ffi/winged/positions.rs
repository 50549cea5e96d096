//! Reading and moving the vertex positions of an `hw_winged`.

use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{guard, point_arg};
use crate::ffi::winged::lifecycle::{hw_winged, hw_wvertex, winged_mut, write_triple};

/// Writes the position of `v` to `out_xyz[0..3]` (required: NULL gives `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_xyz` must point to 3 writable doubles.
/// \ingroup winged_attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_position(
    winged: *const hw_winged,
    v: hw_wvertex,
    out_xyz: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { write_triple(winged, out_xyz, "out_xyz", |w| Ok(w.position(v.into())?)) }
}

/// Moves vertex `v` to `xyz[0..3]` (finite).
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call; `xyz` 3
/// doubles.
/// \ingroup winged_attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_set_vertex_position(
    winged: *mut hw_winged,
    v: hw_wvertex,
    xyz: *const f64,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (w, p) = unsafe { (winged_mut(winged)?, point_arg(xyz, "xyz")?) };
        Ok(w.set_position(v.into(), p)?)
    })
}
