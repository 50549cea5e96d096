//! Applying a [`BuildPolicy`] to a face list: find every defect, then refuse, leave out or repair
//! until the faces pair into an oriented 2-manifold (up to non-manifold vertices, which the
//! structures can hold). Both kernels build from the result.

use std::borrow::Cow;
use std::collections::HashMap;

use super::orient::{faces_to_flip, flip_faces};
use super::pairing::{EdgeDefect, EdgePairing, ProblemEdge, pair_edges};
use super::table::{MAX_VERTICES, non_finite_vertices};
use super::umbrellas::split_umbrellas;
use super::{BuildError, BuildPolicy, Diagnostic, EdgeReport, FaceList, FaceTable, ListProblem};

/// Rounds of "copy the endpoints of the refused faces' edges" before repair gives each still
/// refused face vertices of its own (which always succeeds).
const REPAIR_ROUNDS: usize = 8;

/// A face list made buildable: every corner's edge pairs with at most one other corner, walking
/// it the other way.
#[derive(Debug)]
pub struct Resolved<'a> {
    /// The faces to build, with their input face indices.
    pub table: FaceTable<'a>,
    /// Positions of the built vertices: the input's, then those of repair's copies.
    pub positions: Cow<'a, [[f64; 3]]>,
    /// Every defect found so far (builders add vertex-level and geometric findings).
    pub diagnostic: Diagnostic,
}

/// Checks `list` and applies `policy` (see [`BuildPolicy`] for what each one does).
pub fn resolve<'a>(list: &FaceList<'a>, policy: BuildPolicy) -> Result<Resolved<'a>, BuildError> {
    let mut diagnostic = Diagnostic::default();
    let invalid = |diagnostic: Diagnostic| BuildError::InvalidInput(Box::new(diagnostic));
    let n_input_vertices = list.positions.len();
    if n_input_vertices as u64 > MAX_VERTICES {
        diagnostic.list_problem = Some(ListProblem::TooManyElements {
            what: "vertices",
            count: n_input_vertices as u64,
        });
        return Err(invalid(diagnostic));
    }
    let mut table = match FaceTable::new(list) {
        Ok(table) => table,
        Err(problem) => {
            diagnostic.list_problem = Some(problem);
            return Err(invalid(diagnostic));
        }
    };

    let defects = table.face_defects(n_input_vertices);
    diagnostic.non_finite_vertices = non_finite_vertices(list.positions);
    diagnostic.faces_too_small = defects.too_small.clone();
    diagnostic.faces_out_of_range = defects.out_of_range.clone();
    diagnostic.faces_repeated_vertex = defects.repeated_vertex.clone();
    let mut copies = VertexCopies::new(n_input_vertices);
    match policy {
        BuildPolicy::Strict if diagnostic.has_invalid_input() => return Err(invalid(diagnostic)),
        BuildPolicy::Strict => {}
        BuildPolicy::Skip if !defects.is_empty() => {
            let mut keep = vec![true; table.n_faces()];
            for &f in defects
                .too_small
                .iter()
                .chain(&defects.out_of_range)
                .chain(&defects.repeated_vertex)
            {
                keep[f as usize] = false;
            }
            diagnostic.skipped_faces = (0..table.n_faces() as u32)
                .filter(|&f| !keep[f as usize])
                .collect();
            table = table.retain(&keep);
        }
        BuildPolicy::Skip => {}
        BuildPolicy::Repair => {
            if !defects.too_small.is_empty() || !defects.out_of_range.is_empty() {
                return Err(invalid(diagnostic));
            }
            if !defects.repeated_vertex.is_empty() {
                let (repaired, collapsed) =
                    repair_repeated_vertices(&table, &defects.repeated_vertex, &mut copies)?;
                if !collapsed.is_empty() {
                    diagnostic.faces_too_small = collapsed;
                    return Err(invalid(diagnostic));
                }
                table = repaired;
            }
        }
    }

    let mut pairing = pair_edges(&table, copies.n_vertices());
    if !pairing.problems.is_empty() {
        report_problems(&table, &pairing.problems, &mut diagnostic);
        match policy {
            BuildPolicy::Strict => return Err(BuildError::NonManifold(Box::new(diagnostic))),
            BuildPolicy::Skip => {
                let refused = first_come_refusals(&table, &pairing.problems);
                let mut keep = vec![true; table.n_faces()];
                for &(f, _) in &refused {
                    keep[f] = false;
                }
                diagnostic
                    .skipped_faces
                    .extend(refused.iter().map(|&(f, _)| table.input_face(f)));
                diagnostic.skipped_faces.sort_unstable();
                table = table.retain(&keep);
                pairing = pair_edges(&table, copies.n_vertices());
            }
            BuildPolicy::Repair => {
                let flips = faces_to_flip(&table, &pairing);
                if !flips.is_empty() {
                    diagnostic.reoriented_faces =
                        flips.iter().map(|&f| table.input_face(f)).collect();
                    flip_faces(&mut table, &flips);
                    pairing = pair_edges(&table, copies.n_vertices());
                }
                if split_umbrellas(&mut table, &pairing, &mut copies)? {
                    pairing = pair_edges(&table, copies.n_vertices());
                }
                pairing = repair_edges(&mut table, pairing, &mut copies)?;
                copies.drop_unused(&mut table);
            }
        }
    }
    debug_assert!(pairing.problems.is_empty());

    let positions = if copies.copied_from.is_empty() {
        Cow::Borrowed(list.positions)
    } else {
        let mut positions = list.positions.to_vec();
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
        diagnostic,
    })
}

/// Vertices added by repair, each remembering the input vertex it copies.
pub(super) struct VertexCopies {
    n_input: usize,
    copied_from: Vec<u32>,
}

impl VertexCopies {
    fn new(n_input: usize) -> Self {
        VertexCopies {
            n_input,
            copied_from: Vec::new(),
        }
    }

    pub(super) fn n_vertices(&self) -> usize {
        self.n_input + self.copied_from.len()
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
        let original = match (vertex as usize).checked_sub(self.n_input) {
            Some(copy) => self.copied_from[copy],
            None => vertex,
        };
        self.copied_from.push(original);
        Ok(id as u32)
    }

    /// Drops the copies no corner uses any more and renumbers the others, in order: a later
    /// repair round moves refused corners off the copies an earlier step gave them, and a copy
    /// left behind would be a vertex repair added to the mesh with nothing on it.
    fn drop_unused(&mut self, table: &mut FaceTable<'_>) {
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
/// the vertex. Returns the repaired table and the faces left with fewer than 3 corners.
fn repair_repeated_vertices(
    table: &FaceTable<'_>,
    faces: &[u32],
    copies: &mut VertexCopies,
) -> Result<(FaceTable<'static>, Vec<u32>), BuildError> {
    let mut offsets = Vec::with_capacity(table.n_faces() + 1);
    let mut corners = Vec::with_capacity(table.n_corners());
    let mut collapsed = Vec::new();
    let mut next_repair = faces.iter().peekable();
    offsets.push(0);
    for f in 0..table.n_faces() {
        let face = table.face(f);
        if next_repair
            .next_if(|&&repair| repair as usize == f)
            .is_none()
        {
            corners.extend_from_slice(face);
        } else {
            let start = corners.len();
            for (i, &v) in face.iter().enumerate() {
                let previous = face[(i + face.len() - 1) % face.len()];
                if v == previous {
                    continue;
                }
                let v = if corners[start..].contains(&v) {
                    copies.copy(v)?
                } else {
                    v
                };
                corners.push(v);
            }
            if corners.len() - start < 3 {
                collapsed.push(table.input_face(f));
            }
        }
        offsets.push(corners.len() as u32);
    }
    Ok((
        FaceTable::from_parts(offsets, corners, Some(table.input_faces())),
        collapsed,
    ))
}

/// Lists the problem edges in the diagnostic, with input vertex and face indices.
fn report_problems(table: &FaceTable<'_>, problems: &[ProblemEdge], diagnostic: &mut Diagnostic) {
    for problem in problems {
        let mut faces: Vec<u32> = problem
            .corners
            .iter()
            .map(|&c| table.input_face(table.face_of_corner(c as usize)))
            .collect();
        faces.sort_unstable();
        let report = EdgeReport {
            vertices: problem.vertices,
            faces,
        };
        match problem.defect {
            EdgeDefect::NonManifold => diagnostic.non_manifold_edges.push(report),
            EdgeDefect::Inconsistent => diagnostic.inconsistent_edges.push(report),
        }
    }
}

/// Takes faces in table order and refuses a face when one of its problem edges is already used in
/// its direction by an accepted face. Returns the refused faces with their problem corners.
fn first_come_refusals(
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

/// Gives the faces that cannot share their problem edges copies of those edges' endpoints, round
/// after round, until everything pairs; after [`REPAIR_ROUNDS`] rounds the faces still refused
/// get vertices of their own.
fn repair_edges(
    table: &mut FaceTable<'_>,
    mut pairing: EdgePairing,
    copies: &mut VertexCopies,
) -> Result<EdgePairing, BuildError> {
    for round in 0..=REPAIR_ROUNDS {
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
