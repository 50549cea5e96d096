//! Render buffers of OBJ files whose normals and texture coordinates cover some corners only, and
//! of files whose normals an explicit shading must override: every value is finite and is the
//! documented one (a file normal at unit length where there is one, the smooth normal elsewhere;
//! the file's uv where there is one, `(0, 0)` elsewhere), through the Rust API and the C API.

use std::ffi::CString;

use halfwing::ffi::{
    HW_BUILD_POLICY_STRICT, HW_OK, HW_RENDER_FLOATS_NORMALS, HW_RENDER_FLOATS_UVS,
    HW_SHADING_CORNER_NORMALS, HW_SHADING_CREASE, HW_SHADING_FLAT, HW_SHADING_SMOOTH, hw_mesh,
    hw_mesh_free, hw_mesh_read, hw_render_buffers, hw_render_buffers_build,
    hw_render_buffers_floats, hw_render_buffers_free, hw_render_buffers_n_vertices,
    hw_render_options, hw_render_options_default,
};
use halfwing::geom::{VertexNormalWeighting, face_normals, vertex_normals};
use halfwing::io::read_obj_bytes;
use halfwing::mesh::{BuildPolicy, Mesh};
use halfwing::render::{Shading, SurfaceBuffer, SurfaceOptions, surface_buffer};

/// The unit cube's outward quads over the vertices `i → (i & 1, i >> 1 & 1, i >> 2 & 1)`.
const CUBE_QUADS: [[usize; 4]; 6] = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
];

/// The cube as OBJ: its `v` records, then `records` (`vn`, `vt`), then the faces, corner `k` of
/// face `f` written as its vertex followed by `corner(f, k)` (such as `/1` or `//2`).
fn cube_obj(records: &str, corner: impl Fn(usize, usize) -> String) -> String {
    let mut text = String::new();
    for i in 0..8 {
        text += &format!("v {} {} {}\n", i & 1, i >> 1 & 1, i >> 2 & 1);
    }
    text += records;
    for (f, quad) in CUBE_QUADS.iter().enumerate() {
        text += "f";
        for (k, &v) in quad.iter().enumerate() {
            text += &format!(" {}{}", v + 1, corner(f, k));
        }
        text += "\n";
    }
    text
}

fn mesh_of(obj: &str) -> Mesh {
    let soup = read_obj_bytes(obj.as_bytes()).unwrap();
    Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap().0
}

/// The buffer the default options give with the mesh's own corner attributes, as a viewer asks
/// for it (and as the C API's defaults do).
fn buffer_with_file_attributes(mesh: &Mesh, shading: Shading) -> SurfaceBuffer {
    let options = SurfaceOptions {
        shading,
        corner_normals: mesh.corner_normals(),
        corner_uvs: mesh.corner_uvs(),
        ..SurfaceOptions::default()
    };
    surface_buffer(mesh, &options).unwrap()
}

/// Calls `check(face, corner_in_face, render_vertex)` for every triangle corner of the buffer.
fn for_each_corner(buffer: &SurfaceBuffer, mut check: impl FnMut(usize, usize, usize)) {
    for (triangle, &face) in buffer.triangles.chunks_exact(3).zip(&buffer.triangle_faces) {
        for &r in triangle {
            let v = buffer.vertex_sources[r as usize] as usize;
            let k = CUBE_QUADS[face as usize].iter().position(|&q| q == v);
            check(face as usize, k.expect("a corner of its face"), r as usize);
        }
    }
}

fn normal_of(buffer: &SurfaceBuffer, r: usize) -> [f32; 3] {
    std::array::from_fn(|axis| buffer.normals[3 * r + axis])
}

fn assert_close(got: [f32; 3], expected: [f64; 3], what: &str) {
    assert!(
        (0..3).all(|axis| (got[axis] - expected[axis] as f32).abs() <= f32::EPSILON),
        "{what}: {got:?}, expected {expected:?}"
    );
}

#[test]
fn corners_without_a_file_normal_get_the_smooth_normal() {
    // Only the bottom face has normals, and not of unit length.
    let obj = cube_obj(
        "vn 0 0 -3\n",
        |f, _| if f == 0 { "//1".into() } else { "".into() },
    );
    let mesh = mesh_of(&obj);
    let smooth = vertex_normals(&mesh, VertexNormalWeighting::Angle);
    let buffer = buffer_with_file_attributes(&mesh, Shading::default());
    assert!(buffer.normals.iter().all(|c| c.is_finite()));
    assert!(!buffer.has_uvs());
    for_each_corner(&buffer, |face, k, r| {
        let v = CUBE_QUADS[face][k];
        let expected = if face == 0 {
            [0.0, 0.0, -1.0]
        } else {
            smooth[v]
        };
        assert_close(normal_of(&buffer, r), expected, &format!("face {face}"));
    });
    // The bottom face's corners are split from the others: 8 smooth vertices + 4.
    assert_eq!(buffer.n_vertices(), 12);
}

#[test]
fn corners_without_a_file_uv_get_zero_whatever_the_corner_forms() {
    // Face 0: `v/vt/vn`; face 1: `v/vt`, `v`, `v//vn`, `v` in turn; the others bare.
    let obj = cube_obj("vt 0.25 0.75\nvt 1 0.5\nvn 0 0 -1\n", |f, k| {
        match (f, k % 2) {
            (0, _) => "/1/1".into(),
            (1, 0) if k == 0 => "/2".into(),
            (1, 0) => "//1".into(),
            _ => "".into(),
        }
    });
    let mesh = mesh_of(&obj);
    let smooth = vertex_normals(&mesh, VertexNormalWeighting::Angle);
    let buffer = buffer_with_file_attributes(&mesh, Shading::default());
    assert!(buffer.has_uvs());
    assert!(
        buffer
            .normals
            .iter()
            .chain(&buffer.uvs)
            .all(|c| c.is_finite())
    );
    for_each_corner(&buffer, |face, k, r| {
        let expected_uv = match (face, k) {
            (0, _) => [0.25, 0.75],
            (1, 0) => [1.0, 0.5],
            _ => [0.0, 0.0],
        };
        assert_eq!(
            &buffer.uvs[2 * r..2 * r + 2],
            &expected_uv,
            "face {face} corner {k}"
        );
        let v = CUBE_QUADS[face][k];
        let expected_normal = match (face, k) {
            (0, _) | (1, 2) => [0.0, 0.0, -1.0],
            _ => smooth[v],
        };
        assert_close(
            normal_of(&buffer, r),
            expected_normal,
            &format!("face {face}"),
        );
    });
}

#[test]
fn explicit_shadings_override_the_file_normals() {
    // Every corner's file normal is +z: only the default shading shows it.
    let obj = cube_obj("vn 0 0 1\n", |_, _| "//1".into());
    let mesh = mesh_of(&obj);
    let faces = face_normals(&mesh);
    let with_file = buffer_with_file_attributes(&mesh, Shading::default());
    assert_eq!(with_file.n_vertices(), 8);
    assert!(
        with_file
            .normals
            .chunks_exact(3)
            .all(|n| n == [0.0, 0.0, 1.0])
    );

    let flat = buffer_with_file_attributes(&mesh, Shading::Flat);
    assert_eq!(flat.n_vertices(), 24);
    for_each_corner(&flat, |face, _, r| {
        assert_close(normal_of(&flat, r), faces[face], "flat");
    });
    for shading in [
        Shading::Flat,
        Shading::Smooth(VertexNormalWeighting::Angle),
        Shading::Crease(0.5),
    ] {
        let computed = surface_buffer(
            &mesh,
            &SurfaceOptions {
                shading,
                ..SurfaceOptions::default()
            },
        )
        .unwrap();
        assert_eq!(
            buffer_with_file_attributes(&mesh, shading).normals,
            computed.normals,
            "{shading:?}"
        );
    }
}

/// A mesh read from an OBJ file through the C API, and freed when dropped.
struct CMesh(*mut hw_mesh);

impl CMesh {
    fn read(name: &str, obj: &str) -> CMesh {
        let dir = std::env::temp_dir().join(format!("halfwing-render-obj-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, obj).unwrap();
        let c_path = CString::new(path.to_str().unwrap()).unwrap();
        let mut mesh = std::ptr::null_mut();
        // SAFETY: a NUL-terminated path and a writable output; no diagnostic asked for.
        let status = unsafe {
            hw_mesh_read(
                c_path.as_ptr(),
                HW_BUILD_POLICY_STRICT,
                &mut mesh,
                std::ptr::null_mut(),
            )
        };
        std::fs::remove_file(&path).unwrap();
        assert_eq!(status, HW_OK);
        CMesh(mesh)
    }

    /// The number of render vertices and the normals and uvs `options` give.
    fn render(&self, options: &hw_render_options) -> (usize, Vec<f32>, Vec<f32>) {
        let mut buffers: *mut hw_render_buffers = std::ptr::null_mut();
        // SAFETY: a live mesh, readable options without corner arrays, a writable output.
        let status =
            unsafe { hw_render_buffers_build(self.0, std::ptr::null(), options, &mut buffers) };
        assert_eq!(status, HW_OK);
        let floats = |which| {
            let (mut data, mut len) = (std::ptr::null(), 0usize);
            // SAFETY: live buffers and writable outputs; the view lives as long as `buffers`.
            unsafe {
                assert_eq!(
                    hw_render_buffers_floats(buffers, which, &mut data, &mut len),
                    HW_OK
                );
                if len == 0 {
                    Vec::new()
                } else {
                    std::slice::from_raw_parts(data, len).to_vec()
                }
            }
        };
        // SAFETY: live buffers, freed once after their last use.
        let result = unsafe {
            (
                hw_render_buffers_n_vertices(buffers),
                floats(HW_RENDER_FLOATS_NORMALS),
                floats(HW_RENDER_FLOATS_UVS),
            )
        };
        // SAFETY: as above.
        unsafe { hw_render_buffers_free(buffers) };
        result
    }
}

impl Drop for CMesh {
    fn drop(&mut self) {
        // SAFETY: a mesh from hw_mesh_read(), freed once.
        unsafe { hw_mesh_free(self.0) };
    }
}

#[test]
fn c_api_defaults_use_file_attributes_and_explicit_shadings_override_them() {
    let mesh = CMesh::read(
        "all_normals.obj",
        &cube_obj("vn 0 0 1\n", |_, _| "//1".into()),
    );
    let mut options = hw_render_options_default();
    assert_eq!(options.shading, HW_SHADING_CORNER_NORMALS);
    let (n, normals, _) = mesh.render(&options);
    assert_eq!(n, 8);
    assert!(normals.chunks_exact(3).all(|n| n == [0.0, 0.0, 1.0]));
    // Each explicit shading computes its own normals (none of them is +z everywhere).
    let mut results = Vec::new();
    for (shading, expected_vertices) in [
        (HW_SHADING_FLAT, 24),
        (HW_SHADING_SMOOTH, 8),
        (HW_SHADING_CREASE, 24),
    ] {
        options.shading = shading;
        options.crease_angle = 0.5;
        let (n, normals, _) = mesh.render(&options);
        assert_eq!(n, expected_vertices, "shading {shading}");
        assert!(
            normals.chunks_exact(3).any(|n| n != [0.0, 0.0, 1.0]),
            "shading {shading}"
        );
        results.push(normals);
    }
    assert_ne!(results[0], results[1]);
    assert_ne!(results[1], results[2]);

    // Normals and uvs on some corners only: everything finite, uvs (0, 0) where the file has none.
    let partial = cube_obj("vt 0.5 0.5\nvn 0 0 -1\n", |f, k| match (f, k) {
        (0, 0) => "/1/1".into(),
        (0, _) => "//1".into(),
        _ => "".into(),
    });
    let mesh = CMesh::read("partial.obj", &partial);
    let (_, normals, uvs) = mesh.render(&hw_render_options_default());
    assert!(normals.iter().chain(&uvs).all(|c| c.is_finite()));
    assert_eq!(
        uvs.chunks_exact(2).filter(|uv| *uv == [0.5, 0.5]).count(),
        1
    );
    assert!(
        uvs.chunks_exact(2)
            .all(|uv| uv == [0.5, 0.5] || uv == [0.0, 0.0])
    );
}
