//! Long work off the interpreter: a build, a solve, a list of solves, a sweep.
//!
//! [`run`] hands the job to a worker thread and waits for it with the GIL released (`Python::detach`), waking every
//! [`POLL`] to run Python's signal handlers (`check_signals`). On Ctrl-C the wait ends at once with
//! `KeyboardInterrupt`, and the job's cancellation token ([`rollbem::cancel::Cancel`]) is raised: a list of drives
//! or a sweep stops before its next drive or case, a load path before its next substep, and every solver at its
//! next iteration (a pivot, an active-set iteration, a Gauss–Seidel sweep, an interior-point step), so the worker is
//! idle again within an iteration and its partial work is dropped. Not interrupted: a model's build, and a call into
//! a solver written in Python ([`crate::plugin`]). A panic inside the job is caught on its thread and becomes
//! `InternalError`: no panic crosses into Python.
//!
//! The workers are kept between calls ([`Pool`]): a thread per call made a 50-point creep curve solved point by point
//! 1.5× slower in CPU time than the same solves on one thread (each new thread's allocations started on cold
//! memory), so a job goes to an idle worker, and a new worker starts only when every worker is busy (as many as the
//! caller's threads solve at once, plus the ones still finishing an interrupted solve).

use crate::errors::{to_py, Failure};
use pyo3::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Duration;

/// How often the waiting thread runs Python's signal handlers.
pub const POLL: Duration = Duration::from_millis(20);

/// The stack of a worker thread (the main thread's usual size: the library is written for it).
const STACK: usize = 8 << 20;

pub use rollbem::cancel::Cancel;

/// A job for a worker.
type Task = Box<dyn FnOnce() + Send>;

/// The workers: a queue of tasks and the number of workers waiting for one.
struct Pool {
    /// Where tasks are sent.
    queue: Mutex<mpsc::Sender<Task>>,
    /// Where workers take them from (one at a time).
    tasks: Arc<Mutex<mpsc::Receiver<Task>>>,
    /// Workers waiting for a task and not yet promised to one.
    idle: Arc<AtomicUsize>,
}

static POOL: OnceLock<Pool> = OnceLock::new();

impl Pool {
    fn get() -> &'static Pool {
        POOL.get_or_init(|| {
            let (tx, rx) = mpsc::channel();
            Pool { queue: Mutex::new(tx), tasks: Arc::new(Mutex::new(rx)), idle: Arc::new(AtomicUsize::new(0)) }
        })
    }

    /// Run `task` on a worker: an idle one if there is one (promised to this task), else a new one.
    fn submit(&self, task: Task) -> std::io::Result<()> {
        let promised = self.idle.fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| n.checked_sub(1)).is_ok();
        if !promised {
            let (tasks, idle) = (self.tasks.clone(), self.idle.clone());
            std::thread::Builder::new().name("rollbem".into()).stack_size(STACK).spawn(move || loop {
                // A poisoned lock only means another worker panicked while holding it; the receiver is intact.
                let next = tasks.lock().unwrap_or_else(|e| e.into_inner()).recv();
                let Ok(task) = next else { return };
                task();
                idle.fetch_add(1, Ordering::AcqRel);
            })?;
        }
        // The receiver lives in the pool for the process's life, so the send cannot fail.
        let _ = self.queue.lock().unwrap_or_else(|e| e.into_inner()).send(task);
        Ok(())
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
    let cancel = Cancel::new();
    let (tx, rx) = mpsc::channel();
    let flag = cancel.clone();
    let spawned = Pool::get().submit(Box::new(move || {
        let out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(&flag)));
        // The caller may have gone (interrupted): the result is then dropped.
        let _ = tx.send(out.unwrap_or_else(|p| Err(Failure::Panic(panic_message(p)))));
    }));
    if let Err(e) = spawned {
        return Err(pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start a worker thread: {e}")));
    }
    let waited: Result<Result<T, Failure>, PyErr> = py.detach(move || loop {
        match rx.recv_timeout(POLL) {
            Ok(out) => return Ok(out),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    cancel.cancel();
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
