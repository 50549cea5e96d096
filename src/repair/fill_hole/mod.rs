//! Filling holes: closing a boundary loop of a [`Mesh`] with triangles on its own corners (no
//! new vertex), like CGAL's `triangulate_hole`.
//!
//! What a good fill is: one that spans the hole like the plane across its mean (Newell)
//! normal, bent only as the surface around it is. Each new triangle's *turn* is the largest of
//! its tilt from the mean normal, its angle to each new triangle beside it, and its angle to a
//! face across the hole's rim beyond the angle the mean plane makes with that face.
//!
//! Which triangulation: a loop of at most [`EXACT_CORNERS_MAX`] corners gets Liepa's
//! minimum-weight triangulation (the smallest largest turn, then the least bent patch); it
//! costs O(n³) time and O(n²) memory, hence the bound. A longer loop is projected onto its
//! best-fit plane (across its Newell normal) and, when the projection is a simple polygon,
//! triangulated there in O(n log n), then improved by edge flips that lower the largest turn of
//! the two triangles (at most a fixed number per corner). A long loop whose projection crosses
//! or touches itself is refused ([`FillError::NotSimple`]).
//!
//! Never folded: before the mesh is touched, every triangulation passes the fold test — no new
//! triangle is degenerate (twice its area at most [`DEGENERATE_RATIO`] times its longest side
//! squared) and none has a normal turned more than [`FOLD_ANGLE_DEGREES`] from the normal of a
//! face beside it (a new triangle, or the face across the hole's rim). A hole that fails is left
//! open with [`FillError::Folded`].
//!
//! Never intersecting: the new triangles are tested exactly against the mesh's faces near them
//! (fans of their corners whose boxes meet the fill's) and against each other. The minimum-weight
//! triangulation is then computed again without the triangles that cross, up to
//! [`CROSSING_RETRIES`] times; a projected one (whose triangles cannot cross each other) is not
//! retried. A hole whose every triangulation tried crosses the mesh is left open with
//! [`FillError::SelfIntersecting`]. A fill touches no face but along its rim.
//!
//! Refined and faired (optional, [`FillMode`]): the triangulation above can be refined so that
//! its edges match the lengths of the mesh's edges around the hole (Liepa's centroid splits and
//! Delaunay-like flips, see [`REFINE_ROUNDS_MAX`] and [`DENSITY`]), adding vertices inside the
//! hole, and the added vertices then faired: moved to minimise a thin-plate energy (the
//! squared cotangent Laplacian), the rim and the mesh around it fixed, by a sparse Cholesky
//! factorisation refined to [`FAIR_TOLERANCE`] within [`FAIR_ITERATIONS_MAX`] iterations; the
//! faired patch is refined again where fairing stretched it, and faired again, up to
//! [`REFINE_PASSES_MAX`] times. The refined (and faired) patch passes the same fold and
//! intersection tests before the mesh is touched; a solve that does not converge refuses the
//! hole ([`FillError::NotFaired`], which says how far it got).
//!
//! New faces, edges and corners get zero user attributes (as [`Mesh::add_face`] and
//! [`Mesh::split_face`] give them); the mesh keeps no per-corner normals or texture coordinates
//! of its own, so a mesh exported afterwards has none on the new faces. A triangulation adds no
//! vertex; a refined fill's vertices get user attributes interpolated from the corners of the
//! triangle they split (their mean; integer columns rounded, unit-vector columns renormalised),
//! at the positions refinement created them, whatever fairing then does to their positions.

mod crossings;
mod fair;
mod folds;
mod geometry;
mod laplacian;
mod peel;
mod pinches;
mod projected;
mod refine;
mod turns;
mod weights;

use std::collections::HashSet;

use thiserror::Error;

pub use fair::{FAIR_ITERATIONS_MAX, FAIR_TOLERANCE};
pub use folds::{DEGENERATE_RATIO, FOLD_ANGLE_DEGREES};
pub use refine::{DENSITY, REFINE_PASSES_MAX, REFINE_ROUNDS_MAX};

use crate::OutOfMemory;
use crate::mesh::{EditError, FaceId, HalfedgeId, HandleError, JoinedCorners, Mesh, VertexId};
use crossings::Surroundings;
use fair::{FairFailure, FairLimits, FairProgress, fair};
use folds::{Fold, first_fold};
use geometry::{norm, sub, unit};
use laplacian::Surround;
use peel::peeling_order;
use pinches::{split_at_pinches, undo_open_pinches};
use projected::{ProjectionRefusal, projected_triangles};
use refine::{Patch, rim_scale};
use turns::Turns;

/// Loops of at most this many corners get the exact minimum-weight triangulation; longer ones
/// the O(n log n) projected triangulation. 100 corners: about 1.7·10⁵ candidate triangles.
pub const EXACT_CORNERS_MAX: usize = 100;

/// Times the minimum-weight triangulation of a hole is computed again, each time without the
/// triangles of the last one that crossed the mesh, before the hole is refused.
pub const CROSSING_RETRIES: usize = 16;

/// How a hole is closed (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FillMode {
    /// Triangles on the hole's corners only; no vertex is added.
    #[default]
    Triangulate,
    /// The triangulation refined so that its edges match those of the mesh around the hole:
    /// adds vertices.
    Refine,
    /// Refined, then the added vertices faired to continue the surface around the hole.
    Fair,
}

/// Which holes [`fill_holes`] fills, and how.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HoleFillOptions {
    /// Holes with more boundary edges than this are left open.
    pub max_edges: usize,
    /// Holes whose perimeter (the sum of their boundary edges' lengths) exceeds this are left
    /// open; infinity for no bound.
    pub max_perimeter: f64,
    /// How each hole is closed.
    pub mode: FillMode,
}

impl Default for HoleFillOptions {
    /// Every hole, triangulated: no bound on edges or perimeter.
    fn default() -> Self {
        HoleFillOptions {
            max_edges: usize::MAX,
            max_perimeter: f64::INFINITY,
            mode: FillMode::Triangulate,
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
    /// The new triangles (`edges − 2 + 2 × vertices`: the fill is a disk).
    pub faces: Vec<FaceId>,
    /// The new vertices, inside the hole (none unless refined).
    pub vertices: Vec<VertexId>,
}

/// What [`fill_holes`] did, hole by hole. A hole whose boundary passes more than once through
/// one point counts as the loops it was split into there (see [`fill_holes`]).
#[derive(Debug, Default, PartialEq)]
pub struct HoleFillReport {
    /// The holes filled, in the order of [`Mesh::boundary_loops`].
    pub filled: Vec<FilledHole>,
    /// The holes within the bounds that were refused, each by one of its boundary half-edges,
    /// with the reason; they are left open.
    pub refused: Vec<(HalfedgeId, FillError)>,
    /// The holes beyond the bounds, left open.
    pub skipped: usize,
    /// Copies of one vertex where a hole's boundary passed twice through one point, welded when
    /// the loops split off there were filled, as `[gone, kept]`: the first is deleted, its faces
    /// now name the second.
    pub welded_vertices: Vec<[VertexId; 2]>,
}

impl HoleFillReport {
    /// The faces added over all holes.
    pub fn faces_added(&self) -> usize {
        self.filled.iter().map(|h| h.faces.len()).sum()
    }

    /// The vertices added over all holes (by refinement).
    pub fn vertices_added(&self) -> usize {
        self.filled.iter().map(|h| h.vertices.len()).sum()
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
    /// Every triangulation tried has a new triangle that intersects a face of the mesh or
    /// another new triangle.
    #[error("hole filling refused: every triangulation tried intersects the mesh or itself")]
    SelfIntersecting,
    /// Fairing did not reach [`FAIR_TOLERANCE`] within [`FAIR_ITERATIONS_MAX`] iterations, a
    /// position came out NaN or infinite, or the factorisation met a pivot that is not positive.
    #[error(
        "hole filling refused: fairing {reason} after {iterations} iterations (residual \
         {relative_residual:.3e} of the first); the fill would have added {vertices} vertices"
    )]
    NotFaired {
        /// What went wrong: "did not converge", "gave a position that is not finite", or
        /// "met a system that is not positive definite".
        reason: &'static str,
        /// Solves with the factor done (see [`FAIR_ITERATIONS_MAX`]).
        iterations: usize,
        /// The residual of the fairing equations left, over the one the solve started from
        /// (1 when no solve was made; NaN when it is not finite).
        relative_residual: f64,
        /// Vertices the refined fill would have added inside the hole.
        vertices: usize,
    },
    /// Refining or fairing the fill needs more memory than the system gives.
    #[error("hole filling refused: {0}")]
    OutOfMemory(#[from] OutOfMemory),
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
/// docs for which) and returns them. O(n) for a mesh of `n` elements (the faces near the hole
/// are found by a scan of the faces' boxes per intersection test, of which there are at most
/// [`CROSSING_RETRIES`] + 1), plus O(k log k) for the `k` faces found, plus O(m³) for a loop of
/// `m` ≤ [`EXACT_CORNERS_MAX`] corners.
///
/// # Errors
/// Refused, with the mesh unchanged, when `h` is invalid or has a face, when the loop passes
/// twice through one vertex, when every triangulation needs an edge that exists already, when
/// a long loop does not project onto a simple polygon, when the fill would fold, or when it
/// would intersect the mesh or itself.
pub fn fill_hole(mesh: &mut Mesh, h: HalfedgeId) -> Result<FilledHole, FillError> {
    fill_hole_with(mesh, h, FillMode::Triangulate)
}

/// [`fill_hole`], then refined or refined and faired as `mode` says (see the module docs).
/// Refinement costs O(m log m) more for a fill of m triangles (about the hole's area over the
/// square of the mean length of the edges at its rim); fairing O(m^1.5) time and O(m log m)
/// memory per round of refinement (a sparse Cholesky factorisation in nested-dissection order).
///
/// # Errors
/// As [`fill_hole`]; and [`FillError::NotFaired`] when fairing does not converge. The mesh is
/// unchanged.
pub fn fill_hole_with(
    mesh: &mut Mesh,
    h: HalfedgeId,
    mode: FillMode,
) -> Result<FilledHole, FillError> {
    boundary_sides(mesh, h)?;
    let mut surroundings = Surroundings::scanned();
    fill_hole_within(mesh, h, mode, &mut surroundings, FairLimits::default())
}

/// [`fill_hole_with`] against `surroundings` (the mesh's faces), to which the new faces are
/// added, fairing within `limits`.
fn fill_hole_within(
    mesh: &mut Mesh,
    h: HalfedgeId,
    mode: FillMode,
    surroundings: &mut Surroundings,
    limits: FairLimits,
) -> Result<FilledHole, FillError> {
    let sides = boundary_sides(mesh, h)?;
    let n = sides.len();
    let corners: Vec<VertexId> = sides.iter().map(|&s| mesh.origin(s)).collect();
    let mut seen = HashSet::with_capacity(n);
    if let Some(v) = corners.iter().find(|v| !seen.insert(v.0)) {
        return Err(FillError::RepeatedVertex(v.0));
    }
    let points: Vec<[f64; 3]> = corners.iter().map(|&v| mesh.position(v)).collect();
    let ids: Vec<u32> = corners.iter().map(|v| v.0).collect();
    let rim_normals: Vec<[f64; 3]> = sides.iter().map(|&s| face_normal_across(mesh, s)).collect();
    let joined = JoinedCorners::new(mesh, &corners);
    let triangles = if n <= EXACT_CORNERS_MAX {
        let turns = Turns::new(unit(crate::geom::newell_vector(points.iter().copied())));
        let is_joined = |i: usize, j: usize| !joined.may_join(i as u32, j as u32);
        let mut forbidden = HashSet::new();
        let mut attempt = 0;
        loop {
            let is_forbidden = |t: [u32; 3]| forbidden.contains(&t);
            let triangles = weights::minimum_weight_triangles(
                &points,
                &rim_normals,
                &turns,
                &is_joined,
                &is_forbidden,
            )
            .ok_or(if forbidden.is_empty() {
                FillError::Joined
            } else {
                FillError::SelfIntersecting
            })?;
            check_folds(&points, &rim_normals, &triangles)?;
            let crossing = surroundings.crossing_triangles(mesh, &ids, &points, &triangles, true);
            if crossing.is_empty() {
                break triangles;
            }
            attempt += 1;
            if attempt > CROSSING_RETRIES {
                return Err(FillError::SelfIntersecting);
            }
            forbidden.extend(crossing.into_iter().map(|t| triangles[t]));
        }
    } else {
        let triangles =
            projected_triangles(&points, &rim_normals, &joined).map_err(|e| match e {
                ProjectionRefusal::Joined => FillError::Joined,
                ProjectionRefusal::NoPlane | ProjectionRefusal::NotSimple => FillError::NotSimple,
            })?;
        check_folds(&points, &rim_normals, &triangles)?;
        // Triangles of a simple polygon in projection cannot cross each other.
        if !surroundings
            .crossing_triangles(mesh, &ids, &points, &triangles, false)
            .is_empty()
        {
            return Err(FillError::SelfIntersecting);
        }
        triangles
    };
    if mode != FillMode::Triangulate {
        let scales = corners.iter().map(|&v| rim_scale(mesh, v)).collect();
        let mut patch = Patch::new(&points, triangles, scales);
        let surround = (mode == FillMode::Fair).then(|| Surround::of(mesh, &corners));
        let refined = patch.refine(&joined, |patch| match &surround {
            Some(surround) => fair(patch, surround, limits).map(|_| ()),
            None => Ok(()),
        });
        if let Err(failure) = refined {
            return Err(not_faired(failure, patch.n_added()));
        }
        return add_patch(mesh, h, &patch, &ids, &rim_normals, surroundings);
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
    surroundings.add(mesh, faces.iter().copied());
    Ok(FilledHole {
        boundary_halfedge: h,
        edges: n,
        faces,
        vertices: Vec::new(),
    })
}

/// The refusal for a fairing that failed on a patch of `vertices` added vertices.
fn not_faired(failure: FairFailure, vertices: usize) -> FillError {
    let (reason, progress) = match failure {
        FairFailure::OutOfMemory(refusal) => return FillError::OutOfMemory(refusal),
        FairFailure::NotConverged(progress) => ("did not converge", progress),
        FairFailure::NotFinite(progress) => ("gave a position that is not finite", progress),
        FairFailure::NotPositiveDefinite => (
            "met a system that is not positive definite",
            FairProgress {
                iterations: 0,
                relative_residual: 1.0,
            },
        ),
    };
    FillError::NotFaired {
        reason,
        iterations: progress.iterations,
        relative_residual: progress.relative_residual,
        vertices,
    }
}

/// Tests a refined patch for folds and crossings and, when it passes, adds its vertices and
/// triangles to the mesh (in peeling order, see [`peeling_order`]).
fn add_patch(
    mesh: &mut Mesh,
    h: HalfedgeId,
    patch: &Patch,
    rim_ids: &[u32],
    rim_normals: &[[f64; 3]],
    surroundings: &mut Surroundings,
) -> Result<FilledHole, FillError> {
    check_folds(&patch.points, rim_normals, &patch.triangles)?;
    let first = u32::try_from(mesh.n_vertex_slots())
        .ok()
        .filter(|first| first.checked_add(patch.n_added() as u32).is_some())
        .ok_or(EditError::Full {
            operation: "hole filling",
        })?;
    // The ids the added vertices will get.
    let ids: Vec<u32> = rim_ids
        .iter()
        .copied()
        .chain((0..patch.n_added() as u32).map(|k| first + k))
        .collect();
    if !surroundings
        .crossing_triangles(mesh, &ids, &patch.points, &patch.triangles, true)
        .is_empty()
    {
        return Err(FillError::SelfIntersecting);
    }
    let order = peeling_order(patch.n_rim, patch.points.len(), &patch.triangles)
        .ok_or(FillError::Folded("the refined fill is not a disk".into()))?;
    let mut vertices = Vec::with_capacity(patch.n_added());
    let mut faces = Vec::with_capacity(patch.triangles.len());
    let added = (|| -> Result<(), EditError> {
        for (k, &position) in patch.points[patch.n_rim..].iter().enumerate() {
            let v = mesh.add_vertex(position)?;
            mesh.interpolate_vertex_attributes(
                patch.parents[k].map(|p| VertexId(ids[p as usize])),
                v,
            );
            vertices.push(v);
        }
        for &t in &order {
            let corners = patch.triangles[t].map(|k| VertexId(ids[k as usize]));
            faces.push(mesh.add_face(&corners)?);
        }
        Ok(())
    })();
    if let Err(e) = added {
        for &f in faces.iter().rev() {
            mesh.delete_face(f, false)
                .expect("a face just added is live");
        }
        for &v in &vertices {
            mesh.delete_vertex(v).expect("a vertex just added is live");
        }
        return Err(e.into());
    }
    faces.sort_unstable();
    surroundings.add(mesh, faces.iter().copied());
    Ok(FilledHole {
        boundary_halfedge: h,
        edges: patch.n_rim,
        faces,
        vertices,
    })
}

/// The fold test ([`first_fold`]) as an error.
fn check_folds(
    points: &[[f64; 3]],
    rim_normals: &[[f64; 3]],
    triangles: &[[u32; 3]],
) -> Result<(), FillError> {
    match first_fold(points, rim_normals, triangles) {
        None => Ok(()),
        Some(Fold::Degenerate(_)) => Err(FillError::Folded("a new triangle has no area".into())),
        Some(Fold::Folded(_, angle)) => Err(FillError::Folded(format!(
            "a new triangle turns {angle:.1}° from a face beside it"
        ))),
    }
}

/// Fills every hole within `options`' bounds, in the order of [`Mesh::boundary_loops`], and
/// reports each one filled, refused (left open, see [`fill_hole`]) or skipped. The mesh's faces
/// go into one box tree for all holes: O(n log² n) for a mesh of `n` elements, plus O(m³) for
/// each loop of `m` ≤ [`EXACT_CORNERS_MAX`] corners.
///
/// A hole whose boundary passes more than once through one point (a vertex with two boundary
/// fans, or two copies of a vertex at one position, as splitting a non-manifold vertex leaves)
/// is split there into simple loops, each filled as a hole; two copies are welded into one
/// vertex ([`HoleFillReport::welded_vertices`]) when a loop beside them is filled, and left as
/// they were when neither is. Copies with more than one fan, or with a neighbour in common, are
/// not welded.
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
    let mut surroundings = Surroundings::new(mesh);
    let mut several_fans = None;
    for h in mesh.boundary_loops() {
        let sides = match boundary_sides(mesh, h) {
            Ok(sides) => sides,
            Err(e) => {
                report.refused.push((h, e));
                continue;
            }
        };
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
        let split = split_at_pinches(mesh, h, &mut surroundings, &mut several_fans);
        let (n_filled, n_refused) = (report.filled.len(), report.refused.len());
        for &part in &split.loops {
            match fill_hole_within(
                mesh,
                part,
                options.mode,
                &mut surroundings,
                FairLimits::default(),
            ) {
                Ok(hole) => report.filled.push(hole),
                Err(e) => report.refused.push((part, e)),
            }
        }
        let split_apart = split.loops.len() > 1;
        report
            .welded_vertices
            .extend(undo_open_pinches(mesh, split, &mut surroundings));
        if split_apart && report.filled.len() == n_filled {
            // Nothing filled: the loop is whole again, refused for its first part's reason.
            report.refused.truncate(n_refused + 1);
            report.refused[n_refused].0 = h;
        } else if split_apart {
            // Parts joined again by an undone pinch are one hole, refused once.
            let mut seen = HashSet::new();
            let parts = report.refused.split_off(n_refused);
            report
                .refused
                .extend(parts.into_iter().filter(|&(part, _)| {
                    seen.insert(part) && {
                        seen.extend(mesh.halfedge_loop(part));
                        true
                    }
                }));
        }
    }
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::BuildPolicy;

    /// A unit icosphere of `level` with the faces whose centroids lie above z = 0.6 removed.
    fn capless_sphere(level: u32) -> Mesh {
        let soup = crate::surfaces::icosphere(1.0, level).unwrap();
        let (mut mesh, _) = Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap();
        let cap: Vec<FaceId> = (0..mesh.n_face_slots() as u32)
            .map(FaceId)
            .filter(|&f| {
                let z: f64 = mesh.face_vertices(f).map(|v| mesh.position(v)[2]).sum();
                z / 3.0 > 0.6
            })
            .collect();
        for f in cap {
            mesh.delete_face(f, true).unwrap();
        }
        mesh.garbage_collect();
        mesh
    }

    #[test]
    fn fairing_takes_few_iterations_and_a_shortfall_is_reported() {
        let mesh = capless_sphere(4);
        let h = mesh.boundary_loops()[0];
        let fill = |mode, limits| {
            let mut filled = mesh.clone();
            let result =
                fill_hole_within(&mut filled, h, mode, &mut Surroundings::scanned(), limits);
            (filled, result)
        };
        // One solve with the factor reaches the tolerance: refinement by the residual has
        // nothing left to do.
        let one = FairLimits {
            iterations_max: 1,
            ..FairLimits::default()
        };
        let (faired, result) = fill(FillMode::Fair, one);
        assert!(!result.unwrap().vertices.is_empty());
        faired.check().unwrap();
        // No solve allowed: refused after refinement's first pass, reporting what it had.
        let refined = fill(FillMode::Refine, FairLimits::default()).1.unwrap();
        let none = FairLimits {
            iterations_max: 0,
            ..FairLimits::default()
        };
        let (untouched, refused) = fill(FillMode::Fair, none);
        let error = refused.unwrap_err();
        assert_eq!(
            error,
            FillError::NotFaired {
                reason: "did not converge",
                iterations: 0,
                relative_residual: 1.0,
                vertices: refined.vertices.len(),
            }
        );
        assert_eq!(untouched.n_vertices(), mesh.n_vertices());
        assert_eq!(untouched.n_faces(), mesh.n_faces());
        let message = error.to_string();
        assert!(
            message.contains("after 0 iterations")
                && message.contains(&format!("added {} vertices", refined.vertices.len())),
            "{message}"
        );
    }
}
