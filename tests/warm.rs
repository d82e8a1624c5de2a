//! Warm starts are typed and stamped (issue 31, item 3): a solver's state and a nearby solution from another model
//! or another problem layout are dropped, never trusted; every solver then answers as from its cold start, or
//! refuses, and never panics. Reference: the same solver's cold run on the same problem (an answer does not depend
//! on the start: both are certified by the same residuals).

use rollbem::formulation::{ContactProblem, Solution};
use rollbem::pipeline::{stages, Model, Warm};
use rollbem::scene::Scene;
use rollbem::solvers::{registry, Solver, Start, Termination};
use rollbem::source::{self, Built};
use std::path::Path;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("warm.toml")).unwrap()
}

/// A frictional half-plane scene of `n` elements (μ = 0.3, a shift under a normal load).
fn half_plane(n: usize, load: &str) -> Scene {
    scene(&format!(
        "name = \"hp\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\nmodel = \"half_plane\"\n\
         [mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\ncontact_elements = {n}\n[contact]\nfriction = 0.3\n\
         [drive]\n{load}\ntangential_shift = -0.0004\n[solvers]\nuse = [\"all\", \"lemke_dense\"]\n"
    ))
}

/// A frictional BEM wheel of `n` contact elements.
fn bem(n: usize) -> Scene {
    scene(&format!(
        "name = \"bem\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         support = {{ kind = \"hub\", radius = 115.0 }}\n[mesh]\nelement = \"constant\"\ncontact_arc_deg = 4.0\n\
         contact_elements = {n}\nother_elements = 80\n[contact]\nfriction = 0.3\n[drive]\nnormal_load = 20000.0\n\
         tangential_load = 2000.0\n[solvers]\nuse = [\"all\", \"lemke_dense\"]\n"
    ))
}

fn built(s: &Scene) -> Built {
    source::build(s, stages::blocks_for(s)).unwrap()
}

/// Every registered solver that applies to `p`.
fn solvers(p: &ContactProblem) -> Vec<Box<dyn Solver>> {
    registry().into_iter().filter_map(|e| e.id.build(&Default::default())).filter(|s| s.applies(p).is_ok()).collect()
}

fn max_diff(a: &Solution, b: &Solution) -> f64 {
    assert_eq!(a.f.len(), b.f.len());
    let fmax = b.f.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    a.f.iter().zip(&b.f).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / fmax
}

/// The states and solutions a solve on one problem leaves, handed to every solver on another problem (another
/// model, another size): each solver ignores them and gives its cold answer.
#[test]
fn a_start_from_another_model_is_dropped_by_every_solver() {
    let (a, b) = (half_plane(40, "normal_load = 1000.0"), bem(30));
    let (ba, bb) = (built(&a), built(&b));
    let pa = stages::scene_problem(&a, &ba.flex).unwrap();
    let pb = stages::scene_problem(&b, &bb.flex).unwrap();
    let mut checked = 0;
    for solver in solvers(&pa) {
        let on_a = solver.solve(&pa);
        assert_eq!(on_a.status, Termination::Solved, "{}: {}", solver.name(), on_a.message);
        if solver.applies(&pb).is_err() {
            continue;
        }
        let cold = solver.solve(&pb);
        // A's state and A's solution (40 nodes) on B (30 nodes): dropped.
        let start = Start { solution: on_a.solution.clone(), state: on_a.state, ..Start::cold() };
        let warm = solver.solve_from(&pb, start);
        assert_eq!(warm.status, cold.status, "{}: {}", solver.name(), warm.message);
        if cold.status == Termination::Solved {
            let d = max_diff(warm.solution.as_ref().unwrap(), cold.solution.as_ref().unwrap());
            assert!(d <= 1e-9, "{}: warm from another model differs from cold by {d:e} of max f", solver.name());
        }
        checked += 1;
    }
    assert!(checked >= 4, "solvers compared: {checked}");
}

/// A state from the same flexibility but another layout (the load, not the approach, driven) is dropped; a
/// solution of the right length but garbage values (NaN) is ignored, not indexed or trusted.
#[test]
fn a_start_of_another_layout_or_with_bad_values_is_dropped() {
    let s = half_plane(40, "normal_load = 1000.0");
    let b = built(&s);
    let load = stages::scene_problem(&s, &b.flex).unwrap();
    let approach_scene = half_plane(40, "normal_approach = 0.002");
    let approach = stages::scene_problem(&approach_scene, &b.flex).unwrap();
    for solver in solvers(&load) {
        if solver.applies(&approach).is_err() {
            continue;
        }
        let first = solver.solve(&load);
        let cold = solver.solve(&approach);
        let warm = solver.solve_from(&approach, Start { state: first.state, ..Start::cold() });
        assert_eq!(warm.status, cold.status, "{}", solver.name());
        if cold.status == Termination::Solved {
            let d = max_diff(warm.solution.as_ref().unwrap(), cold.solution.as_ref().unwrap());
            assert!(d <= 1e-9, "{}: {d:e}", solver.name());
        }
        let n = approach.n();
        let garbage =
            Solution { f: vec![f64::NAN; n], h: Some(vec![1.0; n + 3]), rigid: vec![0.0; 1], tangential_known: true };
        let out = solver.solve_from(&approach, Start { solution: Some(garbage), ..Start::cold() });
        assert_eq!(out.status, cold.status, "{}: {}", solver.name(), out.message);
    }
}

/// Through the model API: a `Warm` written by one model and handed to another is cleared before the solve, and the
/// answers equal the other model's cold ones. The two models have the same grid and drive (so every solution and
/// state of A has B's shape and layout): only the models' identities tell them apart.
#[test]
fn a_warm_of_another_model_is_cleared() {
    let a = half_plane(40, "normal_load = 1000.0");
    let b = a.edit(|d| d.wheel.youngs_modulus = 70000.0).unwrap();
    let (ma, mb) = (Model::build(&a).unwrap(), Model::build(&b).unwrap());
    let mut warm = Warm::default();
    ma.solve_warm(&a, &mut warm).unwrap();
    let model_a = warm.model();
    assert!(model_a.is_some() && registry().iter().any(|e| warm.holds(e.id)));
    let warm_b = mb.solve_warm(&b, &mut warm).unwrap();
    assert_ne!(warm.model(), model_a, "the Warm now belongs to model B");
    // A state of A handed to B's solvers directly (bypassing the Warm) is dropped by its stamp: same layout, other
    // flexibility.
    let (ba, bb) = (built(&a), built(&b));
    let (pa, pb) = (stages::scene_problem(&a, &ba.flex).unwrap(), stages::scene_problem(&b, &bb.flex).unwrap());
    for solver in solvers(&pa) {
        let on_a = solver.solve(&pa);
        if let Some(state) = &on_a.state {
            assert!(!state.fits(solver.id(), &pb), "{}: a state of A fits B", solver.name());
            assert!(state.fits(solver.id(), &pa), "{}: its own state does not fit", solver.name());
        }
        let from_a = solver.solve_from(&pb, Start { solution: on_a.solution, state: on_a.state, ..Start::cold() });
        let cold = solver.solve(&pb);
        assert_eq!(from_a.status, cold.status, "{}", solver.name());
        if cold.status == Termination::Solved {
            let d = max_diff(from_a.solution.as_ref().unwrap(), cold.solution.as_ref().unwrap());
            assert!(d <= 1e-9, "{}: {d:e}", solver.name());
        }
    }
    let cold_b = mb.solve(&b).unwrap();
    for (w, c) in warm_b.runs.iter().zip(&cold_b.runs) {
        assert_eq!(w.solver, c.solver);
        assert_eq!(w.status, c.status, "{}", w.explanation());
        let (pw, pc) = (w.contact.as_ref().unwrap().peak_pressure, c.contact.as_ref().unwrap().peak_pressure);
        assert!((pw - pc).abs() <= 1e-9 * pc, "{}: {pw} vs {pc}", w.solver);
    }
    assert_eq!(warm_b.runs.len(), cold_b.runs.len());
}
