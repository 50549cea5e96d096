//! Repair's orientation steps: flip whole faces so that neighbours agree, as
//! CGAL's `orient_polygon_soup` does, before any vertex is duplicated; and, once the faces pair,
//! flip closed components that face inward.

use super::pairing::{BOUNDARY, EdgeDefect, EdgePairing, UNPAIRED};
use super::{FaceTable, component_volumes};
use crate::support::disjoint_sets;

/// Orientations given to the faces of a table breadth-first through their two-face edges: the
/// same across an edge walked both ways, opposite across an edge walked one way twice; each
/// face's neighbours are visited in face order, so the search tree does not depend on the
/// faces' orientations. Each
/// connected component is walked from its first face; a face reached again with the other
/// orientation (a Möbius band) keeps its first one, and the pair is a conflict.
pub(crate) struct OrientationSearch {
    /// Whether each face must be reversed to agree with its component's first face.
    pub(crate) flipped: Vec<bool>,
    /// The face each face was reached from (a component's first face: itself).
    pub(crate) reached_from: Vec<u32>,
    /// The first face of each face's component.
    pub(crate) root: Vec<u32>,
    /// `(f, g)`: face `g`, reached before, disagrees with the orientation `f` asks of it; in
    /// search order.
    pub(crate) conflicts: Vec<(usize, usize)>,
}

/// The [`OrientationSearch`] of `table`, whose edges `pairing` pairs.
pub(crate) fn search_orientations(
    table: &FaceTable<'_>,
    pairing: &EdgePairing,
) -> OrientationSearch {
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

    const UNSEEN: u32 = u32::MAX;
    let mut search = OrientationSearch {
        flipped: vec![false; n_faces],
        reached_from: vec![UNSEEN; n_faces],
        root: vec![UNSEEN; n_faces],
        conflicts: Vec::new(),
    };
    let mut queue = Vec::new();
    let mut neighbours = Vec::new();
    for seed in 0..n_faces {
        if search.reached_from[seed] != UNSEEN {
            continue;
        }
        search.reached_from[seed] = seed as u32;
        search.root[seed] = seed as u32;
        queue.clear();
        queue.push(seed);
        let mut head = 0;
        while head < queue.len() {
            let f = queue[head];
            head += 1;
            // Neighbours in face order, not corner order: reversing faces then leaves the
            // search tree as it was, so orienting a second time changes nothing.
            neighbours.clear();
            neighbours.extend(
                across[table.face_range(f)]
                    .iter()
                    .filter(|&&(neighbour, _)| neighbour != u32::MAX),
            );
            neighbours.sort_unstable();
            for &(neighbour, differ) in &neighbours {
                let g = neighbour as usize;
                let wanted = search.flipped[f] ^ differ;
                if search.reached_from[g] == UNSEEN {
                    search.reached_from[g] = f as u32;
                    search.root[g] = seed as u32;
                    search.flipped[g] = wanted;
                    queue.push(g);
                } else if search.flipped[g] != wanted {
                    search.conflicts.push((f, g));
                }
            }
        }
    }
    search
}

/// Chooses faces to reverse so that as many edges as possible become consistently oriented: in
/// each component of the [`OrientationSearch`] the smaller side is flipped (ties keep the
/// component's first face as given); a conflicting edge is left for the vertex duplication that
/// follows. Returns the table faces to reverse, ascending.
pub(crate) fn faces_to_flip(table: &FaceTable<'_>, pairing: &EdgePairing) -> Vec<usize> {
    let search = search_orientations(table, pairing);
    let n_faces = table.n_faces();
    let (mut size, mut flipped) = (vec![0usize; n_faces], vec![0usize; n_faces]);
    for f in 0..n_faces {
        let root = search.root[f] as usize;
        size[root] += 1;
        flipped[root] += usize::from(search.flipped[f]);
    }
    (0..n_faces)
        .filter(|&f| {
            let root = search.root[f] as usize;
            let keep_flipped = 2 * flipped[root] > size[root];
            search.flipped[f] != keep_flipped
        })
        .collect()
}

/// Reverses the corner order of `faces` in place.
pub(crate) fn flip_faces(table: &mut FaceTable<'_>, faces: &[usize]) {
    for &f in faces {
        let range = table.face_range(f);
        table.corners_mut()[range].reverse();
    }
}

/// Whether a closed component of `table` (well formed, its vertices at `positions`) encloses a
/// negative volume: the Repair policy must then turn it outward, so the build cannot take the
/// direct route.
pub(crate) fn has_inward_closed_component(table: &FaceTable<'_>, positions: &[[f64; 3]]) -> bool {
    let pairing = super::pair_edges(table, positions.len());
    !faces_facing_inward(table, &pairing, |v| positions[v as usize]).is_empty()
}

/// The faces of the closed components of `table` that enclose a negative volume, ascending:
/// flipped, every closed component faces outward. `pairing` is `table`'s; components are joined
/// through paired edges, and a component is closed when none of its corners is on the boundary
/// or on a problem edge. Vertex `v` is at `position(v)`. A component enclosing no volume
/// (flat) is left as it is.
pub(crate) fn faces_facing_inward(
    table: &FaceTable<'_>,
    pairing: &EdgePairing,
    position: impl Fn(u32) -> [f64; 3],
) -> Vec<usize> {
    let n_faces = table.n_faces();
    let mut parent: Vec<u32> = (0..n_faces as u32).collect();
    let mut open = vec![false; n_faces];
    for (f, open) in open.iter_mut().enumerate() {
        for c in table.face_range(f) {
            match pairing.partner[c] {
                BOUNDARY | UNPAIRED => *open = true,
                p => disjoint_sets::join(
                    &mut parent,
                    0,
                    f as u32,
                    table.face_of_corner(p as usize) as u32,
                ),
            }
        }
    }
    let component: Vec<usize> = (0..n_faces as u32)
        .map(|f| disjoint_sets::root(&mut parent, 0, f) as usize)
        .collect();
    let mut closed = vec![true; n_faces];
    for (f, &open) in open.iter().enumerate() {
        if open {
            closed[component[f]] = false;
        }
    }
    let volume = component_volumes(table, &component, n_faces, |c| closed[c], position);
    (0..n_faces)
        .filter(|&f| closed[component[f]] && volume[component[f]].sign < 0.0)
        .collect()
}
