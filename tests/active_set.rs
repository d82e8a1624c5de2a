//! Issue 14: the active-set solver against Lemke (the peer solver; Lemke is exact to round-off on the discrete
//! problem) on every reference scene and every hard case: the same status, and where both solve, the same nodal
//! tractions to 1e-10 of the peak pressure, node by node; on load paths at every substep. When the active-set method
//! falls back to Lemke its message must say so.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::results::SolverRun;
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use std::path::{Path, PathBuf};

fn scenes(dir: &str) -> Vec<PathBuf> {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    v.sort();
    v
}

/// Compare the two runs of one (sub)step; returns the largest traction difference over p0 when both solved.
fn compare(what: &str, l: &SolverRun, a: &SolverRun) -> Option<f64> {
    assert_eq!(
        a.status,
        l.status,
        "{what}: active_set {} ({}) vs lemke {} ({})",
        a.status,
        a.message,
        l.status,
        l.explanation()
    );
    if l.status != Status::Solved {
        return None;
    }
    assert_eq!(a.nodes.len(), l.nodes.len(), "{what}");
    let p0 = l.nodes.iter().map(|n| n.pressure).fold(0.0, f64::max);
    if p0 == 0.0 {
        assert!(a.nodes.iter().all(|n| n.pressure == 0.0 && n.shear == 0.0), "{what}: no contact");
        return Some(0.0);
    }
    let d = paired(&l.nodes, &a.nodes)
        .map(|(x, y)| (x.pressure - y.pressure).abs().max((x.shear - y.shear).abs()))
        .fold(0.0, f64::max)
        / p0;
    assert!(d <= 1e-10, "{what}: active_set differs from lemke by {d:.2e} p0");
    Some(d)
}

#[test]
fn active_set_agrees_with_lemke_on_every_reference_scene_and_hard_case() {
    let mut compared = 0;
    let mut fallbacks = Vec::new();
    let mut worst: f64 = 0.0;
    for p in scenes("reference/scenes").into_iter().chain(scenes("reference/hard")) {
        let mut s = Scene::from_file(&p).unwrap();
        s = s.edit(|d| d.solvers.use_ = vec!["lemke".into(), "active_set".into()]).unwrap();
        let r = run_scene(&s).unwrap();
        let pairs: Vec<(String, &SolverRun, &SolverRun)> = if r.steps.is_empty() {
            vec![(p.display().to_string(), &r.runs[0], &r.runs[1])]
        } else {
            r.steps
                .iter()
                .filter(|st| st.runs.len() == 2)
                .map(|st| (format!("{} step {}.{}", p.display(), st.step, st.substep), &st.runs[0], &st.runs[1]))
                .collect()
        };
        assert!(!pairs.is_empty(), "{}: nothing to compare", p.display());
        for (what, l, a) in &pairs {
            assert_eq!(l.solver, "lemke");
            assert_eq!(a.solver, "active_set");
            if let Some(d) = compare(what, l, a) {
                worst = worst.max(d);
            }
            // A fallback runs Lemke inside the active-set solver (its pivots are counted): it must say so.
            let fell_back = a.message.contains("fell back to Lemke");
            assert_eq!(
                a.work.get("pivots").unwrap_or(0) > 0,
                fell_back,
                "{what}: Lemke pivots {:?} but message {:?}",
                a.work.get("pivots"),
                a.message
            );
            if fell_back {
                fallbacks.push(what.clone());
            }
            compared += 1;
        }
    }
    eprintln!("{compared} (sub)steps compared; worst difference {worst:.2e} p0; fallbacks to Lemke: {fallbacks:?}");
    assert!(compared >= 30);
}
