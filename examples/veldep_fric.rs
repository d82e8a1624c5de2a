//! A sequence of steady and transient rolling cases with a friction law of the slip velocity, as CONTACT's
//! `examples/veldep_fric.inp` poses them (benches/peer/contact_examples.py runs it beside CONTACT).
//!
//! ```sh
//! cargo run --release --example veldep_fric -- SCENE.toml CASES.csv
//! ```
//!
//! SCENE is a steady-rolling scene with `[contact] friction_law` and `[rolling] velocity` (its law, speed, bodies,
//! grid and load; its own creepage is not used). CASES has a header and one line per case, `mode,cksi,inislp`:
//! `steady` solves the steady problem at that creepage from below (INISLP > 0) or above (< 0)
//! (`rollbem::veldep::solve_steady`); `transient` rolls one time step of Δq = one element from the previous case's
//! state (`rollbem::veldep::transient::roll`). Prints one CSV line per case: the case, its status, the law's
//! residual, FX/(μ(0) FN) (the force on the wheel over the static coefficient times the load), the contact and
//! stick counts and the peak pressure (the same in every case). A case that does not converge is printed with its
//! status and residual and ends the sequence (its state is not a solution to roll on from).

use rollbem::formulation::SlipOperator;
use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use rollbem::veldep::transient::{roll, TransientProblem, TransientStatus};
use rollbem::veldep::{solve_steady, Start, SteadyOutcome, SteadyProblem, SteadyStatus};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        eprintln!("usage: veldep_fric SCENE.toml CASES.csv");
        return ExitCode::from(2);
    }
    match run(&args[1], &args[2]) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(scene_path: &str, cases_path: &str) -> Result<(), String> {
    let scene = Scene::from_file(std::path::Path::new(scene_path)).map_err(|e| e.to_string())?;
    let friction = scene.slip_velocity_friction().ok_or("the scene has no falling `[contact] friction_law`")?;
    let direction = scene.rolling().map_or(1, |r| r.direction());
    let model = Model::build(&scene).map_err(|e| e.to_string())?;
    let report = model.solve(&scene).map_err(|e| e.to_string())?;
    let run = report.runs.first().ok_or("no run")?;
    let flex = &model.built().flex;
    let e = flex.scales.modulus;
    // The normal nodal forces of the scene's run (dimensionless): the same in every case (the uncoupled problem).
    let f: Vec<f64> = run.nodes.iter().zip(&flex.weights).map(|(n, w)| n.pressure * w / e).collect();
    if f.len() != flex.n() {
        return Err(format!("the scene's run did not solve: {}", run.explanation()));
    }
    let k_tt = flex.k_tt.as_ref().ok_or("no tangential flexibility")?;
    let m = SlipOperator::steady(&flex.x, direction).apply_mat(k_tt);
    let force = e * flex.scales.length;
    let mu_fn = friction.law.static_coefficient() * f.iter().sum::<f64>() * force;
    let ncon = f.iter().filter(|&&v| v > 0.0).count();
    let text = std::fs::read_to_string(cases_path).map_err(|e| format!("{cases_path}: {e}"))?;
    let pmax = run.nodes.iter().fold(0.0f64, |a, n| a.max(n.pressure));
    println!("case,status,residual,fx_over_mu_fn,ncon,nadh,pmax");
    let mut previous: Option<Vec<f64>> = None;
    for (k, line) in text.lines().skip(1).filter(|l| !l.trim().is_empty()).enumerate() {
        let c: Vec<&str> = line.split(',').map(str::trim).collect();
        let bad = || format!("{cases_path}: line {} is not `mode,cksi,inislp`", k + 2);
        let (mode, cksi, inislp) = match c.as_slice() {
            [m, x, i] => (*m, x.parse::<f64>().map_err(|_| bad())?, i.parse::<i32>().map_err(|_| bad())?),
            _ => return Err(bad()),
        };
        let start = if inislp < 0 { Start::Above } else { Start::Below };
        let out: SteadyOutcome = match (mode, &previous) {
            ("steady", _) => {
                let p = SteadyProblem {
                    slip_matrix: &m,
                    normal: &f,
                    creepage: cksi,
                    offset: None,
                    velocity: friction.velocity,
                    law: friction.law,
                };
                solve_steady(&p, start, 1e-10, 200).map_err(|e| e.to_string())?
            }
            ("transient", Some(h)) => {
                let p = TransientProblem {
                    k_tt,
                    normal: &f,
                    creepage: cksi,
                    velocity: friction.velocity,
                    law: friction.law,
                    dq: flex.x[1] - flex.x[0],
                    direction,
                };
                let r = roll(&p, h, &[start], 1e-10, 200).map_err(|e| e.to_string())?;
                debug_assert!(r.status == TransientStatus::Completed || r.steps.len() == 1);
                r.steps.into_iter().next().ok_or("no step")?
            }
            ("transient", None) => return Err(format!("case {}: a time step needs a previous case", k + 1)),
            _ => return Err(bad()),
        };
        let (status, residual) = match out.status {
            SteadyStatus::Converged { residual, .. } => ("converged", residual),
            SteadyStatus::NotConverged { residual, .. } => ("not_converged", residual),
        };
        let fx = out.tangential.iter().sum::<f64>() * force / mu_fn;
        let nadh = out.stick.iter().filter(|&&s| s).count();
        println!("{},{status},{residual:.3e},{fx:.6},{ncon},{nadh},{pmax:.6}", k + 1);
        if status != "converged" {
            return Ok(());
        }
        previous = Some(out.tangential);
    }
    Ok(())
}
