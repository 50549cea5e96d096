//! Normals drawn as line glyphs: a segment from each vertex (or face centroid) along its unit
//! normal. Sources are vertex ids or face ids.

use crate::geom::{VertexNormalWeighting, face_normals, vertex_normals};
use crate::mesh::{FaceId, Mesh, VertexId};

use super::LineBuffer;
use super::error::RenderError;

fn checked_length(length: f64) -> Result<f64, RenderError> {
    if length.is_finite() && length > 0.0 {
        Ok(length)
    } else {
        Err(RenderError::BadGlyphLength(length))
    }
}

fn along(from: [f64; 3], unit: [f64; 3], length: f64) -> [f64; 3] {
    std::array::from_fn(|axis| from[axis] + length * unit[axis])
}

/// The mean length of the live edges (0 without edges): a glyph length that suits the mesh's
/// resolution, whatever its units.
pub fn mean_edge_length(mesh: &Mesh) -> f64 {
    // A running mean of lengths computed without squaring overflow: finite for any finite
    // coordinates (a sum of lengths near 1e308, or their squares above 1e154, would not be).
    let (mut mean, mut count) = (0.0, 0.0);
    for e in 0..mesh.n_edge_slots() {
        let e = crate::mesh::EdgeId(e as u32);
        if mesh.is_edge_deleted(e) {
            continue;
        }
        let h = e.halfedge(0);
        let (a, b) = (mesh.position(mesh.origin(h)), mesh.position(mesh.target(h)));
        let half: [f64; 3] = std::array::from_fn(|k| 0.5 * b[k] - 0.5 * a[k]);
        let largest = half.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let length = if largest > 0.0 {
            let sum: f64 = half.iter().map(|x| (x / largest).powi(2)).sum();
            2.0 * largest * sum.sqrt()
        } else {
            0.0
        };
        count += 1.0;
        mean += (length - mean) / count;
    }
    if mean.is_finite() { mean } else { f64::MAX }
}

/// One glyph per vertex that has a normal (isolated vertices have none), `length` long.
///
/// # Errors
/// [`RenderError::BadGlyphLength`] unless `length` is positive and finite.
pub fn vertex_normal_glyphs(
    mesh: &Mesh,
    weighting: VertexNormalWeighting,
    length: f64,
) -> Result<LineBuffer, RenderError> {
    let length = checked_length(length)?;
    let mut lines = LineBuffer::default();
    for (v, normal) in vertex_normals(mesh, weighting).into_iter().enumerate() {
        let vertex = VertexId(v as u32);
        if normal != [0.0; 3] && !mesh.is_vertex_deleted(vertex) {
            let at = mesh.position(vertex);
            lines.push(at, along(at, normal, length), vertex.0);
        }
    }
    Ok(lines)
}

/// One glyph per non-degenerate face, from its vertex centroid, `length` long.
///
/// # Errors
/// [`RenderError::BadGlyphLength`] unless `length` is positive and finite.
pub fn face_normal_glyphs(mesh: &Mesh, length: f64) -> Result<LineBuffer, RenderError> {
    let length = checked_length(length)?;
    let mut lines = LineBuffer::default();
    for (f, normal) in face_normals(mesh).into_iter().enumerate() {
        let face = FaceId(f as u32);
        if normal == [0.0; 3] || mesh.is_face_deleted(face) {
            continue;
        }
        let (mut centroid, mut corners) = ([0.0; 3], 0.0);
        for v in mesh.face_vertices(face) {
            let p = mesh.position(v);
            (0..3).for_each(|axis| centroid[axis] += p[axis]);
            corners += 1.0;
        }
        let centroid = centroid.map(|c| c / corners);
        lines.push(centroid, along(centroid, normal, length), face.0);
    }
    Ok(lines)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::BuildPolicy;
    use crate::surfaces::cube;

    fn unit_cube() -> Mesh {
        let soup = cube(1.0).unwrap();
        Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
            .unwrap()
            .0
    }

    #[test]
    fn face_glyphs_start_at_centroids_and_point_outwards() {
        let mesh = unit_cube();
        let glyphs = face_normal_glyphs(&mesh, 0.25).unwrap();
        assert_eq!(glyphs.n_segments(), 6);
        for segment in glyphs.positions.chunks_exact(6) {
            let (from, to) = (&segment[..3], &segment[3..]);
            // A face centre of the unit cube centred at the origin: one coordinate ±0.5.
            assert_eq!(from.iter().filter(|c| c.abs() == 0.5).count(), 1);
            let outward: f32 = (0..3).map(|a| from[a] * (to[a] - from[a])).sum();
            assert!((outward - 0.5 * 0.25).abs() < 1e-6);
        }
    }

    #[test]
    fn vertex_glyphs_have_the_requested_length() {
        let mesh = unit_cube();
        let glyphs = vertex_normal_glyphs(&mesh, VertexNormalWeighting::Angle, 0.5).unwrap();
        assert_eq!(glyphs.n_segments(), 8);
        for segment in glyphs.positions.chunks_exact(6) {
            let length: f32 = (0..3).map(|a| (segment[3 + a] - segment[a]).powi(2)).sum();
            assert!((length.sqrt() - 0.5).abs() < 1e-6);
        }
        assert_eq!(mean_edge_length(&mesh), 1.0);
    }

    #[test]
    fn bad_lengths_are_refused() {
        let mesh = unit_cube();
        for length in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(face_normal_glyphs(&mesh, length).is_err());
            assert!(vertex_normal_glyphs(&mesh, VertexNormalWeighting::Uniform, length).is_err());
        }
    }
}
