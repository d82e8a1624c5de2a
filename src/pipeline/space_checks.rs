//! The checks of a half-space run ([`SpaceReport::checks`]), each with its reference and the source of its
//! tolerance:
//!
//! - **status**: every step ends with the scene's expected status (`[checks] status`, default `solved`); a verdict.
//! - **residual**: the largest inner residual of a solved step (the solvers' own measure of the discrete
//!   conditions, recomputed from the final tractions) below `[checks] residual`, default the solver's acceptance
//!   bound [`crate::halfspace::PathSettings::residual`].
//! - **resultants**: a prescribed load `P` and force `F` against `A Σ p`, `A Σ q` summed here from the element
//!   arrays, to [`crate::tolerances::LOAD_RESULTANT`] (1e-10; the solvers hold the sums as constraints).
//! - **Coulomb's disc**: `max (|q| − μp)` over the elements, relative to `μ max p`, at most [`DISC_ROUND_OFF`] (the
//!   tangential solver projects onto the disc, so only round-off may exceed it).
//! - **Hertz** ([`crate::theory::Hertz3D`], Johnson §4.2(b)) at the end of each step of a quadratic profile whose
//!   normal problem is not coupled: the semi-axes and peak pressure of the least-squares fit
//!   `p² = p₀²(1 − x²/a_x² − y²/a_y²)` over the loaded elements, and the approach, to `[checks] hertz`, default
//!   [`crate::tolerances::HERTZ_CONSTANT`] (1.5 %: the 2D constant-element bound, which the same piecewise-constant
//!   tractions meet in 3D with room: measured on `reference/scenes/half-space/hertz-ellipse.toml`, a/b = 2, largest of
//!   a_x, a_y, p₀, approach 0.17 % at 20 and 0.018 % at 40 elements across the minor axis), at the resolution it assumes: with fewer than
//!   [`crate::tolerances::HERTZ_MIN_ELEMENTS`] elements across the minor axis the check does not apply (as in 2D). A
//!   coupled normal problem (a dissimilar pair with friction) is not Hertz's: not applicable.
//! - **Cattaneo–Mindlin** (Johnson §7.2, eqs. 7.38–7.42) on a circle (A = B), uncoupled, after a first step that
//!   presses without tangential drive, for each later step at the same load whose tangential drive grows along one
//!   direction: the stick radius `c = a (1 − Q/μP)^(1/3)` (from the stick area, `√(N_stick A/π)`) to one element
//!   side (the 2D rule [`crate::tolerances::CATTANEO_ELEMENTS`]: each edge is known to an element), and the shift
//!   `δ = 3μP/(16a) Σ(2 − ν)/G [1 − (1 − Q/μP)^(2/3)]` for a prescribed force (or the force `Q(δ)` for a prescribed
//!   shift) to `[checks] cattaneo`, default [`CATTANEO_3D`]. The theory is exact for ν = 0 only (no Poisson term in
//!   the tangential compliance); for ν > 0 the stick area is not exactly a circle (Munisamy, Hills & Nowell 1991)
//!   and these rows are model comparisons: the difference is shown, not judged.

use crate::results::space::{SpaceReport, SpaceStepResult, TangentialDriveDoc};
use crate::results::{Check, CheckKind};
use crate::scene::{SpaceScene, SpaceStatus};
use crate::tolerances::{CATTANEO_ELEMENTS, HERTZ_CONSTANT, HERTZ_MIN_ELEMENTS, LOAD_RESULTANT};

/// Largest excess of a shear over Coulomb's disc, relative to `μ max p`: round-off (the tangential solver ends on a
/// projection onto the disc).
pub const DISC_ROUND_OFF: f64 = 1e-12;

/// Default relative tolerance of the Cattaneo–Mindlin shift (or force): 1 %, the bound of the library's test at 40
/// elements across the contact (`halfspace::tangential`, `cattaneo_mindlin_circle`: measured 5.3e-4 at 20 and 9.3e-6
/// at 40 elements across, ν = 0).
pub const CATTANEO_3D: f64 = 0.01;

/// A figure check.
fn figure(name: String, measured: f64, reference: f64, tolerance: f64) -> Check {
    let error = if reference != 0.0 { (measured - reference).abs() / reference.abs() } else { measured.abs() };
    Check {
        name,
        measured,
        reference,
        error,
        tolerance,
        pass: error <= tolerance,
        kind: CheckKind::Figure,
        model_error: None,
        uncertainty: None,
        note: None,
    }
}

/// A check without a figure.
fn verdict(name: String, pass: bool, kind: CheckKind, note: String) -> Check {
    Check {
        name,
        measured: f64::from(u8::from(pass)),
        reference: 1.0,
        error: f64::from(u8::from(!pass)),
        tolerance: 0.0,
        pass: pass || kind == CheckKind::NotApplicable,
        kind,
        model_error: None,
        uncertainty: None,
        note: Some(note),
    }
}

/// Add every check of the module docs to `report`.
pub(super) fn add_checks(scene: &SpaceScene, coupled: bool, report: &mut SpaceReport) {
    let expect = scene.expect();
    let bad: Vec<String> = report
        .steps
        .iter()
        .filter(|s| s.status != expect.status)
        .map(|s| format!("step {}.{}: {} ({})", s.step, s.substep, s.status, s.message))
        .collect();
    let mut checks = vec![verdict(
        format!("status of every step (expected {})", expect.status),
        bad.is_empty(),
        CheckKind::Verdict,
        if bad.is_empty() { format!("{} steps, all {}", report.steps.len(), expect.status) } else { bad.join("; ") },
    )];
    let solved: Vec<&SpaceStepResult> = report.steps.iter().filter(|s| s.status == SpaceStatus::Solved).collect();
    if !solved.is_empty() {
        let res = solved.iter().map(|s| s.residual_normal.max(s.residual_tangential)).fold(0.0, f64::max);
        let tol = expect.residual.unwrap_or(scene.settings().residual);
        let mut c = figure("largest inner residual (relative)".into(), res, 0.0, tol);
        c.pass = res <= tol;
        checks.push(c);
    }
    let area = report.grid.dx * report.grid.dy;
    for s in report.step_ends().filter(|s| s.status == SpaceStatus::Solved) {
        checks.extend(resultant_checks(s, area, scene.friction()));
        checks.extend(hertz_checks(scene, coupled, s, &report.grid));
    }
    checks.extend(cattaneo_checks(scene, coupled, report));
    report.checks = checks;
}

/// Prescribed load and force against the element sums; the friction disc.
fn resultant_checks(s: &SpaceStepResult, area: f64, mu: f64) -> Vec<Check> {
    let e = &s.elements;
    let tag = format!("step {}", s.step);
    let load = area * e.pressure.iter().sum::<f64>();
    let mut out = Vec::new();
    if let crate::results::space::NormalDriveDoc::Load(p) = s.normal_drive {
        out.push(figure(format!("{tag}: resultant P = normal_load"), load, p, LOAD_RESULTANT));
    }
    if let TangentialDriveDoc::Force([fx, fy]) = s.tangential_drive {
        let (sx, sy) = (area * e.qx.iter().sum::<f64>(), area * e.qy.iter().sum::<f64>());
        let scale = fx.hypot(fy).max(mu * load);
        let err = (sx - fx).hypot(sy - fy) / scale;
        let mut c = figure(
            format!("{tag}: resultant F = tangential_load (relative to max(|F|, μP))"),
            err,
            0.0,
            LOAD_RESULTANT,
        );
        c.pass = err <= LOAD_RESULTANT;
        out.push(c);
    }
    if mu > 0.0 {
        let pmax = e.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        let excess = (0..e.pressure.len()).map(|i| e.qx[i].hypot(e.qy[i]) - mu * e.pressure[i]).fold(0.0, f64::max);
        let rel = if pmax > 0.0 { excess / (mu * pmax) } else { 0.0 };
        let mut c =
            figure(format!("{tag}: shear outside Coulomb's disc (relative to μ p_max)"), rel, 0.0, DISC_ROUND_OFF);
        c.pass = rel <= DISC_ROUND_OFF;
        out.push(c);
    }
    out
}

/// The least-squares fit `p² = c₀ + c₁x² + c₂y²` over the loaded elements: (a_x, a_y, p₀), `None` when it is not
/// an ellipse (too few elements, or a coefficient of the wrong sign).
pub fn fit_ellipse(grid: &crate::results::space::GridInfo, pressure: &[f64]) -> Option<(f64, f64, f64)> {
    let mut m = [[0.0_f64; 3]; 3];
    let mut r = [0.0_f64; 3];
    let mut n = 0;
    for iy in 0..grid.my {
        for ix in 0..grid.mx {
            let p = pressure[ix + grid.mx * iy];
            if p <= 0.0 {
                continue;
            }
            let (x, y) = grid.centre(ix, iy);
            let f = [1.0, x * x, y * y];
            for i in 0..3 {
                r[i] += f[i] * p * p;
                for j in 0..3 {
                    m[i][j] += f[i] * f[j];
                }
            }
            n += 1;
        }
    }
    if n < 6 {
        return None;
    }
    let c = solve3(m, r)?;
    (c[0] > 0.0 && c[1] < 0.0 && c[2] < 0.0).then(|| ((-c[0] / c[1]).sqrt(), (-c[0] / c[2]).sqrt(), c[0].sqrt()))
}

/// Solve a 3 × 3 system by Cramer's rule (`None` when singular).
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let mut a = m;
        for i in 0..3 {
            a[i][k] = r[i];
        }
        *o = det(a) / d;
    }
    Some(out)
}

/// Hertz's ellipse at a step's end (module docs).
fn hertz_checks(
    scene: &SpaceScene,
    coupled: bool,
    s: &SpaceStepResult,
    grid: &crate::results::space::GridInfo,
) -> Vec<Check> {
    let tag = format!("step {}: Hertz", s.step);
    let Some((a, b)) = scene.curvatures() else { return Vec::new() };
    if coupled && scene.friction() > 0.0 {
        let why = "the pair is dissimilar and coupled: its pressure is not Hertz's (Spence)".to_string();
        return vec![verdict(tag, true, CheckKind::NotApplicable, why)];
    }
    let Some(h) = crate::theory::Hertz3D::from_load(a, b, scene.contact_modulus(), s.load) else {
        return vec![verdict(tag, true, CheckKind::NotApplicable, "no contact load".into())];
    };
    let tol = scene.expect().hertz.unwrap_or(HERTZ_CONSTANT);
    let across = 2.0 * (h.a_x / grid.dx).min(h.a_y / grid.dy);
    if across < HERTZ_MIN_ELEMENTS {
        let why = format!(
            "{across:.3} elements across Hertz's minor axis; its tolerance ({tol:.1e}) needs at least {HERTZ_MIN_ELEMENTS}"
        );
        return vec![verdict(format!("{tag} ellipse (fit)"), true, CheckKind::NotApplicable, why)];
    }
    let mut out = Vec::new();
    match fit_ellipse(grid, &s.elements.pressure) {
        Some((ax, ay, p0)) => {
            out.push(figure(format!("{tag} semi-axis a_x (fit)"), ax, h.a_x, tol));
            out.push(figure(format!("{tag} semi-axis a_y (fit)"), ay, h.a_y, tol));
            out.push(figure(format!("{tag} peak pressure p0 (fit)"), p0, h.p0, tol));
        }
        None => out.push(verdict(
            format!("{tag} ellipse fit"),
            false,
            CheckKind::Verdict,
            "the loaded elements do not fit an ellipse p² = p0²(1 − x²/a² − y²/b²)".into(),
        )),
    }
    out.push(figure(format!("{tag} approach"), s.approach, h.approach, tol));
    out
}

/// Cattaneo–Mindlin (module docs): the steps it applies to, each with its stick radius and shift (or force).
fn cattaneo_checks(scene: &SpaceScene, coupled: bool, report: &SpaceReport) -> Vec<Check> {
    let Some((a_curv, b_curv)) = scene.curvatures() else { return Vec::new() };
    let mu = scene.friction();
    let ends: Vec<&SpaceStepResult> = report.step_ends().collect();
    if mu == 0.0 || a_curv != b_curv || ends.len() < 2 || coupled {
        return Vec::new();
    }
    let first = ends[0];
    let pressed = match first.tangential_drive {
        TangentialDriveDoc::Force(v) | TangentialDriveDoc::ShiftIncrement(v) => v == [0.0, 0.0],
    };
    if !pressed || first.status != SpaceStatus::Solved {
        return Vec::new();
    }
    let exact = scene.body().poisson_ratio() == 0.0
        && (scene.counter().youngs_modulus().is_infinite() || scene.counter().poisson_ratio() == 0.0);
    let compliance = |h: crate::halfspace::HalfSpace| {
        if h.youngs_modulus().is_infinite() {
            0.0
        } else {
            (2.0 - h.poisson_ratio()) / h.shear_modulus()
        }
    };
    let sum = compliance(scene.body()) + compliance(scene.counter());
    let shift0 = first.shift.unwrap_or([0.0, 0.0]);
    let mut out = Vec::new();
    let mut direction: Option<[f64; 2]> = None;
    let mut last = 0.0;
    for s in ends.iter().skip(1) {
        if s.status != SpaceStatus::Solved || (s.load - first.load).abs() > 1e-9 * first.load {
            break;
        }
        let Some(shift) = s.shift else { break };
        let (drive, magnitude) = match s.tangential_drive {
            TangentialDriveDoc::Force([x, y]) => ([x, y], x.hypot(y)),
            TangentialDriveDoc::ShiftIncrement(_) => {
                let w = [shift[0] - shift0[0], shift[1] - shift0[1]];
                (w, w[0].hypot(w[1]))
            }
        };
        if magnitude == 0.0 || magnitude < last {
            break;
        }
        let unit = [drive[0] / magnitude, drive[1] / magnitude];
        if direction
            .is_some_and(|d| (d[0] * unit[1] - d[1] * unit[0]).abs() > 1e-9 || d[0] * unit[0] + d[1] * unit[1] < 0.0)
        {
            break;
        }
        direction = Some(unit);
        last = magnitude;
        let theory = Cattaneo { load: s.load, a: hertz_radius(scene, s.load), mu, sum };
        out.extend(cattaneo_step(scene, s, shift0, unit, theory, exact, &report.grid));
    }
    out
}

/// Cattaneo–Mindlin's circle at load `load`: Hertz radius `a`, friction `mu`, `sum` = Σ(2 − ν)/G.
#[derive(Clone, Copy)]
struct Cattaneo {
    load: f64,
    a: f64,
    mu: f64,
    sum: f64,
}

impl Cattaneo {
    /// The shift at full sliding, δ_s = 3μP/(16a) Σ(2 − ν)/G.
    fn slide(&self) -> f64 {
        3.0 * self.mu * self.load / (16.0 * self.a) * self.sum
    }
}

/// Hertz's radius of a circular contact at `load`.
fn hertz_radius(scene: &SpaceScene, load: f64) -> f64 {
    let (a, b) = scene.curvatures().unwrap_or((1.0, 1.0));
    crate::theory::Hertz3D::from_load(a, b, scene.contact_modulus(), load).map_or(f64::NAN, |h| h.a_x)
}

/// One step's Cattaneo–Mindlin rows.
fn cattaneo_step(
    scene: &SpaceScene,
    s: &SpaceStepResult,
    shift0: [f64; 2],
    unit: [f64; 2],
    th: Cattaneo,
    exact: bool,
    grid: &crate::results::space::GridInfo,
) -> Vec<Check> {
    let tag = format!("step {}: Cattaneo–Mindlin", s.step);
    let shift = s.shift.unwrap_or(shift0);
    let mu_p = th.mu * th.load;
    // Q > 0 along the force on body 1; body 1 then moves by −δ along it (module docs).
    let (ratio, delta_num, q_num) = match s.tangential_drive {
        TangentialDriveDoc::Force(_) => {
            let q = s.force[0] * unit[0] + s.force[1] * unit[1];
            (q / mu_p, -((shift[0] - shift0[0]) * unit[0] + (shift[1] - shift0[1]) * unit[1]), q)
        }
        TangentialDriveDoc::ShiftIncrement(_) => {
            let delta = (shift[0] - shift0[0]) * unit[0] + (shift[1] - shift0[1]) * unit[1];
            let x = delta / th.slide();
            if x >= 1.0 {
                let why = format!("the shift {delta:e} is beyond Cattaneo's full sliding {:e}", th.slide());
                return vec![verdict(tag, true, CheckKind::NotApplicable, why)];
            }
            let q = -(s.force[0] * unit[0] + s.force[1] * unit[1]);
            (1.0 - (1.0 - x).powf(1.5), delta, q)
        }
    };
    if !(ratio > 0.0 && ratio < 1.0) {
        return vec![verdict(tag, true, CheckKind::NotApplicable, format!("Q/μP = {ratio} outside (0, 1)"))];
    }
    let c_theory = th.a * (1.0 - ratio).cbrt();
    let c_num = (s.stick as f64 * grid.dx * grid.dy / std::f64::consts::PI).sqrt();
    let side = grid.dx.max(grid.dy);
    let tol = scene.expect().cattaneo.unwrap_or(CATTANEO_3D);
    let mut rows = vec![{
        let mut c = figure(
            format!("{tag} stick radius c (from the stick area; error in elements)"),
            c_num,
            c_theory,
            CATTANEO_ELEMENTS,
        );
        c.error = (c_num - c_theory).abs() / side;
        c.pass = c.error <= CATTANEO_ELEMENTS;
        c
    }];
    rows.push(match s.tangential_drive {
        TangentialDriveDoc::Force(_) => {
            let delta = th.slide() * (1.0 - (1.0 - ratio).powf(2.0 / 3.0));
            figure(format!("{tag} shift δ for the force"), delta_num, delta, tol)
        }
        TangentialDriveDoc::ShiftIncrement(_) => {
            figure(format!("{tag} force Q for the shift"), q_num, ratio * mu_p, tol)
        }
    });
    if !exact {
        for c in &mut rows {
            c.kind = CheckKind::ModelComparison;
            c.pass = true;
            c.note = Some(
                "Cattaneo–Mindlin is exact for ν = 0; with ν > 0 the tangential compliance has a Poisson term and the \
                 stick area is not exactly a circle (Munisamy, Hills & Nowell 1991): the difference is shown, not judged"
                    .into(),
            );
        }
    }
    rows
}
