//! Raster label images of Voronoi diagrams under the Euclidean, Manhattan and Chebyshev metrics.
//!
//! Each pixel gets the index of its nearest site, decided exactly (ties to the smallest index),
//! for the pixel centre as computed in floating point. Candidates come from a uniform bucket grid
//! searched in square rings around the pixel: after ring `r`, every unvisited site is at least
//! `r` cell widths away in L∞ — a lower bound for all three metrics — so the search stops as soon
//! as the best distance is below it.

use super::delaunay::{Delaunay, INVALID};
use super::error::VoronoiError;
use super::exact_distance::Metric;
use std::cmp::Ordering;

use crate::support::allocation::try_filled;

/// A `width × height` image of site indices, row-major, row 0 at the top (largest y).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LabelImage {
    /// Pixels per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Site index of every pixel ([`INVALID`] when there are no sites).
    pub labels: Vec<u32>,
}

/// Uniform grid of the distinct sites.
struct BucketGrid<'a> {
    points: &'a [[f64; 2]],
    origin: [f64; 2],
    cell: f64,
    dims: [usize; 2],
    start: Vec<u32>,
    sites: Vec<u32>,
}

impl<'a> BucketGrid<'a> {
    fn new(points: &'a [[f64; 2]], sites: &[u32]) -> Self {
        let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for &s in sites {
            let p = points[s as usize];
            for k in 0..2 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let extent = (max[0] - min[0]).max(max[1] - min[1]);
        let per_axis = ((sites.len() as f64).sqrt().ceil() as usize).max(1);
        let cell = if extent > 0.0 {
            extent / per_axis as f64
        } else {
            1.0
        };
        let dims = [0, 1].map(|k| (((max[k] - min[k]) / cell) as usize + 1).min(per_axis + 1));
        let mut grid = BucketGrid {
            points,
            origin: min,
            cell,
            dims,
            start: vec![0; dims[0] * dims[1] + 1],
            sites: Vec::new(),
        };
        for &s in sites {
            let c = grid.cell_index(grid.cell_of(points[s as usize]));
            grid.start[c + 1] += 1;
        }
        for i in 1..grid.start.len() {
            grid.start[i] += grid.start[i - 1];
        }
        let mut fill = grid.start.clone();
        grid.sites = vec![0; sites.len()];
        for &s in sites {
            let c = grid.cell_index(grid.cell_of(points[s as usize]));
            grid.sites[fill[c] as usize] = s;
            fill[c] += 1;
        }
        grid
    }

    fn cell_of(&self, p: [f64; 2]) -> [usize; 2] {
        [0, 1].map(|k| {
            let c = ((p[k] - self.origin[k]) / self.cell).floor();
            if c.is_nan() || c < 0.0 {
                0
            } else {
                (c as usize).min(self.dims[k] - 1)
            }
        })
    }

    fn cell_index(&self, c: [usize; 2]) -> usize {
        c[1] * self.dims[0] + c[0]
    }

    /// Exact nearest site of `q` under `metric`, ties to the smallest index.
    fn nearest(&self, q: [f64; 2], metric: Metric) -> u32 {
        let c = self.cell_of(q);
        let mut best = INVALID;
        let max_ring = self.dims[0].max(self.dims[1]);
        for r in 0..=max_ring {
            let (x0, x1) = (c[0].saturating_sub(r), (c[0] + r).min(self.dims[0] - 1));
            let (y0, y1) = (c[1].saturating_sub(r), (c[1] + r).min(self.dims[1] - 1));
            for y in y0..=y1 {
                let on_edge_row = y + r == c[1] || y == c[1] + r;
                let mut x = x0;
                while x <= x1 {
                    if on_edge_row || x + r == c[0] || x == c[0] + r {
                        let ci = self.cell_index([x, y]);
                        for &s in &self.sites[self.start[ci] as usize..self.start[ci + 1] as usize]
                        {
                            best = self.better(q, metric, s, best);
                        }
                        x += 1;
                    } else {
                        // Interior of the ring's row: jump to its right edge.
                        x = c[0] + r;
                    }
                }
            }
            if best != INVALID {
                let reach = r as f64 * self.cell;
                let bound = if metric == Metric::Euclidean {
                    reach * reach
                } else {
                    reach
                };
                if metric.approx(q, self.points[best as usize]) < bound * (1.0 - 1e-9) {
                    break;
                }
            }
        }
        best
    }

    #[inline]
    fn better(&self, q: [f64; 2], metric: Metric, s: u32, best: u32) -> u32 {
        if best == INVALID {
            return s;
        }
        match metric.compare(q, self.points[s as usize], self.points[best as usize]) {
            Ordering::Less => s,
            Ordering::Equal if s < best => s,
            _ => best,
        }
    }
}

impl Delaunay {
    /// Labels every pixel of the rectangle `[min, max]` sampled at `width × height` pixel centres
    /// with its nearest site under `metric` (see the module documentation).
    pub fn label_image(
        &self,
        metric: Metric,
        min: [f64; 2],
        max: [f64; 2],
        width: u32,
        height: u32,
    ) -> Result<LabelImage, VoronoiError> {
        let pixels = (width as usize).checked_mul(height as usize);
        if width == 0 || height == 0 || pixels.is_none_or(|p| p > isize::MAX as usize / 4) {
            return Err(VoronoiError::InvalidRasterSize { width, height });
        }
        if !(min.iter().chain(&max).all(|c| c.is_finite())) {
            return Err(VoronoiError::NonFiniteQuery);
        }
        let mut labels = try_filled(pixels.unwrap_or(0), INVALID, "pixels")?;
        let unique: Vec<u32> = (0..self.n_sites() as u32)
            .filter(|&s| self.representative[s as usize] == s)
            .collect();
        let scale = self.scale;
        let scaled_ok = [min, max]
            .iter()
            .all(|p| (p[0] * scale).is_finite() && (p[1] * scale).is_finite());
        let (frame, scale) = if scaled_ok {
            (self.scaled(), scale)
        } else {
            (&self.sites[..], 1.0)
        };
        let grid = BucketGrid::new(frame, &unique);
        let (dx, dy) = (
            (max[0] - min[0]) / width as f64,
            (max[1] - min[1]) / height as f64,
        );
        let row = |j: usize, out: &mut [u32]| {
            let y = max[1] - (j as f64 + 0.5) * dy;
            for (i, label) in out.iter_mut().enumerate() {
                let x = min[0] + (i as f64 + 0.5) * dx;
                *label = if unique.is_empty() {
                    INVALID
                } else {
                    grid.nearest([x * scale, y * scale], metric)
                };
            }
        };
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            labels
                .par_chunks_mut(width as usize)
                .enumerate()
                .for_each(|(j, out)| row(j, out));
        }
        #[cfg(not(feature = "parallel"))]
        labels
            .chunks_mut(width as usize)
            .enumerate()
            .for_each(|(j, out)| row(j, out));
        Ok(LabelImage {
            width,
            height,
            labels,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::voronoi::SiteId;
    use crate::voronoi::tests::random_points;

    #[test]
    fn labels_match_brute_force_in_every_metric() {
        let mut sites = random_points(300, 21);
        sites.extend((0..30).map(|i| [(i % 6) as f64 / 5.0, (i / 6) as f64 / 5.0])); // ties galore
        let d = Delaunay::new(&sites).unwrap();
        for metric in [Metric::Euclidean, Metric::Manhattan, Metric::Chebyshev] {
            let img = d
                .label_image(metric, [-0.2, -0.1], [1.1, 1.3], 64, 48)
                .unwrap();
            for j in 0..48 {
                for i in 0..64 {
                    let q = [
                        -0.2 + (i as f64 + 0.5) * (1.3 / 64.0),
                        1.3 - (j as f64 + 0.5) * (1.4 / 48.0),
                    ];
                    let q = [q[0] * d.scale, q[1] * d.scale];
                    let mut best = INVALID;
                    for s in 0..sites.len() as u32 {
                        if d.representative()[s as usize] != s {
                            continue;
                        }
                        let better = best == INVALID
                            || match metric.compare(
                                q,
                                d.scaled()[s as usize],
                                d.scaled()[best as usize],
                            ) {
                                Ordering::Less => true,
                                Ordering::Equal => s < best,
                                Ordering::Greater => false,
                            };
                        if better {
                            best = s;
                        }
                    }
                    assert_eq!(img.labels[j * 64 + i], best, "{metric:?} pixel ({i}, {j})");
                }
            }
        }
    }

    #[test]
    fn euclidean_labels_agree_with_nearest_site_query() {
        let d = Delaunay::new(&random_points(500, 3)).unwrap();
        let img = d
            .label_image(Metric::Euclidean, [0.0, 0.0], [1.0, 1.0], 40, 40)
            .unwrap();
        for j in 0..40 {
            for i in 0..40 {
                let q = [(i as f64 + 0.5) / 40.0, 1.0 - (j as f64 + 0.5) / 40.0];
                assert_eq!(
                    Some(SiteId(img.labels[j * 40 + i])),
                    d.nearest_site(q, None).unwrap()
                );
            }
        }
    }

    #[test]
    fn bad_raster_arguments_are_refused() {
        let d = Delaunay::new(&random_points(10, 3)).unwrap();
        assert!(
            d.label_image(Metric::Manhattan, [0.0, 0.0], [1.0, 1.0], 0, 5)
                .is_err()
        );
        assert!(
            d.label_image(Metric::Manhattan, [0.0, f64::NAN], [1.0, 1.0], 5, 5)
                .is_err()
        );
        let empty = Delaunay::new(&[]).unwrap();
        let img = empty
            .label_image(Metric::Chebyshev, [0.0, 0.0], [1.0, 1.0], 2, 2)
            .unwrap();
        assert!(img.labels.iter().all(|&l| l == INVALID));
    }
}
