//! Normals and render buffers of real triangles at the ends of the double range. Before: a
//! triangle with coordinates near 1e308 got a (0, 0, 0) normal (its cross product overflowed),
//! and the render buffers failed with "normal glyph length inf" though no length was given.

use halfwing::geom::{VertexNormalWeighting, face_normals, vertex_normals};
use halfwing::mesh::Mesh;
use halfwing::render::{MeshBufferOptions, RenderError, mesh_buffers};
use halfwing::soup::{BuildPolicy, FaceList};
use halfwing::winged::{FaceId, Winged};

/// The triangle (0,0,0), (s,0,0), (0,s,0) and the quad beside it, at scale `s`.
fn at_scale(s: f64) -> (Vec<[f64; 3]>, Vec<u32>, Vec<u32>) {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [s, 0.0, 0.0],
        [0.0, s, 0.0],
        [-s, 0.0, 0.0],
        [-s, s, 0.0],
    ];
    (positions, vec![3, 4], vec![0, 1, 2, 0, 2, 4, 3])
}

#[test]
fn faces_near_overflow_and_underflow_have_unit_normals_in_both_kernels() {
    for s in [1e308, f64::MAX / 2.0, 1e200, 1e-160, 1e-300, 5e-324 * 4.0] {
        let (positions, sizes, indices) = at_scale(s);
        let list = FaceList::polygons(&positions, &sizes, &indices);
        let (mesh, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
        let (winged, _) = Winged::from_face_list(&list, BuildPolicy::Strict).unwrap();
        assert_eq!(face_normals(&mesh), vec![[0.0, 0.0, 1.0]; 2], "scale {s}");
        for f in 0..2 {
            assert_eq!(
                winged.face_normal(FaceId(f)),
                Ok([0.0, 0.0, 1.0]),
                "scale {s}"
            );
        }
        for weighting in [VertexNormalWeighting::Uniform, VertexNormalWeighting::Angle] {
            for n in vertex_normals(&mesh, weighting) {
                assert_eq!(n, [0.0, 0.0, 1.0], "scale {s}, {weighting:?}");
            }
        }
    }
}

#[test]
fn render_buffers_name_coordinates_beyond_single_precision() {
    let (positions, sizes, indices) = at_scale(1e308);
    let list = FaceList::polygons(&positions, &sizes, &indices);
    let (mesh, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
    let error = mesh_buffers(&mesh, None, &MeshBufferOptions::default()).unwrap_err();
    assert!(
        matches!(error, RenderError::BeyondSinglePrecision { vertex: 1, .. }),
        "{error}"
    );
    assert!(error.to_string().contains("single-precision"), "{error}");
    // Within single precision, huge or tiny, the buffers build with glyphs of the mean edge.
    for s in [1e38, 1e-38] {
        let (positions, sizes, indices) = at_scale(s);
        let list = FaceList::polygons(&positions, &sizes, &indices);
        let (mesh, _) = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap();
        let buffers = mesh_buffers(&mesh, None, &MeshBufferOptions::default()).unwrap();
        assert!(
            buffers
                .surface
                .normals
                .chunks(3)
                .all(|n| n == [0.0, 0.0, 1.0]),
            "scale {s}"
        );
        assert!(
            buffers
                .vertex_normals
                .positions
                .iter()
                .all(|x| x.is_finite()),
            "scale {s}"
        );
    }
}
