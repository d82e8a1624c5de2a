//! Issue 31: every scene-level incompatibility is refused when the scene is read, not when it is run. A solver named
//! in `[solvers] use` that cannot take the scene for a reason the scene shows (its [`Solver::admits`] of the scene's
//! facts: the one rule per solver that its run applies to each problem), and a tangential load on a frictionless
//! contact, are bad input found by validation: `Scene::from_toml` returns `Error::Invalid` naming the key and why,
//! `rollbem sweep --dry-run` (which validates and runs nothing) refuses the scene, and `rollbem run --json` exits 2
//! with the key and writes nothing. Before (c0f3874) each of these scenes validated, `--dry-run` accepted it, and the
//! run refused it (`unsupported`), or — a moment at a later step of a load path — ran pgs on a problem it cannot
//! carry (a `numerical_error`).
//!
//! What each solver cannot take is its documented limit (the registry's summaries, `rollbem solvers`, and the
//! README's solver table): clarabel the frictionless QP without a moment; the NORM-TANG split (pgs, normtang_qp)
//! no moment and not the sliding limit |Q| = μP (lemke's full-slip problem); normtang_qp not steady rolling with
//! friction (its QP symmetrises D K_TT). Each refused scene has a control: the same scene with the solver that can
//! take it, which validates.
//!
//! [`Solver::admits`]: rollbem::solvers::Solver::admits

use rollbem::scene::Scene;
use rollbem::Error;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A small BEM wheel (the seed's Fig. 6 mesh) with `contact`, `drive` (or steps) and `solvers` as given.
fn bem(friction: f64, drive: &str, solvers: &str) -> String {
    format!(
        r#"
name = "incompatible"
[wheel]
radius = 1.0
youngs_modulus = 94500.0
poisson_ratio = 0.1
support = {{ kind = "top_arc", angle_deg = 30.0 }}
[mesh]
element = "constant"
contact_arc_deg = 30.0
contact_elements = 24
other_elements = 32
[contact]
friction = {friction:?}
{drive}
[solvers]
use = [{solvers}]
"#
    )
}

/// Carter's steady rolling on the half-plane (reference/scenes/carter-steady-rolling.toml, 40 elements).
fn steady(friction: f64, solvers: &str) -> String {
    format!(
        r#"
name = "steady"
[wheel]
radius = 460.0
youngs_modulus = 210000.0
poisson_ratio = 0.3
model = "half_plane"
profile = "parabola"
[mesh]
element = "constant"
contact_half_width = 9.0
contact_elements = 40
[contact]
friction = {friction:?}
coupling = false
[drive]
normal_load = 20000.0
[rolling]
mode = "steady"
creepage = {}
direction = 1
[solvers]
use = [{solvers}]
"#,
        if friction > 0.0 { "0.0015" } else { "0.0" }
    )
}

const LOAD: &str = "[drive]\nnormal_load = 749.7";
const MOMENT: &str = "[drive]\nnormal_load = 749.7\nmoment = 5.0";
/// |Q| = μP with μ = 0.3: the sliding limit.
const LIMIT: &str = "[drive]\nnormal_load = 749.7\ntangential_load = 224.91";
/// A moment at the second step of a load path only.
const LATER_MOMENT: &str =
    "[[steps]]\nnormal_load = 700.0\n[[steps]]\nnormal_load = 700.0\ntangential_load = 50.0\nmoment = 5.0\nsubsteps = 2";

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The scene is refused when read, naming `key` and saying `why`; the CLI refuses it with exit 2 before running
/// (`sweep --dry-run`) and `run --json` writes nothing.
fn refused(text: &str, key: &str, why: &str) {
    match Scene::from_toml(text, Path::new("s.toml")) {
        Err(Error::Invalid { field, message, .. }) => {
            assert_eq!(field, key, "{message}");
            assert!(message.contains(why), "no {why:?} in: {message}");
        }
        Err(other) => panic!("expected Error::Invalid naming {key}, got {other}"),
        Ok(_) => panic!("validated, but should be refused naming {key} ({why})"),
    }
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "s.toml", text);
    let spec = write(
        dir.path(),
        "spec.toml",
        &format!("name = \"read\"\nbase = '{}'\n[[grid]]\n\"description\" = [\"x\"]\n", scene.display()),
    );
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(dir.path().join("o.csv")).arg("--dry-run").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "sweep --dry-run: {err}");
    assert!(err.contains(&format!("`{key}`")) && err.contains(why), "{err}");
    let json = dir.path().join("out.json");
    let o = bin().arg("run").arg(&scene).arg("--json").arg(&json).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "run: {err}");
    assert!(err.contains(&format!("invalid value for `{key}`")) && err.contains(why), "{err}");
    assert!(!json.exists(), "nothing written");
}

/// The control: the scene validates.
fn accepted(text: &str) {
    if let Err(e) = Scene::from_toml(text, Path::new("s.toml")) {
        panic!("refused: {e}");
    }
}

#[test]
fn clarabel_with_friction() {
    refused(&bem(0.3, LOAD, r#""clarabel""#), "solvers.use", "with friction use normtang_qp");
    accepted(&bem(0.0, LOAD, r#""clarabel""#));
    accepted(&bem(0.3, LOAD, r#""normtang_qp""#));
}

#[test]
fn clarabel_with_a_moment_load() {
    refused(&bem(0.0, MOMENT, r#""clarabel""#), "solvers.use", "this scene prescribes a moment");
    accepted(&bem(0.0, MOMENT, r#""lemke""#));
}

#[test]
fn norm_tang_with_a_moment_load() {
    for solver in ["pgs", "normtang_qp"] {
        refused(&bem(0.3, MOMENT, &format!("{solver:?}")), "solvers.use", "does not carry a prescribed moment");
    }
    accepted(&bem(0.3, MOMENT, r#""lemke", "active_set""#));
    // `all` takes the solvers that apply and is not refused.
    accepted(&bem(0.3, MOMENT, r#""all""#));
}

#[test]
fn norm_tang_with_a_moment_load_at_a_later_step_of_a_load_path() {
    for solver in ["pgs", "normtang_qp"] {
        refused(&bem(0.3, LATER_MOMENT, &format!("{solver:?}")), "solvers.use", "does not carry a prescribed moment");
    }
    accepted(&bem(0.3, LATER_MOMENT, r#""lemke""#));
}

#[test]
fn norm_tang_at_the_sliding_limit() {
    for solver in ["pgs", "normtang_qp"] {
        refused(&bem(0.3, LIMIT, &format!("{solver:?}")), "solvers.use", "at the sliding limit |Q| = μP");
    }
    accepted(&bem(0.3, LIMIT, r#""lemke""#));
    // Below the limit the split applies.
    accepted(&bem(0.3, "[drive]\nnormal_load = 749.7\ntangential_load = 200.0", r#""pgs", "normtang_qp""#));
}

#[test]
fn normtang_qp_in_steady_rolling_with_friction() {
    refused(&steady(0.3, r#""normtang_qp""#), "solvers.use", "steady-rolling tangential operator");
    accepted(&steady(0.3, r#""pgs""#));
    accepted(&steady(0.0, r#""normtang_qp""#));
}

#[test]
fn a_tangential_load_on_a_frictionless_contact() {
    let q = "[drive]\nnormal_load = 749.7\ntangential_load = 50.0";
    refused(&bem(0.0, q, r#""lemke""#), "drive.tangential_load", "on a frictionless contact");
    let path = "[[steps]]\nnormal_load = 700.0\n[[steps]]\nnormal_load = 700.0\ntangential_load = 50.0";
    refused(&bem(0.0, path, r#""lemke""#), "steps[1].tangential_load", "on a frictionless contact");
    accepted(&bem(0.3, q, r#""lemke""#));
}
