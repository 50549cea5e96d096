//! How a render buffer's normals are chosen, and how its vertex attributes are laid out.

use crate::geom::VertexNormalWeighting;

/// Where a triangle corner's normal comes from. `Flat`, `Smooth` and `Crease` compute every
/// normal from the positions, whatever normals the mesh or its file has; `CornerNormals` uses
/// those.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shading {
    /// Every corner takes its face's normal: a faceted look; vertices are split per face.
    Flat,
    /// Every corner takes its vertex's normal with this weighting: one render vertex per mesh
    /// vertex (unless per-corner attributes differ).
    Smooth(VertexNormalWeighting),
    /// Corners take the angle-weighted normal of the faces around their vertex reachable without
    /// crossing an edge sharper than this angle (radians, in `[0, π]`), so vertices are split
    /// along creases only.
    Crease(f64),
    /// Every corner takes its normal from
    /// [`SurfaceOptions::corner_normals`](super::SurfaceOptions::corner_normals) (a file's `vn`,
    /// a mesh's [`corner_normals`](crate::mesh::Mesh::corner_normals)), scaled to unit length. A
    /// corner without one takes the smooth normal with this weighting: so do all corners when no
    /// normals are given, and a corner whose given normal is the zero vector (how a mesh read
    /// from an OBJ stores the corners its file gives no normal) or has a NaN or infinite
    /// component.
    CornerNormals(VertexNormalWeighting),
}

impl Default for Shading {
    /// The given corner normals with the angle-weighted smooth normal where there are none: a
    /// file's own normals where it has them, as viewers show a file, and smooth shading otherwise.
    fn default() -> Self {
        Shading::CornerNormals(VertexNormalWeighting::Angle)
    }
}

/// How vertex attributes are stored.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum VertexLayout {
    /// One array per attribute: positions (xyz), normals (xyz) and, with uvs, uvs (uv).
    #[default]
    Separate,
    /// One array of `stride` floats per vertex: x y z nx ny nz, then u v when there are uvs.
    Interleaved,
}
