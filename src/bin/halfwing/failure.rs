//! Why a command failed, and the exit code that says so.

/// A usage error: unknown command or option, missing argument.
pub const USAGE: u8 = 2;
/// An input file cannot be read or parsed.
pub const INPUT: u8 = 3;
/// An output file cannot be written.
pub const OUTPUT: u8 = 4;
/// The operation refused its input.
pub const REFUSED: u8 = 5;

/// A message for stderr and the exit code.
#[derive(Debug)]
pub struct Failure {
    pub message: String,
    pub code: u8,
}

impl Failure {
    pub fn usage(message: String) -> Self {
        Failure {
            message,
            code: USAGE,
        }
    }

    pub fn input(message: String) -> Self {
        Failure {
            message,
            code: INPUT,
        }
    }

    pub fn output(message: String) -> Self {
        Failure {
            message,
            code: OUTPUT,
        }
    }

    pub fn refused(message: String) -> Self {
        Failure {
            message,
            code: REFUSED,
        }
    }
}

/// What a command gives back: an exit code, or a failure.
pub type Outcome = Result<u8, Failure>;
