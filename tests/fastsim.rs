//! FASTSIM (`rollbem::fastsim`) checked three ways, each test saying where its expected value comes from:
//! (a) at vanishing creepage it reproduces the linear theory it is built on (Kalker's C_ij through the flexibilities,
//! derived in the module docs), converging as the grid refines; (b) at large creepage the whole contact slides and
//! the force is μ Σ pn dA (→ μN); (c) CONTACT's `examples/fastsim.inp` (its FASTSIM cases 2, 3, 5, 6, 8) against
//! the author's printed output and our CONTACT build's per-element files (`reference/contact3d/fastsim/`, whose
//! README says which number comes from where); its cases 4 and 7 (FaStrip, `M = 5`) against `fastsim::fastrip`, and
//! FaStrip against its own theory (Kalker's linear limit, Carter in every strip). Case 1 (CONTACT's exact half-space
//! solver) is tests/rolling3d.rs's. Also CONTACT's `tractcurv.inp` cases 61–90 (its original-FASTSIM creep curve).

use rollbem::fastsim::{fastrip, solve, Bound, Contact, Creepages, Direction, Flexibility, Grid, Options, State};
use rollbem::theory::kalker::creep_coefficients;
use std::collections::HashMap;
use std::f64::consts::PI;

#[path = "common/contact_ref.rs"]
mod contact_ref;
use contact_ref::{half_unit, num};

/// One CSV of `reference/contact3d/fastsim/`.
fn csv(name: &str) -> Vec<std::collections::HashMap<String, String>> {
    contact_ref::csv(&format!("fastsim/{name}"))
}

/// CONTACT's material and load of `fastsim.inp`.
fn contact_of(row: &HashMap<String, String>) -> Contact {
    Contact {
        a: num(row, "a"),
        b: num(row, "b"),
        shear_modulus: num(row, "g"),
        nu: num(row, "nu"),
        mu: num(row, "mu"),
        normal_force: num(row, "fn"),
    }
}

/// CONTACT's M = 3 (three blended flexibilities) with B = 2 or 3 on its grid IPOTCN = −3, DQ = DX.
fn options_of(row: &HashMap<String, String>) -> Options {
    let bound = match row["bound"].as_str() {
        "parabolic" => Bound::Parabolic,
        "elliptic" => Bound::Elliptic,
        b => panic!("bound {b}"),
    };
    let direction = if num(row, "chi_deg") == 0.0 { Direction::PlusX } else { Direction::MinusX };
    let (mx, my, scale) = (num(row, "mx") as usize, num(row, "my") as usize, num(row, "scale"));
    let grid = Grid::Contact { mx, my, scale, spin_offset: 1.0 / 6.0 };
    // CONTACT steps by DQ and assumes DQ = DX: check that the input says so.
    let dx = 2.0 * scale * num(row, "a") / mx as f64;
    assert!((dx - num(row, "dq")).abs() < 1e-12, "case {}: DQ {} is not DX {dx}", row["case"], row["dq"]);
    Options { bound, flexibility: Flexibility::Blended, direction, grid }
}

/// The printed totals of a `fastsim.inp` case against a solution: FX, FY, MZ, FY/FSTAT/FN and PMAX within half a
/// unit of their last printed digit, NCON, NADH, NSLIP exactly.
fn assert_printed(row: &HashMap<String, String>, s: &rollbem::fastsim::Solution) {
    let case = &row["case"];
    let fy_rel = s.fy / (num(row, "mu") * num(row, "fn"));
    let pmax = s.elements.iter().map(|e| e.pn).fold(0.0, f64::max);
    for (key, got) in [("fx", s.fx), ("fy", s.fy), ("mz", s.mz), ("fy_rel", fy_rel), ("pmax", pmax)] {
        let d = (got - num(row, key)).abs();
        assert!(d <= half_unit(&row[key]), "case {case} {key}: {got:.6e} vs printed {}", row[key]);
    }
    for (key, got) in [("ncon", s.n_contact), ("nadh", s.n_adhesion), ("nslip", s.n_slip)] {
        assert_eq!(got, num(row, key) as usize, "case {case} {key}");
    }
}

#[test]
fn contact_fastsim_cases_reproduced_to_the_printed_digits() {
    // Expected: the author's fastsim.ref_out as printed (FX, FY, MZ, FY/FSTAT/FN, PMAX to 4 digits, NCON, NADH,
    // NSLIP exactly) and the flexibilities to six digits from our build's .mat files (CONTACT's linrol + simpflex:
    // Table E.3 interpolated to a/b = 2, ν = 0.28, then blended). Each within half a unit of the last printed digit.
    let mut compared = 0;
    for row in csv("fastsim_cases.csv") {
        if !row["method"].starts_with("fastsim") {
            continue; // case 1 (exact half-space): tests/rolling3d.rs; 4 and 7 (FaStrip): the test below
        }
        let case = &row["case"];
        let cr = Creepages { xi: num(&row, "xi"), eta: num(&row, "eta"), phi: num(&row, "phi") };
        let s = solve(&contact_of(&row), &cr, &options_of(&row)).unwrap();
        for (i, key) in ["flx1_mat", "flx2_mat", "flx3_mat"].iter().enumerate() {
            let d = (s.flexibilities[i] - num(&row, key)).abs();
            assert!(d <= half_unit(&row[*key]), "case {case} {key}: {} vs {}", s.flexibilities[i], row[*key]);
        }
        assert_printed(&row, &s);
        println!("case {case}: Fy {:.6e} (printed {}), Mz {:.6e} (printed {})", s.fy, row["fy"], s.mz, row["mz"]);
        compared += 1;
    }
    assert_eq!(compared, 5);
}

#[test]
fn contact_fastsim_tractions_reproduced_per_element() {
    // Expected: our CONTACT build's per-element results of cases 2, 3 (FASTSIM) and 4 (FaStrip) (fastsim.000K.mat,
    // six significant digits): every element's state equal, pn, px, py within half a unit of their sixth digit
    // (plus the single-precision slack explained below).
    let cases = csv("fastsim_cases.csv");
    for case in [2, 3, 4] {
        let row = cases.iter().find(|r| r["case"] == case.to_string()).unwrap();
        let cr = Creepages { xi: num(row, "xi"), eta: num(row, "eta"), phi: num(row, "phi") };
        let opt = options_of(row);
        let contact = contact_of(row);
        let s = if case == 4 { fastrip(&contact, &cr, &opt) } else { solve(&contact, &cr, &opt) }.unwrap();
        let pmax = s.elements.iter().map(|e| e.pn).fold(0.0, f64::max);
        let reference = csv(&format!("fastsim_case{case}_elements.csv"));
        assert_eq!(reference.len(), s.n_contact, "case {case}: elements in contact");
        let mut worst: f64 = 0.0;
        // The largest |p|/(μ pn) of CONTACT's elements: ≤ 1 for FASTSIM; FaStrip's strip tractions exceed the bound
        // (fastsim::fastrip's docs), and Solution::bound_ratio must report it as CONTACT's own numbers show it.
        let ratio = |r: &HashMap<String, String>| num(r, "px").hypot(num(r, "py")) / (contact.mu * num(r, "pn"));
        let contact_ratio = reference.iter().map(ratio).fold(0.0, f64::max);
        assert!((s.bound_ratio - contact_ratio).abs() < 1e-4 * contact_ratio, "case {case}: {}", s.bound_ratio);
        assert_eq!(contact_ratio > 1.0 + 1e-5, case == 4, "case {case}: CONTACT's ratio {contact_ratio}");
        for r in &reference {
            let (ix, iy) = (num(r, "ix") as usize - 1, num(r, "iy") as usize - 1);
            let e = &s.elements[ix + opt.grid.size().0 * iy];
            let state = match e.state {
                State::Adhesion => "adhesion",
                State::Slip => "slip",
                State::Exterior => "exterior",
            };
            assert_eq!(state, r["state"], "case {case} element ({}, {})", ix + 1, iy + 1);
            for (key, got) in [("pn", e.pn), ("px", e.px), ("py", e.py)] {
                let want = num(r, key);
                // Sixth significant digit: half a unit of 10^(floor(log10|want|) − 5).
                let tol = 0.5 * 10f64.powi(want.abs().max(1e-300).log10().floor() as i32 - 5);
                // Plus 1e-7 of the largest traction μ·max pn: CONTACT's Table E.3 is a Fortran DATA statement of
                // default-real (single precision) literals, so its C_ij and flexibilities differ from ours (the
                // decimal numbers in double precision) by up to 2^-24 ≈ 6e-8 relative, and its tractions by as
                // much of their scale (more of a small py that is a difference of the η and spin terms); a value
                // near a rounding boundary of its sixth digit then prints differently (68 of the 2 × 1 264 × 3
                // numbers; checked: with the table rounded to f32 every number agrees within half a sixth-digit
                // unit).
                let beyond = ((got - want).abs() - tol).max(0.0) / (contact.mu * pmax);
                worst = worst.max(beyond);
                assert!(beyond <= 1e-7, "case {case} ({}, {}) {key}: {got} vs {want}", ix + 1, iy + 1);
            }
        }
        println!(
            "case {case}: {} elements, largest difference beyond half a sixth-digit unit {worst:.2e} of μ max pn; \
             largest |p|/(μ pn) {:.4}",
            reference.len(),
            s.bound_ratio
        );
    }
}

fn kalker_contact(a: f64, b: f64, nu: f64) -> Contact {
    Contact { a, b, shear_modulus: 80_000.0, nu, mu: 0.3, normal_force: 10_000.0 }
}

fn fine(flexibility: Flexibility, n: usize, strips: bool) -> Options {
    let grid = if strips { Grid::Strips { mx: n, my: n } } else { Grid::contact(n, n, 1.0) };
    Options { flexibility, grid, ..Options::default() }
}

#[test]
fn small_creepage_reproduces_kalkers_linear_theory() {
    // Expected (theory, derived in rollbem::fastsim's module docs): with nothing slipping the simplified theory with
    // L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = π a^{3/2}/(4 C23 G √b) gives exactly Fx = −G c² C11 ξ,
    // Fy = −G c² C22 η and, for the spin, Fy = −G c³ C23 φ (c = √(ab)); the C_ij from Table E.3
    // (rollbem::theory::kalker). The grid's error must fall as the grid refines: as dy² on Grid::Strips (exact
    // along x; under 1e-5 with 400 strips of 400), as dx on CONTACT's grid (under 0.5 % on 400 × 400; module
    // docs). Also, FASTSIM's own Mz for η alone is π a³ b η/(4 L2) (the same integral).
    for (a, b, nu) in [(8.0, 4.0, 0.28), (3.0, 6.0, 0.25), (5.0, 5.0, 0.0)] {
        let contact = kalker_contact(a, b, nu);
        let k = creep_coefficients(a, b, nu).unwrap();
        let (g, c) = (contact.shear_modulus, (a * b).sqrt());
        let l2 = 8.0 * a / (3.0 * k.c22 * g);
        let eps = 1e-9;
        let cases: [(Creepages, f64); 3] = [
            (Creepages { xi: eps, eta: 0.0, phi: 0.0 }, -g * c * c * k.c11 * eps),
            (Creepages { xi: 0.0, eta: eps, phi: 0.0 }, -g * c * c * k.c22 * eps),
            (Creepages { xi: 0.0, eta: 0.0, phi: eps / c }, -g * c * c * c * k.c23 * eps / c),
        ];
        for (strips, flexibility) in [
            (true, Flexibility::Weighted),
            (true, Flexibility::Three),
            (false, Flexibility::Weighted),
            (false, Flexibility::Three),
        ] {
            for (i, (cr, want)) in cases.iter().enumerate() {
                let mut errors = vec![];
                for n in [100, 200, 400] {
                    let s = solve(&contact, cr, &fine(flexibility, n, strips)).unwrap();
                    assert_eq!(s.n_slip, 0, "no slip at vanishing creepage");
                    let got = if i == 0 { s.fx } else { s.fy };
                    errors.push((got - want).abs() / want.abs());
                    if i == 1 && n == 400 {
                        let mz = PI * a.powi(3) * b * eps / (4.0 * l2);
                        assert!((s.mz - mz).abs() < 0.01 * mz.abs(), "Mz(η) {} vs {mz}", s.mz);
                    }
                }
                println!(
                    "a/b = {}, ν = {nu}, strips {strips}, {flexibility:?}, creepage {i}: relative errors {errors:?}",
                    a / b
                );
                // Strips: second order (the y-midpoint rule; x is exact), CONTACT's grid: first order.
                let (order, bound) = if strips { (3.5, 1e-5) } else { (1.8, 5e-3) };
                assert!(errors[0] / errors[1] > order && errors[1] / errors[2] > order, "{errors:?}");
                assert!(errors[2] < bound, "{errors:?}");
            }
        }
    }
}

#[test]
fn large_creepage_slides_everywhere_at_mu_n() {
    // Expected (Coulomb's law, full sliding): when every element slips, |p| = μ pn everywhere and, without spin,
    // every traction has the direction of the first trial step, −(ξ/L1, η/L2): so F = −μ Σ pn dA · d/|d| with
    // d = (ξ/L1, η/L2), exactly (to rounding). With one flexibility (Weighted) d is along w = (ξ, η), the slip's
    // direction; with L1 ≠ L2 (Three, Blended) the force leans off it (the known price of three flexibilities,
    // module docs) — its angle is printed. And Σ pn dA → N as the grid refines (the parabolic and Hertzian pressures
    // integrate to N over the ellipse; the element-centre rule converges).
    let contact = kalker_contact(8.0, 4.0, 0.28);
    for bound in [Bound::Parabolic, Bound::Elliptic] {
        for flexibility in [Flexibility::Weighted, Flexibility::Three, Flexibility::Blended] {
            for (xi, eta) in [(0.5, 0.0), (0.0, -0.5), (0.3, 0.4)] {
                let mut o = fine(flexibility, 200, true);
                o.bound = bound;
                let s = solve(&contact, &Creepages { xi, eta, phi: 0.0 }, &o).unwrap();
                assert_eq!(s.n_slip, s.n_contact, "{bound:?} {flexibility:?}: all slip");
                let (dx, dy) = (xi / s.flexibilities[0], eta / s.flexibilities[1]);
                let d = dx.hypot(dy);
                let limit = contact.mu * s.fn_discrete;
                assert!((s.fx + limit * dx / d).abs() < 1e-12 * limit, "{bound:?} {flexibility:?} {}", s.fx);
                assert!((s.fy + limit * dy / d).abs() < 1e-12 * limit, "{bound:?} {flexibility:?} {}", s.fy);
                if flexibility == Flexibility::Weighted {
                    assert!((dx / d - xi / xi.hypot(eta)).abs() < 1e-15);
                }
                assert!((s.fn_discrete - contact.normal_force).abs() < 2e-3 * contact.normal_force);
                let lean = (dy.atan2(dx) - eta.atan2(xi)).to_degrees();
                println!(
                    "{bound:?} {flexibility:?} ({xi}, {eta}): |F|/(μN) = {:.6}, lean off w {lean:.3}°",
                    s.fx.hypot(s.fy) / (contact.mu * contact.normal_force)
                );
            }
        }
    }
    // The discrete load converges to N: 100 → 400 elements across.
    let load = |n| solve(&contact, &Creepages::default(), &fine(Flexibility::Weighted, n, true)).unwrap().fn_discrete;
    let (e1, e2) = ((load(100) - 1e4).abs(), (load(400) - 1e4).abs());
    println!("Σ pn dA − N: {e1:.3e} (100 across), {e2:.3e} (400 across)");
    assert!(e2 < e1 && e2 < 1e-4 * 1e4, "{e1} {e2}");
}

#[test]
fn bad_input_is_refused_naming_the_argument() {
    // Expected: the documented ranges of rollbem::fastsim::solve.
    let ok = kalker_contact(8.0, 4.0, 0.28);
    let cr = Creepages { xi: 1e-3, eta: 0.0, phi: 0.0 };
    let o = Options::default();
    let cases: Vec<(Contact, Creepages, Options, &str)> = vec![
        (Contact { a: -1.0, ..ok }, cr, o, "a"),
        (Contact { b: f64::NAN, ..ok }, cr, o, "b"),
        (Contact { shear_modulus: 0.0, ..ok }, cr, o, "shear_modulus"),
        (Contact { normal_force: f64::INFINITY, ..ok }, cr, o, "normal_force"),
        (Contact { mu: -0.1, ..ok }, cr, o, "mu"),
        (Contact { nu: 0.7, ..ok }, cr, o, "nu"),
        (Contact { a: 80.0, ..ok }, cr, o, "a"),
        (ok, Creepages { eta: f64::NAN, ..cr }, o, "eta"),
        (ok, Creepages { phi: f64::INFINITY, ..cr }, o, "phi"),
        (ok, cr, Options { grid: Grid::Strips { mx: 0, my: 10 }, ..o }, "grid"),
        (ok, cr, Options { grid: Grid::contact(10, 0, 1.1), ..o }, "grid"),
        (ok, cr, Options { grid: Grid::contact(10, 10, 0.9), ..o }, "grid.scale"),
        (
            ok,
            cr,
            Options { grid: Grid::Contact { mx: 10, my: 10, scale: 1.1, spin_offset: f64::NAN }, ..o },
            "grid.spin_offset",
        ),
        (ok, cr, Options { grid: Grid::Strips { mx: 1 << 20, my: 1 << 20 }, ..o }, "grid"),
    ];
    for (contact, cr, o, arg) in cases {
        let e = solve(&contact, &cr, &o).unwrap_err();
        assert_eq!(e.argument, arg, "{e:?}");
    }
}

#[test]
fn contact_tractcurv_original_fastsim_series_reproduced() {
    // Expected: CONTACT's tractcurv.inp, cases 61–90 (its third series: "original Fastsim", M = 3 with
    // K0_MF = ALFAMF = 1, parabolic bound B = 3, Coulomb μ = 0.33, the Eurosprinter creep curve of Polach 2005:
    // ξ from 1e-5 to 0.25, η = φ = 0): the author's tractcurv.ref_out as printed (FX, FX/FSTAT/FN, PMAX to their
    // digits; NCON, NADH, NSLIP exactly) and the flexibilities to six digits from our build's .mat files. The
    // ellipse (IPOTCN = −2: curvature A1 and a/b given, CONTACT solves Hertz) is taken from the .mat grid,
    // a = MX·DX/(2·1.1), b = MY·DY/(2·1.1), six digits: the flexibilities (∝ a) are compared within half a unit of
    // their sixth digit plus 1e-6 of their value for it.
    let mut largest: f64 = 0.0;
    for row in csv("tractcurv_fastsim_cases.csv") {
        let case = &row["case"];
        let (mx, my, scale) = (num(&row, "mx") as usize, num(&row, "my") as usize, num(&row, "scale"));
        let a = mx as f64 * num(&row, "dx") / (2.0 * scale);
        let b = my as f64 * num(&row, "dy") / (2.0 * scale);
        assert!(
            (a - num(&row, "a")).abs() <= half_unit(&row["a"]) && (b - num(&row, "b")).abs() <= half_unit(&row["b"])
        );
        let contact = Contact {
            a,
            b,
            shear_modulus: num(&row, "g"),
            nu: num(&row, "nu"),
            mu: num(&row, "mu"),
            normal_force: num(&row, "fn_input"),
        };
        let cr = Creepages { xi: num(&row, "xi"), eta: num(&row, "eta"), phi: num(&row, "phi") };
        let o = Options {
            bound: Bound::Parabolic,
            flexibility: Flexibility::Blended,
            direction: Direction::PlusX,
            grid: Grid::contact(mx, my, scale),
        };
        assert!((o.grid.size().0 as f64 * num(&row, "dq") - 2.0 * scale * a).abs() < 1e-3, "DQ = DX");
        let s = solve(&contact, &cr, &o).unwrap();
        for (i, key) in ["flx1_mat", "flx2_mat", "flx3_mat"].iter().enumerate() {
            let (got, want) = (s.flexibilities[i], num(&row, key));
            assert!((got - want).abs() <= half_unit(&row[*key]) + 1e-6 * want, "case {case} {key}: {got} vs {want}");
        }
        let fx_rel = s.fx / (contact.mu * contact.normal_force);
        let pmax = s.elements.iter().map(|e| e.pn).fold(0.0, f64::max);
        for (key, got) in [("fx", s.fx), ("fy", s.fy), ("mz", s.mz), ("fx_rel", fx_rel), ("pmax", pmax)] {
            let d = (got - num(&row, key)).abs();
            assert!(d <= half_unit(&row[key]), "case {case} {key}: {got:.6e} vs printed {}", row[key]);
            if key == "fx" {
                largest = largest.max(d / half_unit(&row[key]));
            }
        }
        for (key, got) in [("ncon", s.n_contact), ("nadh", s.n_adhesion), ("nslip", s.n_slip)] {
            assert_eq!(got, num(&row, key) as usize, "case {case} {key}");
        }
    }
    println!("tractcurv 61–90: largest |ΔFx| {largest:.2} of half a printed unit");
}

#[test]
fn rolling_along_minus_x_mirrors_rolling_along_plus_x() {
    // Expected (symmetry): mirroring the problem in x (x → −x) turns rolling along +x with (ξ, η, φ) into rolling
    // along −x with (−ξ, η, −φ) (the rigid slip's x-component changes sign, its y-component not), so Fx and Mz
    // change sign and Fy does not; both grids are symmetric in x, so this holds to rounding, with slip and without,
    // for every flexibility variant and bound. (CONTACT's case 8 of fastsim.inp is the same check on its side.)
    let contact = kalker_contact(6.0, 4.0, 0.28);
    for grid in [Grid::Strips { mx: 60, my: 40 }, Grid::contact(60, 40, 1.1)] {
        for flexibility in [Flexibility::Weighted, Flexibility::Three, Flexibility::Blended] {
            for bound in [Bound::Parabolic, Bound::Elliptic] {
                for scale in [1e-7, 1e-3] {
                    let cr = Creepages { xi: 0.4 * scale, eta: -0.7 * scale, phi: 0.2 * scale };
                    let mut o = Options { bound, flexibility, direction: Direction::PlusX, grid };
                    let p = solve(&contact, &cr, &o).unwrap();
                    o.direction = Direction::MinusX;
                    let m = solve(&contact, &Creepages { xi: -cr.xi, eta: cr.eta, phi: -cr.phi }, &o).unwrap();
                    let f = p.fx.abs() + p.fy.abs();
                    assert!((p.fx + m.fx).abs() < 1e-9 * f, "{grid:?} {flexibility:?}: {} {}", p.fx, m.fx);
                    assert!((p.fy - m.fy).abs() < 1e-9 * f, "{grid:?} {flexibility:?}: {} {}", p.fy, m.fy);
                    assert!((p.mz + m.mz).abs() < 1e-9 * f * 6.0, "{grid:?} {flexibility:?}: {} {}", p.mz, m.mz);
                    assert_eq!((p.n_adhesion, p.n_slip), (m.n_adhesion, m.n_slip));
                    if scale > 1e-5 {
                        assert!(p.n_slip > 0 && p.n_adhesion > 0, "both zones present: {} {}", p.n_slip, p.n_adhesion);
                    }
                }
            }
        }
    }
}

#[test]
fn contact_fastrip_cases_reproduced_to_the_printed_digits() {
    // Expected: the author's fastsim.ref_out for cases 4 and 7 (CONTACT's M = 5, "modified FaStrip", B = 2), as
    // printed: FX, FY, MZ, FY/FSTAT/FN and PMAX within half a unit of their last digit, NCON, NADH, NSLIP exactly.
    // rollbem::fastsim::fastrip is written from Sichani et al. (2016) and the decisions its module docs list.
    let mut compared = 0;
    for row in csv("fastsim_cases.csv") {
        if !row["method"].starts_with("fastrip") {
            continue;
        }
        let case = &row["case"];
        let cr = Creepages { xi: num(&row, "xi"), eta: num(&row, "eta"), phi: num(&row, "phi") };
        let s = fastrip(&contact_of(&row), &cr, &options_of(&row)).unwrap();
        let fy_rel = s.fy / (num(&row, "mu") * num(&row, "fn"));
        let pmax = s.elements.iter().map(|e| e.pn).fold(0.0, f64::max);
        println!(
            "case {case}: Fx {:.4e} Fy {:.4e} (printed {}) Mz {:.4e} (printed {}) counts {} {} {} (printed {} {} {})",
            s.fx,
            s.fy,
            row["fy"],
            s.mz,
            row["mz"],
            s.n_contact,
            s.n_adhesion,
            s.n_slip,
            row["ncon"],
            row["nadh"],
            row["nslip"]
        );
        for (key, got) in [("fx", s.fx), ("fy", s.fy), ("mz", s.mz), ("fy_rel", fy_rel), ("pmax", pmax)] {
            let d = (got - num(&row, key)).abs();
            assert!(d <= half_unit(&row[key]), "case {case} {key}: {got:.6e} vs printed {}", row[key]);
        }
        for (key, got) in [("ncon", s.n_contact), ("nadh", s.n_adhesion), ("nslip", s.n_slip)] {
            assert_eq!(got, num(&row, key) as usize, "case {case} {key}");
        }
        compared += 1;
    }
    assert_eq!(compared, 2);
}

/// FaStrip on `n` strips of `n` elements (the ellipse followed exactly), elliptic bound, three flexibilities.
fn fastrip_on_strips(contact: &Contact, cr: &Creepages, n: usize) -> rollbem::fastsim::Solution {
    let grid = Grid::Strips { mx: n, my: n };
    let o = Options { bound: Bound::Elliptic, flexibility: Flexibility::Three, direction: Direction::PlusX, grid };
    fastrip(contact, cr, &o).unwrap()
}

#[test]
fn fastrip_small_creepage_reproduces_kalkers_linear_theory() {
    // Expected (theory, fastsim::fastrip's module docs): the strip theory's creepages are scaled by Kalker's C_ij so
    // that at vanishing creepage Fx = −G ab C11 ξ, Fy = −G ab C22 η and, for the spin alone, Fy = −G (ab)^{3/2} C23 φ
    // (C_ij from Table E.3, theory::kalker). At vanishing creepage the strip tractions have the linear theory's
    // square-root singularity at the trailing edge, ∝ √((a_j − x)/(a_j + x)), and the grid's midpoint sums of it err
    // by C h^{1/2} (h the element length): the error must shrink by √2 per halving of h (checked to 3 %), and the
    // Richardson extrapolation with that rate, (√2 F(2n) − F(n))/(√2 − 1), must agree with Kalker within 2e-4. The
    // spin's lateral traction has no such singularity (its leading term is φ' √((a_j − d)² − (x − d)²)): its error
    // must fall with h and be below 0.1 % at 400 strips of 400.
    let contact = kalker_contact(6.0, 4.0, 0.28);
    let c = creep_coefficients(6.0, 4.0, 0.28).unwrap();
    let (g, ab) = (contact.shear_modulus, 24.0);
    let small = 1e-9;
    let cases = [
        (Creepages { xi: small, eta: 0.0, phi: 0.0 }, -g * ab * c.c11 * small, 0, true),
        (Creepages { xi: 0.0, eta: small, phi: 0.0 }, -g * ab * c.c22 * small, 1, true),
        (Creepages { xi: 0.0, eta: 0.0, phi: small / 5.0 }, -g * ab.powf(1.5) * c.c23 * small / 5.0, 1, false),
    ];
    for (cr, linear, component, singular) in cases {
        let forces: Vec<f64> = [100, 200, 400]
            .iter()
            .map(|&n| {
                let s = fastrip_on_strips(&contact, &cr, n);
                if component == 0 {
                    s.fx
                } else {
                    s.fy
                }
            })
            .collect();
        let errors: Vec<f64> = forces.iter().map(|f| f / linear - 1.0).collect();
        let r2 = std::f64::consts::SQRT_2;
        let extrapolated = (r2 * forces[2] - forces[1]) / (r2 - 1.0);
        println!(
            "{cr:?}: relative errors at 100, 200, 400: {errors:?}; extrapolated {:.2e}",
            extrapolated / linear - 1.0
        );
        if singular {
            for w in errors.windows(2) {
                assert!((w[0] / w[1] / r2 - 1.0).abs() < 0.03, "{cr:?}: not the h^1/2 rate: {errors:?}");
            }
            assert!((extrapolated / linear - 1.0).abs() < 2e-4, "{cr:?}: extrapolated {extrapolated} vs {linear}");
        } else {
            assert!(errors.windows(2).all(|w| w[1].abs() < w[0].abs()), "{cr:?}: not converging {errors:?}");
            assert!(errors[2].abs() < 1e-3, "{cr:?}: {errors:?}");
        }
    }
}

#[test]
fn fastrip_longitudinal_creepage_is_carter_in_every_strip() {
    // Expected (an independent computation): for ξ alone every strip is Carter's 2D problem with the pressure
    // pmax √(a_j² − x²)/a, so Fx = −sign(ξ) μ pmax (π/2a) ∫ (a_j² − max(a_j − d, 0)²) dy with d = |ξ'| a/(1 − ν) and
    // ξ' = 4(1 − ν) G C11 ξ/(2π² μ pmax) (Sichani et al. 2016), integrated here by a 200 000-point midpoint rule in y.
    // The strips grid's sums are the midpoint rule of the same tractions in x: the error falls as the grid refines.
    let contact = kalker_contact(6.0, 4.0, 0.28);
    let c = creep_coefficients(6.0, 4.0, 0.28).unwrap();
    let (a, b, nu, mu) = (contact.a, contact.b, contact.nu, contact.mu);
    let pmax = 1.5 * contact.normal_force / (PI * a * b);
    for d_over_a in [0.1, 0.3, 0.7] {
        // The creepage that gives d = d_over_a · a.
        let xi_p = d_over_a * (1.0 - nu);
        let xi = xi_p * 2.0 * PI * PI * mu * pmax / (4.0 * (1.0 - nu) * contact.shear_modulus * c.c11);
        let d = d_over_a * a;
        let n = 200_000;
        let integral: f64 = (0..n)
            .map(|i| {
                let y = -b + (i as f64 + 0.5) * 2.0 * b / n as f64;
                let aj = a * (1.0 - (y / b).powi(2)).sqrt();
                (aj * aj - (aj - d).max(0.0).powi(2)) * 2.0 * b / n as f64
            })
            .sum();
        let expected = -mu * pmax * PI / (2.0 * a) * integral;
        let mut errors = Vec::new();
        for m in [100, 200, 400] {
            let s = fastrip_on_strips(&contact, &Creepages { xi, eta: 0.0, phi: 0.0 }, m);
            assert!(s.fy.abs() < 1e-12 * s.fx.abs(), "ξ alone: no lateral force, {}", s.fy);
            errors.push((s.fx / expected - 1.0).abs());
        }
        println!("d/a = {d_over_a}: Fx {expected:.6e}, relative errors at 100, 200, 400: {errors:?}");
        assert!(errors.windows(2).all(|w| w[1] < w[0]) && errors[2] < 1e-3, "d/a = {d_over_a}: {errors:?}");
    }
}

#[test]
fn fastrip_rolling_along_minus_x_is_the_point_reflection() {
    // Expected (symmetry, fastsim::fastrip's module docs): rolling along −x with (ξ, η, −φ) is rolling along +x with
    // (ξ, η, φ) seen after (x, y) → (−x, −y): every element's traction and state equal those of its reflection, so Fx
    // and Fy are equal and Mz changes sign.
    let contact = kalker_contact(6.0, 4.0, 0.28);
    let cr = Creepages { xi: 3e-4, eta: -6e-4, phi: 8e-4 };
    for grid in [Grid::Strips { mx: 60, my: 40 }, Grid::contact(60, 40, 1.1)] {
        let mut o =
            Options { bound: Bound::Elliptic, flexibility: Flexibility::Blended, direction: Direction::PlusX, grid };
        let p = fastrip(&contact, &cr, &o).unwrap();
        o.direction = Direction::MinusX;
        let m = fastrip(&contact, &Creepages { phi: -cr.phi, ..cr }, &o).unwrap();
        let n = p.elements.len();
        let scale = contact.mu * p.elements.iter().map(|e| e.pn).fold(0.0, f64::max);
        for (i, e) in p.elements.iter().enumerate() {
            let r = &m.elements[n - 1 - i];
            assert_eq!(e.state, r.state, "{grid:?} element {i}");
            assert!((e.px - r.px).abs() < 1e-12 * scale && (e.py - r.py).abs() < 1e-12 * scale, "{grid:?} {i}");
        }
        assert!(p.n_slip > 0 && p.n_adhesion > 0, "both zones present: {} {}", p.n_slip, p.n_adhesion);
        let f = p.fx.abs() + p.fy.abs();
        assert!((p.fx - m.fx).abs() < 1e-9 * f && (p.fy - m.fy).abs() < 1e-9 * f, "{grid:?}: {p:?} {m:?}");
        // Mz = Σ (x py − y px) changes sign with the lever arms.
        assert!((p.mz + m.mz).abs() < 1e-9 * f * contact.a, "{grid:?}: Mz {} {}", p.mz, m.mz);
    }
}

#[test]
fn fastrip_refuses_a_parabolic_bound_naming_it() {
    // Expected (fastsim::fastrip's module docs): the strip theory presumes Hertz's pressure.
    let contact = kalker_contact(6.0, 4.0, 0.28);
    let parabolic = Options { bound: Bound::Parabolic, ..Options::default() };
    let e = fastrip(&contact, &Creepages { xi: 1e-3, eta: 0.0, phi: 0.0 }, &parabolic).unwrap_err();
    assert!(e.to_string().contains("bound") && e.to_string().contains("Bound::Elliptic"), "{e}");
}
