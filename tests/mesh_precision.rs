//! The BEM wheel's geometry at small contact angles: the initial gap keeps its precision, and a zone too small for
//! double precision is refused when the scene is read.
//!
//! Expected values: the gap from the node's x by the cancellation-free R − √(R² − x²) = x²/(R + √(R² − x²)) (an
//! independent formula: the mesh evaluates 2R sin²(φ/2) from the polar angle); Hertz's line contact (Johnson eq.
//! 4.43–4.45), towards which the wheel tends as a/R → 0; and the same scene at a/R = 6e-4, where the old `y + R` gap
//! was already exact to 1e-9, for the claim that nothing but round-off changes between scales.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::mesh::{Mesh, MeshSpec, Shape};
use rollbem::pipeline::run_scene;
use rollbem::results::SolverRun;
use rollbem::scene::{Scene, MIN_CONTACT_ELEMENT_ANGLE};
use rollbem::status::Status;
use rollbem::theory::Hertz2D;

/// A frictionless top-arc wheel (R = 1, E = 1, ν = 0.3) with `n` elements of kind `element` on a contact arc of
/// half-angle `half` rad, loaded so that Hertz's a is 0.7 of the zone's half-width; with that Hertz contact.
fn scene(element: &str, half: f64, n: usize) -> (Scene, Hertz2D) {
    let e_star = 1.0 / (1.0 - 0.09);
    let a = 0.7 * half.sin();
    let h = Hertz2D::from_half_width(a, 1.0, e_star);
    let p = h.load;
    let text = format!(
        r#"
name = "small-arc"
[wheel]
radius = 1.0
youngs_modulus = 1.0
poisson_ratio = 0.3
support = {{ kind = "top_arc", angle_deg = 30.0 }}
[mesh]
element = "{element}"
contact_arc_deg = {arc:e}
contact_elements = {n}
other_elements = 40
[contact]
friction = 0.0
[drive]
normal_load = {p:e}
[solvers]
use = ["lemke"]
"#,
        arc = (2.0 * half).to_degrees()
    );
    (Scene::from_toml(&text, std::path::Path::new("small-arc.toml")).unwrap(), h)
}

fn solved(s: &Scene) -> SolverRun {
    let report = run_scene(s).unwrap();
    let run = report.runs.into_iter().next().unwrap();
    assert_eq!(run.status, Status::Solved, "{}", run.explanation());
    run
}

/// R − √(R² − x²) without cancellation.
fn gap_from_x(r: f64, x: f64) -> f64 {
    x * x / (r + (r * r - x * x).sqrt())
}

#[test]
fn the_initial_gap_keeps_its_relative_precision_at_small_angles() {
    for kind in ["constant", "quadratic"] {
        for half in [1e-2, 1e-5, 1e-8] {
            let (s, _) = scene(kind, half, 30);
            let (support, spec) = MeshSpec::of_scene(&s).unwrap();
            let mesh = Mesh::wheel(1.0, support, &spec).unwrap();
            let mut worst = 0.0_f64;
            for &i in &mesh.contact_nodes {
                let node = &mesh.nodes[i];
                let expected = match mesh.elements[node.element].shape {
                    // A chord's midpoint: the mean of its vertices' gaps.
                    Shape::Straight { a, b } => 0.5 * (gap_from_x(1.0, a[0]) + gap_from_x(1.0, b[0])),
                    Shape::Arc(_) => gap_from_x(1.0, node.pos[0]),
                };
                worst = worst.max((mesh.initial_gap(i).unwrap() - expected).abs() / expected.max(f64::MIN_POSITIVE));
            }
            // x carries relative rounding, the polar angle absolute rounding of 2.2e-16 rad near −π/2: the gap's
            // relative error is about 4e-16/φ at the node nearest the contact point (φ ≥ half/30 here).
            let bound = 1e-13 + 30.0 * 4.0 * f64::EPSILON / half;
            assert!(worst <= bound, "{kind}, half-angle {half:e}: relative gap error {worst:e} > {bound:e}");
        }
    }
}

/// At a contact half-angle of 1e-7 rad (a/R = 7e-8) the pressure is Hertz's and the same as at a/R = 6e-4. With
/// the gap computed as `y + R` it was wrong by 0.8 p0 for quadratic elements (0.34 p0 for constant ones at 1e-7
/// rad), and still reported `solved`.
#[test]
fn a_tiny_contact_is_solved_as_accurately_as_a_small_one() {
    for kind in ["constant", "quadratic"] {
        let (small, h_small) = scene(kind, 1e-3, 30);
        let (tiny, h_tiny) = scene(kind, 1e-7, 30);
        let (rs, rt) = (solved(&small), solved(&tiny));
        assert_eq!(rs.nodes.len(), rt.nodes.len());
        let shape_difference = paired(&rs.nodes, &rt.nodes)
            .map(|(s, t)| (s.pressure / h_small.p0 - t.pressure / h_tiny.p0).abs())
            .fold(0.0, f64::max);
        let hertz = |run: &SolverRun, h: &Hertz2D| {
            run.nodes.iter().map(|n| (n.pressure - h.pressure(n.x)).abs() / h.p0).fold(0.0, f64::max)
        };
        let (hs, ht) = (hertz(&rs, &h_small), hertz(&rt, &h_tiny));
        eprintln!(
            "{kind}: max |Δ(p/p0)| tiny vs small {shape_difference:.2e}; against Hertz: small {hs:.2e}, tiny {ht:.2e}"
        );
        // Measured: quadratic 6.7e-5; constant 1.8e-3, which is 4.6e-4 per decade of a/R at every scale from a/R =
        // 6e-3 down to 6e-9 (a discretisation effect of the straight chords; the old round-off grew 100-fold per
        // decade). Against Hertz both scales are within 2e-3 of each other (the largest error, about 5e-2 p0, is at
        // the last node before each edge, at either scale).
        let tolerance = if kind == "quadratic" { 2e-4 } else { 3e-3 };
        assert!(shape_difference <= tolerance, "{kind}: {shape_difference:e}");
        assert!((ht - hs).abs() <= tolerance, "{kind}: against Hertz small {hs:e}, tiny {ht:e}");
    }
}

/// A zone whose elements subtend less than `MIN_CONTACT_ELEMENT_ANGLE` is refused, naming the key that set it;
/// just above the floor the scene is read.
#[test]
fn a_zone_below_double_precision_is_refused_when_read() {
    let text = |key: &str, value: f64| {
        format!(
            "name = \"x\"\n[wheel]\nradius = 2.0\nyoungs_modulus = 1.0\npoisson_ratio = 0.3\nsupport = {{ kind = \
             \"top_arc\", angle_deg = 30.0 }}\n[mesh]\nelement = \"quadratic\"\n{key} = {value:e}\n\
             contact_elements = 10\nother_elements = 12\n[contact]\nfriction = 0.3\n[drive]\nnormal_load = 1.0\n"
        )
    };
    let read = |t: String| Scene::from_toml(&t, std::path::Path::new("x.toml"));
    let floor = MIN_CONTACT_ELEMENT_ANGLE * 10.0;
    for (key, value) in [("contact_arc_deg", floor.to_degrees()), ("contact_half_width", 2.0 * (floor / 2.0).sin())] {
        read(text(key, value * 1.01)).unwrap_or_else(|e| panic!("{key} just above the floor: {e}"));
        let e = read(text(key, value * 0.99)).unwrap_err().to_string();
        assert!(e.contains(&format!("mesh.{key}")) && e.contains("double precision"), "{key}: {e}");
    }
    // The fuzz target's reproducer: a contact arc of 2.2e-308 degrees.
    let crash = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/fuzz/regressions/scene-subnormal-contact-arc.toml"
    ))
    .unwrap();
    let e = read(crash).unwrap_err().to_string();
    assert!(e.contains("mesh.contact_arc_deg") && e.contains("double precision"), "{e}");
}
