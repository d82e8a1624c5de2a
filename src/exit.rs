//! The command line's exit codes, one table for every command, so that scripts can act on them:
//!
//! | code | meaning |
//! |---|---|
//! | 0 | every requested solver solved (or ended with the status the scene declares, `[checks] status`), and for `check` every check passed |
//! | 1 | a check failed (`check`; `run` only for a scene that declares `[checks]`) |
//! | 2 | bad input: a file that cannot be read, a malformed or invalid scene, sweep spec or LCP file, a bad option |
//! | 3 | an output file could not be written or produced |
//! | 4 | numerical failure of the BEM system (a singular or non-finite system) |
//! | 5 | a requested solver did not solve (infeasible, ray termination, not converged, numerical error, an answer cut off by the candidate zone or outside the linearised kinematics), where the scene does not declare that status |
//!
//! When several scenes give several codes, the command exits with the largest.

use crate::results::Report;

/// Success.
pub const SUCCESS: u8 = 0;
/// A check failed.
pub const CHECK_FAILED: u8 = 1;
/// Bad input.
pub const BAD_INPUT: u8 = 2;
/// An output could not be written.
pub const OUTPUT: u8 = 3;
/// Numerical failure of the BEM system.
pub const NUMERICAL: u8 = 4;
/// A requested solver did not solve.
pub const NOT_SOLVED: u8 = 5;

/// Whether a run ended with a status other than the one its scene expects of it (`solved` unless declared).
pub fn unexpected_status(report: &Report) -> bool {
    report.runs.iter().any(|r| r.status != report.scene.expect().status_for(r.solver))
}

/// The exit code of a report: [`NOT_SOLVED`] when a run's status is not the expected one, else [`CHECK_FAILED`] when
/// a check fails and `checks_count` (for `check` always; for `run` when the scene declares `[checks]`), else
/// [`SUCCESS`].
pub fn of_report(report: &Report, checks_count: bool) -> u8 {
    if unexpected_status(report) {
        NOT_SOLVED
    } else if checks_count && !report.all_pass() {
        CHECK_FAILED
    } else {
        SUCCESS
    }
}

/// Whether a report's scene declares expectations of its own (a `[checks]` table).
pub fn declares_checks(report: &Report) -> bool {
    report.scene.declares_checks()
}
