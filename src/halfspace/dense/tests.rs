//! Tests of the dense formulations. Each says where its expected values come from: a peer solver on the same
//! matrices, a theory (Hertz, Cattaneo–Mindlin, Mindlin–Deresiewicz: K.L. Johnson, *Contact Mechanics*, CUP 1985,
//! §4.2, §7.2), or the problem's own optimality conditions. Discretisation errors are measured at two grid levels,
//! asserted to fall, and bounded by the measured values (with the margins stated) so that a regression shows.

use super::super::{HalfSpace, Kernels};
use super::*;
use crate::theory::Hertz3D;

/// Steel on steel (MPa, mm): E = 210 000 for both bodies (alike: no coupling), the load 1 000 N.
const E: f64 = 210e3;
const LOAD: f64 = 1000.0;
const MU: f64 = 0.3;

struct Case {
    inf: Influence,
    h: Vec<f64>,
    hertz: Hertz3D,
}

/// Hertz's contact of the separation `ca x² + cb y²` (1/mm) between two identical half-spaces of Poisson's ratio
/// `nu` under [`LOAD`], on an `m × m` grid covering ±1.2 semi-axes (elements of the contact's aspect).
fn case(nu: f64, ca: f64, cb: f64, m: usize, kernels: Kernels) -> Case {
    let body = HalfSpace::new(E, nu).unwrap();
    let e_star = E / (2.0 * (1.0 - nu * nu));
    let hertz = Hertz3D::from_load(ca, cb, e_star, LOAD).unwrap();
    let (ax, ay) = (1.2 * hertz.a_x, 1.2 * hertz.a_y);
    let grid = ContactGrid::covering(m, m, -ax, ax, -ay, ay).unwrap();
    let inf = Influence::new(grid, body.pair(&body), kernels).unwrap();
    let h = grid.sample(|x, y| ca * x * x + cb * y * y);
    Case { inf, h, hertz }
}

/// The pressure of the load-driven problem by Lemke.
fn pressure(c: &Case) -> Vec<f64> {
    let dn = DenseNormal::new(&c.inf, &c.h).unwrap();
    let s = dn.lemke(NormalDrive::Load(LOAD), &LemkeSettings::default()).unwrap();
    assert!(s.status.is_solved(), "{}", s.message);
    s.pressure
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

fn max_of(a: &[f64]) -> f64 {
    a.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
}

/// Semi-axes from the second moments of the pressure: for Hertz's pressure `⟨x²⟩ = a²/5`, `⟨y²⟩ = b²/5`.
fn moment_axes(grid: &ContactGrid, p: &[f64]) -> (f64, f64) {
    let c = grid.centres();
    let total: f64 = p.iter().sum();
    let mx: f64 = p.iter().zip(&c).map(|(p, (x, _))| p * x * x).sum::<f64>() / total;
    let my: f64 = p.iter().zip(&c).map(|(p, (_, y))| p * y * y).sum::<f64>() / total;
    ((5.0 * mx).sqrt(), (5.0 * my).sqrt())
}

/// Two independent solvers on the same matrices (a peer check): Lemke's pivoting and clarabel's interior point
/// with its polish agree on the pressure to 1e-10 of p0 and on the approach to 1e-10 of it, load- and
/// approach-driven, on a circle and an ellipse (15 × 15, 12.5 elements across; measured: 1.6e-14 and 6e-16);
/// prescribing the approach found with the load gives back the load and the pressure; both residuals ≤ 1e-12.
#[test]
fn lemke_and_clarabel_agree_on_the_normal_problem() {
    for (ca, cb) in [(0.05, 0.05), (0.05, 0.15)] {
        let c = case(0.3, ca, cb, 15, Kernels::Normal);
        let dn = DenseNormal::new(&c.inf, &c.h).unwrap();
        let l = dn.lemke(NormalDrive::Load(LOAD), &LemkeSettings::default()).unwrap();
        let q = dn.clarabel(NormalDrive::Load(LOAD), &QpSettings::default()).unwrap();
        let d = l.approach;
        let la = dn.lemke(NormalDrive::Approach(d), &LemkeSettings::default()).unwrap();
        let qa = dn.clarabel(NormalDrive::Approach(d), &QpSettings::default()).unwrap();
        let p0 = c.hertz.p0;
        for s in [&l, &q, &la, &qa] {
            assert!(s.status.is_solved() && s.residual <= 1e-12, "{:?} {}: {:e}", s.status, s.message, s.residual);
            assert!(max_abs_diff(&s.pressure, &l.pressure) <= 1e-10 * p0, "{}", s.message);
            assert!((s.approach - d).abs() <= 1e-10 * d && (s.load - LOAD).abs() <= 1e-10 * LOAD, "{}", s.message);
            assert!(s.gap.iter().all(|g| *g >= -1e-12 * d));
        }
        assert!(l.contact.iter().filter(|c| **c).count() > 50);
    }
}

/// Measures of a discrete normal solution against Hertz: (p0, approach, a, b, pressure L2), relative errors.
fn hertz_errors(c: &Case, s: &NormalSolution) -> [f64; 5] {
    let (hz, g) = (c.hertz, c.inf.grid());
    let (a, b) = moment_axes(g, &s.pressure);
    let (mut e2, mut n2) = (0.0, 0.0);
    for ((x, y), p) in g.centres().iter().zip(&s.pressure) {
        let th = hz.p0 * (1.0 - (x / hz.a_x).powi(2) - (y / hz.a_y).powi(2)).max(0.0).sqrt();
        e2 += (p - th).powi(2);
        n2 += th * th;
    }
    [
        max_of(&s.pressure) / hz.p0 - 1.0,
        s.approach / hz.approach - 1.0,
        a / hz.a_x - 1.0,
        b / hz.a_y - 1.0,
        (e2 / n2).sqrt(),
    ]
    .map(f64::abs)
}

/// Against Hertz (Johnson §4.2: p0, the approach, the semi-axes) on a circle and on an ellipse of curvature ratio
/// B/A = 3, at two grid levels (15 × 15 and 25 × 25 over ±1.2 semi-axes: 12.5 and 20.8 elements across each axis).
/// The semi-axes are read off the pressure's second moments (Hertz: `⟨x²⟩ = a²/5`). Every error falls with the
/// refinement and stays within 1.3 × the value measured (module docs, "Measured").
#[test]
fn the_normal_problem_converges_to_hertz() {
    // Measured errors [p0, approach, a, b, L2] at the two levels, circle then ellipse.
    let measured = [
        [[1.61e-3, 6.41e-4, 2.24e-3, 2.24e-3, 2.13e-2], [2.67e-4, 5.26e-4, 2.90e-4, 2.90e-4, 1.77e-2]],
        [[1.57e-3, 6.24e-4, 2.12e-3, 2.32e-3, 2.14e-2], [2.54e-4, 5.26e-4, 2.24e-4, 3.40e-4, 1.72e-2]],
    ];
    for (k, (ca, cb)) in [(0.05, 0.05), (0.05, 0.15)].into_iter().enumerate() {
        let mut errs = Vec::new();
        for m in [15, 25] {
            let c = case(0.3, ca, cb, m, Kernels::Normal);
            let dn = DenseNormal::new(&c.inf, &c.h).unwrap();
            let s = dn.lemke(NormalDrive::Load(LOAD), &LemkeSettings::default()).unwrap();
            let e = hertz_errors(&c, &s);
            println!(
                "B/A = {:.0}, a/b = {:.3}, {m} x {m}: p0, d, a, b, L2 errors {} ({} pivots, {:.3} s)",
                cb / ca,
                c.hertz.a_x / c.hertz.a_y,
                sci(&e),
                s.iterations,
                s.seconds
            );
            errs.push(e);
        }
        for j in 0..5 {
            assert!(errs[1][j] < errs[0][j], "measure {j} does not fall: {errs:?}");
            for l in 0..2 {
                let bound = measured[k][l][j];
                assert!(errs[l][j] <= 1.3 * bound, "measure {j} level {l}: {:e} > {bound:e}", errs[l][j]);
            }
        }
    }
}

fn sci(v: &[f64]) -> String {
    v.iter().map(|x| format!("{x:.2e}")).collect::<Vec<_>>().join(", ")
}
