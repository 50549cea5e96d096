//! The winged-edge kernel beside the half-edge kernel, in one run on the same ~1M-triangle torus:
//! construction from an indexed face list, face loops over all faces, vertex rings over all
//! vertices, face and vertex normals; and the memory per face of both structures.
//!
//!   cargo bench --bench winged
//!
//! Target (issue 4): the winged build within 1.5× of the half-edge bulk build.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use halfwing::geom::VertexNormalWeighting;
use halfwing::mesh::{self, BuildPolicy, Mesh};
use halfwing::soup::PolygonSoup;
use halfwing::surfaces::{CellFaces, Torus, torus};
use halfwing::winged::{FaceId, VertexId, Winged};

/// A closed triangle torus of 2 · 708² = 1,002,528 faces.
fn input() -> PolygonSoup {
    torus(&Torus {
        major_radius: 1.0,
        minor_radius: 0.35,
        major_steps: 708,
        minor_steps: 708,
        faces: CellFaces::Triangles,
    })
    .expect("valid torus parameters")
}

/// Bytes of the half-edge mesh's arrays: four `u32` per half-edge, a position and a half-edge
/// per vertex, a half-edge per face.
fn halfedge_bytes(m: &Mesh) -> usize {
    4 * 4 * m.halfedge_origins().len()
        + (24 + 4) * m.vertex_halfedges().len()
        + 4 * m.face_halfedges().len()
}

fn bench_winged(c: &mut Criterion) {
    let soup = input();
    let list = soup.as_face_list();
    let (m, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).expect("clean torus");
    let (w, _) = Winged::from_face_list(&list, BuildPolicy::Strict).expect("clean torus");
    let n_faces = soup.n_faces() as f64;
    println!(
        "torus-tri: {} faces; memory per face: half-edge {:.1} B, winged-edge {:.1} B",
        soup.n_faces(),
        halfedge_bytes(&m) as f64 / n_faces,
        w.memory_bytes() as f64 / n_faces,
    );

    let mut group = c.benchmark_group("torus-tri");
    group.sample_size(10);
    group.bench_function("build/half-edge", |b| {
        b.iter(|| Mesh::from_face_list(black_box(&list), BuildPolicy::Strict))
    });
    group.bench_function("build/winged", |b| {
        b.iter(|| Winged::from_face_list(black_box(&list), BuildPolicy::Strict))
    });
    group.bench_function("face-loops/half-edge", |b| {
        b.iter(|| {
            (0..m.n_faces() as u32)
                .flat_map(|f| m.face_vertices(mesh::FaceId(f)))
                .fold(0u64, |sum, v| sum + u64::from(v.0))
        })
    });
    group.bench_function("face-loops/winged", |b| {
        b.iter(|| {
            (0..w.n_faces())
                .flat_map(|f| w.face_vertices(FaceId(f)).expect("live face"))
                .fold(0u64, |sum, v| sum + u64::from(v.0))
        })
    });
    group.bench_function("vertex-rings/half-edge", |b| {
        b.iter(|| {
            (0..m.n_vertices() as u32)
                .flat_map(|v| m.vertex_vertices(mesh::VertexId(v)))
                .fold(0u64, |sum, v| sum + u64::from(v.0))
        })
    });
    group.bench_function("vertex-rings/winged", |b| {
        b.iter(|| {
            (0..w.n_vertices())
                .flat_map(|v| w.vertex_neighbors(VertexId(v)).expect("live vertex"))
                .fold(0u64, |sum, v| sum + u64::from(v.0))
        })
    });
    group.bench_function("face-normals/half-edge", |b| b.iter(|| m.face_normals()));
    group.bench_function("face-normals/winged", |b| b.iter(|| w.face_normals()));
    group.bench_function("vertex-normals/half-edge", |b| {
        b.iter(|| m.vertex_normals(VertexNormalWeighting::Uniform))
    });
    group.bench_function("vertex-normals/winged", |b| {
        b.iter(|| w.vertex_normals(VertexNormalWeighting::Uniform))
    });
    group.finish();
}

criterion_group!(benches, bench_winged);
criterion_main!(benches);
