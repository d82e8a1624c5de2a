//! Every fuzz input kept in the repository, replayed through the library without libFuzzer, with the fuzz targets'
//! own checks (see `FUZZING.md`): the seeds (`fuzz/seeds/<target>/`), the minimized corpora (`fuzz/corpus/<target>/`)
//! and the regression inputs of bugs found (`fuzz/regressions/`, by name: `lcp-*.dat` LCP files, `sweep-*.toml`
//! sweep specs, any other `*.toml` a scene).
//!
//! - scene: `Scene::from_toml` returns `Ok` or an `Err` with a message; a valid scene is run through the model API
//!   exactly as the `scene` target runs it (`fuzz/fuzz_targets/bounded.rs`, included here): scenes of more than
//!   `MAX_RUN_ELEMENTS` = 24 elements or `MAX_SUBSTEPS` = 16 load-path substeps are only validated, the others
//!   built and solved with capped iteration budgets, and the report's runs must be consistent; a regression scene
//!   is then also built and solved as written (budgets not capped);
//! - LCP file: `lcp_io::parse` returns `Ok` or an `Err` with a message; an LCP of size ≤ 30 is solved by both
//!   Lemke engines within the pivot budget 5 n + 100;
//! - sweep spec: `SweepSpec::from_toml` returns `Ok` with 1 to `MAX_CASES` cases or an `Err` with a message; a spec
//!   of at most 64 cases is expanded against fixed reference bases into one case per grid point, or refused.
//!
//! A panic anywhere fails the test; so does a kind with no input at all (the folders must not silently vanish).

#[allow(dead_code)]
#[path = "../fuzz/fuzz_targets/bounded.rs"]
mod bounded;

use bounded::Ran;
use rollbem::lcp_io;
use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use rollbem::solvers::lemke::{self, dense::solve_dense, LemkeSettings};
use rollbem::sweep::{SweepSpec, MAX_CASES};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The files of a folder of the repository, sorted; none if the folder does not exist (`fuzz/corpus/<target>` is
/// optional: the seeds and regressions are always there).
fn files(dir: &str) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(root().join(dir)) else { return Vec::new() };
    let mut v: Vec<PathBuf> = entries.map(|e| e.unwrap().path()).filter(|p| p.is_file()).collect();
    v.sort();
    v
}

/// The input as the fuzz targets see it: bytes decoded lossily as UTF-8.
fn text(p: &Path) -> String {
    String::from_utf8_lossy(&std::fs::read(p).unwrap()).into_owned()
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Scene,
    Lcp,
    Sweep,
}

fn regression_kind(p: &Path) -> Option<Kind> {
    let name = p.file_name()?.to_str()?;
    match p.extension()?.to_str()? {
        "dat" if name.starts_with("lcp-") => Some(Kind::Lcp),
        "toml" if name.starts_with("sweep-") => Some(Kind::Sweep),
        "toml" => Some(Kind::Scene),
        _ => None,
    }
}

/// Seeds, corpus and regressions of one kind.
fn inputs(kind: Kind) -> Vec<PathBuf> {
    let target = match kind {
        Kind::Scene => "scene",
        Kind::Lcp => "lcp_file",
        Kind::Sweep => "sweep_spec",
    };
    let mut v = files(&format!("fuzz/seeds/{target}"));
    v.extend(files(&format!("fuzz/corpus/{target}")));
    v.extend(files("fuzz/regressions").into_iter().filter(|p| regression_kind(p) == Some(kind)));
    v
}

fn has_message(e: &rollbem::Error) -> bool {
    !e.to_string().trim().is_empty()
}

#[test]
fn every_regression_input_has_a_kind() {
    let all = files("fuzz/regressions");
    assert!(!all.is_empty(), "fuzz/regressions is empty");
    for p in &all {
        assert!(regression_kind(p).is_some(), "{}: not lcp-*.dat, sweep-*.toml or a scene *.toml", p.display());
    }
}

#[test]
fn scene_inputs_are_refused_with_a_message_or_run_on_a_model_without_panicking() {
    let all = inputs(Kind::Scene);
    let (mut invalid, mut too_large, mut refused, mut reported, mut solved_runs) = (0, 0, 0, 0, 0);
    let mut regressions_uncapped = 0;
    for p in &all {
        match Scene::from_toml(&text(p), p) {
            Err(e) => {
                assert!(has_message(&e), "{}: an error without a message", p.display());
                invalid += 1;
            }
            Ok(scene) => match bounded::run(&scene) {
                // A regression input is also run as written, its budgets not capped (the Lemke pivot-limit overflow
                // needs its huge `max_pivots_per_unknown`); they are few and small.
                Ran::Reported { solved, .. } if p.starts_with(root().join("fuzz/regressions")) => {
                    let model = Model::build(&scene).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
                    if let Err(e) = model.solve(&scene) {
                        assert!(has_message(&e), "{}: an error without a message", p.display());
                    }
                    reported += 1;
                    solved_runs += solved;
                    regressions_uncapped += 1;
                }
                Ran::TooLarge => too_large += 1,
                Ran::CapRefused | Ran::BuildRefused | Ran::SolveRefused => refused += 1,
                Ran::Reported { solved, .. } => {
                    reported += 1;
                    solved_runs += solved;
                }
            },
        }
    }
    eprintln!(
        "{} scene inputs: {invalid} invalid, {too_large} valid but too large to run, {refused} refused by the model \
         API, {reported} solved to a report ({solved_runs} runs `solved`); {regressions_uncapped} regression inputs \
         also run uncapped",
        all.len()
    );
    // The seeds alone give valid scenes, tiny ones that are run and solved, and full-size ones that are not.
    assert!(reported > 0 && solved_runs > 0 && too_large > 0, "nothing was run");
    assert!(regressions_uncapped > 0, "no regression scene was run as written");
}

#[test]
fn lcp_inputs_parse_or_are_refused_and_small_ones_are_solved_within_the_pivot_budget() {
    let all = inputs(Kind::Lcp);
    // The settings of the fuzz target: a pivot budget of 5 n + 100.
    let settings = LemkeSettings { max_pivots_per_unknown: 5, refactor_every: 7, ..LemkeSettings::default() };
    let (mut invalid, mut solved) = (0, 0);
    for p in &all {
        let lcp = match lcp_io::parse(&text(p), p) {
            Ok(lcp) => lcp,
            Err(e) => {
                assert!(has_message(&e), "{}: an error without a message", p.display());
                invalid += 1;
                continue;
            }
        };
        let n = lcp.size();
        if n > 30 {
            continue;
        }
        solved += 1;
        for (engine, out) in [("block", lemke::solve(&lcp, &settings)), ("dense", solve_dense(&lcp, &settings))] {
            assert_eq!((out.z.len(), out.w.len()), (n, n), "{} {engine}", p.display());
            assert!(out.pivots <= 5 * n + 100, "{} {engine}: {} pivots", p.display(), out.pivots);
        }
    }
    eprintln!("{} LCP inputs: {invalid} refused, {solved} of size ≤ 30 solved by both engines", all.len());
    assert!(invalid > 0 && solved > 0, "{} LCP inputs, {invalid} refused, {solved} solved", all.len());
}

#[test]
fn sweep_inputs_read_within_the_case_limit_or_are_refused() {
    let all = inputs(Kind::Sweep);
    let reference = |rel: &str| root().join("reference").join(rel);
    let spec_path = reference("sweeps/fuzz.toml");
    let (mut invalid, mut expanded) = (0, 0);
    for p in &all {
        let mut spec = match SweepSpec::from_toml(&text(p), &spec_path) {
            Ok(spec) => spec,
            Err(e) => {
                assert!(has_message(&e), "{}: an error without a message", p.display());
                invalid += 1;
                continue;
            }
        };
        let cases = spec.len();
        assert!((1..=MAX_CASES).contains(&cases), "{}: {cases} cases", p.display());
        if cases > 64 {
            continue;
        }
        spec.base = reference("scenes/hertz-hub-fine.toml");
        for b in spec.grid_base.iter_mut().flatten() {
            *b = reference("sweeps/bases/half-plane-cattaneo.toml");
        }
        match spec.cases(&spec_path) {
            Ok(built) => {
                assert_eq!(built.len(), cases, "{}: one case per grid point", p.display());
                assert!(built.iter().enumerate().all(|(i, c)| c.index == i), "{}: cases in order", p.display());
                expanded += 1;
            }
            Err(e) => assert!(has_message(&e), "{}: an error without a message", p.display()),
        }
    }
    eprintln!("{} sweep inputs: {invalid} refused, {expanded} expanded into their cases", all.len());
    assert!(invalid > 0 && expanded > 0, "{} sweep inputs, {invalid} refused, {expanded} expanded", all.len());
}

/// `fuzz/regressions/lemke-nan-residual-max-load.toml` (found by the `scene` target): a normal load of f64::MAX made
/// Lemke's complementarity residual NaN, which `Residuals::max` dropped (`f64::max(0, NaN) = 0`), so the run was
/// reported `solved` with a NaN residual. A NaN residual is now refused like one above the bound.
#[test]
fn a_nan_residual_is_not_a_solved_run() {
    let p = root().join("fuzz/regressions/lemke-nan-residual-max-load.toml");
    let scene = Scene::from_toml(&text(&p), &p).unwrap();
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    let mut statuses = Vec::new();
    for run in &report.runs {
        statuses.push(format!("{} {}", run.solver, run.status));
        if let Some(res) = run.residuals {
            assert!(!res.max().is_nan(), "{}: {} with residuals {res:?}", run.solver, run.status);
        }
        if run.status == rollbem::status::Status::Solved {
            let res = run.residuals.unwrap();
            assert!(res.complementarity.is_finite(), "{}: solved with residuals {res:?}", run.solver);
        }
    }
    eprintln!("{statuses:?}");
}

/// The `scene` target's second finding of 2026-11-27: a hub wheel of modulus 2.2e-308 (the smallest normal double)
/// under a load of 7. The compliance overflows; clarabel returned NaN pressures and an infinite d_N, every residual
/// computed from them came out 0, and the run was reported `solved`. Now a solution with a non-finite value is
/// `numerical_error` naming it, whatever its residuals (`post::Evaluation::first_non_finite`).
#[test]
fn a_solution_with_non_finite_values_is_not_a_solved_run() {
    let p = root().join("fuzz/regressions/clarabel-nan-pressure-subnormal-modulus.toml");
    let scene = Scene::from_toml(&text(&p), &p).unwrap();
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    let clarabel = report.runs.iter().find(|r| r.solver == "clarabel").expect("a clarabel run");
    assert_eq!(clarabel.status, rollbem::status::Status::NumericalError, "{}", clarabel.explanation());
    assert!(clarabel.explanation().contains("cannot be evaluated"), "{}", clarabel.explanation());
    for run in &report.runs {
        if run.status == rollbem::status::Status::Solved {
            let finite = run.nodes.iter().all(|n| n.pressure.is_finite() && n.shear.is_finite() && n.gap.is_finite());
            assert!(finite, "{}: solved with non-finite nodal values", run.solver);
        }
    }
}

/// The `scene` target's fourth finding of 2026-11-27 (bug 9 in FUZZING.md): a half-plane wheel of radius f64::MAX.
/// The models compute in units of the diameter 2R, which overflowed to ∞; the default datum depth R then scaled to
/// 0 and `HalfPlane::new` panicked on it. Other inputs reach the same kind of panic through a ratio that is 0 or ∞
/// in the kernels: a datum depth, a hub radius, a half-plane element width or a counter-body modulus too far from
/// the wheel's. Each is now refused when the scene is read, naming the key; a ratio just inside the range of normal
/// doubles is still read.
/// Expected outcome from the kernels' documented domain (`HalfPlane::new`: E > 0, 0 < D < ∞).
#[test]
fn lengths_and_moduli_the_kernels_cannot_represent_are_refused() {
    let p = root().join("fuzz/regressions/halfplane-radius-overflows-diameter.toml");
    let refused_field = |text: &str| match Scene::from_toml(text, Path::new("x.toml")) {
        Err(rollbem::Error::Invalid { field, message, .. }) => {
            assert!(message.contains("double"), "{field}: {message}");
            Some(field)
        }
        Err(e) => panic!("refused, but not as an invalid field: {e}"),
        Ok(_) => None,
    };
    assert_eq!(refused_field(&text(&p)).as_deref(), Some("wheel.radius"));
    // A half-plane wheel with an elastic counter-body (a reference scene), edited key by key.
    let base = text(&root().join("reference/scenes/steel-on-steel-cattaneo.toml"));
    assert_eq!(refused_field(&base), None);
    let counter = |modulus: &str| {
        let (head, tail) = base.split_once("[counter_body]").unwrap();
        format!("{head}[counter_body]{}", tail.replacen("youngs_modulus = 210000.0", modulus, 1))
    };
    let wheel = |from: &str, to: &str| base.replacen(from, to, 1);
    let cases = [
        // E_cb / E_w = 1e-305 / 2.1e5 is subnormal (< 2.2e-308); 1e-300 / 2.1e5 is normal.
        (counter("youngs_modulus = 1e-305"), Some("counter_body.youngs_modulus")),
        (counter("youngs_modulus = 1e-300"), None),
        // D / 2R with R = 460: 1e-310 is subnormal already, 1e306 / 920 is finite, 1e308 / 920 is not.
        (wheel("profile = \"parabola\"", "profile = \"parabola\"\ndatum_depth = 1e-310"), Some("wheel.datum_depth")),
        (wheel("profile = \"parabola\"", "profile = \"parabola\"\ndatum_depth = 1e306"), None),
        (
            wheel("kind = \"half_plane\"", "kind = \"half_plane\"\ndatum_depth = 1e-307"),
            Some("counter_body.datum_depth"),
        ),
        (wheel("kind = \"half_plane\"", "kind = \"half_plane\"\ndatum_depth = 1e-300"), None),
        // 2R = 2 × 8.9e307 is finite; 2 × 9e307 is not (the zone is widened with it: 12 / 1.8e308 is subnormal).
        (wheel("radius = 460.0", "radius = 9e307"), Some("wheel.radius")),
        (
            wheel("radius = 460.0", "radius = 8.9e307").replacen(
                "contact_half_width = 12.0",
                "contact_half_width = 1e306",
                1,
            ),
            None,
        ),
    ];
    for (i, (text, expected)) in cases.iter().enumerate() {
        assert_eq!(refused_field(text).as_deref(), *expected, "case {i}");
    }
    // Half-plane elements 2 × 1e-320 / 100 wide are 0 in units of 2R (the kernel asserted a width > 0); 2 × 1e-300
    // / 100 are a normal 2.2e-305 diameters (such a zone is then too small for the load: contact at its edge).
    let half_width = |hw: &str| base.replacen("contact_half_width = 12.0", hw, 1);
    assert_eq!(refused_field(&half_width("contact_half_width = 1e-320")).as_deref(), Some("mesh.contact_half_width"));
    assert_eq!(refused_field(&half_width("contact_half_width = 1e-300")), None);
    assert_eq!(refused_field(&half_width("contact_x = [1e-303, 2e-303]")).as_deref(), Some("mesh.contact_x"));
    // A hub-supported BEM wheel: hub radius / 2R = 1e-310 / 920 is subnormal.
    let hub = text(&root().join("reference/scenes/hertz-hub-fine.toml"));
    assert_eq!(refused_field(&hub), None);
    let tiny_hub = hub.replacen("radius = 100.0", "radius = 1e-310", 1);
    assert_eq!(refused_field(&tiny_hub).as_deref(), Some("wheel.support.radius"));
}
