//! `[mesh] strip_width`: the contact as a strip of half-spaces, CONTACT's model of its 2D cases.
//!
//! Expected values: an independent 40-digit solve of the same discrete problem (benches/peer/strip_reference.py,
//! mpmath, the point-load integral written out in the textbook form; its output is below), and plane strain, the
//! limit of a widening strip.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::results::{CheckKind, SolverRun};
use rollbem::scene::Scene;
use rollbem::status::Status;

/// CONTACT's examples/carter2d.inp as benches/peer/contact.sh poses it: 55 elements of 0.04 from XC1 = −1.05, two
/// identical bodies (G = 82 000, ν = 0.28: E = 2G(1 + ν)), h = 0.001 x², FN = 35 780 on DY = 200 (178.9 per unit
/// width), μ = 0.3, CKSI = −0.00024.
const CARTER2D: &str = r#"
name = "contact-carter2d"
units = "N, mm, MPa"
[wheel]
radius = 500
youngs_modulus = 209920
poisson_ratio = 0.28
model = "half_plane"
profile = "parabola"
[counter_body]
kind = "half_plane"
youngs_modulus = 209920
poisson_ratio = 0.28
[mesh]
element = "constant"
contact_x = [-1.07, 1.13]
contact_elements = 55
strip_width = 200
[contact]
friction = 0.3
coupling = false
[drive]
normal_load = 178.9
[rolling]
mode = "steady"
creepage = -0.00024
direction = 1
[solvers]
use = ["active_set", "lemke"]
"#;

/// benches/peer/strip_reference.py (DY = 200): the element pressures of the exact discrete problem, 40 digits
/// rounded to f64 (element i + 1 of CONTACT is index i; 50 in contact, elements 3–52).
const REFERENCE_P: [f64; 55] = [
    0.0,
    0.0,
    28.22581650912168,
    42.10653737355921,
    52.05433643572096,
    60.07581857310196,
    66.84578169418101,
    72.71037712063394,
    77.87247704428053,
    82.4632120167305,
    86.57304782793643,
    90.26742165048671,
    93.59537743530288,
    96.59468832673947,
    99.29506851824635,
    101.72027844117025,
    103.889555223711,
    105.81861384185419,
    107.52036501017884,
    109.0054401621821,
    110.28258127268828,
    111.35893346745142,
    112.24026592018684,
    112.93113847446324,
    113.43502604710594,
    113.75440916698021,
    113.89083636480694,
    113.8449621672326,
    113.61656290386105,
    113.20453122693095,
    112.60684902770988,
    111.82053718489699,
    110.84157916624505,
    109.6648137651158,
    108.28378997125157,
    106.69057383023706,
    104.87549264427801,
    102.82679521080894,
    100.53019665463361,
    97.96826048605683,
    95.11954469582211,
    91.95739529941936,
    88.4481947673019,
    84.54873329814329,
    80.20210001418207,
    75.33092755916961,
    69.82555440909073,
    63.521367504975316,
    56.151727494395615,
    47.20491442666458,
    35.86448884491954,
    13.022703527836649,
    0.0,
    0.0,
    0.0,
];

fn scene(edit: impl FnOnce(&mut String)) -> Scene {
    let mut text = CARTER2D.to_string();
    edit(&mut text);
    Scene::from_toml(&text, std::path::Path::new("carter2d.toml")).unwrap()
}

/// max(|Δp|, |Δq|) over the nodes relative to `a`'s peak pressure (the library's one definition, `checks::compare`).
fn largest_difference(a: &SolverRun, b: &SolverRun) -> f64 {
    assert_eq!(a.nodes.len(), b.nodes.len());
    rollbem::checks::compare(a, b, 0.3).max_dtraction
}

#[test]
fn carter2d_on_contacts_strip_is_the_exact_discrete_answer() {
    let report = run_scene(&scene(|_| {})).unwrap();
    let pmax = REFERENCE_P.iter().cloned().fold(0.0, f64::max);
    for r in &report.runs {
        assert_eq!(r.status, Status::Solved, "{}: {}", r.solver, r.explanation());
        assert_eq!(r.nodes.len(), 55);
        let worst = paired(&r.nodes, REFERENCE_P).map(|(n, p)| (n.pressure - p).abs()).fold(0.0, f64::max) / pmax;
        assert!(worst <= 1e-12, "{}: max |p − p_ref| / max p = {worst:e}", r.solver);
        let contact = r.nodes.iter().filter(|n| n.pressure > 0.0).count();
        assert_eq!(contact, 50, "{}", r.solver);
    }
    // The plane-strain theories are not compared with a strip, and the report says so.
    let note = report.checks.iter().find(|c| c.name.starts_with("plane-strain theories")).expect("a note");
    assert_eq!(note.kind, CheckKind::NotApplicable);
    assert!(note.note.as_deref().unwrap().contains("mesh.strip_width"), "{:?}", note.note);
    let carter = report.checks.iter().filter(|c| c.name.contains("Carter") && c.kind != CheckKind::NotApplicable);
    assert_eq!(carter.count(), 0, "no Carter figure on a strip");
}

/// A frictionless scene on a strip gets no Hertz figure (Hertz is plane strain), only the note that says so; on
/// plane strain the same scene is checked against Hertz (the contrast shows the test can tell).
#[test]
fn a_frictionless_strip_is_not_checked_against_hertz() {
    let frictionless = |t: &mut String| {
        *t = t
            .replace("friction = 0.3", "friction = 0.0")
            .replace("[rolling]\nmode = \"steady\"\ncreepage = -0.00024\ndirection = 1\n", "");
    };
    for width in ["2", "200"] {
        let strip = run_scene(&scene(|t| {
            frictionless(t);
            *t = t.replace("strip_width = 200", &format!("strip_width = {width}"));
        }))
        .unwrap();
        assert!(strip.references.hertz.is_none(), "w = {width}");
        let hertz = strip.checks.iter().filter(|c| c.name.contains("Hertz") && c.kind != CheckKind::NotApplicable);
        assert_eq!(hertz.count(), 0, "w = {width}: {:?}", strip.checks.iter().map(|c| &c.name).collect::<Vec<_>>());
    }
    let plane = run_scene(&scene(|t| {
        frictionless(t);
        *t = t.replace("strip_width = 200\n", "");
    }))
    .unwrap();
    assert!(plane.references.hertz.is_some());
    assert!(plane.checks.iter().any(|c| c.name.contains("Hertz") && c.kind == CheckKind::Figure));
}

/// As the strip widens its answer tends to plane strain's: the coefficients differ from plane strain's by a
/// constant per element and terms of order (x/w)² (src/halfplane.rs tests), so the tractions converge as 1/w².
#[test]
fn a_widening_strip_tends_to_the_plane_strain_answer() {
    let plane = run_scene(&scene(|t| *t = t.replace("strip_width = 200\n", ""))).unwrap();
    assert!(plane.runs[0].status == Status::Solved);
    let at = |w: f64| {
        let s = scene(|t| *t = t.replace("strip_width = 200", &format!("strip_width = {w}")));
        let r = run_scene(&s).unwrap();
        largest_difference(&plane.runs[0], &r.runs[0])
    };
    let (d1, d2, d3) = (at(200.0), at(2000.0), at(20000.0));
    eprintln!("strip against plane strain, max |Δp|, |Δq| / p0: w = 200 {d1:.2e}, 2000 {d2:.2e}, 20000 {d3:.2e}");
    assert!(d1 > 1e-5 && d1 < 1e-3, "w = 200: {d1:e}");
    assert!(d2 < d1 / 50.0 && d3 < d2 / 50.0, "not converging as 1/w²: {d1:e}, {d2:e}, {d3:e}");
}

#[test]
fn a_strip_is_refused_where_it_means_nothing() {
    let bad = |edit: &dyn Fn(&mut String), key: &str, words: &str| {
        let mut text = CARTER2D.to_string();
        edit(&mut text);
        let e = Scene::from_toml(&text, std::path::Path::new("bad.toml")).unwrap_err().to_string();
        assert!(e.contains(key) && e.contains(words), "{key}: {e}");
    };
    bad(&|t| *t = t.replace("strip_width = 200", "strip_width = -1"), "mesh.strip_width", "> 0");
    bad(&|t| *t = t.replace("strip_width = 200", "strip_width = nan"), "mesh.strip_width", "> 0");
    bad(&|t| *t = t.replace("strip_width = 200", "strip_width = 1e-320"), "mesh.strip_width", "element lengths");
    // 1e14 element lengths: plane strain to round-off, and the closed forms' far-field cancellation grows with it.
    bad(&|t| *t = t.replace("strip_width = 200", "strip_width = 4e12"), "mesh.strip_width", "leave strip_width out");
    bad(
        &|t| *t = t.replace("profile = \"parabola\"", "profile = \"parabola\"\ndatum_depth = 5"),
        "wheel.datum_depth",
        "no datum",
    );
    bad(
        &|t| *t = t.replace("poisson_ratio = 0.28\n[mesh]", "poisson_ratio = 0.28\ndatum_depth = 5\n[mesh]"),
        "counter_body.datum_depth",
        "no datum",
    );
    bad(
        &|t| t.push_str("[stresses]\nx = [-1.0, 1.0]\ndepth = [0.1, 1.0]\npoints = [3, 3]\n"),
        "stresses",
        "plane strain",
    );
    let bem = |t: &mut String| {
        *t = t
            .replace("model = \"half_plane\"\nprofile = \"parabola\"", "support = { kind = \"hub\", radius = 250 }")
            .replace("contact_x = [-1.07, 1.13]", "contact_half_width = 1.1\nother_elements = 40");
    };
    bad(&bem, "mesh.strip_width", "half-plane");
}
