//! The hard-case suite (`reference/hard/`): every case meets the expectation its description states — solved
//! with the residual bound, or the named diagnosis — and passes its checks against theory and peer solvers.

use rollbem::pipeline::run_scene;
use rollbem::post::NodeState;
use rollbem::results::Report;
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use std::path::{Path, PathBuf};

fn hard(name: &str) -> (Scene, Report) {
    let p: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/hard").join(format!("{name}.toml"));
    let s = Scene::from_file(&p).unwrap();
    let r = run_scene(&s).unwrap();
    (s, r)
}

#[test]
fn every_hard_case_meets_its_stated_expectation() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/hard");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "toml").then(|| p.file_stem().unwrap().to_string_lossy().into_owned())
        })
        .collect();
    names.sort();
    assert!(names.len() >= 15, "{names:?}");
    for n in &names {
        let (s, r) = hard(n);
        let failed: Vec<String> = r.checks.iter().filter(|c| !c.pass).map(|c| c.name.clone()).collect();
        assert!(failed.is_empty(), "{n}: {failed:?}");
        for run in &r.runs {
            assert_eq!(run.status, s.expect().status_for(run.solver), "{n} {}: {}", run.solver, run.explanation());
            assert!(!run.explanation().is_empty());
        }
    }
}

#[test]
fn hard_cases_say_what_their_descriptions_promise() {
    let (_, r) = hard("no-contact");
    for run in &r.runs {
        assert_eq!(run.resultants.unwrap().normal, 0.0, "{}", run.solver);
        assert!(run.nodes.iter().all(|n| n.state == NodeState::Separated));
    }
    let (_, r) = hard("one-node-contact");
    let c = r.runs[0].contact.as_ref().unwrap();
    assert!((1..=2).contains(&c.nodes_contact), "{} nodes in contact", c.nodes_contact);
    assert!(r.runs[0].resultants.unwrap().normal > 0.0);
    let (_, r) = hard("load-above-mu-p");
    assert!(r.runs.iter().all(|x| x.status == Status::Infeasible && x.explanation().contains("μP")));
    let (_, r) = hard("moment-overturning");
    assert!(r.runs[0].explanation().contains("pressure centre"), "{}", r.runs[0].explanation());
    let (_, r) = hard("fine-contact-mesh");
    assert!(r.mesh.contact_nodes >= 300);
    let (s, r) = hard("load-0999-mu-p");
    let c = r.runs[0].contact.as_ref().unwrap();
    assert!(c.nodes_stick >= 1, "a stick zone of about √0.001 a survives");
    assert!(s.document().contact.friction > 0.0);
    let (_, r) = hard("rail-wheel-R-over-a-660");
    let a = r.references.hertz.unwrap().a;
    assert!(460.0 / a >= 500.0);
    assert!(r.checks.iter().any(|c| c.name.contains("Hertz half-width") && c.pass));
}
