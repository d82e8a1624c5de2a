//! Long work off the interpreter: a build, a solve, a list of solves, a sweep.
//!
//! [`run`] hands the job to a new thread and waits for it with the GIL released (`Python::detach`), waking every
//! [`POLL`] to run Python's signal handlers (`check_signals`). On Ctrl-C the wait ends at once with
//! `KeyboardInterrupt`, and the job's [`Cancel`] flag is raised: a job that solves a list of drives stops before its
//! next drive; a single solve the library cannot stop in the middle runs on to its end in the background, its result
//! dropped (the library has no cancellation point inside a solve). A panic inside the job is caught on its thread
//! and becomes `InternalError`: no panic crosses into Python.

use crate::errors::{to_py, Failure};
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::Duration;

/// How often the waiting thread runs Python's signal handlers.
pub const POLL: Duration = Duration::from_millis(20);

/// The stack of a worker thread (the main thread's usual size: the library is written for it).
const STACK: usize = 8 << 20;

/// Raised when the caller was interrupted: a job checks it between units of work and stops.
#[derive(Clone, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// Whether the caller was interrupted.
    pub fn raised(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    fn raise(&self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

/// The message of a caught panic.
fn panic_message(payload: Box<dyn std::any::Any + Send>) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".into())
}

/// Run `job` on a worker thread, the GIL released, interruptible by Ctrl-C (module docs).
pub fn run<T, F>(py: Python<'_>, job: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Cancel) -> Result<T, Failure> + Send + 'static,
{
    let cancel = Cancel::default();
    let (tx, rx) = mpsc::channel();
    let flag = cancel.clone();
    let spawned = std::thread::Builder::new().name("rollbem".into()).stack_size(STACK).spawn(move || {
        let out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(&flag)));
        // The caller may have gone (interrupted): the result is then dropped.
        let _ = tx.send(out.unwrap_or_else(|p| Err(Failure::Panic(panic_message(p)))));
    });
    if let Err(e) = spawned {
        return Err(pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start a worker thread: {e}")));
    }
    let waited: Result<Result<T, Failure>, PyErr> = py.detach(move || loop {
        match rx.recv_timeout(POLL) {
            Ok(out) => return Ok(out),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    cancel.raise();
                    return Err(e);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Ok(Err(Failure::Panic("the worker thread ended without a result".into())))
            }
        }
    });
    waited?.map_err(|f| to_py(py, f))
}
