//! Whole-mesh topology on a `const hw_mesh *`: validation, boundary loops, components.

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, copy_items, guard};
use crate::ffi::mesh::elements::hw_halfedge;
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// Validates every invariant of the half-edge structure (twins, next/prev, closed face and
/// boundary loops, vertex half-edges outgoing and on the boundary when there is one, ids in
/// range), with every walk bounded. `HW_OK`, or `HW_ERR_INVALID_INPUT` with a message naming the
/// first broken invariant and its element.
///
/// # Safety
/// `mesh` must be NULL or a live mesh.
/// \ingroup topology
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_check(mesh: *const hw_mesh) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        unsafe { mesh_ref(mesh) }?
            .check()
            .map_err(|broken| FfiError::invalid_input(broken.to_string()))
    })
}

/// Number of boundary loops (holes and open borders).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_count` writable.
/// \ingroup topology
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_boundary_loops(
    mesh: *const hw_mesh,
    out_count: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_count, "out_count")?;
        // SAFETY: forwarded from the caller.
        let loops = unsafe { mesh_ref(mesh) }?.boundary_loops().len();
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(loops) };
        Ok(())
    })
}

/// One half-edge of every boundary loop (the lowest id of the loop), ascending, copied into
/// `out_halfedges` (`capacity` elements). `*out_needed` always receives the loop count; walk a loop
/// with hw_mesh_he_next() or hw_circ_along_loop().
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_halfedges` NULL or `capacity` writable elements;
/// `out_needed` NULL or writable.
/// \ingroup topology
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_boundary_loops(
    mesh: *const hw_mesh,
    out_halfedges: *mut hw_halfedge,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let loops: Vec<hw_halfedge> = unsafe { mesh_ref(mesh) }?
            .boundary_loops()
            .into_iter()
            .map(Into::into)
            .collect();
        // SAFETY: forwarded from the caller.
        unsafe { copy_items(&loops, out_halfedges, capacity, out_needed, "out_halfedges") }
    })
}

/// Number of connected components (faces connected across edges, as CGAL and OpenMesh count
/// them; fans that only touch at a vertex are separate).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_count` writable.
/// \ingroup topology
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_components(
    mesh: *const hw_mesh,
    out_count: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_count, "out_count")?;
        // SAFETY: forwarded from the caller.
        let count = unsafe { mesh_ref(mesh) }?.connected_components().count;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(count) };
        Ok(())
    })
}

/// The component of every face (`0..count`, numbered by lowest face; `HW_INVALID_INDEX` for a
/// deleted face), indexed by face id, copied into `out_components` (`capacity` elements).
/// `*out_needed` always receives the number of face slots.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_components` NULL or `capacity` writable elements;
/// `out_needed` NULL or writable.
/// \ingroup topology
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_face_components(
    mesh: *const hw_mesh,
    out_components: *mut u32,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let components = unsafe { mesh_ref(mesh) }?.connected_components();
        // SAFETY: forwarded from the caller.
        unsafe {
            copy_items(
                &components.face_component,
                out_components,
                capacity,
                out_needed,
                "out_components",
            )
        }
    })
}
