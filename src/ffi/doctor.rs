//! `hw_doctor_report`: the mesh doctor's findings on a face list or a mesh.

use crate::doctor::{DoctorOptions, DoctorReport, Finding, examine};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_ref, copy_text, guard, guard_value, guard_void, view_start};
use crate::ffi::mesh::diagnostic::hw_diagnostic;
use crate::ffi::mesh::lifecycle::{hw_mesh, mesh_ref};

/// The doctor's thresholds; hw_doctor_options_default() gives the documented defaults.
/// \ingroup doctor
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_doctor_options {
    /// Distance under which two vertices are near duplicates and a vertex lies on an edge,
    /// relative to the diagonal of the bounding box of the vertices faces name. 0 to 1; default
    /// 1e-9.
    pub relative_tolerance: f64,
    /// A triangle with an angle below this (degrees) is a needle. Default 5.
    pub needle_angle_degrees: f64,
    /// A triangle with an angle above this (degrees) is a cap. Default 175.
    pub cap_angle_degrees: f64,
    /// Two faces sharing an edge whose normals are more than this (degrees) apart are folded.
    /// Default 175.
    pub fold_angle_degrees: f64,
    /// An edge longer than this many times the median edge is long. At least 1; default 10.
    pub long_edge_ratio: f64,
    /// A component is small when its face count or diameter is at most this fraction of the
    /// largest's. 0 to 1; default 0.01.
    pub small_component_ratio: f64,
}

impl From<hw_doctor_options> for DoctorOptions {
    fn from(o: hw_doctor_options) -> Self {
        DoctorOptions {
            relative_tolerance: o.relative_tolerance,
            needle_angle_degrees: o.needle_angle_degrees,
            cap_angle_degrees: o.cap_angle_degrees,
            fold_angle_degrees: o.fold_angle_degrees,
            long_edge_ratio: o.long_edge_ratio,
            small_component_ratio: o.small_component_ratio,
        }
    }
}

/// The doctor's default thresholds.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub extern "C" fn hw_doctor_options_default() -> hw_doctor_options {
    let d = DoctorOptions::default();
    hw_doctor_options {
        relative_tolerance: d.relative_tolerance,
        needle_angle_degrees: d.needle_angle_degrees,
        cap_angle_degrees: d.cap_angle_degrees,
        fold_angle_degrees: d.fold_angle_degrees,
        long_edge_ratio: d.long_edge_ratio,
        small_component_ratio: d.small_component_ratio,
    }
}

/// Everything the doctor found. Opaque; from hw_doctor_examine_indexed() or
/// hw_doctor_examine_mesh(); release with hw_doctor_report_free().
///
/// Indices are input indices: faces of the face list, vertices of its positions (for a mesh,
/// those of the face list hw_mesh_write() would write: the mesh's own ids when nothing is
/// deleted). Malformed faces are listed in the report's diagnostic and left out of every other
/// finding. The report's size follows the findings, not the mesh.
/// \ingroup doctor
pub struct hw_doctor_report {
    report: DoctorReport,
    diagnostic: hw_diagnostic,
}

fn into_report(report: DoctorReport) -> *mut hw_doctor_report {
    let diagnostic = hw_diagnostic {
        diagnostic: report.diagnostic.clone(),
    };
    into_handle(hw_doctor_report { report, diagnostic })
}

/// `options` as the doctor takes them: the defaults for NULL.
///
/// # Safety
/// `options` must be NULL or readable.
unsafe fn options_arg(options: *const hw_doctor_options) -> DoctorOptions {
    // SAFETY: forwarded from the caller.
    unsafe { options.as_ref() }.map_or_else(DoctorOptions::default, |o| (*o).into())
}

fn doctor_error(error: crate::doctor::DoctorError) -> FfiError {
    match error {
        crate::doctor::DoctorError::OutOfMemory(refusal)
        | crate::doctor::DoctorError::SelfIntersections(
            crate::geom::SelfIntersectionError::OutOfMemory(refusal),
        ) => refusal.into(),
        _ => FfiError::invalid_input(error.to_string()),
    }
}

/// Examines an indexed face list (same arrays as hw_mesh_from_indexed()) with `options` (NULL
/// for the defaults). Malformed faces and non-finite coordinates are findings, not errors;
/// `HW_ERR_INVALID_INPUT` means an option is out of range or the list as a whole is malformed
/// (sizes not adding up to `n_indices`), or its triangulation is too large for 32-bit indices.
/// On success `*out_report` receives a report to release
/// with hw_doctor_report_free(). The input is never changed.
///
/// # Safety
/// As for hw_mesh_from_indexed(); `options` NULL or readable; `out_report` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_examine_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    options: *const hw_doctor_options,
    out_report: *mut *mut hw_doctor_report,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_report, "out_report")?;
        // SAFETY: forwarded from the caller.
        let (list, options) = unsafe {
            (
                face_list_arg(
                    positions, n_vertices, face_sizes, n_faces, indices, n_indices,
                )?,
                options_arg(options),
            )
        };
        let report = with_threads(|| examine(&list, &options)).map_err(doctor_error)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_report(report)) };
        Ok(())
    })
}

/// Examines a mesh's live faces (see hw_doctor_examine_indexed()).
///
/// # Safety
/// `mesh` must be NULL or live; `options` NULL or readable; `out_report` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_examine_mesh(
    mesh: *const hw_mesh,
    options: *const hw_doctor_options,
    out_report: *mut *mut hw_doctor_report,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_report, "out_report")?;
        // SAFETY: forwarded from the caller.
        let (mesh, options) = unsafe { (mesh_ref(mesh)?, options_arg(options)) };
        let report = with_threads(|| mesh.examine(&options)).map_err(doctor_error)?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_report(report)) };
        Ok(())
    })
}

/// Releases a report. NULL is a no-op; freeing twice is detected and refused.
///
/// # Safety
/// `report` must be NULL or a report from this library, not in use by another thread.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_free(report: *mut hw_doctor_report) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(report, "hw_doctor_report") });
}

/// The report's diagnostic of the input (malformed faces, non-finite coordinates, non-manifold
/// and inconsistently oriented edges, non-manifold and unreferenced vertices, zero-area faces),
/// read with the hw_diagnostic_* calls; owned by the report (do not free it), valid as long as
/// the report. NULL for a NULL report.
///
/// # Safety
/// `report` must be NULL or live.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_diagnostic(
    report: *const hw_doctor_report,
) -> *const hw_diagnostic {
    // SAFETY: forwarded from the caller.
    guard_value(std::ptr::null(), || {
        Ok(&unsafe { arg_ref(report, "report") }?.diagnostic as *const hw_diagnostic)
    })
}

/// One kind of finding that is a list of elements (see hw_doctor_report_finding()). The values
/// run from ::HW_DOCTOR_FINDING_FIRST to `HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT - 1`,
/// apart from the diagnostic's lists (::hw_diagnostic_list, ::hw_diagnostic_edges), so a value of
/// one family passed where another is expected is refused, never read as a different list.
/// \ingroup doctor
pub type hw_doctor_finding = u32;
/// The first finding kind.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_FIRST: hw_doctor_finding = 64;
/// Indices of small components (into hw_doctor_report_component()); one id per item.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_SMALL_COMPONENTS: hw_doctor_finding = 64;
/// Faces of a closed path along which the orientation flips (the surface is not orientable),
/// each sharing an edge with the next and the last with the first; one id per item.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_NON_ORIENTABLE_WITNESS: hw_doctor_finding = 65;
/// Edges whose ends are at the same position: 2 ids per item (vertices, smaller first).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_ZERO_LENGTH_EDGES: hw_doctor_finding = 66;
/// Triangles with an angle below the needle threshold; one id per item.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_NEEDLES: hw_doctor_finding = 67;
/// Triangles with an angle above the cap threshold; one id per item.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_CAPS: hw_doctor_finding = 68;
/// Edges whose two faces fold onto each other: 4 ids per item (the two vertices, smaller
/// first, then the two faces, ascending).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_FOLDED_EDGES: hw_doctor_finding = 69;
/// Edges longer than the long-edge ratio times the median: 2 ids per item (vertices).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_LONG_EDGES: hw_doctor_finding = 70;
/// Vertices at exactly the position of a lower vertex: 2 ids per item (the vertex, then the
/// lowest vertex at that position).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_DUPLICATE_POSITIONS: hw_doctor_finding = 71;
/// Vertices within the tolerance of a lower vertex (not at its position): 2 ids per item (the
/// vertex, then the first vertex of its group).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_NEAR_DUPLICATE_VERTICES: hw_doctor_finding = 72;
/// Faces on the vertex set of a lower face, in either orientation: 2 ids per item (the face,
/// then the lowest such face).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_DUPLICATE_FACES: hw_doctor_finding = 73;
/// Vertices lying inside a boundary edge they are not an end of: 4 ids per item (the vertex,
/// the edge's two ends, smaller first, and the edge's face).
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_T_VERTICES: hw_doctor_finding = 74;
/// Pairs of faces that intersect other than along the vertices and edges they share, decided
/// exactly (polygons as their triangles; touching counts; triangles with exactly collinear
/// corners and faces on non-finite vertices are not tested): 2 ids per item (faces, smaller first),
/// sorted.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_SELF_INTERSECTIONS: hw_doctor_finding = 75;
/// The number of finding kinds.
/// \ingroup doctor
pub const HW_DOCTOR_FINDING_COUNT: hw_doctor_finding = 12;

/// The kind whose value is `kind`, if any.
fn finding_at(kind: hw_doctor_finding) -> Option<Finding> {
    Finding::from_index(kind.checked_sub(HW_DOCTOR_FINDING_FIRST)?)
}

/// The kind numbered `kind`.
pub(super) fn finding_kind(kind: hw_doctor_finding) -> Result<Finding, FfiError> {
    finding_at(kind)
        .ok_or_else(|| FfiError::invalid_input(format!("unknown doctor finding {kind}")))
}

/// The name of a finding kind ("needles", "T-vertices", …) as static text; NULL for an unknown
/// kind.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub extern "C" fn hw_doctor_finding_name(kind: hw_doctor_finding) -> *const std::ffi::c_char {
    finding_at(kind).map_or(std::ptr::null(), |kind| kind.c_name().as_ptr())
}

/// A zero-copy view of one finding: `*out_ids` holds `*out_n_items` items of
/// `*out_ids_per_item` ids each (see each ::hw_doctor_finding), NULL when there are none;
/// valid as long as the report.
///
/// # Safety
/// `report` must be NULL or live; `out_ids`, `out_n_items` and `out_ids_per_item` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_finding(
    report: *const hw_doctor_report,
    kind: hw_doctor_finding,
    out_ids: *mut *const u32,
    out_n_items: *mut usize,
    out_ids_per_item: *mut usize,
) -> hw_status {
    guard(|| {
        let out_ids = Out::new(out_ids, "out_ids")?;
        let out_n_items = Out::new(out_n_items, "out_n_items")?;
        let out_ids_per_item = Out::new(out_ids_per_item, "out_ids_per_item")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        let (ids, per_item) = report.finding(finding_kind(kind)?);
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_ids.write(view_start(ids));
            out_n_items.write(ids.len() / per_item);
            out_ids_per_item.write(per_item);
        }
        Ok(())
    })
}

/// The surface's verdicts. `manifold`: no non-manifold edge or vertex and no malformed face;
/// `closed`: no boundary; `oriented`: every component orientable and consistently oriented;
/// `closed_polyhedron`: all three, finite coordinates, every component enclosing a positive
/// volume, no self-intersection and no zero-area face.
/// \ingroup doctor
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct hw_doctor_verdict {
    /// No non-manifold edge or vertex and no malformed face.
    pub manifold: bool,
    /// No boundary.
    pub closed: bool,
    /// Every component orientable and consistently oriented.
    pub oriented: bool,
    /// All three, finite coordinates, every component enclosing a positive volume, no
    /// self-intersection and no zero-area face.
    pub closed_polyhedron: bool,
    /// Why it is not a closed polyhedron (the first reason, static text), NULL when it is one.
    pub reason: *const std::ffi::c_char,
}

/// The report's verdicts.
///
/// # Safety
/// `report` must be NULL or live; `out_verdict` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_verdict(
    report: *const hw_doctor_report,
    out_verdict: *mut hw_doctor_verdict,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_verdict, "out_verdict")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        let reason = report.closed_polyhedron_fault();
        let verdict = hw_doctor_verdict {
            manifold: report.is_manifold(),
            closed: report.is_closed(),
            oriented: report.is_oriented(),
            closed_polyhedron: reason.is_none(),
            reason: reason.map_or(std::ptr::null(), |r| r.as_ptr()),
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(verdict) };
        Ok(())
    })
}

/// One connected component (faces joined through shared edges).
/// \ingroup doctor
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct hw_doctor_component {
    /// Its lowest face.
    pub first_face: u32,
    /// Its faces.
    pub n_faces: usize,
    /// Its distinct edges.
    pub n_edges: usize,
    /// Distinct vertices (one shared with another component through a non-manifold vertex
    /// counts in both).
    pub n_vertices: usize,
    /// Its boundary loops (0 when it is closed).
    pub n_boundary_loops: usize,
    /// V − E + F.
    pub euler_characteristic: i64,
    /// The genus of an orientable 2-manifold component; -1 for any other.
    pub genus: i64,
    /// No boundary edge (every edge has two or more faces).
    pub closed: bool,
    /// No non-manifold edge or vertex.
    pub manifold: bool,
    /// Its faces can be oriented so that every two-face edge is walked both ways.
    pub orientable: bool,
    /// Every two-face edge is walked both ways as given.
    pub consistently_oriented: bool,
    /// 1 when a closed, manifold, consistently oriented component faces outward (encloses a
    /// positive volume), -1 inward, 0 otherwise or when it encloses no volume.
    pub outward: i32,
    /// The signed volume it encloses (when `outward` is not 0 or the volume is 0; NaN for a
    /// component that is not closed, manifold and consistently oriented). May overflow to
    /// infinity or underflow to 0 at extreme coordinates: `outward` keeps the sign.
    pub volume: f64,
    /// The sum of its faces' areas.
    pub area: f64,
    /// Its bounding box: lowest x, y, z, then highest x, y, z.
    pub bounding_box: [f64; 6],
}

/// The number of components (`*out_count`).
///
/// # Safety
/// `report` must be NULL or live; `out_count` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_n_components(
    report: *const hw_doctor_report,
    out_count: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { give_count(report, out_count, |r| r.components.len()) }
}

/// Component `index` (components in order of their lowest face).
///
/// # Safety
/// `report` must be NULL or live; `out_component` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_component(
    report: *const hw_doctor_report,
    index: usize,
    out_component: *mut hw_doctor_component,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_component, "out_component")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        let c = item(&report.components, index, "component")?;
        let [low, high] = c.bounding_box;
        let component = hw_doctor_component {
            first_face: c.first_face,
            n_faces: c.n_faces,
            n_edges: c.n_edges,
            n_vertices: c.n_vertices,
            n_boundary_loops: c.n_boundary_loops,
            euler_characteristic: c.euler_characteristic,
            genus: c.genus.map_or(-1, i64::from),
            closed: c.closed,
            manifold: c.manifold,
            orientable: c.orientable,
            consistently_oriented: c.consistently_oriented,
            outward: c.outward.map_or(0, |o| if o { 1 } else { -1 }),
            volume: c.volume.unwrap_or(f64::NAN),
            area: c.area,
            bounding_box: [low[0], low[1], low[2], high[0], high[1], high[2]],
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(component) };
        Ok(())
    })
}

/// The number of boundary loops (`*out_count`).
///
/// # Safety
/// `report` must be NULL or live; `out_count` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_n_boundary_loops(
    report: *const hw_doctor_report,
    out_count: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { give_count(report, out_count, |r| r.boundary_loops.len()) }
}

/// Boundary loop `index`: a zero-copy view of its vertices in order (each joined by a boundary
/// edge to the next, the last to the first), valid as long as the report; its perimeter; and a
/// face along it.
///
/// # Safety
/// `report` must be NULL or live; every output writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_boundary_loop(
    report: *const hw_doctor_report,
    index: usize,
    out_vertices: *mut *const u32,
    out_n_vertices: *mut usize,
    out_perimeter: *mut f64,
    out_face: *mut u32,
) -> hw_status {
    guard(|| {
        let out_vertices = Out::new(out_vertices, "out_vertices")?;
        let out_n_vertices = Out::new(out_n_vertices, "out_n_vertices")?;
        let out_perimeter = Out::new(out_perimeter, "out_perimeter")?;
        let out_face = Out::new(out_face, "out_face")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        let found = item(&report.boundary_loops, index, "boundary loop")?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_vertices.write(view_start(&found.vertices));
            out_n_vertices.write(found.vertices.len());
            out_perimeter.write(found.perimeter);
            out_face.write(found.face);
        }
        Ok(())
    })
}

/// The number of non-manifold vertices whose fans the report lists (`*out_count`): those of
/// ::HW_DIAGNOSTIC_LIST_NON_MANIFOLD_VERTICES, in the same order.
///
/// # Safety
/// `report` must be NULL or live; `out_count` writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_n_vertex_fans(
    report: *const hw_doctor_report,
    out_count: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { give_count(report, out_count, |r| r.non_manifold_vertex_fans.len()) }
}

/// Fan `fan` of non-manifold vertex `index` (see hw_doctor_report_n_vertex_fans()): the vertex,
/// its number of fans, and a zero-copy view of the fan's faces (ascending; fans in order of their
/// lowest face), valid as long as the report.
///
/// # Safety
/// `report` must be NULL or live; every output writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_vertex_fan(
    report: *const hw_doctor_report,
    index: usize,
    fan: usize,
    out_vertex: *mut u32,
    out_n_fans: *mut usize,
    out_faces: *mut *const u32,
    out_n_faces: *mut usize,
) -> hw_status {
    guard(|| {
        let out_vertex = Out::new(out_vertex, "out_vertex")?;
        let out_n_fans = Out::new(out_n_fans, "out_n_fans")?;
        let out_faces = Out::new(out_faces, "out_faces")?;
        let out_n_faces = Out::new(out_n_faces, "out_n_faces")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        let fans = item(
            &report.non_manifold_vertex_fans,
            index,
            "non-manifold vertex",
        )?;
        let faces = item(&fans.fans, fan, "fan")?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe {
            out_vertex.write(fans.vertex);
            out_n_fans.write(fans.fans.len());
            out_faces.write(view_start(faces));
            out_n_faces.write(faces.len());
        }
        Ok(())
    })
}

/// The report as text (a summary line, the diagnostic, a line per component and per non-empty
/// finding naming its first few elements), copied NUL-terminated into `out_text`; `*out_needed`
/// receives the size needed even when `out_text` is too small (then `HW_ERR_BUFFER_TOO_SMALL` and
/// nothing is written to `out_text`).
///
/// # Safety
/// `report` must be NULL or live; `out_text` NULL or `capacity` writable bytes; `out_needed` NULL
/// or writable.
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_text(
    report: *const hw_doctor_report,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_text(
            report,
            out_text,
            capacity,
            out_needed,
            DoctorReport::to_string,
        )
    }
}

/// The whole report as one JSON object (every element of every finding), copied as
/// hw_doctor_report_text() copies its text.
///
/// # Safety
/// As for hw_doctor_report_text().
/// \ingroup doctor
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_doctor_report_json(
    report: *const hw_doctor_report,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_text(
            report,
            out_text,
            capacity,
            out_needed,
            DoctorReport::to_json,
        )
    }
}

/// Copies `render(report)` into the caller's buffer: the body of the text calls.
///
/// # Safety
/// As for hw_doctor_report_text().
unsafe fn give_text(
    report: *const hw_doctor_report,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
    render: impl FnOnce(&DoctorReport) -> String,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(&render(report), out_text, capacity, out_needed) }
    })
}

/// Writes `count(report)` to `out_count`: the body of the `_count` calls.
///
/// # Safety
/// `report` must be NULL or live; `out_count` writable.
unsafe fn give_count(
    report: *const hw_doctor_report,
    out_count: *mut usize,
    count: impl FnOnce(&DoctorReport) -> usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_count, "out_count")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { report_ref(report) }?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(count(report)) };
        Ok(())
    })
}

fn item<'a, T>(list: &'a [T], index: usize, what: &str) -> Result<&'a T, FfiError> {
    list.get(index)
        .ok_or_else(|| FfiError::invalid_input(format!("{what} {index} of {}", list.len())))
}

/// The report behind a C handle.
///
/// # Safety
/// `report` must be NULL or live.
pub(super) unsafe fn report_ref<'a>(
    report: *const hw_doctor_report,
) -> Result<&'a DoctorReport, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(report, "report") }?.report)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_c_kinds_number_the_rust_kinds_in_order() {
        let numbered = [
            (HW_DOCTOR_FINDING_SMALL_COMPONENTS, Finding::SmallComponents),
            (
                HW_DOCTOR_FINDING_NON_ORIENTABLE_WITNESS,
                Finding::NonOrientableWitness,
            ),
            (
                HW_DOCTOR_FINDING_ZERO_LENGTH_EDGES,
                Finding::ZeroLengthEdges,
            ),
            (HW_DOCTOR_FINDING_NEEDLES, Finding::Needles),
            (HW_DOCTOR_FINDING_CAPS, Finding::Caps),
            (HW_DOCTOR_FINDING_FOLDED_EDGES, Finding::FoldedEdges),
            (HW_DOCTOR_FINDING_LONG_EDGES, Finding::LongEdges),
            (
                HW_DOCTOR_FINDING_DUPLICATE_POSITIONS,
                Finding::DuplicatePositions,
            ),
            (
                HW_DOCTOR_FINDING_NEAR_DUPLICATE_VERTICES,
                Finding::NearDuplicateVertices,
            ),
            (HW_DOCTOR_FINDING_DUPLICATE_FACES, Finding::DuplicateFaces),
            (HW_DOCTOR_FINDING_T_VERTICES, Finding::TVertices),
            (
                HW_DOCTOR_FINDING_SELF_INTERSECTIONS,
                Finding::SelfIntersections,
            ),
        ];
        assert_eq!(numbered.len(), HW_DOCTOR_FINDING_COUNT as usize);
        assert_eq!(Finding::ALL.len(), HW_DOCTOR_FINDING_COUNT as usize);
        for (c, kind) in numbered {
            assert_eq!(finding_kind(c).ok(), Some(kind));
            // SAFETY: a known kind's name is static text.
            let c_name = unsafe { std::ffi::CStr::from_ptr(hw_doctor_finding_name(c)) };
            assert_eq!(c_name.to_str(), Ok(kind.name()));
        }
        let past_the_last = HW_DOCTOR_FINDING_FIRST + HW_DOCTOR_FINDING_COUNT;
        for unknown in [0, HW_DOCTOR_FINDING_FIRST - 1, past_the_last] {
            assert!(finding_kind(unknown).is_err());
            assert!(hw_doctor_finding_name(unknown).is_null());
        }
    }
}
