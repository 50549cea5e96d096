//! Removing vertices no face names.

use super::soup_edit::{checked_table, identity_maps, remove_vertices};
use super::{RepairError, RepairReport};
use crate::soup::{PolygonSoup, unnamed_vertices};

/// Removes the vertices of `soup` that no face names (the doctor's unreferenced vertices),
/// renumbering the others in their order ([`RepairReport::maps`]). Faces are untouched.
///
/// Linear time. Refused (the soup unchanged) for a malformed soup.
pub fn remove_unreferenced_vertices(soup: &mut PolygonSoup) -> Result<RepairReport, RepairError> {
    let table = checked_table(soup)?;
    let unreferenced = unnamed_vertices(&table, soup.positions.len());
    drop(table);
    let mut report = RepairReport {
        maps: identity_maps(soup),
        ..RepairReport::default()
    };
    if unreferenced.is_empty() {
        return Ok(report);
    }
    let mut remove = vec![false; soup.positions.len()];
    for &v in &unreferenced {
        remove[v as usize] = true;
    }
    report.maps.vertices = remove_vertices(soup, &remove);
    report.removed_vertices = unreferenced;
    Ok(report)
}
