//! Removing faces on the vertex set of an earlier face.

use super::soup_edit::{checked_table, identity_maps, ids_where, retain_faces};
use super::{RepairError, RepairReport};
use crate::doctor::duplicate_faces;
use crate::soup::PolygonSoup;

/// Removes every face of `soup` whose vertex set is that of a lower face (in either
/// orientation, from any starting corner: the doctor's duplicate faces), keeping the lowest of
/// each set with its corners' normals and texture coordinates. [`RepairReport::duplicate_faces`]
/// pairs each removed face with the face kept. Malformed faces (fewer than 3 corners, a repeated
/// vertex) are neither removed nor kept for another. Vertices are untouched (identity map).
///
/// O(n log n): faces are sorted by their sorted vertex sets. Refused (the soup unchanged) for a
/// malformed soup.
pub fn remove_duplicate_faces(soup: &mut PolygonSoup) -> Result<RepairReport, RepairError> {
    let table = checked_table(soup)?;
    let defects = table.face_defects(soup.positions.len());
    let well_formed = if defects.is_empty() {
        table.clone()
    } else {
        let mut keep = vec![true; table.n_faces()];
        for &f in defects.too_small.iter().chain(&defects.repeated_vertex) {
            keep[f as usize] = false;
        }
        table.retain(&keep)
    };
    let duplicates = duplicate_faces(&well_formed);
    let n_faces = table.n_faces();
    drop((table, well_formed));
    let mut report = RepairReport {
        maps: identity_maps(soup),
        ..RepairReport::default()
    };
    if duplicates.is_empty() {
        return Ok(report);
    }
    let mut removed = vec![false; n_faces];
    for &[f, _] in &duplicates {
        removed[f as usize] = true;
    }
    let keep: Vec<bool> = removed.iter().map(|&r| !r).collect();
    report.maps.faces = retain_faces(soup, &keep, None);
    report.removed_faces = ids_where(&removed);
    report.duplicate_faces = duplicates;
    Ok(report)
}
