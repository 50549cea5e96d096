//! `hw_delaunay`: the Delaunay triangulation of 2D sites alone, without the Voronoi diagram —
//! construction, counts and zero-copy views of its index arrays.
//!
//! Its arrays are the Delaunay arrays of an `hw_voronoi` ([`crate::ffi::voronoi::diagram`]), under the same
//! names and numbering.

use crate::voronoi::{Delaunay, Dimension};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::handle::{free_handle, into_handle};
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, arg_ref, give_view, guard, guard_value, guard_void};
use crate::ffi::voronoi::diagram::{
    HW_SITE_DIMENSION_EMPTY, HW_SITE_DIMENSION_LINE, HW_SITE_DIMENSION_PLANE,
    HW_SITE_DIMENSION_POINT, HW_VORONOI_ARRAY_HULL, HW_VORONOI_ARRAY_REPRESENTATIVE,
    HW_VORONOI_ARRAY_TRIANGLE_TWINS, HW_VORONOI_ARRAY_TRIANGLES, hw_site_dimension,
    hw_voronoi_array, points_arg,
};

/// A 2D Delaunay triangulation, without its Voronoi diagram. Opaque; build it with
/// hw_delaunay_build() and release it with hw_delaunay_free(). It never changes after
/// construction, so every function taking a `const hw_delaunay *` may run concurrently.
///
/// Numbering as for ::hw_voronoi: sites keep their input index, a duplicated site is represented
/// by the smallest index of its group, and the arrays are those of the same names in
/// ::hw_voronoi_view() (the triangulation is the same one).
/// \ingroup voronoi
pub struct hw_delaunay {
    pub(crate) delaunay: Delaunay,
}

/// Borrows the triangulation of a `const hw_delaunay *` argument.
///
/// # Safety
/// `delaunay` must be NULL or a live `hw_delaunay`.
unsafe fn delaunay_ref<'a>(delaunay: *const hw_delaunay) -> Result<&'a Delaunay, FfiError> {
    // SAFETY: forwarded from the caller.
    Ok(&unsafe { arg_ref(delaunay, "delaunay") }?.delaunay)
}

/// The code of a site set's dimension.
pub(crate) fn site_dimension(dimension: Dimension) -> hw_site_dimension {
    match dimension {
        Dimension::Empty => HW_SITE_DIMENSION_EMPTY,
        Dimension::Point => HW_SITE_DIMENSION_POINT,
        Dimension::Line => HW_SITE_DIMENSION_LINE,
        Dimension::Plane => HW_SITE_DIMENSION_PLANE,
    }
}

/// The triangulation's index array `which`, or `None` for an array of the Voronoi diagram.
pub(crate) fn delaunay_array(delaunay: &Delaunay, which: hw_voronoi_array) -> Option<&[u32]> {
    match which {
        HW_VORONOI_ARRAY_REPRESENTATIVE => Some(delaunay.representative()),
        HW_VORONOI_ARRAY_TRIANGLES => Some(delaunay.triangles()),
        HW_VORONOI_ARRAY_TRIANGLE_TWINS => Some(delaunay.twins()),
        HW_VORONOI_ARRAY_HULL => Some(delaunay.hull()),
        _ => None,
    }
}

/// Builds the Delaunay triangulation of `n_sites` sites given as `2 * n_sites` doubles (x, y per
/// site), without the Voronoi diagram (hw_voronoi_build() builds both): for callers that need
/// only the triangles, it takes less time and memory.
///
/// Input as for hw_voronoi_build(): any finite sites, duplicates merged (see
/// ::HW_VORONOI_ARRAY_REPRESENTATIVE), collinear sites give no triangles; a NaN or infinite
/// coordinate gives `HW_ERR_INVALID_INPUT` with a message naming the site.
///
/// On success `*out_delaunay` receives a new triangulation to release with hw_delaunay_free().
///
/// # Safety
/// `xy` must point to `2 * n_sites` doubles (NULL only when `n_sites` is 0); `out_delaunay`
/// writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_delaunay_build(
    xy: *const f64,
    n_sites: usize,
    out_delaunay: *mut *mut hw_delaunay,
) -> hw_status {
    guard(|| {
        let out = Out::new(out_delaunay, "out_delaunay")?;
        // SAFETY: forwarded from the caller.
        let sites = unsafe { points_arg(xy, n_sites, "xy") }?;
        let delaunay = with_threads(|| Delaunay::new(sites))?;
        // SAFETY: checked non-NULL, writable per the caller.
        unsafe { out.write(into_handle(hw_delaunay { delaunay })) };
        Ok(())
    })
}

/// Releases a triangulation. NULL is a no-op; a triangulation freed already is refused, the last
/// error saying so (within the limits the ownership conventions at the top of the header state).
///
/// # Safety
/// `delaunay` must be NULL or a triangulation from this library not in use by another thread.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_delaunay_free(delaunay: *mut hw_delaunay) {
    // SAFETY: forwarded from the caller.
    guard_void(|| unsafe { free_handle(delaunay, "hw_delaunay") });
}

/// Number of triangles (0 when all sites are collinear); 0 for a NULL triangulation.
///
/// # Safety
/// `delaunay` must be NULL or a live triangulation.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_delaunay_n_triangles(delaunay: *const hw_delaunay) -> usize {
    // SAFETY: forwarded from the caller.
    guard_value(0, || Ok(unsafe { delaunay_ref(delaunay) }?.n_triangles()))
}

/// The dimension of the site set (::HW_SITE_DIMENSION_EMPTY for a NULL triangulation, with the
/// error recorded).
///
/// # Safety
/// `delaunay` must be NULL or a live triangulation.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_delaunay_dimension(delaunay: *const hw_delaunay) -> hw_site_dimension {
    // SAFETY: forwarded from the caller.
    guard_value(HW_SITE_DIMENSION_EMPTY, || {
        Ok(site_dimension(
            unsafe { delaunay_ref(delaunay) }?.dimension(),
        ))
    })
}

/// A read-only view of one index array of the triangulation: `which` is one of
/// ::HW_VORONOI_ARRAY_REPRESENTATIVE, ::HW_VORONOI_ARRAY_TRIANGLES,
/// ::HW_VORONOI_ARRAY_TRIANGLE_TWINS and ::HW_VORONOI_ARRAY_HULL (the other arrays belong to the
/// Voronoi diagram: `HW_ERR_INVALID_INPUT`). `*out_data` (NULL when empty) and its length
/// `*out_len` are valid as long as the triangulation.
///
/// # Safety
/// `delaunay` must be NULL or a live triangulation; `out_data` and `out_len` writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_delaunay_view(
    delaunay: *const hw_delaunay,
    which: hw_voronoi_array,
    out_data: *mut *const u32,
    out_len: *mut usize,
) -> hw_status {
    // SAFETY: forwarded from the caller.
    unsafe {
        give_view(out_data, "out_data", out_len, || {
            delaunay_array(delaunay_ref(delaunay)?, which).ok_or_else(|| {
                FfiError::invalid_input(format!(
                    "array {which} is not an array of the Delaunay triangulation"
                ))
            })
        })
    }
}
