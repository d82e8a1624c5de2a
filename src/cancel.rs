//! Cancellation: a flag that a caller raises (Ctrl-C in the CLI, `KeyboardInterrupt` in Python) and that the work
//! it started checks at its natural steps — a load path before each substep, a sweep and a list of drives before
//! each case, every solver at each of its iterations (a pivot, an active-set iteration, a Gauss–Seidel sweep or
//! NORM-TANG outer iteration, clarabel's interior-point step). Not checked: a model's build (the BEM assembly and
//! condensation), the frictional LCP's formulation, and NORM-TANG's inner QPs (its outer loop checks). A
//! cancelled solve returns promptly with what it has (never a panic), and the pipeline then returns
//! [`crate::Error::Cancelled`] instead of a result: a cancelled run has no answer to report.
//!
//! Checking costs one relaxed atomic load; a token that can never be raised ([`Cancel::never`], the default) costs
//! nothing more.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// A cancellation token: clones share one flag. [`Cancel::never`] (the default) is never raised.
#[derive(Debug, Clone, Default)]
pub struct Cancel(Option<Arc<AtomicBool>>);

impl Cancel {
    /// A token that can be raised ([`Cancel::cancel`]), by this value or any clone of it.
    pub fn new() -> Cancel {
        Cancel(Some(Arc::new(AtomicBool::new(false))))
    }

    /// A token that is never raised.
    pub fn never() -> Cancel {
        Cancel(None)
    }

    /// Raise the flag: the work that holds a clone stops at its next check.
    pub fn cancel(&self) {
        if let Some(flag) = &self.0 {
            flag.store(true, Ordering::Relaxed);
        }
    }

    /// Whether the flag is raised.
    pub fn is_cancelled(&self) -> bool {
        self.0.as_ref().is_some_and(|flag| flag.load(Ordering::Relaxed))
    }

    /// `Err(Error::Cancelled)` when the flag is raised (for `?` at a natural step of the pipeline).
    ///
    /// # Errors
    /// [`crate::Error::Cancelled`] when the flag is raised.
    pub fn check(&self) -> crate::Result<()> {
        if self.is_cancelled() {
            Err(crate::Error::Cancelled)
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Cancel;

    #[test]
    fn clones_share_one_flag_and_never_stays_down() {
        let a = Cancel::new();
        let b = a.clone();
        assert!(!b.is_cancelled() && a.check().is_ok());
        a.cancel();
        assert!(b.is_cancelled() && b.check().is_err());
        let never = Cancel::never();
        never.cancel();
        assert!(!never.is_cancelled());
    }
}
