//! Checks of a scene's runs: each solver's status against the scene's expectation, its solver-independent residual
//! against its bound, the resultant against the prescribed load, Hertz and Cattaneo–Mindlin where they apply
//! ([`crate::references`]), and every pair of solvers against each other ([`compare`], the one definition of a
//! solver-vs-reference difference, shared with `rollbem report`).

use crate::hertz::Hertz;
use crate::post::NodeResult;
use crate::results::{Check, SolverRun};
use crate::scene::{Dof, ElementKind, Scene};
use crate::tolerances as tol;

/// How two solvers' answers differ.
#[derive(Debug, Clone, Copy, PartialEq)]
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
    Check { name, measured, reference, error, tolerance, pass: error <= tolerance }
}

/// Every check of a scene's runs. `bounds[k]` is run k's residual check bound ([`crate::solvers::residual_bounds`]),
/// `element` the element family, `element_length` the contact element length (user's unit).
pub fn make_checks(
    scene: &Scene,
    element: ElementKind,
    element_length: f64,
    runs: &[SolverRun],
    bounds: &[f64],
    hertz: Option<&Hertz>,
) -> Vec<Check> {
    let mut out = Vec::new();
    for (r, &bound) in runs.iter().zip(bounds) {
        let expected = scene.checks.status_for(r.solver.0);
        let ok = r.status == expected;
        out.push(Check {
            name: format!("{}: status {} (expected {})", r.solver, r.status, expected),
            measured: if ok { 0.0 } else { 1.0 },
            reference: 0.0,
            error: if ok { 0.0 } else { 1.0 },
            tolerance: 0.0,
            pass: ok,
        });
        let (Some(res), Some(resultants), Some(contact)) = (&r.residuals, &r.resultants, &r.contact) else {
            continue;
        };
        let bound = scene.checks.residual.unwrap_or(bound);
        out.push(Check {
            name: format!("{}: largest residual (absolute)", r.solver),
            measured: res.max(),
            reference: 0.0,
            error: res.max(),
            tolerance: bound,
            pass: res.max() <= bound,
        });
        if let Dof::Load(p) = scene.drive.normal() {
            out.push(check(
                format!("{}: resultant P = normal_load", r.solver),
                resultants.normal,
                p,
                tol::LOAD_RESULTANT,
            ));
        }
        if let Some(h) = hertz {
            let across = 2.0 * h.half_width / element_length;
            let applies =
                across >= tol::HERTZ_MIN_ELEMENTS && h.half_width / scene.wheel.radius <= tol::HERTZ_MAX_A_OVER_R;
            let t = scene.checks.hertz.unwrap_or(match element {
                ElementKind::Constant => tol::HERTZ_CONSTANT,
                ElementKind::Quadratic => tol::HERTZ_QUADRATIC,
            });
            if applies {
                if let (Some(a), Some(p0)) = (contact.fit_half_width, contact.fit_peak_pressure) {
                    out.push(check(format!("{}: Hertz half-width a (fit)", r.solver), a, h.half_width, t));
                    out.push(check(format!("{}: Hertz peak pressure p0 (fit)", r.solver), p0, h.peak_pressure, t));
                }
            }
        }
    }
    // Cattaneo–Mindlin where it applies.
    if crate::references::cattaneo_applies(scene) {
        let t = scene.checks.cattaneo_elements.unwrap_or(tol::CATTANEO_ELEMENTS);
        for r in runs.iter().filter(|r| r.contact.is_some()) {
            let m = crate::references::metrics(scene, r);
            if let (Some(c), Some(ce), Some(err), Some(centre)) =
                (m.cm_c_over_a, m.cm_c_over_a_exact, m.cm_c_err_elements, m.cm_centre_elements)
            {
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin c/a (error in elements)", r.solver),
                    measured: c,
                    reference: ce,
                    error: err.abs(),
                    tolerance: t,
                    pass: err.abs() <= t,
                });
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin stick-zone centre (elements)", r.solver),
                    measured: centre,
                    reference: 0.0,
                    error: centre.abs(),
                    tolerance: t,
                    pass: centre.abs() <= t,
                });
            } else {
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin stick zone exists", r.solver),
                    measured: 0.0,
                    reference: 1.0,
                    error: 1.0,
                    tolerance: 0.0,
                    pass: false,
                });
            }
        }
    }
    // Carter where it applies (steady rolling, β = 0).
    let elem = element_length;
    for r in runs.iter().filter(|r| r.contact.is_some()) {
        let m = crate::references::metrics(scene, r);
        let (Some(qm), Some(qe), Some(ce), Some(cerr)) =
            (m.carter_q_over_mup, m.carter_q_over_mup_exact, m.carter_c_over_a_exact, m.carter_c_err_elements)
        else {
            continue;
        };
        let t = scene.checks.cattaneo_elements.unwrap_or(tol::CATTANEO_ELEMENTS);
        let a = crate::references::hertz_at(scene, r.resultants.map_or(0.0, |x| x.normal)).half_width;
        // One element of stick zone moves Q/(μP) = 1 − (c/a)² by about 2(c/a)(h/a) + (h/a)².
        let tq = t * (2.0 * ce * elem / a + (elem / a).powi(2));
        out.push(Check {
            name: format!("{}: Carter Q/(μP)", r.solver),
            measured: qm,
            reference: qe,
            error: (qm - qe).abs(),
            tolerance: tq,
            pass: (qm - qe).abs() <= tq,
        });
        out.push(Check {
            name: format!("{}: Carter stick-zone half-width c (error in elements)", r.solver),
            measured: m.carter_c_over_a.unwrap_or(0.0),
            reference: ce,
            error: cerr.abs(),
            tolerance: t,
            pass: cerr.abs() <= t,
        });
        if let Some(centre) = m.carter_centre_err_elements {
            out.push(Check {
                name: format!("{}: Carter stick zone at the leading edge (centre error, elements)", r.solver),
                measured: centre,
                reference: 0.0,
                error: centre.abs(),
                tolerance: t,
                pass: centre.abs() <= t,
            });
        }
    }
    // Solvers against each other: pressures and shears relative to the peak pressure, and active sets.
    let solved: Vec<&SolverRun> = runs.iter().filter(|r| r.contact.is_some()).collect();
    let mu = scene.contact.friction;
    for i in 0..solved.len() {
        for j in i + 1..solved.len() {
            let (a, b) = (solved[i], solved[j]);
            let c = compare(a, b, mu);
            let t = scene.checks.agreement.unwrap_or(tol::SOLVER_AGREEMENT);
            out.push(Check {
                name: format!("{} vs {}: max |Δp|, |Δq| / p_max", a.solver, b.solver),
                measured: c.max_dtraction,
                reference: 0.0,
                error: c.max_dtraction,
                tolerance: t,
                pass: c.max_dtraction <= t,
            });
            out.push(Check {
                name: format!("{} vs {}: nodes in different states (stick/slip/separated)", a.solver, b.solver),
                measured: c.state_mismatches as f64,
                reference: 0.0,
                error: c.state_mismatches as f64,
                tolerance: 0.0,
                pass: c.state_mismatches == 0,
            });
        }
    }
    out
}
