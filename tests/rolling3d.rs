//! Steady rolling on the half-space (`rollbem::halfspace::rolling`, issue 36) against independent answers:
//!
//! - the limit of transient rolling, marched here by the shift solver (`halfspace::tangential`, itself checked
//!   against clarabel's cone program) with the previous shears carried one element downstream per step — the same
//!   discrete equations reached by another method;
//! - the mirror image of a problem rolling the other way (the half-space's reflection symmetry);
//! - CONTACT's steady-rolling performance inputs `tang_problm_1c` (creepages prescribed) and `1f` (forces
//!   prescribed), element by element (`reference/contact3d/`, from our MKL build of CONTACT r2707; their slip counts
//!   equal the author's `perfc_test/get_times.ref_out`);
//! - Kalker's linear theory: C11, C22, C23 of Table E.3 (`theory::kalker`) in full adhesion, and the reciprocity
//!   C32 = −C23 (Betti's theorem);
//! - full sliding: at a creepage far beyond saturation the force tends to μ F_n against the creepage.

use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::{self, Drive, NormalSettings};
use rollbem::halfspace::rolling::{self, RollingDirection, RollingDrive, RollingSettings, RollingStop, SteadyRolling};
use rollbem::halfspace::tangential::{self, ElementState, ShiftStep, TangentialDrive, TangentialSettings};
use rollbem::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use rollbem::theory::kalker;

#[path = "common/contact_ref.rs"]
mod contact_ref;
use contact_ref::{csv, half_unit, num};

/// A Hertzian ellipse (semi-axes 1 and 0.8, p0 = 0.01, G = 1, ν = 0.28) on a 26 × 22 grid of 0.09: the pressure
/// sampled from Hertz's formula at the element centres (the tangential problem only needs some pressure).
fn ellipse() -> (Influence, Vec<f64>) {
    let h = 0.09;
    let grid = ContactGrid::new(26, 22, h, h, -12.5 * h, -10.5 * h).unwrap();
    let body = HalfSpace::new(2.0 * 1.28, 0.28).unwrap();
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full).unwrap();
    let p = grid.sample(|x, y| 0.01 * (1.0 - x * x - y * y / 0.64).max(0.0).sqrt());
    (inf, p)
}

/// The shears one element downstream: the traction each particle carried one step earlier (rolling along +x the
/// material moves to smaller x; nothing enters at the leading edge).
fn carried(q: &[f64], mx: usize) -> Vec<f64> {
    let mut out = vec![0.0; q.len()];
    for (row_in, row_out) in q.chunks(mx).zip(out.chunks_mut(mx)) {
        row_out[..mx - 1].copy_from_slice(&row_in[1..]);
    }
    out
}

/// Kalker's transient rolling, marched from rest by shift steps of one element Δx (CONTACT's T = 2 with DQ = DX):
/// step n solves the shift problem with the rigid shift Δx·(ξ − φy, η + φ(x + Δx/6)) from the previous shears
/// carried one element downstream, until a step changes no shear by more than 1e-13 μp₀ (or 600 steps). Its fixed
/// point satisfies exactly the steady-rolling equations of `halfspace::rolling`.
#[test]
fn steady_rolling_is_the_limit_of_transient_rolling() {
    let (inf, p) = ellipse();
    let grid = *inf.grid();
    let (mu, xi, eta, phi) = (0.3, 0.002, -0.001, 0.002);
    let h = grid.dx();
    let ox: Vec<f64> = grid.centres().iter().map(|c| -phi * c.1 * h).collect();
    let oy: Vec<f64> = grid.centres().iter().map(|c| phi * (c.0 + h / 6.0) * h).collect();
    let n = grid.len();
    let (mut qx, mut qy) = (vec![0.0; n], vec![0.0; n]);
    let settings = TangentialSettings::new(1e-13, 100_000);
    let gmax = mu * 0.01;
    let mut steps = 0;
    loop {
        let (px, py) = (carried(&qx, grid.mx()), carried(&qy, grid.mx()));
        let step =
            ShiftStep::new(&p, mu, TangentialDrive::Shift(h * xi, h * eta)).after(&px, &py).with_offset(&ox, &oy);
        let s = tangential::solve(&inf, &step, &settings, &Cancel::never()).unwrap();
        let change = (0..n).map(|i| (s.qx[i] - qx[i]).hypot(s.qy[i] - qy[i])).fold(0.0, f64::max);
        (qx, qy) = (s.qx, s.qy);
        steps += 1;
        if change <= 1e-13 * gmax || steps == 600 {
            break;
        }
    }
    let problem = SteadyRolling::new(&p, mu, phi, RollingDrive::Creepage(xi, eta));
    let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-12, 100_000), &Cancel::never()).unwrap();
    let diff = (0..n).map(|i| (r.qx[i] - qx[i]).hypot(r.qy[i] - qy[i])).fold(0.0, f64::max) / gmax;
    println!(
        "transient march: {steps} steps; steady: {} products, {} stick, {} slip, residual {:.1e}; largest difference {diff:.1e} of μp₀",
        r.products, r.stick, r.slip, r.residual
    );
    assert!(steps < 600, "the march did not settle");
    assert_eq!(r.stop, RollingStop::Converged);
    assert!(r.stick > 50 && r.slip > 50, "a partial-slip case: {} stick, {} slip", r.stick, r.slip);
    assert!(r.residual <= 1e-10, "natural residual {:e}", r.residual);
    assert!(diff <= 1e-8, "steady rolling differs from the transient limit by {diff:e} of μp₀");
}

/// Reflecting x → −x turns a contact rolling along +x with creepages (ξ, η, φ) into one rolling along −x with
/// (−ξ, η, −φ), and its shears (q_x, q_y)(x, y) into (−q_x, q_y)(−x, y). The grid and the pressure are symmetric.
#[test]
fn rolling_backwards_is_the_mirror_image() {
    let (inf, p) = ellipse();
    let grid = *inf.grid();
    let (mx, n) = (grid.mx(), grid.len());
    let s = RollingSettings::new(1e-12, 100_000);
    let fwd = SteadyRolling::new(&p, 0.3, 0.002, RollingDrive::Creepage(0.002, -0.001));
    let bwd =
        SteadyRolling::new(&p, 0.3, -0.002, RollingDrive::Creepage(-0.002, -0.001)).rolling(RollingDirection::MinusX);
    let a = rolling::solve(&inf, &fwd, &s, &Cancel::never()).unwrap();
    let b = rolling::solve(&inf, &bwd, &s, &Cancel::never()).unwrap();
    let mirror = |i: usize| (mx - 1 - i % mx) + mx * (i / mx);
    let diff =
        (0..n).map(|i| (a.qx[i] + b.qx[mirror(i)]).abs().max((a.qy[i] - b.qy[mirror(i)]).abs())).fold(0.0, f64::max);
    println!("mirror: largest difference {diff:.1e} (μp₀ = 3e-3)");
    assert!(diff <= 1e-10 * 0.003, "{diff:e}");
    assert_eq!((a.stick, a.slip), (b.stick, b.slip));
}

/// CONTACT's `tang_problm_1c` / `1f`: the normal problem of `norm_problm_1p` (rail–wheel profile, approach
/// 0.02084 mm, G = 82 000, ν = 0.28, 71 × 81 elements of 0.1 mm), then steady rolling with μ = 0.3, spin
/// CPHI = 0.0003 rad/mm and CKSI = 0.0005 (1c) or FX/(μFN) = −0.573, FY/(μFN) = −0.327 (1f), χ = 0, DQ = DX,
/// CONTACT's FACPHI = 1/6.
fn contact_perfc(name: &str) {
    let prof: Vec<f64> = csv(&format!("{name}_profile.csv")).iter().map(|r| num(r, "p")).collect();
    let profile = |y: f64| {
        let t = ((y + 12.0) / 0.1).clamp(0.0, (prof.len() - 1) as f64);
        let k = (t.floor() as usize).min(prof.len() - 2);
        prof[k] + (t - k as f64) * (prof[k + 1] - prof[k])
    };
    let grid = ContactGrid::new(71, 81, 0.1, 0.1, -3.55 + 0.05, -6.15 + 0.05).unwrap();
    let steel = HalfSpace::new(2.0 * 82000.0 * 1.28, 0.28).unwrap();
    let inf = Influence::new(grid, steel.pair(&steel), Kernels::Full).unwrap();
    let h = grid.sample(|x, y| profile(y) + x * x / (2.0 * 483.931));
    let ns = NormalSettings::new(1e-10, 10_000);
    let n = normal::solve(&inf, &h, Drive::Approach(0.02084), &ns, &Cancel::never()).unwrap();
    let drive = if name.ends_with('c') {
        RollingDrive::Creepage(0.0005, 0.0)
    } else {
        RollingDrive::Force(-0.573 * 0.3 * n.load, -0.327 * 0.3 * n.load)
    };
    let problem = SteadyRolling::new(&n.pressure, 0.3, 0.0003, drive);
    let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-10, 100_000), &Cancel::never()).unwrap();
    assert_eq!(r.stop, RollingStop::Converged);
    let rows = csv(&format!("{name}_case1_elements.csv"));
    let pmax = rows.iter().map(|r| num(r, "pn")).fold(0.0, f64::max);
    let (mut dt, mut states) = (0.0_f64, 0);
    for row in &rows {
        let i = (num(row, "ix") as usize - 1) + 71 * (num(row, "iy") as usize - 1);
        dt = dt.max((r.qx[i] - num(row, "px")).abs().max((r.qy[i] - num(row, "py")).abs()) / pmax);
        let theirs = if row["state"] == "adhesion" { ElementState::Stick } else { ElementState::Slip };
        states += usize::from(r.state[i] != theirs);
    }
    let c = &csv(&format!("{name}_cases.csv"))[0];
    println!(
        "{name}: px, py within {dt:.1e} of pmax; {states} states differ; stick {} slip {}; FX {:.1} FY {:.2} MZ {:.1}; creepage {:.4e}, {:.4e}; {} products",
        r.stick, r.slip, r.force.0, r.force.1, r.moment, r.creepage.0, r.creepage.1, r.products
    );
    // CONTACT stops at EPS = 1e-7 and prints 6 digits per element, 4 in its totals.
    assert!(dt <= 2e-5, "tractions differ by {dt:e} of pmax");
    assert_eq!(states, 0);
    assert_eq!((r.stick, r.slip), (num(c, "nadh") as usize, num(c, "nslip") as usize));
    let close = |ours: f64, key: &str| {
        let theirs = num(c, key);
        assert!((ours - theirs).abs() <= 6e-4 * theirs.abs(), "{key}: {ours} against CONTACT's {theirs}");
    };
    close(r.force.0, "fx");
    close(r.force.1, "fy");
    close(r.moment, "mz");
    if name.ends_with('f') {
        close(r.creepage.0, "creep_x");
        close(r.creepage.1, "creep_y");
    }
}

#[test]
fn tang_problm_1c_agrees_with_contact() {
    contact_perfc("tang_problm_1c");
}

#[test]
fn tang_problm_1f_agrees_with_contact() {
    contact_perfc("tang_problm_1f");
}

/// The force drive finds the creepages that give the force: the creepages of a creepage-prescribed solution from
/// its own force, and the same shears. A force beyond μ A Σ p is gross sliding, a status. Far beyond saturation the
/// force of a prescribed creepage tends to μ F_n against it (full sliding; the elastic term's share of the slip
/// vanishes as the creepage grows).
#[test]
fn force_and_creepage_drives_agree() {
    let (inf, p) = ellipse();
    let s = RollingSettings::new(1e-12, 100_000);
    let a = rolling::solve(
        &inf,
        &SteadyRolling::new(&p, 0.3, 0.001, RollingDrive::Creepage(0.001, 0.0005)),
        &s,
        &Cancel::never(),
    )
    .unwrap();
    let f = RollingDrive::Force(a.force.0, a.force.1);
    let b = rolling::solve(&inf, &SteadyRolling::new(&p, 0.3, 0.001, f), &s, &Cancel::never()).unwrap();
    let dq = (0..p.len()).map(|i| (a.qx[i] - b.qx[i]).hypot(a.qy[i] - b.qy[i])).fold(0.0, f64::max);
    println!("force drive: creepage {:.6e}, {:.6e}; shears within {dq:.1e}", b.creepage.0, b.creepage.1);
    assert_eq!(b.stop, RollingStop::Converged);
    assert!((b.creepage.0 - 0.001).abs() <= 1e-9 && (b.creepage.1 - 0.0005).abs() <= 1e-9);
    assert!(dq <= 1e-9 * 0.003);
    let area = inf.grid().area();
    let fn_ = area * p.iter().sum::<f64>();
    let g = rolling::solve(
        &inf,
        &SteadyRolling::new(&p, 0.3, 0.0, RollingDrive::Force(0.31 * fn_, 0.0)),
        &s,
        &Cancel::never(),
    )
    .unwrap();
    assert_eq!(g.stop, RollingStop::GrossSliding);
    assert!(g.creepage.0.is_nan());
    let full =
        rolling::solve(&inf, &SteadyRolling::new(&p, 0.3, 0.0, RollingDrive::Creepage(1.0, 0.0)), &s, &Cancel::never())
            .unwrap();
    let ratio = -full.force.0 / (0.3 * fn_);
    println!("full sliding: Fx/(μFn) = {ratio:.6}, {} stick", full.stick);
    assert!(full.stick == 0 && (ratio - 1.0).abs() <= 1e-3 && full.force.1.abs() <= 1e-3 * 0.3 * fn_);
}

/// Kalker's creep coefficients from the exact theory in full adhesion (`rolling::linear_coefficients`: an ellipse
/// of semi-axes a (rolling direction) and b with G = 1, ν = 0.25, a unit pressure with μ = 1e4 (nothing slips), the
/// creepages one at a time, spin evaluated at the element centres); `Fx = −G c² C11 ξ`, `Fy = −G c² C22 η − G c³ C23 φ`,
/// `Mz = −G c³ C32 η`. Against Table E.3 at a/b = 0.2, 1, 5 with 160 elements across the smaller diameter: all
/// nine within 1 % (measured: largest 0.64 %, C23 at a/b = 1; `examples/kalker_coefficients.rs` prints the
/// convergence table 20 → 160: e.g. C11 at a/b = 1 +1.9 %, +1.2 %, +0.11 %, +0.014 %). C32 = −C23 by Betti's
/// reciprocal theorem, to 1e-6.
#[test]
fn kalker_coefficients_from_full_adhesion() {
    for ratio in [0.2, 1.0, 5.0] {
        let (a, b) = if ratio <= 1.0 { (ratio, 1.0) } else { (1.0, 1.0 / ratio) };
        let table = kalker::creep_coefficients(a, b, 0.25).unwrap();
        let k = |n| rolling::linear_coefficients(a, b, 0.25, n, &Cancel::never()).unwrap();
        let (k20, k160) = (k(20), k(160));
        let (coarse, fine) = ([k20.c11, k20.c22, k20.c23, k20.c32], [k160.c11, k160.c22, k160.c23, k160.c32]);
        let err = |c: [f64; 4]| {
            [(c[0] - table.c11) / table.c11, (c[1] - table.c22) / table.c22, (c[2] - table.c23) / table.c23]
        };
        let (e20, e160) = (err(coarse), err(fine));
        println!("a/b = {ratio}: errors at 20 across {e20:.3?}, at 160 {e160:.3?}; C32/C23 = {:.8}", fine[3] / fine[2]);
        for (k, e) in e160.iter().enumerate() {
            assert!(e.abs() <= 0.01, "a/b = {ratio}, coefficient {k}: {e:+.2e}");
        }
        assert!(e160.iter().map(|e| e.abs()).sum::<f64>() < e20.iter().map(|e| e.abs()).sum::<f64>());
        assert!((fine[3] / fine[2] + 1.0).abs() <= 1e-6, "C32 = {} against C23 = {}", fine[3], fine[2]);
    }
}

/// CONTACT's `tractcurv.inp`, first series (cases 1–30): the Eurosprinter creep curve of Polach (2005) by the exact
/// theory. A Hertzian profile `A x² + B y²` with A = 0.0008/mm and B such that Hertz's ellipse has a/b = 0.5
/// (CONTACT's IPOTCN = −2; B/A from `theory::hertz3d`'s `curvatures_for`, CONTACT prints B = 0.2814e-3), FN = 106.7 kN
/// prescribed, G = 82 000, ν = 0.28 on both bodies, μ = 0.33, ξ from 1e-5 to 0.25, η = φ = 0, rolling along +x, on
/// CONTACT's 48 × 44 grid over 1.1 times the ellipse (its six-digit grid from our build's .mat files). Expected:
/// CONTACT's reference output `tractcurv.ref_out` as printed (`reference/contact3d/fastsim/tractcurv_exact_cases.csv`):
/// FX, FX/(μFN) and PMAX within half a unit of their last digit plus CONTACT's EPS = 1e-6 of the value, NCON, NADH,
/// NSLIP exactly.
#[test]
fn tractcurv_exact_series_agrees_with_contact() {
    let rows = csv("fastsim/tractcurv_exact_cases.csv");
    let r0 = &rows[0];
    let (g, nu, fn_) = (num(r0, "g"), num(r0, "nu"), num(r0, "fn_input"));
    let e_star = 2.0 * g * (1.0 + nu) / (2.0 * (1.0 - nu * nu));
    // B/A of Hertz's ellipse with a/b = 0.5 (any size), then A = 0.0008.
    let (ca, cb) = rollbem::theory::hertz3d::Hertz3D::curvatures_for(0.5, 1.0, e_star, fn_).unwrap();
    let (curv_a, curv_b) = (0.0008, 0.0008 * cb / ca);
    assert!((curv_b - 0.2814e-3).abs() <= 0.5e-7, "B = {curv_b:e}, CONTACT prints 0.2814E-03");
    let (mx, my) = (num(r0, "mx") as usize, num(r0, "my") as usize);
    let (dx, dy) = (num(r0, "dx"), num(r0, "dy"));
    let grid = ContactGrid::new(mx, my, dx, dy, num(r0, "xl") + 0.5 * dx, num(r0, "yl") + 0.5 * dy).unwrap();
    let steel = HalfSpace::new(2.0 * g * (1.0 + nu), nu).unwrap();
    let inf = Influence::new(grid, steel.pair(&steel), Kernels::Full).unwrap();
    let h = grid.sample(|x, y| curv_a * x * x + curv_b * y * y);
    let n = normal::solve(&inf, &h, Drive::Load(fn_), &NormalSettings::new(1e-10, 10_000), &Cancel::never()).unwrap();
    let pmax = n.pressure.iter().fold(0.0_f64, |m, &v| m.max(v));
    let mu = num(r0, "mu");
    let settings = RollingSettings::new(1e-10, 100_000);
    let (mut qx, mut qy) = (vec![0.0; grid.len()], vec![0.0; grid.len()]);
    let mut worst: f64 = 0.0;
    for row in &rows {
        let xi = num(row, "xi");
        let problem = SteadyRolling::new(&n.pressure, mu, 0.0, RollingDrive::Creepage(xi, 0.0)).starting_from(&qx, &qy);
        let r = rolling::solve(&inf, &problem, &settings, &Cancel::never()).unwrap();
        assert_eq!(r.stop, RollingStop::Converged, "case {}", row["case"]);
        let fx_rel = r.force.0 / (mu * fn_);
        for (key, got) in [("fx", r.force.0), ("fx_rel", fx_rel), ("pmax", pmax)] {
            let d = (got - num(row, key)).abs();
            let allowed = half_unit(&row[key]) + 1e-6 * got.abs();
            worst = worst.max(d / allowed);
            assert!(d <= allowed, "case {} {key}: {got:.6e} against CONTACT's {}", row["case"], row[key]);
        }
        assert_eq!(n.in_contact, num(row, "ncon") as usize, "case {} NCON", row["case"]);
        assert_eq!((r.stick, r.slip), (num(row, "nadh") as usize, num(row, "nslip") as usize), "case {}", row["case"]);
        (qx, qy) = (r.qx, r.qy);
    }
    println!("tractcurv 1–30: largest difference {worst:.2} of the allowance (half a printed unit + 1e-6)");
}

/// CONTACT's `fastsim.inp`, case 1: the exact theory on Hertz's ellipse a = 8, b = 4 mm (IPOTCN = −3: the profile
/// `A x² + B y²` whose Hertz ellipse at FN = 82 kN has these semi-axes, A and B from
/// `theory::hertz3d`'s `curvatures_for`), G = 82 000, ν = 0.28, μ = 0.3, η = −0.000625, φ = 0.000625 rad/mm, ξ = 0, on 44 × 44
/// elements over [−1.1a, 1.1a] × [−1.1b, 1.1b]. Expected: the author's `fastsim.ref_out` as printed
/// (`reference/contact3d/fastsim/fastsim_cases.csv`, case 1): FY, MZ, FY/(μFN) and PMAX within half a unit of their
/// last digit plus CONTACT's EPS = 1e-6 of the value, NCON, NADH, NSLIP exactly. FASTSIM's cases 2–8 on the same
/// contact are `tests/fastsim.rs`'s; their error against this answer is the report's.
#[test]
fn fastsim_inp_exact_case_agrees_with_contact() {
    let row = csv("fastsim/fastsim_cases.csv").swap_remove(0);
    assert_eq!(row["case"], "1");
    let (a, b, fn_, g, nu) = (num(&row, "a"), num(&row, "b"), num(&row, "fn"), num(&row, "g"), num(&row, "nu"));
    let e_star = 2.0 * g * (1.0 + nu) / (2.0 * (1.0 - nu * nu));
    let (ca, cb) = rollbem::theory::hertz3d::Hertz3D::curvatures_for(a, b, e_star, fn_).unwrap();
    let hertz = rollbem::theory::hertz3d::Hertz3D::from_load(ca, cb, e_star, fn_).unwrap();
    assert!((hertz.a_x - a).abs() <= 1e-8 * a && (hertz.a_y - b).abs() <= 1e-8 * b);
    let (mx, my) = (num(&row, "mx") as usize, num(&row, "my") as usize);
    let (dx, dy) = (2.2 * a / mx as f64, 2.2 * b / my as f64);
    let grid = ContactGrid::new(mx, my, dx, dy, -1.1 * a + 0.5 * dx, -1.1 * b + 0.5 * dy).unwrap();
    let steel = HalfSpace::new(2.0 * g * (1.0 + nu), nu).unwrap();
    let inf = Influence::new(grid, steel.pair(&steel), Kernels::Full).unwrap();
    let h = grid.sample(|x, y| ca * x * x + cb * y * y);
    let n = normal::solve(&inf, &h, Drive::Load(fn_), &NormalSettings::new(1e-10, 10_000), &Cancel::never()).unwrap();
    let mu = num(&row, "mu");
    let drive = RollingDrive::Creepage(num(&row, "xi"), num(&row, "eta"));
    let problem = SteadyRolling::new(&n.pressure, mu, num(&row, "phi"), drive);
    let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-10, 100_000), &Cancel::never()).unwrap();
    let pmax = n.pressure.iter().fold(0.0_f64, |m, &v| m.max(v));
    let fy_rel = r.force.1 / (mu * fn_);
    println!(
        "fastsim.inp case 1: FY {:.1} MZ {:.1} PMAX {pmax:.1}; {} stick {} slip",
        r.force.1, r.moment, r.stick, r.slip
    );
    for (key, got) in [("fy", r.force.1), ("mz", r.moment), ("fy_rel", fy_rel), ("pmax", pmax)] {
        let d = (got - num(&row, key)).abs();
        assert!(d <= half_unit(&row[key]) + 1e-6 * got.abs(), "{key}: {got:.6e} against CONTACT's {}", row[key]);
    }
    assert!(r.force.0.abs() <= 0.5, "FX = {} (printed 0.000)", r.force.0);
    assert_eq!((n.in_contact, r.stick, r.slip), (1276, 356, 920));
}

/// CONTACT's `catt_to_cart.inp`, cases 1–57: the onset of rolling, "from Cattaneo to Carter" (Kalker 1990,
/// §5.2.2.5). A sphere pair (G = 1, ν = 0.28, h = 0.002963 (x² + y²), FN = 0.4705, μ = 0.4013) on 34 × 33 elements
/// of 0.25 from (−4.125, −4.125); case 1 a Cattaneo shift from rest to FX = −0.657 μFN; cases 2–57 transient rolling
/// (`rolling::transient_step`), one element DQ = DX along +x per case, FX kept, the creepage found each step. Expected:
/// the author's `catt_to_cart.ref_out` as printed (`reference/contact3d/catt_to_cart_cases.csv`): the shift of case 1
/// and the creepage of every case within half a printed unit plus 1e-6 of the value (CONTACT's EPS = 1e-7), NADH and
/// NSLIP where printed exactly, and cases 2 and 57 element by element (our build's .mat files, 6 digits) to 1e-5 of
/// pmax.
#[test]
fn catt_to_cart_agrees_with_contact() {
    let cases = csv("catt_to_cart_cases.csv");
    let grid = ContactGrid::new(34, 33, 0.25, 0.25, -4.125 + 0.125, -4.125 + 0.125).unwrap();
    let body = HalfSpace::new(2.0 * 1.28, 0.28).unwrap();
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full).unwrap();
    let h = grid.sample(|x, y| 0.002963 * (x * x + y * y));
    let n =
        normal::solve(&inf, &h, Drive::Load(0.4705), &NormalSettings::new(1e-12, 10_000), &Cancel::never()).unwrap();
    let (mu, fx) = (0.4013, -0.657 * 0.4013 * 0.4705);
    let settings = TangentialSettings::new(1e-12, 100_000);
    let shift = ShiftStep::new(&n.pressure, mu, TangentialDrive::Force(fx, 0.0));
    let mut q = tangential::solve(&inf, &shift, &settings, &Cancel::never()).unwrap();
    let within = |got: f64, printed: &str, what: String| {
        let d = (got - printed.trim().parse::<f64>().unwrap()).abs();
        assert!(d <= half_unit(printed) + 1e-6 * got.abs(), "{what}: {got:.6e} against CONTACT's {printed}");
    };
    within(q.shift.0, &cases[0]["shift_x"], "case 1 shift".into());
    let mut worst: f64 = 0.0;
    for (k, row) in cases.iter().enumerate().take(57) {
        if k > 0 {
            let problem = SteadyRolling::new(&n.pressure, mu, 0.0, RollingDrive::Force(fx, 0.0));
            let next =
                rolling::transient_step(&inf, &problem, Some((&q.qx, &q.qy)), &settings, &Cancel::never()).unwrap();
            q = next;
            within(rolling::transient_creepage(&grid, &q).0, &row["creep_x"], format!("case {} creepage", k + 1));
        }
        within(q.force.0, &row["fx"], format!("case {} FX", k + 1));
        if !row["nadh"].is_empty() {
            assert_eq!((q.stick, q.slip), (num(row, "nadh") as usize, num(row, "nslip") as usize), "case {}", k + 1);
        }
        if matches!(k + 1, 1 | 2 | 57) {
            let rows = csv(&format!("catt_to_cart_case{}_elements.csv", k + 1));
            let pmax = rows.iter().map(|r| num(r, "pn")).fold(0.0, f64::max);
            for r in &rows {
                let i = (num(r, "ix") as usize - 1) + 34 * (num(r, "iy") as usize - 1);
                worst = worst.max((q.qx[i] - num(r, "px")).abs().max((q.qy[i] - num(r, "py")).abs()) / pmax);
            }
        }
    }
    // Two contact diameters on, the transient has nearly reached Carter's steady state (it approaches it
    // asymptotically; marched to the end it equals it, `steady_rolling_is_the_limit_of_transient_rolling`): measured
    // 1.2e-5 from the steady solver's creepage.
    let steady = SteadyRolling::new(&n.pressure, mu, 0.0, RollingDrive::Force(fx, 0.0));
    let s = rolling::solve(&inf, &steady, &RollingSettings::new(1e-12, 100_000), &Cancel::never()).unwrap();
    let xi = rolling::transient_creepage(&grid, &q).0;
    println!(
        "catt_to_cart 1–57: tractions of cases 1, 2, 57 within {worst:.1e} of pmax; creepage at case 57 {xi:.6e}, steady {:.6e}",
        s.creepage.0
    );
    assert!(worst <= 1e-5, "{worst:e}");
    assert!((xi - s.creepage.0).abs() <= 2e-5 * xi.abs(), "transient {xi:e} against steady {:e}", s.creepage.0);
}

/// CONTACT's `catt_to_cart.inp`, cases 58–171: the same onset of rolling as cases 1–57, now as shifts (T = 1) in
/// world-fixed coordinates, the approach PEN = 0.07258 mm prescribed after each sequence's first case and
/// FX/(FSTAT FN) = −0.657. Cases 58–114: a fixed 90 × 33 grid, the profile `0.002963 ((x − 0.25k)² + y²)` moved
/// one element DX = 0.25 mm per case, the previous shears where they were. Cases 115–171: a 34 × 33 window moving
/// with the profile, so each element's previous shear is the one of its right neighbour (`rolling::carried`).
/// Expected: the author's `catt_to_cart.ref_out` as printed (`reference/contact3d/catt_to_cart_cases.csv`): the
/// shift and FN within one unit of their last digit (why: in the test) plus 1e-6 of the value, and the counts in
/// adhesion and slip exactly (those of our build's `.mat` files, which equal the printed ones where printed).
#[test]
fn catt_to_cart_world_fixed_sequences_agree_with_contact() {
    let cases = csv("catt_to_cart_cases.csv");
    let (mu, fx_rel, pen) = (0.4013, -0.657, 0.07258);
    let body = HalfSpace::new(2.0 * 1.28, 0.28).unwrap();
    let settings = TangentialSettings::new(1e-12, 100_000);
    // The shifts within one unit of the last printed digit (plus 1e-6 of the value): the agreement CONTACT's own build check
    // asks between two builds (benches/peer/contact_refcmp.py), not half a unit as for cases 1–57. The shift of a
    // step is a small difference of large displacements (7.7e-4 against 1.8e-2 mm), and 10 of the 114 shifts here
    // differ from the printed ones by 0.58–0.74 of a unit; CONTACT run with EPS = 1e-12 prints the same digits, so
    // it is not its tolerance, and every count agrees. The origin of the difference was not found.
    // FN (not a difference of large quantities) within half a unit as everywhere else.
    let mut worst: f64 = 0.0;
    let mut within = |got: f64, printed: &str, units: f64, what: String| {
        let d = (got - printed.trim().parse::<f64>().unwrap()).abs();
        worst = worst.max(d / (2.0 * half_unit(printed)));
        let allowed = units * 2.0 * half_unit(printed) + 1e-6 * got.abs();
        assert!(d <= allowed, "{what}: {got:.6e} against CONTACT's {printed}");
    };
    for (first, mx, moving) in [(58, 90, false), (115, 34, true)] {
        let grid = ContactGrid::new(mx, 33, 0.25, 0.25, -4.125 + 0.125, -4.125 + 0.125).unwrap();
        let inf = Influence::new(grid, body.pair(&body), Kernels::Full).unwrap();
        let (mut qx, mut qy) = (Vec::new(), Vec::new());
        for k in 0..57 {
            let row = &cases[first - 1 + k];
            assert_eq!(row["case"], (first + k).to_string());
            // The profile as the input writes it: `B1 x² + B3 y² + B4 x + B6` in world coordinates, the profile moved
            // by 0.25k, B4 = −2 B1 (0.25k) and B6 = B1 (0.25k)² rounded to the input's 7 decimals (the rounding of B6,
            // up to 5e-8 mm of the 0.07 mm approach, moves the shift by up to 7e-5 of itself: case 72 prints
            // 8.508E-04, 8.507E-04 with the exact profile). The moving window's x is the world's less 0.25k.
            let (b1, c) = (0.002963, 0.25 * k as f64);
            let round7 = |v: f64| (v * 1e7).round() / 1e7;
            let (b4, b6) = (round7(-2.0 * b1 * c), round7(b1 * c * c));
            let origin = if moving { c } else { 0.0 };
            let h = grid.sample(|x, y| b1 * ((x + origin).powi(2) + y * y) + b4 * (x + origin) + b6);
            let drive = if k == 0 { Drive::Load(0.4705) } else { Drive::Approach(pen) };
            let n = normal::solve(&inf, &h, drive, &NormalSettings::new(1e-12, 10_000), &Cancel::never()).unwrap();
            let step = ShiftStep::new(&n.pressure, mu, TangentialDrive::Force(fx_rel * mu * n.load, 0.0));
            let q = if k == 0 {
                tangential::solve(&inf, &step, &settings, &Cancel::never()).unwrap()
            } else if moving {
                let (px, py) = (carried(&qx, mx), carried(&qy, mx));
                tangential::solve(&inf, &step.after(&px, &py), &settings, &Cancel::never()).unwrap()
            } else {
                tangential::solve(&inf, &step.after(&qx, &qy), &settings, &Cancel::never()).unwrap()
            };
            let case = first + k;
            within(n.load, &row["fn"], 0.5, format!("case {case} FN"));
            within(q.shift.0, &row["shift_x"], 1.0, format!("case {case} shift"));
            let counts = (num(row, "nadh_mat") as usize, num(row, "nslip_mat") as usize);
            assert_eq!((q.stick, q.slip), counts, "case {case}: adhesion and slip");
            (qx, qy) = (q.qx, q.qy);
        }
    }
    println!("catt_to_cart 58–171: largest difference in FN and the shifts {worst:.2} of a printed unit");
}

/// The creep-table engine `exact` (`creeptable::Exact`, Hertz's pressure on the case's grid) against theory: at a
/// small creepage it follows Kalker's linear theory (Table E.3, `creeptable::KalkerLinear`) within the grid's
/// discretisation (3 % at 48 × 48 over 1.1 times a circle; measured +0.68 %), and far beyond saturation every element
/// slips (status gross sliding) and the force tends to μN against the creepage: at ξ = 0.05 within 1e-4 (measured
/// 6e-6: the elastic part of the slip, `C_yx D q_x`, still turns each shear slightly off the x axis; Fy cancels by
/// symmetry).
#[test]
fn the_exact_creep_engine_follows_kalker_and_saturates() {
    use rollbem::creeptable::{CaseStatus, CreepCase, CreepEngine, Exact, KalkerLinear, Load, Resolution};
    use rollbem::fastsim::Creepages;
    let case = |xi: f64| {
        let cr = Creepages { xi, eta: 0.0, phi: 0.0 };
        CreepCase::from_shape(
            1.0,
            5.0,
            0.28,
            82_000.0,
            0.3,
            Load::NormalForce(50_000.0),
            cr,
            Resolution { mx: 48, my: 48 },
        )
    };
    let small = case(1e-6);
    let exact = Exact::default().forces(&small).unwrap();
    let linear = KalkerLinear.forces(&small).unwrap();
    let (fe, fl) = (exact.forces.unwrap().fx, linear.forces.unwrap().fx);
    println!(
        "exact engine at ξ = 1e-6: Fx {fe:.4} against the linear theory's {fl:.4} ({:+.2} %)",
        100.0 * (fe / fl - 1.0)
    );
    assert_eq!(exact.status, CaseStatus::Solved);
    assert!((fe / fl - 1.0).abs() <= 0.03);
    let big = Exact::default().forces(&case(0.05)).unwrap();
    assert_eq!(big.status, CaseStatus::GrossSliding);
    let f = big.forces.unwrap();
    assert!((f.fx + 0.3 * 50_000.0).abs() <= 1e-4 * 15_000.0 && f.fy.abs() <= 1e-9 * 15_000.0, "{f:?}");
}
