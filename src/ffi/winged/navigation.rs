//! One step on a `const hw_winged *`: live-element tests, an edge's record, a vertex's and a
//! face's edge.

use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, give_view, guard};
use crate::ffi::winged::lifecycle::{
    hw_wedge, hw_wedge_record, hw_wface, hw_winged, hw_wvertex, query, winged_ref,
};

/// Whether `v` names a live vertex (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_vertex(winged: *const hw_winged, v: hw_wvertex) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_vertex(v.into()))) }
}

/// Whether `e` names a live edge (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_edge(winged: *const hw_winged, e: hw_wedge) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_edge(e.into()))) }
}

/// Whether `f` names a live face (false for a NULL structure, with the error recorded).
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_is_face(winged: *const hw_winged, f: hw_wface) -> bool {
    unsafe { query(winged, false, |w| Ok(w.is_face(f.into()))) }
}

/// Copies the record of edge `e` (its vertices, faces and wings) into `*out_record`.
/// `HW_ERR_INVALID_HANDLE` for an edge that does not exist or was deleted.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_record` writable.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_edge(
    winged: *const hw_winged,
    e: hw_wedge,
    out_record: *mut hw_wedge_record,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_record, "out_record")?;
        // SAFETY: forwarded from the caller.
        let record = unsafe { winged_ref(winged) }?.edge(e.into())?.into();
        // SAFETY: checked non-NULL; writable per the caller.
        unsafe { out.write(record) };
        Ok(())
    })
}

/// A zero-copy, read-only view of all edge records, indexed by edge id: `*out_records` (NULL when
/// there are none) and `*out_len`. A deleted edge's record has `start.idx == HW_INVALID_INDEX`.
/// Valid until the next call that modifies the structure.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_records` and `out_len` writable.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_edge_records(
    winged: *const hw_winged,
    out_records: *mut *const hw_wedge_record,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_records, "out_records", out_len, || {
            let records = winged_ref(winged)?.edge_records();
            // SAFETY: `hw_wedge_record` and `EdgeRecord` are both `repr(C)` structs of eight
            // 32-bit ids in the same order (sizes and alignments asserted above), so the slice
            // reads as either type.
            Ok(std::slice::from_raw_parts(
                records.as_ptr().cast::<hw_wedge_record>(),
                records.len(),
            ))
        })
    }
}

/// The edge vertex `v` stores: its ring starts there (for a boundary vertex, the edge whose side
/// leaving `v` is a hole). Invalid for an isolated vertex, and (with the error recorded) for a
/// vertex that does not exist.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_vertex_edge(
    winged: *const hw_winged,
    v: hw_wvertex,
) -> hw_wedge {
    unsafe {
        query(winged, hw_wedge::INVALID, |w| {
            Ok(w.vertex_edge(v.into())?.into())
        })
    }
}

/// The edge face `f` stores: its loop starts there. Invalid for a point face (made by
/// hw_winged_mvfs()), and (with the error recorded) for a face that does not exist.
///
/// # Safety
/// `winged` must be NULL or a live structure.
/// \ingroup winged_navigation
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_face_edge(winged: *const hw_winged, f: hw_wface) -> hw_wedge {
    unsafe {
        query(winged, hw_wedge::INVALID, |w| {
            Ok(w.face_edge(f.into())?.into())
        })
    }
}
