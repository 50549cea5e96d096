//! The course notes' tables of an `hw_winged`: vertex, face and edge tables in three naming
//! conventions, as text, Markdown or CSV.

use crate::winged::{Naming, TableFormat};

use crate::ffi::boundary::error::FfiError;
use crate::ffi::boundary::status::*;
use crate::ffi::boundary::{copy_text, guard};
use crate::ffi::winged::lifecycle::{hw_winged, winged_ref};

/// Which table hw_winged_table() prints.
/// \ingroup winged_io
pub type hw_wtable = u32;
/// The vertex table: id, coordinates, stored edge (Baumgart's "Vertex-Edge" table).
/// \ingroup winged_io
pub const HW_WTABLE_VERTICES: hw_wtable = 0;
/// The face table: id, stored edge ("Face-Edge").
/// \ingroup winged_io
pub const HW_WTABLE_FACES: hw_wtable = 1;
/// The edge table: id, vertices, faces and wings ("Edge-Edge relation").
/// \ingroup winged_io
pub const HW_WTABLE_EDGES: hw_wtable = 2;
/// The three tables, vertex, face and edge, separated by a blank line.
/// \ingroup winged_io
pub const HW_WTABLE_ALL: hw_wtable = 3;

/// Which naming scheme a table's columns use.
/// \ingroup winged_io
pub type hw_wnaming = u32;
/// Baumgart's (his cube example): VSTART VEND EPCW ENCW EPCCW ENCCW FCW FCCW; elements labelled
/// from 1 with a letter (V1, E1, F1).
/// \ingroup winged_io
pub const HW_WNAMING_CW_CCW: hw_wnaming = 0;
/// The University of Granada notes': Vi Vf Cd Ci Ada Ads Aia Ais; elements numbered from 0.
/// \ingroup winged_io
pub const HW_WNAMING_DIRECT_INVERSE: hw_wnaming = 1;
/// Wikipedia's winged-edge article: vert_origin ... edge_right_ccw; elements numbered from 0.
/// \ingroup winged_io
pub const HW_WNAMING_LEFT_RIGHT: hw_wnaming = 2;

/// How a table is written.
/// \ingroup winged_io
pub type hw_table_format = u32;
/// Columns aligned with spaces; a hole is `∅` (UTF-8).
/// \ingroup winged_io
pub const HW_TABLE_FORMAT_TEXT: hw_table_format = 0;
/// A Markdown table; a hole is `∅`.
/// \ingroup winged_io
pub const HW_TABLE_FORMAT_MARKDOWN: hw_table_format = 1;
/// Comma-separated values with a header row; a hole is an empty field.
/// \ingroup winged_io
pub const HW_TABLE_FORMAT_CSV: hw_table_format = 2;

/// Prints a table of the structure in a textbook layout (`which`: ::HW_WTABLE_VERTICES, ...;
/// `naming`: ::HW_WNAMING_CW_CCW, ...; `format`: ::HW_TABLE_FORMAT_TEXT, ...) into `out_text`
/// (`capacity` bytes), NUL-terminated, every line ending with a newline. `*out_needed` (when not
/// NULL) always receives the size needed, terminator included; `HW_ERR_BUFFER_TOO_SMALL` when
/// `out_text` is NULL or shorter (call with `out_text = NULL` to learn the size). Unknown enum
/// values give `HW_ERR_INVALID_INPUT`.
///
/// # Safety
/// `winged` must be NULL or a live structure; `out_text` NULL or `capacity` writable bytes;
/// `out_needed` NULL or writable.
/// \ingroup winged_io
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hw_winged_table(
    winged: *const hw_winged,
    which: hw_wtable,
    naming: hw_wnaming,
    format: hw_table_format,
    out_text: *mut std::ffi::c_char,
    capacity: usize,
    out_needed: *mut usize,
) -> hw_status {
    guard(|| {
        // SAFETY: forwarded from the caller.
        let w = unsafe { winged_ref(winged) }?;
        let naming = match naming {
            HW_WNAMING_CW_CCW => Naming::ClockwiseCounterclockwise,
            HW_WNAMING_DIRECT_INVERSE => Naming::DirectInverse,
            HW_WNAMING_LEFT_RIGHT => Naming::LeftRight,
            other => return Err(FfiError::invalid_input(format!("unknown naming {other}"))),
        };
        let format = match format {
            HW_TABLE_FORMAT_TEXT => TableFormat::Text,
            HW_TABLE_FORMAT_MARKDOWN => TableFormat::Markdown,
            HW_TABLE_FORMAT_CSV => TableFormat::Csv,
            other => {
                return Err(FfiError::invalid_input(format!(
                    "unknown table format {other}"
                )));
            }
        };
        let text = match which {
            HW_WTABLE_VERTICES => w.vertex_table(naming, format),
            HW_WTABLE_FACES => w.face_table(naming, format),
            HW_WTABLE_EDGES => w.edge_table(naming, format),
            HW_WTABLE_ALL => w.tables(naming, format),
            other => return Err(FfiError::invalid_input(format!("unknown table {other}"))),
        };
        // SAFETY: forwarded from the caller.
        unsafe { copy_text(&text, out_text, capacity, out_needed) }
    })
}
