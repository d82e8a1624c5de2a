//! CONTACT's 3D examples, posed to rollbem's half-space model (`rollbem::halfspace::Path`) and compared with
//! CONTACT's own results (the peer: E. Vollebregt's CONTACT; the data in `reference/contact3d/`, written by
//! `benches/peer/contact_ref3d.py` from the author's reference outputs and our MKL build's per-element files — its
//! README says which number comes from where, and decodes every input parameter used below).
//!
//! The discrete problems are the same (the same grid, Kalker's piecewise-constant elements collocated at the
//! centres, the same closed-form influence coefficients), so the answers differ by the two programs' stopping
//! criteria and CONTACT's printed digits only: CONTACT stops when ‖pᵏ − pᵏ⁻¹‖ < EPS‖pᵏ‖ (EPS = 1e-4 in cattaneo,
//! 1e-6 in spence35) and prints 6 significant digits in its per-element files, 4 in its totals.

use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::Drive;
use rollbem::halfspace::tangential::{ElementState, TangentialDrive};
use rollbem::halfspace::{ContactGrid, HalfSpace, Path, PathSettings, PathStatus, Profile, Step, StepOutcome};

#[path = "common/contact_ref.rs"]
mod contact_ref;
use contact_ref::{csv, num};

/// CONTACT's material input (G, ν) as a half-space (E = 2G(1 + ν)).
fn body(g: f64, nu: f64) -> HalfSpace {
    HalfSpace::new(2.0 * g * (1.0 + nu), nu).unwrap()
}

/// CONTACT's grid: MX × MY elements DX × DY, element (ix, iy) (1-based) centred at XL + (ix − ½)DX, YL + (iy − ½)DY.
fn grid(mx: usize, my: usize, xl: f64, yl: f64, dx: f64, dy: f64) -> ContactGrid {
    ContactGrid::new(mx, my, dx, dy, xl + 0.5 * dx, yl + 0.5 * dy).unwrap()
}

/// The largest difference of pn, px, py between rollbem's step and CONTACT's element table, relative to CONTACT's
/// largest pn; and the elements whose state differs (in contact or not, stick or slip).
fn compare(o: &StepOutcome, g: &ContactGrid, table: &str) -> (f64, f64, usize) {
    let rows = csv(table);
    let pmax = rows.iter().map(|r| num(r, "pn")).fold(0.0, f64::max);
    let mut seen = vec![false; g.len()];
    let (mut dn, mut dt, mut states) = (0.0_f64, 0.0_f64, 0);
    for r in &rows {
        let (ix, iy) = (num(r, "ix") as usize - 1, num(r, "iy") as usize - 1);
        let i = ix + g.mx() * iy;
        seen[i] = true;
        dn = dn.max((o.pressure[i] - num(r, "pn")).abs() / pmax);
        dt = dt.max((o.qx[i] - num(r, "px")).abs().max((o.qy[i] - num(r, "py")).abs()) / pmax);
        let theirs = if r["state"] == "adhesion" { ElementState::Stick } else { ElementState::Slip };
        let ours = o.state[i];
        let frictionless_contact = ours == ElementState::Slip && o.qx[i] == 0.0 && o.qy[i] == 0.0;
        if ours != theirs && !(frictionless_contact && r["state"] == "adhesion") {
            states += 1;
        }
    }
    for (i, s) in seen.iter().enumerate() {
        if !s {
            dn = dn.max(o.pressure[i] / pmax);
            if o.pressure[i] > 0.0 {
                states += 1;
            }
        }
    }
    (dn, dt, states)
}

/// `examples/cattaneo.inp`: G = 200, ν = 0.42 on both bodies (no coupling), h = 0.01(x² + y²), FN = 9.1954 N;
/// case 1 frictionless on CONTACT's Hertzian grid (19 × 19 on ±1.26667 mm), case 2 a shift with μ = 0.4 to
/// FX = −0.875 μ FN on the grid it reads (DX = 0.13333 from XL = −1.26667). Tractions per element agree with
/// CONTACT's to 1e-4 of p_max (CONTACT's EPS = 1e-4; measured 1.3e-6 (case 1), 1.2e-5 (pn) and 5.4e-6 (pt) in case
/// 2), every element's state and the counts (177 in contact, 45 stick, 132 slip) exactly, the approach and
/// CONTACT's shift (8.155e-3 mm, for the prescribed force) to their 4 printed digits (measured 1.9998e-2 and
/// 8.1549e-3).
#[test]
fn cattaneo_inp_agrees_with_contact() {
    let cases = csv("cattaneo_cases.csv");
    let (g, nu, mu, fn_) = (200.0, 0.42, 0.4, 9.1954);
    let prof = Profile::Quadratic { a: 0.01, b: 0.01 };
    let settings = PathSettings::default();
    // Case 1: frictionless.
    let dx1 = 2.0 * 1.26667 / 19.0;
    let g1 = grid(19, 19, -1.26667, -1.26667, dx1, dx1);
    let s1 = Step::new(Drive::Load(fn_), TangentialDrive::Shift(0.0, 0.0));
    let p1 = Path::new(g1, body(g, nu), body(g, nu), prof.clone(), 0.0, true, vec![s1]).unwrap();
    let o1 = &p1.solve(&settings, &Cancel::never()).unwrap()[0];
    assert_eq!(o1.status, PathStatus::Solved, "{}", o1.message);
    let (dn, _, states) = compare(o1, &g1, "cattaneo_case1_elements.csv");
    let c1 = &cases[0];
    println!(
        "cattaneo 1: pn {dn:.2e} of pmax, {states} states differ; approach {:.4e} vs {:.4e}",
        o1.approach,
        num(c1, "approach")
    );
    assert!(dn <= 1e-4 && states == 0, "pn {dn:e}, states {states}");
    assert_eq!(o1.counts.0, num(c1, "ncon") as usize);
    assert!((o1.approach - num(c1, "approach")).abs() <= 5e-4 * num(c1, "approach"));
    // Case 2: the shift to FX = −0.875 μ FN.
    let g2 = grid(19, 19, -1.26667, -1.26667, 0.13333, 0.13333);
    let fx = -0.875 * mu * fn_;
    let s2 = Step::new(Drive::Load(fn_), TangentialDrive::Force(fx, 0.0));
    let p2 = Path::new(g2, body(g, nu), body(g, nu), prof, mu, true, vec![s2]).unwrap();
    let o2 = &p2.solve(&settings, &Cancel::never()).unwrap()[0];
    assert_eq!(o2.status, PathStatus::Solved, "{}", o2.message);
    let (dn, dt, states) = compare(o2, &g2, "cattaneo_case2_elements.csv");
    let c2 = &cases[1];
    println!(
        "cattaneo 2: pn {dn:.2e}, pt {dt:.2e} of pmax, {states} states differ; counts {:?} vs {} {} {}; shift {:.4e} vs {:.4e}; fx {:.4} vs {}",
        o2.counts, num(c2, "ncon"), num(c2, "nadh"), num(c2, "nslip"), o2.shift.0, num(c2, "shift_x"), o2.force.0, num(c2, "fx")
    );
    assert!(dn <= 1e-4 && dt <= 1e-4 && states == 0, "pn {dn:e}, pt {dt:e}, states {states}");
    assert_eq!((o2.counts.0, o2.counts.1, o2.counts.2), (177, 45, 132));
    assert!((o2.shift.0 - num(c2, "shift_x")).abs() <= 5e-4 * num(c2, "shift_x").abs());
}

/// `examples/spence35.inp`: Spence's compression of a soft body (G₁ = 0.5, ν₁ = 0) on a nearly rigid one
/// (G₂ = 1e5, ν₂ = 0): coupled (K ≠ 0), μ = 0.2986, h = 0.004116(x² + y²), 35 load stages at zero shift on a 45 × 45
/// grid of 0.2 mm from XL = YL = −4.4999. Per-element tractions of stages 1, 12, 24 and 35 within 2e-5 of p_max
/// (CONTACT's 6 printed digits, 5e-6 of a value, and its EPS = 1e-6; measured ≤ 8.4e-6), every element's state,
/// and the contact, stick and slip counts of all 35 stages exactly (stage 35: 921, 225, 696).
#[test]
fn spence35_inp_agrees_with_contact() {
    let cases = csv("spence35_cases.csv");
    let loads: Vec<f64> = cases
        .iter()
        .map(|r| r["prescribed"].split("FN = ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(loads.len(), 35);
    let steps = loads.iter().map(|&l| Step::new(Drive::Load(l), TangentialDrive::Shift(0.0, 0.0))).collect();
    let g = grid(45, 45, -4.4999, -4.4999, 0.2, 0.2);
    let prof = Profile::Quadratic { a: 0.004116, b: 0.004116 };
    let path = Path::new(g, body(0.5, 0.0), body(1e5, 0.0), prof, 0.2986, true, steps).unwrap();
    assert!(path.is_coupled());
    let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
    assert_eq!(out.len(), 35);
    let mut worst_counts = 0;
    for (k, (o, c)) in out.iter().zip(&cases).enumerate() {
        assert_eq!(o.status, PathStatus::Solved, "stage {}: {}", k + 1, o.message);
        let theirs = (num(c, "ncon_mat") as usize, num(c, "nadh_mat") as usize, num(c, "nslip_mat") as usize);
        let diff = o.counts.0.abs_diff(theirs.0) + o.counts.1.abs_diff(theirs.1) + o.counts.2.abs_diff(theirs.2);
        worst_counts = worst_counts.max(diff);
        if diff > 0 {
            println!("stage {}: counts {:?} vs CONTACT {:?}", k + 1, o.counts, theirs);
        }
    }
    for stage in [1, 12, 24, 35] {
        let (dn, dt, states) = compare(&out[stage - 1], &g, &format!("spence35_case{stage}_elements.csv"));
        println!(
            "spence35 stage {stage}: pn {dn:.2e}, pt {dt:.2e} of pmax, {states} states differ, {} alternations",
            out[stage - 1].outer_iterations
        );
        assert!(dn <= 2e-5 && dt <= 2e-5 && states == 0, "stage {stage}: pn {dn:e}, pt {dt:e}, states {states}");
    }
    assert_eq!(worst_counts, 0);
}

/// `perfc_test/norm_problm_1p.inp`: a wheel on a rail, frictionless, approach 0.02084 mm prescribed, G = 82 000,
/// ν = 0.28 on both bodies, the profile p(y) + x²/(2·483.931) with CONTACT's tabulated p(y) (271 points, linearly
/// interpolated), 71 × 81 elements of 0.1 mm from (−3.55, −6.15). Our profile at the element centres equals
/// CONTACT's `h` to its 6 printed digits; the contact has CONTACT's 3 148 elements, exactly those; the pressures
/// agree to 2e-5 of p_max (CONTACT's EPS = 1e-7 and its 6 digits), FN and p_max to their 4 printed digits.
#[test]
fn norm_problm_1p_agrees_with_contact() {
    let p: Vec<f64> = csv("norm_problm_1p_profile.csv").iter().map(|r| num(r, "p")).collect();
    let profile = |y: f64| {
        let t = ((y + 12.0) / 0.1).clamp(0.0, (p.len() - 1) as f64);
        let k = (t.floor() as usize).min(p.len() - 2);
        p[k] + (t - k as f64) * (p[k + 1] - p[k])
    };
    let g = grid(71, 81, -3.55, -6.15, 0.1, 0.1);
    let h = g.sample(|x, y| profile(y) + x * x / (2.0 * 483.931));
    for r in csv("norm_problm_1p_case1_elements.csv") {
        let i = (num(&r, "ix") as usize - 1) + 71 * (num(&r, "iy") as usize - 1);
        assert!(
            (h[i] - num(&r, "h")).abs() <= 5e-6 * num(&r, "h").abs().max(1e-3),
            "element {i}: h {} vs {}",
            h[i],
            num(&r, "h")
        );
    }
    let steel = body(82000.0, 0.28);
    let step = Step::new(Drive::Approach(0.02084), TangentialDrive::Shift(0.0, 0.0));
    let path = Path::new(g, steel, steel, Profile::Gap(h), 0.0, true, vec![step]).unwrap();
    let o = &path.solve(&PathSettings::default(), &Cancel::never()).unwrap()[0];
    assert_eq!(o.status, PathStatus::Solved, "{}", o.message);
    let (dn, _, states) = compare(o, &g, "norm_problm_1p_case1_elements.csv");
    let c = &csv("norm_problm_1p_cases.csv")[0];
    let pmax = o.pressure.iter().fold(0.0_f64, |m, &v| m.max(v));
    println!(
        "norm_problm_1p: pn {dn:.2e} of pmax, {states} states differ; FN {:.1} vs {}; pmax {pmax:.2} vs {}",
        o.load,
        num(c, "fn"),
        num(c, "pmax")
    );
    assert!(dn <= 2e-5 && states == 0, "pn {dn:e}, states {states}");
    assert_eq!(o.counts.0, 3148);
    assert!(
        (o.load - num(c, "fn")).abs() <= 5e-4 * num(c, "fn") && (pmax - num(c, "pmax")).abs() <= 5e-4 * num(c, "pmax")
    );
}

/// Spence's receding stick zone for dissimilar spheres, as theory (`rollbem::theory::spence_sphere_c_over_a`, the
/// self-similar solution in Goodman's approximation, derived in `src/theory/spence3d.rs`): an elastic sphere (R = 1,
/// ν = 0.45, E* = 1) pressed on a rigid flat (β = (1 − 2ν)/(2(1 − ν)) = 1/11), μ = β/2 (β/μ = 2, c/a = 0.4851; βμ =
/// 0.004, so the coupling the theory neglects is small), the load raised from a = 0.2 to a = 1 in steps of half an
/// element of radius, coupled (`halfspace::Path`, zero tangential force). Error measure: |c/a − theory| with c/a =
/// √(N_stick/N_contact), the radii of the stick and contact areas (counts of elements) at the last step. Measured:
/// 0.0244 at 10 elements per radius (c/a 0.4608), 0.0054 at 20 (0.4798): a factor 4.5 per halving, order ≈ 2 (an
/// area count resolves a radius to O(h²) on average, but with O(h) jitter: two grids show the trend, not a
/// rate). 40 elements per radius (145 steps of 7 225 elements) would take minutes: not run here.
#[test]
fn spence_sphere_stick_radius_converges_to_theory() {
    let nu = 0.45;
    let beta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let mu = beta / 2.0;
    let theory = rollbem::theory::spence_sphere_c_over_a(beta / mu);
    let elastic = HalfSpace::new(1.0 - nu * nu, nu).unwrap();
    let rigid = HalfSpace::new(f64::INFINITY, nu).unwrap();
    let mut errs = Vec::new();
    for n in [10usize, 20] {
        let m = 2 * n + 5;
        let d = 1.0 / n as f64;
        let g = ContactGrid::new(m, m, d, d, -((n + 2) as f64) * d, -((n + 2) as f64) * d).unwrap();
        // a³ = 3PR/(4E*): P = (4/3) a³; a from 0.1 to 1 in steps of d/4.
        let steps: Vec<Step> = (0..)
            .map(|k| 0.2 + 0.5 * d * k as f64)
            .take_while(|&a| a < 1.0 + 1e-12)
            .map(|a| Step::new(Drive::Load(4.0 / 3.0 * a * a * a), TangentialDrive::Force(0.0, 0.0)))
            .collect();
        let path = Path::new(g, elastic, rigid, Profile::Quadratic { a: 0.5, b: 0.5 }, mu, true, steps).unwrap();
        let t0 = std::time::Instant::now();
        let out = path.solve(&PathSettings::default(), &Cancel::never()).unwrap();
        let o = out.last().unwrap();
        assert!(out.iter().all(|o| o.status == PathStatus::Solved), "{}", o.message);
        let ratio = (o.counts.1 as f64 / o.counts.0 as f64).sqrt();
        let outer: usize = out.iter().map(|o| o.outer_iterations).sum();
        let inner = out.iter().fold((0, 0), |a, o| (a.0 + o.iterations.0, a.1 + o.iterations.1));
        println!(
            "n = {n}: {} steps ({outer} alternations, inner {inner:?}), c/a {ratio:.4} ({} stick of {} in contact) vs \
             theory {theory:.4}: error {:.4}, {:.1} s",
            out.len(),
            o.counts.1,
            o.counts.0,
            (ratio - theory).abs(),
            t0.elapsed().as_secs_f64()
        );
        errs.push((ratio - theory).abs());
    }
    assert!(errs[1] < 0.5 * errs[0] && errs[1] < 0.01, "{errs:?}");
}
