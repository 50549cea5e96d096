//! What is wrong with a face list as it is, before any policy acts on it: the findings half of
//! every [`Diagnostic`].

use super::degenerate::DegenerateFaces;
use super::pairing::{EdgeDefect, EdgePairing, ProblemEdge, pair_edges};
use super::table::{MAX_VERTICES, non_finite_vertices};
use super::umbrellas::Fans;
use super::{Diagnostic, EdgeReport, FaceDefects, FaceList, FaceTable, ListProblem};
use crate::OutOfMemory;

/// A face list laid out as a table, with its malformed faces and the diagnostic of its findings.
pub(crate) struct Inspection<'a> {
    /// Every face of the list, malformed ones included.
    pub(crate) table: FaceTable<'a>,
    /// The malformed faces.
    pub(crate) defects: FaceDefects,
    /// The faces that are not malformed, which the edge, fan and area findings are about.
    pub(crate) well_formed: FaceTable<'a>,
    /// The pairing of `well_formed`'s edges.
    pub(crate) pairing: EdgePairing,
    /// The findings (the policy lists are empty).
    pub(crate) diagnostic: Diagnostic,
}

/// Everything wrong with `list` as it is (see [`Diagnostic`] for each finding's definition), or
/// the diagnostic of a list that is malformed as a whole.
pub(crate) fn inspect<'a>(list: &FaceList<'a>) -> Result<Inspection<'a>, Box<Diagnostic>> {
    let n_vertices = list.positions.len();
    let list_problem = |problem: ListProblem| {
        Box::new(Diagnostic {
            list_problem: Some(problem),
            ..Diagnostic::default()
        })
    };
    if n_vertices as u64 > MAX_VERTICES {
        return Err(list_problem(ListProblem::TooManyElements {
            what: "vertices",
            count: n_vertices as u64,
        }));
    }
    let table = FaceTable::new(list).map_err(list_problem)?;
    let defects = table.face_defects(n_vertices);
    let mut diagnostic = Diagnostic {
        faces_too_small: defects.too_small.clone(),
        faces_out_of_range: defects.out_of_range.clone(),
        faces_repeated_vertex: defects.repeated_vertex.clone(),
        non_finite_vertices: non_finite_vertices(list.positions),
        isolated_vertices: unnamed_vertices(&table, n_vertices),
        ..Diagnostic::default()
    };
    // Edges, fans and areas are those of the well-formed faces.
    let well_formed = if defects.is_empty() {
        table.clone()
    } else {
        let mut keep = vec![true; table.n_faces()];
        for &f in defects
            .too_small
            .iter()
            .chain(&defects.out_of_range)
            .chain(&defects.repeated_vertex)
        {
            keep[f as usize] = false;
        }
        table.retain(&keep)
    };
    let pairing = pair_edges(&well_formed, n_vertices);
    report_problems(&well_formed, &pairing.problems, &mut diagnostic);
    diagnostic.non_manifold_vertices = Fans::through_shared_edges(&well_formed, &pairing)
        .non_manifold_vertices(&well_formed, n_vertices);
    diagnostic.degenerate_faces =
        DegenerateFaces::of_table(&well_formed, list.positions).into_faces();
    Ok(Inspection {
        table,
        defects,
        well_formed,
        pairing,
        diagnostic,
    })
}

/// The vertices below `n_vertices` that no face of `table` names (malformed faces count),
/// ascending.
pub(crate) fn unnamed_vertices(table: &FaceTable<'_>, n_vertices: usize) -> Vec<u32> {
    let mut named = vec![false; n_vertices];
    for &v in table.corners() {
        if let Some(named) = named.get_mut(v as usize) {
            *named = true;
        }
    }
    (0..n_vertices as u32)
        .filter(|&v| !named[v as usize])
        .collect()
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

/// The findings of `list` as it is (see [`Diagnostic`]; the lists of what a policy changes are
/// empty). When the list as a whole is malformed, only [`Diagnostic::list_problem`] is set.
///
/// # Errors
/// [`OutOfMemory`] when the analysis needs more memory than the system gives (checked before
/// anything the size of the list is allocated).
pub fn diagnose(list: &FaceList<'_>) -> Result<Diagnostic, OutOfMemory> {
    list.ensure_working_room()?;
    Ok(match inspect(list) {
        Ok(inspection) => inspection.diagnostic,
        Err(diagnostic) => *diagnostic,
    })
}
