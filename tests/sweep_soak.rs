//! The soak of issue 23: a 10 000-case sweep on small meshes, run whole and in four shards, one shard SIGKILLed
//! half-way and resumed; the merged shards must be the whole run's CSV (provenance columns masked), every case
//! once, and the peak memory of the 10 000-case run within twice that of a 100-case sweep on the same meshes (each
//! run reports its peak, VmHWM, in its closing line). About 15 s on two cores (the 10 000 cases take about 6 s), so it is part
//! of `cargo test`; the figures it prints (`--nocapture`) are in the README, "Sweeps at scale".

#[path = "common/sweep_cli.rs"]
mod common;

use common::{bin, kill_at, masked, partial, peak_mb, run, write};
use std::path::{Path, PathBuf};

/// `cases / 20` loads on four BEM meshes (12 to 24 contact elements) × five friction coefficients, lemke.
fn spec(dir: &Path, name: &str, cases: usize) -> PathBuf {
    let loads: Vec<String> = (0..cases / 20).map(|i| format!("{:.2}", 100.0 + 0.5 * i as f64)).collect();
    write(
        dir,
        &format!("{name}.toml"),
        &format!(
            "name = \"{name}\"\nbase = '{}/reference/scenes/seed-fig6-constant.toml'\n[[grid]]\n\
             \"mesh.contact_elements\" = [12, 16, 20, 24]\n\"contact.friction\" = [0.0, 0.1, 0.2, 0.3, 0.4]\n\
             \"drive.normal_load\" = [{}]\n\"solvers.use\" = [[\"lemke\"]]\n",
            env!("CARGO_MANIFEST_DIR"),
            loads.join(", ")
        ),
    )
}

#[test]
fn ten_thousand_cases_killed_and_resumed_in_bounded_memory() {
    let dir = tempfile::tempdir().unwrap();
    let small = spec(dir.path(), "soak-100", 100);
    let large = spec(dir.path(), "soak-10000", 10_000);
    let peak_small = peak_mb(&run(bin().arg("sweep").arg(&small).arg("--out").arg(dir.path().join("small.csv"))));
    let whole = dir.path().join("whole.csv");
    let started = std::time::Instant::now();
    let said = run(bin().arg("sweep").arg(&large).arg("--out").arg(&whole));
    let seconds = started.elapsed().as_secs_f64();
    let peak_large = peak_mb(&said);
    let (header, rows) = masked(&whole);
    assert_eq!(rows.len(), 10_000, "one row per case (one solver)");
    let cases: Vec<usize> = rows.iter().map(|r| r[0].parse().unwrap()).collect();
    assert!(cases.iter().copied().eq(0..10_000), "every case once, in order");

    // Four shards; shard 2 killed half-way through its journal, then resumed.
    let n = 4;
    let half = std::fs::metadata(&whole).unwrap().len() / n / 2;
    let mut shards = Vec::new();
    let mut shard_peaks = Vec::new();
    let mut resumed = String::new();
    for k in 1..=n {
        let out = dir.path().join(format!("shard-{k}.csv"));
        let cmd = || {
            let mut c = bin();
            c.arg("sweep").arg(&large).args(["--shard", &format!("{k}/{n}"), "--out"]).arg(&out).arg("--resume");
            c
        };
        if k == 2 {
            assert!(kill_at(&mut cmd(), &out, half, 0), "the kill landed while shard 2 ran");
            assert!(partial(&out).exists() && !out.exists());
            let o = cmd().output().unwrap();
            assert!(o.status.success());
            resumed = String::from_utf8_lossy(&o.stderr).lines().next().unwrap_or("").to_string();
            shard_peaks.push(peak_mb(&String::from_utf8_lossy(&o.stdout)));
        } else {
            shard_peaks.push(peak_mb(&run(&mut cmd())));
        }
        shards.push(out);
    }
    let merged = dir.path().join("merged.csv");
    run(bin().args(["sweep-merge", "--spec"]).arg(&large).arg(&merged).args(&shards));
    assert_eq!(masked(&merged), (header, rows), "the merged shards are the whole run's CSV");
    eprintln!(
        "soak: 10 000 cases, 10 000 rows in {seconds:.1} s, peak memory {peak_large} MB (100 cases: {peak_small} MB); \
         shards' peaks {shard_peaks:?} MB; resumed shard 2: {resumed}"
    );
    assert!(peak_large <= 2.0 * peak_small, "peak memory {peak_large} MB against {peak_small} MB for 100 cases");
}
