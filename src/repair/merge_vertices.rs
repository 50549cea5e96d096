//! Merging vertices at one position, or within a tolerance of each other.

use super::soup_edit::{checked_table, identity_maps, ids_where, remove_vertices, retain_faces};
use super::tolerance::clusters;
use super::{RepairError, RepairReport, Tolerance};
use crate::doctor::{bounding_box, distance};
use crate::mesh::IndexMaps;
use crate::soup::PolygonSoup;

/// Merges the vertices of `soup` that are at one position, or within `tolerance` of each other,
/// into the lowest of each cluster, which keeps its position (clusters are made by the rule of
/// the doctor's near duplicates: exact duplicates always merge; near ones greedily, in index
/// order, into the first lower kept vertex within the tolerance, so kept vertices end up more
/// than the tolerance apart, and the rule is not transitive). Vertices with a non-finite
/// coordinate are never merged.
///
/// Faces that name a merged vertex then drop every corner that repeats the vertex of the
/// corner before it (cyclically), with its normal and texture coordinate; such a face left with
/// fewer than 3 corners has collapsed and is removed (listed in
/// [`RepairReport::removed_faces`]). Other faces are untouched. Merged vertices are removed;
/// vertices that only collapsed faces named stay (see
/// [`remove_unreferenced_vertices`](super::remove_unreferenced_vertices)).
///
/// O(n log n) whatever the positions: a sort for exact duplicates, a grid for near ones. Refused
/// (the soup unchanged) for a tolerance that is negative, NaN, infinite, relative above 1, or
/// positive but below 2^-48 of the positions' extent, and for a malformed soup.
pub fn merge_vertices(
    soup: &mut PolygonSoup,
    tolerance: Tolerance,
) -> Result<RepairReport, RepairError> {
    let table = checked_table(soup)?;
    // The diagonal of every position, not only the named ones: a merge can only shrink it, so
    // a second run's tolerance is no larger and finds nothing more.
    let diagonal = match tolerance {
        Tolerance::Relative(_) => {
            let [low, high] = bounding_box(soup.positions.iter().copied());
            distance(low, high)
        }
        Tolerance::Absolute(_) => f64::NAN,
    };
    let absolute = tolerance.absolute(diagonal)?;
    let kept = clusters(&soup.positions, absolute)?;
    let merged: Vec<bool> = kept
        .iter()
        .enumerate()
        .map(|(v, &k)| k as usize != v)
        .collect();
    if !merged.contains(&true) {
        return Ok(RepairReport {
            maps: identity_maps(soup),
            ..RepairReport::default()
        });
    }

    let n_faces = table.n_faces();
    drop(table);
    let mut keep_face = vec![true; n_faces];
    let mut keep_corner = vec![true; soup.indices.len()];
    let mut removed_corners = 0;
    let mut distinct = Vec::new();
    let mut first = 0;
    for (f, &size) in soup.face_sizes.iter().enumerate() {
        let range = first..first + size as usize;
        first = range.end;
        let corners = &soup.indices[range.clone()];
        if !corners.iter().any(|&v| merged[v as usize]) {
            continue;
        }
        distinct.clear();
        for (i, c) in range.enumerate() {
            let before = corners[(i + corners.len() - 1) % corners.len()];
            if kept[corners[i] as usize] == kept[before as usize] {
                keep_corner[c] = false;
            } else {
                distinct.push(kept[corners[i] as usize]);
            }
        }
        // Three corners left, none repeating the one before, are three vertices; only longer
        // loops can still name a vertex twice.
        if distinct.len() > 3 {
            distinct.sort_unstable();
            distinct.dedup();
        }
        if distinct.len() < 3 {
            keep_face[f] = false;
        } else {
            removed_corners += corners.len()
                - keep_corner[first - corners.len()..first]
                    .iter()
                    .filter(|&&k| k)
                    .count();
        }
    }
    for v in &mut soup.indices {
        *v = kept[*v as usize];
    }
    let faces = retain_faces(soup, &keep_face, Some(&keep_corner));
    let vertices = remove_vertices(soup, &merged);
    Ok(RepairReport {
        maps: IndexMaps {
            vertices,
            faces,
            ..IndexMaps::default()
        },
        merged_vertices: ids_where(&merged)
            .into_iter()
            .map(|v| [v, kept[v as usize]])
            .collect(),
        removed_vertices: ids_where(&merged),
        removed_faces: ids_where(&keep_face.iter().map(|&k| !k).collect::<Vec<_>>()),
        removed_corners,
        ..RepairReport::default()
    })
}
