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
use std::sync::atomic::{AtomicUsize, Ordering};
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

/// Solves counted by a plug-in solver that is Lemke underneath ([`COUNTING`]): how far a path got.
static SOLVES: AtomicUsize = AtomicUsize::new(0);

/// Lemke, counting its solves.
struct Counting;

impl rollbem::solvers::Solver for Counting {
    fn id(&self) -> rollbem::solvers::SolverId {
        COUNTING.id
    }
    fn uses_lcp(&self) -> bool {
        true
    }
    fn solve_from(&self, p: &rollbem::formulation::ContactProblem, start: Start) -> rollbem::solvers::Outcome {
        SOLVES.fetch_add(1, Ordering::Relaxed);
        let lemke = rollbem::solvers::build("lemke").unwrap();
        let mut out = lemke.solve_from(p, Start { state: None, ..start });
        out.state = None;
        out
    }
}

static COUNTING: rollbem::solvers::Entry = rollbem::solvers::Entry::new::<rollbem::solvers::lemke::LemkeSettings>(
    "counting_lemke",
    "Lemke, counting its solves (tests/cancel.rs)",
    false,
    &["pivots"],
    |_, _| Box::new(Counting),
    |m| (1e-9 * m * m * m, 8.0 * m * m),
);

#[test]
fn a_path_stops_when_its_token_is_raised() {
    let _ = rollbem::solvers::register(&COUNTING);
    let text = long_path(5000).replace("use = [\"lemke\", \"active_set\"]", "use = [\"counting_lemke\"]");
    let scene = Scene::from_toml(&text, Path::new("long.toml")).unwrap();
    let total = 1 + 2 * 5000;
    let model = Model::build(&scene).unwrap();
    let cancel = Cancel::new();
    let raiser = {
        let c = cancel.clone();
        std::thread::spawn(move || {
            // Once the walk is under way (a count, not a timer), raise the token.
            while SOLVES.load(Ordering::Relaxed) < 20 {
                std::thread::sleep(Duration::from_millis(1));
            }
            c.cancel();
            SOLVES.load(Ordering::Relaxed)
        })
    };
    let out = model.solve_with(&scene, &mut Warm::default(), &cancel);
    let at_cancel = raiser.join().unwrap();
    let done = SOLVES.load(Ordering::Relaxed);
    assert!(matches!(out, Err(rollbem::Error::Cancelled)), "{:?}", out.map(|r| r.steps.len()));
    // The walk stops at the substep in progress: at most one solve after the token rose, of 10 001.
    assert!(done <= at_cancel + 1 && done < total / 10, "{done} solves of {total} (token raised at {at_cancel})");
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
    // 800 000 substeps of 20 elements with Lemke alone: minutes of work run to the end, so a CLI that ignored Ctrl-C
    // would still be running when the patience below runs out.
    let text = long_path(400_000)
        .replace("contact_elements = 200", "contact_elements = 20")
        .replace("use = [\"lemke\", \"active_set\"]", "use = [\"lemke\"]");
    std::fs::write(&scene, text).unwrap();
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
    // Patience: a cancelled run ends at its next substep; one run to its end would take minutes (see above).
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(child.wait_with_output());
    });
    let out = rx.recv_timeout(Duration::from_secs(60)).expect("the CLI stopped after Ctrl-C").unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{err}");
    assert!(err.contains("interrupted"), "{err}");
    assert!(!json.exists(), "a cancelled run writes no output");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers.len(), 1, "only the scene is left: {leftovers:?}");
}
