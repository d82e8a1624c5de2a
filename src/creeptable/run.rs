//! Running a creep table: all of it or one shard, in parallel, with a journal to resume from, and the merge of the
//! shards — the discipline of `rollbem sweep` (README "Sweeps at scale"), so the SLURM scripts of `scripts/slurm/`
//! run a creep-table spec as they run a sweep: `rollbem sweep SPEC --shard k/n --out F --resume` and
//! `rollbem sweep-merge --spec SPEC OUT SHARDS...` dispatch here when SPEC says `kind = "creep_table"`.
//!
//! * **Journal.** Rows are appended to `OUT.partial` as chunks of cases finish (whole lines, synced every few
//!   seconds); its first line records the rollbem version, the spec's name, the shard and a digest of the table
//!   ([`TableSpec::digest`]). At the end the rows are written to `OUT` sorted by case (and, for a whole table, the
//!   `.npz` beside it), then the journal is removed.
//! * **Resume** (`--resume`): from `OUT.partial` (a cut last line dropped, every complete row kept after checking its
//!   case belongs to this shard and carries the case's digest), or from a finished `OUT` holding every case of the
//!   shard (nothing runs). A journal written for another table, shard or version is refused naming what differs.
//! * **Shards**: `k/n` runs the cases with `index % n == k − 1`; the merge joins shard CSVs sorted by case, refuses a
//!   case held twice, and with the spec checks every case is there once with its coordinates and digest; it then
//!   writes the `.npz` too. A case's row does not depend on which process computed it, so a merged table equals the
//!   serial one byte for byte (`tests/creeptable.rs`, `tests/slurm.rs`).

use super::spec::TableSpec;
use super::table::{header_line, rows_of, CreepTable, TableRow};
use super::CreepEngine;
use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::sweep::Shard;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How to run a table.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TableOptions {
    /// Run only this shard.
    pub shard: Option<Shard>,
    /// Go on from the journal or a finished output.
    pub resume: bool,
    /// Run more than [`super::MAX_CASES`] cases.
    pub allow_large: bool,
    /// Validate and count, run nothing, write nothing.
    pub dry_run: bool,
}

/// What a run did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TableOutcome {
    /// Cases of the whole table.
    pub total: usize,
    /// Cases of this run's shard (all of them without one).
    pub cases: usize,
    /// Cases computed by this run.
    pub ran: usize,
    /// Cases taken from the journal or the finished output.
    pub resumed: usize,
    /// Cases per status: solved, gross_sliding, not_converged, refused (over the shard's rows written).
    pub statuses: [usize; 4],
    /// The `.npz` written (a whole table only).
    pub npz: Option<PathBuf>,
}

/// Whether a file is a creep-table spec (TOML with `kind = "creep_table"`); false for anything else, including a
/// file that cannot be read or parsed (the sweep's reader then reports it).
pub fn is_table_spec(path: &Path) -> bool {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|t| toml::from_str::<toml::Table>(&t).ok())
        .is_some_and(|d| super::spec::is_table_document(&d))
}

/// Whether a file starts with a creep table's header line.
pub fn is_table_csv(path: &Path) -> bool {
    let Ok(f) = std::fs::File::open(path) else { return false };
    let mut first = String::new();
    let _ = std::io::BufRead::read_line(&mut std::io::BufReader::new(f), &mut first);
    first == header_line()
}

fn invalid(path: &Path, field: &str, message: impl Into<String>) -> Error {
    Error::Invalid { path: path.to_path_buf(), field: field.to_string(), message: message.into() }
}

/// The journal's first line.
fn identity(spec: &TableSpec, shard: Option<Shard>, digest: &str) -> String {
    let shard = shard.map_or("whole".to_string(), |s| s.to_string());
    format!(
        "# rollbem creep-table journal; version={}; spec={}; shard={shard}; digest={digest}\n",
        env!("CARGO_PKG_VERSION"),
        spec.name
    )
}

/// The row of case `index`.
fn compute(spec: &TableSpec, engine: &dyn CreepEngine, settings: &str, index: usize) -> Result<TableRow> {
    let (case, norm) = spec.case(index)?;
    let answer = engine.forces(&case).map_err(|e| e.to_string());
    let digest = spec.case_digest(index, settings);
    let values = spec.axes.values(index);
    Ok(TableRow::new(index, values, engine.name(), case.a, case.b, case.creepages, &norm, answer, digest))
}

/// The rows of cases `cases` in parallel, in order.
fn compute_all(spec: &TableSpec, engine: &dyn CreepEngine, settings: &str, cases: &[usize]) -> Result<Vec<TableRow>> {
    cases.par_iter().map(|&i| compute(spec, engine, settings, i)).collect()
}

/// Computes the whole table of the spec at `spec_path` in memory (no file written; for the report): the table and its
/// engine's name. Errors: a bad spec (exit 2, naming the key), more than [`super::MAX_CASES`] cases.
pub fn compute_table(spec_path: &Path) -> Result<(CreepTable, String)> {
    compute_spec(&TableSpec::from_file(spec_path)?, spec_path)
}

/// Every ellipse of the spec has Kalker's coefficients (ν and a/b within Table E.3), or the refusal naming `axes`.
fn check_normalisations(spec: &TableSpec, spec_path: &Path) -> Result<()> {
    for inu in 0..spec.axes.nu.len() {
        for iab in 0..spec.axes.a_over_b.len() {
            spec.normalisation(inu, iab).map_err(|e| invalid(spec_path, "axes", e.to_string()))?;
        }
    }
    Ok(())
}

/// [`compute_table`] of a spec already read (`spec_path` names it in errors).
pub fn compute_spec(spec: &TableSpec, spec_path: &Path) -> Result<(CreepTable, String)> {
    let engine = spec.engine(spec_path)?;
    if spec.len() > super::MAX_CASES {
        let msg = format!("{} cases, more than {}", spec.len(), super::MAX_CASES);
        return Err(invalid(spec_path, "axes", msg));
    }
    check_normalisations(spec, spec_path)?;
    let cases: Vec<usize> = (0..spec.len()).collect();
    let rows = compute_all(spec, engine.as_ref(), &engine.settings(), &cases)?;
    let table = CreepTable::from_rows(&rows).map_err(|m| invalid(spec_path, "axes", m))?;
    Ok((table, engine.name().to_string()))
}

/// Checks that a kept row is case `row.case` of this table (its coordinates and digest) and in the shard.
fn check_row(
    spec: &TableSpec,
    settings: &str,
    shard: Option<Shard>,
    row: &TableRow,
) -> std::result::Result<(), String> {
    if row.case >= spec.len() || shard.is_some_and(|s| !s.contains(row.case)) {
        return Err(format!("case {} is not a case of this table or shard", row.case));
    }
    let values = spec.axes.values(row.case).map(f64::to_bits);
    if values != [row.nu, row.a_over_b, row.xi_n, row.eta_n, row.phi_n].map(f64::to_bits) {
        return Err(format!("case {}'s coordinates are not the spec's", row.case));
    }
    if row.case_digest != spec.case_digest(row.case, settings) {
        return Err(format!("case {} was computed for another engine, contact or grid (its case_digest)", row.case));
    }
    Ok(())
}

/// The journal's complete rows after checking its identity line; the byte length of its complete lines.
fn read_journal(
    journal: &Path,
    expected: &str,
    check: impl Fn(&TableRow) -> std::result::Result<(), String>,
) -> Result<(Vec<TableRow>, usize)> {
    let text = std::fs::read_to_string(journal).map_err(|source| Error::Io { path: journal.to_path_buf(), source })?;
    let complete = text.rfind('\n').map_or(0, |i| i + 1);
    let text = &text[..complete];
    let first = text.split_inclusive('\n').next().unwrap_or("");
    if first != expected {
        let msg = format!(
            "it was written for {:?}, this run is {:?}; remove it or run without --resume",
            first.trim(),
            expected.trim()
        );
        return Err(invalid(journal, "--resume", msg));
    }
    let rows = rows_of(&text[first.len()..], journal)?;
    for r in &rows {
        check(r).map_err(|m| invalid(journal, "--resume", m))?;
    }
    Ok((rows, complete))
}

/// Runs a creep table (module docs): the spec at `spec_path`, written to `out` (`-`: standard output, no journal,
/// no `.npz`). Errors: bad spec (exit 2, naming the key), a journal of another table, an output that cannot be
/// written (exit 3).
pub fn run_table(spec_path: &Path, out: &Path, opts: &TableOptions) -> Result<TableOutcome> {
    run_table_with(spec_path, out, opts, &Cancel::never())
}

/// [`run_table`], stopping before its next chunk of cases once `cancel` is raised ([`Error::Cancelled`]; the journal
/// keeps every case finished, for `--resume`). A bar of cases shows on stderr when `crate::progress` is on.
pub fn run_table_with(spec_path: &Path, out: &Path, opts: &TableOptions, cancel: &Cancel) -> Result<TableOutcome> {
    let spec = TableSpec::from_file(spec_path)?;
    let engine = spec.engine(spec_path)?;
    let settings = engine.settings();
    let total = spec.len();
    if total > super::MAX_CASES && !opts.allow_large && !opts.dry_run {
        let msg = format!("{total} cases, more than {} (pass --allow-large to run it)", super::MAX_CASES);
        return Err(invalid(spec_path, "axes", msg));
    }
    check_normalisations(&spec, spec_path)?;
    let cases: Vec<usize> = (0..total).filter(|&i| opts.shard.is_none_or(|s| s.contains(i))).collect();
    let mut outcome = TableOutcome { total, cases: cases.len(), ran: 0, resumed: 0, statuses: [0; 4], npz: None };
    if opts.dry_run {
        return Ok(outcome);
    }
    let whole = opts.shard.is_none_or(|s| s.n == 1);
    if crate::io::is_stdout(out) {
        let rows = compute_all(&spec, engine.as_ref(), &settings, &cases)?;
        outcome.ran = rows.len();
        return finish(out, rows, false, outcome);
    }
    let journal = PathBuf::from(format!("{}.partial", out.display()));
    let id = identity(&spec, opts.shard, &spec.digest(&settings));
    let check = |r: &TableRow| check_row(&spec, &settings, opts.shard, r);
    let mut kept = Vec::new();
    let mut file = if opts.resume && journal.exists() {
        let (rows, len) = read_journal(&journal, &id, check)?;
        kept = rows;
        let f = std::fs::OpenOptions::new().write(true).open(&journal);
        let f = f.and_then(|f| f.set_len(len as u64).map(|_| f));
        let mut f = f.map_err(|source| Error::Write { path: journal.clone(), source })?;
        std::io::Seek::seek(&mut f, std::io::SeekFrom::End(0))
            .map_err(|source| Error::Write { path: journal.clone(), source })?;
        f
    } else {
        if opts.resume && out.exists() {
            if let Some(done) = finished(out, &cases, check)? {
                outcome.resumed = done.len();
                return finish(out, done, whole, outcome);
            }
        }
        let mut f = std::fs::File::create(&journal).map_err(|source| Error::Write { path: journal.clone(), source })?;
        f.write_all((id + &header_line()).as_bytes())
            .map_err(|source| Error::Write { path: journal.clone(), source })?;
        f
    };
    let mut seen = vec![false; total];
    kept.iter().for_each(|r| seen[r.case] = true);
    let pending: Vec<usize> = cases.iter().copied().filter(|&i| !seen[i]).collect();
    outcome.resumed = kept.len();
    let mut last_sync = Instant::now();
    let bar = progress_bar(pending.len());
    for chunk in pending.chunks(256) {
        cancel.check()?;
        let rows = compute_all(&spec, engine.as_ref(), &settings, chunk)?;
        let text: String = rows.iter().map(TableRow::line).collect();
        file.write_all(text.as_bytes()).map_err(|source| Error::Write { path: journal.clone(), source })?;
        if last_sync.elapsed() > Duration::from_secs(3) {
            let _ = file.sync_data();
            last_sync = Instant::now();
        }
        outcome.ran += rows.len();
        bar.inc(rows.len() as u64);
        kept.extend(rows);
    }
    bar.finish_and_clear();
    drop(file);
    let outcome = finish(out, kept, whole, outcome)?;
    let _ = std::fs::remove_file(&journal);
    Ok(outcome)
}

/// A bar of `len` cases on stderr, or a hidden one when progress is off.
fn progress_bar(len: usize) -> ProgressBar {
    if !crate::progress::enabled() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template("creep table {bar:30} {pos}/{len} cases [{elapsed} < {eta}]") {
        bar.set_style(style);
    }
    bar
}

/// The rows of a finished output when it holds exactly `cases` (each checked), else `None` (run afresh).
fn finished(
    out: &Path,
    cases: &[usize],
    check: impl Fn(&TableRow) -> std::result::Result<(), String>,
) -> Result<Option<Vec<TableRow>>> {
    let rows = TableRow::read_csv(out)?;
    for r in &rows {
        check(r).map_err(|m| invalid(out, "--resume", m))?;
    }
    let held: Vec<usize> = rows.iter().map(|r| r.case).collect();
    Ok((held == cases).then_some(rows))
}

/// Sorts the rows, writes the `.npz` (a whole table) and the CSV.
fn finish(out: &Path, mut rows: Vec<TableRow>, whole: bool, mut outcome: TableOutcome) -> Result<TableOutcome> {
    rows.sort_by_key(|r| r.case);
    for r in &rows {
        outcome.statuses[r.status_code().clamp(0, 3) as usize] += 1;
    }
    if whole && !crate::io::is_stdout(out) {
        let table = CreepTable::from_rows(&rows)
            .map_err(|message| Error::Output { what: out.display().to_string(), message })?;
        let npz = out.with_extension("npz");
        table.write_npz(&npz)?;
        outcome.npz = Some(npz);
    }
    let text: String = std::iter::once(header_line()).chain(rows.iter().map(TableRow::line)).collect();
    crate::io::write_output(out, &text)?;
    Ok(outcome)
}

/// Joins shard CSVs into the whole table's CSV (sorted by case) and, with the spec, checks every case is there once
/// with its coordinates and digest and writes the `.npz` beside `out`. Returns the number of rows. Errors: a file
/// that cannot be read or is not a creep table, a case held twice, with the spec a missing or foreign case (exit 2);
/// nothing is written then.
pub fn merge_tables(inputs: &[PathBuf], out: &Path, spec_path: Option<&Path>) -> Result<usize> {
    let mut rows: Vec<(TableRow, usize)> = Vec::new();
    for (k, p) in inputs.iter().enumerate() {
        rows.extend(TableRow::read_csv(p)?.into_iter().map(|r| (r, k)));
    }
    rows.sort_by_key(|(r, _)| r.case);
    for w in rows.windows(2) {
        if w[0].0.case == w[1].0.case {
            let (a, b) = (inputs[w[0].1].display(), inputs[w[1].1].display());
            return Err(invalid(&inputs[w[1].1], "case", format!("case {} is in {a} and in {b}", w[0].0.case)));
        }
    }
    let rows: Vec<TableRow> = rows.into_iter().map(|(r, _)| r).collect();
    let n = rows.len();
    let Some(spec_path) = spec_path else {
        let text: String = std::iter::once(header_line()).chain(rows.iter().map(TableRow::line)).collect();
        crate::io::write_output(out, &text)?;
        return Ok(n);
    };
    let spec = TableSpec::from_file(spec_path)?;
    let settings = spec.engine(spec_path)?.settings();
    for (i, r) in rows.iter().enumerate() {
        if r.case != i {
            return Err(invalid(spec_path, "case", format!("case {i} of {} is in none of the shards", spec.len())));
        }
        check_row(&spec, &settings, None, r).map_err(|m| invalid(spec_path, "case", m))?;
    }
    if n != spec.len() {
        return Err(invalid(spec_path, "case", format!("case {n} of {} is in none of the shards", spec.len())));
    }
    let outcome = TableOutcome { total: n, cases: n, ran: 0, resumed: n, statuses: [0; 4], npz: None };
    finish(out, rows, true, outcome)?;
    Ok(n)
}
