//! `rollbem plot TABLE.csv`: figures of the user's own tables.
//!
//! - A **load path's CSV** (`rollbem run SCENE --path-csv FILE`): the tangential force against the rigid shift (the
//!   hysteresis loop, `STEM-loop.svg`), the same loop less its chord (`STEM-loop-opened.svg`: the straight chord
//!   through the tips of the first solver's loop subtracted from every curve, so that a hysteresis thin beside the
//!   elastic compliance shows; the figure a result document's path gets, drawn by the same code), the stick zone's
//!   half-width and the approach against the substep, one series per solver. With `--scene SCENE.toml` (the scene
//!   that wrote it), Mindlin–Deresiewicz's loop and stick zone are drawn beside them where that theory applies (the
//!   half-plane model with β = 0 — against a rigid flat or against an elastic half-plane of a β = 0 pair, steel on
//!   steel — P held, Q cycled ±Q*). An approach held along the path is drawn as the constant it is, its axis saying
//!   so, rather than its round-off.
//! - A **sweep's CSV** (`rollbem sweep`): the figures of its analysis (`--analysis`, as the sweep spec names it:
//!   `creep_curve` draws Q/(μP) against ξR/(μa) with Carter's curve; `accuracy` the errors against the mesh and
//!   against time; `finite_vs_half_plane` the relative differences against a/R; `finite_bodies` a twin disc's and a
//!   pin in a bore's departures from Hertz and the pin-bore reference; `table`, a 3D half-space sweep's, its Pareto
//!   fronts against time per error measure). The analysis is not guessed from the rows: a sweep CSV without
//!   `--analysis` is refused with the choices, and one whose analysis does not fit its rows (a 2D analysis on 3D
//!   rows, `table` on 2D rows) is refused before anything is drawn.
//!
//! Files are written into the output folder as `STEM-WHAT.svg` (STEM the table's file name without `.csv`).

use super::paths::{loop_less_chord, Curve};
use super::plot_result::Plotted;
use super::{Figs, SweepFigures};
use crate::error::{Error, Result};
use crate::plot::{Chart, Series, Style};
use crate::scene::Scene;
use crate::sweep::Analysis;
use crate::theory::TangentialPath;
use std::collections::BTreeMap;
use std::path::Path;

/// Draw the figures of a CSV table (see the module docs) into `out`.
pub fn plot_csv(csv: &Path, out: &Path, analysis: Option<Analysis>, scene: Option<&Scene>) -> Result<Plotted> {
    let mut rd =
        csv::Reader::from_path(csv).map_err(|e| Error::Parse { path: csv.to_path_buf(), message: e.to_string() })?;
    let header: Vec<String> = rd
        .headers()
        .map_err(|e| Error::Parse { path: csv.to_path_buf(), message: e.to_string() })?
        .iter()
        .map(str::to_string)
        .collect();
    let stem = csv.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "table".into());
    std::fs::create_dir_all(out).map_err(|source| Error::Write { path: out.to_path_buf(), source })?;
    match header.first().map(String::as_str) {
        Some("step") => path_table(csv, &stem, out, scene),
        Some("case") => {
            let Some(analysis) = analysis else {
                return Err(Error::Invalid {
                    path: csv.to_path_buf(),
                    field: "--analysis".into(),
                    message: "a sweep's CSV does not say what the sweep is: give --analysis creep_curve, accuracy, \
                              finite_vs_half_plane, finite_bodies or table (as its spec's `analysis`)"
                        .into(),
                });
            };
            let mut figs = Figs::new(out, "");
            SweepFigures::from_csv(csv, &stem)?.draw(analysis, &mut figs)?;
            Ok(Plotted { files: figs.list.into_iter().map(|(_, f)| out.join(f)).collect(), skipped: Vec::new() })
        }
        _ => Err(Error::Parse {
            path: csv.to_path_buf(),
            message: "neither a load path's CSV (first column `step`) nor a sweep's (first column `case`)".into(),
        }),
    }
}

/// One row of a load path's CSV, as far as the figures need it.
struct PathRow {
    step: usize,
    solver: String,
    q: Option<f64>,
    shift: Option<f64>,
    approach: Option<f64>,
    stick: Option<(f64, f64)>,
}

/// Read a load path's CSV.
fn read_path(csv: &Path) -> Result<Vec<PathRow>> {
    let bad = |m: String| Error::Parse { path: csv.to_path_buf(), message: m };
    let mut rd = csv::Reader::from_path(csv).map_err(|e| bad(e.to_string()))?;
    let header = rd.headers().map_err(|e| bad(e.to_string()))?.clone();
    let col = |name: &str| {
        header.iter().position(|h| h == name).ok_or_else(|| bad(format!("not a load path's CSV: no `{name}` column")))
    };
    let (step, solver, q, shift, approach, left, right) = (
        col("step")?,
        col("solver")?,
        col("Q")?,
        col("shift")?,
        col("approach")?,
        col("stick_left")?,
        col("stick_right")?,
    );
    let mut rows = Vec::new();
    for (k, rec) in rd.records().enumerate() {
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        let num = |i: usize| -> Result<Option<f64>> {
            match rec.get(i).unwrap_or("") {
                "" => Ok(None),
                c => c.parse().map(Some).map_err(|_| bad(format!("line {}: `{c}` is not a number", k + 2))),
            }
        };
        let step = rec.get(step).unwrap_or("").parse().map_err(|_| bad(format!("line {}: no step number", k + 2)))?;
        let stick = match (num(left)?, num(right)?) {
            (Some(l), Some(r)) => Some((l, r)),
            _ => None,
        };
        rows.push(PathRow {
            step,
            solver: rec.get(solver).unwrap_or("").to_string(),
            q: num(q)?,
            shift: num(shift)?,
            approach: num(approach)?,
            stick,
        });
    }
    Ok(rows)
}

/// The load path's figures.
fn path_table(csv: &Path, stem: &str, out: &Path, scene: Option<&Scene>) -> Result<Plotted> {
    let rows = read_path(csv)?;
    let mut by_solver: BTreeMap<&str, Vec<(usize, &PathRow)>> = BTreeMap::new();
    for r in &rows {
        let runs = by_solver.entry(r.solver.as_str()).or_default();
        runs.push((runs.len() + 1, r));
    }
    let md = scene.and_then(|s| Some((s, super::md_pattern(s)?)));
    let (lu, fu) = match scene.and_then(Scene::units) {
        Some(u) => {
            let u = super::Units::parse(Some(u));
            (u.length.clone(), u.line_load())
        }
        None => ("L".to_string(), "F/L".to_string()),
    };
    let mut loop_ = Chart::new(format!("{stem}: tangential force against rigid shift"), "rigid shift δ_T", "Q")
        .x_unit(lu.clone())
        .y_unit(fu.clone());
    let mut stick = Chart::new(format!("{stem}: stick zone along the path"), "substep", "stick half-width")
        .x_unit("1")
        .y_unit(lu.clone());
    let mut approach = Chart::new(format!("{stem}: approach along the path"), "substep", "approach d_N")
        .x_unit("1")
        .y_unit(lu.clone());
    // The loops, also drawn less their chord below.
    let mut loops: Vec<Curve> = Vec::new();
    for (solver, runs) in &by_solver {
        let pts: Vec<(f64, f64)> = runs.iter().filter_map(|(_, r)| Some((r.shift?, r.q?))).collect();
        loops.push((solver.to_string(), pts.clone(), Style::LineMarkers));
        loop_ = loop_.add(Series::new(*solver, pts, Style::LineMarkers));
        let c: Vec<(f64, f64)> =
            runs.iter().filter_map(|(k, r)| r.stick.map(|(l, rr)| (*k as f64, 0.5 * (rr - l)))).collect();
        stick = stick.add(Series::new(*solver, c, Style::Markers));
        let d: Vec<(f64, f64)> = runs.iter().filter_map(|(k, r)| Some((*k as f64, r.approach?))).collect();
        approach = approach.add(Series::new(*solver, d, Style::LineMarkers));
    }
    if let Some((s, (p, q_star))) = md {
        let curve = super::md_curve(s, p, q_star);
        loops.push(("Mindlin–Deresiewicz (2D)".into(), curve.clone(), Style::Dashed));
        loop_ = loop_.add(Series::new("Mindlin–Deresiewicz (2D)", curve, Style::Dashed));
        if let Some((_, runs)) = by_solver.iter().next() {
            let h = crate::references::hertz_at(s, p);
            let c: Vec<(f64, f64)> = runs
                .iter()
                .filter(|(_, r)| r.step >= 1)
                .filter_map(|(k, r)| {
                    let branch = match r.step {
                        1 => TangentialPath::Loading,
                        n if n % 2 == 0 => TangentialPath::Unloading { q_star },
                        _ => TangentialPath::Reloading { q_star },
                    };
                    Some((*k as f64, crate::theory::md_stick_half_width(&h, s.friction(), branch, r.q?)))
                })
                .collect();
            stick = stick.add(Series::new("Mindlin–Deresiewicz: current branch", c, Style::Dashed));
        }
    }
    // The chord through the tips of the first solver's loop (the CSV's rows are in the scene's solver order).
    let first = rows.first().map_or("", |r| r.solver.as_str());
    let tips = loops.iter().find(|(label, ..)| label == first).map_or(&[][..], |c| &c.1[..]);
    let opened = loop_less_chord(stem, tips, &loops, &lu, &fu);
    let mut figs = Figs::new(out, "");
    figs.save(&loop_, &format!("{stem}-loop.svg"), "loop".into())?;
    if let Some((chart, _)) = &opened {
        figs.save(chart, &format!("{stem}-loop-opened.svg"), "loop less its chord".into())?;
    }
    figs.save(&stick, &format!("{stem}-stick-zone.svg"), "stick zone".into())?;
    figs.save(&approach, &format!("{stem}-approach.svg"), "approach".into())?;
    let mut skipped = match (scene, md) {
        (Some(_), None) => {
            vec!["Mindlin–Deresiewicz: the scene is not of its pattern (half-plane, β = 0, P then ±Q*)".into()]
        }
        (None, _) => vec!["theory: no --scene given".into()],
        _ => Vec::new(),
    };
    if opened.is_none() {
        skipped.push("loop less its chord: Q does not vary along the path".into());
    }
    Ok(Plotted { files: figs.list.into_iter().map(|(_, f)| out.join(f)).collect(), skipped })
}
