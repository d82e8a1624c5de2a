//! The elastic half-plane beside the finite wheel, and the elastic counter-body. Expected values: Hertz and
//! Cattaneo–Mindlin (REFERENCES.md; half-plane theories, exact for the half-plane model with Hertz's parabolic
//! gap), an independent numerical quadrature of the Flamant line-load solution for the influence coefficients, and
//! the finite wheel (BEM) against the half-plane as a/R → 0.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::halfplane::HalfPlane;
use rollbem::pipeline::run_scene;
use rollbem::references::metrics;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use rollbem::source::{self, Blocks};
use rollbem::theory::{contact_modulus, Hertz2D};
use std::path::Path;
use std::process::Command;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("<test>")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn run(s: &Scene) -> Report {
    run_scene(s).unwrap()
}

fn lemke(r: &Report) -> &SolverRun {
    r.runs.iter().find(|x| x.solver == "lemke").expect("lemke run")
}

/// The steel wheel of hertz-hub-fine (R = 460 mm, E = 210 GPa in MPa, ν = 0.3, P = 20 000 N/mm: a = 7.12 mm) as a
/// half-plane with Hertz's parabolic gap.
fn steel(extra_wheel: &str, mesh: &str, contact: &str, drive: &str) -> Scene {
    scene(&format!(
        r#"
name = "half-plane-test"
[wheel]
radius = 460.0
youngs_modulus = 210000.0
poisson_ratio = 0.3
model = "half_plane"
profile = "parabola"
{extra_wheel}
[mesh]
element = "constant"
{mesh}
[contact]
{contact}
[drive]
{drive}
[solvers]
use = ["lemke"]
"#
    ))
}

#[test]
fn half_plane_hertz_is_met_to_a_tenth_of_a_percent_and_converges() {
    // Reference: Hertz (REFERENCES.md) at P. ≥ 40 elements across the contact: a and p0 (fitted) within 0.1 %;
    // the resultant equals the load to 1e-10; the L2 pressure error falls with the mesh at a fitted order ≥ 1.
    let h = Hertz2D::from_load(20000.0, 460.0, contact_modulus(210000.0, 0.3, f64::INFINITY, 0.0));
    let mut pts = Vec::new();
    for n in [20usize, 40, 80, 160, 320] {
        let s = steel("", &format!("contact_half_width = 9.0\ncontact_elements = {n}"), "", "normal_load = 20000.0");
        let r = run(&s);
        let l = lemke(&r);
        assert_eq!(l.status, Status::Solved, "{}", l.explanation());
        let res = l.resultants.unwrap();
        assert!((res.normal / 20000.0 - 1.0).abs() <= 1e-10, "P = {}", res.normal);
        let m = metrics(&s, l);
        let across = 2.0 * h.a / (18.0 / n as f64);
        if across >= 40.0 {
            assert!(m.hertz_a_err.unwrap() <= 1e-3, "n = {n}: a error {:?}", m.hertz_a_err);
            assert!(m.hertz_p0_err.unwrap() <= 1e-3, "n = {n}: p0 error {:?}", m.hertz_p0_err);
        }
        pts.push(((18.0 / n as f64).ln(), m.hertz_l2_err.unwrap().ln()));
        eprintln!(
            "n = {n} ({across:.0} across): a {:.2e} p0 {:.2e} L2 {:.2e}",
            m.hertz_a_err.unwrap(),
            m.hertz_p0_err.unwrap(),
            m.hertz_l2_err.unwrap()
        );
    }
    // Least-squares slope of ln(error) against ln(h) over all five meshes.
    let k = pts.len() as f64;
    let (mx, my) = (pts.iter().map(|p| p.0).sum::<f64>() / k, pts.iter().map(|p| p.1).sum::<f64>() / k);
    let slope =
        pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>() / pts.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
    eprintln!("fitted order of the L2 pressure error: {slope:.2}");
    assert!(slope >= 1.0, "order {slope}");
}

/// Cattaneo–Mindlin on a half-plane pair with β = 0 (REFERENCES.md): stick half-width within one element, shear
/// within 1 % of μp0 away from ±a and ±c (the metrics of `rollbem::references`).
fn cattaneo_check(s: &Scene) {
    let r = run(s);
    let l = lemke(&r);
    assert_eq!(l.status, Status::Solved, "{}", l.explanation());
    let m = metrics(s, l);
    let (err, centre, shear) = (m.cm_c_err_elements.unwrap(), m.cm_centre_elements.unwrap(), m.cm_shear_err.unwrap());
    eprintln!(
        "c/a {:.4} vs {:.4}: {err:+.2} elements, centre {centre:+.2}, shear {shear:.2e}",
        m.cm_c_over_a.unwrap(),
        m.cm_c_over_a_exact.unwrap()
    );
    assert!(err.abs() <= 1.0 && centre.abs() <= 1.0, "stick zone {err} {centre}");
    assert!(shear <= 0.01, "shear error {shear}");
    assert!(r.checks.iter().all(|c| c.pass), "{:?}", r.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
}

#[test]
fn cattaneo_on_the_half_plane_with_coupling_off_and_on_two_identical_half_planes() {
    let drive = "normal_load = 20000.0\ntangential_load = 2000.0";
    for mu in [0.3, 0.5] {
        // Rigid flat, coupling switched off.
        let s = steel(
            "",
            "contact_half_width = 9.0\ncontact_elements = 200",
            &format!("friction = {mu}\ncoupling = false"),
            drive,
        );
        cattaneo_check(&s);
        // Steel on steel: two identical half-planes, coupling on (β = 0 exactly). E* halves: a grows by √2.
        let mut s = steel("", "contact_half_width = 12.5\ncontact_elements = 250", &format!("friction = {mu}"), drive);
        s = s
            .edit(|d| {
                d.counter_body = rollbem::scene::document::CounterBodyTable::HalfPlane {
                    youngs_modulus: 210000.0,

                    poisson_ratio: 0.3,

                    datum_depth: None,
                    viscoelastic: None,
                }
            })
            .unwrap();
        assert_eq!(s.dundurs_beta(), 0.0);
        cattaneo_check(&s);
    }
}

#[test]
fn identical_half_planes_have_no_coupling_and_tangential_tractions_independent_of_nu() {
    // Two identical half-planes: the coupling blocks cancel exactly (the counter-body's mirror image of the wheel's).
    let pair = |nu: f64, e: f64| {
        let mut s = steel(
            "",
            "contact_half_width = 12.5\ncontact_elements = 100",
            "friction = 0.4",
            "normal_load = 20000.0\ntangential_load = 3000.0",
        );
        s = s
            .edit(|d| {
                d.wheel.poisson_ratio = nu;
                d.wheel.youngs_modulus = e;
            })
            .unwrap();
        s = s
            .edit(|d| {
                d.counter_body = rollbem::scene::document::CounterBodyTable::HalfPlane {
                    youngs_modulus: e,

                    poisson_ratio: nu,

                    datum_depth: None,
                    viscoelastic: None,
                }
            })
            .unwrap();
        s
    };
    let s = pair(0.3, 210000.0);
    let fl = source::build(&s, Blocks::All).unwrap().flex;
    assert!(fl.k_nt.as_ref().unwrap().col_iter().all(|c| c.iter().all(|v| *v == 0.0)));
    assert!(fl.k_tn.as_ref().unwrap().col_iter().all(|c| c.iter().all(|v| *v == 0.0)));
    // Same E* = E/(1 − ν²) at ν = 0.1 and ν = 0.45: with β = 0 the tractions are the same (the tangential problem
    // depends on the materials only through the tangential compliance 2(1 − ν²)/(πE) of each body). Reference: the
    // ν = 0.1 pair.
    let estar = 210000.0 / (1.0 - 0.09);
    let (a, b) = (run(&pair(0.1, estar * (1.0 - 0.01))), run(&pair(0.45, estar * (1.0 - 0.2025))));
    let (la, lb) = (lemke(&a), lemke(&b));
    assert_eq!((la.status, lb.status), (Status::Solved, Status::Solved), "{} / {}", la.explanation(), lb.explanation());
    let p0 = la.contact.as_ref().unwrap().peak_pressure;
    for (x, y) in paired(&la.nodes, &lb.nodes) {
        assert!((x.shear - y.shear).abs() <= 1e-10 * p0, "q at x = {}: {} vs {}", x.x, x.shear, y.shear);
        assert!((x.pressure - y.pressure).abs() <= 1e-10 * p0);
    }
}

/// Composite Gauss–Legendre (20 points per panel) of f over [a, b] split at the given points.
fn quad(f: &dyn Fn(f64) -> f64, a: f64, b: f64, splits: &[f64]) -> f64 {
    // Nodes and weights of the 20-point rule, from the Golub–Welsch eigenvalue problem solved here by Newton's
    // method on the Legendre polynomial (independent of the library's quadrature module).
    let n = 20;
    let mut nodes = Vec::new();
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                let w = 2.0 / ((1.0 - x * x) * dp * dp);
                nodes.push((x, w));
                break;
            }
        }
    }
    let mut cuts: Vec<f64> =
        std::iter::once(a).chain(splits.iter().copied().filter(|s| *s > a && *s < b)).chain([b]).collect();
    cuts.sort_by(f64::total_cmp);
    let mut total = 0.0;
    for w in cuts.windows(2) {
        // Geometric panels towards both ends (the integrand has log singularities there): [end ± h/2^(k+1), end ±
        // h/2^k] for k = 0..36; Gauss–Legendre integrates each to round-off. The 2^-36 h left at each end holds
        // ≲ 2^-36 h |ln(2^-36 h)| ≈ 1e-12 of the integral: below the 1e-10 asserted.
        let (lo, hi) = (w[0], w[1]);
        let half = 0.5 * (hi - lo);
        let mut panels = Vec::new();
        for k in 0..36 {
            let (f0, f1) = (0.5f64.powi(k + 1), 0.5f64.powi(k));
            panels.push((lo + half * f0, lo + half * f1));
            panels.push((hi - half * f1, hi - half * f0));
        }
        for (u0, u1) in panels {
            let (c, h) = (0.5 * (u0 + u1), 0.5 * (u1 - u0));
            total += nodes.iter().map(|(x, wt)| wt * h * f(c + h * x)).sum::<f64>();
        }
    }
    total
}

#[test]
fn influence_coefficients_match_quadrature_of_the_line_load_solution() {
    // The flexibility the half-plane source builds (per unit nodal force) against an independent integration of
    // the Flamant line-load surface displacement over each strip, divided by the strip width; relative to the
    // largest entry, ≤ 1e-10. The quadrature splits at the collocation point (log singularity).
    let s = steel(
        "datum_depth = 300.0",
        "contact_arc_deg = 3.0\ncontact_elements = 12",
        "friction = 0.3",
        "normal_load = 1000.0",
    );
    let fl = source::build(&s, Blocks::All).unwrap().flex;
    let n = fl.n();
    let hp = HalfPlane::new(1.0, 0.3, 300.0 / 920.0).unwrap();
    let edges: Vec<f64> =
        (0..n).map(|j| fl.x[j] - 0.5 * fl.weights[j]).chain([fl.x[n - 1] + 0.5 * fl.weights[n - 1]]).collect();
    let kmax = fl.k_nn.col_iter().flat_map(|c| c.iter().map(|v| v.abs()).collect::<Vec<_>>()).fold(0.0, f64::max);
    for i in [0, 3, 6, 11] {
        for j in [0, 2, 5, 6, 11] {
            let (a, b, x) = (edges[j], edges[j + 1], fl.x[i]);
            let w = b - a;
            let uz_p = quad(&|t| hp.line_load_displacement(t, 1.0, 0.0, x, 0.0).uz, a, b, &[x]) / w;
            let ux_q = quad(&|t| hp.line_load_displacement(t, 0.0, 1.0, x, 0.0).ux, a, b, &[x]) / w;
            let ux_p = quad(&|t| hp.line_load_displacement(t, 1.0, 0.0, x, 0.0).ux, a, b, &[x]) / w;
            let uz_q = quad(&|t| hp.line_load_displacement(t, 0.0, 1.0, x, 0.0).uz, a, b, &[x]) / w;
            let blocks = [
                (fl.k_nn[(i, j)], uz_p, "K_NN"),
                (fl.k_tt.as_ref().unwrap()[(i, j)], ux_q, "K_TT"),
                (fl.k_tn.as_ref().unwrap()[(i, j)], ux_p, "K_TN"),
                (fl.k_nt.as_ref().unwrap()[(i, j)], uz_q, "K_NT"),
            ];
            for (got, want, what) in blocks {
                assert!((got - want).abs() <= 1e-10 * kmax, "{what}[{i},{j}]: {got:e} vs quadrature {want:e}");
            }
        }
    }
}

#[test]
fn the_finite_wheel_converges_to_the_half_plane_as_a_over_r_shrinks() {
    // The same loads on the BEM wheel (quadratic elements, hub) and on the half-plane with the wheel's circle, on
    // the same contact zone |x| ≤ 1.25a: the differences of the fitted a and p0 shrink like (a/R)^s with s ≥ 1.5
    // (measured s ≈ 1.9; both models' own discretisation errors are well below the differences at these meshes).
    let mut rows = Vec::new();
    for ar in [0.1, 0.05, 0.025] {
        let estar = 1.0 / (1.0 - 0.09);
        let p = Hertz2D::from_half_width(ar, 1.0, estar).load;
        let fit = |model: &str, element: &str, n: usize, extra: &str| {
            let s = scene(&format!(
                r#"
name = "finite"
[wheel]
radius = 1.0
youngs_modulus = 1.0
poisson_ratio = 0.3
model = "{model}"
{extra}
[mesh]
element = "{element}"
contact_half_width = {}
contact_elements = {n}
{}
[drive]
normal_load = {p}
[solvers]
use = ["lemke"]
"#,
                1.25 * ar,
                if model == "bem" { "other_elements = 120" } else { "" }
            ));
            let r = run(&s);
            let c = lemke(&r).contact.clone().unwrap();
            (c.fit_half_width.unwrap(), c.fit_peak_pressure.unwrap())
        };
        let (ab, pb) = fit("bem", "quadratic", 60, "support = { kind = \"hub\", radius = 0.25 }");
        let (ah, ph) = fit("half_plane", "constant", 400, "");
        let (da, dp) = ((ab / ah - 1.0).abs(), (pb / ph - 1.0).abs());
        eprintln!("a/R = {ar}: Δa/a = {da:.2e}, Δp0/p0 = {dp:.2e}");
        rows.push((ar, da, dp));
    }
    for w in rows.windows(2) {
        let sa = (w[0].1 / w[1].1).ln() / (w[0].0 / w[1].0).ln();
        let sp = (w[0].2 / w[1].2).ln() / (w[0].0 / w[1].0).ln();
        assert!(sa >= 1.5 && sp >= 1.5, "slopes {sa:.2} {sp:.2} between a/R = {} and {}", w[0].0, w[1].0);
    }
}

#[test]
fn half_plane_bad_input_names_the_key_and_writes_nothing() {
    let good = r#"
name = "hp-cli"
[wheel]
radius = 1.0
youngs_modulus = 94500.0
poisson_ratio = 0.3
model = "half_plane"
[mesh]
element = "constant"
contact_half_width = 0.06
contact_elements = 24
[drive]
normal_load = 187.42
"#;
    let r = |from: &str, to: &str| {
        assert!(good.contains(from), "{from}");
        good.replacen(from, to, 1)
    };
    let cases = [
        (
            "support on a half-plane",
            r("model = \"half_plane\"", "model = \"half_plane\"\nsupport = { kind = \"hub\", radius = 0.2 }"),
            "wheel.support",
        ),
        (
            "other_elements on a half-plane",
            r("contact_elements = 24", "contact_elements = 24\nother_elements = 32"),
            "mesh.other_elements",
        ),
        (
            "rotation on a half-plane",
            r("normal_load = 187.42", "normal_load = 187.42\nrotation = 0.0"),
            "drive.rotation",
        ),
        ("moment on a half-plane", r("normal_load = 187.42", "normal_load = 187.42\nmoment = 1.0"), "drive.moment"),
        (
            "both zone keys",
            r("contact_half_width = 0.06", "contact_half_width = 0.06\ncontact_arc_deg = 8.0"),
            "mesh.contact_arc_deg",
        ),
        ("neither zone key", r("contact_half_width = 0.06\n", ""), "contact_half_width"),
        ("half-width beyond R", r("contact_half_width = 0.06", "contact_half_width = 1.5"), "mesh.contact_half_width"),
        ("quadratic half-plane", r("element = \"constant\"", "element = \"quadratic\""), "mesh.element"),
        (
            "counter-body without a modulus",
            format!("{good}\n[counter_body]\nkind = \"half_plane\"\npoisson_ratio = 0.3\n"),
            "youngs_modulus",
        ),
        (
            "counter-body with a bad ratio",
            format!("{good}\n[counter_body]\nkind = \"half_plane\"\nyoungs_modulus = 1.0\npoisson_ratio = 0.6\n"),
            "counter_body.poisson_ratio",
        ),
        (
            "negative datum",
            r("model = \"half_plane\"", "model = \"half_plane\"\ndatum_depth = -1.0"),
            "wheel.datum_depth",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (i, (what, text, needle)) in cases.into_iter().enumerate() {
        let p = dir.path().join(format!("bad{i}.toml"));
        std::fs::write(&p, &text).unwrap();
        let json = dir.path().join(format!("bad{i}.json"));
        let out =
            Command::new(env!("CARGO_BIN_EXE_rollbem")).arg("run").arg(&p).arg("--json").arg(&json).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        assert!(err.contains(needle), "{what}: `{needle}` not named: {err}");
        assert!(!json.exists(), "{what}: output written");
    }
    // The good scene runs.
    let p = dir.path().join("good.toml");
    std::fs::write(&p, good).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rollbem")).arg("run").arg(&p).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stdout));
}
