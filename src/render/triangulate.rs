//! Polygon triangulation by ear clipping, for index buffers of arbitrary polygon meshes.
//!
//! A face is projected onto the plane of its Newell normal (the seed's face-normal loop), which
//! makes it counter-clockwise in 2D whenever it is simple, then ears are clipped with exact
//! orientation predicates (`robust::orient2d`) on the projected coordinates, so every decision is
//! consistent with every other. The walk is deterministic: same input, same triangles.
//!
//! Degenerate input never panics: collinear and repeated corners are clipped as zero-area ears
//! only when no proper ear is left (so T-junction corners stay in proper triangles), and a face
//! with no area, a non-finite corner or a self-intersection falls back to a fan, which is
//! reported. Any face of `n ≥ 3` corners yields exactly `n − 2` triangles.

use glam::DVec3;
use robust::{Coord, orient2d};
use thiserror::Error;

use crate::soup::{FaceList, FaceSizes};

/// Why a polygon was not (entirely) ear clipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FallbackReason {
    /// A corner has a NaN or infinite coordinate: the whole polygon is a fan.
    NonFinite,
    /// The polygon has no area to speak of (all corners collinear or coincident), so it has no
    /// plane to be projected on: the whole polygon is a fan.
    ZeroArea,
    /// Ear clipping found no ear, or its last triangle is inverted: the polygon intersects
    /// itself. The ears found so far are kept and the rest is a fan.
    SelfIntersecting,
}

/// What happened to one polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PolygonOutcome {
    /// `n − 2` triangles covering the polygon exactly, none inverted.
    Clipped,
    /// Fewer than 3 corners: no triangle.
    TooFewCorners,
    /// `n − 2` triangles, part or all of them a fan that may overlap or be inverted.
    Fallback(FallbackReason),
}

/// Reusable ear clipper: keeps its scratch buffers between polygons so a mesh is triangulated
/// without an allocation per face.
#[derive(Debug, Default)]
pub struct EarClipper {
    projected: Vec<Coord<f64>>,
    prev: Vec<u32>,
    next: Vec<u32>,
    /// Reflex or flat corners: the only ones that can lie inside an ear of a simple polygon.
    concave: Vec<bool>,
}

impl EarClipper {
    /// A clipper with empty scratch buffers.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends the triangles of the polygon `corners` to `out`, as local corner indices in the
    /// polygon's own winding.
    pub fn triangulate(&mut self, corners: &[[f64; 3]], out: &mut Vec<[u32; 3]>) -> PolygonOutcome {
        let n = corners.len();
        if n < 3 {
            return PolygonOutcome::TooFewCorners;
        }
        if n == 3 {
            out.push([0, 1, 2]);
            return PolygonOutcome::Clipped;
        }
        if corners.iter().flatten().any(|c| !c.is_finite()) {
            push_fan(0..n as u32, out);
            return PolygonOutcome::Fallback(FallbackReason::NonFinite);
        }
        if !self.project(corners) {
            push_fan(0..n as u32, out);
            return PolygonOutcome::Fallback(FallbackReason::ZeroArea);
        }
        self.clip_ears(out)
    }

    /// Projects the corners onto the plane of their Newell normal, oriented so that the polygon
    /// is counter-clockwise; `false` when that normal vanishes.
    fn project(&mut self, corners: &[[f64; 3]]) -> bool {
        let points: Vec<DVec3> = corners.iter().map(|c| DVec3::from_array(*c)).collect();
        let centre = points.iter().sum::<DVec3>() / points.len() as f64;
        let mut normal = DVec3::ZERO;
        let mut perimeter = 0.0;
        for (i, &p) in points.iter().enumerate() {
            let q = points[(i + 1) % points.len()];
            normal += (p - centre).cross(q - centre);
            perimeter += p.distance(q);
        }
        // Twice the area against the perimeter squared: a scale-free flatness test.
        let length = normal.length();
        let flatness = points.len() as f64 * f64::EPSILON * perimeter * perimeter;
        // Huge coordinates can overflow the normal to infinity or NaN: treated as no plane too.
        if !length.is_finite() || length <= flatness {
            return false;
        }
        let normal = normal / length;
        // u × v = u × (normal × u) = normal: CCW about the normal is CCW in (u, v).
        let u = normal.any_orthonormal_vector();
        let v = normal.cross(u);
        self.projected.clear();
        self.projected.extend(points.iter().map(|&p| Coord {
            x: (p - centre).dot(u),
            y: (p - centre).dot(v),
        }));
        true
    }

    fn orient(&self, a: u32, b: u32, c: u32) -> f64 {
        orient2d(
            self.projected[a as usize],
            self.projected[b as usize],
            self.projected[c as usize],
        )
    }

    fn update_concavity(&mut self, corner: u32) -> bool {
        let concave = self.orient(
            self.prev[corner as usize],
            corner,
            self.next[corner as usize],
        ) <= 0.0;
        let was = std::mem::replace(&mut self.concave[corner as usize], concave);
        concave != was
    }

    /// A proper ear: strictly convex, and no reflex or flat corner inside or on it.
    fn is_ear(&self, corner: u32, reflex_left: usize) -> bool {
        let (a, b, c) = (
            self.prev[corner as usize],
            corner,
            self.next[corner as usize],
        );
        if self.orient(a, b, c) <= 0.0 {
            return false;
        }
        if reflex_left == 0 {
            return true;
        }
        let mut q = self.next[c as usize];
        while q != a {
            if self.concave[q as usize]
                && self.orient(a, b, q) >= 0.0
                && self.orient(b, c, q) >= 0.0
                && self.orient(c, a, q) >= 0.0
            {
                return false;
            }
            q = self.next[q as usize];
        }
        true
    }

    fn clip_ears(&mut self, out: &mut Vec<[u32; 3]>) -> PolygonOutcome {
        let n = self.projected.len() as u32;
        self.prev.clear();
        self.prev.extend((0..n).map(|i| (i + n - 1) % n));
        self.next.clear();
        self.next.extend((0..n).map(|i| (i + 1) % n));
        self.concave.clear();
        self.concave.resize(n as usize, false);
        let mut reflex_left = 0;
        for corner in 0..n {
            self.update_concavity(corner);
            reflex_left += usize::from(self.concave[corner as usize]);
        }

        let mut remaining = n as usize;
        let mut corner = 0u32;
        let mut misses = 0;
        while remaining > 3 {
            let clip = if misses < remaining {
                self.is_ear(corner, reflex_left)
            } else {
                // A full lap without a proper ear: drop a zero-area corner (collinear or repeated)
                // if there is one; it does not change the polygon's area.
                match self.find_flat_corner(corner) {
                    Some(flat) => {
                        corner = flat;
                        true
                    }
                    None => {
                        push_fan(self.walk(corner).collect::<Vec<_>>().into_iter(), out);
                        return PolygonOutcome::Fallback(FallbackReason::SelfIntersecting);
                    }
                }
            };
            if !clip {
                corner = self.next[corner as usize];
                misses += 1;
                continue;
            }
            let (a, c) = (self.prev[corner as usize], self.next[corner as usize]);
            out.push([a, corner, c]);
            reflex_left -= usize::from(self.concave[corner as usize]);
            self.next[a as usize] = c;
            self.prev[c as usize] = a;
            remaining -= 1;
            for neighbour in [a, c] {
                if self.update_concavity(neighbour) {
                    if self.concave[neighbour as usize] {
                        reflex_left += 1;
                    } else {
                        reflex_left -= 1;
                    }
                }
            }
            corner = c;
            misses = 0;
        }
        let (a, c) = (self.prev[corner as usize], self.next[corner as usize]);
        out.push([a, corner, c]);
        if self.orient(a, corner, c) < 0.0 {
            return PolygonOutcome::Fallback(FallbackReason::SelfIntersecting);
        }
        PolygonOutcome::Clipped
    }

    fn find_flat_corner(&self, start: u32) -> Option<u32> {
        self.walk(start)
            .find(|&k| self.orient(self.prev[k as usize], k, self.next[k as usize]) == 0.0)
    }

    /// The remaining corners in order, from `start`.
    fn walk(&self, start: u32) -> impl Iterator<Item = u32> + '_ {
        let mut k = start;
        let mut first = true;
        std::iter::from_fn(move || {
            if !first && k == start {
                return None;
            }
            first = false;
            let here = k;
            k = self.next[k as usize];
            Some(here)
        })
    }
}

/// Fan from the first corner of `ring`.
fn push_fan(ring: impl Iterator<Item = u32>, out: &mut Vec<[u32; 3]>) {
    let ring: Vec<u32> = ring.collect();
    for pair in ring[1..].windows(2) {
        out.push([ring[0], pair[0], pair[1]]);
    }
}

/// Triangulates one polygon: local corner triangles and what happened.
pub fn triangulate_polygon(corners: &[[f64; 3]]) -> (Vec<[u32; 3]>, PolygonOutcome) {
    let mut triangles = Vec::with_capacity(corners.len().saturating_sub(2));
    let outcome = EarClipper::new().triangulate(corners, &mut triangles);
    (triangles, outcome)
}

/// Why a face list could not be triangulated.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum TriangulateError {
    /// The face sizes do not add up to the number of corner indices.
    #[error("face sizes account for {expected} corners but {got} indices were given")]
    CornerCountMismatch {
        /// Corners the sizes describe.
        expected: usize,
        /// Indices given.
        got: usize,
    },
    /// A uniform face size does not divide the number of corner indices.
    #[error("{got} indices do not make whole faces of {size} corners")]
    UniformSizeMismatch {
        /// The uniform face size.
        size: u32,
        /// Indices given.
        got: usize,
    },
    /// A corner refers to a vertex that does not exist.
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
    /// The triangle list would need more than `u32::MAX` entries.
    #[error("the triangulation would need more than 2^32 - 1 indices")]
    TooLarge,
}

/// A triangle index buffer for a polygon mesh, ready for `glBufferData(GL_ELEMENT_ARRAY_BUFFER)`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TriangleBuffer {
    /// Vertex indices, three per triangle, in each face's winding.
    pub indices: Vec<u32>,
    /// Global corner indices (positions in the face list's `indices`), three per triangle, for
    /// per-corner attributes such as split normals and uvs.
    pub corners: Vec<u32>,
    /// The face each triangle comes from.
    pub source_faces: Vec<u32>,
    /// Faces that fell back to a fan (entirely or partly), with the reason.
    pub fallbacks: Vec<(u32, FallbackReason)>,
    /// Faces with fewer than 3 corners, which produce no triangle.
    pub skipped_faces: Vec<u32>,
}

impl TriangleBuffer {
    /// Number of triangles.
    pub fn n_triangles(&self) -> usize {
        self.source_faces.len()
    }
}

/// Triangulates every face of a face list. Triangles keep their face's winding, come face by
/// face in face order, and every face of `n ≥ 3` corners gives `n − 2` of them.
///
/// # Errors
/// Sizes that do not match the index count, an index out of range, or more than `u32::MAX`
/// output indices. Degenerate faces are not errors: they are fanned and listed in `fallbacks`.
pub fn triangulate_faces(faces: &FaceList<'_>) -> Result<TriangleBuffer, TriangulateError> {
    let ranges = face_ranges(faces)?;
    let vertices = faces.positions.len();
    let mut total = 0usize;
    for (face, range) in ranges.iter().enumerate() {
        for (corner, &vertex) in faces.indices[range.clone()].iter().enumerate() {
            if vertex as usize >= vertices {
                return Err(TriangulateError::IndexOutOfRange {
                    face,
                    corner,
                    vertex,
                    vertices,
                });
            }
        }
        total += range.len().saturating_sub(2) * 3;
    }
    if total > u32::MAX as usize || ranges.len() > u32::MAX as usize {
        return Err(TriangulateError::TooLarge);
    }

    let mut buffer = TriangleBuffer {
        indices: Vec::with_capacity(total),
        corners: Vec::with_capacity(total),
        source_faces: Vec::with_capacity(total / 3),
        ..TriangleBuffer::default()
    };
    let mut clipper = EarClipper::new();
    let mut corners = Vec::new();
    let mut local = Vec::new();
    for (face, range) in ranges.into_iter().enumerate() {
        let face_id = face as u32;
        let first_corner = range.start as u32;
        let ring = &faces.indices[range];
        corners.clear();
        corners.extend(ring.iter().map(|&v| faces.positions[v as usize]));
        local.clear();
        match clipper.triangulate(&corners, &mut local) {
            PolygonOutcome::Clipped => {}
            PolygonOutcome::TooFewCorners => buffer.skipped_faces.push(face_id),
            PolygonOutcome::Fallback(reason) => buffer.fallbacks.push((face_id, reason)),
        }
        for triangle in &local {
            for &k in triangle {
                buffer.indices.push(ring[k as usize]);
                buffer.corners.push(first_corner + k);
            }
            buffer.source_faces.push(face_id);
        }
    }
    Ok(buffer)
}

/// The corner range of every face, checked against the index count.
fn face_ranges(faces: &FaceList<'_>) -> Result<Vec<std::ops::Range<usize>>, TriangulateError> {
    corner_ranges(faces.sizes, faces.indices.len())
}

/// The corner range of every face of the given sizes, checked against the `got` corners there are.
pub(super) fn corner_ranges(
    sizes: FaceSizes<'_>,
    got: usize,
) -> Result<Vec<std::ops::Range<usize>>, TriangulateError> {
    match sizes {
        FaceSizes::Uniform(0) if got == 0 => Ok(Vec::new()),
        FaceSizes::Uniform(size) if size > 0 && got.is_multiple_of(size as usize) => {
            let size = size as usize;
            Ok((0..got / size).map(|f| f * size..(f + 1) * size).collect())
        }
        FaceSizes::Uniform(size) => Err(TriangulateError::UniformSizeMismatch { size, got }),
        FaceSizes::PerFace(sizes) => {
            let mut ranges = Vec::with_capacity(sizes.len());
            let mut start = 0usize;
            for &size in sizes {
                let end = start.saturating_add(size as usize);
                ranges.push(start..end);
                start = end;
            }
            if start != got {
                return Err(TriangulateError::CornerCountMismatch {
                    expected: start,
                    got,
                });
            }
            Ok(ranges)
        }
    }
}
