//! Regression suite: the key figures of every reference scene (Lemke's run) against recorded values.
//!
//! Origin of the recorded values: `reference/expected/key-figures.csv`, written by this test itself when run as
//! `ROLLBEM_RECORD=1 cargo test --release --test regression` (the only way to regenerate it; never edit it by
//! hand). Recorded values guard against *unintended change*; they are not evidence of correctness, which comes
//! from the tests against theory (Hertz, Cattaneo–Mindlin, BEM closed forms) and against peer solvers. Every
//! reference scene must also pass its own checks (`tests/reference_scenes.rs`). Counts of nodes per state must
//! match exactly; real figures to 1e-9 of their natural scale (the computation is deterministic on one machine;
//! the slack covers instruction-set differences in faer's kernels): forces relative to the scene's P, the moment to
//! P·R, lengths to R, the rotation to 1 rad, the peak pressure to itself. A figure that is zero to round-off (the
//! moment of a symmetric contact, the shear of a frictionless one) is compared on that scale, not on its own. Scenes
//! with `[stresses]` also record the largest principal shear (to itself) and its depth (to R).

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::scene::Scene;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const FIGURES: [&str; 18] = [
    "status",
    "normal",
    "tangential",
    "moment",
    "d_normal",
    "d_tangential",
    "rotation",
    "x_min",
    "x_max",
    "peak_pressure",
    "fit_half_width",
    "stick_x_min",
    "stick_x_max",
    "nodes_contact",
    "nodes_stick",
    "nodes_slip",
    "max_principal_shear",
    "max_principal_shear_depth",
];

fn figures() -> BTreeMap<String, Vec<String>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    paths.retain(|p| p.extension().is_some_and(|x| x == "toml"));
    paths.sort();
    let mut out = BTreeMap::new();
    for p in paths {
        let mut s = Scene::from_file(&p).unwrap();
        s = s.edit(|d| d.solvers.use_ = vec!["lemke".to_string()]).unwrap();
        let r = run_scene(&s).unwrap();
        let l = &r.runs[0];
        let f = |v: Option<f64>| v.map(|v| format!("{v:e}")).unwrap_or_default();
        let (res, rb, c) = (l.resultants, l.rigid_body, l.contact.as_ref());
        // With [stresses]: the maximum of the principal shear and its depth.
        let max_tau1 =
            l.stresses.as_ref().and_then(|st| st.field.maximum(rollbem::stresses::StressQuantity::PrincipalShear));
        out.insert(
            s.name().to_string(),
            vec![
                l.status.to_string(),
                f(res.map(|x| x.normal)),
                f(res.map(|x| x.tangential)),
                f(res.map(|x| x.moment)),
                f(rb.map(|x| x.normal)),
                f(rb.and_then(|x| x.tangential)),
                f(rb.map(|x| x.rotation)),
                f(c.and_then(|x| x.x_min)),
                f(c.and_then(|x| x.x_max)),
                f(c.map(|x| x.peak_pressure)),
                f(c.and_then(|x| x.fit_half_width)),
                f(c.and_then(|x| x.stick_x_min)),
                f(c.and_then(|x| x.stick_x_max)),
                c.map(|x| x.nodes_contact.to_string()).unwrap_or_default(),
                c.map(|x| x.nodes_stick.to_string()).unwrap_or_default(),
                c.map(|x| x.nodes_slip.to_string()).unwrap_or_default(),
                f(max_tau1.map(|m| m.value)),
                f(max_tau1.map(|m| m.depth)),
            ],
        );
    }
    out
}

#[test]
fn key_figures_match_the_recorded_values() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/expected/key-figures.csv");
    let now = figures();
    if std::env::var("ROLLBEM_RECORD").is_ok() {
        let mut text = String::from(
            "# Recorded key figures of the reference scenes (Lemke). Regenerate ONLY with\n\
             # ROLLBEM_RECORD=1 cargo test --release --test regression ; never edit by hand.\n",
        );
        text.push_str(&format!("scene,{}\n", FIGURES.join(",")));
        for (k, v) in &now {
            text.push_str(&format!("{k},{}\n", v.join(",")));
        }
        std::fs::write(&path, text).unwrap();
        return;
    }
    let mut rd =
        csv::ReaderBuilder::new().comment(Some(b'#')).from_path(&path).expect("recorded figures (see module docs)");
    let mut recorded = BTreeMap::new();
    for rec in rd.records() {
        let rec = rec.unwrap();
        recorded.insert(rec[0].to_string(), rec.iter().skip(1).map(|s| s.to_string()).collect::<Vec<_>>());
    }
    assert_eq!(
        recorded.keys().collect::<Vec<_>>(),
        now.keys().collect::<Vec<_>>(),
        "the set of reference scenes changed: re-record (see module docs)"
    );
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes");
    for (scene, vals) in &now {
        let old = &recorded[scene];
        let s = Scene::from_file(&dir.join(format!("{scene}.toml"))).unwrap();
        let r = s.document().wheel.radius;
        let p = vals[1].parse::<f64>().unwrap_or(0.0).abs();
        // One value per figure, now and recorded, before zipping them (a short row would compare only its head).
        assert_eq!(vals.len(), FIGURES.len(), "{scene}: figures now");
        assert_eq!(old.len(), FIGURES.len(), "{scene}: figures recorded (re-record, see module docs)");
        for ((name, a), b) in paired(paired(&FIGURES, vals), old) {
            let natural = match *name {
                "normal" | "tangential" => p,
                "moment" => p * r,
                "rotation" => 1.0,
                "peak_pressure" | "max_principal_shear" => 0.0,
                _ => r,
            };
            match (a.parse::<f64>(), b.parse::<f64>()) {
                (Ok(x), Ok(y)) if a.contains('e') || b.contains('e') => {
                    let scale = x.abs().max(y.abs()).max(natural).max(1e-300);
                    assert!((x - y).abs() <= 1e-9 * scale, "{scene}.{name}: {a} now, {b} recorded");
                }
                _ => assert_eq!(a, b, "{scene}.{name}"),
            }
        }
    }
}
