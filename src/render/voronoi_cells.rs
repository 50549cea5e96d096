//! A Voronoi diagram's clipped cells as render buffers: each cell a filled polygon with its
//! outline, indexed by site (so a cell's colour can follow its site). The cells share their
//! vertices in [`ClippedCells`]; here each gets its own copies, which per-cell colours need.

use crate::voronoi::ClippedCells;

use super::PolygonBuffer;
use super::error::RenderError;
use super::polygon_buffer::{PolygonList, build_polygon_buffer, lift_to_plane};

/// Fills and outlines of every cell, polygon `i` being the cell of site `i` (empty for duplicate
/// sites and sites whose cell misses the clip region: no triangle, no outline).
///
/// # Errors
/// [`RenderError::Polygons`] only if the cells would need more than `u32` indices.
pub fn voronoi_cell_buffer(cells: &ClippedCells) -> Result<PolygonBuffer, RenderError> {
    let positions = cells.positions();
    let indices = cells.indices();
    let mut corners = Vec::with_capacity(indices.len());
    let mut sizes = Vec::with_capacity(cells.n_cells());
    for &[start, length] in cells.cell_ranges() {
        let ring = &indices[start as usize..(start + length) as usize];
        corners.extend(ring.iter().map(|&p| positions[p as usize]));
        sizes.push(length);
    }
    // Unchecked: an empty cell stays an empty polygon, so polygon `i` is still site `i`.
    build_polygon_buffer(&PolygonList {
        corners: &lift_to_plane(&corners),
        sizes: &sizes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::voronoi::{ClipPolygon, Voronoi};

    fn triangle_area(p: &[f32], t: &[u32]) -> f32 {
        let at = |k: usize| [p[3 * t[k] as usize], p[3 * t[k] as usize + 1]];
        let (a, b, c) = (at(0), at(1), at(2));
        0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    }

    #[test]
    fn cells_tile_the_clip_rectangle_and_follow_their_sites() {
        // Four sites, one per quadrant of [-2, 2]²; the fifth duplicates the first.
        let sites = [
            [-1.0, -1.0],
            [1.0, -1.0],
            [1.0, 1.0],
            [-1.0, 1.0],
            [-1.0, -1.0],
        ];
        let cells = Voronoi::new(&sites)
            .unwrap()
            .clip(&ClipPolygon::rectangle([-2.0, -2.0], [2.0, 2.0]).unwrap());
        let buffer = voronoi_cell_buffer(&cells).unwrap();

        // Every triangle counter-clockwise; together they cover the 4 x 4 square once.
        let mut total = 0.0;
        let mut per_site = [0.0f32; 5];
        for (t, &site) in buffer
            .triangles
            .chunks_exact(3)
            .zip(&buffer.triangle_polygons)
        {
            let area = triangle_area(&buffer.positions, t);
            assert!(area > 0.0);
            total += area;
            per_site[site as usize] += area;
        }
        assert!((total - 16.0).abs() < 1e-5);
        // Each quadrant cell has area 4 and its corners' mean in its site's quadrant; the
        // duplicate's cell is empty.
        for (site, &[x, y]) in sites.iter().enumerate().take(4) {
            assert!((per_site[site] - 4.0).abs() < 1e-5, "{per_site:?}");
            let corners: Vec<usize> = (0..buffer.vertex_polygons.len())
                .filter(|&c| buffer.vertex_polygons[c] == site as u32)
                .collect();
            let mean = |axis: usize| {
                corners
                    .iter()
                    .map(|&c| buffer.positions[3 * c + axis])
                    .sum::<f32>()
                    / corners.len() as f32
            };
            assert!(mean(0) * x as f32 > 0.0 && mean(1) * y as f32 > 0.0);
        }
        assert_eq!(per_site[4], 0.0);
        assert!(!buffer.outline.sources.contains(&4));
        // Quadrant cells are squares: four sides each.
        assert_eq!(buffer.outline.n_segments(), 16);
    }
}
