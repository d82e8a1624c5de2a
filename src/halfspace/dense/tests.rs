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

/// `μ p0/a · Σ_j w_j √(r_j² − r²)₊`: Mindlin's tractions as sums of Hertz-like distributions on the radii `r_j`.
fn hertz_sum(r2: f64, a: f64, p0: f64, terms: &[(f64, f64)]) -> f64 {
    MU * p0 / a * terms.iter().map(|(w, rj)| w * (rj * rj - r2).max(0.0).sqrt()).sum::<f64>()
}

/// Max and L2 errors of `q_x` against `theory(r²)`, relative to `μ p0` and to the theory's L2 norm.
fn traction_errors(grid: &ContactGrid, qx: &[f64], p0: f64, theory: impl Fn(f64) -> f64) -> (f64, f64) {
    let (mut emax, mut e2, mut n2) = (0.0_f64, 0.0, 0.0);
    for ((x, y), q) in grid.centres().iter().zip(qx) {
        let th = theory(x * x + y * y);
        emax = emax.max((q - th).abs() / (MU * p0));
        e2 += (q - th).powi(2);
        n2 += th * th;
    }
    (emax, (e2 / n2).sqrt())
}

/// Cattaneo–Mindlin on the circle, ν = 0 (then the normal and tangential problems uncouple and Mindlin's solution
/// is exact; Johnson §7.2): a force `Q = 0.5 μP` along x by the disc (clarabel). Expected: the stick radius
/// `c = a (1 − Q/μP)^(1/3)`, the traction `μp0/a (√(a² − r²) − √(c² − r²))` (Hertz's a and p0), the shift of
/// body 1 relative to body 2 `w_x = −(3μP/16a)·2(2 − ν)/G·[1 − (1 − Q/μP)^(2/3)]` (Johnson eq. 7.42 for two
/// identical bodies; negative: body 1 carries +Q, its slip tends to −x) and `q_y ≡ 0` (ν = 0: `C_xy = 0`).
/// Measured at 15 × 15 and 25 × 25 (12.5 and 20.8 elements across; the stick radius from the stick set's area):
/// every error falls with refinement and stays within 1.3 × the value measured (module docs, "Measured").
#[test]
fn cattaneo_mindlin_on_the_circle() {
    let ratio = 0.5;
    // Measured: [stick radius, traction max, traction L2, shift], relative.
    let measured = [[2.36e-2, 6.93e-2, 6.13e-2, 2.83e-3], [1.45e-2, 4.62e-2, 4.23e-2, 1.11e-4]];
    let mut errs = Vec::new();
    for m in [15, 25] {
        let c = case(0.0, 0.05, 0.05, m, Kernels::Full);
        let sh = DenseShift::new(&c.inf, &pressure(&c), MU, None).unwrap();
        let s = sh.disc(ShiftDrive::Force([ratio * MU * LOAD, 0.0]), &ConeSettings::default()).unwrap();
        assert!(s.status.is_solved() && s.disc_residual <= 1e-8, "{} {:e}", s.message, s.disc_residual);
        assert!((s.force[0] - ratio * MU * LOAD).abs() <= 1e-9 * LOAD && s.force[1] == 0.0, "{:?}", s.force);
        assert!(max_of(&s.qy) == 0.0 && s.shift[1] == 0.0);
        let (hz, g) = (c.hertz, sh.grid());
        let (a, cr) = (hz.a_x, hz.a_x * (1.0 - ratio).cbrt());
        let c_num = (s.stick.iter().filter(|s| **s).count() as f64 * g.area() / PI).sqrt();
        let (emax, el2) = traction_errors(g, &s.qx, hz.p0, |r2| hertz_sum(r2, a, hz.p0, &[(1.0, a), (-1.0, cr)]));
        let shear_modulus = E / 2.0;
        let mindlin = -3.0 * MU * LOAD / (16.0 * a) * 2.0 * 2.0 / shear_modulus * (1.0 - (1.0 - ratio).powf(2.0 / 3.0));
        let e = [(c_num / cr - 1.0).abs(), emax, el2, (s.shift[0] / mindlin - 1.0).abs()];
        println!(
            "Cattaneo {m} x {m}: stick radius, q max, q L2, shift errors {} ({} iterations, {:.3} s)",
            sci(&e),
            s.iterations,
            s.seconds
        );
        errs.push(e);
    }
    for j in 0..4 {
        assert!(errs[1][j] < errs[0][j], "measure {j} does not fall: {errs:?}");
        for l in 0..2 {
            assert!(errs[l][j] <= 1.3 * measured[l][j], "measure {j} level {l}: {:e}", errs[l][j]);
        }
    }
}

/// The disc by clarabel against its own optimality conditions and the sign of the force's multiplier (module docs,
/// 2a), on ν = 0.3 (so `C_xy ≠ 0`) with an oblique force `0.6 μP` at 30°: |q| ≤ μp everywhere (to 1e-9); where an
/// element slips (|s| above 1e-6 of the largest slip) its traction is opposite to its slip (cosine −1 to 1e-6) and
/// on the bound (to 1e-6); sticking elements have |s| ≤ 1e-6 of the largest slip; and the shift `w = σκ z_eq` read
/// off the equality's multiplier, prescribed, gives back the force (to 1e-8 of it) and the shears (to 1e-6 μp0: measured 2.4e-7, the interior point's
/// resolution of the elements at the stick–slip boundary, where its disc residual is 2e-7 too). A wrong sign of the
/// multiplier would give back −F.
#[test]
fn disc_optimality_and_the_force_multiplier_is_the_shift() {
    let c = case(0.3, 0.05, 0.05, 15, Kernels::Full);
    let p = pressure(&c);
    let sh = DenseShift::new(&c.inf, &p, MU, None).unwrap();
    let (fm, t) = (0.6 * MU * LOAD, PI / 6.0);
    let f = [fm * t.cos(), fm * t.sin()];
    let s = sh.disc(ShiftDrive::Force(f), &ConeSettings::default()).unwrap();
    assert!(s.status.is_solved(), "{}", s.message);
    let smax = s.sx.iter().zip(&s.sy).fold(0.0_f64, |m, (x, y)| m.max(x.hypot(*y)));
    let (mut slipping, mut sticking) = (0, 0);
    for &i in sh.contact() {
        let (q, sl, bound) = ([s.qx[i], s.qy[i]], [s.sx[i], s.sy[i]], MU * p[i]);
        assert!(norm(q) <= bound * (1.0 + 1e-9), "element {i}: |q| {:e} > μp {bound:e}", norm(q));
        if norm(sl) > 1e-6 * smax {
            let cosine = (q[0] * sl[0] + q[1] * sl[1]) / (norm(q) * norm(sl));
            assert!(cosine < -1.0 + 1e-6 && norm(q) >= bound * (1.0 - 1e-6), "element {i}: cos {cosine}");
            slipping += 1;
        }
        if s.stick[i] {
            assert!(norm(sl) <= 1e-6 * smax, "sticking element {i} slips {:e}", norm(sl));
            sticking += 1;
        }
    }
    assert!(slipping > 10 && sticking > 10, "{slipping} slipping, {sticking} sticking");
    let back = sh.disc(ShiftDrive::Shift(s.shift), &ConeSettings::default()).unwrap();
    assert!(norm([back.force[0] - f[0], back.force[1] - f[1]]) <= 1e-8 * fm, "{:?} vs {f:?}", back.force);
    let scale = MU * c.hertz.p0;
    let dq = max_abs_diff(&back.qx, &s.qx).max(max_abs_diff(&back.qy, &s.qy)) / scale;
    println!("shears force- vs shift-driven: {dq:.1e} of μp0");
    assert!(dq <= 1e-6, "{dq:e}");
    println!(
        "disc: {} iterations, {:.3} s, residual {:.1e}; back: residual {:.1e}",
        s.iterations, s.seconds, s.disc_residual, back.disc_residual
    );
}

/// Memory (the previous shears q′), ν = 0, 15 × 15 and 25 × 25: (i) loading to `0.3 μP` then to `0.6 μP` in two
/// steps gives the one-step answer (Mindlin–Deresiewicz: under a monotone load the state does not depend on the
/// path), to 1e-6 μp0; (ii) unloading from `Q* = 0.6 μP` to `Q = 0.2 μP` gives Mindlin–Deresiewicz's traction
/// `μp0/a [−√(a² − r²) + 2√(b² − r²) − √(c² − r²)]`, `b = a (1 − (Q* − Q)/2μP)^(1/3)`, `c = a (1 − Q*/μP)^(1/3)`
/// (Johnson §7.2), with a reversed-slip annulus `b < r < a`; error measured at both levels, falling, within 1.3 ×.
#[test]
fn memory_loading_path_and_unloading() {
    let measured = [[1.19e-1, 1.83e-1], [6.66e-2, 9.84e-2]];
    let mut errs = Vec::new();
    for m in [15, 25] {
        let c = case(0.0, 0.05, 0.05, m, Kernels::Full);
        let p = pressure(&c);
        let set = ConeSettings::default();
        let solve = |prev: Option<(&[f64], &[f64])>, q: f64| {
            let s = DenseShift::new(&c.inf, &p, MU, prev)
                .unwrap()
                .disc(ShiftDrive::Force([q * MU * LOAD, 0.0]), &set)
                .unwrap();
            assert!(s.status.is_solved(), "{}", s.message);
            s
        };
        let one = solve(None, 0.6);
        let half = solve(None, 0.3);
        let two = solve(Some((&half.qx, &half.qy)), 0.6);
        let scale = MU * c.hertz.p0;
        assert!(max_abs_diff(&one.qx, &two.qx) <= 1e-6 * scale, "{:e}", max_abs_diff(&one.qx, &two.qx) / scale);
        let down = solve(Some((&one.qx, &one.qy)), 0.2);
        let (a, p0) = (c.hertz.a_x, c.hertz.p0);
        let (b, cr) = (a * (1.0 - 0.4 / 2.0_f64).cbrt(), a * 0.4_f64.cbrt());
        let e =
            traction_errors(c.inf.grid(), &down.qx, p0, |r2| hertz_sum(r2, a, p0, &[(-1.0, a), (2.0, b), (-1.0, cr)]));
        println!(
            "unloading {m} x {m}: q max, q L2 errors {:.2e}, {:.2e}; two steps vs one {:.1e}",
            e.0,
            e.1,
            max_abs_diff(&one.qx, &two.qx) / scale
        );
        errs.push([e.0, e.1]);
    }
    for j in 0..2 {
        assert!(errs[1][j] < errs[0][j], "measure {j} does not fall: {errs:?}");
        for l in 0..2 {
            assert!(errs[l][j] <= 1.3 * measured[l][j], "measure {j} level {l}: {:e}", errs[l][j]);
        }
    }
}

/// The least-squares slope of `ln e` against `ln k`: the measured order (negative: falling).
fn slope(k: &[f64], e: &[f64]) -> f64 {
    let n = k.len() as f64;
    let (lk, le): (Vec<f64>, Vec<f64>) = (k.iter().map(|v| v.ln()).collect(), e.iter().map(|v| v.ln()).collect());
    let (mk, me) = (lk.iter().sum::<f64>() / n, le.iter().sum::<f64>() / n);
    let num: f64 = lk.iter().zip(&le).map(|(a, b)| (a - mk) * (b - me)).sum();
    num / lk.iter().map(|a| (a - mk).powi(2)).sum::<f64>()
}

/// The pyramid's error against the disc, k = 4, 8, 16, 32, on the same grid and pressure (11 × 11 over ±1.2a,
/// ν = 0.3, 69 elements in contact: LCPs of 345 to 2 281 rows, kept small for Lemke's dense O(m²) pivots). The
/// reference is the disc by clarabel with the force `0.6 μP` at 30° (between the vertices of every k-gon here);
/// the pyramid is driven by the disc's shift (errors of the force and the tractions) and by the force (error of
/// the shift). Expected from the geometry (module docs, 2b): the polygon is inscribed, so its tractions never leave
/// the disc (checked to 1e-12); the set's error is `1 − cos(π/k) ~ k⁻²`, the direction of a vertex traction is off
/// by up to `π/k`. Measured (asserted within 1.3 ×, each falling with k, and the fitted orders): total force
/// `k^-2.4`, shift `k^-2.5`, per-element traction max-norm and disc residual `k^-1` — the tractions converge at
/// first order only, the force (an average over the patch) at second.
#[test]
fn the_pyramid_converges_to_the_disc() {
    let c = case(0.3, 0.05, 0.05, 11, Kernels::Full);
    let p = pressure(&c);
    let sh = DenseShift::new(&c.inf, &p, MU, None).unwrap();
    let (fm, t) = (0.6 * MU * LOAD, PI / 6.0);
    let f = [fm * t.cos(), fm * t.sin()];
    let disc = sh.disc(ShiftDrive::Force(f), &ConeSettings::default()).unwrap();
    assert!(disc.status.is_solved());
    let scale = MU * c.hertz.p0;
    let ks = [4.0, 8.0, 16.0, 32.0];
    // Measured: [force, traction max, disc residual, shift] per k.
    let measured = [
        [3.66e-2, 1.73e-1, 1.85e-1, 8.95e-2],
        [9.80e-3, 7.42e-2, 8.06e-2, 1.75e-2],
        [2.93e-3, 3.65e-2, 3.98e-2, 5.08e-3],
        [2.32e-4, 2.19e-2, 2.09e-2, 4.66e-4],
    ];
    let mut errs = Vec::new();
    for (row, &kf) in ks.iter().enumerate() {
        let k = kf as usize;
        let ps = sh.pyramid(k, ShiftDrive::Shift(disc.shift), &LemkeSettings::default()).unwrap();
        let pf = sh.pyramid(k, ShiftDrive::Force(f), &LemkeSettings::default()).unwrap();
        for s in [&ps, &pf] {
            assert!(s.status.is_solved(), "{}", s.message);
            for &i in sh.contact() {
                let q = [s.qx[i], s.qy[i]];
                assert!(norm(q) <= MU * p[i] * (1.0 + 1e-12) && polygon_gauge(q, MU * p[i], k) <= 1.0 + 1e-12);
            }
        }
        assert!(norm([pf.force[0] - f[0], pf.force[1] - f[1]]) <= 1e-10 * fm, "{:?}", pf.force);
        let dq = (0..p.len()).fold(0.0_f64, |m, i| m.max(norm([ps.qx[i] - disc.qx[i], ps.qy[i] - disc.qy[i]])));
        let e = [
            norm([ps.force[0] - f[0], ps.force[1] - f[1]]) / (MU * LOAD),
            dq / scale,
            ps.disc_residual,
            norm([pf.shift[0] - disc.shift[0], pf.shift[1] - disc.shift[1]]) / norm(disc.shift),
        ];
        println!(
            "k = {k}: force, traction, residual, shift errors {} | shift-driven {} pivots {:.3} s, force-driven {} pivots {:.3} s",
            sci(&e), ps.iterations, ps.seconds, pf.iterations, pf.seconds
        );
        for j in 0..4 {
            assert!(e[j] <= 1.3 * measured[row][j], "k = {k} measure {j}: {:e}", e[j]);
        }
        errs.push(e);
    }
    let orders: Vec<f64> = (0..4).map(|j| slope(&ks, &errs.iter().map(|e| e[j]).collect::<Vec<_>>())).collect();
    println!("fitted orders (force, traction, residual, shift): {}", sci(&orders));
    for j in 0..4 {
        assert!(errs.windows(2).all(|w| w[1][j] < w[0][j]), "measure {j} does not fall with k: {errs:?}");
    }
    assert!(orders[0] < -1.5 && orders[3] < -1.5, "force and shift orders {orders:?}");
    assert!(orders[1] < -0.7 && orders[2] < -0.7, "traction and residual orders {orders:?}");
}

/// A force beyond what the friction set carries is the status `gross_sliding`, not a panic nor an error: `1.01 μP`
/// for the disc and for the 8-gon (a vertex on x), both by the exact pre-check and by the solvers themselves when
/// asked directly (clarabel's infeasibility certificate; Lemke's ray on the positive semi-definite LCP); `0.9 μP`
/// at 45° exceeds the inscribed square (`μP cos 45°`) but not the disc. No element in contact: a zero shift or
/// force is solved with no shear, a non-zero force slides. A tensile load is `infeasible` for both normal solvers.
#[test]
fn gross_sliding_and_infeasible_loads_are_statuses() {
    let c = case(0.3, 0.05, 0.05, 9, Kernels::Full);
    let p = pressure(&c);
    let sh = DenseShift::new(&c.inf, &p, MU, None).unwrap();
    let cone = ConeSettings::default();
    let lemke = LemkeSettings::default();
    let over = ShiftDrive::Force([1.01 * MU * LOAD, 0.0]);
    assert_eq!(sh.disc(over, &cone).unwrap().status, DenseStatus::GrossSliding);
    assert_eq!(sh.pyramid(8, over, &lemke).unwrap().status, DenseStatus::GrossSliding);
    assert_eq!(sh.disc_solve(over, &cone).status, DenseStatus::GrossSliding);
    assert_eq!(sh.pyramid_solve(8, over, &lemke).status, DenseStatus::GrossSliding);
    let diagonal = ShiftDrive::Force([0.9 * MU * LOAD / 2.0_f64.sqrt(); 2]);
    assert_eq!(sh.pyramid(4, diagonal, &lemke).unwrap().status, DenseStatus::GrossSliding);
    assert_eq!(sh.pyramid_solve(4, diagonal, &lemke).status, DenseStatus::GrossSliding);
    assert!(sh.disc(diagonal, &cone).unwrap().status.is_solved());
    assert!(sh.pyramid(8, diagonal, &lemke).unwrap().status.is_solved());
    let gross = sh.disc(over, &cone).unwrap();
    assert!(gross.message.contains("gross sliding") && Termination::from(gross.status) == Termination::Infeasible);

    let free = DenseShift::new(&c.inf, &vec![0.0; p.len()], MU, None).unwrap();
    let s = free.disc(ShiftDrive::Shift([1e-3, 0.0]), &cone).unwrap();
    assert!(s.status.is_solved() && max_of(&s.qx) == 0.0 && s.shift == [1e-3, 0.0]);
    assert!(free.pyramid(4, ShiftDrive::Force([0.0; 2]), &lemke).unwrap().status.is_solved());
    assert_eq!(free.disc(ShiftDrive::Force([1.0, 0.0]), &cone).unwrap().status, DenseStatus::GrossSliding);

    let dn = DenseNormal::new(&c.inf, &c.h).unwrap();
    assert_eq!(dn.lemke(NormalDrive::Load(-1.0), &lemke).unwrap().status, DenseStatus::Infeasible);
    assert_eq!(dn.clarabel(NormalDrive::Load(-1.0), &QpSettings::default()).unwrap().status, DenseStatus::Infeasible);
    let zero = dn.lemke(NormalDrive::Load(0.0), &lemke).unwrap();
    assert!(zero.status.is_solved() && max_of(&zero.pressure) == 0.0 && zero.approach == 0.0);
}

/// Bad input is refused with an [`ArgumentError`] naming the argument; nothing panics.
#[test]
fn bad_input_is_refused_by_name() {
    let c = case(0.3, 0.05, 0.05, 7, Kernels::Full);
    let n = c.h.len();
    let arg = |e: ArgumentError| e.argument;
    assert_eq!(arg(DenseNormal::new(&c.inf, &c.h[1..]).unwrap_err()), "separation");
    let mut nan = c.h.clone();
    nan[3] = f64::NAN;
    assert_eq!(arg(DenseNormal::new(&c.inf, &nan).unwrap_err()), "separation");
    let dn = DenseNormal::new(&c.inf, &c.h).unwrap();
    assert_eq!(arg(dn.lemke(NormalDrive::Approach(f64::NAN), &LemkeSettings::default()).unwrap_err()), "drive");
    assert_eq!(arg(dn.clarabel(NormalDrive::Load(f64::INFINITY), &QpSettings::default()).unwrap_err()), "drive");
    assert_eq!(arg(dn.gap(&c.h[1..], 0.0).unwrap_err()), "pressure");
    let p = vec![1.0; n];
    let normal_only = Influence::new(*c.inf.grid(), HalfSpace::new(E, 0.3).unwrap().compliance(), Kernels::Normal);
    assert_eq!(arg(DenseShift::new(&normal_only.unwrap(), &p, MU, None).unwrap_err()), "influence");
    let mut neg = p.clone();
    neg[0] = -1.0;
    assert_eq!(arg(DenseShift::new(&c.inf, &neg, MU, None).unwrap_err()), "pressure");
    for mu in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(arg(DenseShift::new(&c.inf, &p, mu, None).unwrap_err()), "mu");
    }
    assert_eq!(arg(DenseShift::new(&c.inf, &p, MU, Some((&p, &p[1..]))).unwrap_err()), "previous");
    let sh = DenseShift::new(&c.inf, &p, MU, None).unwrap();
    let s = ShiftDrive::Shift([0.0; 2]);
    assert_eq!(arg(sh.pyramid(2, s, &LemkeSettings::default()).unwrap_err()), "facets");
    assert_eq!(arg(sh.pyramid(1025, s, &LemkeSettings::default()).unwrap_err()), "facets");
    let big = sh.pyramid(400, s, &LemkeSettings::default()).unwrap_err();
    assert!(big.argument == "facets" && big.message.contains("16384"), "{big}");
    let bad = ShiftDrive::Force([f64::NAN, 0.0]);
    assert_eq!(arg(sh.disc(bad, &ConeSettings::default()).unwrap_err()), "drive");
    assert_eq!(arg(ConeSettings::new(0.0, 10).unwrap_err()), "tolerance");
    assert_eq!(arg(ConeSettings::new(1e-8, 0).unwrap_err()), "max_iter");
    let huge = ContactGrid::new(65, 64, 1.0, 1.0, 0.0, 0.0).unwrap();
    let inf = Influence::new(huge, HalfSpace::new(E, 0.3).unwrap().compliance(), Kernels::Full).unwrap();
    assert!(DenseNormal::new(&inf, &vec![0.0; huge.len()]).unwrap_err().message.contains("4096"));
}
