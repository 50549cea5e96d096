//! The half-edge polygon-mesh kernel.
