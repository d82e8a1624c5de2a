//! The model API: a scene's flexibility built once and solved for many drives gives the same answers as separate
//! runs, says in its timings that it reused the build, and refuses a scene of other bodies or mesh by name.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
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
    for (k, (s, r)) in paired(&scenes, &curve).enumerate() {
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
        for (a, b) in paired(&on_model.nodes, &alone.nodes) {
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
    // (The scene names clarabel, which cannot take friction: the frictional variant names the two that can.)
    let frictional = s
        .edit(|d| {
            d.contact.friction = 0.3;
            d.solvers.use_ = vec!["lemke".into(), "active_set".into()];
        })
        .unwrap();
    let e = model.solve(&frictional).unwrap_err().to_string();
    assert!(e.contains("contact.friction") && e.contains("normal problem only"), "{e}");
}

#[test]
fn an_empty_solver_list_is_bad_input_not_an_empty_answer() {
    // Before the model API, `solvers.use = []` in a scene built in code ran nothing and returned Ok (issue 20).
    let base = carter();
    let e = base.edit(|d| d.solvers.use_.clear()).unwrap_err();
    assert!(matches!(e, rollbem::Error::Invalid { ref field, .. } if field == "solvers.use"), "{e}");
    // And a named solver that does not apply is refused by name, not skipped: when the scene is read (issue 31).
    let e = base.edit(|d| d.solvers.use_ = vec!["clarabel".into()]).unwrap_err();
    assert!(matches!(e, rollbem::Error::Invalid { ref field, .. } if field == "solvers.use"), "{e}");
    assert!(e.to_string().contains("clarabel does not apply"), "{e}");
}

/// The largest |Δp|, |Δq| over the nodes of two runs of one problem, relative to the second's peak pressure.
fn traction_difference(a: &rollbem::results::SolverRun, b: &rollbem::results::SolverRun) -> f64 {
    let p0 = b.contact.as_ref().unwrap().peak_pressure;
    assert_eq!(a.nodes.len(), b.nodes.len());
    paired(&a.nodes, &b.nodes)
        .fold(0.0_f64, |w, (x, y)| w.max((x.pressure - y.pressure).abs() / p0).max((x.shear - y.shear).abs() / p0))
}

/// Warm starts (issue 21) change the work, not the answer: on the coupled problem (a steel wheel on a rigid flat,
/// β ≠ 0: the active set's whole-system path) and on a family of tangential loads (the creepage an unknown), each
/// case of a warm `solve_all` equals the same scene run alone from a cold start (its own model, its own start) to
/// 1e-12 of p0, and the warm family needs fewer factorisations in all than the cold runs.
#[test]
fn warm_starts_change_the_work_not_the_answers() {
    let base = carter();
    let coupled = base.edit(|d| d.contact.coupling = true).unwrap();
    let coupled_curve: Vec<Scene> = (1..=12).map(|k| coupled.with_creepage(2e-4 * k as f64).unwrap()).collect();
    let load_family: Vec<Scene> = (1..=12)
        .map(|k| {
            base.with_drive(Drive {
                normal: Dof::Load(20000.0),
                tangential: Dof::Load(-400.0 * k as f64),
                rotational: Dof::Displacement(0.0),
            })
            .unwrap()
        })
        .collect();
    for (name, family) in [("coupled creep curve", &coupled_curve), ("tangential-load family", &load_family)] {
        let model = Model::build(&family[0]).unwrap();
        let warm = model.solve_all(family).unwrap();
        let (mut warm_work, mut cold_work, mut worst) = (0, 0, 0.0_f64);
        for (s, r) in paired(family, &warm) {
            let alone = run_scene(s).unwrap();
            let (w, c) = (&r.runs[0], &alone.runs[0]);
            assert_eq!(w.status, Status::Solved, "{name}: {}", w.explanation());
            assert_eq!(c.status, Status::Solved, "{name}: {}", c.explanation());
            worst = worst.max(traction_difference(w, c));
            warm_work += w.work.get("factorisations").unwrap();
            cold_work += c.work.get("factorisations").unwrap();
        }
        assert!(worst <= 1e-12, "{name}: max |Δp|, |Δq| / p0 = {worst:e}");
        assert!(warm_work < cold_work, "{name}: {warm_work} factorisations warm, {cold_work} cold");
    }
}

/// `[mesh] contact_x` places the half-plane grid off-centre (CONTACT's grids). Checked against the centred grid, an
/// independent construction: a span of whole elements shifted from a centred one puts the same collocation points
/// under the contact, so the tractions at those points are the same discrete answer (to round-off); and the symmetric
/// span [−w, w] is exactly `contact_half_width = w`.
#[test]
fn an_off_centre_grid_gives_the_centred_grids_answer_at_the_same_points() {
    let base = carter()
        .edit(|d| {
            d.mesh.contact_half_width = Some(10.0);
            d.mesh.contact_elements = 100;
        })
        .unwrap();
    let centred = run_scene(&base).unwrap();
    let on_span = |x: [f64; 2]| {
        let s = base
            .edit(|d| {
                d.mesh.contact_half_width = None;
                d.mesh.contact_x = Some(x);
            })
            .unwrap();
        run_scene(&s).unwrap()
    };
    let same = on_span([-10.0, 10.0]);
    assert_eq!(traction_difference(&same.runs[0], &centred.runs[0]), 0.0);
    // Shifted right by 8 elements of 0.2: [−8.4, 11.6]; the contact (a = 7.1) lies inside both.
    let shifted = on_span([-8.4, 11.6]);
    let (c, s) = (&centred.runs[0], &shifted.runs[0]);
    assert_eq!(s.status, Status::Solved, "{}", s.explanation());
    let p0 = c.contact.as_ref().unwrap().peak_pressure;
    let mut compared = 0;
    for (k, b) in s.nodes.iter().enumerate() {
        assert!((b.x - (-8.4 + 0.2 * (k as f64 + 0.5))).abs() < 1e-9, "node {k} at x = {}", b.x);
        if let Some(a) = c.nodes.iter().find(|a| (a.x - b.x).abs() < 1e-9) {
            assert!((a.pressure - b.pressure).abs() <= 1e-10 * p0, "x = {}: p {} vs {}", b.x, a.pressure, b.pressure);
            assert!((a.shear - b.shear).abs() <= 1e-10 * p0, "x = {}: q {} vs {}", b.x, a.shear, b.shear);
            compared += 1;
        }
    }
    assert_eq!(compared, 92);
}

#[test]
fn an_off_centre_zone_is_refused_where_it_means_nothing() {
    let base = carter();
    let both = base.edit(|d| d.mesh.contact_x = Some([-9.0, 9.0])).unwrap_err().to_string();
    assert!(both.contains("mesh.contact_half_width") && both.contains("not several"), "{both}");
    let reversed = base
        .edit(|d| {
            d.mesh.contact_half_width = None;
            d.mesh.contact_x = Some([9.0, -9.0]);
        })
        .unwrap_err()
        .to_string();
    assert!(reversed.contains("mesh.contact_x") && reversed.contains("x_min < x_max"), "{reversed}");
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/cattaneo-decoupled.toml");
    let bem = Scene::from_file(&p)
        .unwrap()
        .edit(|d| {
            d.mesh.contact_arc_deg = None;
            d.mesh.contact_x = Some([-0.05, 0.06]);
        })
        .unwrap_err()
        .to_string();
    assert!(bem.contains("mesh.contact_x") && bem.contains("half-plane model"), "{bem}");
}

/// Without coupling the active set solves the normal problem once and then the stick–slip problem with bordered
/// updates of its factorisation (`src/solvers/active_set/phases.rs`). The peer is Lemke on the same discrete
/// problem's LCP (an independent method: pivoting, no factorisation reused): on a creep curve (creepage given) and on
/// a tangential-load family (creepage unknown: a tangential load row in the bordered system), solved warm on one
/// model, every case agrees with Lemke's to 1e-9 of p0 (Lemke's own accuracy on this problem is about 1e-12).
#[test]
fn the_two_phase_active_set_agrees_with_lemke() {
    let base = carter().edit(|d| d.solvers.use_ = vec!["active_set".into(), "lemke".into()]).unwrap();
    let curve: Vec<Scene> = (1..=10).map(|k| base.with_creepage(4e-4 * k as f64).unwrap()).collect();
    let loads: Vec<Scene> = (1..=10)
        .map(|k| {
            base.with_drive(Drive {
                normal: Dof::Load(20000.0),
                tangential: Dof::Load(550.0 * k as f64),
                rotational: Dof::Displacement(0.0),
            })
            .unwrap()
        })
        .collect();
    for (name, family) in [("creep curve", &curve), ("tangential-load family", &loads)] {
        let model = Model::build(&family[0]).unwrap();
        let mut worst = 0.0_f64;
        for r in model.solve_all(family).unwrap() {
            let (a, l) = (&r.runs[0], &r.runs[1]);
            assert_eq!(a.status, Status::Solved, "{name}: {}", a.explanation());
            assert_eq!(l.status, Status::Solved, "{name}: {}", l.explanation());
            worst = worst.max(traction_difference(a, l));
        }
        assert!(worst <= 1e-9, "{name}: max |Δp|, |Δq| / p0 against Lemke = {worst:e}");
    }
}

/// A half-plane model built for an uncoupled scene holds K_NN and K_TT only (two n × n blocks, not four: the memory
/// the 841-element curve saves), and refuses a coupled scene by naming `contact.coupling`; a coupled model serves
/// both.
#[test]
fn an_uncoupled_model_holds_two_blocks_and_refuses_coupling() {
    let base = carter();
    let model = Model::build(&base).unwrap();
    let flex = &model.built().flex;
    assert!(flex.k_tt.is_some() && flex.k_nt.is_none() && flex.k_tn.is_none());
    let coupled = base.edit(|d| d.contact.coupling = true).unwrap();
    let e = model.solve(&coupled).unwrap_err().to_string();
    assert!(e.contains("contact.coupling"), "{e}");
    let both = Model::build(&coupled).unwrap();
    assert!(both.built().flex.k_nt.is_some());
    assert_eq!(both.solve(&base).unwrap().runs[0].status, Status::Solved);
}
