//! The seed's rolling formulation against steady-state rolling (issue 10, item 6), on every reference scene with
//! `[rolling] mode = "seed"` (the seed's Figs. 10, 14, 18).
//!
//! The seed solves a static frictional problem and evaluates the slip velocity afterwards (eq. 12); the steady
//! formulation makes that slip velocity the unknown of Coulomb's law. The steady counterpart of a seed scene is the
//! same mesh, material, friction and normal drive with `mode = "steady"` and:
//! - when the seed scene prescribes a tangential load (Figs. 15–18): that load, with the creepage computed;
//! - otherwise (Figs. 7–14): the seed scene's creepage, with the tangential force computed. A seed tangential shift
//!   (Figs. 11–14) has no steady counterpart — in steady rolling the tangential rigid motion is the creepage — and
//!   is dropped; the table says so.
//!
//! Counted per run (from [`crate::post::RollingResult`], evaluated by post-processing, not by the solver): sticking
//! nodes whose slip velocity is not zero, and slipping nodes whose shear does not oppose their slip velocity. Both
//! are inconsistencies of Coulomb's law; a steady solution has none.

use super::table::Units;
use super::{lemke_run as lemke, plot_err, Figures};
use crate::error::Result;
use crate::pipeline::run_scene;
use crate::plot::{Chart, Series, Style};
use crate::post::NodeState;
use crate::results::{Report, SolverRun};
use crate::scene::{RollingMode, Scene};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// The steady counterpart of a seed rolling scene, and how it is driven (see the module docs).
fn steady_counterpart(s: &Scene) -> Result<Option<(Scene, &'static str)>> {
    if !matches!(s.rolling(), Some(crate::scene::Rolling::Seed { .. })) {
        return Ok(None);
    }
    let d = s.document();
    let how = if d.drive.tangential_load.is_some() {
        "Q prescribed, ξ computed"
    } else if d.drive.tangential_shift.is_some() {
        "ξ prescribed, seed's shift dropped"
    } else {
        "ξ prescribed"
    };
    let t = s.edit(|t| {
        let q = t.drive.tangential_load.is_some();
        t.drive.tangential_shift = None;
        // Steady rolling turns the wheel continuously: its rotation is the creepage's, not a drive.
        t.drive.rotation = None;
        t.drive.moment = None;
        if let Some(r) = t.rolling.as_mut() {
            r.mode = RollingMode::Steady;
            if q {
                r.creepage = None;
            }
        }
        t.name = format!("{}-steady", t.name);
    })?;
    Ok(Some((t, how)))
}

fn stick_range(run: &SolverRun) -> String {
    let xs: Vec<f64> = run.nodes.iter().filter(|n| n.state == NodeState::Stick).map(|n| n.x).collect();
    match (xs.iter().copied().reduce(f64::min), xs.iter().copied().reduce(f64::max)) {
        (Some(l), Some(r)) => format!("{} on [{l:.4}, {r:.4}]", xs.len()),
        _ => "none".into(),
    }
}

/// The tangential force of a run ("–" without one).
fn force(r: &SolverRun) -> String {
    r.resultants.map(|f| format!("{:.4e}", f.tangential)).unwrap_or_else(|| "–".into())
}

/// The table row of a seed scene and its solved steady counterpart.
fn compared_row(name: &str, rep: &Report, how: &str, seed: &SolverRun, st: &SolverRun) -> String {
    let counts =
        |r: &SolverRun| r.rolling.as_ref().map(|x| format!("{} / {}", x.stick_nodes_moving, x.slip_nodes_not_opposed));
    let xi = |r: &SolverRun| r.rolling.as_ref().and_then(|x| x.creepage).map(|v| format!("{v:.4e}"));
    format!(
        "| {name} | {} | {how} | {} | {} | {} | {} | {} | {} | {} |\n",
        rep.scene.friction(),
        force(seed),
        force(st),
        xi(st).unwrap_or_else(|| "–".into()),
        stick_range(seed),
        stick_range(st),
        counts(seed).unwrap_or_else(|| "–".into()),
        if xi(st).is_some() {
            counts(st).unwrap_or_else(|| "–".into())
        } else {
            "not evaluable: ξ indeterminate at full slip".into()
        },
    )
}

/// Table, slip-velocity figures and the inconsistency counts; nothing when no reference scene is a seed rolling scene.
pub fn seed_vs_steady(
    reports: &BTreeMap<String, Report>,
    out: &Path,
    md: &mut String,
    figs: &mut Figures,
) -> Result<()> {
    let mut rows = String::new();
    let mut charts: BTreeMap<String, Chart> = BTreeMap::new();
    let mut any = false;
    for (name, rep) in reports {
        let Some((steady, how)) = steady_counterpart(&rep.scene)? else { continue };
        let Some(seed) = lemke(rep) else { continue };
        any = true;
        let sr = run_scene(&steady)?;
        let st = lemke(&sr);
        let units = Units::parse(rep.scene.units());
        match st {
            Some(st) => {
                rows.push_str(&compared_row(name, rep, how, seed, st));
                // The group of the seed's figures this scene belongs to: one chart per drive.
                let key = how.to_string();
                let chart = charts.entry(key.clone()).or_insert_with(|| {
                    Chart::new(format!("seed against steady: {key}"), "x", "slip velocity s")
                        .x_unit(units.length.clone())
                        .y_unit("1")
                });
                let pts = |r: &SolverRun| -> Vec<(f64, f64)> {
                    r.nodes.iter().filter_map(|n| Some((n.x, n.slip_velocity?))).collect()
                };
                let c = std::mem::replace(chart, Chart::new("", "", ""));
                *chart = c.add(Series::new(format!("{name}: seed"), pts(seed), Style::Markers)).add(Series::new(
                    format!("{name}: steady"),
                    pts(st),
                    Style::Line,
                ));
            }
            None => {
                let (status, message) = sr
                    .runs
                    .iter()
                    .find(|r| r.solver == "lemke")
                    .map(|r| (r.status.to_string(), r.explanation()))
                    .unwrap_or_else(|| ("not run".into(), "the steady counterpart has no Lemke run".into()));
                writeln!(
                    rows,
                    "| {name} | {} | {how} | {} | {status}: {message} | | | | | |",
                    rep.scene.friction(),
                    force(seed)
                )
                .unwrap();
            }
        }
    }
    if !any {
        return Ok(());
    }
    writeln!(
        md,
        "\n## The seed's rolling formulation against steady rolling\n\n\
         Each scene below solves the seed's formulation (a static problem, then the slip velocity of eq. 12) and its \
         steady counterpart (the slip velocity the unknown of Coulomb's law; same mesh, material, μ and normal drive), \
         both with Lemke. Inconsistencies are counted by post-processing: sticking nodes whose slip velocity is not \
         zero / slipping nodes whose shear does not oppose their slip velocity (relative margin \
         {:.0e} of the slip-velocity scale).\n",
        crate::tolerances::STATE_MARGIN
    )
    .unwrap();
    writeln!(
        md,
        "| scene | μ | steady drive | Q seed | Q steady | ξ steady | stick nodes, seed | stick nodes, steady | \
         inconsistencies, seed | inconsistencies, steady |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    md.push_str(&rows);
    writeln!(md).unwrap();
    for (k, (how, chart)) in charts.into_iter().enumerate() {
        let file = format!("figures/seed-vs-steady-{k}.svg");
        chart.write(&out.join(&file)).map_err(plot_err)?;
        let title = format!("seed against steady slip velocity ({how})");
        writeln!(md, "![{title}]({file})\n").unwrap();
        figs.push((title, file));
    }
    Ok(())
}
