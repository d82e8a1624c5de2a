//! Two finite bodies through the CLI (issue 34, item 4): `rollbem run` and `check` of the two-body scenes, their
//! sweeps (`reference/two_bodies/sweeps/`: the load, the clearance, a creep curve) with shards, merge and resume as
//! for one wheel, and `rollbem plot` of their CSVs. Expected values come from theory: Hertz with the pair's R*
//! (R* = R/2 for two equal discs, Johnson §4.2), Carter's creep curve with that R* (Johnson §8.2), and the pin in a
//! bore from `rollbem::theory::pin_bore` (Persson's problem, derived and solved by Gauss–Chebyshev: shares nothing
//! with the BEM), each computed here independently of the CSV's reference columns.

#[path = "common/sweep_cli.rs"]
mod sweep_cli;

use rollbem::sweep::SweepRow;
use rollbem::theory::PinBore;
use std::path::{Path, PathBuf};
use sweep_cli::{bin, masked, run};

fn two_bodies(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies").join(name)
}

/// Run a sweep spec to `out` (extra arguments after it) and read its rows.
fn sweep(spec: &Path, out: &Path, extra: &[&str]) -> Vec<SweepRow> {
    run(bin().args(["--quiet", "sweep"]).arg(spec).arg("--out").arg(out).args(extra));
    SweepRow::read_csv(out).unwrap().1
}

const E_STAR: f64 = 210_000.0 / (2.0 * (1.0 - 0.09));

#[test]
fn pin_in_bore_sweep_meets_the_pin_bore_reference_and_shards_merge_and_resume() {
    // Expected: every row's half-angle and peak pressure within 1 % of theory::pin_bore at the row's load (issue
    // 34), from 6° to 75° and at zero clearance; the reference columns equal theory::pin_bore computed here; a zero
    // clearance row has no Hertz figures (R* infinite). Measured: the row at ΔR/R = 1e-2 is 0.5 % off where the
    // others are about 0.1 % (attributed, not isolated, to the O(ΔR/R) terms the reference drops: it linearises the
    // gap in ΔR and takes both radii as R). Shards merged and a resumed finished run equal the whole run
    // (provenance masked).
    let dir = tempfile::tempdir().unwrap();
    let spec = two_bodies("sweeps/pin-in-bore-load.toml");
    let whole = dir.path().join("whole.csv");
    let rows = sweep(&spec, &whole, &[]);
    assert_eq!(rows.len(), 6);
    for r in &rows {
        assert!(r.status.solved(), "{}", r.message);
        let (p, rb) = (r.normal_load.unwrap(), r.bodies.counter_radius.unwrap());
        let theory = if rb > 10.0 {
            PinBore::at_load(p / (E_STAR * (rb - 10.0)), 64).unwrap()
        } else {
            assert!(r.hertz_a.is_none() && r.bodies.contact_radius.is_none(), "zero clearance: no Hertz");
            PinBore::zero_clearance(64).unwrap()
        };
        let p0 = theory.peak_times_radius_over_load() * p / 10.0;
        assert!((r.bodies.pin_bore_half_angle.unwrap() / theory.half_angle - 1.0).abs() < 1e-9);
        assert!((r.bodies.pin_bore_p0.unwrap() / p0 - 1.0).abs() < 1e-9);
        let (b, pk) = (r.bodies.contact_half_angle.unwrap(), r.bodies.peak_pressure.unwrap());
        let (eb, ep) = (b / theory.half_angle - 1.0, pk / p0 - 1.0);
        eprintln!("ΔR {:.3}, P {p:.2}: b {:.3}° ({eb:+.2e}), p0 {pk:.3} ({ep:+.2e})", rb - 10.0, b.to_degrees());
        assert!(eb.abs() < 0.01 && ep.abs() < 0.01, "{eb} {ep}");
        assert!((r.bodies.pin_bore_half_angle_err.unwrap() - eb.abs()).abs() < 1e-12);
        assert_eq!(r.bodies.counter_body.as_deref(), Some("bore"));
    }
    // Shards 1/2 and 2/2, merged against the spec, equal the whole run; a resume of a finished CSV runs nothing.
    let shards: Vec<PathBuf> = (1..=2).map(|k| dir.path().join(format!("s{k}.csv"))).collect();
    for (k, s) in shards.iter().enumerate() {
        sweep(&spec, s, &["--shard", &format!("{}/2", k + 1)]);
    }
    let merged = dir.path().join("merged.csv");
    run(bin().args(["--quiet", "sweep-merge"]).arg(&merged).args(&shards).arg("--spec").arg(&spec));
    assert_eq!(masked(&merged), masked(&whole));
    let before = std::fs::read(&whole).unwrap();
    let out = run(bin().args(["--quiet", "sweep"]).arg(&spec).arg("--out").arg(&whole).arg("--resume"));
    assert!(out.contains("0 cases run now"), "{out}");
    assert_eq!(std::fs::read(&whole).unwrap(), before, "a finished sweep is left as it was");
    // Its figures: the half-angle and the peak pressure against P/(E*ΔR); the analysis is never guessed.
    let plots = dir.path().join("plots");
    run(bin().args(["--quiet", "plot"]).arg(&whole).args(["--analysis", "finite_bodies", "--out"]).arg(&plots));
    for f in ["whole-bore-angle.svg", "whole-bore-peak.svg"] {
        let svg = std::fs::read_to_string(plots.join(f)).unwrap();
        assert!(svg.contains("P/(E*ΔR) [1]") && svg.contains("pin_bore reference"), "{f}");
    }
    let o = bin().args(["--quiet", "plot"]).arg(&whole).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "a sweep CSV without --analysis is bad input");
    assert!(String::from_utf8_lossy(&o.stderr).contains("finite_bodies"));
}

#[test]
fn twin_disc_sweeps_against_hertz_and_carter_with_the_pairs_radius() {
    // Expected: R* = R/2 = 20 mm in every row; at a/R = 0.01 a and p0 within 0.5 % of Hertz (issue 34), and the
    // departure grows with the load (measured: 4.7e-3 in a at a/R = 0.1, tests/two_bodies.rs); the creep curve
    // within 1 % of μP of Carter with R* = R/2 at every creepage (Carter computed here).
    let dir = tempfile::tempdir().unwrap();
    let load = sweep(&two_bodies("sweeps/twin-disc-load.toml"), &dir.path().join("load.csv"), &[]);
    assert_eq!(load.len(), 3);
    let errs: Vec<f64> = load.iter().map(|r| r.metrics.hertz_a_err.unwrap()).collect();
    for r in &load {
        assert_eq!(r.bodies.contact_radius, Some(20.0));
        assert_eq!(r.bodies.counter_body.as_deref(), Some("disc"));
        assert!(r.bodies.pin_bore_half_angle.is_none());
    }
    assert!(errs[0] < 5e-3 && load[0].metrics.hertz_p0_err.unwrap() < 5e-3, "{errs:?}");
    assert!(errs.windows(2).all(|w| w[1] > w[0]), "{errs:?}");
    let creep = sweep(&two_bodies("sweeps/twin-disc-creep-curve.toml"), &dir.path().join("creep.csv"), &[]);
    assert_eq!(creep.len(), 5);
    for r in &creep {
        let (p, xi) = (r.normal_load.unwrap(), r.creepage.unwrap());
        let h = rollbem::theory::Hertz2D::from_load(p, 20.0, E_STAR);
        let carter = rollbem::theory::carter_force(&h, 0.3, 20.0, xi) / (0.3 * p);
        let q = r.tangential_load.unwrap() / (0.3 * p);
        assert!((q - carter).abs() < 0.01, "ξ {xi}: Q/μP {q} against Carter {carter}");
    }
    let plots = dir.path().join("plots");
    run(bin()
        .args(["--quiet", "plot"])
        .arg(dir.path().join("load.csv"))
        .args(["--analysis", "finite_bodies"])
        .arg("--out")
        .arg(&plots));
    assert!(plots.join("load-twin-disc.svg").is_file());
    run(bin()
        .args(["--quiet", "plot"])
        .arg(dir.path().join("creep.csv"))
        .args(["--analysis", "creep_curve"])
        .arg("--out")
        .arg(&plots));
    assert!(plots.join("creep-creep-curves.svg").is_file());
}

#[test]
fn two_body_scenes_run_check_and_plot_on_the_command_line() {
    // Expected: the scenes run and pass their checks (exit 0), the result document names the counter-body's
    // effect, and its tractions plot; a bad second body is bad input (exit 2) naming its key.
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("pin.json");
    run(bin().args(["--quiet", "run"]).arg(two_bodies("pin-in-bore.toml")).arg("--json").arg(&json));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert!(doc.to_string().contains("counter_body"), "the effects name the second body");
    run(bin().args(["--quiet", "check"]).arg(two_bodies("twin-disc-creep.toml")));
    run(bin().args(["--quiet", "plot"]).arg(&json).arg("--out").arg(dir.path()));
    assert!(dir.path().join("pin.lemke.tractions.svg").is_file());
    let text =
        std::fs::read_to_string(two_bodies("pin-in-bore.toml")).unwrap().replacen("radius = 10.01", "radius = 9.9", 1);
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, text).unwrap();
    let o = bin().args(["--quiet", "run"]).arg(&bad).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("counter_body.radius"));
}
