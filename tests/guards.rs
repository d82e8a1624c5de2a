//! Nothing runaway, nothing unreadable (issue 31, items 2 and 3): a load path too large to hold is refused when the
//! scene is read, naming the step; a result document is read back with keys this version does not know, and one
//! written under looser checks is read as recorded but cannot be run again.

use rollbem::pipeline::{run_scene, Model};
use rollbem::results::Report;
use rollbem::scene::Scene;
use std::path::Path;

fn path_scene(substeps: &str, elements: usize, solvers: &str) -> String {
    format!(
        "name = \"p\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\nmodel = \"half_plane\"\n\
         [mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\ncontact_elements = {elements}\n[contact]\n\
         friction = 0.3\n[solvers]\nuse = {solvers}\n[[steps]]\nnormal_load = 1000.0\n\
         [[steps]]\nnormal_load = 1000.0\ntangential_load = 100.0\nsubsteps = {substeps}\n"
    )
}

#[test]
fn a_path_of_a_billion_substeps_is_refused_when_read() {
    // The limit on substeps (MAX_PATH_SUBSTEPS = 1e6), whatever the mesh.
    let e = Scene::from_toml(&path_scene("1000000000", 20, "[\"lemke\"]"), Path::new("p.toml")).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    let text = e.to_string();
    assert!(text.contains("steps[1].substeps") && text.contains("1000000001 substeps"), "{text}");
    // The memory estimate: 400 000 substeps × 6 solvers × 2000 nodes × 128 B = 614 GiB > 4 GiB.
    let e = Scene::from_toml(&path_scene("400000", 2000, "[\"all\"]"), Path::new("p.toml")).unwrap_err().to_string();
    assert!(e.contains("steps[1].substeps") && e.contains("GiB") && e.contains("× 2000 contact nodes"), "{e}");
    // Just inside both: read (and not run here).
    let ok = Scene::from_toml(&path_scene("100000", 40, "[\"lemke\"]"), Path::new("p.toml"));
    assert!(ok.is_ok(), "{:?}", ok.err());
}

#[test]
fn a_path_of_a_billion_substeps_is_refused_by_the_cli_with_code_2() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("p.toml");
    std::fs::write(&file, path_scene("1000000000", 20, "[\"lemke\"]")).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(["run", "--quiet", "--json"])
        .arg(dir.path().join("out.json"))
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("steps[1].substeps"));
    assert!(!dir.path().join("out.json").exists());
}

/// A result document of today, with keys added as a later version would add them (a scene key, a run key, a
/// top-level key): read, the unknown scene key named, the scene marked not runnable; everything else as written.
#[test]
fn a_document_with_keys_this_version_does_not_know_is_read() {
    let s = Scene::from_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml"))
        .unwrap();
    let report = run_scene(&s).unwrap();
    let mut v = serde_json::to_value(&report).unwrap();
    v["scene"]["wheel"]["thermal_expansion"] = serde_json::json!(1.2e-5);
    v["scene"]["future_table"] = serde_json::json!({ "x": 1 });
    v["runs"][0]["energy_release"] = serde_json::json!(3.0);
    v["provenance"] = serde_json::json!({ "host": "x" });
    let read = Report::from_json(&v.to_string(), Path::new("future.json")).unwrap();
    assert_eq!(read.runs.len(), report.runs.len());
    assert_eq!(read.runs[0].nodes.len(), report.runs[0].nodes.len());
    assert_eq!(read.scene.name(), s.name());
    let why = read.scene.runnable().unwrap_err().to_string();
    assert!(why.contains("wheel.thermal_expansion") && why.contains("future_table"), "{why}");
    assert!(Model::build(&read.scene).is_err(), "a scene with ignored keys is not run as if it had none");
    // Without additions the scene read back is runnable.
    let plain = Report::from_json(&serde_json::to_string(&report).unwrap(), Path::new("r.json")).unwrap();
    assert!(plain.scene.runnable().is_ok());
}

/// A document whose scene this version's checks refuse (as if a check had been tightened since it was written):
/// read, its scene as recorded and marked with the check's message; a schema-2 document's `polish_change` is read
/// into the run's figures.
#[test]
fn a_document_from_looser_checks_or_schema_2_is_read() {
    let s = Scene::from_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml"))
        .unwrap()
        .edit(|d| d.solvers = rollbem::scene::document::SolversTable::using(&["clarabel"]))
        .unwrap();
    let report = run_scene(&s).unwrap();
    let mut v = serde_json::to_value(&report).unwrap();
    v["scene"]["wheel"]["poisson_ratio"] = serde_json::json!(0.7);
    let read = Report::from_json(&v.to_string(), Path::new("old.json")).unwrap();
    assert_eq!(read.scene.wheel().material.poisson_ratio, 0.7, "the scene as recorded");
    assert!(read.scene.runnable().unwrap_err().to_string().contains("poisson_ratio"));
    // Schema 2: polish_change was a key of the run.
    let polish = report.runs[0].figures.get("polish_change").expect("clarabel reports its polish change");
    let mut v = serde_json::to_value(&report).unwrap();
    v["schema"] = serde_json::json!(2);
    let run = v["runs"][0].as_object_mut().unwrap();
    run.remove("figures");
    run.insert("polish_change".into(), serde_json::json!(polish));
    let read = Report::from_json(&v.to_string(), Path::new("v2.json")).unwrap();
    assert_eq!(read.runs[0].figures.get("polish_change"), Some(polish));
    // A newer schema is refused, saying so.
    v["schema"] = serde_json::json!(99);
    let e = Report::from_json(&v.to_string(), Path::new("v99.json")).unwrap_err().to_string();
    assert!(e.contains("schema 99"), "{e}");
}

/// A recorded scene cannot be made runnable by an edit, and solver settings a later version added or a tightened
/// range are read as the defaults, marked (review of issue 31).
#[test]
fn a_recorded_scene_stays_not_runnable_and_its_settings_read_leniently() {
    let s = Scene::from_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml"))
        .unwrap();
    let report = run_scene(&s).unwrap();
    let mut v = serde_json::to_value(&report).unwrap();
    v["scene"]["solvers"]["lemke"]["future_key"] = serde_json::json!(3);
    v["scene"]["solvers"]["clarabel"]["tolerance"] = serde_json::json!(7.0);
    let read = Report::from_json(&v.to_string(), Path::new("future.json")).unwrap();
    let why = read.scene.runnable().unwrap_err().to_string();
    assert!(why.contains("solvers.lemke") && why.contains("solvers.clarabel"), "{why}");
    assert!(read.scene.with_creepage(1e-3).is_err() && read.scene.edit(|_| {}).is_err());
}
