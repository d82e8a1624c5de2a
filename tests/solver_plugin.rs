//! Adding a solver is one file and one registry line (issue 31, item 3): the solver in `tests/plugin/lcp_pgs.rs`,
//! written against the library's public seam only, registered by one call, runs through the model, the sweep and
//! the command line (`examples/cli_with_plugin.rs`: the `rollbem` CLI with the plug-in registered), checked by the
//! harness like a built-in solver. Reference for its answers: Lemke on the same scenes (an independent solver),
//! compared by the harness's own agreement check and here to 1e-6 of the peak pressure.
//! (Through Python: python/tests/test_plugin.py registers a solver written in Python the same way.)

#[path = "plugin/lcp_pgs.rs"]
mod lcp_pgs;

use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use rollbem::status::Status;
use std::path::{Path, PathBuf};
use std::process::Command;

fn register() {
    // One line; a second registration of the same name is refused (tests run in one process).
    let _ = rollbem::solvers::register(&lcp_pgs::ENTRY);
    assert!(rollbem::solvers::register(&lcp_pgs::ENTRY).is_err(), "a name is registered once");
}

/// Hertz on the half-plane, the approach prescribed (the plug-in takes the frictionless LCP without load rows).
fn hertz(solvers: &str, friction: f64) -> String {
    format!(
        "name = \"plugin-hertz\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         model = \"half_plane\"\nprofile = \"parabola\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 9.0\n\
         contact_elements = 100\n[contact]\nfriction = {friction}\n[drive]\nnormal_approach = 0.15\n\
         [solvers]\nuse = {solvers}\n[solvers.lcp_pgs]\ntolerance = 1e-13\n"
    )
}

#[test]
fn the_plugin_runs_through_the_model_like_a_built_in_solver() {
    register();
    let scene = Scene::from_toml(&hertz("[\"lcp_pgs\", \"lemke\"]", 0.0), Path::new("p.toml")).unwrap();
    let report = Model::build(&scene).unwrap().solve(&scene).unwrap();
    let run = |name: &str| report.runs.iter().find(|r| r.solver == name).expect("a run of each");
    let (pgs, lemke) = (run("lcp_pgs"), run("lemke"));
    // Registry order: the built-in solvers, then those registered at run time.
    assert_eq!(report.runs.iter().map(|r| r.solver.name()).collect::<Vec<_>>(), ["lemke", "lcp_pgs"]);
    assert_eq!(pgs.status, Status::Solved, "{}", pgs.explanation());
    assert_eq!(lemke.status, Status::Solved);
    assert!(pgs.work.get("sweeps").is_some_and(|s| s > 1));
    let p0 = lemke.contact.as_ref().unwrap().peak_pressure;
    let diff = lcp_pgs_diff(&pgs.nodes, &lemke.nodes);
    assert!(diff <= 1e-6 * p0, "lcp_pgs against Lemke: {diff:e} (p0 {p0})");
    // The harness compared them itself (the agreement check between solvers).
    let agree = report.checks.iter().find(|c| c.name.contains("lcp_pgs") && c.name.contains("lemke"));
    assert!(agree.is_some_and(|c| c.pass), "{:?}", report.checks.iter().map(|c| &c.name).collect::<Vec<_>>());
    // Its settings are validated when the scene is read, naming the key; its own `admits` refuses friction there.
    let bad = hertz("[\"lcp_pgs\"]", 0.0).replace("tolerance = 1e-13", "tolerance = 2.0");
    let e = Scene::from_toml(&bad, Path::new("p.toml")).unwrap_err().to_string();
    assert!(e.contains("solvers.lcp_pgs.tolerance"), "{e}");
    let e = Scene::from_toml(&hertz("[\"lcp_pgs\"]", 0.3), Path::new("p.toml")).unwrap_err().to_string();
    assert!(e.contains("solvers.use") && e.contains("frictionless scenes only"), "{e}");
}

fn lcp_pgs_diff(a: &[rollbem::post::NodeResult], b: &[rollbem::post::NodeResult]) -> f64 {
    assert!(!a.is_empty() && a.len() == b.len());
    a.iter().zip(b).map(|(x, y)| (x.pressure - y.pressure).abs()).fold(0.0, f64::max)
}

/// The `rollbem` CLI with the plug-in registered (built by `cargo test` with the other examples).
fn cli() -> Command {
    let exe = std::env::current_exe().unwrap();
    let release = exe.parent().and_then(Path::parent).unwrap();
    let bin: PathBuf = release.join("examples").join("cli_with_plugin");
    assert!(bin.exists(), "{} is built by `cargo test` with the examples (not by `--test` alone)", bin.display());
    Command::new(bin)
}

#[test]
fn the_plugin_runs_through_the_cli_and_the_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let listed = cli().arg("solvers").output().unwrap();
    assert!(String::from_utf8_lossy(&listed.stdout).contains("lcp_pgs"));
    let scene = dir.path().join("hertz.toml");
    std::fs::write(&scene, hertz("[\"lcp_pgs\", \"lemke\"]", 0.0)).unwrap();
    let json = dir.path().join("hertz.json");
    let out = cli().args(["run", "--quiet", "--json"]).arg(&json).arg(&scene).output().unwrap();
    // The stock binary reads (and plots) the plug-in's result document: its runs keep the plug-in's name.
    let plot = Command::new(env!("CARGO_BIN_EXE_rollbem")).args(["plot", "--quiet"]).arg(&json).output().unwrap();
    assert_eq!(plot.status.code(), Some(0), "{}", String::from_utf8_lossy(&plot.stderr));
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let report = rollbem::results::Report::read(&json).unwrap();
    let plugin = report.runs.iter().find(|r| r.solver == "lcp_pgs").expect("the plug-in's run, read back");
    assert_eq!(plugin.status, Status::Solved);
    // A sweep over the approach with the plug-in and Lemke: every row solved.
    let spec = dir.path().join("sweep.toml");
    std::fs::write(
        &spec,
        "name = \"plugin-sweep\"\nbase = \"hertz.toml\"\n[[grid]]\n\"drive.normal_approach\" = [0.1, 0.15, 0.2]\n",
    )
    .unwrap();
    let csv = dir.path().join("sweep.csv");
    let out = cli().args(["sweep", "--quiet"]).arg(&spec).arg("--out").arg(&csv).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let mut reader = csv::Reader::from_path(&csv).unwrap();
    let head = reader.headers().unwrap().clone();
    let (solver, status) = (head.iter().position(|h| h == "solver"), head.iter().position(|h| h == "status"));
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 6, "3 cases × 2 solvers");
    let plugin_rows: Vec<_> = rows.iter().filter(|r| &r[solver.unwrap()] == "lcp_pgs").collect();
    assert_eq!(plugin_rows.len(), 3);
    assert!(plugin_rows.iter().all(|r| &r[status.unwrap()] == "solved"));
    // The stock binary does not know it: the scene is bad input there (exit 2), naming the solver.
    let stock = Command::new(env!("CARGO_BIN_EXE_rollbem")).args(["run", "--quiet"]).arg(&scene).output().unwrap();
    assert_eq!(stock.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&stock.stderr).contains("lcp_pgs"));
}
