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

/// What was being done to a file when the operating system refused it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileAction {
    /// Opening it for reading.
    Open,
    /// Reading it once open.
    Read,
    /// Creating (or truncating) it for writing.
    Create,
    /// Writing it once created.
    Write,
}

impl fmt::Display for FileAction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FileAction::Open => "open",
            FileAction::Read => "read",
            FileAction::Create => "create",
            FileAction::Write => "write",
        })
    }
}

/// Why reading or writing a mesh failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IoError {
    /// The operating system refused to open, read, create or write a named file.
    #[error("cannot {action} '{}': {}", path.display(), system_message(source))]
    File {
        /// What was being done.
        action: FileAction,
        /// The file.
        path: std::path::PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// A read from or a write to a stream failed (a reader or writer given no file name).
    #[error("the stream failed: {}", system_message(.0))]
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
    /// A 2D point file is malformed: a token that is not a number, a line without a point, a
    /// header announcing more points than follow, and so on.
    #[error("{}line {line}: {message} ({format} point file)", file_prefix(path))]
    PointParse {
        /// The file, when the points were read from one.
        path: Option<std::path::PathBuf>,
        /// The format being read.
        format: super::PointFormat,
        /// The 1-based line of the problem.
        line: u64,
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

/// The operating system's description of `error`, without Rust's " (os error N)" suffix.
fn system_message(error: &std::io::Error) -> String {
    let text = error.to_string();
    match (error.raw_os_error(), text.rfind(" (os error ")) {
        (Some(_), Some(suffix)) => text[..suffix].to_string(),
        _ => text,
    }
}

/// `'path' ` before a located message, or nothing.
fn file_prefix(path: &Option<std::path::PathBuf>) -> String {
    path.as_ref()
        .map(|p| format!("'{}' ", p.display()))
        .unwrap_or_default()
}

impl IoError {
    /// The error of `action` on the file `path`, from the operating system's `error`; errors of
    /// other kinds pass through.
    pub(crate) fn on_file(self, action: FileAction, path: &std::path::Path) -> IoError {
        match self {
            IoError::Io(source) => IoError::File {
                action,
                path: path.to_path_buf(),
                source,
            },
            other => other,
        }
    }

    /// The 1-based line of a text parse error, if this is one.
    pub fn line(&self) -> Option<u64> {
        match self {
            IoError::Parse {
                location: Location::Line(line),
                ..
            } => Some(*line),
            IoError::PointParse { line, .. } => Some(*line),
            _ => None,
        }
    }

    /// This error, a point file's parse error naming the file `path`.
    pub(crate) fn in_file(self, path: &std::path::Path) -> IoError {
        match self {
            IoError::PointParse {
                format,
                line,
                message,
                ..
            } => IoError::PointParse {
                path: Some(path.to_path_buf()),
                format,
                line,
                message,
            },
            other => other,
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
