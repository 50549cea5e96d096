//! The half-edge polygon-mesh kernel.
//!
//! [`Mesh`] stores general polygon meshes as struct-of-arrays of `u32` ids (see its docs for the
//! conventions: `twin(h) = h ^ 1`, boundary half-edges with no face linked in loops, vertices
//! storing their boundary half-edge). Build one with [`Mesh::from_face_list`]; navigate with the
//! fast accessors or their checked `try_*` forms; circulate with the iterators of
//! [`circulators`]; validate with [`Mesh::check`].

pub mod attributes;
mod build;
mod check;
pub mod circulators;
mod compact;
mod components;
mod diagnose;
mod edit;
mod ids;
mod navigation;
mod normals;
mod raw_parts;
mod soup_conversion;
mod structure;
mod vertex_fans;

pub use crate::soup::{BuildError, BuildPolicy, Diagnostic};
pub use crate::support::index_maps::IndexMaps;
pub(crate) use crate::support::index_maps::compaction_map;
pub use attributes::{AttributeError, AttributeInfo, Scalar, ScalarType};
pub use check::{Element, Invariant, InvariantError};
pub use circulators::{Step, Walk, WalkState};
pub use components::Components;
pub use edit::EditError;
pub(crate) use edit::{JoinedCorners, Pinch, chords_of};
pub use ids::{EdgeId, FaceId, HalfedgeId, INVALID_INDEX, VertexId};
pub use navigation::{ElementKind, HandleError};
pub(crate) use raw_parts::MeshArrays;
pub use structure::Mesh;
