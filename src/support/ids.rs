//! Typed ids: one `u32` newtype per element kind, `u32::MAX` meaning "no element".
//!
//! Every kernel and the Voronoi diagram define their ids with [`typed_id!`], so every id has the
//! same accessors ([`index`](crate::mesh::VertexId::index), `is_valid`, `INVALID`) and names its
//! element the same way in every message: the kind and the number ("vertex 3"), or, for the
//! invalid id, "vertex 4294967295 (the invalid id)" (the number a C caller passed as
//! `HW_INVALID_INDEX`).

/// The index that means "no element" (`u32::MAX`), as in the C API's `HW_INVALID_INDEX`.
pub const INVALID_INDEX: u32 = u32::MAX;

/// Defines a `u32` id newtype named `$name` whose messages call its element `$kind`.
macro_rules! typed_id {
    ($(#[$doc:meta])* $name:ident, $kind:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[repr(transparent)]
        pub struct $name(pub u32);

        impl $name {
            /// The id that names no element (`u32::MAX`, `HW_INVALID_INDEX` in C).
            pub const INVALID: Self = Self($crate::support::ids::INVALID_INDEX);

            /// Wraps a raw index.
            #[inline]
            pub const fn new(index: u32) -> Self {
                Self(index)
            }

            /// The raw index as a `usize`, for indexing storage arrays.
            #[inline]
            pub const fn index(self) -> usize {
                self.0 as usize
            }

            /// `false` only for [`Self::INVALID`]. A valid id may still be out of range or name
            /// a deleted element; the checked accessors of its structure say so.
            #[inline]
            pub const fn is_valid(self) -> bool {
                self.0 != $crate::support::ids::INVALID_INDEX
            }
        }

        impl Default for $name {
            /// The invalid id.
            fn default() -> Self {
                Self::INVALID
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                if self.is_valid() {
                    write!(f, concat!($kind, " {}"), self.0)
                } else {
                    write!(f, concat!($kind, " {} (the invalid id)"), self.0)
                }
            }
        }

        /// The same text as `Display`, so assertion messages name elements as errors do.
        impl std::fmt::Debug for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                std::fmt::Display::fmt(self, f)
            }
        }

        impl From<$name> for u32 {
            fn from(id: $name) -> u32 {
                id.0
            }
        }
    };
}

pub(crate) use typed_id;

#[cfg(test)]
mod tests {
    typed_id!(
        /// A test id.
        ThingId,
        "thing"
    );

    #[test]
    fn ids_name_their_kind_and_number() {
        assert_eq!(ThingId::new(3).to_string(), "thing 3");
        assert_eq!(format!("{:?}", ThingId(3)), "thing 3");
        assert_eq!(
            ThingId::INVALID.to_string(),
            "thing 4294967295 (the invalid id)"
        );
        assert_eq!(ThingId::new(7).index(), 7);
        assert!(!ThingId::default().is_valid());
        assert!(ThingId::new(0).is_valid());
        assert_eq!(u32::from(ThingId(5)), 5);
    }
}
