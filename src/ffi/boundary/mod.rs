//! The plumbing every exported function shares: the guard that catches panics and checks
//! pointers, status codes, the last-error message, object handles, and the library-wide settings
//! (threads, version). Nothing here knows a kernel.

pub(crate) mod error;
pub(crate) mod face_list;
mod guard;
pub(crate) mod handle;
mod quiet_panics;
pub mod status;
pub mod threads;
pub mod version;

pub(crate) use guard::*;
