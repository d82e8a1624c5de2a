//! Frictionless contact, end to end from a scene: Hertz at equal load, Lemke against clarabel, resultants,
//! problem sizes and unit invariance. Expected values: Hertz's formulas (REFERENCES.md, `rollbem::theory::Hertz2D`), the
//! prescribed load, and the peer solver.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use rollbem::source::{self, Blocks};
use rollbem::tolerances as tol;
use std::path::Path;

/// A hub-supported wheel scene. `a_over_r` sets the Hertz half-width the load is chosen for; the candidate arc is
/// 4a wide, so with `ne` contact elements there are ne/2 elements across the contact.
#[allow(clippy::too_many_arguments)]
fn scene(r: f64, e: f64, nu: f64, hub: f64, a_over_r: f64, element: &str, ne: usize, other: usize) -> Scene {
    let estar = e / (1.0 - nu * nu);
    let a = a_over_r * r;
    let p = rollbem::theory::Hertz2D::from_half_width(a, r, estar).load;
    let arc_deg = (4.0 * a_over_r).to_degrees();
    let text = format!(
        r#"
name = "hertz-test"
[wheel]
radius = {r}
youngs_modulus = {e}
poisson_ratio = {nu}
support = {{ kind = "hub", radius = {hub} }}
[mesh]
element = "{element}"
contact_arc_deg = {arc_deg}
contact_elements = {ne}
other_elements = {other}
[drive]
normal_load = {p}
[solvers]
use = ["all"]
"#
    );
    Scene::from_toml(&text, Path::new("<test>")).expect("valid scene")
}

fn run(s: &Scene) -> Report {
    run_scene(s).expect("runs")
}

fn solver<'a>(r: &'a Report, name: &str) -> &'a SolverRun {
    r.runs.iter().find(|x| x.solver == name).unwrap_or_else(|| panic!("no {name} run"))
}

/// The two wheels of the Hertz test: (R, E, ν, hub radius) in different units and materials.
const WHEELS: [(f64, f64, f64, f64); 2] = [
    (1.0, 94500.0, 0.1, 0.2),      // the seed's material, metres and a generic stress unit
    (460.0, 210000.0, 0.3, 100.0), // a steel rail wheel in mm and MPa
];

#[test]
fn hertz_at_equal_load_constant_and_quadratic() {
    for &(r, e, nu, hub) in &WHEELS {
        for (element, ne, t) in [("constant", 48, tol::HERTZ_CONSTANT), ("quadratic", 40, tol::HERTZ_QUADRATIC)] {
            let s = scene(r, e, nu, hub, 0.03, element, ne, 96);
            let rep = run(&s);
            let h = rep.references.hertz.expect("Hertz applies");
            for run in &rep.runs {
                assert_eq!(run.status, Status::Solved, "{element} {}: {}", run.solver, run.explanation());
                let a = run.contact.as_ref().unwrap().fit_half_width.unwrap();
                let p0 = run.contact.as_ref().unwrap().fit_peak_pressure.unwrap();
                let (ea, ep) = ((a / h.a - 1.0).abs(), (p0 / h.p0 - 1.0).abs());
                eprintln!("R={r} {element} {}: a err {ea:.2e}, p0 err {ep:.2e}", run.solver);
                assert!(ea <= t && ep <= t, "R={r} {element} {}: a err {ea:.3e}, p0 err {ep:.3e} > {t}", run.solver);
                // The pressure resultant equals the prescribed load.
                let load = s.document().drive.normal_load.unwrap();
                let el = (run.resultants.unwrap().normal / load - 1.0).abs();
                assert!(el <= tol::LOAD_RESULTANT, "load error {el:e}");
            }
            assert!(rep.all_pass(), "{:?}", rep.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
        }
    }
}

#[test]
fn lemke_and_clarabel_agree_and_lemke_is_complementary() {
    for &(r, e, nu, hub) in &WHEELS {
        for element in ["constant", "quadratic"] {
            let s = scene(r, e, nu, hub, 0.05, element, 30, 60);
            let rep = run(&s);
            let (l, c) = (solver(&rep, "lemke"), solver(&rep, "clarabel"));
            assert_eq!(l.status, Status::Solved);
            assert_eq!(c.status, Status::Solved);
            let p0 = rep.references.hertz.unwrap().p0;
            assert_eq!(l.nodes.len(), c.nodes.len(), "{element}: nodes of the two solvers");
            let d = paired(&l.nodes, &c.nodes).map(|(a, b)| (a.pressure - b.pressure).abs()).fold(0.0, f64::max);
            assert!(d <= tol::SOLVER_AGREEMENT * p0, "{element}: |Δp| = {:.3e} p0", d / p0);
            assert!(
                l.residuals.unwrap().complementarity <= tol::LEMKE_COMPLEMENTARITY,
                "Lemke complementarity {:e}",
                l.residuals.unwrap().complementarity
            );
        }
    }
}

#[test]
fn frictionless_scene_builds_and_solves_only_the_normal_problem() {
    // Displacement-driven: exactly one complementarity unknown per contact node; the flexibility has no
    // tangential blocks; the report says effects = ["normal"] and computes no u_x, slip or slip velocity.
    let mut s = scene(1.0, 94500.0, 0.1, 0.2, 0.05, "constant", 24, 32);
    s = s
        .edit(|d| {
            d.drive.normal_load = None;
            d.drive.normal_approach = Some(0.004);
        })
        .unwrap();
    let flex = source::build(&s, Blocks::Normal).unwrap().flex;
    assert!(flex.k_nt.is_none() && flex.k_tn.is_none() && flex.k_tt.is_none());
    assert!(flex.modes.iter().all(|m| m.tangential.is_none()));
    let prob = rollbem::pipeline::stages::scene_problem(&s, &flex).unwrap();
    assert_eq!(prob.lcp().expect("an LCP below gross sliding").size(), flex.n());
    let rep = run(&s);
    assert_eq!(rep.effects, vec!["normal".to_string()]);
    for run in &rep.runs {
        assert_eq!(run.problem_size, rep.mesh.contact_nodes, "{}", run.solver);
        assert!(run
            .nodes
            .iter()
            .all(|n| n.u_x.is_none() && n.slip.is_none() && n.slip_velocity.is_none() && n.shear == 0.0));
    }
    // Load-driven: one unknown per contact node plus the split approach u⁺, u⁻.
    let s2 = scene(1.0, 94500.0, 0.1, 0.2, 0.05, "constant", 24, 32);
    let rep2 = run(&s2);
    assert_eq!(solver(&rep2, "lemke").problem_size, rep2.mesh.contact_nodes + 2);
}

#[test]
fn displacement_and_load_drives_agree() {
    // Feed the load computed under a prescribed approach back as the drive: the approach and the pressures must
    // come back (the two formulations describe one physics). Reference: the displacement-driven run itself.
    let mut s = scene(1.0, 94500.0, 0.1, 0.2, 0.05, "constant", 24, 32);
    s = s
        .edit(|d| {
            d.drive.normal_load = None;
            d.drive.normal_approach = Some(0.004);
        })
        .unwrap();
    let rd = run(&s);
    let ld = solver(&rd, "lemke");
    s = s
        .edit(|d| {
            d.drive.normal_approach = None;
            d.drive.normal_load = Some(ld.resultants.unwrap().normal);
        })
        .unwrap();
    let rl = run(&s);
    let ll = solver(&rl, "lemke");
    assert!((ll.rigid_body.unwrap().normal / 0.004 - 1.0).abs() < 1e-10, "approach {}", ll.rigid_body.unwrap().normal);
    let pmax = ld.contact.as_ref().unwrap().peak_pressure;
    assert_eq!(ld.nodes.len(), ll.nodes.len(), "nodes of the two drives");
    for (a, b) in paired(&ld.nodes, &ll.nodes) {
        assert!((a.pressure - b.pressure).abs() <= 1e-10 * pmax);
    }
}

#[test]
fn unit_invariance_m_and_mm() {
    // The same steel wheel in N, mm, MPa and in N, m, Pa: stresses equal to 1e-9 relative.
    let mm = scene(460.0, 210000.0, 0.3, 100.0, 0.03, "quadratic", 24, 48);
    let m = mm
        .edit(|d| {
            d.wheel.radius = 0.46;
            d.wheel.youngs_modulus = 210e9;
            d.wheel.support = Some(rollbem::scene::Support::Hub { radius: 0.1 });
            d.drive.normal_load = d.drive.normal_load.map(|p| p * 1e3); // N/mm → N/m
        })
        .unwrap();
    let (a, b) = (run(&mm), run(&m));
    // The same solvers and the same mesh in both unit systems, before comparing them pairwise.
    assert_eq!(a.runs.len(), b.runs.len(), "solver runs in mm and in m");
    for (ra, rb) in paired(&a.runs, &b.runs) {
        assert_eq!(ra.solver, rb.solver);
        let pmax = ra.contact.as_ref().unwrap().peak_pressure;
        assert_eq!(ra.nodes.len(), rb.nodes.len(), "{}: nodes in mm and in m", ra.solver);
        for (na, nb) in paired(&ra.nodes, &rb.nodes) {
            let d = (na.pressure - nb.pressure * 1e-6).abs();
            assert!(d <= tol::UNIT_INVARIANCE * pmax, "{}: Δp = {:e} of p_max", ra.solver, d / pmax);
            assert!((na.x - nb.x * 1e3).abs() <= 1e-9 * 460.0);
        }
    }
}

#[test]
fn a_negative_approach_gives_no_contact_and_zero_load() {
    // A wheel lifted off the flat: every node separated, P = 0 (exact: q ≥ 0 gives z = 0).
    let mut s = scene(1.0, 94500.0, 0.1, 0.2, 0.05, "constant", 24, 32);
    s = s
        .edit(|d| {
            d.drive.normal_load = None;
            d.drive.normal_approach = Some(-0.001);
            d.solvers.use_ = vec!["lemke".into()];
        })
        .unwrap();
    let rep = run(&s);
    let l = solver(&rep, "lemke");
    assert_eq!(l.status, Status::Solved);
    assert!(l.contact.as_ref().unwrap().nodes_contact == 0);
    assert_eq!(l.resultants.unwrap().normal, 0.0);
}
