//! Conversion to and from [`PolygonSoup`]: building from an owned soup with its per-corner
//! normals and texture coordinates, and the faces back out as an indexed face list.
//!
//! The builder may leave faces out (Skip), drop repeated corners, reverse faces and give corners
//! copies of their vertex (Repair); it keeps face order and reports all of it in the
//! [`Diagnostic`]. Which input corner each half-edge came from is recovered from that report, so
//! the hot build path carries no attribute bookkeeping.

use crate::soup::{BuildError, BuildPolicy, Diagnostic, ListProblem, PolygonSoup};

use super::Mesh;
use super::ids::{FaceId, HalfedgeId, INVALID_INDEX, VertexId};

impl Mesh {
    /// Builds a mesh from `soup` under `policy`, as [`Mesh::from_face_list`] does, and keeps the
    /// soup's corner normals and texture coordinates on the half-edges (see
    /// [`Mesh::corner_normals`]): every face corner gets the value of the input corner it came
    /// from, also when Skip left faces out or Repair reversed faces, collapsed repeated corners
    /// or copied vertices. Boundary half-edges get zero. An attribute array whose length is not
    /// the number of indices is refused as invalid input.
    pub fn from_soup(
        soup: &PolygonSoup,
        policy: BuildPolicy,
    ) -> Result<(Mesh, Diagnostic), BuildError> {
        let n_corners = soup.indices.len() as u64;
        let lengths = [
            ("corner normals", soup.corner_normals.as_ref().map(Vec::len)),
            ("corner uvs", soup.corner_uvs.as_ref().map(Vec::len)),
        ];
        for (what, len) in lengths {
            if let Some(len) = len.filter(|&len| len as u64 != n_corners) {
                let diagnostic = Diagnostic {
                    list_problem: Some(ListProblem::CornerAttributeMismatch {
                        what,
                        expected: n_corners,
                        actual: len as u64,
                    }),
                    ..Diagnostic::default()
                };
                return Err(BuildError::InvalidInput(Box::new(diagnostic)));
            }
        }
        let (mut mesh, diagnostic) = Mesh::from_face_list(&soup.as_face_list(), policy)?;
        if soup.corner_normals.is_none() && soup.corner_uvs.is_none() {
            return Ok((mesh, diagnostic));
        }
        let source = mesh.input_corners(soup, &diagnostic);
        if let Some(normals) = &soup.corner_normals {
            let normals = gather(normals, &source);
            mesh.set_corner_normals(&normals)
                .expect("one normal per half-edge slot");
        }
        if let Some(uvs) = &soup.corner_uvs {
            let uvs = gather(uvs, &source);
            mesh.set_corner_uvs(&uvs)
                .expect("one uv per half-edge slot");
        }
        Ok((mesh, diagnostic))
    }

    /// The input corner of every half-edge slot (`INVALID_INDEX` on the boundary) of a mesh
    /// just built from `soup`. Mesh face `f` is the `f`-th input face not skipped; its loop
    /// from [`Mesh::face_halfedge`] lists its corners in the builder's order: the input corners
    /// that do not repeat their predecessor (Repair drops those), reversed when the face was
    /// reoriented.
    fn input_corners(&self, soup: &PolygonSoup, diagnostic: &Diagnostic) -> Vec<u32> {
        let mut offsets = Vec::with_capacity(soup.face_sizes.len() + 1);
        let mut total = 0u32;
        offsets.push(0);
        for &size in &soup.face_sizes {
            total += size;
            offsets.push(total);
        }
        let mut skipped = diagnostic.skipped_faces.iter().peekable();
        let mut reoriented = diagnostic.reoriented_faces.iter().peekable();
        let kept_faces =
            (0..soup.face_sizes.len() as u32).filter(|f| skipped.next_if_eq(&f).is_none());
        let mut source = vec![INVALID_INDEX; self.n_halfedge_slots()];
        let mut kept = Vec::new();
        for (face, input) in kept_faces.enumerate() {
            let range = offsets[input as usize]..offsets[input as usize + 1];
            let corners = &soup.indices[range.start as usize..range.end as usize];
            kept.clear();
            kept.extend(
                range
                    .clone()
                    .enumerate()
                    .filter(|&(i, _)| {
                        corners[i] != corners[(i + corners.len() - 1) % corners.len()]
                    })
                    .map(|(_, c)| c),
            );
            if reoriented.next_if_eq(&&input).is_some() {
                kept.reverse();
            }
            for (h, &c) in self.face_loop(FaceId(face as u32)).zip(&kept) {
                source[h.index()] = c;
            }
        }
        source
    }
}

/// Per-half-edge values from per-corner ones (zero where there is no source corner).
fn gather<T: Copy + Default>(per_corner: &[T], source: &[u32]) -> Vec<T> {
    source
        .iter()
        .map(|&c| per_corner.get(c as usize).copied().unwrap_or_default())
        .collect()
}

impl Mesh {
    /// The live faces as an indexed face list, corners in face-loop order from
    /// [`Mesh::face_halfedge`]. Deleted vertices and faces are compacted away (live elements keep
    /// their relative order); isolated vertices are kept. Corner normals and texture
    /// coordinates, when the mesh has them, become the soup's per-corner arrays. Building from
    /// the result with [`Mesh::from_soup`] reproduces the mesh.
    pub fn to_soup(&self) -> PolygonSoup {
        let mut new_index = vec![INVALID_INDEX; self.n_vertex_slots()];
        let mut positions = Vec::with_capacity(self.n_vertices());
        for (v, slot) in new_index.iter_mut().enumerate() {
            if !self.is_vertex_deleted(VertexId(v as u32)) {
                *slot = positions.len() as u32;
                positions.push(self.positions[v]);
            }
        }
        let mut face_sizes = Vec::with_capacity(self.n_faces());
        let mut corners = Vec::with_capacity(self.n_halfedges());
        for f in 0..self.n_face_slots() {
            let f = FaceId(f as u32);
            if self.is_face_deleted(f) {
                continue;
            }
            let start = corners.len();
            corners.extend(self.face_loop(f));
            face_sizes.push((corners.len() - start) as u32);
        }
        let indices = corners
            .iter()
            .map(|&h| {
                let v = self.origin(h);
                new_index.get(v.index()).copied().unwrap_or(INVALID_INDEX)
            })
            .collect();
        PolygonSoup {
            positions,
            face_sizes,
            indices,
            corner_normals: self.corner_normals().map(|n| per_corner(n, &corners)),
            corner_uvs: self.corner_uvs().map(|uv| per_corner(uv, &corners)),
        }
    }
}

/// The values of the given half-edges, in order.
fn per_corner<T: Copy>(values: &[T], corners: &[HalfedgeId]) -> Vec<T> {
    corners.iter().map(|h| values[h.index()]).collect()
}
