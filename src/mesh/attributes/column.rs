//! One named column of per-element values: a plain numeric type, a fixed number of components
//! per element, stored flat (element `i` owns `values[i * components .. (i + 1) * components]`).

use std::any::Any;
use std::fmt;

use crate::support::allocation::{OutOfMemory, try_filled};

/// The numeric type of an attribute column.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScalarType {
    /// `f64`.
    F64,
    /// `f32`.
    F32,
    /// `i32`.
    I32,
    /// `u32`.
    U32,
}

impl fmt::Display for ScalarType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ScalarType::F64 => "f64",
            ScalarType::F32 => "f32",
            ScalarType::I32 => "i32",
            ScalarType::U32 => "u32",
        })
    }
}

/// The values of a column, one vector per scalar type.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ColumnData {
    F64(Vec<f64>),
    F32(Vec<f32>),
    I32(Vec<i32>),
    U32(Vec<u32>),
}

/// Runs `$body` with `$values` bound to the column's vector, whatever its type.
macro_rules! with_values {
    ($data:expr, $values:ident => $body:expr) => {
        match $data {
            ColumnData::F64($values) => $body,
            ColumnData::F32($values) => $body,
            ColumnData::I32($values) => $body,
            ColumnData::U32($values) => $body,
        }
    };
}

impl ColumnData {
    /// The values as a `Vec<T>`, if the column holds `T`.
    pub(crate) fn values<T: Scalar>(&self) -> Option<&Vec<T>> {
        with_values!(self, values => (values as &dyn Any).downcast_ref())
    }

    /// The values as a writable `Vec<T>`, if the column holds `T`.
    pub(crate) fn values_mut<T: Scalar>(&mut self) -> Option<&mut Vec<T>> {
        with_values!(self, values => (values as &mut dyn Any).downcast_mut())
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
    impl Sealed for i32 {}
    impl Sealed for u32 {}
}

/// A type an attribute column can hold: `f64`, `f32`, `i32` or `u32`.
pub trait Scalar: sealed::Sealed + Copy + Default + PartialEq + fmt::Debug + 'static {
    /// The matching [`ScalarType`].
    const TYPE: ScalarType;

    /// The value a fraction `t` of the way from `a` to `b`: linear for floating-point types;
    /// integers (labels, counts, ids) take the nearer end, since a mean label means nothing.
    fn blend(a: Self, b: Self, t: f64) -> Self;
}

macro_rules! scalar {
    ($t:ty, $variant:ident, |$a:ident, $b:ident, $s:ident| $blend:expr) => {
        impl Scalar for $t {
            const TYPE: ScalarType = ScalarType::$variant;

            fn blend($a: Self, $b: Self, $s: f64) -> Self {
                $blend
            }
        }
    };
}

scalar!(f64, F64, |a, b, t| a + (b - a) * t);
scalar!(
    f32,
    F32,
    |a, b, t| (f64::from(a) + (f64::from(b) - f64::from(a)) * t) as f32
);
scalar!(i32, I32, |a, b, t| if t < 0.5 { a } else { b });
scalar!(u32, U32, |a, b, t| if t < 0.5 { a } else { b });

/// A named column (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Column {
    pub(crate) name: String,
    pub(crate) components: usize,
    pub(crate) data: ColumnData,
    /// The column holds unit vectors (corner normals): blends are renormalised, since a linear
    /// blend of two unit vectors is shorter than one.
    pub(crate) unit_vectors: bool,
}

impl Column {
    /// A zero-filled column for `n_elements` elements, or the refusal of its memory.
    pub(crate) fn zeroed(
        name: &str,
        scalar: ScalarType,
        components: usize,
        n_elements: usize,
    ) -> Result<Self, OutOfMemory> {
        let len = n_elements.saturating_mul(components);
        const WHAT: &str = "attribute values";
        let data = match scalar {
            ScalarType::F64 => ColumnData::F64(try_filled(len, 0.0, WHAT)?),
            ScalarType::F32 => ColumnData::F32(try_filled(len, 0.0, WHAT)?),
            ScalarType::I32 => ColumnData::I32(try_filled(len, 0, WHAT)?),
            ScalarType::U32 => ColumnData::U32(try_filled(len, 0, WHAT)?),
        };
        Ok(Column {
            name: name.to_owned(),
            components,
            data,
            unit_vectors: false,
        })
    }

    pub(crate) fn scalar_type(&self) -> ScalarType {
        match self.data {
            ColumnData::F64(_) => ScalarType::F64,
            ColumnData::F32(_) => ScalarType::F32,
            ColumnData::I32(_) => ScalarType::I32,
            ColumnData::U32(_) => ScalarType::U32,
        }
    }

    /// Number of scalars stored.
    pub(crate) fn len(&self) -> usize {
        with_values!(&self.data, values => values.len())
    }

    /// Grows (zero-filling) or shrinks the column to `n_elements`.
    pub(crate) fn resize(&mut self, n_elements: usize) {
        let len = n_elements * self.components;
        with_values!(&mut self.data, values => values.resize(len, Default::default()));
    }

    /// Copies element `from`'s values onto element `to`.
    pub(crate) fn copy(&mut self, from: usize, to: usize) {
        let k = self.components;
        with_values!(&mut self.data, values => values.copy_within(from * k..(from + 1) * k, to * k));
    }

    /// Sets element `to` to the blend a fraction `t` of the way from element `a` to `b` (see
    /// [`Scalar::blend`]).
    pub(crate) fn blend(&mut self, a: usize, b: usize, t: f64, to: usize) {
        let k = self.components;
        with_values!(&mut self.data, values => {
            for c in 0..k {
                values[to * k + c] = Scalar::blend(values[a * k + c], values[b * k + c], t);
            }
        });
        if self.unit_vectors {
            self.renormalise(to);
        }
    }

    fn renormalise(&mut self, element: usize) {
        let k = self.components;
        if let ColumnData::F64(values) = &mut self.data {
            let vector = &mut values[element * k..(element + 1) * k];
            let length = vector.iter().map(|x| x * x).sum::<f64>().sqrt();
            if length > 0.0 && length.is_finite() {
                vector.iter_mut().for_each(|x| *x /= length);
            }
        }
    }

    /// Zeroes element `i`.
    pub(crate) fn reset(&mut self, i: usize) {
        let k = self.components;
        with_values!(&mut self.data, values => values[i * k..(i + 1) * k].fill(Default::default()));
    }

    /// Keeps the elements whose `map` entry is valid, moving each to its new index. The map keeps
    /// live elements in order (`map[i] <= i`), so the move is done in place, front to back.
    pub(crate) fn compact(&mut self, map: &[u32]) {
        let k = self.components;
        let mut kept = 0usize;
        for (old, &new) in map.iter().enumerate() {
            if new != u32::MAX {
                debug_assert!(new as usize <= old);
                self.copy(old, new as usize);
                kept = new as usize + 1;
            }
        }
        with_values!(&mut self.data, values => values.truncate(kept * k));
    }
}
