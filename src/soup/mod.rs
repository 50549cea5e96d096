//! Indexed face lists ("polygon soups"): the input every kernel is built from and the output every
//! reader produces. Validation and edge pairing of a face list live here so that the half-edge and
//! winged-edge kernels share one diagnostic instead of two copies.

mod face_list;

pub use face_list::{FaceList, FaceSizes, PolygonSoup};
