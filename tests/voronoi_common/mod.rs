//! Shared helpers of the Voronoi integration tests: point-set readers and exactness checks.
#![allow(dead_code)]

use halfwing::voronoi::predicates::{incircle, orient2d};
use halfwing::voronoi::{
    ClipPolygon, Delaunay, DelaunayHalfedgeId, Dimension, EdgeGeometry, Metric, SiteId, Voronoi,
    VoronoiHalfedgeId, VoronoiVertexId, polygon_area_centroid,
};
use std::cmp::Ordering;
use std::path::Path;

mod exact_cells;
use exact_cells::ExactPlane;

#[path = "../../benches/common/points.rs"]
mod points;

/// Reads a 2D point file of `data/points2d/` with the library's reader (the format by the
/// extension).
pub fn read_points(path: &Path) -> Vec<[f64; 2]> {
    halfwing::io::read_points2d(path).unwrap_or_else(|e| panic!("{e}"))
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
        if !(p[0].is_finite() && p[1].is_finite()) {
            assert_centre_beyond_doubles(k, p, around[..3].iter().map(|i| s[i.index()]));
            continue;
        }
        // Near the top of the range of doubles the distances themselves overflow (a vertex at
        // 1.6e308): they are compared halved there, which is exact short of subnormals.
        let halve = s
            .iter()
            .any(|q| (p[0] - q[0]).hypot(p[1] - q[1]).is_infinite());
        let factor = if halve { 0.5 } else { 1.0 };
        let dist = |i: SiteId| {
            let q = s[i.index()];
            (factor * p[0] - factor * q[0]).hypot(factor * p[1] - factor * q[1])
        };
        let r0 = dist(around[0]);
        // Relative 1e-9, plus the few ulps of the vertex's own coordinates that no floating-point
        // output can beat (sites a few ulps apart have circumcentres that close to them).
        let representable = 8.0 * f64::EPSILON * factor * p[0].abs().max(p[1].abs());
        for &i in &around {
            assert!(
                (dist(i) - r0).abs() <= 1e-9 * r0 + representable,
                "{k} at {p:?} not equidistant: {} vs {r0} ({around:?})",
                dist(i)
            );
        }
    }
}

/// A vertex with an infinite coordinate is a circumcentre beyond the range of doubles: no NaN,
/// and the circumradius of three of its sites, `|ab|·|bc|·|ca| / 2|orient2d(a, b, c)|` taken in
/// logarithms, past `f64::MAX`.
fn assert_centre_beyond_doubles(
    k: VoronoiVertexId,
    p: [f64; 2],
    mut corners: impl Iterator<Item = [f64; 2]>,
) {
    assert!(!p[0].is_nan() && !p[1].is_nan(), "{k} at {p:?}");
    let [a, b, c] = [(); 3].map(|_| corners.next().unwrap());
    // Halved coordinates: no difference of finite values overflows.
    let log_length = |p: [f64; 2], q: [f64; 2]| {
        (0.5 * p[0] - 0.5 * q[0])
            .hypot(0.5 * p[1] - 0.5 * q[1])
            .log2()
            + 1.0
    };
    let log_orientation = ExactPlane::new(&[a, b, c], &[]).log2_orientation([0, 1, 2]);
    let log_radius =
        log_length(a, b) + log_length(b, c) + log_length(c, a) - (1.0 + log_orientation);
    assert!(
        log_radius > f64::MAX.log2(),
        "{k} at {p:?}: circumradius 2^{log_radius} is within the range of doubles"
    );
}

/// Clipped cells: counter-clockwise (or, narrower than the rounding of their corners, of area
/// within it: see [`rounding_of_twice_area`]); a cell for exactly the distinct sites whose part of the
/// region has an interior, decided exactly (`exact_cells`), so a sliver far narrower than an ulp
/// must be there and a cell meeting the region only along its boundary must not; each distinct
/// site in the region (exact test) lies in its own cell; areas sum to the region's area (1e-9
/// relative). Returns the cells' total area.
pub fn check_clipped(v: &Voronoi, clip: &ClipPolygon) -> f64 {
    let cells = v.clip(clip);
    let d = v.delaunay();
    let corners = clip.vertices();
    let exact = ExactPlane::new(d.sites(), corners);
    let neighbours = delaunay_neighbours(d);
    let mut total = 0.0;
    for site in 0..d.n_sites() as u32 {
        let poly = cells.cell_polygon(SiteId(site)).unwrap();
        let area = polygon_area_centroid(&poly).0;
        assert!(
            area >= 0.0 || 2.0 * -area <= rounding_of_twice_area(&poly),
            "cell {site} clockwise beyond the rounding of its corners: area {area:e}, {poly:?}"
        );
        total += area;
        let p = d.sites()[site as usize];
        if d.representative()[site as usize] != site {
            assert!(poly.is_empty(), "duplicate site {site} has a cell");
            continue;
        }
        let has_interior = exact.cell_has_interior(site as usize, neighbours(site));
        assert_eq!(
            !poly.is_empty(),
            has_interior,
            "site {site} at {p:?}: its part of the region has an interior: {has_interior}, \
             its cell {poly:?}"
        );
        let m = corners.len();
        let inside = (0..m).all(|i| orient2d(corners[i], corners[(i + 1) % m], p) >= 0.0);
        // By winding number within the rounding of the corners (see `holds`): a cell whose
        // sides meet between two doubles can come out with a reflex corner an ulp deep, and
        // the extension of a side there passes beside its own site.
        if inside {
            assert!(
                holds(&poly, p, clip.area().sqrt()),
                "site {site} at {p:?} outside its own cell {poly:?}"
            );
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

/// How far rounding a polygon's corners to doubles can move twice its signed area:
/// `4 n ε · X · D` for `n` corners whose largest coordinate magnitude is `X` and largest offset
/// from the first corner is `D` (the bound `ClippedCells` documents for a cell narrower than
/// the rounding of its corners, which may come out clockwise).
fn rounding_of_twice_area(poly: &[[f64; 2]]) -> f64 {
    let Some(&first) = poly.first() else {
        return 0.0;
    };
    let largest = poly.iter().flatten().fold(0.0_f64, |m, c| m.max(c.abs()));
    let offset = poly
        .iter()
        .flat_map(|p| [p[0] - first[0], p[1] - first[1]])
        .fold(0.0_f64, |m, d| m.max(d.abs()));
    4.0 * poly.len() as f64 * f64::EPSILON * largest * offset
}

/// The sites that decide each distinct site's cell: its Delaunay neighbours, or every other
/// distinct site when there are no triangles (collinear sites).
fn delaunay_neighbours(d: &Delaunay) -> impl Fn(u32) -> Vec<usize> + '_ {
    let mut lists = vec![Vec::new(); d.n_sites()];
    for t in d.triangles().chunks_exact(3) {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            lists[a].push(b);
            lists[b].push(a);
        }
    }
    let planar = d.dimension() == Dimension::Plane;
    move |site| {
        if planar {
            lists[site as usize].clone()
        } else {
            (0..d.n_sites())
                .filter(|&s| s != site as usize && d.representative()[s] == s as u32)
                .collect()
        }
    }
}

/// Points of an 8×8 grid across the region's bounding box (those inside it) lie in the cell of
/// their nearest site, with the tolerance of the site test above (a point on a cell's side may
/// go to either neighbour). A cell that meets the region only along its boundary is empty (see
/// `ClippedCells`): a point there nearest to its site must be exactly as near to another site
/// whose cell holds it.
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
            if poly.is_empty() {
                let sites = v.delaunay().sites();
                let tied_holder = (0..sites.len() as u32).map(SiteId).find(|&s| {
                    let ordering =
                        Metric::Euclidean.compare(q, sites[s.index()], sites[owner.index()]);
                    s != owner
                        && ordering == Ordering::Equal
                        && holds(&cells.cell_polygon(s).unwrap(), q, size)
                });
                assert!(
                    tied_holder.is_some(),
                    "point {q:?} is nearest to {owner}, whose cell is empty"
                );
                continue;
            }
            assert!(
                holds(&poly, q, size),
                "point {q:?} is nearest to {owner} but outside its cell {poly:?}"
            );
        }
    }
}

/// Whether the cell `poly` holds `q`, or `q` lies on the cell's boundary within 1e-9 of the
/// region's `size` and four ulps of its own coordinates (the rounding of the cell's corners).
/// By winding number, not by the sides' half-planes: rounding can leave a corner of a cell
/// turning clockwise by an ulp (two ends of a nearly vertical side rounded to either side of
/// it), and the extension of a side there passes beside points of the cell.
fn holds(poly: &[[f64; 2]], q: [f64; 2], size: f64) -> bool {
    let n = poly.len();
    if n < 3 {
        return false;
    }
    let tolerance = q.map(|c| 1e-9 * size + 4.0 * (c.abs().next_up() - c.abs()));
    let mut winding = 0i32;
    for k in 0..n {
        let (a, b) = (poly[k], poly[(k + 1) % n]);
        let within_box = (0..2).all(|i| {
            q[i] >= a[i].min(b[i]) - tolerance[i] && q[i] <= a[i].max(b[i]) + tolerance[i]
        });
        // |orient| is the side's length times q's distance from its line: within the tolerance
        // across each axis, weighted by how far the side runs along the other.
        let slack = tolerance[0] * (b[1] - a[1]).abs() + tolerance[1] * (b[0] - a[0]).abs();
        if within_box && orient2d(a, b, q).abs() <= slack {
            return true;
        }
        if a[1] <= q[1] {
            if b[1] > q[1] && orient2d(a, b, q) > 0.0 {
                winding += 1;
            }
        } else if b[1] <= q[1] && orient2d(a, b, q) < 0.0 {
            winding -= 1;
        }
    }
    winding != 0
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
