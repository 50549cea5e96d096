//! Builds around one vertex or edge that many faces share, at `n`, `2n` and `4n` faces: a star
//! of triangles on one edge, a star of triangles touching only at one vertex, and a manifold fan
//! around one vertex, numbered first (see `common/stars.rs`). The time per face (criterion's
//! throughput) stays flat when a build is linear; a build quadratic in the faces around one
//! vertex takes four times as long at each doubling.
//!
//!   cargo bench --bench high_degree [-- filter]
//!
//! Under [`BuildPolicy::Skip`], which builds every one of them (the star on an edge keeps its
//! first face) and is the policy of `Mesh::diagnose`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use halfwing::mesh::{BuildPolicy, Mesh};
use halfwing::soup::FaceList;
use halfwing::winged::Winged;

#[path = "common/stars.rs"]
mod stars;
use stars::{Star, star};

fn bench_high_degree(c: &mut Criterion) {
    for (name, shape) in [
        ("star on an edge", Star::AtEdge),
        ("star at a vertex", Star::AtVertex),
        ("manifold fan", Star::ManifoldFan),
    ] {
        let mut group = c.benchmark_group(name);
        group.sample_size(10);
        for k in [1 << 15, 1 << 16, 1 << 17] {
            let (positions, indices, _) = star(shape, k, false);
            let list = FaceList::triangles(&positions, &indices);
            group.throughput(Throughput::Elements(u64::from(k)));
            group.bench_with_input(BenchmarkId::new("half-edge", k), &list, |b, list| {
                b.iter(|| Mesh::from_face_list(black_box(list), BuildPolicy::Skip).unwrap())
            });
            group.bench_with_input(BenchmarkId::new("winged", k), &list, |b, list| {
                b.iter(|| Winged::from_face_list(black_box(list), BuildPolicy::Skip).unwrap())
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_high_degree);
criterion_main!(benches);
