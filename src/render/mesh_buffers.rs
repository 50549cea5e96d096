//! Everything a viewer draws for one mesh, built in one call: the shaded surface, the wireframe,
//! the boundary and non-manifold edges, and the normal glyphs. This is what the C API's
//! `hw_render_buffers` object holds.

use crate::geom::VertexNormalWeighting;
use crate::mesh::{Diagnostic, Mesh};

use super::error::RenderError;
use super::{
    LineBuffer, SurfaceBuffer, SurfaceOptions, boundary_lines, face_normal_glyphs,
    mean_edge_length, non_manifold_lines, surface_buffer, vertex_normal_glyphs, wireframe_lines,
};

/// What to build [`MeshBuffers`] with.
#[derive(Clone, Copy, Debug, Default)]
pub struct MeshBufferOptions<'a> {
    /// Shading, layout and per-corner attributes of the surface.
    pub surface: SurfaceOptions<'a>,
    /// The weighting of the vertex-normal glyphs.
    pub glyph_weighting: VertexNormalWeighting,
    /// Length of the normal glyphs; `None` takes the mean edge length.
    pub glyph_length: Option<f64>,
}

/// The buffers of one mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshBuffers {
    /// The shaded, triangulated surface.
    pub surface: SurfaceBuffer,
    /// Every edge (sources: edge ids).
    pub wireframe: LineBuffer,
    /// Edges with a face on one side only (sources: edge ids).
    pub boundary: LineBuffer,
    /// Edges of three or more faces reported by the diagnostic (sources: their index in it);
    /// empty without a diagnostic.
    pub non_manifold: LineBuffer,
    /// Vertex normals (sources: vertex ids).
    pub vertex_normals: LineBuffer,
    /// Face normals from the face centroids (sources: face ids).
    pub face_normals: LineBuffer,
}

/// Builds every buffer of `mesh`. `diagnostic`, when given, must be the one its build returned;
/// it supplies the non-manifold edges (which a half-edge mesh cannot hold as such).
///
/// # Errors
/// [`RenderError::BeyondSinglePrecision`] for a vertex beyond ±3.4e38; as [`surface_buffer`],
/// [`non_manifold_lines`] and the glyph builders.
pub fn mesh_buffers(
    mesh: &Mesh,
    diagnostic: Option<&Diagnostic>,
    options: &MeshBufferOptions<'_>,
) -> Result<MeshBuffers, RenderError> {
    if let Some(v) = (0..mesh.n_vertex_slots() as u32).find(|&v| {
        !mesh.is_vertex_deleted(crate::mesh::VertexId(v))
            && mesh
                .position(crate::mesh::VertexId(v))
                .iter()
                .any(|x| x.abs() > f64::from(f32::MAX))
    }) {
        return Err(RenderError::BeyondSinglePrecision {
            vertex: v,
            position: mesh.position(crate::mesh::VertexId(v)),
        });
    }
    let glyph_length = match options.glyph_length {
        Some(length) => length,
        // A mesh without edges has no glyphs to draw; any positive length will do.
        None => Some(mean_edge_length(mesh))
            .filter(|&length| length > 0.0)
            .unwrap_or(1.0),
    };
    Ok(MeshBuffers {
        surface: surface_buffer(mesh, &options.surface)?,
        wireframe: wireframe_lines(mesh),
        boundary: boundary_lines(mesh),
        non_manifold: diagnostic.map_or(Ok(LineBuffer::default()), |diagnostic| {
            non_manifold_lines(mesh, diagnostic)
        })?,
        vertex_normals: vertex_normal_glyphs(mesh, options.glyph_weighting, glyph_length)?,
        face_normals: face_normal_glyphs(mesh, glyph_length)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::BuildPolicy;
    use crate::surfaces::{CellFaces, Grid, grid};

    #[test]
    fn one_call_builds_every_buffer_with_glyphs_as_long_as_the_mean_edge() {
        let soup = grid(&Grid {
            width: 4.0,
            height: 2.0,
            cells_x: 4,
            cells_y: 2,
            faces: CellFaces::Quads,
        })
        .unwrap();
        let (mesh, diagnostic) =
            Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap();
        let buffers =
            mesh_buffers(&mesh, Some(&diagnostic), &MeshBufferOptions::default()).unwrap();
        assert_eq!(buffers.surface.n_triangles(), 16);
        assert_eq!(buffers.wireframe.n_segments(), mesh.n_edges());
        assert_eq!(buffers.boundary.n_segments(), 12);
        assert_eq!(buffers.non_manifold.n_segments(), 0);
        assert_eq!(buffers.vertex_normals.n_segments(), 15);
        assert_eq!(buffers.face_normals.n_segments(), 8);
        // Unit cells: every glyph 1 long, along +z.
        for glyph in buffers.face_normals.positions.chunks_exact(6) {
            assert_eq!(glyph[5] - glyph[2], 1.0);
        }
        let longer = MeshBufferOptions {
            glyph_length: Some(0.25),
            ..MeshBufferOptions::default()
        };
        let buffers = mesh_buffers(&mesh, None, &longer).unwrap();
        assert_eq!(buffers.vertex_normals.positions[5], 0.25);
    }
}
