//! `rollbem report`: regenerates `reports/` from the reference scenes and sweeps in `reference/`.
//!
//! - `runs/NAME.json`: every reference scene's result document, and `solver-comparison.csv`: per scene and solver
//!   the status, residual, agreement with Lemke (tractions and node states), work and time.
//! - `sweeps/NAME.csv`: every reference sweep ([`crate::sweep`]).
//! - SVG plots (plotters, [`crate::plot`]): accuracy against time for Hertz and Cattaneo–Mindlin per element kind
//!   and solver, convergence under mesh refinement with observed orders, and the seed's figures (tractions against
//!   x with the analytic curves, stick/slip/separation maps, slip velocity for several μ).
//! - `README.md`, the front page (`report/front.rs`): per problem family and target (1e-2, 1e-3, 1e-4) the recommended
//!   method and its time, one figure of every Pareto front, the verification scoreboard, what changed since the
//!   previous run; `families/NAME.md` (one page per problem family: the sweeps' fronts, recommendations, observed
//!   orders, the load paths, the stresses, the seed's figures), `peers/NAME.md`, `methods.md`, `solvers.md`; the
//!   same pages as HTML under `html/` (`report/html.rs`); `recommendations.csv` and `fronts.csv`, the front page's data;
//!   `MANIFEST`, every file written. Files a previous run left and this one did not write are removed
//!   (`report/pages.rs`).
//!
//! Everything is deterministic except the timings (and the plots and tables drawn from them): the machine is
//! noisy, sweeps run cases in parallel, so read times as ratios.

use crate::error::{Error, Result};
use crate::io::write_atomic;
use crate::pipeline::run_scene;
use crate::plot::{Chart, Series, Style};
use crate::post::NodeState;
use crate::results::{Report, SolverRun};
use crate::scene::Scene;
use crate::sweep::Analysis;
use pages::Family;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

mod accuracy;
mod finite_bodies;
mod friction3d;
mod front;
mod html;
mod pages;
mod paths;
mod peer3d;
mod physics;
mod plot_csv;
mod plot_result;
mod rolling;
mod rolling3d;
mod space;
mod table;
mod veldep;
mod visco;

pub use paths::{md_curve, md_pattern, md_shift, path_figures};
pub use plot_csv::plot_csv;
pub use plot_result::{plot_result, Plotted};
pub use table::Units;

/// A sweep's rows read from its CSV, drawn as its analysis draws them (what `rollbem plot SWEEP.csv` does).
pub struct SweepFigures {
    sweep: table::Sweep,
    /// The CSV read (named by errors).
    source: PathBuf,
}

impl SweepFigures {
    /// Read a sweep's CSV (`stem` names its figures).
    pub fn from_csv(path: &Path, stem: &str) -> Result<SweepFigures> {
        let (header, rows) = crate::sweep::SweepRow::read_csv(path)?;
        Ok(SweepFigures {
            sweep: table::Sweep {
                name: stem.to_string(),
                description: String::new(),
                stem: stem.to_string(),
                keys: header.keys,
                rows,
            },
            source: path.to_path_buf(),
        })
    }

    /// Draw the figures of an analysis into `figs` (the Markdown the report would write beside them is dropped).
    /// Errors, before anything is drawn: a 3D half-space sweep's rows (`half_space` runs) with an analysis of the 2D
    /// wheel, or `table` (the 3D sweeps' analysis: their Pareto fronts against time) without 3D rows
    /// ([`Error::Invalid`] naming `--analysis`, exit 2).
    pub fn draw(mut self, analysis: Analysis, figs: &mut Figs) -> Result<()> {
        let mut md = String::new();
        let space = self.sweep.rows.iter().filter(|r| r.kind == crate::sweep::Kind::Space).count();
        let wrong = |message: String| Error::Invalid { path: self.source.clone(), field: "--analysis".into(), message };
        match analysis {
            Analysis::Table if space == 0 => {
                Err(wrong("`table` draws a 3D half-space sweep's fronts; this CSV has no half_space rows".into()))
            }
            Analysis::Table => {
                let before = figs.list.len();
                accuracy::fronts_3d(&self.sweep, &mut md, figs)?;
                if figs.list.len() == before {
                    let msg = "no solved half_space row carries an error measure (hertz_p0_err, hertz_approach_err, \
                               cm_transfer_err): nothing to draw";
                    return Err(wrong(msg.into()));
                }
                Ok(())
            }
            _ if space > 0 && space == self.sweep.rows.len() => Err(wrong(format!(
                "this CSV's rows are 3D half-space runs: their analysis is `table` (the fronts against time), not \
                 `{}`",
                analysis.name()
            ))),
            Analysis::CreepCurve => physics::creep_curves(&self.sweep, &mut md, figs),
            Analysis::FiniteBodies => finite_bodies::sweep_figures(&self.sweep, &mut md, figs),
            Analysis::FiniteVsHalfPlane => physics::finite_vs_half_plane(&self.sweep, &mut md, figs),
            Analysis::Accuracy => accuracy::sections(&mut self.sweep, &mut md, figs).map(|_| ()),
        }
    }
}

/// Where to read and write.
#[derive(Debug, Clone)]
pub struct ReportOptions {
    /// Folder holding `scenes/` and `sweeps/` (normally `reference/`).
    pub reference: PathBuf,
    /// Output folder (normally `reports/`).
    pub out: PathBuf,
    /// Show sweep progress bars.
    pub progress: bool,
}

fn plot_err(e: crate::plot::PlotError) -> Error {
    Error::Output { what: "a report plot".into(), message: e.to_string() }
}

fn toml_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|source| Error::Io { path: dir.to_path_buf(), source })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    v.sort();
    Ok(v)
}

fn fmt_e(v: Option<f64>) -> String {
    v.map(|v| format!("{v:.2e}")).unwrap_or_else(|| "–".into())
}

/// Figures written so far: (title, file relative to the report folder).
pub type Figures = Vec<(String, String)>;

/// Where a section's figures go: `root/sub` + a file name, listed with their titles (files relative to `root`). The
/// report writes into `reports/figures/`; `rollbem plot` into its output folder.
pub struct Figs<'a> {
    /// The folder the listed file names are relative to.
    pub root: &'a Path,
    /// The sub-folder prefix of the files (`"figures/"` or `""`).
    pub sub: &'a str,
    /// The figures written, (title, file relative to `root`).
    pub list: Figures,
}

impl<'a> Figs<'a> {
    /// A sink writing `root/sub/NAME`.
    pub fn new(root: &'a Path, sub: &'a str) -> Figs<'a> {
        Figs { root, sub, list: Vec::new() }
    }

    /// Write a chart as `name` (e.g. `x-creep-curves.svg`), list it under `title`; returns its path relative to
    /// `root` (what a Markdown link needs).
    pub fn save(&mut self, chart: &Chart, name: &str, title: String) -> Result<String> {
        let file = format!("{}{name}", self.sub);
        chart.write(&self.root.join(&file)).map_err(plot_err)?;
        self.list.push((title, file.clone()));
        Ok(file)
    }
}

/// The reference scenes and sweep specs of a report, read and checked.
type Inputs = (Vec<(PathBuf, Scene)>, Vec<(PathBuf, crate::sweep::SweepSpec)>);

/// Read and check every input before anything is written: scene names are safe file names by validation, sweep
/// names are checked here, and both must be unique (they name the output files).
fn read_inputs(opts: &ReportOptions) -> Result<Inputs> {
    let mut scenes = Vec::new();
    for p in toml_files(&opts.reference.join("scenes"))? {
        let s = Scene::from_file(&p)?;
        scenes.push((p, s));
    }
    crate::scene::unique_names(scenes.iter().map(|(p, s)| (p.as_path(), s)))?;
    let mut specs = Vec::new();
    for p in toml_files(&opts.reference.join("sweeps"))? {
        let spec = crate::sweep::SweepSpec::from_file(&p)?;
        crate::scene::safe_name(&spec.name).map_err(|message| Error::Invalid {
            path: p.clone(),
            field: "name".into(),
            message,
        })?;
        specs.push((p, spec));
    }
    crate::scene::unique_output_names(specs.iter().map(|(p, s)| (p.as_path(), s.name.as_str())))?;
    Ok((scenes, specs))
}

/// Everything one run computed, by page, before the pages are written.
struct Parts {
    /// The Markdown of each family's page body (links relative to the report folder).
    family: BTreeMap<Family, String>,
    /// The accuracy summaries, with their families.
    summaries: front::Families,
    /// The 3D Coulomb section's findings.
    found: friction3d::Found,
    /// The solver comparison table (Markdown).
    solvers: String,
    /// Every figure written, (title, file).
    figures: Figures,
}

/// Regenerate everything; returns the path of the front page. Reads the previous run's CSVs and manifest first,
/// writes the pages, CSVs and figures, then removes what the previous run left that this one did not write
/// (`report/pages.rs`; the files it lists but leaves are named on standard error).
pub fn generate(opts: &ReportOptions) -> Result<PathBuf> {
    let out = &opts.out;
    let (scenes, specs) = read_inputs(opts)?;
    let previous = front::Previous::read(out);
    let previous_files = pages::previous_manifest(out);
    for d in ["", "runs", "sweeps", "figures", "families", "peers", "html/families", "html/peers"] {
        let d = out.join(d);
        std::fs::create_dir_all(&d).map_err(|source| Error::Write { path: d.clone(), source })?;
    }
    let mut written = pages::Manifest::default();
    let (reports, solvers) = reference_scenes(opts, scenes, &mut written)?;
    let mut parts = compute(opts, &reports, specs, solvers, &mut written)?;
    let recs = front::recommendations_csv(&parts.summaries);
    let fronts = front::fronts_csv(&parts.summaries);
    let chart = front::figure(&parts.summaries, &parts.found);
    chart.write(&out.join(front::FIGURE)).map_err(plot_err)?;
    parts.figures.push(("Accuracy against time: every Pareto front".into(), front::FIGURE.into()));
    let mut pages: Vec<(String, String)> = Vec::new();
    pages.push(("methods.md".into(), methods_page()));
    pages.push(("solvers.md".into(), solvers_page(&parts.solvers)));
    for (fam, body) in &parts.family {
        pages.push((fam.page(), format!("# {}\n\n{NAV}\n{}", fam.title(), body)));
    }
    // The CONTACT 3D peer table's figure (when the table is present and has the performance series).
    let peer3d_rows: Vec<peer3d::Row> = ["peer-contact3d.md", "peer-contact3d-rolling.md"]
        .iter()
        .flat_map(|f| std::fs::read_to_string(out.join(f)).map(|t| peer3d::rows(&t)).unwrap_or_default())
        .collect();
    if !peer3d_rows.is_empty() {
        peer3d::figure(&peer3d_rows).write(&out.join(peer3d::FIGURE)).map_err(plot_err)?;
        parts.figures.push(("CONTACT's performance series: CPU against elements".into(), peer3d::FIGURE.into()));
    }
    let peers = peer_pages(out, &peer3d_rows);
    pages.extend(peers.iter().map(|(file, _, md)| (file.clone(), md.clone())));
    let changes = front::changes(&previous, &recs, &fronts);
    pages.push(("README.md".into(), front_page(opts, &parts, &reports, &peers, &changes)));
    for (file, md) in &pages {
        let depth = file.matches('/').count();
        write_atomic(&out.join(file), &pages::relink(md, depth))?;
        written.add(out, file);
        written.add(out, html::write_page(out, file, md)?);
    }
    for (file, text) in [(front::RECOMMENDATIONS, &recs), (front::FRONTS, &fronts)] {
        write_atomic(&out.join(file), text)?;
        written.add(out, file);
    }
    for (_, f) in &parts.figures {
        written.add(out, f);
    }
    written.add(out, pages::MANIFEST);
    write_atomic(&out.join(pages::MANIFEST), &written.text())?;
    let cleaned = pages::clean(out, &written, &previous_files)?;
    for f in &cleaned.unknown {
        eprintln!("warning: {} is not a file this report writes; left in place", out.join(f).display());
    }
    Ok(out.join("README.md"))
}

/// The line under every detail page's title.
const NAV: &str = "[Front page](README.md) · [how to read the tables](methods.md)\n";

/// Run the sweeps, the load paths, the figures and the 3D section; sort their Markdown into family pages.
fn compute(
    opts: &ReportOptions,
    reports: &BTreeMap<String, Report>,
    specs: Vec<(PathBuf, crate::sweep::SweepSpec)>,
    solvers: String,
    written: &mut pages::Manifest,
) -> Result<Parts> {
    let out = &opts.out;
    let seed_figs = seed_figures(reports, &out.join("figures"))?;
    let (maps, map_files) = stress_maps(reports, out)?;
    for f in map_files {
        written.add(out, f);
    }
    let (mut family, summaries, plots) = sweeps(opts, specs, written)?;
    let mut path_md = String::new();
    let mut sink = Figs::new(out, "figures/");
    paths::sections(reports, &mut path_md, &mut sink)?;
    let mut path_figs = sink.list;
    let mut roll_md = String::new();
    rolling::seed_vs_steady(reports, out, &mut roll_md, &mut path_figs)?;
    let mut f3 = String::new();
    let found = friction3d::section(&mut f3)?;
    let mut sink3 = Figs::new(out, "figures/");
    rolling3d::section(&mut f3, &mut sink3, &opts.reference)?;
    path_figs.extend(sink3.list);
    family.entry(Family::Space3d).or_default().push_str(&f3);
    let mut visco_md = String::new();
    visco::section(&mut visco_md)?;
    let mut sink_v = Figs::new(out, "figures/");
    veldep::section(&mut visco_md, &mut sink_v, &opts.reference)?;
    path_figs.extend(sink_v.list);
    family.entry(Family::Carter).or_default().push_str(&visco_md);
    let mut finite_md = String::new();
    let mut sink_fb = Figs::new(out, "figures/");
    finite_bodies::section(&mut finite_md, &mut sink_fb)?;
    path_figs.extend(sink_fb.list);
    family.entry(Family::Hertz).or_default().push_str(&finite_md);
    if !path_md.is_empty() {
        family.insert(Family::Paths, path_md);
    }
    let mut seed = String::new();
    if !seed_figs.is_empty() {
        writeln!(seed, "\n## The seed's figures, reproduced\n").unwrap();
        for (title, file) in &seed_figs {
            writeln!(seed, "### {title}\n\n![{title}]({file})\n").unwrap();
        }
    }
    seed.push_str(&roll_md);
    if !seed.is_empty() {
        family.insert(Family::Seed, seed);
    }
    if let Some(m) = stresses_md(&maps) {
        family.insert(Family::Stresses, m);
    }
    let figures = plots.into_iter().chain(path_figs).chain(seed_figs).chain(maps).collect();
    Ok(Parts { family, summaries, found, solvers, figures })
}

/// The methods page: how to read the tables, how times are taken, how mesh limits are estimated.
fn methods_page() -> String {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!(
        "# How the report is made\n\n[Front page](README.md)\n\n## Timing\n\nEverything is deterministic except \
         timings, taken with {cores} logical CPUs available to the process (a sweep that repeats its timings runs its \
         cases one at a time, the others in parallel): read times as ratios between methods, and the benchmarks \
         (`cargo bench`) for stable figures.\n\n## How to read the tables\n\n{}\n## Converged-mesh limits\n\n{}",
        accuracy::how_to_read(),
        accuracy::richardson_method()
    )
}

/// The solver comparison page.
fn solvers_page(table: &str) -> String {
    format!(
        "# Solver comparison on the reference scenes ([CSV](solver-comparison.csv))\n\n{NAV}\n\
         Δ vs Lemke is max(|Δp|, |Δq|) over the nodes divided by Lemke's peak pressure; state mismatches count \
         nodes called stick/slip/separated differently from Lemke. Residuals are solver-independent (physical \
         conditions). The QP symmetrisation effect is, for clarabel, max |p_QP − p| / p_max between the interior-point \
         answer of the symmetrised QP (K_s = (K + Kᵀ)/2) and the polished answer of the nonsymmetric collocation \
         problem: the price of the symmetric assumption, removed by the polish. For a load path the row is the path's \
         last substep.\n\n{table}"
    )
}

/// The peer pages (`peers/NAME.md`), one per peer table present in the folder: (page, title, Markdown).
fn peer_pages(out: &Path, peer3d_rows: &[peer3d::Row]) -> Vec<(String, String, String)> {
    // The peer benchmarks are not part of `report` (they install and build peers and run for minutes): a page is
    // written when its script (`benches/peer/run.sh OUT/peer-lcp.md`, `benches/peer/contact.sh
    // OUT/peer-contact.md`, `benches/peer/contact3d.sh OUT/peer-contact3d.md`) has written its table into this
    // folder (a declared input, [`pages::DECLARED_INPUTS`]).
    let mut v = Vec::new();
    for (file, page, title, script) in [
        ("peer-lcp.md", "siconos", "Side by side with Siconos numerics", "run.sh"),
        ("peer-contact.md", "contact-2d", "Side by side with CONTACT (Vollebregt), 2D Carter", "contact.sh"),
        ("peer-contact3d.md", "contact-3d", "Side by side with CONTACT (Vollebregt), 3D half-space", "contact3d.sh"),
        (
            "peer-contact3d-rolling.md",
            "contact-3d-rolling",
            "Side by side with CONTACT (Vollebregt), 3D steady rolling",
            "contact3d.sh",
        ),
        (
            "peer-contact3d-examples.md",
            "contact-3d-examples",
            "Side by side with CONTACT (Vollebregt), its 3D rolling examples (fastsim, tractcurv, catt_to_cart)",
            "contact3d.sh",
        ),
    ] {
        let peer = out.join(file);
        if let Ok(table) = std::fs::read_to_string(&peer) {
            let figure = if matches!(page, "contact-3d" | "contact-3d-rolling") && !peer3d_rows.is_empty() {
                peer3d::caption(peer3d_rows)
            } else {
                String::new()
            };
            let md = format!(
                "# {title}\n\n{NAV}\nWritten by `bash benches/peer/{script} {}` (run separately; see \
                 benches/peer/README.md), not regenerated by `report`; the table as the script wrote it \
                 ([{file}]({file})):\n\n{}\n{figure}",
                peer.display(),
                table.trim_end()
            );
            v.push((format!("peers/{page}.md"), title.to_string(), md));
        }
    }
    v
}

/// The stress maps' page body (`None` without maps).
fn stresses_md(maps: &Figures) -> Option<String> {
    if maps.is_empty() {
        return None;
    }
    let mut md = String::new();
    writeln!(
        md,
        "The reference scenes with `[stresses]`: Lemke's field as filled contour maps, the maximum (largest \
         |value|) marked. Tension positive; depth drawn downward. Every quantity's map:\n"
    )
    .unwrap();
    for (title, file) in maps {
        writeln!(md, "- [{title}]({file})").unwrap();
    }
    writeln!(md).unwrap();
    for (title, file) in
        maps.iter().filter(|(_, f)| f.ends_with(".principal_shear.svg") || f.ends_with(".von_mises.svg"))
    {
        writeln!(md, "## {title}\n\n![{title}]({file})\n").unwrap();
    }
    Some(md)
}

/// The front page.
fn front_page(
    opts: &ReportOptions,
    parts: &Parts,
    reports: &BTreeMap<String, Report>,
    peers: &[(String, String, String)],
    changes: &str,
) -> String {
    let mut md = String::from("# rollbem reports: what accuracy costs\n\n");
    writeln!(
        md,
        "Generated by `rollbem report --reference {} --out {}` (never edit by hand). Times are medians on this \
         machine: read them as ratios ([timing](methods.md#timing)).\n",
        opts.reference.display(),
        opts.out.display()
    )
    .unwrap();
    writeln!(
        md,
        "## Which method for which accuracy\n\nPer problem family and target error (relative, against the reference \
         the measure names): the recommended discretisation, contact elements and solver, the error it reaches and \
         its total time. Chosen by the [recommendation rule](methods.md#how-to-read-the-tables) on each sweep's Pareto \
         front; each cell is a row of [{0}]({0}); the family's page has the fronts and the alternatives. \"Not \
         resolved\": below the uncertainty of the mesh limit the error is measured against.\n",
        front::RECOMMENDATIONS
    )
    .unwrap();
    md.push_str(&front::recommendation_table(&parts.summaries, &parts.found));
    let untimed: Vec<String> = parts
        .family
        .keys()
        .filter(|f| !parts.summaries.iter().any(|(g, _)| g == *f) && **f != Family::Space3d && **f != Family::Seed)
        .map(|f| format!("[{}]({})", f.short(), f.page()))
        .collect();
    if !untimed.is_empty() {
        writeln!(
            md,
            "\nNo accuracy-against-time sweep yet for {}: their agreement is in the scoreboard and on their pages.",
            untimed.join(", ")
        )
        .unwrap();
    }
    writeln!(md, "\n![Accuracy against time: every Pareto front]({})\n", front::FIGURE).unwrap();
    front_page_tail(&mut md, parts, reports, peers, changes);
    md
}

/// The front page after the figure: scoreboard, changes, pages.
fn front_page_tail(
    md: &mut String,
    parts: &Parts,
    reports: &BTreeMap<String, Report>,
    peers: &[(String, String, String)],
    changes: &str,
) {
    writeln!(
        md,
        "## Verification scoreboard\n\nEvery figure check of the reference scenes (`runs/*.json`), by the reference \
         it compares with: worst agreement = the largest error relative to its tolerance.\n"
    )
    .unwrap();
    md.push_str(&front::scoreboard(reports));
    let loose: Vec<String> = [Family::Carter, Family::Paths, Family::Space3d]
        .into_iter()
        .filter(|f| parts.family.contains_key(f))
        .map(|f| format!("[{}]({})", f.short(), f.page()))
        .collect();
    if !loose.is_empty() {
        writeln!(
            md,
            "\nAlso compared with their theories, without a declared tolerance (the differences are on their pages): \
             {}.",
            loose.join(", ")
        )
        .unwrap();
    }
    if !peers.is_empty() {
        writeln!(
            md,
            "\nPeers, measured by their scripts (`benches/peer/`), which declare no pass/fail tolerance for the \
             agreement with rollbem: each page shows the differences it measured.\n"
        )
        .unwrap();
        for (page, title, _) in peers {
            writeln!(md, "- [{title}]({page})").unwrap();
        }
    }
    writeln!(md, "\n{changes}").unwrap();
    writeln!(md, "## Pages\n").unwrap();
    for f in parts.family.keys() {
        writeln!(md, "- [{}]({})", f.title(), f.page()).unwrap();
    }
    writeln!(md, "- [Solver comparison on the reference scenes](solvers.md)").unwrap();
    writeln!(md, "- [How to read the tables, timing, mesh limits](methods.md)").unwrap();
    writeln!(
        md,
        "- Files: `runs/`, `sweeps/`, [{0}]({0}), [{1}]({1}), [MANIFEST](MANIFEST) (every file of this run)",
        front::RECOMMENDATIONS,
        front::FRONTS
    )
    .unwrap();
}

/// Run every reference scene: its JSON, `solver-comparison.csv`, and the comparison table (Markdown).
fn reference_scenes(
    opts: &ReportOptions,
    scenes: Vec<(PathBuf, Scene)>,
    written: &mut pages::Manifest,
) -> Result<(BTreeMap<String, Report>, String)> {
    let out = &opts.out;
    // ---- reference scenes: JSON, solver comparison, seed figures -----------------------------------------------
    let mut reports: BTreeMap<String, Report> = BTreeMap::new();
    let mut cmp = String::from(
        "scene,solver,formulation,status,problem_size,pivots,sweeps,iterations,outer,residual,max_dtraction_vs_lemke,\
         state_mismatches_vs_lemke,symmetrisation_effect,flexibility_asymmetry,t_solve,t_total\n",
    );
    let mut cmp_md = String::from(
        "| scene | solver | status | size | work | residual | Δ vs Lemke (/p0) | state mismatches | QP symmetrisation effect | solve time [s] |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (_, s) in scenes {
        let r = run_scene(&s)?;
        let text = serde_json::to_string_pretty(&r).expect("report serialises");
        let json = out.join("runs").join(format!("{}.json", s.name()));
        write_atomic(&json, &text)?;
        written.add(out, &json);
        let lemke = r.runs.iter().find(|x| x.solver == "lemke");
        for run in &r.runs {
            let cmp_lemke = match (lemke, &run.contact) {
                (Some(l), Some(_)) if l.contact.is_some() && run.solver != "lemke" => {
                    Some(crate::checks::compare(l, run, s.friction()))
                }
                _ => None,
            };
            let (d, mism) = (cmp_lemke.map(|c| c.max_dtraction), cmp_lemke.map(|c| c.state_mismatches));
            let w = &run.work;
            let opt = |v: Option<u64>| v.map(|v| v.to_string()).unwrap_or_default();
            writeln!(
                cmp,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{:e},{:e},{:e}",
                s.name(),
                run.solver,
                run.formulation,
                run.status,
                run.problem_size,
                opt(w.get("pivots")),
                opt(w.get("sweeps")),
                opt(w.get("iterations")),
                opt(w.get("outer")),
                run.residuals.map(|x| format!("{:e}", x.max())).unwrap_or_default(),
                d.map(|v| format!("{v:e}")).unwrap_or_default(),
                mism.map(|m| m.to_string()).unwrap_or_default(),
                run.figures.get("polish_change").map(|v| format!("{v:e}")).unwrap_or_default(),
                r.diagnostics.flexibility_asymmetry,
                run.timing_s.solve,
                run.timing_s.total
            )
            .unwrap();
            writeln!(
                cmp_md,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.4} |",
                s.name(),
                run.solver,
                run.status,
                run.problem_size,
                w.long(),
                fmt_e(run.residuals.map(|x| x.max())),
                fmt_e(d),
                mism.map(|m| m.to_string()).unwrap_or_else(|| "–".into()),
                fmt_e(run.figures.get("polish_change")),
                run.timing_s.solve
            )
            .unwrap();
        }
        reports.insert(s.name().to_string(), r);
    }
    write_atomic(&out.join("solver-comparison.csv"), &cmp)?;
    written.add(out, "solver-comparison.csv");
    Ok((reports, cmp_md))
}

/// The contour maps of every reference scene with `[stresses]` (`rollbem plot` on its `runs/NAME.json`, into
/// `figures/`): (title, file) of Lemke's map per quantity, in the scene's and the quantities' order, and every file
/// `rollbem plot` wrote.
fn stress_maps(reports: &BTreeMap<String, Report>, out: &Path) -> Result<(Figures, Vec<PathBuf>)> {
    let mut maps = Vec::new();
    let mut files = Vec::new();
    for (name, r) in reports.iter().filter(|(_, r)| r.scene.stresses().is_some()) {
        let json = out.join("runs").join(format!("{name}.json"));
        files.extend(plot_result::plot_result(&json, Some(&out.join("figures")))?.files);
        let Some(st) = r.runs.iter().find(|x| x.solver == "lemke").and_then(|x| x.stresses.as_ref()) else {
            continue;
        };
        for q in &st.quantities {
            let file = format!("figures/{name}.lemke.{}.svg", q.name());
            if out.join(&file).exists() {
                maps.push((format!("{name}: {} (Lemke)", q.name()), file));
            }
        }
    }
    Ok((maps, files))
}

/// Run every reference sweep into its CSV and its sections. Returns the Markdown per family page, the accuracy
/// summaries with their families, and the plots.
#[allow(clippy::type_complexity)]
fn sweeps(
    opts: &ReportOptions,
    specs: Vec<(PathBuf, crate::sweep::SweepSpec)>,
    written: &mut pages::Manifest,
) -> Result<(BTreeMap<Family, String>, front::Families, Figures)> {
    let out = &opts.out;
    let mut pages: BTreeMap<Family, String> = BTreeMap::new();
    let mut summaries = Vec::new();
    let mut sink = Figs::new(out, "figures/");
    for (spec_path, spec) in specs {
        let stem = spec.name.clone();
        let csv_path = out.join("sweeps").join(format!("{stem}.csv"));
        crate::sweep::run_sweep(&spec_path, None, &csv_path, opts.progress)?;
        written.add(out, &csv_path);
        let mut sw = table::Sweep {
            name: spec.name.clone(),
            description: spec.description.clone(),
            stem: stem.clone(),
            keys: spec.keys(),
            rows: crate::sweep::SweepRow::read_csv(&csv_path)?.1,
        };
        let mut md = String::new();
        writeln!(md, "\n### {} ([CSV](sweeps/{stem}.csv), {} rows)\n\n{}\n", sw.name, sw.rows.len(), sw.description)
            .unwrap();
        // The spec says what the sweep is; the report never guesses it from the rows.
        let family = match spec.analysis {
            Analysis::CreepCurve => {
                physics::creep_curves(&sw, &mut md, &mut sink)?;
                Family::Carter
            }
            Analysis::FiniteVsHalfPlane => {
                physics::finite_vs_half_plane(&sw, &mut md, &mut sink)?;
                Family::Hertz
            }
            Analysis::FiniteBodies => {
                finite_bodies::sweep_figures(&sw, &mut md, &mut sink)?;
                Family::Hertz
            }
            Analysis::Accuracy => {
                let s = accuracy::sections(&mut sw, &mut md, &mut sink)?;
                // A sweep whose errors are against Cattaneo–Mindlin (or its stick zone's limit) is about partial slip.
                let cm = s.iter().any(|x| x.measure.starts_with("cm_") || x.measure == "disc_c_err");
                let family = if cm { Family::Cattaneo } else { Family::Hertz };
                summaries.extend(s.into_iter().map(|x| (family, x)));
                family
            }
            Analysis::Table => {
                space::table(&sw, &mut md);
                let s = accuracy::fronts_3d(&sw, &mut md, &mut sink)?;
                summaries.extend(s.into_iter().map(|x| (Family::Space3d, x)));
                Family::Space3d
            }
        };
        pages.entry(family).or_default().push_str(&md);
    }
    // The front page lists families in their order: sort the summaries by it, keeping each sweep's order.
    summaries.sort_by_key(|(f, _)| *f);
    Ok((pages, summaries, sink.list))
}

fn lemke_of<'a>(reports: &'a BTreeMap<String, Report>, name: &str) -> Option<&'a SolverRun> {
    lemke_run(reports.get(name)?)
}

/// Lemke's solved run of a report (the reference every comparison in the report is made against).
fn lemke_run(r: &Report) -> Option<&SolverRun> {
    r.runs.iter().find(|r| r.solver == "lemke" && r.contact.is_some())
}

/// Write a chart into the figures folder and record it.
fn save(dir: &Path, out: &mut Vec<(String, String)>, chart: Chart, file: &str, title: &str) -> Result<()> {
    chart.write(&dir.join(file)).map_err(plot_err)?;
    out.push((title.to_string(), format!("figures/{file}")));
    Ok(())
}

/// The seed's groups of figures: tractions (Figs. 7–9 / 12–13 / 16–17), slip velocity (Figs. 10 / 14 / 18) and
/// state maps (Figs. 11 / 15), each from its reference scenes (name, label).
const SEED_GROUPS: [SeedGroup; 3] = SEED;

/// A group of the seed's figures: (file tag, title, its scenes as (name, label)).
type SeedGroup = (&'static str, &'static str, &'static [(&'static str, &'static str)]);

const SEED: [SeedGroup; 3] = [
    (
        "07-10",
        "Figs. 7–10 (normal displacement)",
        &[("seed-fig07-mu002", "μ = 0.02"), ("seed-fig08-mu01", "μ = 0.1"), ("seed-fig09-mu05", "μ = 0.5")],
    ),
    (
        "11-14",
        "Figs. 11–14 (normal and tangential displacement)",
        &[("seed-fig12-mu01", "μ = 0.1"), ("seed-fig13-mu03", "μ = 0.3")],
    ),
    ("15-18", "Figs. 15–18 (loading, |Q/P| = 0.1)", &[("seed-fig16-mu01", "μ = 0.1"), ("seed-fig17-mu07", "μ = 0.7")]),
];

/// The seed's figures from the reference scenes' Lemke runs. Returns (title, file) pairs.
fn seed_figures(reports: &BTreeMap<String, Report>, dir: &Path) -> Result<Vec<(String, String)>> {
    let mut out = Vec::new();
    if let Some(chart) = seed_fig6(reports) {
        let title = "Fig. 6: frictionless pressure, constant and quadratic elements, and Hertz";
        save(dir, &mut out, chart, "seed-fig06-pressure.svg", title)?;
    }
    for (gi, (tag, title, members)) in SEED_GROUPS.iter().enumerate() {
        if let Some([tr, sv, st]) = seed_group(reports, gi, title, members) {
            save(dir, &mut out, tr, &format!("seed-fig{tag}-tractions.svg"), &format!("{title}: pressure and shear"))?;
            save(dir, &mut out, sv, &format!("seed-fig{tag}-slip-velocity.svg"), &format!("{title}: slip velocity"))?;
            let what = format!("{title}: stick / slip / separation");
            save(dir, &mut out, st, &format!("seed-fig{tag}-states.svg"), &what)?;
        }
    }
    Ok(out)
}

/// Fig. 6: frictionless pressure, constant and quadratic elements, against Hertz.
fn seed_fig6(reports: &BTreeMap<String, Report>) -> Option<Chart> {
    let (c, q) = (lemke_of(reports, "seed-fig6-constant")?, lemke_of(reports, "seed-fig6-quadratic")?);
    let h = reports["seed-fig6-constant"].references.hertz;
    let mut chart = Chart::new("Seed Fig. 6: frictionless pressure against Hertz", "x", "pressure p")
        .add(Series::new("constant elements", c.nodes.iter().map(|n| (n.x, n.pressure)).collect(), Style::Markers))
        .add(Series::new("quadratic elements", q.nodes.iter().map(|n| (n.x, n.pressure)).collect(), Style::Markers));
    if let Some(h) = h {
        let xs: Vec<f64> = (0..=200).map(|i| -1.5 * h.a + 3.0 * h.a * i as f64 / 200.0).collect();
        chart = chart.add(Series::new("Hertz", xs.iter().map(|&x| (x, h.pressure(x))).collect(), Style::Dashed));
    }
    Some(chart)
}

/// One group of the seed's figures: [tractions, slip velocity, node states], `None` when none of its scenes has a
/// solved Lemke run.
fn seed_group(
    reports: &BTreeMap<String, Report>,
    gi: usize,
    title: &str,
    members: &[(&str, &str)],
) -> Option<[Chart; 3]> {
    let units = members
        .first()
        .and_then(|(n, _)| reports.get(*n))
        .map(|r| table::Units::parse(r.scene.units()))
        .unwrap_or_default();
    let mut tr = Chart::new(format!("Seed {title}: tractions"), "x", "traction (p markers, q lines)")
        .x_unit(units.length.clone())
        .y_unit(units.stress.clone());
    let mut sv = Chart::new(format!("Seed {title}: slip velocity s_t* (eq. 12)"), "x", "s_t*")
        .x_unit(units.length.clone())
        .y_unit("1");
    let mut st = Chart::new(format!("Seed {title}: node states"), "x", "state")
        .x_unit(units.length.clone())
        .categories_y(&["separated", "slip", "stick"]);
    let mut any = false;
    for (k, (name, label)) in members.iter().enumerate() {
        let Some(l) = lemke_of(reports, name) else { continue };
        if !any {
            // Hertz's pressure at this scene's load, the analytic curve the seed compares its tractions with.
            let sc = &reports[*name].scene;
            if let Some(res) = l.resultants.filter(|r| r.normal > 0.0) {
                let h = crate::references::hertz_at(sc, res.normal);
                let xs: Vec<f64> = (0..=200).map(|i| -1.5 * h.a + 3.0 * h.a * i as f64 / 200.0).collect();
                tr = tr.add(Series::new(
                    format!("Hertz p at P = {:.4e}", res.normal),
                    xs.iter().map(|&x| (x, h.pressure(x))).collect(),
                    Style::Dashed,
                ));
            }
        }
        any = true;
        if k == 0 || gi > 0 {
            let p = l.nodes.iter().map(|n| (n.x, n.pressure)).collect();
            tr = tr.add(Series::new(format!("p, {label}"), p, Style::Markers));
        }
        let q = l.nodes.iter().map(|n| (n.x, n.shear)).collect();
        tr = tr.add(Series::new(format!("q, {label}"), q, Style::LineMarkers));
        let v = l.nodes.iter().filter_map(|n| n.slip_velocity.map(|v| (n.x, v))).collect();
        sv = sv.add(Series::new(label.to_string(), v, Style::LineMarkers));
        let code = |s: NodeState| match s {
            NodeState::Stick => 2.0,
            NodeState::Slip | NodeState::Contact => 1.0,
            NodeState::Separated => 0.0,
        } + 0.06 * k as f64;
        st = st.add(Series::new(
            label.to_string(),
            l.nodes.iter().map(|n| (n.x, code(n.state))).collect(),
            Style::Markers,
        ));
    }
    any.then_some([tr, sv, st])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stress_maps_of_the_scenes_with_stresses() {
        // A half-plane scene with [stresses] and one without: maps (one per quantity asked for) only for the first.
        let text = |name: &str, stresses: &str| {
            format!(
                "name = \"{name}\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
                 model = \"half_plane\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 9.0\n\
                 contact_elements = 40\n[drive]\nnormal_load = 20000.0\n[solvers]\nuse = [\"lemke\"]\n{stresses}"
            )
        };
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("runs")).unwrap();
        std::fs::create_dir_all(dir.path().join("figures")).unwrap();
        let mut reports = BTreeMap::new();
        for (name, st) in [
            ("with", "[stresses]\nx = [-10.0, 10.0]\ndepth = [0.0, 15.0]\npoints = [21, 16]\nquantities = [\"von_mises\", \"sxx\"]"),
            ("without", ""),
        ] {
            let s = Scene::from_toml(&text(name, st), Path::new("<test>")).unwrap();
            let r = run_scene(&s).unwrap();
            let json = serde_json::to_string_pretty(&r).unwrap();
            std::fs::write(dir.path().join("runs").join(format!("{name}.json")), json).unwrap();
            reports.insert(name.to_string(), r);
        }
        let (maps, _) = stress_maps(&reports, dir.path()).unwrap();
        let files: Vec<&str> = maps.iter().map(|(_, f)| f.as_str()).collect();
        assert_eq!(files, ["figures/with.lemke.sxx.svg", "figures/with.lemke.von_mises.svg"]);
        for f in files {
            assert!(std::fs::read_to_string(dir.path().join(f)).unwrap().contains("<svg"));
        }
        assert!(!dir.path().join("figures/without.lemke.tractions.svg").exists());
    }
}
