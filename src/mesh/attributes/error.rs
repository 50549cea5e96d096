//! Why an attribute call failed.

use super::column::ScalarType;
use crate::mesh::ElementKind;

/// Why an attribute call failed; the mesh is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AttributeError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// No attribute of that kind has that name.
    #[error("no {kind} attribute is named \"{name}\"")]
    NotFound {
        /// Element kind searched.
        kind: ElementKind,
        /// The name asked for.
        name: String,
    },
    /// An attribute of that kind has the name already.
    #[error("a {kind} attribute named \"{name}\" exists already")]
    NameTaken {
        /// Element kind.
        kind: ElementKind,
        /// The name.
        name: String,
    },
    /// The attribute holds another scalar type than the one asked for.
    #[error("{kind} attribute \"{name}\" holds {stored} values, not {requested}")]
    WrongType {
        /// Element kind.
        kind: ElementKind,
        /// The name.
        name: String,
        /// The type it holds.
        stored: ScalarType,
        /// The type asked for.
        requested: ScalarType,
    },
    /// The name is empty or uses the prefix reserved for halfwing's own attributes.
    #[error("attribute name \"{name}\" is not allowed: {reason}")]
    InvalidName {
        /// The name.
        name: String,
        /// Why.
        reason: &'static str,
    },
    /// The component count is outside `1..=MAX_COMPONENTS`.
    #[error("an attribute has 1 to {max} components per element, not {count}", max = super::MAX_COMPONENTS)]
    InvalidComponents {
        /// The count given.
        count: usize,
    },
    /// A whole-column assignment has the wrong number of values.
    #[error("{name}: {actual} values given for {expected} element slots")]
    WrongLength {
        /// The attribute.
        name: &'static str,
        /// Element slots of the mesh (deleted ones included).
        expected: usize,
        /// Values given.
        actual: usize,
    },
}
