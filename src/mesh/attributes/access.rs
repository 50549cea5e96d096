//! Adding, reading, writing, listing and removing named attributes.

use super::column::{Column, Scalar, ScalarType};
use super::{AttributeError, MAX_COMPONENTS, RESERVED_PREFIX};
use crate::mesh::{ElementKind, Mesh};

/// What an attribute holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AttributeInfo {
    /// Its scalar type.
    pub scalar: ScalarType,
    /// Values per element.
    pub components: usize,
}

impl Mesh {
    /// Number of element slots of `kind` (deleted ones included): attribute columns have this
    /// many elements.
    pub fn n_slots(&self, kind: ElementKind) -> usize {
        match kind {
            ElementKind::Vertex => self.n_vertex_slots(),
            ElementKind::Halfedge => self.n_halfedge_slots(),
            ElementKind::Edge => self.n_edge_slots(),
            ElementKind::Face => self.n_face_slots(),
        }
    }

    /// Adds a zero-filled attribute of `components` values of type `T` per element of `kind`.
    /// Refused when the name is taken, empty or starts with `hw:` (reserved for halfwing's own
    /// attributes, such as [`Mesh::CORNER_NORMALS`]), or `components` is not in
    /// `1..=MAX_COMPONENTS`.
    pub fn add_attribute<T: Scalar>(
        &mut self,
        kind: ElementKind,
        name: &str,
        components: usize,
    ) -> Result<(), AttributeError> {
        self.add_attribute_of_type(kind, name, T::TYPE, components)
    }

    /// [`Mesh::add_attribute`] with the type chosen at run time.
    pub fn add_attribute_of_type(
        &mut self,
        kind: ElementKind,
        name: &str,
        scalar: ScalarType,
        components: usize,
    ) -> Result<(), AttributeError> {
        if name.is_empty() {
            return Err(AttributeError::InvalidName {
                name: name.to_owned(),
                reason: "it is empty",
            });
        }
        if name.starts_with(RESERVED_PREFIX) {
            return Err(AttributeError::InvalidName {
                name: name.to_owned(),
                reason: "the prefix \"hw:\" is reserved for halfwing's own attributes",
            });
        }
        self.insert_column(kind, name, scalar, components)
            .map(|_| ())
    }

    /// Adds a zero-filled column, checking only the name's uniqueness and the component count.
    pub(super) fn insert_column(
        &mut self,
        kind: ElementKind,
        name: &str,
        scalar: ScalarType,
        components: usize,
    ) -> Result<&mut Column, AttributeError> {
        if !(1..=MAX_COMPONENTS).contains(&components) {
            return Err(AttributeError::InvalidComponents { count: components });
        }
        let n_elements = self.n_slots(kind);
        let set = self.attributes.of_mut(kind);
        if set.find(name).is_some() {
            return Err(AttributeError::NameTaken {
                kind,
                name: name.to_owned(),
            });
        }
        set.columns
            .push(Column::zeroed(name, scalar, components, n_elements)?);
        Ok(set.columns.last_mut().expect("pushed just now"))
    }

    fn column(&self, kind: ElementKind, name: &str) -> Result<&Column, AttributeError> {
        self.attributes
            .of(kind)
            .find(name)
            .ok_or_else(|| AttributeError::NotFound {
                kind,
                name: name.to_owned(),
            })
    }

    /// Type and component count of attribute `name` of `kind`.
    pub fn attribute_info(
        &self,
        kind: ElementKind,
        name: &str,
    ) -> Result<AttributeInfo, AttributeError> {
        let column = self.column(kind, name)?;
        Ok(AttributeInfo {
            scalar: column.scalar_type(),
            components: column.components,
        })
    }

    /// The values of attribute `name` of `kind`: element `i`'s components are
    /// `values[i * components .. (i + 1) * components]`, for every element slot (deleted ones
    /// included, until [`Mesh::garbage_collect`]).
    pub fn attribute<T: Scalar>(
        &self,
        kind: ElementKind,
        name: &str,
    ) -> Result<&[T], AttributeError> {
        let column = self.column(kind, name)?;
        column
            .data
            .values::<T>()
            .map(Vec::as_slice)
            .ok_or_else(|| wrong_type::<T>(kind, column))
    }

    /// The values of attribute `name` of `kind`, writable (layout as [`Mesh::attribute`]).
    pub fn attribute_mut<T: Scalar>(
        &mut self,
        kind: ElementKind,
        name: &str,
    ) -> Result<&mut [T], AttributeError> {
        let column = self.attributes.of_mut(kind).find_mut(name).ok_or_else(|| {
            AttributeError::NotFound {
                kind,
                name: name.to_owned(),
            }
        })?;
        let error = wrong_type::<T>(kind, column);
        column
            .data
            .values_mut::<T>()
            .map(Vec::as_mut_slice)
            .ok_or(error)
    }

    /// Removes attribute `name` of `kind` (halfwing's own `hw:` attributes included).
    pub fn remove_attribute(
        &mut self,
        kind: ElementKind,
        name: &str,
    ) -> Result<(), AttributeError> {
        let set = self.attributes.of_mut(kind);
        let index = set
            .columns
            .iter()
            .position(|c| c.name == name)
            .ok_or_else(|| AttributeError::NotFound {
                kind,
                name: name.to_owned(),
            })?;
        set.columns.remove(index);
        Ok(())
    }

    /// Names of the attributes of `kind`, in the order they were added.
    pub fn attribute_names(&self, kind: ElementKind) -> impl Iterator<Item = &str> + '_ {
        self.attributes
            .of(kind)
            .columns
            .iter()
            .map(|c| c.name.as_str())
    }
}

fn wrong_type<T: Scalar>(kind: ElementKind, column: &Column) -> AttributeError {
    AttributeError::WrongType {
        kind,
        name: column.name.clone(),
        stored: column.scalar_type(),
        requested: T::TYPE,
    }
}
