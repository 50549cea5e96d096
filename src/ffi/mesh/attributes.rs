//! Attributes of a `hw_mesh *`: per-corner normals and texture coordinates, and named user
//! columns of plain numbers on vertices, half-edges, edges or faces.
//!
//! A column holds `components` values per element slot (deleted slots included, until
//! hw_mesh_garbage_collect()), element `i` owning values `i * components .. (i + 1) *
//! components`. Views and writable pointers stay valid until the next call that modifies the
//! mesh. Every edit carries the values along by documented rules (the Rust `mesh::attributes`
//! module docs): new elements start at zero, an edge split blends, splits copy, compaction
//! follows the index maps. Corner normals and texture coordinates are the half-edge attributes
//! `"hw:corner_normal"` (`double` × 3) and `"hw:corner_uv"` (`double` × 2); the corner of vertex
//! `v` in face `f` is the half-edge of `f` leaving `v`.

use std::ffi::{CStr, c_char, c_void};

use crate::mesh::{AttributeError, ElementKind, Mesh, ScalarType};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{
    Out, arg_mut, arg_ref, arg_slice, copy_text, give_pointer, guard, view_start, view_start_mut,
    write_tuple_view,
};
use crate::ffi::mesh::elements::{element_kind, hw_element_kind};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// The numeric type of an attribute column.
/// \ingroup attributes
pub type hw_scalar_type = u32;
/// `double`.
/// \ingroup attributes
pub const HW_SCALAR_TYPE_F64: hw_scalar_type = 0;
/// `float`.
/// \ingroup attributes
pub const HW_SCALAR_TYPE_F32: hw_scalar_type = 1;
/// `int32_t`.
/// \ingroup attributes
pub const HW_SCALAR_TYPE_I32: hw_scalar_type = 2;
/// `uint32_t`.
/// \ingroup attributes
pub const HW_SCALAR_TYPE_U32: hw_scalar_type = 3;

fn scalar_type(raw: hw_scalar_type) -> Result<ScalarType, FfiError> {
    match raw {
        HW_SCALAR_TYPE_F64 => Ok(ScalarType::F64),
        HW_SCALAR_TYPE_F32 => Ok(ScalarType::F32),
        HW_SCALAR_TYPE_I32 => Ok(ScalarType::I32),
        HW_SCALAR_TYPE_U32 => Ok(ScalarType::U32),
        other => Err(FfiError::invalid_input(format!(
            "unknown scalar type {other}"
        ))),
    }
}

fn raw_scalar_type(scalar: ScalarType) -> hw_scalar_type {
    match scalar {
        ScalarType::F64 => HW_SCALAR_TYPE_F64,
        ScalarType::F32 => HW_SCALAR_TYPE_F32,
        ScalarType::I32 => HW_SCALAR_TYPE_I32,
        ScalarType::U32 => HW_SCALAR_TYPE_U32,
    }
}

impl From<AttributeError> for FfiError {
    fn from(error: AttributeError) -> Self {
        let status = match error {
            AttributeError::NotFound { .. } => HW_ERR_NOT_FOUND,
            AttributeError::OutOfMemory(_) => HW_ERR_OUT_OF_MEMORY,
            _ => HW_ERR_INVALID_INPUT,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Borrows a NUL-terminated UTF-8 attribute name.
///
/// # Safety
/// `name` must be NULL or NUL-terminated.
unsafe fn name_arg<'a>(name: *const c_char) -> Result<&'a str, FfiError> {
    // SAFETY: forwarded from the caller.
    let name = unsafe { CStr::from_ptr(arg_ref(name, "name")?) };
    name.to_str()
        .map_err(|_| FfiError::invalid_input("attribute name is not UTF-8"))
}

/// The column's values as raw memory: start (NULL when empty) and scalar count, after checking
/// that it holds `expected`.
fn column_memory(
    mesh: &Mesh,
    kind: ElementKind,
    name: &str,
    expected: ScalarType,
) -> Result<(*const c_void, usize), FfiError> {
    fn raw<T>(values: &[T]) -> (*const c_void, usize) {
        (view_start(values).cast(), values.len())
    }
    Ok(match expected {
        ScalarType::F64 => raw(mesh.attribute::<f64>(kind, name)?),
        ScalarType::F32 => raw(mesh.attribute::<f32>(kind, name)?),
        ScalarType::I32 => raw(mesh.attribute::<i32>(kind, name)?),
        ScalarType::U32 => raw(mesh.attribute::<u32>(kind, name)?),
    })
}

/// The column's values as writable raw memory (see [`column_memory`]), borrowed mutably so
/// that writing through the pointer is sound.
fn column_memory_mut(
    mesh: &mut Mesh,
    kind: ElementKind,
    name: &str,
    expected: ScalarType,
) -> Result<(*mut c_void, usize), FfiError> {
    fn raw<T>(values: &mut [T]) -> (*mut c_void, usize) {
        (view_start_mut(values).cast(), values.len())
    }
    Ok(match expected {
        ScalarType::F64 => raw(mesh.attribute_mut::<f64>(kind, name)?),
        ScalarType::F32 => raw(mesh.attribute_mut::<f32>(kind, name)?),
        ScalarType::I32 => raw(mesh.attribute_mut::<i32>(kind, name)?),
        ScalarType::U32 => raw(mesh.attribute_mut::<u32>(kind, name)?),
    })
}

/// Adds a zero-filled attribute `name` of `components` (1 to 16) values of type `scalar` per
/// element of `kind`. `HW_ERR_INVALID_INPUT` when the name is taken, empty, not UTF-8 or starts
/// with `hw:` (reserved), or the kind, type or count is out of range.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_add(
    mesh: *mut hw_mesh,
    kind: hw_element_kind,
    name: *const c_char,
    scalar: hw_scalar_type,
    components: usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (mesh, name) = unsafe { (&mut arg_mut(mesh, "mesh")?.mesh, name_arg(name)?) };
        mesh.add_attribute_of_type(element_kind(kind)?, name, scalar_type(scalar)?, components)?;
        Ok(())
    })
}

/// Removes attribute `name` of `kind` (`"hw:corner_normal"` and `"hw:corner_uv"` included).
/// `HW_ERR_NOT_FOUND` when there is none.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_remove(
    mesh: *mut hw_mesh,
    kind: hw_element_kind,
    name: *const c_char,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (mesh, name) = unsafe { (&mut arg_mut(mesh, "mesh")?.mesh, name_arg(name)?) };
        mesh.remove_attribute(element_kind(kind)?, name)?;
        Ok(())
    })
}

/// The type and component count of attribute `name` of `kind` (`HW_ERR_NOT_FOUND` when there is
/// none; a way to test for one). Either output may be NULL.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `name` NULL or NUL-terminated; outputs NULL or writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_info(
    mesh: *const hw_mesh,
    kind: hw_element_kind,
    name: *const c_char,
    out_scalar: *mut hw_scalar_type,
    out_components: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (mesh, name) = unsafe { (mesh_ref(mesh)?, name_arg(name)?) };
        let info = mesh.attribute_info(element_kind(kind)?, name)?;
        // SAFETY: each output is NULL (skipped) or writable per the caller.
        unsafe {
            if let Some(out) = Out::optional(out_scalar) {
                out.write(raw_scalar_type(info.scalar));
            }
            if let Some(out) = Out::optional(out_components) {
                out.write(info.components);
            }
        }
        Ok(())
    })
}

/// A read-only view of attribute `name` of `kind`, which must hold `scalar` values:
/// `*out_data` (cast it to `const double *`, `const float *`, ...; NULL when empty) holds
/// `*out_len` scalars, `components` per element slot. `HW_ERR_NOT_FOUND` for an unknown name,
/// `HW_ERR_INVALID_INPUT` for another type.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `name` NULL or NUL-terminated; `out_data`, `out_len`
/// writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_view(
    mesh: *const hw_mesh,
    kind: hw_element_kind,
    name: *const c_char,
    scalar: hw_scalar_type,
    out_data: *mut *const c_void,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_pointer(out_data, "out_data", out_len, || {
            let (mesh, name) = (mesh_ref(mesh)?, name_arg(name)?);
            column_memory(mesh, element_kind(kind)?, name, scalar_type(scalar)?)
        })
    }
}

/// Writable access to attribute `name` of `kind` (layout as hw_mesh_attribute_view()): write
/// through `*out_data` (NULL when empty) until the next call that modifies the mesh.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `name` NULL or NUL-terminated;
/// `out_data`, `out_len` writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_data(
    mesh: *mut hw_mesh,
    kind: hw_element_kind,
    name: *const c_char,
    scalar: hw_scalar_type,
    out_data: *mut *mut c_void,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_pointer(out_data, "out_data", out_len, || {
            let (mesh, name) = (&mut arg_mut(mesh, "mesh")?.mesh, name_arg(name)?);
            column_memory_mut(mesh, element_kind(kind)?, name, scalar_type(scalar)?)
        })
    }
}

/// Number of attributes of `kind` (halfwing's own `hw:` ones included).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_count` writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_n_attributes(
    mesh: *const hw_mesh,
    kind: hw_element_kind,
    out_count: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_count, "out_count")?;
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        let count = mesh.attribute_names(element_kind(kind)?).count();
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(count) };
        Ok(())
    })
}

/// Copies the name of attribute number `index` (`0 .. count`, in the order they were added) of
/// `kind` NUL-terminated into `out_text` of `capacity` bytes; `*out_needed` (when not NULL)
/// receives the size needed. `HW_ERR_BUFFER_TOO_SMALL` when it does not fit, `HW_ERR_NOT_FOUND`
/// when `index` is past the last.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_text` NULL or `capacity` writable bytes; `out_needed`
/// NULL or writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_attribute_name(
    mesh: *const hw_mesh,
    kind: hw_element_kind,
    index: usize,
    out_text: *mut c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        let kind = element_kind(kind)?;
        let name = mesh.attribute_names(kind).nth(index).ok_or_else(|| {
            FfiError::new(
                HW_ERR_NOT_FOUND,
                format!("{kind} attribute number {index} does not exist"),
            )
        })?;
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(name, out_text, capacity, out_needed) }
    })
}

/// A view of a corner attribute as `N` doubles per half-edge slot. `data_name` is the pointer
/// output's name in the C signature (`out_xyz`, `out_uv`), for the message.
///
/// # Safety
/// As for hw_mesh_corner_normals_view().
unsafe fn corner_view<const N: usize>(
    mesh: *const hw_mesh,
    values: fn(&Mesh) -> Option<&[[f64; N]]>,
    name: &str,
    out_data: *mut *const f64,
    data_name: &str,
    out_n_halfedges: *mut usize,
) -> hw_status {
    guard(|| {
        let out_data = Out::new(out_data, data_name)?;
        let out_n = Out::new(out_n_halfedges, "out_n_halfedges")?;
        // SAFETY: forwarded from the caller.
        let mesh = unsafe { mesh_ref(mesh) }?;
        let values = values(mesh)
            .ok_or_else(|| FfiError::new(HW_ERR_NOT_FOUND, format!("the mesh has no {name}")))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(out_data, out_n, values) };
        Ok(())
    })
}

/// Sets a corner attribute from `N` doubles per half-edge slot. `data_name` is the array's name
/// in the C signature (`xyz`, `uv`), for the message.
///
/// # Safety
/// As for hw_mesh_corner_normals_set().
unsafe fn corner_set<const N: usize>(
    mesh: *mut hw_mesh,
    set: fn(&mut Mesh, &[[f64; N]]) -> Result<(), AttributeError>,
    data: *const f64,
    data_name: &str,
    n_halfedges: usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let mesh = &mut unsafe { arg_mut(mesh, "mesh") }?.mesh;
        // SAFETY: forwarded from the caller: `n_halfedges` vectors of N doubles.
        let values = unsafe { arg_slice(data.cast::<[f64; N]>(), n_halfedges, data_name) }?;
        if let Some(bad) = values.iter().position(|v| v.iter().any(|x| !x.is_finite())) {
            return Err(FfiError::invalid_input(format!(
                "half-edge {bad}: value {:?} is not finite",
                values[bad]
            )));
        }
        set(mesh, values)?;
        Ok(())
    })
}

/// A read-only view of the corner normals: `*out_xyz` holds `3 * *out_n_halfedges` doubles (x,
/// y, z per half-edge slot, boundary ones included; NULL when empty). `HW_ERR_NOT_FOUND` when
/// the mesh has none (a mesh read from a file with normals, or given them with
/// hw_mesh_corner_normals_set(), has them). A zero normal means the corner has none: boundary
/// half-edges, and the corners an OBJ gives no normal while giving others one.
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_xyz` and `out_n_halfedges` writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_corner_normals_view(
    mesh: *const hw_mesh,
    out_xyz: *mut *const f64,
    out_n_halfedges: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        corner_view(
            mesh,
            Mesh::corner_normals,
            "corner normals",
            out_xyz,
            "out_xyz",
            out_n_halfedges,
        )
    }
}

/// Sets the corner normals (adding them when the mesh has none) from `3 * n_halfedges` finite
/// doubles; `n_halfedges` must be the half-edge slot count (hw_mesh_n_halfedge_slots()). Writing
/// single values in place: hw_mesh_attribute_data() on `"hw:corner_normal"`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `xyz` NULL or `3 * n_halfedges`
/// doubles.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_corner_normals_set(
    mesh: *mut hw_mesh,
    xyz: *const f64,
    n_halfedges: usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { corner_set(mesh, Mesh::set_corner_normals, xyz, "xyz", n_halfedges) }
}

/// A read-only view of the corner texture coordinates: `*out_uv` holds `2 * *out_n_halfedges`
/// doubles (u, v per half-edge slot; NULL when empty). `HW_ERR_NOT_FOUND` when the mesh has none.
/// Corners an OBJ gives no texture coordinate while giving others one hold (0, 0).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_uv` and `out_n_halfedges` writable.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_corner_uvs_view(
    mesh: *const hw_mesh,
    out_uv: *mut *const f64,
    out_n_halfedges: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        corner_view(
            mesh,
            Mesh::corner_uvs,
            "corner texture coordinates",
            out_uv,
            "out_uv",
            out_n_halfedges,
        )
    }
}

/// Sets the corner texture coordinates (adding them when needed) from `2 * n_halfedges` finite
/// doubles, `n_halfedges` being the half-edge slot count.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `uv` NULL or `2 * n_halfedges`
/// doubles.
/// \ingroup attributes
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_corner_uvs_set(
    mesh: *mut hw_mesh,
    uv: *const f64,
    n_halfedges: usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { corner_set(mesh, Mesh::set_corner_uvs, uv, "uv", n_halfedges) }
}
