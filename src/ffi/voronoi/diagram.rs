//! `hw_voronoi`: the Voronoi diagram of 2D sites with its Delaunay dual — construction, counts,
//! zero-copy views of both structures, edge geometry, the triangulation as a mesh, and queries.
//!
//! Clipped cells are in [`crate::ffi::voronoi::cells`]; rasters and SVG in
//! [`crate::ffi::voronoi::images`].

use crate::mesh::Mesh;
use crate::soup::BuildPolicy;
use crate::voronoi::{EdgeGeometry, SiteId, Voronoi, VoronoiError, VoronoiHalfedgeId};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{
    Out, arg_ref, arg_slice, copy_items, give_view, guard, guard_value, guard_void,
    write_tuple_view,
};
use crate::ffi::mesh::lifecycle::hw_mesh;
use crate::ffi::voronoi::delaunay::{delaunay_array, site_dimension};
use crate::ffi::voronoi::ids::{hw_site, hw_voronoi_halfedge, hw_voronoi_vertex};

/// A 2D Voronoi diagram and its Delaunay triangulation. Opaque; build it with hw_voronoi_build()
/// and release it with hw_voronoi_free(). It never changes after construction, so every function
/// taking a `const hw_voronoi *` may run concurrently.
///
/// Numbering: sites keep their input index. A duplicated site is represented by the smallest
/// index of its group (::HW_VORONOI_ARRAY_REPRESENTATIVE); the other copies have no cell, no
/// incident Delaunay edge and no Voronoi half-edge. Voronoi half-edges come in twin pairs
/// (`twin = h ^ 1`); half-edge `h` bounds the cell of `site[h]` (on its left) and separates it
/// from `site[h ^ 1]`.
/// \ingroup voronoi
pub struct hw_voronoi {
    pub(crate) voronoi: Voronoi,
}

impl From<VoronoiError> for FfiError {
    fn from(error: VoronoiError) -> Self {
        let status = match &error {
            VoronoiError::InvalidSite { .. } => HW_ERR_INVALID_HANDLE,
            VoronoiError::OutOfMemory(_) => HW_ERR_OUT_OF_MEMORY,
            VoronoiError::NonFiniteSite { .. }
            | VoronoiError::TooManySites { .. }
            | VoronoiError::DegenerateClip(_)
            | VoronoiError::NonConvexClip { .. }
            | VoronoiError::InvalidTolerance(_)
            | VoronoiError::NonFiniteQuery
            | VoronoiError::InvalidRasterSize { .. } => HW_ERR_INVALID_INPUT,
        };
        FfiError::new(status, error.to_string())
    }
}

/// Borrows the diagram of a `const hw_voronoi *` argument.
///
/// # Safety
/// `voronoi` must be NULL or a live `hw_voronoi`.
pub(crate) unsafe fn voronoi_ref<'a>(voronoi: *const hw_voronoi) -> Result<&'a Voronoi, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(voronoi, "voronoi") }?.voronoi)
}

/// Borrows `2 * n_points` doubles (x, y per point) as points.
///
/// # Safety
/// `xy` must be NULL or point to `2 * n_points` doubles, as for [`arg_slice`].
pub(crate) unsafe fn points_arg<'a>(
    xy: *const f64,
    n_points: usize,
    name: &str,
) -> Result<&'a [[f64; 2]], FfiError> {
    // `[f64; 2]` has the alignment of `f64` and no padding, so x, y pairs read in place.
    // SAFETY: forwarded from the caller.
    unsafe { arg_slice(xy.cast::<[f64; 2]>(), n_points, name) }
}

/// The representative of `site`, or `HW_ERR_INVALID_HANDLE` naming it when out of range.
pub(crate) fn checked_site(voronoi: &Voronoi, site: SiteId) -> Result<SiteId, FfiError> {
    voronoi.delaunay().representative_of(site).ok_or_else(|| {
        VoronoiError::InvalidSite {
            site,
            count: voronoi.delaunay().n_sites(),
        }
        .into()
    })
}

/// Builds the Delaunay triangulation and Voronoi diagram of `n_sites` sites given as `2 * n_sites`
/// doubles (x, y per site).
///
/// Predicates are exact, so the result is correct for any finite input: duplicates are merged
/// (see ::HW_VORONOI_ARRAY_REPRESENTATIVE), collinear sites give parallel bisectors and no
/// triangles, cocircular sites one Voronoi vertex of degree > 3. Zero, one or two sites are valid
/// input. A NaN or infinite coordinate gives `HW_ERR_INVALID_INPUT` with a message naming the site.
///
/// On success `*out_voronoi` receives a new diagram to release with hw_voronoi_free().
///
/// # Safety
/// `xy` must point to `2 * n_sites` doubles (NULL only when `n_sites` is 0); `out_voronoi`
/// writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_build(
    xy: *const f64,
    n_sites: usize,
    out_voronoi: *mut *mut hw_voronoi,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_voronoi, "out_voronoi")?;
        // SAFETY: forwarded from the caller.
        let sites = unsafe { points_arg(xy, n_sites, "xy") }?;
        let voronoi = with_threads(|| Voronoi::new(sites))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_voronoi { voronoi })) };
        Ok(())
    })
}

/// Releases a diagram. NULL is a no-op; a diagram freed already is refused, the last error saying
/// so (within the limits the ownership conventions at the top of the header state). Clipped
/// cells made from it (::hw_voronoi_cells) stay valid.
///
/// # Safety
/// `voronoi` must be NULL or a diagram from this library not in use by another thread.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_free(voronoi: *mut hw_voronoi) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(voronoi, "hw_voronoi") });
}

/// Reads one count of a diagram; 0 (with the error recorded) for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
unsafe fn count(voronoi: *const hw_voronoi, of: impl FnOnce(&Voronoi) -> usize) -> usize {
    // SAFETY: forwarded from the caller.
    guard_value(0, || Ok(of(unsafe { voronoi_ref(voronoi) }?)))
}

/// Number of input sites, duplicates included; 0 for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_n_sites(voronoi: *const hw_voronoi) -> usize {
    unsafe { count(voronoi, |v| v.delaunay().n_sites()) }
}

/// Number of distinct sites (= number of cells); 0 for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_n_unique_sites(voronoi: *const hw_voronoi) -> usize {
    unsafe { count(voronoi, |v| v.delaunay().n_unique_sites()) }
}

/// Number of Delaunay triangles (0 when all sites are collinear); 0 for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_n_triangles(voronoi: *const hw_voronoi) -> usize {
    unsafe { count(voronoi, |v| v.delaunay().n_triangles()) }
}

/// Number of Voronoi vertices; 0 for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_n_vertices(voronoi: *const hw_voronoi) -> usize {
    unsafe { count(voronoi, Voronoi::n_vertices) }
}

/// Number of Voronoi half-edges (twice the number of edges); 0 for a NULL diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_n_halfedges(voronoi: *const hw_voronoi) -> usize {
    unsafe { count(voronoi, Voronoi::n_halfedges) }
}

/// The dimension of the site set, as hw_voronoi_dimension() reports it.
/// \ingroup voronoi
pub type hw_site_dimension = u32;
/// No sites.
/// \ingroup voronoi
pub const HW_SITE_DIMENSION_EMPTY: hw_site_dimension = 0;
/// One distinct site (possibly repeated): one cell, the whole plane.
/// \ingroup voronoi
pub const HW_SITE_DIMENSION_POINT: hw_site_dimension = 1;
/// Two or more distinct sites, all collinear: no triangles; cells are slabs between parallel
/// bisectors, and the hull lists the sites in order along their line.
/// \ingroup voronoi
pub const HW_SITE_DIMENSION_LINE: hw_site_dimension = 2;
/// The sites span the plane: at least one triangle.
/// \ingroup voronoi
pub const HW_SITE_DIMENSION_PLANE: hw_site_dimension = 3;

/// The dimension of the site set (::HW_SITE_DIMENSION_EMPTY for a NULL diagram, with the error
/// recorded).
///
/// # Safety
/// `voronoi` must be NULL or a live diagram.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_dimension(voronoi: *const hw_voronoi) -> hw_site_dimension {
    // SAFETY: forwarded from the caller.
    guard_value(HW_SITE_DIMENSION_EMPTY, || {
        Ok(site_dimension(
            unsafe { voronoi_ref(voronoi) }?.delaunay().dimension(),
        ))
    })
}

/// Which index array hw_voronoi_view() shows.
/// \ingroup voronoi
pub type hw_voronoi_array = u32;
/// Per site: the site representing it (itself unless it duplicates a smaller index).
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_REPRESENTATIVE: hw_voronoi_array = 0;
/// Per Delaunay triangle: its three sites, counter-clockwise (`3 * n_triangles` entries).
/// Delaunay half-edge `e` (= corner `e`) runs from site `triangles[e]` to the next corner's site.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_TRIANGLES: hw_voronoi_array = 1;
/// Per Delaunay half-edge: the opposite half-edge, `HW_INVALID_INDEX` on the convex hull.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_TRIANGLE_TWINS: hw_voronoi_array = 2;
/// The convex hull's sites, counter-clockwise (for collinear input: the sites in order along the
/// line; for one distinct site: that site).
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_HULL: hw_voronoi_array = 3;
/// Per Delaunay triangle: its Voronoi vertex (cocircular triangles share one).
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_TRIANGLE_VERTEX: hw_voronoi_array = 4;
/// Per Voronoi half-edge: its start vertex, `HW_INVALID_INDEX` when it comes from infinity.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_HALFEDGE_ORIGIN: hw_voronoi_array = 5;
/// Per Voronoi half-edge: the next half-edge counter-clockwise around its cell (an edge running
/// out to infinity is followed by the one coming back).
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_HALFEDGE_NEXT: hw_voronoi_array = 6;
/// Per Voronoi half-edge: the previous half-edge around its cell.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_HALFEDGE_PREV: hw_voronoi_array = 7;
/// Per Voronoi half-edge: the site whose cell it bounds (on its left).
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_HALFEDGE_SITE: hw_voronoi_array = 8;
/// Per site: one half-edge of its cell (the edge from infinity for an unbounded cell),
/// `HW_INVALID_INDEX` for duplicates and when the diagram has no edges.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_CELL_HALFEDGE: hw_voronoi_array = 9;
/// Per Voronoi vertex: one outgoing half-edge.
/// \ingroup voronoi
pub const HW_VORONOI_ARRAY_VERTEX_HALFEDGE: hw_voronoi_array = 10;

fn array(voronoi: &Voronoi, which: hw_voronoi_array) -> Result<&[u32], FfiError> {
    if let Some(triangulation) = delaunay_array(voronoi.delaunay(), which) {
        return Ok(triangulation);
    }
    Ok(match which {
        HW_VORONOI_ARRAY_TRIANGLE_VERTEX => &voronoi.triangle_vertex,
        HW_VORONOI_ARRAY_HALFEDGE_ORIGIN => &voronoi.half_edges().origin,
        HW_VORONOI_ARRAY_HALFEDGE_NEXT => &voronoi.half_edges().next,
        HW_VORONOI_ARRAY_HALFEDGE_PREV => &voronoi.half_edges().prev,
        HW_VORONOI_ARRAY_HALFEDGE_SITE => &voronoi.half_edges().site,
        HW_VORONOI_ARRAY_CELL_HALFEDGE => &voronoi.half_edges().cell_edge,
        HW_VORONOI_ARRAY_VERTEX_HALFEDGE => &voronoi.half_edges().vertex_edge,
        other => {
            return Err(FfiError::invalid_input(format!(
                "unknown Voronoi array {other}"
            )));
        }
    })
}

/// A read-only view of one index array of the diagram (see ::hw_voronoi_array): `*out_data`
/// (NULL when empty) and its length `*out_len`, valid as long as the diagram. The half-edge
/// arrays are built on first use (by this call or any half-edge query), once, safely even when
/// several threads ask at the same time.
///
/// A cell walk in C:
/// ```c
/// uint32_t h = cell_halfedge[s], start = h;
/// if (h != HW_INVALID_INDEX) do { visit(h); h = next[h]; } while (h != start);
/// ```
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_data` and `out_len` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_view(
    voronoi: *const hw_voronoi,
    which: hw_voronoi_array,
    out_data: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_data, "out_data", out_len, || {
            let voronoi = voronoi_ref(voronoi)?;
            with_threads(|| array(voronoi, which))
        })
    }
}

/// A read-only view of the sites as given: `*out_xy` (x, y per site, NULL when empty) and the
/// number of sites `*out_n_sites`, valid as long as the diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_xy` and `out_n_sites` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_sites(
    voronoi: *const hw_voronoi,
    out_xy: *mut *const f64,
    out_n_sites: *mut usize,
) -> hw_status {
    guard(|| {
        let (out_xy, out_len) = (
            Out::new(out_xy, "out_xy")?,
            Out::new(out_n_sites, "out_n_sites")?,
        );
        // SAFETY: forwarded from the caller.
        let sites = unsafe { voronoi_ref(voronoi) }?.delaunay().sites();
        // SAFETY: both checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(out_xy, out_len, sites) };
        Ok(())
    })
}

/// A read-only view of the Voronoi vertices (circumcentres): `*out_xy` (x, y per vertex, NULL
/// when empty) and their number `*out_n_vertices`, valid as long as the diagram.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_xy` and `out_n_vertices` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_vertices(
    voronoi: *const hw_voronoi,
    out_xy: *mut *const f64,
    out_n_vertices: *mut usize,
) -> hw_status {
    guard(|| {
        let (out_xy, out_len) = (
            Out::new(out_xy, "out_xy")?,
            Out::new(out_n_vertices, "out_n_vertices")?,
        );
        // SAFETY: forwarded from the caller.
        let vertices = unsafe { voronoi_ref(voronoi) }?.vertices();
        // SAFETY: both checked non-NULL, writable per the caller.
        unsafe { write_tuple_view(out_xy, out_len, vertices) };
        Ok(())
    })
}

/// The shape of a Voronoi edge (see ::hw_voronoi_edge).
/// \ingroup voronoi
pub type hw_voronoi_edge_kind = u32;
/// Both ends are Voronoi vertices: from `point` to `end`.
/// \ingroup voronoi
pub const HW_VORONOI_EDGE_KIND_SEGMENT: hw_voronoi_edge_kind = 0;
/// One end at infinity: the points `point + t * direction`, `t >= 0`.
/// \ingroup voronoi
pub const HW_VORONOI_EDGE_KIND_RAY: hw_voronoi_edge_kind = 1;
/// Both ends at infinity (collinear sites): the points `point + t * direction` for every `t`.
/// \ingroup voronoi
pub const HW_VORONOI_EDGE_KIND_LINE: hw_voronoi_edge_kind = 2;

/// One Voronoi edge seen from one of its half-edges: the two sites it separates and its geometry.
/// \ingroup voronoi
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct hw_voronoi_edge {
    /// ::HW_VORONOI_EDGE_KIND_SEGMENT, ::HW_VORONOI_EDGE_KIND_RAY or ::HW_VORONOI_EDGE_KIND_LINE.
    pub kind: hw_voronoi_edge_kind,
    /// The site on the half-edge's left (whose cell it bounds).
    pub site: hw_site,
    /// The site on its right.
    pub opposite_site: hw_site,
    /// Start vertex (`HW_INVALID_INDEX` when it comes from infinity).
    pub origin: hw_voronoi_vertex,
    /// End vertex (`HW_INVALID_INDEX` when it runs to infinity).
    pub target: hw_voronoi_vertex,
    /// Segment: the start. Ray: its finite end (for a half-edge coming from infinity, that is
    /// where it ends). Line: the midpoint of the two sites.
    pub point: [f64; 2],
    /// Segment: the end. Otherwise equal to `point`.
    pub end: [f64; 2],
    /// Ray and line: the direction away from `point` (not normalised; for a half-edge coming
    /// from infinity it points back towards infinity, i.e. against the half-edge). Segment:
    /// `end - point`.
    pub direction: [f64; 2],
}

/// Describes the Voronoi edge of half-edge `halfedge` (see ::hw_voronoi_edge). An index out of
/// range gives `HW_ERR_INVALID_HANDLE`.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_edge` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_edge_describe(
    voronoi: *const hw_voronoi,
    halfedge: hw_voronoi_halfedge,
    out_edge: *mut hw_voronoi_edge,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_edge, "out_edge")?;
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let halfedge = VoronoiHalfedgeId::from(halfedge);
        let geometry = v.edge_geometry(halfedge).ok_or_else(|| {
            FfiError::invalid_handle(format!("{halfedge} out of range (0..{})", v.n_halfedges()))
        })?;
        let (kind, point, end, direction) = match geometry {
            EdgeGeometry::Segment { from, to } => (
                HW_VORONOI_EDGE_KIND_SEGMENT,
                from,
                to,
                [to[0] - from[0], to[1] - from[1]],
            ),
            EdgeGeometry::Ray { origin, direction } => {
                (HW_VORONOI_EDGE_KIND_RAY, origin, origin, direction)
            }
            EdgeGeometry::Line { point, direction } => {
                (HW_VORONOI_EDGE_KIND_LINE, point, point, direction)
            }
        };
        let edge = hw_voronoi_edge {
            kind,
            site: v.site(halfedge).into(),
            opposite_site: v.opposite_site(halfedge).into(),
            origin: v.origin(halfedge).into(),
            target: v.target(halfedge).into(),
            point,
            end,
            direction,
        };
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(edge) };
        Ok(())
    })
}

/// The Delaunay triangulation as a new half-edge mesh (z = 0): vertex `i` is site `i` (duplicates
/// are isolated vertices), one triangle per Delaunay triangle, in the order of
/// ::HW_VORONOI_ARRAY_TRIANGLES. Collinear input gives a mesh without faces. Release it with
/// hw_mesh_free().
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_mesh` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_delaunay_mesh(
    voronoi: *const hw_voronoi,
    out_mesh: *mut *mut hw_mesh,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_mesh, "out_mesh")?;
        // SAFETY: forwarded from the caller.
        let soup = unsafe { voronoi_ref(voronoi) }?
            .delaunay()
            .to_polygon_soup();
        let (mesh, _) =
            with_threads(|| Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_mesh { mesh })) };
        Ok(())
    })
}

/// The site nearest to the point (`x`, `y`) — the site whose cell contains it — exactly, ties
/// going to the smallest index. `hint`, when it is a site, starts the search there (a nearby
/// site makes the query O(1)); pass `(hw_site){HW_INVALID_INDEX}` for none. A NaN or infinite
/// point gives `HW_ERR_INVALID_INPUT`; a diagram without sites `HW_ERR_NOT_FOUND`.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_site` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_nearest_site(
    voronoi: *const hw_voronoi,
    x: f64,
    y: f64,
    hint: hw_site,
    out_site: *mut hw_site,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_site, "out_site")?;
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let hint = (hint != hw_site::INVALID).then_some(SiteId::from(hint));
        let site = v
            .nearest_site([x, y], hint)?
            .ok_or_else(|| FfiError::new(HW_ERR_NOT_FOUND, "the diagram has no sites"))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(site.into()) };
        Ok(())
    })
}

/// Copies the sites whose cells share an edge with the cell of `site` (its Delaunay neighbours,
/// less those cut off by cocircular merging), counter-clockwise, into `out_sites`; `*out_needed`
/// (when not NULL) receives their number. A duplicate site answers for its representative. Out of
/// range: `HW_ERR_INVALID_HANDLE`; `capacity` too small: `HW_ERR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_sites` NULL or `capacity` writable elements;
/// `out_needed` NULL or writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_neighbours(
    voronoi: *const hw_voronoi,
    site: hw_site,
    out_sites: *mut hw_site,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let neighbours = v.neighbours(checked_site(v, site.into())?);
        let neighbours: Vec<hw_site> = neighbours.into_iter().map(hw_site::from).collect();
        // SAFETY: forwarded from the caller.
        unsafe { copy_items(&neighbours, out_sites, capacity, out_needed, "out_sites") }
    })
}

/// The Voronoi half-edge separating the cells of sites `a` and `b`, on the side of `a` (its twin,
/// `h ^ 1`, is on the side of `b`). Duplicates answer for their representatives. Either site out
/// of range: `HW_ERR_INVALID_HANDLE`; cells not adjacent: `HW_ERR_NOT_FOUND`.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_halfedge` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_edge_between(
    voronoi: *const hw_voronoi,
    a: hw_site,
    b: hw_site,
    out_halfedge: *mut hw_voronoi_halfedge,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_halfedge, "out_halfedge")?;
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let (a, b) = (checked_site(v, a.into())?, checked_site(v, b.into())?);
        let h = v.edge_between(a, b).ok_or_else(|| {
            FfiError::new(
                HW_ERR_NOT_FOUND,
                format!("the cells of {a} and {b} share no edge"),
            )
        })?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(h.into()) };
        Ok(())
    })
}
