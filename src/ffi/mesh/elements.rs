//! Element ids as small by-value C structs, so the compiler keeps vertices, half-edges, edges and
//! faces apart (`hw_vertex v = hw_mesh_he_origin(mesh, h);`).

use crate::mesh::{EdgeId, ElementKind, FaceId, HalfedgeId, HandleError, VertexId};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::HW_ERR_INVALID_HANDLE;

/// The raw value of "no element": an id whose `idx` is this is invalid.
/// \ingroup ids
pub const HW_INVALID_INDEX: u32 = u32::MAX;

/// A vertex id.
/// \ingroup ids
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_vertex {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// A half-edge id. Half-edges come in pairs: the twin of `h` is `h.idx ^ 1`, its edge `h.idx >> 1`.
/// \ingroup ids
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_halfedge {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// An (undirected) edge id: edge `e` has the half-edges `2 e` and `2 e + 1`.
/// \ingroup ids
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_edge {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// A face id.
/// \ingroup ids
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct hw_face {
    /// The index; `HW_INVALID_INDEX` means none.
    pub idx: u32,
}

/// An element kind, to pick one of several per-kind arrays.
/// \ingroup ids
pub type hw_element_kind = u32;
/// Vertices.
/// \ingroup ids
pub const HW_ELEMENT_KIND_VERTEX: hw_element_kind = 0;
/// Half-edges.
/// \ingroup ids
pub const HW_ELEMENT_KIND_HALFEDGE: hw_element_kind = 1;
/// Edges.
/// \ingroup ids
pub const HW_ELEMENT_KIND_EDGE: hw_element_kind = 2;
/// Faces.
/// \ingroup ids
pub const HW_ELEMENT_KIND_FACE: hw_element_kind = 3;

/// The Rust element kind of a C one.
pub(crate) fn element_kind(raw: hw_element_kind) -> Result<ElementKind, FfiError> {
    match raw {
        HW_ELEMENT_KIND_VERTEX => Ok(ElementKind::Vertex),
        HW_ELEMENT_KIND_HALFEDGE => Ok(ElementKind::Halfedge),
        HW_ELEMENT_KIND_EDGE => Ok(ElementKind::Edge),
        HW_ELEMENT_KIND_FACE => Ok(ElementKind::Face),
        other => Err(FfiError::invalid_input(format!(
            "unknown element kind {other}"
        ))),
    }
}

/// Pairs each C id struct with its Rust id (also used by the winged-edge ids).
macro_rules! id_conversions {
    ($($c:ident <=> $rust:ident),*) => {$(
        impl From<$c> for $rust {
            fn from(id: $c) -> Self { $rust(id.idx) }
        }
        impl From<$rust> for $c {
            fn from(id: $rust) -> Self { $c { idx: id.0 } }
        }
        impl $c {
            // Not every kind has a call that returns "none".
            #[allow(dead_code)]
            pub(crate) const INVALID: $c = $c { idx: $crate::ffi::mesh::elements::HW_INVALID_INDEX };
        }
    )*};
}
pub(crate) use id_conversions;

id_conversions!(hw_vertex <=> VertexId, hw_halfedge <=> HalfedgeId, hw_edge <=> EdgeId, hw_face <=> FaceId);

impl From<HandleError> for FfiError {
    fn from(error: HandleError) -> Self {
        FfiError::new(HW_ERR_INVALID_HANDLE, error.to_string())
    }
}
