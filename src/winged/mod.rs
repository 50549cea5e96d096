//! The winged-edge (Baumgart) mesh kernel.
//!
//! One [`EdgeRecord`] per undirected edge holds its two vertices, the face on each side and the
//! four *wings*: the previous and next edge around each of the two faces. Vertices and faces
//! hold one edge each. Faces are general polygons, counter-clockwise seen from outside. A side
//! with no face (`FaceId::INVALID`) is a hole: its wings still link the boundary loop, so a
//! boundary walks like a face.
//!
//! # Field names and the three conventions of the literature
//!
//! An edge runs `start → end`. Its **left** side is the loop that walks it `start → end`; its
//! **right** side is the loop that walks it `end → start` (see [`Side`]). Each side has a
//! previous and a next wing *in that side's own loop order*. This is one structure under three
//! names:
//!
//! | halfwing     | Baumgart (his cube)          | Granada                | Wikipedia                |
//! |--------------|------------------------------|------------------------|--------------------------|
//! | `start`      | VSTART                       | Vi                     | `vert_origin`            |
//! | `end`        | VEND                         | Vf                     | `vert_destination`       |
//! | `left_face`  | FCW                          | Cd (cara al derecho)   | `face_left`              |
//! | `right_face` | FCCW                         | Ci (cara invertida)    | `face_right`             |
//! | `left_prev`  | EPCW                         | Ada                    | `edge_left_cw`           |
//! | `left_next`  | ENCW                         | Ads                    | `edge_left_ccw`          |
//! | `right_prev` | EPCCW                        | Aia                    | `edge_right_cw`          |
//! | `right_next` | ENCCW                        | Ais                    | `edge_right_ccw`         |
//!
//! Baumgart names the sides after Baumgart's clockwise faces: its FCW face walks the edge
//! forward, and EPCW/ENCW are the previous/next edges of that walk (checked against its whole
//! cube table in the golden tests). In Wikipedia's terms, walking the left face counter-clockwise
//! goes from this edge to `edge_left_ccw` (our `left_next`), and clockwise to `edge_left_cw`
//! (`left_prev`); likewise on the right.
//!
//! # The orientation test
//!
//! A wing names an edge, not a direction, so every walk must ask which way the next edge is
//! walked. halfwing answers by vertex, not by face ([`EdgeRecord::side_leaving`]): the next edge
//! of a loop is walked on the side that leaves the vertex the loop has reached. That also works
//! where both sides of an edge carry the same face (the dangling edges MEV makes) and on holes.
//! The walks return [`EdgeUse`]s (edge + side), the winged counterpart of a half-edge.
//!
//! # Circulation orders
//!
//! - [`Winged::face_loop`]: counter-clockwise about the face (its loop order), from its stored
//!   edge.
//! - [`Winged::vertex_ring`]: counter-clockwise about the vertex seen from outside, stepping
//!   `e = e->prev->sym` as Baumgart does; holes are crossed like faces.
//!
//! # Building and converting
//!
//! [`Winged::from_face_list`] follows the classic construction ("Creación a partir de malla indexada" in
//! the Granada notes) on the shared face-list analysis of [`crate::soup`]: the same [`BuildPolicy`]
//! (strict, skip, repair), the same [`Diagnostic`] and the same [`BuildError`] as the
//! half-edge kernel's [`Mesh::from_face_list`](crate::mesh::Mesh::from_face_list), so both
//! kernels refuse, skip or repair the same input the same way. [`Winged::to_soup`] converts
//! back losslessly (same faces, same first corner, same order).
//! [`Winged::from_face_list_with_edge_order`] takes a hand-made edge numbering, as textbook
//! tables use.
//!
//! [`Winged::from_mesh`] and [`Winged::to_mesh`] convert record for record, without a face
//! list: edge `e` is mesh edge `e`, its left use half-edge `2e`, its right use half-edge
//! `2e + 1`. Both builders number edges and choose the stored edges of faces and vertices the
//! same way (see [`Winged::from_face_list`]), so building either kernel from a face list and
//! converting gives the other kernel's own build, every array of it.
//!
//! # Memory
//!
//! 32 bytes per edge record, 5 bytes per face, 29 bytes per vertex: about 67.5 bytes per face
//! for a closed triangle mesh (E = 1.5 F, V ≈ 0.5 F), against 66 for the half-edge mesh
//! ([`Winged::memory_bytes`]; `cargo bench --bench winged` prints both).
//!
//! # Editing
//!
//! The Euler operators [`Winged::mvfs`], [`Winged::mev`], [`Winged::mef`] and their inverses
//! [`Winged::kvfs`], [`Winged::kev`], [`Winged::kef`] check their preconditions and leave the
//! structure untouched when they refuse.
//! Deleted elements keep their ids (marked) until [`Winged::garbage_collect`] compacts them.

pub use crate::soup::{BuildError, BuildPolicy, Diagnostic};

mod build;
mod check;
mod circulators;
mod compact;
mod error;
mod euler;
mod ids;
mod mesh_conversion;
mod navigation;
mod normals;
mod record;
mod soup_conversion;
mod structure;
mod table;

pub use crate::support::index_maps::IndexMaps;
pub use circulators::{Step, Walk, WalkState};
pub use error::WingedError;
pub use ids::{EdgeId, EdgeUse, FaceId, Side, VertexId};
pub use record::EdgeRecord;
pub use structure::Winged;
pub use table::{Naming, TableFormat};
