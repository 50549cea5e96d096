//! `hw_diagnostic`: what a build (or a bare analysis) found wrong with an indexed face list.

use crate::soup::{BuildError, Diagnostic, EdgeReport};

use crate::ffi::boundary::error::{FfiError, write_c_message};
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{
    Out, arg_ref, copy_text, give_view, guard, guard_value, guard_void, view_start,
};

/// The defects of an indexed face list, by index. Opaque; from hw_mesh_from_indexed(),
/// hw_diagnose_indexed() and the other builders; release with hw_diagnostic_free().
///
/// Two kinds of lists: the findings describe the input as it is, whatever the policy (they are
/// the same for a build and for hw_diagnose_indexed()); ::HW_DIAGNOSTIC_LIST_SKIPPED_FACES,
/// ::HW_DIAGNOSTIC_LIST_REORIENTED_FACES and ::HW_DIAGNOSTIC_LIST_VERTEX_COPIES list what the
/// policy changed. Face indices refer to the input face list, vertex indices to the input
/// positions. Faces with fewer than 3 corners, an out-of-range index or a repeated vertex are
/// listed as such and left out of the edge, fan and area findings. Every list is sorted ascending.
/// \ingroup mesh
pub struct hw_diagnostic {
    pub(crate) diagnostic: Diagnostic,
}

impl hw_diagnostic {
    pub(crate) fn into_handle(diagnostic: Diagnostic) -> *mut hw_diagnostic {
        into_handle(hw_diagnostic { diagnostic })
    }
}

/// The whole body of a build call: checks `out` (`out_name` is its name in the C signature, for
/// the message), runs `build`, then hands the object to C through `out` and, when the caller asked
/// for it, the build's diagnostic through `out_diagnostic`. An argument error writes neither; a
/// build the policy refuses writes the refusal's diagnostic through `out_diagnostic` (the one
/// output written on failure: the moment the caller needs it) and not `out`.
///
/// # Safety
/// `out` must be NULL or writable; `out_diagnostic` NULL or writable.
pub(crate) unsafe fn give_built<T: 'static>(
    out: *mut *mut T,
    out_name: &str,
    out_diagnostic: *mut *mut hw_diagnostic,
    build: impl FnOnce() -> Result<Result<(T, Diagnostic), BuildError>, FfiError>,
) -> hw_status {
    guard(|| {
        let out = Out::new(out, out_name)?;
        let out_diagnostic = Out::optional(out_diagnostic);
        let (object, diagnostic) = match build()? {
            Ok(built) => built,
            // Not a refusal of the input: there is no diagnostic to give.
            Err(BuildError::OutOfMemory(refusal)) => return Err(refusal.into()),
            Err(refused) => {
                if let Some(out_diagnostic) = out_diagnostic {
                    let diagnostic = hw_diagnostic::into_handle(refused.diagnostic().clone());
                    // SAFETY: present, writable per the caller.
                    unsafe { out_diagnostic.write(diagnostic) };
                }
                return Err(refused.into());
            }
        };
        // SAFETY: checked non-NULL (`out`) or present (`out_diagnostic`); writable per the
        // caller.
        unsafe {
            out.write(into_handle(object));
            if let Some(out_diagnostic) = out_diagnostic {
                out_diagnostic.write(hw_diagnostic::into_handle(diagnostic));
            }
        }
        Ok(())
    })
}

/// One list of element ids in a diagnostic (see hw_diagnostic_ids()). The values run from
/// ::HW_DIAGNOSTIC_LIST_FIRST to `HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT - 1`, apart
/// from the edge lists' (::hw_diagnostic_edges) and the doctor's findings' (::hw_doctor_finding),
/// so a value of one family passed where another is expected is refused, never read as a different
/// list.
/// \ingroup mesh
pub type hw_diagnostic_list = u32;
/// The first id list.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_FIRST: hw_diagnostic_list = 16;
/// Faces with fewer than 3 corners.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL: hw_diagnostic_list = 16;
/// Faces with a vertex index beyond the positions.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_FACES_OUT_OF_RANGE: hw_diagnostic_list = 17;
/// Faces naming one vertex more than once.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_FACES_REPEATED_VERTEX: hw_diagnostic_list = 18;
/// Vertices with a NaN or infinite coordinate.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_NON_FINITE_VERTICES: hw_diagnostic_list = 19;
/// Vertices whose faces form more than one fan, faces being in one fan when they share an edge
/// at the vertex (two cones touching at their tips). ::HW_BUILD_POLICY_STRICT refuses them;
/// ::HW_BUILD_POLICY_SKIP and ::HW_BUILD_POLICY_REPAIR give every fan but the first a copy of the
/// vertex.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES: hw_diagnostic_list = 20;
/// Vertices no face names (a vertex whose every face a policy left out is in the mesh without a
/// face, but not listed here).
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_ISOLATED_VERTICES: hw_diagnostic_list = 21;
/// Faces with zero area.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_DEGENERATE_FACES: hw_diagnostic_list = 22;
/// Faces left out of the mesh by ::HW_BUILD_POLICY_SKIP or ::HW_BUILD_POLICY_REPAIR: mesh face `i`
/// is the `i`-th input face not listed here.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_SKIPPED_FACES: hw_diagnostic_list = 23;
/// Vertices added by ::HW_BUILD_POLICY_SKIP or ::HW_BUILD_POLICY_REPAIR: mesh vertex
/// `n_input_vertices + i` copies input vertex `ids[i]` (same position).
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_VERTEX_COPIES: hw_diagnostic_list = 24;
/// Faces ::HW_BUILD_POLICY_REPAIR built the other way round from the input (to agree with their
/// neighbours, or to turn a closed component outward).
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_REORIENTED_FACES: hw_diagnostic_list = 25;
/// The number of id lists.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_LIST_COUNT: hw_diagnostic_list = 10;

/// One list of edges in a diagnostic (see hw_diagnostic_edge()). The values run from
/// ::HW_DIAGNOSTIC_EDGES_FIRST to `HW_DIAGNOSTIC_EDGES_FIRST + HW_DIAGNOSTIC_EDGES_COUNT - 1`,
/// apart from the id lists' (::hw_diagnostic_list) and the doctor's findings'
/// (::hw_doctor_finding).
/// \ingroup mesh
pub type hw_diagnostic_edges = u32;
/// The first edge list.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_EDGES_FIRST: hw_diagnostic_edges = 32;
/// Edges used by three or more faces.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_EDGES_NON_MANIFOLD: hw_diagnostic_edges = 32;
/// Edges whose two faces traverse them in the same direction.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_EDGES_INCONSISTENT: hw_diagnostic_edges = 33;
/// The number of edge lists.
/// \ingroup mesh
pub const HW_DIAGNOSTIC_EDGES_COUNT: hw_diagnostic_edges = 2;

/// A list of a diagnostic: where it lives in one, and its name.
type NamedList<T> = (fn(&Diagnostic) -> &[T], &'static std::ffi::CStr);

/// Each id list in the order of its values.
const ID_LISTS: [NamedList<u32>; HW_DIAGNOSTIC_LIST_COUNT as usize] = [
    (|d| &d.faces_too_small, c"faces with fewer than 3 corners"),
    (
        |d| &d.faces_out_of_range,
        c"faces with out-of-range vertex indices",
    ),
    (
        |d| &d.faces_repeated_vertex,
        c"faces with a repeated vertex",
    ),
    (
        |d| &d.non_finite_vertices,
        c"vertices with NaN/infinite coordinates",
    ),
    (|d| &d.non_manifold_vertices, c"non-manifold vertices"),
    (|d| &d.isolated_vertices, c"isolated vertices"),
    (|d| &d.degenerate_faces, c"degenerate faces"),
    (|d| &d.skipped_faces, c"skipped faces"),
    (|d| &d.vertex_copies, c"vertex copies"),
    (|d| &d.reoriented_faces, c"reoriented faces"),
];

/// Each edge list in the order of its values.
const EDGE_LISTS: [NamedList<EdgeReport>; HW_DIAGNOSTIC_EDGES_COUNT as usize] = [
    (|d| &d.non_manifold_edges, c"non-manifold edges (3+ faces)"),
    (|d| &d.inconsistent_edges, c"inconsistently oriented edges"),
];

/// The entry of `table` for `value`, the table's values starting at `first`.
fn entry<T: Copy>(table: &[T], first: u32, value: u32) -> Option<T> {
    let offset = value.checked_sub(first)?;
    table.get(offset as usize).copied()
}

fn id_list(diagnostic: &Diagnostic, list: hw_diagnostic_list) -> Result<&[u32], FfiError> {
    let (ids, _) = entry(&ID_LISTS, HW_DIAGNOSTIC_LIST_FIRST, list)
        .ok_or_else(|| FfiError::invalid_input(format!("unknown diagnostic list {list}")))?;
    Ok(ids(diagnostic))
}

fn edge_list(
    diagnostic: &Diagnostic,
    edges: hw_diagnostic_edges,
) -> Result<&[EdgeReport], FfiError> {
    let (list, _) = entry(&EDGE_LISTS, HW_DIAGNOSTIC_EDGES_FIRST, edges)
        .ok_or_else(|| FfiError::invalid_input(format!("unknown diagnostic edge list {edges}")))?;
    Ok(list(diagnostic))
}

/// The name of an id list ("isolated vertices", …) as static text; NULL for an unknown list.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub extern "C" fn hw_diagnostic_list_name(list: hw_diagnostic_list) -> *const std::ffi::c_char {
    entry(&ID_LISTS, HW_DIAGNOSTIC_LIST_FIRST, list)
        .map_or(std::ptr::null(), |(_, name)| name.as_ptr())
}

/// The name of an edge list ("non-manifold edges (3+ faces)", …) as static text; NULL for an
/// unknown list.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub extern "C" fn hw_diagnostic_edges_name(edges: hw_diagnostic_edges) -> *const std::ffi::c_char {
    entry(&EDGE_LISTS, HW_DIAGNOSTIC_EDGES_FIRST, edges)
        .map_or(std::ptr::null(), |(_, name)| name.as_ptr())
}

/// Analyses an indexed face list without building anything (same arguments as
/// hw_mesh_from_indexed()). Malformed data are not an error here — they are what the diagnostic
/// reports; only NULL or impossible array arguments fail, and `HW_ERR_OUT_OF_MEMORY` when the
/// analysis needs more memory than the system gives. On success `*out_diagnostic` receives
/// a diagnostic to release with hw_diagnostic_free().
///
/// # Safety
/// As for hw_mesh_from_indexed().
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnose_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    out_diagnostic: *mut *mut hw_diagnostic,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_diagnostic, "out_diagnostic")?;
        // SAFETY: forwarded from the caller.
        let list = unsafe {
            face_list_arg(
                positions, n_vertices, face_sizes, n_faces, indices, n_indices,
            )?
        };
        let diagnostic = crate::mesh::Mesh::diagnose(&list)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(hw_diagnostic::into_handle(diagnostic)) };
        Ok(())
    })
}

/// Releases a diagnostic. NULL is a no-op; a second free is refused (within the limits the
/// ownership conventions at the top of the header state).
///
/// # Safety
/// `diagnostic` must be NULL or a diagnostic from this library, not in use by another thread.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_free(diagnostic: *mut hw_diagnostic) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(diagnostic, "hw_diagnostic") });
}

/// `true` when nothing at all was found; `false` otherwise or for a NULL diagnostic.
///
/// # Safety
/// `diagnostic` must be NULL or live.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_is_clean(diagnostic: *const hw_diagnostic) -> bool {
    // SAFETY: forwarded from the caller.
    guard_value(false, || {
        Ok(unsafe { arg_ref(diagnostic, "diagnostic") }?
            .diagnostic
            .is_clean())
    })
}

/// A zero-copy view of one id list (`*out_ids`, `*out_len` elements; `*out_ids` is NULL when the
/// list is empty). The view lives as long as the diagnostic.
///
/// # Safety
/// `diagnostic` must be NULL or live; `out_ids` and `out_len` writable.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_ids(
    diagnostic: *const hw_diagnostic,
    list: hw_diagnostic_list,
    out_ids: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_ids, "out_ids", out_len, || {
            id_list(&arg_ref(diagnostic, "diagnostic")?.diagnostic, list)
        })
    }
}

/// The number of edges in one edge list.
///
/// # Safety
/// `diagnostic` must be NULL or live; `out_count` writable.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_n_edges(
    diagnostic: *const hw_diagnostic,
    edges: hw_diagnostic_edges,
    out_count: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_count, "out_count")?;
        // SAFETY: forwarded from the caller.
        let list = edge_list(
            &unsafe { arg_ref(diagnostic, "diagnostic") }?.diagnostic,
            edges,
        )?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(list.len()) };
        Ok(())
    })
}

/// Edge `index` of an edge list: its two input vertices (smaller first) in `out_vertices[0..2]`
/// and a zero-copy view of the input faces using it (ascending; NULL when empty), valid as long as
/// the diagnostic.
///
/// # Safety
/// `diagnostic` must be NULL or live; `out_vertices` must hold 2 writable `uint32_t`;
/// `out_faces` and `out_n_faces` writable.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_edge(
    diagnostic: *const hw_diagnostic,
    edges: hw_diagnostic_edges,
    index: usize,
    out_vertices: *mut u32,
    out_faces: *mut *const u32,
    out_n_faces: *mut usize,
) -> hw_status {
    guard(|| {
        let out_vertices = Out::new(out_vertices.cast::<[u32; 2]>(), "out_vertices")?;
        let out_faces = Out::new(out_faces, "out_faces")?;
        let out_n_faces = Out::new(out_n_faces, "out_n_faces")?;
        // SAFETY: forwarded from the caller.
        let list = edge_list(
            &unsafe { arg_ref(diagnostic, "diagnostic") }?.diagnostic,
            edges,
        )?;
        let edge = list.get(index).ok_or_else(|| {
            FfiError::invalid_input(format!("edge {index} of a list of {}", list.len()))
        })?;
        // SAFETY: checked non-NULL, writable per the caller (`out_vertices` holds two values;
        // written unaligned-safe as `u32` is its own alignment).
        unsafe {
            out_vertices.write(edge.vertices);
            out_faces.write(view_start(&edge.faces));
            out_n_faces.write(edge.faces.len());
        }
        Ok(())
    })
}

/// A human-readable account, copied NUL-terminated into `out_text`: one line per non-empty list,
/// with its count and its first 8 elements
/// (`12 isolated vertices: v0 v1 v2 v3 v4 v5 v6 v7 … and 4 more`); an edge names its first 8
/// faces the same way. `*out_needed` receives the size needed even when `out_text` is too small
/// (then `HW_ERR_BUFFER_TOO_SMALL` and nothing is written to `out_text`); it is never more than
/// ::HW_MAX_MESSAGE_SIZE, whatever the input.
///
/// # Safety
/// `diagnostic` must be NULL or live; `out_text` NULL or `capacity` writable bytes; `out_needed`
/// NULL or writable.
/// \ingroup mesh
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_diagnostic_summary(
    diagnostic: *const hw_diagnostic,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let diagnostic = unsafe { arg_ref(diagnostic, "diagnostic") }?;
        let mut text = String::new();
        write_c_message(&mut text, &diagnostic.diagnostic.summary());
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(&text, out_text, capacity, out_needed) }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_edge_without_faces_gives_a_null_view() {
        // Before: the raw pointer of the empty list (dangling, not NULL) was handed out.
        let mut diagnostic = Diagnostic::default();
        diagnostic.non_manifold_edges.push(EdgeReport {
            vertices: [1, 2],
            faces: Vec::new(),
        });
        let handle = hw_diagnostic::into_handle(diagnostic);
        let (mut vertices, mut faces, mut n_faces) = ([0u32; 2], std::ptr::dangling(), 99usize);
        let status = unsafe {
            hw_diagnostic_edge(
                handle,
                HW_DIAGNOSTIC_EDGES_NON_MANIFOLD,
                0,
                vertices.as_mut_ptr(),
                &mut faces,
                &mut n_faces,
            )
        };
        assert_eq!(status, HW_OK);
        assert_eq!((vertices, faces, n_faces), ([1, 2], std::ptr::null(), 0));
        unsafe { hw_diagnostic_free(handle) };
    }

    #[test]
    fn every_list_has_a_name_and_the_families_never_share_a_value() {
        use crate::ffi::doctor::{HW_DOCTOR_FINDING_COUNT, HW_DOCTOR_FINDING_FIRST};
        let lists = HW_DIAGNOSTIC_LIST_FIRST..HW_DIAGNOSTIC_LIST_FIRST + HW_DIAGNOSTIC_LIST_COUNT;
        let edges =
            HW_DIAGNOSTIC_EDGES_FIRST..HW_DIAGNOSTIC_EDGES_FIRST + HW_DIAGNOSTIC_EDGES_COUNT;
        let findings = HW_DOCTOR_FINDING_FIRST..HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT;
        assert_eq!(
            lists.clone().last(),
            Some(HW_DIAGNOSTIC_LIST_REORIENTED_FACES)
        );
        assert_eq!(edges.clone().last(), Some(HW_DIAGNOSTIC_EDGES_INCONSISTENT));
        for value in 0..=findings.end {
            let families = [&lists, &edges, &findings];
            assert!(families.iter().filter(|f| f.contains(&value)).count() <= 1);
            assert_eq!(
                hw_diagnostic_list_name(value).is_null(),
                !lists.contains(&value)
            );
            assert_eq!(
                hw_diagnostic_edges_name(value).is_null(),
                !edges.contains(&value)
            );
        }
        // A value of the wrong family is refused, not read as another list.
        let handle = hw_diagnostic::into_handle(Diagnostic::default());
        let (mut ids, mut len, mut count) = (std::ptr::null(), 0usize, 0usize);
        let wrong_list = unsafe {
            hw_diagnostic_ids(handle, HW_DIAGNOSTIC_EDGES_NON_MANIFOLD, &mut ids, &mut len)
        };
        let wrong_edges = unsafe {
            hw_diagnostic_n_edges(handle, HW_DIAGNOSTIC_LIST_FACES_TOO_SMALL, &mut count)
        };
        assert_eq!(
            (wrong_list, wrong_edges),
            (HW_ERR_INVALID_INPUT, HW_ERR_INVALID_INPUT)
        );
        unsafe { hw_diagnostic_free(handle) };
    }
}
