//! `rollbem report`: regenerates `reports/` from the reference scenes and sweeps in `reference/`.
//!
//! - `runs/NAME.json`: every reference scene's result document, and `solver-comparison.csv`: per scene and solver
//!   the status, residual, agreement with Lemke (tractions and node states), work and time.
//! - `sweeps/NAME.csv`: every reference sweep ([`crate::sweep`]).
//! - SVG plots (plotters, [`crate::plot`]): accuracy against time for Hertz and Cattaneo–Mindlin per element kind
//!   and solver, convergence under mesh refinement with observed orders, and the seed's figures (tractions against
//!   x with the analytic curves, stick/slip/separation maps, slip velocity for several μ).
//! - `README.md`: the summary a reader uses to choose a method for a given accuracy: Pareto fronts, the cheapest
//!   configuration reaching 1 %, 0.1 % and 0.01 %, observed orders, the solver comparison table, links.
//!
//! Everything is deterministic except the timings (and the plots and tables drawn from them): the machine is
//! noisy, sweeps run cases in parallel, so read times as ratios.

use crate::error::{Error, Result};
use crate::io::write_atomic;
use crate::plot::{Chart, Series, Style};
use crate::post::NodeState;
use crate::results::{Report, SolverRun};
use crate::run::run_scene;
use crate::scene::Scene;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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

/// A CSV read into rows of named cells.
struct Table {
    rows: Vec<BTreeMap<String, String>>,
}

impl Table {
    fn read(path: &Path) -> Result<Table> {
        let mut rd = csv::Reader::from_path(path)
            .map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string() })?;
        let headers =
            rd.headers().map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string() })?.clone();
        let mut rows = Vec::new();
        for rec in rd.records() {
            let rec = rec.map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string() })?;
            rows.push(headers.iter().zip(rec.iter()).map(|(h, v)| (h.to_string(), v.to_string())).collect());
        }
        Ok(Table { rows })
    }
}

fn num(r: &BTreeMap<String, String>, k: &str) -> Option<f64> {
    r.get(k).and_then(|v| v.parse::<f64>().ok()).filter(|v| v.is_finite())
}

fn cell<'a>(r: &'a BTreeMap<String, String>, k: &str) -> &'a str {
    r.get(k).map(|s| s.as_str()).unwrap_or("")
}

/// The configuration a sweep row stands for: element kind, solver and (for iterative solvers) tolerance.
fn config(r: &BTreeMap<String, String>) -> String {
    let solver = cell(r, "solver");
    let tol = r
        .iter()
        .find(|(k, v)| k.ends_with(".tolerance") && k.contains(solver) && !v.is_empty())
        .map(|(_, v)| v.parse::<f64>().map(|t| format!(" τ={t:.0e}")).unwrap_or_else(|_| format!(" τ={v}")))
        .unwrap_or_default();
    format!("{} {solver}{tol}", cell(r, "element"))
}

/// Points (x, y) of the rows with both values, grouped by configuration, in mesh order (so a series' line follows
/// the refinement).
fn grouped(rows: &[&BTreeMap<String, String>], x: &str, y: &str) -> BTreeMap<String, Vec<(f64, f64)>> {
    let mut g: BTreeMap<String, Vec<(f64, f64, f64)>> = BTreeMap::new();
    for r in rows {
        if let (Some(a), Some(b)) = (num(r, x), num(r, y)) {
            g.entry(config(r)).or_default().push((num(r, "contact_elements").unwrap_or(0.0), a, b));
        }
    }
    g.into_iter()
        .map(|(k, mut v)| {
            v.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            (k, v.into_iter().map(|(_, a, b)| (a, b)).collect())
        })
        .collect()
}

/// A configuration enters the Pareto front only if it improves the error by this fraction (timings are noisy, and
/// equal-error points differing only by noise are not choices).
const PARETO_IMPROVEMENT: f64 = 0.02;

/// Pareto front of (time, error): the configurations no other beats on both.
fn pareto<'a>(rows: &[&'a BTreeMap<String, String>], err: &str) -> Vec<&'a BTreeMap<String, String>> {
    let mut pts: Vec<&BTreeMap<String, String>> =
        rows.iter().copied().filter(|r| num(r, err).is_some() && num(r, "t_total").is_some()).collect();
    pts.sort_by(|a, b| num(a, "t_total").unwrap().total_cmp(&num(b, "t_total").unwrap()));
    let mut front = Vec::new();
    let mut best = f64::INFINITY;
    for r in pts {
        let e = num(r, err).unwrap();
        if e < best * (1.0 - PARETO_IMPROVEMENT) {
            best = e;
            front.push(r);
        }
    }
    front
}

/// Observed order of convergence from the two finest meshes of a series (error ∝ h^order, h ∝ 1/elements).
fn order(points: &[(f64, f64)]) -> Option<f64> {
    let n = points.len();
    if n < 2 {
        return None;
    }
    let (a, b) = (points[n - 2], points[n - 1]);
    (a.1 > 0.0 && b.1 > 0.0 && b.0 > a.0).then(|| (a.1 / b.1).ln() / (b.0 / a.0).ln())
}

fn fmt_e(v: Option<f64>) -> String {
    v.map(|v| format!("{v:.2e}")).unwrap_or_else(|| "–".into())
}

/// Regenerate everything; returns the path of the Markdown summary.
pub fn generate(opts: &ReportOptions) -> Result<PathBuf> {
    let out = &opts.out;
    for d in [out.clone(), out.join("runs"), out.join("sweeps"), out.join("figures")] {
        std::fs::create_dir_all(&d).map_err(|source| Error::Write { path: d.clone(), source })?;
    }
    let mut md = String::new();
    writeln!(md, "# rollbem reports\n").unwrap();
    writeln!(
        md,
        "Generated by `cargo run --release -- report` from `reference/` (never edit by hand). Everything is \
         deterministic except timings: this machine has 2 noisy vCPUs and sweeps run cases in parallel, so read \
         times as ratios between methods.\n"
    )
    .unwrap();
    let (reports, cmp_md) = reference_scenes(opts)?;
    let figures = seed_figures(&reports, &out.join("figures"))?;
    let (sweep_md, plots) = sweeps(opts)?;

    // ---- Markdown ----------------------------------------------------------------------------------------------
    writeln!(md, "## Which method for which accuracy\n").unwrap();
    writeln!(
        md,
        "Errors are measured against the analytic references (Hertz at equal load; Cattaneo–Mindlin at β = 0). \
         They fall with the mesh until the wheel's finite size (a/R ≈ 0.015 here) and the node-based fit set a \
         floor; a solver tolerance looser than that floor wastes accuracy, a tighter one wastes time. Direct \
         solvers (Lemke, clarabel with polish) are exact to round-off on the discrete problem; PGS at tolerance τ \
         adds an error of order τ. An error against theory mixes discretisation, the finite wheel's departure from \
         the half-space, and solver error: a loose PGS tolerance can land closer to Hertz by chance, not by merit — \
         read solver error against Lemke (solver comparison below). Times here are single runs, with \
         cases in parallel on 2 vCPUs; criterion benchmarks (`cargo bench`) give the stable figures. A configuration \
         enters a Pareto front only if it lowers the error by at least 2 %.\n"
    )
    .unwrap();
    md.push_str(&sweep_md);
    writeln!(md, "\n## Solver comparison on the reference scenes ([CSV](solver-comparison.csv))\n").unwrap();
    writeln!(
        md,
        "Δ vs Lemke is max(|Δp|, |Δq|) over the nodes divided by Lemke's peak pressure; state mismatches count \
         nodes called stick/slip/separated differently from Lemke. Residuals are solver-independent (physical \
         conditions). The QP symmetrisation effect is, for clarabel, max |p_QP − p| / p_max between the interior-point \
         answer of the symmetrised QP (K_s = (K + Kᵀ)/2) and the polished answer of the nonsymmetric collocation \
         problem: the price of the symmetric assumption, of the order of the flexibility's asymmetry (in \
         `solver-comparison.csv`), removed by the polish.\n"
    )
    .unwrap();
    md.push_str(&cmp_md);
    writeln!(md, "\n## The seed's figures, reproduced\n").unwrap();
    for (title, file) in &figures {
        writeln!(md, "### {title}\n\n![{title}]({file})\n").unwrap();
    }
    writeln!(md, "\n## Files\n\n- `runs/NAME.json`: result document of every reference scene").unwrap();
    writeln!(md, "- `solver-comparison.csv`, `sweeps/*.csv`: the tables behind this page").unwrap();
    for (title, file) in plots.iter().chain(&figures) {
        writeln!(md, "- [{title}]({file})").unwrap();
    }
    let path = out.join("README.md");
    write_atomic(&path, &md)?;
    Ok(path)
}

/// Run every reference scene: its JSON, `solver-comparison.csv`, and the comparison table (Markdown).
fn reference_scenes(opts: &ReportOptions) -> Result<(BTreeMap<String, Report>, String)> {
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
    for p in toml_files(&opts.reference.join("scenes"))? {
        let s = Scene::from_file(&p)?;
        let r = run_scene(&s, &p)?;
        let text = serde_json::to_string_pretty(&r).expect("report serialises");
        write_atomic(&out.join("runs").join(format!("{}.json", s.name)), &text)?;
        let lemke = r.runs.iter().find(|x| x.solver == "lemke");
        for run in &r.runs {
            let cmp_lemke = match (lemke, &run.contact) {
                (Some(l), Some(_)) if l.contact.is_some() && run.solver != "lemke" => {
                    Some(crate::checks::compare(l, run, s.contact.friction))
                }
                _ => None,
            };
            let (d, mism) = (cmp_lemke.map(|c| c.max_dtraction), cmp_lemke.map(|c| c.state_mismatches));
            let w = &run.work;
            let opt = |v: Option<u64>| v.map(|v| v.to_string()).unwrap_or_default();
            writeln!(
                cmp,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{:e},{:e},{:e}",
                s.name,
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
                run.polish_change.map(|v| format!("{v:e}")).unwrap_or_default(),
                r.diagnostics.flexibility_asymmetry,
                run.timing_s.solve,
                run.timing_s.total
            )
            .unwrap();
            writeln!(
                cmp_md,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.4} |",
                s.name,
                run.solver,
                run.status,
                run.problem_size,
                w.long(),
                fmt_e(run.residuals.map(|x| x.max())),
                fmt_e(d),
                mism.map(|m| m.to_string()).unwrap_or_else(|| "–".into()),
                fmt_e(run.polish_change),
                run.timing_s.solve
            )
            .unwrap();
        }
        reports.insert(s.name.clone(), r);
    }
    write_atomic(&out.join("solver-comparison.csv"), &cmp)?;
    Ok((reports, cmp_md))
}

/// Accuracy against time for one error measure of a sweep: the plot, the Pareto front and the cheapest
/// configuration per accuracy target, appended to `md`.
fn accuracy_section(
    name: &str,
    err: &str,
    label: &str,
    solved: &[&BTreeMap<String, String>],
    out: &Path,
    md: &mut String,
    plots: &mut Vec<(String, String)>,
) -> Result<()> {
    // Accuracy against time.
    let mut chart = Chart::new(format!("{name}: {label} against total time"), "total time [s]", label).log_x().log_y();
    for (k, pts) in grouped(solved, "t_total", err) {
        chart = chart.add(Series::new(k, pts, Style::LineMarkers));
    }
    let file = format!("figures/{name}-{err}-vs-time.svg");
    chart.write(&out.join(&file)).map_err(plot_err)?;
    plots.push((format!("{name}: {label} against time"), file.clone()));
    writeln!(md, "![{label} against time]({file})\n").unwrap();
    // Pareto front and cheapest configurations.
    let front = pareto(solved, err);
    writeln!(md, "Pareto front ({label} against total time): ").unwrap();
    writeln!(md, "\n| configuration | contact elements | error | total time [s] |\n|---|---|---|---|").unwrap();
    for r in &front {
        writeln!(
            md,
            "| {} | {} | {:.2e} | {:.4} |",
            config(r),
            cell(r, "contact_elements"),
            num(r, err).unwrap(),
            num(r, "t_total").unwrap()
        )
        .unwrap();
    }
    writeln!(md, "\nCheapest configuration reaching each accuracy ({label}):\n").unwrap();
    writeln!(md, "| target | configuration | contact elements | error | total time [s] |\n|---|---|---|---|---|")
        .unwrap();
    for target in [1e-2, 1e-3, 1e-4] {
        let best = front.iter().find(|r| num(r, err).unwrap() <= target);
        match best {
            Some(r) => writeln!(
                md,
                "| {:.0e} | {} | {} | {:.2e} | {:.4} |",
                target,
                config(r),
                cell(r, "contact_elements"),
                num(r, err).unwrap(),
                num(r, "t_total").unwrap()
            ),
            None => writeln!(
                md,
                "| {target:.0e} | not reached by any configuration of this sweep (smallest error {:.2e}) | | | |",
                front.last().map(|r| num(r, err).unwrap()).unwrap_or(f64::NAN)
            ),
        }
        .unwrap();
    }
    writeln!(md).unwrap();
    Ok(())
}

/// Run every reference sweep: CSVs, plots and the Markdown sections. Returns (Markdown, plots as (title, file)).
fn sweeps(opts: &ReportOptions) -> Result<(String, Vec<(String, String)>)> {
    let out = &opts.out;
    let mut sweep_md = String::new();
    let mut plots: Vec<(String, String)> = Vec::new();
    for spec in toml_files(&opts.reference.join("sweeps"))? {
        let name = spec.file_stem().unwrap().to_string_lossy().into_owned();
        let csv_path = out.join("sweeps").join(format!("{name}.csv"));
        crate::sweep::run_sweep(&spec, None, &csv_path, opts.progress)?;
        let t = Table::read(&csv_path)?;
        let solved: Vec<&BTreeMap<String, String>> = t.rows.iter().filter(|r| cell(r, "status") == "solved").collect();
        writeln!(sweep_md, "\n### Sweep `{name}` ([CSV](sweeps/{name}.csv), {} rows)\n", t.rows.len()).unwrap();
        let errs: Vec<(&str, &str)> = if solved.iter().any(|r| num(r, "hertz_l2_err").is_some()) {
            vec![
                ("hertz_l2_err", "L2 pressure error vs Hertz"),
                ("hertz_a_err", "half-width error vs Hertz"),
                ("hertz_p0_err", "peak-pressure error vs Hertz"),
            ]
        } else {
            vec![("cm_shear_err", "shear error vs Cattaneo–Mindlin (/μp0, away from ±a, ±c)")]
        };
        for (err, label) in &errs {
            accuracy_section(&name, err, label, &solved, out, &mut sweep_md, &mut plots)?;
        }
        // Convergence under refinement, with observed orders (direct solvers, or the tightest tolerance).
        let (err, label) = errs[0];
        let mut chart = Chart::new(format!("{name}: {label} against mesh"), "contact elements", label).log_x().log_y();
        writeln!(sweep_md, "Observed orders of convergence ({label}, from the two finest meshes):\n").unwrap();
        writeln!(sweep_md, "| configuration | order | finest error |\n|---|---|---|").unwrap();
        for (k, pts) in grouped(&solved, "contact_elements", err) {
            writeln!(
                sweep_md,
                "| {k} | {} | {} |",
                fmt_e(order(&pts)).replace("e0", ""),
                fmt_e(pts.last().map(|p| p.1))
            )
            .unwrap();
            chart = chart.add(Series::new(k, pts, Style::LineMarkers));
        }
        let file = format!("figures/{name}-{err}-vs-mesh.svg");
        chart.write(&out.join(&file)).map_err(plot_err)?;
        plots.push((format!("{name}: {label} against mesh"), file.clone()));
        writeln!(sweep_md, "\n![{label} against mesh]({file})").unwrap();
    }
    Ok((sweep_md, plots))
}

fn lemke_of<'a>(reports: &'a BTreeMap<String, Report>, name: &str) -> Option<&'a SolverRun> {
    reports.get(name)?.runs.iter().find(|r| r.solver == "lemke" && r.contact.is_some())
}

/// The seed's figures from the reference scenes' Lemke runs. Returns (title, file) pairs.
fn seed_figures(reports: &BTreeMap<String, Report>, dir: &Path) -> Result<Vec<(String, String)>> {
    let mut out = Vec::new();
    let mut save = |chart: Chart, file: &str, title: &str| -> Result<()> {
        chart.write(&dir.join(file)).map_err(plot_err)?;
        out.push((title.to_string(), format!("figures/{file}")));
        Ok(())
    };
    // Fig. 6: frictionless pressure, constant and quadratic elements, against Hertz.
    if let (Some(c), Some(q)) = (lemke_of(reports, "seed-fig6-constant"), lemke_of(reports, "seed-fig6-quadratic")) {
        let h = reports["seed-fig6-constant"].references.hertz;
        let mut chart = Chart::new("Seed Fig. 6: frictionless pressure against Hertz", "x", "pressure p")
            .add(Series::new("constant elements", c.nodes.iter().map(|n| (n.x, n.pressure)).collect(), Style::Markers))
            .add(Series::new(
                "quadratic elements",
                q.nodes.iter().map(|n| (n.x, n.pressure)).collect(),
                Style::Markers,
            ));
        if let Some(h) = h {
            let xs: Vec<f64> = (0..=200).map(|i| -1.5 * h.half_width + 3.0 * h.half_width * i as f64 / 200.0).collect();
            chart = chart.add(Series::new("Hertz", xs.iter().map(|&x| (x, h.pressure(x))).collect(), Style::Dashed));
        }
        save(
            chart,
            "seed-fig06-pressure.svg",
            "Fig. 6: frictionless pressure, constant and quadratic elements, and Hertz",
        )?;
    }
    // Figs. 7–9 / 12–13 / 16–17: tractions; Figs. 10 / 14 / 18: slip velocity; Figs. 11 / 15: state maps.
    let groups: [(&str, &[(&str, &str)]); 3] = [
        (
            "Figs. 7–10 (normal displacement)",
            &[("seed-fig07-mu002", "μ = 0.02"), ("seed-fig08-mu01", "μ = 0.1"), ("seed-fig09-mu05", "μ = 0.5")],
        ),
        (
            "Figs. 11–14 (normal and tangential displacement)",
            &[("seed-fig12-mu01", "μ = 0.1"), ("seed-fig13-mu03", "μ = 0.3")],
        ),
        ("Figs. 15–18 (loading, |Q/P| = 0.1)", &[("seed-fig16-mu01", "μ = 0.1"), ("seed-fig17-mu07", "μ = 0.7")]),
    ];
    for (gi, (title, members)) in groups.iter().enumerate() {
        let tag = ["07-10", "11-14", "15-18"][gi];
        let mut tr = Chart::new(format!("Seed {title}: tractions"), "x", "traction (p solid markers, q lines)");
        let mut sv = Chart::new(format!("Seed {title}: slip velocity s_t* (eq. 12)"), "x", "s_t*");
        let mut st = Chart::new(format!("Seed {title}: node states (2 stick, 1 slip, 0 separated)"), "x", "state");
        let mut any = false;
        for (k, (name, label)) in members.iter().enumerate() {
            let Some(l) = lemke_of(reports, name) else { continue };
            if !any {
                // Hertz's pressure at this scene's load, the analytic curve the seed compares its tractions with.
                let sc = &reports[*name].scene;
                if let Some(res) = l.resultants.filter(|r| r.normal > 0.0) {
                    let w = &sc.wheel;
                    let h = crate::hertz::Hertz::new(w.radius, w.youngs_modulus, w.poisson_ratio, res.normal);
                    let xs: Vec<f64> =
                        (0..=200).map(|i| -1.5 * h.half_width + 3.0 * h.half_width * i as f64 / 200.0).collect();
                    tr = tr.add(Series::new(
                        format!("Hertz p at P = {:.4e}", res.normal),
                        xs.iter().map(|&x| (x, h.pressure(x))).collect(),
                        Style::Dashed,
                    ));
                }
            }
            any = true;
            if k == 0 || gi > 0 {
                tr = tr.add(Series::new(
                    format!("p, {label}"),
                    l.nodes.iter().map(|n| (n.x, n.pressure)).collect(),
                    Style::Markers,
                ));
            }
            tr = tr.add(Series::new(
                format!("q, {label}"),
                l.nodes.iter().map(|n| (n.x, n.shear)).collect(),
                Style::LineMarkers,
            ));
            sv = sv.add(Series::new(
                label.to_string(),
                l.nodes.iter().filter_map(|n| n.slip_velocity.map(|v| (n.x, v))).collect(),
                Style::LineMarkers,
            ));
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
        if any {
            save(tr, &format!("seed-fig{tag}-tractions.svg"), &format!("{title}: pressure and shear"))?;
            save(sv, &format!("seed-fig{tag}-slip-velocity.svg"), &format!("{title}: slip velocity"))?;
            save(st, &format!("seed-fig{tag}-states.svg"), &format!("{title}: stick / slip / separation"))?;
        }
    }
    Ok(out)
}
