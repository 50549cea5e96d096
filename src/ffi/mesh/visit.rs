//! Callbacks: a function of the caller's called with each id, with the caller's `userdata` —
//! beside copies into caller buffers, zero-copy views and stack circulators, the fourth way to
//! read many ids, for C code that keeps its state in a struct rather than in a loop.
//!
//! ```c
//! static bool add_valence(uint32_t v, void *userdata) {
//!   struct stats *s = userdata;
//!   s->valence_sum += hw_mesh_vertex_valence(s->mesh, (hw_vertex){v});
//!   return true;                       /* false stops the visit */
//! }
//! hw_mesh_visit(mesh, HW_ELEMENT_KIND_VERTEX, add_valence, &stats, NULL);
//! ```
//!
//! No Rust reference to the mesh is held while the caller's function runs (each step reads the
//! mesh anew), so the function may call any read-only function on the mesh. It must not free the
//! mesh, and must not unwind (a C++ exception, a `longjmp`) through the call: it stops a visit by
//! returning `false`. The C++ wrapper's `visit` catches exceptions for that reason.

use std::ffi::c_void;

use crate::mesh::{ElementKind, Mesh};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::{Out, arg_mut, guard};
use crate::ffi::mesh::circulator::{advance, hw_circulator};
use crate::ffi::mesh::elements::{element_kind, hw_element_kind};
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// A caller's function called once per id by the `_visit` calls, with the `userdata` given to
/// them. Returns `true` to go on, `false` to stop the visit there.
/// \ingroup circulators
pub type hw_visit_fn = Option<unsafe extern "C" fn(idx: u32, userdata: *mut c_void) -> bool>;

/// Calls `visit` for each id `next` yields until it yields none or `visit` returns `false`, and
/// writes the number of calls through `out_visited` when it is not NULL.
///
/// # Safety
/// `visit` is called with `userdata` (see the module documentation); `out_visited` must be NULL
/// or writable.
unsafe fn visit_each(
    visit: hw_visit_fn,
    userdata: *mut c_void,
    out_visited: *mut usize,
    mut next: impl FnMut() -> Result<Option<u32>, FfiError>,
) -> hw_status {
    guard(|| {
        let visit = visit.ok_or_else(|| FfiError::null_argument("visit"))?;
        let out_visited = Out::optional(out_visited);
        let mut visited = 0;
        while let Some(id) = next()? {
            visited += 1;
            // SAFETY: the caller's function, called as documented.
            if !unsafe { visit(id, userdata) } {
                break;
            }
        }
        if let Some(out) = out_visited {
            // SAFETY: non-NULL, writable per the caller.
            unsafe { out.write(visited) };
        }
        Ok(())
    })
}

/// The first live (not deleted) id of `kind` at or after `from`.
fn live_from(mesh: &Mesh, kind: ElementKind, from: u32) -> Option<u32> {
    let end = u32::try_from(mesh.n_slots(kind)).unwrap_or(u32::MAX);
    (from..end).find(|&id| !mesh.is_deleted_of(kind, id))
}

/// Calls `visit(id, userdata)` for every live (not deleted) element of `kind`
/// (::HW_ELEMENT_KIND_VERTEX, ::HW_ELEMENT_KIND_HALFEDGE, ::HW_ELEMENT_KIND_EDGE or
/// ::HW_ELEMENT_KIND_FACE), in increasing id order, until `visit` returns `false`. `*out_visited`,
/// when `out_visited` is not NULL, receives the number of calls made. `visit` may read the mesh but
/// must not free it, and must not throw or `longjmp` through this call. An empty mesh makes no
/// call.
///
/// Returns `HW_ERR_NULL_ARGUMENT` for a NULL mesh or `visit`, `HW_ERR_INVALID_INPUT` for an
/// unknown kind (no call is made then).
///
/// # Safety
/// `mesh` must be NULL or a live mesh; `out_visited` NULL or writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_visit(
    mesh: *const hw_mesh,
    kind: hw_element_kind,
    visit: hw_visit_fn,
    userdata: *mut c_void,
    out_visited: *mut usize,
) -> hw_status {
    let mut from = 0;
    // SAFETY: forwarded from the caller.
    unsafe {
        visit_each(visit, userdata, out_visited, || {
            let id = live_from(mesh_ref(mesh)?, element_kind(kind)?, from);
            from = id.map_or(u32::MAX, |id| id.saturating_add(1));
            Ok(id)
        })
    }
}

/// Calls `visit(id, userdata)` for each element `circulator` yields (ids of the kind it was
/// started with: half-edges, vertices, edges or faces), until the walk ends or `visit` returns
/// `false`; the circulator is left where the visit stopped. `*out_visited`, when `out_visited` is
/// not NULL, receives the number of calls made. `visit` may read the mesh but must not modify or
/// free it, and must not throw or `longjmp` through this call.
///
/// Returns `HW_ERR_NULL_ARGUMENT` for a NULL circulator or `visit`.
///
/// # Safety
/// `circulator` must be NULL or a circulator over a live, unmodified mesh; `out_visited` NULL or
/// writable.
/// \ingroup circulators
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_circ_visit(
    circulator: *mut hw_circulator,
    visit: hw_visit_fn,
    userdata: *mut c_void,
    out_visited: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        visit_each(visit, userdata, out_visited, || {
            let kind = arg_mut(circulator, "circulator")?.kind;
            advance(circulator, kind)
        })
    }
}
