//! The `rollbem` command line. Exit codes: 0 success, 1 a check failed (`check`: any check, including a status
//! other than the expected one, `solved` unless declared; `run`: a check of a scene that declares expectations in
//! `[checks]`; `lcp solve`: not solved), 2 bad input, 3 an output file could not be written, 4 numerical failure of
//! the BEM system. Progress goes to stderr when it is a terminal, unless `--quiet`.

use clap::{Parser, Subcommand};
use rollbem::io::write_atomic;
use rollbem::results::{Check, CheckKind, Report};
use rollbem::run::run_scene;
use rollbem::scene::Scene;
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
        /// Write the JSON result document here (one scene only; written only when the run completes).
        #[arg(long, conflicts_with = "out_dir")]
        json: Option<PathBuf>,
        /// Write one JSON document per scene into this folder, named after the scene (`NAME.json`).
        #[arg(long)]
        out_dir: Option<PathBuf>,
        /// Override the scenes' `[solvers] use` (repeatable): `all` or a registered solver (see `rollbem solvers`).
        #[arg(long = "solver", value_parser = parse_solver)]
        solvers: Vec<String>,
        /// Write the load path as CSV here (one scene with `[[steps]]` only): one row per substep and solver with
        /// resultants, rigid motion, stick zone, node counts, dissipated energy, residual and solve time.
        #[arg(long)]
        path_csv: Option<PathBuf>,
        /// Write the nodal table as CSV here (one scene only): one row per contact node and solver with x, y,
        /// pressure, shear, u_x, u_y, gap, slip, state and slip_velocity, and the run's status (a run that did not solve
        /// has no rows, except one judged contact_at_zone_edge or kinematics_out_of_range: its rows are the evidence).
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// List the registered solvers.
    Solvers,
    /// Run a sweep (a grid of scene variants × solvers) in parallel and write one CSV row per solver run.
    Sweep {
        /// Sweep specification (TOML; see reference/sweeps/).
        spec: PathBuf,
        /// Run only shard k of n (1-based), for a batch scheduler; join the shards with `sweep-merge`.
        #[arg(long)]
        shard: Option<rollbem::sweep::Shard>,
        /// Output CSV (default: next to the spec, SPEC.csv or SPEC.shard-K-of-N.csv).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Join shard CSVs into the CSV of the whole sweep (rows sorted by case and solver).
    SweepMerge {
        /// Output CSV.
        out: PathBuf,
        /// Shard CSVs.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
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
        /// Result document (JSON).
        result: PathBuf,
        /// Output folder (default: the result document's folder).
        #[arg(long)]
        out: Option<PathBuf>,
    },
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

fn lcp_cmd(cmd: LcpCmd) -> rollbem::Result<i32> {
    match cmd {
        LcpCmd::Export { scene, out } => {
            let s = Scene::from_file(&scene)?;
            let lcp = rollbem::run::scene_lcp(&s, &scene)?;
            let out = out.unwrap_or_else(|| scene.with_extension("lcp.dat"));
            rollbem::lcp_io::write(&lcp, &out)?;
            say!("LCP of size {} written to {}", lcp.size(), out.display());
            Ok(0)
        }
        LcpCmd::Solve { file, solver, json } => {
            let lcp = rollbem::lcp_io::read(&file)?;
            let lcp_solvers: Vec<&str> = rollbem::solvers::REGISTRY
                .iter()
                .filter(|e| (e.build)(None).is_ok_and(|s| s.solves_lcp()))
                .map(|e| e.name)
                .collect();
            let bad = || rollbem::Error::Invalid {
                path: file.clone(),
                field: "--solver".into(),
                message: format!("`{solver}` does not solve LCP files (expected one of: {})", lcp_solvers.join(", ")),
            };
            let built = rollbem::solvers::build(&solver, None).map_err(|_| bad())?;
            let run = rollbem::lcp_residual::solve_timed(&lcp, built.as_ref()).ok_or_else(bad)?;
            let (out, r) = (&run.outcome, &run.residuals);
            say!(
                "status {}  pivots {}  size {}  solve time {:.3e} s",
                out.status,
                out.pivots,
                lcp.size(),
                run.solve_time_s
            );
            say!(
                "residuals (relative to s = max(‖q‖∞, ‖M‖∞‖z‖∞) = {:.3e}): max(0, −w)/s {:.1e}, max(0, −z)/‖z‖∞ {:.1e}, \
                 max|w z|/(s ‖z‖∞) {:.1e}, max|w − (Mz + q)|/s {:.1e}; Siconos' lcp_compute_error {:.1e}",
                r.scale,
                r.negative_w,
                r.negative_z,
                r.complementarity,
                r.equation,
                r.siconos_error
            );
            say!("{}", out.message);
            if let Some(path) = json {
                let doc = serde_json::json!({
                    "solver": solver, "status": out.status, "pivots": out.pivots, "message": out.message,
                    "solve_time_s": run.solve_time_s, "z": out.z, "w": out.w, "residuals": r,
                });
                write_atomic(&path, &serde_json::to_string_pretty(&doc).expect("json"))?;
            }
            Ok(out.status.exit_code())
        }
    }
}

fn parse_solver(s: &str) -> Result<String, String> {
    if s == "all" || rollbem::solvers::entry(s).is_some() {
        Ok(s.to_string())
    } else {
        Err(format!("unknown solver `{s}` (expected one of: all, {})", rollbem::solvers::names()))
    }
}

/// The `run` table of one scene. Its two time columns: `solve [s]`, the solver alone (what the solvers are compared
/// by), and `total [s]`, the whole pipeline of that run (assembly, condensation, formulation and solve).
/// The memory line is printed from this peak resident size on (bytes): small runs need no memory figure.
const MEMORY_LINE_FROM: u64 = 100_000_000;

/// The process's peak resident set size (Linux `VmHWM` in `/proc/self/status`), `None` where it cannot be read.
fn peak_resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

fn print_report(r: &Report) {
    say!("scene {} — {}", r.scene.name, r.scene.description);
    say!(
        "mesh: {} {} elements, {} nodes, {} contact nodes{}; effects: {}",
        r.mesh.elements,
        r.mesh.element.name(),
        r.mesh.nodes,
        r.mesh.contact_nodes,
        r.mesh.system_size.map(|n| format!(", BEM system {n}×{n}")).unwrap_or_default(),
        r.effects.join(", ")
    );
    let d = &r.diagnostics;
    say!(
        "health: {}κ₁(K_NN) ≈ {:.2e}{}, flexibility asymmetry {:.2e}",
        d.bem_condition.map(|k| format!("κ₁(BEM system) ≈ {k:.2e}, ")).unwrap_or_default(),
        d.flexibility_condition,
        d.tangential_condition.map(|k| format!(", κ₁(K_TT) ≈ {k:.2e}")).unwrap_or_default(),
        d.flexibility_asymmetry
    );
    if let Some(bytes) = peak_resident_bytes().filter(|b| *b >= MEMORY_LINE_FROM) {
        say!(
            "memory: peak resident {:.2} GB (this process so far: the BEM system, its LU and the solvers' work)",
            bytes as f64 / 1e9
        );
    }
    for w in d.warnings.iter().cloned().chain(run_warnings(r)) {
        say!("WARNING: {w}");
    }
    if let Some(h) = &r.references.hertz {
        say!("Hertz at P = {:.6e}: a = {:.6e}, p0 = {:.6e}", h.load, h.half_width, h.peak_pressure);
    }
    let frictional = r.effects.iter().any(|e| e == "friction");
    say!(
        "{:<11} {:<23} {:>5} {:>9} {:>9} {:>12} {:>12} {:>12} {:>20} {:>12} {:>9} {:>9}",
        "solver",
        "status",
        "size",
        "work",
        "residual",
        "P",
        if frictional { "Q" } else { "a (fit)" },
        if frictional { "peak p" } else { "p0 (fit)" },
        if frictional { "stick zone" } else { "contact" },
        "d_N",
        "solve [s]",
        "total [s]"
    );
    let opt = |v: Option<f64>| v.map(|v| format!("{v:.5e}")).unwrap_or_else(|| "-".into());
    for run in &r.runs {
        let work = run.work.short();
        let (Some(res), Some(f), Some(c), Some(rb)) = (&run.residuals, &run.resultants, &run.contact, &run.rigid_body)
        else {
            say!(
                "{:<11} {:<23} {:>5} {:>9} {:>9} {:>12} {:>12} {:>12} {:>20} {:>12} {:>9.4} {:>9.4}",
                run.solver,
                run.status.name(),
                run.problem_size,
                work,
                "-",
                "-",
                "-",
                "-",
                "-",
                "-",
                run.timing_s.solve,
                run.timing_s.total
            );
            say!("            {}", run.message);
            continue;
        };
        let range = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => format!("[{a:.3e},{b:.3e}]"),
            _ => "none".into(),
        };
        say!(
            "{:<11} {:<23} {:>5} {:>9} {:>9.2e} {:>12.5e} {:>12} {:>12} {:>20} {:>12.5e} {:>9.4} {:>9.4}",
            run.solver,
            run.status.name(),
            run.problem_size,
            work,
            res.max(),
            f.normal,
            if frictional { format!("{:.5e}", f.tangential) } else { opt(c.fit_half_width) },
            if frictional { format!("{:.5e}", c.peak_pressure) } else { opt(c.fit_peak_pressure) },
            if frictional { range(c.stick_x_min, c.stick_x_max) } else { range(c.x_min, c.x_max) },
            rb.normal,
            run.timing_s.solve,
            run.timing_s.total
        );
        if run.status != rollbem::solvers::Status::Solved || run.message.contains("sliding limit") {
            say!("            {}", run.message);
        }
    }
    if !r.steps.is_empty() {
        print_path(r);
    }
    print_stresses(r);
    say!("checks:");
    for c in &r.checks {
        say!("  {}", check_line(c));
    }
}

/// The subsurface stresses' maxima per run (largest |value| on the grid, sign kept, and where), with `[stresses]`.
fn print_stresses(r: &Report) {
    let Some(spec) = &r.scene.stresses else { return };
    say!(
        "stresses in the wheel ({} model): {}×{} grid, x in [{:.4e}, {:.4e}], depth in [{:.4e}, {:.4e}]; maxima (largest |value|):",
        r.scene.wheel.model.name(),
        spec.points[0],
        spec.points[1],
        spec.x[0],
        spec.x[1],
        spec.depth[0],
        spec.depth[1]
    );
    say!("{:<9} {:<17} {:>13} {:>13} {:>13}", "solver", "quantity", "max", "x", "depth");
    for run in &r.runs {
        let Some(st) = &run.stresses else {
            say!("{:<9} none (not solved)", run.solver);
            continue;
        };
        for (q, m) in st.maxima() {
            match m {
                Some(m) => {
                    say!("{:<9} {:<17} {:>13.5e} {:>13.5e} {:>13.5e}", run.solver, q.name(), m.value, m.x, m.depth)
                }
                None => say!("{:<9} {:<17} {:>13}", run.solver, q.name(), "-"),
            }
        }
        let refused = st.refused();
        let n: usize = refused.values().sum();
        let why: Vec<String> = refused.iter().map(|(k, v)| format!("{v} {k}")).collect();
        say!(
            "{:<9} {} of {} points evaluated in {:.3} s{}{}",
            "",
            st.field.grid.len() - n,
            st.field.grid.len(),
            st.time_s,
            if n > 0 { format!("; refused: {}", why.join(", ")) } else { String::new() },
            st.csv.as_ref().map(|f| format!("; field in {f}")).unwrap_or_default()
        );
    }
}

/// One check as a line of the `run` table: a figure with its numbers, a verdict or a reference that does not apply
/// with what was found.
fn check_line(c: &Check) -> String {
    let mark = match (c.kind, c.pass) {
        (CheckKind::NotApplicable, _) => "n/a ",
        (_, true) => "pass",
        (_, false) => "FAIL",
    };
    let note = c.note.as_ref().map(|n| format!(": {n}")).unwrap_or_default();
    match c.kind {
        CheckKind::Figure => format!(
            "[{mark}] {:<48} measured {:>12.6e}  reference {:>12.6e}  error {:>9.2e}  tol {:>8.1e}{note}",
            c.name, c.measured, c.reference, c.error, c.tolerance
        ),
        CheckKind::Verdict | CheckKind::NotApplicable => format!("[{mark}] {}{note}", c.name),
    }
}

/// The run-level warnings of a report: a contact with too few elements across it (a failed check in `check`, a
/// warning in `run`), one line per distinct finding with the solvers it concerns.
fn run_warnings(r: &Report) -> Vec<String> {
    let mut found: Vec<(String, Vec<&str>)> = Vec::new();
    for run in &r.runs {
        let c = rollbem::checks::resolution_check(&r.scene, r.mesh.element, r.mesh.contact_element_length, run);
        if let Some(note) = c.filter(|c| !c.pass).and_then(|c| c.note) {
            match found.iter_mut().find(|(n, _)| *n == note) {
                Some((_, solvers)) => solvers.push(run.solver.0),
                None => found.push((note, vec![run.solver.0])),
            }
        }
    }
    found.into_iter().map(|(note, solvers)| format!("{}: {note}", solvers.join(", "))).collect()
}

/// A load path's summary: per solver, how far it got, the dissipated energy and its hardest substep.
fn print_path(r: &Report) {
    let total = r.steps.len();
    say!(
        "load path: {} steps, {total} substeps (the table above is the path's end; `--path-csv` writes every substep)",
        r.scene.steps.len()
    );
    let names: Vec<&str> = r.runs.iter().map(|x| x.solver.0).collect();
    for name in names {
        let runs: Vec<&rollbem::results::SolverRun> =
            r.steps.iter().filter_map(|st| st.runs.iter().find(|x| x.solver == name)).collect();
        let solved = runs.iter().filter(|x| x.status == rollbem::solvers::Status::Solved).count();
        let dissipated = runs.last().and_then(|x| x.history.as_ref()).map_or(0.0, |h| h.dissipated_total);
        let worst = runs.iter().filter_map(|x| x.residuals.map(|res| res.max())).fold(0.0f64, f64::max);
        let time: f64 = runs.iter().map(|x| x.timing_s.total).sum();
        say!(
            "  {name:<10} {solved}/{total} substeps solved, dissipated {dissipated:.6e}, largest residual {worst:.2e}, time {time:.4} s"
        );
    }
}

/// Where `run` writes a scene's outputs (each written atomically, only when the run completes).
#[derive(Default)]
struct Outputs<'a> {
    json: Option<&'a Path>,
    path_csv: Option<&'a Path>,
    csv: Option<&'a Path>,
}

fn run_one(scene: &Path, out: &Outputs, solvers: &[String]) -> rollbem::Result<Report> {
    let mut s = Scene::from_file(scene)?;
    if !solvers.is_empty() {
        s.solvers.use_ = solvers.to_vec();
    }
    let mut report = run_scene(&s, scene)?;
    if let Some(path) = out.json {
        // Large stress fields go to CSV files beside the document, written first: the document names them.
        for (file, text) in report.spill_stress_fields(path) {
            write_atomic(&file, &text)?;
        }
        let text = serde_json::to_string_pretty(&report).expect("report serialises");
        write_atomic(path, &text)?;
    }
    if let Some(path) = out.path_csv {
        write_atomic(path, &rollbem::history::path_csv(&report))?;
    }
    if let Some(path) = out.csv {
        write_atomic(path, &report.nodes_csv())?;
    }
    Ok(report)
}

/// Read and validate every scene of a command before any runs, refusing unsafe or repeated names (they name the
/// output files); the error to print and exit with otherwise.
fn load_all(scenes: &[PathBuf]) -> Result<Vec<Scene>, rollbem::Error> {
    let loaded = scenes.iter().map(|p| Scene::from_file(p)).collect::<rollbem::Result<Vec<Scene>>>()?;
    rollbem::scene::unique_names(scenes.iter().map(PathBuf::as_path).zip(&loaded))?;
    Ok(loaded)
}

/// Whether a scene file declares expectations (a `[checks]` table): only then does `run` exit 1 on a failed check.
fn declares_checks(path: &Path) -> bool {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|t| toml::from_str::<toml::Table>(&t).ok())
        .is_some_and(|t| t.contains_key("checks"))
}

/// `rollbem check`: one table of checks per scene, a closing count line, exit 1 on any failure.
fn check(scenes: &[PathBuf], solvers: &[String]) -> ExitCode {
    if let Err(e) = load_all(scenes) {
        return fail(&e);
    }
    let (mut passed, mut failed, mut na) = (0usize, 0usize, 0usize);
    let mut code = 0u8;
    for p in scenes {
        match run_one(p, &Outputs::default(), solvers) {
            Ok(r) => {
                let bad = r.checks.iter().filter(|c| !c.pass).count();
                let skipped = r.checks.iter().filter(|c| c.kind == CheckKind::NotApplicable).count();
                say!(
                    "{} {} ({} checks, {} failed, {} not applicable; solvers: {})",
                    if bad == 0 { "PASS" } else { "FAIL" },
                    r.scene.name,
                    r.checks.len(),
                    bad,
                    skipped,
                    r.runs.iter().map(|x| format!("{} {}", x.solver, x.status)).collect::<Vec<_>>().join(", ")
                );
                for c in r.checks.iter().filter(|c| !c.pass) {
                    let note = c.note.as_ref().map(|n| format!(": {n}")).unwrap_or_default();
                    match c.kind {
                        CheckKind::Figure => say!(
                            "    FAIL {}: measured {:.6e}, reference {:.6e}, error {:.3e} > tolerance {:.1e}{note}",
                            c.name,
                            c.measured,
                            c.reference,
                            c.error,
                            c.tolerance
                        ),
                        _ => say!("    FAIL {}{note}", c.name),
                    }
                }
                for run in
                    r.runs.iter().filter(|x| !x.message.is_empty() && x.status != r.scene.checks.status_for(x.solver.0))
                {
                    say!("    {}: {}", run.solver, run.message);
                }
                passed += r.checks.len() - bad - skipped;
                failed += bad;
                na += skipped;
                if bad > 0 {
                    code = code.max(1);
                }
            }
            Err(e) => {
                say!("FAIL {}: {e}", p.display());
                failed += 1;
                code = code.max(e.exit_code() as u8);
            }
        }
    }
    say!("checks: {passed} passed, {failed} failed, {na} not applicable");
    ExitCode::from(code)
}

/// `rollbem run`: validate every scene (and the options that take one scene) before running any, then run and print
/// each; exit 1 only when a scene that declares expectations fails a check.
fn run(
    scenes: &[PathBuf],
    json: Option<PathBuf>,
    out_dir: Option<PathBuf>,
    solvers: &[String],
    csvs: [Option<PathBuf>; 2],
) -> ExitCode {
    let [path_csv, csv] = csvs;
    for (flag, given) in [("--json", json.is_some()), ("--path-csv", path_csv.is_some()), ("--csv", csv.is_some())] {
        if given && scenes.len() > 1 {
            eprintln!("error: {flag} takes one scene; use --out-dir for the JSON of several");
            return ExitCode::from(2);
        }
    }
    let loaded = match load_all(scenes) {
        Ok(l) => l,
        Err(e) => return fail(&e),
    };
    if let (Some(_), Some((p, _))) = (&path_csv, scenes.iter().zip(&loaded).find(|(_, s)| s.steps.is_empty())) {
        eprintln!("error: --path-csv: scene {} has no load path (`[[steps]]`)", p.display());
        return ExitCode::from(2);
    }
    if let Some(dir) = &out_dir {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("error: cannot create {}: {e}", dir.display());
            return ExitCode::from(3);
        }
    }
    let mut code = 0u8;
    for (i, (p, s)) in scenes.iter().zip(&loaded).enumerate() {
        let target = json.clone().or_else(|| out_dir.as_ref().map(|d| d.join(format!("{}.json", s.name))));
        if i > 0 {
            say!("");
        }
        let out = Outputs { json: target.as_deref(), path_csv: path_csv.as_deref(), csv: csv.as_deref() };
        match run_one(p, &out, solvers) {
            Ok(report) => {
                print_report(&report);
                if declares_checks(p) && !report.all_pass() {
                    code = code.max(1);
                }
            }
            Err(e) => {
                eprintln!("error: {e}");
                code = code.max(e.exit_code() as u8);
            }
        }
    }
    ExitCode::from(code)
}

/// Print an error and turn it into the process exit code.
fn fail(e: &rollbem::Error) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(e.exit_code() as u8)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    rollbem::progress::enable(!cli.quiet);
    match cli.cmd {
        Cmd::Check { scenes, solvers } => check(&scenes, &solvers),
        Cmd::Plot { result, out } => match rollbem::plot_result::plot_result(&result, out.as_deref()) {
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
            for e in rollbem::solvers::REGISTRY {
                say!("{:<12} {}{}", e.name, e.summary, if e.in_all { "" } else { " (not in `all`)" });
            }
            ExitCode::SUCCESS
        }
        Cmd::Lcp { cmd } => match lcp_cmd(cmd) {
            Ok(code) => ExitCode::from(code as u8),
            Err(e) => fail(&e),
        },
        Cmd::Sweep { spec, shard, out } => {
            let out = out.unwrap_or_else(|| match &shard {
                Some(s) => spec.with_extension(format!("shard-{}-of-{}.csv", s.k, s.n)),
                None => spec.with_extension("csv"),
            });
            match rollbem::sweep::run_sweep(&spec, shard, &out, !cli.quiet) {
                Ok(rows) => {
                    say!("{rows} rows written to {}", out.display());
                    let errors = rollbem::sweep::error_rows_in(&out);
                    if errors > 0 {
                        eprintln!(
                            "warning: {errors} of the {rows} rows have status `error` (a variant that could not run, \
                             e.g. a solver that does not apply to it): see their `message` column"
                        );
                    }
                    ExitCode::SUCCESS
                }
                Err(e) => fail(&e),
            }
        }
        Cmd::SweepMerge { out, inputs } => match rollbem::sweep::merge(&inputs, &out) {
            Ok(rows) => {
                say!("{rows} rows written to {}", out.display());
                ExitCode::SUCCESS
            }
            Err(e) => fail(&e),
        },
        Cmd::Report { reference, out } => {
            let opts = rollbem::report::ReportOptions { reference, out, progress: !cli.quiet };
            match rollbem::report::generate(&opts) {
                Ok(path) => {
                    say!("report written: {}", path.display());
                    ExitCode::SUCCESS
                }
                Err(e) => fail(&e),
            }
        }
        Cmd::Run { scenes, json, out_dir, solvers, path_csv, csv } => {
            run(&scenes, json, out_dir, &solvers, [path_csv, csv])
        }
    }
}
