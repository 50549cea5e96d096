//! Edges of a mesh as line buffers: the wireframe, the boundary, and the non-manifold edges a
//! build diagnostic reported. Each segment's source is its edge id (wireframe, boundary) or its
//! index in the diagnostic's list (non-manifold edges, which may have no single mesh edge).

use crate::mesh::{Diagnostic, EdgeId, Mesh, VertexId};

use super::LineBuffer;
use super::error::RenderError;

/// Live edges, each with its two end points.
fn edges_where(mesh: &Mesh, keep: impl Fn(EdgeId) -> bool) -> LineBuffer {
    let mut lines = LineBuffer::default();
    for e in 0..mesh.n_edge_slots() {
        let e = EdgeId(e as u32);
        if mesh.is_edge_deleted(e) || !keep(e) {
            continue;
        }
        let h = e.halfedge(0);
        lines.push(
            mesh.position(mesh.origin(h)),
            mesh.position(mesh.target(h)),
            e.0,
        );
    }
    lines
}

/// Every live edge once: the wireframe of the polygons (not of their triangulation).
pub fn wireframe_lines(mesh: &Mesh) -> LineBuffer {
    edges_where(mesh, |_| true)
}

/// The edges with a face on one side only: the mesh's boundary loops.
pub fn boundary_lines(mesh: &Mesh) -> LineBuffer {
    edges_where(mesh, |e| mesh.is_boundary_edge(e))
}

/// The edges used by three or more faces, as `diagnostic` (the one the mesh's build returned)
/// reports them. Under [`BuildPolicy::Skip`](crate::soup::BuildPolicy::Skip) and
/// [`BuildPolicy::Repair`](crate::soup::BuildPolicy::Repair) the mesh keeps the input vertex
/// ids, so the reported vertex pairs are mesh vertices.
///
/// # Errors
/// [`RenderError::DiagnosticMismatch`] when a reported vertex is not a vertex slot of `mesh`.
pub fn non_manifold_lines(mesh: &Mesh, diagnostic: &Diagnostic) -> Result<LineBuffer, RenderError> {
    let mut lines = LineBuffer::default();
    let vertices = mesh.n_vertex_slots();
    let position = |v: u32| {
        if (v as usize) < vertices {
            Ok(mesh.position(VertexId(v)))
        } else {
            Err(RenderError::DiagnosticMismatch {
                vertex: v,
                vertices,
            })
        }
    };
    for (i, edge) in diagnostic.non_manifold_edges.iter().enumerate() {
        let [a, b] = edge.vertices;
        lines.push(position(a)?, position(b)?, i as u32);
    }
    Ok(lines)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::soup::{BuildPolicy, EdgeReport, FaceList};
    use crate::surfaces::{CellFaces, Grid, cube, grid};

    fn build(list: &FaceList<'_>, policy: BuildPolicy) -> (Mesh, Diagnostic) {
        Mesh::from_face_list(list, policy).unwrap()
    }

    #[test]
    fn grid_wireframe_and_boundary() {
        let soup = grid(&Grid {
            width: 2.0,
            height: 2.0,
            cells_x: 2,
            cells_y: 2,
            faces: CellFaces::Quads,
        })
        .unwrap();
        let (mesh, _) = build(&soup.as_face_list(), BuildPolicy::Strict);
        let wireframe = wireframe_lines(&mesh);
        assert_eq!(wireframe.n_segments(), 12);
        assert_eq!(wireframe.positions.len(), 6 * 12);
        let boundary = boundary_lines(&mesh);
        assert_eq!(boundary.n_segments(), 8);
        for (segment, &e) in boundary.positions.chunks_exact(6).zip(&boundary.sources) {
            assert!(mesh.is_boundary_edge(EdgeId(e)));
            // Both ends on the square's border |x| = 1 or |y| = 1.
            for end in segment.chunks_exact(3) {
                assert!(end[0].abs() == 1.0 || end[1].abs() == 1.0, "{end:?}");
            }
        }
    }

    #[test]
    fn closed_mesh_has_no_boundary_lines() {
        let soup = cube(1.0).unwrap();
        let (mesh, diagnostic) = build(&soup.as_face_list(), BuildPolicy::Strict);
        assert_eq!(boundary_lines(&mesh).n_segments(), 0);
        assert_eq!(
            non_manifold_lines(&mesh, &diagnostic).unwrap().n_segments(),
            0
        );
    }

    #[test]
    fn non_manifold_edges_come_from_the_diagnostic() {
        // Three triangles on the edge 0-1: a book with three pages.
        let positions = [
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
        ];
        let indices = [0, 1, 2, 1, 0, 3, 0, 1, 4];
        let (mesh, diagnostic) = build(
            &FaceList::triangles(&positions, &indices),
            BuildPolicy::Repair,
        );
        assert_eq!(diagnostic.non_manifold_edges.len(), 1);
        let lines = non_manifold_lines(&mesh, &diagnostic).unwrap();
        assert_eq!(lines.positions, vec![0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(lines.sources, vec![0]);

        let foreign = Diagnostic {
            non_manifold_edges: vec![EdgeReport {
                vertices: [0, 99],
                faces: vec![0, 1, 2],
            }],
            ..Diagnostic::default()
        };
        assert_eq!(
            non_manifold_lines(&mesh, &foreign),
            Err(RenderError::DiagnosticMismatch {
                vertex: 99,
                vertices: mesh.n_vertex_slots()
            })
        );
    }
}
