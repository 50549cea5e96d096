//! The front both kernels' bulk builders share: a face walk over [`EdgeBuckets`] on well-formed
//! input, and [`resolve`] first only for input that needs a policy decision.

use std::borrow::Cow;

use super::edge_buckets::EdgeBuckets;
use super::resolve::resolve;
use super::table::{MAX_VERTICES, non_finite_vertices};
use super::{BuildError, BuildPolicy, DegenerateFaces, Diagnostic, FaceList, FaceTable};
use crate::large_arrays;

/// What a builder's walk made, with the table it walked, the positions of its vertices (the
/// input's, then those of repair's copies) and the diagnostic so far (degenerate faces
/// included).
pub(crate) struct Walked<'a, T> {
    pub(crate) walked: T,
    pub(crate) table: FaceTable<'a>,
    pub(crate) positions: Vec<[f64; 3]>,
    pub(crate) diagnostic: Diagnostic,
}

/// A builder's face walk: `walk(table, buckets, positions, degenerate)` meets every corner's edge
/// in the buckets, checks each face's area into `degenerate` when given one, and gives `None` on
/// an edge defect.
pub(crate) trait Walk<T>:
    Fn(&FaceTable<'_>, &mut EdgeBuckets, &[[f64; 3]], Option<&mut DegenerateFaces<'_>>) -> Option<T>
    + Sync
{
}

impl<T, W> Walk<T> for W where
    W: Fn(
            &FaceTable<'_>,
            &mut EdgeBuckets,
            &[[f64; 3]],
            Option<&mut DegenerateFaces<'_>>,
        ) -> Option<T>
        + Sync
{
}

/// Runs `walk` (see [`Walk`]) directly on well-formed input, else on the table [`resolve`] makes
/// under `policy` (where it cannot meet a defect).
pub(crate) fn walk_faces<'a, T: Send>(
    list: &FaceList<'a>,
    policy: BuildPolicy,
    walk: impl Walk<T>,
) -> Result<Walked<'a, T>, BuildError> {
    // The structure's copy of the positions needs nothing from the faces: with two threads it
    // is made beside the bucket count; with one, after the walk, in the buckets' block, whose
    // pages are faulted in already (cold memory, one thread, best of 300 builds in three rounds
    // taking turns: armadillo 9.4-9.7 -> 8.8-9.1 ms; 1M-triangle torus, best of 100: 32.0-32.3
    // -> 31.3-32.1 ms).
    let copy_early = thread_count() > 1;
    let later_positions = if copy_early { 0 } else { list.positions.len() };
    let mut input_copy = None;
    // Lists with more vertices than ids are left to resolve to refuse, before anything the size
    // of the input is allocated.
    if list.positions.len() as u64 <= MAX_VERTICES {
        let (edges, (early_copy, non_finite_vertices)) = join(
            || well_formed_edges(list, later_positions),
            || {
                let copy = copy_early.then(|| large_arrays::copied(list.positions));
                (copy, non_finite_vertices(list.positions))
            },
        );
        input_copy = early_copy;
        if let Some((table, mut buckets)) = edges {
            let (walked, degenerate_faces) =
                walk_checking_areas(&table, &mut buckets, list.positions, &walk);
            // Strict refuses non-finite coordinates: resolve says so, with the diagnostic.
            if let Some(walked) = walked
                && (non_finite_vertices.is_empty() || policy != BuildPolicy::Strict)
            {
                let diagnostic = Diagnostic {
                    non_finite_vertices,
                    degenerate_faces,
                    ..Diagnostic::default()
                };
                let positions =
                    input_copy.unwrap_or_else(|| buckets.into_positions(list.positions));
                return Ok(Walked {
                    walked,
                    table,
                    positions,
                    diagnostic,
                });
            }
        }
    }
    let resolved = resolve(list, policy)?;
    let mut buckets = EdgeBuckets::new(&resolved.table, resolved.positions.len(), later_positions)
        .expect("a resolved face table is well formed");
    let (walked, degenerate_faces) =
        walk_checking_areas(&resolved.table, &mut buckets, &resolved.positions, &walk);
    let walked = walked.expect("a resolved face table has no edge defects");
    let mut diagnostic = resolved.diagnostic;
    diagnostic.degenerate_faces = degenerate_faces;
    let positions = match resolved.positions {
        Cow::Borrowed(input) => input_copy.unwrap_or_else(|| buckets.into_positions(input)),
        Cow::Owned(repaired) => repaired,
    };
    Ok(Walked {
        walked,
        table: resolved.table,
        positions,
        diagnostic,
    })
}

/// `walk(table, buckets, positions, degenerate)` with the degenerate faces of `table` (input
/// face indices, ascending): found in a pass of their own beside the walk when a second thread is
/// free; with one thread, by the walk itself as it reads each face when the vertex order follows
/// the faces (the position loads then hide in the walk's), else in a pass of their own before
/// it, where the scattered position loads overlap each other instead of the walk's misses
/// (measured: about 10% faster on the scanned models; on the generated torus the pass of its
/// own is 5% slower than checking in the walk).
fn walk_checking_areas<T: Send>(
    table: &FaceTable<'_>,
    buckets: &mut EdgeBuckets,
    positions: &[[f64; 3]],
    walk: &impl Walk<T>,
) -> (Option<T>, Vec<u32>) {
    let beside = thread_count() > 1 || !buckets.vertices_follow_faces();
    let (found_beside, (walked, found_in_walk)) = join(
        || beside.then(|| DegenerateFaces::of_table(table, positions)),
        || {
            let mut degenerate = (!beside).then(|| DegenerateFaces::new(positions));
            (
                walk(table, buckets, positions, degenerate.as_mut()),
                degenerate,
            )
        },
    );
    let degenerate_faces = found_beside
        .or(found_in_walk.map(DegenerateFaces::into_faces))
        .unwrap_or_default();
    (walked, degenerate_faces)
}

/// `list` laid out as a table, with the buckets of its edges, when no face needs a policy
/// decision: the list is consistent, no face is too small, out of range or repeats a vertex
/// (`list` has at most [`MAX_VERTICES`] vertices). Builders try this fast path first and call
/// [`resolve`] only for the rest (non-finite coordinates and edge defects are theirs to find on
/// it).
fn well_formed_edges<'a>(
    list: &FaceList<'a>,
    later_positions: usize,
) -> Option<(FaceTable<'a>, EdgeBuckets)> {
    let n_vertices = list.positions.len();
    let table = FaceTable::new(list).ok()?;
    let buckets = EdgeBuckets::new(&table, n_vertices, later_positions)?;
    Some((table, buckets))
}

/// Threads of the pool the build runs in (1 without the `parallel` feature).
fn thread_count() -> usize {
    #[cfg(feature = "parallel")]
    {
        rayon::current_num_threads()
    }
    #[cfg(not(feature = "parallel"))]
    {
        1
    }
}

/// Runs `a` and `b`, in parallel when the `parallel` feature and the thread pool allow.
fn join<A: Send, B: Send>(a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
    #[cfg(feature = "parallel")]
    {
        rayon::join(a, b)
    }
    #[cfg(not(feature = "parallel"))]
    {
        (a(), b())
    }
}
