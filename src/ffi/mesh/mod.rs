//! The half-edge kernel's C functions (`hw_mesh_*`, `hw_circ_*`, `hw_soup_*`), in the order the
//! header lists them: lifecycle, navigation, circulators, topology, edits, attributes, normals,
//! files.

// Lifecycle: element ids, the mesh object, the build diagnostic.
pub(crate) mod elements;

pub(crate) mod lifecycle;

pub(crate) mod diagnostic;

// Navigation: single steps, zero-copy arrays, the inline view.
pub(crate) mod navigation;

pub(crate) mod views;

pub(crate) mod nav;

// Circulators and callbacks.
pub(crate) mod circulator;

pub(crate) mod visit;

// Whole-mesh topology.
pub(crate) mod topology;

// Edits.
pub(crate) mod edit;

// Positions and attributes.
pub(crate) mod positions;

pub(crate) mod attributes;

// Normals.
pub(crate) mod normals;

// Files.
pub(crate) mod io;

pub use attributes::*;
pub use circulator::*;
pub use diagnostic::*;
pub use edit::*;
pub use elements::*;
pub use io::*;
pub use lifecycle::*;
pub use nav::*;
pub use navigation::*;
pub use normals::*;
pub use positions::*;
pub use topology::*;
pub use views::*;
pub use visit::*;
