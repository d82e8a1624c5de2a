//! Viscoelastic bodies in steady rolling (`viscoelastic = { ... }`, `[rolling] velocity`; src/viscoelastic.rs).
//!
//! Expected values: (i) an independent 30-digit integration of the memory integral of the strip kernel (mpmath
//! `quad`, split at the element ends; the script is in the comment of `MPMATH_CZZ`); (ii) CONTACT's printed output
//! for its example `visc_cylindr.inp` (`examples/visc_cylindr.ref_out` of CONTACT v25.x, open-source version; the
//! figures are copied below with the case they come from); (iii) the elastic limits, the elastic model itself.

use rollbem::halfplane::{Block, HalfPlane};
use rollbem::pipeline::run_scene;
use rollbem::post::NodeState;
use rollbem::scene::Scene;
use rollbem::status::Status;
use rollbem::viscoelastic::Memory;

/// CONTACT's visc_cylindr.inp as a scene: two PA6 cylinders R = 100 (combined 50, CONTACT's B1 = 0.01: h = x²/100,
/// `profile = "parabola"` with R = 50), G = 1143, ν = 0.4 (E = 2G(1 + ν) = 3200.4), FN = 600 000 on DY = 1000
/// (600 per unit width), FX/(μ FN) = −0.6 (Q = −108; CONTACT's FX on body 1 and rollbem's Q on the wheel have the
/// same sign), μ = 0.3, 99 elements of 0.16 from XC1 = −7.92, V = 1000 mm/s, CHI = 0 (direction +1).
fn visc_cylindr(solid: Option<(f64, f64)>, g: f64, plane_strain: bool) -> Scene {
    let e = 2.0 * g * 1.4;
    let visc = solid
        .map(|(f, tc)| format!("viscoelastic = {{ compliance_ratio = {f}, creep_time = {tc:e} }}\n"))
        .unwrap_or_default();
    let strip = if plane_strain { "" } else { "strip_width = 1000\n" };
    let velocity = if solid.is_some() { "velocity = 1000\n" } else { "" };
    let text = format!(
        r#"
name = "visc-cylindr"
units = "N, mm, MPa"
[wheel]
radius = 50
youngs_modulus = {e}
poisson_ratio = 0.4
model = "half_plane"
profile = "parabola"
{visc}
[counter_body]
kind = "half_plane"
youngs_modulus = {e}
poisson_ratio = 0.4
{visc}
[mesh]
element = "constant"
contact_x = [-8.0, 7.84]
contact_elements = 99
{strip}
[contact]
friction = 0.3
coupling = false
[drive]
normal_load = 600
tangential_load = -108
[rolling]
mode = "steady"
direction = 1
{velocity}
[solvers]
use = ["active_set", "lemke"]
"#
    );
    Scene::from_toml(&text, std::path::Path::new("visc_cylindr.toml")).unwrap()
}

/// What a run gives to compare: creepage, approach, peak pressure, contact and stick counts, first and last contact
/// element (1-based, CONTACT's numbering), and the pressures and shears.
struct Outcome {
    creepage: f64,
    approach: f64,
    pmax: f64,
    contact: usize,
    stick: usize,
    first_last: (usize, usize),
    p: Vec<f64>,
    q: Vec<f64>,
}

fn outcome(scene: &Scene) -> Vec<Outcome> {
    let report = run_scene(scene).unwrap();
    report
        .runs
        .iter()
        .map(|r| {
            assert_eq!(
                r.status,
                Status::Solved,
                "{} {:?}: {}",
                r.solver,
                scene.viscoelastic_memories(),
                r.explanation()
            );
            let states: Vec<NodeState> = r.nodes.iter().map(|n| n.state).collect();
            let in_contact: Vec<usize> = (0..states.len()).filter(|&i| states[i] != NodeState::Separated).collect();
            Outcome {
                creepage: r.rolling.as_ref().unwrap().creepage.unwrap(),
                approach: r.rigid_body.unwrap().normal,
                pmax: r.nodes.iter().map(|n| n.pressure).fold(0.0, f64::max),
                contact: in_contact.len(),
                stick: states.iter().filter(|s| **s == NodeState::Stick).count(),
                first_last: (in_contact[0] + 1, in_contact[in_contact.len() - 1] + 1),
                p: r.nodes.iter().map(|n| n.pressure).collect(),
                q: r.nodes.iter().map(|n| n.shear).collect(),
            }
        })
        .collect()
}

/// `x` rounded to `digits` significant digits, as CONTACT prints it.
fn printed(x: f64, digits: i32) -> f64 {
    let e = x.abs().log10().floor() as i32;
    let s = 10f64.powi(digits - 1 - e);
    (x * s).round() / s
}

/// The strip kernel with memory against an independent integration. mpmath, 30 digits:
/// `czz(ta, tb) = (1−ν) K I1`, `K = (1+ν)/π` (E = 1), `I1 = 2[ta asinh(H/|ta|) − tb asinh(H/|tb|) + H (asinh(ta/H)
/// − asinh(tb/H))]`, H = 5, ν = 0.4, element 0.0016, L = 20 (CONTACT's case 4 in wheel diameters: V τ_C = 2000 mm,
/// 2R = 100 mm), value `czz(ta, tb) + quad(lambda e: exp(−e) czz(ta + L e, tb + L e), [0, −ta/L, −tb/L, inf])` at
/// `ta = (k + ½)·0.0016`, `tb = (k − ½)·0.0016` for the offset k = i − j.
const MPMATH_CZZ: [(i64, f64); 7] = [
    (0, 0.009_485_797_318_032_843),
    (10, 0.006_062_694_108_660_681),
    (-10, 0.006_071_981_756_688_87),
    (50, 0.004_672_236_371_652_269),
    (-50, 0.004_707_661_095_594_819),
    (98, 0.004_084_015_468_064_989),
    (-98, 0.004_144_421_150_865_119),
];

#[test]
fn the_memory_kernel_is_the_independent_integral() {
    let hp = HalfPlane::new(1.0, 0.4, 1.0)
        .unwrap()
        .strip(10.0)
        .unwrap()
        .viscoelastic(Memory { ratio: 1.0, distance: 20.0 })
        .unwrap();
    let n = 99;
    let block = hp.influence_block_uniform(-0.08, 0.0016, n, Block::Zz).unwrap();
    for (k, reference) in MPMATH_CZZ {
        // Entry (i, j) with i − j = k: pick j = 0 for k ≥ 0, i = 0 otherwise.
        let (i, j) = if k >= 0 { (k as usize, 0) } else { (0, (-k) as usize) };
        let v = block[i * n + j];
        assert!((v - reference).abs() <= 1e-13 * reference, "k = {k}: {v:e} against {reference:e}");
    }
    // The memory makes the block nonsymmetric: upstream (k < 0, the load downstream of the point... ) differs.
    assert!(block[n] != block[1]);
}

/// CONTACT's visc_cylindr.ref_out, per case: (FG, TC) or elastic G; CREEP X, PMAX, NCON, NADH, the first and last
/// contact element of its "FORM OF THE CONTACT" line, and APPROACH.
struct ContactCase {
    case: usize,
    solid: Option<(f64, f64)>,
    g: f64,
    creepage: f64,
    pmax: f64,
    contact: usize,
    stick: usize,
    first_last: (usize, usize),
    approach: f64,
}

const CONTACT: [ContactCase; 6] = [
    ContactCase {
        case: 1,
        solid: Some((1.0, 0.0)),
        g: 1143.0,
        creepage: 1.378e-2,
        pmax: 60.32,
        contact: 80,
        stick: 51,
        first_last: (11, 90),
        approach: 2.50845,
    },
    ContactCase {
        case: 2,
        solid: Some((1.0, 0.009)),
        g: 1143.0,
        creepage: 1.365e-2,
        pmax: 78.74,
        contact: 62,
        stick: 37,
        first_last: (26, 87),
        approach: 2.36736,
    },
    ContactCase {
        case: 3,
        solid: Some((1.0, 0.045)),
        g: 1143.0,
        creepage: 1.152e-2,
        pmax: 84.72,
        contact: 57,
        stick: 36,
        first_last: (26, 82),
        approach: 2.06321,
    },
    ContactCase {
        case: 4,
        solid: Some((1.0, 2.0)),
        g: 1143.0,
        creepage: 9.932e-3,
        pmax: 85.31,
        contact: 56,
        stick: 35,
        first_last: (23, 78),
        approach: 1.45462,
    },
    ContactCase {
        case: 5,
        solid: None,
        g: 571.5,
        creepage: 1.378e-2,
        pmax: 60.32,
        contact: 80,
        stick: 51,
        first_last: (11, 90),
        approach: 2.50845,
    },
    ContactCase {
        case: 6,
        solid: None,
        g: 1143.0,
        creepage: 9.792e-3,
        pmax: 85.29,
        contact: 56,
        stick: 36,
        first_last: (23, 78),
        approach: 1.32370,
    },
];

/// The six cases against CONTACT's printed output: the creepage to its 4 printed digits, the contact and adhesion
/// counts and the contact's place (first and last element) exactly, the peak pressure to its 4 printed digits in
/// five cases. Case 4 (τ_C = 2 s, V τ_C = 2000 mm, 250 contact widths) prints PMAX = 85.31 where rollbem has
/// 85.299 (1.3e-4 relative; its creepage and counts agree): CONTACT integrates the memory with QUADPACK at a
/// relative accuracy of 1e-3 (m_visc.f90, `dnumin`), and at this relaxation distance the x-dependent part of the
/// integral is a small remainder of a large constant; rollbem's kernel meets the 30-digit integral above to 1e-13.
/// That difference is asserted as it stands, not absorbed into a tolerance. The approach depends on the constant
/// part too: it is checked to 5e-5 relative (case 4: 1.45465 against 1.45462).
#[test]
fn visc_cylindr_against_contacts_printed_output() {
    for c in &CONTACT {
        for o in outcome(&visc_cylindr(c.solid, c.g, false)) {
            let case = c.case;
            assert_eq!(printed(o.creepage, 4), c.creepage, "case {case}: creepage {:e}", o.creepage);
            assert_eq!((o.contact, o.stick, o.first_last), (c.contact, c.stick, c.first_last), "case {case}");
            if case == 4 {
                assert!((o.pmax - 85.299).abs() < 5e-4, "case 4: pmax {}", o.pmax);
            } else {
                assert_eq!(printed(o.pmax, 4), c.pmax, "case {case}: pmax {}", o.pmax);
            }
            assert!((o.approach - c.approach).abs() <= 5e-5 * c.approach, "case {case}: approach {}", o.approach);
        }
    }
}

/// The scene with the active-set solver alone.
fn active_set(s: Scene) -> Scene {
    s.edit(|d| d.solvers = rollbem::scene::document::SolversTable::using(&["active_set"])).unwrap()
}

/// max |Δp|, |Δq| over the nodes, relative to the peak pressure of `b`.
fn traction_difference(a: &Outcome, b: &Outcome) -> f64 {
    let pmax = b.pmax;
    let dp = a.p.iter().zip(&b.p).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    let dq = a.q.iter().zip(&b.q).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    dp.max(dq) / pmax
}

/// τ_C → 0 (instantaneous creep) is the elastic body of the relaxed modulus G/(1 + f); τ_C → ∞ (frozen) that of the
/// glassy G. Both through the memory integral (τ_C = 1e-15 s: L = 1e-12 mm against 0.16 mm elements; τ_C = 1e10 s:
/// L = 1e13 mm, 1e11 wheel diameters, the largest the scene admits), on CONTACT's strip and in plane strain, against
/// the elastic model's tractions and creepage to 1e-10. On the strip the approach agrees as well (to 1e-10 at
/// τ_C → 0; as 1/L at τ_C → ∞, 1.9e-10 here); in plane strain the frozen memory adds a constant that grows like
/// ln L (the far field of a 2D load), so only the tractions and the creepage are compared there.
#[test]
fn the_elastic_limits_are_the_elastic_model() {
    for plane_strain in [false, true] {
        for (tc, g_elastic) in [(1e-15, 571.5), (1e10, 1143.0)] {
            let v = &outcome(&active_set(visc_cylindr(Some((1.0, tc)), 1143.0, plane_strain)))[0];
            let e = &outcome(&visc_cylindr(None, g_elastic, plane_strain))[0];
            let d = traction_difference(v, e);
            let what = format!("plane strain {plane_strain}, τ_C = {tc:e}");
            assert!(d <= 1e-10, "{what}: tractions differ by {d:e}");
            assert!((v.creepage - e.creepage).abs() <= 1e-10 * e.creepage, "{what}: {} {}", v.creepage, e.creepage);
            if !plane_strain {
                // The strip's approach converges as 1/L (measured: 1.7e-9 at τ_C = 1e9 s, 1.9e-10 at 1e10 s).
                let bound = if tc < 1.0 { 1e-10 } else { 1e-9 };
                assert!((v.approach - e.approach).abs() <= bound * e.approach, "{what}: {} {}", v.approach, e.approach);
            }
        }
    }
    // And an intermediate τ_C is neither: the test can tell.
    let v = &outcome(&visc_cylindr(Some((1.0, 0.009)), 1143.0, false))[0];
    for g in [571.5, 1143.0] {
        let e = &outcome(&visc_cylindr(None, g, false))[0];
        assert!(traction_difference(v, e) > 1e-2, "G = {g}");
    }
}

/// The viscoelastic pressure leans forward (towards the leading edge, +x) and the contact shifts forward: the
/// pressure's centre x̄ = Σ x p / Σ p is ahead of the elastic one's (0 by symmetry), and a rolling resistance
/// (the normal load's moment arm x̄ > 0) appears. (Wang & Knothe's and CONTACT's user guide's description.)
#[test]
fn the_pressure_leans_forward() {
    let scene = visc_cylindr(Some((1.0, 0.009)), 1143.0, false);
    let report = run_scene(&scene).unwrap();
    let r = &report.runs[0];
    let (sp, sxp) = r.nodes.iter().fold((0.0, 0.0), |(s, sx), n| (s + n.pressure, sx + n.x * n.pressure));
    let centre = sxp / sp;
    assert!(centre > 0.1, "centre of pressure {centre}");
    let elastic = run_scene(&visc_cylindr(None, 1143.0, false)).unwrap();
    let r = &elastic.runs[0];
    let (sp, sxp) = r.nodes.iter().fold((0.0, 0.0), |(s, sx), n| (s + n.pressure, sx + n.x * n.pressure));
    assert!((sxp / sp).abs() < 0.01, "elastic centre {}", sxp / sp);
}

/// An elastic scene builds no memory, and a memory with f = 0 is the elastic kernel bit for bit.
#[test]
fn an_elastic_scene_takes_the_elastic_path() {
    let s = visc_cylindr(None, 1143.0, false);
    assert_eq!(s.viscoelastic_memories(), (None, None));
    assert!(!s.is_viscoelastic());
    let hp = HalfPlane::new(1.0, 0.4, 1.0).unwrap();
    let zero = hp.viscoelastic(Memory { ratio: 0.0, distance: 3.0 }).unwrap();
    for which in [Block::Xx, Block::Xz, Block::Zx, Block::Zz] {
        let a = hp.influence_block_uniform(-0.1, 0.01, 20, which).unwrap();
        let b = zero.influence_block_uniform(-0.1, 0.01, 20, which).unwrap();
        assert_eq!(a, b);
    }
}

#[test]
fn bad_viscoelastic_input_is_refused_naming_the_key() {
    use rollbem::scene::document::{CounterBodyTable, ViscoelasticTable};
    let good = visc_cylindr(Some((1.0, 0.009)), 1143.0, false);
    let refused = |edit: &dyn Fn(&mut rollbem::scene::document::SceneDocument), key: &str| {
        let e = good.edit(edit).unwrap_err().to_string();
        assert!(e.contains(key), "{key}: {e}");
    };
    refused(&|d| d.rolling.as_mut().unwrap().velocity = None, "rolling.velocity");
    refused(&|d| d.rolling.as_mut().unwrap().velocity = Some(-1.0), "rolling.velocity");
    refused(&|d| d.rolling.as_mut().unwrap().velocity = Some(f64::NAN), "rolling.velocity");
    refused(&|d| d.rolling.as_mut().unwrap().velocity = Some(1e30), "wheel diameters");
    refused(&|d| d.wheel.viscoelastic.as_mut().unwrap().creep_time = Some(-1.0), "wheel.viscoelastic.creep_time");
    refused(&|d| d.wheel.viscoelastic.as_mut().unwrap().compliance_ratio = None, "wheel.viscoelastic");
    refused(&|d| d.wheel.viscoelastic.as_mut().unwrap().relaxed_modulus = Some(100.0), "wheel.viscoelastic");
    refused(
        &|d| {
            d.wheel.viscoelastic = Some(ViscoelasticTable {
                relaxed_modulus: Some(5000.0),
                relaxation_time: Some(1.0),
                ..Default::default()
            })
        },
        "wheel.viscoelastic.relaxed_modulus",
    );
    refused(
        &|d| {
            if let CounterBodyTable::HalfPlane { viscoelastic, .. } = &mut d.counter_body {
                viscoelastic.as_mut().unwrap().compliance_ratio = Some(f64::INFINITY);
            }
        },
        "counter_body.viscoelastic.compliance_ratio",
    );
    refused(
        &|d| {
            let r = d.rolling.as_mut().unwrap();
            r.mode = rollbem::scene::RollingMode::Seed;
            r.creepage = Some(0.001);
            d.drive.tangential_load = None;
        },
        "wheel.viscoelastic",
    );
    // A velocity without a viscoelastic body means nothing.
    let elastic = visc_cylindr(None, 1143.0, false);
    let e = elastic.edit(|d| d.rolling.as_mut().unwrap().velocity = Some(3.0)).unwrap_err().to_string();
    assert!(e.contains("rolling.velocity"), "{e}");
    // The relaxation form converts: E_r = E_g/2, τ_E = τ_C/2 is the same solid as f = 1, τ_C (CONTACT's table).
    let relaxation = good
        .edit(|d| {
            let t = ViscoelasticTable {
                relaxed_modulus: Some(1600.2),
                relaxation_time: Some(0.0045),
                ..Default::default()
            };
            d.wheel.viscoelastic = Some(t);
            if let CounterBodyTable::HalfPlane { viscoelastic, .. } = &mut d.counter_body {
                *viscoelastic = Some(t);
            }
        })
        .unwrap();
    let a = outcome(&relaxation);
    let b = outcome(&good);
    assert!(traction_difference(&a[0], &b[0]) < 1e-12);
}
