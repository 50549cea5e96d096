//! Cutting or removing faces at edges that three faces or more share.

use super::soup_edit::{
    apply_vertex_copies, identity_maps, ids_where, retain_faces, too_many_vertices,
    well_formed_faces,
};
use super::{RepairError, RepairReport};
use crate::soup::{
    EdgeDefect, PolygonSoup, ProblemEdge, VertexCopies, first_come_refusals, pair_edges,
    repair_edges, split_umbrellas,
};

/// What [`repair_non_manifold_edges`] does at an edge of three faces or more.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum NonManifoldEdges {
    /// Keep every face and cut the surface along the edge, as
    /// [`BuildPolicy::Repair`](crate::soup::BuildPolicy::Repair) does: around each end of the
    /// edge, the faces joined through other (two-face) edges keep one vertex; faces that would be
    /// left alone on the edge are matched two by two in soup order, one running each way, and
    /// keep the edge between them (of three triangles on one edge, two stay joined); every
    /// other group gets copies of the edge's ends. Two closed cubes sharing an edge become two
    /// closed cubes.
    #[default]
    Cut,
    /// Keep the faces in soup order while the edge has at most one face running each way, and
    /// remove the others (as [`BuildPolicy::Skip`](crate::soup::BuildPolicy::Skip) does and
    /// OpenMesh's `add_face` loop would): of three triangles on one edge the first two kept when
    /// they run opposite ways.
    RemoveFaces,
}

/// Makes every edge of `soup` shared by at most two faces (the doctor's non-manifold edges go),
/// by cutting or by removing faces as `how` says; edges two faces use the same way are left to
/// [`orient_faces`](super::orient_faces), which should run first (a cut separates faces joined
/// only through such an edge at the cut edge's ends).
///
/// Cutting appends vertex copies at their originals' positions
/// ([`RepairReport::vertex_copies`]: vertex `n + i`, `n` the vertex count before, copies
/// `vertex_copies[i]`; the vertex map is the identity on the old vertices); faces keep their
/// ids and their corners' normals and texture coordinates. Removing lists the removed faces
/// ([`RepairReport::removed_faces`], with the face map) and leaves the vertices (some may no
/// longer be named: see [`remove_unreferenced_vertices`](super::remove_unreferenced_vertices)).
/// Malformed faces (fewer than 3 corners, a vertex named twice) are left as they are. A second
/// run changes nothing.
///
/// O(n log n). Refused (the soup unchanged) for a malformed soup and when copies would take the
/// vertex count beyond 32-bit ids.
pub fn repair_non_manifold_edges(
    soup: &mut PolygonSoup,
    how: NonManifoldEdges,
) -> Result<RepairReport, RepairError> {
    let is_non_manifold = |edge: &ProblemEdge| edge.defect == EdgeDefect::NonManifold;
    let mut table = well_formed_faces(soup)?;
    let n_vertices = soup.positions.len();
    let mut pairing = pair_edges(&table, n_vertices);
    pairing.problems.retain(is_non_manifold);
    let mut report = RepairReport {
        maps: identity_maps(soup),
        ..RepairReport::default()
    };
    if pairing.problems.is_empty() {
        return Ok(report);
    }
    match how {
        NonManifoldEdges::Cut => {
            let mut copies = VertexCopies::new(n_vertices);
            let too_many = |copies: &VertexCopies| too_many_vertices(copies);
            if split_umbrellas(&mut table, &pairing, &mut copies).map_err(|_| too_many(&copies))? {
                pairing = pair_edges(&table, copies.n_vertices());
            }
            repair_edges(&mut table, pairing, &mut copies, is_non_manifold)
                .map_err(|_| too_many(&copies))?;
            copies.drop_unused(&mut table);
            apply_vertex_copies(soup, &table, &copies);
            report.vertex_copies = copies.copied_from().to_vec();
        }
        NonManifoldEdges::RemoveFaces => {
            let mut removed = vec![false; soup.n_faces()];
            for (f, _) in first_come_refusals(&table, &pairing.problems) {
                removed[table.input_face(f) as usize] = true;
            }
            drop(table);
            let keep: Vec<bool> = removed.iter().map(|&r| !r).collect();
            report.maps.faces = retain_faces(soup, &keep, None);
            report.removed_faces = ids_where(&removed);
        }
    }
    Ok(report)
}
