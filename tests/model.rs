//! The model API: a scene's flexibility built once and solved for many drives gives the same answers as separate
//! runs, says in its timings that it reused the build, and refuses a scene of other bodies or mesh by name.

use rollbem::pipeline::{run_scene, Model};
use rollbem::results::Setup;
use rollbem::scene::{Dof, Drive, Scene};
use rollbem::status::Status;
use std::path::Path;

fn carter() -> Scene {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/carter-steady-rolling.toml");
    // One solver keeps the test short; the creep curve of 50 creepages spans the stick-slip range up to saturation
    // (critical μa/R = 4.65e-3 for this scene).
    Scene::from_file(&p).unwrap().edit(|d| d.solvers.use_ = vec!["active_set".into()]).unwrap()
}

#[test]
fn a_creep_curve_on_one_model_equals_separate_runs_and_builds_once() {
    let base = carter();
    let scenes: Vec<Scene> = (1..=50).map(|k| base.with_creepage(1e-4 * k as f64).unwrap()).collect();
    let model = Model::build(&base).unwrap();
    let curve = model.solve_all(&scenes).unwrap();
    assert_eq!(model.solves(), 50);
    let mut worst: f64 = 0.0;
    for (k, (s, r)) in scenes.iter().zip(&curve).enumerate() {
        let on_model = &r.runs[0];
        assert_eq!(on_model.status, Status::Solved, "ξ = {:e}: {}", s.creepage().unwrap(), on_model.explanation());
        // The timing says the flexibility was built once: the first solve built it, the other 49 reused it.
        let expected = if k == 0 { Setup::Built } else { Setup::Reused };
        assert_eq!(on_model.timing_s.setup, expected, "point {k}");
        // Reference: the same scene run on its own (its own model, built for it).
        let alone = run_scene(s).unwrap();
        let alone = &alone.runs[0];
        assert_eq!(alone.timing_s.setup, Setup::Built);
        let p0 = alone.contact.as_ref().unwrap().peak_pressure;
        assert_eq!(on_model.nodes.len(), alone.nodes.len());
        for (a, b) in on_model.nodes.iter().zip(&alone.nodes) {
            worst = worst.max((a.pressure - b.pressure).abs() / p0).max((a.shear - b.shear).abs() / p0);
        }
    }
    // The same discrete problem solved by the same solver: equal to round-off (the criterion: 1e-12 of p0).
    assert!(worst <= 1e-12, "max |Δp|, |Δq| / p0 = {worst:e}");
    // The curve rises with the creepage up to saturation at μP (Carter): Q(ξ) nondecreasing in |Q|.
    let q: Vec<f64> = curve.iter().map(|r| r.runs[0].resultants.unwrap().tangential.abs()).collect();
    assert!(q.windows(2).all(|w| w[1] >= w[0] - 1e-9 * w[0]), "{q:?}");
}

#[test]
fn a_model_refuses_a_scene_of_other_bodies_naming_the_part() {
    let base = carter();
    let model = Model::build(&base).unwrap();
    let finer = base.edit(|d| d.mesh.contact_elements = 201).unwrap();
    let e = model.solve(&finer).unwrap_err().to_string();
    assert!(e.contains("`mesh`") && e.contains("differs"), "{e}");
    let stiffer = base.edit(|d| d.wheel.youngs_modulus = 2.0e5).unwrap();
    let e = model.solve(&stiffer).unwrap_err().to_string();
    assert!(e.contains("`wheel`"), "{e}");
    // Another drive on the same bodies is accepted: a load instead of a creepage (ξ computed).
    let by_load = base
        .with_drive(Drive {
            normal: Dof::Load(20000.0),
            tangential: Dof::Load(2000.0),
            rotational: Dof::Displacement(0.0),
        })
        .unwrap();
    let r = model.solve(&by_load).unwrap();
    assert_eq!(r.runs[0].status, Status::Solved, "{}", r.runs[0].explanation());
    assert!((r.runs[0].resultants.unwrap().tangential - 2000.0).abs() < 1e-6 * 2000.0);
}

#[test]
fn a_frictionless_model_holds_the_normal_problem_only_and_says_so() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/half-plane-hertz.toml");
    let s = Scene::from_file(&p).unwrap();
    let model = Model::build(&s).unwrap();
    assert!(!model.built().flex.has_tangential());
    let frictional = s.edit(|d| d.contact.friction = 0.3).unwrap();
    let e = model.solve(&frictional).unwrap_err().to_string();
    assert!(e.contains("contact.friction") && e.contains("normal problem only"), "{e}");
}

#[test]
fn an_empty_solver_list_is_bad_input_not_an_empty_answer() {
    // Before the model API, `solvers.use = []` in a scene built in code ran nothing and returned Ok (issue 20).
    let base = carter();
    let e = base.edit(|d| d.solvers.use_.clear()).unwrap_err();
    assert!(matches!(e, rollbem::Error::Invalid { ref field, .. } if field == "solvers.use"), "{e}");
    // And a named solver that does not apply is refused by name, not skipped.
    let e = run_scene(&base.edit(|d| d.solvers.use_ = vec!["clarabel".into()]).unwrap()).unwrap_err();
    assert!(e.to_string().contains("solvers.use: clarabel does not apply"), "{e}");
}
