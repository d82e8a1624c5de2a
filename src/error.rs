//! Error types. Bad input is an [`Error`]; a contact problem without a solution is *not* an error but a
//! [`crate::solvers::Status`] recorded in the result.

use std::path::PathBuf;

/// Everything that stops rollbem before it can produce a result.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An input file (a scene, a sweep spec, an LCP file, a CSV to merge) could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// A scene file is not valid TOML or does not match the scene schema (missing key, wrong type, unknown key).
    #[error("{path}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// The parser's message, with the line and column and the key where known.
        message: String,
    },
    /// A scene value is out of its valid range.
    #[error("{path}: invalid value for `{field}`: {message}")]
    Invalid {
        /// The file (or `<scene>` for a scene built in code).
        path: PathBuf,
        /// Dotted path of the offending key, e.g. `wheel.radius`.
        field: String,
        /// What is wrong and what is expected.
        message: String,
    },
    /// The scene asks for something this version cannot simulate (stated precisely).
    #[error("{path}: unsupported: {message}")]
    Unsupported {
        /// The file.
        path: PathBuf,
        /// What is not supported.
        message: String,
    },
    /// An output file could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// An output (a plot, a table of a report) could not be produced from its inputs.
    #[error("cannot produce {what}: {message}")]
    Output {
        /// What was being produced, e.g. `reports/figures/x.svg`.
        what: String,
        /// Why.
        message: String,
    },
    /// The BEM system is singular or not finite (a degenerate mesh or support).
    #[error("numerical failure in {stage}: {message}")]
    Numerical {
        /// Pipeline stage, e.g. `condensation`.
        stage: &'static str,
        /// Diagnosis.
        message: String,
    },
    /// The caller cancelled the work ([`crate::cancel::Cancel`]): Ctrl-C in the CLI, `KeyboardInterrupt` in Python.
    /// Nothing was produced.
    #[error("interrupted: the run was cancelled before it finished; nothing was produced")]
    Cancelled,
}

impl Error {
    /// Process exit code for this error: 2 for bad input (the user's to fix), 3 for an output that could not be
    /// written or produced, 4 for numerical failure of the BEM system, 130 for a run cancelled by the user (Ctrl-C:
    /// the shell's 128 + SIGINT).
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Io { .. } | Error::Parse { .. } | Error::Invalid { .. } | Error::Unsupported { .. } => 2,
            Error::Write { .. } | Error::Output { .. } => 3,
            Error::Numerical { .. } => 4,
            Error::Cancelled => 130,
        }
    }
}

/// Result alias.
pub type Result<T> = std::result::Result<T, Error>;

/// A value a caller passed to a library function outside that function's domain (a negative modulus, vectors of
/// different lengths, an empty mesh): the function refuses it with this error, naming the function, the argument and
/// what it must be, instead of panicking. Scenes never produce one: they are validated when read, with errors naming
/// their keys ([`Error::Invalid`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{function}: `{argument}` {message}")]
#[non_exhaustive]
pub struct ArgumentError {
    /// The function (or constructor) that refused it, e.g. `HalfPlane::new`.
    pub function: &'static str,
    /// The argument, e.g. `nu`.
    pub argument: &'static str,
    /// What is wrong and what is expected, with the value given.
    pub message: String,
}

impl ArgumentError {
    /// The error of `function` refusing `argument`: `message` says what it must be and what it was.
    pub fn new(function: &'static str, argument: &'static str, message: impl Into<String>) -> ArgumentError {
        ArgumentError { function, argument, message: message.into() }
    }
}

/// An argument error met while running a scene (a library function refusing a value derived from it) is bad input:
/// [`Error::Invalid`], with the function and the argument as its field.
impl From<ArgumentError> for Error {
    fn from(e: ArgumentError) -> Error {
        Error::Invalid {
            path: PathBuf::from("<argument>"),
            field: format!("{}({})", e.function, e.argument),
            message: e.message,
        }
    }
}
