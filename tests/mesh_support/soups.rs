//! Soups the repair tests share: random ones on a small lattice of positions, and every test
//! model as the library's reader gives it.

use halfwing::io::read_path;
use halfwing::soup::PolygonSoup;
use proptest::prelude::*;

use super::data_dir;

/// Soups of 1 to 24 triangles and quads on 3 to `max_vertices - 1` vertices placed on a small
/// lattice (so duplicates, collapses and non-manifold elements are frequent), each corner's uv
/// its corner index.
pub fn lattice_soup(max_vertices: usize) -> impl Strategy<Value = PolygonSoup> {
    (3usize..max_vertices, 1usize..25).prop_flat_map(|(n_vertices, n_faces)| {
        (
            prop::collection::vec((0..3i32, 0..3i32, 0..2i32), n_vertices),
            prop::collection::vec(prop::collection::vec(0..n_vertices as u32, 3..5), n_faces),
        )
            .prop_map(|(points, faces)| PolygonSoup {
                positions: points
                    .into_iter()
                    .map(|(x, y, z)| [f64::from(x), f64::from(y), f64::from(z)])
                    .collect(),
                face_sizes: faces.iter().map(|f| f.len() as u32).collect(),
                corner_uvs: Some(
                    (0..faces.iter().map(Vec::len).sum::<usize>())
                        .map(|c| [c as f64, 0.0])
                        .collect(),
                ),
                indices: faces.into_iter().flatten().collect(),
                corner_normals: None,
            })
    })
}

/// Every test model the reader accepts, by group and in name order: `(group, path, soup)`.
pub fn test_models() -> Vec<(&'static str, String, PolygonSoup)> {
    let mut models = Vec::new();
    for group in ["broken", "closed", "open", "polygonal"] {
        let mut entries: Vec<_> = std::fs::read_dir(data_dir().join(group))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for path in entries {
            if let Ok(soup) = read_path(&path) {
                models.push((group, path.display().to_string(), soup));
            }
        }
    }
    assert!(models.len() > 50, "only {} models read", models.len());
    models
}
