//! Repairs: merging vertices, removing duplicate faces, unreferenced vertices and small
//! components, orienting faces, repairing non-manifold edges and splitting non-manifold vertices
//! of a soup (`hw_soup_*`), mending a mesh's degenerate triangles
//! (`hw_mesh_remove_degenerate_faces`), splitting its boundary edges at T-vertices
//! (`hw_mesh_remove_t_vertices`) and stitching its borders (`hw_mesh_stitch_borders`),
//! each with a report of what changed (`hw_repair_report`), and filling a mesh's holes
//! (`hw_mesh_fill_hole`, `hw_mesh_fill_holes`).

use crate::repair::{FillError, FillMode, HoleFillOptions, fill_hole, fill_holes};
use crate::repair::{
    NonManifoldEdges, RepairError, RepairReport, SmallComponents, Tolerance, merge_vertices,
    orient_faces, remove_degenerate_faces, remove_duplicate_faces, remove_small_components,
    remove_t_vertices, remove_unreferenced_vertices, repair_non_manifold_edges,
    split_non_manifold_vertices, stitch_borders,
};
use crate::soup::PolygonSoup;

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::face_list::face_list_arg;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, arg_mut, arg_ref, give_view, guard, guard_void};
use crate::ffi::mesh::edit::hw_index_maps;
use crate::ffi::mesh::elements::hw_halfedge;
use crate::ffi::mesh::io::hw_soup;
use crate::ffi::mesh::lifecycle::hw_mesh;

/// What a repair changed. Opaque; from the `hw_soup_*` repairs, hw_mesh_remove_degenerate_faces(),
/// hw_mesh_remove_t_vertices() and hw_mesh_stitch_borders();
/// read with hw_repair_report_list() and hw_repair_report_maps(), release with
/// hw_repair_report_free(). Ids are those of the input.
/// \ingroup repair
pub struct hw_repair_report {
    report: RepairReport,
    maps: hw_index_maps,
}

/// One list of a repair report, for hw_repair_report_list().
/// \ingroup repair
pub type hw_repair_list = u32;
/// Pairs `removed, kept` (2 values each) of vertices merged into another.
/// \ingroup repair
pub const HW_REPAIR_LIST_MERGED_VERTICES: hw_repair_list = 0;
/// Vertices removed (merged ones included).
/// \ingroup repair
pub const HW_REPAIR_LIST_REMOVED_VERTICES: hw_repair_list = 1;
/// Faces removed.
/// \ingroup repair
pub const HW_REPAIR_LIST_REMOVED_FACES: hw_repair_list = 2;
/// Pairs `removed, kept` (2 values each) of duplicate faces.
/// \ingroup repair
pub const HW_REPAIR_LIST_DUPLICATE_FACES: hw_repair_list = 3;
/// Pairs `a, b` (2 values each) of boundary half-edges stitched: `a`'s edge stays, `b`'s goes.
/// \ingroup repair
pub const HW_REPAIR_LIST_STITCHED_HALFEDGES: hw_repair_list = 4;
/// The vertex each added vertex copies: the `i`-th added vertex (id `n + i`, `n` the vertex
/// count before the repair) copies vertex `ids[i]`.
/// \ingroup repair
pub const HW_REPAIR_LIST_VERTEX_COPIES: hw_repair_list = 5;
/// Faces whose corner order was reversed.
/// \ingroup repair
pub const HW_REPAIR_LIST_REORIENTED_FACES: hw_repair_list = 6;
/// Pairs `cap, across` (2 values each) of triangles whose shared edge
/// hw_mesh_remove_degenerate_faces() flipped (`cap` had a corner on the edge; both stay).
/// \ingroup repair
pub const HW_REPAIR_LIST_FLIPPED_FACES: hw_repair_list = 7;

/// Which components hw_soup_remove_small_components() removes.
/// \ingroup repair
pub type hw_small_components = u32;
/// Components of at most `value` faces.
/// \ingroup repair
pub const HW_SMALL_COMPONENTS_BY_FACE_COUNT: hw_small_components = 0;
/// Components whose bounding-box diagonal is at most `value` (0 to 1) times the largest one's.
/// \ingroup repair
pub const HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER: hw_small_components = 1;

/// What hw_soup_repair_non_manifold_edges() does at an edge of three faces or more.
/// \ingroup repair
pub type hw_non_manifold_edges = u32;
/// Keep every face and cut the surface along the edge (copies of its ends).
/// \ingroup repair
pub const HW_NON_MANIFOLD_EDGES_CUT: hw_non_manifold_edges = 0;
/// Keep faces in order while the edge has at most one face each way; remove the others.
/// \ingroup repair
pub const HW_NON_MANIFOLD_EDGES_REMOVE_FACES: hw_non_manifold_edges = 1;

impl From<RepairError> for FfiError {
    fn from(error: RepairError) -> Self {
        match error {
            RepairError::Build(build) => build.into(),
            other => FfiError::invalid_input(other.to_string()),
        }
    }
}

impl From<FillError> for FfiError {
    fn from(error: FillError) -> Self {
        let status = match &error {
            FillError::Handle(_) => HW_ERR_INVALID_HANDLE,
            FillError::BadOption { .. } => HW_ERR_INVALID_INPUT,
            FillError::Edit(e) => return FfiError::from(*e),
            FillError::OutOfMemory(refusal) => return FfiError::from(*refusal),
            _ => HW_ERR_REFUSED,
        };
        FfiError::new(status, error.to_string())
    }
}

pub(super) fn tolerance_arg(tolerance: f64, relative: bool) -> Tolerance {
    if relative {
        Tolerance::Relative(tolerance)
    } else {
        Tolerance::Absolute(tolerance)
    }
}

/// Runs `repair` on the soup and gives its report (when `out_report` is not NULL).
///
/// # Safety
/// `soup` NULL or live and not used by another thread; `out_report` NULL or writable.
unsafe fn repair_soup(
    soup: *mut hw_soup,
    out_report: *mut *mut hw_repair_report,
    repair: impl FnOnce(&mut PolygonSoup) -> Result<RepairReport, FfiError>,
) -> hw_status {
    guard(|| {
        let out = Out::optional(out_report);
        // SAFETY: forwarded from the caller.
        let soup = &mut unsafe { arg_mut(soup, "soup") }?.soup;
        let report = repair(soup)?;
        give_report(out, report);
        Ok(())
    })
}

fn give_report(out: Option<Out<*mut hw_repair_report>>, mut report: RepairReport) {
    if let Some(out) = out {
        let maps = hw_index_maps {
            maps: std::mem::take(&mut report.maps),
        };
        // SAFETY: writable per the caller.
        unsafe { out.write(into_handle(hw_repair_report { report, maps })) };
    }
}

/// Makes a soup of an indexed face list (the arrays hw_mesh_from_indexed() takes), copied as
/// they are (nothing checked until a repair or a build looks at them), for the `hw_soup_*`
/// repairs; read it back with hw_soup_view(), release it with hw_soup_free().
///
/// # Safety
/// As for hw_mesh_from_indexed(); `out_soup` writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_from_indexed(
    positions: *const f64,
    n_vertices: usize,
    face_sizes: *const u32,
    n_faces: usize,
    indices: *const u32,
    n_indices: usize,
    out_soup: *mut *mut hw_soup,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_soup, "out_soup")?;
        // SAFETY: forwarded from the caller.
        let list = unsafe {
            face_list_arg(
                positions, n_vertices, face_sizes, n_faces, indices, n_indices,
            )
        }?;
        let crate::soup::FaceSizes::PerFace(sizes) = list.sizes else {
            unreachable!("face_list_arg gives per-face sizes");
        };
        let soup = PolygonSoup {
            positions: list.positions.to_vec(),
            face_sizes: sizes.to_vec(),
            indices: list.indices.to_vec(),
            corner_normals: None,
            corner_uvs: None,
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_soup { soup })) };
        Ok(())
    })
}

/// Merges the soup's vertices at one position or within `tolerance` of each other (an absolute
/// distance, or when `relative` a fraction 0 to 1 of the bounding-box diagonal of the
/// vertices) into the lowest of each cluster, which keeps its position. Exact duplicates always
/// merge; near ones greedily, in index order, into the first lower kept vertex within the
/// tolerance (not transitively). Faces naming a merged vertex drop corners that repeat the one
/// before; one left with fewer than 3 distinct corners is removed (::HW_REPAIR_LIST_REMOVED_FACES).
/// Corner normals and texture coordinates follow their corners. `HW_ERR_INVALID_INPUT`, the
/// soup unchanged, for a tolerance negative, NaN, infinite, relative above 1 or positive below
/// 2^-48 of the positions' extent, and for a malformed soup (index out of range, sizes not
/// adding up). On success `*out_report` (when not NULL) receives the report.
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_merge_vertices(
    soup: *mut hw_soup,
    tolerance: f64,
    relative: bool,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_soup(soup, out_report, |soup| {
            Ok(merge_vertices(soup, tolerance_arg(tolerance, relative))?)
        })
    }
}

/// Removes every face whose vertex set is that of a lower face (either orientation, any
/// starting corner), keeping the lowest (::HW_REPAIR_LIST_DUPLICATE_FACES pairs each removed face
/// with the one kept). Vertices are untouched. Refusals and report as for
/// hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_remove_duplicate_faces(
    soup: *mut hw_soup,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { repair_soup(soup, out_report, |soup| Ok(remove_duplicate_faces(soup)?)) }
}

/// Removes the vertices no face names, renumbering the others in order (the report's vertex
/// map). Refusals and report as for hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_remove_unreferenced_vertices(
    soup: *mut hw_soup,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_soup(soup, out_report, |soup| {
            Ok(remove_unreferenced_vertices(soup)?)
        })
    }
}

/// Removes the faces of the small components (faces joined through shared edges) and the
/// vertices only they named: by ::HW_SMALL_COMPONENTS_BY_FACE_COUNT (at most `value` faces, a whole
/// number) or ::HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER (a diagonal at most `value` times the
/// largest). `HW_ERR_INVALID_INPUT`, the soup unchanged, for a bad rule or value; otherwise as
/// hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_remove_small_components(
    soup: *mut hw_soup,
    rule: hw_small_components,
    value: f64,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    let small = match rule {
        HW_SMALL_COMPONENTS_BY_FACE_COUNT if value >= 0.0 && value.fract() == 0.0 => {
            // Saturates above usize::MAX: every component is then small.
            Ok(SmallComponents::FaceCount(value as usize))
        }
        HW_SMALL_COMPONENTS_BY_FACE_COUNT => Err(FfiError::invalid_input(format!(
            "face count {value} is not a whole number of 0 or more"
        ))),
        HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER => Ok(SmallComponents::RelativeDiameter(value)),
        other => Err(FfiError::invalid_input(format!(
            "unknown small-component rule {other}"
        ))),
    };
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_soup(soup, out_report, |soup| {
            Ok(remove_small_components(soup, small?)?)
        })
    }
}

/// Reverses faces so that neighbours agree in orientation (in each connected part the smaller
/// side turns) and every closed component faces outward, as a build's `HW_BUILD_POLICY_REPAIR`
/// does; a non-orientable part keeps an edge whose faces disagree. Reversed faces keep their
/// corners' normals and texture coordinates, in reverse order (::HW_REPAIR_LIST_REORIENTED_FACES);
/// vertices are untouched. Refusals and report as for hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_orient_faces(
    soup: *mut hw_soup,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { repair_soup(soup, out_report, |soup| Ok(orient_faces(soup)?)) }
}

/// Makes every edge shared by at most two faces: ::HW_NON_MANIFOLD_EDGES_CUT keeps every face
/// and gives the groups of faces around the edge's ends copies of them (appended,
/// ::HW_REPAIR_LIST_VERTEX_COPIES), ::HW_NON_MANIFOLD_EDGES_REMOVE_FACES keeps faces in order while
/// the edge has at most one face running each way and removes the others
/// (::HW_REPAIR_LIST_REMOVED_FACES). Run hw_soup_orient_faces() first. `HW_ERR_INVALID_INPUT`, the
/// soup unchanged, for an unknown `how`; otherwise as hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_repair_non_manifold_edges(
    soup: *mut hw_soup,
    how: hw_non_manifold_edges,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    let how = match how {
        HW_NON_MANIFOLD_EDGES_CUT => Ok(NonManifoldEdges::Cut),
        HW_NON_MANIFOLD_EDGES_REMOVE_FACES => Ok(NonManifoldEdges::RemoveFaces),
        other => Err(FfiError::invalid_input(format!(
            "unknown non-manifold edge repair {other}"
        ))),
    };
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_soup(soup, out_report, |soup| {
            Ok(repair_non_manifold_edges(soup, how?)?)
        })
    }
}

/// Gives every fan of faces around a non-manifold vertex but the first a copy of the vertex
/// (appended, ::HW_REPAIR_LIST_VERTEX_COPIES), as builds do; corners keep their normals and texture
/// coordinates. Refusals and report as for hw_soup_merge_vertices().
///
/// # Safety
/// `soup` must be NULL or a live soup no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_soup_split_non_manifold_vertices(
    soup: *mut hw_soup,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_soup(soup, out_report, |soup| {
            Ok(split_non_manifold_vertices(soup)?)
        })
    }
}

/// Runs `repair` on the mesh and gives its report (when `out_report` is not NULL).
///
/// # Safety
/// `mesh` NULL or live and not used by another thread; `out_report` NULL or writable.
unsafe fn repair_mesh_in_place(
    mesh: *mut hw_mesh,
    out_report: *mut *mut hw_repair_report,
    repair: impl FnOnce(&mut crate::mesh::Mesh) -> Result<RepairReport, RepairError>,
) -> hw_status {
    guard(|| {
        let out = Out::optional(out_report);
        // SAFETY: forwarded from the caller.
        let mesh = &mut unsafe { arg_mut(mesh, "mesh") }?.mesh;
        let report = repair(mesh)?;
        give_report(out, report);
        Ok(())
    })
}

/// Mends the mesh's degenerate triangles: those whose corners lie exactly on one line (decided
/// exactly), or within `tolerance` of it (absolute, or when `relative` a fraction of the live
/// vertices' bounding-box diagonal). A triangle with an edge at most the tolerance long (zero
/// when exact) has the edge collapsed into its lower end (::HW_REPAIR_LIST_MERGED_VERTICES), which
/// removes the two triangles beside it and keeps the surface closed; a cap (its corner opposite
/// its longest edge on that edge) has that edge flipped with the triangle across it
/// (::HW_REPAIR_LIST_FLIPPED_FACES) when the two new triangles are sound; any other is removed,
/// leaving a boundary. Every removed face is in ::HW_REPAIR_LIST_REMOVED_FACES. Faces of more than 3
/// corners are left as they are; vertices only removed faces named stay, isolated. Corners keep
/// their normals and texture coordinates (a corner at a merged vertex keeps its own). The mesh
/// is then compacted (the report's maps; the identity when nothing changed, the mesh then
/// unchanged). Afterwards no triangle is degenerate. `HW_ERR_INVALID_INPUT`, the mesh
/// unchanged, for a tolerance negative, NaN, infinite or relative above 1.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_remove_degenerate_faces(
    mesh: *mut hw_mesh,
    tolerance: f64,
    relative: bool,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_mesh_in_place(mesh, out_report, |mesh| {
            remove_degenerate_faces(mesh, tolerance_arg(tolerance, relative))
        })
    }
}

/// Splits every boundary edge on whose inside a boundary vertex lies (a T-vertex: exactly, or
/// within `tolerance` as for hw_mesh_remove_degenerate_faces()) with a new vertex at the
/// T-vertex's position, so that hw_mesh_stitch_borders() can then close the crack. The `i`-th
/// new vertex (id `n + i`, `n` the vertex count before) copies T-vertex `ids[i]` of
/// ::HW_REPAIR_LIST_VERTEX_COPIES; its attributes, and the new corner of the face beside the edge,
/// are interpolated along the edge. Edges whose face has a corner at the T-vertex's position
/// are left. Nothing is removed; the mesh is compacted (the report's maps cover the elements
/// there were before; the identity when nothing was split). Afterwards no boundary vertex lies
/// inside a boundary edge. Refusals as for hw_mesh_remove_degenerate_faces().
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_remove_t_vertices(
    mesh: *mut hw_mesh,
    tolerance: f64,
    relative: bool,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_mesh_in_place(mesh, out_report, |mesh| {
            remove_t_vertices(mesh, tolerance_arg(tolerance, relative))
        })
    }
}

/// Glues the mesh's boundary edges that lie on each other end on end (exactly, or within
/// `tolerance`, absolute or when `relative` a fraction of the live vertices' bounding-box
/// diagonal), like CGAL's `stitch_borders`: an edge is stitched when exactly one other boundary
/// edge joins the same positions the opposite way, and only where the mesh stays manifold with
/// distinct edges. Faces keep their corners' data; merged vertices go into the lowest, which
/// keeps its position and attributes. The mesh is then compacted: the report's maps give the
/// new ids (the identity when nothing was stitched, the mesh then unchanged). Refusals as for
/// hw_soup_merge_vertices(), the mesh unchanged.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_report` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_stitch_borders(
    mesh: *mut hw_mesh,
    tolerance: f64,
    relative: bool,
    out_report: *mut *mut hw_repair_report,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        repair_mesh_in_place(mesh, out_report, |mesh| {
            stitch_borders(mesh, tolerance_arg(tolerance, relative))
        })
    }
}

/// A read-only view of one list of the report (`*out_ids`, NULL when empty, with `*out_len`
/// values; pair lists hold 2 values per pair). Lives as long as the report.
///
/// # Safety
/// `report` must be NULL or live; `out_ids` and `out_len` writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_report_list(
    report: *const hw_repair_report,
    list: hw_repair_list,
    out_ids: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_ids, "out_ids", out_len, || {
            let report = arg_ref(report, "report")?;
            match list {
                HW_REPAIR_LIST_MERGED_VERTICES => Ok(report.report.merged_vertices.as_flattened()),
                HW_REPAIR_LIST_REMOVED_VERTICES => Ok(&report.report.removed_vertices[..]),
                HW_REPAIR_LIST_REMOVED_FACES => Ok(&report.report.removed_faces[..]),
                HW_REPAIR_LIST_DUPLICATE_FACES => Ok(report.report.duplicate_faces.as_flattened()),
                HW_REPAIR_LIST_STITCHED_HALFEDGES => {
                    Ok(report.report.stitched_halfedges.as_flattened())
                }
                HW_REPAIR_LIST_VERTEX_COPIES => Ok(&report.report.vertex_copies[..]),
                HW_REPAIR_LIST_REORIENTED_FACES => Ok(&report.report.reoriented_faces[..]),
                HW_REPAIR_LIST_FLIPPED_FACES => Ok(report.report.flipped_faces.as_flattened()),
                other => Err(FfiError::invalid_input(format!(
                    "unknown repair list {other}"
                ))),
            }
        })
    }
}

/// The report's old-to-new maps, to read with hw_index_maps_view() (a soup's repairs fill the
/// vertex and face maps; the `hw_mesh_*` repairs all four). Owned by the report: do not free
/// it; it lives as long as the report. Also `*out_removed_corners` (when not NULL): corners
/// dropped from kept faces.
///
/// # Safety
/// `report` must be NULL or live; `out_maps` writable; `out_removed_corners` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_report_maps(
    report: *const hw_repair_report,
    out_maps: *mut *const hw_index_maps,
    out_removed_corners: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_maps, "out_maps")?;
        // SAFETY: forwarded from the caller.
        let report = unsafe { arg_ref(report, "report") }?;
        // SAFETY: checked non-NULL and writable per the caller; the other NULL or writable.
        unsafe {
            out.write(&report.maps);
            if let Some(out) = Out::optional(out_removed_corners) {
                out.write(report.report.removed_corners);
            }
        }
        Ok(())
    })
}

/// Releases a repair report. NULL is a no-op; a second free is refused (within the limits the
/// ownership conventions at the top of the header state).
///
/// # Safety
/// `report` must be NULL or a report from this library, not in use by another thread.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_report_free(report: *mut hw_repair_report) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(report, "hw_repair_report") });
}

/// How hw_mesh_fill_holes() and hw_repair_mesh() close a hole.
/// \ingroup repair
pub type hw_fill_mode = u32;
/// Triangles on the hole's corners only; no vertex is added.
/// \ingroup repair
pub const HW_FILL_MODE_TRIANGULATE: hw_fill_mode = 0;
/// The triangulation refined (centroid splits and Delaunay-like flips) until its edges match
/// the lengths of the mesh's edges at the hole's rim; adds vertices inside the hole, whose
/// attributes are the mean of those of the triangle they split.
/// \ingroup repair
pub const HW_FILL_MODE_REFINE: hw_fill_mode = 1;
/// Refined, then the added vertices moved to minimise a thin-plate energy (squared cotangent
/// Laplacian) with the rim and the mesh around it fixed, so the fill continues the surface
/// (a sparse Cholesky solve, refined by up to 8 iterations); a hole whose solve does not
/// converge is refused.
/// \ingroup repair
pub const HW_FILL_MODE_FAIR: hw_fill_mode = 2;

/// The Rust mode of `mode`, or a refusal naming it.
pub(super) fn fill_mode_arg(mode: hw_fill_mode) -> Result<FillMode, FfiError> {
    match mode {
        HW_FILL_MODE_TRIANGULATE => Ok(FillMode::Triangulate),
        HW_FILL_MODE_REFINE => Ok(FillMode::Refine),
        HW_FILL_MODE_FAIR => Ok(FillMode::Fair),
        other => Err(FfiError::invalid_input(format!(
            "unknown fill mode {other}"
        ))),
    }
}

/// Which holes hw_mesh_fill_holes() fills, and how; start from hw_fill_hole_options_default().
/// \ingroup repair
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_fill_hole_options {
    /// Holes with more boundary edges than this are left open.
    pub max_edges: usize,
    /// Holes whose perimeter exceeds this are left open; infinity for no bound.
    pub max_perimeter: f64,
    /// How each hole is closed. Default ::HW_FILL_MODE_TRIANGULATE.
    pub mode: hw_fill_mode,
}

/// Options that fill every hole, triangulated: no bound on edges or perimeter.
/// \ingroup repair
#[unsafe(no_mangle)]
pub extern "C" fn hw_fill_hole_options_default() -> hw_fill_hole_options {
    let options = HoleFillOptions::default();
    hw_fill_hole_options {
        max_edges: options.max_edges,
        max_perimeter: options.max_perimeter,
        mode: HW_FILL_MODE_TRIANGULATE,
    }
}

/// Fills the hole whose boundary loop holds half-edge `h` with triangles on its corners (no new
/// vertex): Liepa's minimum-weight triangulation up to 100 edges, beyond that a triangulation
/// on the hole's best-fit plane improved by edge flips. `*out_faces_added` (when not NULL)
/// receives the number of new triangles (edges − 2). New faces, edges and corners get zero
/// attributes. `HW_ERR_INVALID_HANDLE` for a bad `h`; `HW_ERR_REFUSED`, the mesh unchanged,
/// when `h` has a face, the loop passes twice through a vertex, every triangulation needs an
/// edge that exists already, a hole of more than 100 edges does not project onto a simple
/// polygon, or the fill would fold (a new triangle degenerate, or turned more than 150° from a
/// face beside it).
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `out_faces_added` NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_fill_hole(
    mesh: *mut hw_mesh,
    h: hw_halfedge,
    out_faces_added: *mut usize,
) -> hw_status {
    guard(|| {
        let out = Out::optional(out_faces_added);
        // SAFETY: forwarded from the caller.
        let mesh = &mut unsafe { arg_mut(mesh, "mesh") }?.mesh;
        let filled = fill_hole(mesh, h.into())?;
        if let Some(out) = out {
            // SAFETY: writable per the caller.
            unsafe { out.write(filled.faces.len()) };
        }
        Ok(())
    })
}

/// Fills every hole within `options`' bounds (NULL: every hole) as hw_mesh_fill_hole() does;
/// holes it refuses are left open. `*out_filled`, `*out_refused` and `*out_faces_added` (each
/// when not NULL) receive the holes filled, the holes refused and the triangles added.
/// `HW_ERR_INVALID_INPUT`, the mesh unchanged, for a NaN or negative `max_perimeter`.
///
/// # Safety
/// `mesh` must be NULL or a live mesh no other thread uses; `options` NULL or readable; the
/// outputs NULL or writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_mesh_fill_holes(
    mesh: *mut hw_mesh,
    options: *const hw_fill_hole_options,
    out_filled: *mut usize,
    out_refused: *mut usize,
    out_faces_added: *mut usize,
) -> hw_status {
    guard(|| {
        let outs = [
            Out::optional(out_filled),
            Out::optional(out_refused),
            Out::optional(out_faces_added),
        ];
        // SAFETY: forwarded from the caller.
        let mesh = &mut unsafe { arg_mut(mesh, "mesh") }?.mesh;
        // SAFETY: NULL or readable per the caller.
        let raw = unsafe { options.as_ref() }
            .copied()
            .unwrap_or_else(|| hw_fill_hole_options_default());
        let report = fill_holes(
            mesh,
            &HoleFillOptions {
                max_edges: raw.max_edges,
                max_perimeter: raw.max_perimeter,
                mode: fill_mode_arg(raw.mode)?,
            },
        )?;
        let values = [
            report.filled.len(),
            report.refused.len(),
            report.faces_added(),
        ];
        for (out, value) in outs.into_iter().zip(values) {
            if let Some(out) = out {
                // SAFETY: writable per the caller.
                unsafe { out.write(value) };
            }
        }
        Ok(())
    })
}
