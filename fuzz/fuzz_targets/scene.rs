//! Fuzz target: arbitrary bytes (as UTF-8, lossily) → `Scene::from_toml`; a scene that parses and validates and has
//! a tiny mesh is also run through the whole pipeline (`run_scene`, every requested solver). Both must return `Ok`
//! or `Err`, never panic; a solved run must carry finite residuals within the harness's refusal bound.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rollbem::run::{residual_bounds, run_scene};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use std::path::Path;

/// Largest mesh (contact + other elements) run through the pipeline: keeps one execution within milliseconds.
const MAX_RUN_ELEMENTS: usize = 24;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let path = Path::new("<fuzz>");
    let Ok(scene) = Scene::from_toml(&text, path) else { return };
    if scene.mesh.contact_elements + scene.mesh.other_elements > MAX_RUN_ELEMENTS {
        return;
    }
    // Iterative solvers' budgets are user settings: cap them so a hostile scene cannot stall the fuzzer.
    let mut scene = scene;
    let s = &mut scene.solvers;
    for (solver, key, cap) in [
        ("pgs", "max_sweeps", 2_000),
        ("pgs", "max_outer", 50),
        ("normtang_qp", "max_outer", 50),
        ("clarabel", "max_iter", 200),
        ("normtang_qp", "qp.max_iter", 200),
    ] {
        if let Some(v) = s.get(solver, key).and_then(|v| v.as_integer()) {
            s.set(solver, key, v.min(cap));
        }
    }
    let Ok(report) = run_scene(&scene, path) else { return };
    for run in &report.runs {
        if run.status == Status::Solved {
            let res = run.residuals.expect("a solved run carries residuals");
            let bound = residual_bounds(&scene, run.solver.0).1;
            assert!(res.max() <= bound, "{}: solved with residual {:e} > {bound:e}", run.solver, res.max());
        } else {
            assert!(run.residuals.is_none() && run.resultants.is_none(), "{}: unsolved run with results", run.solver);
        }
    }
});
