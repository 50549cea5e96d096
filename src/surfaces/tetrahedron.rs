//! The regular tetrahedron of the winged-edge literature's worked example, with its exact coordinates
//! and face numbering.

use crate::soup::PolygonSoup;

/// The worked example's tetrahedron: unit edges, base in the plane z = 0 centred on the z axis,
/// `V0 = (√3/3, 0, 0)`, `V1 = (−√3/6, 1/2, 0)`, `V2 = (−√3/6, −1/2, 0)`, `V3 = (0, 0, √6/3)`,
/// faces `F0 = {0, 1, 3}`, `F1 = {1, 2, 3}`, `F2 = {0, 3, 2}`, `F3 = {0, 2, 1}` (CCW from outside).
pub fn tetrahedron() -> PolygonSoup {
    let sqrt3 = 3f64.sqrt();
    PolygonSoup {
        positions: vec![
            [sqrt3 / 3.0, 0.0, 0.0],
            [-sqrt3 / 6.0, 0.5, 0.0],
            [-sqrt3 / 6.0, -0.5, 0.0],
            [0.0, 0.0, 6f64.sqrt() / 3.0],
        ],
        face_sizes: vec![3; 4],
        indices: vec![0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 1],
        corner_normals: None,
        corner_uvs: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn every_edge_has_unit_length() {
        let t = tetrahedron();
        for i in 0..4 {
            for j in i + 1..4 {
                let d =
                    DVec3::from_array(t.positions[i]).distance(DVec3::from_array(t.positions[j]));
                assert!((d - 1.0).abs() < 1e-15, "edge {i}-{j} has length {d}");
            }
        }
    }
}
