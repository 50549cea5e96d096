//! Exact self-intersection detection with one and with two threads: the 1M-triangle torus and
//! the largest closed models of the test data set (read from `HALFWING_DATA`, else from the copy
//! in `tests/data`, which has the first of them; the others are left out when missing).
//!
//!   cargo bench --bench self_intersections [-- filter]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use halfwing::geom::self_intersections;
use halfwing::soup::PolygonSoup;
use halfwing::surfaces::{CellFaces, Torus, torus};

#[path = "../tests/test_data/mod.rs"]
mod test_data;

/// The test models with the most triangles (about 100k, 100k and 86k).
const MODELS: [&str; 3] = [
    "meshes/closed/luke_dragon.obj",
    "meshes/closed/c3d_nefertiti.obj",
    "meshes/closed/igl_armadillo.obj",
];

/// Positions and triangles of a triangle soup.
fn triangles_of(soup: &PolygonSoup) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    assert!(
        soup.face_sizes.iter().all(|&size| size == 3),
        "triangles only"
    );
    let triangles = soup
        .indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    (soup.positions.clone(), triangles)
}

/// A named triangle mesh: positions and triangles.
type Input = (String, Vec<[f64; 3]>, Vec<[u32; 3]>);

fn inputs() -> Vec<Input> {
    let ring = torus(&Torus {
        major_radius: 1.0,
        minor_radius: 0.35,
        major_steps: 708,
        minor_steps: 708,
        faces: CellFaces::Triangles,
    })
    .expect("valid torus parameters");
    let (positions, triangles) = triangles_of(&ring);
    let mut inputs = vec![("torus-1M".to_string(), positions, triangles)];
    for model in MODELS {
        let path = test_data::root().join(model);
        let Ok(soup) = halfwing::io::read_path(&path) else {
            eprintln!("skipping {}: not readable", path.display());
            continue;
        };
        let (positions, triangles) = triangles_of(&soup);
        let name = model.rsplit('/').next().unwrap_or(model).to_string();
        inputs.push((name, positions, triangles));
    }
    inputs
}

fn bench_self_intersections(c: &mut Criterion) {
    for (name, positions, triangles) in inputs() {
        let mut group = c.benchmark_group(format!("self_intersections/{name}"));
        group.sample_size(10);
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            group.bench_function(format!("{threads} thread(s)"), |b| {
                b.iter(|| {
                    pool.install(|| {
                        self_intersections(black_box(&positions), black_box(&triangles))
                            .expect("valid input")
                    })
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_self_intersections);
criterion_main!(benches);
