//! Pairing the directed edges of a face table into undirected edges by bucketing.
//!
//! Every corner `c` stands for its directed edge `corners[c] → corners[next(c)]`. The edges
//! running from a smaller to a larger vertex are counting-sorted by their smaller vertex (one pass
//! to count, one to scatter); every edge running the other way then looks its partner up in the
//! bucket of its smaller vertex, which holds that vertex's few forward edges. This is linear in
//! the corner count, in three sequential passes, unlike the one-ring search per new face that
//! OpenMesh's and CGAL's `add_face` do.

use super::FaceTable;
use crate::large_arrays::{filled, zeroed};

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
///
/// Forward edges (`a < b`) are counting-sorted into buckets by `a`, keyed by `b`; each backward
/// edge (`a > b`) then finds its partner by scanning the few forward edges of bucket `b`. Only
/// half the edges are moved, and no bucket is sorted. Anything unusual — two forward edges with
/// one key, a backward edge meeting an already paired forward one, two unmatched backward edges
/// with one key — marks the undirected edge as a problem, whose corners are gathered afterwards.
pub fn pair_edges(table: &FaceTable<'_>, n_vertices: usize) -> EdgePairing {
    let corners = table.corners();
    let n_corners = table.n_corners();

    // `bucket_start[a]..bucket_start[a + 1]` will hold the forward edges leaving `a`.
    let mut bucket_start = vec![0u32; n_vertices + 1];
    table.for_each_corner_edge(|_, c, n| {
        let (a, b) = (corners[c], corners[n]);
        if a < b {
            bucket_start[a as usize + 1] += 1;
        }
    });
    for v in 0..n_vertices {
        bucket_start[v + 1] += bucket_start[v];
    }
    // Entry = larger vertex in the high half, corner in the low half.
    let mut entries = zeroed::<u64>(bucket_start[n_vertices] as usize);
    let mut problem_keys: Vec<u64> = Vec::new();
    {
        let mut cursor = bucket_start[..n_vertices].to_vec();
        table.for_each_corner_edge(|_, c, n| {
            let (a, b) = (corners[c], corners[n]);
            if a < b {
                let slot = &mut cursor[a as usize];
                let bucket = &entries[bucket_start[a as usize] as usize..*slot as usize];
                if bucket.iter().any(|&entry| (entry >> 32) as u32 == b) {
                    problem_keys.push(edge_key(a, b));
                }
                entries[*slot as usize] = (u64::from(b) << 32) | c as u64;
                *slot += 1;
            }
        });
    }

    // A forward entry that a backward edge has taken is marked in the entry itself (corner ids
    // are below 2^31, so bit 31 is free): the bucket is in cache already, while `partner` of the
    // forward corner may be anywhere in memory.
    const MATCHED: u64 = 1 << 31;
    let mut partner = filled(n_corners, BOUNDARY);
    let mut unmatched_backward: Vec<(u64, u32)> = Vec::new();
    table.for_each_corner_edge(|_, c, n| {
        let (a, b) = (corners[c], corners[n]);
        if a > b {
            let bucket = &mut entries
                [bucket_start[b as usize] as usize..bucket_start[b as usize + 1] as usize];
            match bucket.iter_mut().find(|entry| (**entry >> 32) as u32 == a) {
                Some(entry) => {
                    if *entry & MATCHED == 0 {
                        let forward = (*entry & u64::from(u32::MAX)) as usize;
                        *entry |= MATCHED;
                        partner[forward] = c as u32;
                        partner[c] = forward as u32;
                    } else {
                        problem_keys.push(edge_key(b, a));
                    }
                }
                None => unmatched_backward.push((edge_key(b, a), c as u32)),
            }
        }
    });
    drop(entries);
    unmatched_backward.sort_unstable();
    for pair in unmatched_backward.windows(2) {
        if pair[0].0 == pair[1].0 {
            problem_keys.push(pair[0].0);
        }
    }

    let problems = if problem_keys.is_empty() {
        Vec::new()
    } else {
        gather_problems(table, problem_keys, &mut partner)
    };
    EdgePairing { partner, problems }
}

/// An undirected edge as one sortable number: smaller vertex high, larger low.
#[inline]
fn edge_key(low: u32, high: u32) -> u64 {
    (u64::from(low) << 32) | u64::from(high)
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
