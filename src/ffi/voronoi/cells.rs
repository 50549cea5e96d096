//! `hw_voronoi_cells`: every cell of a diagram clipped to a rectangle or convex polygon —
//! closed polygons with shared vertices, their areas and centroids, and the tiling as a mesh.

use crate::mesh::Mesh;
use crate::soup::BuildPolicy;
use crate::voronoi::{ClipPolygon, ClippedCells, SiteId, polygon_area_centroid};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{
    Out, arg_ref, copy_items, give_view, guard, guard_value, guard_void, write_tuple_view,
};
use crate::ffi::mesh::lifecycle::hw_mesh;
use crate::ffi::voronoi::diagram::{hw_voronoi, points_arg, voronoi_ref};
use crate::ffi::voronoi::ids::hw_site;

/// The cells of a Voronoi diagram clipped to a convex region. Opaque; made by
/// hw_voronoi_clip_rect() or hw_voronoi_clip_convex(), released with hw_voronoi_cells_free(). It
/// owns its data: it stays valid after its diagram is freed, and never changes.
///
/// The cells tile the region without gaps or overlaps; a corner shared by several cells is one
/// entry of hw_voronoi_cells_positions(). Cells are indexed by site and counter-clockwise; a
/// duplicate site, or a site whose cell misses the region or meets it only along its boundary,
/// has an empty cell. A cell narrower than the spacing of doubles is still listed (its corners
/// may coincide once rounded; where rounding collapses it, it is rebuilt from its exact polygon
/// with corners of its own); one narrower than the rounding of its own corners can come out
/// clockwise, with twice its area within `4nε·X·D` (n corners, largest coordinate magnitude X,
/// largest offset D from the first corner, ε = DBL_EPSILON).
/// \ingroup voronoi
pub struct hw_voronoi_cells {
    pub(crate) cells: ClippedCells,
}

/// Borrows the cells of a `const hw_voronoi_cells *` argument.
///
/// # Safety
/// `cells` must be NULL or a live `hw_voronoi_cells`.
pub(crate) unsafe fn cells_ref<'a>(
    cells: *const hw_voronoi_cells,
) -> Result<&'a ClippedCells, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(cells, "cells") }?.cells)
}

/// Clips every cell of `voronoi` to `region` and hands the result to C.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_cells` writable.
unsafe fn clip_to(
    voronoi: *const hw_voronoi,
    region: impl FnOnce() -> Result<ClipPolygon, FfiError>,
    out_cells: *mut *mut hw_voronoi_cells,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_cells, "out_cells")?;
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let region = region()?;
        let cells = with_threads(|| v.clip(&region));
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_voronoi_cells { cells })) };
        Ok(())
    })
}

/// Clips every cell to the rectangle `[xmin, xmax] × [ymin, ymax]`. A rectangle of zero or
/// negative extent, or with a non-finite bound, gives `HW_ERR_INVALID_INPUT`. On success
/// `*out_cells` receives new cells to release with hw_voronoi_cells_free().
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_cells` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_clip_rect(
    voronoi: *const hw_voronoi,
    xmin: f64,
    ymin: f64,
    xmax: f64,
    ymax: f64,
    out_cells: *mut *mut hw_voronoi_cells,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        clip_to(
            voronoi,
            || Ok(ClipPolygon::rectangle([xmin, ymin], [xmax, ymax])?),
            out_cells,
        )
    }
}

/// Borrows a convex clip polygon given as `2 * n_vertices` doubles.
///
/// # Safety
/// As for [`points_arg`].
pub(crate) unsafe fn clip_polygon_arg(
    xy: *const f64,
    n_vertices: usize,
) -> Result<ClipPolygon, FfiError> {
    // SAFETY: forwarded from the caller.
    let vertices = unsafe { points_arg(xy, n_vertices, "clip_xy") }?;
    Ok(ClipPolygon::convex(vertices)?)
}

/// Clips every cell to the convex polygon of `n_vertices` vertices given as `2 * n_vertices`
/// doubles (x, y per vertex), in either orientation; vertices on the segment between their
/// neighbours are dropped. Fewer than three distinct vertices, zero area or a non-finite vertex
/// give `HW_ERR_INVALID_INPUT`, and so does a polygon that is not convex (the message names a
/// vertex where it turns the wrong way). On success `*out_cells` receives new cells to release
/// with hw_voronoi_cells_free().
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `clip_xy` must point to `2 * n_vertices` doubles;
/// `out_cells` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_clip_convex(
    voronoi: *const hw_voronoi,
    clip_xy: *const f64,
    n_vertices: usize,
    out_cells: *mut *mut hw_voronoi_cells,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe { clip_to(voronoi, || clip_polygon_arg(clip_xy, n_vertices), out_cells) }
}

/// Releases clipped cells. NULL is a no-op; cells freed already are refused (within the limits
/// the ownership conventions at the top of the header state).
///
/// # Safety
/// `cells` must be NULL or cells from this library not in use by another thread.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_free(cells: *mut hw_voronoi_cells) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(cells, "hw_voronoi_cells") });
}

/// Number of cells, one per input site (empty ones included); 0 for NULL.
///
/// # Safety
/// `cells` must be NULL or live cells.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_n_cells(cells: *const hw_voronoi_cells) -> usize {
    // SAFETY: forwarded from the caller.
    guard_value(0, || Ok(unsafe { cells_ref(cells) }?.n_cells()))
}

/// A read-only view of all cell corners: `*out_xy` (x, y per position; the region's corners
/// first, then Voronoi vertices inside it, then boundary crossings, then the corners of cells
/// rebuilt from their exact polygons; NULL when empty) and their
/// number `*out_n_positions`, valid as long as the cells.
///
/// # Safety
/// `cells` must be NULL or live cells; `out_xy` and `out_n_positions` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_positions(
    cells: *const hw_voronoi_cells,
    out_xy: *mut *const f64,
    out_n_positions: *mut usize,
) -> hw_status {
    guard(|| {
        let (out_xy, out_len) = (
            Out::new(out_xy, "out_xy")?,
            Out::new(out_n_positions, "out_n_positions")?,
        );
        // SAFETY: forwarded from the caller.
        let positions = unsafe { cells_ref(cells) }?.positions();
        // SAFETY: both checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(out_xy, out_len, positions) };
        Ok(())
    })
}

/// A read-only view of the cell of `site`: `*out_indices` (NULL when empty), indices into
/// hw_voronoi_cells_positions(), counter-clockwise, and their number `*out_len` (0 for a
/// duplicate site or a cell that misses the region). Out of range: `HW_ERR_INVALID_HANDLE`.
///
/// # Safety
/// `cells` must be NULL or live cells; `out_indices` and `out_len` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_polygon(
    cells: *const hw_voronoi_cells,
    site: hw_site,
    out_indices: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_indices, "out_indices", out_len, || {
            Ok(cells_ref(cells)?.cell(site.into())?)
        })
    }
}

/// Area and centroid of the cell of `site`. An empty cell has area 0 and gives
/// `HW_ERR_NOT_FOUND` when its centroid is asked for; pass NULL for an output not wanted. Out of
/// range: `HW_ERR_INVALID_HANDLE`.
///
/// # Safety
/// `cells` must be NULL or live cells; `out_area` NULL or writable; `out_centroid` NULL or two
/// writable doubles.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_area_centroid(
    cells: *const hw_voronoi_cells,
    site: hw_site,
    out_area: *mut f64,
    out_centroid: *mut f64,
) -> hw_status {
    guard(|| {
        let out_area = Out::optional(out_area);
        let out_centroid = Out::optional(out_centroid.cast::<[f64; 2]>());
        // SAFETY: forwarded from the caller.
        let site = SiteId::from(site);
        let polygon = unsafe { cells_ref(cells) }?.cell_polygon(site)?;
        if polygon.is_empty() && out_centroid.is_some() {
            return Err(FfiError::new(
                HW_ERR_NOT_FOUND,
                format!("the cell of {site} is empty: it has no centroid"),
            ));
        }
        let (area, centroid) = polygon_area_centroid(&polygon);
        // SAFETY: non-NULL, writable per the caller.
        unsafe {
            if let Some(out) = out_area {
                out.write(if polygon.is_empty() { 0.0 } else { area });
            }
            if let Some(out) = out_centroid {
                out.write(centroid);
            }
        }
        Ok(())
    })
}

/// The cells as a new half-edge mesh (z = 0) whose vertices are hw_voronoi_cells_positions(), so
/// neighbouring cells share edges: face `k` is the `k`-th non-empty cell in site order (see
/// hw_voronoi_cells_face_sites()). The mesh kernel can edit it. Release it with hw_mesh_free().
///
/// # Safety
/// `cells` must be NULL or live cells; `out_mesh` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_mesh(
    cells: *const hw_voronoi_cells,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let (soup, _) = unsafe { cells_ref(cells) }?.to_polygon_soup();
        let (mesh, _) =
            with_threads(|| Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_mesh { mesh })) };
        Ok(())
    })
}

/// Copies the site of every face of hw_voronoi_cells_mesh() into `out_sites` (`*out_needed`, when
/// not NULL, receives the face count); `capacity` too small: `HW_ERR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `cells` must be NULL or live cells; `out_sites` NULL or `capacity` writable elements;
/// `out_needed` NULL or writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_cells_face_sites(
    cells: *const hw_voronoi_cells,
    out_sites: *mut hw_site,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        // The soup decides which cells become faces; asking it keeps the two in agreement.
        let (_, face_sites) = unsafe { cells_ref(cells) }?.to_polygon_soup();
        let face_sites: Vec<hw_site> = face_sites.into_iter().map(hw_site::from).collect();
        // SAFETY: forwarded from the caller.
        unsafe { copy_items(&face_sites, out_sites, capacity, out_needed, "out_sites") }
    })
}
