//! Delaunay and clipped-Voronoi construction times on 10k, 100k and 1M uniform random sites and
//! on the 1000×1000 integer grid (the inputs of issue 5's benchmark table).
//!
//! Run: `cargo bench --bench voronoi` (`-- voronoi_clip/` for the clipping alone). The triangulation is single-threaded; the Voronoi dual and
//! the clipping run their per-element passes on rayon's pool (the `parallel` feature).

use criterion::{BatchSize, BenchmarkId, Criterion, criterion_group, criterion_main};
use halfwing::voronoi::{ClipPolygon, Delaunay, Voronoi};
use std::hint::black_box;

#[path = "common/points.rs"]
mod points;
use points::uniform;

fn grid(side: usize) -> Vec<[f64; 2]> {
    (0..side * side)
        .map(|i| [(i % side) as f64, (i / side) as f64])
        .collect()
}

fn inputs() -> Vec<(String, Vec<[f64; 2]>, ClipPolygon)> {
    let unit = ClipPolygon::rectangle([0.0, 0.0], [1.0, 1.0]).expect("unit square");
    let mut v: Vec<_> = [10_000, 100_000, 1_000_000]
        .iter()
        .map(|&n| (format!("uniform_{n}"), uniform(n, 42), unit.clone()))
        .collect();
    let grid_clip = ClipPolygon::rectangle([-0.5, -0.5], [999.5, 999.5]).expect("grid box");
    v.push(("grid_1000x1000".to_string(), grid(1000), grid_clip));
    v
}

fn bench(c: &mut Criterion) {
    let inputs = inputs();
    let mut group = c.benchmark_group("delaunay");
    group.sample_size(10);
    for (name, sites, _) in &inputs {
        group.bench_with_input(BenchmarkId::from_parameter(name), sites, |b, s| {
            b.iter(|| black_box(Delaunay::new(black_box(s)).expect("finite sites")))
        });
    }
    group.finish();
    let mut group = c.benchmark_group("clipped_voronoi");
    group.sample_size(10);
    for (name, sites, clip) in &inputs {
        group.bench_with_input(BenchmarkId::from_parameter(name), sites, |b, s| {
            b.iter(|| {
                let v = Voronoi::new(black_box(s)).expect("finite sites");
                black_box(v.clip(clip))
            })
        });
    }
    group.finish();
    // The dual and the clipping alone, from a finished triangulation (not in the table,
    // but it separates the two costs).
    let mut group = c.benchmark_group("voronoi_clip_only");
    group.sample_size(10);
    for (name, sites, clip) in &inputs {
        group.bench_with_input(BenchmarkId::from_parameter(name), sites, |b, s| {
            b.iter_batched(
                || Delaunay::new(s).expect("finite sites"),
                |d| black_box(Voronoi::from_delaunay(d).clip(clip)),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
    // The clipping alone, from a finished diagram: 100k and 1M sites in their box.
    let mut group = c.benchmark_group("voronoi_clip");
    group.sample_size(10);
    for (name, sites, clip) in inputs.iter().filter(|(_, s, _)| s.len() >= 100_000) {
        let diagram = Voronoi::new(sites).expect("finite sites");
        group.bench_with_input(BenchmarkId::from_parameter(name), clip, |b, clip| {
            b.iter(|| black_box(diagram.clip(black_box(clip))))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
