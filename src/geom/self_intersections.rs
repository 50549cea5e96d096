//! Self-intersections of triangle and polygon meshes: the pairs of faces that meet other than
//! along the vertices and edges they share, with the semantics of CGAL's
//! `Polygon_mesh_processing::self_intersections`.

use thiserror::Error;

use super::box_tree::{BoundingBox, BoxTree, Boxed};
use super::embedded_stars::{StarTriangle, embedded_stars};
use super::exact_orientation::ExponentRange;
use super::parallel::map_indexed;
use super::triangle_intersection::{SharedCorners, is_degenerate_exactly, triangles_meet_exactly};
use crate::render::{TriangulateError, triangulate_faces};
use crate::soup::FaceList;
use crate::support::allocation::{OutOfMemory, ensure_room};

/// Why the self-intersections of a mesh could not be computed.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum SelfIntersectionError {
    /// A face refers to a vertex that does not exist.
    #[error(
        "face {face} corner {corner} refers to vertex {vertex}, but there are {vertices} vertices"
    )]
    IndexOutOfRange {
        /// Face index.
        face: usize,
        /// Corner within the face.
        corner: usize,
        /// The bad vertex index.
        vertex: u32,
        /// Number of vertices.
        vertices: usize,
    },
    /// A vertex of a face has a NaN or infinite coordinate: no intersection can be decided
    /// there. (Vertices no face uses are not read.)
    #[error("vertex {vertex}, a corner of face {face}, has a coordinate that is not finite")]
    NonFiniteCoordinate {
        /// The first face (in face order) with such a corner.
        face: usize,
        /// The vertex.
        vertex: u32,
    },
    /// More faces than the `u32` face indices of the result can name.
    #[error("{count} faces are more than 32-bit face indices can name")]
    TooManyFaces {
        /// Number of faces given.
        count: usize,
    },
    /// The face sizes do not match the indices, or the triangulation would be too large.
    #[error("malformed face list: {0}")]
    MalformedFaceList(TriangulateError),
    /// The system refused the memory the search needs (see [`OutOfMemory`]).
    #[error(transparent)]
    OutOfMemory(#[from] OutOfMemory),
}

/// Makes sure the memory a search over `n_triangles` triangles on `n_vertices` vertices needs
/// can be had, before anything that size is allocated; a refusal names `n_triangles` items of
/// `what` (the triangles, or the corners that bound their number).
fn ensure_search_room(
    n_triangles: usize,
    n_vertices: usize,
    what: &'static str,
) -> Result<(), OutOfMemory> {
    // Per triangle: its triangulation entry (16 bytes), its prepared form twice (prepared, then
    // kept: 2 × 72) and its box tree node and order (64); per vertex, its embedded-star flag and
    // the stars' working arrays (16).
    const BYTES_PER_TRIANGLE: u64 = 224;
    const BYTES_PER_VERTEX: u64 = 16;
    let bytes = (n_triangles as u64)
        .saturating_mul(BYTES_PER_TRIANGLE)
        .saturating_add((n_vertices as u64).saturating_mul(BYTES_PER_VERTEX));
    ensure_room(bytes, n_triangles, what)
}

/// The pairs of triangles that intersect other than along the vertices and the edge they share,
/// as `[f, g]` with `f < g`, sorted, plus `[f, f]` for every degenerate triangle `f`.
///
/// Two triangles sharing (by vertex index, not by position)
/// - no vertex are reported when the closed triangles have any point in common, touching
///   included;
/// - one vertex, when they have a point in common other than that vertex;
/// - an edge (two vertices), when they overlap beyond it: when they are coplanar with their
///   third corners on the same side of the edge;
/// - all three vertices, always (the same triangle twice overlaps itself).
///
/// A degenerate triangle, whose corners are collinear or coincide (a repeated vertex index
/// included), is reported once, as `[f, f]`, and not tested against the others: what it
/// intersects is not defined. CGAL reports degenerate faces the same way.
///
/// Every decision is exact, whatever the coordinates' magnitudes (from subnormal numbers to near
/// overflow): the signs of orientation determinants in adaptive or, when one decision's
/// coordinates span more than some 150 decimal orders of magnitude, integer arithmetic. Coplanar
/// triangles are compared in the coordinate plane where their normal has its largest component.
///
/// Cost: O(n log n + k) for `n` triangles and `k` pairs of triangles whose bounding boxes overlap
/// (a small multiple of `n` on any reasonable mesh); with the `parallel` feature the search runs
/// on rayon's current thread pool, and the result does not depend on the number of threads.
///
/// # Errors
/// A vertex index out of range, a non-finite coordinate at a triangle's corner, or more than
/// `u32::MAX` triangles.
pub fn self_intersections(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
) -> Result<Vec<[u32; 2]>, SelfIntersectionError> {
    if triangles.len() >= u32::MAX as usize {
        return Err(SelfIntersectionError::TooManyFaces {
            count: triangles.len(),
        });
    }
    let pairs = intersecting_faces(positions, triangles, None)?;
    Ok(sorted(pairs))
}

/// [`self_intersections`] of a polygon mesh, by face index: the pairs `[f, g]`, `f < g`, sorted,
/// of faces `f` and `g` one triangle of which intersects one of the other, and `[f, f]` for every
/// degenerate face `f`.
///
/// Faces are triangulated as [`triangulate_faces`] does it, which covers a simple polygon
/// (planar or nearly) exactly with `n − 2` triangles. A non-planar or
/// self-intersecting polygon is tested as the triangles it gets there, so its pairs are those of
/// that triangulation. The triangles of one face are not tested against each other: a polygon's
/// own self-intersections are not reported. A face is degenerate when it has fewer than three
/// corners or one of its triangles is (its corners repeat, or the polygon has no area).
///
/// # Errors
/// Face sizes that do not match the index count, a vertex index out of range, a non-finite
/// coordinate at a corner of a face of three corners or more, or a triangulation of more than
/// `u32::MAX` indices.
pub fn face_self_intersections(
    faces: &FaceList<'_>,
) -> Result<Vec<[u32; 2]>, SelfIntersectionError> {
    // Each face gives at most as many triangles as it has corners.
    ensure_search_room(faces.indices.len(), faces.positions.len(), "corners")?;
    let triangulation = triangulate_faces(faces).map_err(|error| match error {
        TriangulateError::IndexOutOfRange {
            face,
            corner,
            vertex,
            vertices,
        } => SelfIntersectionError::IndexOutOfRange {
            face,
            corner,
            vertex,
            vertices,
        },
        other => SelfIntersectionError::MalformedFaceList(other),
    })?;
    let triangles: Vec<[u32; 3]> = triangulation
        .indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    let mut pairs = intersecting_faces(
        faces.positions,
        &triangles,
        Some(&triangulation.source_faces),
    )?;
    pairs.extend(triangulation.skipped_faces.iter().map(|&f| [f, f]));
    Ok(sorted(pairs))
}

/// A triangle ready for the search: its corners' vertex ids and box, the face it belongs to,
/// and the exponent range of its coordinates (which decides the arithmetic of its tests).
#[derive(Clone, Copy, Debug)]
struct PreparedTriangle {
    bounds: BoundingBox,
    corners: [u32; 3],
    face: u32,
    exponents: ExponentRange,
}

/// A triangle with area, for the search, or the face of a degenerate one.
enum Prepared {
    Proper(PreparedTriangle),
    Degenerate(u32),
}

impl Boxed for PreparedTriangle {
    fn bounding_box(&self) -> &BoundingBox {
        &self.bounds
    }
}

/// The pairs of faces (`[f, g]`, `f < g`, in no order, possibly repeated) with intersecting
/// triangles, and `[f, f]` for each degenerate triangle of face `f`. Triangle `t` belongs to face
/// `faces[t]`, or to face `t` without `faces`; triangles of one face are not tested together.
fn intersecting_faces(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    faces: Option<&[u32]>,
) -> Result<Vec<[u32; 2]>, SelfIntersectionError> {
    let face_of = |t: usize| faces.map_or(t as u32, |faces| faces[t]);
    check_corners(positions, triangles, face_of)?;
    ensure_search_room(triangles.len(), positions.len(), "triangles")?;
    let prepare = |t: usize| {
        let corners = &triangles[t];
        let points = corners.map(|v| positions[v as usize]);
        let exponents = ExponentRange::of(points.iter().flatten().copied());
        if is_degenerate_exactly(points, exponents) {
            return Prepared::Degenerate(face_of(t));
        }
        Prepared::Proper(PreparedTriangle {
            bounds: BoundingBox::of_points(&points),
            corners: *corners,
            face: face_of(t),
            exponents,
        })
    };
    let prepared = map_indexed(triangles.len(), prepare);

    let mut degenerate_faces = Vec::new();
    let proper: Vec<PreparedTriangle> = prepared
        .into_iter()
        .filter_map(|t| match t {
            Prepared::Proper(triangle) => Some(triangle),
            Prepared::Degenerate(face) => {
                degenerate_faces.push([face, face]);
                None
            }
        })
        .collect();
    let embedded = embedded_stars(positions, proper.len(), |t| StarTriangle {
        corners: proper[t].corners,
        exponents: proper[t].exponents,
    });
    let tree = BoxTree::new(proper);
    let mut pairs = tree.overlapping_pairs(|a, b| {
        if a.face == b.face {
            return None;
        }
        let shared = SharedCorners::of(a.corners, b.corners);
        // Pairs meeting at a vertex whose star is embedded do not intersect.
        let embedded_at = |i: usize| embedded[a.corners[i] as usize];
        let settled = match shared {
            SharedCorners::Vertex(i, _) => embedded_at(i),
            SharedCorners::Edge(i, _) => embedded_at(i) || embedded_at((i + 1) % 3),
            SharedCorners::None | SharedCorners::All => false,
        };
        if settled {
            return None;
        }
        let corners = |t: &PreparedTriangle| t.corners.map(|v| positions[v as usize]);
        triangles_meet_exactly(
            (a.corners, corners(a), a.exponents),
            (b.corners, corners(b), b.exponents),
        )
        .then(|| [a.face.min(b.face), a.face.max(b.face)])
    });
    pairs.extend(degenerate_faces);
    Ok(pairs)
}

/// The first corner (in triangle order) whose vertex index is out of range or whose position is
/// not finite, as an error.
fn check_corners(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    face_of: impl Fn(usize) -> u32,
) -> Result<(), SelfIntersectionError> {
    for (t, corners) in triangles.iter().enumerate() {
        for (corner, &vertex) in corners.iter().enumerate() {
            let Some(position) = positions.get(vertex as usize) else {
                return Err(SelfIntersectionError::IndexOutOfRange {
                    face: face_of(t) as usize,
                    corner,
                    vertex,
                    vertices: positions.len(),
                });
            };
            if !position.iter().all(|x| x.is_finite()) {
                return Err(SelfIntersectionError::NonFiniteCoordinate {
                    face: face_of(t) as usize,
                    vertex,
                });
            }
        }
    }
    Ok(())
}

fn sorted(mut pairs: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}
