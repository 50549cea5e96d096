//! Conversion to and from [`PolygonSoup`], lossless both ways for the faces.

use super::structure::Winged;
use crate::soup::{BuildError, BuildPolicy, Diagnostic, PolygonSoup};

impl Winged {
    /// Builds from an owned face list under `policy` (see [`Winged::from_face_list`]).
    ///
    /// Per-corner normals and texture coordinates are not kept: the winged-edge structure has
    /// one record per edge and no place for per-corner data (the limitation the Granada notes name).
    pub fn from_soup(
        soup: &PolygonSoup,
        policy: BuildPolicy,
    ) -> Result<(Self, Diagnostic), BuildError> {
        Self::from_face_list(&soup.as_face_list(), policy)
    }

    /// The indexed face list of the live faces, in face id order, each starting at the tail of
    /// its stored edge's use and following its loop. For a structure built from a face list
    /// (and not edited), this reproduces the input exactly: same faces, same first corner, same
    /// vertex order, same positions.
    ///
    /// Vertices are renumbered densely over the live ones (in id order), which is the identity
    /// when nothing was deleted. Point faces (MVFS) have no polygon and are left out; a face
    /// with a dangling edge (MEV) lists the edge's vertices as its loop meets them.
    pub fn to_soup(&self) -> PolygonSoup {
        let mut new_index = vec![u32::MAX; self.positions.len()];
        let mut positions = Vec::with_capacity(self.n_live_vertices as usize);
        for v in self.vertices() {
            new_index[v.index()] = positions.len() as u32;
            positions.push(self.positions[v.index()]);
        }
        let mut face_sizes = Vec::with_capacity(self.n_live_faces as usize);
        let mut indices = Vec::with_capacity(2 * self.n_live_edges as usize);
        for f in self.faces() {
            let before = indices.len();
            if let Ok(walk) = self.face_loop(f) {
                indices.extend(walk.map(|u| new_index[self.tail_of(u).index()]));
            }
            if indices.len() > before {
                face_sizes.push((indices.len() - before) as u32);
            }
        }
        PolygonSoup {
            positions,
            face_sizes,
            indices,
            corner_normals: None,
            corner_uvs: None,
        }
    }
}
