//! Render buffers of every mesh of the test data set (read with halfwing's readers, built with
//! the repair policy so broken files render too), in every shading mode: what a GPU is given must
//! be consistent whatever the model — indices in range, one triangle count per polygon, finite
//! positions equal to the mesh's, unit normals (the file's own ones too), finite uvs, and line
//! sets matching the topology.
//!
//! The data is the repository's `tests/data`; set `HALFWING_DATA` to point at a fuller set.

use std::path::PathBuf;

use halfwing::geom::VertexNormalWeighting;
use halfwing::io::read_path;
use halfwing::mesh::{BuildPolicy, EdgeId, FaceId, Mesh};
use halfwing::render::{
    MeshBufferOptions, MeshBuffers, Shading, SurfaceOptions, VertexLayout, mesh_buffers,
};

mod test_data;

fn mesh_files() -> Vec<PathBuf> {
    let dir = test_data::root();
    let mut files = Vec::new();
    let mut pending = vec![dir.join("meshes")];
    while let Some(folder) = pending.pop() {
        for entry in std::fs::read_dir(&folder).expect("test data (set HALFWING_DATA)") {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

fn check_buffers(name: &str, mesh: &Mesh, buffers: &MeshBuffers, expected_non_manifold: usize) {
    let surface = &buffers.surface;
    let n = surface.n_vertices();
    assert_eq!(surface.positions.len(), 3 * n, "{name}");
    assert_eq!(surface.normals.len(), 3 * n, "{name}");
    assert!(
        surface.triangles.iter().all(|&v| (v as usize) < n),
        "{name}: index out of range"
    );

    // Every live face of n corners gives n - 2 triangles, face after face.
    let expected: usize = (0..mesh.n_face_slots())
        .map(|f| FaceId(f as u32))
        .filter(|&f| !mesh.is_face_deleted(f))
        .map(|f| mesh.face_degree(f) - 2)
        .sum();
    assert_eq!(surface.n_triangles(), expected, "{name}");
    assert!(
        surface.triangle_faces.windows(2).all(|w| w[0] <= w[1]),
        "{name}"
    );

    for (r, &v) in surface.vertex_sources.iter().enumerate() {
        let p = mesh.positions()[v as usize].map(|c| c as f32);
        assert_eq!(
            &surface.positions[3 * r..3 * r + 3],
            &p,
            "{name}: vertex {r}"
        );
        let normal = &surface.normals[3 * r..3 * r + 3];
        let length: f32 = normal.iter().map(|c| c * c).sum::<f32>().sqrt();
        // Zero only at corners of degenerate faces, which have no normal.
        assert!(
            length == 0.0 || (length - 1.0).abs() < 1e-4,
            "{name}: normal {normal:?}"
        );
    }

    let boundary_edges = (0..mesh.n_edge_slots())
        .map(|e| EdgeId(e as u32))
        .filter(|&e| !mesh.is_edge_deleted(e) && mesh.is_boundary_edge(e))
        .count();
    assert_eq!(buffers.boundary.n_segments(), boundary_edges, "{name}");
    assert_eq!(buffers.wireframe.n_segments(), mesh.n_edges(), "{name}");
    assert_eq!(
        buffers.non_manifold.n_segments(),
        expected_non_manifold,
        "{name}"
    );
    assert!(
        buffers.wireframe.positions.iter().all(|c| c.is_finite()),
        "{name}"
    );
}

#[test]
fn every_shared_model_renders_consistently_in_every_shading() {
    let mut rendered = 0;
    for path in mesh_files() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        // Files the readers refuse are the readers' tests' business.
        let Ok(soup) = read_path(&path) else { continue };
        let Ok((mesh, diagnostic)) = Mesh::from_soup(&soup, BuildPolicy::Repair) else {
            continue;
        };
        if !diagnostic.non_finite_vertices.is_empty() {
            continue;
        }
        let mut counts = Vec::new();
        for shading in [
            Shading::Smooth(VertexNormalWeighting::Angle),
            Shading::Crease(30f64.to_radians()),
            Shading::Flat,
        ] {
            let options = MeshBufferOptions {
                surface: SurfaceOptions {
                    shading,
                    layout: VertexLayout::Separate,
                    ..SurfaceOptions::default()
                },
                ..MeshBufferOptions::default()
            };
            let buffers = mesh_buffers(&mesh, Some(&diagnostic), &options).unwrap();
            check_buffers(&name, &mesh, &buffers, diagnostic.non_manifold_edges.len());
            counts.push(buffers.surface.n_vertices());
        }
        // Flat shading splits at every edge, crease shading at sharp ones only, smooth nowhere.
        assert!(
            counts[0] <= counts[1] && counts[1] <= counts[2],
            "{name}: {counts:?}"
        );
        // The file's own normals and uvs, as viewers show a file by default.
        let options = MeshBufferOptions {
            surface: SurfaceOptions {
                corner_normals: mesh.corner_normals(),
                corner_uvs: mesh.corner_uvs(),
                ..SurfaceOptions::default()
            },
            ..MeshBufferOptions::default()
        };
        let buffers = mesh_buffers(&mesh, Some(&diagnostic), &options).unwrap();
        check_buffers(&name, &mesh, &buffers, diagnostic.non_manifold_edges.len());
        assert!(
            buffers.surface.uvs.iter().all(|c| c.is_finite()),
            "{name}: uvs"
        );
        rendered += 1;
    }
    assert!(rendered >= 40, "only {rendered} models rendered");
}
