//! The winged-edge kernel's C functions (`hw_winged_*`, `hw_wcirc_*`): the object and its
//! walks, circulators, then the Euler operators.

pub(crate) mod lifecycle;

pub(crate) mod circulator;

pub(crate) mod euler;

pub use circulator::*;
pub use euler::*;
pub use lifecycle::*;
