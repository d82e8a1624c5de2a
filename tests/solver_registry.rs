//! The solver seam: one registry is the only list of solvers. `lemke_dense` (the dense reference engine, its own
//! file `src/solvers/lemke/dense.rs` plus one registry line) is selectable from a scene, from `--solver` and from
//! `rollbem lcp solve`, and agrees with the block-revised `lemke`. Reference: the block engine (an independent
//! implementation of the same pivoting rule, which follows the same path on exact data).

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::scene::Scene;
use rollbem::solvers::{registry, Status};
use std::path::Path;
use std::process::Command;

fn load(rel: &str) -> (Scene, std::path::PathBuf) {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference").join(rel);
    (Scene::from_file(&p).unwrap(), p)
}

#[test]
fn lemke_dense_is_selectable_from_a_scene_and_agrees_with_lemke() {
    for rel in ["scenes/seed-fig6-constant.toml", "scenes/seed-fig17-mu07.toml", "scenes/cattaneo-decoupled.toml"] {
        let (mut s, _) = load(rel);
        s = s.edit(|d| d.solvers.use_ = vec!["lemke".into(), "lemke_dense".into()]).unwrap();
        let r = run_scene(&s).unwrap();
        let names: Vec<&str> = r.runs.iter().map(|x| x.solver.name()).collect();
        assert_eq!(names, ["lemke", "lemke_dense"], "{rel}");
        for run in &r.runs {
            assert_eq!(run.status, Status::Solved, "{rel} {}: {}", run.solver, run.explanation());
        }
        // Same pivot path: the same number of pivots; tractions to round-off (the harness's agreement check).
        assert_eq!(r.runs[0].work, r.runs[1].work, "{rel}");
        let agree = r.checks.iter().find(|c| c.name.starts_with("lemke vs lemke_dense: max")).expect("agreement");
        assert!(agree.pass && agree.measured <= 1e-10, "{rel}: {agree:?}");
    }
}

#[test]
fn all_does_not_run_the_reference_engine_and_names_come_from_the_registry() {
    let (s, p) = load("scenes/seed-fig6-constant.toml");
    let r = run_scene(&s).unwrap();
    assert!(r.runs.iter().all(|x| x.solver != "lemke_dense"));
    // Every registered solver builds with its defaults and reports its own name.
    for e in registry() {
        assert_eq!((e.build)(e.id, (e.defaults)().as_ref()).name(), e.name());
    }
    // An unknown solver is refused at parse time, naming the key and the registry's names.
    let text = std::fs::read_to_string(&p).unwrap().replace("use = [\"all\"]", "use = [\"lemkee\"]");
    let text = if text.contains("lemkee") { text } else { format!("{text}\n[solvers]\nuse = [\"lemkee\"]\n") };
    let e = Scene::from_toml(&text, &p).unwrap_err().to_string();
    assert!(e.contains("solvers.use") && e.contains("lemkee") && e.contains("lemke_dense"), "{e}");
}

#[test]
fn lemke_dense_solves_lcp_files_and_the_other_solvers_say_they_do_not() {
    let dir = tempfile::tempdir().unwrap();
    let (_, scene) = load("scenes/cattaneo-decoupled.toml");
    let file = dir.path().join("c.lcp.dat");
    let bin = env!("CARGO_BIN_EXE_rollbem");
    let st = Command::new(bin).args(["lcp", "export"]).arg(&scene).arg("--out").arg(&file).status().unwrap();
    assert!(st.success());
    let mut z = Vec::new();
    for solver in ["lemke", "lemke_dense"] {
        let json = dir.path().join(format!("{solver}.json"));
        let out = Command::new(bin)
            .args(["lcp", "solve"])
            .arg(&file)
            .args(["--solver", solver, "--json"])
            .arg(&json)
            .output();
        let out = out.unwrap();
        assert!(out.status.success(), "{solver}: {}", String::from_utf8_lossy(&out.stderr));
        let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        assert_eq!(doc["status"], "solved");
        z.push(doc["z"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect::<Vec<f64>>());
    }
    let zmax = z[0].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    for (a, b) in paired(&z[0], &z[1]) {
        assert!((a - b).abs() <= 1e-10 * zmax, "{a} vs {b}");
    }
    let out = Command::new(bin).args(["lcp", "solve"]).arg(&file).args(["--solver", "pgs"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("pgs") && err.contains("lemke_dense"), "{err}");
}
