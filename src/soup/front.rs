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
    Fn(&FaceTable<'_>, EdgeBuckets, &[[f64; 3]], Option<&mut DegenerateFaces<'_>>) -> Option<T> + Sync
{
}

impl<T, W> Walk<T> for W where
    W: Fn(&FaceTable<'_>, EdgeBuckets, &[[f64; 3]], Option<&mut DegenerateFaces<'_>>) -> Option<T>
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
    let mut input_copy = None;
    // Lists with more vertices than ids are left to resolve to refuse, before anything the size
    // of the input is allocated.
    if list.positions.len() as u64 <= MAX_VERTICES {
        // The structure's copy of the positions and their check need nothing from the faces:
        // with two threads they are made beside the bucket count; with one, just before the
        // walk, which then finds the positions in cache.
        let (edges, (positions, non_finite_vertices)) = join(
            || well_formed_edges(list),
            || {
                let copy = large_arrays::copied(list.positions);
                (copy, non_finite_vertices(list.positions))
            },
        );
        if let Some((table, buckets)) = edges {
            let (walked, degenerate_faces) =
                walk_checking_areas(&table, buckets, list.positions, &walk);
            // Strict refuses non-finite coordinates: resolve says so, with the diagnostic.
            if let Some(walked) = walked
                && (non_finite_vertices.is_empty() || policy != BuildPolicy::Strict)
            {
                let diagnostic = Diagnostic {
                    non_finite_vertices,
                    degenerate_faces,
                    ..Diagnostic::default()
                };
                return Ok(Walked {
                    walked,
                    table,
                    positions,
                    diagnostic,
                });
            }
        }
        input_copy = Some(positions);
    }
    let resolved = resolve(list, policy)?;
    let buckets = EdgeBuckets::new(&resolved.table, resolved.positions.len())
        .expect("a resolved face table is well formed");
    let (walked, degenerate_faces) =
        walk_checking_areas(&resolved.table, buckets, &resolved.positions, &walk);
    let walked = walked.expect("a resolved face table has no edge defects");
    let mut diagnostic = resolved.diagnostic;
    diagnostic.degenerate_faces = degenerate_faces;
    let positions = match resolved.positions {
        Cow::Borrowed(input) => input_copy.unwrap_or_else(|| large_arrays::copied(input)),
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
    buckets: EdgeBuckets,
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
fn well_formed_edges<'a>(list: &FaceList<'a>) -> Option<(FaceTable<'a>, EdgeBuckets)> {
    let n_vertices = list.positions.len();
    let table = FaceTable::new(list).ok()?;
    let buckets = EdgeBuckets::new(&table, n_vertices)?;
    Some((table, buckets))
}

/// Threads of the pool the build runs in (1 without the `parallel` feature).
pub(crate) fn thread_count() -> usize {
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
pub(crate) fn join<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    #[cfg(feature = "parallel")]
    {
        rayon::join(a, b)
    }
    #[cfg(not(feature = "parallel"))]
    {
        (a(), b())
    }
}
