//! Pairing the directed edges of a face table into undirected edges by bucketing.
//!
//! Every corner `c` stands for its directed edge `corners[c] → corners[next(c)]`. The edges are
//! counting-sorted by their smaller vertex (one pass to count, one to scatter); each bucket — a
//! vertex's few edges towards larger vertices — is then sorted by the larger vertex, so the corners
//! of one undirected edge end up adjacent, in face order. This is linear in the corner count with
//! sequential passes, unlike the one-ring search per new face that OpenMesh's and CGAL's
//! `add_face` do.

use super::FaceTable;

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
    let n_corners = table.n_corners();

    // Counting sort by the smaller vertex: `bucket_start[v]..bucket_start[v + 1]` will hold the
    // edges whose smaller vertex is `v`.
    let mut bucket_start = vec![0u32; n_vertices + 1];
    table.for_each_corner_edge(|_, c, n| {
        let low = corners[c].min(corners[n]) as usize;
        bucket_start[low + 1] += 1;
    });
    for v in 0..n_vertices {
        bucket_start[v + 1] += bucket_start[v];
    }
    let mut cursor = bucket_start[..n_vertices].to_vec();
    // Entry = larger vertex in the high half, corner in the low half: sorting a bucket groups
    // one undirected edge's corners together, in corner (face) order.
    let mut entries = vec![0u64; n_corners];
    table.for_each_corner_edge(|_, c, n| {
        let (a, b) = (corners[c], corners[n]);
        let slot = &mut cursor[a.min(b) as usize];
        entries[*slot as usize] = (u64::from(a.max(b)) << 32) | c as u64;
        *slot += 1;
    });
    drop(cursor);

    let mut partner = vec![BOUNDARY; n_corners];
    let mut problems = Vec::new();
    for low in 0..n_vertices {
        let bucket = &mut entries[bucket_start[low] as usize..bucket_start[low + 1] as usize];
        if bucket.len() < 2 {
            continue; // a lone edge is a boundary edge: already marked
        }
        bucket.sort_unstable();
        let mut run_start = 0;
        while run_start < bucket.len() {
            let high = bucket[run_start] >> 32;
            let run_end = run_start
                + bucket[run_start..]
                    .iter()
                    .take_while(|&&entry| entry >> 32 == high)
                    .count();
            let run = &bucket[run_start..run_end];
            let corner = |i: usize| (run[i] & u64::from(u32::MAX)) as u32;
            let forward = |c: u32| corners[c as usize] as usize == low;
            match run.len() {
                1 => {}
                2 if forward(corner(0)) != forward(corner(1)) => {
                    partner[corner(0) as usize] = corner(1);
                    partner[corner(1) as usize] = corner(0);
                }
                len => {
                    let edge_corners: Vec<u32> = (0..len).map(corner).collect();
                    for &c in &edge_corners {
                        partner[c as usize] = UNPAIRED;
                    }
                    problems.push(ProblemEdge {
                        vertices: [low as u32, high as u32],
                        corners: edge_corners,
                        defect: if len == 2 {
                            EdgeDefect::Inconsistent
                        } else {
                            EdgeDefect::NonManifold
                        },
                    });
                }
            }
            run_start = run_end;
        }
    }
    EdgePairing { partner, problems }
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
