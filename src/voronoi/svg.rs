//! SVG pictures of clipped Voronoi diagrams.

use super::clipped::ClippedCells;
use super::diagram::Voronoi;
use super::ids::SiteId;
use std::fmt::Write;

/// What to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvgOptions {
    /// Output width in pixels (height follows the clip region's aspect ratio).
    pub width_px: f64,
    /// Fill cells with distinct pastel colours (otherwise outline only).
    pub fill_cells: bool,
    /// Draw the sites as dots.
    pub sites: bool,
    /// Draw the Delaunay edges.
    pub delaunay_edges: bool,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions {
            width_px: 800.0,
            fill_cells: true,
            sites: true,
            delaunay_edges: false,
        }
    }
}

/// An SVG document of the clipped cells of `voronoi` (y axis pointing up, as in the plane).
pub fn to_svg(voronoi: &Voronoi, cells: &ClippedCells, options: &SvgOptions) -> String {
    let region = cells.clip_region().vertices();
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in region {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    let (w, h) = (max[0] - min[0], max[1] - min[1]);
    let px = options.width_px / w;
    let height_px = h * px;
    // Map plane coordinates to pixels directly (no SVG transform, so strokes keep their width).
    let map = |p: [f64; 2]| ((p[0] - min[0]) * px, (max[1] - p[1]) * px);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{:.0}" height="{:.0}" viewBox="0 0 {} {}">"#,
        options.width_px, height_px, options.width_px, height_px
    );
    let n_sites = cells.n_cells();
    for s in 0..n_sites as u32 {
        let Ok(cell) = cells.cell(SiteId(s)) else {
            continue;
        };
        if cell.len() < 3 {
            continue;
        }
        let points: Vec<String> = cell
            .iter()
            .map(|&i| {
                let (x, y) = map(cells.positions()[i as usize]);
                format!("{x:.3},{y:.3}")
            })
            .collect();
        let fill = if options.fill_cells {
            // Golden-angle hues spread neighbouring indices apart.
            format!("hsl({:.0},70%,85%)", (s as f64 * 137.507_764) % 360.0)
        } else {
            "none".to_string()
        };
        let _ = writeln!(
            out,
            r#"<polygon points="{}" fill="{fill}" stroke="black" stroke-width="0.6"/>"#,
            points.join(" ")
        );
    }
    if options.delaunay_edges {
        let sites = voronoi.delaunay().sites();
        for (a, b) in voronoi.delaunay().edges() {
            let ((x1, y1), (x2, y2)) = (map(sites[a.index()]), map(sites[b.index()]));
            let _ = writeln!(
                out,
                r#"<line x1="{x1:.3}" y1="{y1:.3}" x2="{x2:.3}" y2="{y2:.3}" stroke="steelblue" stroke-width="0.5"/>"#
            );
        }
    }
    if options.sites {
        let d = voronoi.delaunay();
        for (s, &p) in d.sites().iter().enumerate() {
            if d.representative()[s] as usize == s {
                let (x, y) = map(p);
                let _ = writeln!(
                    out,
                    r#"<circle cx="{x:.3}" cy="{y:.3}" r="1.5" fill="black"/>"#
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}
