//! Two finite bodies (issue 34): the twin-disc rig and the pin in a bore, each body a BEM model condensed once
//! (`rollbem::source::two_body`). Expected values come from theory: Hertz's line contact with 1/R* = 1/R₁ + 1/R₂
//! and E* of the pair (Johnson, Contact Mechanics, §4.2) for the twin disc.

use rollbem::formulation::{ContactLaw, ContactProblem, Dof, Drive, SlipOperator};
use rollbem::material::Material;
use rollbem::mesh::MeshSpec;
use rollbem::post::{evaluate, Evaluation};
use rollbem::scene::{ElementKind, Support, Wheel};
use rollbem::source::two_body::{build, Counter, TwoBodies};
use rollbem::source::Blocks;
use rollbem::status::Termination;
use rollbem::theory::Hertz2D;

const E: f64 = 210_000.0;
const NU: f64 = 0.3;

fn steel() -> Material {
    Material::new(E, NU)
}

/// A twin disc of radii r1, r2 (mm), both on hubs of 0.2 R, with a candidate arc 4a wide on the wheel for the Hertz
/// half-width `a` and `ne` quadratic contact elements on it.
fn twin_disc(r1: f64, r2: f64, a: f64, ne: usize, other: usize) -> TwoBodies {
    let arc_deg = (4.0 * a / r1).to_degrees();
    let spec = MeshSpec::arc(ElementKind::Quadratic, arc_deg, ne, other);
    let counter = Counter::Disc { radius: r2, material: steel(), support: Support::Hub { radius: 0.2 * r2 } };
    TwoBodies::new(Wheel { radius: r1, material: steel() }, Support::Hub { radius: 0.2 * r1 }, spec, counter, other)
}

/// Solve the frictionless normal problem under the load P (the wheel held against shift and rotation).
fn solve_normal(bodies: &TwoBodies, load: f64) -> Evaluation {
    let built = build(bodies, Blocks::Normal).expect("builds");
    let law = ContactLaw { friction: 0.0, coupling: false };
    let drive =
        Drive { normal: Dof::Load(load), tangential: Dof::Displacement(0.0), rotational: Dof::Displacement(0.0) };
    let problem = ContactProblem::new(&built.flex, law, drive, SlipOperator::static_slip()).expect("fits");
    let out = rollbem::solvers::build("lemke").unwrap().solve(&problem);
    assert_eq!(out.status, Termination::Solved, "{}", out.message);
    evaluate(&problem, out.solution.as_ref().unwrap(), None).unwrap()
}

/// Hertz's figures of the pair: E* = E/(2(1 − ν²)) for two steel bodies, R* = R₁R₂/(R₁ + R₂).
fn hertz_pair(load: f64, r1: f64, r2: f64) -> Hertz2D {
    let estar = 1.0 / (2.0 * (1.0 - NU * NU) / E);
    Hertz2D::from_load(load, r1 * r2 / (r1 + r2), estar)
}

#[test]
fn twin_disc_at_a_over_r_001_is_hertz_with_half_the_radius() {
    // Expected: Hertz with R* = R/2 and E* = E/(2(1 − ν²)) (Johnson §4.2), within 0.5 % (issue 34).
    // Also R₂ = 2R₁ (R* = 2R/3): the counter-disc's zone is placed on the rays through the wheel's vertices.
    let estar = 1.0 / (2.0 * (1.0 - NU * NU) / E);
    for (r1, r2) in [(40.0, 40.0), (40.0, 80.0)] {
        let a = 0.01 * r1;
        let load = Hertz2D::from_half_width(a, r1 * r2 / (r1 + r2), estar).load;
        let ev = solve_normal(&twin_disc(r1, r2, a, 40, 96), load);
        let h = hertz_pair(load, r1, r2);
        let (fa, fp) = (ev.contact.fit_half_width.unwrap(), ev.contact.fit_peak_pressure.unwrap());
        let (ea, ep) = (fa / h.a - 1.0, fp / h.p0 - 1.0);
        eprintln!(
            "R1 {r1}, R2 {r2}, a/R1 = 0.01: a {fa:.6} (Hertz {:.6}, {ea:+.2e}), p0 {fp:.3} ({:.3}, {ep:+.2e})",
            h.a, h.p0
        );
        assert!(ea.abs() <= 0.005 && ep.abs() <= 0.005, "a err {ea:.3e}, p0 err {ep:.3e}");
        assert!((ev.resultants.normal / load - 1.0).abs() < 1e-8, "P = {}", ev.resultants.normal);
    }
}
