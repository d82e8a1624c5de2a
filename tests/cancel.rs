//! Cancellation (issue 31, item 2): a raised token stops a load path before its next substep and every solver at its
//! next iteration; the pipeline then returns `Error::Cancelled` (nothing produced), and the CLI exits 130 after
//! Ctrl-C without writing its outputs. No wall-clock bound here: a path that finished would return `Ok` and write
//! its output, so `Err(Cancelled)` and the missing output are the evidence that it stopped early.

use rollbem::cancel::Cancel;
use rollbem::pipeline::{stages, Model, Warm};
use rollbem::scene::Scene;
use rollbem::solvers::{registry, Start, Termination};
use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// A fretting path on a frictional half-plane: `substeps` substeps of a tangential load cycle (long enough to be
/// interrupted: about a millisecond a substep per solver).
fn long_path(substeps: usize) -> String {
    format!(
        "name = \"long-path\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         model = \"half_plane\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\ncontact_elements = 200\n\
         [contact]\nfriction = 0.3\n[solvers]\nuse = [\"lemke\", \"active_set\"]\n\
         [[steps]]\nnormal_load = 1000.0\n\
         [[steps]]\nnormal_load = 1000.0\ntangential_load = 200.0\nsubsteps = {substeps}\n\
         [[steps]]\nnormal_load = 1000.0\ntangential_load = -200.0\nsubsteps = {substeps}\n"
    )
}

#[test]
fn a_path_stops_when_its_token_is_raised() {
    let scene = Scene::from_toml(&long_path(5000), Path::new("long.toml")).unwrap();
    let model = Model::build(&scene).unwrap();
    let cancel = Cancel::new();
    let raiser = {
        let c = cancel.clone();
        std::thread::spawn(move || {
            std::thread::sleep(Duration::from_millis(200));
            c.cancel();
        })
    };
    let out = model.solve_with(&scene, &mut Warm::default(), &cancel);
    raiser.join().unwrap();
    assert!(matches!(out, Err(rollbem::Error::Cancelled)), "{:?}", out.map(|r| r.steps.len()));
    assert_eq!(rollbem::Error::Cancelled.exit_code(), 130);
}

#[test]
fn every_solver_stops_at_its_first_iteration_on_a_raised_token() {
    // A problem that takes every solver many iterations: 400 frictional nodes under a shift.
    let text = "name = \"c\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
                model = \"half_plane\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\n\
                contact_elements = 400\n[contact]\nfriction = 0.3\n[drive]\nnormal_load = 1000.0\n\
                tangential_shift = -0.0004\n";
    let frictional = Scene::from_toml(text, Path::new("c.toml")).unwrap();
    let frictionless = frictional.edit(|d| d.contact.friction = 0.0).unwrap();
    let mut stopped = Vec::new();
    for scene in [&frictional, &frictionless] {
        let built = rollbem::source::build(scene, stages::blocks_for(scene)).unwrap();
        let p = stages::scene_problem(scene, &built.flex).unwrap();
        for e in registry() {
            let solver = e.id.build(&Default::default()).unwrap();
            if solver.applies(&p).is_err() {
                continue;
            }
            let cancel = Cancel::new();
            cancel.cancel();
            let out = solver.solve_from(&p, Start::cancellable(cancel));
            assert_ne!(out.status, Termination::Solved, "{}: {}", e.name(), out.message);
            assert!(
                out.message.contains("cancel") || out.message.contains("Callback"),
                "{}: {}",
                e.name(),
                out.message
            );
            stopped.push(e.name());
        }
    }
    for name in ["lemke", "active_set", "clarabel", "pgs", "normtang_qp", "lemke_dense"] {
        assert!(stopped.contains(&name), "{name} was not exercised: {stopped:?}");
    }
}

#[test]
fn ctrl_c_stops_the_cli_with_code_130_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("long.toml");
    std::fs::write(&scene, long_path(20000)).unwrap();
    let json = dir.path().join("out.json");
    let child = Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(["run", "--quiet", "--json"])
        .arg(&json)
        .arg(&scene)
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Long enough for the handler to be installed and the path to start (the handler is installed before the scene
    // is read).
    std::thread::sleep(Duration::from_millis(500));
    let st = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(st.success());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{err}");
    assert!(err.contains("interrupted"), "{err}");
    assert!(!json.exists(), "a cancelled run writes no output");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers.len(), 1, "only the scene is left: {leftovers:?}");
}
