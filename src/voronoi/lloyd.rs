//! Lloyd relaxation with the true centroids of the clipped cells.

use super::clip_region::ClipPolygon;
use super::delaunay::check_sites;
use super::diagram::Voronoi;
use super::error::VoronoiError;
use super::ids::SiteId;

/// When Lloyd relaxation stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LloydOptions {
    /// Most iterations to run.
    pub max_iterations: u32,
    /// Stop once no site moved farther than this in one iteration (0 runs every iteration).
    pub tolerance: f64,
}

/// Outcome of a relaxation.
#[derive(Clone, Debug, PartialEq)]
pub struct LloydResult {
    /// Relaxed sites, in input order.
    pub sites: Vec<[f64; 2]>,
    /// Iterations run.
    pub iterations: u32,
    /// Largest displacement of the last iteration.
    pub max_displacement: f64,
}

/// Moves every site to the centroid of its Voronoi cell clipped to `clip`, repeatedly.
///
/// Sites whose cell misses the region stay where they are; a duplicate stays in place while its
/// representative moves, so the two separate in the next iteration.
///
/// # Errors
/// [`VoronoiError::InvalidTolerance`] for a negative or non-finite tolerance; the errors of
/// [`Voronoi::new`] for the sites (also when `max_iterations` is 0).
pub fn lloyd_relaxation(
    sites: &[[f64; 2]],
    clip: &ClipPolygon,
    options: LloydOptions,
) -> Result<LloydResult, VoronoiError> {
    if !options.tolerance.is_finite() || options.tolerance < 0.0 {
        return Err(VoronoiError::InvalidTolerance(options.tolerance));
    }
    // Checked up front: with no iteration to run, no triangulation would look at them.
    check_sites(sites)?;
    let mut current = sites.to_vec();
    let mut result = LloydResult {
        sites: Vec::new(),
        iterations: 0,
        max_displacement: 0.0,
    };
    while result.iterations < options.max_iterations {
        let cells = Voronoi::new(&current)?.clip(clip);
        let mut moved = 0.0_f64;
        for (s, p) in current.iter_mut().enumerate() {
            if let Some(c) = cells.cell_centroid(SiteId(s as u32))? {
                moved = moved.max((c[0] - p[0]).hypot(c[1] - p[1]));
                *p = c;
            }
        }
        result.iterations += 1;
        result.max_displacement = moved;
        if moved <= options.tolerance {
            break;
        }
    }
    result.sites = current;
    Ok(result)
}
