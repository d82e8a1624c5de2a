//! Streamed sweeps that are killed and resumed (issue 23): the real binary, SIGKILLed at random points of its run
//! and resumed with `--resume`, always ends with the CSV of an uninterrupted run (provenance columns masked), every
//! case once; a cut last line and a case cut short are redone; a journal or a finished output of other cases is
//! refused, naming what changed — the base scene's key, the spec's name, a swept value, the shard, the version
//! (issue 31); a finished output is not run again; `-` and FIFOs get the sorted CSV; the size guard;
//! `sweep-merge --spec`, which also refuses a shard computed before the base scene was edited.

#[path = "common/sweep_cli.rs"]
mod common;

use common::{bin, kill_at, masked, partial, write};
use rollbem::sweep::MARKER;
use std::path::{Path, PathBuf};
use std::process::Command;

/// 1024 cases on four small BEM meshes, two rows each (lemke, active_set), frictionless and frictional, and four
/// frictionless cases of clarabel alone (one row each): about a second on two cores.
fn spec(dir: &Path, name: &str) -> PathBuf {
    spec_on(dir, name, &format!("{}/reference/scenes/seed-fig6-constant.toml", env!("CARGO_MANIFEST_DIR")))
}

/// [`spec`] on another base scene.
fn spec_on(dir: &Path, name: &str, base: &str) -> PathBuf {
    let loads: Vec<String> = (0..51).map(|i| format!("{:.1}", 90.0 + 4.0 * i as f64)).collect();
    write(
        dir,
        &format!("{name}.toml"),
        &format!(
            r#"
name = "{name}"
base = '{base}'

[[grid]]
"mesh.contact_elements" = [12, 16, 20, 24]
"drive.normal_load" = [{}]
"contact.friction" = [0.0, 0.1, 0.2, 0.3, 0.4]
"solvers.use" = [["lemke", "active_set"]]

[[grid]]
"mesh.contact_elements" = [12, 16, 20, 24]
"contact.friction" = [0.0]
"solvers.use" = [["clarabel"]]
"#,
            loads.join(", ")
        ),
    )
}

/// The journal's first two lines (its marker and identity line, each with its line break), from a real run killed
/// as soon as its journal exists.
fn journal_head(spec: &Path, dir: &Path) -> String {
    let out = dir.join("head.csv");
    kill_at(bin().arg("sweep").arg(spec).arg("--out").arg(&out), &out, 1, 0);
    let text = std::fs::read_to_string(partial(&out)).unwrap();
    std::fs::remove_file(partial(&out)).unwrap();
    let lines: Vec<&str> = text.split_inclusive('\n').take(2).collect();
    assert!(lines[0].starts_with("# rollbem sweep journal") && lines[1].starts_with("# identity "), "{text}");
    lines.concat()
}

/// The column of `name` in a masked CSV.
fn col(csv: &(Vec<String>, Vec<Vec<String>>), name: &str) -> usize {
    csv.0.iter().position(|h| h == name).unwrap()
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
/// it to the end; the CSV must equal the uninterrupted run's, row for row, provenance columns masked.
#[test]
fn killed_and_resumed_sweeps_end_as_an_uninterrupted_one() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "trials");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let reference = masked(&whole);
    assert_eq!(reference.1.len(), 1020 * 2 + 4);
    let solver = col(&reference, "solver");
    let mut pairs: Vec<(&str, &str)> = reference.1.iter().map(|r| (r[0].as_str(), r[solver].as_str())).collect();
    pairs.dedup();
    assert_eq!(pairs.len(), reference.1.len(), "the reference has each (case, solver) once");
    // The journal of a complete run is as long as the CSV plus its first two lines.
    let full = std::fs::metadata(&whole).unwrap().len() + journal_head(&spec, dir.path()).len() as u64;
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
    let journal = format!("{}{kept}\n{}", journal_head(&spec, dir.path()), &lines[22][..lines[22].len() / 2]);
    std::fs::write(partial(&out), journal).unwrap();
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("10 already done") && err.contains("case 10 run again"), "{err}");
    assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("({} cases run now", 1024 - 10)));
    assert_eq!(masked(&out), masked(&whole));
}

/// What `--resume` refuses: a journal of other cases (a swept value changed) or of another shard, standard output.
#[test]
fn resume_refuses_what_is_not_this_sweeps() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "other");
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let text = std::fs::read_to_string(&whole).unwrap();
    let out = dir.path().join("out.csv");
    std::fs::write(partial(&out), format!("{}{text}", journal_head(&spec, dir.path()))).unwrap();
    // Another spec: a load changed (the spec's second load), named with its values.
    let changed = std::fs::read_to_string(&spec).unwrap().replace("[90.0, 94.0,", "[90.0, 95.0,");
    let other = write(dir.path(), "changed.toml", &changed);
    let o = bin().arg("sweep").arg(&other).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("`--resume`") && err.contains("grid 1's swept values changed: `drive.normal_load`"), "{err}");
    assert!(err.contains("[90.0,94.0,") && err.contains("[90.0,95.0,"), "{err}");
    assert!(!out.exists());
    // Another shard.
    let o = bin().arg("sweep").arg(&spec).args(["--shard", "2/3", "--out"]).arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("it was written for the whole sweep, this run is shard 2/3"), "{err}");
    // Standard output keeps no journal.
    let o = bin().arg("sweep").arg(&spec).args(["--out", "-", "--resume"]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("`--resume`") && o.stdout.is_empty(), "{err}");
}

/// Issue 31: a sweep killed mid-run whose base scene is then edited (ν 0.1 → 0.11, the spec's name and grid
/// unchanged) is refused on resume, naming the base scene, the key and both values, and nothing is written; so is
/// a renamed spec and a journal of another version. Put back as it was, the resume goes on and ends with the
/// uninterrupted run's CSV. Before the identity (c0f3874) the edited resume was accepted and mixed both materials.
#[test]
fn a_resume_after_the_base_scene_or_the_spec_changed_is_refused_naming_the_change() {
    let dir = tempfile::tempdir().unwrap();
    let seed = format!("{}/reference/scenes/seed-fig6-constant.toml", env!("CARGO_MANIFEST_DIR"));
    let original = std::fs::read_to_string(seed).unwrap();
    let base = write(dir.path(), "base.toml", &original);
    let spec = spec_on(dir.path(), "edited", base.to_str().unwrap());
    let whole = dir.path().join("whole.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&whole).status().unwrap().success());
    let out = dir.path().join("out.csv");
    let full = std::fs::metadata(&whole).unwrap().len();
    assert!(kill_at(bin().arg("sweep").arg(&spec).arg("--out").arg(&out), &out, full / 3, 0), "killed mid-run");
    let journal = std::fs::read(partial(&out)).unwrap();
    let resume = |spec: &Path| bin().arg("sweep").arg(spec).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let refused = |o: std::process::Output, what: &[&str]| {
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        assert_eq!(o.status.code(), Some(2), "{err}");
        for w in what {
            assert!(err.contains(w), "no {w:?} in: {err}");
        }
        assert!(!out.exists(), "nothing written");
        assert_eq!(std::fs::read(partial(&out)).unwrap(), journal, "the journal is left as it was");
    };
    // The base scene's ν.
    assert!(original.contains("poisson_ratio = 0.1\n"));
    std::fs::write(&base, original.replace("poisson_ratio = 0.1\n", "poisson_ratio = 0.11\n")).unwrap();
    let base_named = format!("the base scene {} changed: `wheel.poisson_ratio` 0.1 → 0.11", base.display());
    refused(resume(&spec), &["`--resume`", &base_named]);
    std::fs::write(&base, &original).unwrap();
    // The spec's name.
    let text = std::fs::read_to_string(&spec).unwrap();
    let renamed = write(dir.path(), "renamed.toml", &text.replace("name = \"edited\"", "name = \"renamed\""));
    refused(resume(&renamed), &["the spec's name was `edited`, it is `renamed` now"]);
    // Another version of rollbem wrote it.
    let version = format!("\"rollbem\":\"{}\"", env!("CARGO_PKG_VERSION"));
    let text = String::from_utf8(journal.clone()).unwrap();
    assert!(text.contains(&version), "the identity line records the version");
    std::fs::write(partial(&out), text.replacen(&version, "\"rollbem\":\"0.0.1\"", 1)).unwrap();
    let o = resume(&spec);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    let said = format!("it was written by rollbem 0.0.1, this is rollbem {}", env!("CARGO_PKG_VERSION"));
    assert!(err.contains(&said), "{err}");
    // The running digest over the resolved cases differs (what a change of rollbem's resolution without a new
    // version number would do; here written into the identity line).
    let resolved = text.find("\"resolved\":\"fnv1a64:").unwrap() + "\"resolved\":\"fnv1a64:".len();
    let mut other = text.clone();
    other.replace_range(resolved..resolved + 16, "0123456789abcdef");
    std::fs::write(partial(&out), &other).unwrap();
    let o = resume(&spec);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("its cases resolved to other scenes than they do now (digest fnv1a64:0123456789abcdef"),
        "{err}"
    );
    // A row of a case done whose digest is not its case's (rows written for another scene, identity line intact).
    let row = text.lines().nth(3).unwrap();
    let digest = &row[row.find("fnv1a64:").unwrap()..][..24];
    std::fs::write(partial(&out), text.replace(digest, "fnv1a64:0123456789abcdef")).unwrap();
    let o = resume(&spec);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cases were computed for other scenes than the spec's cases are now"), "{err}");
    std::fs::write(partial(&out), &journal).unwrap();
    // Unchanged: the resume goes on, and ends as the uninterrupted run.
    let o = resume(&spec);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("already done"));
    assert_eq!(masked(&out), masked(&whole));
    // A finished output of the old ν is refused too (its rows carry their scenes' digests), and left alone.
    let finished = std::fs::read(&out).unwrap();
    std::fs::write(&base, original.replace("poisson_ratio = 0.1\n", "poisson_ratio = 0.11\n")).unwrap();
    let o = resume(&spec);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("1024 of its 1024 cases were computed for other scenes") && err.contains("case 0 ("), "{err}");
    assert_eq!(std::fs::read(&out).unwrap(), finished);
}

/// A finished output that lacks cases of the sweep (here: one case's rows removed) is refused on resume: a resume
/// never adds cases to a finished CSV.
#[test]
fn a_finished_output_missing_a_case_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec(dir.path(), "missing");
    let out = dir.path().join("out.csv");
    assert!(bin().arg("sweep").arg(&spec).arg("--out").arg(&out).status().unwrap().success());
    let text = std::fs::read_to_string(&out).unwrap();
    let kept: String = text.split_inclusive('\n').filter(|l| !l.starts_with("7,")).collect();
    std::fs::write(&out, &kept).unwrap();
    let o = bin().arg("sweep").arg(&spec).arg("--out").arg(&out).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("it holds 1023 of the 1024 cases of this sweep (the first missing: case 7)"), "{err}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), kept);
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

/// `sweep-merge --spec` refuses a shard computed before the base scene was edited (its rows' `scene_digest` are not
/// the cases' now), naming the case and the file; without `--spec` nothing can tell.
#[test]
fn merge_with_the_spec_refuses_a_shard_of_an_edited_base_scene() {
    let dir = tempfile::tempdir().unwrap();
    let seed = format!("{}/reference/scenes/seed-fig6-constant.toml", env!("CARGO_MANIFEST_DIR"));
    let original = std::fs::read_to_string(seed).unwrap();
    let base = write(dir.path(), "base.toml", &original);
    let spec = spec_on(dir.path(), "stale", base.to_str().unwrap());
    let shard = |k: usize| {
        let p = dir.path().join(format!("s{k}.csv"));
        let o = bin().arg("sweep").arg(&spec).args(["--shard", &format!("{k}/2"), "--out"]).arg(&p).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        p
    };
    let s1 = shard(1);
    std::fs::write(&base, original.replace("poisson_ratio = 0.1\n", "poisson_ratio = 0.11\n")).unwrap();
    let s2 = shard(2);
    let merged = dir.path().join("merged.csv");
    let o = bin().args(["sweep-merge", "--spec"]).arg(&spec).arg(&merged).arg(&s1).arg(&s2).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    let named = format!(
        "512 of its cases were computed for other scenes than the spec's cases are now (the first: case 0, in {})",
        s1.display()
    );
    assert!(err.contains(&named), "{err}");
    assert!(!merged.exists());
}
