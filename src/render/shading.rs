//! How a render buffer's normals are chosen, and how its vertex attributes are laid out.

use crate::geom::VertexNormalWeighting;

/// Where a triangle corner's normal comes from.
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
}

impl Default for Shading {
    /// Smooth with the angle weighting, the usual choice of viewers.
    fn default() -> Self {
        Shading::Smooth(VertexNormalWeighting::Angle)
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
