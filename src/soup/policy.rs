//! What a builder does with input it cannot represent as it is, and how it says no.

use super::Diagnostic;

/// How a builder treats faces that cannot be placed in a manifold structure.
///
/// Whatever the policy, the returned [`Diagnostic`] lists every defect of the input as it is, and
/// apart from them what the policy changed. Isolated vertices and degenerate faces are kept and
/// reported, never refused. Whatever the policy, a built structure holds no non-finite
/// coordinate (such a vertex is there as a deleted vertex, keeping the ids of the others) and no
/// non-manifold vertex (several fans of faces touching at a vertex, which a vertex's circulation
/// could not see whole): `Strict` refuses them, `Skip` and `Repair` leave out the faces on
/// non-finite vertices and give every fan of a non-manifold vertex but the first a copy of the
/// vertex ([`Diagnostic::vertex_copies`]). An empty face list is valid: it builds a structure
/// with no faces (its vertices, if any, isolated).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BuildPolicy {
    /// Refuse any malformed face, non-finite coordinate, non-manifold or inconsistently oriented
    /// edge, or non-manifold vertex: the build gives the input exactly as it is, or fails with
    /// the diagnostic.
    #[default]
    Strict,
    /// Leave out malformed faces and faces on a non-finite vertex, then the faces that cannot be
    /// placed: faces are taken in input order and a face is left out when one of its edges is
    /// already used in its direction (as OpenMesh's `add_face` loop does). Left-out faces are
    /// listed in [`Diagnostic::skipped_faces`]; then non-manifold vertices are split.
    Skip,
    /// Keep every face that can be kept: a vertex named twice in one face loses its consecutive
    /// repeats and gets a copy for a non-consecutive one; faces are reversed where that makes
    /// their neighbours agree; then the surface is cut along the edges that are still
    /// non-manifold or inconsistently oriented, and every fan of faces around their endpoints
    /// gets a vertex of its own (as CGAL's polygon-soup orientation does: two cubes sharing an
    /// edge become two closed cubes); faces that still cannot share an edge get copies of its
    /// endpoints; non-manifold vertices are split; last, every closed component that encloses a
    /// negative volume is reversed, so closed components face outward. Copies are recorded in
    /// [`Diagnostic::vertex_copies`], reversed faces in [`Diagnostic::reoriented_faces`]. Faces
    /// that cannot be kept — fewer than 3 distinct corners, an out-of-range index, a corner on a
    /// non-finite vertex — are left out and listed in [`Diagnostic::skipped_faces`]: Repair
    /// accepts every input `Skip` accepts.
    Repair,
}

/// Why a build failed. Every variant carries the full diagnostic.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BuildError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
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

/// The diagnostic of a build that ran out of memory before it had one.
static NOTHING_FOUND: Diagnostic = Diagnostic::EMPTY;

impl BuildError {
    /// The diagnostic of the refused input (empty when memory ran out before it was made).
    pub fn diagnostic(&self) -> &Diagnostic {
        match self {
            BuildError::InvalidInput(d) | BuildError::NonManifold(d) => d,
            BuildError::OutOfMemory(_) => &NOTHING_FOUND,
        }
    }
}
