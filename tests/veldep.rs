//! Friction laws of the slip velocity in steady rolling (src/veldep.rs), against CONTACT's `veldep_fric.inp`.
//!
//! Expected values: for a constant law, rollbem's Coulomb LCP solver on the same problem (an independent algorithm);
//! for the falling law, CONTACT's printed output of its case 1 (`examples/veldep_fric.ref_out`: FX/(FSTAT·FN) =
//! 0.5941, NCON = 81, NADH = 45; steady rolling at CKSI = −0.0009999, the exponential law L = 4, INISLP = 1).

use rollbem::formulation::SlipOperator;
use rollbem::pipeline::{run_scene, Model};
use rollbem::post::NodeState;
use rollbem::scene::Scene;
use rollbem::status::Status;
use rollbem::veldep::{
    solve_both, solve_steady, transient_step, FrictionLaw, Start, SteadyOutcome, SteadyProblem, SteadyStatus,
};

/// veldep_fric.inp's grid and bodies: wheel R = 460 (circle) on a flat, both G = 82 000, ν = 0.28 (E = 209 920),
/// 92 elements of 0.1 from XC1 = −4.6 on a strip DY = 200, FN = 622 216 (3111.08 per unit width), CKSI =
/// −0.0009999, CHI = 0 (direction +1).
fn scene() -> Scene {
    // The same scene the report's falling-friction section runs.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/veldep/veldep-fric.toml");
    Scene::from_file(std::path::Path::new(path)).unwrap()
}

/// D·K_TT, the normal nodal forces of the Coulomb run (the normal problem does not depend on the tangential one:
/// identical materials), the force unit E·L0 and the Coulomb run itself.
fn parts() -> (faer::Mat<f64>, Vec<f64>, f64, rollbem::results::SolverRun) {
    let s = scene();
    let model = Model::build(&s).unwrap();
    let flex = &model.built().flex;
    let run = run_scene(&s).unwrap().runs[0].clone();
    assert_eq!(run.status, Status::Solved, "{}", run.explanation());
    let e = flex.scales.modulus;
    let f: Vec<f64> = run.nodes.iter().zip(&flex.weights).map(|(n, w)| n.pressure * w / e).collect();
    let m = SlipOperator::steady(&flex.x, 1).apply_mat(flex.k_tt.as_ref().unwrap());
    (m, f, e * flex.scales.length, run)
}

fn solve(law: FrictionLaw, start: Start) -> (SteadyOutcome, f64, usize, usize) {
    let (m, f, force, _) = parts();
    let p = SteadyProblem { slip_matrix: &m, normal: &f, creepage: -0.0009999, offset: None, velocity: 45000.0, law };
    let out = solve_steady(&p, start, 1e-10, 200).unwrap();
    let q = out.tangential.iter().sum::<f64>() * force;
    let contact = f.iter().filter(|&&v| v > 0.0).count();
    let stick = out.stick.iter().filter(|&&b| b).count();
    (out, q, contact, stick)
}

/// A constant law is Coulomb: from either start the solver meets the LCP's answer on the same problem.
#[test]
fn a_constant_law_is_coulomb() {
    let (_, _, _, run) = parts();
    let q_lcp = run.resultants.unwrap().tangential;
    let stick_lcp = run.nodes.iter().filter(|n| n.state == NodeState::Stick).count();
    for start in [Start::Below, Start::Above] {
        let (out, q, _, stick) = solve(FrictionLaw::Coulomb { mu: 0.3 }, start);
        assert!(matches!(out.status, SteadyStatus::Converged { .. }), "{start:?}: {:?}", out.status);
        assert!((q - q_lcp).abs() <= 1e-9 * 0.3 * 3111.08, "{start:?}: {q} against {q_lcp}");
        assert_eq!(stick, stick_lcp, "{start:?}");
    }
}

/// CONTACT's case 1: the exponential law (FKIN 0.18, FEXP1 0.12, SABSH1 100 mm/s: μ(0) = 0.3), V = 45 m/s: FX/(μ FN),
/// the contact and adhesion counts to CONTACT's printed digits, from both starts (here they meet: one solution).
#[test]
fn veldep_fric_case_1_against_contact() {
    let law = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
    for start in [Start::Below, Start::Above] {
        let (out, q, contact, stick) = solve(law, start);
        assert!(matches!(out.status, SteadyStatus::Converged { residual, .. } if residual < 1e-12), "{:?}", out.status);
        let ratio = q / (0.3 * 3111.08);
        assert_eq!((ratio * 1e4).round() / 1e4, 0.5941, "{start:?}: FX/(μ FN) = {ratio}");
        assert_eq!((contact, stick), (81, 45), "{start:?}");
    }
}

/// CONTACT's rational law (L = 3: FKIN 0.18, FRAT1 0.06, SABSH1 100, FRAT2 0.06, SABSH2 0.3162) falls steeply at
/// small slip velocities: at CKSI = −0.0009999 the two starts converge (residual ≤ 1e-12) to two different solutions,
/// and the outcome says so (CONTACT finds two as well: `branch_pair_against_contact`).
#[test]
fn falling_friction_has_two_branches_and_says_so() {
    let law = FrictionLaw::Rational { kinetic: 0.18, first: (0.06, 100.0), second: (0.06, 0.3162) };
    let (m, f, force, _) = parts();
    let p = SteadyProblem { slip_matrix: &m, normal: &f, creepage: -0.0009999, offset: None, velocity: 45000.0, law };
    let b = solve_both(&p, 1e-10, 200).unwrap();
    assert!(b.distinct);
    assert_eq!((b.below.start, b.above.start), (Start::Below, Start::Above));
    for o in [&b.below, &b.above] {
        assert!(matches!(o.status, SteadyStatus::Converged { residual, .. } if residual < 1e-12), "{:?}", o.status);
    }
    // The forces differ between the branches (CONTACT: 0.5655 and 0.5652; compared in branch_pair_against_contact).
    let q = |o: &SteadyOutcome| o.tangential.iter().sum::<f64>() * force / (0.3 * 3111.08);
    assert!(q(&b.below) - q(&b.above) > 2e-4, "{} {}", q(&b.below), q(&b.above));
    // The exponential law of case 1 has one: not distinct.
    let exp = SteadyProblem {
        law: FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) },
        ..p.clone()
    };
    assert!(!solve_both(&exp, 1e-10, 200).unwrap().distinct);
}

/// An iteration cut short is a status with its residual, not a solution.
#[test]
fn a_cut_short_iteration_is_not_a_solution() {
    let law = FrictionLaw::Rational { kinetic: 0.18, first: (0.06, 100.0), second: (0.06, 0.3162) };
    let (m, f, _, _) = parts();
    let p = SteadyProblem { slip_matrix: &m, normal: &f, creepage: -0.0009999, offset: None, velocity: 45000.0, law };
    let out = solve_steady(&p, Start::Below, 1e-10, 1).unwrap();
    match out.status {
        SteadyStatus::NotConverged { iterations, residual } => {
            assert!(iterations == 1 && residual > 1e-10, "{residual}")
        }
        s => panic!("{s:?}"),
    }
    let bad = SteadyProblem { velocity: -1.0, ..p.clone() };
    assert!(solve_steady(&bad, Start::Below, 1e-10, 10).unwrap_err().to_string().contains("velocity"));
}

/// CONTACT's cases 2 and 4: one time step (Δq = DX = 0.1 mm, CKSI = −0.001) from the steady state of case 1 (case 3
/// repeats it), started from below (case 2, INISLP = 1: FX/(μ FN) = 0.5977, NCON 81, NADH 77) and from above (case 4,
/// INISLP = −1: 0.5702, 81, 34), the exponential law: two different solutions of one step from two starts, both
/// converged. The counts agree in both, FX within 1e-4 (case 4 to the printed digits, case 2 0.59764).
#[test]
fn veldep_fric_time_steps_against_contact() {
    let law = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
    let s = scene();
    let model = Model::build(&s).unwrap();
    let flex = &model.built().flex;
    let k = flex.k_tt.as_ref().unwrap();
    let (m, f, force, _) = parts();
    let steady =
        SteadyProblem { slip_matrix: &m, normal: &f, creepage: -0.0009999, offset: None, velocity: 45000.0, law };
    let h1 = solve_steady(&steady, Start::Below, 1e-10, 200).unwrap().tangential;
    let dq = flex.x[1] - flex.x[0];
    let (mt, c) = transient_step(k, &h1, dq, 1).unwrap();
    for (start, ratio, stick) in [(Start::Below, 0.5977, 77), (Start::Above, 0.5702, 34)] {
        let p =
            SteadyProblem { slip_matrix: &mt, normal: &f, creepage: -0.001, offset: Some(&c), velocity: 45000.0, law };
        let out = solve_steady(&p, start, 1e-10, 200).unwrap();
        let q = out.tangential.iter().sum::<f64>() * force / (0.3 * 3111.08);
        let n_stick = out.stick.iter().filter(|&&b| b).count();
        assert!(matches!(out.status, SteadyStatus::Converged { residual, .. } if residual < 1e-12), "{:?}", out.status);
        assert_eq!((f.iter().filter(|&&v| v > 0.0).count(), n_stick), (81, stick), "{start:?}");
        // Within 1e-4 of the printed value: print rounding plus CONTACT's stopping rule (the bound of
        // `veldep_fric_fifty_time_steps_against_contact`); case 4 rounds to the printed digits, case 2 is 0.59764
        // against the printed 0.5977.
        assert!((q - ratio).abs() <= 1e-4, "{start:?}: {q}");
    }
}

// ---- The scene keys (`[contact] friction_law`, `[rolling] velocity`) and the pipeline -------------------------------

/// veldep_fric.inp's scene (as [`scene`]) without `[contact]` and `[rolling]`.
const BASE: &str = r#"
name = "veldep-fric"
[wheel]
radius = 460
youngs_modulus = 209920
poisson_ratio = 0.28
model = "half_plane"
profile = "circle"
[counter_body]
kind = "half_plane"
youngs_modulus = 209920
poisson_ratio = 0.28
[mesh]
element = "constant"
contact_x = [-4.65, 4.55]
contact_elements = 92
strip_width = 200
[drive]
normal_load = 3111.08
[solvers]
use = ["active_set"]
"#;

/// [`BASE`] with `[contact]` and `[rolling]` given by the caller.
fn scene_with(contact: &str, rolling: &str) -> Result<Scene, rollbem::Error> {
    let text = format!("{BASE}\n[contact]\n{contact}\n[rolling]\n{rolling}\n");
    Scene::from_toml(&text, std::path::Path::new("veldep-scene.toml"))
}

const EXPONENTIAL: &str = r#"friction_law = { kind = "exponential", kinetic = 0.18, first = [0.12, 100.0] }"#;
const STEADY: &str = "mode = \"steady\"\ncreepage = -0.0009999\ndirection = 1\nvelocity = 45000";

/// CONTACT's case 1 as a scene: the run carries the start from below, FX/(μ FN), NCON, NADH to CONTACT's printed
/// digits (0.5941, 81, 45); both starts are reported, converged, and the same solution (one branch here); the node
/// states are the law's (45 stick, 36 slip; CONTACT's NSLIP 36), Carter is not compared (a note says why).
#[test]
fn a_falling_law_scene_runs_case_1() {
    let s = scene_with(EXPONENTIAL, STEADY).unwrap();
    assert!(s.slip_velocity_friction().is_some());
    assert_eq!(s.friction(), 0.3, "friction is the law's μ(0)");
    let before = rollbem::veldep::solves_on_this_thread();
    let report = run_scene(&s).unwrap();
    assert_eq!(rollbem::veldep::solves_on_this_thread() - before, 2, "one solve per start");
    let run = &report.runs[0];
    assert_eq!(run.status, Status::Solved, "{}", run.explanation());
    let q = run.resultants.unwrap().tangential / (0.3 * 3111.08);
    assert_eq!((q * 1e4).round() / 1e4, 0.5941, "{q}");
    let c = run.contact.as_ref().unwrap();
    assert_eq!((c.nodes_contact, c.nodes_stick, c.nodes_slip), (81, 45, 36));
    let b = run.branches.unwrap();
    assert!(b.below.converged && b.above.converged && !b.distinct, "{b:?}");
    assert_eq!(b.carried, Start::Below);
    assert_eq!((b.below.nodes_stick, b.above.nodes_stick), (Some(45), Some(45)));
    assert!((b.below.tangential.unwrap() - run.resultants.unwrap().tangential).abs() < 1e-9 * 3111.08);
    assert!(run.residuals.unwrap().friction.unwrap() < 1e-10);
    let text = rollbem::results::render::run_table(&report);
    assert!(text.contains("from below (all stick)") && text.contains("the same solution"), "{text}");
    assert!(report.checks.iter().all(|c| c.pass), "{:?}", report.checks);
}

/// A constant law (both terms 0) is Coulomb's μ = kinetic, posed to the same solver on the same problem: every
/// nodal value and resultant is bit for bit the Coulomb scene's (the reason: it IS the Coulomb scene, normalised when
/// read), and neither run reaches `rollbem::veldep` (its per-thread solve count does not move).
#[test]
fn a_constant_law_scene_is_coulomb_bit_for_bit() {
    let steady = "mode = \"steady\"\ncreepage = -0.0009999\ndirection = 1";
    let coulomb = scene_with("friction = 0.3", steady).unwrap();
    let constant = scene_with(
        r#"friction_law = { kind = "rational", kinetic = 0.3, first = [0.0, 0.0], second = [0.0, 0.0] }"#,
        &format!("{steady}\nvelocity = 45000"),
    )
    .unwrap();
    assert!(constant.slip_velocity_friction().is_none());
    let before = rollbem::veldep::solves_on_this_thread();
    let (a, b) = (run_scene(&coulomb).unwrap(), run_scene(&constant).unwrap());
    assert_eq!(rollbem::veldep::solves_on_this_thread(), before, "a Coulomb path called the veldep solver");
    let (ra, rb) = (&a.runs[0], &b.runs[0]);
    assert_eq!(ra.status, Status::Solved);
    assert!(rb.branches.is_none());
    let bits = |r: &rollbem::results::SolverRun| -> Vec<u64> {
        let res = r.resultants.unwrap();
        r.nodes
            .iter()
            .flat_map(|n| [n.pressure, n.shear, n.gap, n.slip_velocity.unwrap_or(0.0)])
            .chain([res.normal, res.tangential, res.moment])
            .map(f64::to_bits)
            .collect()
    };
    assert_eq!(bits(ra), bits(rb));
    assert!(ra.nodes.iter().zip(&rb.nodes).all(|(x, y)| x.state == y.state));
}

/// The rational law's two branches at CKSI = −0.0009999 through a scene: both starts reported, distinct, each with
/// its force and stick count (the library's, compared with CONTACT in `branch_pair_against_contact`), the run
/// carrying the start the scene names; the table says "two different solutions".
#[test]
fn a_scene_reports_both_branches() {
    let rational = |start: &str| {
        format!(
            r#"friction_law = {{ kind = "rational", kinetic = 0.18, first = [0.06, 100.0], second = [0.06, 0.3162], start = "{start}" }}"#
        )
    };
    for (start, carried, stick) in [("below", Start::Below, 40), ("above", Start::Above, 39)] {
        let report = run_scene(&scene_with(&rational(start), STEADY).unwrap()).unwrap();
        let run = &report.runs[0];
        assert_eq!(run.status, Status::Solved, "{}", run.explanation());
        let b = run.branches.unwrap();
        assert!(b.distinct && b.carried == carried, "{b:?}");
        // CONTACT: 40 from below, 38 from above (39 here: see branch_pair_against_contact).
        assert_eq!((b.below.nodes_stick, b.above.nodes_stick), (Some(40), Some(39)));
        assert_eq!(run.contact.as_ref().unwrap().nodes_stick, stick);
        let text = rollbem::results::render::run_table(&report);
        assert!(text.contains("two different solutions"), "{text}");
    }
}

/// Bad keys and values are refused when the scene is read, naming the key (exit 2 through the CLI: below).
#[test]
fn bad_friction_law_keys_are_refused_naming_them() {
    let law = |body: &str| format!("friction_law = {{ {body} }}");
    let cases = [
        (law(r#"kind = "exponential", kinetic = 0.0, first = [0.12, 100.0]"#), STEADY.to_string(), "kinetic"),
        (law(r#"kind = "linear", kinetic = 0.18, first = [-0.1, 100.0]"#), STEADY.into(), "friction_law.first"),
        (law(r#"kind = "rational", kinetic = 0.18, first = [0.1, 0.0]"#), STEADY.into(), "friction_law.first"),
        (
            law(r#"kind = "rational", kinetic = 0.18, first = [0.1, 1.0], second = [0.1, -1.0]"#),
            STEADY.into(),
            "friction_law.second",
        ),
        (law(r#"kind = "cubic", kinetic = 0.18, first = [0.1, 1.0]"#), STEADY.into(), "kind"),
        (law(r#"kind = "linear", kinetic = 0.18, first = [0.1, 1.0], memory = 1.0"#), STEADY.into(), "memory"),
        (format!("friction = 0.2\n{EXPONENTIAL}"), STEADY.into(), "contact.friction"),
        (EXPONENTIAL.into(), "mode = \"steady\"\ncreepage = -0.001\ndirection = 1".into(), "rolling.velocity"),
        (
            EXPONENTIAL.into(),
            "mode = \"steady\"\ncreepage = -0.001\ndirection = 1\nvelocity = 0".into(),
            "rolling.velocity",
        ),
        (
            EXPONENTIAL.into(),
            "mode = \"steady\"\ncreepage = -0.001\ndirection = 1\nvelocity = -1".into(),
            "rolling.velocity",
        ),
        (
            EXPONENTIAL.into(),
            "mode = \"seed\"\ncreepage = -0.001\ndirection = 1\nvelocity = 45000".into(),
            "contact.friction_law",
        ),
        ("friction = 0.3".into(), STEADY.into(), "rolling.velocity"),
        (
            law(
                r#"kind = "exponential", kinetic = 0.18, first = [0.12, 100.0], memory = { distance = 0.0, min_velocity = 1.0 }"#,
            ),
            STEADY.into(),
            "friction_law.memory.distance",
        ),
        (
            law(
                r#"kind = "exponential", kinetic = 0.18, first = [0.12, 100.0], memory = { distance = 0.003, min_velocity = -1.0 }"#,
            ),
            STEADY.into(),
            "friction_law.memory.min_velocity",
        ),
        (
            law(r#"kind = "exponential", kinetic = 0.18, first = [0.12, 100.0], memory = { distance = 0.003 }"#),
            STEADY.into(),
            "min_velocity",
        ),
    ];
    for (contact, rolling, key) in cases {
        let err = scene_with(&contact, &rolling).map(|_| ()).unwrap_err().to_string();
        assert!(err.contains(key), "{contact} / {rolling}: `{err}` does not name {key}");
    }
    // A coupled pair (steel on aluminium, coupling on) is refused when its model is built, naming the key.
    let s = scene_with(EXPONENTIAL, STEADY).unwrap();
    let coupled = s
        .edit(|d| {
            d.counter_body = rollbem::scene::document::CounterBodyTable::HalfPlane {
                youngs_modulus: 70000.0,
                poisson_ratio: 0.33,
                datum_depth: None,
                viscoelastic: None,
            }
        })
        .unwrap();
    let err = Model::build(&coupled).unwrap_err();
    assert!(err.to_string().contains("contact.friction_law"), "{err}");
    assert_eq!(err.exit_code(), 2);
}

/// Through the CLI: a bad friction-law value exits 2 naming the key, and writes nothing.
#[test]
fn the_cli_refuses_a_bad_law_with_exit_2() {
    let dir = std::env::temp_dir().join(format!("rollbem-veldep-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad-law.toml");
    // The base scene, with a negative half-value slip velocity.
    let scene = format!(
        "{BASE}\n[contact]\nfriction_law = {{ kind = \"exponential\", kinetic = 0.18, first = [0.12, -100.0] }}\n\
         [rolling]\n{STEADY}\n"
    );
    std::fs::write(&path, scene).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(["run", path.to_str().unwrap(), "--json", dir.join("out").to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("contact.friction_law.first"), "{stderr}");
    assert!(!dir.join("out").join("veldep-fric.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}

// ---- Transient rolling over many steps: CONTACT's cases 3 to 53 ------------------------------------------------------

/// One row of reference/veldep/veldep_fric_cases.csv (CONTACT's printed figures, extracted by
/// reference/veldep/extract.py from examples/veldep_fric.ref_out): (case, steady, CKSI, INISLP, FX/FSTAT/FN as
/// printed, NADH where printed).
fn contact_cases() -> Vec<(usize, bool, f64, i32, String, Option<usize>)> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/reference/veldep/veldep_fric_cases.csv"))
        .unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            (
                c[0].parse().unwrap(),
                c[1] == "steady",
                c[2].parse().unwrap(),
                c[3].parse().unwrap(),
                c[4].into(),
                c[6].parse().ok(),
            )
        })
        .collect()
}

/// CONTACT's case 3 (the steady state of case 1, from below) and then its 50 time steps, cases 4 to 53 (Δq = DX =
/// 0.1 mm, CKSI = −0.001, every step started from above, INISLP = −1, each from the previous step's state), the
/// exponential law: every step converges (law residual < 1e-12), FX/(μ FN) follows CONTACT's printed value at every
/// step — the force rises over six steps and drops as the traction peak leaves the contact, eight times — and NADH
/// where CONTACT prints it (cases 4 and 53: 34 and 35).
///
/// The bound, 1e-4 on FX/(μ FN): half a unit of the printed fourth digit (5e-5) plus CONTACT's stopping rule, whose
/// outer iteration ends when the slip velocities change by less than 1e-3 of their RMS (m_stang.f90): stopping this
/// solver's outer iteration by that rule (an experiment, not kept) moved FX/(μ FN) by up to 5.9e-5 from the converged
/// value. Measured: 40 of the 50 steps round to CONTACT's four digits, the largest difference is 8.2e-5 (the
/// experiment stopped by CONTACT's rule gave 39 of 50, so the rule alone does not explain which ones differ).
#[test]
fn veldep_fric_fifty_time_steps_against_contact() {
    use rollbem::veldep::transient::{roll, TransientProblem, TransientStatus};
    let cases = contact_cases();
    let law = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
    let s = scene();
    let model = Model::build(&s).unwrap();
    let flex = &model.built().flex;
    let (m, f, force, _) = parts();
    let (_, steady, cksi, inislp, _, _) = &cases[2];
    assert!(*steady && *inislp > 0);
    let p3 = SteadyProblem { slip_matrix: &m, normal: &f, creepage: *cksi, offset: None, velocity: 45000.0, law };
    let h3 = solve_steady(&p3, Start::Below, 1e-10, 200).unwrap().tangential;
    let steps = &cases[3..];
    assert_eq!(steps.len(), 50);
    assert!(steps.iter().all(|c| !c.1 && c.2 == -0.001 && c.3 < 0));
    let problem = TransientProblem {
        k_tt: flex.k_tt.as_ref().unwrap(),
        normal: &f,
        creepage: -0.001,
        velocity: 45000.0,
        law,
        dq: flex.x[1] - flex.x[0],
        direction: 1,
    };
    let run = roll(&problem, &h3, &[Start::Above; 50], 1e-10, 200).unwrap();
    assert_eq!(run.status, TransientStatus::Completed);
    let mut misses = Vec::new();
    for ((case, _, _, _, printed, nadh), out) in steps.iter().zip(&run.steps) {
        assert!(matches!(out.status, SteadyStatus::Converged { residual, .. } if residual < 1e-12), "{case}");
        let q = out.tangential.iter().sum::<f64>() * force / (0.3 * 3111.08);
        let contact: f64 = printed.parse().unwrap();
        if (q - contact).abs() > 1e-4 {
            misses.push(format!("case {case}: {q:.6} against {printed}"));
        }
        if let Some(nadh) = nadh {
            assert_eq!(out.stick.iter().filter(|&&b| b).count(), *nadh, "case {case}");
        }
    }
    assert!(misses.is_empty(), "{misses:#?}");
}

// ---- The branch pair: the steady problem at CKSI = −0.001 and −0.0009999 from both starts --------------------------

/// CONTACT's steady solutions of veldep_fric's problem (reference/veldep/steady_branches.csv, written by
/// reference/veldep/steady_branches.sh running CONTACT r2707): (law, CKSI, INISLP, FX/FSTAT/FN, NADH, MEMDST).
fn contact_branches_all() -> Vec<(String, f64, i32, f64, usize, f64)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/veldep/steady_branches.csv");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            let num = |k: usize| c[k].parse::<f64>().unwrap();
            (c[1].into(), num(2), c[3].parse().unwrap(), num(4), c[6].parse().unwrap(), num(8))
        })
        .collect()
}

/// The cases of [`contact_branches_all`] without friction memory, at the issue's two creepages from both starts:
/// (law, CKSI, INISLP, FX/FSTAT/FN, NADH).
fn contact_branches() -> Vec<(String, f64, i32, f64, usize)> {
    contact_branches_all().into_iter().filter(|r| r.5 == 0.0).map(|(l, c, i, f, n, _)| (l, c, i, f, n)).collect()
}

/// The branch pair (issue 33): the steady problem at CKSI = −0.001 and −0.0009999, from below (INISLP = 1) and from
/// above (INISLP = −1), against CONTACT's own runs of the same eight cases (`contact_branches`). The exponential law
/// of veldep_fric.inp has one solution at both creepages (both starts meet: 0.5941, 45 stick, as CONTACT); the
/// rational law has two, found from the two starts at both creepages and reported as two (`distinct`), as CONTACT
/// finds two (0.5656/0.5655 from below, 0.5652 from above). FX/(μ FN) within 1e-4 of CONTACT's printed value (the
/// bound of `veldep_fric_fifty_time_steps_against_contact`: print rounding plus CONTACT's stopping rule); the stick
/// counts equal CONTACT's NADH except the rational law from above, where one element differs (39 here against
/// CONTACT's 38 at both creepages; CONTACT run with EPS = 1e-12 instead of 1e-7 still prints 38, so it is not its
/// stopping rule). Not explained: that branch's count is held to within one element of CONTACT's, not to our own
/// figure.
#[test]
fn branch_pair_against_contact() {
    let (m, f, force, _) = parts();
    for (law_name, cksi, inislp, fx, nadh) in contact_branches() {
        let law = match law_name.as_str() {
            "exponential" => FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) },
            _ => FrictionLaw::Rational { kinetic: 0.18, first: (0.06, 100.0), second: (0.06, 0.3162) },
        };
        let p = SteadyProblem { slip_matrix: &m, normal: &f, creepage: cksi, offset: None, velocity: 45000.0, law };
        let b = solve_both(&p, 1e-10, 200).unwrap();
        let case = format!("{law_name} at {cksi} from {}", if inislp > 0 { "below" } else { "above" });
        assert_eq!(b.distinct, law_name == "rational", "{case}");
        let o = if inislp > 0 { &b.below } else { &b.above };
        assert_eq!(o.start, if inislp > 0 { Start::Below } else { Start::Above });
        assert!(matches!(o.status, SteadyStatus::Converged { residual, .. } if residual < 1e-12), "{case}");
        let q = o.tangential.iter().sum::<f64>() * force / (0.3 * 3111.08);
        assert!((q - fx).abs() <= 1e-4, "{case}: {q} against CONTACT's {fx}");
        let stick = o.stick.iter().filter(|&&x| x).count();
        let allowed = if law_name == "rational" && inislp < 0 { 1 } else { 0 };
        assert!(stick.abs_diff(nadh) <= allowed, "{case}: {stick} stick (CONTACT: {nadh})");
    }
}

/// CONTACT's friction memory (MEMDST = 0.003 mm, MEM_S0 = 1 mm/s, the exponential law of veldep_fric.inp) in steady
/// rolling at both creepages from both starts, against CONTACT's own runs (reference/veldep/steady_branches.csv,
/// cases 9–12: FX/(μ FN) 0.6117 and 0.6116, NADH 48): within 1e-4 of μ FN (the bound of the time steps: print
/// rounding and CONTACT's stopping rule), the same stick counts, one solution from both starts; without memory the
/// same problem gives 0.5941 (memory raises the force: the coefficient falls gradually behind the stick zone).
/// Measured: 0.611630 and 0.611587 (both starts alike), law residual ≤ 1e-14, 14–15 outer iterations.
#[test]
fn friction_memory_against_contact() {
    use rollbem::veldep::{solve_both_with, Memory};
    let (m, f, force, _) = parts();
    let s = scene();
    let model = Model::build(&s).unwrap();
    let flex = &model.built().flex;
    let element = (flex.x[1] - flex.x[0]) * flex.scales.length;
    assert!((element - 0.1).abs() < 1e-12, "{element}");
    let memory = Memory { distance: 0.003, min_velocity: 1.0, element, direction: 1 };
    let law = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
    let rows: Vec<_> = contact_branches_all().into_iter().filter(|r| r.5 > 0.0).collect();
    assert_eq!(rows.len(), 4);
    for (law_name, cksi, inislp, fx, nadh, memdst) in rows {
        assert_eq!((law_name.as_str(), memdst), ("exponential", 0.003));
        let p = SteadyProblem { slip_matrix: &m, normal: &f, creepage: cksi, offset: None, velocity: 45000.0, law };
        let b = solve_both_with(&p, Some(memory), 1e-10, 200).unwrap();
        assert!(!b.distinct);
        let o = if inislp > 0 { &b.below } else { &b.above };
        assert!(matches!(o.status, SteadyStatus::Converged { residual, .. } if residual < 1e-10), "{:?}", o.status);
        let q = o.tangential.iter().sum::<f64>() * force / (0.3 * 3111.08);
        assert!((q - fx).abs() <= 1e-4, "{cksi} {inislp}: {q} against CONTACT's {fx}");
        assert_eq!(o.stick.iter().filter(|&&x| x).count(), nadh, "{cksi} {inislp}");
    }
}

/// Friction memory through a scene (`memory = { distance, min_velocity }`): CONTACT's case 11 of
/// steady_branches.csv (CKSI = −0.0009999, MEMDST = 0.003, MEM_S0 = 1: 0.6116, NADH 48) within 1e-4 of μ FN, both
/// starts one solution.
#[test]
fn friction_memory_in_a_scene() {
    let s = scene_with(
        r#"friction_law = { kind = "exponential", kinetic = 0.18, first = [0.12, 100.0], memory = { distance = 0.003, min_velocity = 1.0 } }"#,
        STEADY,
    )
    .unwrap();
    let run = run_scene(&s).unwrap().runs[0].clone();
    assert_eq!(run.status, Status::Solved, "{}", run.explanation());
    let q = run.resultants.unwrap().tangential / (0.3 * 3111.08);
    assert!((q - 0.6116).abs() <= 1e-4, "{q}");
    assert_eq!(run.contact.as_ref().unwrap().nodes_stick, 48);
    assert!(!run.branches.unwrap().distinct);
}
