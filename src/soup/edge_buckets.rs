//! Undirected edges of a face table, met corner by corner ("first come"): the first corner that
//! walks an edge opens it with a value of the caller's choosing; the second, walking it the other
//! way, pairs with it and learns that value. A second corner walking the same way, or a third
//! corner, finds the edge defective.
//!
//! Edges are kept in buckets by their smaller vertex, keyed by the larger one. A bucket's room is
//! counted beforehand in one pass: the corners running from that vertex to a larger one. On an
//! oriented closed manifold that is exactly its number of edges, so buckets are never searched
//! past a handful of slots and never overflow; edges beyond the room (a boundary edge only walked
//! from its larger vertex, or defective input) go to a small spill map. No sorting, no hashing on
//! the usual path, and one 8-byte slot per forward corner.
//!
//! A bucket is searched slot by slot, so a vertex with room for `d` edges would cost up to `d`
//! steps per corner, `d²` in all: a vertex or edge many faces share (a star of 64k triangles
//! around one edge built in 2.3 s) would make the build quadratic. A vertex with more room than
//! [`LARGEST_SCANNED_BUCKET`] therefore gets no slots among the others, decided once as the room
//! is counted: its edges are kept sorted in [`LargeBuckets`] instead, found by binary search.
//! Its corners then leave their (empty) bucket for the same cold path as the spilled ones, so
//! the walk over the usual buckets has no test of its own for them.

use std::collections::HashMap;

use super::FaceTable;
use super::large_buckets::LargeBuckets;
use super::table::{face_edges, is_well_formed};
use crate::support::large_arrays::{copied_into, zeroed, zeroed_reusable};
use crate::support::prefetch::prefetch;

/// A slot: larger vertex in the high half, then whether the first corner ran from the smaller
/// vertex to the larger (bit 31), then the value (bits 0..31), which becomes [`CLOSED`] once a
/// second corner came. The direction travels in the slot so a pairing corner needs no other
/// memory than its bucket. Larger vertices are at least 1, so an all-zero slot is empty.
const FORWARD: u64 = 1 << 31;
const VALUE_MASK: u64 = FORWARD - 1;
const CLOSED: u64 = VALUE_MASK;

/// Largest value an edge can carry (values are corner or edge ids, below 2^31 − 1).
pub(super) const MAX_EDGE_VALUE: u32 = CLOSED as u32 - 1;

/// What a corner found when it met its edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EdgeVisit {
    /// First corner on the edge: it opened the edge with its value.
    Opened,
    /// Second corner, running the other way: the edge carried this value (the first corner's).
    Paired(u32),
    /// A second corner running the same way as the first, or a third corner: the edge cannot
    /// be an edge of an oriented 2-manifold.
    Defective,
}

/// The buckets of one face table's edges.
pub(crate) struct EdgeBuckets {
    /// `start[v]..start[v + 1]`: the slots of vertex `v`'s bucket.
    start: Vec<u32>,
    slots: Vec<u64>,
    /// The edges of vertices without slots among the others, and of full buckets.
    overflow: Overflow,
    /// Whether the table's vertex order follows its faces
    /// ([`FaceTable::vertices_follow_faces`]): then a walk meets its buckets nearly in order.
    vertices_follow_faces: bool,
    /// Whether a visitor was made: until then every slot is empty.
    visited: bool,
}

impl EdgeBuckets {
    /// Empty buckets sized for `table`'s edges, or `None` when a face is not well formed (fewer
    /// than 3 corners, an index `>= n_vertices`, a repeated vertex: the one pass over the faces
    /// that counts the buckets' room checks them too). `n_vertices` is below 2^32 − 1. The
    /// slots' block has room for `later_positions` positions once the walk is done (see
    /// [`EdgeBuckets::into_positions`]).
    pub(crate) fn new(
        table: &FaceTable<'_>,
        n_vertices: usize,
        later_positions: usize,
    ) -> Option<Self> {
        let mut start = zeroed::<u32>(n_vertices + 1);
        let vertices_follow_faces = table.vertices_follow_faces();
        let counted = if vertices_follow_faces {
            count_forward_corners::<true>(table, n_vertices, &mut start)
        } else {
            count_forward_corners::<false>(table, n_vertices, &mut start)
        };
        if !counted {
            return None;
        }
        // The running total stays in a register: reading back each sum just stored would wait
        // on the store every step. The rooms' bits are gathered a run at a time on the way (a
        // packed pass over the run, still in cache), which tells whether a bucket is too large
        // to scan (see `LARGEST_SCANNED_BUCKET`); only then are the rooms counted again,
        // without those.
        let (mut total, mut room_bits) = (0, 0);
        for rooms in start.chunks_mut(1024) {
            room_bits |= rooms.iter().fold(0, |bits, &room| bits | room);
            for room in rooms {
                total += *room;
                *room = total;
            }
        }
        let large = if room_bits > LARGEST_SCANNED_BUCKET {
            let room = |v: u32| start[v as usize + 1] - start[v as usize];
            let large = LargeBuckets::new(table, n_vertices, |v| room(v) > LARGEST_SCANNED_BUCKET);
            leave_out_large_buckets(&mut start);
            large
        } else {
            LargeBuckets::default()
        };
        let slots = zeroed_reusable::<_, [f64; 3]>(start[n_vertices] as usize, later_positions);
        Some(EdgeBuckets {
            start,
            slots,
            overflow: Overflow {
                large,
                spill: HashMap::new(),
            },
            vertices_follow_faces,
            visited: false,
        })
    }

    /// Does the table's vertex order follow its faces (judged once, when the buckets were
    /// made)? Builders also choose where to check face areas by it.
    pub(crate) fn vertices_follow_faces(&self) -> bool {
        self.vertices_follow_faces
    }

    /// Spends the buckets on a copy of `positions`, in the slots' block when it has the room
    /// ([`EdgeBuckets::new`]): its pages, faulted in by the walk, then hold the positions
    /// instead of fresh ones.
    pub(crate) fn into_positions(self, positions: &[[f64; 3]]) -> Vec<[f64; 3]> {
        copied_into(self.slots, positions)
    }

    /// The buckets as a visitor for one walk (see [`EdgeVisitor`]).
    #[inline]
    pub(crate) fn visitor(&mut self) -> EdgeVisitor<'_> {
        self.visited = true;
        EdgeVisitor {
            start: &self.start,
            slots: &mut self.slots,
            overflow: &mut self.overflow,
            prefetch_ahead: if self.vertices_follow_faces {
                usize::MAX
            } else {
                PREFETCH_FACES_AHEAD
            },
        }
    }

    /// The buckets' first visitor (this panics if they had one): every value it meets was then
    /// stored through it.
    #[inline]
    pub(crate) fn first_visitor(&mut self) -> EdgeVisitor<'_> {
        assert!(!self.visited, "edge buckets are walked once");
        self.visitor()
    }

    /// [`EdgeVisitor::visit`] through a visitor made for the call (the builders' walks keep one
    /// visitor for all their corners instead).
    #[inline]
    pub(crate) fn visit(&mut self, a: u32, b: u32, value: u32) -> EdgeVisit {
        self.visitor().visit(a, b, value)
    }
}

/// Counts into `start[v + 1]` the corners of `table` running from `v` to a larger vertex, or
/// gives `false` when a face is not well formed (see [`EdgeBuckets::new`]). When the vertex order
/// follows the faces (`FOLLOW`), whether a corner runs forward has a pattern the branch predictor
/// learns, and only forward corners touch their count (fewer chained read-modify-writes of one
/// count: the 1M-triangle torus built in 32.2–33.4 ms against 33.1–34.6, four rounds taking
/// turns); otherwise it is a coin toss, and every corner adds 0 or 1 without a branch.
fn count_forward_corners<const FOLLOW: bool>(
    table: &FaceTable<'_>,
    n_vertices: usize,
    start: &mut [u32],
) -> bool {
    let mut scratch = Vec::new();
    let mut count = |a: u32, b: u32| {
        if !FOLLOW {
            start[a as usize + 1] += u32::from(a < b);
        } else if a < b {
            start[a as usize + 1] += 1;
        }
    };
    table
        .try_for_each_face(
            #[inline(always)]
            |_, face| {
                if !is_well_formed(face, n_vertices, &mut scratch) {
                    return None;
                }
                match *face {
                    [a, b, c] => {
                        count(a, b);
                        count(b, c);
                        count(c, a);
                    }
                    [a, b, c, d] => {
                        count(a, b);
                        count(b, c);
                        count(c, d);
                        count(d, a);
                    }
                    _ => {
                        for (a, b) in face_edges(face) {
                            count(a, b);
                        }
                    }
                }
                Some(())
            },
        )
        .is_some()
}

/// The largest room a bucket is given among the others: a vertex with more forward corners has
/// its edges in [`LargeBuckets`] instead (see the module documentation), so no visit scans more
/// slots than this. Ordinary meshes rarely have a vertex near it (a closed triangle mesh's vertex
/// has about 3 forward corners). It is about where a scan becomes slower than the binary search:
/// 1M triangles in fans of `d` around vertices with forward corners only, one thread, best of 7
/// builds, took 59-63 ns a face scanned at `d` = 64 (against 85-88 searched), 87-94 scanned at
/// 128 (against 93-97), 163-180 scanned at 256 (against 93-94). One less than a power of two, so
/// that the rooms' bits gathered by `EdgeBuckets::new` exceed it exactly when a room does.
const LARGEST_SCANNED_BUCKET: u32 = 127;

/// Gives no room to the buckets of more than [`LARGEST_SCANNED_BUCKET`] slots in `start`, the
/// running total of the rooms (see [`EdgeBuckets`]), whose edges [`LargeBuckets`] holds.
#[cold]
#[inline(never)]
fn leave_out_large_buckets(start: &mut [u32]) {
    let (mut total, mut previous) = (0, 0);
    for start in start {
        let room = *start - previous;
        previous = *start;
        if room <= LARGEST_SCANNED_BUCKET {
            total += room;
        }
        *start = total;
    }
}

/// How many faces ahead of its current face a walk prefetches buckets
/// ([`EdgeVisitor::prefetch_ahead_of`]) when the vertex order does not follow the faces (scanned
/// models): nearly every bucket is then a cache miss, and sixteen faces give the loads time to
/// arrive (armadillo, 86k faces, one thread, cold memory, four rounds of 400 builds: best
/// 10.2–11.4 -> 9.5–11.0 ms, median 17.1–18.9 -> 14.7–16.1 ms). When it does, the buckets are in
/// cache already and the hints would only cost instructions (the 1M-triangle torus built 5%
/// slower with them), so the visitor's distance is then past any table.
const PREFETCH_FACES_AHEAD: usize = 16;

/// The buckets' arrays borrowed for a walk. A walk keeps this on its stack, so the arrays'
/// addresses and lengths stay in registers across the walk's own stores (read through
/// [`EdgeBuckets`] itself they are reloaded after every store the compiler cannot tell apart).
pub(crate) struct EdgeVisitor<'b> {
    start: &'b [u32],
    slots: &'b mut [u64],
    overflow: &'b mut Overflow,
    /// See [`PREFETCH_FACES_AHEAD`].
    prefetch_ahead: usize,
}

impl EdgeVisitor<'_> {
    /// For a walk at table face `f`: starts loading the buckets of the face it will reach a few
    /// faces later, when its vertex order does not follow the faces (see
    /// [`PREFETCH_FACES_AHEAD`]).
    #[inline(always)]
    pub(crate) fn prefetch_ahead_of(&self, table: &FaceTable<'_>, f: usize) {
        self.prefetch_face(table, f.saturating_add(self.prefetch_ahead));
    }

    /// Starts loading the buckets of table face `f`'s edges; nothing when `f` is past the table.
    #[inline(always)]
    fn prefetch_face(&self, table: &FaceTable<'_>, f: usize) {
        if f < table.n_faces() {
            for (a, b) in face_edges(table.face(f)) {
                let low = a.min(b) as usize;
                // A vertex without forward corners starts where the slots end.
                if let Some(slot) = self
                    .start
                    .get(low)
                    .and_then(|&s| self.slots.get(s as usize))
                {
                    prefetch(slot);
                }
            }
        }
    }

    /// The vertex count the buckets were made for: every vertex a visit names is below it.
    #[inline(always)]
    pub(crate) fn n_vertices(&self) -> usize {
        self.start.len() - 1
    }

    /// Meets the edge of a corner running `a → b` (`a != b`, both below
    /// [`EdgeVisitor::n_vertices`], else this panics) with `value` (at most [`MAX_EDGE_VALUE`]),
    /// which is stored if this corner opens the edge.
    #[inline(always)]
    pub(crate) fn visit(&mut self, a: u32, b: u32, value: u32) -> EdgeVisit {
        assert!(
            (a.max(b) as usize) < self.n_vertices(),
            "a vertex beyond the buckets"
        );
        // SAFETY: just checked.
        unsafe { self.visit_unchecked(a, b, value) }
    }

    /// [`EdgeVisitor::visit`] for a walk that has checked its vertices: the walks check a whole
    /// face's at once, and the checks per corner (the vertex, the slots' range) took registers
    /// the walk spilled (see `LoopWriter` in `mesh::build` for what that gained).
    ///
    /// # Safety
    /// `a` and `b` are below [`EdgeVisitor::n_vertices`].
    #[inline(always)]
    pub(crate) unsafe fn visit_unchecked(&mut self, a: u32, b: u32, value: u32) -> EdgeVisit {
        debug_assert!(value <= MAX_EDGE_VALUE && a != b);
        let (low, high, forward) = if a < b { (a, b, FORWARD) } else { (b, a, 0) };
        let opened = (u64::from(high) << 32) | forward | u64::from(value);
        // SAFETY: `low` is below the vertex count, `start`'s length minus one; `start` never
        // decreases and ends at the slot count (`EdgeBuckets::new` makes it so, and nothing
        // changes it after), so every bucket is a range of the slots.
        let bucket = unsafe {
            let (first, end) = (
                *self.start.get_unchecked(low as usize),
                *self.start.get_unchecked(low as usize + 1),
            );
            self.slots.get_unchecked_mut(first as usize..end as usize)
        };
        for slot in bucket {
            if *slot == 0 {
                *slot = opened;
                return EdgeVisit::Opened;
            }
            if (*slot >> 32) as u32 == high {
                return pair(slot, forward);
            }
        }
        self.overflow.visit(low, high, opened)
    }
}

/// Where the edges without a slot in their vertex's bucket are kept.
struct Overflow {
    /// The edges of the vertices with more room than [`LARGEST_SCANNED_BUCKET`].
    large: LargeBuckets,
    /// Edges that found their bucket full, by [`edge_key`].
    spill: HashMap<u64, u64>,
}

impl Overflow {
    /// Meets the edge `low`–`high` with the slot a corner would open it with (`opened`), as
    /// [`EdgeVisitor::visit`].
    #[cold]
    #[inline(never)]
    fn visit(&mut self, low: u32, high: u32, opened: u64) -> EdgeVisit {
        let slot = match self.large.slot_mut(low, high) {
            Some(slot) => slot,
            // A slot that was opened is never 0 (its larger vertex is not).
            None => self.spill.entry(edge_key(low, high)).or_insert(0),
        };
        if *slot == 0 {
            *slot = opened;
            EdgeVisit::Opened
        } else {
            pair(slot, opened & FORWARD)
        }
    }
}

/// A second or later corner (direction `forward`) on the open or closed edge in `slot`; the
/// edge is closed afterwards either way.
#[inline(always)]
fn pair(slot: &mut u64, forward: u64) -> EdgeVisit {
    let first = *slot & VALUE_MASK;
    let same_direction = *slot & FORWARD == forward;
    *slot |= CLOSED;
    if first == CLOSED || same_direction {
        EdgeVisit::Defective
    } else {
        EdgeVisit::Paired(first as u32)
    }
}

/// An undirected edge as one sortable number: smaller vertex high, larger low.
#[inline]
pub(crate) fn edge_key(low: u32, high: u32) -> u64 {
    (u64::from(low) << 32) | u64::from(high)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::FaceList;

    #[test]
    fn opposite_corner_pairs_same_way_or_third_is_defective_and_overflow_spills() {
        let positions = vec![[0.0; 3]; 4];
        // One forward corner per vertex 0 and 1: edge 0-2 is only walked backward (2→0), so
        // vertex 0's bucket (room 1) overflows into the spill map.
        let indices = [0, 1, 2, 1, 3, 2];
        let table = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap();
        let mut buckets = EdgeBuckets::new(&table, 4, 0).unwrap();
        assert_eq!(buckets.visit(0, 1, 7), EdgeVisit::Opened);
        assert_eq!(buckets.visit(2, 0, 8), EdgeVisit::Opened);
        assert_eq!(buckets.visit(1, 0, 9), EdgeVisit::Paired(7));
        assert_eq!(buckets.visit(0, 2, 10), EdgeVisit::Paired(8));
        assert_eq!(buckets.visit(0, 2, 11), EdgeVisit::Defective);
        assert_eq!(buckets.visit(1, 0, 12), EdgeVisit::Defective);
        assert_eq!(buckets.visit(3, 1, MAX_EDGE_VALUE), EdgeVisit::Opened);
        assert_eq!(buckets.visit(1, 3, 0), EdgeVisit::Paired(MAX_EDGE_VALUE));
        // Same direction twice, in a bucket and in the spill map.
        assert_eq!(buckets.visit(1, 2, 0), EdgeVisit::Opened);
        assert_eq!(buckets.visit(1, 2, 1), EdgeVisit::Defective);
        assert_eq!(buckets.visit(3, 0, 0), EdgeVisit::Opened);
        assert_eq!(buckets.visit(3, 0, 1), EdgeVisit::Defective);
        assert_eq!(buckets.visit(0, 3, 1), EdgeVisit::Defective);
    }

    #[test]
    fn prefetching_any_face_changes_no_visit() {
        // Vertex 3, the largest, has no forward corner: its bucket is empty and starts where the
        // slots end.
        let positions = vec![[0.0; 3]; 4];
        let indices = [0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2];
        let table = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap();
        let visits = |prefetch: bool| {
            let mut buckets = EdgeBuckets::new(&table, 4, 0).unwrap();
            let mut visitor = buckets.visitor();
            let mut seen = Vec::new();
            for f in 0..table.n_faces() {
                if prefetch {
                    visitor.prefetch_ahead_of(&table, f);
                    visitor.prefetch_face(&table, f);
                    visitor.prefetch_face(&table, f + 2);
                    visitor.prefetch_face(&table, usize::MAX);
                }
                for (a, b) in face_edges(table.face(f)) {
                    seen.push(visitor.visit(a, b, f as u32));
                }
            }
            seen
        };
        let plain = visits(false);
        assert_eq!(plain.iter().filter(|v| **v == EdgeVisit::Opened).count(), 6);
        assert_eq!(visits(true), plain);
    }

    /// The guards the walks' unchecked visits rest on: a vertex beyond the buckets is refused,
    /// and the first visitor is the only one.
    #[test]
    fn a_vertex_beyond_the_buckets_or_a_second_first_visitor_panics() {
        let positions = vec![[0.0; 3]; 3];
        let table = FaceTable::new(&FaceList::triangles(&positions, &[0, 1, 2])).unwrap();
        let mut buckets = EdgeBuckets::new(&table, 3, 0).unwrap();
        assert_eq!(buckets.visitor().n_vertices(), 3);
        let beyond = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            buckets.visit(1, 3, 0);
        }));
        assert!(beyond.is_err());
        assert!(
            std::panic::catch_unwind(|| {
                let mut fresh = EdgeBuckets::new(&table, 3, 0).unwrap();
                assert_eq!(fresh.first_visitor().visit(0, 1, 0), EdgeVisit::Opened);
                fresh.first_visitor();
            })
            .is_err()
        );
    }

    /// Vertices with more forward corners than a bucket is given among the others (a fan and a
    /// star on one edge around them, numbered first or last, and reversed and repeated faces on
    /// their edges) meet their edges as a plain map of first corners would have them, whether
    /// each corner met them through a large bucket, a scanned one or the spill map.
    #[test]
    fn large_buckets_meet_edges_as_small_ones_do() {
        let k = 3 * LARGEST_SCANNED_BUCKET;
        let n_vertices = k + 3;
        let mut faces: Vec<[u32; 3]> = Vec::new();
        faces.extend((0..k).map(|i| [0, i + 2, i + 3]));
        faces.extend((0..k).map(|i| [0, 1, i + 2]));
        faces.extend((0..k).step_by(7).map(|i| [i + 3, i + 2, 0]));
        faces.extend((0..k).step_by(5).map(|i| [1, 0, i + 2]));
        faces.extend((0..k).step_by(11).map(|i| [0, i + 2, i + 3]));
        let positions = vec![[0.0; 3]; n_vertices as usize];
        for hub_last in [false, true] {
            let renumber = |v: u32| if hub_last { n_vertices - 1 - v } else { v };
            let indices: Vec<u32> = faces.iter().flatten().map(|&v| renumber(v)).collect();
            let table = FaceTable::new(&FaceList::triangles(&positions, &indices)).unwrap();
            let mut buckets = EdgeBuckets::new(&table, n_vertices as usize, 0).unwrap();
            if !hub_last {
                // Vertices 0 and 1 run forward to ~k vertices each: no slots among the others.
                assert_eq!(buckets.start[0], buckets.start[2]);
            }
            // The first corner's value and direction per edge, and whether it was closed.
            let mut first: HashMap<(u32, u32), (u32, bool, bool)> = HashMap::new();
            let mut visitor = buckets.visitor();
            let mut n_defective = 0;
            for (c, (a, b)) in (0..).zip(table.faces().flat_map(face_edges)) {
                let key = (a.min(b), a.max(b));
                let expected = match first.get_mut(&key) {
                    None => {
                        first.insert(key, (c, a < b, false));
                        EdgeVisit::Opened
                    }
                    Some((value, forward, closed)) => {
                        let paired = !*closed && *forward != (a < b);
                        *closed = true;
                        if paired {
                            EdgeVisit::Paired(*value)
                        } else {
                            EdgeVisit::Defective
                        }
                    }
                };
                n_defective += usize::from(expected == EdgeVisit::Defective);
                assert_eq!(
                    visitor.visit(a, b, c),
                    expected,
                    "{a}→{b}, hub last: {hub_last}"
                );
            }
            assert!(n_defective > k as usize);
            if !hub_last {
                // Every edge of vertices 0 and 1 had its slot in their large buckets.
                assert!(visitor.overflow.spill.is_empty());
            }
        }
    }

    #[test]
    fn malformed_faces_give_no_buckets() {
        let positions = vec![[0.0; 3]; 4];
        for (sizes, indices) in [
            (&[3][..], &[0, 1, 4][..]),
            (&[3], &[0, 1, 0]),
            (&[2, 3], &[0, 1, 1, 2, 3]),
            (&[4], &[0, 1, 2, 1]),
        ] {
            let table = FaceTable::new(&FaceList::polygons(&positions, sizes, indices)).unwrap();
            assert!(EdgeBuckets::new(&table, 4, 0).is_none(), "{indices:?}");
        }
    }
}
