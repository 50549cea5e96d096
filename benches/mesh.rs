//! Rust-side benchmarks of the half-edge kernel on ~1M-face models: bulk build (as the C API does
//! it, from per-face sizes), face + vertex normals, a one-ring valence sum and connected
//! components. The side-by-side comparison with OpenMesh and CGAL is bench/mesh_compare.cpp.
//!
//!   cargo bench --bench mesh [-- filter]
//!
//! Set HALFWING_BENCH_MODEL to a model file to add it to the inputs.

use std::hint::black_box;

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use halfwing::geom::{VertexNormalWeighting, normals_into};
use halfwing::mesh::{BuildPolicy, Mesh, VertexId};
use halfwing::soup::PolygonSoup;
use halfwing::surfaces::{CellFaces, Grid, Torus, grid, torus};

/// ~1M-face inputs: a closed triangle torus, a closed quad torus, an open triangle grid, and the
/// model named by HALFWING_BENCH_MODEL, if any.
fn inputs() -> Vec<(String, PolygonSoup)> {
    let torus_of = |steps: u32, faces: CellFaces| {
        torus(&Torus {
            major_radius: 1.0,
            minor_radius: 0.35,
            major_steps: steps,
            minor_steps: steps,
            faces,
        })
        .expect("valid torus parameters")
    };
    let open_grid = grid(&Grid {
        width: 1.0,
        height: 1.0,
        cells_x: 708,
        cells_y: 708,
        faces: CellFaces::Triangles,
    })
    .expect("valid grid parameters");
    let mut inputs = vec![
        ("torus-tri".to_string(), torus_of(708, CellFaces::Triangles)),
        ("torus-quad".to_string(), torus_of(1011, CellFaces::Quads)),
        ("grid-tri".to_string(), open_grid),
    ];
    if let Ok(path) = std::env::var("HALFWING_BENCH_MODEL") {
        let soup = halfwing::io::read_path(&path).expect("HALFWING_BENCH_MODEL is readable");
        inputs.push((path.rsplit('/').next().unwrap_or(&path).to_string(), soup));
    }
    inputs
}

fn build(soup: &PolygonSoup) -> Mesh {
    Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
        .expect("benchmark inputs are clean manifolds")
        .0
}

/// The one-ring walk a C user writes over the raw arrays: `h = twin(prev(h))` around each vertex.
fn valence_sum(mesh: &Mesh) -> usize {
    let prev = mesh.halfedge_prevs();
    let mut sum = 0;
    for &start in mesh.vertex_halfedges() {
        if start == u32::MAX {
            continue;
        }
        let mut h = start;
        loop {
            sum += 1;
            h = prev[h as usize] ^ 1;
            if h == start {
                break;
            }
        }
    }
    sum
}

fn bench_mesh(c: &mut Criterion) {
    for (name, soup) in inputs() {
        let mut group = c.benchmark_group(name);
        group.sample_size(10);
        group.bench_function("build", |b| b.iter(|| build(black_box(&soup))));
        let mesh = build(&soup);
        let mut face_normals = vec![[0.0; 3]; mesh.n_face_slots()];
        let mut vertex_normals = vec![[0.0; 3]; mesh.n_vertex_slots()];
        group.bench_function("face+vertex normals", |b| {
            b.iter(|| {
                normals_into(
                    &mesh,
                    VertexNormalWeighting::Uniform,
                    Some(&mut face_normals),
                    &mut vertex_normals,
                )
            })
        });
        group.bench_function("valence sum", |b| b.iter(|| valence_sum(black_box(&mesh))));
        group.bench_function("valence sum (Mesh::valence)", |b| {
            b.iter(|| {
                (0..mesh.n_vertex_slots() as u32)
                    .map(|v| mesh.valence(VertexId(v)))
                    .sum::<usize>()
            })
        });
        group.bench_function("connected components", |b| {
            b.iter_batched(
                || (),
                |()| mesh.connected_components().count,
                BatchSize::SmallInput,
            )
        });
        group.finish();
    }
}

criterion_group!(benches, bench_mesh);
criterion_main!(benches);
