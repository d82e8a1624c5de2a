//! Text renderings of a half-space result document ([`SpaceReport`]): the `rollbem run` table, the `rollbem check`
//! summary, and the CSV exports (`--csv`: one row per element and step; `--path-csv`: one row per step).

use super::render::check_line;
use super::space::{SpaceReport, ELEMENT_STATES};
use super::CheckKind;
use std::fmt::Write as _;

/// `writeln!` into a `String` (which cannot fail).
macro_rules! w {
    ($out:expr, $($t:tt)*) => {{
        let _ = writeln!($out, $($t)*);
    }};
}

/// The `run` table: the scene, the grid and the kernels built, Hertz's ellipse, one row per (sub)step (status, load,
/// approach, force, shift, contact/stick/slip counts, residuals, iterations), the times and the checks.
pub fn run_table(r: &SpaceReport) -> String {
    let mut out = String::new();
    let g = &r.grid;
    w!(out, "scene {} — {}", r.scene.name, r.scene.description);
    w!(
        out,
        "grid: {} × {} = {} elements of {:.4e} × {:.4e} (half-space pair); kernels: normal{}{}; effects: {}",
        g.mx,
        g.my,
        g.len(),
        g.dx,
        g.dy,
        if r.kernels.tangential { ", tangential" } else { "" },
        if r.kernels.coupling { ", coupling" } else { "" },
        r.effects.join(", ")
    );
    for n in r.effect_notes.iter().filter(|n| n.asked && !n.simulated) {
        w!(out, "effects: {} not simulated: {}", n.effect, n.why);
    }
    w!(out, "E* = {:.6e}, Dundurs' beta = {:.4}", r.references.contact_modulus, r.references.dundurs_beta);
    if let Some(h) = r.references.hertz {
        w!(
            out,
            "Hertz at P = {:.6e}: a_x = {:.6e}, a_y = {:.6e}, p0 = {:.6e}, approach = {:.6e}",
            h.load,
            h.a_x,
            h.a_y,
            h.p0,
            h.approach
        );
    }
    w!(
        out,
        "{:<6} {:<21} {:>12} {:>12} {:>12} {:>12} {:>13} {:>7} {:>6} {:>6} {:>9} {:>9} {:>11}",
        "step",
        "status",
        "P",
        "approach",
        "Fx",
        "Fy",
        "shift |w|",
        "contact",
        "stick",
        "slip",
        "res N",
        "res T",
        "its N/T/out"
    );
    for s in &r.steps {
        let shift = s.shift.map_or("-".to_string(), |w| format!("{:.5e}", w[0].hypot(w[1])));
        w!(
            out,
            "{:<6} {:<21} {:>12.5e} {:>12.5e} {:>12.5e} {:>12.5e} {:>13} {:>7} {:>6} {:>6} {:>9.2e} {:>9.2e} {:>11}",
            format!("{}.{}", s.step, s.substep),
            s.status.name(),
            s.load,
            s.approach,
            s.force[0],
            s.force[1],
            shift,
            s.contact,
            s.stick,
            s.slip,
            s.residual_normal,
            s.residual_tangential,
            format!("{}/{}/{}", s.iterations_normal, s.iterations_tangential, s.outer_iterations)
        );
    }
    w!(
        out,
        "time: build {:.4} s, solve {:.4} s, total {:.4} s ({} steps)",
        r.timing_s.build,
        r.timing_s.solve,
        r.timing_s.total,
        r.steps.len()
    );
    for line in &r.warnings {
        w!(out, "warning: {line}");
    }
    w!(out, "checks:");
    for c in &r.checks {
        w!(out, "  {}", check_line(c));
    }
    out
}

/// (failed, not applicable) checks.
pub fn check_counts(r: &SpaceReport) -> (usize, usize) {
    let bad = r.checks.iter().filter(|c| !c.pass).count();
    let skipped = r.checks.iter().filter(|c| c.kind == CheckKind::NotApplicable).count();
    (bad, skipped)
}

/// What `rollbem check` prints for a half-space scene: PASS or FAIL with the counts and the last step's status,
/// then each failed check.
pub fn check_summary(r: &SpaceReport) -> String {
    let mut out = String::new();
    let (bad, skipped) = check_counts(r);
    let last = r.steps.last().map_or("no steps".to_string(), |s| format!("last step {}", s.status));
    w!(
        out,
        "{} {} ({} checks, {} failed, {} not applicable; half_space: {} steps, {last})",
        if bad == 0 { "PASS" } else { "FAIL" },
        r.scene.name,
        r.checks.len(),
        bad,
        skipped,
        r.steps.len()
    );
    for c in r.checks.iter().filter(|c| !c.pass) {
        let note = c.note.as_ref().map(|n| format!(": {n}")).unwrap_or_default();
        match c.kind {
            CheckKind::Figure => w!(
                out,
                "    FAIL {}: measured {:.6e}, reference {:.6e}, error {:.3e} > tolerance {:.1e}{note}",
                c.name,
                c.measured,
                c.reference,
                c.error,
                c.tolerance
            ),
            _ => w!(out, "    FAIL {}{note}", c.name),
        }
    }
    out.trim_end().to_string()
}

impl SpaceReport {
    /// The element table (`run --csv`): one row per element and (sub)step: `step, substep, ix, iy, x, y, pn, px,
    /// py, state, gap` (tractions on body 1; state `exterior`, `stick` or `slip`).
    pub fn elements_csv(&self) -> String {
        let mut out = String::from("step,substep,ix,iy,x,y,pn,px,py,state,gap\n");
        let g = &self.grid;
        for s in &self.steps {
            let e = &s.elements;
            for iy in 0..g.my {
                for ix in 0..g.mx {
                    let i = ix + g.mx * iy;
                    let (x, y) = g.centre(ix, iy);
                    let state = ELEMENT_STATES.get(e.state[i] as usize).copied().unwrap_or("?");
                    w!(
                        out,
                        "{},{},{ix},{iy},{x:e},{y:e},{:e},{:e},{:e},{state},{:e}",
                        s.step,
                        s.substep,
                        e.pressure[i],
                        e.qx[i],
                        e.qy[i],
                        e.gap[i]
                    );
                }
            }
        }
        out
    }

    /// The path table (`run --path-csv`): one row per (sub)step with its status, resultants, shift, counts,
    /// residuals and iterations.
    pub fn steps_csv(&self) -> String {
        let mut out = String::from(
            "step,substep,status,load,approach,force_x,force_y,shift_x,shift_y,contact,stick,slip,residual_normal,\
             residual_tangential,outer_iterations,iterations_normal,iterations_tangential\n",
        );
        for s in &self.steps {
            let [wx, wy] =
                s.shift.map_or([String::new(), String::new()], |w| [format!("{:e}", w[0]), format!("{:e}", w[1])]);
            w!(
                out,
                "{},{},{},{:e},{:e},{:e},{:e},{wx},{wy},{},{},{},{:e},{:e},{},{},{}",
                s.step,
                s.substep,
                s.status,
                s.load,
                s.approach,
                s.force[0],
                s.force[1],
                s.contact,
                s.stick,
                s.slip,
                s.residual_normal,
                s.residual_tangential,
                s.outer_iterations,
                s.iterations_normal,
                s.iterations_tangential
            );
        }
        out
    }
}
