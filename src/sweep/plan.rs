//! Before a sweep runs ([`Plan::new`]): the size guard, the cases already done (`--resume`), every grid point
//! validated, the cases to run grouped by the model they share, and an estimate of time and memory
//! ([`Plan::summary`]). Nothing is written until [`Plan::run`].
//!
//! **Bounded memory.** Every case's scene is built and validated in one streaming pass, in blocks of
//! [`SURVEY_BLOCK`] cases validated in parallel, digested ([`super::identity::scene_digest`], folded into running
//! digests as the pass goes) and dropped: what the plan keeps is 4 bytes per case to run (its number, in its model's
//! group) and a bit per case (done or not). A case's scene is built again when it runs.
//!
//! **Resume.** With `--resume`, the rows already written count: the journal's (`OUT.partial`, the rows of a run that
//! was stopped) or, without one, the output's (a finished sweep CSV). Nothing of another sweep is ever mixed in:
//! - a journal must carry this sweep's identity ([`super::identity`]): the same rollbem version, spec name, shard,
//!   `warm_start`, `timing_repeats`, grids and base scenes (every key). It is compared before a row is read, and a
//!   mismatch is refused naming what changed (a base scene's key with its old and new values, a swept key, the
//!   name, the shard, the version); once every case is validated, its running digest over the resolved cases must
//!   also be the sweep's now;
//! - every case of the file must belong to this sweep and shard, once, with the case's parameters and the digest of
//!   the case's resolved scene (`scene_digest`, summed over the cases done and compared with the spec's, so that a
//!   finished output, which has no identity line, is checked case by case too);
//! - a finished output must hold every case of the sweep (or shard): a resume never adds cases to it.
//!
//! A journal's last case is run again (its rows may be incomplete: [`super::journal`]), and a cut last line is
//! dropped.
//!
//! **Estimate.** From the sizes of each case's dense matrices: a model's build costs about
//! `k·N² + 2.5e-10·(2N)³` s and `24·(2N)²` bytes for a BEM wheel of N nodes (k = 2e-7 s for constant elements, 8e-7 s
//! for quadratic ones), `1.5e-7·n²` s and `32·n²` bytes for a half-plane of n strips; a solver run on m
//! complementarity unknowns about 0.5 ms plus `4e-10·m³` s (Lemke), `1e-7·m²` s (active set), `5e-9·m³` s (PGS) or
//! `2e-9·m³` s (the QP solvers), per substep, and `24·m²` bytes (`8·m²` for the active set). The constants were fitted
//! on this project's 2-core development machine (BEM meshes up to 2688 unknowns, half-planes up to 3200 strips). The
//! estimate is rough — on the six reference sweeps it came out between 0.6× and 2.5× the measured time and between
//! 0.6× and 1.0× the measured peak memory — and is meant to tell minutes from days and megabytes from the machine's
//! memory. A 3D case of N = MX·MY elements ([`super::space`]'s cost model): a build of `2e-8·k·N·log₂(4N)` s and
//! `64·k·N` bytes (k = 1 kernel frictionless, 6 with friction), per (sub)step `5e-7·N·log₂(4N)` s (`3e-6·…` with
//! friction) and 48 bytes per element kept; on the two 3D reference sweeps the estimate came out 2× (0.1 s against
//! 0.05 s, `hertz3d-convergence`) and 1.0× (0.9 s against 0.92 s, `cattaneo3d-load`) the measured time, and 1.2–1.6×
//! the peak memory. 3D cases share a model only with a case of the same scene (its kernels, profile and path are one
//! object).

use super::identity::{case_digest, mark, show_digest, Identity, Running};
use super::journal::{self, Block, Target};
use super::row::header_of;
use super::{invalid, Analysis, Expansion, Kind, Shard, SweepSpec, LARGE_SWEEP_CASES, REPEAT_BELOW_S};
use crate::error::Result;
use crate::pipeline::Model;
use crate::scene::{AnyScene, CounterBody, ElementKind, Loading, Scene};
use crate::solvers::SolverId;
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Cases validated together (in parallel) in the validation pass; only their model keys are kept.
pub const SURVEY_BLOCK: usize = 1024;

/// Most cases solved on one model: a larger group of cases sharing bodies and mesh is cut into runs of this many,
/// each with its own model, so that it spreads over the cores (the build is then repeated once per 256 cases).
pub const UNIT_CASES: usize = 256;

/// Memory of the process before any model: the binary, the allocator, the threads (measured: 8–10 MB).
const BASE_BYTES: f64 = 10e6;

/// How a sweep runs (the `sweep` command's flags).
#[derive(Debug, Clone, Default)]
pub struct SweepOptions {
    /// Run only this shard's cases.
    pub shard: Option<Shard>,
    /// Go on from the rows already written (the journal of a stopped run, or a finished output) instead of
    /// starting afresh.
    pub resume: bool,
    /// Run a grid of more than [`LARGE_SWEEP_CASES`] cases.
    pub allow_large: bool,
    /// Show a progress bar (only when standard error is a terminal).
    pub progress: bool,
    /// The caller's cancellation token: no case starts after it is raised, the cases in progress stop at their
    /// solvers' next iteration, and the run returns [`crate::Error::Cancelled`] (the journal keeps every case that
    /// finished: `--resume` goes on from there).
    pub cancel: crate::cancel::Cancel,
}

/// Where a run starts from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Start {
    /// A new journal.
    Fresh,
    /// The journal, kept up to this byte: its cases known complete.
    Journal(u64),
    /// A new journal holding the output's rows (a finished sweep CSV).
    Output,
}

/// The counts of a plan.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Counts {
    /// Cases of the whole sweep.
    pub cases: usize,
    /// Cases of this shard (all without one).
    pub mine: usize,
    /// Of those, already done (`--resume`).
    pub done: usize,
    /// Of those, to run now.
    pub to_run: usize,
    /// Models the cases to run are solved on.
    pub models: usize,
    /// The journal's last case, run again (`--resume` after a stop).
    pub redone: Option<usize>,
}

/// An estimate of a run's time and memory (see the module docs for the cost model).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[non_exhaustive]
pub struct Estimate {
    /// Seconds of work, summed over the model builds, solves and timing repeats.
    pub work_s: f64,
    /// Threads the run uses.
    pub threads: usize,
    /// The largest memory of one run in flight: a model and one case's problem (bytes).
    pub unit_bytes: f64,
    /// What the plan keeps (bytes): 4 per case to run, a bit per case.
    pub plan_bytes: f64,
}

impl Estimate {
    /// Wall-clock seconds.
    pub fn seconds(&self) -> f64 {
        self.work_s / self.threads.max(1) as f64
    }

    /// Peak resident memory (bytes).
    pub fn peak_bytes(&self) -> f64 {
        BASE_BYTES + self.threads.max(1) as f64 * self.unit_bytes + self.plan_bytes
    }
}

/// A sweep ready to run: checked, validated, grouped, estimated.
#[derive(Debug)]
#[non_exhaustive]
pub struct Plan {
    pub(crate) spec: SweepSpec,
    pub(crate) expansion: Expansion,
    pub(crate) keys: Vec<String>,
    /// The kind of the sweep's scenes (its CSV's columns).
    pub(crate) kind: Kind,
    pub(crate) options: SweepOptions,
    pub(crate) out: PathBuf,
    pub(crate) journal: PathBuf,
    pub(crate) start: Start,
    /// The cases to run, in runs sharing one model.
    pub(crate) units: Vec<Vec<u32>>,
    counts: Counts,
    estimate: Estimate,
    /// What the sweep's journal is written for.
    pub(crate) identity: Identity,
}

/// One bit per case.
#[derive(Debug, Clone)]
pub(crate) struct Bits(Vec<u64>);

impl Bits {
    fn new(n: usize) -> Bits {
        Bits(vec![0; n.div_ceil(64)])
    }
    fn get(&self, i: usize) -> bool {
        self.0[i / 64] >> (i % 64) & 1 == 1
    }
    fn set(&mut self, i: usize) {
        self.0[i / 64] |= 1 << (i % 64);
    }
}

/// The journal of an output: `OUT.partial` beside a file; for standard output or a FIFO, a file in the temporary
/// folder (such a run cannot be resumed).
fn journal_path(out: &Path, target: &Target, name: &str) -> PathBuf {
    match target {
        Target::File(_) => {
            let mut p = out.as_os_str().to_owned();
            p.push(".partial");
            PathBuf::from(p)
        }
        _ => std::env::temp_dir().join(format!("rollbem-sweep-{name}-{}.partial", std::process::id())),
    }
}

impl Plan {
    /// Plan a sweep of the spec at `spec_path` into `out` (see the module docs). Bad input — the spec, a grid point,
    /// a grid over the size limit without [`SweepOptions::allow_large`], `--resume` on an output that cannot be
    /// resumed or a file to resume from that is not this sweep's — is an error before anything is written; so is an
    /// output that cannot be written (a folder, a link to nothing).
    pub fn new(spec_path: &Path, out: &Path, options: &SweepOptions) -> Result<Plan> {
        let spec = SweepSpec::from_file(spec_path)?;
        let cases = spec.len();
        if cases > LARGE_SWEEP_CASES && !options.allow_large {
            return Err(invalid(
                spec_path,
                "grid",
                format!(
                    "{cases} cases, more than {LARGE_SWEEP_CASES}, the most a sweep runs without `--allow-large`: \
                     pass `--allow-large` to run it (`--dry-run --allow-large` prints its estimate of time and \
                     memory without running it), or split the grid"
                ),
            ));
        }
        // Per-case messages name the spec by its file name only: the CSV must not depend on where a shard ran.
        let label = PathBuf::from(spec_path.file_name().unwrap_or(spec_path.as_os_str()));
        let expansion = spec.expand(spec_path, &label)?;
        let kind = expansion.kind(0).unwrap_or_default();
        if kind == Kind::Space && spec.analysis != Analysis::Table {
            return Err(invalid(
                spec_path,
                "analysis",
                format!(
                    "`{}` is an analysis of 2D sweeps; a sweep of 3D half-space scenes is a table of rows (remove \
                     `analysis`, or give `table`)",
                    spec.analysis.name()
                ),
            ));
        }
        let keys = spec.keys();
        let target = Target::of(out)?;
        let journal = journal_path(out, &target, &spec.name);
        let shard = options.shard;
        let mine = |i: usize| shard.is_none_or(|s| s.contains(i));
        let mut identity = expansion.identity(&spec, shard);
        let mut done = Bits::new(cases);
        let mut counts = Counts { cases, mine: (0..cases).filter(|&i| mine(i)).count(), ..Counts::default() };
        let found = if !options.resume {
            None
        } else if !matches!(target, Target::File(_)) {
            return Err(invalid(
                out,
                "--resume",
                "a sweep written to standard output or a FIFO keeps no journal to resume: give a file (--out)",
            ));
        } else {
            let resumed =
                Resume { expansion: &expansion, keys: &keys, kind, shard, identity: &identity, done: &mut done };
            let found = resumed.read(&journal, out)?;
            counts.done = found.done;
            counts.redone = found.redone;
            Some(found)
        };
        let survey = survey(&expansion, kind, |i| mine(i) && !done.get(i), |i| done.get(i), spec.timing_repeats)?;
        identity.resolved = show_digest(survey.resolved);
        if let Some(found) = &found {
            let resume =
                Resume { expansion: &expansion, keys: &keys, kind, shard, identity: &identity, done: &mut done };
            resume.confirm(found, survey.done_marks, counts)?;
        }
        let start = found.map_or(Start::Fresh, |f| f.start);
        counts.to_run = survey.units.iter().map(Vec::len).sum();
        counts.models = survey.models;
        let serial = spec.timing_repeats > 1;
        let threads = if serial { 1 } else { rayon::current_num_threads().min(survey.units.len()).max(1) };
        let estimate = Estimate {
            work_s: survey.work_s,
            threads,
            unit_bytes: survey.unit_bytes,
            plan_bytes: 4.0 * counts.to_run as f64 + cases as f64 / 8.0,
        };
        Ok(Plan {
            spec,
            expansion,
            keys,
            kind,
            options: options.clone(),
            out: out.to_path_buf(),
            journal,
            start,
            units: survey.units,
            counts,
            estimate,
            identity,
        })
    }

    /// The counts: cases, this shard's, done, to run, models.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// The estimate of time and memory.
    pub fn estimate(&self) -> Estimate {
        self.estimate
    }

    /// Where the rows stream while the sweep runs.
    pub fn journal(&self) -> &Path {
        &self.journal
    }

    /// What the sweep will do, in a few lines: the cases, the shard, what is done already, the estimate.
    pub fn summary(&self) -> String {
        let c = &self.counts;
        let mut s = format!("sweep `{}`: {} cases", self.spec.name, c.cases);
        if let Some(k) = self.options.shard {
            s += &format!(", shard {k}: {} of them", c.mine);
        }
        if self.options.resume {
            let from = match self.start {
                Start::Output => self.out.display().to_string(),
                _ => self.journal.display().to_string(),
            };
            s += &format!("; {} already done (in {from})", c.done);
            if let Some(case) = c.redone {
                s += &format!(", case {case} run again (the last one written before the stop)");
            }
        }
        let e = &self.estimate;
        s += &format!(
            "\n{} to run on {} model{}: estimate {} on {} thread{}, peak memory {} (a rough cost model: README, \
             Sweeps)",
            c.to_run,
            c.models,
            if c.models == 1 { "" } else { "s" },
            duration(e.seconds()),
            e.threads,
            if e.threads == 1 { "" } else { "s" },
            bytes(e.peak_bytes()),
        );
        s
    }
}

/// `3.2 s`, `4.5 min`, `2.1 h`, `3.0 days`.
fn duration(s: f64) -> String {
    match s {
        s if s < 60.0 => format!("{s:.1} s"),
        s if s < 3600.0 => format!("{:.1} min", s / 60.0),
        s if s < 86400.0 => format!("{:.1} h", s / 3600.0),
        s => format!("{:.1} days", s / 86400.0),
    }
}

/// `23 MB`, `1.4 GB`.
fn bytes(b: f64) -> String {
    if b < 1e9 {
        format!("{:.0} MB", b / 1e6)
    } else {
        format!("{:.1} GB", b / 1e9)
    }
}

/// Reading the rows already written, for `--resume`.
struct Resume<'a> {
    expansion: &'a Expansion,
    keys: &'a [String],
    kind: Kind,
    shard: Option<Shard>,
    /// The sweep's identity as it is now (`resolved` set only once every case is validated).
    identity: &'a Identity,
    done: &'a mut Bits,
}

/// What `--resume` found.
#[derive(Debug)]
struct Found {
    start: Start,
    /// The file the rows were read from.
    from: PathBuf,
    /// Cases done.
    done: usize,
    /// The journal's last case, run again.
    redone: Option<usize>,
    /// The journal's identity (none for a finished output).
    written: Option<Identity>,
    /// The sum of [`mark`] over the cases done, from their rows' `scene_digest`.
    marks: u64,
}

/// `--resume` refused: `path` is not this sweep's, `why`.
fn refuse(path: &Path, why: impl std::fmt::Display) -> crate::error::Error {
    invalid(path, "--resume", format!("{why}: remove it, or run without --resume to start afresh"))
}

impl Resume<'_> {
    /// Mark the cases done by the journal (its last case excepted) or, without a journal, by the finished output.
    /// A journal must be of this sweep's identity (all but `resolved`, which [`Resume::confirm`] checks once every
    /// case is validated).
    fn read(self, journal: &Path, out: &Path) -> Result<Found> {
        let head = header_of(self.keys, self.kind);
        if journal.exists() {
            let line = journal::read_identity(journal)?.ok_or_else(|| {
                refuse(journal, "it has no identity line: an older rollbem wrote it, which did not record its cases")
            })?;
            let written = Identity::from_line(&line).map_err(|why| refuse(journal, why))?;
            let changed = written.differences(self.identity);
            if !changed.is_empty() {
                return Err(refuse(journal, format!("it was written for other cases: {}", changed.join("; "))));
            }
            let (mut last, mut n, mut marks): (Option<(Block, u64)>, usize, u64) = (None, 0, 0);
            let scanned = journal::scan(journal, 0, true, Some(head.as_slice()), |b, rows| {
                let digest = self.check(journal, b, rows, last.map(|l| l.0.case))?;
                if let Some((l, d)) = last.replace((b, digest)) {
                    self.done.set(l.case as usize);
                    marks = marks.wrapping_add(mark(l.case as usize, d));
                    n += 1;
                }
                Ok(())
            })?;
            let keep = last.map_or(scanned.rows_start, |l| l.0.start);
            let redone = last.map(|l| l.0.case as usize);
            let from = journal.to_path_buf();
            Ok(Found { start: Start::Journal(keep), from, done: n, redone, written: Some(written), marks })
        } else if out.exists() {
            let (mut n, mut marks) = (0, 0u64);
            let scanned = journal::scan(out, 0, false, Some(head.as_slice()), |b, rows| {
                let digest = self.check(out, b, rows, None)?;
                self.done.set(b.case as usize);
                marks = marks.wrapping_add(mark(b.case as usize, digest));
                n += 1;
                Ok(())
            })?;
            if scanned.cut {
                return Err(refuse(out, "it ends in a cut line: it is not a finished sweep CSV"));
            }
            Ok(Found { start: Start::Output, from: out.to_path_buf(), done: n, redone: None, written: None, marks })
        } else {
            Ok(Found { start: Start::Fresh, from: out.to_path_buf(), done: 0, redone: None, written: None, marks: 0 })
        }
    }

    /// A block of rows counts for its case only if the case is this sweep's and shard's, its parameters are the
    /// case's, the case has not been seen before (`pending`: the block before, not yet marked) and its rows carry
    /// one scene digest, returned.
    fn check(&self, path: &Path, b: Block, rows: &[super::SweepRow], pending: Option<u32>) -> Result<u64> {
        let case = b.case as usize;
        let refuse = |why: String| refuse(path, format!("case {case}: {why}: the file was written for other cases"));
        if self.shard.is_some_and(|s| !s.contains(case)) {
            return Err(refuse(format!("not a case of shard {}", self.shard.expect("checked"))));
        }
        if case < self.expansion.len() && (self.done.get(case) || pending == Some(b.case)) {
            return Err(refuse("its rows appear twice".into()));
        }
        self.expansion.check_rows(case, rows).map_err(refuse)?;
        match rows.first().and_then(|r| r.scene_digest) {
            Some(d) if rows.iter().all(|r| r.scene_digest == Some(d)) => Ok(d),
            _ => Err(refuse("its rows do not carry one `scene_digest`".into())),
        }
    }

    /// Once every case is validated: the rows kept were computed for the cases as they resolve now (`done_marks`,
    /// the sum of [`mark`] over the cases done, from the spec), a journal's cases resolve as they did when it was
    /// written, and a finished output holds every case of this sweep (a resume never adds cases to it).
    fn confirm(self, found: &Found, done_marks: u64, counts: Counts) -> Result<()> {
        if let Some(why) = found.written.as_ref().and_then(|w| w.resolved_differs(self.identity)) {
            return Err(refuse(&found.from, why));
        }
        if found.marks != done_marks {
            return Err(refuse(&found.from, self.changed_cases(found)?));
        }
        if found.start == Start::Output && counts.done < counts.mine {
            let first = (0..counts.cases)
                .find(|&i| self.shard.is_none_or(|s| s.contains(i)) && !self.done.get(i))
                .expect("a case not done");
            return Err(refuse(
                &found.from,
                format!(
                    "it holds {} of the {} cases of this sweep{} (the first missing: case {first}): the spec has \
                     cases it was not written for",
                    counts.done,
                    counts.mine,
                    self.shard.map(|s| format!("'s shard {s}")).unwrap_or_default()
                ),
            ));
        }
        Ok(())
    }

    /// Which of the file's cases were computed for other scenes than the spec's now, in words (a second pass over
    /// the file, on the error path only).
    fn changed_cases(&self, found: &Found) -> Result<String> {
        let journal = matches!(found.start, Start::Journal(_));
        let (mut n, mut total, mut first) = (0, 0, None);
        journal::scan(&found.from, 0, journal, None, |b, rows| {
            let case = b.case as usize;
            total += 1;
            let now = case_digest(&self.expansion.any_case(case)?.scene);
            if rows.first().and_then(|r| r.scene_digest) != Some(now) {
                n += 1;
                first.get_or_insert_with(|| super::describe(case, &self.expansion.params(case).unwrap_or_default()));
            }
            Ok(())
        })?;
        Ok(format!(
            "{n} of its {total} cases were computed for other scenes than the spec's cases are now (the first: {}): \
             their base scene, swept values or solver settings changed since",
            first.unwrap_or_else(|| "none found on a second reading: the file changed meanwhile?".into())
        ))
    }
}

/// The key of the model a scene is solved on: cases with equal keys share bodies, mesh, zone and counter-body
/// ([`Model::shares_source`]) and what they need of the model ([`Model::needs`]). (A run checks the sharing again
/// before solving on a model, so the key only decides which cases are tried together.)
fn model_key(scene: &AnyScene) -> String {
    match scene {
        AnyScene::Plane(s) => plane_model_key(s),
        // A 3D model is the case's scene whole (kernels, profile, path): shared only by cases of one scene.
        AnyScene::Space(_) => format!("space|{:016x}", case_digest(scene)),
    }
}

/// [`model_key`] of a 2D scene.
fn plane_model_key(scene: &Scene) -> String {
    format!(
        "{:?}|{:?}|{:?}|{:?}|{:?}",
        scene.wheel(),
        scene.body(),
        scene.zone(),
        scene.counter_body(),
        Model::needs(scene)
    )
}

/// The rough costs of a case (module docs): its model's build (seconds, bytes) and its solves (seconds, bytes).
#[derive(Debug, Clone, Copy, Default)]
struct Costs {
    build_s: f64,
    model_bytes: f64,
    solve_s: f64,
    solve_bytes: f64,
}

fn costs(scene: &AnyScene) -> Costs {
    match scene {
        AnyScene::Plane(s) => plane_costs(s),
        AnyScene::Space(s) => {
            let (build_s, model_bytes, solve_s, solve_bytes) = super::space::costs(s);
            Costs { build_s, model_bytes, solve_s, solve_bytes }
        }
    }
}

/// [`costs`] of a 2D scene.
fn plane_costs(scene: &Scene) -> Costs {
    let per_element = |e: ElementKind| if e == ElementKind::Quadratic { 3.0 } else { 1.0 };
    let strips = scene.zone().elements as f64;
    let half_plane = (1.5e-7 * strips * strips, 32.0 * strips * strips);
    let (mut build_s, mut model_bytes) = match scene.bem_wheel() {
        Some((_, element, other)) => {
            let nodes = (scene.zone().elements + other) as f64 * per_element(element);
            let k = if element == ElementKind::Quadratic { 8e-7 } else { 2e-7 };
            let n = 2.0 * nodes;
            (k * nodes * nodes + 2.5e-10 * n * n * n, 24.0 * n * n)
        }
        None => half_plane,
    };
    if matches!(scene.counter_body(), CounterBody::HalfPlane { .. }) {
        build_s += half_plane.0;
        model_bytes += half_plane.1;
    }
    // A second finite body (disc or bore): its own BEM system, of its contact zone and other elements (a bore's outer
    // circle and a disc's hub add about as many again: counted twice).
    if let Some((_, other)) = crate::source::two_body::counter_of(scene.counter_body()) {
        let nodes = (scene.zone().elements + 2 * other) as f64 * per_element(scene.element());
        let n = 2.0 * nodes;
        build_s += 8e-7 * nodes * nodes + 2.5e-10 * n * n * n;
        model_bytes += 24.0 * n * n;
    }
    let contact = strips * per_element(scene.element());
    let m = if Model::needs(scene).0 > crate::source::Blocks::Normal { 3.0 * contact + 2.0 } else { contact + 2.0 };
    let set = scene.solvers();
    let all = crate::solvers::registry().into_iter().filter(|e| set.all && e.in_all && !set.names(e.id)).map(|e| e.id);
    let substeps = match scene.loading() {
        Loading::Drive(_) => 1.0,
        Loading::Path(steps) => steps.iter().map(|s| s.substeps as f64).sum(),
    };
    let (mut solve_s, mut solve_bytes) = (0.0, 0.0f64);
    for id in set.named.iter().copied().chain(all) {
        let (s, b) = solver_cost(id, m);
        solve_s += substeps * (5e-4 + s);
        solve_bytes = solve_bytes.max(b);
    }
    Costs { build_s, model_bytes, solve_s, solve_bytes }
}

/// A solver's rough time (s) and memory (bytes) on m complementarity unknowns, beyond a fixed 0.5 ms a run
/// (module docs): its registry entry's cost model ([`crate::solvers::Entry::cost`]).
fn solver_cost(id: SolverId, m: f64) -> (f64, f64) {
    id.entry().map_or((0.0, 0.0), |e| (e.cost)(m))
}

/// The cases to run, in units sharing a model, the estimate's sums, and the digests of the cases.
struct Survey {
    units: Vec<Vec<u32>>,
    models: usize,
    work_s: f64,
    unit_bytes: f64,
    /// The running digest over every case's `scene_digest`, in case order ([`Identity::resolved`]).
    resolved: u64,
    /// The sum of [`mark`] over the cases done.
    done_marks: u64,
}

/// The cases of one model key, in enumeration order.
struct Group {
    cases: Vec<u32>,
    costs: Costs,
    solve_s: f64,
    solve_bytes: f64,
}

/// Build and validate every case's scene (all shards'), in blocks of [`SURVEY_BLOCK`] built in parallel, hand
/// `map` each case and give `fold` the results in case order; nothing is kept per case. The first case that does
/// not validate, in enumeration order, is the error.
pub(crate) fn each_case<T: Send>(
    expansion: &Expansion,
    map: impl Fn(usize, super::Case<AnyScene>) -> T + Sync,
    mut fold: impl FnMut(usize, T) -> Result<()>,
) -> Result<()> {
    let n = expansion.len();
    for start in (0..n).step_by(SURVEY_BLOCK) {
        let end = (start + SURVEY_BLOCK).min(n);
        let found: Vec<Result<T>> = (start..end).into_par_iter().map(|i| Ok(map(i, expansion.any_case(i)?))).collect();
        for (i, f) in (start..end).zip(found) {
            fold(i, f?)?;
        }
    }
    Ok(())
}

/// A sweep whose case `i` is of another kind than its first case: bad input naming `wheel.model`.
fn mixed(expansion: &Expansion, i: usize, first: Kind, other: Kind) -> crate::error::Error {
    let what = super::describe(i, &expansion.params(i).unwrap_or_default());
    invalid(
        &expansion.label,
        "wheel.model",
        format!(
            "{what} is of {}, case 0 of {}: a sweep's cases are all 2D or all 3D (`wheel.model = \"half_space\"`), \
             its CSV has the columns of one kind; split the sweep",
            other.describe(),
            first.describe()
        ),
    )
}

/// The validation pass: every case's scene built and validated ([`each_case`]) and digested, keeping only the
/// model key of the cases to run (`take`); the cases done (`done`) summed by [`mark`].
fn survey(
    expansion: &Expansion,
    kind: Kind,
    take: impl Fn(usize) -> bool + Sync,
    done: impl Fn(usize) -> bool,
    repeats: usize,
) -> Result<Survey> {
    let mut index: HashMap<String, usize> = HashMap::new();
    let mut groups: Vec<Group> = Vec::new();
    let mut repeat_s = 0.0;
    let (mut resolved, mut done_marks) = (Running::default(), 0u64);
    let map = |i: usize, case: super::Case<AnyScene>| {
        let digest = case_digest(&case.scene);
        (digest, Kind::of(&case.scene), take(i).then(|| (model_key(&case.scene), costs(&case.scene))))
    };
    each_case(expansion, map, |i, (digest, k, kept)| {
        if k != kind {
            return Err(mixed(expansion, i, kind, k));
        }
        resolved.add(digest);
        if done(i) {
            done_marks = done_marks.wrapping_add(mark(i, digest));
        }
        let Some((key, c)) = kept else { return Ok(()) };
        let g = *index.entry(key).or_insert_with(|| {
            groups.push(Group { cases: Vec::new(), costs: c, solve_s: 0.0, solve_bytes: 0.0 });
            groups.len() - 1
        });
        let g = &mut groups[g];
        // A case number fits in 4 bytes: a spec has at most MAX_CASES < 2^32 cases.
        g.cases.push(i as u32);
        g.solve_s += c.solve_s;
        g.solve_bytes = g.solve_bytes.max(c.solve_bytes);
        if repeats > 1 && c.build_s + c.solve_s < REPEAT_BELOW_S {
            repeat_s += repeats as f64 * (c.build_s + c.solve_s);
        }
        Ok(())
    })?;
    let mut survey = Survey {
        units: Vec::new(),
        models: 0,
        work_s: repeat_s,
        unit_bytes: 0.0,
        resolved: resolved.digest(),
        done_marks,
    };
    for g in groups {
        let units = g.cases.chunks(UNIT_CASES).map(<[u32]>::to_vec).collect::<Vec<_>>();
        survey.models += units.len();
        survey.work_s += units.len() as f64 * g.costs.build_s + g.solve_s;
        survey.unit_bytes = survey.unit_bytes.max(g.costs.model_bytes + g.solve_bytes);
        survey.units.extend(units);
    }
    Ok(survey)
}
