//! A scene's LCP exported to a file (Siconos format), solved from the file, and solved directly give identical
//! results: the LCP read back is bitwise the LCP built, and Lemke's z from the file equals the in-process z bit for
//! bit — also through the command line (`rollbem lcp export` / `rollbem lcp solve --json`).

use rollbem::lcp_io;
use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use rollbem::solvers::lemke::{solve, LemkeSettings};
use rollbem::solvers::Termination;
use std::path::Path;
use std::process::Command;

const SCENES: [&str; 4] = [
    "scenes/seed-fig6-constant.toml",
    "scenes/seed-fig17-mu07.toml",
    "scenes/cattaneo-decoupled.toml",
    "hard/moment-nearly-overturning.toml",
];

#[test]
fn exported_solved_from_file_and_solved_directly_are_identical() {
    let dir = tempfile::tempdir().unwrap();
    for name in SCENES {
        let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference").join(name);
        let s = Scene::from_file(&p).unwrap();
        let lcp = Model::build(&s).unwrap().lcp(&s).unwrap();
        let file = dir.path().join("x.dat");
        lcp_io::write(&lcp, &file).unwrap();
        let back = lcp_io::read(&file).unwrap();
        assert_eq!(back.q(), lcp.q(), "{name}: q");
        for j in 0..lcp.size() {
            for i in 0..lcp.size() {
                assert_eq!(back.m()[(i, j)].to_bits(), lcp.m()[(i, j)].to_bits(), "{name}: M[{i},{j}]");
            }
        }
        let direct = solve(&lcp, &LemkeSettings::default());
        let from_file = solve(&back, &LemkeSettings::default());
        assert_eq!(direct.status, Termination::Solved, "{name}");
        assert_eq!(direct.pivots, from_file.pivots);
        assert_eq!(direct.z, from_file.z, "{name}: z");

        // Through the binary.
        let out_dat = dir.path().join("cli.dat");
        let out_json = dir.path().join("cli.json");
        let bin = env!("CARGO_BIN_EXE_rollbem");
        let st = Command::new(bin).args(["lcp", "export"]).arg(&p).arg("--out").arg(&out_dat).status().unwrap();
        assert!(st.success());
        let st = Command::new(bin).args(["lcp", "solve"]).arg(&out_dat).arg("--json").arg(&out_json).status().unwrap();
        assert!(st.success());
        let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out_json).unwrap()).unwrap();
        let z: Vec<f64> = doc["z"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert_eq!(z, direct.z, "{name}: z through the CLI");
        assert_eq!(doc["status"], "solved");
    }
}

#[test]
fn gross_sliding_has_no_lcp_to_export_and_bad_files_are_refused() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/gross-sliding.toml");
    let s = Scene::from_file(&p).unwrap();
    let e = Model::build(&s).unwrap().lcp(&s).unwrap_err().to_string();
    assert!(e.contains("μP"), "{e}");
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.dat");
    std::fs::write(&bad, "3\n0\n3 3\n1 2\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rollbem")).args(["lcp", "solve"]).arg(&bad).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bad.dat"));
}
