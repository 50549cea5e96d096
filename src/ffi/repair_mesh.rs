//! The repair pipeline (`hw_repair_mesh`): every repair in turn, from a soup to a clean mesh,
//! with the fate of every input vertex and face (`hw_repair_fates`).

use crate::mesh::INVALID_INDEX;
use crate::repair::{
    FaceFate, FateCounts, HoleFillOptions, Removal, RepairFates, RepairOptions, SmallComponents,
    VertexFate, repair_mesh,
};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{Out, arg_ref, give_view, guard, guard_void};
use crate::ffi::mesh::io::hw_soup;
use crate::ffi::mesh::lifecycle::hw_mesh;
use crate::ffi::repair::{
    HW_FILL_MODE_TRIANGULATE, HW_SMALL_COMPONENTS_BY_FACE_COUNT,
    HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER, fill_mode_arg, hw_fill_mode, hw_small_components,
    tolerance_arg,
};

/// Options of hw_repair_mesh(); hw_repair_options_default() merges and stitches exact
/// duplicates only, mends exactly degenerate triangles, splits boundary edges at vertices
/// exactly on them, fills no hole and keeps every component.
/// \ingroup repair
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct hw_repair_options {
    /// Vertices this close merge (absolute, or when `merge_relative` a fraction 0 to 1 of the
    /// bounding-box diagonal). Default 0: identical positions.
    pub merge_tolerance: f64,
    /// Whether `merge_tolerance` is relative. Default false.
    pub merge_relative: bool,
    /// Boundary edges whose ends are this close stitch (as `merge_tolerance`). Default 0.
    pub stitch_tolerance: f64,
    /// Whether `stitch_tolerance` is relative. Default false.
    pub stitch_relative: bool,
    /// Whether small components are removed (by `small_rule` and `small_value`, as
    /// hw_soup_remove_small_components() takes them). Default false.
    pub remove_small_components: bool,
    /// ::HW_SMALL_COMPONENTS_BY_FACE_COUNT or ::HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER.
    pub small_rule: hw_small_components,
    /// The face count or the diameter ratio.
    pub small_value: f64,
    /// Whether degenerate triangles are mended (hw_mesh_remove_degenerate_faces(), after the
    /// build). Default true.
    pub remove_degenerate_faces: bool,
    /// Triangles this close to a line are degenerate (as `merge_tolerance`). Default 0: exactly
    /// on one line.
    pub degenerate_tolerance: f64,
    /// Whether `degenerate_tolerance` is relative. Default false.
    pub degenerate_relative: bool,
    /// Whether boundary edges are split at T-vertices (hw_mesh_remove_t_vertices(), before
    /// stitching). Default true.
    pub remove_t_vertices: bool,
    /// Boundary vertices this close to another boundary edge split it (as `merge_tolerance`).
    /// Default 0: exactly on the edge.
    pub t_vertex_tolerance: f64,
    /// Whether `t_vertex_tolerance` is relative. Default false.
    pub t_vertex_relative: bool,
    /// Whether holes are filled (after stitching, as hw_mesh_fill_holes() fills them; holes it
    /// refuses stay open). Default false: an open surface is often open on purpose.
    pub fill_holes: bool,
    /// Holes with more boundary edges than this are left open. Default `SIZE_MAX`.
    pub fill_max_edges: usize,
    /// How holes are closed. Default ::HW_FILL_MODE_TRIANGULATE.
    pub fill_mode: hw_fill_mode,
}

/// The default options of hw_repair_mesh().
/// \ingroup repair
#[unsafe(no_mangle)]
pub extern "C" fn hw_repair_options_default() -> hw_repair_options {
    hw_repair_options {
        merge_tolerance: 0.0,
        merge_relative: false,
        stitch_tolerance: 0.0,
        stitch_relative: false,
        remove_small_components: false,
        small_rule: HW_SMALL_COMPONENTS_BY_FACE_COUNT,
        small_value: 0.0,
        remove_degenerate_faces: true,
        degenerate_tolerance: 0.0,
        degenerate_relative: false,
        remove_t_vertices: true,
        t_vertex_tolerance: 0.0,
        t_vertex_relative: false,
        fill_holes: false,
        fill_max_edges: usize::MAX,
        fill_mode: HW_FILL_MODE_TRIANGULATE,
    }
}

impl TryFrom<&hw_repair_options> for RepairOptions {
    type Error = FfiError;

    fn try_from(o: &hw_repair_options) -> Result<Self, FfiError> {
        let small_components = if !o.remove_small_components {
            None
        } else {
            Some(match o.small_rule {
                HW_SMALL_COMPONENTS_BY_FACE_COUNT
                    if o.small_value >= 0.0 && o.small_value.fract() == 0.0 =>
                {
                    SmallComponents::FaceCount(o.small_value as usize)
                }
                HW_SMALL_COMPONENTS_BY_FACE_COUNT => {
                    return Err(FfiError::invalid_input(format!(
                        "face count {} is not a whole number of 0 or more",
                        o.small_value
                    )));
                }
                HW_SMALL_COMPONENTS_BY_RELATIVE_DIAMETER => {
                    SmallComponents::RelativeDiameter(o.small_value)
                }
                other => {
                    return Err(FfiError::invalid_input(format!(
                        "unknown small-component rule {other}"
                    )));
                }
            })
        };
        Ok(RepairOptions {
            merge_tolerance: tolerance_arg(o.merge_tolerance, o.merge_relative),
            degenerate_tolerance: o
                .remove_degenerate_faces
                .then(|| tolerance_arg(o.degenerate_tolerance, o.degenerate_relative)),
            t_vertex_tolerance: o
                .remove_t_vertices
                .then(|| tolerance_arg(o.t_vertex_tolerance, o.t_vertex_relative)),
            stitch_tolerance: tolerance_arg(o.stitch_tolerance, o.stitch_relative),
            fill_holes: if o.fill_holes {
                Some(HoleFillOptions {
                    max_edges: o.fill_max_edges,
                    mode: fill_mode_arg(o.fill_mode)?,
                    ..HoleFillOptions::default()
                })
            } else {
                None
            },
            small_components,
        })
    }
}

/// What hw_repair_mesh() did to every input element. Opaque; read with hw_repair_fates_list()
/// and hw_repair_fates_counts(), release with hw_repair_fates_free().
/// \ingroup repair
pub struct hw_repair_fates {
    fates: RepairFates,
    vertex_kinds: Vec<u32>,
    vertex_ids: Vec<u32>,
    face_kinds: Vec<u32>,
    face_ids: Vec<u32>,
}

/// The fate of an element, in the kinds lists of hw_repair_fates_list().
/// \ingroup repair
pub type hw_fate = u32;
/// Kept: its id is the output element.
/// \ingroup repair
pub const HW_FATE_KEPT: hw_fate = 0;
/// A vertex merged into another: its id is the output vertex it went into.
/// \ingroup repair
pub const HW_FATE_MERGED: hw_fate = 1;
/// A face kept, reversed: its id is the output face.
/// \ingroup repair
pub const HW_FATE_REVERSED: hw_fate = 2;
/// A face removed: fewer than 3 distinct corners after merging (id `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATE_COLLAPSED: hw_fate = 3;
/// A face removed as a duplicate: its id is the input face kept in its place.
/// \ingroup repair
pub const HW_FATE_DUPLICATE: hw_fate = 4;
/// Removed: a face the repairing build could not keep, or a vertex with a non-finite
/// coordinate (id `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATE_UNBUILDABLE: hw_fate = 5;
/// Removed with a small component (id `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATE_SMALL_COMPONENT: hw_fate = 6;
/// A vertex removed because no kept face names it (id `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATE_UNREFERENCED: hw_fate = 7;
/// A face removed as degenerate: its corners on one line, collapsed with a short edge or
/// removed by hw_mesh_remove_degenerate_faces() (id `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATE_DEGENERATE: hw_fate = 8;

/// One list of hw_repair_fates_list().
/// \ingroup repair
pub type hw_fates_list = u32;
/// The ::hw_fate of every input vertex.
/// \ingroup repair
pub const HW_FATES_LIST_VERTEX_KINDS: hw_fates_list = 0;
/// The id that goes with every input vertex's fate.
/// \ingroup repair
pub const HW_FATES_LIST_VERTEX_IDS: hw_fates_list = 1;
/// The ::hw_fate of every input face.
/// \ingroup repair
pub const HW_FATES_LIST_FACE_KINDS: hw_fates_list = 2;
/// The id that goes with every input face's fate.
/// \ingroup repair
pub const HW_FATES_LIST_FACE_IDS: hw_fates_list = 3;
/// Pairs `output vertex, input vertex` (2 values each) of the output vertices no input vertex
/// became, by output id: copies of an input vertex, and vertices a refined hole fill placed
/// (input vertex `UINT32_MAX`).
/// \ingroup repair
pub const HW_FATES_LIST_ADDED_VERTICES: hw_fates_list = 4;
/// The output faces no input face became (the triangles filling holes), by output id.
/// \ingroup repair
pub const HW_FATES_LIST_ADDED_FACES: hw_fates_list = 5;

/// The counts of hw_repair_fates_counts().
/// \ingroup repair
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct hw_repair_fate_counts {
    /// Input vertices in the output.
    pub kept_vertices: usize,
    /// Input vertices merged into another.
    pub merged_vertices: usize,
    /// Input vertices removed.
    pub removed_vertices: usize,
    /// Output vertices no input vertex became: copies of an input vertex, and vertices placed
    /// by a refined hole fill (kept + added = output vertices).
    pub added_vertices: usize,
    /// Input faces in the output (kept + added = output faces).
    pub kept_faces: usize,
    /// Kept faces that run the other way round.
    pub reversed_faces: usize,
    /// Input faces removed.
    pub removed_faces: usize,
    /// Pairs of boundary edges stitched into one.
    pub stitched_edges: usize,
    /// Edges flipped to mend a degenerate triangle.
    pub flipped_edges: usize,
    /// Boundary edges split at a T-vertex.
    pub split_edges: usize,
    /// Output faces no input face became: the triangles filling holes.
    pub added_faces: usize,
    /// Holes filled.
    pub filled_holes: usize,
    /// Holes within the fill bounds that filling refused (left open).
    pub refused_holes: usize,
}

fn removal_kind(why: Removal) -> (hw_fate, u32) {
    match why {
        Removal::Collapsed => (HW_FATE_COLLAPSED, INVALID_INDEX),
        Removal::Duplicate { of } => (HW_FATE_DUPLICATE, of),
        Removal::Unbuildable => (HW_FATE_UNBUILDABLE, INVALID_INDEX),
        Removal::Degenerate => (HW_FATE_DEGENERATE, INVALID_INDEX),
        Removal::SmallComponent => (HW_FATE_SMALL_COMPONENT, INVALID_INDEX),
        Removal::Unreferenced => (HW_FATE_UNREFERENCED, INVALID_INDEX),
    }
}

impl hw_repair_fates {
    fn new(fates: RepairFates) -> Self {
        let (vertex_kinds, vertex_ids) = fates
            .vertices
            .iter()
            .map(|f| match *f {
                VertexFate::Kept(v) => (HW_FATE_KEPT, v),
                VertexFate::Merged { into } => (HW_FATE_MERGED, into),
                VertexFate::Removed(why) => removal_kind(why),
            })
            .unzip();
        let (face_kinds, face_ids) = fates
            .faces
            .iter()
            .map(|f| match *f {
                FaceFate::Kept {
                    face,
                    reversed: false,
                } => (HW_FATE_KEPT, face),
                FaceFate::Kept {
                    face,
                    reversed: true,
                } => (HW_FATE_REVERSED, face),
                FaceFate::Removed(why) => removal_kind(why),
            })
            .unzip();
        hw_repair_fates {
            fates,
            vertex_kinds,
            vertex_ids,
            face_kinds,
            face_ids,
        }
    }
}

/// Repairs the soup into a new mesh: merges duplicate vertices (within the options' merge
/// tolerance), removes duplicate faces, builds under ::HW_BUILD_POLICY_REPAIR (non-manifold vertices
/// split, non-manifold edges cut, faces oriented consistently, closed components outward, faces
/// that cannot be kept left out), mends degenerate triangles and splits boundary edges at
/// T-vertices (each when the options ask, as by default), stitches borders, fills holes (when
/// asked), removes small components (when asked) and
/// unreferenced vertices. The soup is unchanged. `*out_mesh` passes hw_mesh_check() and its
/// faces build again under ::HW_BUILD_POLICY_STRICT. `*out_fates` (when not NULL) says what became of
/// every input vertex and face. `HW_ERR_INVALID_INPUT`, nothing written, for bad options and a
/// malformed soup; `HW_ERR_OUT_OF_MEMORY` when memory ran out.
///
/// # Safety
/// `soup` NULL or live; `options` NULL or readable; `out_mesh` writable; `out_fates` NULL or
/// writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_mesh(
    soup: *const hw_soup,
    options: *const hw_repair_options,
    out_mesh: *mut *mut hw_mesh,
    out_fates: *mut *mut hw_repair_fates,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        let out_fates = Out::optional(out_fates);
        // SAFETY: forwarded from the caller.
        let soup = &unsafe { arg_ref(soup, "soup") }?.soup;
        // SAFETY: forwarded from the caller.
        let options = RepairOptions::try_from(unsafe { arg_ref(options, "options") }?)?;
        let (mesh, fates) = repair_mesh(soup, &options)?;
        // SAFETY: checked non-NULL and writable per the caller; the other NULL or writable.
        unsafe {
            out.write(into_handle(hw_mesh { mesh }));
            if let Some(out_fates) = out_fates {
                out_fates.write(into_handle(hw_repair_fates::new(fates)));
            }
        }
        Ok(())
    })
}

/// A read-only view of one list of the fates (`*out_ids`, NULL when empty, with `*out_len`
/// values). Lives as long as the fates.
///
/// # Safety
/// `fates` NULL or live; `out_ids` and `out_len` writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_fates_list(
    fates: *const hw_repair_fates,
    list: hw_fates_list,
    out_ids: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_ids, "out_ids", out_len, || {
            let fates = arg_ref(fates, "fates")?;
            match list {
                HW_FATES_LIST_VERTEX_KINDS => Ok(&fates.vertex_kinds[..]),
                HW_FATES_LIST_VERTEX_IDS => Ok(&fates.vertex_ids[..]),
                HW_FATES_LIST_FACE_KINDS => Ok(&fates.face_kinds[..]),
                HW_FATES_LIST_FACE_IDS => Ok(&fates.face_ids[..]),
                HW_FATES_LIST_ADDED_VERTICES => Ok(fates.fates.added_vertices.as_flattened()),
                HW_FATES_LIST_ADDED_FACES => Ok(&fates.fates.added_faces[..]),
                other => Err(FfiError::invalid_input(format!(
                    "unknown fates list {other}"
                ))),
            }
        })
    }
}

/// The number of elements of every fate, written to `*out_counts`.
///
/// # Safety
/// `fates` NULL or live; `out_counts` writable.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_fates_counts(
    fates: *const hw_repair_fates,
    out_counts: *mut hw_repair_fate_counts,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_counts, "out_counts")?;
        // SAFETY: forwarded from the caller.
        let fates = &unsafe { arg_ref(fates, "fates") }?.fates;
        let FateCounts {
            kept_vertices,
            merged_vertices,
            removed_vertices,
            added_vertices,
            added_faces,
            kept_faces,
            reversed_faces,
            removed_faces,
        } = fates.counts();
        let counts = hw_repair_fate_counts {
            kept_vertices,
            merged_vertices,
            removed_vertices,
            added_vertices,
            kept_faces,
            reversed_faces,
            removed_faces,
            stitched_edges: fates.stitched_edges,
            flipped_edges: fates.flipped_edges,
            split_edges: fates.split_edges,
            added_faces,
            filled_holes: fates.filled_holes,
            refused_holes: fates.refused_holes,
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(counts) };
        Ok(())
    })
}

/// Releases the fates. NULL is a no-op; a second free is refused (within the limits the
/// ownership conventions at the top of the header state).
///
/// # Safety
/// `fates` NULL or fates from this library, not in use by another thread.
/// \ingroup repair
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_repair_fates_free(fates: *mut hw_repair_fates) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(fates, "hw_repair_fates") });
}
