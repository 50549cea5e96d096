//! Reading and moving vertex positions.

use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, arg_mut, guard, point_arg};
use crate::ffi::mesh::elements::hw_vertex;
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// Copies the position of `v` into `out_xyz[0..3]`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_xyz` must hold 3 writable doubles.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_vertex_position(
    mesh: *const hw_mesh,
    v: hw_vertex,
    out_xyz: *mut f64,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_xyz.cast::<[f64; 3]>(), "out_xyz")?;
        // SAFETY: forwarded from the caller.
        let position = unsafe { mesh_ref(mesh) }?.try_position(v.into())?;
        // SAFETY: checked non-NULL, 3 writable doubles per the caller.
        unsafe { out.write(position) };
        Ok(())
    })
}

/// Moves `v` to `xyz[0..3]`. Non-finite coordinates are refused (`HW_ERR_INVALID_INPUT`).
///
/// # Safety
/// `mesh` must be NULL or a live mesh used by no other thread; `xyz` must hold 3 doubles.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_set_vertex_position(
    mesh: *mut hw_mesh,
    v: hw_vertex,
    xyz: *const f64,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (mesh, xyz) = unsafe { (arg_mut(mesh, "mesh")?, point_arg(xyz, "xyz")?) };
        Ok(mesh.mesh.set_position(v.into(), xyz)?)
    })
}
