//! Pictures of a diagram: exact nearest-site label rasters under the L2, L1 and L∞ metrics, and
//! SVG drawings of clipped cells, into a caller's buffer or a file.

use std::ffi::c_char;

use crate::voronoi::{Metric, SvgOptions, to_svg};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::threads::with_threads;
use crate::ffi::boundary::{copy_text, guard, out_array};
use crate::ffi::mesh::io::path_arg;
use crate::ffi::voronoi::cells::{cells_ref, hw_voronoi_cells};
use crate::ffi::voronoi::diagram::{hw_voronoi, voronoi_ref};

/// A distance function for hw_voronoi_label_image().
/// \ingroup voronoi
pub type hw_metric = u32;
/// Euclidean distance (the diagram's own metric).
/// \ingroup voronoi
pub const HW_METRIC_EUCLIDEAN: hw_metric = 0;
/// Manhattan (L1, taxicab) distance `|dx| + |dy|`.
/// \ingroup voronoi
pub const HW_METRIC_MANHATTAN: hw_metric = 1;
/// Chebyshev (L∞) distance `max(|dx|, |dy|)`.
/// \ingroup voronoi
pub const HW_METRIC_CHEBYSHEV: hw_metric = 2;

fn metric(raw: hw_metric) -> Result<Metric, FfiError> {
    match raw {
        HW_METRIC_EUCLIDEAN => Ok(Metric::Euclidean),
        HW_METRIC_MANHATTAN => Ok(Metric::Manhattan),
        HW_METRIC_CHEBYSHEV => Ok(Metric::Chebyshev),
        other => Err(FfiError::invalid_input(format!("unknown metric {other}"))),
    }
}

/// Labels every pixel of a `width × height` image of the rectangle `[xmin, xmax] × [ymin, ymax]`
/// with the index of the site nearest to the pixel's centre under `metric` — decided exactly,
/// ties to the smallest index; duplicates never appear. Row-major, row 0 at the top (largest y).
///
/// `out_labels` must hold `width * height` labels; `*out_needed` (when not NULL) always receives
/// that count, and a smaller `capacity` gives `HW_ERR_BUFFER_TOO_SMALL` before any work. A diagram
/// without sites labels every pixel `HW_INVALID_INDEX`. A zero size, an unknown metric, a
/// non-finite bound or a misaligned `out_labels` give `HW_ERR_INVALID_INPUT`.
///
/// # Safety
/// `voronoi` must be NULL or a live diagram; `out_labels` NULL or `capacity` writable elements;
/// `out_needed` NULL or writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hw_voronoi_label_image(
    voronoi: *const hw_voronoi,
    metric_kind: hw_metric,
    xmin: f64,
    ymin: f64,
    xmax: f64,
    ymax: f64,
    width: u32,
    height: u32,
    out_labels: *mut u32,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let v = unsafe { voronoi_ref(voronoi) }?;
        let metric = metric(metric_kind)?;
        let pixels = (width as usize)
            .checked_mul(height as usize)
            .ok_or_else(|| {
                FfiError::invalid_input(format!("{width}x{height} pixels overflow size_t"))
            })?;
        // Checked before the work, which can be long.
        // SAFETY: forwarded from the caller.
        let labels = unsafe { out_array(out_labels, capacity, pixels, out_needed, "out_labels") }?;
        let image = with_threads(|| {
            v.delaunay()
                .label_image(metric, [xmin, ymin], [xmax, ymax], width, height)
        })?;
        labels.copy_from_slice(&image.labels);
        Ok(())
    })
}

/// What hw_voronoi_svg() draws. hw_svg_options_default() gives the defaults.
/// \ingroup voronoi
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct hw_svg_options {
    /// Picture width in pixels (> 0); the height follows the clip region's aspect ratio.
    pub width_px: f64,
    /// Fill cells with distinct pastel colours (otherwise outlines only).
    pub fill_cells: bool,
    /// Draw the sites as dots.
    pub sites: bool,
    /// Draw the Delaunay edges.
    pub delaunay_edges: bool,
}

impl From<SvgOptions> for hw_svg_options {
    fn from(o: SvgOptions) -> Self {
        hw_svg_options {
            width_px: o.width_px,
            fill_cells: o.fill_cells,
            sites: o.sites,
            delaunay_edges: o.delaunay_edges,
        }
    }
}

/// The default SVG options: 800 pixels wide, filled cells, sites, no Delaunay edges.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub extern "C" fn hw_svg_options_default() -> hw_svg_options {
    SvgOptions::default().into()
}

/// Draws `cells` (made from `voronoi`) as an SVG document; `options` NULL means the defaults.
///
/// # Safety
/// The pointers must be NULL or live objects.
unsafe fn svg_document(
    voronoi: *const hw_voronoi,
    cells: *const hw_voronoi_cells,
    options: *const hw_svg_options,
) -> Result<String, FfiError> {
    // SAFETY: forwarded from the caller.
    let (v, c) = unsafe { (voronoi_ref(voronoi)?, cells_ref(cells)?) };
    // SAFETY: NULL or readable per the caller.
    let o = unsafe { options.as_ref() }
        .copied()
        .unwrap_or_else(|| SvgOptions::default().into());
    if !(o.width_px.is_finite() && o.width_px > 0.0) {
        return Err(FfiError::invalid_input(format!(
            "SVG width {} is not a positive number of pixels",
            o.width_px
        )));
    }
    if c.n_cells() != v.delaunay().n_sites() {
        return Err(FfiError::invalid_input(format!(
            "the cells ({} sites) were not clipped from this diagram ({} sites)",
            c.n_cells(),
            v.delaunay().n_sites()
        )));
    }
    let options = SvgOptions {
        width_px: o.width_px,
        fill_cells: o.fill_cells,
        sites: o.sites,
        delaunay_edges: o.delaunay_edges,
    };
    Ok(to_svg(v, c, &options))
}

/// Copies an SVG drawing of `cells` (clipped from `voronoi`) into `out_text`, NUL-terminated;
/// `options` NULL means hw_svg_options_default(). `*out_needed` (when not NULL) always receives the
/// size needed, terminator included; a smaller `capacity` gives `HW_ERR_BUFFER_TOO_SMALL`. Cells
/// from another diagram or a non-positive width give `HW_ERR_INVALID_INPUT`.
///
/// # Safety
/// `voronoi` and `cells` must be NULL or live objects; `options` NULL or readable; `out_text` NULL
/// or `capacity` writable bytes; `out_needed` NULL or writable.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_svg(
    voronoi: *const hw_voronoi,
    cells: *const hw_voronoi_cells,
    options: *const hw_svg_options,
    out_text: *mut c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let svg = unsafe { svg_document(voronoi, cells, options) }?;
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(&svg, out_text, capacity, out_needed) }
    })
}

/// Writes an SVG drawing of `cells` (clipped from `voronoi`) to the file `path`; `options` NULL
/// means hw_svg_options_default(). A file that cannot be written gives `HW_ERR_IO`.
///
/// # Safety
/// `voronoi` and `cells` must be NULL or live objects; `options` NULL or readable; `path` NULL
/// or NUL-terminated.
/// \ingroup voronoi
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_voronoi_svg_write(
    voronoi: *const hw_voronoi,
    cells: *const hw_voronoi_cells,
    options: *const hw_svg_options,
    path: *const c_char,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let path = unsafe { path_arg(path) }?;
        // SAFETY: forwarded from the caller.
        let svg = unsafe { svg_document(voronoi, cells, options) }?;
        std::fs::write(&path, svg)
            .map_err(|e| FfiError::new(HW_ERR_IO, format!("cannot write {}: {e}", path.display())))
    })
}
