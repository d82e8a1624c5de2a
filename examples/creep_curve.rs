//! A creep curve through the model API: one scene, its flexibility built once, solved at many creepages, printed
//! beside Carter's closed form (β = 0 here, where Carter's theory holds).
//!
//! Run: `cargo run --release --example creep_curve [SCENE.toml]` (default: the reference Carter scene).

use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).map(PathBuf::from).unwrap_or_else(|| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/carter-steady-rolling.toml")
    });
    let scene = Scene::from_file(&path)?.edit(|d| d.solvers.use_ = vec!["active_set".into()])?;
    let model = Model::build(&scene)?;
    let t = model.timing();
    println!("{}: flexibility built once in {:.3} s", scene.name(), t.assembly + t.condensation);
    let mu = scene.friction();
    println!("{:>10} {:>12} {:>14} {:>10}", "creepage", "Q/(μP)", "Carter Q/(μP)", "solve [s]");
    for k in 1..=25 {
        let xi = 2e-4 * k as f64;
        let report = model.solve(&scene.with_creepage(xi)?)?;
        let run = &report.runs[0];
        let Some(f) = run.resultants else {
            println!("{xi:>10.2e} {}", run.explanation());
            continue;
        };
        // Carter (Johnson §8.2): ξ = (μa/R)(1 − √(1 − |Q|/(μP))), so |Q|/(μP) = 1 − (1 − ξR/(μa))² below saturation.
        let a = rollbem::references::hertz_at(&scene, f.normal).a;
        let s = (xi * scene.radius() / (mu * a)).min(1.0);
        let carter = 1.0 - (1.0 - s) * (1.0 - s);
        println!(
            "{xi:>10.2e} {:>12.5} {carter:>14.5} {:>10.4}",
            f.tangential.abs() / (mu * f.normal),
            run.timing_s.solve
        );
    }
    Ok(())
}
