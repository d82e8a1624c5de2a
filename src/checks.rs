//! Checks of a scene's runs: each solver's status against the scene's expectation, its solver-independent residual
//! against its bound, the resultant against the prescribed load, Hertz and Cattaneo–Mindlin where they apply
//! ([`crate::references`]), and every pair of solvers against each other ([`compare`], the one definition of a
//! solver-vs-reference difference, shared with `rollbem report`).

use crate::post::NodeResult;
use crate::results::{Check, CheckKind, SolverRun};
use crate::scene::{Dof, ElementKind, Scene};
use crate::theory::Hertz2D;
use crate::tolerances as tol;

/// How two solvers' answers differ.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Comparison {
    /// max(|Δp|, |Δq|) over the nodes, divided by `a`'s pressure scale (its peak pressure, floored: see
    /// [`crate::post::ContactSummary::pressure_scale`]).
    pub max_dtraction: f64,
    /// Nodes that both solvers call decisively but differently (stick / slip / separated). A node is decisive for
    /// a run when its pressure is zero or above [`tol::STATE_MARGIN`] × the pressure scale, and | |q| − μp | is
    /// above [`tol::STATE_MARGIN`] × μ × the pressure scale: a node on the stick/slip boundary to within an
    /// iterative solver's tolerance may legitimately be called either.
    pub state_mismatches: usize,
}

/// Compare run `b` against run `a` (both solved, same nodes) for friction coefficient μ.
pub fn compare(a: &SolverRun, b: &SolverRun, mu: f64) -> Comparison {
    let p0 = a.contact.as_ref().map(|c| c.pressure_scale).unwrap_or(0.0).max(f64::MIN_POSITIVE);
    let max_dtraction = a
        .nodes
        .iter()
        .zip(&b.nodes)
        .fold(0.0_f64, |m, (x, y)| m.max((x.pressure - y.pressure).abs()).max((x.shear - y.shear).abs()))
        / p0;
    let decisive = |n: &NodeResult| {
        let pm = p0 * tol::STATE_MARGIN;
        (n.pressure <= 0.0 || n.pressure > pm) && (n.shear.abs() - mu * n.pressure).abs() > mu * pm
    };
    let state_mismatches =
        a.nodes.iter().zip(&b.nodes).filter(|(x, y)| x.state != y.state && decisive(x) && decisive(y)).count();
    Comparison { max_dtraction, state_mismatches }
}

fn check(name: String, measured: f64, reference: f64, tolerance: f64) -> Check {
    let error = if reference != 0.0 { (measured - reference).abs() / reference.abs() } else { measured.abs() };
    figure(name, measured, reference, error, tolerance, error <= tolerance)
}

/// A figure against a reference (the numbers mean what they say).
fn figure(name: String, measured: f64, reference: f64, error: f64, tolerance: f64, pass: bool) -> Check {
    Check {
        name,
        measured,
        reference,
        error,
        tolerance,
        pass,
        kind: CheckKind::Figure,
        note: None,
        model_error: None,
        uncertainty: None,
    }
}

/// A verdict without a figure: measured/error 0 when it passes, 1 when it fails; `note` says what was found.
fn verdict(name: String, pass: bool, note: Option<String>) -> Check {
    let e = if pass { 0.0 } else { 1.0 };
    Check {
        name,
        measured: e,
        reference: 0.0,
        error: e,
        tolerance: 0.0,
        pass,
        kind: CheckKind::Verdict,
        note,
        model_error: None,
        uncertainty: None,
    }
}

/// A reference that does not apply to this run: it passes, and the note says why.
fn not_applicable(name: String, why: String) -> Check {
    Check {
        name,
        measured: 0.0,
        reference: 0.0,
        error: 0.0,
        tolerance: 0.0,
        pass: true,
        kind: CheckKind::NotApplicable,
        note: Some(why),
        model_error: None,
        uncertainty: None,
    }
}

/// A count that may be fractional (quadratic elements: nodes / 3), shown with at most three decimals.
fn round3(v: f64) -> String {
    let t = format!("{v:.3}");
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Contact nodes per element of a family (nodes in contact / this = elements across the contact).
pub fn nodes_per_element(element: ElementKind) -> f64 {
    match element {
        ElementKind::Constant => 1.0,
        ElementKind::Quadratic => 3.0,
    }
}

/// The resolution check of a run with a loaded contact: at least `checks.contact_elements` (default
/// [`tol::MIN_CONTACT_ELEMENTS`]) elements across it. `None` when nothing is in contact.
pub fn resolution_check(scene: &Scene, element: ElementKind, element_length: f64, r: &SolverRun) -> Option<Check> {
    let contact = r.contact.as_ref().filter(|c| c.nodes_contact > 0)?;
    let across = contact.nodes_contact as f64 / nodes_per_element(element);
    let min = scene.expect().contact_elements.unwrap_or(tol::MIN_CONTACT_ELEMENTS);
    let pass = across >= min;
    let mut c = figure(
        format!("{}: elements across the contact (at least)", r.solver),
        across,
        min,
        (min - across).max(0.0),
        0.0,
        pass,
    );
    if !pass {
        let p = r.resultants.map_or(0.0, |x| x.normal);
        let a = crate::references::hertz_at(scene, p).a;
        let needed = (scene.zone().elements as f64 * element_length * min / (2.0 * a)).ceil();
        c.note = Some(format!(
            "the contact spans {} element(s) ({} loaded node(s)); at least {min} are needed for its width and \
             pressures to mean anything: refine the contact mesh (about contact_elements ≥ {needed:.0} for Hertz's \
             width 2a = {:.3e} at P = {p:.4e}) or narrow the candidate zone",
            round3(across),
            contact.nodes_contact,
            2.0 * a
        ));
    }
    Some(c)
}

/// Hertz's a and p0 for a run of a frictionless scene: figures when the reference applies and the elliptic fit
/// exists, a failed verdict when it applies and the fit fails, a note when the reference does not apply (too few
/// elements across Hertz's width, or a/R beyond the half-space theory).
fn hertz_checks(scene: &Scene, element: ElementKind, element_length: f64, r: &SolverRun, h: &Hertz2D) -> Vec<Check> {
    let Some(contact) = &r.contact else { return Vec::new() };
    let across = 2.0 * h.a / element_length;
    let a_over_r = h.a / scene.radius();
    let t = scene.expect().hertz.unwrap_or(match element {
        ElementKind::Constant => tol::HERTZ_CONSTANT,
        ElementKind::Quadratic => tol::HERTZ_QUADRATIC,
    });
    let name = |what: &str| format!("{}: Hertz {what}", r.solver);
    if across < tol::HERTZ_MIN_ELEMENTS {
        return vec![not_applicable(
            name("a and p0 (fit)"),
            format!(
                "{across:.3} elements across Hertz's contact width 2a = {:.3e}; its tolerance ({t:.1e}) needs at \
                 least {}",
                2.0 * h.a,
                tol::HERTZ_MIN_ELEMENTS
            ),
        )];
    }
    if a_over_r > tol::HERTZ_MAX_A_OVER_R {
        return vec![not_applicable(
            name("a and p0 (fit)"),
            format!("a/R = {a_over_r:.3} > {}: beyond the half-space theory", tol::HERTZ_MAX_A_OVER_R),
        )];
    }
    match (contact.fit_half_width, contact.fit_peak_pressure) {
        (Some(a), Some(p0)) => {
            vec![check(name("half-width a (fit)"), a, h.a, t), check(name("peak pressure p0 (fit)"), p0, h.p0, t)]
        }
        _ => vec![verdict(
            name("a and p0 (fit)"),
            false,
            Some(format!(
                "cannot be evaluated: the elliptic fit p² = p0²(1 − x²/a²) to the {} loaded node(s) failed (fewer than \
                 two, or a pressure that is not elliptic: not a Hertz-like contact)",
                contact.nodes_contact
            )),
        )],
    }
}

/// The run-level warnings of a scene's runs: a contact with too few elements across it, one line per distinct finding
/// with the solvers it concerns.
pub fn run_warnings(scene: &Scene, element: ElementKind, element_length: f64, runs: &[SolverRun]) -> Vec<String> {
    let mut found: Vec<(String, Vec<&str>)> = Vec::new();
    for run in runs {
        let c = resolution_check(scene, element, element_length, run);
        if let Some(note) = c.filter(|c| !c.pass).and_then(|c| c.note) {
            match found.iter_mut().find(|(n, _)| *n == note) {
                Some((_, solvers)) => solvers.push(run.solver.name()),
                None => found.push((note, vec![run.solver.name()])),
            }
        }
    }
    found.into_iter().map(|(note, solvers)| format!("{}: {note}", solvers.join(", "))).collect()
}

/// Every check of a scene's runs. `bounds[k]` is run k's residual check bound ([`crate::solvers::residual_bounds`]),
/// `element` the element family, `element_length` the contact element length (user's unit), `model` the half-plane
/// counterpart of a finite wheel compared with a half-space theory.
pub fn make_checks(
    scene: &Scene,
    element: ElementKind,
    element_length: f64,
    runs: &[SolverRun],
    bounds: &[f64],
    hertz: Option<&Hertz2D>,
    model: Option<&ModelReference>,
) -> Vec<Check> {
    let mut out = Vec::new();
    for (r, &bound) in runs.iter().zip(bounds) {
        out.extend(run_checks(scene, element, element_length, r, bound, hertz));
    }
    if let Some(w) = scene.strip_width() {
        out.push(not_applicable(
            "plane-strain theories (Hertz, Cattaneo–Mindlin, Carter)".into(),
            format!(
                "not compared: the contact is a strip of half-spaces {} wide (`mesh.strip_width`), CONTACT's 2D \
                 model, not the plane strain of the theories",
                if (1e-3..1e6).contains(&w) { format!("{w}") } else { format!("{w:e}") }
            ),
        ));
    }
    if scene.is_viscoelastic() {
        out.push(not_applicable(
            "elastic theories (Hertz, Cattaneo–Mindlin, Carter)".into(),
            "not compared: a body is viscoelastic (`viscoelastic = { ... }`), the theories are elastic".into(),
        ));
    }
    if scene.slip_velocity_friction().is_some() {
        out.push(not_applicable(
            "Coulomb theories (Cattaneo–Mindlin, Carter)".into(),
            "not compared: the friction falls with the slip velocity (`[contact] friction_law`), the theories are \
             Coulomb's"
                .into(),
        ));
    }
    if crate::references::cattaneo_applies(scene) {
        out.extend(cattaneo_checks(scene, runs, model));
    }
    out.extend(carter_checks(scene, element_length, runs, model));
    out.extend(agreement_checks(scene, runs));
    out
}

/// One run's own checks: its status against the expected one, its residual, its resultant, its resolution and
/// Hertz where Hertz applies.
fn run_checks(
    scene: &Scene,
    element: ElementKind,
    element_length: f64,
    r: &SolverRun,
    bound: f64,
    hertz: Option<&Hertz2D>,
) -> Vec<Check> {
    let mut out = Vec::new();
    let expected = scene.expect().status_for(r.solver);
    let ok = r.status == expected;
    out.push(verdict(format!("{}: status {} (expected {})", r.solver, r.status, expected), ok, None));
    let (Some(res), Some(_)) = (&r.residuals, &r.resultants) else {
        return out;
    };
    let bound = scene.expect().residual.unwrap_or(bound);
    out.push(figure(
        format!("{}: largest residual (absolute)", r.solver),
        res.max(),
        0.0,
        res.max(),
        bound,
        res.max() <= bound,
    ));
    if let (Some(Dof::Load(p)), Some(f)) = (scene.drive().map(|d| d.normal), &r.resultants) {
        out.push(check(format!("{}: resultant P = normal_load", r.solver), f.normal, p, tol::LOAD_RESULTANT));
    }
    out.extend(resolution_check(scene, element, element_length, r));
    if let Some(h) = hertz {
        out.extend(hertz_checks(scene, element, element_length, r, h));
    }
    out
}

/// The same problem on the model a theory assumes — the half-plane counterpart of a finite wheel
/// ([`crate::references::half_space_counterpart`]) — and its run (`None` when it did not run): what a model
/// comparison subtracts.
#[derive(Debug, Clone, Copy)]
pub struct ModelReference<'a> {
    /// The counterpart scene.
    pub scene: &'a Scene,
    /// Its run (one solver), if it produced one.
    pub run: Option<&'a SolverRun>,
}

/// A model comparison: a figure against a theory that does not hold for the scene, with the model error (measured
/// minus the same figure on the model the theory assumes) and its uncertainty.
fn model_comparison(name: String, measured: f64, theory: f64, on_model: f64, uncertainty: f64, note: String) -> Check {
    Check {
        name,
        measured,
        reference: theory,
        error: (measured - theory).abs(),
        tolerance: 0.0,
        pass: true,
        kind: CheckKind::ModelComparison,
        note: Some(note),
        model_error: Some(measured - on_model),
        uncertainty: Some(uncertainty),
    }
}

/// Why a finite wheel is compared with a half-space theory rather than checked against it.
fn finite_body_note(theory: &str, on_model: f64, model: &Scene) -> String {
    format!(
        "{theory} is a half-space theory; on the finite wheel (coupled through its curvature and support, an effect \
         of order a/R that no mesh refinement removes) the half-plane counterpart {} with the same loads and mesh gives \
         {on_model:.6e}",
        model.name()
    )
}

/// A counterpart that did not solve: the comparison cannot be evaluated, and says so.
fn counterpart_missing(name: String, model: Option<&ModelReference>) -> Check {
    let why = match model.and_then(|m| m.run) {
        Some(r) => format!("its half-plane counterpart ended {}: {}", r.status, r.explanation()),
        None => "its half-plane counterpart could not be run".into(),
    };
    verdict(name, false, Some(format!("cannot be evaluated: {why}")))
}

/// Cattaneo–Mindlin's stick zone: checked within a tolerance in elements where the theory holds (the half-plane
/// model), compared with the model error beside it on the finite wheel ([`crate::references::Domain`]).
fn cattaneo_checks(scene: &Scene, runs: &[SolverRun], model: Option<&ModelReference>) -> Vec<Check> {
    use crate::references::{decoupled_domain, element_length, metrics, Domain};
    let t = scene.expect().cattaneo_elements.unwrap_or(tol::CATTANEO_ELEMENTS);
    let elem = element_length(scene);
    let mut out = Vec::new();
    let finite = decoupled_domain(scene) == Domain::FiniteBody;
    let reference = model.and_then(|m| Some((m.scene, m.run.filter(|r| r.contact.is_some())?)));
    if let (true, Some((ms, mr))) = (finite, reference) {
        out.extend(cattaneo_figures("half-space counterpart", &metrics(ms, mr), t));
    }
    for r in runs.iter().filter(|r| r.contact.is_some()) {
        let m = metrics(scene, r);
        if !finite {
            out.extend(cattaneo_figures(r.solver.name(), &m, t));
            continue;
        }
        let name = |what: &str| format!("{}: Cattaneo–Mindlin {what} (finite wheel)", r.solver);
        let (Some((ms, mr)), Some(c), Some(ce), Some(centre)) =
            (reference, m.cm_c_over_a, m.cm_c_over_a_exact, m.cm_centre_elements)
        else {
            out.push(counterpart_missing(name("stick zone"), model));
            continue;
        };
        let mh = metrics(ms, mr);
        let a = hertz_at_load(scene, r);
        let (hc, hcentre) = (mh.cm_c_over_a.unwrap_or(0.0) * a, mh.cm_centre_elements.unwrap_or(0.0) * elem);
        let note = |v: f64| finite_body_note("Cattaneo–Mindlin", v, ms);
        out.push(model_comparison(name("stick-zone half-width c"), c * a, ce * a, hc, elem, note(hc)));
        out.push(model_comparison(name("stick-zone centre"), centre * elem, 0.0, hcentre, elem, note(hcentre)));
    }
    out
}

/// Hertz's half-width at a run's normal load.
fn hertz_at_load(scene: &Scene, r: &SolverRun) -> f64 {
    crate::references::hertz_at(scene, r.resultants.map_or(0.0, |x| x.normal)).a
}

/// The figure checks of Cattaneo–Mindlin's stick zone (half-width and centre, in elements) of one run's metrics,
/// or a failed verdict when nothing sticks.
fn cattaneo_figures(who: &str, m: &crate::references::Metrics, t: f64) -> Vec<Check> {
    match (m.cm_c_over_a, m.cm_c_over_a_exact, m.cm_c_err_elements, m.cm_centre_elements) {
        (Some(c), Some(ce), Some(err), Some(centre)) => vec![
            figure(format!("{who}: Cattaneo–Mindlin c/a (error in elements)"), c, ce, err.abs(), t, err.abs() <= t),
            figure(
                format!("{who}: Cattaneo–Mindlin stick-zone centre (elements)"),
                centre,
                0.0,
                centre.abs(),
                t,
                centre.abs() <= t,
            ),
        ],
        _ => vec![verdict(
            format!("{who}: Cattaneo–Mindlin stick zone exists"),
            false,
            Some("cannot be evaluated: no node sticks, where Cattaneo–Mindlin has a stick zone".into()),
        )],
    }
}

/// Carter's creep force (or, with the tangential load prescribed, the creepage) and stick zone where Carter is
/// compared (steady rolling, decoupled): checked within a tolerance on the half-plane model, compared with the
/// model error beside it on the finite wheel.
fn carter_checks(scene: &Scene, elem: f64, runs: &[SolverRun], model: Option<&ModelReference>) -> Vec<Check> {
    use crate::references::{decoupled_domain, metrics, Domain};
    let t = scene.expect().cattaneo_elements.unwrap_or(tol::CATTANEO_ELEMENTS);
    let finite = decoupled_domain(scene) == Domain::FiniteBody;
    let reference = model.and_then(|m| Some((m.scene, m.run.filter(|r| r.contact.is_some())?)));
    let mut out = Vec::new();
    if let (true, Some((ms, mr))) = (finite, reference) {
        out.extend(carter_figures(ms, "half-space counterpart", mr, elem, t));
    }
    for r in runs.iter().filter(|r| r.contact.is_some()) {
        if !finite {
            out.extend(carter_figures(scene, r.solver.name(), r, elem, t));
            continue;
        }
        let m = metrics(scene, r);
        let name = |what: &str| format!("{}: Carter {what} (finite wheel)", r.solver);
        let (Some(qm), Some(qe), Some(ce)) = (m.carter_q_over_mup, m.carter_q_over_mup_exact, m.carter_c_over_a_exact)
        else {
            continue;
        };
        let Some((ms, mr)) = reference else {
            out.push(counterpart_missing(name("creep force and stick zone"), model));
            continue;
        };
        let mh = metrics(ms, mr);
        let note = |v: f64| finite_body_note("Carter", v, ms);
        match creepages(scene, r, mr) {
            // The tangential load is prescribed: the creepage is the answer.
            Some((xi, xe, xh)) => out.push(model_comparison(name("creepage ξ"), xi, xe, xh, 0.0, note(xh))),
            None => {
                let qh = mh.carter_q_over_mup.unwrap_or(f64::NAN);
                out.push(model_comparison(name("Q/(μP)"), qm, qe, qh, 0.0, note(qh)));
            }
        }
        let a = hertz_at_load(scene, r);
        let c = m.carter_c_over_a.unwrap_or(0.0) * a;
        let hc = mh.carter_c_over_a.unwrap_or(0.0) * a;
        out.push(model_comparison(name("stick-zone half-width c"), c, ce * a, hc, elem, note(hc)));
    }
    out
}

/// With the tangential load prescribed in steady rolling: (computed ξ, Carter's ξ, the counterpart's ξ).
fn creepages(scene: &Scene, r: &SolverRun, mr: &SolverRun) -> Option<(f64, f64, f64)> {
    let computed = |r: &SolverRun| r.rolling.and_then(|x| (!x.creepage_prescribed).then_some(x.creepage).flatten());
    let (xi, xh) = (computed(r)?, computed(mr)?);
    Some((xi, carter_creepage(scene, r)?, xh))
}

/// Carter's creepage at a run's loads (with Q prescribed: [`crate::theory::carter_creepage`]).
fn carter_creepage(scene: &Scene, r: &SolverRun) -> Option<f64> {
    crate::references::carter_solution(scene, r).map(|c| c.creepage)
}

/// The figure checks of Carter where it holds: Q/(μP) with the creepage prescribed, the creepage with Q
/// prescribed, and the stick zone (half-width and centre, in elements).
fn carter_figures(scene: &Scene, who: &str, r: &SolverRun, elem: f64, t: f64) -> Vec<Check> {
    let m = crate::references::metrics(scene, r);
    let (Some(qm), Some(qe), Some(ce), Some(cerr)) =
        (m.carter_q_over_mup, m.carter_q_over_mup_exact, m.carter_c_over_a_exact, m.carter_c_err_elements)
    else {
        return Vec::new();
    };
    let a = hertz_at_load(scene, r);
    let mut out = Vec::new();
    let computed = r.rolling.and_then(|x| (!x.creepage_prescribed).then_some(x.creepage).flatten());
    match (computed, carter_creepage(scene, r)) {
        // Q prescribed: Q/(μP) is the input; the creepage is the answer. One element of stick zone moves
        // ξ = (μa/R)(1 − c/a) by μh/R.
        (Some(xi), Some(xe)) => {
            let tx = t * scene.friction() * elem / scene.radius();
            out.push(figure(format!("{who}: Carter creepage ξ"), xi, xe, (xi - xe).abs(), tx, (xi - xe).abs() <= tx));
        }
        _ => {
            // One element of stick zone moves Q/(μP) = 1 − (c/a)² by about 2(c/a)(h/a) + (h/a)².
            let tq = t * (2.0 * ce * elem / a + (elem / a).powi(2));
            out.push(figure(format!("{who}: Carter Q/(μP)"), qm, qe, (qm - qe).abs(), tq, (qm - qe).abs() <= tq));
        }
    }
    out.push(figure(
        format!("{who}: Carter stick-zone half-width c (error in elements)"),
        m.carter_c_over_a.unwrap_or(0.0),
        ce,
        cerr.abs(),
        t,
        cerr.abs() <= t,
    ));
    if let Some(centre) = m.carter_centre_err_elements {
        out.push(figure(
            format!("{who}: Carter stick zone at the leading edge (centre error, elements)"),
            centre,
            0.0,
            centre.abs(),
            t,
            centre.abs() <= t,
        ));
    }
    out
}

/// Solvers against each other: pressures and shears relative to the peak pressure, and active sets.
fn agreement_checks(scene: &Scene, runs: &[SolverRun]) -> Vec<Check> {
    let solved: Vec<&SolverRun> = runs.iter().filter(|r| r.contact.is_some()).collect();
    let mu = scene.friction();
    let t = scene.expect().agreement.unwrap_or(tol::SOLVER_AGREEMENT);
    let mut out = Vec::new();
    for i in 0..solved.len() {
        for b in &solved[i + 1..] {
            let a = solved[i];
            let c = compare(a, b, mu);
            out.push(figure(
                format!("{} vs {}: max |Δp|, |Δq| / p_max", a.solver, b.solver),
                c.max_dtraction,
                0.0,
                c.max_dtraction,
                t,
                c.max_dtraction <= t,
            ));
            let mism = c.state_mismatches as f64;
            out.push(figure(
                format!("{} vs {}: nodes in different states", a.solver, b.solver),
                mism,
                0.0,
                mism,
                0.0,
                c.state_mismatches == 0,
            ));
        }
    }
    out
}
