//! Repair's first step on orientation conflicts: flip whole faces so that neighbours agree, as
//! CGAL's `orient_polygon_soup` does, before any vertex is duplicated.

use super::FaceTable;
use super::pairing::{BOUNDARY, EdgeDefect, EdgePairing, UNPAIRED};

/// Chooses faces to reverse so that as many edges as possible become consistently oriented.
///
/// Faces are linked through their two-face edges: across a consistent edge two faces must keep
/// the same orientation, across an inconsistent one they must differ. Each connected component is
/// walked breadth-first from its first face; a face reached by contradictory constraints (a
/// Möbius band) keeps its first assignment, and the conflicting edge is left for the vertex
/// duplication that follows. In each component the smaller side is flipped (ties keep the
/// component's first face as given). Returns the table faces to reverse, ascending.
pub(crate) fn faces_to_flip(table: &FaceTable<'_>, pairing: &EdgePairing) -> Vec<usize> {
    let n_faces = table.n_faces();
    let mut corner_face = vec![0u32; table.n_corners()];
    for f in 0..n_faces {
        corner_face[table.face_range(f)].fill(f as u32);
    }
    // Neighbours: (face, must_differ) per corner, as a CSR over faces' corner ranges.
    let mut across: Vec<(u32, bool)> = vec![(u32::MAX, false); table.n_corners()];
    for (c, &p) in pairing.partner.iter().enumerate() {
        if p != BOUNDARY && p != UNPAIRED {
            across[c] = (corner_face[p as usize], false);
        }
    }
    for problem in pairing
        .problems
        .iter()
        .filter(|p| p.defect == EdgeDefect::Inconsistent)
    {
        let (a, b) = (problem.corners[0] as usize, problem.corners[1] as usize);
        across[a] = (corner_face[b], true);
        across[b] = (corner_face[a], true);
    }

    const UNSEEN: u8 = 2;
    let mut flip = vec![UNSEEN; n_faces];
    let mut to_flip = Vec::new();
    let mut queue = Vec::new();
    for seed in 0..n_faces {
        if flip[seed] != UNSEEN {
            continue;
        }
        flip[seed] = 0;
        queue.clear();
        queue.push(seed);
        let mut head = 0;
        while head < queue.len() {
            let f = queue[head];
            head += 1;
            for &(neighbour, differ) in &across[table.face_range(f)] {
                if neighbour != u32::MAX && flip[neighbour as usize] == UNSEEN {
                    flip[neighbour as usize] = flip[f] ^ u8::from(differ);
                    queue.push(neighbour as usize);
                }
            }
        }
        let flipped = queue.iter().filter(|&&f| flip[f] == 1).count();
        let keep = if 2 * flipped > queue.len() { 1 } else { 0 };
        to_flip.extend(queue.iter().copied().filter(|&f| flip[f] != keep));
    }
    to_flip.sort_unstable();
    to_flip
}

/// Reverses the corner order of `faces` in place.
pub(crate) fn flip_faces(table: &mut FaceTable<'_>, faces: &[usize]) {
    for &f in faces {
        let range = table.face_range(f);
        table.corners_mut()[range].reverse();
    }
}
