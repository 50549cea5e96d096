//! Lloyd relaxation through the C API: sites moved to the true centroids of their clipped cells.

use crate::voronoi::{LloydOptions, lloyd_relaxation};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::hw_status;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{Out, check_aligned, guard};
use crate::ffi::voronoi::cells::clip_polygon_arg;
use crate::ffi::voronoi::diagram::points_arg;

/// Lloyd relaxation: moves every site to the centroid of its Voronoi cell clipped to the convex
/// polygon `clip_xy` (`2 * n_clip_vertices` doubles; a rectangle is four corners), repeatedly,
/// for at most `max_iterations` iterations or until no site moved farther than `tolerance` in
/// one iteration (0 runs them all).
///
/// `xy` holds the `n_sites` sites (x, y each); the relaxed sites are written to `out_xy`, which
/// holds as many doubles and may be the same array as `xy`. Sites whose cell misses the region
/// stay where they are; a duplicate stays while its representative moves, so they separate.
/// `*out_iterations` and `*out_max_displacement` (each may be NULL) receive the iterations run
/// and the largest move of the last one. Bad sites, a bad clip polygon (see
/// hw_voronoi_clip_convex()) or a negative or non-finite tolerance give `HW_ERR_INVALID_INPUT`,
/// naming the site or the tolerance (sites are checked also when `max_iterations` is 0); so does
/// a misaligned `out_xy`.
///
/// # Safety
/// `xy` and `out_xy` must point to `2 * n_sites` doubles (readable, resp. writable; NULL only
/// when `n_sites` is 0); `clip_xy` to `2 * n_clip_vertices` doubles; the other outputs NULL or
/// writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hw_voronoi_lloyd(
    xy: *const f64,
    n_sites: usize,
    clip_xy: *const f64,
    n_clip_vertices: usize,
    max_iterations: u32,
    tolerance: f64,
    out_xy: *mut f64,
    out_iterations: *mut u32,
    out_max_displacement: *mut f64,
) -> hw_status {
    guard(|| {
        if n_sites > 0 {
            if out_xy.is_null() {
                return Err(FfiError::null_argument("out_xy"));
            }
            check_aligned(out_xy, "out_xy")?;
        }
        let out_iterations = Out::optional(out_iterations);
        let out_max_displacement = Out::optional(out_max_displacement);
        // SAFETY: forwarded from the caller.
        let clip = unsafe { clip_polygon_arg(clip_xy, n_clip_vertices) }?;
        let options = LloydOptions {
            max_iterations,
            tolerance,
        };
        // The input is read (and copied) before anything is written, so `out_xy` may alias it.
        let result = {
            // SAFETY: forwarded from the caller.
            let sites = unsafe { points_arg(xy, n_sites, "xy") }?;
            with_threads(|| lloyd_relaxation(sites, &clip, options))?
        };
        // SAFETY: `out_xy` holds `2 * n_sites` writable doubles; the input borrow has ended and
        // the result is a Rust allocation, so the copy does not overlap.
        unsafe {
            std::ptr::copy_nonoverlapping(
                result.sites.as_ptr().cast::<f64>(),
                out_xy,
                2 * result.sites.len(),
            );
            if let Some(out) = out_iterations {
                out.write(result.iterations);
            }
            if let Some(out) = out_max_displacement {
                out.write(result.max_displacement);
            }
        }
        Ok(())
    })
}
