//! The sweep under a real batch scheduler (issue 23): on a SLURM cluster (a single-node one on this machine:
//! `scripts/slurm/cluster.sh start`), `scripts/slurm/submit.sh` runs a reference sweep as a job array of shards and a
//! dependent merge job; the merged CSV must be the single-process sweep's, row for row (timings masked). Then one
//! shard is cancelled (`scancel`) while it runs, submitted again (it resumes from its journal), merged again: nothing
//! lost, nothing twice (the merge checks every case of the spec is there once), the same CSV.
//!
//! Needs the cluster (`SLURM_CONF` set), so ignored by `cargo test`; CI starts the cluster and runs
//! `cargo test --release --test slurm -- --ignored --nocapture`. `ROLLBEM_SLURM_SPEC` and `ROLLBEM_SLURM_SHARDS`
//! choose another sweep (default `reference/sweeps/finite-vs-half-plane.toml`, 3 shards).

#[path = "common/sweep_cli.rs"]
mod common;

use common::{bin, masked, partial, run};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Submit the array and the merge with `scripts/slurm/submit.sh`: (array job, merge job).
fn submit(spec: &Path, n: usize, dir: &Path) -> (String, String) {
    let out = run(Command::new(root().join("scripts/slurm/submit.sh"))
        .arg(spec)
        .arg(n.to_string())
        .arg(dir)
        .env("ROLLBEM", env!("CARGO_BIN_EXE_rollbem")));
    let ids: Vec<String> = out.split_whitespace().map(str::to_string).collect();
    assert_eq!(ids.len(), 2, "{out}");
    (ids[0].clone(), ids[1].clone())
}

/// Whether a job (or array task, `ID_K`) is still in the queue.
fn queued(job: &str) -> bool {
    let out = run(Command::new("squeue").args(["-h", "-o", "%i %T"]));
    out.lines().any(|l| l.split_whitespace().next().is_some_and(|id| id == job || id.starts_with(&format!("{job}_"))))
}

/// Wait until the jobs have left the queue (a guard of 10 minutes against a stuck cluster, not a time limit).
fn wait(jobs: &[&str]) {
    let start = Instant::now();
    while jobs.iter().any(|j| queued(j)) {
        assert!(start.elapsed() < Duration::from_secs(600), "jobs {jobs:?} still queued after 10 minutes");
        std::thread::sleep(Duration::from_millis(200));
    }
}

/// Complete lines of a file (0 when there is none).
fn lines(p: &Path) -> usize {
    std::fs::read(p).map_or(0, |b| b.iter().filter(|&&c| c == b'\n').count())
}

#[test]
#[ignore = "needs a SLURM cluster: scripts/slurm/cluster.sh start (CI runs it)"]
fn a_job_array_merges_to_the_serial_sweep_and_a_cancelled_shard_resumes() {
    assert!(std::env::var_os("SLURM_CONF").is_some(), "no SLURM_CONF: start a cluster with scripts/slurm/cluster.sh");
    let spec = std::env::var_os("ROLLBEM_SLURM_SPEC")
        .map_or_else(|| root().join("reference/sweeps/finite-vs-half-plane.toml"), PathBuf::from);
    let n: usize = std::env::var("ROLLBEM_SLURM_SHARDS").map_or(3, |s| s.parse().unwrap());
    let dir = tempfile::tempdir().unwrap();
    let serial = dir.path().join("serial.csv");
    run(bin().arg("sweep").arg(&spec).arg("--out").arg(&serial));
    let reference = masked(&serial);

    // The job array and its merge.
    let t = Instant::now();
    let plain = dir.path().join("plain");
    let (array, merge) = submit(&spec, n, &plain);
    wait(&[&array, &merge]);
    assert_eq!(
        masked(&plain.join("merged.csv")),
        reference,
        "merge log: {:?}",
        std::fs::read_to_string(plain.join("merge.log"))
    );
    eprintln!(
        "job array of {n} shards and merge: {:.1} s; merged CSV = serial CSV ({} rows)",
        t.elapsed().as_secs_f64(),
        reference.1.len()
    );

    // Shard 2 cancelled once its journal holds two cases, submitted again, merged again.
    let t = Instant::now();
    let dir2 = dir.path().join("cancelled");
    let (array, merge) = submit(&spec, n, &dir2);
    let shard = dir2.join(format!("shard-2-of-{n}.csv"));
    let start = Instant::now();
    // The journal's first line, the header, then two cases of one row each.
    while lines(&partial(&shard)) < 4 {
        assert!(!shard.exists(), "shard 2 finished before it could be cancelled: use a slower sweep");
        assert!(start.elapsed() < Duration::from_secs(600), "shard 2 never started");
        std::thread::sleep(Duration::from_millis(10));
    }
    run(Command::new("scancel").arg(format!("{array}_2")));
    wait(&[&format!("{array}_2")]);
    assert!(!shard.exists(), "shard 2 was cancelled before it finished");
    let kept = lines(&partial(&shard)).saturating_sub(2);
    // The merge waits on a task that will never succeed: cancel it, resubmit the task and a merge after it.
    run(Command::new("scancel").arg(&merge));
    wait(&[&array, &merge]);
    let sbatch = |args: &[&str], script: &str| {
        let mut c = Command::new("sbatch");
        c.arg("--parsable").args(args).arg(root().join("scripts/slurm").join(script));
        c.arg(env!("CARGO_BIN_EXE_rollbem")).arg(&spec).arg(n.to_string()).arg(&dir2);
        run(&mut c).trim().to_string()
    };
    let log = format!("--output={}", dir2.join("shard-%a.log").display());
    let again = sbatch(&["--array=2", &log], "shard.sbatch");
    let merge_log = format!("--output={}", dir2.join("merge.log").display());
    let merge2 = sbatch(&[&format!("--dependency=afterok:{again}"), &merge_log], "merge.sbatch");
    wait(&[&again, &merge2]);
    let log = std::fs::read_to_string(dir2.join("shard-2.log")).unwrap();
    let resumed = log.lines().find(|l| l.contains("already done")).unwrap_or_else(|| panic!("no resume: {log}"));
    // The cases of the journal but its last one (which resume runs again, as it may be cut short) are not rerun.
    let done: usize = resumed.split("; ").nth(1).and_then(|s| s.split_whitespace().next()).unwrap().parse().unwrap();
    assert_eq!(done, kept - 1, "{log}");
    assert_eq!(masked(&dir2.join("merged.csv")), reference, "{:?}", std::fs::read_to_string(dir2.join("merge.log")));
    eprintln!(
        "shard 2 cancelled with {kept} rows in its journal, resubmitted: {}; merged CSV = serial CSV ({:.1} s)",
        resumed,
        t.elapsed().as_secs_f64()
    );
}
