//! The sweep under a real batch scheduler (issue 23): on a SLURM cluster (a single-node one on this machine:
//! `scripts/slurm/cluster.sh start`), `scripts/slurm/submit.sh` runs a reference sweep as a job array of shards and a
//! dependent merge job; the merged CSV must be the single-process sweep's, row for row (provenance columns masked).
//! Then (issue 31) one shard of three is cancelled (`scancel`) while another still runs, and the README's recovery,
//! `scripts/slurm/resubmit.sh DIR 2`, submits it again (it resumes from its journal) and re-chains the merge: the
//! merge must not run while any shard job is queued, and must be the serial CSV: nothing lost, nothing twice (the
//! merge checks every case of the spec is there once), nothing raced.
//!
//! Needs the cluster (`SLURM_CONF` set), so ignored by `cargo test`; CI starts the cluster and runs
//! `cargo test --release --test slurm -- --ignored --nocapture`. `ROLLBEM_SLURM_SPEC` and `ROLLBEM_SLURM_SHARDS`
//! choose another sweep for the first part (default `reference/sweeps/finite-vs-half-plane.toml`, 3 shards); the
//! recovery runs a sweep of its own ([`slow_spec`]), whose timing it needs. Between the two, the 3D reference sweep
//! `cattaneo3d-load` (issue 32) runs as an array of 3 shards whose merge must equal its serial CSV.
//! A second test (issue 36) runs the creep-force table `reference/creep-tables/fastsim-usetab.toml` (7 000 cases) as
//! an array of 4 shards: the merged CSV and `.npz` must be the serial run's byte for byte.

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

/// What [`watch`] saw of a merge job and the shard jobs it must wait for.
#[derive(Debug, Default)]
struct Seen {
    /// Polls in which the merge was pending while a shard job was queued or running.
    held: usize,
    /// Polls in which the merge was running, completing or done while a shard job was queued or running.
    overlaps: usize,
    /// Whether the merge was seen running, or has left the queue.
    merge_ran: bool,
    /// Whether the resubmitted tasks had all ended while a task of the original array was still queued or running:
    /// the moment a merge that waited for the resubmitted tasks only would have started.
    early: bool,
}

/// Poll the queue until the original array, the resubmitted tasks and the merge have left it, noting how the merge's
/// state and the shards' overlapped (a guard of 10 minutes against a stuck cluster, not a time limit).
fn watch(original: &str, again: &str, merge: &str) -> Seen {
    let mut seen = Seen::default();
    let start = Instant::now();
    loop {
        let out = run(Command::new("squeue").args(["-h", "-o", "%i %T"]));
        let jobs: Vec<(&str, &str)> = out.lines().filter_map(|l| l.split_once(' ')).collect();
        let of = |array: &str| jobs.iter().any(|(id, _)| *id == array || id.starts_with(&format!("{array}_")));
        let (original_queued, again_queued) = (of(original), of(again));
        seen.early |= original_queued && !again_queued;
        let shard_queued = original_queued || again_queued;
        match jobs.iter().find(|(id, _)| *id == merge).map(|(_, st)| *st) {
            // Gone: it ran (it is never cancelled here), and ran while a shard job was queued if one still is.
            None => {
                seen.merge_ran = true;
                if !shard_queued {
                    return seen;
                }
                seen.overlaps += 1;
            }
            Some("PENDING") => seen.held += usize::from(shard_queued),
            Some(_) => {
                seen.merge_ran = true;
                seen.overlaps += usize::from(shard_queued);
            }
        }
        assert!(start.elapsed() < Duration::from_secs(600), "jobs still queued after 10 minutes: {out}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// A sweep whose shard 3 is slow: 60 frictional BEM wheels, a model each, 20 cases (of one row) per shard of three;
/// the cases of shard 3 (every third, `index % 3 == 2`) have 900 elements besides the contact zone, the others 400
/// (measured, one thread: 1.3 s for shard 2, 6.6 s for shard 3). So a shard cancelled half-way and resubmitted ends
/// well before shard 3, which starts when it is cancelled.
fn slow_spec(dir: &Path) -> PathBuf {
    let pairs: Vec<String> = (0..60).map(|i| format!("[{}, {}]", 60 + i, if i % 3 == 2 { 900 } else { 400 })).collect();
    let text = format!(
        "name = \"slurm-recovery\"\nbase = '{}'\n[[grid]]\n\"mesh.contact_elements & mesh.other_elements\" = [{}]\n\
         \"contact.friction\" = [0.3]\n\"drive.tangential_load\" = [100.0]\n\"solvers.use\" = [[\"lemke\"]]\n",
        root().join("reference/scenes/seed-fig6-constant.toml").display(),
        pairs.join(", ")
    );
    let p = dir.join("slurm-recovery.toml");
    std::fs::write(&p, text).unwrap();
    p
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

    // A 3D sweep (issue 32: half-space scenes through the same machinery) as an array of 3 shards: about 1 s of
    // computing (10 cases of reference/sweeps/cattaneo3d-load.toml), the rest the scheduler's.
    let t = Instant::now();
    let spec3 = root().join("reference/sweeps/cattaneo3d-load.toml");
    let serial3 = dir.path().join("serial3d.csv");
    run(bin().arg("sweep").arg(&spec3).arg("--out").arg(&serial3));
    let dir3 = dir.path().join("space");
    let (array3, merge3) = submit(&spec3, 3, &dir3);
    wait(&[&array3, &merge3]);
    assert_eq!(
        masked(&dir3.join("merged.csv")),
        masked(&serial3),
        "merge log: {:?}",
        std::fs::read_to_string(dir3.join("merge.log"))
    );
    eprintln!(
        "3D sweep as a job array of 3 shards and merge: {:.1} s; merged CSV = serial CSV",
        t.elapsed().as_secs_f64()
    );

    // The recovery of the README (issue 31): on a sweep whose shard 3 is slow, shard 2 of 3 is cancelled once its
    // journal holds 8 of its 20 cases, while shard 1 runs and shard 3 waits for a core (two on this cluster);
    // `scripts/slurm/resubmit.sh DIR 2`, exactly as the README says, submits it again and re-chains the merge. The
    // resubmitted shard ends long before shard 3, so a merge that waited for the resubmitted task only (the recipe
    // before) started while shard 3 ran and failed ("cannot read shard-3-of-3.csv": seen on this cluster with this
    // sweep); this one must not run while any shard job is queued, and must equal the serial CSV.
    let t = Instant::now();
    let dir2 = dir.path().join("cancelled");
    std::fs::create_dir(&dir2).unwrap();
    let slow = slow_spec(&dir2);
    let slow_serial = dir2.join("serial.csv");
    run(bin().arg("sweep").arg(&slow).arg("--out").arg(&slow_serial));
    let (array, _merge) = submit(&slow, 3, &dir2);
    let shard = dir2.join("shard-2-of-3.csv");
    let start = Instant::now();
    // The journal's first three lines (marker, identity, header), then one row per case: 8 of shard 2's 20 cases.
    while lines(&partial(&shard)) < 3 + 8 {
        assert!(!shard.exists(), "shard 2 finished before it could be cancelled: use a slower sweep");
        assert!(start.elapsed() < Duration::from_secs(600), "shard 2 never started");
        std::thread::sleep(Duration::from_millis(10));
    }
    let others: Vec<String> = ["1", "3"].iter().map(|k| format!("{array}_{k}")).filter(|j| queued(j)).collect();
    assert!(!others.is_empty(), "no other shard is queued or running: the cancel does not test the recovery");
    // resubmit.sh refuses a task still running (two runs of one shard would share its journal) and one not of 1..3.
    for (task, why) in [("2", "is still queued or running"), ("4", "not a shard of 1..3")] {
        let o = Command::new(root().join("scripts/slurm/resubmit.sh")).arg(&dir2).arg(task).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.code() == Some(2) && err.contains(why), "task {task}: {err}");
    }
    run(Command::new("scancel").arg(format!("{array}_2")));
    wait(&[&format!("{array}_2")]);
    assert!(!shard.exists(), "shard 2 was cancelled before it finished");
    let kept = lines(&partial(&shard)).saturating_sub(3);
    let out = run(Command::new(root().join("scripts/slurm/resubmit.sh")).arg(&dir2).arg("2"));
    let ids: Vec<&str> = out.split_whitespace().collect();
    assert_eq!(ids.len(), 2, "{out}");
    let (again, merge2) = (ids[0].to_string(), ids[1].to_string());
    let dependency = run(Command::new("scontrol").args(["show", "job", &merge2]));
    let waits_for_array = others.iter().any(|j| queued(j));
    // The merge waits for the resubmitted task to succeed and for the original array to end (if it was still queued
    // when resubmit.sh looked: it is checked again just after, so a shard that ended in between may be missing).
    assert!(dependency.contains(&format!("afterok:{again}")), "{dependency}");
    if waits_for_array {
        assert!(dependency.contains(&format!("afterany:{array}")), "{dependency}");
    }
    let seen = watch(&array, &again, &merge2);
    assert!(seen.merge_ran, "the merge never ran");
    assert_eq!(seen.overlaps, 0, "the merge ran while a shard job was queued or running: {seen:?}");
    assert!(seen.early, "the resubmitted shard did not end before the original array: the race is not tested");
    let log = std::fs::read_to_string(dir2.join("shard-2.log")).unwrap();
    let resumed = log.lines().find(|l| l.contains("already done")).unwrap_or_else(|| panic!("no resume: {log}"));
    // The cases of the journal but its last one (which resume runs again, as it may be cut short) are not rerun.
    let done: usize = resumed.split("; ").nth(1).and_then(|s| s.split_whitespace().next()).unwrap().parse().unwrap();
    assert_eq!(done, kept - 1, "{log}");
    let merged = dir2.join("merged.csv");
    assert!(merged.exists(), "no merged CSV: {:?}", std::fs::read_to_string(dir2.join("merge.log")));
    assert_eq!(masked(&merged), masked(&slow_serial), "{:?}", std::fs::read_to_string(dir2.join("merge.log")));
    eprintln!(
        "shard 2 cancelled with {kept} of its 20 cases in its journal while {others:?} were queued; resubmit.sh: \
         {again} {merge2} ({dependency_line}); the resubmitted shard ended before the original array; merge pending \
         while a shard was queued in {} polls, ran in none of them; {resumed}; merged CSV = serial CSV ({:.1} s)",
        seen.held,
        t.elapsed().as_secs_f64(),
        dependency_line = dependency.lines().find(|l| l.contains("Dependency=")).unwrap_or("").trim(),
    );
}

#[test]
#[ignore = "needs a SLURM cluster: scripts/slurm/cluster.sh start (CI runs it)"]
fn a_creep_table_as_a_job_array_equals_the_serial_table_byte_for_byte() {
    table_through_array("fastsim-usetab.toml");
    // The exact theory (`reference/creep-tables/exact-usetab.toml`: 3 000 cases of `halfspace::rolling` on 32 × 32
    // elements, about 14 s of CPU), the same way.
    table_through_array("exact-usetab.toml");
}

/// The table `reference/creep-tables/NAME` as an array of 4 shards and the merge job, against its serial run.
fn table_through_array(name: &str) {
    // Issue 36: a creep-force table of at least 3 000 cases (reference/creep-tables/fastsim-usetab.toml: 7 000
    // FASTSIM cases on 100 × 100 strips, about 2 s of CPU) through `scripts/slurm/submit.sh`, unchanged (the sweep
    // commands dispatch on the spec's `kind = "creep_table"`), as an array of 4 shards and the merge job. Expected:
    // the merged CSV and .npz are the serial run's byte for byte (a row depends on its case alone; the table has no
    // timing columns), and the merge holds every case once (`sweep-merge --spec` checks it).
    assert!(std::env::var_os("SLURM_CONF").is_some(), "no SLURM_CONF: start a cluster with scripts/slurm/cluster.sh");
    let spec = root().join("reference/creep-tables").join(name);
    let dir = tempfile::tempdir().unwrap();
    let serial = dir.path().join("serial.csv");
    run(bin().arg("sweep").arg(&spec).arg("--out").arg(&serial));
    let t = Instant::now();
    let array_dir = dir.path().join("table");
    let (array, merge) = submit(&spec, 4, &array_dir);
    wait(&[&array, &merge]);
    let merged = array_dir.join("merged.csv");
    let log = std::fs::read_to_string(array_dir.join("merge.log"));
    assert!(merged.exists(), "no merged table: {log:?}");
    let rows = std::fs::read_to_string(&merged).unwrap().lines().count() - 1;
    assert!(rows >= 3000, "{rows} cases");
    assert!(std::fs::read(&merged).unwrap() == std::fs::read(&serial).unwrap(), "merged CSV differs: {log:?}");
    assert!(
        std::fs::read(array_dir.join("merged.npz")).unwrap() == std::fs::read(serial.with_extension("npz")).unwrap(),
        "merged .npz differs"
    );
    for k in 1..=4 {
        assert!(!partial(&array_dir.join(format!("shard-{k}-of-4.csv"))).exists(), "shard {k} left its journal");
    }
    eprintln!(
        "creep table {name} of {rows} cases as a job array of 4 shards and merge: {:.1} s; merged CSV and .npz = \
         serial, byte for byte",
        t.elapsed().as_secs_f64()
    );
}
