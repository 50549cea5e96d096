//! Polygon triangulation at `n`, `2n` and `4n` corners on the inputs that were quadratic (see
//! `common/polygons.rs`): a comb, in the render buffers and the half-edge kernel's face
//! triangulation, and a face over 3 places built with the repair policy, in the render buffers.
//! The time per corner (criterion's throughput) stays nearly flat for O(n log n); a quadratic
//! triangulation takes four times as long at each doubling.
//!
//!   cargo bench --bench triangulation [-- filter]

use std::hint::black_box;

use criterion::{BatchSize, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use halfwing::mesh::{BuildPolicy, FaceId, Mesh};
use halfwing::render::{MeshBufferOptions, mesh_buffers};
use halfwing::soup::FaceList;

#[path = "common/polygons.rs"]
mod polygons;

/// The mesh of one face.
fn one_face(positions: &[[f64; 3]], indices: &[u32], policy: BuildPolicy) -> Mesh {
    let sizes = [indices.len() as u32];
    let list = FaceList::polygons(positions, &sizes, indices);
    Mesh::from_face_list(&list, policy).unwrap().0
}

fn bench_triangulation(c: &mut Criterion) {
    let mut group = c.benchmark_group("comb");
    group.sample_size(10);
    for teeth in [20_000, 40_000, 80_000] {
        let comb = polygons::comb(teeth);
        let indices: Vec<u32> = (0..comb.len() as u32).collect();
        let mesh = one_face(&comb, &indices, BuildPolicy::Strict);
        group.throughput(Throughput::Elements(comb.len() as u64));
        group.bench_with_input(
            BenchmarkId::new("render buffers", comb.len()),
            &mesh,
            |b, mesh| {
                b.iter(|| {
                    mesh_buffers(black_box(mesh), None, &MeshBufferOptions::default()).unwrap()
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("triangulate_face", comb.len()),
            &mesh,
            |b, mesh| {
                b.iter_batched(
                    || mesh.clone(),
                    |mut mesh| mesh.triangulate_face(FaceId(0)).unwrap(),
                    BatchSize::LargeInput,
                )
            },
        );
    }
    group.finish();

    let mut group = c.benchmark_group("3 places");
    group.sample_size(10);
    for n in [20_000, 40_000, 80_000] {
        let (positions, indices) = polygons::three_places(n);
        let mesh = one_face(&positions, &indices, BuildPolicy::Repair);
        group.throughput(Throughput::Elements(u64::from(n)));
        group.bench_with_input(BenchmarkId::new("render buffers", n), &mesh, |b, mesh| {
            b.iter(|| mesh_buffers(black_box(mesh), None, &MeshBufferOptions::default()).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, bench_triangulation);
criterion_main!(benches);
