//! What a builder does with input it cannot represent as it is, and how it says no.

use super::Diagnostic;

/// How a builder treats faces that cannot be placed in a manifold structure.
///
/// Whatever the policy, every defect is listed in the returned [`Diagnostic`]; isolated vertices,
/// degenerate faces and non-manifold vertices the structure can hold (several fans touching at a
/// vertex) are kept and reported, never refused. Non-finite coordinates are refused by `Strict`
/// and kept (reported) by `Skip` and `Repair`, which only act on connectivity. An empty face list
/// is valid: it builds a structure with no faces (its vertices, if any, isolated).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BuildPolicy {
    /// Refuse any malformed face, non-finite coordinate, non-manifold or inconsistently oriented
    /// edge: the build fails with the diagnostic.
    #[default]
    Strict,
    /// Leave out malformed faces, then the faces that cannot be placed: faces are taken in input
    /// order and a face is left out when one of its edges is already used in its direction
    /// (as OpenMesh's `add_face` loop does). Left-out faces are listed in
    /// [`Diagnostic::skipped_faces`].
    Skip,
    /// Keep every face: a vertex named twice in one face loses its consecutive repeats and gets a
    /// copy for a non-consecutive one; faces are reversed where that makes their neighbours agree
    /// (listed in [`Diagnostic::reoriented_faces`]); then the surface is cut along the edges that
    /// are still non-manifold or inconsistently oriented, and every fan of faces around their
    /// endpoints gets a vertex of its own (as CGAL's polygon-soup orientation does: two cubes
    /// sharing an edge become two closed cubes); faces that still cannot share an edge get copies
    /// of its endpoints. Copies are recorded in [`Diagnostic::vertex_copies`]. Faces with an out-of-range
    /// index or fewer than 3 distinct corners cannot be kept, so the build fails instead of
    /// dropping them.
    Repair,
}

/// Why a build failed. Every variant carries the full diagnostic.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BuildError {
    /// The input is malformed: the list as a whole (sizes vs. indices, 32-bit overflow), faces
    /// with fewer than 3 corners, out-of-range or repeated indices, or (under
    /// [`BuildPolicy::Strict`]) non-finite coordinates.
    #[error("invalid face list:\n{0}")]
    InvalidInput(Box<Diagnostic>),
    /// Under [`BuildPolicy::Strict`]: the faces do not form an oriented 2-manifold
    /// (non-manifold or inconsistently oriented edges).
    #[error("face list is not an oriented manifold:\n{0}")]
    NonManifold(Box<Diagnostic>),
}

impl BuildError {
    /// The diagnostic of the refused input.
    pub fn diagnostic(&self) -> &Diagnostic {
        match self {
            BuildError::InvalidInput(d) | BuildError::NonManifold(d) => d,
        }
    }
}
