//! Removing degenerate triangles: collapsing their short edges, flipping caps away, removing
//! what cannot be mended in place.

use super::mesh_maps::identity_maps;
use super::tolerance::absolute_on_mesh;
use super::{RepairError, RepairReport, Tolerance};
use crate::doctor::distance;
use crate::geom::exact_orientation::are_collinear;
use crate::geom::{cross, difference};
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

/// Mends the degenerate triangles of `mesh` — triangles whose corners lie on one line, exactly
/// (decided with exact arithmetic), or within `tolerance` of it — and compacts the mesh
/// ([`RepairReport::maps`]). A triangle is degenerate when it has an edge of zero length (or
/// at most the tolerance), or when its corner opposite its longest edge lies on that edge
/// (within the tolerance: a cap, whose angle there is near 180°). Each degenerate triangle, in
/// face order and again whenever an edit changes it:
///
/// - with a short edge (its shortest, when several are): the edge is collapsed, its higher
///   end merged into its lower one ([`RepairReport::merged_vertices`]), which keeps its
///   position; the two triangles beside the edge go, and the surface stays closed around them.
/// - a cap: its longest edge is flipped with the triangle across it
///   ([`RepairReport::flipped_faces`]), when that triangle exists and the two triangles the
///   flip makes are neither degenerate nor turned against the one they replace; both faces
///   stay.
/// - otherwise (a collapse the mesh's link condition refuses, a cap on the boundary or beside
///   a polygon): the triangle is removed, which leaves a boundary where it was.
///
/// Every removed face is in [`RepairReport::removed_faces`], whether collapsed or removed.
/// Faces with more than 3 corners are left as they are. Vertices that only removed faces named
/// stay, isolated (see [`remove_unreferenced_vertices`](super::remove_unreferenced_vertices)).
///
/// Corner data follows its corner: a face's corner at a merged vertex keeps its normal and
/// texture coordinate, now at the kept vertex; a flip's two faces keep the corners of the
/// vertices they still name, and each takes the other's corner at the new edge's far end (as
/// [`Mesh::flip_edge`] does). A kept vertex keeps its attributes.
///
/// Afterwards no triangle is degenerate, so a second run changes nothing. Each edit removes a
/// vertex or a face, or replaces a degenerate triangle by two that are not: the work is linear
/// in the faces, times the valence of the vertices that collapses merge. Refused (the mesh
/// unchanged) for a tolerance that is negative, NaN, infinite or relative above 1; a
/// relative one scales the diagonal of the live vertices' bounding box. When nothing changes
/// the maps are the identity.
pub fn remove_degenerate_faces(
    mesh: &mut Mesh,
    tolerance: Tolerance,
) -> Result<RepairReport, RepairError> {
    let tolerance = absolute_on_mesh(tolerance, mesh)?;
    let n_faces = mesh.n_face_slots();
    let was_live: Vec<bool> = (0..n_faces as u32)
        .map(|f| !mesh.is_face_deleted(FaceId(f)))
        .collect();
    let mut merged_into: Vec<u32> = (0..mesh.n_vertex_slots() as u32).collect();
    let mut flipped_faces = Vec::new();
    let mut changed = false;
    // A stack popped lowest first: faces are taken in order, and again after a collapse
    // changed them.
    let mut pending: Vec<FaceId> = (0..n_faces as u32).rev().map(FaceId).collect();
    let mut is_pending = vec![true; n_faces];
    while let Some(f) = pending.pop() {
        is_pending[f.index()] = false;
        if mesh.is_face_deleted(f) || mesh.face_degree(f) != 3 {
            continue;
        }
        let Some(shape) = triangle_shape(corners(mesh, mesh.face_halfedge(f)), tolerance) else {
            continue;
        };
        changed = true;
        let mended = match shape {
            Shape::ShortEdge(h) => collapse_short_edge(mesh, h, &mut merged_into).inspect(|&v| {
                for g in mesh.vertex_faces(v).collect::<Vec<_>>() {
                    if !is_pending[g.index()] {
                        is_pending[g.index()] = true;
                        pending.push(g);
                    }
                }
            }),
            Shape::Cap(h) => flip_cap(mesh, h, tolerance).map(|across| {
                flipped_faces.push([f.0, across.0]);
                VertexId::INVALID
            }),
        };
        if mended.is_none() {
            // Only a live face is deleted, which cannot fail.
            let _ = mesh.delete_face(f, false);
        }
    }
    if !changed {
        return Ok(RepairReport {
            maps: identity_maps(mesh),
            ..RepairReport::default()
        });
    }

    let merged_vertices: Vec<[u32; 2]> = (0..merged_into.len() as u32)
        .filter(|&v| merged_into[v as usize] != v)
        .map(|v| [v, final_vertex(&merged_into, v)])
        .collect();
    let removed_faces = (0..n_faces as u32)
        .filter(|&f| was_live[f as usize] && mesh.is_face_deleted(FaceId(f)))
        .collect();
    let maps = mesh.garbage_collect();
    Ok(RepairReport {
        maps,
        removed_vertices: merged_vertices.iter().map(|&[v, _]| v).collect(),
        merged_vertices,
        removed_faces,
        flipped_faces,
        ..RepairReport::default()
    })
}

/// How a degenerate triangle is mended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    /// Its shortest edge (this half-edge, in the triangle) is at most the tolerance long.
    ShortEdge(HalfedgeId),
    /// Its corner opposite this half-edge (its longest edge) lies on the edge.
    Cap(HalfedgeId),
}

/// The half-edges of the triangle of `h`, from `h`, with their origins' positions.
fn corners(mesh: &Mesh, h: HalfedgeId) -> [(HalfedgeId, [f64; 3]); 3] {
    let (h1, h2) = (mesh.next(h), mesh.prev(h));
    [h, h1, h2].map(|g| (g, mesh.position(mesh.origin(g))))
}

/// How the triangle whose half-edges and origins are `corners` is degenerate, if it is.
/// Triangles with a non-finite coordinate are not judged.
fn triangle_shape(corners: [(HalfedgeId, [f64; 3]); 3], tolerance: f64) -> Option<Shape> {
    let points = corners.map(|(_, p)| p);
    if !points.iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    let lengths: [f64; 3] = std::array::from_fn(|i| distance(points[i], points[(i + 1) % 3]));
    let shortest = (0..3).min_by(|&i, &j| lengths[i].total_cmp(&lengths[j]))?;
    let zero_length = |i: usize| points[i] == points[(i + 1) % 3];
    if let Some(i) = (0..3).find(|&i| zero_length(i)) {
        return Some(Shape::ShortEdge(corners[i].0));
    }
    if lengths[shortest] <= tolerance {
        return Some(Shape::ShortEdge(corners[shortest].0));
    }
    let longest = (0..3).max_by(|&i, &j| lengths[i].total_cmp(&lengths[j]))?;
    let [a, b, c] = [0, 1, 2].map(|k| points[(longest + k) % 3]);
    let on_line = are_collinear(a, b, c) || (tolerance > 0.0 && height(a, b, c) <= tolerance);
    on_line.then_some(Shape::Cap(corners[longest].0))
}

/// The distance from `c` to the line through `a` and `b` (distinct), from a unit direction so
/// that neither huge nor tiny coordinates over- or underflow.
fn height(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let ab = difference(b, a);
    let length = distance(a, b);
    let unit = ab.map(|x| x / length);
    distance(cross(unit, difference(c, a)), [0.0; 3])
}

/// Whether the triangle `a b c` is degenerate under `tolerance` (as [`triangle_shape`] judges).
fn is_degenerate(points: [[f64; 3]; 3], tolerance: f64) -> bool {
    let corners = points.map(|p| (HalfedgeId::INVALID, p));
    triangle_shape(corners, tolerance).is_some()
}

/// Collapses the edge of `h` into its lower end (or, when the mesh refuses, into its higher
/// one), recording the merge; gives the kept vertex, or `None` when neither way is allowed.
fn collapse_short_edge(
    mesh: &mut Mesh,
    h: HalfedgeId,
    merged_into: &mut [u32],
) -> Option<VertexId> {
    let into_lower = if mesh.origin(h) > mesh.target(h) {
        h
    } else {
        h.twin()
    };
    for g in [into_lower, into_lower.twin()] {
        let gone = mesh.origin(g);
        if let Ok(kept) = mesh.collapse_halfedge(g) {
            merged_into[gone.index()] = kept.0;
            return Some(kept);
        }
    }
    None
}

/// Flips the cap's longest edge `h` (`a → b`, the cap's corner `c` on it) with the triangle
/// `b a d` across it, giving `d c a` and `c d b`; gives the face across, or `None` (nothing
/// changed) when there is none, the mesh refuses the flip, or a new triangle would be
/// degenerate or turned against `b a d`.
fn flip_cap(mesh: &mut Mesh, h: HalfedgeId, tolerance: f64) -> Option<FaceId> {
    let across = h.twin();
    if mesh.is_boundary_halfedge(across) || mesh.can_flip_edge(h.edge()).is_err() {
        return None;
    }
    let at = |g: HalfedgeId| mesh.position(mesh.origin(g));
    let (a, b, c, d) = (at(h), at(across), at(mesh.prev(h)), at(mesh.prev(across)));
    let replaced = cross(difference(a, b), difference(d, b));
    for new in [[d, c, a], [c, d, b]] {
        let normal = cross(difference(new[1], new[0]), difference(new[2], new[0]));
        let agrees = normal
            .iter()
            .zip(&replaced)
            .map(|(x, y)| x * y)
            .sum::<f64>()
            > 0.0;
        if !agrees || is_degenerate(new, tolerance) {
            return None;
        }
    }
    let face = mesh.face(across);
    mesh.flip_edge(h.edge()).ok()?;
    Some(face)
}

/// The vertex `v` ends in, following merges.
fn final_vertex(merged_into: &[u32], mut v: u32) -> u32 {
    while merged_into[v as usize] != v {
        v = merged_into[v as usize];
    }
    v
}
