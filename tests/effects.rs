//! Effects by the physics, not by the flag (issue 31, item 1): a scene whose normal–tangential cross flexibilities
//! vanish identically takes the uncoupled path without being told, says so, and gets the coupled path's answer.
//!
//! The reference for "the same answer" is an independent computation: the coupled path itself, run by hand through the
//! library (all four blocks built, `coupling = true` in the contact law, the active-set method's joint iteration),
//! on the same scene. The reference for "vanish" is `halfplane`'s unit test, which checks the predicate against the
//! built blocks.

use rollbem::formulation::ContactProblem;
use rollbem::pipeline::{stages, Model};
use rollbem::scene::Scene;
use rollbem::solvers::Termination;
use rollbem::source::{self, Blocks};
use rollbem::status::Status;
use std::path::Path;

/// CONTACT's carter2d input as a user writes it (`examples/carter2d.inp`, `perfc_test/carter2d_100.inp`,
/// `carter2d_800.inp`: two half-planes of the same steel on a strip DY = 200, its grid XC1 = −1.05, DX), `coupling`
/// left at its default, or written out by `coupling`.
fn carter2d(n: usize, counter: (f64, f64), coupling: Option<bool>) -> Scene {
    let dx = if n > 200 { 0.0025 } else { 0.02 };
    let x0 = -1.05 - 0.5 * dx;
    let coupling = coupling.map(|c| format!("coupling = {c}\n")).unwrap_or_default();
    let text = format!(
        "name = \"carter2d\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 209920.0\npoisson_ratio = 0.28\n\
         model = \"half_plane\"\nprofile = \"parabola\"\n[counter_body]\nkind = \"half_plane\"\n\
         youngs_modulus = {}\npoisson_ratio = {}\n[mesh]\nelement = \"constant\"\ncontact_x = [{x0}, {}]\n\
         contact_elements = {n}\nstrip_width = 200.0\n[contact]\nfriction = 0.3\n{coupling}[drive]\n\
         normal_load = 178.9\n[rolling]\nmode = \"steady\"\ncreepage = 1e-5\ndirection = 1\n[solvers]\n\
         use = [\"active_set\"]\n",
        counter.0,
        counter.1,
        x0 + dx * n as f64
    );
    Scene::from_toml(&text, Path::new("carter2d.toml")).unwrap()
}

const STEEL: (f64, f64) = (209920.0, 0.28);

/// Q of the scene's active-set run, solved.
fn tangential(report: &rollbem::results::Report) -> f64 {
    let run = &report.runs[0];
    assert_eq!(run.status, Status::Solved, "{}", run.explanation());
    run.resultants.unwrap().tangential
}

/// The coupled path, by hand: all four blocks, the scene's law with coupling on, the active-set solver.
fn coupled_path_q(scene: &Scene) -> f64 {
    let built = source::build(scene, Blocks::All).unwrap();
    let flex = &built.flex;
    assert!(flex.k_nt.is_some() && flex.k_tn.is_some());
    let mut law = scene.law();
    law.coupling = true;
    let problem = ContactProblem::new(flex, law, *scene.drive().unwrap(), stages::slip_operator(scene, flex)).unwrap();
    let out = rollbem::solvers::build("active_set").unwrap().solve(&problem);
    assert_eq!(out.status, Termination::Solved, "{}", out.message);
    let ev = rollbem::post::evaluate(&problem, out.solution.as_ref().unwrap(), stages::rolling_post(scene)).unwrap();
    ev.resultants.tangential
}

#[test]
fn a_same_material_pair_takes_the_uncoupled_path_and_says_why() {
    let scene = carter2d(111, STEEL, None);
    assert!(scene.law().coupling, "the default asks for coupling");
    assert_eq!(stages::blocks_for(&scene), Blocks::Uncoupled);
    let model = Model::build(&scene).unwrap();
    assert!(model.built().flex.k_nt.is_none() && model.built().flex.k_tn.is_none(), "no cross blocks built");
    let report = model.solve(&scene).unwrap();
    assert!(!report.effects.iter().any(|e| e == "coupling"), "{:?}", report.effects);
    let note = report.effect_notes.iter().find(|n| n.effect == "coupling").expect("a coupling note");
    assert!(note.asked && !note.simulated, "{note:?}");
    assert!(note.why.contains("vanish"), "{}", note.why);
    let text = rollbem::results::render::run_table(&report);
    assert!(text.contains("coupling not simulated"), "{text}");
    // Written out, `coupling = false` says it is the scene's choice.
    let off = Model::build(&carter2d(111, STEEL, Some(false))).unwrap().solve(&carter2d(111, STEEL, Some(false)));
    let off = off.unwrap();
    let note = off.effect_notes.iter().find(|n| n.effect == "coupling").unwrap();
    assert!(!note.asked && !note.simulated && note.why.contains("coupling = false"), "{note:?}");
}

#[test]
fn a_pair_of_two_materials_keeps_its_coupling() {
    // Steel on a stiffer metal (β ≠ 0): the cross blocks are built and the coupled path is taken.
    let scene = carter2d(111, (300000.0, 0.25), None);
    assert_eq!(stages::blocks_for(&scene), Blocks::All);
    let model = Model::build(&scene).unwrap();
    assert!(model.built().flex.k_nt.is_some());
    let report = model.solve(&scene).unwrap();
    assert!(report.effects.iter().any(|e| e == "coupling"), "{:?}", report.effects);
    tangential(&report);
}

/// Lemke's Q on the same scene (a direct pivoting method: its answer is exact to round-off).
fn lemke_q(scene: &Scene) -> f64 {
    let lemke = scene.edit(|d| d.solvers.use_ = vec!["lemke".into()]).unwrap();
    tangential(&rollbem::pipeline::run_scene(&lemke).unwrap())
}

#[test]
fn the_default_path_gives_the_coupled_paths_creep_forces() {
    // carter2d_100's grid and carter2d_800's (841 elements), creepages across the curve up to near gross sliding (μP
    // at ξ ≈ 6e-4 here). Three references for Q on the default path:
    // - `coupling = false` written out: the same to 1e-12 of μP (issue 31's bar). The coupled path differs from it by
    //   up to 1.9e-12 μP here (its GMRES), so this fails if the default takes the coupled path again;
    // - Lemke (a direct method, an independent solver): to 1e-12 of μP;
    // - the coupled path run by hand (all four blocks, the joint iteration): to 1e-10 of μP, the accuracy of that
    //   path's GMRES (relative residual 1e-12, `active_set::GMRES_TOLERANCE`, times κ(K) of order 1e2).
    let mu_p = 0.3 * 178.9;
    for (n, creepages) in [(111, vec![1e-5, 1e-4, 2.5e-4, 4e-4, 5e-4]), (841, vec![5e-5, 3e-4])] {
        let base = carter2d(n, STEEL, None);
        let (model, off) = (Model::build(&base).unwrap(), Model::build(&carter2d(n, STEEL, Some(false))).unwrap());
        for xi in creepages {
            let scene = base.with_creepage(xi).unwrap();
            let q = tangential(&model.solve(&scene).unwrap());
            assert!(q.abs() > 0.01 * mu_p, "ξ = {xi}: a creep force to compare ({q})");
            let written = carter2d(n, STEEL, Some(false)).with_creepage(xi).unwrap();
            let q_off = tangential(&off.solve(&written).unwrap());
            assert!((q - q_off).abs() <= 1e-12 * mu_p, "n = {n}, ξ = {xi}: Q {q} vs coupling = false {q_off}");
            let q_lemke = lemke_q(&scene);
            assert!((q - q_lemke).abs() <= 1e-12 * mu_p, "n = {n}, ξ = {xi}: Q {q} vs Lemke {q_lemke}");
            let q_coupled = coupled_path_q(&scene);
            assert!((q - q_coupled).abs() <= 1e-10 * mu_p, "n = {n}, ξ = {xi}: Q {q} vs coupled path {q_coupled}");
        }
    }
}
