//! The shaded surface of a mesh as GPU buffers: `f32` vertex attributes and a `u32` triangle index
//! buffer (a VBO and an EBO).
//!
//! Every polygon is triangulated (non-convex faces included). A triangle corner is a mesh corner
//! (a half-edge with a face: the corner at its origin), and its attributes — position, normal,
//! uv — are chosen per corner. Corners of one mesh vertex with bit-identical attributes share a
//! render vertex; where they differ (a flat-shaded edge, a crease, a uv seam) the vertex is split,
//! since OpenGL has one index per vertex for all attributes.

use crate::geom::{VertexNormalWeighting, corner_normals, face_normals, vertex_normals};
use crate::mesh::{FaceId, HalfedgeId, Mesh};
use crate::support::allocation::ensure_room;

use super::error::RenderError;
use super::line_buffer::push_point;
use super::shading::{Shading, VertexLayout};
use super::{Bounds, FallbackReason, PolygonOutcome, PolygonTriangulator};

/// What to build a [`SurfaceBuffer`] with.
#[derive(Clone, Copy, Debug, Default)]
pub struct SurfaceOptions<'a> {
    /// Where normals come from; the default, [`Shading::CornerNormals`], takes `corner_normals`
    /// where they are given and smooth normals elsewhere.
    pub shading: Shading,
    /// Separate arrays or one interleaved array.
    pub layout: VertexLayout,
    /// Per-corner normals, one per half-edge slot (indexed by half-edge id, the corner at the
    /// half-edge's origin), such as a file's `vn` or the mesh's
    /// [`corner_normals`](Mesh::corner_normals). Only [`Shading::CornerNormals`] uses them (a
    /// zero vector there meaning "none"); the other shadings compute every normal.
    pub corner_normals: Option<&'a [[f64; 3]]>,
    /// Per-corner texture coordinates, one per half-edge slot: when given, the buffer has uvs,
    /// copied as given (a mesh read from an OBJ has `(0, 0)` at the corners its file gives none).
    pub corner_uvs: Option<&'a [[f64; 2]]>,
}

/// Vertex attributes and triangles of a mesh, ready for `glBufferData`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SurfaceBuffer {
    /// Layout of the attributes below.
    pub layout: VertexLayout,
    /// x y z per vertex ([`VertexLayout::Separate`]; empty when interleaved).
    pub positions: Vec<f32>,
    /// Unit nx ny nz per vertex ([`VertexLayout::Separate`]; empty when interleaved). Zero for
    /// corners of degenerate faces, which have no normal.
    pub normals: Vec<f32>,
    /// u v per vertex ([`VertexLayout::Separate`] with uvs; empty otherwise).
    pub uvs: Vec<f32>,
    /// [`Self::stride`] floats per vertex: x y z nx ny nz [u v] ([`VertexLayout::Interleaved`];
    /// empty otherwise).
    pub interleaved: Vec<f32>,
    /// Floats per vertex of the interleaved array: 6, or 8 with uvs.
    pub stride: usize,
    /// Per vertex, the mesh vertex it shows.
    pub vertex_sources: Vec<u32>,
    /// Three vertex indices per triangle, counter-clockwise seen from outside.
    pub triangles: Vec<u32>,
    /// Per triangle, the mesh face it comes from.
    pub triangle_faces: Vec<u32>,
    /// Faces whose triangles may not cover them exactly (see [`FallbackReason`]).
    pub fallbacks: Vec<(u32, FallbackReason)>,
    /// Box around the vertices.
    pub bounds: Bounds,
}

impl SurfaceBuffer {
    /// Number of render vertices.
    pub fn n_vertices(&self) -> usize {
        self.vertex_sources.len()
    }

    /// Number of triangles.
    pub fn n_triangles(&self) -> usize {
        self.triangle_faces.len()
    }

    /// `true` when the vertices carry texture coordinates.
    pub fn has_uvs(&self) -> bool {
        self.stride == 8
    }
}

/// The normal of every corner (half-edge slot) under the options' shading; zero for boundary
/// half-edges.
fn shaded_corner_normals(
    mesh: &Mesh,
    options: &SurfaceOptions<'_>,
) -> Result<Vec<[f64; 3]>, RenderError> {
    let halfedges = (0..mesh.n_halfedge_slots()).map(|h| HalfedgeId(h as u32));
    Ok(match options.shading {
        Shading::Flat => {
            let faces = face_normals(mesh);
            halfedges
                .map(|h| {
                    let f = mesh.face(h);
                    if f.is_valid() {
                        faces[f.index()]
                    } else {
                        [0.0; 3]
                    }
                })
                .collect()
        }
        Shading::Smooth(weighting) => {
            let vertices = vertex_normals(mesh, weighting);
            halfedges
                .map(|h| normal_at_origin(mesh, &vertices, h))
                .collect()
        }
        Shading::Crease(angle) => {
            if !angle.is_finite() || angle < 0.0 {
                return Err(RenderError::BadCreaseAngle(angle));
            }
            corner_normals(mesh, angle)
        }
        Shading::CornerNormals(weighting) => given_corner_normals(mesh, options, weighting),
    })
}

/// The vertex normal of `h`'s origin, zero when `h` has none (a deleted half-edge).
fn normal_at_origin(mesh: &Mesh, vertex_normals: &[[f64; 3]], h: HalfedgeId) -> [f64; 3] {
    let v = mesh.origin(h);
    if v.is_valid() {
        vertex_normals[v.index()]
    } else {
        [0.0; 3]
    }
}

/// [`Shading::CornerNormals`]: the given normals at unit length, and the smooth normal with
/// `weighting` at the face corners without one. The smooth normals are only computed when some
/// corner needs them.
fn given_corner_normals(
    mesh: &Mesh,
    options: &SurfaceOptions<'_>,
    weighting: VertexNormalWeighting,
) -> Vec<[f64; 3]> {
    let mut normals = match options.corner_normals {
        Some(given) => given.iter().map(|&n| unit_or_zero(n)).collect(),
        None => vec![[0.0; 3]; mesh.n_halfedge_slots()],
    };
    let lacks_normal = |normals: &[[f64; 3]], h: usize| {
        normals[h] == [0.0; 3] && mesh.face(HalfedgeId(h as u32)).is_valid()
    };
    if (0..normals.len()).any(|h| lacks_normal(&normals, h)) {
        let vertices = vertex_normals(mesh, weighting);
        for h in 0..normals.len() {
            if lacks_normal(&normals, h) {
                normals[h] = normal_at_origin(mesh, &vertices, HalfedgeId(h as u32));
            }
        }
    }
    normals
}

/// `n` scaled to unit length, or zero when it has no direction: zero, or a NaN or infinite
/// component. Scaling by the largest component first keeps tiny and huge vectors from
/// underflowing or overflowing on the way.
fn unit_or_zero(n: [f64; 3]) -> [f64; 3] {
    let largest = n.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if !(largest > 0.0 && largest.is_finite()) || n.iter().any(|c| c.is_nan()) {
        return [0.0; 3];
    }
    let scaled = n.map(|c| c / largest);
    let length = scaled.iter().map(|c| c * c).sum::<f64>().sqrt();
    scaled.map(|c| c / length)
}

/// Checks that a per-corner attribute has one entry per half-edge slot.
fn check_corner_attribute<T>(
    mesh: &Mesh,
    what: &'static str,
    values: Option<&[T]>,
) -> Result<(), RenderError> {
    match values {
        Some(values) if values.len() != mesh.n_halfedge_slots() => {
            Err(RenderError::CornerAttributeLength {
                what,
                expected: mesh.n_halfedge_slots(),
                got: values.len(),
            })
        }
        _ => Ok(()),
    }
}

/// Render vertices deduplicated per mesh vertex: each mesh vertex keeps a short chain of the
/// render vertices made for it, compared by attribute bits (a vertex rarely has more than a few).
struct VertexSplitter {
    first_of_vertex: Vec<u32>,
    next_of_same_vertex: Vec<u32>,
    attributes: Vec<([f32; 3], [f32; 2])>,
    sources: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl VertexSplitter {
    fn new(mesh_vertices: usize) -> Self {
        VertexSplitter {
            first_of_vertex: vec![NONE; mesh_vertices],
            next_of_same_vertex: Vec::new(),
            attributes: Vec::new(),
            sources: Vec::new(),
        }
    }

    /// The render vertex of mesh vertex `v` with this normal and uv, made if new.
    fn vertex(&mut self, v: usize, normal: [f32; 3], uv: [f32; 2]) -> u32 {
        let same_bits = |a: &([f32; 3], [f32; 2])| {
            a.0.map(f32::to_bits) == normal.map(f32::to_bits)
                && a.1.map(f32::to_bits) == uv.map(f32::to_bits)
        };
        let mut r = self.first_of_vertex[v];
        while r != NONE {
            if same_bits(&self.attributes[r as usize]) {
                return r;
            }
            r = self.next_of_same_vertex[r as usize];
        }
        let made = self.sources.len() as u32;
        self.next_of_same_vertex.push(self.first_of_vertex[v]);
        self.first_of_vertex[v] = made;
        self.attributes.push((normal, uv));
        self.sources.push(v as u32);
        made
    }
}

/// Builds the triangles and vertex attributes of every live face of `mesh`.
///
/// # Errors
/// A per-corner attribute without one entry per half-edge slot, or a crease angle that is not a
/// finite non-negative angle.
pub fn surface_buffer(
    mesh: &Mesh,
    options: &SurfaceOptions<'_>,
) -> Result<SurfaceBuffer, RenderError> {
    check_corner_attribute(mesh, "corner normals", options.corner_normals)?;
    check_corner_attribute(mesh, "corner uvs", options.corner_uvs)?;
    // Per half-edge slot, at most: its corner normal and the smooth normals behind it (48
    // bytes), a buffer vertex (position, normal, uv, in both layouts and in the splitter: 84)
    // and a triangle corner with its face (8).
    const BYTES_PER_HALFEDGE: u64 = 140;
    let n_halfedges = mesh.n_halfedge_slots();
    ensure_room(
        n_halfedges as u64 * BYTES_PER_HALFEDGE,
        n_halfedges,
        "half-edges",
    )?;
    let normals = shaded_corner_normals(mesh, options)?;

    let mut splitter = VertexSplitter::new(mesh.n_vertex_slots());
    let mut buffer = SurfaceBuffer {
        layout: options.layout,
        stride: if options.corner_uvs.is_some() { 8 } else { 6 },
        ..SurfaceBuffer::default()
    };
    let mut triangulator = PolygonTriangulator::new();
    let (mut corner_positions, mut corner_vertices, mut local) =
        (Vec::new(), Vec::new(), Vec::new());
    for f in 0..mesh.n_face_slots() {
        let face = FaceId(f as u32);
        if mesh.is_face_deleted(face) {
            continue;
        }
        corner_positions.clear();
        corner_vertices.clear();
        for h in mesh.face_loop(face) {
            let v = mesh.origin(h);
            let uv = options
                .corner_uvs
                .map_or([0.0; 2], |uvs| uvs[h.index()].map(|c| c as f32));
            let normal = normals[h.index()].map(|c| c as f32);
            corner_positions.push(mesh.position(v));
            corner_vertices.push(splitter.vertex(v.index(), normal, uv));
        }
        local.clear();
        if let PolygonOutcome::Fallback(reason) =
            triangulator.triangulate(&corner_positions, &mut local)
        {
            buffer.fallbacks.push((face.0, reason));
        }
        for triangle in &local {
            buffer
                .triangles
                .extend(triangle.map(|k| corner_vertices[k as usize]));
            buffer.triangle_faces.push(face.0);
        }
    }

    let mut positions = Vec::with_capacity(3 * splitter.sources.len());
    for &v in &splitter.sources {
        push_point(&mut positions, mesh.positions()[v as usize]);
    }
    buffer.bounds = Bounds::of_points(&positions);
    match options.layout {
        VertexLayout::Separate => {
            buffer.normals = splitter.attributes.iter().flat_map(|a| a.0).collect();
            if options.corner_uvs.is_some() {
                buffer.uvs = splitter.attributes.iter().flat_map(|a| a.1).collect();
            }
            buffer.positions = positions;
        }
        VertexLayout::Interleaved => {
            buffer.interleaved = Vec::with_capacity(buffer.stride * splitter.sources.len());
            for (xyz, (normal, uv)) in positions.chunks_exact(3).zip(&splitter.attributes) {
                buffer.interleaved.extend_from_slice(xyz);
                buffer.interleaved.extend_from_slice(normal);
                if options.corner_uvs.is_some() {
                    buffer.interleaved.extend_from_slice(uv);
                }
            }
        }
    }
    buffer.vertex_sources = splitter.sources;
    Ok(buffer)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::VertexNormalWeighting;
    use crate::soup::{BuildPolicy, FaceList};
    use crate::surfaces::cube;

    fn unit_cube() -> Mesh {
        let soup = cube(1.0).unwrap();
        Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
            .unwrap()
            .0
    }

    fn with(shading: Shading) -> SurfaceOptions<'static> {
        SurfaceOptions {
            shading,
            ..SurfaceOptions::default()
        }
    }

    fn vertex(attribute: &[f32], r: u32) -> [f32; 3] {
        std::array::from_fn(|axis| attribute[3 * r as usize + axis])
    }

    /// Every triangle's geometric normal agrees with the normals of its corners: the winding is
    /// counter-clockwise seen from where the normals point.
    fn assert_windings_agree_with_normals(buffer: &SurfaceBuffer) {
        for t in buffer.triangles.chunks_exact(3) {
            let [a, b, c] = [0, 1, 2].map(|k| vertex(&buffer.positions, t[k]));
            let (u, v) = (
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            let cross = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            for &r in t {
                let n = vertex(&buffer.normals, r);
                assert!(cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2] > 0.0);
            }
        }
    }

    #[test]
    fn flat_cube_splits_every_corner_and_keeps_face_normals() {
        let mesh = unit_cube();
        let buffer = surface_buffer(&mesh, &with(Shading::Flat)).unwrap();
        assert_eq!(buffer.n_vertices(), 24);
        assert_eq!(buffer.n_triangles(), 12);
        assert_eq!(buffer.positions.len(), 72);
        assert_eq!(buffer.normals.len(), 72);
        assert!(buffer.interleaved.is_empty() && buffer.uvs.is_empty());
        for normal in buffer.normals.chunks_exact(3) {
            let ones = normal.iter().filter(|c| c.abs() == 1.0).count();
            assert_eq!(ones, 1, "axis-aligned unit normal, got {normal:?}");
        }
        assert_windings_agree_with_normals(&buffer);
        // Two triangles per face, face by face.
        assert_eq!(&buffer.triangle_faces[..4], &[0, 0, 1, 1]);
    }

    #[test]
    fn smooth_cube_shares_vertices_with_diagonal_normals() {
        let mesh = unit_cube();
        for weighting in [
            VertexNormalWeighting::Uniform,
            VertexNormalWeighting::Area,
            VertexNormalWeighting::Angle,
        ] {
            let buffer = surface_buffer(&mesh, &with(Shading::Smooth(weighting))).unwrap();
            assert_eq!(buffer.n_vertices(), 8);
            for r in 0..8 {
                let (p, n) = (vertex(&buffer.positions, r), vertex(&buffer.normals, r));
                for axis in 0..3 {
                    let expected = p[axis].signum() / 3f32.sqrt();
                    assert!((n[axis] - expected).abs() < 1e-6);
                }
            }
        }
    }

    #[test]
    fn crease_angle_splits_only_sharp_edges() {
        let mesh = unit_cube();
        let sharp = surface_buffer(&mesh, &with(Shading::Crease(0.5))).unwrap();
        assert_eq!(sharp.n_vertices(), 24);
        assert_windings_agree_with_normals(&sharp);
        let blunt = surface_buffer(&mesh, &with(Shading::Crease(std::f64::consts::PI))).unwrap();
        assert_eq!(blunt.n_vertices(), 8);
    }

    #[test]
    fn interleaved_layout_holds_the_separate_arrays_side_by_side() {
        let mesh = unit_cube();
        let separate = surface_buffer(&mesh, &with(Shading::Flat)).unwrap();
        let interleaved = surface_buffer(
            &mesh,
            &SurfaceOptions {
                shading: Shading::Flat,
                layout: VertexLayout::Interleaved,
                ..SurfaceOptions::default()
            },
        )
        .unwrap();
        assert!(interleaved.positions.is_empty() && interleaved.normals.is_empty());
        assert_eq!(interleaved.stride, 6);
        assert_eq!(interleaved.triangles, separate.triangles);
        for (r, row) in interleaved.interleaved.chunks_exact(6).enumerate() {
            assert_eq!(&row[..3], &separate.positions[3 * r..3 * r + 3]);
            assert_eq!(&row[3..], &separate.normals[3 * r..3 * r + 3]);
        }
    }

    #[test]
    fn given_corner_normals_are_used_and_uvs_split_at_seams() {
        let mesh = unit_cube();
        let slots = mesh.n_halfedge_slots();
        // Every corner gets the same normal, and a uv that depends on its face only: the cube is
        // split at every face border (24 vertices), as a uv atlas would split it.
        let normals = vec![[0.0, 0.0, 1.0]; slots];
        let uvs: Vec<[f64; 2]> = (0..slots)
            .map(|h| {
                let f = mesh.face(HalfedgeId(h as u32));
                [f.0 as f64, 0.5]
            })
            .collect();
        let options = SurfaceOptions {
            shading: Shading::CornerNormals(VertexNormalWeighting::Angle),
            layout: VertexLayout::Interleaved,
            corner_normals: Some(&normals),
            corner_uvs: Some(&uvs),
        };
        let buffer = surface_buffer(&mesh, &options).unwrap();
        assert!(buffer.has_uvs());
        assert_eq!(buffer.stride, 8);
        assert_eq!(buffer.n_vertices(), 24);
        for row in buffer.interleaved.chunks_exact(8) {
            assert_eq!(&row[3..6], &[0.0, 0.0, 1.0]);
            assert_eq!(row[7], 0.5);
        }
        // One normal for all and no uvs (the default shading uses given normals): back to one
        // vertex per mesh vertex.
        let shared = SurfaceOptions {
            corner_normals: Some(&normals),
            ..SurfaceOptions::default()
        };
        assert_eq!(surface_buffer(&mesh, &shared).unwrap().n_vertices(), 8);
    }

    #[test]
    fn explicit_shadings_compute_their_normals_whatever_normals_are_given() {
        let mesh = unit_cube();
        let normals = vec![[0.0, 0.0, 1.0]; mesh.n_halfedge_slots()];
        let mut vertex_counts = Vec::new();
        for shading in [
            Shading::Flat,
            Shading::Smooth(VertexNormalWeighting::Angle),
            Shading::Crease(0.5),
        ] {
            let computed = surface_buffer(&mesh, &with(shading)).unwrap();
            let options = SurfaceOptions {
                corner_normals: Some(&normals),
                ..with(shading)
            };
            assert_eq!(surface_buffer(&mesh, &options).unwrap(), computed);
            vertex_counts.push(computed.n_vertices());
        }
        assert_eq!(vertex_counts, [24, 8, 24]);
        // Without normals, the corner-normal shading is the smooth one with its weighting.
        for weighting in [VertexNormalWeighting::Uniform, VertexNormalWeighting::Area] {
            assert_eq!(
                surface_buffer(&mesh, &with(Shading::CornerNormals(weighting))).unwrap(),
                surface_buffer(&mesh, &with(Shading::Smooth(weighting))).unwrap()
            );
        }
    }

    #[test]
    fn corners_without_a_usable_normal_take_the_smooth_one() {
        let mesh = unit_cube();
        let smooth = vertex_normals(&mesh, VertexNormalWeighting::Angle);
        let inverse_sqrt_2 = std::f64::consts::FRAC_1_SQRT_2;
        // Per face: the given normal, and the normal its corners must get (None: the smooth one).
        let per_face: [([f64; 3], Option<[f64; 3]>); 6] = [
            ([0.0, 0.0, 2.0], Some([0.0, 0.0, 1.0])),
            ([0.0; 3], None),
            ([f64::NAN, 0.0, 1.0], None),
            ([1e-300, 0.0, 0.0], Some([1.0, 0.0, 0.0])),
            (
                [1e300, 1e300, 0.0],
                Some([inverse_sqrt_2, inverse_sqrt_2, 0.0]),
            ),
            ([f64::INFINITY, 0.0, 0.0], None),
        ];
        let given: Vec<[f64; 3]> = (0..mesh.n_halfedge_slots())
            .map(|h| per_face[mesh.face(HalfedgeId(h as u32)).index()].0)
            .collect();
        let options = SurfaceOptions {
            corner_normals: Some(&given),
            ..with(Shading::CornerNormals(VertexNormalWeighting::Angle))
        };
        let buffer = surface_buffer(&mesh, &options).unwrap();
        assert!(buffer.normals.iter().all(|c| c.is_finite()));
        for (triangle, &face) in buffer.triangles.chunks_exact(3).zip(&buffer.triangle_faces) {
            for &r in triangle {
                let v = buffer.vertex_sources[r as usize] as usize;
                let expected = per_face[face as usize].1.unwrap_or(smooth[v]);
                let got = vertex(&buffer.normals, r);
                for axis in 0..3 {
                    assert!(
                        (got[axis] - expected[axis] as f32).abs() <= f32::EPSILON,
                        "face {face}: {got:?} for {expected:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn wrong_attribute_lengths_and_crease_angles_are_refused() {
        let mesh = unit_cube();
        let short = vec![[0.0; 3]; 3];
        let options = SurfaceOptions {
            corner_normals: Some(&short),
            ..SurfaceOptions::default()
        };
        assert!(matches!(
            surface_buffer(&mesh, &options),
            Err(RenderError::CornerAttributeLength { got: 3, .. })
        ));
        for angle in [-0.1, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                surface_buffer(&mesh, &with(Shading::Crease(angle))),
                Err(RenderError::BadCreaseAngle(_))
            ));
        }
    }

    #[test]
    fn non_convex_faces_are_ear_clipped() {
        // An L-shaped hexagon: a fan from corner 0 would cover the notch.
        let positions = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        let list = FaceList::polygons(&positions, &[6], &[0, 1, 2, 3, 4, 5]);
        let mesh = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0;
        let buffer = surface_buffer(&mesh, &with(Shading::Flat)).unwrap();
        assert_eq!(buffer.n_triangles(), 4);
        assert!(buffer.fallbacks.is_empty());
        assert_windings_agree_with_normals(&buffer);
        assert_eq!(buffer.bounds.min, [0.0; 3]);
        assert_eq!(buffer.bounds.max, [2.0, 2.0, 0.0]);
    }
}
