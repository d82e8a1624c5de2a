//! Subsurface stresses (`[stresses]`, `rollbem::stresses`) against closed-form elasticity. Run with `--nocapture` to
//! see every measured figure.
//!
//! References (each test names its own): McEwen (1949), Phil. Mag. 40, 454–459, and Johnson, *Contact Mechanics*
//! (1985) §4.2 and §7.1 for the field under a Hertz line contact, frictionless and in full sliding
//! (`rollbem::theory::{mcewen_normal, mcewen_sliding, hertz_axis_max_tau1, mcewen_max_tau1, mcewen_max_von_mises}`,
//! each verified in theory.rs against independent quadrature of the Flamant solution); Timoshenko & Goodier,
//! *Theory of Elasticity* §41, for the disk under two opposite point loads (`theory::disk_point_loads`); Hertz
//! (`theory::Hertz2D`) for a and p0 at the applied load. Expected values never come from rollbem's own output.

use rollbem::pipeline::run_scene;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use rollbem::stresses::StressResult;
use rollbem::theory::{
    disk_point_loads, hertz_axis_max_tau1, mcewen_max_tau1, mcewen_max_von_mises, mcewen_normal, mcewen_sliding,
    Hertz2D, Stress2D,
};
use std::path::{Path, PathBuf};
use std::process::Command;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("<test>")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn run(s: &Scene) -> Report {
    run_scene(s).unwrap()
}

fn lemke(r: &Report) -> &SolverRun {
    r.runs.iter().find(|x| x.solver == "lemke").expect("lemke run")
}

fn stresses(r: &Report) -> &StressResult {
    let l = lemke(r);
    assert_eq!(l.status, Status::Solved, "{}", l.explanation());
    l.stresses.as_ref().expect("a solved run of a scene with [stresses] has its field")
}

/// Steel (R = 460 mm, E = 210 GPa in MPa, ν = 0.3), P = 20 000 N/mm: a = 7.1246 mm, p0 = 1787.1 MPa.
const R: f64 = 460.0;
const E: f64 = 210000.0;
const NU: f64 = 0.3;
const P: f64 = 20000.0;

fn estar() -> f64 {
    E / (1.0 - NU * NU)
}

/// Hertz at load `p` (theory, independent of rollbem's own Hertz module).
fn hertz(p: f64, r: f64) -> Hertz2D {
    Hertz2D::from_load(p, r, estar())
}

/// The steel wheel as a half-plane with Hertz's parabola (so Hertz and McEwen are exact for it), `n` strips on
/// |x| ≤ 9 mm, a `[contact]` and `[drive]` body, and a `[stresses]` grid.
fn half_plane(n: usize, contact: &str, drive: &str, grid: &str) -> Scene {
    scene(&half_plane_text(n, contact, drive, grid))
}

/// The TOML text of [`half_plane`].
fn half_plane_text(n: usize, contact: &str, drive: &str, grid: &str) -> String {
    format!(
        r#"
name = "stress-half-plane"
[wheel]
radius = {R}
youngs_modulus = {E}
poisson_ratio = {NU}
model = "half_plane"
profile = "parabola"
[mesh]
element = "constant"
contact_half_width = 9.0
contact_elements = {n}
[contact]
{contact}
[drive]
{drive}
[solvers]
use = ["lemke"]
[stresses]
{grid}
"#
    )
}

/// `[stresses]` grid text in units of a.
fn grid(a: f64, x: [f64; 2], depth: [f64; 2], points: [usize; 2]) -> String {
    format!(
        "x = [{}, {}]\ndepth = [{}, {}]\npoints = [{}, {}]",
        x[0] * a,
        x[1] * a,
        depth[0] * a,
        depth[1] * a,
        points[0],
        points[1]
    )
}

/// Largest component difference |Δσ_xx|, |Δσ_zz|, |Δτ_xz| between the computed field and `reference(x, z)` over
/// the points with depth in `depths`, and where: (error, x, depth).
fn field_error(st: &StressResult, depths: [f64; 2], reference: impl Fn(f64, f64) -> Stress2D) -> (f64, f64, f64) {
    let f = &st.field;
    let mut worst = (0.0, f64::NAN, f64::NAN);
    for k in 0..f.stress.len() {
        let (x, z) = f.grid.point(k);
        if z < depths[0] || z > depths[1] {
            continue;
        }
        let s = f.stress[k].unwrap_or_else(|e| panic!("point ({x}, {z}) refused: {e:?}"));
        let t = reference(x, z);
        let e = (s[0] - t.xx).abs().max((s[1] - t.yy).abs()).max((s[2] - t.xy).abs());
        if e > worst.0 {
            worst = (e, x, z);
        }
    }
    worst
}

#[test]
fn frictionless_hertz_max_principal_shear_is_mcewens() {
    // Reference: McEwen (1949), Johnson §4.2: on the axis of a Hertz line contact τ₁ peaks at 0.300 p0 at depth
    // 0.786 a (theory::hertz_axis_max_tau1, golden-section search of the closed-form axis stresses). Required: within
    // 1 % in value and depth at ≥ 40 elements across the contact. The grid brackets the axis finely (depth step
    // 0.001a), so the grid's own resolution is below 0.1 %.
    let h = hertz(P, R);
    let (z_ref, tau_ref) = hertz_axis_max_tau1();
    for n in [51usize, 120] {
        let across = 2.0 * h.a / (18.0 / n as f64);
        let s = half_plane(n, "", &format!("normal_load = {P}"), &grid(h.a, [-0.1, 0.1], [0.7, 0.87], [5, 171]));
        let r = run(&s);
        let m = stresses(&r).field.maximum(rollbem::stresses::StressQuantity::PrincipalShear).unwrap();
        let (ev, ez) = (m.value / (tau_ref * h.p0) - 1.0, m.depth / (z_ref * h.a) - 1.0);
        eprintln!(
            "n = {n} ({across:.1} across): max τ₁ = {:.5} p0 at z = {:.5} a, x = {:.3} a; errors value {ev:+.2e}, depth {ez:+.2e}",
            m.value / h.p0,
            m.depth / h.a,
            m.x / h.a
        );
        assert!(across >= 40.0);
        assert!(ev.abs() <= 0.01 && ez.abs() <= 0.01, "n = {n}: value {ev:e}, depth {ez:e}");
        assert!(m.x.abs() <= 0.026 * h.a, "off the axis: x = {}", m.x);
    }
}

#[test]
fn frictionless_field_on_a_grid_is_mcewens() {
    // Reference: McEwen's closed form (theory::mcewen_normal) at Hertz's a and p0 for the applied load, on the grid
    // |x| ≤ 2a, 0 < z ≤ 3a. The half-plane's field is exact for its piecewise-uniform tractions, so what is measured
    // is the traction discretisation's imprint on the field. On the surface itself the field is the traction (σ_zz =
    // −p_j, τ_xz = −q_j of the strip under the point: checked exactly, the "boundary-exact value"); its error there
    // is the traction's own pointwise error, up to ~p0·√(h/a) beside the contact edges, where p has infinite slope.
    let h = hertz(P, R);
    let mut deep = Vec::new();
    for n in [51usize, 120, 240] {
        let s = half_plane(n, "", &format!("normal_load = {P}"), &grid(h.a, [-2.0, 2.0], [0.0, 3.0], [81, 61]));
        let r = run(&s);
        let st = stresses(&r);
        let near = field_error(st, [1e-9, 0.1 * h.a], |x, z| mcewen_normal(&h, x, z));
        let far = field_error(st, [0.1 * h.a, 3.0 * h.a], |x, z| mcewen_normal(&h, x, z));
        eprintln!(
            "n = {n}: max |Δσ| / p0 at 0 < z < 0.1a {:.2e} at ({:.3} a, {:.3} a); at 0.1a ≤ z ≤ 3a {:.2e} at ({:.3} a, {:.3} a)",
            near.0 / h.p0,
            near.1 / h.a,
            near.2 / h.a,
            far.0 / h.p0,
            far.1 / h.a,
            far.2 / h.a
        );
        deep.push(far.0 / h.p0);
        // The surface row: exactly the strip's traction (a point on a strip edge: the mean of the two strips).
        let l = lemke(&r);
        let f = &st.field;
        for i in 0..f.grid.points[0] {
            let x = f.grid.x_at(i);
            let strip = ((x + 9.0) / (18.0 / n as f64)).floor();
            let s0 = f.stress[i].expect("surface points of the half-plane have values");
            if strip >= 0.0 && (strip as usize) < n && ((x + 9.0) / (18.0 / n as f64)).fract() != 0.0 {
                let pj = l.nodes[strip as usize].pressure;
                assert!((s0[1] + pj).abs() <= 1e-12 * h.p0 && s0[2].abs() <= 1e-12 * h.p0, "x = {x}: {s0:?} vs p {pj}");
            }
        }
    }
    assert!(deep[0] <= 5e-3 && deep[1] <= 5e-4 && deep[2] <= 5e-4, "{deep:?}");
}

/// The maxima of τ₁ and von Mises on a fine grid under full sliding q = μp, against McEwen's closed form.
fn sliding_maxima(mu: f64) -> (rollbem::stresses::Maximum, rollbem::stresses::Maximum, Hertz2D, f64) {
    use rollbem::stresses::StressQuantity::{PrincipalShear, VonMises};
    let h = hertz(P, R);
    let contact = format!("friction = {mu}\ncoupling = false");
    let drive = format!("normal_load = {P}\ntangential_load = {}", mu * P);
    // x nodes at the 120 strips' centres (|x| ≤ 8.925 mm = 1.253a, step h = 0.15 mm = 0.021a), depth step 0.01a.
    // On the surface the discrete field of piecewise-uniform shear has a log singularity in σ_xx at every strip
    // edge, (2Δq/π) ln(h/d) at a distance d from it, Δq the jump between strips: a grid node that happens to fall
    // close to an edge sees a spike that is the discretisation's, not the contact's. At a strip centre (d = h/2 from
    // both edges) the spikes of neighbouring edges cancel to O(Δq), so the surface row there is the continuous
    // field up to the traction's own error.
    let grid = format!("x = [-8.925, 8.925]\ndepth = [0.0, {}]\npoints = [120, 151]", 1.5 * h.a);
    let s = half_plane(120, &contact, &drive, &grid);
    let r = run(&s);
    let st = stresses(&r);
    // The whole field against McEwen's combined loading (theory::mcewen_sliding), below 0.1a.
    let far = field_error(st, [0.1 * h.a, 1.5 * h.a], |x, z| mcewen_sliding(&h, mu, x, z));
    let f = &st.field;
    (f.maximum(PrincipalShear).unwrap(), f.maximum(VonMises).unwrap(), h, far.0 / h.p0)
}

#[test]
fn full_sliding_field_and_its_maximum_moving_to_the_surface() {
    // Reference: McEwen (1949) / Johnson §7.1 for Hertz pressure plus q = μp (theory::mcewen_sliding), with the
    // locations of max τ₁ and max von Mises from theory::mcewen_max_tau1 / mcewen_max_von_mises (grid search and
    // compass refinement of the closed form, cross-checked in theory.rs). The scene is the onset of gross sliding,
    // Q = μP (every node slips, q = μp), with the coupling off so that the pressure stays Hertz's (β = 0). The grid
    // steps are 0.021a in x (strip centres) and 0.01a in depth, so locations agree to about a step (0.02a asked);
    // values to 1 %. The field itself below 0.1a: within 5e-4 p0, the frictionless grid's figure at the same mesh
    // (frictionless_field_on_a_grid_is_mcewens: 7e-5 at 95 elements across), the shear adding an error of the same
    // order as the pressure's.
    let mut depths = Vec::new();
    for mu in [0.0, 0.1, 0.2, 0.3, 0.4, 0.5] {
        let (t1, vm, h, far) = sliding_maxima(mu);
        let (tt, tv) = (mcewen_max_tau1(mu), mcewen_max_von_mises(mu, NU));
        let (a, p0) = (h.a, h.p0);
        eprintln!(
            "μ = {mu}: field error below 0.1a {far:.2e} p0; max τ₁ {:.4} p0 at ({:.3}, {:.3}) a, theory {:.4} at ({:.3}, {:.3}); \
             max von Mises {:.4} p0 at ({:.3}, {:.3}) a, theory {:.4} at ({:.3}, {:.3})",
            t1.value / p0,
            t1.x / a,
            t1.depth / a,
            tt.value,
            tt.x,
            tt.z,
            vm.value / p0,
            vm.x / a,
            vm.depth / a,
            tv.value,
            tv.x,
            tv.z
        );
        assert!(far <= 5e-4, "μ = {mu}: field error {far:e} p0");
        assert!((t1.depth / a - tt.z).abs() <= 0.02, "μ = {mu}: τ₁ depth {} vs {}", t1.depth / a, tt.z);
        assert!((vm.depth / a - tv.z).abs() <= 0.02, "μ = {mu}: vM depth {} vs {}", vm.depth / a, tv.z);
        assert!((vm.value / p0 / tv.value - 1.0).abs() <= 0.01, "μ = {mu}: vM {} vs {}", vm.value / p0, tv.value);
        assert!((vm.x / a - tv.x).abs() <= 0.02, "μ = {mu}: vM x {} vs {}", vm.x / a, tv.x);
        // Johnson §7.1 (fig. 7.8): from μ ≈ 0.3 on, the maximum of von Mises is on the surface.
        assert_eq!(vm.depth == 0.0, mu >= 0.3, "μ = {mu}: vM depth {}", vm.depth / a);
        if mu < 0.378 {
            // Below μ = 1/√7 the maximum of τ₁ is a single subsurface point.
            assert!((t1.value / p0 / tt.value - 1.0).abs() <= 0.01, "μ = {mu}: τ₁ {} vs {}", t1.value / p0, tt.value);
            assert!((t1.x / a - tt.x).abs() <= 0.02, "μ = {mu}: τ₁ x {} vs {}", t1.x / a, tt.x);
        } else {
            // Above it, τ₁ = μp0 on the whole contact surface (a plateau, McEwen / Johnson §7.1), so where on the
            // plateau the grid's maximum falls is arbitrary; its value is μp0. On the surface the half-plane's
            // field at a strip centre is its tractions' (σ_zz = −p_j, τ_xz = −q_j) and σ_xx up to O(Δq): the
            // plateau holds to 1 % away from the contact edges (|x| ≤ 0.9a; beside them the piecewise-uniform
            // pressure's own error, ~p0√(h/a), dominates).
            let f = &st_plateau(mu);
            let row: Vec<f64> = (0..f.0.len()).filter(|&i| f.0[i].abs() <= 0.9 * a).map(|i| f.1[i]).collect();
            let worst = row.iter().map(|v| (v / (mu * p0) - 1.0).abs()).fold(0.0, f64::max);
            eprintln!("  surface plateau |x| ≤ 0.9a: τ₁/(μp0) − 1 within {worst:.2e} over {} points", row.len());
            assert!(worst <= 0.01, "plateau {worst}");
            assert!((t1.value / (mu * p0) - 1.0).abs() <= 0.01, "max τ₁ {} vs μp0 {}", t1.value, mu * p0);
        }
        depths.push(t1.depth / a);
    }
    // The maximum of τ₁ moves towards the surface as μ grows (strictly, while below it), and is on it above
    // μ = 1/√7 (μ = 0.4, 0.5).
    assert!(depths.windows(2).all(|w| w[1] < w[0] || (w[0] == 0.0 && w[1] == 0.0)), "{depths:?}");
    assert_eq!(&depths[4..], &[0.0, 0.0], "{depths:?}");
}

/// τ₁ on the surface row (x, τ₁) under full sliding q = μp (the grid of [`sliding_maxima`]).
fn st_plateau(mu: f64) -> (Vec<f64>, Vec<f64>) {
    use rollbem::stresses::StressQuantity::PrincipalShear;
    let h = hertz(P, R);
    let contact = format!("friction = {mu}\ncoupling = false");
    let drive = format!("normal_load = {P}\ntangential_load = {}", mu * P);
    // x nodes at the strips' centres, as in sliding_maxima (a node on a strip edge would be singular).
    let s = half_plane(
        120,
        &contact,
        &drive,
        &format!("x = [-8.925, 8.925]\ndepth = [0.0, {}]\npoints = [120, 2]", 0.01 * h.a),
    );
    let r = run(&s);
    let f = &stresses(&r).field;
    let n = f.grid.points[0];
    ((0..n).map(|i| f.grid.x_at(i)).collect(), (0..n).map(|i| f.value(PrincipalShear, i).unwrap()).collect())
}

#[test]
fn steady_rolling_in_full_slip_has_the_sliding_field() {
    // Reference: as above (theory::mcewen_sliding). Steady rolling at a creepage above μa/R (Carter's saturation,
    // REFERENCES.md) slips everywhere: q = μp with the sign of the solved Q. The field is then McEwen's for
    // μ_eff = Q/P.
    let (mu, h) = (0.2, hertz(P, R));
    let xi = 2.0 * mu * h.a / R;
    let contact =
        format!("friction = {mu}\ncoupling = false\n[rolling]\nmode = \"steady\"\ncreepage = {xi}\ndirection = 1");
    let s = half_plane(120, &contact, &format!("normal_load = {P}"), &grid(h.a, [-1.5, 1.5], [0.0, 1.5], [61, 31]));
    let r = run(&s);
    let l = lemke(&r);
    let f = l.resultants.unwrap();
    let mu_eff = f.tangential / f.normal;
    assert!((mu_eff.abs() - mu).abs() <= 1e-9, "not in full slip: Q/P = {mu_eff}");
    let far = field_error(stresses(&r), [0.1 * h.a, 1.5 * h.a], |x, z| mcewen_sliding(&h, mu_eff, x, z));
    eprintln!("steady rolling at ξ = 2μa/R: Q/P = {mu_eff:+.6}, field error below 0.1a {:.2e} p0", far.0 / h.p0);
    assert!(far.0 <= 2e-3 * h.p0);
}

/// The steel wheel on a hub (R = 460, hub 100) at a/R = `ar`, `n` elements on |x| ≤ 1.25a (100 across for constant
/// elements with n = 125), or the half-plane with the wheel's circle on the same grid; `[stresses]` over
/// |x| ≤ 1.25a (inside the contact mesh, elements 0.02a long with n = 125), 0.1a ≤ z ≤ 3a.
fn small_contact(model: &str, element: &str, n: usize, ar: f64) -> (Scene, Hertz2D) {
    let a = ar * R;
    let p = Hertz2D::from_half_width(a, R, estar()).load;
    let body = if model == "bem" { "support = { kind = \"hub\", radius = 100.0 }" } else { "" };
    let other = if model == "bem" { "other_elements = 200" } else { "" };
    let s = scene(&format!(
        r#"
name = "small-contact"
[wheel]
radius = {R}
youngs_modulus = {E}
poisson_ratio = {NU}
model = "{model}"
{body}
[mesh]
element = "{element}"
contact_half_width = {hw}
contact_elements = {n}
{other}
[drive]
normal_load = {p}
[solvers]
use = ["lemke"]
[stresses]
{grid}
"#,
        hw = 1.25 * a,
        grid = grid(a, [-1.25, 1.25], [0.1, 3.0], [51, 59])
    ));
    (s, hertz(p, R))
}

#[test]
fn finite_wheel_field_agrees_with_the_half_plane_at_small_a_over_r() {
    // References: McEwen's field (theory::mcewen_normal at Hertz's a, p0; the half-plane theory the finite wheel
    // tends to as a/R → 0) and, as an independent computation, rollbem's half-plane model of the same scene (closed-
    // form strips, no BEM). Required: within 1 % of p0 at depths 0.1a to 3a. What remains at a/R = 0.0025 is the
    // finite wheel's own O(a/R) difference (the hub's reaction, the curvature; measured 0.93 % at a/R = 0.01, 0.4 %
    // at 0.0025), not the evaluation: the grid stays ≥ 5 element lengths from the surface.
    let ar = 0.0025;
    let (hs, h) = small_contact("half_plane", "constant", 125, ar);
    let hp = run(&hs);
    let hp_field = &stresses(&hp).field;
    for (element, n) in [("constant", 125usize), ("quadratic", 42)] {
        let (s, _) = small_contact("bem", element, n, ar);
        let r = run(&s);
        let st = stresses(&r);
        assert!(st.refused().is_empty(), "{:?}", st.refused());
        let theory = field_error(st, [0.0, f64::INFINITY], |x, z| mcewen_normal(&h, x, z));
        let other = field_error(st, [0.0, f64::INFINITY], |x, z| {
            let k =
                hp_field.grid.len().min((0..hp_field.grid.len()).find(|&k| hp_field.grid.point(k) == (x, z)).unwrap());
            let v = hp_field.stress[k].unwrap();
            Stress2D { xx: v[0], yy: v[1], xy: v[2] }
        });
        eprintln!(
            "BEM ({element}, a/R = {ar}) vs McEwen: max |Δσ| = {:.2e} p0 at ({:.2} a, {:.2} a); vs the half-plane model: {:.2e} p0 at ({:.2} a, {:.2} a); {} points in {:.3} s",
            theory.0 / h.p0,
            theory.1 / h.a,
            theory.2 / h.a,
            other.0 / h.p0,
            other.1 / h.a,
            other.2 / h.a,
            st.field.grid.len(),
            st.time_s
        );
        assert!(theory.0 <= 0.01 * h.p0 && other.0 <= 0.01 * h.p0);
    }
}

/// The wheel clamped on a top arc of `top` degrees (quadratic elements), loaded by a Hertz contact at a/R = 0.01;
/// its field over the centre region of the disk, and the contact's resultant P.
fn clamped_disk(top: f64, other: usize) -> (StressResult, f64) {
    let (r, e) = (1.0, 1.0);
    let a = 0.01 * r;
    let p = Hertz2D::from_half_width(a, r, e / (1.0 - NU * NU)).load;
    let s = scene(&format!(
        r#"
name = "clamped-disk"
[wheel]
radius = {r}
youngs_modulus = {e}
poisson_ratio = {NU}
support = {{ kind = "top_arc", angle_deg = {top} }}
[mesh]
element = "quadratic"
contact_half_width = {hw}
contact_elements = 20
other_elements = {other}
[drive]
normal_load = {p}
[solvers]
use = ["lemke"]
[stresses]
x = [-0.6, 0.6]
depth = [0.4, 1.6]
points = [25, 25]
"#,
        hw = 1.25 * a
    ));
    let rep = run(&s);
    let l = lemke(&rep);
    (l.stresses.clone().unwrap(), l.resultants.unwrap().normal)
}

#[test]
fn finite_wheel_far_field_is_the_diametrally_loaded_disk() {
    // Reference: Timoshenko & Goodier §41, the disk under two opposite point loads P at (0, ±R)
    // (theory::disk_point_loads). Which wheel it applies to: the full disk clamped on a short arc at the top (support
    // top_arc) and pressed on the flat at the bottom carries the contact force P at the bottom and the clamp's
    // reaction, P in all, at the top; nothing else loads it. With a contact of a = 0.01R and a clamp of 1° or 2°,
    // both loads are points as seen from the disk's centre region (|r| ≤ 0.6R, at least 0.4R from either), where
    // the point-load solution applies up to the loads' finite size. The contact's spread is Hertzian, symmetric and
    // frictionless (an error ~(a/r)²); the clamp also grips tangentially (it stops the Poisson expansion of the
    // clamped arc), a self-equilibrated horizontal pair whose field falls like (w/r) relative to P/r, w the clamp's
    // half-width: so the comparison is held tightest in the lower half (≥ 1R from the clamp), and the upper half's
    // difference must shrink with the clamp. The scale is the centre's |σ_yy| = 3P/(πR).
    let mut upper = Vec::new();
    for top in [2.0, 1.0] {
        let (st, p) = clamped_disk(top, 480);
        let scale = 3.0 * p / std::f64::consts::PI;
        let (mut lo, mut up) = (0.0f64, 0.0f64);
        let f = &st.field;
        for k in 0..f.stress.len() {
            let (x, z) = f.grid.point(k);
            let y = z - 1.0;
            if x.hypot(y) > 0.6 {
                continue;
            }
            let s = f.stress[k].unwrap_or_else(|e| panic!("({x}, {y}): {e:?}"));
            let d = disk_point_loads(1.0, p, x, y);
            let e = (s[0] - d.xx).abs().max((s[1] - d.yy).abs()).max((s[2] - d.xy).abs()) / scale;
            if y < 0.0 {
                lo = lo.max(e);
            } else {
                up = up.max(e);
            }
        }
        let centre = f.stress[12 * 25 + 12].unwrap();
        eprintln!(
            "clamp {top}°: centre σ = [{:.4}, {:.4}] × P/(πR) (point loads: [1, −3]); max |Δσ| / (3P/πR): lower half {lo:.2e}, upper half {up:.2e}",
            centre[0] * std::f64::consts::PI / p,
            centre[1] * std::f64::consts::PI / p
        );
        assert!(lo <= 2e-3, "lower half {lo}");
        upper.push(up);
    }
    assert!(upper[1] <= 0.6 * upper[0] && upper[1] <= 1e-2, "upper half {upper:?}");
}

/// The steel wheel of [`small_contact`] at a/R = 0.0025 (BEM, hub, constant elements, 50 across) with the
/// `[stresses]` table `stresses` (empty: none).
fn bem_scene_text(stresses: &str) -> String {
    let a = 0.0025 * R;
    let p = Hertz2D::from_half_width(a, R, estar()).load;
    format!(
        r#"
name = "stress-input"
[wheel]
radius = {R}
youngs_modulus = {E}
poisson_ratio = {NU}
support = {{ kind = "hub", radius = 100.0 }}
[mesh]
element = "constant"
contact_half_width = {hw}
contact_elements = 50
other_elements = 120
[drive]
normal_load = {p}
[solvers]
use = ["lemke"]
{stresses}
"#,
        hw = 1.25 * a
    )
}

const GOOD_STRESSES: &str = "[stresses]\nx = [-1.0, 1.0]\ndepth = [0.5, 3.0]\npoints = [5, 4]";

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rollbem"))
}

/// `rollbem run SCENE --json OUT` in a fresh folder: (exit code, stderr, the folder's files other than the scene,
/// the folder).
fn run_cli(text: &str) -> (Option<i32>, String, Vec<PathBuf>, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let out = bin().arg("run").arg(&scene).arg("--json").arg(dir.path().join("out.json")).output().unwrap();
    let files = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().is_some_and(|n| n != "scene.toml"))
        .collect();
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned(), files, dir)
}

#[test]
fn bad_stresses_tables_are_refused_naming_the_field_exit_2_nothing_written() {
    // Reference: the input contract of the command line (tests/cli.rs, DESIGN.md): bad input exits with code 2, the
    // error names the file and the dotted key, and no output file is written.
    let good = GOOD_STRESSES;
    let r = |from: &str, to: &str| {
        assert!(good.contains(from), "{from}");
        bem_scene_text(&good.replacen(from, to, 1))
    };
    let cases = [
        ("negative depth", r("depth = [0.5, 3.0]", "depth = [-0.5, 3.0]"), "stresses.depth"),
        ("empty depth range", r("depth = [0.5, 3.0]", "depth = [3.0, 0.5]"), "stresses.depth"),
        ("zero points", r("points = [5, 4]", "points = [0, 4]"), "stresses.points"),
        ("one point", r("points = [5, 4]", "points = [5, 1]"), "stresses.points"),
        ("too many points", r("points = [5, 4]", "points = [2000, 1000]"), "stresses.points"),
        ("unknown quantity", r("points = [5, 4]", "points = [5, 4]\nquantities = [\"tresca\"]"), "stresses.quantities"),
        ("no quantity", r("points = [5, 4]", "points = [5, 4]\nquantities = []"), "stresses.quantities"),
        ("x outside the wheel", r("x = [-1.0, 1.0]", "x = [-500.0, 1.0]"), "stresses.x"),
        ("NaN x", r("x = [-1.0, 1.0]", "x = [nan, 1.0]"), "stresses.x"),
        ("unknown key", r("points = [5, 4]", "points = [5, 4]\nspacing = 0.1"), "spacing"),
        // Contact elements are 2.5a/50 = 0.05a long and points within 2.5 lengths (0.125a) are refused: a grid
        // from the surface down, and one whose shallowest row is 0.1a deep (checked before anything is solved).
        ("grid from the surface (BEM)", r("depth = [0.5, 3.0]", "depth = [0.0, 3.0]"), "stresses.depth"),
        ("grid too shallow (BEM)", r("depth = [0.5, 3.0]", "depth = [0.115, 3.0]"), "stresses.depth"),
        // The hub's hole: depth R ± 100 mm.
        ("grid in the hub's hole (BEM)", r("depth = [0.5, 3.0]", "depth = [455.0, 465.0]"), "stresses.depth"),
    ];
    for (what, text, needle) in cases {
        let (code, stderr, files, _dir) = run_cli(&text);
        eprintln!("{what}: {}", stderr.trim());
        assert_eq!(code, Some(2), "{what}: exit {code:?}, stderr {stderr}");
        assert!(stderr.contains(needle), "{what}: error does not name `{needle}`: {stderr}");
        assert!(stderr.contains("scene.toml"), "{what}: error does not name the file: {stderr}");
        assert!(files.is_empty(), "{what}: output written: {files:?}");
        assert!(!stderr.to_lowercase().contains("nan ") && !stderr.contains("panicked"), "{what}: {stderr}");
    }
    // The good table runs, and every point has a finite value (no null, no NaN).
    let (code, stderr, files, _dir) = run_cli(&bem_scene_text(good));
    assert_eq!(code, Some(0), "{stderr}");
    let json = files.iter().find(|f| f.extension().is_some_and(|e| e == "json")).expect("the document");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap();
    let st = &doc["runs"][0]["stresses"];
    assert_eq!(st["refused"], serde_json::json!({}));
    for (name, values) in st["field"]["values"].as_object().unwrap() {
        let values = values.as_array().unwrap();
        assert_eq!(values.len(), 20, "{name}");
        assert!(values.iter().all(|v| v.as_f64().is_some_and(f64::is_finite)), "{name}: {values:?}");
    }
    assert!(st["maxima"]["principal_shear"]["value"].as_f64().unwrap() > 0.0);
}

#[test]
fn a_scene_without_stresses_computes_none() {
    // Reference: the effects rule (DESIGN.md: simulate only the effects a scene calls for). The same BEM scene with
    // and without [stresses]: without it, "stresses" is not among the effects, no run carries a field (the result
    // document has no `stresses` key), and the source does not keep the boundary response the evaluation needs
    // (no memory held for it); with it, all three are there.
    use rollbem::pipeline::stages::blocks_for;
    for (with, text) in [(false, bem_scene_text("")), (true, bem_scene_text(GOOD_STRESSES))] {
        let s = scene(&text);
        let r = run(&s);
        assert_eq!(r.effects.iter().any(|e| e == "stresses"), with, "{:?}", r.effects);
        assert!(r.runs.iter().all(|x| x.stresses.is_some() == with));
        let doc = serde_json::to_value(&r).unwrap();
        assert_eq!(doc["runs"][0].get("stresses").is_some(), with);
        let built = rollbem::source::build(&s, blocks_for(&s)).unwrap();
        assert_eq!(built.boundary.is_some(), with);
    }
    // The same for the half-plane model (no boundary response there at all) and a load path.
    let hp = |grid: &str| {
        let text = format!(
            "name = \"hp\"\n[wheel]\nradius = {R}\nyoungs_modulus = {E}\npoisson_ratio = {NU}\nmodel = \"half_plane\"\n\
             [mesh]\nelement = \"constant\"\ncontact_half_width = 9.0\ncontact_elements = 60\n[contact]\nfriction = 0.3\n\
             [[steps]]\nnormal_load = {P}\n[[steps]]\nnormal_load = {P}\ntangential_load = {}\n[solvers]\n\
             use = [\"lemke\"]\n{grid}",
            0.1 * P
        );
        run(&scene(&text))
    };
    let without = hp("");
    assert!(!without.effects.iter().any(|e| e == "stresses"));
    assert!(without.runs.iter().chain(without.steps.iter().flat_map(|s| s.runs.iter())).all(|x| x.stresses.is_none()));
    let with = hp(GOOD_STRESSES);
    assert!(with.runs.iter().chain(with.steps.iter().flat_map(|s| s.runs.iter())).all(|x| x.stresses.is_some()));
}

#[test]
fn large_field_goes_to_csv_and_plot_draws_every_quantity() {
    // Reference: the output contract of the issue (maxima per quantity as {value, x, depth} in the document; a
    // large field in a CSV file beside it; a contour map per quantity from `rollbem plot`). The maxima in the
    // document are checked against the CSV's own columns (an independent reduction of the written field), and
    // the principal shear's against McEwen's 0.300 p0 at 0.786a within the grid's resolution (steps 0.015a in x,
    // 0.03a in depth: τ₁ is flat at its maximum, within 0.2 % of 0.3 p0 for |Δz| ≤ 0.03a).
    let h = hertz(P, R);
    let g = grid(h.a, [-1.5, 1.5], [0.0, 3.0], [201, 101]);
    let text = half_plane_text(120, "", &format!("normal_load = {P}"), &g);
    let dir = tempfile::tempdir().unwrap();
    let scene_file = dir.path().join("big.toml");
    std::fs::write(&scene_file, text).unwrap();
    let json = dir.path().join("big.json");
    let out = bin().arg("run").arg(&scene_file).arg("--json").arg(&json).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("stresses in the wheel"), "no run-table lines: {stdout}");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let st = &doc["runs"][0]["stresses"];
    assert!(st["field"].is_null(), "a 20 301-point field is not inline");
    let csv_name = st["csv"].as_str().expect("the CSV file is named");
    let csv = std::fs::read_to_string(dir.path().join(csv_name)).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 201 * 101);
    for q in rollbem::scene::StressQuantity::ALL {
        let col = header.iter().position(|&c| c == q.name()).unwrap_or_else(|| panic!("no column {}", q.name()));
        let (mut best, mut at) = (0.0f64, (0.0, 0.0));
        for r in &rows {
            if let Ok(v) = r[col].parse::<f64>() {
                if v.abs() > best.abs() {
                    best = v;
                    at = (r[0].parse::<f64>().unwrap(), r[1].parse::<f64>().unwrap());
                }
            }
        }
        let m = &st["maxima"][q.name()];
        let (v, x, z) = (m["value"].as_f64().unwrap(), m["x"].as_f64().unwrap(), m["depth"].as_f64().unwrap());
        assert!(
            (v - best).abs() <= 1e-12 * best.abs() && (x - at.0).abs() <= 1e-9 && (z - at.1).abs() <= 1e-9,
            "{q:?}"
        );
    }
    let t1 = &st["maxima"]["principal_shear"];
    let (v, z) = (t1["value"].as_f64().unwrap() / h.p0, t1["depth"].as_f64().unwrap() / h.a);
    eprintln!("CSV field: max τ₁ = {v:.5} p0 at depth {z:.4} a");
    assert!((v / 0.3 - 1.0).abs() <= 0.003 && (z - 0.786).abs() <= 0.03, "{v}, {z}");
    // rollbem plot: the tractions and one contour map per quantity, from the CSV.
    let out = bin().arg("plot").arg(&json).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for q in rollbem::scene::StressQuantity::ALL {
        let svg = dir.path().join(format!("big.lemke.{}.svg", q.name()));
        let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{}: {e}", svg.display()));
        assert!(text.starts_with("<svg") || text.contains("<svg"), "{}", svg.display());
    }
    assert!(dir.path().join("big.lemke.tractions.svg").exists());
}

#[test]
fn near_boundary_reach_is_where_the_bem_field_goes_wrong() {
    // Reference: McEwen's field (theory::mcewen_normal at Hertz's a, p0), the BEM wheel of
    // finite_wheel_field_agrees_with_the_half_plane_at_small_a_over_r (a/R = 0.0025, 100 elements across). The grids
    // of [stresses] refuse points closer to the boundary than STRESS_NEAR_BOUNDARY_CONSTANT (2.5) or _QUADRATIC
    // (0.5) element lengths; here the Somigliana identity is evaluated directly (rollbem::bem::stress, below the
    // refusal) at depths of k element lengths across two elements' width at several x, to show what the refusal
    // protects against: at and beyond the reach the error stays within the 1 % of p0 asked of the wheel's field
    // (measured: constant 0.45 % at 2.5 lengths, quadratic 0.86 % at 0.5; about 0.4 % of it is the finite wheel's
    // difference from the half-plane), inside it it does not (constant 19 % at 0.5 lengths and 2.2 % at 1;
    // quadratic 5.3 % at 0.1 and 2.7 % at 0.2). Values are finite everywhere (the quadrature is accurate up to the
    // boundary: it is the boundary data, not the integration, that spoils the field).
    use rollbem::bem::stress::InteriorStress;
    use rollbem::tolerances::{STRESS_NEAR_BOUNDARY_CONSTANT, STRESS_NEAR_BOUNDARY_QUADRATIC};
    let ar = 0.0025;
    for (element, n, reach) in
        [("constant", 125usize, STRESS_NEAR_BOUNDARY_CONSTANT), ("quadratic", 42, STRESS_NEAR_BOUNDARY_QUADRATIC)]
    {
        let (s, h) = small_contact("bem", element, n, ar);
        let r = run(&s);
        let nodes = &lemke(&r).nodes;
        let built = rollbem::source::build(&s, rollbem::pipeline::stages::blocks_for(&s)).unwrap();
        let response = built.boundary.as_ref().unwrap();
        let (l0, e) = (built.flex.scales.length, E);
        let p: Vec<f64> = nodes.iter().map(|n| n.pressure / e).collect();
        let q: Vec<f64> = nodes.iter().map(|n| n.shear / e).collect();
        let (u, t) = response.boundary(&p, &q).unwrap();
        let ev = InteriorStress::new(&response.model.mesh, &response.model.kelvin, &u, &t).unwrap();
        let len = 2.5 * h.a / n as f64;
        let error_at = |k: f64| {
            // 21 points across two elements' width (element edges and centres included) around x = 0, 0.5a,
            // 0.9a, a (the contact edge, where p has infinite slope) and 1.1a.
            let mut worst = 0.0f64;
            let xs = [0.0, 0.5, 0.9, 1.0, 1.1]
                .into_iter()
                .flat_map(|c| (0..=20).map(move |i| c * h.a + i as f64 * len / 10.0 - len));
            for x in xs {
                // Depth below the (curved) surface: z = k·len + x²/(2R).
                let z = k * len + x * x / (2.0 * R);
                let sv = ev.at([x / l0, (z - R) / l0]).unwrap();
                let m = mcewen_normal(&h, x, z);
                let d = (sv[0] * e - m.xx).abs().max((sv[1] * e - m.yy).abs()).max((sv[2] * e - m.xy).abs());
                worst = worst.max(d / h.p0);
            }
            worst
        };
        let ks = [0.2 * reach, 0.4 * reach, reach, 2.0 * reach];
        let errors: Vec<f64> = ks.iter().map(|&k| error_at(k)).collect();
        let shown: Vec<String> = errors.iter().map(|v| format!("{v:.2e}")).collect();
        eprintln!("{element}: max |Δσ|/p0 at {ks:?} element lengths below the surface: {shown:?}");
        assert!(errors[2] <= 0.01 && errors[3] <= 0.01, "{element}: beyond the reach {errors:?}");
        assert!(errors[0] > 0.01, "{element}: inside the reach the refusal is not needed? {errors:?}");
    }
}

#[test]
fn half_plane_strip_edge_on_the_surface_under_shear_is_refused_not_nan() {
    // Reference: the closed form of a uniform shear strip (Johnson §2.6, eq. 2.28): on the surface σ_xx =
    // (2q/π) ln|(x − b)/(x − a)|, infinite at the strip's edges. A grid node exactly on a loaded strip's edge on the
    // surface therefore has no value: it is refused by name (`singular`, null in the document), never NaN or ∞;
    // one row below (z > 0) every node has a finite value.
    let h = hertz(P, R);
    let (mu, n) = (0.3, 120);
    let contact = format!("friction = {mu}\ncoupling = false");
    let drive = format!("normal_load = {P}\ntangential_load = {}", mu * P);
    // Strip edges at −9 + 0.15j mm: x = −0.15, 0, 0.15 are edges of loaded strips, equal to the grid's nodes only up
    // to round-off (the strips are laid out in the wheel's dimensionless units), which must not give a value either.
    let s =
        half_plane(n, &contact, &drive, &format!("x = [-0.15, 0.15]\ndepth = [0.0, {}]\npoints = [3, 2]", 0.01 * h.a));
    let r = run(&s);
    let st = stresses(&r);
    let doc = serde_json::to_value(st).unwrap();
    eprintln!("refused: {}; surface row: {:?}", doc["refused"], &st.field.stress[..3]);
    for k in 0..6 {
        let v = st.field.stress[k];
        if k < 3 {
            assert_eq!(v, Err(rollbem::stresses::PointError::Singular), "surface node {k}: {v:?}");
            assert!(doc["field"]["values"]["sxx"][k].is_null());
            assert_eq!(doc["field"]["error"][k], "singular");
        } else {
            assert!(v.is_ok_and(|s| s.iter().all(|c| c.is_finite())), "node {k}: {v:?}");
        }
    }
    assert_eq!(doc["refused"], serde_json::json!({"singular": 3}));
}

/// Issue 19: with μ = 0.4 in full slip the maximum principal shear is μ p0 on the surface (McEwen / Smith & Liu:
/// τ₁ = μp0 at every surface point of the contact for μ ≥ 1/√7). A grid whose surface row falls on the strips'
/// edges (where σ_xx of a piecewise-uniform shear is singular and the points are refused) used to report the
/// subsurface 0.392 p0; the surface values at the elements' centres put the maximum back at the surface.
#[test]
fn full_slip_maximum_principal_shear_is_on_the_surface_whatever_the_grid() {
    use rollbem::stresses::StressQuantity::PrincipalShear;
    let mu = 0.4;
    let h = hertz(P, R);
    let contact = format!("friction = {mu}\ncoupling = false");
    let drive = format!("normal_load = {P}\ntangential_load = {}", mu * P);
    // 120 strips on |x| ≤ 9 mm: edges every 0.15 mm from −9; a grid of 121 nodes on [−9, 9] sits on every edge.
    let grid = format!("x = [-9.0, 9.0]\ndepth = [0.0, {}]\npoints = [121, 61]", 1.5 * h.a);
    let r = run(&half_plane(120, &contact, &drive, &grid));
    let st = stresses(&r);
    assert!(st.refused()["singular"] > 0, "the grid's surface row is on the strips' edges: refused there");
    let m = st.maximum_of(PrincipalShear).expect("a maximum");
    assert_eq!(m.depth, 0.0, "the maximum is on the surface: {m:?}");
    assert!((m.value / (mu * h.p0) - 1.0).abs() <= 0.01, "max τ₁ = {} p0, μ = {mu}", m.value / h.p0);
}

/// The elastic counter-body's field is reported beside the wheel's. Two identical steel half-planes, frictionless:
/// the rail carries the same pressure, so its field is the wheel's (McEwen: max τ₁ = 0.300 p0 at depth 0.786a,
/// Johnson §4.2, with a and p0 of the pair); with friction the shear flips sign with the body, so the rail's τ_xz
/// field is the mirror image of the wheel's (τ_xz(x) of the rail = −τ_xz(x) of the wheel's q → −q problem).
#[test]
fn the_elastic_rail_gets_its_own_field() {
    use rollbem::stresses::StressQuantity::{PrincipalShear, Szz};
    let text = half_plane_text(
        160,
        "friction = 0.0",
        &format!("normal_load = {P}"),
        "x = [-12.0, 12.0]\ndepth = [0.0, 20.0]\npoints = [81, 201]",
    )
    .replace("contact_half_width = 9.0", "contact_half_width = 12.0")
    .replace("[mesh]", "[counter_body]\nkind = \"half_plane\"\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n[mesh]");
    let r = run(&scene(&text));
    let l = lemke(&r);
    let (wheel, rail) = (l.stresses.as_ref().unwrap(), l.counter_body_stresses.as_ref().expect("the rail's field"));
    assert_eq!((wheel.body.as_str(), rail.body.as_str()), ("wheel", "counter_body"));
    // The pair's Hertz: E* = E/(2(1 − ν²)).
    let h = Hertz2D::from_load(P, R, estar() / 2.0);
    for st in [wheel, rail] {
        let t1 = st.maximum_of(PrincipalShear).unwrap();
        assert!((t1.value / h.p0 - 0.300).abs() <= 0.003, "{}: max τ₁ {} p0", st.body, t1.value / h.p0);
        assert!((t1.depth / h.a - 0.786).abs() <= 0.02, "{}: at depth {} a", st.body, t1.depth / h.a);
        let szz = st.maximum_of(Szz).unwrap();
        assert!((szz.value / h.p0 + 1.0).abs() <= 0.01 && szz.depth == 0.0, "{}: σ_zz {szz:?}", st.body);
    }
}
