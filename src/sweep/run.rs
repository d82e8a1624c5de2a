//! Running a sweep ([`Plan::run`]): the cases that share bodies and mesh are solved on one [`Model`] (built once per
//! run of at most [`super::plan::UNIT_CASES`] cases), the runs go in parallel, every solver run becomes a typed
//! [`SweepRow`], and each case's rows are appended to the journal the moment the case is done
//! ([`super::journal`]). When every case is done, the journal is written out sorted by (case, solver) as the sweep's
//! CSV and removed. [`merge`] joins shard CSVs the same way.
//!
//! What is in memory at any time: the plan (4 bytes per case to run), and per thread one model and one case; with
//! `timing_repeats`, the rows of at most [`TIMING_BATCH`] cases waiting for their repeats. Never the grid's rows.

use super::identity::{case_digest, mark};
use super::journal::{self, Block, Journal, Written};
use super::plan::{Plan, Start, SweepOptions};
use super::row::{set_timing, RowStatus, SweepRow};
use super::{invalid, Case, Shard, SweepSpec};
use crate::error::{Error, Result};
use crate::pipeline::space::SpaceModel;
use crate::pipeline::Model;
use crate::references::metrics;
use crate::results::{Report, SolverRun, Timing};
use crate::scene::{AnyScene, Scene, SpaceScene};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::collections::BTreeSet;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// A case is timed again (up to the spec's `timing_repeats`) only when its first run took less than this (seconds):
/// repeating small cases is cheap and is where the noise of a busy machine dominates.
pub const REPEAT_BELOW_S: f64 = 2.0;

/// With `timing_repeats`, the cases are timed in batches of this many: their first runs, then the repeats in rounds
/// over the batch, then their rows are written (a sweep of fewer cases is one batch).
pub const TIMING_BATCH: usize = 256;

/// The rows of a run of one 2D case, sorted by solver.
fn case_rows(case: &Case<AnyScene>, scene: &Scene, report: &Report) -> Vec<SweepRow> {
    let nodes = report.mesh.contact_nodes;
    let mut rows: Vec<SweepRow> = report.runs.iter().map(|r| run_row(case, scene, nodes, r)).collect();
    rows.sort_by(|a, b| a.solver.cmp(&b.solver));
    rows
}

/// The row of one solver run.
fn run_row(case: &Case<AnyScene>, scene: &Scene, contact_nodes: usize, r: &SolverRun) -> SweepRow {
    let mut row = SweepRow::new(case.index, r.solver.name(), RowStatus::Run(r.status));
    row.params = case.params.clone();
    row.scene = scene.name().to_string();
    row.element = Some(scene.element());
    row.contact_elements = Some(scene.zone().elements);
    row.contact_nodes = Some(contact_nodes);
    row.formulation = Some(r.formulation.name().to_string());
    row.problem_size = Some(r.problem_size);
    row.work = r.work.clone();
    row.residual = r.residuals.map(|x| x.max());
    row.normal_load = r.resultants.map(|x| x.normal);
    row.tangential_load = r.resultants.map(|x| x.tangential);
    row.half_width_fit = r.contact.as_ref().and_then(|c| c.fit_half_width);
    row.peak_pressure_fit = r.contact.as_ref().and_then(|c| c.fit_peak_pressure);
    row.metrics = metrics(scene, r);
    row.model = Some(scene.model());
    row.strip_width = scene.strip_width();
    row.radius = Some(scene.radius());
    row.contact_modulus = Some(scene.contact_modulus());
    row.friction = Some(scene.friction());
    // A bore at zero clearance has no Hertzian R* (infinite): no Hertz figures.
    let hertz = r
        .resultants
        .filter(|f| f.normal > 0.0 && scene.contact_radius().is_finite())
        .map(|f| crate::references::hertz_at(scene, f.normal));
    row.hertz_a = hertz.map(|h| h.a);
    row.hertz_p0 = hertz.map(|h| h.p0);
    row.shift = r.rigid_body.and_then(|b| b.tangential);
    row.approach = r.rigid_body.map(|b| b.normal);
    let edges = crate::post::stick_edges(r.answer_nodes()).filter(|_| scene.friction() > 0.0);
    row.stick_left = edges.map(|e| e.0);
    row.stick_right = edges.map(|e| e.1);
    row.creepage = r.rolling.as_ref().and_then(|x| x.creepage);
    row.bodies = super::two_body::figures(scene, r);
    set_timing(&mut row, &r.timing_s, None);
    // One line per row (the journal's rule): a line break in a message is written as a space.
    row.message = r.explanation().replace(['\n', '\r'], " ");
    row
}

/// Rows for a case that could not be built or run: one per solver its scene asks for (by name; `all` when it asks
/// for every solver), status `error`, the message last.
fn error_rows(case: &Case<AnyScene>, scene: &Scene, err: &Error) -> Vec<SweepRow> {
    let set = scene.solvers();
    let mut solvers: BTreeSet<String> = set.named.iter().map(|id| id.name().to_string()).collect();
    if set.all {
        solvers.insert("all".into());
    }
    let message = err.to_string().replace(['\n', '\r'], " ");
    solvers
        .into_iter()
        .map(|solver| {
            let mut row = SweepRow::new(case.index, &solver, RowStatus::Error);
            row.params = case.params.clone();
            row.scene = scene.name().to_string();
            row.element = Some(scene.element());
            row.contact_elements = Some(scene.zone().elements);
            row.message = message.clone();
            row
        })
        .collect()
}

/// The model a run of cases is solved on: built for the first case, kept while the next cases share its source and
/// needs ([`Model::shares_source`], [`Model::needs`]: a frictionless case is never solved on a model built with the
/// tangential blocks another case needed), built again for a case that does not.
///
/// With the spec's `warm_start`, each case starts from the previous case's solutions on the same model
/// ([`Model::solve_warm`]): a creep curve's next creepage from the last one's node states (see
/// [`super::SweepSpec::warm_start`] for what then depends on the order).
#[derive(Default)]
struct Shared {
    built: Option<Built>,
    warm: Option<crate::pipeline::Warm>,
    cancel: crate::cancel::Cancel,
}

/// The model of the last case, with the scene it was built for: the case runner's one seam between the kinds of
/// scene. A 2D model serves the next cases that share its source; a 3D model ([`SpaceModel`]: kernels, profile and
/// load path together) serves only a case of the same scene. (One per thread: its size does not matter.)
#[allow(clippy::large_enum_variant)]
enum Built {
    Plane(Scene, Result<Model>),
    Space(SpaceScene, Result<SpaceModel>),
}

impl Shared {
    /// The rows of a case, sorted by solver.
    fn rows(&mut self, case: &Case<AnyScene>) -> Result<Vec<SweepRow>> {
        self.cancel.check()?;
        let mut rows = match &case.scene {
            AnyScene::Plane(s) => self.plane_rows(case, s)?,
            AnyScene::Space(s) => self.space_rows(case, s)?,
        };
        let digest = Some(case_digest(&case.scene));
        for r in &mut rows {
            r.scene_digest = digest;
        }
        Ok(rows)
    }

    fn plane_rows(&mut self, case: &Case<AnyScene>, s: &Scene) -> Result<Vec<SweepRow>> {
        let fits = |m: &Scene| Model::shares_source(m, s) && Model::needs(m) == Model::needs(s);
        if !matches!(&self.built, Some(Built::Plane(m, _)) if fits(m)) {
            self.built = Some(Built::Plane(s.clone(), Model::build(s)));
            if let Some(w) = self.warm.as_mut() {
                w.clear();
            }
        }
        let mut cold = crate::pipeline::Warm::default();
        let solved = match (&self.built, self.warm.as_mut()) {
            (Some(Built::Plane(_, Ok(m))), w) => {
                m.solve_with(s, w.unwrap_or(&mut cold), &self.cancel).map_err(|e| error_rows(case, s, &e))
            }
            (Some(Built::Plane(_, Err(e))), _) => Err(error_rows(case, s, e)),
            _ => return Err(Error::Cancelled),
        };
        // A case cancelled in its solve has no rows: the run stops (its journal keeps the finished cases).
        self.cancel.check()?;
        Ok(match solved {
            Ok(report) => case_rows(case, s, &report),
            Err(rows) => rows,
        })
    }

    fn space_rows(&mut self, case: &Case<AnyScene>, s: &SpaceScene) -> Result<Vec<SweepRow>> {
        if !matches!(&self.built, Some(Built::Space(m, _)) if m == s) {
            self.built = Some(Built::Space(s.clone(), SpaceModel::build(s)));
        }
        let solved = match &self.built {
            Some(Built::Space(_, Ok(m))) => m.solve(&self.cancel),
            Some(Built::Space(_, Err(e))) => return Ok(super::space::error_rows(case, s, e)),
            _ => return Err(Error::Cancelled),
        };
        self.cancel.check()?;
        Ok(match solved {
            Ok(report) => super::space::case_rows(case, s, &report),
            Err(e) => super::space::error_rows(case, s, &e),
        })
    }
}

/// The timings of a case run again from scratch (model built and solved), by solver; `None` when it failed.
fn rerun(scene: &AnyScene) -> Option<Vec<(String, Timing)>> {
    match scene {
        AnyScene::Plane(s) => {
            let again = crate::pipeline::run_scene(s).ok()?;
            Some(again.runs.iter().map(|r| (r.solver.name().to_string(), r.timing_s)).collect())
        }
        AnyScene::Space(s) => {
            let t = crate::pipeline::space::run_space_scene(s).ok()?.timing_s;
            let timing = Timing {
                assembly: t.build,
                solve: t.solve,
                total: t.total,
                setup: crate::results::Setup::Built,
                ..Timing::default()
            };
            Some(vec![(super::space::SOLVER.to_string(), timing)])
        }
    }
}

/// The counts of a finished sweep.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Outcome {
    /// Rows of the CSV.
    pub rows: usize,
    /// Of which with status `error` (a variant that could not run).
    pub errors: usize,
    /// Cases run now (the others were done before: `--resume`).
    pub ran: usize,
}

/// The journal, shared by the threads.
type Shelf = Mutex<Journal>;

fn append(journal: &Shelf, rows: &[SweepRow]) -> Result<()> {
    journal.lock().unwrap_or_else(std::sync::PoisonError::into_inner).append(rows)
}

impl Plan {
    /// Run the plan: every case to run is solved and its rows appended to the journal as it finishes; then the
    /// journal is written out as the sweep's CSV, sorted by (case, solver), and removed.
    ///
    /// Runs go in parallel with rayon, with an indicatif progress bar (hidden unless asked for and standard error
    /// is a terminal). A sweep that asks for repeated timings runs its cases one at a time, so that no case is timed
    /// while another competes for the cores (on 2 cores, parallel cases moved timings by tens of percent between
    /// report runs and reordered configurations on the Pareto front). Sets faer's global parallelism to sequential:
    /// the runs are the parallel unit.
    pub fn run(self) -> Result<Outcome> {
        let to_run = self.counts().to_run;
        if self.start == Start::Output {
            // Every case is in the finished output already (a resume from an output that lacks one is refused when
            // planned): leave it as it is.
            let mut n = Written::default();
            journal::scan(&self.out, 0, false, None, |_, rows| {
                n.rows += rows.len();
                n.errors += rows.iter().filter(|r| r.status == RowStatus::Error).count();
                Ok(())
            })?;
            return Ok(Outcome { rows: n.rows, errors: n.errors, ran: 0 });
        }
        let journal = match self.start {
            Start::Journal(keep) => Journal::reopen(&self.journal, &self.keys, keep)?,
            Start::Fresh | Start::Output => {
                Journal::create(&self.journal, &self.keys, self.kind, &self.identity.line())?
            }
        };
        faer::set_global_parallelism(faer::Par::Seq);
        // The runs go in parallel: their stage spinners would draw over each other and over the bar below.
        let _no_stages = crate::progress::suppress();
        let bar = self.progress_bar(to_run);
        let journal = Mutex::new(journal);
        if self.spec.timing_repeats > 1 {
            self.run_timed(&journal, &bar)?;
        } else {
            self.units.par_iter().try_for_each(|unit| {
                let mut model = Shared {
                    warm: self.spec.warm_start.then(Default::default),
                    cancel: self.options.cancel.clone(),
                    ..Default::default()
                };
                for &i in unit {
                    append(&journal, &model.rows(&self.expansion.any_case(i as usize)?)?)?;
                    bar.inc(1);
                }
                Ok::<(), Error>(())
            })?;
        }
        bar.finish_and_clear();
        journal.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner).finish()?;
        let written = self.write_out()?;
        Ok(Outcome { rows: written.rows, errors: written.errors, ran: to_run })
    }

    fn progress_bar(&self, len: usize) -> ProgressBar {
        let bar = if self.options.progress && std::io::stderr().is_terminal() {
            ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::stderr())
        } else {
            ProgressBar::hidden()
        };
        bar.set_style(
            ProgressStyle::with_template("{prefix} [{elapsed_precise}] {wide_bar} {pos}/{len} runs (eta {eta})")
                .expect("valid template"),
        );
        bar.set_prefix(match self.options.shard {
            Some(s) => format!("{} {s}", self.spec.name),
            None => self.spec.name.clone(),
        });
        bar
    }

    /// The finished journal, sorted, to the output; the journal removed.
    fn write_out(&self) -> Result<Written> {
        let mut blocks = Vec::with_capacity(self.counts().mine);
        let scanned = journal::scan(&self.journal, 0, true, None, |b, _| {
            blocks.push(b);
            Ok(())
        })?;
        blocks.sort_unstable_by_key(|b| b.case);
        let cases: Vec<u32> = blocks.iter().map(|b| b.case).collect();
        let expected = (0..self.counts().cases).filter(|&i| self.options.shard.is_none_or(|s| s.contains(i)));
        if scanned.cut || !cases.iter().map(|&c| c as usize).eq(expected) {
            return Err(invalid(
                &self.journal,
                "journal",
                "its cases are not the sweep's, each once: was it written by another process meanwhile? Run the \
                 sweep again with --resume",
            ));
        }
        let written = journal::write_sorted(std::slice::from_ref(&self.journal), blocks, &scanned.header, &self.out)?;
        std::fs::remove_file(&self.journal).map_err(|source| Error::Write { path: self.journal.clone(), source })?;
        Ok(written)
    }

    /// The cases one at a time, timed repeatedly ([`retime`]) in batches of [`TIMING_BATCH`].
    fn run_timed(&self, journal: &Shelf, bar: &ProgressBar) -> Result<()> {
        let mut model = Shared {
            warm: self.spec.warm_start.then(Default::default),
            cancel: self.options.cancel.clone(),
            ..Default::default()
        };
        let mut cases = self.units.iter().flatten().copied().peekable();
        while cases.peek().is_some() {
            let mut batch = Vec::with_capacity(TIMING_BATCH);
            for i in cases.by_ref().take(TIMING_BATCH) {
                batch.push((i, model.rows(&self.expansion.any_case(i as usize)?)?));
                bar.inc(1);
            }
            self.retime(&mut batch, bar)?;
            for (_, rows) in &batch {
                append(journal, rows)?;
            }
        }
        Ok(())
    }

    /// Time the fast cases of a batch (every run under [`REPEAT_BELOW_S`]) `timing_repeats` more times in rounds —
    /// every fast case once per round, in case order, each repeat from scratch (model built and solved) — and give
    /// each row the timing of its median repeat, with the fastest and slowest. Results (not times) are the first
    /// run's.
    ///
    /// The first run's times are left out: it runs cold (first touches of the allocator's pages, caches) and was
    /// measured 2–50× slower than the repeats on small cases (e.g. 1.2 ms against 0.11 ms for lemke on 50 half-plane
    /// elements). The repeats go in rounds rather than back to back so that a slow spell of the machine lands on one
    /// repeat of many cases instead of on every repeat of the few cases running during it: back to back, all of one
    /// sweep's active_set cases (a block of the grid) once came out 1.6× slower than in the next sweep while the
    /// lemke cases before them did not, and a Pareto front changed with it.
    fn retime(&self, batch: &mut [(u32, Vec<SweepRow>)], bar: &ProgressBar) -> Result<()> {
        let repeats = self.spec.timing_repeats;
        let fast = |rows: &[SweepRow]| {
            !rows.is_empty()
                && rows.iter().all(|r| r.status != RowStatus::Error && r.t_total.is_some_and(|t| t < REPEAT_BELOW_S))
        };
        let mut order: Vec<usize> = (0..batch.len()).filter(|&k| fast(&batch[k].1)).collect();
        order.sort_by_key(|&k| batch[k].0);
        bar.inc_length((repeats * order.len()) as u64);
        let mut times: Vec<Vec<Vec<Timing>>> = batch.iter().map(|(_, rows)| vec![Vec::new(); rows.len()]).collect();
        for _ in 0..repeats {
            for &k in &order {
                let again = rerun(&self.expansion.any_case(batch[k].0 as usize)?.scene);
                bar.inc(1);
                let Some(again) = again else { continue };
                for (solver, timing) in again {
                    if let Some(j) = batch[k].1.iter().position(|row| row.solver == solver) {
                        times[k][j].push(timing);
                    }
                }
            }
        }
        for ((_, rows), times) in batch.iter_mut().zip(times) {
            for (row, mut t) in rows.iter_mut().zip(times) {
                if t.is_empty() {
                    continue;
                }
                t.sort_by(|a, b| a.total.total_cmp(&b.total));
                set_timing(row, &t[t.len() / 2], Some((t[0].total, t[t.len() - 1].total, t.len())));
            }
        }
        Ok(())
    }
}

/// Run the cases of this shard (all cases without one) afresh and write the CSV: one row per (case, solver run),
/// sorted by case then solver name. Returns the number of rows written. The library's short way to
/// [`Plan::new`] then [`Plan::run`], without `--resume` and within the size limit.
///
/// The spec and the base scene must read, and every variant of every grid (not only this shard's) must parse and
/// validate as a scene: an unknown key, a value of the wrong type or out of range, an unknown solver stops the sweep
/// before anything runs ([`Error::Parse`] or [`Error::Invalid`], naming the case and its keys); so does a named
/// solver that cannot take a variant (validation refuses it). A valid variant that still cannot be built or run
/// (e.g. its BEM system singular, [`Error::Numerical`]) gets rows with status `error` and the reason in the
/// column `message` (which holds the solver's explanation for the runs that did run).
pub fn run_sweep(spec_path: &Path, shard: Option<Shard>, out_csv: &Path, progress: bool) -> Result<usize> {
    let options = SweepOptions { shard, progress, ..SweepOptions::default() };
    Ok(Plan::new(spec_path, out_csv, &options)?.run()?.rows)
}

/// Run the cases of this shard (all cases without one) and return the rows [`run_sweep`] writes, in its order, with
/// the swept keys (the CSV's columns after `case`): for a caller that wants typed rows rather than a file (the
/// Python binding). The sweep runs as [`Plan::run`] runs it (streamed case by case, memory bounded by the cases in
/// flight) into a private temporary folder, removed afterwards; the rows are then read back typed, so they are
/// exactly the CSV's. Errors as [`run_sweep`]'s; a grid above the size guard is refused as it is by the CLI.
pub fn sweep_rows(spec_path: &Path, shard: Option<Shard>, progress: bool) -> Result<(Vec<String>, Vec<SweepRow>)> {
    sweep_rows_with(spec_path, shard, progress, &crate::cancel::Cancel::never())
}

/// [`sweep_rows`], stopped by `cancel` ([`SweepOptions::cancel`]): [`Error::Cancelled`] and no rows.
pub fn sweep_rows_with(
    spec_path: &Path,
    shard: Option<Shard>,
    progress: bool,
    cancel: &crate::cancel::Cancel,
) -> Result<(Vec<String>, Vec<SweepRow>)> {
    sweep_table_with(spec_path, shard, progress, cancel).map(|(header, rows)| (header.keys, rows))
}

/// [`sweep_rows_with`] with the CSV's whole header ([`super::row::Header`]: its kind, 2D or 3D, and every column's
/// name in order) instead of the swept keys alone.
pub fn sweep_table_with(
    spec_path: &Path,
    shard: Option<Shard>,
    progress: bool,
    cancel: &crate::cancel::Cancel,
) -> Result<(super::row::Header, Vec<SweepRow>)> {
    static SEQ: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let seq = SEQ.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.subsec_nanos());
    let dir = std::env::temp_dir().join(format!("rollbem-sweep-{}-{seq}-{nanos}", std::process::id()));
    std::fs::create_dir(&dir).map_err(|source| Error::Write { path: dir.clone(), source })?;
    let out = dir.join("rows.csv");
    let options = SweepOptions { shard, progress, cancel: cancel.clone(), ..SweepOptions::default() };
    let result =
        Plan::new(spec_path, &out, &options).and_then(|plan| plan.run()).and_then(|_| SweepRow::read_csv(&out));
    // The folder is ours alone; failing to remove it loses nothing.
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// The number of rows with status `error` in a sweep CSV (0 when it cannot be read), read without keeping its rows.
pub fn error_rows_in(csv_path: &Path) -> usize {
    let mut n = 0;
    let read = journal::scan(csv_path, 0, false, None, |_, rows| {
        n += rows.iter().filter(|r| r.status == RowStatus::Error).count();
        Ok(())
    });
    read.map_or(0, |_| n)
}

/// Join shard CSVs (the same header required, else an error) into one CSV sorted by (case, solver) — identical to
/// the unsharded sweep's CSV except for the [`super::PROVENANCE_COLUMNS`]. A case present twice (the same shard given
/// twice) is an error, and so is a journal (a sweep that has not finished) or a file ending in a cut line. Returns
/// the number of rows written. Reads the files block by block: memory is 24 bytes per case, not the rows.
pub fn merge(inputs: &[PathBuf], out_csv: &Path) -> Result<usize> {
    merge_checked(inputs, out_csv, None)
}

/// [`merge`], and with `spec` (a sweep spec's path) check that the inputs hold every case of that sweep, each with
/// its parameters, and no other, and that every case's rows were computed for the case's scene as the spec and its
/// base scenes resolve it now (their `scene_digest`: a shard run before the base scene was edited is refused, never
/// mixed with one run after): nothing lost, nothing twice, nothing stale. Checking the digests validates every case
/// of the spec once, as a sweep does before it runs. Nothing is written when a check fails.
pub fn merge_checked(inputs: &[PathBuf], out_csv: &Path, spec: Option<&Path>) -> Result<usize> {
    let no_input = || invalid(out_csv, "inputs", "no shard CSV to merge");
    let Some(first) = inputs.first() else {
        return Err(no_input());
    };
    let expansion = match spec {
        Some(p) => Some(SweepSpec::from_file(p)?.expand(p, p)?),
        None => None,
    };
    let mut blocks: Vec<Block> = Vec::new();
    let mut head: Option<super::row::Header> = None;
    let mut marks = 0u64;
    for (f, path) in inputs.iter().enumerate() {
        let scanned = journal::scan(path, f as u32, false, head.as_ref().map(|h| h.names.as_slice()), |b, rows| {
            if let Some(e) = &expansion {
                marks = marks.wrapping_add(check_case(e, path, b, rows)?);
            }
            blocks.push(b);
            Ok(())
        })
        .map_err(|e| match e {
            Error::Invalid { field, .. } if field == "header" => invalid(
                path,
                "header",
                format!(
                    "its header differs from that of {}: the CSVs come from different sweeps (or versions)",
                    first.display()
                ),
            ),
            other => other,
        })?;
        if scanned.cut {
            return Err(invalid(path, "rows", "it ends in a cut line: a shard that did not finish?"));
        }
        head.get_or_insert(scanned.header);
    }
    blocks.sort_by_key(|b| (b.case, b.file, b.start));
    for w in blocks.windows(2) {
        if w[0].case == w[1].case {
            let (a, b) = (&inputs[w[0].file as usize], &inputs[w[1].file as usize]);
            let place = if a == b {
                format!("twice in {}", a.display())
            } else {
                format!("in {} and {}", a.display(), b.display())
            };
            return Err(invalid(b, "case", format!("case {} appears {place}: is a shard given twice?", w[0].case)));
        }
    }
    if let (Some(e), Some(spec)) = (&expansion, spec) {
        check_spec(e, spec, inputs, &blocks, marks)?;
    }
    // Every input's header was read, and there is at least one input.
    let Some(header) = head else { return Err(no_input()) };
    Ok(journal::write_sorted(inputs, blocks, &header, out_csv)?.rows)
}

/// The blocks of a merge hold every case of the spec (none missing), each computed for the case's scene as it is
/// now (`marks`, the sum of [`mark`] over the blocks, equals the spec's).
fn check_spec(e: &super::Expansion, spec: &Path, inputs: &[PathBuf], blocks: &[Block], marks: u64) -> Result<()> {
    let missing = missing_cases(e.len(), blocks);
    if let Some(first) = missing.first() {
        return Err(invalid(
            spec,
            "case",
            format!(
                "{} of its cases are in none of the inputs (the first: case {first}): a shard missing or not \
                 finished?",
                missing.len()
            ),
        ));
    }
    let mut now = 0u64;
    super::plan::each_case(
        e,
        |_, case| case_digest(&case.scene),
        |i, d| {
            now = now.wrapping_add(mark(i, d));
            Ok(())
        },
    )?;
    if now == marks {
        return Ok(());
    }
    // Which case, in which input (a second pass, on the error path only).
    let (mut n, mut first) = (0, None);
    for path in inputs {
        journal::scan(path, 0, false, None, |b, rows| {
            let case = b.case as usize;
            if rows[0].scene_digest != Some(case_digest(&e.any_case(case)?.scene)) {
                n += 1;
                first.get_or_insert_with(|| format!("case {case}, in {}", path.display()));
            }
            Ok(())
        })?;
    }
    Err(invalid(
        spec,
        "case",
        format!(
            "{n} of its cases were computed for other scenes than the spec's cases are now (the first: {}): their \
             base scene, swept values or solver settings changed since that shard ran; run it again",
            first.unwrap_or_else(|| "none found on a second reading: an input changed meanwhile?".into())
        ),
    ))
}

/// The cases below `n` that no block holds (blocks sorted by case).
fn missing_cases(n: usize, blocks: &[Block]) -> Vec<usize> {
    let mut present = blocks.iter().map(|b| b.case as usize).peekable();
    (0..n)
        .filter(|&i| {
            while present.next_if(|&c| c < i).is_some() {}
            present.peek() != Some(&i)
        })
        .collect()
}

/// A block of a merge's input belongs to the spec: its case is one of the spec's, with the case's parameters, and
/// its rows carry one scene digest; returns the case's [`mark`].
fn check_case(e: &super::Expansion, path: &Path, b: Block, rows: &[SweepRow]) -> Result<u64> {
    let bad = |why: String| invalid(path, "case", format!("case {}: {why}", b.case));
    e.check_rows(b.case as usize, rows).map_err(bad)?;
    match rows.first().and_then(|r| r.scene_digest) {
        Some(d) if rows.iter().all(|r| r.scene_digest == Some(d)) => Ok(mark(b.case as usize, d)),
        Some(_) => Err(bad("its rows carry different `scene_digest`s".into())),
        None => Err(bad(
            "its rows carry no `scene_digest` (an older rollbem wrote them): `--spec` cannot check that they were \
             computed for the spec's cases as they are now; run that shard again, or merge without --spec"
                .into(),
        )),
    }
}
