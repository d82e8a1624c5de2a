//! Progress of long work on stderr (never stdout, which tests and scripts compare): a spinner with the stage and
//! its elapsed time for the BEM assembly, the condensation and each solve, and the sweeps' bar of cases.
//!
//! Off by default (a library caller sees nothing); the command line turns it on when stderr is a terminal and
//! `--quiet` is not given ([`enable`]). Stage spinners are suppressed while a sweep runs its cases in parallel (its
//! own bar shows the progress; [`suppress`]).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

static ENABLED: AtomicBool = AtomicBool::new(false);
static SUPPRESSED: AtomicUsize = AtomicUsize::new(0);

/// Turn progress on (when stderr is a terminal) or off.
pub fn enable(on: bool) {
    ENABLED.store(on && std::io::stderr().is_terminal(), Ordering::Relaxed);
}

/// Whether progress is shown.
pub fn enabled() -> bool {
    ENABLED.load(Ordering::Relaxed)
}

/// A stage of work shown as a spinner with its elapsed time until it is dropped (then cleared).
pub struct Stage(Option<ProgressBar>);

impl Drop for Stage {
    fn drop(&mut self) {
        if let Some(bar) = self.0.take() {
            bar.finish_and_clear();
        }
    }
}

/// Show `what` as a stage spinner (nothing when progress is off or a sweep is running).
pub fn stage(what: impl FnOnce() -> String) -> Stage {
    if !enabled() || SUPPRESSED.load(Ordering::Relaxed) > 0 {
        return Stage(None);
    }
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(ProgressStyle::with_template("{spinner} {msg} [{elapsed}]").expect("valid template"));
    bar.set_message(what());
    bar.enable_steady_tick(Duration::from_millis(200));
    Stage(Some(bar))
}

/// While the returned guard lives, stage spinners are not shown (a sweep's parallel cases would draw over each
/// other and over the sweep's bar).
pub fn suppress() -> Suppressed {
    SUPPRESSED.fetch_add(1, Ordering::Relaxed);
    Suppressed(())
}

/// Guard of [`suppress`].
pub struct Suppressed(());

impl Drop for Suppressed {
    fn drop(&mut self) {
        SUPPRESSED.fetch_sub(1, Ordering::Relaxed);
    }
}
