//! Checking a face list before a repair, and removing its faces, corners and vertices with
//! their corner data.

use super::RepairError;
use crate::mesh::{IndexMaps, compaction_map};
use crate::soup::{FaceTable, ListProblem, MAX_VERTICES, PolygonSoup};

/// The soup laid out as a table, refused when a repair cannot work on it: list-level problems,
/// corner attributes that are not one per corner, an index naming no vertex.
pub(super) fn checked_table(soup: &PolygonSoup) -> Result<FaceTable<'_>, RepairError> {
    let n_vertices = soup.positions.len();
    if n_vertices as u64 > MAX_VERTICES {
        return Err(RepairError::MalformedList(ListProblem::TooManyElements {
            what: "vertices",
            count: n_vertices as u64,
        }));
    }
    let table = FaceTable::new(&soup.as_face_list()).map_err(RepairError::MalformedList)?;
    let lengths = [
        ("corner normals", soup.corner_normals.as_ref().map(Vec::len)),
        ("corner uvs", soup.corner_uvs.as_ref().map(Vec::len)),
    ];
    for (what, len) in lengths {
        if let Some(len) = len.filter(|&len| len != soup.indices.len()) {
            return Err(RepairError::MalformedList(
                ListProblem::CornerAttributeMismatch {
                    what,
                    expected: soup.indices.len() as u64,
                    actual: len as u64,
                },
            ));
        }
    }
    if let Some(c) = soup.indices.iter().position(|&v| v as usize >= n_vertices) {
        return Err(RepairError::IndexOutOfRange {
            face: table.face_of_corner(c) as u32,
            vertex: soup.indices[c],
            n_vertices,
        });
    }
    Ok(table)
}

/// Identity maps of the soup's vertices and faces: what a repair that changed nothing reports.
pub(super) fn identity_maps(soup: &PolygonSoup) -> IndexMaps {
    IndexMaps {
        vertices: (0..soup.positions.len() as u32).collect(),
        faces: (0..soup.n_faces() as u32).collect(),
        ..IndexMaps::default()
    }
}

/// Keeps the faces where `keep_face` holds and, of those, the corners where `keep_corner` holds
/// (all when `None`), with their normals and texture coordinates; returns the old-to-new face
/// map. A kept face should keep 3 corners or more.
pub(super) fn retain_faces(
    soup: &mut PolygonSoup,
    keep_face: &[bool],
    keep_corner: Option<&[bool]>,
) -> Vec<u32> {
    let removed: Vec<bool> = keep_face.iter().map(|&keep| !keep).collect();
    let face_map = compaction_map(keep_face.len(), &removed);
    let mut kept_corners = vec![false; soup.indices.len()];
    let mut sizes = Vec::with_capacity(keep_face.len());
    let mut first = 0;
    for (f, &size) in soup.face_sizes.iter().enumerate() {
        let range = first..first + size as usize;
        first = range.end;
        if !keep_face[f] {
            continue;
        }
        let mut size = 0;
        for c in range {
            if keep_corner.is_none_or(|keep| keep[c]) {
                kept_corners[c] = true;
                size += 1;
            }
        }
        sizes.push(size);
    }
    soup.face_sizes = sizes;
    retain_by(&mut soup.indices, &kept_corners);
    if let Some(normals) = &mut soup.corner_normals {
        retain_by(normals, &kept_corners);
    }
    if let Some(uvs) = &mut soup.corner_uvs {
        retain_by(uvs, &kept_corners);
    }
    face_map
}

/// Removes the vertices where `remove` holds (no corner may name one) and renumbers the corners;
/// returns the old-to-new vertex map.
pub(super) fn remove_vertices(soup: &mut PolygonSoup, remove: &[bool]) -> Vec<u32> {
    let map = compaction_map(soup.positions.len(), remove);
    let kept: Vec<bool> = remove.iter().map(|&r| !r).collect();
    retain_by(&mut soup.positions, &kept);
    for v in &mut soup.indices {
        *v = map[*v as usize];
    }
    map
}

/// The ids where `flags` holds, ascending.
pub(super) fn ids_where(flags: &[bool]) -> Vec<u32> {
    (0..flags.len() as u32)
        .filter(|&i| flags[i as usize])
        .collect()
}

fn retain_by<T>(values: &mut Vec<T>, keep: &[bool]) {
    let mut i = 0;
    values.retain(|_| {
        i += 1;
        keep[i - 1]
    });
}
