//! Library version, at compile time (macros in the header) and at run time.

use std::ffi::c_char;

/// Major version: incompatible API changes.
/// \ingroup errors
pub const HW_VERSION_MAJOR: u32 = 0;
/// Minor version: added functionality.
/// \ingroup errors
pub const HW_VERSION_MINOR: u32 = 2;
/// Patch version: bug fixes.
/// \ingroup errors
pub const HW_VERSION_PATCH: u32 = 0;
/// `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if HW_VERSION_NUMBER >= ...` checks.
/// \ingroup errors
pub const HW_VERSION_NUMBER: u32 =
    HW_VERSION_MAJOR * 10000 + HW_VERSION_MINOR * 100 + HW_VERSION_PATCH;

/// The version number of the library actually linked, in the form of `HW_VERSION_NUMBER`.
/// Compare with `HW_VERSION_NUMBER` to detect a header/library mismatch.
/// \ingroup errors
#[unsafe(no_mangle)]
pub extern "C" fn hw_version_number() -> u32 {
    HW_VERSION_NUMBER
}

/// The version of the library actually linked, as a static NUL-terminated string such as
/// `"0.2.0"`. Never NULL; must not be freed.
/// \ingroup errors
#[unsafe(no_mangle)]
pub extern "C" fn hw_version_string() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cargo_part(part: &str) -> u32 {
        part.parse().expect("Cargo.toml version parts are numbers")
    }

    /// The header's macros are written out in Rust for cbindgen; they must follow Cargo.toml.
    #[test]
    fn version_constants_match_cargo_toml() {
        assert_eq!(
            HW_VERSION_MAJOR,
            cargo_part(env!("CARGO_PKG_VERSION_MAJOR"))
        );
        assert_eq!(
            HW_VERSION_MINOR,
            cargo_part(env!("CARGO_PKG_VERSION_MINOR"))
        );
        assert_eq!(
            HW_VERSION_PATCH,
            cargo_part(env!("CARGO_PKG_VERSION_PATCH"))
        );
        let (major, minor, patch) = (
            cargo_part(env!("CARGO_PKG_VERSION_MAJOR")),
            cargo_part(env!("CARGO_PKG_VERSION_MINOR")),
            cargo_part(env!("CARGO_PKG_VERSION_PATCH")),
        );
        assert_eq!(hw_version_number(), major * 10000 + minor * 100 + patch);
        let text = unsafe { std::ffi::CStr::from_ptr(hw_version_string()) };
        assert_eq!(text.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    }
}
