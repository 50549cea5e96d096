//! Attributes: named columns of plain numeric values (`f64`, `f32`, `i32`, `u32`; 1 to
//! [`MAX_COMPONENTS`] per element) on vertices, half-edges, edges or faces, plus halfwing's own
//! per-corner normals and texture coordinates ([`Mesh::CORNER_NORMALS`], [`Mesh::CORNER_UVS`]),
//! which are half-edge attributes: the corner of vertex `v` in face `f` lives on the half-edge of
//! `f` leaving `v`.
//!
//! A column has one entry per element slot, deleted slots included, and follows the mesh through
//! every edit by these rules:
//! - **New elements** start at zero: [`Mesh::add_vertex`], and in [`Mesh::add_face`] the face,
//!   its new edges and all its corners (boundary half-edges it takes over lose their values).
//! - **Edge split** ([`Mesh::split_edge`] of `a → b` at `p`): with `t` the position of `p`
//!   projected on the segment (clamped to `[0, 1]`; `0.5` for a zero-length edge), the new
//!   vertex and, in each face beside the edge, the new corner are the blend of the values at `a`
//!   and `b` a fraction `t` of the way (linear for floats — corner normals renormalised —, the
//!   nearer end for integers); the corners at `a` and `b` keep their values, and both halves of
//!   the edge keep the edge's values.
//! - **Face split and triangulation**: each new face copies the split face; each corner keeps
//!   its value on both sides of the new edge; the new edge starts at zero.
//! - **Edge flip**: the edge and the faces keep their ids and values; every corner keeps its
//!   value, and each end of the new diagonal copies the corner of the same vertex in the
//!   triangle across (the corner it had before the flip in the other face).
//! - **Collapse**: the kept vertex keeps its values; half-edges keep theirs, so corners that
//!   moved from the removed vertex keep the removed vertex's corner values; where a vanishing
//!   triangle merges two edges, the surviving edge keeps its values and its half-edge takes the
//!   corner value of the half-edge it replaces.
//! - **Deletion** only marks elements; [`Mesh::garbage_collect`] drops their values and compacts
//!   the columns with the returned index maps.
//!
//! Building with [`Mesh::from_soup`] keeps a soup's corner normals and texture coordinates on the
//! half-edges, and [`Mesh::to_soup`] exports them, so per-corner OBJ data round-trips.

mod access;
mod column;
mod corner;
mod error;
mod follow;
mod set;

pub use access::AttributeInfo;
pub use column::{Scalar, ScalarType};
pub use error::AttributeError;
pub(crate) use set::Attributes;

/// Largest number of components per element (a 4 × 4 matrix).
pub const MAX_COMPONENTS: usize = 16;

/// Prefix of the names halfwing reserves for its own attributes.
pub(crate) const RESERVED_PREFIX: &str = "hw:";
