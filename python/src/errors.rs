//! rollbem's errors as Python exceptions (the classes live in `rollbem/errors.py`, where they can inherit from two
//! built-in exceptions: `InputError` is a `ValueError`, `NumericalError` an `ArithmeticError`, `OutputError` an
//! `OSError`).
//!
//! | [`rollbem::Error`] | exception | the CLI's exit code |
//! |---|---|---|
//! | `Io` from the system (a file not there, not readable, a directory) | Python's own `OSError` of that `errno`: `FileNotFoundError`, `PermissionError`, `IsADirectoryError`, ... (`filename`: the file) | 2 |
//! | `Io` without an `errno` (a file that is not UTF-8 text), `Parse`, `Invalid`, `Unsupported` | `InputError` (`key`: the dotted key where known) | 2 |
//! | `Write`, `Output` | `OutputError` | 3 |
//! | `Numerical` | `NumericalError` (`stage`) | 4 |
//! | a run not solved, when the caller asks ([`solve_error`]) | `SolveError` | 5 |
//! | a panic inside rollbem (a bug) | `InternalError` | — |

use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::Error;

/// Why a call failed, in a form that can cross threads (the worker of [`crate::worker`] returns it).
#[derive(Debug)]
pub enum Failure {
    /// An error of the library.
    Rollbem(Error),
    /// An error of the library whose key is known to the binding (a parse error located by `serde_path_to_error`).
    Keyed {
        /// The error.
        error: Error,
        /// The dotted key, e.g. `wheel.radus`.
        key: String,
    },
    /// A panic inside rollbem, with its message.
    Panic(String),
}

impl From<Error> for Failure {
    fn from(e: Error) -> Failure {
        Failure::Rollbem(e)
    }
}

/// An exception of `rollbem.errors` by class name, made with keyword arguments.
fn raise(py: Python<'_>, class: &str, message: String, kwargs: &[(&str, Option<String>)]) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let cls = py.import("rollbem.errors")?.getattr(class)?;
        let kw = PyDict::new(py);
        for (k, v) in kwargs {
            kw.set_item(k, v)?;
        }
        Ok(PyErr::from_value(cls.call((message,), Some(&kw))?))
    })();
    made.unwrap_or_else(|e| e)
}

/// The key a `Parse` or `Unsupported` message of the library starts with (`solvers.use: ...`, `steps[].tangential_load: ...`), if any.
fn leading_key(message: &str) -> Option<String> {
    let (head, _) = message.split_once(": ")?;
    let ok = !head.is_empty() && head.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '[' | ']'));
    ok.then(|| head.to_string())
}

/// Python's `OSError(errno, strerror, filename)`, which Python makes the subclass of that `errno`
/// (`FileNotFoundError` for `ENOENT`, `PermissionError` for `EACCES`, ...), as `open()` raises it.
fn os_error(py: Python<'_>, errno: i32, file: &std::path::Path) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let strerror = py.import("os")?.call_method1("strerror", (errno,))?;
        let cls = py.import("builtins")?.getattr("OSError")?;
        Ok(PyErr::from_value(cls.call1((errno, strerror, file.display().to_string()))?))
    })();
    made.unwrap_or_else(|e| e)
}

/// The Python exception of a failure (see the module docs).
pub fn to_py(py: Python<'_>, failure: Failure) -> PyErr {
    let (error, known_key) = match failure {
        Failure::Panic(message) => {
            return raise(py, "InternalError", format!("internal error in rollbem (please report it): {message}"), &[])
        }
        Failure::Keyed { error, key } => (error, Some(key)),
        Failure::Rollbem(error) => (error, None),
    };
    let message = error.to_string();
    let path = |p: &std::path::Path| Some(p.display().to_string());
    match &error {
        Error::Io { path: p, source } => match source.raw_os_error() {
            Some(errno) => os_error(py, errno, p),
            None => raise(py, "InputError", message, &[("key", known_key), ("path", path(p))]),
        },
        Error::Parse { path: p, message: m } => {
            let key = known_key.or_else(|| leading_key(m));
            raise(py, "InputError", message, &[("key", key), ("path", path(p))])
        }
        Error::Invalid { path: p, field, .. } => {
            raise(py, "InputError", message, &[("key", Some(field.clone())), ("path", path(p))])
        }
        Error::Unsupported { path: p, message: m } => {
            let key = known_key.or_else(|| leading_key(m));
            raise(py, "InputError", message, &[("key", key), ("path", path(p))])
        }
        Error::Write { path: p, .. } => raise(py, "OutputError", message, &[("path", path(p))]),
        Error::Output { .. } => raise(py, "OutputError", message, &[]),
        Error::Numerical { stage, .. } => raise(py, "NumericalError", message, &[("stage", Some(stage.to_string()))]),
        // Only a Ctrl-C cancels a job, and the caller has then raised KeyboardInterrupt already; should a cancelled
        // job's error reach Python anyway, it is that.
        Error::Cancelled => pyo3::exceptions::PyKeyboardInterrupt::new_err(message),
        // `rollbem::Error` is `#[non_exhaustive]`: a kind added after this binding was written has no class here yet.
        _ => raise(
            py,
            "InternalError",
            format!("{message} (an error kind this binding does not know: please report it)"),
            &[],
        ),
    }
}

/// The `SolveError` of a report whose runs did not all end with the status the scene expects (`solved` unless its
/// `[checks] status` says otherwise: the CLI's exit code 5), or `None`.
pub fn solve_error(py: Python<'_>, report: &Bound<'_, PyAny>, inner: &rollbem::results::Report) -> Option<PyErr> {
    let expect = inner.scene.expect();
    let run = inner.runs.iter().find(|r| r.status != expect.status_for(r.solver))?;
    let message = format!(
        "{}: {} ended {} (expected {}): {}",
        inner.scene.name(),
        run.solver,
        run.status,
        expect.status_for(run.solver),
        run.explanation()
    );
    let made = (|| -> PyResult<PyErr> {
        let cls = py.import("rollbem.errors")?.getattr("SolveError")?;
        let kw = PyDict::new(py);
        kw.set_item("status", run.status.name())?;
        kw.set_item("solver", run.solver.name())?;
        kw.set_item("explanation", run.explanation())?;
        kw.set_item("report", report)?;
        Ok(PyErr::from_value(cls.call((message,), Some(&kw))?))
    })();
    Some(made.unwrap_or_else(|e| e))
}

/// A key error of the binding's own (a value Python cannot express in a scene document, such as NaN or an object
/// of no JSON type): an `InputError` naming the key.
pub fn keyed(origin: &std::path::Path, key: &str, message: String) -> Failure {
    Failure::Rollbem(Error::Invalid { path: origin.to_path_buf(), field: key.to_string(), message })
}
