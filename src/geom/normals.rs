//! Face, vertex and corner normals of a polygon mesh.
//!
//! - Face normals: Newell's method (Baumgart's loop), so non-planar polygons get their best-fit
//!   plane's normal; degenerate faces get the zero vector.
//! - Vertex normals: the sum over the vertex's faces of a weighted face normal, normalised, in one
//!   linear pass over the faces (the face-list algorithm), so every fan of a
//!   non-manifold vertex counts. Weightings: [`VertexNormalWeighting`].
//! - Corner normals (per half-edge, the "winged half-edges" of the Granada notes): angle-weighted like
//!   vertex normals, but only over the faces reachable around the vertex without crossing a
//!   boundary or an edge sharper than the crease angle.
//!
//! Isolated vertices and boundary half-edges get the zero vector.
//!
//! Face and vertex normals come from one set of passes over a [`PolygonFaces`], which both
//! kernels give: the half-edge [`Mesh`] and the winged structure
//! ([`Winged`](crate::winged::Winged)) get the same normals, bit for bit, for the same faces with
//! the same first corners. A vertex sums its faces in face id order, each face's corners in loop
//! order, whether every vertex is computed or one alone.

use crate::mesh::{FaceId, HalfedgeId, Mesh};

use super::newell::rescued_area_vector;
use super::polygon_faces::{PolygonFaces, SmallFace, gather};
use super::{face_corners_area_vector, quad_area_vector, triangle_area_vector};

/// How a vertex normal weighs the normals of the faces around the vertex.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum VertexNormalWeighting {
    /// Unit face normals summed (OpenMesh's default; Baumgart's winged-edge vertex normal).
    #[default]
    Uniform,
    /// Face normals weighted by face area (the raw Newell vectors summed).
    Area,
    /// Unit face normals weighted by the face's interior angle at the vertex (pmp's default).
    Angle,
}

impl VertexNormalWeighting {
    /// Every weighting.
    pub const ALL: [VertexNormalWeighting; 3] = [
        VertexNormalWeighting::Uniform,
        VertexNormalWeighting::Area,
        VertexNormalWeighting::Angle,
    ];
}

/// Unit normal of every face slot (zero for degenerate and deleted faces), indexed by face id.
pub fn face_normals(mesh: &Mesh) -> Vec<[f64; 3]> {
    face_normals_of(mesh)
}

/// [`face_normals`] written into `out`, one entry per face slot (`mesh.n_face_slots()`): the
/// form for callers that own the buffer (the C API).
///
/// # Panics
/// When `out.len() != mesh.n_face_slots()`.
pub fn face_normals_into(mesh: &Mesh, out: &mut [[f64; 3]]) {
    face_normals_into_of(mesh, out)
}

/// Newell vector of face `f`: along its normal, twice its area long; when that length would
/// overflow or underflow a double (coordinates near 1e308, faces smaller than about 1e-154),
/// along its normal at another length. Zero for no face.
pub fn face_area_vector(mesh: &Mesh, f: FaceId) -> [f64; 3] {
    if f.index() >= mesh.n_face_slots() {
        return [0.0; 3];
    }
    area_vector_of(mesh, f.0)
}

/// Unit normal of every vertex slot, indexed by vertex id, from the faces' normals. One pass over
/// the faces, with no per-face array: each face's normal is computed and scattered to its corners.
pub fn vertex_normals(mesh: &Mesh, weighting: VertexNormalWeighting) -> Vec<[f64; 3]> {
    vertex_normals_of(mesh, weighting)
}

/// Face normals (as [`face_normals`]) and vertex normals (as [`vertex_normals`]) in one pass,
/// as OpenMesh's `update_normals` gives them.
pub fn face_and_vertex_normals(
    mesh: &Mesh,
    weighting: VertexNormalWeighting,
) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    face_and_vertex_normals_of(mesh, weighting)
}

/// Vertex normals, and face normals when `faces` is given, written into caller buffers (one
/// entry per vertex slot, one per face slot) in one pass.
///
/// # Panics
/// When a buffer's length is not the slot count.
pub fn normals_into(
    mesh: &Mesh,
    weighting: VertexNormalWeighting,
    faces: Option<&mut [[f64; 3]]>,
    vertices: &mut [[f64; 3]],
) {
    assert_eq!(
        vertices.len(),
        mesh.n_vertex_slots(),
        "one normal per vertex slot"
    );
    normals_into_of(mesh, weighting, faces, vertices)
}

/// [`face_normals`] of either kernel.
pub(crate) fn face_normals_of(mesh: &impl PolygonFaces) -> Vec<[f64; 3]> {
    let mut normals = vec![[0.0; 3]; mesh.face_slot_count()];
    face_normals_into_of(mesh, &mut normals);
    normals
}

/// [`face_normals_into`] of either kernel.
fn face_normals_into_of(mesh: &impl PolygonFaces, out: &mut [[f64; 3]]) {
    assert_eq!(
        out.len(),
        mesh.face_slot_count(),
        "one normal per face slot"
    );
    let normal = |f: usize| {
        if mesh.is_live_face(f as u32) {
            normalized(area_vector_of(mesh, f as u32))
        } else {
            [0.0; 3]
        }
    };
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        out.par_iter_mut()
            .with_min_len(4096)
            .enumerate()
            .for_each(|(f, n)| *n = normal(f));
    }
    #[cfg(not(feature = "parallel"))]
    {
        out.iter_mut().enumerate().for_each(|(f, n)| *n = normal(f));
    }
}

/// The unit normal of live face `f` of either kernel: what [`face_normals_of`] gives it.
pub(crate) fn face_normal_of(mesh: &impl PolygonFaces, f: u32) -> [f64; 3] {
    normalized(area_vector_of(mesh, f))
}

/// [`face_area_vector`] of live face `f` of either kernel.
fn area_vector_of(mesh: &impl PolygonFaces, f: u32) -> [f64; 3] {
    let corners = || mesh.corners(f).map(|v| mesh.positions()[v as usize]);
    let area_vector = mesh
        .small_face(f)
        .area_vector(mesh.positions())
        .unwrap_or_else(|| face_corners_area_vector(corners()));
    rescued_area_vector(area_vector, || corners().collect())
}

/// [`vertex_normals`] of either kernel.
pub(crate) fn vertex_normals_of(
    mesh: &impl PolygonFaces,
    weighting: VertexNormalWeighting,
) -> Vec<[f64; 3]> {
    let mut vertices = vec![[0.0; 3]; mesh.positions().len()];
    normals_into_of(mesh, weighting, None, &mut vertices);
    vertices
}

/// [`face_and_vertex_normals`] of either kernel.
fn face_and_vertex_normals_of(
    mesh: &impl PolygonFaces,
    weighting: VertexNormalWeighting,
) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let mut faces = vec![[0.0; 3]; mesh.face_slot_count()];
    let mut vertices = vec![[0.0; 3]; mesh.positions().len()];
    normals_into_of(mesh, weighting, Some(&mut faces), &mut vertices);
    (faces, vertices)
}

/// [`normals_into`] of either kernel; `vertices` has one entry per position.
fn normals_into_of(
    mesh: &impl PolygonFaces,
    weighting: VertexNormalWeighting,
    faces: Option<&mut [[f64; 3]]>,
    vertices: &mut [[f64; 3]],
) {
    match faces {
        Some(faces) => {
            assert_eq!(
                faces.len(),
                mesh.face_slot_count(),
                "one normal per face slot"
            );
            // Live faces come in increasing id order: the slots between two of them (deleted
            // faces) are zeroed as they are passed, not the whole buffer first (that memset was
            // a sixth of the pass).
            let mut unwritten = 0;
            accumulate_normals(
                mesh,
                weighting,
                |f, unit| {
                    let f = f as usize;
                    faces[unwritten..f].fill([0.0; 3]);
                    faces[f] = unit;
                    unwritten = f + 1;
                },
                vertices,
            );
            faces[unwritten..].fill([0.0; 3]);
        }
        None => accumulate_normals(mesh, weighting, |_, _| {}, vertices),
    }
}

/// The unit normal of vertex `v` of either kernel under `weighting`: what [`vertex_normals_of`]
/// gives it, bit for bit (its faces in id order, each by the pass's own arithmetic).
pub(crate) fn vertex_normal_of(
    mesh: &impl PolygonFaces,
    v: u32,
    weighting: VertexNormalWeighting,
) -> [f64; 3] {
    let mut faces = mesh.faces_at(v);
    faces.sort_unstable();
    faces.dedup();
    let mut sum = [0.0; 3];
    for f in faces {
        share_face(
            mesh,
            f,
            weighting,
            &mut |_, _| {},
            &mut |at, normal, weight| {
                if at == v {
                    add_scaled(&mut sum, normal, weight);
                }
            },
        );
    }
    normalized(sum)
}

/// The shared pass: for each live face, its unit normal goes to `visit_face` and its weighted
/// normal to each corner's vertex sum in `sums`; the sums are normalised at the end.
fn accumulate_normals(
    mesh: &impl PolygonFaces,
    weighting: VertexNormalWeighting,
    mut visit_face: impl FnMut(u32, [f64; 3]),
    sums: &mut [[f64; 3]],
) {
    assert_eq!(
        sums.len(),
        mesh.positions().len(),
        "one normal per vertex slot"
    );
    sums.fill([0.0; 3]);
    // One copy of the loop per weighting, each with its weighting a constant: the per-face
    // choices and the unit corner weights then fold away (the shared loop cost the half-edge
    // vertex normals 10 % more instructions).
    match weighting {
        VertexNormalWeighting::Uniform => {
            share_live_faces(mesh, VertexNormalWeighting::Uniform, &mut visit_face, sums)
        }
        VertexNormalWeighting::Area => {
            share_live_faces(mesh, VertexNormalWeighting::Area, &mut visit_face, sums)
        }
        VertexNormalWeighting::Angle => {
            share_live_faces(mesh, VertexNormalWeighting::Angle, &mut visit_face, sums)
        }
    }
    for sum in sums.iter_mut() {
        *sum = normalized(*sum);
    }
}

/// [`share_face`] for every live face, adding into `sums`.
#[inline(always)]
fn share_live_faces(
    mesh: &impl PolygonFaces,
    weighting: VertexNormalWeighting,
    visit_face: &mut impl FnMut(u32, [f64; 3]),
    sums: &mut [[f64; 3]],
) {
    for f in mesh.live_faces() {
        share_face(mesh, f, weighting, visit_face, &mut |v, normal, weight| {
            add_scaled(&mut sums[v as usize], normal, weight)
        });
    }
}

/// What live face `f` gives the normals: its unit normal to `visit_face`, then corner by corner
/// in loop order the corner's vertex, the face's weighted normal and the corner's weight to
/// `add` (the vertex's sum gains the normal times the weight). Triangles and quads under the
/// weightings that give all corners one normal take the fixed-size reads of [`SmallFace`]; other
/// faces take [`share_polygon`].
#[inline(always)]
fn share_face(
    mesh: &impl PolygonFaces,
    f: u32,
    weighting: VertexNormalWeighting,
    visit_face: &mut impl FnMut(u32, [f64; 3]),
    add: &mut impl FnMut(u32, [f64; 3], f64),
) {
    if weighting != VertexNormalWeighting::Angle {
        let corners = mesh.small_face(f);
        if let Some(area_vector) = corners.area_vector(mesh.positions()) {
            let unit = normalized(area_vector);
            // No area, or a length out of a double's range: the general walk rescues the latter.
            if unit != [0.0; 3] {
                visit_face(f, unit);
                let normal = face_weighted(weighting, area_vector, unit);
                corners.for_each_corner(|v| add(v, normal, 1.0));
                return;
            }
        }
    }
    share_polygon(mesh, f, weighting, visit_face, add);
}

/// [`share_face`] by the general walk around the face: any degree, any weighting.
#[inline(never)]
fn share_polygon(
    mesh: &impl PolygonFaces,
    f: u32,
    weighting: VertexNormalWeighting,
    visit_face: &mut impl FnMut(u32, [f64; 3]),
    add: &mut impl FnMut(u32, [f64; 3], f64),
) {
    let positions = mesh.positions();
    let area_vector = area_vector_of(mesh, f);
    let unit = normalized(area_vector);
    visit_face(f, unit);
    let face_normal = face_weighted(weighting, area_vector, unit);
    match mesh.small_face(f) {
        SmallFace::Triangle(corners) => {
            share_corners(positions, corners.into_iter(), weighting, face_normal, add)
        }
        SmallFace::Quad(corners) => {
            share_corners(positions, corners.into_iter(), weighting, face_normal, add)
        }
        SmallFace::Larger => share_corners(positions, mesh.corners(f), weighting, face_normal, add),
    }
}

/// Gives `add` each of `corners` (a face's, in loop order) with `face_normal` and the corner's
/// weight: its angle between the corners before and after it under `Angle`, else 1.
#[inline(always)]
fn share_corners(
    positions: &[[f64; 3]],
    corners: impl Iterator<Item = u32> + Clone,
    weighting: VertexNormalWeighting,
    face_normal: [f64; 3],
    add: &mut impl FnMut(u32, [f64; 3], f64),
) {
    if weighting != VertexNormalWeighting::Angle {
        corners.for_each(|v| add(v, face_normal, 1.0));
        return;
    }
    let (Some(first), Some(last)) = (corners.clone().next(), corners.clone().last()) else {
        return;
    };
    let (mut previous, mut at) = (last, first);
    for next in corners.skip(1).chain(std::iter::once(first)) {
        let weight = angle_between(
            positions[at as usize],
            positions[next as usize],
            positions[previous as usize],
        );
        add(at, face_normal, weight);
        (previous, at) = (at, next);
    }
}

/// The normal a face gives each of its corners under `weighting`, before the corner's own weight
/// (its angle, under `Angle`).
#[inline(always)]
fn face_weighted(
    weighting: VertexNormalWeighting,
    area_vector: [f64; 3],
    unit: [f64; 3],
) -> [f64; 3] {
    match weighting {
        VertexNormalWeighting::Area => area_vector,
        _ => unit,
    }
}

impl SmallFace {
    /// The face's area vector, as [`face_corners_area_vector`] gives it for the same corners
    /// (`None` for a larger face).
    #[inline(always)]
    fn area_vector(&self, positions: &[[f64; 3]]) -> Option<[f64; 3]> {
        match *self {
            SmallFace::Triangle(corners) => {
                let [a, b, c] = gather(positions, corners);
                Some(triangle_area_vector(a, b, c))
            }
            SmallFace::Quad(corners) => {
                let [a, b, c, d] = gather(positions, corners);
                Some(quad_area_vector(a, b, c, d))
            }
            SmallFace::Larger => None,
        }
    }

    /// Calls `visit` with each corner in loop order (none for a larger face).
    #[inline(always)]
    fn for_each_corner(&self, visit: impl FnMut(u32)) {
        match *self {
            SmallFace::Triangle(corners) => corners.into_iter().for_each(visit),
            SmallFace::Quad(corners) => corners.into_iter().for_each(visit),
            SmallFace::Larger => {}
        }
    }
}

/// Unit normal of every half-edge slot's corner (the corner at `origin(h)` inside `face(h)`),
/// indexed by half-edge id: the angle-weighted average of the face normals around the vertex that
/// are reachable from `face(h)` without crossing a boundary or an edge whose two faces' normals
/// differ by more than `crease_angle` radians. With `crease_angle >= π` it is the angle-weighted
/// vertex normal (per fan); with `crease_angle == 0` it is the face normal for a faceted look.
pub fn corner_normals(mesh: &Mesh, crease_angle: f64) -> Vec<[f64; 3]> {
    let unit_face_normals = face_normals(mesh);
    let cos_crease = crease_angle.cos();
    let smooth_across = |a: FaceId, b: FaceId| {
        b.is_valid()
            && (crease_angle >= std::f64::consts::PI
                || dot(unit_face_normals[a.index()], unit_face_normals[b.index()]) >= cos_crease)
    };
    let corner = |h: usize| -> [f64; 3] {
        let h = HalfedgeId(h as u32);
        let face = mesh.face(h);
        if !face.is_valid() || mesh.is_halfedge_deleted(h) {
            return [0.0; 3];
        }
        let mut sum = [0.0; 3];
        add_scaled(
            &mut sum,
            unit_face_normals[face.index()],
            corner_angle(mesh, h),
        );
        // Turns from h by `turn`, adding each corner met while the faces stay smooth; `true` when
        // the turn came back to h (a closed fan: nothing is left to gather the other way).
        let budget = mesh.n_halfedge_slots();
        let gather = |sum: &mut [f64; 3], turn: &dyn Fn(HalfedgeId) -> HalfedgeId| -> bool {
            let mut g = h;
            for _ in 0..budget {
                let rotated = turn(g);
                if rotated == h {
                    return true;
                }
                if !smooth_across(mesh.face(g), mesh.face(rotated)) {
                    return false;
                }
                add_scaled(
                    sum,
                    unit_face_normals[mesh.face(rotated).index()],
                    corner_angle(mesh, rotated),
                );
                g = rotated;
            }
            false
        };
        // Counter-clockwise crosses the edge of prev(g) into face(twin(prev(g))); clockwise crosses
        // the edge of g into face(next(twin(g))).
        if !gather(&mut sum, &|g| mesh.prev(g).twin()) {
            gather(&mut sum, &|g| mesh.next(g.twin()));
        }
        normalized(sum)
    };
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        (0..mesh.n_halfedge_slots())
            .into_par_iter()
            .with_min_len(4096)
            .map(corner)
            .collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        (0..mesh.n_halfedge_slots()).map(corner).collect()
    }
}

/// Interior angle of `face(h)` at `origin(h)`, between the edges to `target(h)` and to
/// `origin(prev(h))`, in radians (0 for a zero-length edge).
pub fn corner_angle(mesh: &Mesh, h: HalfedgeId) -> f64 {
    angle_between(
        mesh.position(mesh.origin(h)),
        mesh.position(mesh.target(h)),
        mesh.position(mesh.origin(mesh.prev(h))),
    )
}

/// The angle at corner `at` between the edges to `next` and to `previous`, in radians (0 for a
/// zero-length edge).
#[inline]
fn angle_between(at: [f64; 3], next: [f64; 3], previous: [f64; 3]) -> f64 {
    // Each edge vector scaled to a largest component of 1 (halved first, so no difference
    // overflows): the angle does not change, and no product over- or underflows at any scale.
    let direction = |to: [f64; 3]| {
        let half: [f64; 3] = std::array::from_fn(|k| 0.5 * to[k] - 0.5 * at[k]);
        let largest = half.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        // A division, not a reciprocal: 1 / largest overflows for subnormal edges.
        if largest > 0.0 {
            half.map(|x| x / largest)
        } else {
            half
        }
    };
    let to_next = direction(next);
    let to_prev = direction(previous);
    let c = cross(to_next, to_prev);
    // atan2 of |a×b| and a·b is accurate for small and near-π angles alike.
    dot(c, c).sqrt().atan2(dot(to_next, to_prev))
}

fn add_scaled(sum: &mut [f64; 3], v: [f64; 3], weight: f64) {
    for i in 0..3 {
        sum[i] += weight * v[i];
    }
}

pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v / |v|`, or zero when `v` is zero or not finite. One division and three products (within
/// an ulp of three divisions): this runs once per face and once per vertex in every normal pass.
pub(crate) fn normalized(v: [f64; 3]) -> [f64; 3] {
    let length = dot(v, v).sqrt();
    // Also false for NaN.
    if length > 0.0 && length < f64::INFINITY {
        let inverse = 1.0 / length;
        [v[0] * inverse, v[1] * inverse, v[2] * inverse]
    } else {
        [0.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::VertexId;
    use crate::soup::{BuildPolicy, FaceList};

    /// The unit cube [0,1]^3 as six outward quads.
    fn cube() -> Mesh {
        let positions: Vec<[f64; 3]> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
            .collect();
        let quads = [
            0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
        ];
        let list = FaceList {
            positions: &positions,
            sizes: crate::soup::FaceSizes::Uniform(4),
            indices: &quads,
        };
        Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0
    }

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    #[test]
    fn cube_face_normals_point_outwards() {
        let mesh = cube();
        let normals = face_normals(&mesh);
        assert!(close(normals[0], [0.0, 0.0, -1.0]));
        assert!(close(normals[1], [0.0, 0.0, 1.0]));
        for f in 0..6 {
            let centre = mesh.face_vertices(FaceId(f)).fold([0.0; 3], |mut c, v| {
                add_scaled(&mut c, mesh.position(v), 0.25);
                c
            });
            assert!(dot(normals[f as usize], centre.map(|x| x - 0.5)) > 0.0);
        }
    }

    #[test]
    fn cube_vertex_normals_are_diagonals_for_every_weighting() {
        let mesh = cube();
        let diagonal = 1.0 / 3f64.sqrt();
        for weighting in VertexNormalWeighting::ALL {
            let normals = vertex_normals(&mesh, weighting);
            for v in 0..8 {
                let p = mesh.position(VertexId(v));
                let expected = p.map(|c| if c > 0.5 { diagonal } else { -diagonal });
                assert!(
                    close(normals[v as usize], expected),
                    "{weighting:?} v{v}: {:?}",
                    normals[v as usize]
                );
            }
        }
    }

    #[test]
    fn one_pass_normals_match_the_separate_ones() {
        let mesh = cube();
        for weighting in VertexNormalWeighting::ALL {
            let (faces, vertices) = face_and_vertex_normals(&mesh, weighting);
            assert_eq!(faces, face_normals(&mesh));
            assert_eq!(vertices, vertex_normals(&mesh, weighting));
        }
    }

    #[test]
    fn one_pass_into_dirty_buffers_zeroes_deleted_faces_before_between_and_after_live_ones() {
        let mut mesh = cube();
        for f in [0, 2, 5] {
            mesh.delete_face(FaceId(f), false).unwrap();
        }
        for weighting in VertexNormalWeighting::ALL {
            let mut faces = vec![[7.0; 3]; mesh.n_face_slots()];
            let mut vertices = vec![[7.0; 3]; mesh.n_vertex_slots()];
            normals_into(&mesh, weighting, Some(&mut faces), &mut vertices);
            assert_eq!(faces, face_normals(&mesh), "{weighting:?}");
            for f in [0, 2, 5] {
                assert_eq!(faces[f], [0.0; 3], "{weighting:?} deleted face {f}");
            }
            assert_eq!(vertices, vertex_normals(&mesh, weighting), "{weighting:?}");
        }
    }

    /// A triangle, a quad and a pentagon side by side in the plane z = 0, seen from +z.
    fn mixed_degrees() -> Mesh {
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [3.0, 0.5, 0.0],
            [2.5, 1.5, 0.0],
        ];
        let (sizes, indices) = ([3, 4, 5], [0, 1, 2, 1, 4, 3, 2, 4, 6, 7, 5, 3]);
        let list = FaceList::polygons(&positions, &sizes, &indices);
        Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0
    }

    #[test]
    fn every_face_degree_gets_its_newell_normal_in_every_pass() {
        let mut mesh = mixed_degrees();
        for f in 0..3 {
            let walked = super::super::newell_vector(
                mesh.face_vertices(FaceId(f)).map(|v| mesh.position(v)),
            );
            assert!(
                close(face_area_vector(&mesh, FaceId(f)), walked),
                "face {f}"
            );
            assert!(walked[2] > 0.0, "face {f} is counter-clockwise");
        }
        assert_eq!(face_area_vector(&mesh, FaceId(3)), [0.0; 3], "no such face");
        for weighting in [VertexNormalWeighting::Uniform, VertexNormalWeighting::Area] {
            let (faces, vertices) = face_and_vertex_normals(&mesh, weighting);
            assert_eq!(faces, face_normals(&mesh));
            assert!(
                faces
                    .iter()
                    .chain(&vertices)
                    .all(|&n| close(n, [0.0, 0.0, 1.0]))
            );
        }
        mesh.delete_face(FaceId(1), false).unwrap();
        let (faces, vertices) = face_and_vertex_normals(&mesh, VertexNormalWeighting::Uniform);
        assert_eq!(faces, [[0.0, 0.0, 1.0], [0.0; 3], [0.0, 0.0, 1.0]]);
        assert_eq!(faces, face_normals(&mesh));
        assert!(close(vertices[4], [0.0, 0.0, 1.0]), "still on the pentagon");
    }

    #[test]
    fn crease_angle_splits_or_smooths_corners() {
        let mesh = cube();
        let faces = face_normals(&mesh);
        let sharp = corner_normals(&mesh, 30f64.to_radians());
        let smooth = corner_normals(&mesh, std::f64::consts::PI);
        let vertex = vertex_normals(&mesh, VertexNormalWeighting::Angle);
        for h in 0..mesh.n_halfedge_slots() as u32 {
            let h = HalfedgeId(h);
            assert!(close(sharp[h.index()], faces[mesh.face(h).index()]));
            assert!(close(smooth[h.index()], vertex[mesh.origin(h).index()]));
        }
    }

    #[test]
    fn corner_angles_of_a_square_are_right_angles() {
        let mesh = cube();
        let total: f64 = mesh
            .face_loop(FaceId(0))
            .map(|h| corner_angle(&mesh, h))
            .sum();
        assert!((total - 2.0 * std::f64::consts::PI).abs() < 1e-12);
    }

    #[test]
    fn open_fan_corner_normals_stop_at_the_boundary() {
        // Two triangles folded at 90° along edge 0-1; crease 45° keeps them apart.
        let positions = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, -1.0],
        ];
        let list = FaceList::triangles(&positions, &[0, 1, 2, 1, 0, 3]);
        let mesh = Mesh::from_face_list(&list, BuildPolicy::Strict).unwrap().0;
        let faces = face_normals(&mesh);
        let corners = corner_normals(&mesh, 45f64.to_radians());
        let merged = corner_normals(&mesh, 100f64.to_radians());
        let h = mesh.face_halfedge(FaceId(0));
        assert!(close(corners[h.index()], faces[0]));
        assert!(!close(merged[h.index()], faces[0]));
        let boundary =
            (0..mesh.n_halfedge_slots()).find(|&h| !mesh.face(HalfedgeId(h as u32)).is_valid());
        assert_eq!(corners[boundary.unwrap()], [0.0; 3]);
    }
}
