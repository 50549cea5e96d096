//! Face, vertex and corner normals into caller buffers.
//!
//! Each array is indexed by element id and holds one normal (x, y, z) per id slot: as many as the
//! element count unless elements were deleted and not yet garbage-collected. `capacity` counts
//! normals (not doubles); `*out_needed` always receives the number of normals the array needs.
//! Degenerate and deleted faces, isolated vertices and boundary half-edges get (0, 0, 0).

use crate::geom::{VertexNormalWeighting, corner_normals, face_normals_into, normals_into};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{copy_items, guard, out_array};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// How a vertex normal weighs the faces around it.
/// \ingroup normals
pub type hw_normal_weighting = u32;
/// Unit face normals summed: OpenMesh's default, the textbook average.
/// \ingroup normals
pub const HW_NORMAL_WEIGHTING_UNIFORM: hw_normal_weighting = 0;
/// Face normals weighted by face area.
/// \ingroup normals
pub const HW_NORMAL_WEIGHTING_AREA: hw_normal_weighting = 1;
/// Unit face normals weighted by the face's angle at the vertex: pmp's default.
/// \ingroup normals
pub const HW_NORMAL_WEIGHTING_ANGLE: hw_normal_weighting = 2;

pub(crate) fn weighting(raw: hw_normal_weighting) -> Result<VertexNormalWeighting, FfiError> {
    match raw {
        HW_NORMAL_WEIGHTING_UNIFORM => Ok(VertexNormalWeighting::Uniform),
        HW_NORMAL_WEIGHTING_AREA => Ok(VertexNormalWeighting::Area),
        HW_NORMAL_WEIGHTING_ANGLE => Ok(VertexNormalWeighting::Angle),
        other => Err(FfiError::invalid_input(format!(
            "unknown normal weighting {other}"
        ))),
    }
}

/// Borrows the `slots` normals of a caller's buffer of `capacity` normals (`name` in the C
/// signature), with the protocol of [`out_array`].
///
/// # Safety
/// `out` must be NULL or point to `3 * capacity` writable doubles.
unsafe fn normal_buffer<'a>(
    out: *mut f64,
    capacity: usize,
    slots: usize,
    out_needed: *mut usize,
    name: &str,
) -> Result<&'a mut [[f64; 3]], FfiError> {
    // SAFETY: forwarded from the caller; `[f64; 3]` has the alignment of `f64`.
    unsafe { out_array(out.cast::<[f64; 3]>(), capacity, slots, out_needed, name) }
}

/// Unit face normals by Newell's method (the best-fit plane of non-planar polygons).
///
/// # Safety
/// `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
/// NULL or writable.
/// \ingroup normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_face_normals(
    mesh: *const hw_mesh,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        // SAFETY: forwarded from the caller.
        let out = unsafe {
            normal_buffer(
                out_normals,
                capacity,
                mesh.n_face_slots(),
                out_needed,
                "out_normals",
            )
        }?;
        with_threads(|| face_normals_into(mesh, out));
        Ok(())
    })
}

/// Unit vertex normals with the chosen weighting, in one pass over the faces. Every fan of a
/// non-manifold vertex counts.
///
/// # Safety
/// `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
/// NULL or writable.
/// \ingroup normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_vertex_normals(
    mesh: *const hw_mesh,
    weighting_kind: hw_normal_weighting,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        let weighting = weighting(weighting_kind)?;
        // SAFETY: forwarded from the caller.
        let out = unsafe {
            normal_buffer(
                out_normals,
                capacity,
                mesh.n_vertex_slots(),
                out_needed,
                "out_normals",
            )
        }?;
        with_threads(|| normals_into(mesh, weighting, None, out));
        Ok(())
    })
}

/// Face and vertex normals together, in one pass (what OpenMesh's `update_normals` computes):
/// `out_face_normals` needs one normal per face slot (hw_mesh_n_face_slots()),
/// `out_vertex_normals` one per vertex slot (hw_mesh_n_vertex_slots()). `*out_face_needed` and
/// `*out_vertex_needed` (each when not NULL) always receive those counts, both of them also when
/// either array is too small (then `HW_ERR_BUFFER_TOO_SMALL` and neither array is written).
///
/// # Safety
/// `mesh` must be NULL or live; `out_face_normals` NULL or `3 * face_capacity` writable doubles;
/// `out_vertex_normals` NULL or `3 * vertex_capacity` writable doubles, not overlapping
/// `out_face_normals`; `out_face_needed` and `out_vertex_needed` NULL or writable.
/// \ingroup normals
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hw_mesh_normals(
    mesh: *const hw_mesh,
    weighting_kind: hw_normal_weighting,
    out_face_normals: *mut f64,
    face_capacity: usize,
    out_face_needed: *mut usize,
    out_vertex_normals: *mut f64,
    vertex_capacity: usize,
    out_vertex_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        let weighting = weighting(weighting_kind)?;
        // Both arrays are checked (and both sizes reported) before either result is looked at.
        // SAFETY: forwarded from the caller.
        let faces = unsafe {
            normal_buffer(
                out_face_normals,
                face_capacity,
                mesh.n_face_slots(),
                out_face_needed,
                "out_face_normals",
            )
        };
        // SAFETY: forwarded from the caller.
        let vertices = unsafe {
            normal_buffer(
                out_vertex_normals,
                vertex_capacity,
                mesh.n_vertex_slots(),
                out_vertex_needed,
                "out_vertex_normals",
            )
        };
        let (faces, vertices) = (faces?, vertices?);
        with_threads(|| normals_into(mesh, weighting, Some(faces), vertices));
        Ok(())
    })
}

/// Per-corner normals, one per half-edge slot (the corner at the half-edge's origin inside its
/// face): angle-weighted over the faces around the vertex reachable without crossing a boundary or
/// an edge sharper than `crease_angle` radians. `crease_angle >= pi` gives smooth normals per fan,
/// 0 a faceted look.
///
/// # Safety
/// `mesh` must be NULL or live; `out_normals` NULL or `3 * capacity` writable doubles; `out_needed`
/// NULL or writable.
/// \ingroup normals
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_corner_normals(
    mesh: *const hw_mesh,
    crease_angle: f64,
    out_normals: *mut f64,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        if crease_angle.is_nan() || crease_angle < 0.0 {
            return Err(FfiError::invalid_input(format!(
                "crease angle {crease_angle} is not >= 0"
            )));
        }
        let normals = with_threads(|| corner_normals(mesh, crease_angle));
        // SAFETY: forwarded from the caller (capacity in normals).
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
