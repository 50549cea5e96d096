//! Splitting non-manifold vertices: one vertex per fan of faces.

use super::soup_edit::{apply_vertex_copies, identity_maps, too_many_vertices, well_formed_faces};
use super::{RepairError, RepairReport};
use crate::soup::{PolygonSoup, VertexCopies, pair_edges, split_non_manifold_vertices as split};

/// Gives every fan of faces around a non-manifold vertex of `soup` but the first a vertex of
/// its own, as builds do (the doctor's non-manifold vertices: corners at a vertex are in one
/// fan when their faces share an edge there, any number of faces on it). Fans are taken in the
/// order of their first corner; the first keeps the vertex. Each copy is appended at its
/// original's position, in the order the copies are made ([`RepairReport::vertex_copies`]:
/// vertex `n + i`, `n` the vertex count before, copies `vertex_copies[i]`); the vertex map is
/// the identity on the old vertices. The corners of a moved fan keep their normals and texture
/// coordinates; faces keep their ids. Malformed faces (fewer than 3 corners, a vertex named
/// twice) belong to no fan and are untouched.
///
/// Edges shared by three faces or more stay shared (they join fans): see
/// [`repair_non_manifold_edges`](super::repair_non_manifold_edges) to cut them first. Afterwards no
/// vertex has two fans, so a second run changes nothing.
///
/// O(n log n). Refused (the soup unchanged) for a malformed soup and when the copies would take
/// the vertex count beyond 32-bit ids.
pub fn split_non_manifold_vertices(soup: &mut PolygonSoup) -> Result<RepairReport, RepairError> {
    let mut table = well_formed_faces(soup)?;
    let n_vertices = soup.positions.len();
    let pairing = pair_edges(&table, n_vertices);
    let mut copies = VertexCopies::new(n_vertices);
    split(&mut table, &pairing, &mut copies).map_err(|_| too_many_vertices(&copies))?;
    let mut report = RepairReport {
        maps: identity_maps(soup),
        ..RepairReport::default()
    };
    if copies.copied_from().is_empty() {
        return Ok(report);
    }
    apply_vertex_copies(soup, &table, &copies);
    report.vertex_copies = copies.copied_from().to_vec();
    Ok(report)
}
