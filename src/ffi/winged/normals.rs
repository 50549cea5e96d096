//! Normals of an `hw_winged`: one face's or vertex's, or every face's or vertex's at once.

use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{copy_items, guard};
use crate::ffi::winged::lifecycle::{hw_wface, hw_winged, hw_wvertex, winged_ref, write_triple};
use crate::winged::Winged;

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

/// The unit normals of all faces by Newell's method, indexed by face id, copied into
/// `out_normals` as x, y, z per face slot (zero for deleted and degenerate faces), as
/// hw_mesh_face_normals() copies a mesh's: `capacity` and `*out_needed` count normals (3 doubles
/// each), `*out_needed` (when not NULL) always receiving the number of face slots;
/// `HW_ERR_BUFFER_TOO_SMALL` when `out_normals` is NULL or too short.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_normals` NULL or `3 * capacity` writable
/// doubles; `out_needed` NULL or writable.
/// \ingroup winged_normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_normals(
    winged: *const hw_winged,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_normals(
            winged,
            out_normals,
            capacity,
            out_needed,
            Winged::face_normals,
        )
    }
}

/// The unit normals of all vertices as hw_winged_vertex_normal() computes them, indexed by vertex
/// id (zero for deleted vertices and those without faces), copied as hw_winged_face_normals()
/// copies the faces'.
///
/// # Safety
/// As for hw_winged_face_normals().
/// \ingroup winged_normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_normals(
    winged: *const hw_winged,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_normals(
            winged,
            out_normals,
            capacity,
            out_needed,
            Winged::vertex_normals,
        )
    }
}

/// The body of the two calls above: computes the normals, then copies them (`capacity` in
/// normals).
///
/// # Safety
/// As for hw_winged_face_normals().
unsafe fn give_normals(
    winged: *const hw_winged,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
    compute: impl FnOnce(&Winged) -> Vec<[f64; 3]>,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let normals = compute(unsafe { winged_ref(winged) }?);
        // SAFETY: forwarded from the caller; `[f64; 3]` has the alignment of `f64`.
        unsafe {
            copy_items(
                &normals,
                out_normals.cast::<[f64; 3]>(),
                capacity,
                out_needed,
                "out_normals",
            )
        }
    })
}
