//! Checking a face list before a repair, and removing its faces, corners and vertices with
//! their corner data.

use super::RepairError;
use crate::mesh::{IndexMaps, compaction_map};
use crate::soup::{FaceTable, ListProblem, MAX_VERTICES, PolygonSoup, VertexCopies};

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

/// The soup's well-formed faces (3 corners or more, no vertex named twice), in order, with
/// their soup face ids ([`FaceTable::input_face`]): what the edge-pairing repairs work on.
/// Refused as [`checked_table`] refuses.
pub(super) fn well_formed_faces(soup: &PolygonSoup) -> Result<FaceTable<'static>, RepairError> {
    let table = checked_table(soup)?;
    let defects = table.face_defects(soup.positions.len());
    let mut keep = vec![true; table.n_faces()];
    for &f in defects.too_small.iter().chain(&defects.repeated_vertex) {
        keep[f as usize] = false;
    }
    Ok(table.retain(&keep))
}

/// The first corner of every soup face, and one past the last as the last entry.
pub(super) fn face_offsets(soup: &PolygonSoup) -> Vec<usize> {
    let mut offsets = Vec::with_capacity(soup.n_faces() + 1);
    offsets.push(0);
    for &size in &soup.face_sizes {
        offsets.push(offsets[offsets.len() - 1] + size as usize);
    }
    offsets
}

/// Writes the corners of `table` (the soup's well-formed faces, edited in place: same sizes, some
/// corners moved to copies) back into the soup, and appends the copies at their originals'
/// positions. Corner data stays with its corner.
pub(super) fn apply_vertex_copies(
    soup: &mut PolygonSoup,
    table: &FaceTable<'_>,
    copies: &VertexCopies,
) {
    let offsets = face_offsets(soup);
    for f in 0..table.n_faces() {
        let first = offsets[table.input_face(f) as usize];
        let face = table.face(f);
        soup.indices[first..first + face.len()].copy_from_slice(face);
    }
    let n_vertices = soup.positions.len();
    soup.positions.reserve(copies.copied_from().len());
    for &v in copies.copied_from() {
        let position = soup.positions[v as usize];
        soup.positions.push(position);
    }
    debug_assert_eq!(
        soup.positions.len(),
        n_vertices + copies.copied_from().len()
    );
}

/// The refusal of a repair whose vertex copies would go beyond 32-bit ids.
pub(super) fn too_many_vertices(copies: &VertexCopies) -> RepairError {
    RepairError::MalformedList(ListProblem::TooManyElements {
        what: "vertices",
        count: copies.n_vertices() as u64 + 1,
    })
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
