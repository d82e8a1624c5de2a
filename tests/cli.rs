//! The real binary, end to end: a good scene writes the JSON document of DESIGN.md; bad input is refused with
//! exit code 2, an error naming the field (or line), and no output file.

use std::path::{Path, PathBuf};
use std::process::Command;

const GOOD: &str = r#"
name = "cli-good"
description = "small frictionless scene"
[wheel]
radius = 1.0
youngs_modulus = 94500.0
poisson_ratio = 0.1
support = { kind = "top_arc", angle_deg = 30.0 }
[mesh]
element = "constant"
contact_arc_deg = 30.0
contact_elements = 24
other_elements = 32
[contact]
friction = 0.0
[drive]
normal_load = 749.70
[solvers]
use = ["lemke", "clarabel"]
"#;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn good_scene_writes_the_json_document() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "good.toml", GOOD);
    let json = dir.path().join("out.json");
    let out = bin().arg("run").arg(&scene).arg("--json").arg(&json).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("lemke") && stdout.contains("clarabel"));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    for key in ["scene", "effects", "mesh", "references", "runs", "checks"] {
        assert!(doc.get(key).is_some(), "missing key {key}");
    }
    let run = &doc["runs"][0];
    for key in [
        "solver",
        "formulation",
        "status",
        "problem_size",
        "work",
        "timing_s",
        "residuals",
        "resultants",
        "rigid_body",
        "contact",
        "nodes",
    ] {
        assert!(run.get(key).is_some(), "missing runs[].{key}");
    }
    for key in ["x", "y", "pressure", "shear", "u_x", "u_y", "gap", "slip", "state", "slip_velocity"] {
        assert!(run["nodes"][0].get(key).is_some(), "missing nodes[].{key}");
    }
    assert_eq!(doc["effects"], serde_json::json!(["normal"]));
    assert_eq!(run["status"], "solved");
}

/// (what is wrong, scene text, a string the error must contain)
fn bad_cases() -> Vec<(&'static str, String, &'static str)> {
    let r = |from: &str, to: &str| {
        assert!(GOOD.contains(from), "{from}");
        GOOD.replacen(from, to, 1)
    };
    vec![
        ("missing key", r("radius = 1.0\n", ""), "radius"),
        ("wrong type", r("radius = 1.0", "radius = \"one\""), "radius"),
        ("negative radius", r("radius = 1.0", "radius = -1.0"), "wheel.radius"),
        ("NaN modulus", r("youngs_modulus = 94500.0", "youngs_modulus = nan"), "wheel.youngs_modulus"),
        ("Poisson out of range", r("poisson_ratio = 0.1", "poisson_ratio = 0.7"), "wheel.poisson_ratio"),
        ("unknown element", r("element = \"constant\"", "element = \"quartic\""), "quartic"),
        ("unknown solver", r("use = [\"lemke\", \"clarabel\"]", "use = [\"lemk\"]"), "lemk"),
        ("malformed TOML", r("[drive]", "[drive"), "line"),
        ("unknown key", r("friction = 0.0", "friction = 0.0\nfriktion = 0.3"), "friktion"),
        (
            "both drives",
            r("normal_load = 749.70", "normal_load = 749.70\nnormal_approach = 0.01"),
            "drive.normal_approach",
        ),
        ("no normal drive", r("normal_load = 749.70", ""), "normal_load"),
        ("zero contact elements", r("contact_elements = 24", "contact_elements = 0"), "mesh.contact_elements"),
        ("arc too wide", r("contact_arc_deg = 30.0", "contact_arc_deg = 200.0"), "mesh.contact_arc_deg"),
        ("negative friction", r("friction = 0.0", "friction = -0.1"), "contact.friction"),
        (
            "hub larger than wheel",
            r("{ kind = \"top_arc\", angle_deg = 30.0 }", "{ kind = \"hub\", radius = 1.5 }"),
            "wheel.support.radius",
        ),
        ("unknown support", r("kind = \"top_arc\"", "kind = \"axle\""), "axle"),
        ("negative load", r("normal_load = 749.70", "normal_load = -5.0"), "drive.normal_load"),
        ("infinite approach", r("normal_load = 749.70", "normal_approach = inf"), "drive.normal_approach"),
        ("mesh too large for memory", r("other_elements = 32", "other_elements = 9000"), "GiB"),
    ]
}

#[test]
fn bad_scenes_are_refused_with_exit_2_naming_the_field_and_nothing_written() {
    let dir = tempfile::tempdir().unwrap();
    for (i, (what, text, needle)) in bad_cases().into_iter().enumerate() {
        let scene = write(dir.path(), &format!("bad{i}.toml"), &text);
        let json = dir.path().join(format!("bad{i}.json"));
        let out = bin().arg("run").arg(&scene).arg("--json").arg(&json).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: exit {:?}, stderr {stderr}", out.status.code());
        assert!(stderr.contains(needle), "{what}: error does not name `{needle}`: {stderr}");
        assert!(stderr.contains(&format!("bad{i}.toml")), "{what}: error does not name the file: {stderr}");
        assert!(!json.exists(), "{what}: output written");
        // Nothing half-written either: no temporary file left behind.
        assert_eq!(
            std::fs::read_dir(dir.path())
                .unwrap()
                .filter(|e| e.as_ref().unwrap().path().extension().is_some_and(|x| x != "toml"))
                .count(),
            0
        );
    }
}

#[test]
fn missing_scene_file_is_bad_input() {
    let out = bin().args(["run", "/nonexistent/scene.toml"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/scene.toml"));
}
