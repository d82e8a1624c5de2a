//! `rollbem plot RESULT.json [--out DIR]`: the figures of a result document written by `rollbem run --json`.
//!
//! Per solver run (`runs[]`, for a load path the runs at its end): the surface tractions p and q against x
//! (`STEM.SOLVER.tractions.svg`) with Hertz's pressure when the document carries it (`references.hertz`); the node
//! states against x (`STEM.SOLVER.states.svg`: separated / contact or slip / stick); the slip velocity against x
//! when the scene rolls (`STEM.SOLVER.slip_velocity.svg`); and, when the run has subsurface stresses ([`crate::stresses`]), one filled contour
//! map per quantity (`STEM.SOLVER.QUANTITY.svg`, and `STEM.SOLVER.counter_body.QUANTITY.svg` for an elastic
//! counter-body's field) with the maximum (largest |value|, as in the result document)
//! marked and captioned. STEM is the result file's name without `.json`; DIR defaults to the result file's folder.
//! A field written to a CSV file beside the document (large grids) is read from there.
//!
//! The axes carry the scene's units: its `[stresses]` `length_unit` and `stress_unit` when given, else the length
//! and stress of its `units` label ("N, mm, MPa": force, length, stress), else the words "length unit" and "stress
//! unit" (rollbem's units are the user's, consistent, and a scene need not name
//! them). Depth is drawn downward, x and depth to the same scale when the grid's aspect ratio is moderate.
//!
//! The document is read typed ([`Report::read`]: its schema version is checked, so a document of another layout is
//! refused with a message rather than drawn wrongly). Every file is written by [`crate::io::write_output`].

use crate::error::{Error, Result};
use crate::plot::{Chart, ContourMap, Field, Series, Style};
use crate::post::{NodeResult, NodeState};
use crate::results::{Report, SolverRun};
use crate::scene::StressQuantity;
use crate::status::Status;
use crate::stresses::StressResult;
use std::path::{Path, PathBuf};

/// What `plot` wrote, and what it could not draw (and why).
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct Plotted {
    /// Files written.
    pub files: Vec<PathBuf>,
    /// Figures left out, with the reason (e.g. a run that did not solve has no tractions).
    pub skipped: Vec<String>,
}

/// The label of a quantity on a colour bar.
fn label(q: StressQuantity) -> &'static str {
    match q {
        StressQuantity::Sxx => "σ_xx",
        StressQuantity::Szz => "σ_zz",
        StressQuantity::Txz => "τ_xz",
        StressQuantity::Syy => "σ_yy = ν(σ_xx + σ_zz)",
        StressQuantity::PrincipalShear => "principal shear τ₁",
        StressQuantity::VonMises => "von Mises stress",
        StressQuantity::OrthogonalShear => "orthogonal shear τ_xz",
    }
}

/// `v` to four significant digits, in positional notation for magnitudes 1e-3 to 1e6 (scientific beyond).
fn sig4(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..6).contains(&e) {
        format!("{:.*}", (3 - e).max(0) as usize, v)
    } else {
        format!("{v:.3e}")
    }
}

/// A malformed document: an input error naming the file and the key.
fn bad(path: &Path, message: String) -> Error {
    Error::Parse { path: path.to_path_buf(), message }
}

fn plot_err(e: crate::plot::PlotError) -> Error {
    Error::Output { what: "a plot".into(), message: e.to_string() }
}

/// What every figure of a document needs: where to write, the file stem, the scene's name, units and Hertz.
struct Context {
    out: PathBuf,
    dir: PathBuf,
    json: PathBuf,
    stem: String,
    name: String,
    length_unit: String,
    stress_unit: String,
    hertz: Option<crate::theory::Hertz2D>,
}

/// Draw the figures of the result document `json` into `out` (default: its folder); see the module docs.
pub fn plot_result(json: &Path, out: Option<&Path>) -> Result<Plotted> {
    let report = Report::read(json)?;
    let dir = json.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new(".")).to_path_buf();
    let out = out.map(Path::to_path_buf).unwrap_or_else(|| dir.clone());
    std::fs::create_dir_all(&out).map_err(|source| Error::Write { path: out.clone(), source })?;
    let stem = json.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "result".into());
    let scene = &report.scene;
    // The scene's `units` label, "force, length, stress"; `[stresses]` may name the length and stress units.
    let label_units: Vec<String> =
        scene.units().map(|u| u.split(',').map(|p| p.trim().to_string()).collect()).unwrap_or_default();
    let from_label =
        |k: usize, default: &str| label_units.get(k).filter(|u| !u.is_empty()).cloned().unwrap_or(default.into());
    let spec = scene.stresses();
    let ctx = Context {
        out,
        dir,
        json: json.to_path_buf(),
        stem,
        name: scene.name().to_string(),
        length_unit: spec.and_then(|s| s.length_unit.clone()).unwrap_or_else(|| from_label(1, "length unit")),
        stress_unit: spec.and_then(|s| s.stress_unit.clone()).unwrap_or_else(|| from_label(2, "stress unit")),
        hertz: report.references.hertz.filter(|h| h.a > 0.0 && h.p0 > 0.0),
    };
    let mut done = Plotted::default();
    for run in &report.runs {
        run_figures(&ctx, run, &mut done)?;
    }
    if !report.steps.is_empty() {
        // A load path: the loop (or the approach to steady rolling) and the stick zone along it, with the theory
        // where it applies, as the report draws them.
        let mut figs = super::Figs::new(&ctx.out, "");
        super::path_figures(&ctx.stem, &report, &mut String::new(), &mut figs)?;
        done.files.extend(figs.list.into_iter().map(|(_, f)| ctx.out.join(f)));
    }
    Ok(done)
}

/// The figures of one run: tractions, node states, slip velocity, stress maps.
fn run_figures(ctx: &Context, run: &SolverRun, done: &mut Plotted) -> Result<()> {
    let solver = run.solver.name();
    let series = |f: fn(&NodeResult) -> Option<f64>| -> Vec<(f64, f64)> {
        run.nodes.iter().filter_map(|n| Some((n.x, f(n)?))).collect()
    };
    let (p, q) = (series(|n| Some(n.pressure)), series(|n| Some(n.shear)));
    // A run judged not an answer (contact at the zone's edge, kinematics out of range) keeps its nodes as
    // evidence: its titles say so.
    let verdict =
        if run.status == Status::Solved { String::new() } else { format!(" ({}: not an answer)", run.status) };
    if p.is_empty() {
        done.skipped.push(format!("{solver}: no tractions (status \"{}\")", run.status));
        return Ok(());
    }
    let (name, lu) = (&ctx.name, ctx.length_unit.as_str());
    let mut chart = Chart::new(format!("{name}, {solver}: surface tractions on the wheel{verdict}"), "x", "traction")
        .x_unit(lu)
        .y_unit(ctx.stress_unit.as_str())
        .add(Series::new("pressure p", p, Style::LineMarkers))
        .add(Series::new("shear q", q, Style::LineMarkers));
    if let Some(h) = ctx.hertz {
        let a = h.a;
        let curve = (0..=200).map(|i| -a + 2.0 * a * f64::from(i) / 200.0).map(|x| (x, h.pressure(x))).collect();
        chart = chart.add(Series::new("Hertz pressure", curve, Style::Dashed));
    }
    write(ctx, chart, &format!("{solver}.tractions"), done)?;
    // Node states on a categorical axis.
    let states: Vec<(f64, f64)> = run
        .nodes
        .iter()
        .map(|n| {
            let y = match n.state {
                NodeState::Separated => 0.0,
                NodeState::Slip | NodeState::Contact => 1.0,
                NodeState::Stick => 2.0,
            };
            (n.x, y)
        })
        .collect();
    let chart = Chart::new(format!("{name}, {solver}: node states{verdict}"), "x", "state")
        .x_unit(lu)
        .categories_y(&["separated", "contact / slip", "stick"])
        .add(Series::new(solver, states, Style::Markers));
    write(ctx, chart, &format!("{solver}.states"), done)?;
    let sv = series(|n| n.slip_velocity);
    if !sv.is_empty() {
        let chart = Chart::new(format!("{name}, {solver}: slip velocity{verdict}"), "x", "slip velocity s")
            .x_unit(lu)
            .y_unit("1")
            .add(Series::new(solver, sv, Style::LineMarkers));
        write(ctx, chart, &format!("{solver}.slip_velocity"), done)?;
    }
    if let Some(st) = &run.stresses {
        stress_maps(ctx, solver, st, done)?;
    }
    if let Some(st) = &run.counter_body_stresses {
        stress_maps(ctx, solver, st, done)?;
    }
    Ok(())
}

/// Write a chart as `STEM.WHAT.svg` in the output folder.
fn write(ctx: &Context, chart: Chart, what: &str, done: &mut Plotted) -> Result<()> {
    let file = ctx.out.join(format!("{}.{what}.svg", ctx.stem));
    chart.write(&file).map_err(plot_err)?;
    done.files.push(file);
    Ok(())
}

/// One filled contour map per quantity of a run's stresses, with its maximum marked.
fn stress_maps(ctx: &Context, solver: &str, st: &StressResult, done: &mut Plotted) -> Result<()> {
    let maps = StressMaps::read(&ctx.json, &ctx.dir, st)?;
    let (name, lu, su) = (&ctx.name, ctx.length_unit.as_str(), ctx.stress_unit.as_str());
    for (q, values) in &maps.values {
        let Some(Some(max)) = st.maxima.iter().find(|(m, _)| m == q).map(|(_, m)| *m) else {
            done.skipped.push(format!("{solver}: {}: no point of the grid has a value", q.name()));
            continue;
        };
        let field = Field::new(maps.points[0], maps.points[1], values.clone(), maps.x, maps.depth);
        let caption = if matches!(q, StressQuantity::PrincipalShear | StressQuantity::VonMises) {
            format!("max {} = {} {su}", label(*q), sig4(max.value))
        } else {
            format!("largest |{}|: {} {su}", label(*q), sig4(max.value))
        };
        let body = if st.body == "counter_body" { "the counter-body" } else { "the wheel" };
        let mut map = ContourMap::new(format!("{name}, {solver}: {} in {body}", label(*q)), field)
            .x_axis("x", lu)
            .depth_axis("depth", lu)
            .value_axis(label(*q), su)
            .bands(12)
            .size(960, 600)
            .marker(max.x, max.depth, caption);
        let aspect = (maps.depth.1 - maps.depth.0) / (maps.x.1 - maps.x.0);
        if (0.2..=5.0).contains(&aspect) {
            map = map.equal_aspect();
        }
        let tag = if st.body == "counter_body" { ".counter_body" } else { "" };
        let file = ctx.out.join(format!("{}.{solver}{tag}.{}.svg", ctx.stem, q.name()));
        map.write(&file).map_err(plot_err)?;
        done.files.push(file);
    }
    Ok(())
}

/// A run's stress fields as the maps need them: the grid and, per quantity, the values (NaN where refused).
struct StressMaps {
    points: [usize; 2],
    x: (f64, f64),
    depth: (f64, f64),
    values: Vec<(StressQuantity, Vec<f64>)>,
}

impl StressMaps {
    /// The maps of a run's stresses in the document `json` (folder `dir`): the inline field, or the CSV file it
    /// names.
    fn read(json: &Path, dir: &Path, st: &StressResult) -> Result<StressMaps> {
        let g = st.grid;
        let n = g.len();
        let values = match (&st.csv, &st.values) {
            (Some(file), _) => read_csv(&dir.join(file), &st.quantities, n)?,
            (None, Some(field)) => st
                .quantities
                .iter()
                .map(|&q| {
                    let v = field.values.get(q.name()).filter(|v| v.len() == n).ok_or_else(|| {
                        bad(json, format!("stresses.field.values.{}: missing or not one value per point", q.name()))
                    })?;
                    Ok((q, v.iter().map(|v| v.unwrap_or(f64::NAN)).collect()))
                })
                .collect::<Result<Vec<_>>>()?,
            (None, None) => return Err(bad(json, "stresses: neither an inline field nor a CSV file".into())),
        };
        Ok(StressMaps { points: g.points, x: (g.x[0], g.x[1]), depth: (g.depth[0], g.depth[1]), values })
    }
}

/// The quantities' columns of a stress CSV ([`crate::stresses::StressField::csv`]); empty cells are NaN.
fn read_csv(path: &Path, quantities: &[StressQuantity], n: usize) -> Result<Vec<(StressQuantity, Vec<f64>)>> {
    let mut rd = csv::Reader::from_path(path)
        .map_err(|e| bad(path, format!("cannot read the stress field named by the result document: {e}")))?;
    let header = rd.headers().map_err(|e| bad(path, e.to_string()))?.clone();
    let mut cols = Vec::new();
    for &q in quantities {
        let c =
            header.iter().position(|h| h == q.name()).ok_or_else(|| bad(path, format!("no column `{}`", q.name())))?;
        cols.push((q, c, Vec::with_capacity(n)));
    }
    for (line, rec) in rd.records().enumerate() {
        let rec = rec.map_err(|e| bad(path, e.to_string()))?;
        for (q, c, v) in &mut cols {
            let cell = rec.get(*c).unwrap_or("");
            let value = if cell.is_empty() {
                f64::NAN
            } else {
                cell.parse::<f64>()
                    .map_err(|_| bad(path, format!("row {}: `{}` is not a number ({})", line + 2, cell, q.name())))?
            };
            v.push(value);
        }
    }
    cols.into_iter()
        .map(|(q, _, v)| {
            if v.len() == n {
                Ok((q, v))
            } else {
                Err(bad(path, format!("{} rows for a grid of {n} points", v.len())))
            }
        })
        .collect()
}
