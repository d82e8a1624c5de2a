//! Running a sweep: the cases that share bodies and mesh are solved on one [`Model`] (built once), groups run in
//! parallel, every solver run becomes a typed [`SweepRow`], and the CSV is written by [`SweepRow::record`] only.

use super::row::{header, RowStatus, SweepRow};
use super::{Shard, SweepSpec, Variant};
use crate::error::{Error, Result};
use crate::io::write_output;
use crate::pipeline::Model;
use crate::references::metrics;
use crate::results::{Report, SolverRun, Timing};
use crate::scene::Scene;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::collections::{BTreeSet, HashSet};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

/// A case is timed again (up to the spec's `timing_repeats`) only when its first run took less than this (seconds):
/// repeating small cases is cheap and is where the noise of a busy machine dominates.
pub const REPEAT_BELOW_S: f64 = 2.0;

/// The rows of a run of one case; `spread` is (fastest, slowest, repeats) of each solver run's total time when the
/// case was timed repeatedly.
fn case_rows(case: &Variant, scene: &Scene, report: &Report, spreads: &[Option<(f64, f64, usize)>]) -> Vec<SweepRow> {
    report
        .runs
        .iter()
        .enumerate()
        .map(|(i, r)| run_row(case, scene, report.mesh.contact_nodes, r, spreads.get(i).copied().flatten()))
        .collect()
}

/// The row of one solver run.
fn run_row(
    case: &Variant,
    scene: &Scene,
    contact_nodes: usize,
    r: &SolverRun,
    spread: Option<(f64, f64, usize)>,
) -> SweepRow {
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
    row.radius = Some(scene.radius());
    row.contact_modulus = Some(scene.contact_modulus());
    row.friction = Some(scene.friction());
    let hertz = r.resultants.filter(|f| f.normal > 0.0).map(|f| crate::references::hertz_at(scene, f.normal));
    row.hertz_a = hertz.map(|h| h.half_width);
    row.hertz_p0 = hertz.map(|h| h.peak_pressure);
    row.shift = r.rigid_body.and_then(|b| b.tangential);
    row.approach = r.rigid_body.map(|b| b.normal);
    let edges = crate::post::stick_edges(r.answer_nodes()).filter(|_| scene.friction() > 0.0);
    row.stick_left = edges.map(|e| e.0);
    row.stick_right = edges.map(|e| e.1);
    row.creepage = r.rolling.as_ref().and_then(|x| x.creepage);
    set_timing(&mut row, &r.timing_s, spread);
    row.message = r.explanation();
    row
}

fn set_timing(row: &mut SweepRow, t: &Timing, spread: Option<(f64, f64, usize)>) {
    row.t_assembly = Some(t.assembly);
    row.t_condensation = Some(t.condensation);
    row.t_formulation = Some(t.formulation);
    row.t_solve = Some(t.solve);
    row.t_total = Some(t.total);
    let (lo, hi, k) = spread.unwrap_or((t.total, t.total, 1));
    row.t_total_min = Some(lo);
    row.t_total_max = Some(hi);
    row.timing_runs = Some(k);
    row.setup = Some(t.setup);
}

/// Rows for a case that could not be built or run: one per solver its scene asks for (by name; `all` when it asks
/// for every solver), status `error`, the message last.
fn error_rows(case: &Variant, scene: &Scene, err: &Error) -> Vec<SweepRow> {
    let set = scene.solvers();
    let mut solvers: BTreeSet<String> = set.named.iter().map(|id| id.name().to_string()).collect();
    if set.all {
        solvers.insert("all".into());
    }
    let message = err.to_string().replace('\n', " ");
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

/// Cases that share one model: the same bodies, mesh, zone and counter-body, and the same needs of the model (the
/// tangential blocks, the BEM wheel's boundary response): a frictionless case is never solved on a model built
/// with the tangential blocks another case needed.
struct Group<'a> {
    cases: Vec<&'a Variant>,
}

/// Group the cases by the model they share, keeping the enumeration order within a group.
fn groups<'a>(cases: &[&'a Variant]) -> Vec<Group<'a>> {
    let mut out: Vec<Group<'a>> = Vec::new();
    for &v in cases {
        let s = v.scene();
        let fits = |g: &Group| {
            let first = g.cases[0].scene();
            Model::shares_source(first, s) && Model::needs(first) == Model::needs(s)
        };
        match out.iter_mut().find(|g| fits(g)) {
            Some(g) => g.cases.push(v),
            None => out.push(Group { cases: vec![v] }),
        }
    }
    out
}

/// Solve every case of a group on one model; the rows, and per case its report (for repeated timing).
fn run_group(group: &Group, bar: &ProgressBar) -> Vec<(usize, std::result::Result<Report, Vec<SweepRow>>)> {
    let model = Model::build(group.cases[0].scene());
    group
        .cases
        .iter()
        .map(|v| {
            let outcome = match &model {
                Ok(m) => m.solve(v.scene()).map_err(|e| error_rows(v, v.scene(), &e)),
                Err(e) => Err(error_rows(v, v.scene(), e)),
            };
            bar.inc(1);
            (v.index, outcome)
        })
        .collect()
}

/// The rows of every case, each group on its own model, groups in parallel (or one at a time when `serial`).
fn first_runs(
    cases: &[&Variant],
    serial: bool,
    bar: &ProgressBar,
) -> Vec<(usize, std::result::Result<Report, Vec<SweepRow>>)> {
    let gs = groups(cases);
    let mut out: Vec<(usize, std::result::Result<Report, Vec<SweepRow>>)> = if serial {
        gs.iter().flat_map(|g| run_group(g, bar)).collect()
    } else {
        gs.par_iter().flat_map_iter(|g| run_group(g, bar)).collect()
    };
    out.sort_by_key(|(i, _)| *i);
    out
}

/// Time the fast cases (first run under [`REPEAT_BELOW_S`]) `repeats` more times in rounds — every fast case once
/// per round, each repeat from scratch (model built and solved) — and give each solver run the timing of its
/// median repeat, with the fastest and slowest. Results (not times) are the first run's.
///
/// The first run's times are left out: it runs cold (first touches of the allocator's pages, caches) and was
/// measured 2–50× slower than the repeats on small cases (e.g. 1.2 ms against 0.11 ms for lemke on 50 half-plane
/// elements). The repeats go in rounds rather than back to back so that a slow spell of the machine lands on one
/// repeat of many cases instead of on every repeat of the few cases running during it: back to back, all of one
/// sweep's active_set cases (a block of the grid) once came out 1.6× slower than in the next sweep while the lemke
/// cases before them did not, and a Pareto front changed with it.
fn retime(
    cases: &[&Variant],
    firsts: &mut [(usize, std::result::Result<Report, Vec<SweepRow>>)],
    repeats: usize,
    bar: &ProgressBar,
) -> Vec<Vec<Option<(f64, f64, usize)>>> {
    let fast = |r: &Report| r.runs.iter().map(|x| x.timing_s.total).fold(0.0, f64::max) < REPEAT_BELOW_S;
    let mut times: Vec<Vec<Vec<Timing>>> =
        firsts.iter().map(|(_, f)| f.as_ref().map_or(Vec::new(), |r| vec![Vec::new(); r.runs.len()])).collect();
    let n_fast = firsts.iter().filter(|(_, f)| f.as_ref().is_ok_and(fast)).count();
    bar.inc_length((repeats * n_fast) as u64);
    for _ in 0..repeats {
        for ((case, (_, first)), t) in cases.iter().zip(firsts.iter()).zip(times.iter_mut()) {
            let Ok(report) = first else { continue };
            if !fast(report) {
                continue;
            }
            let again = crate::pipeline::run_scene(case.scene());
            bar.inc(1);
            let Ok(again) = again else { continue };
            for (ti, r) in t.iter_mut().zip(&again.runs) {
                ti.push(r.timing_s);
            }
        }
    }
    let mut spreads = Vec::with_capacity(firsts.len());
    for ((_, first), t) in firsts.iter_mut().zip(times) {
        let Ok(report) = first else {
            spreads.push(Vec::new());
            continue;
        };
        spreads.push(
            report
                .runs
                .iter_mut()
                .zip(t)
                .map(|(r, mut t)| {
                    if t.is_empty() {
                        return None;
                    }
                    t.sort_by(|a, b| a.total.total_cmp(&b.total));
                    r.timing_s = t[t.len() / 2];
                    Some((t[0].total, t[t.len() - 1].total, t.len()))
                })
                .collect(),
        );
    }
    spreads
}

/// Sort rows by (case, solver), the order of every sweep CSV.
fn sort_rows(rows: &mut [SweepRow]) {
    rows.sort_by(|a, b| (a.case, &a.solver).cmp(&(b.case, &b.solver)));
}

/// Write rows as a sweep CSV with the given swept keys.
fn write_csv(out_csv: &Path, keys: &[String], rows: &[SweepRow]) -> Result<()> {
    let werr = |e: csv::Error| Error::Write { path: out_csv.to_path_buf(), source: std::io::Error::other(e) };
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header(keys)).map_err(werr)?;
    for r in rows {
        w.write_record(r.record(keys)).map_err(werr)?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Write { path: out_csv.to_path_buf(), source: e.into_error() })?;
    let text = String::from_utf8(bytes).expect("CSV of UTF-8 cells is UTF-8");
    write_output(out_csv, &text)
}

/// Run the cases of this shard (all cases without one) and write the CSV: one row per (case, solver run), sorted by
/// case then solver name. Returns the number of rows written.
///
/// The spec and the base scene must read, and every variant of every grid (not only this shard's) must parse and
/// validate as a scene: an unknown key, a value of the wrong type or out of range, an unknown solver stops the sweep
/// before anything runs ([`Error::Parse`] or [`Error::Invalid`], naming the case and its keys). A valid variant
/// that cannot run (e.g. a named solver that does not apply to it, [`Error::Unsupported`]) gets rows with status
/// `error` and the message in the last column, `message` (which holds the solver's explanation for the runs that
/// did run); [`error_rows_in`] counts them for the caller.
///
/// Cases sharing bodies and mesh are solved on one model (one BEM assembly and condensation); groups run in
/// parallel with rayon, with an indicatif progress bar (hidden when `progress` is false or stderr is not a
/// terminal). A sweep that asks for repeated timings runs its groups one at a time, so that no case is timed while
/// another competes for the cores (on 2 cores, parallel cases moved timings by tens of percent between report runs
/// and reordered configurations on the Pareto front). Sets faer's global parallelism to sequential: the groups are
/// the parallel unit.
pub fn run_sweep(spec_path: &Path, shard: Option<Shard>, out_csv: &Path, progress: bool) -> Result<usize> {
    let spec = SweepSpec::from_file(spec_path)?;
    // Per-case messages name the spec by its file name only: the CSV must not depend on where a shard ran.
    let label = PathBuf::from(spec_path.file_name().unwrap_or(spec_path.as_os_str()));
    let variants = spec.variants(spec_path, &label)?;
    let mine: Vec<&Variant> = variants.iter().filter(|v| shard.is_none_or(|s| s.contains(v.index))).collect();
    let keys = spec.keys();

    faer::set_global_parallelism(faer::Par::Seq);
    // The groups run in parallel: their stage spinners would draw over each other and over the bar below.
    let _no_stages = crate::progress::suppress();
    let bar = if progress && std::io::stderr().is_terminal() {
        ProgressBar::with_draw_target(Some(mine.len() as u64), ProgressDrawTarget::stderr())
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template("{prefix} [{elapsed_precise}] {wide_bar} {pos}/{len} runs (eta {eta})")
            .expect("valid template"),
    );
    bar.set_prefix(match shard {
        Some(s) => format!("{} {s}", spec.name),
        None => spec.name.clone(),
    });
    let serial = spec.timing_repeats > 1;
    let mut firsts = first_runs(&mine, serial, &bar);
    let spreads = if serial { retime(&mine, &mut firsts, spec.timing_repeats, &bar) } else { Vec::new() };
    bar.finish_and_clear();
    let mut rows = Vec::new();
    for (k, (case, (_, first))) in mine.iter().zip(firsts).enumerate() {
        match first {
            Ok(report) => {
                rows.extend(case_rows(case, case.scene(), &report, spreads.get(k).map_or(&[], Vec::as_slice)))
            }
            Err(r) => rows.extend(r),
        }
    }
    sort_rows(&mut rows);
    write_csv(out_csv, &keys, &rows)?;
    Ok(rows.len())
}

/// The number of rows with status `error` in a sweep CSV written by [`run_sweep`] (0 when it cannot be read).
pub fn error_rows_in(csv_path: &Path) -> usize {
    SweepRow::read_csv(csv_path).map_or(0, |(_, rows)| rows.iter().filter(|r| r.status == RowStatus::Error).count())
}

/// Join shard CSVs (the same header required, else an error) into one CSV sorted by (case, solver) — identical to
/// the unsharded sweep's CSV except for the [`super::TIMING_COLUMNS`]. A (case, solver) pair present twice (the same
/// shard given twice) is an error. Returns the number of rows written.
pub fn merge(inputs: &[PathBuf], out_csv: &Path) -> Result<usize> {
    let Some(first) = inputs.first() else {
        return Err(super::invalid(out_csv, "inputs", "no shard CSV to merge"));
    };
    let mut header: Option<super::row::Header> = None;
    let mut rows: Vec<SweepRow> = Vec::new();
    let mut seen = HashSet::new();
    for path in inputs {
        let (h, these) = SweepRow::read_csv(path)?;
        match &header {
            None => header = Some(h),
            Some(h0) if h0.names != h.names => {
                return Err(super::invalid(
                    path,
                    "header",
                    format!(
                        "its header differs from that of {}: the CSVs come from different sweeps (or \
                         versions)\n  {}\n  {}",
                        first.display(),
                        h0.names.join(","),
                        h.names.join(",")
                    ),
                ))
            }
            Some(_) => {}
        }
        for r in these {
            if !seen.insert((r.case, r.solver.clone())) {
                return Err(super::invalid(
                    path,
                    "case",
                    format!("case {}, solver {} appears twice: is a shard given twice?", r.case, r.solver),
                ));
            }
            rows.push(r);
        }
    }
    sort_rows(&mut rows);
    let keys = header.map(|h| h.keys).unwrap_or_default();
    write_csv(out_csv, &keys, &rows)?;
    Ok(rows.len())
}
