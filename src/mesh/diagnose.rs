//! Analysis of a face list without keeping a mesh: the diagnostic a user reads before deciding on
//! a policy.

use super::Mesh;
use crate::soup::{BuildPolicy, Diagnostic, FaceList};

impl Mesh {
    /// Everything wrong with `list`, by index, whatever it is: malformed faces, non-finite
    /// coordinates, non-manifold and inconsistently oriented edges, non-manifold and isolated
    /// vertices, degenerate faces.
    ///
    /// It is the diagnostic of a [`BuildPolicy::Skip`] build, so
    /// [`Diagnostic::skipped_faces`] lists the faces such a build leaves out (malformed ones, then
    /// those that cannot be placed in input order); vertex-level findings are those of the faces
    /// kept. When the list as a whole is malformed, only [`Diagnostic::list_problem`] is set.
    pub fn diagnose(list: &FaceList<'_>) -> Diagnostic {
        match Mesh::from_face_list(list, BuildPolicy::Skip) {
            Ok((_, diagnostic)) => diagnostic,
            Err(error) => error.diagnostic().clone(),
        }
    }
}
