//! Self-intersections: pairs of faces that meet other than along the vertices and edges they
//! share, decided exactly (see [`crate::geom::face_self_intersections`]).

use crate::geom::{SelfIntersectionError, face_self_intersections};
use crate::soup::{FaceList, FaceTable};

/// The pairs `[f, g]`, `f < g`, sorted, of input faces of `surface` that intersect. Faces with a
/// corner at a non-finite position are left out (the diagnostic lists those vertices), and so
/// are triangles with exactly collinear corners, which intersect nothing in particular (their
/// faces are among the diagnostic's zero-area faces).
///
/// # Errors
/// Only a triangulation too large for 32-bit indices.
pub(super) fn self_intersections(
    surface: &FaceTable<'_>,
    positions: &[[f64; 3]],
) -> Result<Vec<[u32; 2]>, SelfIntersectionError> {
    let finite = |v: &u32| positions[*v as usize].iter().all(|x| x.is_finite());
    let mut sizes = Vec::with_capacity(surface.n_faces());
    let mut indices = Vec::with_capacity(surface.n_corners());
    let mut input_faces = Vec::with_capacity(surface.n_faces());
    for f in 0..surface.n_faces() {
        let face = surface.face(f);
        if face.iter().all(finite) {
            sizes.push(face.len() as u32);
            indices.extend_from_slice(face);
            input_faces.push(surface.input_face(f));
        }
    }
    let list = FaceList::polygons(positions, &sizes, &indices);
    let pairs = face_self_intersections(&list)?;
    let mut found: Vec<[u32; 2]> = pairs
        .into_iter()
        .filter(|[f, g]| f != g)
        .map(|[f, g]| {
            let (f, g) = (input_faces[f as usize], input_faces[g as usize]);
            [f.min(g), f.max(g)]
        })
        .collect();
    found.sort_unstable();
    Ok(found)
}
