//! Files: reading OBJ, OFF and PLY into an indexed face list (`hw_soup`) or straight into a mesh,
//! and writing a mesh out. The format follows the path's extension (`.obj`, `.off`, `.ply`).

use std::ffi::{CStr, c_char};
use std::path::PathBuf;

use crate::io::{IoError, read_path, write_path};
use crate::mesh::Mesh;
use crate::soup::PolygonSoup;

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_ref, guard, guard_void, view_start, write_view};
use crate::ffi::mesh::diagnostic::{give_built, hw_diagnostic};
use crate::ffi::mesh::lifecycle::{build_policy, hw_build_policy, hw_mesh, mesh_ref};

/// An indexed face list read from a file, exactly as the file numbers its vertices (nothing
/// welded, reordered or dropped). Opaque; read with hw_soup_read(), look at with hw_soup_view(),
/// release with hw_soup_free().
/// \ingroup io
pub struct hw_soup {
    pub(crate) soup: PolygonSoup,
}

impl From<IoError> for FfiError {
    fn from(error: IoError) -> Self {
        let status = match &error {
            IoError::Io(io) | IoError::File { source: io, .. }
                if io.kind() == std::io::ErrorKind::OutOfMemory =>
            {
                HW_ERR_OUT_OF_MEMORY
            }
            IoError::Io(_) | IoError::File { .. } => HW_ERR_IO,
            IoError::Parse { .. } => HW_ERR_PARSE,
            IoError::OutOfMemory(_) => HW_ERR_OUT_OF_MEMORY,
            _ => HW_ERR_INVALID_INPUT,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Borrows a NUL-terminated path argument.
///
/// # Safety
/// `path` must be NULL or a NUL-terminated string.
pub(crate) unsafe fn path_arg(path: *const c_char) -> Result<PathBuf, FfiError> {
    // SAFETY: forwarded from the caller.
    let path = unsafe { CStr::from_ptr(arg_ref(path, "path")?) };
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        Ok(PathBuf::from(std::ffi::OsStr::from_bytes(path.to_bytes())))
    }
    #[cfg(not(unix))]
    {
        path.to_str()
            .map(PathBuf::from)
            .map_err(|_| FfiError::invalid_input("path is not UTF-8"))
    }
}

/// Reads a mesh file into an indexed face list. Malformed files give `HW_ERR_PARSE` with the
/// line (or binary PLY record) and the problem; unreadable ones `HW_ERR_IO`; an unknown extension
/// `HW_ERR_INVALID_INPUT`.
///
/// # Safety
/// `path` must be NULL or NUL-terminated; `out_soup` writable.
/// \ingroup io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_read(
    path: *const c_char,
    out_soup: *mut *mut hw_soup,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_soup, "out_soup")?;
        // SAFETY: forwarded from the caller.
        let soup = read_path(unsafe { path_arg(path) }?)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_soup { soup })) };
        Ok(())
    })
}

/// Zero-copy views of a soup's arrays, in the form hw_mesh_from_indexed() takes: positions
/// (`3 * n_vertices` doubles), face sizes (`n_faces`) and corner indices (`n_indices`). They live
/// as long as the soup; an empty array's pointer is NULL. Any output pointer may be NULL when not
/// wanted.
///
/// # Safety
/// `soup` must be NULL or live; each output NULL or writable.
/// \ingroup io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_view(
    soup: *const hw_soup,
    out_positions: *mut *const f64,
    out_n_vertices: *mut usize,
    out_face_sizes: *mut *const u32,
    out_n_faces: *mut usize,
    out_indices: *mut *const u32,
    out_n_indices: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let soup = &unsafe { arg_ref(soup, "soup") }?.soup;
        // SAFETY: each output is NULL (skipped) or writable per the caller.
        unsafe {
            if let Some(out) = Out::optional(out_positions) {
                out.write(view_start(soup.positions.as_flattened()));
            }
            if let Some(out) = Out::optional(out_n_vertices) {
                out.write(soup.positions.len());
            }
            if let (Some(data), Some(len)) =
                (Out::optional(out_face_sizes), Out::optional(out_n_faces))
            {
                write_view(data, len, &soup.face_sizes);
            } else if let Some(len) = Out::optional(out_n_faces) {
                len.write(soup.face_sizes.len());
            }
            if let (Some(data), Some(len)) =
                (Out::optional(out_indices), Out::optional(out_n_indices))
            {
                write_view(data, len, &soup.indices);
            } else if let Some(len) = Out::optional(out_n_indices) {
                len.write(soup.indices.len());
            }
        }
        Ok(())
    })
}

/// Releases a soup. NULL is a no-op; a second free is refused (within the limits the ownership
/// conventions at the top of the header state).
///
/// # Safety
/// `soup` must be NULL or a soup from this library, not in use by another thread.
/// \ingroup io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_free(soup: *mut hw_soup) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(soup, "hw_soup") });
}

/// Reads a mesh file and builds a mesh from it, as hw_soup_read() then hw_mesh_from_indexed()
/// would (same policies, same diagnostic, also on a refusal; `out_diagnostic` may be NULL), keeping the file's
/// normals and texture coordinates per corner (hw_mesh_corner_normals_view(),
/// hw_mesh_corner_uvs_view()); hw_mesh_write() writes them back. When an OBJ gives them to some
/// corners only, the others get the zero normal (no direction: render buffers use their computed
/// normal there) and the texture coordinate (0, 0).
///
/// # Safety
/// `path` must be NULL or NUL-terminated; `out_mesh` writable; `out_diagnostic` NULL or writable.
/// \ingroup io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_read(
    path: *const c_char,
    policy: hw_build_policy,
    out_mesh: *mut *mut hw_mesh,
    out_diagnostic: *mut *mut hw_diagnostic,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_built(out_mesh, "out_mesh", out_diagnostic, || {
            let policy = build_policy(policy)?;
            let soup = read_path(path_arg(path)?)?;
            let built = with_threads(|| Mesh::from_soup(&soup, policy));
            Ok(built.map(|(mesh, diagnostic)| (hw_mesh { mesh }, diagnostic)))
        })
    }
}

/// Writes a mesh to a file (format by extension; PLY is written binary little-endian). Deleted
/// elements are left out.
///
/// # Safety
/// `mesh` must be NULL or live; `path` NULL or NUL-terminated.
/// \ingroup io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_write(mesh: *const hw_mesh, path: *const c_char) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let (mesh, path) = unsafe { (mesh_ref(mesh)?, path_arg(path)?) };
        write_path(path, &mesh.to_soup())?;
        Ok(())
    })
}
