//! Test-only helpers shared by the `mesh_*` integration tests: a minimal OFF/OBJ reader for the
//! test data set (positions and polygons only) and mesh generators.

#![allow(dead_code)] // each test binary uses a different subset

use std::path::{Path, PathBuf};

use halfwing::soup::PolygonSoup;

pub mod soups;
#[path = "../test_data/mod.rs"]
mod test_data;

/// Root of the test meshes.
pub fn data_dir() -> PathBuf {
    test_data::root().join("meshes")
}

/// Reads an OFF (also NOFF/COFF: extra per-vertex and per-face columns are ignored) or OBJ file
/// (`v` and `f` records; `v/vt/vn` and negative indices understood) into positions and polygons.
/// Indices are kept as they are (even out of range), so builders see the file's defects.
pub fn load(path: &Path) -> PolygonSoup {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    match path.extension().and_then(|e| e.to_str()) {
        Some("off") => parse_off(&text),
        Some("obj") => parse_obj(&text),
        other => panic!("unsupported extension {other:?}"),
    }
}

fn parse_off(text: &str) -> PolygonSoup {
    let mut lines = text
        .lines()
        .map(|line| line.split('#').next().unwrap_or("").trim())
        .filter(|line| !line.is_empty());
    let header = lines.next().expect("OFF header");
    assert!(header.ends_with("OFF"), "not an OFF header: {header}");
    // Counts may follow the keyword on the header line ("OFF 8 6 0") or sit on the next line.
    let inline_counts: Vec<&str> = header.split_whitespace().skip(1).collect();
    let counts_line = if inline_counts.is_empty() {
        lines.next().expect("OFF counts").to_string()
    } else {
        inline_counts.join(" ")
    };
    let counts: Vec<usize> = counts_line
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    let (n_vertices, n_faces) = (counts[0], counts[1]);
    let mut soup = PolygonSoup::default();
    for _ in 0..n_vertices {
        let values: Vec<f64> = lines
            .next()
            .unwrap()
            .split_whitespace()
            .take(3)
            .map(|t| t.parse().unwrap())
            .collect();
        soup.positions.push([values[0], values[1], values[2]]);
    }
    for _ in 0..n_faces {
        let mut tokens = lines
            .next()
            .unwrap()
            .split_whitespace()
            .map(|t| t.parse::<i64>().unwrap());
        let size = tokens.next().unwrap() as usize;
        soup.face_sizes.push(size as u32);
        soup.indices.extend(tokens.take(size).map(|i| i as u32));
    }
    soup
}

fn parse_obj(text: &str) -> PolygonSoup {
    let mut soup = PolygonSoup::default();
    for line in text.lines() {
        let mut tokens = line.split_whitespace();
        match tokens.next() {
            Some("v") => {
                let values: Vec<f64> = tokens.take(3).map(|t| t.parse().unwrap()).collect();
                soup.positions.push([values[0], values[1], values[2]]);
            }
            Some("f") => {
                let start = soup.indices.len();
                for token in tokens {
                    let index: i64 = token.split('/').next().unwrap().parse().unwrap();
                    let zero_based = if index < 0 {
                        soup.positions.len() as i64 + index
                    } else {
                        index - 1
                    };
                    soup.indices.push(zero_based as u32);
                }
                soup.face_sizes.push((soup.indices.len() - start) as u32);
            }
            _ => {}
        }
    }
    soup
}

/// A `columns × rows` grid of quads on a torus (closed, genus 1) when `closed`, else an open
/// `columns × rows` quad grid in the plane; each quad split into two triangles when `triangles`.
pub fn grid(columns: u32, rows: u32, closed: bool, triangles: bool) -> PolygonSoup {
    let (vertex_columns, vertex_rows) = if closed {
        (columns, rows)
    } else {
        (columns + 1, rows + 1)
    };
    let mut soup = PolygonSoup::default();
    for j in 0..vertex_rows {
        for i in 0..vertex_columns {
            let (u, v) = (i as f64 / columns as f64, j as f64 / rows as f64);
            soup.positions.push(if closed {
                let (a, b) = (u * std::f64::consts::TAU, v * std::f64::consts::TAU);
                [
                    (2.0 + b.cos()) * a.cos(),
                    (2.0 + b.cos()) * a.sin(),
                    b.sin(),
                ]
            } else {
                [u, v, 0.0]
            });
        }
    }
    let id = |i: u32, j: u32| (j % vertex_rows) * vertex_columns + (i % vertex_columns);
    for j in 0..rows {
        for i in 0..columns {
            let quad = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            if triangles {
                soup.indices
                    .extend([quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]]);
                soup.face_sizes.extend([3, 3]);
            } else {
                soup.indices.extend(quad);
                soup.face_sizes.push(4);
            }
        }
    }
    soup
}

/// Unit normal of face `f` (Newell's), asserting the face has an area.
pub fn unit_normal(mesh: &halfwing::mesh::Mesh, f: halfwing::mesh::FaceId) -> [f64; 3] {
    let v = halfwing::geom::newell_vector(mesh.face_vertices(f).map(|v| mesh.position(v)));
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    assert!(len > 0.0, "face {f:?} has no area");
    v.map(|x| x / len)
}

/// The largest angle (degrees) between one of `faces`' normals and that of a face beside it.
pub fn largest_turn(mesh: &halfwing::mesh::Mesh, faces: &[halfwing::mesh::FaceId]) -> f64 {
    let mut largest: f64 = 0.0;
    for &f in faces {
        let n = unit_normal(mesh, f);
        for g in mesh.face_faces(f) {
            let m = unit_normal(mesh, g);
            let cos = (n[0] * m[0] + n[1] * m[1] + n[2] * m[2]).clamp(-1.0, 1.0);
            largest = largest.max(cos.acos().to_degrees());
        }
    }
    largest
}
