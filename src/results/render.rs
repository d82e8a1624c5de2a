//! Text renderings of result documents: the table `rollbem run` prints per scene, the check lines of `rollbem
//! check`, a load path's summary and the stresses' maxima. Every function returns text; printing is the caller's.

use super::{Check, CheckKind, ProblemClass, Report};
use crate::status::Status;
use std::fmt::Write as _;

/// `writeln!` into a `String` (which cannot fail).
macro_rules! w {
    ($out:expr, $($t:tt)*) => {{
        let _ = writeln!($out, $($t)*);
    }};
}

/// The memory line is printed from this peak resident size on (bytes): small runs need no memory figure.
pub const MEMORY_LINE_FROM: u64 = 100_000_000;

/// The process's peak resident set size (Linux `VmHWM` in `/proc/self/status`), `None` where it cannot be read.
pub fn peak_resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// The `run` table of one scene: its header (mesh, health, warnings, Hertz), one row per solver run, a load path's
/// summary, the stresses' maxima and the checks. Its two time columns: `solve [s]`, the solver alone (what the
/// solvers are compared by), and `total [s]`, the whole pipeline of that run (assembly, condensation, formulation
/// and solve).
pub fn run_table(r: &Report) -> String {
    let mut out = String::new();
    header(&mut out, r);
    runs_table(&mut out, r);
    if !r.steps.is_empty() {
        path_summary(&mut out, r);
    }
    stresses_table(&mut out, r);
    w!(out, "checks:");
    for c in &r.checks {
        w!(out, "  {}", check_line(c));
    }
    out
}

/// The scene's name, mesh, health, memory, warnings and Hertz's reference.
fn header(out: &mut String, r: &Report) {
    w!(out, "scene {} — {}", r.scene.name(), r.scene.description());
    w!(
        out,
        "mesh: {} {} elements, {} nodes, {} contact nodes{}; effects: {}",
        r.mesh.elements,
        r.mesh.element.name(),
        r.mesh.nodes,
        r.mesh.contact_nodes,
        r.mesh.system_size.map(|n| format!(", BEM system {n}×{n}")).unwrap_or_default(),
        r.effects.join(", ")
    );
    for n in r.effect_notes.iter().filter(|n| n.asked && !n.simulated) {
        w!(out, "effects: {} not simulated: {}", n.effect, n.why);
    }
    let d = &r.diagnostics;
    w!(
        out,
        "health: {}κ₁(K_NN) ≈ {:.2e}{}, flexibility asymmetry {:.2e}",
        d.bem_condition.map(|k| format!("κ₁(BEM system) ≈ {k:.2e}, ")).unwrap_or_default(),
        d.flexibility_condition,
        d.tangential_condition.map(|k| format!(", κ₁(K_TT) ≈ {k:.2e}")).unwrap_or_default(),
        d.flexibility_asymmetry
    );
    if let Some(bytes) = peak_resident_bytes().filter(|b| *b >= MEMORY_LINE_FROM) {
        w!(
            out,
            "memory: peak resident {:.2} GB (this process so far: the BEM system, its LU and the solvers' work)",
            bytes as f64 / 1e9
        );
    }
    for w in d.warnings.iter().chain(&r.warnings) {
        w!(out, "WARNING: {w}");
    }
    if let Some(h) = &r.references.hertz {
        w!(out, "Hertz at P = {:.6e}: a = {:.6e}, p0 = {:.6e}", h.load, h.a, h.p0);
    }
}

/// One row per solver run (with its explanation below when it did not solve, or solved at the sliding limit).
fn runs_table(out: &mut String, r: &Report) {
    let frictional = r.effects.iter().any(|e| e == "friction");
    w!(
        out,
        "{:<11} {:<23} {:>5} {:>9} {:>9} {:>12} {:>12} {:>12} {:>20} {:>12} {:>9} {:>9}",
        "solver",
        "status",
        "size",
        "work",
        "residual",
        "P",
        if frictional { "Q" } else { "a (fit)" },
        if frictional { "peak p" } else { "p0 (fit)" },
        if frictional { "stick zone" } else { "contact" },
        "d_N",
        "solve [s]",
        "total [s]"
    );
    let opt = |v: Option<f64>| v.map(|v| format!("{v:.5e}")).unwrap_or_else(|| "-".into());
    let range = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("[{a:.3e},{b:.3e}]"),
        _ => "none".into(),
    };
    for run in &r.runs {
        let work = run.work.short();
        let (Some(res), Some(f), Some(c), Some(rb)) = (&run.residuals, &run.resultants, &run.contact, &run.rigid_body)
        else {
            w!(
                out,
                "{:<11} {:<23} {:>5} {:>9} {:>9} {:>12} {:>12} {:>12} {:>20} {:>12} {:>9.4} {:>9.4}",
                run.solver,
                run.status.name(),
                run.problem_size,
                work,
                "-",
                "-",
                "-",
                "-",
                "-",
                "-",
                run.timing_s.solve,
                run.timing_s.total
            );
            w!(out, "            {}", run.explanation());
            continue;
        };
        w!(
            out,
            "{:<11} {:<23} {:>5} {:>9} {:>9.2e} {:>12.5e} {:>12} {:>12} {:>20} {:>12.5e} {:>9.4} {:>9.4}",
            run.solver,
            run.status.name(),
            run.problem_size,
            work,
            res.max(),
            f.normal,
            if frictional { format!("{:.5e}", f.tangential) } else { opt(c.fit_half_width) },
            if frictional { format!("{:.5e}", c.peak_pressure) } else { opt(c.fit_peak_pressure) },
            if frictional { range(c.stick_x_min, c.stick_x_max) } else { range(c.x_min, c.x_max) },
            rb.normal,
            run.timing_s.solve,
            run.timing_s.total
        );
        if let Some(xi) = run.rolling.filter(|x| !x.creepage_prescribed).and_then(|x| x.creepage) {
            // Steady rolling with the tangential load prescribed: the creepage is the answer.
            w!(out, "            creepage ξ = {xi:.6e} (computed for the prescribed Q)");
        }
        if run.status != Status::Solved || run.problem == ProblemClass::SlidingLimit {
            w!(out, "            {}", run.explanation());
        }
        if let Some(b) = &run.branches {
            w!(out, "            {}", b.describe());
        }
    }
}

/// The subsurface stresses' maxima per run (largest |value| on the grid, sign kept, and where), with `[stresses]`.
fn stresses_table(out: &mut String, r: &Report) {
    let Some(spec) = &r.scene.stresses() else { return };
    let counter = r.runs.iter().any(|x| x.counter_body_stresses.is_some());
    w!(
        out,
        "stresses in the wheel ({} model){}: {}×{} grid, x in [{:.4e}, {:.4e}], depth in [{:.4e}, {:.4e}] and the \
         surface at the contact elements' centres; maxima (largest |value|):",
        r.scene.model().name(),
        if counter { " and in the counter-body (depth into it)" } else { "" },
        spec.points[0],
        spec.points[1],
        spec.x[0],
        spec.x[1],
        spec.depth[0],
        spec.depth[1]
    );
    w!(out, "{:<11} {:<12} {:<17} {:>13} {:>13} {:>13}", "solver", "body", "quantity", "max", "x", "depth");
    for run in &r.runs {
        let Some(st) = &run.stresses else {
            w!(out, "{:<11} none (not solved)", run.solver);
            continue;
        };
        for st in std::iter::once(st).chain(&run.counter_body_stresses) {
            stress_maxima(out, run.solver.name(), st);
        }
    }
}

/// One body's maxima and what was evaluated.
fn stress_maxima(out: &mut String, solver: &str, st: &crate::stresses::StressResult) {
    for (q, m) in st.maxima() {
        match m {
            Some(m) => w!(
                out,
                "{:<11} {:<12} {:<17} {:>13.5e} {:>13.5e} {:>13.5e}",
                solver,
                st.body,
                q.name(),
                m.value,
                m.x,
                m.depth
            ),
            None => w!(out, "{:<11} {:<12} {:<17} {:>13}", solver, st.body, q.name(), "-"),
        }
    }
    let refused = st.refused();
    let n: usize = refused.values().sum();
    let why: Vec<String> = refused.iter().map(|(k, v)| format!("{v} {k}")).collect();
    w!(
        out,
        "{:<11} {:<12} {} of {} grid points evaluated in {:.3} s{}{}",
        "",
        "",
        st.grid.len() - n,
        st.grid.len(),
        st.time_s,
        if n > 0 { format!("; refused: {}", why.join(", ")) } else { String::new() },
        st.csv.as_ref().map(|f| format!("; field in {f}")).unwrap_or_default()
    );
}

/// One check as a line of the `run` table: a figure with its numbers, a verdict or a reference that does not apply
/// with what was found.
pub fn check_line(c: &Check) -> String {
    let mark = match (c.kind, c.pass) {
        (CheckKind::NotApplicable, _) => "n/a ",
        (CheckKind::ModelComparison, _) => "model",
        (_, true) => "pass",
        (_, false) => "FAIL",
    };
    let note = c.note.as_ref().map(|n| format!(": {n}")).unwrap_or_default();
    match c.kind {
        CheckKind::Figure => format!(
            "[{mark}] {:<48} measured {:>12.6e}  reference {:>12.6e}  error {:>9.2e}  tol {:>8.1e}{note}",
            c.name, c.measured, c.reference, c.error, c.tolerance
        ),
        CheckKind::Verdict | CheckKind::NotApplicable => format!("[{mark}] {}{note}", c.name),
        CheckKind::ModelComparison => format!(
            "[{mark}] {:<47} measured {:>12.6e}  theory {:>12.6e}  difference {:>10.3e}  model error {:>10.3e} ± {:.1e}{note}",
            c.name,
            c.measured,
            c.reference,
            c.measured - c.reference,
            c.model_error.unwrap_or(f64::NAN),
            c.uncertainty.unwrap_or(f64::NAN)
        ),
    }
}

/// A load path's summary: per solver, how far it got, the dissipated energy and its hardest substep.
fn path_summary(out: &mut String, r: &Report) {
    let total = r.steps.len();
    w!(
        out,
        "load path: {} steps, {total} substeps (the table above is the path's end; `--path-csv` writes every substep)",
        r.scene.document().steps.len()
    );
    let names: Vec<&str> = r.runs.iter().map(|x| x.solver.name()).collect();
    for name in names {
        let runs: Vec<&crate::results::SolverRun> =
            r.steps.iter().filter_map(|st| st.runs.iter().find(|x| x.solver == name)).collect();
        let solved = runs.iter().filter(|x| x.status == crate::solvers::Status::Solved).count();
        let dissipated = runs.last().and_then(|x| x.history.as_ref()).map_or(0.0, |h| h.dissipated_total);
        let worst = runs.iter().filter_map(|x| x.residuals.map(|res| res.max())).fold(0.0f64, f64::max);
        let time: f64 = runs.iter().map(|x| x.timing_s.total).sum();
        w!(
        out,
            "  {name:<10} {solved}/{total} substeps solved, dissipated {dissipated:.6e}, largest residual {worst:.2e}, time {time:.4} s"
        );
    }
}

/// (failed, not applicable) checks of a report.
pub fn check_counts(r: &Report) -> (usize, usize) {
    let bad = r.checks.iter().filter(|c| !c.pass).count();
    let skipped = r.checks.iter().filter(|c| c.kind == CheckKind::NotApplicable).count();
    (bad, skipped)
}

/// What `rollbem check` prints for a scene: PASS or FAIL with the counts and the solvers' statuses, then each failed
/// check, then the explanation of every run that ended otherwise than the scene expects.
pub fn check_summary(r: &Report) -> String {
    let mut out = String::new();
    let (bad, skipped) = check_counts(r);
    let statuses: Vec<String> = r.runs.iter().map(|x| format!("{} {}", x.solver, x.status)).collect();
    w!(
        out,
        "{} {} ({} checks, {} failed, {} not applicable; solvers: {})",
        if bad == 0 { "PASS" } else { "FAIL" },
        r.scene.name(),
        r.checks.len(),
        bad,
        skipped,
        statuses.join(", ")
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
    for run in r.runs.iter().filter(|x| x.status != r.scene.expect().status_for(x.solver)) {
        w!(out, "    {}: {}", run.solver, run.explanation());
    }
    out.trim_end().to_string()
}
