//! The harness: NORM-TANG (PGS and clarabel-QP inner solvers) against Lemke, the solver registry, the effects a
//! scene calls for, `rollbem check` and its failure on a violated declared tolerance. Reference values: the peer
//! solver (Lemke, a pivoting method exact to round-off) and the declared tolerances.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use rollbem::tolerances as tol;
use std::path::{Path, PathBuf};
use std::process::Command;

fn reference(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes").join(name)
}

fn load(name: &str) -> Scene {
    Scene::from_file(&reference(name)).unwrap()
}

fn run(s: &Scene) -> Report {
    run_scene(s).unwrap()
}

fn get<'a>(r: &'a Report, solver: &str) -> &'a SolverRun {
    r.runs.iter().find(|x| x.solver == solver).unwrap_or_else(|| panic!("no {solver} run"))
}

fn max_diff(a: &SolverRun, b: &SolverRun) -> f64 {
    let p0 = a.contact.as_ref().unwrap().peak_pressure;
    paired(&a.nodes, &b.nodes)
        .fold(0.0_f64, |m, (x, y)| m.max((x.pressure - y.pressure).abs()).max((x.shear - y.shear).abs()))
        / p0
}

#[test]
fn normtang_and_clarabel_agree_with_lemke() {
    // Frictionless (constant and quadratic), decoupled frictional (Cattaneo), weakly coupled (ν = 0.45), and the
    // seed's strongly coupled ν = 0.1 cases, all at the default NORM-TANG tolerance 1e-10.
    let mut weak = load("cattaneo-decoupled.toml");
    weak = weak
        .edit(|d| {
            d.contact.coupling = true;
            d.wheel.poisson_ratio = 0.45;
        })
        .unwrap();
    let cases = vec![
        load("hertz-hub-fine.toml"),
        load("seed-fig6-quadratic.toml"),
        load("cattaneo-decoupled.toml"),
        weak,
        load("seed-fig09-mu05.toml"),
        load("seed-fig13-mu03.toml"),
    ];
    for s in &cases {
        let mut s = s.clone();
        s = s.edit(|d| d.solvers.use_ = vec!["all".to_string()]).unwrap();
        let r = run(&s);
        let lemke = get(&r, "lemke");
        assert_eq!(lemke.status, Status::Solved);
        for other in r.runs.iter().filter(|x| x.solver != "lemke") {
            assert_eq!(other.status, Status::Solved, "{} {}: {}", s.name(), other.solver, other.explanation());
            let d = max_diff(lemke, other);
            eprintln!("{} {}: max |Δp|,|Δq| / p0 = {d:.2e}, work {:?}", s.name(), other.solver, other.work);
            assert!(d <= tol::SOLVER_AGREEMENT, "{} {} vs lemke: {d:e}", s.name(), other.solver);
        }
        if s.document().contact.friction == 0.0 {
            assert!(r.runs.iter().any(|x| x.solver == "clarabel"));
        }
    }
}

#[test]
fn effects_and_problem_sizes_are_what_the_scene_calls_for() {
    // Frictionless: the normal problem only, one unknown per contact node (plus u± for a prescribed load).
    let s = load("seed-fig6-approach.toml");
    let r = run(&s);
    assert_eq!(r.effects, ["normal"]);
    for x in &r.runs {
        assert_eq!(x.problem_size, r.mesh.contact_nodes);
        assert!(x.nodes.iter().all(|n| n.u_x.is_none() && n.slip_velocity.is_none()));
    }
    // coupling = false: no "coupling" effect, and NORM-TANG converges in at most two outer iterations (the normal
    // problem does not depend on the shear: one NORM, one TANG, one confirming pass).
    let mut c = load("cattaneo-decoupled.toml");
    c = c.edit(|d| d.solvers.use_ = vec!["pgs".to_string()]).unwrap();
    let r = run(&c);
    assert_eq!(r.effects, ["normal", "friction"]);
    let pgs = get(&r, "pgs");
    assert!(pgs.work.get("outer").unwrap() <= 2, "outer iterations {:?}", pgs.work.get("outer"));
    // Friction with coupling and rolling: every effect, 3n + 4 unknowns for P and Q prescribed.
    let f = load("seed-fig17-mu07.toml");
    let r = run(&f);
    assert_eq!(r.effects, ["normal", "friction", "coupling", "rolling"]);
    assert_eq!(get(&r, "lemke").problem_size, 3 * r.mesh.contact_nodes + 4);
    assert!(get(&r, "lemke").nodes.iter().any(|n| n.slip_velocity.is_some()));
}

#[test]
fn registry_all_runs_only_valid_solvers_and_refuses_invalid_ones() {
    // A moment load: only Lemke and the active-set method carry it (the QP and NORM-TANG splits do not).
    let mut s = load("cattaneo-decoupled.toml");
    s = s
        .edit(|d| {
            d.drive.rotation = None;
            d.drive.moment = Some(18.742 * 1.0 + 187.42 * 0.001);
        })
        .unwrap();
    let r = run(&s);
    let names: Vec<&str> = r.runs.iter().map(|x| x.solver.name()).collect();
    assert_eq!(names, ["lemke", "active_set"]);
    // Named, a solver that cannot take the scene is refused when the scene is read (issue 31), not when it is run.
    let e = s.edit(|d| d.solvers.use_ = vec!["pgs".to_string()]).unwrap_err().to_string();
    assert!(e.contains("solvers.use") && e.contains("pgs") && e.contains("moment"), "{e}");
    // Frictional: clarabel alone does not apply, and says what does.
    let f = load("cattaneo-decoupled.toml");
    let e = f.edit(|d| d.solvers.use_ = vec!["clarabel".to_string()]).unwrap_err().to_string();
    assert!(e.contains("normtang_qp"), "{e}");
}

#[test]
fn normtang_says_when_it_does_not_converge() {
    // One outer iteration cannot settle a coupled problem (ν = 0.1): status not_converged with the achieved change.
    let mut s = load("seed-fig09-mu05.toml");
    s = s
        .edit(|d| {
            d.solvers.use_ = vec!["pgs".to_string()];
            d.solvers.set("pgs", "max_outer", 1);
        })
        .unwrap();
    let r = run(&s);
    let p = get(&r, "pgs");
    assert_eq!(p.status, Status::NotConverged, "{}", p.message);
    assert!(p.message.contains("last change") && p.residuals.is_none(), "{}", p.message);
    // Too few sweeps for the inner solve.
    s = s
        .edit(|d| {
            d.solvers.set("pgs", "max_outer", 200);
            d.solvers.set("pgs", "max_sweeps", 3);
        })
        .unwrap();
    let r = run(&s);
    let p = get(&r, "pgs");
    assert_eq!(p.status, Status::NotConverged);
    assert!(p.message.contains("Gauss–Seidel did not converge in 3 sweeps"), "{}", p.message);
}

#[test]
fn loose_tolerance_is_honest_about_its_error() {
    // PGS at tolerance τ = 1e-4 stays within τ of Lemke (the direct peer solver, exact to round-off), and its
    // residual check uses 100 τ. The scene is frictionless, so NORM-TANG's outer loop stops at once and the error
    // is that of the inner Gauss–Seidel sweeps and load root-find, both stopped at 0.1 τ: measured |Δp|/p0 =
    // 1.6e-5 (0.16 τ), not "about τ" as this comment once said.
    let mut s = load("hertz-hub-fine.toml");
    s = s
        .edit(|d| {
            d.solvers.use_ = vec!["lemke".to_string(), "pgs".to_string()];
            d.solvers.set("pgs", "tolerance", 1e-4);
        })
        .unwrap();
    let r = run(&s);
    let d = max_diff(get(&r, "lemke"), get(&r, "pgs"));
    eprintln!("pgs at 1e-4: |Δp|/p0 = {d:.2e}");
    assert!(d < 1e-4, "|Δp|/p0 = {d:e} is beyond the tolerance τ = 1e-4");
    assert_eq!(get(&r, "pgs").status, Status::Solved);
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

#[test]
fn check_passes_on_a_reference_scene_and_fails_on_a_violated_declared_tolerance() {
    let out = bin().args(["check"]).arg(reference("hertz-hub-fine.toml")).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("PASS hertz-hub-fine"));
    // Declare a Hertz tolerance the mesh cannot meet: check must fail and say which figure and by how much.
    let dir = tempfile::tempdir().unwrap();
    let scene = std::fs::read_to_string(reference("hertz-hub-fine.toml")).unwrap();
    let tight = dir.path().join("tight.toml");
    std::fs::write(&tight, format!("{scene}\n[checks]\nhertz = 1e-5\n")).unwrap();
    let out = bin().args(["check"]).arg(&tight).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("FAIL hertz-hub-fine") && text.contains("Hertz half-width a (fit)"), "{text}");
    assert!(text.contains("> tolerance 1.0e-5"), "{text}");
    assert!(text.lines().last().unwrap().contains("failed"), "{text}");
}
