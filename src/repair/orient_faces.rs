//! Orienting faces coherently, and closed components outward.

use super::soup_edit::{face_offsets, identity_maps, well_formed_faces};
use super::{RepairError, RepairReport};
use crate::soup::{
    PolygonSoup, faces_facing_inward, faces_to_flip, flip_faces, pair_edges, symmetric_difference,
};

/// Reverses faces of `soup` so that neighbours agree in orientation and every closed component
/// faces outward, with the steps of [`BuildPolicy::Repair`](crate::soup::BuildPolicy::Repair)
/// (CGAL's `orient_polygon_soup` and `orient_to_bound_a_volume` do the same): faces joined
/// through edges two faces share are oriented breadth-first from their component's first face,
/// and the smaller side of each component is reversed (a tie keeps the first face as given);
/// then each closed component (every edge shared by two faces running opposite ways) that
/// encloses a negative volume is reversed. A non-orientable component (a Möbius band) keeps an
/// edge whose faces disagree; edges of three faces or more are left as they are (they neither
/// join components here nor close one). Vertices are not touched, so what stays non-manifold
/// still fails a strict build: see [`repair_non_manifold_edges`](super::repair_non_manifold_edges)
/// and [`split_non_manifold_vertices`](super::split_non_manifold_vertices).
///
/// A reversed face keeps its corners, in reverse order, each with its normal and texture
/// coordinate (normals are not negated: they say how the surface is shaded, which the
/// orientation of its faces does not change). [`RepairReport::reoriented_faces`] lists them;
/// the maps are the identity. Malformed faces (fewer than 3 corners, a vertex named twice) are
/// left as they are. A second run reverses nothing.
///
/// O(n log n). Refused (the soup unchanged) for a malformed soup.
pub fn orient_faces(soup: &mut PolygonSoup) -> Result<RepairReport, RepairError> {
    let mut table = well_formed_faces(soup)?;
    let n_vertices = soup.positions.len();
    let mut pairing = pair_edges(&table, n_vertices);
    let mut flipped = Vec::new();
    if !pairing.problems.is_empty() {
        flipped = faces_to_flip(&table, &pairing);
        if !flipped.is_empty() {
            flip_faces(&mut table, &flipped);
            pairing = pair_edges(&table, n_vertices);
        }
    }
    let inward = faces_facing_inward(&table, &pairing, |v| soup.positions[v as usize]);
    let reoriented: Vec<u32> = symmetric_difference(&flipped, &inward)
        .map(|f| table.input_face(f))
        .collect();
    drop(table);
    let offsets = face_offsets(soup);
    for &f in &reoriented {
        let corners = offsets[f as usize]..offsets[f as usize + 1];
        soup.indices[corners.clone()].reverse();
        if let Some(normals) = &mut soup.corner_normals {
            normals[corners.clone()].reverse();
        }
        if let Some(uvs) = &mut soup.corner_uvs {
            uvs[corners].reverse();
        }
    }
    Ok(RepairReport {
        maps: identity_maps(soup),
        reoriented_faces: reoriented,
        ..RepairReport::default()
    })
}
