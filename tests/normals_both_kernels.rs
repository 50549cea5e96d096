//! Both kernels compute face and vertex normals with the same code: on the same faces, the
//! half-edge mesh and the winged structure give the same normals bit for bit, for every
//! weighting, all at once or one element at a time, on meshes with boundaries, holes,
//! non-planar polygons, degenerate faces, faces too small or too large for a plain cross
//! product, deleted faces and a vertex where two fans meet; and those normals are the
//! weighted sums the weightings define, computed here from the face list alone.

use halfwing::geom::{VertexNormalWeighting, newell_vector};
use halfwing::mesh::{self, Mesh};
use halfwing::soup::{BuildPolicy, FaceList};
use halfwing::winged::{self, Winged};

/// A face list: positions, face sizes, corner indices.
struct Faces {
    positions: Vec<[f64; 3]>,
    sizes: Vec<u32>,
    indices: Vec<u32>,
}

impl Faces {
    fn list(&self) -> FaceList<'_> {
        FaceList::polygons(&self.positions, &self.sizes, &self.indices)
    }

    fn add(&mut self, corners: &[u32]) {
        self.sizes.push(corners.len() as u32);
        self.indices.extend_from_slice(corners);
    }

    /// The faces in order, each as its corner indices.
    fn faces(&self) -> Vec<&[u32]> {
        let mut start = 0;
        let mut faces = Vec::new();
        for &size in &self.sizes {
            faces.push(&self.indices[start..start + size as usize]);
            start += size as usize;
        }
        faces
    }
}

/// A bent 4 × 4 grid of vertices (z varies, so the quads are not planar) with its middle cell
/// left out (a hole), its first cell split into two triangles, and its last cell a pentagon
/// through a raised point on the outer border; beside it, degenerate faces: a triangle whose
/// corners lie on a line, sharing an edge with a proper triangle, and a quad on a line; and
/// faces whose area vectors underflow (corners 1e-160 apart) and overflow (corners near 1e300).
fn awkward_faces() -> Faces {
    let mut faces = Faces {
        positions: Vec::new(),
        sizes: Vec::new(),
        indices: Vec::new(),
    };
    for j in 0..4 {
        for i in 0..4 {
            let (x, y) = (f64::from(i), f64::from(j));
            faces.positions.push([x, y, 0.3 * x * y - 0.1 * x * x]);
        }
    }
    let at = |i: u32, j: u32| 4 * j + i;
    for j in 0..3 {
        for i in 0..3 {
            match (i, j) {
                (1, 1) => {}
                (0, 0) => {
                    faces.add(&[at(0, 0), at(1, 0), at(1, 1)]);
                    faces.add(&[at(0, 0), at(1, 1), at(0, 1)]);
                }
                (2, 2) => {
                    faces.positions.push([2.5, 3.0, 1.5]);
                    faces.add(&[at(2, 2), at(3, 2), at(3, 3), 16, at(2, 3)]);
                }
                _ => faces.add(&[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]),
            }
        }
    }
    let first = faces.positions.len() as u32;
    faces.positions.extend([
        // A line: a, b, c, with d off it.
        [10.0, 0.0, 0.0],
        [11.0, 0.0, 0.0],
        [12.0, 0.0, 0.0],
        [11.0, -1.0, 0.0],
        // A quad on a line.
        [20.0, 0.0, 0.0],
        [21.0, 0.0, 0.0],
        [22.0, 0.0, 0.0],
        [23.0, 0.0, 0.0],
        // Tiny and huge triangles.
        [1e-160, 0.0, 0.0],
        [2e-160, 0.0, 0.0],
        [1e-160, 1e-160, 1e-160],
        [1e300, 0.0, 0.0],
        [-1e300, 1e300, 0.0],
        [0.0, -1e300, 1e300],
    ]);
    let v = |k: u32| first + k;
    faces.add(&[v(0), v(1), v(2)]);
    faces.add(&[v(1), v(0), v(3)]);
    faces.add(&[v(4), v(5), v(6), v(7)]);
    faces.add(&[v(8), v(9), v(10)]);
    faces.add(&[v(11), v(12), v(13)]);
    faces
}

/// Both kernels built from `faces`.
fn both(faces: &Faces) -> (Mesh, Winged) {
    let (mesh, _) = Mesh::from_face_list(&faces.list(), BuildPolicy::Strict).expect("mesh");
    let (winged, _) = Winged::from_face_list(&faces.list(), BuildPolicy::Strict).expect("winged");
    (mesh, winged)
}

/// The two kernels' normals are equal bit for bit, all at once and one by one.
fn assert_same_normals(mesh: &Mesh, winged: &Winged) {
    let faces = mesh.face_normals();
    assert_eq!(winged.face_normals(), faces, "face normals");
    for f in 0..faces.len() as u32 {
        let (m, w) = (mesh::FaceId(f), winged::FaceId(f));
        if winged.is_face(w) {
            assert_eq!(mesh.face_normal(m).unwrap(), faces[f as usize], "face {f}");
            assert_eq!(
                winged.face_normal(w).unwrap(),
                faces[f as usize],
                "face {f}"
            );
        } else {
            assert!(mesh.face_normal(m).is_err() && winged.face_normal(w).is_err());
        }
    }
    for weighting in VertexNormalWeighting::ALL {
        let vertices = mesh.vertex_normals(weighting);
        assert_eq!(winged.vertex_normals(weighting), vertices, "{weighting:?}");
        for v in 0..vertices.len() as u32 {
            let (m, w) = (mesh::VertexId(v), winged::VertexId(v));
            if winged.is_vertex(w) {
                let expected = vertices[v as usize];
                assert_eq!(mesh.vertex_normal(m, weighting).unwrap(), expected, "{v}");
                assert_eq!(winged.vertex_normal(w, weighting).unwrap(), expected, "{v}");
            } else {
                assert!(mesh.vertex_normal(m, weighting).is_err());
                assert!(winged.vertex_normal(w, weighting).is_err());
            }
        }
    }
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if length > 0.0 && length.is_finite() {
        v.map(|x| x / length)
    } else {
        [0.0; 3]
    }
}

/// The vertex normals the weightings define, from the face list alone: each face's normal
/// (Newell's vector, scaled into a double's range first), weighed as `weighting` says and summed
/// at each of its corners.
fn reference_vertex_normals(faces: &Faces, weighting: VertexNormalWeighting) -> Vec<[f64; 3]> {
    let mut sums = vec![[0.0; 3]; faces.positions.len()];
    for face in faces.faces() {
        let corners: Vec<[f64; 3]> = face.iter().map(|&v| faces.positions[v as usize]).collect();
        let scale = corners
            .iter()
            .flat_map(|p| p.map(|x| (x - corners[0][0]).abs()))
            .fold(0.0f64, f64::max);
        let area_vector = newell_vector(corners.iter().map(|p| p.map(|x| x / scale)));
        let normal = match weighting {
            // Back to the face's own scale, where a double holds its area; a face whose area
            // no double holds weighs as its copy of unit size.
            VertexNormalWeighting::Area => {
                let area = area_vector.map(|x| x * scale * scale);
                if unit(area) == [0.0; 3] {
                    area_vector
                } else {
                    area
                }
            }
            _ => unit(area_vector),
        };
        for (k, &v) in face.iter().enumerate() {
            let weight = match weighting {
                VertexNormalWeighting::Angle => {
                    let n = corners.len();
                    let at = corners[k];
                    let to = |p: [f64; 3]| unit([p[0] - at[0], p[1] - at[1], p[2] - at[2]]);
                    let (a, b) = (to(corners[(k + 1) % n]), to(corners[(k + n - 1) % n]));
                    (a[0] * b[0] + a[1] * b[1] + a[2] * b[2])
                        .clamp(-1.0, 1.0)
                        .acos()
                }
                _ => 1.0,
            };
            for i in 0..3 {
                sums[v as usize][i] += weight * normal[i];
            }
        }
    }
    sums.into_iter().map(unit).collect()
}

#[test]
fn both_kernels_give_the_same_normals_on_awkward_faces() {
    let faces = awkward_faces();
    let (mesh, winged) = both(&faces);
    assert_same_normals(&mesh, &winged);
    let normals = mesh.face_normals();
    let degenerate = normals.len() - 5;
    assert_eq!(normals[degenerate], [0.0; 3], "the triangle on a line");
    assert_eq!(normals[degenerate + 2], [0.0; 3], "the quad on a line");
    for rescued in [degenerate + 3, degenerate + 4] {
        let length: f64 = normals[rescued].iter().map(|x| x * x).sum();
        assert!((length - 1.0).abs() < 1e-12, "face {rescued}: {length}");
    }
}

#[test]
fn the_normals_are_the_weighted_sums_the_weightings_define() {
    let faces = awkward_faces();
    let (mesh, winged) = both(&faces);
    for weighting in VertexNormalWeighting::ALL {
        let expected = reference_vertex_normals(&faces, weighting);
        let found = winged.vertex_normals(weighting);
        for (v, (found, expected)) in found.iter().zip(&expected).enumerate() {
            let distance = (0..3)
                .map(|k| (found[k] - expected[k]).abs())
                .fold(0.0, f64::max);
            assert!(
                distance < 1e-9,
                "{weighting:?} vertex {v}: {found:?} against {expected:?}"
            );
        }
        assert_eq!(mesh.vertex_normals(weighting), found);
    }
}

#[test]
fn two_fans_at_a_vertex_and_deleted_faces_count_the_same_in_both_kernels() {
    // Two fans of triangles meeting at vertex 0 only.
    let faces = Faces {
        positions: vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.2],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.3],
            [-1.0, 0.0, 0.5],
            [-1.0, -1.0, 0.0],
            [0.0, -1.0, -0.4],
        ],
        sizes: vec![3; 4],
        indices: vec![0, 1, 2, 0, 2, 3, 0, 4, 5, 0, 5, 6],
    };
    // Added one face at a time: a build would give each fan a vertex of its own.
    let mut mesh = Mesh::new();
    for &p in &faces.positions {
        mesh.add_vertex(p).unwrap();
    }
    for face in faces.faces() {
        let corners: Vec<mesh::VertexId> = face.iter().map(|&v| mesh::VertexId(v)).collect();
        mesh.add_face(&corners).unwrap();
    }
    let winged = Winged::from_mesh(&mesh);
    assert_same_normals(&mesh, &winged);
    for weighting in VertexNormalWeighting::ALL {
        let expected = reference_vertex_normals(&faces, weighting)[0];
        let found = mesh.vertex_normal(mesh::VertexId(0), weighting).unwrap();
        assert!(
            (0..3).all(|k| (found[k] - expected[k]).abs() < 1e-12),
            "{weighting:?}: both fans count: {found:?} against {expected:?}"
        );
    }

    // Killing the edge between faces 0 and 1 merges them into a non-planar quad and leaves
    // face 1's slot deleted, in the winged structure and in the mesh converted from it.
    let mut winged = winged;
    let shared = winged
        .edges()
        .find(|&e| {
            let mut faces = winged.edge_faces(e).unwrap();
            faces.sort();
            faces == [winged::FaceId(0), winged::FaceId(1)]
        })
        .unwrap();
    winged.kef(shared, winged::FaceId(1)).unwrap();
    let mesh = winged.to_mesh().unwrap();
    assert!(!winged.is_face(winged::FaceId(1)) && mesh.is_face_deleted(mesh::FaceId(1)));
    assert_same_normals(&mesh, &winged);
    assert_eq!(mesh.face_normals()[1], [0.0; 3]);
    assert_eq!(mesh.face_degree(mesh::FaceId(0)), 4);
}
