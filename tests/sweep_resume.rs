//! Streamed sweeps that are killed and resumed (issue 23): the real binary, SIGKILLed at random points of its run
//! and resumed with `--resume`, always ends with the CSV of an uninterrupted run (timings masked), every case once;
//! a cut last line and a case cut short are redone; a journal of another spec is refused; a finished output is not
//! run again; `-` and FIFOs get the sorted CSV; the size guard; `sweep-merge --spec`.

#[path = "common/sweep_cli.rs"]
mod common;

use common::{bin, kill_at, masked, partial, write};
use rollbem::sweep::journal::MARKER;
use std::path::{Path, PathBuf};
use std::process::Command;

/// 1024 cases on four small BEM meshes, two rows each (lemke, active_set), frictionless and frictional, and four
/// cases whose named solver does not apply (one `error` row each): about a second on two cores.
fn spec(dir: &Path, name: &str) -> PathBuf {
    let loads: Vec<String> = (0..51).map(|i| format!("{:.1}", 90.0 + 4.0 * i as f64)).collect();
    write(
        dir,
        &format!("{name}.toml"),
        &format!(
            r#"
name = "{name}"
base = '{}/reference/scenes/seed-fig6-constant.toml'

[[grid]]
"mesh.contact_elements" = [12, 16, 20, 24]
"drive.normal_load" = [{}]
"contact.friction" = [0.0, 0.1, 0.2, 0.3, 0.4]
"solvers.use" = [["lemke", "active_set"]]

[[grid]]
"mesh.contact_elements" = [12, 16, 20, 24]
"contact.friction" = [0.2]
"solvers.use" = [["clarabel"]]
"#,
            env!("CARGO_MANIFEST_DIR"),
            loads.join(", ")
        ),
    )
}

/// A small deterministic generator (xorshift64*), so that the trials are the same on every run.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) % n.max(1)
    }
}

/// 24 trials: each kills a sweep with SIGKILL one to three times at random points (by the journal's size, or right
/// after the start), after some kills also cuts the journal at a random byte (a write torn by a crash), then resumes
/// it to the end; the CSV must equal the uninterrupted run's, row for row, timings masked.
#[test]
fn killed_and_resumed_sweeps_end_as_an_uninterrupted_one() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "trials");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let reference = masked(&whole);
    assert_eq!(reference.1.len(), 1020 * 2 + 4);
    let mut pairs: Vec<(&str, &str)> = reference.1.iter().map(|r| (r[0].as_str(), r[9].as_str())).collect();
    pairs.dedup();
    assert_eq!(pairs.len(), reference.1.len(), "the reference has each (case, solver) once");
    // The journal of a complete run is about as long as the CSV plus its first line.
    let full = std::fs::metadata(&whole).unwrap().len() + MARKER.len() as u64 + 1;
    let mut rng = Rng(0x5eed_2023);
    let (mut kills, mut mid_run, mut cuts) = (0, 0, 0);
    for trial in 0..24 {
        let out = dir.path().join(format!("t{trial}.csv"));
        for _ in 0..1 + rng.below(3) {
            let early = rng.below(6) == 0;
            let bytes = if early { 0 } else { 1 + rng.below(full * 95 / 100) };
            kills += 1;
            mid_run += usize::from(kill_at(
                bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume"),
                &out,
                bytes,
                rng.below(40),
            ));
            let journal = partial(&out);
            if journal.exists() && rng.below(3) == 0 {
                let len = std::fs::metadata(&journal).unwrap().len();
                let f = std::fs::OpenOptions::new().write(true).open(&journal).unwrap();
                f.set_len(len - rng.below(len / 4)).unwrap();
                cuts += 1;
            }
        }
        let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume").output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "trial {trial}: {err}");
        assert!(!partial(&out).exists(), "trial {trial}: the journal is removed at the end");
        assert_eq!(masked(&out), reference, "trial {trial}: {err}");
    }
    eprintln!("{kills} kills ({mid_run} while the sweep ran), {cuts} journals cut at a random byte");
    assert!(mid_run >= 20, "only {mid_run} kills landed while a sweep ran");
}

/// A journal whose last case lost a row and whose last line is cut: both are found and redone.
#[test]
fn a_cut_line_and_a_case_cut_short_are_redone() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "cut");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let text = std::fs::read_to_string(&whole).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    // Keep the header and the rows of cases 0..=9 (two rows each), then case 10's first row, then half a line.
    let out = dir.path().join("out.csv");
    let kept = lines[..1 + 20 + 1].join("\n");
    let journal = format!("{MARKER}\n{kept}\n{}", &lines[22][..lines[22].len() / 2]);
    std::fs::write(partial(&out), journal).unwrap();
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("10 already done") && err.contains("case 10 run again"), "{err}");
    assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("({} cases run now", 1024 - 10)));
    assert_eq!(masked(&out), masked(&whole));
}

/// What `--resume` refuses: a journal of another spec (a value changed) or shard, standard output.
#[test]
fn resume_refuses_what_is_not_this_sweeps() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "other");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let text = std::fs::read_to_string(&whole).unwrap();
    let out = dir.path().join("out.csv");
    std::fs::write(partial(&out), format!("{MARKER}\n{text}")).unwrap();
    // Another spec: a load changed, so case 4's parameters (the second load) are not the journal's.
    let changed = std::fs::read_to_string(&spec).unwrap().replace("[90.0, 94.0,", "[90.0, 95.0,");
    let other = write(dir.path(), "changed.toml", &changed);
    let o = bin().arg("sweep").arg(&other).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("`--resume`") && err.contains("case 4:") && err.contains("94.0"), "{err}");
    assert!(!out.exists());
    // Another shard.
    let o = bin().arg("sweep").arg(&spec).args(["--shard", "2/3", "--out"]).arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("not a case of shard 2/3"), "{err}");
    // Standard output keeps no journal.
    let o = bin().arg("sweep").arg(&spec).args(["--out", "-", "--resume"]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("`--resume`") && o.stdout.is_empty(), "{err}");
}

/// Resuming a finished sweep runs nothing and leaves its CSV alone; a shard resumed from its finished CSV too.
#[test]
fn resuming_a_finished_sweep_runs_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "finished");
    let out = dir.path().join("out.csv");
    assert!(bin().arg("sweep").arg(&spec).args(["--shard", "2/4", "--out"]).arg(&out).status().unwrap().success());
    let before = std::fs::read(&out).unwrap();
    let o = bin().arg("sweep").arg(&spec).args(["--shard", "2/4", "--out"]).arg(&out).arg("--resume").output().unwrap();
    assert!(o.status.success());
    let (said, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(said.contains("(0 cases run now") && err.contains("256 already done"), "{said} {err}");
    assert_eq!(std::fs::read(&out).unwrap(), before);
    assert!(!partial(&out).exists());
}

/// The plan is printed before the run: the cases and an estimate of time and memory; `-` gets the sorted CSV and the
/// messages go to standard error; a FIFO gets it too, written through.
#[test]
fn the_plan_is_printed_and_stdout_and_fifos_get_the_sorted_csv() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "targets");
    let whole = dir.path().join("whole.csv");
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("1024 cases") && err.contains("estimate") && err.contains("peak memory"), "{err}");
    let o = bin().arg("sweep").arg(&spec).args(["--out", "-"]).output().unwrap();
    assert!(o.status.success());
    let piped = write(dir.path(), "piped.csv", std::str::from_utf8(&o.stdout).unwrap());
    assert_eq!(masked(&piped), masked(&whole));
    assert!(String::from_utf8_lossy(&o.stderr).contains("rows written to -"));
    // A FIFO.
    let fifo = dir.path().join("fifo");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&fifo).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let got = reader.join().unwrap();
    let through = write(dir.path(), "through.csv", std::str::from_utf8(&got).unwrap());
    assert_eq!(masked(&through), masked(&whole));
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "the FIFO stays a FIFO");
}

/// Above 100 000 cases a sweep needs `--allow-large`; `--dry-run` prints the plan without running.
#[test]
fn a_large_grid_needs_allow_large() {
    let dir = tempfile::tempdir().unwrap();
    let values = |n: usize| (0..n).map(|i| format!("{}.0", 100 + i)).collect::<Vec<_>>().join(", ");
    let large = write(
        dir.path(),
        "large.toml",
        &format!(
            "name = \"large\"\nbase = '{}/reference/scenes/seed-fig6-constant.toml'\n[[grid]]\n\
             \"drive.normal_load\" = [{}]\n\"mesh.contact_elements\" = [10, 11, 12, 13, 14, 15, 16, 17, 18, 19]\n\
             \"wheel.radius\" = [{}]\n",
            env!("CARGO_MANIFEST_DIR"),
            values(1001),
            (0..10).map(|i| format!("{}.0", 1 + i)).collect::<Vec<_>>().join(", ")
        ),
    );
    let out = dir.path().join("large.csv");
    let o = bin().arg("sweep").arg(&large).arg("--out").arg(&out).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("`grid`") && err.contains("100100 cases") && err.contains("--allow-large"), "{err}");
    assert!(!out.exists() && !partial(&out).exists());
    // A dry run validates every case and prints the plan, and writes nothing.
    let o = bin().arg("sweep").arg(&large).arg("--out").arg(&out).arg("--dry-run").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("100100 cases") && err.contains("100100 to run on 400 models") && err.contains("estimate"),
        "{err}"
    );
    assert!(!out.exists() && !partial(&out).exists());
}

/// `sweep-merge --spec` checks that the shards hold every case of the sweep once: a missing shard is named.
#[test]
fn merge_with_the_spec_finds_a_missing_shard() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "merged");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let mut shards = Vec::new();
    for k in 1..=3 {
        let p = dir.path().join(format!("s{k}.csv"));
        let o = bin().arg("sweep").arg(&spec).args(["--shard", &format!("{k}/3"), "--out"]).arg(&p).output().unwrap();
        assert!(o.status.success());
        shards.push(p);
    }
    let merged = dir.path().join("merged.csv");
    let o = bin().args(["sweep-merge", "--spec"]).arg(&spec).arg(&merged).args(&shards[..2]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("341 of its cases are in none of the inputs (the first: case 2)"), "{err}");
    assert!(!merged.exists());
    let o = bin().args(["sweep-merge", "--spec"]).arg(&spec).arg(&merged).args(&shards).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(masked(&merged), masked(&whole));
    // A journal is not a shard CSV.
    std::fs::write(partial(&merged), format!("{MARKER}\n{}", std::fs::read_to_string(&whole).unwrap())).unwrap();
    let o = bin().arg("sweep-merge").arg(dir.path().join("m2.csv")).arg(partial(&merged)).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--resume"), "{err}");
}
