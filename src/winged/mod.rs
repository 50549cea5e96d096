//! The winged-edge (Baumgart) mesh kernel.
