//! Filling holes: closing a boundary loop of a [`Mesh`] with triangles on its own corners (no
//! new vertex), like CGAL's `triangulate_hole`.
//!
//! Which triangulation: a loop of at most [`EXACT_CORNERS_MAX`] corners gets Liepa's
//! minimum-weight triangulation (smallest largest angle between the normals of neighbouring
//! triangles — new ones and the faces around the hole — or between a new triangle and the
//! hole's mean normal, then the least bent patch); it costs O(n³)
//! time and O(n²) memory, hence the bound. A longer loop is projected onto its best-fit plane
//! (across its Newell normal) and, when the projection is a simple polygon, triangulated there
//! in O(n log n), then improved by edge flips that lower the angles between neighbouring normals
//! (at most a fixed number per corner). A long loop whose projection crosses or touches itself
//! is refused ([`FillError::NotSimple`]).
//!
//! Never folded: before the mesh is touched, every triangulation passes the fold test — no new
//! triangle is degenerate (twice its area at most [`DEGENERATE_RATIO`] times its longest side
//! squared) and none has a normal turned more than [`FOLD_ANGLE_DEGREES`] from the normal of a
//! face beside it (a new triangle, or the face across the hole's rim). A hole that fails is left
//! open with [`FillError::Folded`].
//!
//! New faces, edges and corners get zero user attributes (as [`Mesh::add_face`] and
//! [`Mesh::split_face`] give them); the mesh keeps no per-corner normals or texture coordinates
//! of its own, so a mesh exported afterwards has none on the new faces. No vertex is added.

mod folds;
mod geometry;
mod projected;
mod weights;

use thiserror::Error;

pub use folds::{DEGENERATE_RATIO, FOLD_ANGLE_DEGREES};

use crate::mesh::{EditError, FaceId, HalfedgeId, HandleError, JoinedCorners, Mesh, VertexId};
use folds::{Fold, first_fold};
use geometry::{norm, sub, unit};
use projected::{ProjectionRefusal, projected_triangles};

/// Loops of at most this many corners get the exact minimum-weight triangulation; longer ones
/// the O(n log n) projected triangulation. 100 corners: about 1.7·10⁵ candidate triangles.
pub const EXACT_CORNERS_MAX: usize = 100;

/// Which holes [`fill_holes`] fills.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HoleFillOptions {
    /// Holes with more boundary edges than this are left open.
    pub max_edges: usize,
    /// Holes whose perimeter (the sum of their boundary edges' lengths) exceeds this are left
    /// open; infinity for no bound.
    pub max_perimeter: f64,
}

impl Default for HoleFillOptions {
    /// Every hole: no bound on edges or perimeter.
    fn default() -> Self {
        HoleFillOptions {
            max_edges: usize::MAX,
            max_perimeter: f64::INFINITY,
        }
    }
}

/// What filling one hole added.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FilledHole {
    /// The boundary half-edge the hole was named by (for [`fill_holes`]: the one
    /// [`Mesh::boundary_loops`] listed for it).
    pub boundary_halfedge: HalfedgeId,
    /// Boundary edges (and corners) of the hole.
    pub edges: usize,
    /// The new triangles (`edges − 2` of them). No vertex is added.
    pub faces: Vec<FaceId>,
}

/// What [`fill_holes`] did, hole by hole.
#[derive(Debug, Default, PartialEq)]
pub struct HoleFillReport {
    /// The holes filled, in the order of [`Mesh::boundary_loops`].
    pub filled: Vec<FilledHole>,
    /// The holes within the bounds that were refused, each by one of its boundary half-edges,
    /// with the reason; they are left open.
    pub refused: Vec<(HalfedgeId, FillError)>,
    /// The holes beyond the bounds, left open.
    pub skipped: usize,
}

impl HoleFillReport {
    /// The faces added over all holes.
    pub fn faces_added(&self) -> usize {
        self.filled.iter().map(|h| h.faces.len()).sum()
    }
}

/// Why a hole was not filled; the mesh is unchanged.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum FillError {
    /// The half-edge names no live element.
    #[error(transparent)]
    Handle(#[from] HandleError),
    /// The half-edge has a face: it is not on a hole.
    #[error("hole filling refused: the half-edge is not on a boundary")]
    NotBoundary,
    /// An option is out of range.
    #[error("hole filling refused: option {name} is {value}: it must be {range}")]
    BadOption {
        /// The option's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The values it may take.
        range: &'static str,
    },
    /// The hole's boundary passes twice through one vertex: a fill would pinch it.
    #[error("hole filling refused: the boundary passes twice through vertex {0}")]
    RepeatedVertex(u32),
    /// Every triangulation tried needs an edge between two of the hole's vertices that an edge
    /// already joins: a second edge would make the mesh non-manifold.
    #[error("hole filling refused: every triangulation needs an edge that exists already")]
    Joined,
    /// The hole is longer than [`EXACT_CORNERS_MAX`] and its projection onto its best-fit plane
    /// crosses or touches itself, or it has no area to be projected.
    #[error("hole filling refused: the boundary does not project onto a simple polygon")]
    NotSimple,
    /// The best triangulation found folds: a new triangle would be degenerate, or turned more
    /// than [`FOLD_ANGLE_DEGREES`] from a face beside it.
    #[error("hole filling refused: the fill would fold ({0})")]
    Folded(String),
    /// The mesh refused the new faces (a vertex whose fans cannot take them, ids exhausted).
    #[error(transparent)]
    Edit(#[from] EditError),
}

/// The half-edges of the boundary loop through `h` in loop order; corner `i` is the origin of
/// side `i`.
fn boundary_sides(mesh: &Mesh, h: HalfedgeId) -> Result<Vec<HalfedgeId>, FillError> {
    mesh.check_halfedge(h)?;
    if !mesh.is_boundary_halfedge(h) {
        return Err(FillError::NotBoundary);
    }
    Ok(mesh.halfedge_loop(h).collect())
}

/// Unit normal of the face across boundary side `s`, zero when it has none or no area.
fn face_normal_across(mesh: &Mesh, s: HalfedgeId) -> [f64; 3] {
    let f = mesh.face(s.twin());
    if !f.is_valid() {
        return [0.0; 3];
    }
    unit(crate::geom::newell_vector(
        mesh.face_vertices(f).map(|v| mesh.position(v)),
    ))
}

/// Fills the hole whose boundary loop holds `h` with triangles on its corners (see the module
/// docs for which) and returns them.
///
/// # Errors
/// Refused, with the mesh unchanged, when `h` is invalid or has a face, when the loop passes
/// twice through one vertex, when every triangulation needs an edge that exists already, when
/// a long loop does not project onto a simple polygon, or when the fill would fold.
pub fn fill_hole(mesh: &mut Mesh, h: HalfedgeId) -> Result<FilledHole, FillError> {
    let sides = boundary_sides(mesh, h)?;
    let n = sides.len();
    let corners: Vec<VertexId> = sides.iter().map(|&s| mesh.origin(s)).collect();
    let mut seen = std::collections::HashSet::with_capacity(n);
    if let Some(v) = corners.iter().find(|v| !seen.insert(v.0)) {
        return Err(FillError::RepeatedVertex(v.0));
    }
    let points: Vec<[f64; 3]> = corners.iter().map(|&v| mesh.position(v)).collect();
    let rim_normals: Vec<[f64; 3]> = sides.iter().map(|&s| face_normal_across(mesh, s)).collect();
    let joined = JoinedCorners::new(mesh, &corners);
    let triangles = if n <= EXACT_CORNERS_MAX {
        let is_joined = |i: usize, j: usize| !joined.may_join(i as u32, j as u32);
        weights::minimum_weight_triangles(&points, &rim_normals, &is_joined)
            .ok_or(FillError::Joined)?
    } else {
        projected_triangles(&points, &rim_normals, &joined).map_err(|e| match e {
            ProjectionRefusal::Joined => FillError::Joined,
            ProjectionRefusal::NoPlane | ProjectionRefusal::NotSimple => FillError::NotSimple,
        })?
    };
    match first_fold(&points, &rim_normals, &triangles) {
        None => {}
        Some(Fold::Degenerate(_)) => {
            return Err(FillError::Folded("a new triangle has no area".into()));
        }
        Some(Fold::Folded(_, angle)) => {
            return Err(FillError::Folded(format!(
                "a new triangle turns {angle:.1}° from a face beside it"
            )));
        }
    }
    let mut chords = Vec::with_capacity(n.saturating_sub(3));
    crate::mesh::chords_of(&triangles, n as u32, &mut chords);
    if !joined.allows(&chords) {
        return Err(FillError::Joined);
    }
    let f = mesh.add_face(&corners)?;
    // Side i now belongs to `f` and leads into corner i + 1.
    let into: Vec<HalfedgeId> = (0..n).map(|i| sides[(i + n - 1) % n]).collect();
    let faces = match mesh.cut_along_chords(f, into, &chords) {
        Ok(faces) => faces,
        Err(e) => {
            mesh.delete_face(f, false)
                .expect("a face just added is live");
            return Err(e.into());
        }
    };
    Ok(FilledHole {
        boundary_halfedge: h,
        edges: n,
        faces,
    })
}

/// Fills every hole within `options`' bounds, in the order of [`Mesh::boundary_loops`], and
/// reports each one filled, refused (left open, see [`fill_hole`]) or skipped.
///
/// # Errors
/// [`FillError::BadOption`] when `max_perimeter` is NaN or negative (the mesh is unchanged).
pub fn fill_holes(mesh: &mut Mesh, options: &HoleFillOptions) -> Result<HoleFillReport, FillError> {
    if options.max_perimeter.is_nan() || options.max_perimeter < 0.0 {
        return Err(FillError::BadOption {
            name: "max_perimeter",
            value: options.max_perimeter,
            range: "0 or more (infinity for no bound)",
        });
    }
    let mut report = HoleFillReport::default();
    for h in mesh.boundary_loops() {
        let sides = boundary_sides(mesh, h)?;
        let perimeter: f64 = sides
            .iter()
            .map(|&s| {
                norm(sub(
                    mesh.position(mesh.target(s)),
                    mesh.position(mesh.origin(s)),
                ))
            })
            .sum();
        if sides.len() > options.max_edges
            || perimeter.is_nan()
            || perimeter > options.max_perimeter
        {
            report.skipped += 1;
            continue;
        }
        match fill_hole(mesh, h) {
            Ok(hole) => report.filled.push(hole),
            Err(e) => report.refused.push((h, e)),
        }
    }
    Ok(report)
}
