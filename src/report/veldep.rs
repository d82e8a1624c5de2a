//! The report's section on falling friction (issue 33): CONTACT's `veldep_fric.inp` (Vollebregt & Schuttelaars
//! 2012; `reference/veldep/veldep-fric.toml`) with its friction laws of the slip velocity ([`crate::veldep`]): the
//! steady problem at CKSI = −0.001 and −0.0009999 solved from both starts (every node sticking, every node sliding),
//! beside CONTACT's own runs of the same eight cases (`reference/veldep/steady_branches.csv`), and the 50 time steps
//! of its case 4–53 beside CONTACT's printed forces (`reference/veldep/veldep_fric_cases.csv`). Computed afresh by
//! every `rollbem report` (a few seconds); skipped when the reference folder lacks these files.

use super::{Figs, Result};
use crate::error::{ArgumentError, Error};
use crate::formulation::SlipOperator;
use crate::pipeline::{run_scene, Model};
use crate::plot::{Chart, Series, Style};
use crate::scene::Scene;
use crate::veldep::transient::{roll, TransientProblem, TransientStatus};
use crate::veldep::{solve_both, solve_steady, FrictionLaw, Start, SteadyProblem, SteadyStatus};
use std::fmt::Write as _;
use std::path::Path;

/// The exponential law of veldep_fric.inp (L = 4: FKIN 0.18, FEXP1 0.12, SABSH1 100 mm/s; μ(0) = 0.3).
const EXPONENTIAL: FrictionLaw = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
/// Its commented alternative, the rational law (L = 3: FKIN 0.18, FRAT1 0.06, SABSH1 100, FRAT2 0.06, SH2 0.3162).
const RATIONAL: FrictionLaw = FrictionLaw::Rational { kinetic: 0.18, first: (0.06, 100.0), second: (0.06, 0.3162) };
/// The rolling velocity (mm/s) and μ(0) FN per unit width (N/mm).
const VELOCITY: f64 = 45_000.0;
const MU_FN: f64 = 0.3 * 3111.08;

/// A CSV of `reference/veldep/` as rows of cells (header dropped).
fn rows(path: &Path) -> Result<Vec<Vec<String>>> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
    Ok(text.lines().skip(1).map(|l| l.split(',').map(str::to_string).collect()).collect())
}

/// Append the section to `md` and its figure to `figs` when `reference/veldep/` holds the scene and CONTACT's data.
pub(super) fn section(md: &mut String, figs: &mut Figs<'_>, reference: &Path) -> Result<()> {
    let dir = reference.join("veldep");
    let (scene_path, branches_csv, cases_csv) =
        (dir.join("veldep-fric.toml"), dir.join("steady_branches.csv"), dir.join("veldep_fric_cases.csv"));
    if !(scene_path.is_file() && branches_csv.is_file() && cases_csv.is_file()) {
        return Ok(());
    }
    let scene = Scene::from_file(&scene_path)?;
    let model = Model::build(&scene)?;
    let flex = &model.built().flex;
    let run = run_scene(&scene)?.runs.into_iter().next();
    let Some(run) = run.filter(|r| r.status == crate::status::Status::Solved) else {
        let msg = "the Coulomb run of the scene did not solve";
        return Err(ArgumentError::new("report::veldep", "veldep-fric.toml", msg).into());
    };
    let Some(k_tt) = flex.k_tt.as_ref() else {
        return Err(ArgumentError::new("report::veldep", "veldep-fric.toml", "no tangential flexibility").into());
    };
    // The normal nodal forces (the normal problem does not depend on the tangential one: identical materials).
    let e = flex.scales.modulus;
    let normal: Vec<f64> = run.nodes.iter().zip(&flex.weights).map(|(n, w)| n.pressure * w / e).collect();
    let m = SlipOperator::steady(&flex.x, 1).apply_mat(k_tt);
    let force = e * flex.scales.length / MU_FN;
    writeln!(
        md,
        "\n## Falling friction: CONTACT's `veldep_fric` (Vollebregt & Schuttelaars 2012)\n\n\
         A wheel of R = 460 mm on a flat (steel, 92 elements of 0.1 mm, FN = 3 111 N/mm), V = 45 m/s, friction \
         falling with the slip velocity from μ(0) = 0.3 to 0.18 (`reference/veldep/veldep-fric.toml`, \
         `crate::veldep`). With a falling law the steady problem may have more than one solution: each case is \
         solved from every node sticking (below) and from every node sliding (above), as CONTACT's INISLP = ±1, \
         beside CONTACT's own runs of the same cases (`reference/veldep/steady_branches.csv`, written by \
         `steady_branches.sh` with our CONTACT build). FX/(μ(0)FN) and the nodes in stick:\n\n\
         | law | CKSI | start | rollbem FX/(μFN) | CONTACT | rollbem stick | CONTACT NADH | two solutions (rollbem) |\n\
         |---|---:|---|---:|---:|---:|---:|---|"
    )
    .unwrap();
    for r in rows(&branches_csv)?.iter().filter(|r| r.len() > 8 && r[8].trim() == "0.0") {
        let law = if r[1] == "rational" { RATIONAL } else { EXPONENTIAL };
        let cksi: f64 = r[2].parse().unwrap_or(f64::NAN);
        let p =
            SteadyProblem { slip_matrix: &m, normal: &normal, creepage: cksi, offset: None, velocity: VELOCITY, law };
        let b = solve_both(&p, 1e-10, 200)?;
        let (o, start) = if r[3].trim() == "1" { (&b.below, "below") } else { (&b.above, "above") };
        let fx = match o.status {
            SteadyStatus::Converged { .. } => format!("{:.4}", o.tangential.iter().sum::<f64>() * force),
            _ => format!("not converged ({:?})", o.status),
        };
        let stick = o.stick.iter().filter(|&&s| s).count();
        let two = if b.distinct { "yes" } else { "no" };
        writeln!(md, "| {} | {cksi} | {start} | {fx} | {} | {stick} | {} | {two} |", r[1], r[4], r[6]).unwrap();
    }
    transient(md, figs, &m, &normal, k_tt, flex.x[1] - flex.x[0], force, &cases_csv)
}

/// CONTACT's cases 3–53: the steady state from below, then 50 time steps at CKSI = −0.001, each from above.
#[allow(clippy::too_many_arguments)]
fn transient(
    md: &mut String,
    figs: &mut Figs<'_>,
    m: &faer::Mat<f64>,
    normal: &[f64],
    k_tt: &faer::Mat<f64>,
    dq: f64,
    force: f64,
    cases_csv: &Path,
) -> Result<()> {
    let cases = rows(cases_csv)?;
    let printed: Vec<f64> = cases.iter().skip(3).take(50).filter_map(|c| c.get(4)?.parse().ok()).collect();
    let p3 = SteadyProblem {
        slip_matrix: m,
        normal,
        creepage: -0.0009999,
        offset: None,
        velocity: VELOCITY,
        law: EXPONENTIAL,
    };
    let h3 = solve_steady(&p3, Start::Below, 1e-10, 200)?.tangential;
    let problem =
        TransientProblem { k_tt, normal, creepage: -0.001, velocity: VELOCITY, law: EXPONENTIAL, dq, direction: 1 };
    let run = roll(&problem, &h3, &[Start::Above; 50], 1e-10, 200)?;
    let ours: Vec<f64> = run.steps.iter().map(|o| o.tangential.iter().sum::<f64>() * force).collect();
    let worst = ours.iter().zip(&printed).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    let completed = run.status == TransientStatus::Completed && printed.len() == 50;
    let peaks = ours.windows(3).filter(|w| w[1] > w[0] && w[1] > w[2]).count();
    let settles = if peaks > 1 {
        format!(
            "The force does not settle: it rises and drops {peaks} times as traction peaks travel through the contact."
        )
    } else {
        format!("The force has {peaks} local maximum over the steps.")
    };
    let mut chart = Chart::new("veldep_fric: 50 time steps with falling friction", "time step", "FX/(μ(0) FN)")
        .x_unit("1")
        .y_unit("1");
    let pts = |v: &[f64]| v.iter().enumerate().map(|(k, f)| ((k + 1) as f64, *f)).collect::<Vec<_>>();
    chart = chart.add(Series::new("rollbem (crate::veldep::transient)", pts(&ours), Style::LineMarkers));
    chart = chart.add(Series::new("CONTACT's printed FX/FSTAT/FN", pts(&printed), Style::Markers));
    let file = figs.save(&chart, "veldep-fric-transient.svg", "veldep_fric: falling friction, 50 time steps".into())?;
    writeln!(
        md,
        "\nTime stepping (CONTACT's cases 4–53: Δq = 0.1 mm per step at CKSI = −0.001, each step from above, from the \
         steady state of case 3): {} steps computed{}, the largest difference from CONTACT's printed FX/(μFN) \
         {worst:.1e} (its print rounding is 5e-5). {settles}\n\n![veldep_fric: FX/(μ(0)FN) per time step]({file})\n",
        run.steps.len(),
        if completed { ", all converged" } else { ", **the run stopped early**" },
    )
    .unwrap();
    Ok(())
}
