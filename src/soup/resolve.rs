//! Applying a [`BuildPolicy`] to a face list: find every defect, then refuse, leave out or repair
//! until the faces pair into an oriented 2-manifold whose every vertex has one fan. Both kernels
//! build from the result.

use std::borrow::Cow;
use std::collections::{HashMap, HashSet};

use super::inspect::{Inspection, inspect};
use super::orient::{faces_facing_inward, faces_to_flip, flip_faces};
use super::pairing::{EdgePairing, ProblemEdge, pair_edges};
use super::table::{MAX_VERTICES, has_repeated_vertex};
use super::umbrellas::{split_non_manifold_vertices, split_umbrellas};
use super::{BuildError, BuildPolicy, Diagnostic, FaceList, FaceTable, ListProblem};

/// Rounds of "copy the endpoints of the refused faces' edges" before repair gives each still
/// refused face vertices of its own (which always succeeds).
const REPAIR_ROUNDS: usize = 8;

/// A face list made buildable: every corner's edge pairs with at most one other corner, walking
/// it the other way, and the faces around every vertex form one fan.
#[derive(Debug)]
pub struct Resolved<'a> {
    /// The faces to build, with their input face indices.
    pub table: FaceTable<'a>,
    /// Positions of the built vertices: the input's, then those of the copies (see
    /// [`Diagnostic::vertex_copies`]); the slots of [`Resolved::deleted_vertices`] hold zeros.
    pub positions: Cow<'a, [[f64; 3]]>,
    /// Input vertices the structure must hold as deleted: those with a non-finite coordinate,
    /// which never enter a structure (their faces are left out).
    pub deleted_vertices: Vec<u32>,
    /// The input's findings and what the policy changed (builders add nothing but the areas).
    pub diagnostic: Diagnostic,
}

/// Checks `list` and applies `policy` (see [`BuildPolicy`] for what each one does).
pub fn resolve<'a>(list: &FaceList<'a>, policy: BuildPolicy) -> Result<Resolved<'a>, BuildError> {
    list.ensure_working_room()?;
    let Inspection {
        mut table,
        defects,
        mut diagnostic,
        ..
    } = inspect(list).map_err(BuildError::InvalidInput)?;
    if policy == BuildPolicy::Strict {
        if diagnostic.has_invalid_input() {
            return Err(BuildError::InvalidInput(Box::new(diagnostic)));
        }
        if diagnostic.has_edge_defects() || !diagnostic.non_manifold_vertices.is_empty() {
            return Err(BuildError::NonManifold(Box::new(diagnostic)));
        }
        return Ok(Resolved {
            table,
            positions: Cow::Borrowed(list.positions),
            deleted_vertices: Vec::new(),
            diagnostic,
        });
    }

    // Faces no policy can keep: too small, out of range, on a non-finite vertex, and under Skip
    // those that repeat a vertex.
    let mut unkept: Vec<u32> = defects
        .too_small
        .iter()
        .chain(&defects.out_of_range)
        .copied()
        .collect();
    if policy == BuildPolicy::Skip {
        unkept.extend(&defects.repeated_vertex);
    }
    let non_finite = &diagnostic.non_finite_vertices;
    if !non_finite.is_empty() {
        let is_non_finite = |v: &u32| non_finite.binary_search(v).is_ok();
        unkept.extend(
            (0..table.n_faces() as u32)
                .filter(|&f| table.face(f as usize).iter().any(is_non_finite)),
        );
    }
    unkept.sort_unstable();
    unkept.dedup();
    let mut left_out = unkept.clone();
    table = without_faces(table, &unkept);

    let mut copies = VertexCopies::new(list.positions.len());
    let mut flipped = Vec::new();
    match policy {
        BuildPolicy::Strict => unreachable!("handled above"),
        BuildPolicy::Skip => {
            let pairing = pair_edges(&table, copies.n_vertices());
            if !pairing.problems.is_empty() {
                let mut refused: Vec<u32> = first_come_refusals(&table, &pairing.problems)
                    .into_iter()
                    .map(|(f, _)| f as u32)
                    .collect();
                left_out.extend(refused.iter().map(|&f| table.input_face(f as usize)));
                refused.sort_unstable();
                table = without_faces(table, &refused);
            }
        }
        BuildPolicy::Repair => {
            let collapsed;
            (table, collapsed) = repair_repeated_vertices(table, &mut copies)?;
            left_out.extend(collapsed);
            let mut pairing = pair_edges(&table, copies.n_vertices());
            if !pairing.problems.is_empty() {
                flipped = faces_to_flip(&table, &pairing);
                if !flipped.is_empty() {
                    flip_faces(&mut table, &flipped);
                    pairing = pair_edges(&table, copies.n_vertices());
                }
                if split_umbrellas(&mut table, &pairing, &mut copies)? {
                    pairing = pair_edges(&table, copies.n_vertices());
                }
                repair_edges(&mut table, pairing, &mut copies, |_| true)?;
            }
        }
    }
    left_out.sort_unstable();
    diagnostic.skipped_faces = left_out;

    let pairing = pair_edges(&table, copies.n_vertices());
    debug_assert!(pairing.problems.is_empty());
    split_non_manifold_vertices(&mut table, &pairing, &mut copies)?;
    if policy == BuildPolicy::Repair {
        copies.drop_unused(&mut table);
        // Splitting a vertex keeps every paired corner paired: the pairing still holds.
        let position = |v: u32| list.positions[copies.original(v) as usize];
        let inward = faces_facing_inward(&table, &pairing, position);
        flip_faces(&mut table, &inward);
        diagnostic.reoriented_faces = symmetric_difference(&flipped, &inward)
            .map(|f| table.input_face(f))
            .collect();
    }

    let deleted_vertices = diagnostic.non_finite_vertices.clone();
    let positions = if copies.copied_from.is_empty() && deleted_vertices.is_empty() {
        Cow::Borrowed(list.positions)
    } else {
        let mut positions = list.positions.to_vec();
        for &v in &deleted_vertices {
            positions[v as usize] = [0.0; 3];
        }
        positions.extend(
            copies
                .copied_from
                .iter()
                .map(|&v| list.positions[v as usize]),
        );
        Cow::Owned(positions)
    };
    diagnostic.vertex_copies = copies.copied_from;
    Ok(Resolved {
        table,
        positions,
        deleted_vertices,
        diagnostic,
    })
}

/// `table` without its faces `faces` (table indices, ascending).
fn without_faces<'a>(table: FaceTable<'a>, faces: &[u32]) -> FaceTable<'a> {
    if faces.is_empty() {
        return table;
    }
    let mut keep = vec![true; table.n_faces()];
    for &f in faces {
        keep[f as usize] = false;
    }
    table.retain(&keep)
}

/// The elements of exactly one of two ascending lists, ascending.
pub(crate) fn symmetric_difference<'l>(
    a: &'l [usize],
    b: &'l [usize],
) -> impl Iterator<Item = usize> + 'l {
    let (mut i, mut j) = (0, 0);
    std::iter::from_fn(move || {
        loop {
            match (a.get(i), b.get(j)) {
                (Some(&x), Some(&y)) if x == y => (i, j) = (i + 1, j + 1),
                (Some(&x), Some(&y)) if x < y => {
                    i += 1;
                    return Some(x);
                }
                (_, Some(&y)) => {
                    j += 1;
                    return Some(y);
                }
                (Some(&x), None) => {
                    i += 1;
                    return Some(x);
                }
                (None, None) => return None,
            }
        }
    })
}

/// Vertices added by repair, each remembering the input vertex it copies.
pub(crate) struct VertexCopies {
    n_input: usize,
    copied_from: Vec<u32>,
}

impl VertexCopies {
    pub(crate) fn new(n_input: usize) -> Self {
        VertexCopies {
            n_input,
            copied_from: Vec::new(),
        }
    }

    pub(crate) fn n_vertices(&self) -> usize {
        self.n_input + self.copied_from.len()
    }

    /// The input vertex each copy copies, in the order the copies were made.
    pub(crate) fn copied_from(&self) -> &[u32] {
        &self.copied_from
    }

    /// The input vertex `vertex` is (or copies).
    fn original(&self, vertex: u32) -> u32 {
        match (vertex as usize).checked_sub(self.n_input) {
            Some(copy) => self.copied_from[copy],
            None => vertex,
        }
    }

    /// A new vertex at the position of `vertex` (an input vertex or an earlier copy).
    pub(super) fn copy(&mut self, vertex: u32) -> Result<u32, BuildError> {
        let id = self.n_vertices() as u64;
        if id > MAX_VERTICES {
            let diagnostic = Diagnostic {
                list_problem: Some(ListProblem::TooManyElements {
                    what: "vertices",
                    count: id + 1,
                }),
                ..Diagnostic::default()
            };
            return Err(BuildError::InvalidInput(Box::new(diagnostic)));
        }
        let original = self.original(vertex);
        self.copied_from.push(original);
        Ok(id as u32)
    }

    /// Drops the copies no corner uses any more and renumbers the others, in order: a later
    /// repair round moves refused corners off the copies an earlier step gave them, and a copy
    /// left behind would be a vertex repair added to the mesh with nothing on it.
    pub(crate) fn drop_unused(&mut self, table: &mut FaceTable<'_>) {
        let copy_index = |v: u32| (v as usize).checked_sub(self.n_input);
        let mut used = vec![false; self.copied_from.len()];
        for &v in table.corners() {
            if let Some(copy) = copy_index(v) {
                used[copy] = true;
            }
        }
        if used.iter().all(|&u| u) {
            return;
        }
        let mut new_id = vec![u32::MAX; used.len()];
        let mut kept = Vec::new();
        for (copy, &original) in self.copied_from.iter().enumerate() {
            if used[copy] {
                new_id[copy] = (self.n_input + kept.len()) as u32;
                kept.push(original);
            }
        }
        for v in table.corners_mut() {
            if let Some(copy) = copy_index(*v) {
                *v = new_id[copy];
            }
        }
        self.copied_from = kept;
    }
}

/// Collapses consecutive repeats (cyclically) and gives later non-consecutive repeats a copy of
/// the vertex, in every face of `table` that names a vertex twice. Returns the repaired table
/// without the faces left with fewer than 3 corners, and those faces' input indices.
fn repair_repeated_vertices<'a>(
    table: FaceTable<'a>,
    copies: &mut VertexCopies,
) -> Result<(FaceTable<'a>, Vec<u32>), BuildError> {
    let mut scratch = Vec::new();
    let mut repeats = |f: usize| has_repeated_vertex(table.face(f), &mut scratch);
    let repaired: Vec<bool> = (0..table.n_faces()).map(&mut repeats).collect();
    if !repaired.contains(&true) {
        return Ok((table, Vec::new()));
    }
    let mut offsets = Vec::with_capacity(table.n_faces() + 1);
    let mut corners = Vec::with_capacity(table.n_corners());
    let mut input_faces = Vec::with_capacity(table.n_faces());
    let mut collapsed = Vec::new();
    let mut seen = HashSet::new();
    offsets.push(0);
    for (f, &repair) in repaired.iter().enumerate() {
        let face = table.face(f);
        let start = corners.len();
        if !repair {
            corners.extend_from_slice(face);
        } else {
            seen.clear();
            for (i, &v) in face.iter().enumerate() {
                let previous = face[(i + face.len() - 1) % face.len()];
                if v == previous {
                    continue;
                }
                let v = if seen.insert(v) { v } else { copies.copy(v)? };
                corners.push(v);
            }
            if corners.len() - start < 3 {
                corners.truncate(start);
                collapsed.push(table.input_face(f));
                continue;
            }
        }
        offsets.push(corners.len() as u32);
        input_faces.push(table.input_face(f));
    }
    Ok((
        FaceTable::from_parts(offsets, corners, Some(input_faces)),
        collapsed,
    ))
}

/// Takes faces in table order and refuses a face when one of its problem edges is already used in
/// its direction by an accepted face. Returns the refused faces with their problem corners.
pub(crate) fn first_come_refusals(
    table: &FaceTable<'_>,
    problems: &[ProblemEdge],
) -> Vec<(usize, Vec<usize>)> {
    // (face, problem, direction, corner) for every corner on a problem edge, in face order.
    let mut claims: Vec<(usize, usize, usize, usize)> = problems
        .iter()
        .enumerate()
        .flat_map(|(p, problem)| {
            problem.corners.iter().map(move |&c| {
                let forward = table.corners()[c as usize] == problem.vertices[0];
                (
                    table.face_of_corner(c as usize),
                    p,
                    usize::from(forward),
                    c as usize,
                )
            })
        })
        .collect();
    claims.sort_unstable();
    let mut taken = vec![[false; 2]; problems.len()];
    let mut refused = Vec::new();
    for face_claims in claims.chunk_by(|a, b| a.0 == b.0) {
        if face_claims.iter().all(|&(_, p, dir, _)| !taken[p][dir]) {
            for &(_, p, dir, _) in face_claims {
                taken[p][dir] = true;
            }
        } else {
            refused.push((
                face_claims[0].0,
                face_claims.iter().map(|claim| claim.3).collect(),
            ));
        }
    }
    refused
}

/// Gives the faces that cannot share their problem edges (those `wanted` selects) copies of those edges' endpoints, round
/// after round, until everything pairs; after [`REPAIR_ROUNDS`] rounds the faces still refused
/// get vertices of their own.
pub(crate) fn repair_edges(
    table: &mut FaceTable<'_>,
    mut pairing: EdgePairing,
    copies: &mut VertexCopies,
    wanted: impl Fn(&ProblemEdge) -> bool,
) -> Result<EdgePairing, BuildError> {
    for round in 0..=REPAIR_ROUNDS {
        pairing.problems.retain(&wanted);
        if pairing.problems.is_empty() {
            break;
        }
        let refused = first_come_refusals(table, &pairing.problems);
        let mut round_copies: HashMap<u32, u32> = HashMap::new();
        for (face, problem_corners) in refused {
            let targets: Vec<usize> = if round < REPAIR_ROUNDS {
                problem_corners
                    .iter()
                    .flat_map(|&c| [c, table.next_corner(c)])
                    .collect()
            } else {
                table.face_range(face).collect()
            };
            for c in targets {
                let vertex = table.corners()[c];
                let copy = match round_copies.get(&vertex) {
                    // Refused faces of one round share copies, so they can pair among themselves;
                    // the last round's copies are private to one corner.
                    Some(&copy) if round < REPAIR_ROUNDS => copy,
                    _ => {
                        let copy = copies.copy(vertex)?;
                        round_copies.insert(vertex, copy);
                        copy
                    }
                };
                table.corners_mut()[c] = copy;
            }
        }
        pairing = pair_edges(table, copies.n_vertices());
    }
    Ok(pairing)
}
