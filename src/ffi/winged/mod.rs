//! The winged-edge kernel's C functions (`hw_winged_*`, `hw_wcirc_*`), in the order the header
//! lists them: lifecycle, navigation, circulators, edits (the Euler operators), positions,
//! normals, tables.

pub(crate) mod lifecycle;

pub(crate) mod navigation;

pub(crate) mod circulator;

pub(crate) mod euler;

pub(crate) mod positions;

pub(crate) mod normals;

pub(crate) mod table;

pub use circulator::*;
pub use euler::*;
pub use lifecycle::*;
pub use navigation::*;
pub use normals::*;
pub use positions::*;
pub use table::*;
