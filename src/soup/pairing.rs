//! Pairing the directed edges of a face table into undirected edges.
//!
//! Every corner `c` stands for its directed edge `corners[c] → corners[next(c)]`. The corners
//! meet their edges in face order in [`EdgeBuckets`] (bucketed by smaller vertex, no sorting and
//! no one-ring search per new face as OpenMesh's and CGAL's `add_face` do): the second corner on
//! an edge becomes the first one's partner when it runs the other way. Anything else — a second
//! corner running the same way, a third corner — marks the edge as a problem.

use super::FaceTable;
use super::edge_buckets::{EdgeBuckets, EdgeVisit, edge_key};
use crate::support::large_arrays::filled;

/// `partner` value of a corner whose edge no other face uses.
pub const BOUNDARY: u32 = u32::MAX;
/// `partner` value of a corner on a [`ProblemEdge`].
pub const UNPAIRED: u32 = u32::MAX - 1;

/// Why an undirected edge cannot be an edge of an oriented 2-manifold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeDefect {
    /// Three or more faces use the edge.
    NonManifold,
    /// Two faces use the edge in the same direction.
    Inconsistent,
}

/// An undirected edge the faces cannot share as they are.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProblemEdge {
    /// The edge's vertices, smaller first.
    pub vertices: [u32; 2],
    /// The corners (table indices) whose directed edge this is, ascending (so in face order).
    pub corners: Vec<u32>,
    /// What is wrong.
    pub defect: EdgeDefect,
}

/// The result of pairing: each corner's partner corner on the same undirected edge (running the
/// other way), [`BOUNDARY`], or [`UNPAIRED`] for corners on problem edges.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgePairing {
    /// Per corner: the partner corner, [`BOUNDARY`] or [`UNPAIRED`].
    pub partner: Vec<u32>,
    /// Edges with 3+ faces or two faces of the same direction, by smaller vertex then larger.
    pub problems: Vec<ProblemEdge>,
}

/// Pairs the directed edges of `table`. Preconditions (checked by
/// [`FaceTable::face_defects`]): every index is below `n_vertices` and no face repeats a vertex.
pub fn pair_edges(table: &FaceTable<'_>, n_vertices: usize) -> EdgePairing {
    let corners = table.corners();
    let mut buckets = EdgeBuckets::new(table, n_vertices, 0)
        .expect("pair_edges' precondition: well-formed faces");
    let mut partner = filled(table.n_corners(), BOUNDARY);
    let mut problem_keys: Vec<u64> = Vec::new();
    table.for_each_corner_edge(|_, c, n| {
        let (a, b) = (corners[c], corners[n]);
        // Corner ids are below `MAX_CORNERS`, so they fit an edge's value.
        match buckets.visit(a, b, c as u32) {
            EdgeVisit::Opened => {}
            EdgeVisit::Paired(first) => {
                partner[first as usize] = c as u32;
                partner[c] = first;
            }
            EdgeVisit::Defective => problem_keys.push(edge_key(a.min(b), a.max(b))),
        }
    });
    let problems = if problem_keys.is_empty() {
        Vec::new()
    } else {
        gather_problems(table, problem_keys, &mut partner)
    };
    EdgePairing { partner, problems }
}

/// The rare path: collects every corner of the problem edges, marks them [`UNPAIRED`] and
/// classifies each edge by its number of corners.
fn gather_problems(
    table: &FaceTable<'_>,
    mut keys: Vec<u64>,
    partner: &mut [u32],
) -> Vec<ProblemEdge> {
    keys.sort_unstable();
    keys.dedup();
    let corners = table.corners();
    let mut edge_corners: Vec<Vec<u32>> = vec![Vec::new(); keys.len()];
    table.for_each_corner_edge(|_, c, n| {
        let (a, b) = (corners[c], corners[n]);
        if let Ok(problem) = keys.binary_search(&edge_key(a.min(b), a.max(b))) {
            edge_corners[problem].push(c as u32);
            partner[c] = UNPAIRED;
        }
    });
    keys.iter()
        .zip(edge_corners)
        .map(|(&key, corners)| ProblemEdge {
            vertices: [(key >> 32) as u32, key as u32],
            defect: if corners.len() == 2 {
                EdgeDefect::Inconsistent
            } else {
                EdgeDefect::NonManifold
            },
            corners,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::FaceList;

    fn pair(n_vertices: usize, sizes: &[u32], indices: &[u32]) -> EdgePairing {
        let positions = vec![[0.0; 3]; n_vertices];
        let table = FaceTable::new(&FaceList::polygons(&positions, sizes, indices)).unwrap();
        pair_edges(&table, n_vertices)
    }

    #[test]
    fn two_triangles_share_one_edge() {
        // 0-1-2 and 2-1-3 share edge 1-2 (corner 1: 1→2, corner 3: 2→1).
        let pairing = pair(4, &[3, 3], &[0, 1, 2, 2, 1, 3]);
        assert_eq!(pairing.partner[1], 3);
        assert_eq!(pairing.partner[3], 1);
        let boundary = pairing.partner.iter().filter(|&&p| p == BOUNDARY).count();
        assert_eq!(boundary, 4);
        assert!(pairing.problems.is_empty());
    }

    #[test]
    fn same_direction_and_three_faces_are_problems() {
        let flipped = pair(4, &[3, 3], &[0, 1, 2, 1, 2, 3]);
        assert_eq!(flipped.problems.len(), 1);
        assert_eq!(flipped.problems[0].vertices, [1, 2]);
        assert_eq!(flipped.problems[0].corners, vec![1, 3]);
        assert_eq!(flipped.problems[0].defect, EdgeDefect::Inconsistent);
        assert_eq!(flipped.partner[1], UNPAIRED);

        let book = pair(5, &[3, 3, 3], &[0, 1, 2, 1, 0, 3, 0, 1, 4]);
        assert_eq!(book.problems.len(), 1);
        assert_eq!(book.problems[0].vertices, [0, 1]);
        assert_eq!(book.problems[0].corners, vec![0, 3, 6]);
        assert_eq!(book.problems[0].defect, EdgeDefect::NonManifold);
    }
}
