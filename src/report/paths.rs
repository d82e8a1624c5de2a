//! Load paths among the reference scenes (`[[steps]]`): the Q–δ_T hysteresis loop, the stick zone against the
//! substep, the energy dissipated, and for rolling paths the approach to the steady-rolling solution of the same
//! mesh. Theory is drawn only where it applies to the scene as written: Mindlin–Deresiewicz for a β = 0 half-plane
//! under constant P and a tangential load cycled ±Q*, Spence for a coupled half-plane under a growing normal load.

use super::table::Units;
use super::Figs;
use crate::error::Result;
use crate::pipeline::run_scene;
use crate::plot::{Chart, Series, Style};
use crate::post::stick_edges;
use crate::references::beta_zero;
use crate::results::{Report, SolverRun};
use crate::scene::{BodyModel, CounterBody, RollingMode, Scene};
use crate::theory::{self, TangentialPath};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The runs of one solver along a path, in order (a solver whose path broke has fewer).
fn runs_of<'a>(r: &'a Report, solver: &str) -> Vec<(usize, &'a SolverRun)> {
    r.steps.iter().enumerate().filter_map(|(k, st)| Some((k, st.runs.iter().find(|x| x.solver == solver)?))).collect()
}

/// The half-plane model in plane strain (not on a strip of half-spaces): the model of the 2D path theories.
fn plane_strain_half_plane(s: &Scene) -> bool {
    s.model() == BodyModel::HalfPlane && s.strip_width().is_none()
}

/// The Mindlin–Deresiewicz pattern: step 0 loads P alone, then every step holds P and takes Q to +Q*, −Q*, +Q*, …
/// (|Q*| ≤ μP), on the half-plane model in plane strain with β = 0 — against a rigid flat, or against an elastic
/// half-plane of a β = 0 pair (steel on steel). Returns (P, Q*).
pub fn md_pattern(s: &Scene) -> Option<(f64, f64)> {
    let p = s.document().steps.first()?.normal_load?;
    if !plane_strain_half_plane(s) || s.rolling().is_some() || !beta_zero(s, p) || s.document().steps.len() < 3 {
        return None;
    }
    if s.document().steps[0].tangential_load.unwrap_or(0.0) != 0.0 || s.document().steps[0].tangential_shift.is_some() {
        return None;
    }
    let q_star = s.document().steps[1].tangential_load?;
    let ok = q_star > 0.0
        && q_star <= s.friction() * p
        && s.document().steps[1..].iter().enumerate().all(|(k, st)| {
            st.normal_load == Some(p) && st.tangential_load == Some(if k % 2 == 0 { q_star } else { -q_star })
        });
    ok.then_some((p, q_star))
}

/// The MD branch of substep `k` (index into `r.steps`) for the pattern of [`md_pattern`].
fn md_branch(r: &Report, k: usize, q_star: f64) -> TangentialPath {
    match r.steps[k].step {
        0 | 1 => TangentialPath::Loading,
        s if s % 2 == 0 => TangentialPath::Unloading { q_star },
        _ => TangentialPath::Reloading { q_star },
    }
}

/// Spence's pattern: a coupled half-plane (β ≠ 0) on a rigid flat, one or more steps raising the normal load
/// monotonically from rest with no tangential drive. Returns β.
fn spence_pattern(s: &Scene) -> Option<f64> {
    let single = plane_strain_half_plane(s) && matches!(s.counter_body(), CounterBody::Rigid);
    let p_end = s.document().steps.last()?.normal_load?;
    let monotone =
        s.document().steps.windows(2).all(|w| w[0].normal_load.unwrap_or(0.0) <= w[1].normal_load.unwrap_or(0.0));
    let no_tangential =
        s.document().steps.iter().all(|st| st.tangential_load.unwrap_or(0.0) == 0.0 && st.roll.is_none());
    (single && s.law().coupling && s.friction() > 0.0 && monotone && no_tangential && !beta_zero(s, p_end))
        .then(|| s.dundurs_beta())
}

/// The path sections of every reference scene with `[[steps]]`.
pub fn sections(reports: &BTreeMap<String, Report>, md: &mut String, figs: &mut Figs) -> Result<()> {
    for (name, r) in reports.iter().filter(|(_, r)| !r.steps.is_empty()) {
        writeln!(md, "### `{name}`\n\n{}\n", r.scene.description().split_whitespace().collect::<Vec<_>>().join(" "))
            .unwrap();
        summary(r, md);
        path_figures(name, r, md, figs)?;
    }
    Ok(())
}

/// The figures of one load path (its first solver's solved substeps): the Q–δ_T loop (or, rolling, the approach to
/// steady rolling) and the stick zone along the path, each with the theory where it applies; what they show is
/// written to `md`.
pub fn path_figures(name: &str, r: &Report, md: &mut String, figs: &mut Figs) -> Result<()> {
    let units = Units::parse(r.scene.units());
    let solver = r.runs.first().map(|x| x.solver.name()).unwrap_or("lemke");
    // The figures and theory comparisons use the solved substeps only (a path that broke, or a substep judged
    // not an answer, has no tractions to compare); the summary above says how many there are.
    let all = runs_of(r, solver);
    let runs: Vec<(usize, &SolverRun)> =
        all.iter().copied().filter(|(_, x)| x.status == crate::solvers::Status::Solved).collect();
    if runs.len() < all.len() {
        writeln!(
            md,
            "{solver} solved {} of the path's {} substeps; the figures below show the solved ones.\n",
            runs.len(),
            r.steps.len()
        )
        .unwrap();
    }
    if r.scene.document().steps.iter().any(|st| st.roll.unwrap_or(0.0) > 0.0) {
        rolling_approach(name, r, &runs, &units, md, figs)?;
    } else {
        hysteresis(name, r, &runs, &units, md, figs)?;
    }
    stick_zone(name, r, &runs, &units, md, figs)?;
    Ok(())
}

/// Per solver: substeps solved, dissipated energy, largest residual, time.
fn summary(r: &Report, md: &mut String) {
    writeln!(
        md,
        "| solver | substeps solved | dissipated (total) | largest residual | time [s] |\n|---|---|---|---|---|"
    )
    .unwrap();
    for run in &r.runs {
        let runs = runs_of(r, run.solver.name());
        let solved = runs.iter().filter(|(_, x)| x.status == crate::solvers::Status::Solved).count();
        // The total dissipated up to the last solved substep.
        let dissipated = runs
            .iter()
            .rev()
            .find(|(_, x)| x.status == crate::solvers::Status::Solved)
            .and_then(|(_, x)| x.history.as_ref())
            .map_or(0.0, |h| h.dissipated_total);
        let worst = runs.iter().filter_map(|(_, x)| x.residuals.map(|res| res.max())).fold(0.0, f64::max);
        let time: f64 = runs.iter().map(|(_, x)| x.timing_s.total).sum();
        writeln!(md, "| {} | {solved}/{} | {dissipated:.4e} | {worst:.1e} | {time:.3} |", run.solver, r.steps.len())
            .unwrap();
    }
    writeln!(md).unwrap();
}

/// A curve to draw: label, points, style.
pub(super) type Curve = (String, Vec<(f64, f64)>, Style);

/// Q against the rigid shift, with Mindlin–Deresiewicz where it applies; the cycle's dissipation against theory.
fn hysteresis(
    name: &str,
    r: &Report,
    runs: &[(usize, &SolverRun)],
    units: &Units,
    md: &mut String,
    figs: &mut Figs,
) -> Result<()> {
    let pts: Vec<(f64, f64)> =
        runs.iter().filter_map(|(_, x)| Some((x.rigid_body?.tangential?, x.resultants?.tangential))).collect();
    // A loop exists only when the path drives the tangential DOF (Q or δ_T); a purely normal path (Spence's) has
    // Q at round-off, which is no loop.
    let tangential = r
        .scene
        .document()
        .steps
        .iter()
        .any(|st| st.tangential_load.is_some_and(|q| q != 0.0) || st.tangential_shift.is_some_and(|d| d != 0.0));
    if !tangential || pts.is_empty() {
        return Ok(());
    }
    let solver = runs.first().map(|(_, x)| x.solver.name()).unwrap_or("");
    let mut series: Vec<Curve> = vec![(format!("{solver}, substep ends"), pts.clone(), Style::LineMarkers)];
    if let Some(curve) = md_loop(r, runs, solver, md) {
        series.push(curve);
    }
    let mut chart = Chart::new(format!("{name}: tangential force against rigid shift"), "rigid shift δ_T", "Q")
        .x_unit(units.length.clone())
        .y_unit(units.line_load());
    for (label, p, style) in &series {
        chart = chart.add(Series::new(label.clone(), p.clone(), *style));
    }
    let file = figs.save(&chart, &format!("{name}-hysteresis.svg"), format!("{name}: Q against δ_T"))?;
    writeln!(md, "![hysteresis loop]({file})\n").unwrap();
    opened_loop(name, &pts, &series, units, md, figs)?;
    Ok(())
}

/// Mindlin–Deresiewicz's loop for a path of its pattern ([`md_pattern`]), with the cycle's dissipation and the
/// distance of the computed shifts from the loop written to `md`; `None` for other paths.
fn md_loop(r: &Report, runs: &[(usize, &SolverRun)], solver: &str, md: &mut String) -> Option<Curve> {
    let s = &r.scene;
    let (p, q_star) = md_pattern(s)?;
    let mu = s.friction();
    let delta = md_shift(s, p);
    let curve = md_curve(s, p, q_star);
    let w: f64 = runs
        .iter()
        .filter(|(k, _)| r.steps[*k].step >= 2 && r.steps[*k].step <= 3)
        .filter_map(|(_, x)| x.history.as_ref().map(|h| h.dissipated))
        .sum();
    let exact = theory::md_cycle_dissipation(mu, p, s.contact_modulus(), q_star);
    let in_cycle = |k: usize| (2..=3).contains(&r.steps[k].step);
    let complete =
        runs.iter().filter(|(k, _)| in_cycle(*k)).count() == (0..r.steps.len()).filter(|&k| in_cycle(k)).count();
    if r.scene.document().steps.len() >= 4 && !complete {
        writeln!(md, "The cycle +Q* → −Q* → +Q* did not complete ({solver} failed in it): no cycle energy.\n").unwrap();
    } else if r.scene.document().steps.len() >= 4 {
        writeln!(
            md,
            "Energy dissipated in the cycle +Q* → −Q* → +Q* (Q* = {q_star}, {solver}): {w:.6e}; Mindlin–Deresiewicz \
             in 2D, W = (2μ²P²/(πE*))[1 − γ² + 2γ ln γ] with γ = 1 − Q*/(μP): {exact:.6e} (relative difference \
             {:+.1e}).\n",
            w / exact - 1.0
        )
        .unwrap();
    }
    let worst = runs
        .iter()
        .filter_map(|(k, x)| {
            let q = x.resultants?.tangential;
            Some((x.rigid_body?.tangential? - delta(md_branch(r, *k, q_star), q)).abs())
        })
        .fold(0.0, f64::max);
    let span = delta(TangentialPath::Loading, q_star).abs();
    writeln!(
        md,
        "Largest distance of the computed shift from the theory's loop: {:.1e} of the loop's half-span.\n",
        worst / span
    )
    .unwrap();
    Some(("Mindlin–Deresiewicz (2D)".into(), curve, Style::Dashed))
}

/// The wheel's rigid shift on Mindlin–Deresiewicz's loop at load P, as a function of the branch and Q, for a scene
/// of the pattern ([`md_pattern`]). Each half-plane's datum is the material point at its depth D; theory's log datum
/// is D' = D e^(1/(2(1 − ν))) (tests/history.rs derives it); the compliances of the two bodies of a pair add (the
/// displacement is linear in 1/E*, each body with its own datum); the wheel's shift is minus the counter-body's δ.
pub fn md_shift(s: &Scene, p: f64) -> impl Fn(TangentialPath, f64) -> f64 {
    let h = crate::references::hertz_at(s, p);
    let mu = s.friction();
    let wheel_datum = match s.body() {
        crate::scene::Body::HalfPlane { datum_depth, .. } => *datum_depth,
        crate::scene::Body::Bem { .. } => s.radius(),
    };
    let log_datum = |d: f64, nu: f64| d * (0.5 / (1.0 - nu)).exp();
    let w = s.wheel().material;
    let mut bodies = vec![(w.plane_strain_modulus(), log_datum(wheel_datum, w.poisson_ratio))];
    if let CounterBody::HalfPlane { material, datum_depth, .. } = s.counter_body() {
        bodies.push((material.plane_strain_modulus(), log_datum(*datum_depth, material.poisson_ratio)));
    }
    move |path: TangentialPath, q: f64| {
        -bodies.iter().map(|&(e, d)| theory::md_displacement(&h, mu, e, d, path, q)).sum::<f64>()
    }
}

/// Mindlin–Deresiewicz's loop (shift, Q) at P: loading to Q*, unloading to −Q*, reloading to Q*.
pub fn md_curve(s: &Scene, p: f64, q_star: f64) -> Vec<(f64, f64)> {
    let delta = md_shift(s, p);
    let qs: Vec<f64> = (0..=100).map(|i| q_star * (i as f64 / 50.0 - 1.0)).collect();
    let mut curve: Vec<(f64, f64)> =
        (0..=50).map(|i| q_star * i as f64 / 50.0).map(|q| (delta(TangentialPath::Loading, q), q)).collect();
    curve.extend(qs.iter().rev().map(|&q| (delta(TangentialPath::Unloading { q_star }, q), q)));
    curve.extend(qs.iter().map(|&q| (delta(TangentialPath::Reloading { q_star }, q), q)));
    curve
}

/// The loop with the chord through its tips subtracted, so that its width shows (the loop is thin beside the
/// elastic compliance): the report's figure and text.
fn opened_loop(
    name: &str,
    pts: &[(f64, f64)],
    series: &[Curve],
    units: &Units,
    md: &mut String,
    figs: &mut Figs,
) -> Result<()> {
    let Some((chart, slope)) = loop_less_chord(name, pts, series, &units.length, &units.line_load()) else {
        return Ok(());
    };
    let file = figs.save(&chart, &format!("{name}-hysteresis-opened.svg"), format!("{name}: the loop opened"))?;
    writeln!(
        md,
        "The same loop with the straight chord through its tips (δ_T at the largest and smallest Q, compliance \
         {slope:.3e} {}/({})) subtracted, so that its width shows:\n\n![hysteresis loop opened]({file})\n",
        units.length,
        units.line_load()
    )
    .unwrap();
    Ok(())
}

/// The Q–δ_T loop less its chord, titled `NAME: loop less its chord`: every curve of `series` with the straight
/// chord through the tips of `pts` (the computed loop's (δ_T, Q): the shifts at its largest and smallest Q)
/// subtracted from its shifts, so that the loop's width shows beside the elastic compliance it is thin against.
/// Returns the chart and the chord's slope (compliance, shift per unit Q); `None` when Q does not vary. Drawn for a
/// result document's path and for a path's CSV (`rollbem plot`).
pub(super) fn loop_less_chord(
    name: &str,
    pts: &[(f64, f64)],
    series: &[Curve],
    length_unit: &str,
    load_unit: &str,
) -> Option<(Chart, f64)> {
    let hi = pts.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1))?;
    let lo = pts.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1))?;
    if hi.1 <= lo.1 {
        return None;
    }
    let slope = (hi.0 - lo.0) / (hi.1 - lo.1);
    let open = |v: &[(f64, f64)]| v.iter().map(|&(d, q)| (d - lo.0 - slope * (q - lo.1), q)).collect::<Vec<_>>();
    let mut chart =
        Chart::new(format!("{name}: loop less its chord"), "δ_T − chord(Q)", "Q").x_unit(length_unit).y_unit(load_unit);
    for (label, p, style) in series {
        chart = chart.add(Series::new(label.clone(), open(p), *style));
    }
    Some((chart, slope))
}

/// Grid size of the coupled Spence reference in the report (per half contact; 1.25 a / 250 = 0.005 a).
const SPENCE_COUPLED_ELEMENTS: usize = 250;

/// Spence's closed form and the coupled numerical reference against the last substep's stick zone: the closed form
/// is Goodman's approximation (the shear's effect on the pressure neglected), exact as βμ → 0; where it differs
/// from the coupled reference by more than the reference's resolution it is outside its range, and the comparison
/// with it is a model comparison, not a check.
fn spence_comparison(
    s: &Scene,
    beta: f64,
    (closed, coupled, in_range): (f64, theory::CoupledSpence, bool),
    last: &SolverRun,
    units: &Units,
    md: &mut String,
) {
    let mu = s.friction();
    let tol = 2.0 * coupled.resolution;
    let h = s.zone().element_length(s.radius());
    let computed = last.contact.as_ref().zip(stick_edges(&last.nodes)).and_then(|(c, (l, r))| {
        let contact = c.half_width? + 0.5 * h;
        Some((0.5 * (r - l) / contact, contact))
    });
    writeln!(
        md,
        "Spence's closed form, c/a = {closed:.4} for β/μ = {:.3}, is the Goodman approximation (the shear's effect on \
         the pressure neglected): exact as βμ → 0, off by O(βμ). Here βμ = {:.3}: the coupled numerical reference \
         (the same problem with that effect retained, solved by an incremental active-set method on {} elements per \
         half contact, independent of rollbem's BEM and LCP solvers; c/a to ±{tol:.3}) gives c/a = {:.3}, the contact \
         {:.1} % {} than Hertz's, so the closed form is {}.\n",
        beta.abs() / mu,
        beta.abs() * mu,
        SPENCE_COUPLED_ELEMENTS,
        coupled.c_over_a,
        100.0 * (1.0 - coupled.contact_over_hertz).abs(),
        if coupled.contact_over_hertz <= 1.0 { "narrower" } else { "wider" },
        if in_range {
            "within its range here (it agrees with the coupled reference to the resolution of the two)"
        } else {
            "outside its range here: the comparison with it is a model comparison, and the coupled reference is the \
             check"
        }
    )
    .unwrap();
    if let Some((ratio, contact)) = computed {
        let res = h / contact;
        writeln!(
            md,
            "Computed at the last substep: stick half-width over contact half-width c/a = {ratio:.4} (contact \
             half-width {contact:.4} {}; each edge to half an element, c/a to ±{res:.3}): {:.4} from the coupled \
             reference ({}), {:.4} from the closed form.\n",
            units.length,
            (ratio - coupled.c_over_a).abs(),
            if (ratio - coupled.c_over_a).abs() <= tol + res {
                "within the two resolutions"
            } else {
                "outside the two resolutions"
            },
            (ratio - closed).abs()
        )
        .unwrap();
    }
}

/// The stick zone's half-width at each substep, with theory where it applies.
fn stick_zone(
    name: &str,
    r: &Report,
    runs: &[(usize, &SolverRun)],
    units: &Units,
    md: &mut String,
    figs: &mut Figs,
) -> Result<()> {
    let pts: Vec<(f64, f64)> = runs
        .iter()
        .filter_map(|(k, x)| {
            let (l, rr) = stick_edges(&x.nodes)?;
            Some(((k + 1) as f64, 0.5 * (rr - l)))
        })
        .collect();
    if pts.is_empty() {
        return Ok(());
    }
    let solver = runs.first().map(|(_, x)| x.solver.name()).unwrap_or("");
    let mut chart = Chart::new(format!("{name}: stick zone along the path"), "substep", "stick half-width")
        .x_unit("1")
        .y_unit(units.length.clone())
        .add(Series::new(solver, pts.clone(), Style::Markers));
    let s = &r.scene;
    let mut theory_pts = Vec::new();
    let mut what = "";
    if let Some((p, q_star)) = md_pattern(s) {
        let h = crate::references::hertz_at(s, p);
        for (k, x) in runs {
            if let Some(f) = x.resultants {
                if r.steps[*k].step >= 1 {
                    let c = theory::md_stick_half_width(&h, s.friction(), md_branch(r, *k, q_star), f.tangential);
                    theory_pts.push(((k + 1) as f64, c));
                }
            }
        }
        what = "Mindlin–Deresiewicz: the current branch's stick zone";
    } else if let Some(beta) = spence_pattern(s) {
        let closed = theory::spence_c_over_a(beta.abs() / s.friction());
        let coupled = theory::spence_coupled_c_over_a(beta.abs(), s.friction(), SPENCE_COUPLED_ELEMENTS);
        // Within its range for this comparison when its departure from the coupled reference is below what the
        // comparison resolves: the reference's two elements plus the run's one element over Hertz's a at the end.
        let a_end = runs
            .last()
            .and_then(|(_, x)| x.resultants)
            .map_or(f64::INFINITY, |f| crate::references::hertz_at(s, f.normal).a);
        let resolved = 2.0 * coupled.resolution + s.zone().element_length(s.radius()) / a_end;
        let in_range = (closed - coupled.c_over_a).abs() <= resolved;
        // Self-similar: c(P) = (c/a) · a(P), with the coupled contact half-width for the coupled reference.
        let line = |ratio: f64| -> Vec<(f64, f64)> {
            runs.iter()
                .filter_map(|(k, x)| {
                    let f = x.resultants.filter(|f| f.normal > 0.0)?;
                    Some(((k + 1) as f64, ratio * crate::references::hertz_at(s, f.normal).a))
                })
                .collect()
        };
        if in_range {
            theory_pts = line(closed);
            what = "Spence (Goodman approximation): c = (c/a)(β/μ) · a(P), self-similar";
        } else {
            // The closed form is outside its range: drawn for comparison, the coupled reference is the check.
            let goodman = line(closed);
            chart = chart.add(Series::new("Spence closed form (Goodman, outside its range)", goodman, Style::Line));
            theory_pts = line(coupled.c_over_a * coupled.contact_over_hertz);
            what = "Coupled numerical reference: c = (c/a) · a_coupled(P), self-similar";
        }
        if let Some((_, last)) = runs.last() {
            spence_comparison(s, beta, (closed, coupled, in_range), last, units, md);
        }
    }
    if !theory_pts.is_empty() {
        let (worst, at) = pts
            .iter()
            .filter_map(|(k, c)| theory_pts.iter().find(|t| t.0 == *k).map(|t| ((c - t.1).abs(), *k)))
            .fold((0.0, 0.0), |m, d| if d.0 > m.0 { d } else { m });
        let h = s.zone().element_length(s.radius());
        writeln!(md, "{what}; largest difference along the path {:.2} elements (substep {at}).\n", worst / h).unwrap();
        chart = chart.add(Series::new(what.split(':').next().unwrap_or(what), theory_pts, Style::Dashed));
    }
    let file = figs.save(&chart, &format!("{name}-stick-zone.svg"), format!("{name}: stick zone along the path"))?;
    writeln!(md, "![stick zone along the path]({file})\n").unwrap();
    Ok(())
}

/// The steady-rolling counterpart of a rolling path: the last step's drive with `[rolling] mode = "steady"` (the
/// tangential load kept when the path prescribes it, else the creepage with the tangential DOF free).
fn steady_counterpart(s: &Scene) -> Result<Scene> {
    s.edit(|c| {
        let last = c.steps.last().cloned().unwrap_or_default();
        c.steps.clear();
        c.drive = last.drive();
        c.drive.tangential_shift = None;
        c.drive.rotation = None;
        c.drive.moment = None;
        if let Some(rolling) = c.rolling.as_mut() {
            rolling.mode = RollingMode::Steady;
            if c.drive.tangential_load.is_some() {
                rolling.creepage = None;
            }
        }
        c.solvers.use_ = vec!["lemke".into()];
    })
}

/// Distance of the tractions to the steady-rolling solution against the distance rolled (log scale).
fn rolling_approach(
    name: &str,
    r: &Report,
    runs: &[(usize, &SolverRun)],
    units: &Units,
    md: &mut String,
    figs: &mut Figs,
) -> Result<()> {
    let steady = run_scene(&steady_counterpart(&r.scene)?)?;
    let Some(y) = steady.runs.first().filter(|y| y.status == crate::solvers::Status::Solved) else {
        writeln!(md, "The steady-rolling counterpart did not solve; no approach plot.\n").unwrap();
        return Ok(());
    };
    let p0 = y.contact.as_ref().map_or(1.0, |c| c.peak_pressure);
    let pts: Vec<(f64, f64)> = runs
        .iter()
        .filter(|(k, _)| r.steps[*k].rolled > 0.0)
        .map(|(k, x)| {
            let d = x.nodes.iter().zip(&y.nodes).fold(0.0f64, |m, (u, v)| m.max((u.shear - v.shear).abs()));
            (r.steps[*k].rolled, (d / p0).max(1e-17))
        })
        .collect();
    let Some(&(end_x, end_d)) = pts.last() else { return Ok(()) };
    let chart = Chart::new(format!("{name}: distance to steady rolling"), "distance rolled", "max |q − q_steady| / p0")
        .x_unit(units.length.clone())
        .y_unit("1")
        .log_y()
        .add(Series::new(runs.first().map(|(_, x)| x.solver.name()).unwrap_or(""), pts, Style::Line));
    let file = figs.save(&chart, &format!("{name}-approach.svg"), format!("{name}: approach to steady rolling"))?;
    writeln!(
        md,
        "Against the steady-rolling solution of the same mesh (solved beside it, Lemke): after {end_x:.4} {} rolled \
         the largest traction difference is {end_d:.1e} p0. With one element rolled per substep the path's fixed point \
         is exactly the steady problem of the mesh (history module docs).\n\n![approach to steady rolling]({file})\n",
        units.length
    )
    .unwrap();
    Ok(())
}
