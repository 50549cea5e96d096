//! Per-corner normals and texture coordinates: halfwing's own half-edge attributes.
//!
//! The corner of vertex `v` in face `f` is the half-edge of `f` leaving `v` (the Granada notes'
//! "semiaristas aladas"), so a vertex on a crease or a texture seam holds one normal or texture
//! coordinate per face around it. Boundary half-edges have slots too; their values mean nothing
//! and are zero unless written.
//!
//! Every value is defined. A zero normal means "no normal": boundary half-edges have it, and so
//! do the corners of a mesh read from an OBJ that gives normals to some corners only (the render
//! buffers give such corners their computed normal). Those corners' texture coordinates are
//! `(0, 0)`.

use super::AttributeError;
use super::column::ScalarType;
use crate::mesh::{ElementKind, Mesh};

impl Mesh {
    /// Name of the corner-normal half-edge attribute (`f64` × 3, unit vectors, or zero for a
    /// corner without a normal).
    pub const CORNER_NORMALS: &'static str = "hw:corner_normal";
    /// Name of the texture-coordinate half-edge attribute (`f64` × 2; `(0, 0)` for a corner its
    /// file gives none).
    pub const CORNER_UVS: &'static str = "hw:corner_uv";

    /// The normal of every half-edge slot's corner, if the mesh has corner normals; zero where a
    /// corner has none (see the module docs).
    pub fn corner_normals(&self) -> Option<&[[f64; 3]]> {
        self.corner_vectors(Self::CORNER_NORMALS)
    }

    /// The corner normals, writable.
    pub fn corner_normals_mut(&mut self) -> Option<&mut [[f64; 3]]> {
        self.corner_vectors_mut(Self::CORNER_NORMALS)
    }

    /// Sets every half-edge slot's corner normal (one per slot, deleted ones included), adding
    /// the attribute if needed. Edits renormalise the normals they blend.
    pub fn set_corner_normals(&mut self, normals: &[[f64; 3]]) -> Result<(), AttributeError> {
        self.set_corner_vectors(Self::CORNER_NORMALS, normals, true)
    }

    /// The texture coordinates of every half-edge slot's corner, if the mesh has them.
    pub fn corner_uvs(&self) -> Option<&[[f64; 2]]> {
        self.corner_vectors(Self::CORNER_UVS)
    }

    /// The corner texture coordinates, writable.
    pub fn corner_uvs_mut(&mut self) -> Option<&mut [[f64; 2]]> {
        self.corner_vectors_mut(Self::CORNER_UVS)
    }

    /// Sets every half-edge slot's texture coordinates, adding the attribute if needed.
    pub fn set_corner_uvs(&mut self, uvs: &[[f64; 2]]) -> Result<(), AttributeError> {
        self.set_corner_vectors(Self::CORNER_UVS, uvs, false)
    }

    fn corner_vectors<const N: usize>(&self, name: &str) -> Option<&[[f64; N]]> {
        let flat = self.attribute::<f64>(ElementKind::Halfedge, name).ok()?;
        Some(as_vectors(flat))
    }

    fn corner_vectors_mut<const N: usize>(&mut self, name: &str) -> Option<&mut [[f64; N]]> {
        let flat = self
            .attribute_mut::<f64>(ElementKind::Halfedge, name)
            .ok()?;
        Some(as_vectors_mut(flat))
    }

    fn set_corner_vectors<const N: usize>(
        &mut self,
        name: &'static str,
        values: &[[f64; N]],
        unit_vectors: bool,
    ) -> Result<(), AttributeError> {
        let expected = self.n_halfedge_slots();
        if values.len() != expected {
            return Err(AttributeError::WrongLength {
                name,
                expected,
                actual: values.len(),
            });
        }
        if self.attributes.halfedge.find(name).is_none() {
            let column = self.insert_column(ElementKind::Halfedge, name, ScalarType::F64, N)?;
            column.unit_vectors = unit_vectors;
        }
        self.attribute_mut::<f64>(ElementKind::Halfedge, name)?
            .copy_from_slice(values.as_flattened());
        Ok(())
    }
}

/// Reads a flat column of `N`-vectors as vectors (its length is a multiple of `N`).
fn as_vectors<const N: usize>(flat: &[f64]) -> &[[f64; N]] {
    debug_assert_eq!(flat.len() % N, 0);
    // SAFETY: `[f64; N]` has the alignment of `f64` and the size of `N` of them, without padding,
    // and the slice holds `flat.len() / N` whole vectors. (`slice::as_chunks` needs Rust 1.88,
    // above the crate's minimum.)
    unsafe { std::slice::from_raw_parts(flat.as_ptr().cast(), flat.len() / N) }
}

fn as_vectors_mut<const N: usize>(flat: &mut [f64]) -> &mut [[f64; N]] {
    debug_assert_eq!(flat.len() % N, 0);
    // SAFETY: as in `as_vectors`; the exclusive borrow moves to the result.
    unsafe { std::slice::from_raw_parts_mut(flat.as_mut_ptr().cast(), flat.len() / N) }
}
