//! Unit tests of the Delaunay triangulation (exactness checks shared with the Voronoi tests).

use super::predicates::incircle;
use super::*;

#[path = "../../benches/common/points.rs"]
mod points;

/// Deterministic pseudo-random points in the unit square (the benchmarks' generator, started one
/// step further along).
pub(crate) fn random_points(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let start = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    points::uniform(n, start)
}

/// Checks the structure and the exact empty-circle property against every site (small inputs)
/// or against the neighbouring triangles' apexes (large inputs, which is equivalent).
pub(crate) fn check_delaunay(d: &Delaunay, against_all: bool) {
    let tri = d.triangles();
    for e in (0..tri.len() as u32).map(DelaunayHalfedgeId) {
        let t = d.twin(e);
        if t.is_valid() {
            assert_eq!(d.twin(t), e);
            assert_eq!(d.origin(t), d.origin(d.next(e)));
            assert_eq!(d.origin(d.next(t)), d.origin(e));
        }
    }
    for t in 0..d.n_triangles() {
        let [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
        assert!(
            d.orient(a, b, c) > 0.0,
            "triangle {t} is not counter-clockwise"
        );
        let (pa, pb, pc) = (d.scaled_point(a), d.scaled_point(b), d.scaled_point(c));
        if against_all {
            for s in 0..d.n_sites() as u32 {
                if d.representative()[s as usize] == s {
                    assert!(
                        incircle(pa, pb, pc, d.scaled_point(s)) <= 0.0,
                        "site {s} inside circle of {t}"
                    );
                }
            }
        } else {
            for e in 3 * t..3 * t + 3 {
                let o = d.twin(DelaunayHalfedgeId(e as u32));
                if o.is_valid() {
                    let apex = d.origin(d.prev(o));
                    assert!(
                        incircle(pa, pb, pc, d.scaled_point(apex.0)) <= 0.0,
                        "edge {e} not locally Delaunay"
                    );
                }
            }
        }
    }
    // Euler: for a triangulated convex region, T = 2n - h - 2 (h counts hull vertices).
    if d.dimension() == Dimension::Plane {
        assert_eq!(d.n_triangles(), 2 * d.n_unique_sites() - d.hull().len() - 2);
        let h = d.hull();
        for i in 0..h.len() {
            let (a, b, c) = (h[i], h[(i + 1) % h.len()], h[(i + 2) % h.len()]);
            assert!(d.orient(a, b, c) >= 0.0, "hull not convex at {b}");
        }
    }
}

#[test]
fn random_points_are_triangulated_exactly() {
    for (n, seed) in [(3, 1), (4, 2), (10, 3), (100, 4), (1000, 5)] {
        let d = Delaunay::new(&random_points(n, seed)).unwrap();
        assert_eq!(d.dimension(), Dimension::Plane);
        check_delaunay(&d, true);
    }
    let d = Delaunay::new(&random_points(50_000, 9)).unwrap();
    check_delaunay(&d, false);
}

#[test]
fn integer_grid_is_triangulated() {
    let pts: Vec<[f64; 2]> = (0..40 * 40)
        .map(|i| [(i % 40) as f64, (i / 40) as f64])
        .collect();
    let d = Delaunay::new(&pts).unwrap();
    check_delaunay(&d, true);
    assert_eq!(d.n_triangles(), 2 * 39 * 39);
}

#[test]
fn duplicates_are_merged_to_smallest_index() {
    let mut pts = random_points(200, 7);
    pts.push(pts[5]);
    pts.push(pts[5]);
    pts.insert(0, pts[10]);
    let d = Delaunay::new(&pts).unwrap();
    check_delaunay(&d, true);
    assert_eq!(d.n_unique_sites(), 200);
    let dups: Vec<(u32, u32)> = d.duplicates().map(|(s, r)| (s.0, r.0)).collect();
    assert_eq!(dups, vec![(11, 0), (201, 6), (202, 6)]);
    assert!(
        d.triangles()
            .iter()
            .all(|&v| d.representative()[v as usize] == v)
    );
}

#[test]
fn tiny_and_collinear_inputs() {
    let d = Delaunay::new(&[]).unwrap();
    assert_eq!(
        (d.dimension(), d.n_triangles(), d.hull().len()),
        (Dimension::Empty, 0, 0)
    );
    let d = Delaunay::new(&[[1.0, 2.0], [1.0, 2.0]]).unwrap();
    assert_eq!((d.dimension(), d.hull()), (Dimension::Point, &[0u32][..]));
    let d = Delaunay::new(&[[3.0, 3.0], [1.0, 1.0], [2.0, 2.0], [1.0, 1.0]]).unwrap();
    assert_eq!(d.dimension(), Dimension::Line);
    assert_eq!(d.hull(), &[1, 2, 0]);
    let s = SiteId;
    assert_eq!(d.edges(), vec![(s(1), s(2)), (s(2), s(0))]);
    assert_eq!(d.duplicates().collect::<Vec<_>>(), vec![(s(3), s(1))]);
}

#[test]
fn non_finite_sites_are_refused() {
    assert!(matches!(
        Delaunay::new(&[[0.0, 0.0], [f64::NAN, 1.0]]),
        Err(VoronoiError::NonFiniteSite {
            site: SiteId(1),
            ..
        })
    ));
    assert!(matches!(
        Delaunay::new(&[[f64::INFINITY, 0.0]]),
        Err(VoronoiError::NonFiniteSite {
            site: SiteId(0),
            ..
        })
    ));
}

#[test]
fn circulation_visits_every_incident_triangle() {
    let d = Delaunay::new(&random_points(500, 11)).unwrap();
    let mut seen = vec![0usize; d.n_sites()];
    for v in (0..d.n_sites() as u32).map(SiteId) {
        for e in d.outgoing(v) {
            assert_eq!(d.origin(e), v);
            seen[v.index()] += 1;
        }
    }
    let mut expected = vec![0usize; d.n_sites()];
    for &v in d.triangles() {
        expected[v as usize] += 1;
    }
    assert_eq!(seen, expected);
}

/// DCEL invariants and the equidistance of every vertex from its sites.
pub(crate) fn check_voronoi(v: &Voronoi) {
    let sites = v.delaunay().sites();
    for h in (0..v.n_halfedges() as u32).map(VoronoiHalfedgeId) {
        assert_eq!(v.prev(v.next(h)), h);
        assert_eq!(v.site(v.next(h)), v.site(h), "next stays in the cell");
        assert_eq!(v.opposite_site(v.twin(h)), v.site(h));
        if v.target(h).is_valid() && v.origin(v.next(h)).is_valid() {
            assert_eq!(v.origin(v.next(h)), v.target(h));
        }
        if let Some(EdgeGeometry::Segment { from, to }) = v.edge_geometry(h) {
            assert_ne!(from, to, "zero-length edge {h}");
        }
    }
    for (k, &p) in v.vertices().iter().enumerate() {
        let around = v.vertex_sites(VoronoiVertexId(k as u32));
        assert!(around.len() >= 3, "vertex {k} has degree {}", around.len());
        let r0 = (p[0] - sites[around[0].index()][0]).hypot(p[1] - sites[around[0].index()][1]);
        for &s in &around {
            let r = (p[0] - sites[s.index()][0]).hypot(p[1] - sites[s.index()][1]);
            assert!(
                (r - r0).abs() <= 1e-9 * r0.max(1e-300),
                "vertex {k}: {r} vs {r0}"
            );
        }
    }
}

/// Clipped cells tile the region and contain their own sites.
pub(crate) fn check_clipped(v: &Voronoi, clip: &ClipPolygon) {
    let cells = v.clip(clip);
    let d = v.delaunay();
    let mut total = 0.0;
    for s in 0..d.n_sites() as u32 {
        let poly = cells.cell_polygon(SiteId(s)).unwrap();
        let area = polygon_area_centroid(&poly).0;
        assert!(area >= 0.0, "cell {s} is clockwise: {area}");
        total += area;
        let p = d.sites()[s as usize];
        if d.representative()[s as usize] == s && clip.contains(p) && poly.len() >= 3 {
            let n = poly.len();
            for i in 0..n {
                let o = predicates::orient2d(poly[i], poly[(i + 1) % n], p);
                let scale = (poly[i][0] - p[0])
                    .abs()
                    .max((poly[i][1] - p[1]).abs())
                    .powi(2);
                assert!(o >= -1e-9 * scale, "site {s} outside its own cell");
            }
        }
    }
    let rel = (total - clip.area()).abs() / clip.area();
    assert!(rel <= 1e-9, "areas sum to {total}, region {}", clip.area());
}

#[test]
fn voronoi_of_random_points_is_consistent_and_tiles_the_clip() {
    for (n, seed) in [(3, 1), (5, 2), (100, 3), (2000, 4)] {
        let v = Voronoi::new(&random_points(n, seed)).unwrap();
        check_voronoi(&v);
        check_clipped(&v, &ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap());
        check_clipped(&v, &ClipPolygon::rectangle([0.2, 0.3], [0.6, 0.5]).unwrap());
        let hexagon: Vec<[f64; 2]> = (0..6)
            .map(|k| {
                let a = k as f64 * std::f64::consts::PI / 3.0;
                [0.5 + 0.7 * a.cos(), 0.5 + 0.7 * a.sin()]
            })
            .collect();
        check_clipped(&v, &ClipPolygon::convex(&hexagon).unwrap());
    }
}

#[test]
fn grid_gives_degree_four_vertices() {
    let pts: Vec<[f64; 2]> = (0..100)
        .map(|i| [(i % 10) as f64, (i / 10) as f64])
        .collect();
    let v = Voronoi::new(&pts).unwrap();
    check_voronoi(&v);
    assert_eq!(v.n_vertices(), 81);
    assert!((0..81).all(|k| v.vertex_sites(VoronoiVertexId(k)).len() == 4));
    check_clipped(
        &v,
        &ClipPolygon::rectangle([-0.5, -0.5], [9.5, 9.5]).unwrap(),
    );
    let cells = v.clip(&ClipPolygon::rectangle([-0.5, -0.5], [9.5, 9.5]).unwrap());
    for s in (0..100).map(SiteId) {
        assert!((cells.cell_area(s).unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(
            cells.cell(s).unwrap().len(),
            4,
            "unit square cells, no extra vertices"
        );
    }
    let s = SiteId;
    assert_eq!(v.neighbours(s(11)).len(), 4);
    let h = v.edge_between(s(11), s(12)).unwrap();
    assert_eq!((v.site(h), v.opposite_site(h)), (s(11), s(12)));
    assert!(
        v.edge_between(s(11), s(22)).is_none(),
        "diagonal neighbours only touch at a vertex"
    );
}

#[test]
fn grid_split_into_parallel_runs_merges_across_their_seams() {
    // 120 × 120 sites: about 28k triangles and 14k cells, so every parallel pass splits them
    // into several runs (`parallel::run_length`, `seamed_run_length`, the latter only when
    // threads share the work), and cocircular squares straddle the seams between the Voronoi
    // vertices' runs.
    let side = 120;
    let pts: Vec<[f64; 2]> = (0..side * side)
        .map(|i| [(i % side) as f64, (i / side) as f64])
        .collect();
    #[cfg(feature = "parallel")]
    let v = {
        let in_pool = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| Voronoi::new(&pts).unwrap())
        };
        let (alone, shared) = (in_pool(1), in_pool(2));
        assert_eq!(alone.vertices(), shared.vertices());
        assert_eq!(alone.triangle_vertex, shared.triangle_vertex);
        shared
    };
    #[cfg(not(feature = "parallel"))]
    let v = Voronoi::new(&pts).unwrap();
    check_voronoi(&v);
    assert_eq!(v.n_vertices(), (side - 1) * (side - 1));
    let clip =
        ClipPolygon::rectangle([-0.5, -0.5], [side as f64 - 0.5, side as f64 - 0.5]).unwrap();
    let cells = v.clip(&clip);
    for s in (0..pts.len() as u32).map(SiteId) {
        assert!((cells.cell_area(s).unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(cells.cell(s).unwrap().len(), 4);
    }
}

#[test]
fn collinear_and_single_site_diagrams_clip_to_slabs() {
    let clip = ClipPolygon::rectangle([-1.0, -1.0], [4.0, 4.0]).unwrap();
    let v = Voronoi::new(&[[0.0, 0.0], [1.0, 1.0], [3.0, 3.0], [2.0, 2.0]]).unwrap();
    check_voronoi(&v);
    check_clipped(&v, &clip);
    assert_eq!(v.neighbours(SiteId(3)), vec![SiteId(1), SiteId(2)]);
    let v = Voronoi::new(&[[0.5, 0.5], [0.5, 0.5]]).unwrap();
    let cells = v.clip(&clip);
    assert_eq!(cells.cell_area(SiteId(0)).unwrap(), 25.0);
    assert!(cells.cell(SiteId(1)).unwrap().is_empty());
}

#[test]
fn sites_outside_the_clip_are_handled() {
    let mut pts = random_points(200, 5);
    pts.extend([[5.0, 5.0], [-3.0, 0.5], [0.5, 1.0000001]]);
    let v = Voronoi::new(&pts).unwrap();
    let clip = ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap();
    check_clipped(&v, &clip);
    let cells = v.clip(&clip);
    assert!(cells.cell(SiteId(200)).unwrap().is_empty());
    // Whole region inside one far cell.
    let v = Voronoi::new(&[[10.0, 10.0], [20.0, 10.0], [10.0, 20.0]]).unwrap();
    let cells = v.clip(&clip);
    assert_eq!(cells.cell(SiteId(0)).unwrap().len(), 4);
    assert_eq!(cells.cell_area(SiteId(0)).unwrap(), 1.0);
}

#[test]
fn soup_export_shares_vertices() {
    let v = Voronoi::new(&random_points(300, 8)).unwrap();
    let cells = v.clip(&ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap());
    let (soup, face_site) = cells.to_polygon_soup();
    assert_eq!(soup.n_faces(), face_site.len());
    // Every interior edge is used twice, in opposite directions; boundary edges once.
    let mut directed = std::collections::HashMap::new();
    let mut at = 0;
    for &size in &soup.face_sizes {
        let f = &soup.indices[at..at + size as usize];
        for i in 0..f.len() {
            *directed.entry((f[i], f[(i + 1) % f.len()])).or_insert(0) += 1;
        }
        at += size as usize;
    }
    for (&(a, b), &count) in &directed {
        assert_eq!(count, 1, "directed edge used twice");
        assert_ne!(a, b);
    }
    let boundary = directed
        .keys()
        .filter(|&&(a, b)| !directed.contains_key(&(b, a)))
        .count();
    assert!((4..200).contains(&boundary));
}

#[test]
fn nearest_site_matches_brute_force() {
    let pts = random_points(1000, 12);
    let d = Delaunay::new(&pts).unwrap();
    for q in random_points(200, 13)
        .into_iter()
        .chain([[-5.0, 3.0], [100.0, -100.0]])
    {
        let best = (0..pts.len())
            .min_by(|&i, &j| {
                let di = (pts[i][0] - q[0]).powi(2) + (pts[i][1] - q[1]).powi(2);
                let dj = (pts[j][0] - q[0]).powi(2) + (pts[j][1] - q[1]).powi(2);
                di.partial_cmp(&dj).unwrap()
            })
            .map(|i| SiteId(i as u32));
        assert_eq!(d.nearest_site(q, None).unwrap(), best);
        assert_eq!(d.nearest_site(q, Some(SiteId(7))).unwrap(), best);
    }
    assert!(d.nearest_site([f64::NAN, 0.0], None).is_err());
    assert_eq!(
        Delaunay::new(&[])
            .unwrap()
            .nearest_site([0.0, 0.0], None)
            .unwrap(),
        None
    );
    // Ties resolve to the smallest index: the centre of a grid square.
    let grid: Vec<[f64; 2]> = (0..16).map(|i| [(i % 4) as f64, (i / 4) as f64]).collect();
    assert_eq!(
        Delaunay::new(&grid)
            .unwrap()
            .nearest_site([1.5, 1.5], Some(SiteId(15)))
            .unwrap(),
        Some(SiteId(5))
    );
}

#[test]
fn lloyd_relaxation_converges_towards_centroidal_cells() {
    let clip = ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap();
    let sites = random_points(100, 17);
    let r = lloyd_relaxation(
        &sites,
        &clip,
        LloydOptions {
            max_iterations: 50,
            tolerance: 1e-4,
        },
    )
    .unwrap();
    assert!(r.iterations >= 2 && r.iterations <= 50);
    let cells = Voronoi::new(&r.sites).unwrap().clip(&clip);
    // Near a fixed point each site sits close to its cell centroid.
    let worst = (0..100u32)
        .map(|s| {
            let c = cells.cell_centroid(SiteId(s)).unwrap().unwrap();
            (c[0] - r.sites[s as usize][0]).hypot(c[1] - r.sites[s as usize][1])
        })
        .fold(0.0, f64::max);
    assert!(
        worst <= r.max_displacement.max(1e-4) * 1.5 + 1e-12,
        "worst {worst}, last move {}",
        r.max_displacement
    );
    for tolerance in [f64::NAN, -1.0, f64::INFINITY] {
        let bad = LloydOptions {
            max_iterations: 1,
            tolerance,
        };
        let error = lloyd_relaxation(&sites, &clip, bad).unwrap_err();
        assert!(
            matches!(error, VoronoiError::InvalidTolerance(_)),
            "{error:?}"
        );
        assert!(error.to_string().starts_with("tolerance"), "{error}");
    }
    // Bad sites are refused even when no iteration would triangulate them.
    let mut with_nan = sites.clone();
    with_nan[3][1] = f64::NAN;
    let none = LloydOptions {
        max_iterations: 0,
        tolerance: 0.0,
    };
    assert!(matches!(
        lloyd_relaxation(&with_nan, &clip, none),
        Err(VoronoiError::NonFiniteSite {
            site: SiteId(3),
            ..
        })
    ));
}

#[test]
fn svg_lists_cells_sites_and_edges() {
    let v = Voronoi::new(&random_points(20, 2)).unwrap();
    let cells = v.clip(&ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).unwrap());
    let svg = to_svg(
        &v,
        &cells,
        &SvgOptions {
            delaunay_edges: true,
            ..SvgOptions::default()
        },
    );
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<polygon").count(), 20);
    assert_eq!(svg.matches("<circle").count(), 20);
    assert_eq!(svg.matches("<line").count(), v.delaunay().edges().len());
}

#[test]
fn a_cell_touching_the_region_along_a_side_far_out_is_empty() {
    // Sites a few ulps apart at 1e15 + 50: the cell of site 27 meets the region only along its
    // right side, in a segment far shorter than an ulp; its crossings, rounded, made a cell of
    // three corners in a line, where it must be empty.
    let sites = [
        [1000000000000050.3, -32.73869297982655],
        [1000000000000048.6, -32.73869297982652],
        [1000000000000049.1, -32.73869297982652],
        [1000000000000050.3, -32.73869297982649],
        [1000000000000049.5, -32.73869297982649],
        [1000000000000048.3, -32.73869297982652],
        [1000000000000050.9, -32.73869297982656],
        [1000000000000048.3, -32.73869297982651],
        [1000000000000049.8, -32.73869297982648],
        [1000000000000048.5, -32.73869297982647],
        [1000000000000051.1, -32.73869297982646],
        [1000000000000048.6, -32.73869297982653],
        [1000000000000049.5, -32.73869297982652],
        [1000000000000051.5, -32.738692979826496],
        [1000000000000049.8, -32.73869297982653],
        [1000000000000050.6, -32.73869297982655],
        [1000000000000050.5, -32.73869297982655],
        [1000000000000050.9, -32.738692979826546],
        [1000000000000051.5, -32.738692979826546],
        [1000000000000050.6, -32.73869297982648],
        [1000000000000051.5, -32.73869297982653],
        [1000000000000048.9, -32.73869297982651],
        [1000000000000048.6, -32.738692979826524],
        [1000000000000050.3, -32.73869297982651],
        [1000000000000049.8, -32.73869297982656],
        [1000000000000050.3, -32.73869297982649],
        [1000000000000050.3, -32.73869297982649],
        [1000000000000051.1, -32.73869297982652],
        [1000000000000050.9, -32.7386929798265],
        [1000000000000048.9, -32.73869297982657],
        [1000000000000050.5, -32.738692979826524],
        [1000000000000050.5, -32.73869297982649],
        [1000000000000049.8, -32.738692979826496],
        [1000000000000050.3, -32.7386929798265],
        [1000000000000050.0, -32.7386929798265],
        [1000000000000051.5, -32.73869297982646],
        [1000000000000050.9, -32.738692979826524],
        [1000000000000050.6, -32.738692979826496],
        [1000000000000048.5, -32.7386929798265],
        [1000000000000048.3, -32.73869297982652],
        [1000000000000049.5, -32.73869297982648],
        [1000000000000050.6, -32.738692979826546],
        [1000000000000051.5, -32.73869297982646],
        [1000000000000049.5, -32.73869297982657],
        [1000000000000049.5, -32.73869297982646],
        [1000000000000048.5, -32.738692979826546],
        [1000000000000048.5, -32.73869297982646],
        [1000000000000051.4, -32.73869297982657],
        [1000000000000049.1, -32.73869297982651],
        [1000000000000048.6, -32.73869297982646],
        [1000000000000049.5, -32.738692979826475],
    ];
    let clip = ClipPolygon::rectangle(
        [1000000000000050.5, -32.738692979826574],
        [1000000000000051.0, -32.738692979826546],
    )
    .unwrap();
    let cells = Voronoi::new(&sites).unwrap().clip(&clip);
    assert!(cells.cell(SiteId(27)).unwrap().is_empty());
    assert!(cells.cell(SiteId(6)).unwrap().len() >= 3);
}
