//! The 3D (half-space) side of a sweep: a case's rows from its result document ([`SpaceReport`]), its rows when it
//! could not run, and the rough cost of a case for the plan's estimate. The machinery around them — the grid, the
//! plan, the journal, resume, shards and merge — is the 2D sweep's ([`super::run`]'s case runner dispatches on the
//! kind of the case's scene).
//!
//! **One row per case** (solver `half_space`, the one 3D solver). Its figures are those of the path's last
//! (sub)step; its status the first (sub)step's that is not `solved` (its message then says which step), else
//! `solved`. The errors against theory are the run's own checks' (`pipeline::space_checks`), written
//! where they apply and the last step solved:
//! - **Hertz** (a quadratic profile, the normal problem not coupled): the least-squares ellipse fit's semi-axes and
//!   peak pressure against [`crate::theory::Hertz3D`] at the step's load, and the approach, each `|x − x_H|/x_H`.
//!   Written at every resolution (a sweep is a convergence study; the check itself applies only from
//!   [`crate::tolerances::HERTZ_MIN_ELEMENTS`] elements across the minor axis, written in `elements_across`).
//! - **Cattaneo–Mindlin** (a circle, friction, a first step that presses, the last step at the same load driven
//!   along one direction): the stick radius's error in elements (`cm_c_err_elements`), c/a measured and exact, and
//!   the error of the shift for the force or of the force for the shift (`cm_transfer_err`), as the run's checks
//!   compute them (exact theory for ν = 0 only; with ν > 0 a model comparison).

use super::row::{RowStatus, SweepRow};
use super::Case;
use crate::error::Error;
use crate::results::space::{SpaceReport, SpaceStepResult};
use crate::results::{Setup, Timing};
use crate::scene::{AnyScene, SpaceScene, SpaceStatus};

/// The solver column of a 3D row.
pub const SOLVER: &str = "half_space";

/// A 3D row of a case with its head cells (case, kind, parameters, scene name, grid) and a status.
fn head(case: &Case<AnyScene>, scene: &SpaceScene, status: RowStatus) -> SweepRow {
    let mut row = SweepRow::new(case.index, SOLVER, status);
    row.kind = super::Kind::Space;
    row.params = case.params.clone();
    row.scene = scene.name().to_string();
    let g = scene.grid();
    row.space.mx = Some(g.mx());
    row.space.my = Some(g.my());
    row.space.dx = Some(g.dx());
    row.space.dy = Some(g.dy());
    row.space.curvature_a = scene.curvatures().map(|c| c.0);
    row.space.curvature_b = scene.curvatures().map(|c| c.1);
    row.contact_modulus = Some(scene.contact_modulus());
    row.friction = Some(scene.friction());
    row
}

/// The rows of a case that could not be built or run: one, status `error`, the reason in `message`.
pub(super) fn error_rows(case: &Case<AnyScene>, scene: &SpaceScene, err: &Error) -> Vec<SweepRow> {
    let mut row = head(case, scene, RowStatus::Error);
    row.message = err.to_string().replace(['\n', '\r'], " ");
    vec![row]
}

/// The row of a solved case (module docs).
pub(super) fn case_rows(case: &Case<AnyScene>, scene: &SpaceScene, report: &SpaceReport) -> Vec<SweepRow> {
    let failed = report.steps.iter().find(|s| s.status != SpaceStatus::Solved);
    let status = failed.map_or(SpaceStatus::Solved, |s| s.status);
    let mut row = head(case, scene, RowStatus::Space(status));
    let Some(last) = report.steps.last() else {
        row.message = "no step".into();
        return vec![row];
    };
    let f = &mut row.space;
    f.steps = Some(report.steps.len());
    f.iterations_normal = Some(report.steps.iter().map(|s| s.iterations_normal).sum());
    f.iterations_tangential = Some(report.steps.iter().map(|s| s.iterations_tangential).sum());
    f.outer_iterations = Some(report.steps.iter().map(|s| s.outer_iterations).sum());
    f.force_x = Some(last.force[0]);
    f.force_y = Some(last.force[1]);
    f.contact_count = Some(last.contact);
    f.stick_count = Some(last.stick);
    f.slip_count = Some(last.slip);
    f.peak_pressure = Some(last.elements.pressure.iter().fold(0.0_f64, |m, &p| m.max(p)));
    f.shift_x = last.shift.map(|s| s[0]);
    f.shift_y = last.shift.map(|s| s[1]);
    let residual = report.steps.iter().map(|s| s.residual_normal.max(s.residual_tangential)).fold(0.0, f64::max);
    row.residual = Some(residual);
    row.normal_load = Some(last.load);
    row.approach = Some(last.approach);
    if let Some((ax, ay, p0)) = crate::pipeline::fit_ellipse(&report.grid, &last.elements.pressure) {
        row.space.a_x_fit = Some(ax);
        row.space.a_y_fit = Some(ay);
        row.peak_pressure_fit = Some(p0);
    }
    hertz(&mut row, scene, report, last);
    cattaneo(&mut row, report, last);
    let t = &report.timing_s;
    let timing = Timing { assembly: t.build, solve: t.solve, total: t.total, setup: Setup::Built, ..Timing::default() };
    super::row::set_timing(&mut row, &timing, None);
    let message = match failed {
        Some(s) => format!("step {}.{}: {}", s.step, s.substep, s.message),
        None => last.message.clone(),
    };
    // One line per row (the journal's rule).
    row.message = message.replace(['\n', '\r'], " ");
    vec![row]
}

/// Hertz's ellipse at the last step's load and, where it applies, the errors of the fit and the approach.
fn hertz(row: &mut SweepRow, scene: &SpaceScene, report: &SpaceReport, last: &SpaceStepResult) {
    let Some((a, b)) = scene.curvatures() else { return };
    let Some(h) = crate::theory::Hertz3D::from_load(a, b, scene.contact_modulus(), last.load) else { return };
    row.space.hertz_a_x = Some(h.a_x);
    row.space.hertz_a_y = Some(h.a_y);
    row.hertz_p0 = Some(h.p0);
    row.space.hertz_approach = Some(h.approach);
    row.space.elements_across = Some(2.0 * (h.a_x / report.grid.dx).min(h.a_y / report.grid.dy));
    // The run's checks' domain: a coupled normal problem with friction is Spence's, not Hertz's.
    let applies = last.status == SpaceStatus::Solved && !(report.kernels.coupled && scene.friction() > 0.0);
    if !applies {
        return;
    }
    let err = |x: f64, reference: f64| (x - reference).abs() / reference;
    row.space.hertz_a_x_err = row.space.a_x_fit.map(|x| err(x, h.a_x));
    row.space.hertz_a_y_err = row.space.a_y_fit.map(|x| err(x, h.a_y));
    row.metrics.hertz_p0_err = row.peak_pressure_fit.map(|x| err(x, h.p0));
    row.space.hertz_approach_err = Some(err(last.approach, h.approach));
}

/// Cattaneo–Mindlin at the last step, from the run's checks of that step (module docs): none where they do not
/// apply.
fn cattaneo(row: &mut SweepRow, report: &SpaceReport, last: &SpaceStepResult) {
    let tag = format!("step {}: Cattaneo–Mindlin ", last.step);
    let ends_last = report.step_ends().last().is_some_and(|e| std::ptr::eq(e, last));
    if !ends_last || last.status != SpaceStatus::Solved {
        return;
    }
    let ours = || report.checks.iter().filter(|c| c.name.starts_with(&tag));
    let radius = ours().find(|c| c.name[tag.len()..].starts_with("stick radius"));
    let transfer =
        ours().find(|c| c.name[tag.len()..].starts_with("shift") || c.name[tag.len()..].starts_with("force"));
    // Hertz's radius at the step's load (a circle: a_x = a_y).
    let a = row.space.hertz_a_x;
    if let (Some(c), Some(a)) = (radius, a) {
        row.metrics.cm_c_err_elements = Some(c.error);
        row.metrics.cm_c_over_a = Some(c.measured / a);
        row.metrics.cm_c_over_a_exact = Some(c.reference / a);
    }
    row.space.cm_transfer_err = transfer.map(|c| c.error);
}

/// The rough cost of a 3D case for the plan's estimate: (model build s, model bytes, solve s, solve bytes). The
/// kernels are FFTs on the doubled grid, O(N log N) for N = MX·MY elements, one kernel frictionless and six with
/// friction (about 400 bytes per element, [`crate::scene::space::MAX_HALF_SPACE_ELEMENTS`]); every (sub)step solves
/// by FFT-preconditioned iterations of a few FFT products each, and keeps its element arrays
/// ([`crate::scene::space::SPACE_BYTES_PER_ELEMENT`]). The constants were measured on this project's 2-core
/// development machine (module docs of [`super::plan`]).
pub(super) fn costs(scene: &SpaceScene) -> (f64, f64, f64, f64) {
    let n = scene.grid().len() as f64;
    let log = (4.0 * n).log2().max(1.0);
    let friction = scene.friction() > 0.0;
    let kernels = if friction { 6.0 } else { 1.0 };
    let build_s = 2e-8 * kernels * n * log;
    let model_bytes = 64.0 * kernels * n + 1e5;
    let steps = scene.steps().len() as f64;
    // Per step: the normal solve (tens of FFT products) and, with friction, the tangential one (more).
    let per_step = if friction { 3e-6 } else { 5e-7 } * n * log;
    let solve_s = 5e-4 + steps * per_step;
    let solve_bytes = (crate::scene::space::SPACE_BYTES_PER_ELEMENT as f64 * steps + 200.0) * n;
    (build_s, model_bytes, solve_s, solve_bytes)
}
