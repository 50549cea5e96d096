//! The buckets of vertices with too many edges to be searched slot by slot (see
//! [`EdgeBuckets`](super::EdgeBuckets)): a vertex or an edge that many faces share. Their edges
//! are found by the faces beforehand and sorted, so that a corner finds its edge by binary
//! search: a vertex of any degree costs O(log d) per corner, and the buckets of the usual,
//! small vertices are left as they are.

use super::FaceTable;
use super::table::face_edges;

/// The large buckets of one face table: every edge of the table whose smaller vertex has one,
/// with its slot (in [`EdgeBuckets`](super::EdgeBuckets)' encoding: 0 until a corner opens it).
#[derive(Default)]
pub(super) struct LargeBuckets {
    /// Per vertex, its large bucket or [`NO_BUCKET`] (empty when no vertex has one).
    bucket_of: Vec<u32>,
    /// `start[i]..start[i + 1]`: the edges of bucket `i` in `highs` and `slots`.
    start: Vec<u32>,
    /// The larger vertex of each edge, ascending within a bucket.
    highs: Vec<u32>,
    slots: Vec<u64>,
}

/// [`LargeBuckets::bucket_of`] a vertex without a large bucket.
const NO_BUCKET: u32 = u32::MAX;

impl LargeBuckets {
    /// The buckets of the vertices of `table` (well formed, on `n_vertices` vertices) for which
    /// `is_large` holds, with room for every edge of the table whose smaller vertex is one of
    /// them.
    pub(super) fn new(
        table: &FaceTable<'_>,
        n_vertices: usize,
        is_large: impl Fn(u32) -> bool,
    ) -> Self {
        let mut bucket_of = vec![NO_BUCKET; n_vertices];
        let mut n_buckets = 0;
        for (v, bucket) in (0..n_vertices as u32).zip(&mut bucket_of) {
            if is_large(v) {
                *bucket = n_buckets;
                n_buckets += 1;
            }
        }
        // The larger vertex of every corner whose smaller vertex has a bucket, grouped by bucket
        // (counted, then placed: no sort of all of them), then sorted and deduplicated bucket by
        // bucket, in place.
        let bucket_of_corner = |a: u32, b: u32| {
            let bucket = bucket_of[a.min(b) as usize];
            (bucket != NO_BUCKET).then_some((bucket as usize, a.max(b)))
        };
        let mut start = vec![0u32; n_buckets as usize + 1];
        for face in table.faces() {
            for (bucket, _) in face_edges(face).filter_map(|(a, b)| bucket_of_corner(a, b)) {
                start[bucket + 1] += 1;
            }
        }
        for bucket in 0..n_buckets as usize {
            start[bucket + 1] += start[bucket];
        }
        let mut highs = vec![0u32; start[n_buckets as usize] as usize];
        let mut placed = start.clone();
        for face in table.faces() {
            for (bucket, high) in face_edges(face).filter_map(|(a, b)| bucket_of_corner(a, b)) {
                highs[placed[bucket] as usize] = high;
                placed[bucket] += 1;
            }
        }
        let mut n_edges = 0;
        for bucket in 0..n_buckets as usize {
            // `start[bucket + 1]` is still the end of this bucket's corners.
            let corners = start[bucket] as usize..start[bucket + 1] as usize;
            let first_edge = n_edges;
            highs[corners.clone()].sort_unstable();
            for c in corners {
                if n_edges == first_edge || highs[n_edges - 1] != highs[c] {
                    highs[n_edges] = highs[c];
                    n_edges += 1;
                }
            }
            start[bucket] = first_edge as u32;
        }
        start[n_buckets as usize] = n_edges as u32;
        highs.truncate(n_edges);
        LargeBuckets {
            bucket_of,
            start,
            highs,
            slots: vec![0; n_edges],
        }
    }

    /// The slot of the edge `low`–`high` (`low < high`), when `low` has a large bucket and that
    /// edge is one of the table's.
    #[inline]
    pub(super) fn slot_mut(&mut self, low: u32, high: u32) -> Option<&mut u64> {
        let bucket = *self
            .bucket_of
            .get(low as usize)
            .filter(|&&b| b != NO_BUCKET)? as usize;
        let (first, end) = (self.start[bucket] as usize, self.start[bucket + 1] as usize);
        let edge = self.highs[first..end].binary_search(&high).ok()?;
        Some(&mut self.slots[first + edge])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::FaceList;
    use crate::soup::edge_buckets::edge_key;

    #[test]
    fn every_edge_of_a_large_vertex_has_a_slot_and_no_other_edge_has() {
        // A fan around vertex 0 and a face away from it, on vertices 3..6 (5 is large too).
        let positions = vec![[0.0; 3]; 7];
        let indices = [0, 1, 2, 0, 2, 3, 4, 0, 3, 4, 5, 6];
        let table = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap();
        let mut buckets = LargeBuckets::new(&table, 7, |v| v == 0 || v == 5);
        assert_eq!(
            buckets.bucket_of,
            [0, NO_BUCKET, NO_BUCKET, NO_BUCKET, NO_BUCKET, 1, NO_BUCKET]
        );
        assert_eq!(buckets.highs, [1, 2, 3, 4, 6]);
        for (low, high) in [(0, 1), (0, 2), (0, 3), (0, 4), (5, 6)] {
            *buckets.slot_mut(low, high).unwrap() = edge_key(low, high);
        }
        for (low, high) in [(1, 2), (2, 3), (3, 4), (4, 5), (4, 6), (0, 5), (5, 5)] {
            assert!(buckets.slot_mut(low, high).is_none(), "{low}-{high}");
        }
        assert_eq!(buckets.slots, [1, 2, 3, 4, (5 << 32) | 6]);
        assert!(LargeBuckets::default().slot_mut(0, 1).is_none());
    }
}
