//! Shared helpers of the Voronoi integration tests: point-set readers and exactness checks.
#![allow(dead_code)]

use halfwing::voronoi::predicates::{incircle, orient2d};
use halfwing::voronoi::{
    ClipPolygon, Delaunay, DelaunayHalfedgeId, Dimension, EdgeGeometry, SiteId, Voronoi,
    VoronoiHalfedgeId, VoronoiVertexId, polygon_area_centroid,
};
use std::path::Path;

#[path = "../../benches/common/points.rs"]
mod points;

/// Reads a 2D point file of `data/points2d/` by extension: `.json` (array of `[x, y]`),
/// `.xy` / `.cin` (one point per line, extra columns ignored), `.node` / `.poly` (Triangle's
/// vertex section), `boostpoly_*.txt` (count, then points; segments ignored).
pub fn read_points(path: &Path) -> Vec<[f64; 2]> {
    let text = std::fs::read_to_string(path).expect("readable point file");
    let name = path.file_name().unwrap().to_string_lossy().to_string();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_string())
        .unwrap_or_default();
    let numbers = |line: &str| -> Vec<f64> {
        line.split(|c: char| c.is_whitespace() || c == ',' || c == '[' || c == ']')
            .filter(|t| !t.is_empty())
            .map(|t| {
                t.parse::<f64>()
                    .unwrap_or_else(|_| panic!("{name}: bad number {t:?}"))
            })
            .collect()
    };
    let lines: Vec<&str> = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
        .collect();
    match ext.as_str() {
        "json" => numbers(&text).chunks(2).map(|c| [c[0], c[1]]).collect(),
        "xy" | "cin" => lines
            .iter()
            .map(|l| numbers(l))
            .map(|v| [v[0], v[1]])
            .collect(),
        "node" | "poly" => {
            let header = numbers(lines[0]);
            let count = header[0] as usize;
            assert_eq!(header[1], 2.0, "{name}: two-dimensional");
            lines[1..=count]
                .iter()
                .map(|l| numbers(l))
                .map(|v| [v[1], v[2]])
                .collect()
        }
        "txt" => {
            let count = numbers(lines[0])[0] as usize;
            lines[1..=count]
                .iter()
                .map(|l| numbers(l))
                .map(|v| [v[0], v[1]])
                .collect()
        }
        _ => panic!("{name}: unknown point format"),
    }
}

/// Every triangle counter-clockwise and locally (or, for `against_all`, globally) Delaunay,
/// evaluated with the exact predicates on the input coordinates.
pub fn check_delaunay(d: &Delaunay, against_all: bool) {
    let s = d.sites();
    let tri = d.triangles();
    let unique: Vec<u32> = (0..d.n_sites() as u32)
        .filter(|&i| d.representative()[i as usize] == i)
        .collect();
    for t in 0..d.n_triangles() {
        let [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]].map(|v| s[v as usize]);
        assert!(
            orient2d(a, b, c) > 0.0,
            "triangle {t} not counter-clockwise"
        );
        if against_all {
            for &u in &unique {
                assert!(
                    incircle(a, b, c, s[u as usize]) <= 0.0,
                    "site {u} inside circumcircle of {t}"
                );
            }
        } else {
            for e in (3 * t as u32..3 * t as u32 + 3).map(DelaunayHalfedgeId) {
                let o = d.twin(e);
                if o.is_valid() {
                    assert_eq!(d.twin(o), e);
                    let apex = s[d.origin(d.prev(o)).index()];
                    assert!(
                        incircle(a, b, c, apex) <= 0.0,
                        "edge {e} not locally Delaunay"
                    );
                }
            }
        }
    }
    if d.dimension() == Dimension::Plane {
        assert_eq!(d.n_triangles() + d.hull().len() + 2, 2 * d.n_unique_sites());
    }
    assert_eq!(unique.len(), d.n_unique_sites());
    for (dup, rep) in d.duplicates() {
        assert!(rep < dup);
        assert_eq!(s[dup.index()], s[rep.index()]);
    }
}

/// Every Voronoi vertex equidistant (1e-9 relative) from the sites around it, DCEL links valid,
/// no zero-length edge.
pub fn check_voronoi(v: &Voronoi) {
    let s = v.delaunay().sites();
    for h in (0..v.n_halfedges() as u32).map(VoronoiHalfedgeId) {
        assert_eq!(v.prev(v.next(h)), h);
        assert_eq!(v.site(v.next(h)), v.site(h));
        assert_ne!(v.site(h), v.opposite_site(h));
        if let Some(EdgeGeometry::Segment { from, to }) = v.edge_geometry(h) {
            assert_ne!(from, to, "zero-length edge");
        }
    }
    for k in (0..v.n_vertices() as u32).map(VoronoiVertexId) {
        let p = v.vertices()[k.index()];
        let around = v.vertex_sites(k);
        assert!(around.len() >= 3);
        let dist = |i: SiteId| (p[0] - s[i.index()][0]).hypot(p[1] - s[i.index()][1]);
        let r0 = dist(around[0]);
        // Relative 1e-9, plus the few ulps of the vertex's own coordinates that no floating-point
        // output can beat (sites a few ulps apart have circumcentres that close to them).
        let representable = 8.0 * f64::EPSILON * p[0].abs().max(p[1].abs());
        for &i in &around {
            assert!(
                (dist(i) - r0).abs() <= 1e-9 * r0 + representable,
                "{k} at {p:?} not equidistant: {} vs {r0} ({around:?})",
                dist(i)
            );
        }
    }
}

/// Clipped cells: counter-clockwise, each distinct site inside the region lies in its own cell,
/// areas sum to the region's area (1e-9 relative). Returns the cells' total area.
pub fn check_clipped(v: &Voronoi, clip: &ClipPolygon) -> f64 {
    let cells = v.clip(clip);
    let d = v.delaunay();
    let mut total = 0.0;
    for site in 0..d.n_sites() as u32 {
        let poly = cells.cell_polygon(SiteId(site)).unwrap();
        let area = polygon_area_centroid(&poly).0;
        assert!(area >= 0.0, "cell {site} clockwise");
        total += area;
        let p = d.sites()[site as usize];
        if d.representative()[site as usize] == site && clip.contains(p) {
            assert!(
                poly.len() >= 3,
                "site {site} inside the region has an empty cell"
            );
            let n = poly.len();
            let size = clip.area().sqrt();
            for i in 0..n {
                let o = orient2d(poly[i], poly[(i + 1) % n], p);
                assert!(
                    o >= -1e-9 * size * size,
                    "site {site} at {p:?} outside its own cell {poly:?}"
                );
            }
        }
    }
    check_cells_hold_their_nearest_points(v, &cells, clip);
    if d.n_unique_sites() > 0 {
        let error = (total - clip.area()).abs();
        assert!(
            error <= 1e-9 * clip.area(),
            "areas {total} vs {}",
            clip.area()
        );
    } else {
        assert_eq!(total, 0.0, "no sites, no cells");
    }
    total
}

/// Points of an 8×8 grid across the region's bounding box (those inside it) lie in the cell of
/// their nearest site, with the tolerance of the site test above (a point on a cell's side may
/// go to either neighbour).
pub fn check_cells_hold_their_nearest_points(
    v: &Voronoi,
    cells: &halfwing::voronoi::ClippedCells,
    clip: &ClipPolygon,
) {
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in clip.vertices() {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    let size = clip.area().sqrt();
    for i in 0..8 {
        for j in 0..8 {
            let at = |k: usize, step: usize| min[k] + (max[k] - min[k]) * (step as f64 + 0.5) / 8.0;
            let q = [at(0, i), at(1, j)];
            if !clip.contains(q) {
                continue;
            }
            let Some(owner) = v.nearest_site(q, None).unwrap() else {
                continue;
            };
            let poly = cells.cell_polygon(owner).unwrap();
            let n = poly.len();
            assert!(
                n >= 3,
                "point {q:?} is nearest to {owner}, whose cell is empty"
            );
            for k in 0..n {
                let o = orient2d(poly[k], poly[(k + 1) % n], q);
                assert!(
                    o >= -1e-9 * size * size,
                    "point {q:?} is nearest to {owner} but outside its cell {poly:?}"
                );
            }
        }
    }
}

/// Bounding box of the points, widened by `margin` of its size, and by at least one ulp on
/// every side (a margin rounds away beside coordinates far larger than the box).
pub fn bounding_clip(points: &[[f64; 2]], margin: f64) -> ClipPolygon {
    if points.is_empty() {
        return ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).expect("unit square");
    }
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    let size = (max[0] - min[0]).max(max[1] - min[1]);
    let size = if size > 0.0 { size } else { 1.0 };
    let min = min.map(|c| (c - margin * size).min(c.next_down()));
    let max = max.map(|c| (c + margin * size).max(c.next_up()));
    ClipPolygon::rectangle(min, max).unwrap_or_else(|e| panic!("box {min:?} to {max:?}: {e}"))
}

/// Deterministic uniform points in the unit square (the benchmarks' generator, from a scrambled
/// seed).
pub fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    points::uniform(n, seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
}
