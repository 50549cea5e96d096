//! The front both kernels' bulk builders share: a face walk over [`EdgeBuckets`] on well-formed
//! input, and [`resolve`] first only for input that needs a policy decision.

use std::borrow::Cow;

use super::edge_buckets::EdgeBuckets;
use super::orient::has_inward_closed_component;
use super::resolve::resolve;
use super::table::{MAX_VERTICES, non_finite_among, non_finite_vertices};
use super::{BuildError, BuildPolicy, DegenerateFaces, Diagnostic, FaceList, FaceTable};
use crate::support::large_arrays;

/// What a builder's walk made, with the table it walked, the positions of its vertices (the
/// input's, then those of repair's copies) and the diagnostic so far (degenerate faces
/// included).
pub(crate) struct Walked<'a, T> {
    pub(crate) walked: T,
    pub(crate) table: FaceTable<'a>,
    pub(crate) positions: Vec<[f64; 3]>,
    /// Vertices the structure must hold as deleted (see [`super::Resolved::deleted_vertices`]).
    pub(crate) deleted_vertices: Vec<u32>,
    pub(crate) diagnostic: Diagnostic,
}

/// How [`walk_faces`] gets to the faces it walks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Route {
    /// Straight from the list when it is well formed, through [`resolve`] otherwise.
    Direct,
    /// Through [`resolve`] whatever the list (for a list whose direct build showed a vertex
    /// with several fans, which only resolve splits or refuses).
    Resolve,
}

/// A structure a builder made: does a vertex have a fan its circulation misses?
pub(crate) trait Pinched {
    /// Whether some vertex's faces form several fans that the structure keeps apart.
    fn has_pinched_vertices(&self) -> bool;
}

/// Builds with `build(route)`: directly first, and again through [`resolve`] when the direct
/// build has a vertex with several fans (the usual input has none, and the direct build finds
/// that out in one pass over its half-edges).
pub(crate) fn build_splitting_pinched<S: Pinched>(
    build: impl Fn(Route) -> Result<(S, Diagnostic), BuildError>,
) -> Result<(S, Diagnostic), BuildError> {
    let direct = build(Route::Direct)?;
    if !direct.0.has_pinched_vertices() {
        return Ok(direct);
    }
    let resolved = build(Route::Resolve)?;
    debug_assert!(!resolved.0.has_pinched_vertices());
    Ok(resolved)
}

/// What a builder's walk made, which knows the vertices no face reached.
pub(crate) trait Unreached {
    /// The vertices no walked face has, ascending: the isolated vertices of the build.
    fn unreached_vertices(&self) -> Vec<u32>;
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

/// Runs `walk` (see [`Walk`]) directly on well-formed input with finite coordinates (when
/// `route` allows), else on the table [`resolve`] makes under `policy` (where it cannot meet a
/// defect). The diagnostic has the isolated vertices.
pub(crate) fn walk_faces<'a, T: Send + Unreached>(
    list: &FaceList<'a>,
    policy: BuildPolicy,
    route: Route,
    walk: impl Walk<T>,
) -> Result<Walked<'a, T>, BuildError> {
    list.ensure_working_room()?;
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
    if route == Route::Direct && list.positions.len() as u64 <= MAX_VERTICES {
        let (edges, early_copy) = join(
            || well_formed_edges(list, later_positions),
            || copy_early.then(|| large_arrays::copied(list.positions)),
        );
        input_copy = early_copy;
        if let Some((table, mut buckets)) = edges {
            let (walked, areas) = walk_checking_areas(&table, &mut buckets, list.positions, &walk);
            if let Some(walked) = walked {
                let isolated_vertices = walked.unreached_vertices();
                // Every corner's coordinates were read by the area check: when all were finite,
                // only isolated vertices can have others.
                let non_finite_vertices = if areas.corners_finite() {
                    non_finite_among(list.positions, &isolated_vertices)
                } else {
                    non_finite_vertices(list.positions)
                };
                // Non-finite coordinates never enter a structure: resolve refuses them or
                // leaves their faces out. Repair turns inward closed components outward, which
                // only resolve does.
                let turns_outward = policy == BuildPolicy::Repair
                    && has_inward_closed_component(&table, list.positions);
                if non_finite_vertices.is_empty() && !turns_outward {
                    let diagnostic = Diagnostic {
                        degenerate_faces: areas.into_faces(),
                        isolated_vertices,
                        ..Diagnostic::default()
                    };
                    let positions =
                        input_copy.unwrap_or_else(|| buckets.into_positions(list.positions));
                    return Ok(Walked {
                        walked,
                        table,
                        positions,
                        deleted_vertices: Vec::new(),
                        diagnostic,
                    });
                }
            }
        }
    }
    let resolved = resolve(list, policy)?;
    let mut buckets = EdgeBuckets::new(&resolved.table, resolved.positions.len(), later_positions)
        .expect("a resolved face table is well formed");
    // The areas are findings, and resolve has them from the input: the walk checks none.
    let walked = walk(&resolved.table, &mut buckets, &resolved.positions, None)
        .expect("a resolved face table has no edge defects");
    let diagnostic = resolved.diagnostic;
    let positions = match resolved.positions {
        Cow::Borrowed(input) => input_copy.unwrap_or_else(|| buckets.into_positions(input)),
        Cow::Owned(repaired) => repaired,
    };
    Ok(Walked {
        walked,
        table: resolved.table,
        positions,
        deleted_vertices: resolved.deleted_vertices,
        diagnostic,
    })
}

/// `walk(table, buckets, positions, degenerate)` with the area check of every face of `table`
/// (its degenerate faces as input face indices, ascending, and whether every corner was finite):
/// made in a pass of its own beside the walk when a second thread is free; with one thread, by
/// the walk itself as it reads each face when the vertex order follows the faces (the position
/// loads then hide in the walk's), else in a pass of its own before it, where the scattered
/// position loads overlap each other instead of the walk's misses (measured: about 10% faster on
/// the scanned models; on the generated torus the pass of its own is 5% slower than checking in
/// the walk).
fn walk_checking_areas<'p, T: Send>(
    table: &FaceTable<'_>,
    buckets: &mut EdgeBuckets,
    positions: &'p [[f64; 3]],
    walk: &impl Walk<T>,
) -> (Option<T>, DegenerateFaces<'p>) {
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
    let areas = found_beside
        .or(found_in_walk)
        .expect("the areas are checked beside the walk or in it");
    (walked, areas)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Mesh, VertexId};
    use crate::winged::Winged;

    /// The diagnostic's non-finite and isolated vertices under `policy` (of the refusal, if it is
    /// one), from both kernels, with
    /// one thread and, with the `parallel` feature, two (the area check, which finds the
    /// non-finite corners, then runs beside the walk instead of in it or before it).
    fn vertex_findings(list: &FaceList<'_>, policy: BuildPolicy) -> Vec<(Vec<u32>, Vec<u32>)> {
        let findings = || {
            let diagnostics = [
                Mesh::from_face_list(list, policy).map(|(_, d)| d),
                Winged::from_face_list(list, policy).map(|(_, d)| d),
            ];
            diagnostics.map(|built| {
                let diagnostic = built.unwrap_or_else(|error| error.diagnostic().clone());
                (diagnostic.non_finite_vertices, diagnostic.isolated_vertices)
            })
        };
        #[cfg(feature = "parallel")]
        let pools = [1, 2];
        #[cfg(not(feature = "parallel"))]
        let pools = [1];
        pools
            .into_iter()
            .flat_map(|_threads| {
                #[cfg(feature = "parallel")]
                return rayon::ThreadPoolBuilder::new()
                    .num_threads(_threads)
                    .build()
                    .unwrap()
                    .install(findings);
                #[cfg(not(feature = "parallel"))]
                findings()
            })
            .collect()
    }

    /// A NaN or infinite coordinate is reported wherever it is, at a corner of a triangle, a quad
    /// or a hexagon, or at a vertex no face has; in a vertex order that follows the faces (one
    /// thread checks the areas in the walk) or not (in a pass before it). Finite coordinates
    /// whose squares overflow are not reported, and no position is changed.
    #[test]
    fn non_finite_vertices_are_found_at_corners_and_isolated_vertices() {
        let n = 24u32;
        let at = |i: u32, j: u32| i * (n + 1) + j;
        let grid: Vec<[f64; 3]> = (0..=n)
            .flat_map(|i| (0..=n).map(move |j| [f64::from(i), f64::from(j), 0.0]))
            .collect();
        let isolated = grid.len() as u32;
        let (mut triangles, mut quads, mut mixed, mut mixed_sizes) =
            (vec![], vec![], vec![], vec![]);
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                triangles.extend([a, b, c, a, c, d]);
                quads.extend([a, b, c, d]);
                match j % 3 {
                    0 => {
                        mixed_sizes.push(6);
                        mixed.extend([a, b, c, at(i + 1, j + 2), at(i, j + 2), d]);
                    }
                    1 => {}
                    _ => {
                        mixed_sizes.push(4);
                        mixed.extend([a, b, c, d]);
                    }
                }
            }
        }
        let n_vertices = isolated + 1;
        let scatter = |v: u32| v * 7919 % n_vertices;
        for renumber in [&(|v| v) as &dyn Fn(u32) -> u32, &scatter] {
            let mut positions = vec![[0.0; 3]; n_vertices as usize];
            for (v, &point) in grid.iter().chain(&[[0.5, 0.5, 1.0]]).enumerate() {
                positions[renumber(v as u32) as usize] = point;
            }
            let renumbered = |indices: &[u32]| indices.iter().map(|&v| renumber(v)).collect();
            let (triangles, quads, mixed): (Vec<u32>, Vec<u32>, Vec<u32>) = (
                renumbered(&triangles),
                renumbered(&quads),
                renumbered(&mixed),
            );
            let isolated = renumber(isolated);
            let corner = renumber(at(n / 2, n / 2));
            let quad_sizes = vec![4; quads.len() / 4];
            for bad in [corner, isolated] {
                for value in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let mut positions = positions.clone();
                    positions[bad as usize][1] = value;
                    let lists = [
                        FaceList::triangles(&positions, &triangles),
                        FaceList::polygons(&positions, &quad_sizes, &quads),
                        FaceList::polygons(&positions, &mixed_sizes, &mixed),
                    ];
                    for list in &lists {
                        let policies =
                            [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair];
                        for policy in policies {
                            for (non_finite, isolated_found) in vertex_findings(list, policy) {
                                assert_eq!(non_finite, [bad], "{value} at {bad}, {policy:?}");
                                // Refused or built, the findings are the input's.
                                assert_eq!(isolated_found, [isolated]);
                            }
                        }
                        assert!(Mesh::from_face_list(list, BuildPolicy::Strict).is_err());
                        // The vertex never enters the mesh: its faces are left out, and it is
                        // there as a deleted vertex (its position zeroed), keeping the ids.
                        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
                            let (mesh, diagnostic) = Mesh::from_face_list(list, policy).unwrap();
                            assert!(mesh.is_vertex_deleted(VertexId(bad)));
                            assert_eq!(mesh.positions()[bad as usize], [0.0; 3]);
                            assert!(mesh.positions().iter().flatten().all(|x| x.is_finite()));
                            let table = FaceTable::new(list).unwrap();
                            let faces_at_bad: Vec<u32> = (0..table.n_faces() as u32)
                                .filter(|&f| table.face(f as usize).contains(&bad))
                                .collect();
                            assert_eq!(diagnostic.skipped_faces, faces_at_bad);
                            assert_eq!(mesh.n_faces(), table.n_faces() - faces_at_bad.len());
                            assert_eq!(mesh.n_vertices(), positions.len() - 1);
                            mesh.check().unwrap();
                            let (winged, _) = Winged::from_face_list(list, policy).unwrap();
                            assert!(!winged.is_vertex(crate::winged::VertexId(bad)));
                            winged.check().unwrap();
                        }
                    }
                }
            }
            let huge: Vec<[f64; 3]> = positions.iter().map(|p| p.map(|x| x * 1e200)).collect();
            for list in [
                FaceList::triangles(&huge, &triangles),
                FaceList::polygons(&huge, &mixed_sizes, &mixed),
            ] {
                for (non_finite, isolated_found) in vertex_findings(&list, BuildPolicy::Strict) {
                    assert!(non_finite.is_empty());
                    assert_eq!(isolated_found, [isolated]);
                }
            }
        }
    }
}
