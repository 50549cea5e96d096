//! Stress test of the Voronoi diagram: random sites at mixed magnitudes (1e-300 to 1e150 in one
//! input), integer grids (cocircular), collinear runs, duplicates, and clusters a few ulps apart
//! far from the origin, clipped to their box, to random rectangles (a few ulps wide now and then)
//! and to regions whose area under- or overflows. Every site's nearest site is itself; clipped
//! cells are counter-clockwise, hold their own site and the grid points nearest to it, and their
//! areas sum to the region's (`check_clipped`).

mod stress;
mod voronoi_common;

use halfwing::voronoi::predicates::orient2d;
use halfwing::voronoi::{ClipPolygon, SiteId, Voronoi};
use proptest::test_runner::TestRng;
use stress::{Rng, choose, run, run_long};
use voronoi_common::{bounding_clip, check_clipped, check_delaunay, check_voronoi};

/// Sites of one of several shapes, then perhaps some of them moved to other magnitudes.
fn random_sites(rng: &mut TestRng) -> Vec<[f64; 2]> {
    let n = rng.random_range(1..80usize);
    let mut sites: Vec<[f64; 2]> = match rng.random_range(0..5) {
        0 => (0..n).map(|_| [rng.random(), rng.random()]).collect(),
        1 => {
            let side = rng.random_range(1..8);
            (0..n)
                .map(|_| {
                    [
                        rng.random_range(0..side) as f64,
                        rng.random_range(0..side) as f64,
                    ]
                })
                .collect()
        }
        2 => {
            let (dx, dy) = (
                rng.random_range(-3..4) as f64,
                rng.random_range(-3..4) as f64,
            );
            (0..n)
                .map(|_| {
                    let t = rng.random_range(-20..20) as f64;
                    [t * dx, t * dy]
                })
                .collect()
        }
        3 => {
            // A cluster a few ulps wide far from the origin.
            let origin = [1e15 + 50.0, rng.random_range(-1e3..1e3)];
            (0..n)
                .map(|_| {
                    origin.map(|c: f64| {
                        let ulps = rng.random_range(-8..8);
                        c + ulps as f64 * c.abs().max(1.0) * f64::EPSILON
                    })
                })
                .collect()
        }
        _ => {
            let sites: Vec<[f64; 2]> = (0..n).map(|_| [rng.random(), rng.random()]).collect();
            (0..n).map(|_| *choose(rng, &sites)).collect()
        }
    };
    if rng.random_bool(0.4) {
        // Mixed magnitudes: a few sites scaled by powers of ten up to 1e±300.
        // Up to 1e±150: circumcentres of flat triangles lie up to 1e16 times farther out and
        // must stay finite for the checks.
        // Each scaled from where it was drawn: a site drawn twice was scaled twice, up to
        // infinity.
        let drawn = sites.clone();
        for _ in 0..rng.random_range(1..4) {
            let k = rng.random_range(0..sites.len());
            let factor = 10f64.powi(rng.random_range(-300..=150));
            sites[k] = drawn[k].map(|x| x * factor);
        }
    }
    sites
}

/// A rectangle around some of the sites: their box, a random part of it, or a box a few ulps
/// wide around one site.
fn random_clip(rng: &mut TestRng, sites: &[[f64; 2]]) -> ClipPolygon {
    match rng.random_range(0..4) {
        0 | 1 => bounding_clip(sites, 0.1),
        2 => {
            let p = *choose(rng, sites);
            let ulps = |rng: &mut TestRng, c: f64| {
                let (mut low, mut high) = (c, c);
                for _ in 0..rng.random_range(1..5) {
                    low = low.next_down();
                }
                for _ in 0..rng.random_range(1..5) {
                    high = high.next_up();
                }
                [low, high]
            };
            let ([x0, x1], [y0, y1]) = (ulps(rng, p[0]), ulps(rng, p[1]));
            ClipPolygon::rectangle([x0, y0], [x1, y1])
                .unwrap_or_else(|e| panic!("box [{x0:e}, {x1:e}] × [{y0:e}, {y1:e}]: {e}"))
        }
        _ => {
            let [a, b] = [*choose(rng, sites), *choose(rng, sites)];
            let min = [a[0].min(b[0]), a[1].min(b[1])];
            let max = [a[0].max(b[0]), a[1].max(b[1])];
            ClipPolygon::rectangle(min, max).unwrap_or_else(|_| bounding_clip(sites, 0.1))
        }
    }
}

fn case(rng: &mut TestRng) {
    let sites = random_sites(rng);
    let diagram = Voronoi::new(&sites).expect("finite sites build");
    let d = diagram.delaunay();
    check_delaunay(d, sites.len() <= 40);
    check_voronoi(&diagram);
    for (i, &p) in sites.iter().enumerate() {
        let nearest = diagram.nearest_site(p, None).unwrap().unwrap();
        assert_eq!(
            nearest,
            SiteId(d.representative()[i]),
            "site {i} at {p:?}: the nearest site is {nearest} at {:?}",
            sites[nearest.index()]
        );
    }
    let clip = random_clip(rng, &sites);
    if clip.area().is_normal() {
        check_clipped(&diagram, &clip);
    } else {
        // The area itself is beyond doubles: the cells still tile the region, with every corner
        // finite and a cell for every distinct site strictly inside (exactly: the floating-point
        // `contains` takes a site 1e-265 beside a side at 1e-169 as on it, in a region 1e161
        // wide).
        let cells = diagram.clip(&clip);
        assert_eq!(cells.n_cells(), sites.len());
        assert!(cells.positions().iter().flatten().all(|x| x.is_finite()));
        for (i, &p) in sites.iter().enumerate() {
            let corners = clip.vertices();
            let m = corners.len();
            let inside = (0..m).all(|k| orient2d(corners[k], corners[(k + 1) % m], p) > 0.0);
            if d.representative()[i] == i as u32 && inside {
                assert!(
                    cells.cell(SiteId(i as u32)).unwrap().len() >= 3,
                    "site {i}: empty cell"
                );
            }
        }
    }
}

#[test]
fn random_diagrams_tile_their_regions() {
    run("voronoi", 1500, case);
}

#[test]
#[ignore = "long run: cargo test --test stress_voronoi -- --ignored"]
fn random_diagrams_tile_their_regions_long() {
    run_long("voronoi", case);
}
