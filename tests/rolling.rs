//! Steady-state rolling with the slip velocity as the unknown of Coulomb's law, checked against Carter's theory
//! (REFERENCES.md; Johnson, Contact Mechanics §8.2: 2D, β = 0, half-plane), against itself (creepage-driven and
//! load-driven runs are inverse problems), between solvers (Lemke and PGS), and against Coulomb's law node by node.
//! The finite wheel rolls too; its free-rolling creepage (Q = 0) is reported.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::references::metrics;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use std::path::Path;
use std::process::Command;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("<test>")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn run(s: &Scene) -> Report {
    run_scene(s).unwrap()
}

fn get<'a>(r: &'a Report, solver: &str) -> &'a SolverRun {
    r.runs.iter().find(|x| x.solver == solver).unwrap_or_else(|| panic!("no {solver} run"))
}

/// The steel wheel (R = 460 mm, E = 210 GPa, ν = 0.3, P = 20 kN/mm: a = 7.12 mm) as a half-plane with Hertz's
/// parabola, decoupled (β = 0), μ = 0.3 (critical creepage μa/R = 4.65e-3), rolling towards `dir`.
fn carter_scene(n: usize, rolling: &str, drive_extra: &str, dir: i32, solvers: &str) -> Scene {
    scene(&format!(
        r#"
name = "carter"
[wheel]
radius = 460.0
youngs_modulus = 210000.0
poisson_ratio = 0.3
model = "half_plane"
profile = "parabola"
[mesh]
element = "constant"
contact_half_width = 9.0
contact_elements = {n}
[contact]
friction = 0.3
coupling = false
[drive]
normal_load = 20000.0
{drive_extra}
[rolling]
mode = "steady"
direction = {dir}
{rolling}
[solvers]
use = {solvers}
"#
    ))
}

#[test]
fn carter_stick_zone_force_and_traction_converge() {
    // Reference: Carter (REFERENCES.md). Three creepages below saturation, both rolling directions, meshes of
    // 100/200/400 elements on |x| ≤ 9 (79–317 elements across the contact): c/a and Q/(μP) within one element,
    // the stick zone at the leading edge, the traction's RMS error within 1 % of μp0 at ≥ 100 elements across.
    for xi in [0.0005, 0.0015, -0.003] {
        let mut errs = Vec::new();
        for n in [100usize, 200, 400] {
            for dir in [1, -1] {
                let s = carter_scene(n, &format!("creepage = {xi}"), "", dir, r#"["lemke"]"#);
                let r = run(&s);
                let l = get(&r, "lemke");
                assert_eq!(l.status, Status::Solved, "{}", l.explanation());
                let m = metrics(&s, l);
                let (cerr, centre, rms) = (
                    m.carter_c_err_elements.unwrap(),
                    m.carter_centre_err_elements.unwrap(),
                    m.carter_shear_rms.unwrap(),
                );
                let qerr = (m.carter_q_over_mup.unwrap() - m.carter_q_over_mup_exact.unwrap()).abs();
                assert!(cerr.abs() <= 1.0 && centre.abs() <= 1.0, "ξ {xi} n {n} dir {dir}: c {cerr} centre {centre}");
                // Q/(μP) = 1 − (c/a)²: one element of c moves it by ≈ 2(c/a) h/a.
                let h_over_a = 18.0 / n as f64 / 7.124592;
                assert!(qerr <= 2.0 * h_over_a, "ξ {xi} n {n}: Q/μP error {qerr}");
                if 2.0 / h_over_a >= 100.0 {
                    assert!(rms <= 0.01, "ξ {xi} n {n}: traction RMS {rms}");
                }
                assert!(
                    r.checks.iter().all(|c| c.pass),
                    "{:?}",
                    r.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>()
                );
                if dir == 1 {
                    errs.push((n as f64, qerr, rms));
                }
            }
        }
        // Observed order of the traction RMS over the three meshes (least squares in log–log).
        let pts: Vec<(f64, f64)> = errs.iter().map(|e| ((1.0 / e.0).ln(), e.2.ln())).collect();
        let k = pts.len() as f64;
        let (mx, my) = (pts.iter().map(|p| p.0).sum::<f64>() / k, pts.iter().map(|p| p.1).sum::<f64>() / k);
        let order = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / pts.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        eprintln!(
            "ξ = {xi}: traction RMS {:?}, observed order {order:.2}",
            errs.iter().map(|e| e.2).collect::<Vec<_>>()
        );
        assert!(order > 0.3, "the traction error does not fall with the mesh: {errs:?}");
    }
}

#[test]
fn full_slip_above_the_critical_creepage_and_no_force_at_zero() {
    // Reference: Carter: |ξ| ≥ μa/R = 4.65e-3 is full slip, Q = −sgn(ξ) μP; ξ = 0 carries no tangential force
    // (on the half-plane with β = 0 the free-rolling creepage is exactly 0).
    for xi in [0.006_f64, -0.01] {
        let r = run(&carter_scene(200, &format!("creepage = {xi}"), "", 1, r#"["lemke", "pgs"]"#));
        for solver in ["lemke", "pgs"] {
            let l = get(&r, solver);
            assert_eq!(l.status, Status::Solved, "{}", l.explanation());
            let f = l.resultants.unwrap();
            assert!((f.tangential / (0.3 * f.normal) + xi.signum()).abs() <= 1e-9, "{solver}: Q = {}", f.tangential);
            assert_eq!(l.contact.as_ref().unwrap().nodes_stick, 0);
        }
    }
    let r = run(&carter_scene(200, "creepage = 0.0", "", 1, r#"["lemke", "pgs"]"#));
    for solver in ["lemke", "pgs"] {
        let l = get(&r, solver);
        assert_eq!(l.resultants.unwrap().tangential, 0.0, "{solver}");
        assert!(l.nodes.iter().all(|n| n.shear == 0.0), "{solver}");
    }
}

#[test]
fn creepage_and_load_driven_runs_are_inverse_to_each_other() {
    // The Q of a creepage-driven run fed back as the load returns the creepage to 1e-8 relative.
    for xi in [0.0005_f64, 0.002, -0.0035] {
        let a = run(&carter_scene(150, &format!("creepage = {xi}"), "", 1, r#"["lemke"]"#));
        let q = get(&a, "lemke").resultants.unwrap().tangential;
        let b = run(&carter_scene(150, "", &format!("tangential_load = {q:e}"), 1, r#"["lemke", "pgs"]"#));
        for solver in ["lemke", "pgs"] {
            let l = get(&b, solver);
            assert_eq!(l.status, Status::Solved, "{solver}: {}", l.explanation());
            let back = l.rolling.unwrap();
            assert!(!back.creepage_prescribed);
            let err = (back.creepage.unwrap() - xi).abs() / xi.abs();
            // PGS stops at its tolerance (1e-10 on the tractions): its creepage is as good as that.
            let tol = if solver == "lemke" { 1e-8 } else { 1e-6 };
            assert!(err <= tol, "{solver} ξ {xi}: got {} ({err:e})", back.creepage.unwrap());
        }
    }
}

#[test]
fn lemke_and_pgs_agree_and_coulomb_holds_node_by_node() {
    // Reference: Lemke (a direct solver; residuals at round-off). PGS at its default tolerance agrees to 1e-8 of
    // p0; both satisfy Coulomb's law on the slip velocity at every node: stick nodes do not move, slipping nodes'
    // shear opposes their slip velocity.
    for (xi, nu, coupling) in [(0.001, 0.3, "false"), (0.002, 0.3, "true"), (-0.0015, 0.45, "true")] {
        let mut s = carter_scene(200, &format!("creepage = {xi}"), "", 1, r#"["lemke", "pgs"]"#);
        s = s
            .edit(|d| {
                d.wheel.poisson_ratio = nu;
                d.contact.coupling = coupling == "true";
            })
            .unwrap();
        let r = run(&s);
        let (l, p) = (get(&r, "lemke"), get(&r, "pgs"));
        assert_eq!((l.status, p.status), (Status::Solved, Status::Solved), "{} / {}", l.explanation(), p.message);
        assert!(l.residuals.unwrap().max() <= 1e-12, "lemke residual {:?}", l.residuals);
        let p0 = l.contact.as_ref().unwrap().peak_pressure;
        for (a, b) in paired(&l.nodes, &p.nodes) {
            assert!((a.pressure - b.pressure).abs() <= 1e-8 * p0 && (a.shear - b.shear).abs() <= 1e-8 * p0);
        }
        for run in [l, p] {
            let rr = run.rolling.unwrap();
            assert_eq!((rr.stick_nodes_moving, rr.slip_nodes_not_opposed), (0, 0), "{}", run.solver);
            for n in run.nodes.iter().filter(|n| n.state != rollbem::post::NodeState::Separated) {
                let v = n.slip_velocity.expect("a loaded node has a slip velocity");
                match n.state {
                    rollbem::post::NodeState::Stick => assert!(v.abs() <= 1e-9 * rr.slip_velocity_scale, "{v}"),
                    _ => assert!(v * n.shear <= 1e-12 * p0 * rr.slip_velocity_scale, "s {v} q {}", n.shear),
                }
            }
        }
    }
}

#[test]
fn the_finite_wheel_rolls_and_reports_its_free_rolling_creepage() {
    // The BEM wheel (hub) in steady rolling with the tangential load prescribed: Q = 0 gives its free-rolling
    // creepage, which the finite wheel's normal–tangential coupling makes nonzero (coupling on), and which vanishes
    // when the coupling is switched off (no tangential traction at all: ξ = 0 exactly). Reference for the zero:
    // with K_TN dropped and Q = 0 nothing loads the tangential problem.
    let text = |coupling: bool| {
        format!(
            r#"
name = "free-rolling"
[wheel]
radius = 1.0
youngs_modulus = 94500.0
poisson_ratio = 0.3
support = {{ kind = "hub", radius = 0.25 }}
[mesh]
element = "constant"
contact_arc_deg = 6.0
contact_elements = 60
other_elements = 80
[contact]
friction = 0.3
coupling = {coupling}
[drive]
normal_load = 187.42
tangential_load = 0.0
[rolling]
mode = "steady"
direction = 1
[solvers]
use = ["lemke", "pgs"]
"#
        )
    };
    let on = run(&scene(&text(true)));
    let off = run(&scene(&text(false)));
    for solver in ["lemke", "pgs"] {
        let (a, b) = (get(&on, solver), get(&off, solver));
        assert_eq!((a.status, b.status), (Status::Solved, Status::Solved), "{} / {}", a.message, b.message);
        let (xa, xb) = (a.rolling.unwrap().creepage.unwrap(), b.rolling.unwrap().creepage.unwrap());
        eprintln!("{solver}: free-rolling creepage {xa:e} (coupling on), {xb:e} (off)");
        assert!(xa.abs() > 1e-8, "{solver}: coupling on should give a nonzero free-rolling creepage");
        assert!(xb.abs() <= 1e-14, "{solver}: {xb}");
        assert!(a.resultants.unwrap().tangential.abs() <= 1e-10 * 187.42);
    }
}

#[test]
fn steady_rolling_bad_input_names_the_key() {
    let base = r#"
name = "bad-rolling"
[wheel]
radius = 1.0
youngs_modulus = 94500.0
poisson_ratio = 0.3
model = "half_plane"
[mesh]
element = "constant"
contact_half_width = 0.06
contact_elements = 24
[contact]
friction = 0.3
[drive]
normal_load = 187.42
[rolling]
mode = "steady"
creepage = 0.001
direction = 1
"#;
    let r = |from: &str, to: &str| {
        assert!(base.contains(from), "{from}");
        base.replacen(from, to, 1)
    };
    let cases = [
        ("no mode", r("mode = \"steady\"\n", ""), "mode"),
        (
            "creepage and load",
            r("normal_load = 187.42", "normal_load = 187.42\ntangential_load = 5.0"),
            "rolling.creepage",
        ),
        ("neither", r("creepage = 0.001\n", ""), "rolling.creepage"),
        (
            "a shift in steady mode",
            r("normal_load = 187.42", "normal_load = 187.42\ntangential_shift = 0.001"),
            "drive.tangential_shift",
        ),
        ("bad direction", r("direction = 1", "direction = 2"), "rolling.direction"),
        ("seed without creepage", r("mode = \"steady\"\ncreepage = 0.001", "mode = \"seed\""), "rolling.creepage"),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (i, (what, text, needle)) in cases.into_iter().enumerate() {
        let p = dir.path().join(format!("bad{i}.toml"));
        std::fs::write(&p, &text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_rollbem")).arg("run").arg(&p).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        assert!(err.contains(needle), "{what}: `{needle}` not named: {err}");
    }
}
