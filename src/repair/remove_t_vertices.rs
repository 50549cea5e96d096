//! Removing T-vertices: splitting a boundary edge where another boundary's vertex lies on it.

use std::cmp::Ordering;

use super::mesh_maps::identity_maps;
use super::tolerance::absolute_on_mesh;
use super::{RepairError, RepairReport, Tolerance};
use crate::doctor::{PointTree, lies_inside_segment};
use crate::geom::exact_orientation::are_collinear;
use crate::geom::{difference, dot};
use crate::mesh::{EdgeId, HalfedgeId, Mesh, VertexId};

/// Splits the boundary edges of `mesh` on whose inside a boundary vertex of another face lies
/// (a T-vertex: exactly on the edge, or within `tolerance` of it, strictly between its ends and
/// at neither end's position), so that the crack beside the edge has matching edges on both
/// sides: [`stitch_borders`](super::stitch_borders) can then close it. Then compacts the mesh
/// ([`RepairReport::maps`]).
///
/// A T-vertex splits every boundary edge it lies on, except where the edge's own face has a
/// corner at its position (the split would put that position twice in the face); of several
/// T-vertices at one position on an edge only the lowest is taken. So afterwards no boundary
/// vertex lies inside a boundary edge, and a second run changes nothing. Each edge is split at its
/// T-vertices in order along it, each time by a new vertex at the T-vertex's position: the
/// `i`-th new vertex copies T-vertex [`RepairReport::vertex_copies`]`[i]` (its id is `n + i`, `n`
/// the live vertex count before). Its attributes are interpolated between the edge's ends, and
/// the face beside the edge gains a corner there whose data is interpolated between its
/// neighbours (as [`Mesh::split_edge`] gives them); a triangle so becomes a polygon with a
/// straight corner, which stitching turns into an interior corner. Nothing is removed.
///
/// Moving the T-vertex onto the edge's nearer end instead (the collapse variant) is not
/// offered: it moves geometry, and with a tolerance can fold the faces around it.
///
/// O(n log n) for T-vertices scattered over the boundary: the boundary vertices near each edge
/// come from a tree of the boundary vertices split at medians. Refused (the mesh unchanged) for
/// a tolerance that is negative, NaN, infinite or relative above 1; a relative one scales the
/// diagonal of the live vertices' bounding box. When no edge is split the mesh is unchanged and
/// the maps are the identity.
pub fn remove_t_vertices(
    mesh: &mut Mesh,
    tolerance: Tolerance,
) -> Result<RepairReport, RepairError> {
    let tolerance = absolute_on_mesh(tolerance, mesh)?;
    let splits = t_vertex_splits(mesh, tolerance);
    if splits.is_empty() {
        return Ok(RepairReport {
            maps: identity_maps(mesh),
            ..RepairReport::default()
        });
    }
    let capacities = [
        mesh.n_vertex_slots(),
        mesh.n_halfedge_slots(),
        mesh.n_edge_slots(),
        mesh.n_face_slots(),
    ];
    let mut vertex_copies = Vec::with_capacity(splits.len());
    for run in splits.chunk_by(|x, y| x.edge == y.edge) {
        let far_end = mesh.target(run[0].edge);
        let mut edge: EdgeId = run[0].edge.edge();
        for split in run {
            let position = mesh.position(VertexId(split.vertex));
            let Ok(w) = mesh.split_edge(edge, position) else {
                // Only a mesh full to 32-bit ids refuses; the splits made so far stand.
                break;
            };
            vertex_copies.push(split.vertex);
            match mesh.find_halfedge(w, far_end) {
                Some(rest) => edge = rest.edge(),
                None => break,
            }
        }
    }
    let mut maps = mesh.garbage_collect();
    // The maps cover the elements there were before; new ones follow them in order.
    maps.vertices.truncate(capacities[0]);
    maps.halfedges.truncate(capacities[1]);
    maps.edges.truncate(capacities[2]);
    maps.faces.truncate(capacities[3]);
    Ok(RepairReport {
        maps,
        vertex_copies,
        ..RepairReport::default()
    })
}

/// A boundary half-edge to split at a T-vertex, `along` the way from its origin.
#[derive(Clone, Copy, Debug)]
struct Split {
    edge: HalfedgeId,
    along: f64,
    vertex: u32,
}

/// The splits to make, by half-edge and then in order along it.
fn t_vertex_splits(mesh: &Mesh, tolerance: f64) -> Vec<Split> {
    let at = |v: u32| mesh.positions()[v as usize];
    let finite = |v: u32| at(v).iter().all(|x| x.is_finite());
    let boundary: Vec<HalfedgeId> = (0..mesh.n_halfedge_slots() as u32)
        .map(HalfedgeId)
        .filter(|&h| !mesh.is_halfedge_deleted(h) && mesh.is_boundary_halfedge(h))
        .filter(|&h| finite(mesh.origin(h).0) && finite(mesh.target(h).0))
        .collect();
    let mut boundary_vertices: Vec<u32> = boundary.iter().map(|&h| mesh.origin(h).0).collect();
    boundary_vertices.sort_unstable();
    boundary_vertices.dedup();
    let tree = PointTree::new(boundary_vertices, &at);

    let mut splits: Vec<Split> = Vec::new();
    for &h in &boundary {
        let (a, b) = (mesh.origin(h).0, mesh.target(h).0);
        let (pa, pb) = (at(a), at(b));
        let face = mesh.face(h.twin());
        // The tree's box test rounds: a little reach keeps points exactly on the edge in.
        let magnitude = pa.iter().chain(&pb).fold(0.0f64, |m, x| m.max(x.abs()));
        let reach = tolerance.max(magnitude * 1e-12);
        tree.near_segment(pa, pb, reach, |v| {
            let p = at(v);
            let Some(along) = along_segment(p, pa, pb, tolerance) else {
                return;
            };
            if !mesh.face_vertices(face).any(|w| at(w.0) == p) {
                splits.push(Split {
                    edge: h,
                    along,
                    vertex: v,
                });
            }
        });
    }
    splits.sort_unstable_by(|x, y| {
        (x.edge.0.cmp(&y.edge.0))
            .then(x.along.total_cmp(&y.along))
            .then_with(|| {
                let (p, q) = (at(x.vertex), at(y.vertex));
                (0..3).fold(Ordering::Equal, |o, k| o.then(p[k].total_cmp(&q[k])))
            })
            .then(x.vertex.cmp(&y.vertex))
    });
    // One split per position on an edge: a second would make an edge of no length.
    splits.dedup_by(|later, earlier| {
        later.edge == earlier.edge && at(later.vertex) == at(earlier.vertex)
    });
    splits
}

/// When `p` lies inside the segment `a b` (exactly, or within `tolerance` of it and projecting
/// strictly between its ends): how far along from `a` it projects (0 to 1).
fn along_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3], tolerance: f64) -> Option<f64> {
    let exactly =
        are_collinear(a, b, p) && (0..3).all(|k| a[k].min(b[k]) <= p[k] && p[k] <= a[k].max(b[k]));
    let near = tolerance > 0.0 && lies_inside_segment(p, a, b, tolerance);
    if !exactly && !near {
        return None;
    }
    let (ab, ap) = (difference(b, a), difference(p, a));
    Some((dot(ab, ap) / dot(ab, ab)).clamp(0.0, 1.0))
}
