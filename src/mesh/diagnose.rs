//! Analysis of a face list without keeping a mesh: the diagnostic a user reads before deciding on
//! a policy.

use super::Mesh;
use crate::OutOfMemory;
use crate::soup::{Diagnostic, FaceList};

impl Mesh {
    /// Everything wrong with `list` as it is, by index: malformed faces, non-finite
    /// coordinates, non-manifold and inconsistently oriented edges, non-manifold and isolated
    /// vertices, degenerate faces (see [`Diagnostic`] for each definition). The lists of what a
    /// policy changes are empty: this describes the input, not a build. When the list as a whole
    /// is malformed, only [`Diagnostic::list_problem`] is set.
    ///
    /// # Errors
    /// [`OutOfMemory`] when the analysis needs more memory than the system gives (checked
    /// before anything the size of the list is allocated).
    pub fn diagnose(list: &FaceList<'_>) -> Result<Diagnostic, OutOfMemory> {
        crate::soup::diagnose(list)
    }
}
