//! The error every reader and writer returns, and where in a file a problem was found.

use std::fmt;

use super::format::MeshFormat;

/// Where in a file a parse problem was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// A 1-based line of a text file (OBJ, OFF, ASCII PLY). A file that ends too early reports the
    /// line after its last one.
    Line(u64),
    /// A 0-based record of an element of a binary PLY file (binary data has no lines).
    Record {
        /// The element's name as the header declares it (`vertex`, `face`, …).
        element: String,
        /// The record's index within its element.
        index: u64,
    },
    /// The PLY header's end, for problems that only show once the whole header is known.
    Header,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(line) => write!(f, "line {line}"),
            Location::Record { element, index } => write!(f, "element `{element}` record {index}"),
            Location::Header => write!(f, "header"),
        }
    }
}

/// Why reading or writing a mesh failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IoError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// The operating system refused a read or a write.
    #[error("I/O error: {0}")]
    Io(#[from] std::io::Error),
    /// The file is malformed: truncated, non-numeric where a number belongs, an index out of range
    /// of the declared vertex count, and so on.
    #[error("{format} parse error at {location}: {message}")]
    Parse {
        /// The format being read.
        format: MeshFormat,
        /// Where the problem is.
        location: Location,
        /// What the problem is, naming the offending token or count.
        message: String,
    },
    /// A format, variant or file extension halfwing does not read or write (binary OFF, 4D OFF, an
    /// unknown extension, …).
    #[error("unsupported format: {0}")]
    Unsupported(String),
    /// A writer was handed an inconsistent soup (sizes that do not add up to the index count, an
    /// index past the last position, attribute arrays of the wrong length).
    #[error("cannot write an inconsistent polygon soup: {0}")]
    InvalidSoup(String),
}

impl IoError {
    /// The 1-based line of a text parse error, if this is one.
    pub fn line(&self) -> Option<u64> {
        match self {
            IoError::Parse {
                location: Location::Line(line),
                ..
            } => Some(*line),
            _ => None,
        }
    }

    /// Builds a parse error at a line of a text file.
    pub(crate) fn at_line(format: MeshFormat, line: u64, message: impl Into<String>) -> Self {
        IoError::Parse {
            format,
            location: Location::Line(line),
            message: message.into(),
        }
    }
}
