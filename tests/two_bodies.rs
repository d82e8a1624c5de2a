//! Two finite bodies (issue 34): the twin-disc rig and the pin in a bore, each body a BEM model condensed once
//! (`rollbem::source::two_body`). Expected values come from theory: Hertz's line contact with 1/R* = 1/R₁ + 1/R₂
//! and E* of the pair (Johnson, Contact Mechanics, §4.2) for the twin disc; for the pin in a bore, Persson's problem
//! as `rollbem::theory::pin_bore` derives it (the Ciavarella–Decuzzi closed forms were not at hand verbatim: the
//! module derives the compliance of a disc and of a hole in an infinite plate from the Michell solution and solves the
//! resulting singular integral equation by Gauss–Chebyshev collocation, a method that shares nothing with the BEM).

use rollbem::formulation::{ContactLaw, ContactProblem, Dof, Drive, SlipOperator};
use rollbem::material::Material;
use rollbem::mesh::MeshSpec;
use rollbem::post::{evaluate, Evaluation, RollingPost};
use rollbem::scene::{ElementKind, Support, Wheel};
use rollbem::source::two_body::{build, steady_slip, Counter, TwoBodies};
use rollbem::source::Blocks;
use rollbem::status::Termination;
use rollbem::theory::{carter_force, Hertz2D, PinBore, TangentialPath};

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

/// The right edge of the contact arc (radians from the line of the load) from the nodal pressures: p² extrapolated
/// linearly to zero through the last two loaded nodes (p ∝ √(b − θ) at a smooth edge).
fn edge_angle(ev: &Evaluation) -> f64 {
    let theta: Vec<f64> = ev.nodes.iter().map(|n| n.x.atan2(-n.y)).collect();
    let i = (0..theta.len()).rev().find(|&i| ev.nodes[i].pressure > 0.0).expect("a loaded node");
    let (t1, t2) = (theta[i - 1], theta[i]);
    let (q1, q2) = (ev.nodes[i - 1].pressure.powi(2), ev.nodes[i].pressure.powi(2));
    t2 + q2 * (t2 - t1) / (q1 - q2)
}

/// The pressure at the node on the line of the load (θ = 0: an odd number of quadratic elements has one there).
fn peak_on_axis(ev: &Evaluation) -> f64 {
    let c = ev.nodes.iter().min_by(|a, b| a.x.abs().total_cmp(&b.x.abs())).unwrap();
    assert!(c.x.abs() < 1e-12, "a node on the axis");
    c.pressure
}

/// A steel pin of radius r on a hub of 0.05 r in a bore of clearance `dr` of a steel plate of outer radius 30 r
/// (clamped), the candidate arc 2.5 b wide (at most 176°), 61 quadratic elements on it.
fn pin_in_bore(r: f64, dr: f64, b: f64) -> TwoBodies {
    let arc = (2.5 * b.to_degrees()).min(176.0);
    let spec = MeshSpec::arc(ElementKind::Quadratic, arc, 61, 60);
    let counter = Counter::Bore { radius: r + dr, outer_radius: 30.0 * r, outer_elements: 64, material: steel() };
    TwoBodies::new(Wheel { radius: r, material: steel() }, Support::Hub { radius: 0.05 * r }, spec, counter, 60)
}

#[test]
fn pin_in_bore_with_clearance_from_hertzian_to_conformal() {
    // Expected: the contact half-angle b and the peak pressure p(0) at the load P that theory gives for b
    // (rollbem::theory::pin_bore, derived; see the module docs above), within 1 % (issue 34), from 3° to 60°; the
    // clearance ΔR = 1e-3 R (the theory is linear in ΔR/R). Also measured: where Hertz with 1/R* = 1/R − 1/(R + ΔR)
    // leaves it.
    let (r, dr) = (10.0, 1e-2);
    let estar = E / (2.0 * (1.0 - NU * NU));
    let rstar = r * (r + dr) / dr;
    for deg in [3.0_f64, 10.0, 25.0, 45.0, 60.0] {
        let theory = PinBore::at_half_angle(deg.to_radians(), 64);
        let load = theory.load_over_estar_clearance() * estar * dr;
        let ev = solve_normal(&pin_in_bore(r, dr, theory.half_angle), load);
        let (b, p0) = (edge_angle(&ev), peak_on_axis(&ev));
        let p0_theory = theory.peak_times_radius_over_load() * load / r;
        let (eb, ep) = (b / theory.half_angle - 1.0, p0 / p0_theory - 1.0);
        let hertz = Hertz2D::from_load(load, rstar, estar);
        eprintln!(
            "bore b {deg}°: P = {load:.4e}, BEM b {:.4}° ({eb:+.2e}), p0 {p0:.4} ({ep:+.2e}); Hertz b {:.4}° \
             ({:+.2e}), p0 {:.4} ({:+.2e})",
            b.to_degrees(),
            (hertz.a / r).to_degrees(),
            hertz.a / r / b - 1.0,
            hertz.p0,
            hertz.p0 / p0 - 1.0
        );
        assert!(eb.abs() < 0.01 && ep.abs() < 0.01, "b {deg}°: b err {eb:.3e}, p0 err {ep:.3e}");
        assert!((ev.resultants.normal / load - 1.0).abs() < 1e-8, "P = {}", ev.resultants.normal);
    }
}

#[test]
fn pin_in_bore_at_zero_clearance_has_one_angle_whatever_the_load() {
    // Expected: at zero clearance the half-angle is b₀ = 84.83° at every load (k(b₀) = 1 in the derived theory)
    // and p(0) = 0.5996 P/R, within 1 %; the pressure scales with the load (linear problem, no gap).
    let r = 10.0;
    let theory = PinBore::zero_clearance(64).expect("a zero-clearance angle");
    for load in [10.0, 1000.0] {
        let ev = solve_normal(&pin_in_bore(r, 0.0, theory.half_angle), load);
        let (b, p0) = (edge_angle(&ev), peak_on_axis(&ev));
        let p0_theory = theory.peak_times_radius_over_load() * load / r;
        let (eb, ep) = (b / theory.half_angle - 1.0, p0 / p0_theory - 1.0);
        eprintln!("zero clearance, P = {load}: b {:.4}° ({eb:+.2e}), p0 {p0:.5} ({ep:+.2e})", b.to_degrees());
        assert!(eb.abs() < 0.01 && ep.abs() < 0.01, "P {load}: b err {eb:.3e}, p0 err {ep:.3e}");
    }
}

/// A steady-rolling creep curve of two equal steel discs (R = 40 mm, hubs of 0.2R, μ = 0.3) at the Hertz half-width
/// a = `a_over_r`·R, the candidate arc 2.5a wide with `ne` quadratic elements, coupling on: Q/(μP) at the creepages
/// ξ = `fractions` × the critical creepage μa/R* (R* = R/2), with Carter's value at each.
fn twin_disc_creep_curve(a_over_r: f64, ne: usize, fractions: &[f64]) -> Vec<(f64, f64)> {
    creep_curve_of_pair(40.0, a_over_r, ne, fractions, true)
}

/// [`twin_disc_creep_curve`] with a counter-disc of radius `r2` (R* = 40 r2/(40 + r2)), the pair's frame turning
/// (`steady_slip`'s offset) or not (`turning` false: the flat's upwind operator alone).
fn creep_curve_of_pair(r2: f64, a_over_r: f64, ne: usize, fractions: &[f64], turning: bool) -> Vec<(f64, f64)> {
    let (r, mu) = (40.0, 0.3);
    let r_star = r * r2 / (r + r2);
    let estar = E / (2.0 * (1.0 - NU * NU));
    let a = a_over_r * r;
    let load = Hertz2D::from_half_width(a, r_star, estar).load;
    let h = Hertz2D::from_load(load, r_star, estar);
    let spec = MeshSpec::arc(ElementKind::Quadratic, (2.5 * a_over_r).to_degrees(), ne, 96);
    let counter = Counter::Disc { radius: r2, material: steel(), support: Support::Hub { radius: 0.2 * r2 } };
    let bodies =
        TwoBodies::new(Wheel { radius: r, material: steel() }, Support::Hub { radius: 0.2 * r }, spec, counter, 96);
    let built = build(&bodies, Blocks::All).expect("builds");
    let solver = rollbem::solvers::build("active_set").unwrap();
    let law = ContactLaw { friction: mu, coupling: true };
    fractions
        .iter()
        .map(|&frac| {
            let xi = frac * mu * h.a / r_star;
            let drive = Drive {
                normal: Dof::Load(load),
                tangential: Dof::Displacement(xi),
                rotational: Dof::Displacement(0.0),
            };
            let slip = if turning { steady_slip(&built.flex, 1) } else { SlipOperator::steady(&built.flex.x, 1) };
            let problem = ContactProblem::new(&built.flex, law, drive, slip).expect("fits");
            let out = solver.solve(&problem);
            assert_eq!(out.status, Termination::Solved, "{}", out.message);
            let ev = evaluate(&problem, out.solution.as_ref().unwrap(), Some(RollingPost::Steady)).unwrap();
            (ev.resultants.tangential / (mu * load), carter_force(&h, mu, r_star, xi) / (mu * load))
        })
        .collect()
}

const CREEP_FRACTIONS: [f64; 5] = [0.1, 0.3, 0.6, 0.9, 1.2];

#[test]
fn twin_disc_creep_curve_at_a_over_r_001_is_carter() {
    // Expected: Carter's creep curve with R* = R/2 and the pair's E* (theory::carter, Johnson §8.2), within 1 % of
    // μP (issue 34), from 0.1 of the critical creepage to full slip. Braking creepage ξ > 0 gives Q < 0.
    let curve = twin_disc_creep_curve(0.01, 101, &CREEP_FRACTIONS);
    for (frac, (q, carter)) in CREEP_FRACTIONS.iter().zip(&curve) {
        eprintln!("a/R = 0.01, ξ/ξc = {frac}: Q/μP {q:.5}, Carter {carter:.5}, difference {:+.2e}", q - carter);
        assert!((q - carter).abs() <= 0.01, "ξ/ξc = {frac}: Q/μP {q} against Carter {carter}");
        assert!(*q < 0.0);
    }
}

#[test]
fn twin_disc_creep_curve_at_a_over_r_01_departs_from_carter_converged_in_the_mesh() {
    // Measured: at a/R = 0.1 the finite discs carry less creep force than Carter (by 2.8 % of μP at 0.6 of the
    // critical creepage); expected: the departure is a property of the bodies, not of the mesh — 121 and 241
    // quadratic elements give it within 0.1 % of μP, ten times below the departure itself.
    let coarse = twin_disc_creep_curve(0.1, 121, &CREEP_FRACTIONS);
    let fine = twin_disc_creep_curve(0.1, 241, &CREEP_FRACTIONS);
    for ((frac, (qc, carter)), (qf, _)) in CREEP_FRACTIONS.iter().zip(&coarse).zip(&fine) {
        let (departure, mesh) = (qf - carter, qf - qc);
        eprintln!("a/R = 0.1, ξ/ξc = {frac}: Q/μP {qf:.5} (121 el. {qc:.5}), Carter {carter:.5}: departure {departure:+.2e}, mesh {mesh:+.1e}");
        assert!(mesh.abs() <= 1e-3, "ξ/ξc = {frac}: 121 and 241 elements differ by {mesh:e} μP");
    }
    let (q, carter) = fine[2];
    assert!((q - carter).abs() >= 1e-2, "at ξ/ξc = 0.6 the departure {} is resolved", q - carter);
}

#[test]
fn twin_disc_departure_from_hertz_measured_against_load() {
    // Measured: a and p0 of two equal discs against Hertz (R* = R/2) as a/R grows; expected: each departure is the
    // bodies' (40 and 80 quadratic elements on 4a agree within 0.05 %), and within 0.5 % at a/R = 0.01 (issue 34).
    let estar = E / (2.0 * (1.0 - NU * NU));
    let r = 40.0;
    for a_over_r in [0.01, 0.03, 0.1, 0.2] {
        let a = a_over_r * r;
        let load = Hertz2D::from_half_width(a, 0.5 * r, estar).load;
        let h = hertz_pair(load, r, r);
        let fit = |ne: usize| {
            let ev = solve_normal(&twin_disc(r, r, a, ne, 96), load);
            (ev.contact.fit_half_width.unwrap() / h.a - 1.0, ev.contact.fit_peak_pressure.unwrap() / h.p0 - 1.0)
        };
        let ((ca, cp), (fa, fp)) = (fit(40), fit(80));
        eprintln!(
            "twin disc a/R = {a_over_r}: a {fa:+.2e} (40 el. {ca:+.2e}), p0 {fp:+.2e} (40 el. {cp:+.2e}) from Hertz"
        );
        assert!((fa - ca).abs() < 5e-4 && (fp - cp).abs() < 5e-4, "a/R = {a_over_r}: not converged");
        if a_over_r == 0.01 {
            assert!(fa.abs() < 5e-3 && fp.abs() < 5e-3);
        }
    }
}

fn two_body_scene(name: &str) -> rollbem::scene::Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies").join(name);
    rollbem::scene::Scene::from_file(&path).expect("a valid scene")
}

fn run_of<'a>(r: &'a rollbem::results::Report, solver: &str) -> &'a rollbem::results::SolverRun {
    r.runs.iter().find(|x| x.solver == solver).unwrap()
}

#[test]
fn twin_disc_scenes_run_with_hertz_and_carter_of_the_pair() {
    // Expected: the scene's Hertz reference is the pair's (R* = R/2: a = 0.4 mm at P = 725 N/mm) and every check
    // passes; the rolling scene is within 1 % of μP of Carter (Q/(μP) = −0.51 at 0.3 of the critical creepage).
    let scene = two_body_scene("twin-disc-hertz.toml");
    assert!((scene.contact_radius() - 20.0).abs() < 1e-12);
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    let h = report.references.hertz.expect("Hertz applies to a twin disc");
    assert!((h.a / 0.4 - 1.0).abs() < 1e-9, "{h:?}");
    assert!(report.all_pass(), "{:?}", report.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
    let scene = two_body_scene("twin-disc-creep.toml");
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    let run = run_of(&report, "active_set");
    let load = run.resultants.unwrap().normal;
    let q = run.resultants.unwrap().tangential / (0.3 * load);
    eprintln!("twin-disc-creep: Q/(μP) = {q:.5}");
    assert!((q + 0.51).abs() < 0.01, "Q/(μP) = {q}");
    assert!(report.all_pass(), "{:?}", report.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
}

#[test]
fn pin_in_bore_scene_gives_persson_half_angle_and_peak() {
    // Expected: theory::pin_bore at b = 45° (P = 817.43 N/mm, clearance 0.01 mm): the loaded arc ends within one
    // element beyond 45° and the peak pressure on the axis is 72.11 MPa within 1 %.
    let scene = two_body_scene("pin-in-bore.toml");
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    assert!(report.references.hertz.is_none(), "Hertz is not this conformal contact's reference");
    let run = run_of(&report, "lemke");
    let theory = PinBore::at_half_angle(45f64.to_radians(), 64);
    let p0_theory = theory.peak_times_radius_over_load() * 817.43 / 10.0;
    let axis = run.nodes.iter().min_by(|a, b| a.x.abs().total_cmp(&b.x.abs())).unwrap();
    assert!((axis.pressure / p0_theory - 1.0).abs() < 0.01, "p0 {} against {p0_theory}", axis.pressure);
    let last = run.nodes.iter().filter(|n| n.pressure > 0.0).map(|n| n.x.atan2(-n.y)).fold(0.0, f64::max);
    let element = 112.5 / 61.0;
    assert!(
        last.to_degrees() < 45.0 && last.to_degrees() > 45.0 - element,
        "last loaded node at {}°",
        last.to_degrees()
    );
    assert!(report.all_pass(), "{:?}", report.checks.iter().filter(|c| !c.pass).collect::<Vec<_>>());
}

#[test]
fn a_one_wheel_scene_pays_nothing_for_the_second_body() {
    // Expected: a scene without a second finite body builds exactly the one-wheel flexibility as before (the BEM
    // wheel condensed alone: the same blocks bit for bit, the flat's frame, no slip offset), so nothing of the
    // two-body machinery is computed for it.
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/carter-steady-rolling.toml"),
    )
    .unwrap();
    let scene = rollbem::scene::Scene::from_toml(&text, std::path::Path::new("carter.toml")).unwrap();
    for scene in [scene, two_body_scene("twin-disc-hertz.toml").edit(|d| d.counter_body = Default::default()).unwrap()]
    {
        let blocks = rollbem::pipeline::stages::blocks_for(&scene);
        let built = rollbem::source::build(&scene, blocks).unwrap();
        assert!(built.flex.normals.is_none(), "{}: the flat's frame", scene.name());
        let op = rollbem::pipeline::stages::slip_operator(&scene, &built.flex);
        assert!(op.offset.is_none());
        if let Some(model) = rollbem::source::bem_wheel::Model::of_scene(&scene).unwrap() {
            let (alone, _, _) = rollbem::source::bem_wheel::condense(&model, blocks).unwrap();
            assert_eq!(alone.k_nn, built.flex.k_nn, "{}: K_NN as the wheel alone", scene.name());
            assert_eq!(alone.k_tt, built.flex.k_tt);
            assert_eq!(alone.g0, built.flex.g0);
        }
    }
}

#[test]
fn bad_second_bodies_are_refused_naming_the_key() {
    // Expected: each bad value is refused when the scene is read, the error naming its key (exit 2 on the CLI).
    let base = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies/pin-in-bore.toml"),
    )
    .unwrap();
    let cases = [
        ("radius = 10.01", "radius = 9.9", "counter_body.radius"),
        ("outer_radius = 300.0", "outer_radius = 10.0", "counter_body.outer_radius"),
        ("outer_elements = 64", "outer_elements = 4", "counter_body.outer_elements"),
        ("other_elements = 60\nouter", "other_elements = 2\nouter", "counter_body.other_elements"),
        ("[drive]", "[rolling]\nmode = \"steady\"\ncreepage = 1e-3\n[contact]\nfriction = 0.3\n[drive]", "rolling"),
        ("[drive]", "[stresses]\nx = [-1.0, 1.0]\ndepth = [0.5, 2.0]\npoints = [3, 3]\n[drive]", "stresses"),
        ("support = { kind = \"hub\", radius = 0.5 }", "model = \"half_plane\"", "counter_body.kind"),
    ];
    for (from, to, key) in cases {
        assert!(base.contains(from), "{from}");
        let mut text = base.replacen(from, to, 1);
        if key == "counter_body.kind" {
            // A well-formed half-plane wheel otherwise: constant elements, no other_elements.
            text = text.replacen("element = \"quadratic\"", "element = \"constant\"", 1);
            text = text.replacen("other_elements = 60\n\n[drive]", "\n[drive]", 1);
        }
        let err = rollbem::scene::Scene::from_toml(&text, std::path::Path::new("bad.toml")).unwrap_err();
        assert!(err.to_string().contains(key), "{key}: {err}");
    }
    let disc = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies/twin-disc-hertz.toml"),
    )
    .unwrap();
    let text = disc.replacen("radius = 8.0 }\nother", "radius = 80.0 }\nother", 1);
    let err = rollbem::scene::Scene::from_toml(&text, std::path::Path::new("bad.toml")).unwrap_err();
    assert!(err.to_string().contains("counter_body.support.radius"), "{err}");
    let text = disc.replacen("contact_arc_deg = 2.2918311805232928", "contact_arc_deg = 120.0", 1);
    let err = rollbem::scene::Scene::from_toml(&text, std::path::Path::new("bad.toml")).unwrap_err();
    assert!(err.to_string().contains("mesh.contact_arc_deg"), "{err}");
}

#[test]
fn unequal_discs_roll_as_carter_with_the_turning_frame() {
    // Expected: Carter with R* = 2R/3 for R₂ = 2R₁ at a/R₁ = 0.01, within 1 % of μP. The interface curves
    // (κ = (1/R₁ − 1/R₂)/2), so the slip takes the frame's turning (steady_slip's offset −κ g₀, derived in its
    // docs). Measured, not asserted: the offset moves Q/(μP) by up to 3.8e-3 here, a term of order a/(μR) that
    // Carter's half-space theory does not resolve (both curves are within 1 % of it).
    let with = creep_curve_of_pair(80.0, 0.01, 101, &CREEP_FRACTIONS, true);
    let without = creep_curve_of_pair(80.0, 0.01, 101, &CREEP_FRACTIONS, false);
    for ((frac, (q, carter)), (q0, _)) in CREEP_FRACTIONS.iter().zip(&with).zip(&without) {
        eprintln!(
            "R2 = 2R1, ξ/ξc = {frac}: Q/μP {q:.5} (no turning {q0:.5}), Carter {carter:.5}: {:+.2e} ({:+.2e})",
            q - carter,
            q0 - carter
        );
        assert!((q - carter).abs() <= 0.01, "ξ/ξc = {frac}: Q/μP {q} against Carter {carter}");
    }
}

/// The subsurface fields of two equal steel discs (R = 40 mm) at Hertz's a = `a_over_r` R, 80 quadratic elements on
/// 4a, on a grid x in [−a, a], depth 0.5a to 2.5a, against McEwen's field (theory::mcewen_normal): per body
/// (wheel, counter-disc) the largest |σ_zz − σ_zz,M| and |τ_xz − τ_xz,M| over p0, the mean and the spread (max −
/// min) of σ_xx − σ_xx,M over p0; and the largest difference between the two bodies' fields over p0.
fn twin_disc_fields(a_over_r: f64) -> ([[f64; 3]; 2], f64) {
    let (scene, _) = disc_pair_stress_scene(40.0, a_over_r, [0.5, 2.5]);
    fields_against_mcewen(&scene.unwrap(), 40.0)
}

/// A steel wheel of R = 40 mm on a steel counter-disc of radius `r2` (hubs of 0.2 R), loaded to Hertz's a =
/// `a_over_r`·40 mm with R* = 40 r2/(40 + r2), 80 quadratic elements on 4a, `[stresses]` on x in [−a, a] and depth
/// from `depth[0]` a to `depth[1]` a (5 × 5 points): the scene (or the error reading it) and its text.
fn disc_pair_stress_scene(r2: f64, a_over_r: f64, depth: [f64; 2]) -> (rollbem::Result<rollbem::scene::Scene>, String) {
    let (r, estar) = (40.0, E / (2.0 * (1.0 - NU * NU)));
    let a = a_over_r * r;
    let load = Hertz2D::from_half_width(a, r * r2 / (r + r2), estar).load;
    let text = format!(
        "name = \"twin-stresses\"\n[wheel]\nradius = {r}\nyoungs_modulus = {E}\npoisson_ratio = {NU}\nsupport = {{ kind = \
         \"hub\", radius = 8.0 }}\n[counter_body]\nkind = \"disc\"\nradius = {r2}\nyoungs_modulus = {E}\npoisson_ratio = \
         {NU}\nsupport = {{ kind = \"hub\", radius = {} }}\nother_elements = 96\n[mesh]\nelement = \"quadratic\"\n\
         contact_arc_deg = {}\ncontact_elements = 80\nother_elements = 96\n[stresses]\nx = [{}, {a}]\ndepth = [{}, {}]\n\
         points = [5, 5]\n[drive]\nnormal_load = {load}\n[solvers]\nuse = [\"lemke\"]\n",
        0.2 * r2,
        (4.0 * a_over_r).to_degrees(),
        -a,
        depth[0] * a,
        depth[1] * a
    );
    (rollbem::scene::Scene::from_toml(&text, std::path::Path::new("twin-stresses.toml")), text)
}

/// Both bodies' fields of a solved disc pair against McEwen's with the pair's Hertz (see [`twin_disc_fields`]).
fn fields_against_mcewen(scene: &rollbem::scene::Scene, r2: f64) -> ([[f64; 3]; 2], f64) {
    let r = 40.0;
    let report = rollbem::pipeline::run_scene(scene).unwrap();
    let run = run_of(&report, "lemke");
    let wheel = run.stresses.as_ref().expect("the wheel's field");
    let counter = run.counter_body_stresses.as_ref().expect("the counter-disc's field");
    assert_eq!(counter.body, "counter_body");
    let h = hertz_pair(run.resultants.unwrap().normal, r, r2);
    let mut out = [[0.0_f64; 3]; 2];
    let mut symmetry = 0.0_f64;
    for (b, field) in [wheel, counter].iter().enumerate() {
        let mut dxx = Vec::new();
        for k in 0..field.field.stress.len() {
            let (x, z) = field.field.grid.point(k);
            let m = rollbem::theory::mcewen_normal(&h, x, z);
            let s = field.field.stress[k].expect("a value at every grid point");
            out[b][0] = out[b][0].max((s[1] - m.yy).abs().max((s[2] - m.xy).abs()) / h.p0);
            dxx.push((s[0] - m.xx) / h.p0);
            let w = wheel.field.stress[k].unwrap();
            symmetry = symmetry.max((0..3).map(|i| (w[i] - s[i]).abs()).fold(0.0, f64::max) / h.p0);
        }
        out[b][1] = dxx.iter().sum::<f64>() / dxx.len() as f64;
        out[b][2] = dxx.iter().copied().fold(f64::MIN, f64::max) - dxx.iter().copied().fold(f64::MAX, f64::min);
    }
    (out, symmetry)
}

#[test]
fn twin_disc_subsurface_stresses_are_hertz_in_both_discs() {
    // Expected (theory): under the contact each disc's field is McEwen's (Hertz's pressure on a half-plane;
    // Johnson §4.3) plus the finite disc's own stress, smooth on the scale of a: σ_zz and τ_xz within 3e-3 p0 of
    // McEwen in both discs; σ_xx off by a nearly uniform amount (spread below 2e-3 p0) that is O(a/R) — it halves
    // with a/R (ratio 0.5 ± 0.1 from a/R = 0.01 to 0.005: the half-space limit); and by the symmetry of two equal
    // discs the counter-disc's field (its own BEM solution under the opposite tractions, depth measured into it)
    // equals the wheel's within 1e-3 p0. Measured at a/R = 0.01: σ_xx offset +0.9 % of p0 (tension) in both.
    let (f1, sym1) = twin_disc_fields(0.01);
    let (f2, sym2) = twin_disc_fields(0.005);
    eprintln!("a/R 0.01: wheel {:?}, counter {:?}, symmetry {sym1:.2e}", f1[0], f1[1]);
    eprintln!("a/R 0.005: wheel {:?}, counter {:?}, symmetry {sym2:.2e}", f2[0], f2[1]);
    for (f, sym) in [(f1, sym1), (f2, sym2)] {
        for body in f {
            assert!(body[0] < 3e-3 && body[2] < 2e-3, "{body:?}");
        }
        assert!(sym < 1e-3, "the two discs' fields differ by {sym:e} p0");
    }
    for b in 0..2 {
        let ratio = f2[b][1] / f1[b][1];
        assert!((ratio - 0.5).abs() < 0.1, "body {b}: σ_xx offset {} then {} (ratio {ratio})", f1[b][1], f2[b][1]);
    }
}

#[test]
fn unequal_discs_stresses_are_mcewen_and_points_outside_the_counter_disc_are_refused() {
    // Expected: a wheel of R = 40 mm on a disc of 80 mm at a/R = 0.01 (R* = 80/3 mm): both fields McEwen's with the
    // pair's Hertz (σ_zz, τ_xz within 3e-3 p0; the pair's normals tilt by under 1e-3 rad here, so this does not
    // resolve their rotation of the tractions); measured: the σ_xx offset of the 80 mm disc is half the wheel's
    // (0.46 % against 0.88 % of p0, O(a/R) of each body); a grid reaching
    // 12 mm deep is inside the wheel (80 mm across) but beyond a 5 mm counter-disc: refused before anything is
    // solved, naming stresses.depth and the counter-disc.
    let (scene, _) = disc_pair_stress_scene(80.0, 0.01, [0.5, 2.5]);
    let (f, _) = fields_against_mcewen(&scene.unwrap(), 80.0);
    eprintln!("R2 = 2R1, a/R = 0.01: wheel {:?}, counter {:?}", f[0], f[1]);
    assert!(f[0][0] < 3e-3 && f[1][0] < 3e-3, "{f:?}");
    let (scene, _) = disc_pair_stress_scene(5.0, 0.001, [0.5, 300.0]);
    let err = rollbem::pipeline::run_scene(&scene.unwrap()).unwrap_err().to_string();
    assert!(err.contains("stresses.depth") && err.contains("counter-disc"), "{err}");
}

#[test]
fn twin_disc_fretting_loop_is_mindlin_deresiewicz() {
    // Expected: two equal steel discs (β = 0) at a/R = 0.01, μ = 0.3, P held and Q cycled 0 → Q* → −Q* → Q* with
    // Q* = 0.5 μP: the stick zone and the shear of each branch are Mindlin–Deresiewicz's in 2D with R* = R/2
    // (theory::md_stick_half_width, md_traction; Johnson §7.3): stick half-width within one element, shear RMS
    // within 1 % of μp0 over the contact (the tolerances of tests/history.rs on the half-plane).
    let base = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies/twin-disc-hertz.toml"),
    )
    .unwrap();
    let (p, mu, m) = (724.982920059183, 0.3, 6);
    let q_star = 0.5 * mu * p;
    let steps = format!(
        "[contact]\nfriction = {mu}\n\n[[steps]]\nnormal_load = {p}\n\n[[steps]]\nnormal_load = {p}\ntangential_load = \
         {q_star}\nsubsteps = {m}\n\n[[steps]]\nnormal_load = {p}\ntangential_load = {}\nsubsteps = {}\n\n[[steps]]\n\
         normal_load = {p}\ntangential_load = {q_star}\nsubsteps = {}\n\n[solvers]",
        -q_star,
        2 * m,
        2 * m
    );
    let text = base.replacen("[drive]\nnormal_load = 724.982920059183\n\n[solvers]", &steps, 1).replacen(
        "use = [\"lemke\", \"active_set\"]",
        "use = [\"lemke\"]",
        1,
    );
    assert!(text.contains("[[steps]]"), "{text}");
    let scene = rollbem::scene::Scene::from_toml(&text, std::path::Path::new("twin-fretting.toml")).unwrap();
    let report = rollbem::pipeline::run_scene(&scene).unwrap();
    let element = 4.0 * 0.4 / 40.0;
    let checkpoints = [
        (TangentialPath::Loading, 1, m),
        (TangentialPath::Unloading { q_star }, 2, m),
        (TangentialPath::Unloading { q_star }, 2, 2 * m),
        (TangentialPath::Reloading { q_star }, 3, m),
        (TangentialPath::Reloading { q_star }, 3, 2 * m),
    ];
    for (branch, step, sub) in checkpoints {
        let st = report.steps.iter().find(|s| s.step == step && s.substep == sub).expect("the substep");
        let r = run_of_step(&st.runs, "lemke");
        assert_eq!(r.status, rollbem::status::Status::Solved, "{}", r.message);
        let h = hertz_pair(r.resultants.unwrap().normal, 40.0, 40.0);
        let q = r.resultants.unwrap().tangential;
        let c = rollbem::theory::md_stick_half_width(&h, mu, branch, q);
        let (l, rr) = rollbem::post::stick_edges(&r.nodes).expect("a stick zone");
        let c_num = 0.5 * (rr - l);
        let errs: Vec<f64> = r
            .nodes
            .iter()
            .filter(|nd| nd.x.abs() < h.a)
            .map(|nd| (nd.shear - rollbem::theory::md_traction(&h, mu, branch, q, nd.x)) / (mu * h.p0))
            .collect();
        let rms = (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt();
        eprintln!("twin disc {branch:?} Q = {q:.2}: c {c_num:.5} vs {c:.5}, shear RMS {rms:.2e} of μp0");
        assert!((c_num - c).abs() <= element, "{branch:?}: c {c_num} against {c}");
        assert!(rms < 0.01, "{branch:?}: RMS {rms}");
    }
}

fn run_of_step<'a>(runs: &'a [rollbem::results::SolverRun], solver: &str) -> &'a rollbem::results::SolverRun {
    runs.iter().find(|x| x.solver == solver).unwrap()
}
