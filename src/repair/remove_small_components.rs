//! Removing small connected components.

use super::soup_edit::{checked_table, identity_maps, ids_where, remove_vertices, retain_faces};
use super::{RepairError, RepairReport};
use crate::doctor::{EMPTY_BOX, distance, face_components, grow};
use crate::soup::{PolygonSoup, inspect, unnamed_vertices};

/// Which components are small.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SmallComponents {
    /// Components of at most this many faces.
    FaceCount(usize),
    /// Components whose bounding-box diagonal is at most this fraction (between 0 and 1) of the
    /// largest component diagonal.
    RelativeDiameter(f64),
}

/// Removes the faces of the small components of `soup` (faces joined through shared edges, as
/// the doctor counts them), and the vertices that only those faces named. Kept faces and
/// vertices keep their order and corner data ([`RepairReport::maps`]). Malformed faces (fewer
/// than 3 corners, a repeated vertex) belong to no component and are kept.
///
/// O(n log n). Refused (the soup unchanged) for a ratio outside 0..=1 or NaN, and for a
/// malformed soup.
pub fn remove_small_components(
    soup: &mut PolygonSoup,
    small: SmallComponents,
) -> Result<RepairReport, RepairError> {
    if let SmallComponents::RelativeDiameter(ratio) = small
        && !(0.0..=1.0).contains(&ratio)
    {
        return Err(RepairError::BadOption {
            name: "relative diameter",
            value: ratio,
            range: "between 0 and 1",
        });
    }
    let table = checked_table(soup)?;
    let n_faces = table.n_faces();
    let unreferenced_before = unnamed_vertices(&table, soup.positions.len());
    drop(table);
    let inspection = inspect(&soup.as_face_list()).map_err(|diagnostic| {
        let problem = diagnostic.list_problem.clone();
        RepairError::MalformedList(
            problem.unwrap_or(crate::soup::ListProblem::TooManyElements {
                what: "faces",
                count: n_faces as u64,
            }),
        )
    })?;
    let surface = &inspection.well_formed;
    let (component_of, n_components) = face_components(surface, &inspection.pairing);
    let mut sizes = vec![0usize; n_components];
    let mut boxes = vec![EMPTY_BOX; n_components];
    for (f, &component) in component_of.iter().enumerate().take(surface.n_faces()) {
        let component = component as usize;
        sizes[component] += 1;
        for &v in surface.face(f) {
            grow(&mut boxes[component], soup.positions[v as usize]);
        }
    }
    let diameters: Vec<f64> = boxes.iter().map(|b| distance(b[0], b[1])).collect();
    let widest = diameters.iter().copied().fold(0.0, f64::max);
    let is_small = |c: usize| match small {
        SmallComponents::FaceCount(count) => sizes[c] <= count,
        SmallComponents::RelativeDiameter(ratio) => {
            diameters[c].partial_cmp(&(ratio * widest)) != Some(std::cmp::Ordering::Greater)
        }
    };
    let mut removed = vec![false; n_faces];
    for f in 0..surface.n_faces() {
        if is_small(component_of[f] as usize) {
            removed[surface.input_face(f) as usize] = true;
        }
    }
    drop(inspection);
    let mut report = RepairReport {
        maps: identity_maps(soup),
        ..RepairReport::default()
    };
    if !removed.contains(&true) {
        return Ok(report);
    }
    let keep: Vec<bool> = removed.iter().map(|&r| !r).collect();
    report.maps.faces = retain_faces(soup, &keep, None);
    report.removed_faces = ids_where(&removed);
    // The vertices only removed faces named: unreferenced now, not before.
    let table = checked_table(soup)?;
    let mut remove = vec![false; soup.positions.len()];
    for v in unnamed_vertices(&table, soup.positions.len()) {
        remove[v as usize] = true;
    }
    drop(table);
    for &v in &unreferenced_before {
        remove[v as usize] = false;
    }
    report.maps.vertices = remove_vertices(soup, &remove);
    report.removed_vertices = ids_where(&remove);
    Ok(report)
}
