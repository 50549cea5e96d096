//! halfwing's Delaunay triangulation and full clipped Voronoi diagram side by side with the Rust
//! crates spade (bulk load; `voronoi_faces`) and delaunator, and voronoice (clipped cells), on the
//! inputs of issue 5: 10k, 100k and 1M uniform random sites and the 1000×1000 integer grid.
//!
//! Prints one `RESULT <input> <library> <stage> <milliseconds>` line per measurement (best of
//! several runs) for `bench/run-voronoi-compare.sh`, which adds CGAL's times measured on the same
//! generated inputs and prints the table. Run alone: `cargo bench --bench voronoi_compare
//! [input-filter]`; `VORONOI_COMPARE_LIBRARIES=halfwing,spade` limits the libraries timed.
//!
//! Stages: `delaunay` — the triangulation alone; `voronoi` — every cell as a closed polygon.
//! halfwing and voronoice clip the cells to the unit square (the grid: its bounding box plus half
//! a cell); spade has no clipping, so its time is the triangulation plus a walk of every Voronoi
//! face reading each vertex position (unbounded cells stay open) — less work than clipping.

use std::hint::black_box;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

use halfwing::voronoi::{ClipPolygon, Delaunay, Voronoi};
use spade::{DelaunayTriangulation, Point2, Triangulation};

#[path = "common/points.rs"]
mod points;
use points::uniform;

fn grid(side: usize) -> Vec<[f64; 2]> {
    (0..side * side)
        .map(|i| [(i % side) as f64, (i / side) as f64])
        .collect()
}

/// Runs per measurement for `n_sites` sites (the CGAL side, bench/voronoi/voronoi_cgal.cpp, uses
/// the same rule): the smaller the input, the more a passing stall on a shared machine weighs in
/// one run, so small inputs, quick to repeat, get many runs; the best is kept.
fn runs_for(n_sites: usize) -> usize {
    if n_sites <= 10_000 {
        201
    } else if n_sites <= 100_000 {
        31
    } else {
        3
    }
}

/// The best wall-clock time of `runs` runs of `work`, each given a fresh `input` (made outside
/// the timing, as the crates that take ownership of their input need).
fn best_of<I, R>(runs: usize, input: impl Fn() -> I, work: impl Fn(I) -> R) -> Duration {
    (0..runs)
        .map(|_| {
            let i = input();
            let start = Instant::now();
            let r = work(i);
            let elapsed = start.elapsed();
            drop(black_box(r));
            elapsed
        })
        .min()
        .unwrap_or_default()
}

fn report(input: &str, library: &str, stage: &str, time: Option<Duration>) {
    match time {
        Some(t) => println!(
            "RESULT {input} {library} {stage} {:.1}",
            t.as_secs_f64() * 1e3
        ),
        None => println!("RESULT {input} {library} {stage} failed"),
    }
}

/// Runs a measurement, turning a panic of a third-party crate into a "failed" entry.
fn guarded(measure: impl FnOnce() -> Duration) -> Option<Duration> {
    catch_unwind(AssertUnwindSafe(measure)).ok()
}

/// spade's Voronoi cells: every face's edges, reading each finite vertex (a circumcentre).
fn walk_spade_faces(t: &DelaunayTriangulation<Point2<f64>>) -> f64 {
    let mut sum = 0.0;
    for face in t.voronoi_faces() {
        for edge in face.adjacent_edges() {
            if let Some(p) = edge.from().position() {
                sum += p.x + p.y;
            }
        }
    }
    sum
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument selects inputs by name.
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    let libraries = std::env::var("VORONOI_COMPARE_LIBRARIES").ok();
    let wanted = |library: &str| {
        libraries
            .as_ref()
            .is_none_or(|list| list.split(',').any(|l| l == library))
    };
    let unit = ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).expect("unit square");
    let mut inputs: Vec<(String, Vec<[f64; 2]>, ClipPolygon, usize)> = [10_000, 100_000, 1_000_000]
        .iter()
        .map(|&n| {
            (
                format!("uniform_{n}"),
                uniform(n, 42),
                unit.clone(),
                runs_for(n),
            )
        })
        .collect();
    let grid_box = ClipPolygon::rectangle([-0.5, -0.5], [999.5, 999.5]).expect("grid box");
    let grid_sites = grid(1000);
    let grid_runs = runs_for(grid_sites.len());
    inputs.push(("grid_1000x1000".into(), grid_sites, grid_box, grid_runs));

    for (name, sites, clip, runs) in &inputs {
        if filter.as_ref().is_some_and(|f| !name.contains(f.as_str())) {
            continue;
        }
        let runs = *runs;
        let spade_points =
            || -> Vec<Point2<f64>> { sites.iter().map(|p| Point2::new(p[0], p[1])).collect() };
        let delaunator_points: Vec<delaunator::Point> = sites
            .iter()
            .map(|p| delaunator::Point { x: p[0], y: p[1] })
            .collect();
        let voronoice_points = || -> Vec<voronoice::Point> {
            sites
                .iter()
                .map(|p| voronoice::Point { x: p[0], y: p[1] })
                .collect()
        };
        let region = clip.vertices();
        let (min, max) = (region[0], region[2]);
        let centre = voronoice::Point {
            x: 0.5 * (min[0] + max[0]),
            y: 0.5 * (min[1] + max[1]),
        };
        let bounding_box = voronoice::BoundingBox::new(centre, max[0] - min[0], max[1] - min[1]);

        if wanted("halfwing") {
            let time = guarded(|| best_of(runs, || (), |()| Delaunay::new(sites).expect("finite")));
            report(name, "halfwing", "delaunay", time);
            let time = guarded(|| {
                best_of(
                    runs,
                    || (),
                    |()| Voronoi::new(sites).expect("finite").clip(clip),
                )
            });
            report(name, "halfwing", "voronoi", time);
        }
        if wanted("spade") {
            let time = guarded(|| {
                best_of(runs, spade_points, |p| {
                    DelaunayTriangulation::<Point2<f64>>::bulk_load(p).expect("finite")
                })
            });
            report(name, "spade", "delaunay", time);
            let time = guarded(|| {
                best_of(runs, spade_points, |p| {
                    let t = DelaunayTriangulation::<Point2<f64>>::bulk_load(p).expect("finite");
                    walk_spade_faces(&t)
                })
            });
            report(name, "spade", "voronoi", time);
        }
        if wanted("delaunator") {
            let time = guarded(|| {
                best_of(
                    runs,
                    || (),
                    |()| delaunator::triangulate(&delaunator_points),
                )
            });
            report(name, "delaunator", "delaunay", time);
        }
        if wanted("voronoice") {
            let time = guarded(|| {
                best_of(runs, voronoice_points, |p| {
                    voronoice::VoronoiBuilder::default()
                        .set_sites(p)
                        .set_bounding_box(bounding_box.clone())
                        .build()
                        .expect("voronoice builds")
                })
            });
            report(name, "voronoice", "voronoi", time);
        }
    }
}
