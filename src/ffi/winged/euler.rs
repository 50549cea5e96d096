//! Baumgart's Euler operators on an `hw_winged`, and garbage collection after the kills.
//!
//! Each operator keeps V − E + F consistent (MVFS adds a solid: one vertex and one face). Every
//! precondition is checked before anything changes: a refused operator returns
//! `HW_ERR_REFUSED` (a precondition does not hold), `HW_ERR_INVALID_HANDLE` (an id that does not
//! exist) or `HW_ERR_INVALID_INPUT` (a non-finite position), with the reason in the last-error
//! message, and leaves the structure exactly as it was.
//!
//! A cube, operator by operator:
//! ```c
//! hw_wvertex v0, v1; hw_wface f; hw_wedge e;
//! hw_winged_mvfs(w, p0, &v0, &f);          // one vertex, one (point) face
//! hw_winged_mev(w, f, v0, p1, &e, &v1);    // an edge to a new vertex
//! hw_winged_mef(w, f, v3, v0, &e, &top);   // an edge closing a new face
//! ```

use crate::ffi::boundary::handle::into_handle;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, guard, point_arg};
use crate::ffi::mesh::edit::hw_index_maps;
use crate::ffi::winged::lifecycle::{hw_wedge, hw_wface, hw_winged, hw_wvertex, winged_mut};

/// **Make vertex, face, solid**: a new solid of one vertex at `position[0..3]` and one face
/// without edges (a point face). Writes the vertex and the face.
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call; `position`
/// must point to 3 readable doubles (NULL gives `HW_ERR_NULL_ARGUMENT`); `out_vertex` and
/// `out_face` writable.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_mvfs(
    winged: *mut hw_winged,
    position: *const f64,
    out_vertex: *mut hw_wvertex,
    out_face: *mut hw_wface,
) -> hw_status {
    guard(|| {
        let (out_vertex, out_face) = (
            Out::new(out_vertex, "out_vertex")?,
            Out::new(out_face, "out_face")?,
        );
        // SAFETY: forwarded from the caller.
        let (w, p) = unsafe { (winged_mut(winged)?, point_arg(position, "position")?) };
        let (v, f) = w.mvfs(p)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_vertex.write(v.into());
            out_face.write(f.into());
        }
        Ok(())
    })
}

/// **Make edge, vertex**: a new vertex at `position[0..3]` joined to `vertex` by a new edge
/// `vertex → new vertex` lying inside `face` (both its sides are `face`). `vertex` must occur
/// exactly once on `face`'s loop, or be the vertex of a point face. Writes the edge and vertex.
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call; `position`
/// must point to 3 readable doubles (NULL gives `HW_ERR_NULL_ARGUMENT`); `out_edge` and
/// `out_vertex` writable.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_mev(
    winged: *mut hw_winged,
    face: hw_wface,
    vertex: hw_wvertex,
    position: *const f64,
    out_edge: *mut hw_wedge,
    out_vertex: *mut hw_wvertex,
) -> hw_status {
    guard(|| {
        let (out_edge, out_vertex) = (
            Out::new(out_edge, "out_edge")?,
            Out::new(out_vertex, "out_vertex")?,
        );
        // SAFETY: forwarded from the caller.
        let (w, p) = unsafe { (winged_mut(winged)?, point_arg(position, "position")?) };
        let (e, v) = w.mev(face.into(), vertex.into(), p)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_edge.write(e.into());
            out_vertex.write(v.into());
        }
        Ok(())
    })
}

/// **Make edge, face**: splits `face` with a new edge `v1 → v2`. The new face is the new edge's
/// left side (the part of the loop from `v2` back to `v1`); `face` keeps the part from `v1` to
/// `v2`. `v1` and `v2` must differ and each occur exactly once on `face`'s loop. Writes the edge
/// and the new face.
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call; `out_edge`
/// and `out_face` writable.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_mef(
    winged: *mut hw_winged,
    face: hw_wface,
    v1: hw_wvertex,
    v2: hw_wvertex,
    out_edge: *mut hw_wedge,
    out_face: *mut hw_wface,
) -> hw_status {
    guard(|| {
        let (out_edge, out_face) = (
            Out::new(out_edge, "out_edge")?,
            Out::new(out_face, "out_face")?,
        );
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_mut(winged) }?;
        let (e, f) = w.mef(face.into(), v1.into(), v2.into())?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_edge.write(e.into());
            out_face.write(f.into());
        }
        Ok(())
    })
}

/// **Kill edge, vertex** (inverse of MEV): removes `vertex` and `edge`, which must be its only
/// edge. When `edge` was its solid's last edge, the face becomes a point face on the other vertex.
/// Refused (`HW_ERR_REFUSED`, nothing changed) when `vertex` has other edges, also in another fan
/// of a pinched vertex, and when the last edge's other vertex has edges in another fan (a point
/// face's vertex has none).
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_kev(
    winged: *mut hw_winged,
    edge: hw_wedge,
    vertex: hw_wvertex,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    guard(|| Ok(unsafe { winged_mut(winged) }?.kev(edge.into(), vertex.into())?))
}

/// **Kill edge, face** (inverse of MEF): removes `edge` and the face `kill` on one of its sides,
/// merging `kill` into the face on the other side. The two sides must be two different faces.
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_kef(
    winged: *mut hw_winged,
    edge: hw_wedge,
    kill: hw_wface,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    guard(|| Ok(unsafe { winged_mut(winged) }?.kef(edge.into(), kill.into())?))
}

/// **Kill vertex, face, solid** (inverse of MVFS): removes a point face and its vertex.
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_kvfs(winged: *mut hw_winged, face: hw_wface) -> hw_status {
    // SAFETY: forwarded from the caller.
    guard(|| Ok(unsafe { winged_mut(winged) }?.kvfs(face.into())?))
}

/// Drops the elements the kill operators deleted and renumbers the live ones densely, keeping
/// their order. Every id held from before (and every view) is invalidated. When `out_maps` is not
/// NULL it receives the old-to-new maps (read with hw_index_maps_view(): vertices, edges and
/// faces; the half-edge map is empty; deleted → `HW_INVALID_INDEX`).
///
/// # Safety
/// `winged` must be NULL or a live structure used by no one else during the call; `out_maps`
/// NULL or writable.
/// \ingroup winged_edit
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_garbage_collect(
    winged: *mut hw_winged,
    out_maps: *mut *mut hw_index_maps,
) -> hw_status {
    guard(|| {
        let out = Out::optional(out_maps);
        // SAFETY: forwarded from the caller.
        let maps = unsafe { winged_mut(winged) }?.garbage_collect();
        if let Some(out) = out {
            // SAFETY: checked non-NULL, writable per the caller.
            unsafe { out.write(into_handle(hw_index_maps { maps })) };
        }
        Ok(())
    })
}
