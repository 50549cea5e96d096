//! Rendering buffers: polygon triangulation and GPU-ready arrays.
