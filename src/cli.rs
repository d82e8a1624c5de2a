//! The `rollbem` command line: it parses the arguments, calls the library and prints what the library renders.
//! Exit codes: [`crate::exit`]. Progress goes to stderr when it is a terminal, unless `--quiet`.
//!
//! It is a library module so that a program can run the whole command line with solvers of its own plugged in
//! ([`crate::solvers::register`], then [`main`]): `examples/cli_with_plugin.rs` does that.
//!
//! **Ctrl-C** during `run` or `check` raises a cancellation token ([`crate::cancel`]): the load path stops before its
//! next substep and the solver at its next iteration, nothing is written for the scene in progress, and the command
//! exits with code 130 (a second Ctrl-C quits at once). Other commands keep the default (a sweep's journal survives
//! any kill: `--resume`).

use crate::exit;
use crate::io::write_output;
use crate::pipeline::{Model, Warm};
use crate::results::space::SpaceReport;
use crate::results::{render, space_render, Report};
use crate::scene::{AnyScene, Scene, SpaceScene};
use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// `println!` that ignores a closed pipe (`rollbem check ... | head` must not panic).
macro_rules! say {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($t)*);
    }};
}

#[derive(Parser)]
#[command(
    name = "rollbem",
    version,
    about = "Wheel-on-flat contact by BEM and complementarity, checked against theory"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
    /// No progress on stderr (progress is shown only when stderr is a terminal anyway).
    #[arg(long, global = true)]
    quiet: bool,
}

#[derive(Subcommand)]
enum Cmd {
    /// Solve scenes with their solvers and print a table per scene; optionally write the JSON result documents.
    Run {
        /// Scene files (TOML).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Write the JSON result document here (one scene only; written only when the run completes; `-` writes it to
        /// standard output and the table to standard error).
        #[arg(long, conflicts_with = "out_dir")]
        json: Option<PathBuf>,
        /// Write one JSON document per scene into this folder, named after the scene (`NAME.json`).
        #[arg(long)]
        out_dir: Option<PathBuf>,
        /// Override the scenes' `[solvers] use` (repeatable): `all` or a registered solver (see `rollbem solvers`).
        #[arg(long = "solver", value_parser = parse_solver)]
        solvers: Vec<String>,
        /// Write the load path as CSV here (one scene with `[[steps]]` only): one row per substep and solver with
        /// resultants, rigid motion, stick zone, node counts, dissipated energy, residual and solve time (`-`:
        /// standard output).
        #[arg(long)]
        path_csv: Option<PathBuf>,
        /// Write the nodal table as CSV here (one scene only): one row per contact node and solver with x, y,
        /// pressure, shear, u_x, u_y, gap, slip, state and slip_velocity, and the run's status (a run that did not solve
        /// has no rows, except one judged contact_at_zone_edge or kinematics_out_of_range: its rows are the evidence;
        /// `-`: standard output).
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// List the registered solvers.
    Solvers,
    /// Run a sweep (a grid of scene variants × solvers) in parallel and write one CSV row per solver run. Before it
    /// starts it prints the number of cases and an estimate of time and memory; while it runs, each case's rows are
    /// appended to OUT.partial as the case finishes; at the end they are written to OUT sorted by case and solver.
    Sweep {
        /// Sweep specification (TOML; see reference/sweeps/).
        spec: PathBuf,
        /// Run only shard k of n (1-based), for a batch scheduler; join the shards with `sweep-merge`.
        #[arg(long)]
        shard: Option<crate::sweep::Shard>,
        /// Output CSV (default: next to the spec, SPEC.csv or SPEC.shard-K-of-N.csv; `-` for standard output).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Go on from the rows already written: those of a stopped run (OUT.partial; its last case is run again) or
        /// of the finished OUT (which must hold every case). Cases there are not run again; a file written for other
        /// cases (another base scene or key of it, swept values, spec name, shard or rollbem version) is refused,
        /// naming what changed. With neither file, the sweep starts afresh.
        #[arg(long)]
        resume: bool,
        /// Run a grid of more than 100 000 cases (refused without it).
        #[arg(long)]
        allow_large: bool,
        /// Validate every case, print the plan and its estimate, run nothing.
        #[arg(long)]
        dry_run: bool,
    },
    /// Join shard CSVs into the CSV of the whole sweep (rows sorted by case and solver).
    SweepMerge {
        /// Output CSV.
        out: PathBuf,
        /// Shard CSVs.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// The sweep spec: check that the inputs hold each of its cases exactly once, with its parameters, computed
        /// for its scene as the spec resolves it now.
        #[arg(long)]
        spec: Option<PathBuf>,
    },
    /// Regenerate reports/ from the reference scenes and sweeps: JSON runs, CSVs, SVG plots, README.md.
    Report {
        /// Folder with scenes/ and sweeps/.
        #[arg(long, default_value = "reference")]
        reference: PathBuf,
        /// Output folder.
        #[arg(long, default_value = "reports")]
        out: PathBuf,
    },
    /// LCP files in the plain format of Siconos numerics' LCP test collection.
    Lcp {
        #[command(subcommand)]
        cmd: LcpCmd,
    },
    /// Draw a result document's figures (written by `run --json`): per solver run the surface tractions and, with
    /// `[stresses]`, a contour map per stress quantity with its maximum marked (SVG).
    Plot {
        /// A result document (JSON, `run --json`), a load path's CSV (`run --path-csv`) or a sweep's CSV (`sweep`).
        result: PathBuf,
        /// Output folder (default: the input's folder).
        #[arg(long)]
        out: Option<PathBuf>,
        /// For a sweep's CSV: what the sweep is (its spec's `analysis`): creep_curve, accuracy,
        /// finite_vs_half_plane or finite_bodies.
        #[arg(long)]
        analysis: Option<String>,
        /// For a load path's CSV: the scene that wrote it, for the theory drawn beside it.
        #[arg(long)]
        scene: Option<PathBuf>,
    },
    /// One steady-rolling case of an elliptic contact by FASTSIM (Kalker's simplified theory), CONTACT's
    /// conventions: creepages of body 1 relative to body 2, forces on body 1, rolling along +x by default.
    Fastsim(crate::creeptable::FastsimArgs),
    /// Run every requested solver on each scene and check them against theory, against each other and against
    /// the scene's declared expectations; print a pass/fail table; exit 1 if any check fails.
    Check {
        /// Scene files (TOML).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Override the scenes' `[solvers] use` (repeatable).
        #[arg(long = "solver", value_parser = parse_solver)]
        solvers: Vec<String>,
    },
}

#[derive(Subcommand)]
enum LcpCmd {
    /// Write the LCP (w = M z + q) that Lemke solves for a scene.
    Export {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Output file (default: next to the scene file, with its extension replaced by `.lcp.dat`).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Solve an LCP file and print the outcome; optionally write z and w as JSON.
    Solve {
        /// LCP file (Siconos format).
        file: PathBuf,
        /// A registered solver that works on bare LCPs: `lemke` (block-revised engine) or `lemke_dense` (the
        /// reference engine).
        #[arg(long, default_value = "lemke")]
        solver: String,
        /// Write {status, pivots, z, w, residuals} here.
        #[arg(long)]
        json: Option<PathBuf>,
    },
}

fn lcp_cmd(cmd: LcpCmd) -> crate::Result<u8> {
    match cmd {
        LcpCmd::Export { scene, out } => {
            let s = Scene::from_file(&scene)?;
            let lcp = crate::pipeline::Model::build(&s)?.lcp(&s)?;
            let out = out.unwrap_or_else(|| scene.with_extension("lcp.dat"));
            crate::lcp_io::write(&lcp, &out)?;
            say!("LCP of size {} written to {}", lcp.size(), out.display());
            Ok(exit::SUCCESS)
        }
        LcpCmd::Solve { file, solver, json } => {
            let lcp = crate::lcp_io::read(&file)?;
            let run = crate::lcp_residual::solve_named(&lcp, &solver).map_err(|message| crate::Error::Invalid {
                path: file.clone(),
                field: "--solver".into(),
                message,
            })?;
            say!("{}", run.summary(lcp.size()).trim_end());
            if let Some(path) = json {
                write_output(&path, &(run.document(&solver) + "\n"))?;
            }
            Ok(if run.outcome.termination == crate::solvers::Termination::Solved {
                exit::SUCCESS
            } else {
                exit::NOT_SOLVED
            })
        }
    }
}

fn parse_solver(s: &str) -> Result<String, String> {
    if s == "all" || s == "half_space" || crate::solvers::SolverId::from_name(s).is_some() {
        Ok(s.to_string())
    } else {
        Err(format!(
            "unknown solver `{s}` (expected one of: all, {}; half_space for half-space scenes)",
            crate::solvers::names()
        ))
    }
}

/// Where `run` writes a scene's outputs (each by [`crate::io::write_output`], only when the run completes).
#[derive(Default)]
struct Outputs<'a> {
    json: Option<&'a Path>,
    path_csv: Option<&'a Path>,
    csv: Option<&'a Path>,
}

impl Outputs<'_> {
    /// Whether an output goes to standard output (`-`): the table then goes to standard error.
    fn to_stdout(&self) -> bool {
        [self.json, self.path_csv, self.csv].into_iter().flatten().any(crate::io::is_stdout)
    }
}

/// The cancellation token of `run` and `check`, raised by the first Ctrl-C ([`install_interrupt`]).
fn interrupt() -> &'static crate::cancel::Cancel {
    static TOKEN: std::sync::OnceLock<crate::cancel::Cancel> = std::sync::OnceLock::new();
    TOKEN.get_or_init(crate::cancel::Cancel::new)
}

/// Make the first Ctrl-C raise [`interrupt`] (the solve stops at its next iteration) and a second one exit at once
/// with code 130. If the handler cannot be installed, Ctrl-C keeps its default (the process ends at once).
fn install_interrupt() {
    let _ = ctrlc::set_handler(|| {
        if interrupt().is_cancelled() {
            std::process::exit(130);
        }
        interrupt().cancel();
        eprintln!("\ninterrupted: stopping at the next iteration (Ctrl-C again to quit at once)");
    });
}

/// Solve one scene and write its outputs.
fn run_one(scene: &Scene, out: &Outputs) -> crate::Result<Report> {
    let mut report = Model::build(scene)?.solve_with(scene, &mut Warm::default(), interrupt())?;
    if let Some(path) = out.json {
        // Large stress fields go to CSV files beside the document, written first: the document names them.
        if !crate::io::is_stdout(path) {
            for (file, text) in report.spill_stress_fields(path) {
                write_output(&file, &text)?;
            }
        }
        let text = serde_json::to_string_pretty(&report).expect("a report serialises");
        write_output(path, &(text + "\n"))?;
    }
    if let Some(path) = out.path_csv {
        write_output(path, &report.path_csv())?;
    }
    if let Some(path) = out.csv {
        write_output(path, &report.nodes_csv())?;
    }
    Ok(report)
}

/// Read and validate every scene of a command before any runs (with `--solver` overriding `[solvers] use`),
/// refusing unsafe or repeated names (they name the output files). A scene is 2D or 3D by its `[wheel] model`.
fn load_all(paths: &[PathBuf], solvers: &[String]) -> crate::Result<Vec<AnyScene>> {
    let mut scenes = Vec::with_capacity(paths.len());
    for p in paths {
        let s = match AnyScene::from_file(p)? {
            AnyScene::Plane(s) if !solvers.is_empty() => {
                AnyScene::Plane(s.edit(|d| d.solvers.use_ = solvers.to_vec())?)
            }
            AnyScene::Space(s) if !solvers.is_empty() => {
                AnyScene::Space(s.edit(|d| d.solvers.use_ = solvers.to_vec())?)
            }
            other => other,
        };
        scenes.push(s);
    }
    let names: Vec<&str> = scenes.iter().map(AnyScene::name).collect();
    crate::scene::unique_output_names(paths.iter().map(PathBuf::as_path).zip(names))?;
    Ok(scenes)
}

/// Solve one half-space scene and write its outputs (each only when the run completes).
fn run_space(scene: &SpaceScene, out: &Outputs) -> crate::Result<SpaceReport> {
    let report = crate::pipeline::SpaceModel::build(scene)?.solve(interrupt())?;
    if let Some(path) = out.json {
        let text = serde_json::to_string_pretty(&report).expect("a report serialises");
        write_output(path, &(text + "\n"))?;
    }
    if let Some(path) = out.path_csv {
        write_output(path, &report.steps_csv())?;
    }
    if let Some(path) = out.csv {
        write_output(path, &report.elements_csv())?;
    }
    Ok(report)
}

/// The exit code of a half-space report (as [`exit::of_report`]: a step not ending with the expected status is
/// [`exit::NOT_SOLVED`], then a failed check counts when `checks_count`).
fn space_exit(r: &SpaceReport, checks_count: bool) -> u8 {
    if r.unexpected_status() {
        exit::NOT_SOLVED
    } else if checks_count && !r.all_pass() {
        exit::CHECK_FAILED
    } else {
        exit::SUCCESS
    }
}

/// What one scene of `run` or `check` produced.
#[allow(clippy::large_enum_variant)] // one per scene, moved once
enum Ran {
    Plane(Report),
    Space(SpaceReport),
}

/// Solve a scene of either kind.
fn run_any(scene: &AnyScene, out: &Outputs) -> crate::Result<Ran> {
    match scene {
        AnyScene::Plane(s) => run_one(s, out).map(Ran::Plane),
        AnyScene::Space(s) => run_space(s, out).map(Ran::Space),
    }
}

/// `rollbem check`: one table of checks per scene, a closing count line; exit codes of [`crate::exit`].
fn check(paths: &[PathBuf], solvers: &[String]) -> ExitCode {
    let scenes = match load_all(paths, solvers) {
        Ok(s) => s,
        Err(e) => return fail(&e),
    };
    let (mut passed, mut failed, mut na) = (0usize, 0usize, 0usize);
    let mut code = exit::SUCCESS;
    for (p, s) in paths.iter().zip(&scenes) {
        match run_any(s, &Outputs::default()) {
            Ok(Ran::Plane(r)) => {
                say!("{}", render::check_summary(&r));
                let (bad, skipped) = render::check_counts(&r);
                passed += r.checks.len() - bad - skipped;
                failed += bad;
                na += skipped;
                code = code.max(exit::of_report(&r, true));
            }
            Ok(Ran::Space(r)) => {
                say!("{}", space_render::check_summary(&r));
                let (bad, skipped) = space_render::check_counts(&r);
                passed += r.checks.len() - bad - skipped;
                failed += bad;
                na += skipped;
                code = code.max(space_exit(&r, true));
            }
            Err(e) => {
                say!("FAIL {}: {e}", p.display());
                failed += 1;
                code = code.max(e.exit_code() as u8);
                if matches!(e, crate::Error::Cancelled) {
                    break;
                }
            }
        }
    }
    say!("checks: {passed} passed, {failed} failed, {na} not applicable");
    ExitCode::from(code)
}

/// `rollbem run`: validate every scene (and the options that take one scene) before running any, then run and print
/// each; exit codes of [`crate::exit`].
fn run(
    paths: &[PathBuf],
    json: Option<PathBuf>,
    out_dir: Option<PathBuf>,
    solvers: &[String],
    csvs: [Option<PathBuf>; 2],
) -> ExitCode {
    let [path_csv, csv] = csvs;
    for (flag, given) in [("--json", json.is_some()), ("--path-csv", path_csv.is_some()), ("--csv", csv.is_some())] {
        if given && paths.len() > 1 {
            eprintln!("error: {flag} takes one scene; use --out-dir for the JSON of several");
            return ExitCode::from(exit::BAD_INPUT);
        }
    }
    let to_stdout = [&json, &path_csv, &csv].into_iter().flatten().filter(|p| crate::io::is_stdout(p)).count();
    if to_stdout > 1 {
        eprintln!("error: only one output can go to standard output (`-`)");
        return ExitCode::from(exit::BAD_INPUT);
    }
    let scenes = match load_all(paths, solvers) {
        Ok(l) => l,
        Err(e) => return fail(&e),
    };
    let no_path = |s: &AnyScene| match s {
        AnyScene::Plane(s) => s.steps().is_empty(),
        AnyScene::Space(s) => !s.is_path(),
    };
    if let (Some(_), Some((p, _))) = (&path_csv, paths.iter().zip(&scenes).find(|(_, s)| no_path(s))) {
        eprintln!("error: --path-csv: scene {} has no load path (`[[steps]]`)", p.display());
        return ExitCode::from(exit::BAD_INPUT);
    }
    if let Some(dir) = &out_dir {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("error: cannot create {}: {e}", dir.display());
            return ExitCode::from(exit::OUTPUT);
        }
    }
    let mut code = exit::SUCCESS;
    for (i, s) in scenes.iter().enumerate() {
        let target = json.clone().or_else(|| out_dir.as_ref().map(|d| d.join(format!("{}.json", s.name()))));
        let out = Outputs { json: target.as_deref(), path_csv: path_csv.as_deref(), csv: csv.as_deref() };
        match run_any(s, &out) {
            Ok(ran) => {
                let (table, c) = match &ran {
                    Ran::Plane(r) => (render::run_table(r), exit::of_report(r, exit::declares_checks(r))),
                    Ran::Space(r) => (space_render::run_table(r), space_exit(r, r.scene.checks.is_some())),
                };
                if out.to_stdout() {
                    eprint!("{}{table}", if i > 0 { "\n" } else { "" });
                } else {
                    say!("{}{}", if i > 0 { "\n" } else { "" }, table.trim_end());
                }
                code = code.max(c);
            }
            Err(e) => {
                eprintln!("error: {e}");
                code = code.max(e.exit_code() as u8);
                if matches!(e, crate::Error::Cancelled) {
                    break;
                }
            }
        }
    }
    ExitCode::from(code)
}

/// `rollbem sweep`: plan (size guard, validation, resume), print the plan, run it unless `dry_run`. Messages go to
/// standard error when the CSV goes to standard output.
fn sweep(spec: &Path, out: &Path, options: &crate::sweep::SweepOptions, dry_run: bool) -> ExitCode {
    let plan = match crate::sweep::Plan::new(spec, out, options) {
        Ok(p) => p,
        Err(e) => return fail(&e),
    };
    eprintln!("{}", plan.summary());
    if dry_run {
        return ExitCode::SUCCESS;
    }
    match plan.run() {
        Ok(o) => {
            let peak = peak_memory().map(|kb| format!("; peak memory {:.1} MB", kb as f64 / 1e3)).unwrap_or_default();
            let line = format!("{} rows written to {} ({} cases run now{peak})", o.rows, out.display(), o.ran);
            if crate::io::is_stdout(out) {
                eprintln!("{line}");
            } else {
                say!("{line}");
            }
            if o.errors > 0 {
                eprintln!(
                    "warning: {} of the {} rows have status `error` (a variant that could not be built or run): \
                     see their `message` column",
                    o.errors, o.rows
                );
            }
            ExitCode::SUCCESS
        }
        Err(e) => fail(&e),
    }
}

/// Whether `sweep-merge` joins creep tables: its spec is one, or (without a spec) its first input is one.
fn is_creep_merge(spec: Option<&Path>, inputs: &[PathBuf]) -> bool {
    match spec {
        Some(s) => crate::creeptable::is_table_spec(s),
        None => inputs.first().is_some_and(|p| crate::creeptable::is_table_csv(p)),
    }
}

/// `rollbem sweep` of a creep-table spec: run it (or its shard), print what was done.
fn creep_table(spec: &Path, out: &Path, options: &crate::creeptable::TableOptions) -> ExitCode {
    match crate::creeptable::run_table(spec, out, options) {
        Ok(o) => {
            let [solved, sliding, not_converged, refused] = o.statuses;
            let npz = o.npz.map(|p| format!(" and {}", p.display())).unwrap_or_default();
            let line = if options.dry_run {
                format!("creep table: {} cases, {} in this run (dry run: nothing run)", o.total, o.cases)
            } else {
                format!(
                    "creep table: {} of {} cases written to {}{npz} ({} run now, {} resumed; {solved} solved, \
                     {sliding} gross sliding, {not_converged} not converged, {refused} refused)",
                    o.cases,
                    o.total,
                    out.display(),
                    o.ran,
                    o.resumed
                )
            };
            eprintln!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => fail(&e),
    }
}

/// `rollbem plot`: a result document, or a CSV table (with its analysis or its scene).
fn plot(
    input: &Path,
    out: Option<&Path>,
    analysis: Option<String>,
    scene: Option<PathBuf>,
) -> crate::Result<crate::report::Plotted> {
    if crate::creeptable::is_table_csv(input) {
        let dir = input.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        return crate::creeptable::plot_table(input, out.unwrap_or(dir))
            .map(|files| crate::report::Plotted { files, skipped: Vec::new() });
    }
    if input.extension().is_some_and(|e| e == "csv") {
        let analysis = analysis.map(|a| crate::sweep::Analysis::from_name(&a, input)).transpose()?;
        let scene = scene.map(|p| Scene::from_file(&p)).transpose()?;
        let dir = input.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        return crate::report::plot_csv(input, out.unwrap_or(dir), analysis, scene.as_ref());
    }
    if let Ok(text) = std::fs::read_to_string(input) {
        if serde_json::from_str::<serde_json::Value>(&text).is_ok_and(|v| crate::results::space::is_space_value(&v)) {
            let report = SpaceReport::from_json(&text, input)?;
            let dir = input.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
            let files = crate::plot::space::plot_space(&report, out.unwrap_or(dir))?;
            return Ok(crate::report::Plotted { files, skipped: Vec::new() });
        }
    }
    crate::report::plot_result(input, out)
}

/// The process's peak resident memory in kB (`VmHWM` of /proc/self/status; `None` where there is none): a sweep
/// says it beside its estimate.
fn peak_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// Print an error and turn it into the process exit code.
fn fail(e: &crate::Error) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(e.exit_code() as u8)
}

/// The `rollbem` command line on this process's arguments (what the `rollbem` binary runs).
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    crate::progress::enable(!cli.quiet);
    match cli.cmd {
        Cmd::Check { scenes, solvers } => {
            install_interrupt();
            check(&scenes, &solvers)
        }
        Cmd::Plot { result, out, analysis, scene } => match plot(&result, out.as_deref(), analysis, scene) {
            Ok(done) => {
                for f in &done.files {
                    say!("wrote {}", f.display());
                }
                for s in &done.skipped {
                    say!("skipped {s}");
                }
                ExitCode::SUCCESS
            }
            Err(e) => fail(&e),
        },
        Cmd::Solvers => {
            for e in crate::solvers::registry() {
                say!("{:<12} {}{}", e.name(), e.summary, if e.in_all { "" } else { " (not in `all`)" });
            }
            ExitCode::SUCCESS
        }
        Cmd::Lcp { cmd } => match lcp_cmd(cmd) {
            Ok(code) => ExitCode::from(code),
            Err(e) => fail(&e),
        },
        Cmd::Sweep { spec, shard, out, resume, allow_large, dry_run } => {
            let out = out.unwrap_or_else(|| match &shard {
                Some(s) => spec.with_extension(format!("shard-{}-of-{}.csv", s.k, s.n)),
                None => spec.with_extension("csv"),
            });
            if crate::creeptable::is_table_spec(&spec) {
                let options = crate::creeptable::TableOptions { shard, resume, allow_large, dry_run };
                return creep_table(&spec, &out, &options);
            }
            let options = crate::sweep::SweepOptions {
                shard,
                resume,
                allow_large: allow_large || dry_run,
                progress: !cli.quiet,
                ..Default::default()
            };
            sweep(&spec, &out, &options, dry_run)
        }
        Cmd::SweepMerge { out, inputs, spec } if is_creep_merge(spec.as_deref(), &inputs) => {
            match crate::creeptable::merge_tables(&inputs, &out, spec.as_deref()) {
                Ok(rows) => {
                    say!("{rows} rows written to {}", out.display());
                    ExitCode::SUCCESS
                }
                Err(e) => fail(&e),
            }
        }
        Cmd::Fastsim(args) => match crate::creeptable::fastsim_command(&args) {
            Ok(text) => {
                let to_stdout = [&args.json, &args.csv].into_iter().flatten().any(|p| crate::io::is_stdout(p));
                if to_stdout {
                    eprint!("{text}");
                } else {
                    say!("{}", text.trim_end());
                }
                ExitCode::SUCCESS
            }
            Err(e) => fail(&e),
        },
        Cmd::SweepMerge { out, inputs, spec } => match crate::sweep::merge_checked(&inputs, &out, spec.as_deref()) {
            Ok(rows) => {
                let line = format!("{rows} rows written to {}", out.display());
                if crate::io::is_stdout(&out) {
                    eprintln!("{line}");
                } else {
                    say!("{line}");
                }
                ExitCode::SUCCESS
            }
            Err(e) => fail(&e),
        },
        Cmd::Report { reference, out } => {
            let opts = crate::report::ReportOptions { reference, out, progress: !cli.quiet };
            match crate::report::generate(&opts) {
                Ok(path) => {
                    say!("report written: {}", path.display());
                    ExitCode::SUCCESS
                }
                Err(e) => fail(&e),
            }
        }
        Cmd::Run { scenes, json, out_dir, solvers, path_csv, csv } => {
            install_interrupt();
            run(&scenes, json, out_dir, &solvers, [path_csv, csv])
        }
    }
}
