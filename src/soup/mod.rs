//! Indexed face lists ("polygon soups"): the input every kernel is built from and the output every
//! reader produces. Validation and edge pairing of a face list live here so that the half-edge and
//! winged-edge kernels share one diagnostic instead of two copies.
//!
//! A builder calls [`resolve`] with a [`BuildPolicy`]: it lays the list out as a [`FaceTable`],
//! finds malformed faces and non-finite coordinates, pairs directed edges by bucketing
//! ([`pair_edges`]), and refuses, skips or repairs until every corner has a partner corner or is
//! on the boundary. The [`Diagnostic`] lists everything found, by input index.

mod degenerate;
mod diagnostic;
mod edge_buckets;
mod enclosed_volume;
mod face_list;
mod front;
mod inspect;
mod large_buckets;
mod orient;
mod pairing;
mod policy;
mod resolve;
mod table;
mod umbrellas;

pub(crate) use degenerate::DegenerateFaces;
pub use diagnostic::{Diagnostic, EdgeReport, ListProblem};
pub(crate) use edge_buckets::{EdgeBuckets, EdgeVisit, EdgeVisitor};
pub(crate) use enclosed_volume::component_volumes;
pub use face_list::{FaceList, FaceSizes, PolygonSoup};
pub(crate) use front::{Pinched, Unreached, Walked, build_splitting_pinched, walk_faces};
pub use inspect::diagnose;
pub(crate) use inspect::{Inspection, inspect, unnamed_vertices};
pub(crate) use orient::{faces_facing_inward, faces_to_flip, flip_faces, search_orientations};
pub use pairing::{BOUNDARY, EdgeDefect, EdgePairing, ProblemEdge, UNPAIRED, pair_edges};
pub use policy::{BuildError, BuildPolicy};
pub use resolve::{Resolved, resolve};
pub(crate) use resolve::{VertexCopies, first_come_refusals, repair_edges, symmetric_difference};
pub(crate) use table::face_edges;
pub use table::{FaceDefects, FaceTable, Faces, MAX_CORNERS, MAX_VERTICES, non_finite_vertices};
pub(crate) use umbrellas::{Fans, split_non_manifold_vertices, split_umbrellas};
