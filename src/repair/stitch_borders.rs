//! Stitching borders: gluing boundary edges that lie on each other.

use super::mesh_maps::identity_maps;
use super::tolerance::{absolute_on_mesh, clusters};
use super::{RepairError, RepairReport, Tolerance};
use crate::mesh::{HalfedgeId, INVALID_INDEX, Mesh};
use crate::support::disjoint_sets;

/// Glues the boundary edges of `mesh` that lie on each other, end on end (exactly, or within
/// `tolerance`), like CGAL's `stitch_borders`, and compacts the mesh
/// ([`RepairReport::maps`]).
///
/// Boundary vertices are clustered by position as [`merge_vertices`](super::merge_vertices)
/// does. A boundary edge is stitched when exactly one other boundary edge joins the same two
/// clusters, in the opposite direction (so the faces beside them agree in orientation), and
/// neither has an end at a vertex with several boundary fans. Pairs whose gluing would make two
/// edges join the same vertices, an edge join a vertex to itself, or a face name a vertex twice
/// are left out, with every pair that merges a vertex into theirs; what remains keeps the mesh
/// manifold (each merged vertex's fans join end to end into one).
///
/// Each pair's faces keep their half-edges with their corner data; the edge of the pair's lower
/// boundary half-edge stays, with its attributes, the other goes
/// ([`RepairReport::stitched_halfedges`]). Vertices merged at the pairs' ends go into the lowest
/// of each set, which keeps its position and attributes ([`RepairReport::merged_vertices`]).
///
/// O(n log n). Refused (the mesh unchanged) for a bad tolerance (see
/// [`merge_vertices`](super::merge_vertices)); a relative one scales the diagonal of the live
/// vertices' bounding box. When nothing is stitched the mesh is unchanged and the maps are the
/// identity.
pub fn stitch_borders(mesh: &mut Mesh, tolerance: Tolerance) -> Result<RepairReport, RepairError> {
    let n_slots = mesh.n_vertex_slots();
    let absolute = absolute_on_mesh(tolerance, mesh)?;

    let boundary: Vec<HalfedgeId> = (0..mesh.n_halfedge_slots() as u32)
        .map(HalfedgeId)
        .filter(|&h| !mesh.is_halfedge_deleted(h) && mesh.is_boundary_halfedge(h))
        .collect();
    // Cluster of every boundary vertex (by the lowest boundary vertex of its cluster).
    let mut boundary_fans = vec![0u32; n_slots];
    for &h in &boundary {
        boundary_fans[mesh.origin(h).index()] += 1;
    }
    let boundary_vertices: Vec<u32> = (0..n_slots as u32)
        .filter(|&v| boundary_fans[v as usize] > 0)
        .collect();
    let positions: Vec<[f64; 3]> = boundary_vertices
        .iter()
        .map(|&v| mesh.positions()[v as usize])
        .collect();
    let kept = clusters(&positions, absolute)?;
    let mut cluster = vec![INVALID_INDEX; n_slots];
    for (i, &v) in boundary_vertices.iter().enumerate() {
        cluster[v as usize] = boundary_vertices[kept[i] as usize];
    }

    // Candidate pairs: the only two boundary half-edges between two clusters, opposite ways.
    let mut keyed: Vec<([u32; 2], HalfedgeId)> = boundary
        .iter()
        .filter_map(|&h| {
            let (a, b) = (
                cluster[mesh.origin(h).index()],
                cluster[mesh.target(h).index()],
            );
            (a != b).then_some(([a.min(b), a.max(b)], h))
        })
        .collect();
    keyed.sort_unstable();
    let single_fan = |h: HalfedgeId| {
        boundary_fans[mesh.origin(h).index()] == 1 && boundary_fans[mesh.target(h).index()] == 1
    };
    let mut pairs: Vec<[HalfedgeId; 2]> = keyed
        .chunk_by(|x, y| x.0 == y.0)
        .filter_map(|run| match run {
            &[(_, a), (_, b)]
                if cluster[mesh.origin(a).index()] != cluster[mesh.origin(b).index()]
                    && single_fan(a)
                    && single_fan(b) =>
            {
                Some([a.min(b), a.max(b)])
            }
            _ => None,
        })
        .collect();

    // Leave out pairs until the glued mesh is valid (each round removes every pair touching a
    // vertex set that breaks a rule, so the sets it leaves are smaller; it ends at the latest
    // when no pair is left).
    let kept_vertex = loop {
        let kept_vertex = merged_vertices(mesh, &pairs);
        let broken = broken_sets(mesh, &pairs, &kept_vertex);
        if broken.is_empty() {
            break kept_vertex;
        }
        let mut is_broken = vec![false; n_slots];
        for v in broken {
            is_broken[v as usize] = true;
        }
        pairs.retain(|&[a, _]| {
            !is_broken[kept_vertex[mesh.origin(a).index()] as usize]
                && !is_broken[kept_vertex[mesh.target(a).index()] as usize]
        });
    };

    if pairs.is_empty() {
        return Ok(RepairReport {
            maps: identity_maps(mesh),
            ..RepairReport::default()
        });
    }
    let merged: Vec<[u32; 2]> = (0..n_slots as u32)
        .filter(|&v| kept_vertex[v as usize] != v)
        .map(|v| [v, kept_vertex[v as usize]])
        .collect();
    mesh.glue_boundary_pairs(&pairs, &kept_vertex);
    let maps = mesh.garbage_collect();
    Ok(RepairReport {
        maps,
        removed_vertices: merged.iter().map(|&[v, _]| v).collect(),
        merged_vertices: merged,
        stitched_halfedges: pairs.iter().map(|&[a, b]| [a.0, b.0]).collect(),
        ..RepairReport::default()
    })
}

/// The vertex every vertex slot becomes when `pairs` are glued: the lowest of the set the
/// pairs' ends join.
fn merged_vertices(mesh: &Mesh, pairs: &[[HalfedgeId; 2]]) -> Vec<u32> {
    let mut parent: Vec<u32> = (0..mesh.n_vertex_slots() as u32).collect();
    for &[a, b] in pairs {
        disjoint_sets::join(&mut parent, 0, mesh.origin(a).0, mesh.target(b).0);
        disjoint_sets::join(&mut parent, 0, mesh.target(a).0, mesh.origin(b).0);
    }
    (0..parent.len() as u32)
        .map(|v| disjoint_sets::root(&mut parent, 0, v))
        .collect()
}

/// The merged vertices (of sets of two or more) at which gluing `pairs` would break a rule: an
/// edge from a vertex to itself, two edges joining the same vertices, a face naming a vertex
/// twice.
fn broken_sets(mesh: &Mesh, pairs: &[[HalfedgeId; 2]], kept: &[u32]) -> Vec<u32> {
    let mut is_merged = vec![false; kept.len()];
    for (v, &k) in kept.iter().enumerate() {
        if k as usize != v {
            is_merged[v] = true;
            is_merged[k as usize] = true;
        }
    }
    let mut glued_away = vec![false; mesh.n_edge_slots()];
    for &[_, b] in pairs {
        glued_away[b.edge().index()] = true;
    }
    let mut broken = Vec::new();
    let mut ends: Vec<[u32; 2]> = Vec::new();
    for e in 0..mesh.n_edge_slots() as u32 {
        let h = HalfedgeId(2 * e);
        if mesh.is_halfedge_deleted(h) || glued_away[e as usize] {
            continue;
        }
        let (a, b) = (kept[mesh.origin(h).index()], kept[mesh.target(h).index()]);
        if !is_merged[a as usize] && !is_merged[b as usize] {
            continue;
        }
        if a == b {
            broken.push(a);
        } else {
            ends.push([a.min(b), a.max(b)]);
        }
    }
    ends.sort_unstable();
    for run in ends.chunk_by(|x, y| x == y).filter(|run| run.len() > 1) {
        broken.extend(run[0]);
    }
    let mut corners = Vec::new();
    for f in 0..mesh.n_face_slots() as u32 {
        let f = crate::mesh::FaceId(f);
        if mesh.is_face_deleted(f) {
            continue;
        }
        corners.clear();
        corners.extend(mesh.face_vertices(f).map(|v| kept[v.index()]));
        if !corners.iter().any(|&v| is_merged[v as usize]) {
            continue;
        }
        corners.sort_unstable();
        for run in corners.chunk_by(|x, y| x == y).filter(|run| run.len() > 1) {
            broken.push(run[0]);
        }
    }
    broken.retain(|&v| is_merged[v as usize]);
    broken
}
