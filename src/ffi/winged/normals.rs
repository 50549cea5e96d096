//! Normals of an `hw_winged`: one face's or vertex's, or every face's or vertex's at once.

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{copy_items, guard};
use crate::ffi::winged::lifecycle::{hw_wface, hw_winged, hw_wvertex, winged_ref, write_triple};

/// Unit normal of face `f` by Newell's method (outward for a counter-clockwise face; zero for a
/// degenerate or point face), written to `out_normal[0..3]` (required: NULL gives
/// `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
/// \ingroup winged_normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_normal(
    winged: *const hw_winged,
    f: hw_wface,
    out_normal: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        write_triple(winged, out_normal, "out_normal", |w| {
            Ok(w.face_normal(f.into())?)
        })
    }
}

/// Unit normal of vertex `v` as Baumgart's structure computes it: the normalised sum of the unit
/// normals of the faces around it (holes left out; zero if none), written to `out_normal[0..3]`
/// (required: NULL gives `HW_ERR_NULL_ARGUMENT`).
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normal` must point to 3 writable doubles.
/// \ingroup winged_normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_normal(
    winged: *const hw_winged,
    v: hw_wvertex,
    out_normal: *mut f64,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        write_triple(winged, out_normal, "out_normal", |w| {
            Ok(w.vertex_normal(v.into())?)
        })
    }
}

/// Which elements hw_winged_normals() gives normals of.
/// \ingroup winged_normals
pub type hw_wnormals = u32;
/// Face normals (Newell), indexed by face id.
/// \ingroup winged_normals
pub const HW_WNORMALS_FACES: hw_wnormals = 0;
/// Vertex normals (sum of the faces' unit normals, normalised), indexed by vertex id.
/// \ingroup winged_normals
pub const HW_WNORMALS_VERTICES: hw_wnormals = 1;

/// The unit normals of all faces or all vertices (`which`: ::HW_WNORMALS_FACES,
/// ::HW_WNORMALS_VERTICES), indexed by id, as `3 * capacity` doubles (x, y, z per element; zero for
/// deleted and degenerate elements) copied into `out_normals`, which holds `capacity` doubles.
/// `*out_needed` (when not NULL) always receives the number of doubles needed;
/// `HW_ERR_BUFFER_TOO_SMALL` when `out_normals` is NULL or too short.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normals` NULL or `capacity` writable doubles;
/// `out_needed` NULL or writable.
/// \ingroup winged_normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_normals(
    winged: *const hw_winged,
    which: hw_wnormals,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let normals = match which {
            HW_WNORMALS_FACES => w.face_normals(),
            HW_WNORMALS_VERTICES => w.vertex_normals(),
            other => {
                return Err(FfiError::invalid_input(format!(
                    "unknown normals kind {other}"
                )));
            }
        };
        // SAFETY: forwarded from the caller.
        unsafe {
            copy_items(
                normals.as_flattened(),
                out_normals,
                capacity,
                out_needed,
                "out_normals",
            )
        }
    })
}
