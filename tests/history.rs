//! Load paths with memory (`[[steps]]`), checked against analytic theory derived independently of the solver
//! (`rollbem::theory`, REFERENCES.md): Spence's stick zone under a growing normal load with coupling,
//! Mindlin–Deresiewicz's loop under a cycled tangential load, path independence where theory says the path does not
//! matter, and transient rolling from rest settling on the steady-rolling solution of the same mesh.

#[path = "common/paired.rs"]
mod paired;
use paired::paired;
use rollbem::pipeline::run_scene;
use rollbem::post::stick_edges;
use rollbem::post::NodeState;
use rollbem::results::{Report, SolverRun};
use rollbem::scene::Scene;
use rollbem::solvers::Status;
use rollbem::theory::{self, Hertz2D, TangentialPath};
use std::path::Path;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("<test>")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn run(s: &Scene) -> Report {
    run_scene(s).unwrap()
}

fn get<'a>(runs: &'a [SolverRun], solver: &str) -> &'a SolverRun {
    runs.iter().find(|x| x.solver == solver).unwrap_or_else(|| panic!("no {solver} run"))
}

/// A half-plane wheel (R = 460 mm, E = 210 GPa, Hertz's parabola) on a rigid flat, `n` constant elements on
/// |x| ≤ 9 mm, with the given Poisson ratio, friction, coupling, path and solvers.
fn path_scene(nu: f64, mu: f64, coupling: bool, n: usize, body: &str, solvers: &str) -> Scene {
    scene(&format!(
        r#"
name = "path"
[wheel]
radius = 460.0
youngs_modulus = 210000.0
poisson_ratio = {nu}
model = "half_plane"
profile = "parabola"
[mesh]
element = "constant"
contact_half_width = 9.0
contact_elements = {n}
[contact]
friction = {mu}
coupling = {coupling}
{body}
[solvers]
use = {solvers}
"#
    ))
}

/// Hertz of a run (its own normal resultant, the scene's E*).
fn hertz(s: &Scene, r: &SolverRun) -> Hertz2D {
    Hertz2D::from_load(r.resultants.unwrap().normal, s.document().wheel.radius, s.contact_modulus())
}

/// Half-width of the stick zone (midway between the last sticking node and its neighbour), centred.
fn stick_half_width(r: &SolverRun) -> f64 {
    let (l, rr) = stick_edges(&r.nodes).expect("a stick zone");
    0.5 * (rr - l)
}

/// β/μ = 0.5, 1, 2 with β ≈ 0.1 (ν = 0.444 on a rigid flat: β = (1 − 2ν)/(2(1 − ν))).
#[test]
fn spence_stick_zone_under_growing_normal_load() {
    // Reference: Spence (1975), c/a the root of K(k')/K(k) = |β|/μ (theory::spence_c_over_a, checked in the unit
    // tests against K(1/√2) symmetry and the nome series). The load grows from 0 to P in 40 steps; the slip zones
    // at the edges are where material drawn into the growing contact slid. Spence assumes the Hertz pressure: at
    // β = 0.1 the coupling changes p by O(β μ) ≈ 1 %, inside the tolerance of 0.03 on c/a (≈ 2 elements at a/h = 74).
    let nu = 0.444;
    let beta = theory::dundurs_beta(210000.0, nu, f64::INFINITY, 0.0);
    assert!((beta - 0.1007).abs() < 1e-3, "β = {beta}");
    // Small β/μ = 0.1: Spence's slip zones are e^(−π μ/β)-thin (c/a = 1 − 1e-13): every contact node sticks.
    let body = "[[steps]]\nnormal_load = 20000.0\nsubsteps = 40";
    let s = path_scene(nu, beta / 0.1, true, 200, body, r#"["lemke"]"#);
    let l = get(&run(&s).steps.last().unwrap().runs, "lemke").clone();
    assert_eq!(l.status, Status::Solved, "{}", l.explanation());
    assert!(theory::spence_c_over_a(0.1) > 1.0 - 1e-9);
    assert!(l.nodes.iter().all(|n| n.state != NodeState::Slip), "full stick at β/μ = 0.1");
    for ratio in [0.5, 1.0, 2.0] {
        let mu = beta / ratio;
        let body = "[[steps]]\nnormal_load = 20000.0\nsubsteps = 40";
        let s = path_scene(nu, mu, true, 200, body, r#"["lemke", "active_set"]"#);
        let rep = run(&s);
        let last = &rep.steps.last().unwrap().runs;
        let l = get(last, "lemke");
        assert_eq!(l.status, Status::Solved, "{}", l.explanation());
        let h = hertz(&s, l);
        let c = stick_half_width(l) / h.a;
        let exact = theory::spence_c_over_a(ratio);
        eprintln!("β/μ = {ratio}: c/a = {c:.4}, Spence {exact:.4}");
        assert!((c - exact).abs() < 0.03, "β/μ = {ratio}: c/a = {c}, Spence {exact}");
        // Symmetric problem: the two slip zones carry opposite, equal shear, so Q = 0 (held at zero shift).
        let q = l.resultants.unwrap().tangential;
        assert!(q.abs() < 1e-9 * 20000.0, "Q = {q}");
        // The peer on the same path agrees node by node.
        let a = get(last, "active_set");
        assert_eq!(a.status, Status::Solved, "{}", a.message);
        for (x, y) in paired(&l.nodes, &a.nodes) {
            assert_eq!(x.state, y.state, "state at x = {}", x.x);
            assert!((x.shear - y.shear).abs() < 1e-8 * h.p0);
        }
    }
}

#[test]
fn spence_needs_the_path_a_single_step_misses_it() {
    // The same final load in one step from rest is a different problem (the slip is the total displacement): its
    // stick zone differs from Spence's by more than the 40-step path's error. This is what memory buys.
    let nu = 0.444;
    let beta = theory::dundurs_beta(210000.0, nu, f64::INFINITY, 0.0);
    let mu = beta; // β/μ = 1: Spence c/a = 1/√2.
    let exact = theory::spence_c_over_a(1.0);
    let mut errs = Vec::new();
    for m in [1, 40] {
        let body = format!("[[steps]]\nnormal_load = 20000.0\nsubsteps = {m}");
        let s = path_scene(nu, mu, true, 200, &body, r#"["lemke"]"#);
        let rep = run(&s);
        let l = get(&rep.steps.last().unwrap().runs, "lemke");
        assert_eq!(l.status, Status::Solved, "{}", l.explanation());
        let c = stick_half_width(l) / hertz(&s, l).a;
        errs.push((c - exact).abs());
        eprintln!("{m} step(s): c/a = {c:.4} (Spence {exact:.4})");
    }
    assert!(errs[0] > 3.0 * errs[1] && errs[0] > 0.05, "one step {} vs path {}", errs[0], errs[1]);
}

#[test]
fn spence_outside_the_goodman_approximation_matches_the_coupled_reference() {
    // Steel on a rigid flat: β = 0.2857, μ = 0.3 (βμ = 0.086), the shipped scene spence-steel-rigid. Expected: the
    // coupled numerical reference theory::spence_coupled_c_over_a (an incremental active-set solver on its own
    // half grid, independent of the BEM and LCP pipeline, checked in its unit tests against an earlier independent
    // Python computation), c/a = stick half-width over contact half-width, to the two resolutions (reference: 2
    // of its elements; rollbem: one element over the contact half-width). Spence's closed form (the Goodman
    // approximation, 0.744) is outside its range here: the computed c/a differs from it by more than 0.04.
    let s =
        Scene::from_file(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/reference/scenes/spence-steel-rigid.toml")))
            .unwrap();
    let beta = s.dundurs_beta();
    assert!((beta - 0.4 / 1.4).abs() < 1e-12, "β = {beta}");
    let rep = run(&s);
    let l = get(&rep.steps.last().unwrap().runs, "lemke");
    assert_eq!(l.status, Status::Solved, "{}", l.explanation());
    let h = s.zone().element_length(s.document().wheel.radius);
    let contact = l.contact.as_ref().unwrap().half_width.unwrap() + 0.5 * h;
    let c = stick_half_width(l) / contact;
    let reference = theory::spence_coupled_c_over_a(beta, 0.3, 250);
    let closed = theory::spence_c_over_a(beta / 0.3);
    eprintln!("c/a = {c:.4}, coupled reference {:.4}, closed form {closed:.4}", reference.c_over_a);
    assert!((c - reference.c_over_a).abs() <= 2.0 * reference.resolution + h / contact, "{c} vs {reference:?}");
    assert!((c - closed).abs() > 0.04, "{c} vs closed form {closed}");
    // The report says which one is the check.
    let dir = tempfile::tempdir().unwrap();
    let mut md = String::new();
    let mut figs = rollbem::report::Figs::new(dir.path(), "");
    rollbem::report::path_figures("spence-steel-rigid", &rep, &mut md, &mut figs).unwrap();
    assert!(md.contains("Goodman approximation") && md.contains("outside its range here"), "{md}");
    // At βμ = 0.01 (spence-indentation) the closed form's departure from the coupled reference (about 0.01 in c/a)
    // is below what the comparison resolves: there it is the check.
    let s =
        Scene::from_file(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/reference/scenes/spence-indentation.toml")))
            .unwrap();
    let rep = run(&s);
    let mut md = String::new();
    rollbem::report::path_figures("spence-indentation", &rep, &mut md, &mut figs).unwrap();
    assert!(md.contains("within its range here"), "{md}");
}

/// The Mindlin–Deresiewicz path: P, then Q to +Q*, down to −Q*, back to +Q* (substeps m per branch).
fn md_scene(n: usize, q_star: f64, m: usize, solvers: &str) -> Scene {
    let body = format!(
        "[[steps]]\nnormal_load = 20000.0\n\
         [[steps]]\nnormal_load = 20000.0\ntangential_load = {q_star}\nsubsteps = {m}\n\
         [[steps]]\nnormal_load = 20000.0\ntangential_load = {}\nsubsteps = {}\n\
         [[steps]]\nnormal_load = 20000.0\ntangential_load = {q_star}\nsubsteps = {}",
        -q_star,
        2 * m,
        2 * m
    );
    path_scene(0.3, 0.3, false, n, &body, solvers)
}

#[test]
fn mindlin_deresiewicz_loop() {
    // Reference: Mindlin–Deresiewicz in 2D (theory::md_traction, md_stick_half_width, md_cycle_dissipation; derived
    // by superposing Cattaneo solutions, REFERENCES.md). Steel wheel as a half-plane, β = 0 (coupling off), μ = 0.3,
    // P = 20 kN/mm (μP = 6 kN/mm), Q* = 3 kN/mm; 200 elements on |x| ≤ 9 mm (a = 7.12 mm: 158 across).
    let (n, q_star, m) = (200, 3000.0, 10);
    let s = md_scene(n, q_star, m, r#"["lemke", "active_set"]"#);
    let rep = run(&s);
    let hx = 18.0 / n as f64;
    let mu = 0.3;
    let runs_at = |step: usize, sub: usize| {
        &rep.steps.iter().find(|r| r.step == step && r.substep == sub).unwrap_or_else(|| panic!("{step}/{sub}")).runs
    };
    for solver in ["lemke", "active_set"] {
        // Every substep is solved.
        for st in &rep.steps {
            let r = get(&st.runs, solver);
            assert_eq!(r.status, Status::Solved, "{solver} step {}/{}: {}", st.step, st.substep, r.message);
        }
        // (branch, step, substep) checkpoints: loading at Q*/2 and Q*; unloading at Q*/2, 0, −Q*/2, −Q*; reloading
        // at 0 and Q*.
        let checkpoints = [
            (TangentialPath::Loading, 1, m / 2),
            (TangentialPath::Loading, 1, m),
            (TangentialPath::Unloading { q_star }, 2, m / 2),
            (TangentialPath::Unloading { q_star }, 2, m),
            (TangentialPath::Unloading { q_star }, 2, 3 * m / 2),
            (TangentialPath::Unloading { q_star }, 2, 2 * m),
            (TangentialPath::Reloading { q_star }, 3, m),
            (TangentialPath::Reloading { q_star }, 3, 2 * m),
        ];
        for (branch, step, sub) in checkpoints {
            let r = get(runs_at(step, sub), solver);
            let h = hertz(&s, r);
            let q = r.resultants.unwrap().tangential;
            // The stick zone of the current branch (no slip increment in this substep) within one element.
            let c = theory::md_stick_half_width(&h, mu, branch, q);
            let c_num = stick_half_width(r);
            assert!((c_num - c).abs() <= hx, "{solver} {branch:?} Q = {q}: c = {c_num}, theory {c}");
            // The traction against theory: RMS within 1 % of μp0 over the contact, largest within 6 % (the
            // square-root corners at the stick edges are resolved to O(√h)).
            let errs: Vec<f64> = r
                .nodes
                .iter()
                .filter(|nd| nd.x.abs() < h.a)
                .map(|nd| (nd.shear - theory::md_traction(&h, mu, branch, q, nd.x)) / (mu * h.p0))
                .collect();
            let rms = (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt();
            let max = errs.iter().fold(0.0f64, |m, e| m.max(e.abs()));
            eprintln!("{solver} {branch:?} Q = {q:.1}: c {c_num:.4} vs {c:.4}, traction RMS {rms:.2e} max {max:.2e}");
            assert!(rms < 0.01 && max < 0.06, "{solver} {branch:?} Q = {q}: RMS {rms} max {max}");
            // The wheel's tangential shift (the hysteresis loop's abscissa) against theory. The half-plane's datum
            // is the material point at depth D (halfplane.rs): a surface line load Q displaces the surface by
            // −(2Q/(πE*))(ln(|x|/D) − 1/(2(1 − ν))), which is theory's log datum (u = −(2Q/(πE*)) ln(|x|/D'))
            // with D' = D e^(1/(2(1 − ν))). The shift is the wheel's; theory's δ is the counter-body's: opposite.
            let datum = s.document().wheel.datum_depth.unwrap_or(s.radius());
            let d_prime = datum * (0.5 / (1.0 - s.document().wheel.poisson_ratio)).exp();
            let delta = -theory::md_displacement(&h, mu, s.contact_modulus(), d_prime, branch, q);
            let delta_star =
                -theory::md_displacement(&h, mu, s.contact_modulus(), d_prime, TangentialPath::Loading, q_star);
            let shift = r.rigid_body.unwrap().tangential.unwrap();
            eprintln!("    shift {shift:.6e} vs theory {delta:.6e} ({:.1e} of δ*)", (shift - delta) / delta_star);
            assert!((shift - delta).abs() < 1e-4 * delta_star.abs(), "{solver} {branch:?} Q = {q}: {shift} vs {delta}");
        }
        // The loop closes: back at +Q* the tractions are those of the first loading to +Q* (node by node, to the
        // solver's precision: the discrete problem has the same superposition structure as the continuum).
        let first = get(runs_at(1, m), solver);
        let back = get(runs_at(3, 2 * m), solver);
        assert_eq!((first.status, back.status), (Status::Solved, Status::Solved), "{solver}: the loop's ends");
        let p0 = hertz(&s, first).p0;
        for (x, y) in paired(&first.nodes, &back.nodes) {
            assert!((x.shear - y.shear).abs() < 1e-8 * p0, "{solver} x = {}: {} vs {}", x.x, x.shear, y.shear);
            assert!((x.pressure - y.pressure).abs() < 1e-8 * p0);
        }
        // Energy dissipated in the closed cycle +Q* → −Q* → +Q* (steps 2 and 3) against W = (2μ²P²/(πE*))[1 − γ² +
        // 2γ ln γ], γ = 1 − Q*/(μP). Σ −h Δs with the step's end forces is exact for a node slipping throughout a
        // substep at constant p (h = μp while it slips); what remains is the mesh's resolution of the slip zone.
        let w: f64 = rep
            .steps
            .iter()
            .filter(|st| st.step >= 2)
            .map(|st| get(&st.runs, solver).history.as_ref().unwrap().dissipated)
            .sum();
        let p = first.resultants.unwrap().normal;
        let w_exact = theory::md_cycle_dissipation(mu, p, s.contact_modulus(), q_star);
        eprintln!("{solver}: cycle dissipation {w:.6e} vs theory {w_exact:.6e} ({:+.2e})", w / w_exact - 1.0);
        // At 158 elements across the error is expected well below 0.2 % (md_dissipation_converges_with_the_mesh).
        assert!((w / w_exact - 1.0).abs() < 2e-3, "{solver}: W = {w}, theory {w_exact}");
        // No energy is dissipated on the way back to Q = 0 at a node that sticks, and none at all is created.
        for st in &rep.steps {
            let e = get(&st.runs, solver).history.as_ref().unwrap().dissipated;
            assert!(e >= -1e-12 * w_exact, "{solver} step {}/{}: {e}", st.step, st.substep);
        }
    }
}

#[test]
fn md_dissipation_converges_with_the_mesh() {
    // The cycle's dissipation against theory on three meshes: the error falls as the mesh is refined (the slip
    // zones' edges are resolved to one element). Reference: theory::md_cycle_dissipation.
    let q_star = 3000.0;
    let mut errs = Vec::new();
    for n in [50, 100, 200] {
        let s = md_scene(n, q_star, 4, r#"["lemke"]"#);
        let rep = run(&s);
        let w: f64 = rep
            .steps
            .iter()
            .filter(|st| st.step >= 2)
            .map(|st| get(&st.runs, "lemke").history.as_ref().unwrap().dissipated)
            .sum();
        let p = get(&rep.steps[0].runs, "lemke").resultants.unwrap().normal;
        let exact = theory::md_cycle_dissipation(0.3, p, s.contact_modulus(), q_star);
        errs.push((w / exact - 1.0).abs());
    }
    eprintln!("dissipation relative errors at 50/100/200 elements: {errs:?}");
    assert!(errs[2] < errs[1] && errs[1] < errs[0], "{errs:?}");
    // Halving the element at least halves the error (first order in the slip-zone edge; measured: faster).
    assert!(errs[1] < 0.5 * errs[0] && errs[2] < 0.5 * errs[1], "{errs:?}");
}

#[test]
fn frictionless_path_is_the_one_step_solution() {
    // Without friction there is no memory: a normal load reached in 10 steps (with a tangential shift on the way,
    // which frictionless contact ignores) ends where the one-step [drive] scene does. Reference: the peer
    // computation (the static solver) on the same mesh.
    let path = "[[steps]]\nnormal_load = 10000.0\nsubsteps = 4\n\
                [[steps]]\nnormal_load = 20000.0\nsubsteps = 6";
    let one = "[drive]\nnormal_load = 20000.0";
    let a = run(&path_scene(0.3, 0.0, false, 100, path, r#"["lemke"]"#));
    let b = run(&path_scene(0.3, 0.0, false, 100, one, r#"["lemke"]"#));
    let (x, y) = (get(&a.steps.last().unwrap().runs, "lemke"), get(&b.runs, "lemke"));
    assert_eq!(a.steps.len(), 10);
    assert_eq!((x.status, y.status), (Status::Solved, Status::Solved), "{} / {}", x.message, y.message);
    let pmax = y.nodes.iter().fold(0.0f64, |m, n| m.max(n.pressure));
    for (u, v) in paired(&x.nodes, &y.nodes) {
        assert!((u.pressure - v.pressure).abs() < 1e-10 * pmax, "x = {}: {} vs {}", u.x, u.pressure, v.pressure);
        assert_eq!(u.state, v.state);
    }
}

#[test]
fn decoupled_normal_then_tangential_is_cattaneo_in_one_step() {
    // With β = 0 the pressure does not depend on the shear, and a monotone tangential load leaves nested slip zones:
    // P then Q in 8 steps ends on the one-step solution (Cattaneo). Reference: the one-step static solve of the
    // same mesh (a peer computation) and theory::cattaneo_traction.
    let path = "[[steps]]\nnormal_load = 20000.0\n\
                [[steps]]\nnormal_load = 20000.0\ntangential_load = 4000.0\nsubsteps = 8";
    let one = "[drive]\nnormal_load = 20000.0\ntangential_load = 4000.0";
    let a = run(&path_scene(0.3, 0.3, false, 200, path, r#"["lemke"]"#));
    let s1 = path_scene(0.3, 0.3, false, 200, one, r#"["lemke"]"#);
    let b = run(&s1);
    let (x, y) = (get(&a.steps.last().unwrap().runs, "lemke"), get(&b.runs, "lemke"));
    assert_eq!((x.status, y.status), (Status::Solved, Status::Solved), "{} / {}", x.message, y.message);
    let h = hertz(&s1, y);
    for (u, v) in paired(&x.nodes, &y.nodes) {
        assert!((u.shear - v.shear).abs() < 1e-8 * h.p0, "x = {}: {} vs {}", u.x, u.shear, v.shear);
        assert_eq!(u.state, v.state, "x = {}", u.x);
    }
    let rms = (y
        .nodes
        .iter()
        .filter(|n| n.x.abs() < h.a)
        .map(|n| ((n.shear - theory::cattaneo_traction(&h, 0.3, 4000.0, n.x)) / (0.3 * h.p0)).powi(2))
        .sum::<f64>()
        / y.nodes.iter().filter(|n| n.x.abs() < h.a).count() as f64)
        .sqrt();
    assert!(rms < 0.01, "Cattaneo RMS {rms}");
}

#[test]
fn rolling_from_rest_settles_on_steady_rolling() {
    // Rolling from rest: P and Q applied at rest (a Cattaneo state, stick zone centred), then rolled 60 mm (8.4
    // contact widths) one element per substep with Q held. The transient's fixed point is exactly the steady
    // operator's solution when the roll per substep is one element of the uniform grid (history.rs module docs:
    // Δs_i = h s_i^steady), so the end state must match the steady-rolling run of the same mesh to solver
    // precision once the start has been forgotten. Reference: the steady-rolling solver on the same mesh (peer
    // computation), itself checked against Carter in tests/rolling.rs.
    let n = 60;
    let q = -4107.561012825782;
    let transient = format!(
        "[rolling]\nmode = \"transient\"\ncreepage = 0.002\ndirection = 1\n\
         [[steps]]\nnormal_load = 20000.0\ntangential_load = {q}\n\
         [[steps]]\nnormal_load = 20000.0\ntangential_load = {q}\nroll = 60.0\nsubsteps = {}",
        200
    );
    assert_eq!(18.0 / n as f64, 60.0 / 200.0, "one element per substep");
    let steady =
        format!("[rolling]\nmode = \"steady\"\ndirection = 1\n[drive]\nnormal_load = 20000.0\ntangential_load = {q}");
    let a = run(&path_scene(0.3, 0.3, false, n, &transient, r#"["lemke"]"#));
    let sb = path_scene(0.3, 0.3, false, n, &steady, r#"["lemke"]"#);
    let b = run(&sb);
    let y = get(&b.runs, "lemke");
    assert_eq!(y.status, Status::Solved, "{}", y.message);
    let p0 = hertz(&sb, y).p0;
    // Distance from the steady state along the path: it decays (the start is forgotten) and ends below 1e-6 p0.
    let dist =
        |r: &SolverRun| paired(&r.nodes, &y.nodes).fold(0.0f64, |m, (u, v)| m.max((u.shear - v.shear).abs())) / p0;
    let along: Vec<f64> = a.steps.iter().map(|st| dist(get(&st.runs, "lemke"))).collect();
    eprintln!("distance to steady: start {:.2e}, 25 % {:.2e}, end {:.2e}", along[0], along[50], along[200]);
    assert!(along[0] > 0.05, "the rest state is not the rolling state: {}", along[0]);
    assert!(along[200] < 1e-6, "end {:e}", along[200]);
    let end = get(&a.steps.last().unwrap().runs, "lemke");
    // In steady rolling the stick zone sits at the leading edge; at rest it was centred.
    let start = get(&a.steps[0].runs, "lemke");
    let (l0, r0) = stick_edges(&start.nodes).unwrap();
    let (l1, r1) = stick_edges(&end.nodes).unwrap();
    assert!((l0 + r0).abs() < 1e-9, "centred at rest");
    assert!(0.5 * (l1 + r1) > 1.0, "leading edge (direction +x): stick zone [{l1}, {r1}]");
    assert!(end.nodes.iter().filter(|n| n.state == NodeState::Slip).count() > 0);
}

/// The transient under a creepage with the wheel centre held (shift 0 at the half-plane's datum depth `datum`),
/// rolled `roll` mm in `m` substeps of one element each (60 elements on |x| ≤ 9 mm: 0.3 mm).
fn creep_from_rest(datum: f64, roll: f64, m: usize) -> (Scene, Scene) {
    let datum_key = "[rolling]\ndirection = 1\ncreepage = 0.002\n";
    let wheel = |extra: &str| {
        scene(&format!(
            "name = \"creep\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
             model = \"half_plane\"\nprofile = \"parabola\"\ndatum_depth = {datum}\n[mesh]\nelement = \"constant\"\n\
             contact_half_width = 9.0\ncontact_elements = 60\n[contact]\nfriction = 0.3\ncoupling = false\n\
             {datum_key}{extra}\n[solvers]\nuse = [\"lemke\"]\n"
        ))
    };
    (
        wheel(&format!(
            "mode = \"transient\"\n[[steps]]\nnormal_load = 20000.0\n\
             [[steps]]\nnormal_load = 20000.0\nroll = {roll}\nsubsteps = {m}"
        )),
        wheel("mode = \"steady\"\n[drive]\nnormal_load = 20000.0"),
    )
}

#[test]
fn creepage_driven_rolling_from_rest_winds_up_to_steady_rolling() {
    // Rolling from rest at creepage ξ = 0.002 (below saturation μa/R = 4.65e-3) with the wheel centre held: the
    // tangential force builds up monotonically and the tractions reach the steady-rolling solution of the same mesh
    // (peer computation; creepage-driven steady rolling is checked against Carter in tests/rolling.rs).
    //
    // How fast. The held centre sits at the datum depth D; between it and the contact the half-plane's tangential
    // compliance λ = (2/(πE*))(ln(2D/a) + 1/2) is in series with the contact's rolling law ξ_C(Q) (Carter: ξ_C =
    // (μa/R)(1 − √(1 − Q/(μP)))). A first-order model, ξ − ξ_C(Q) = λ dQ/dx, linearised at the steady state gives an
    // exponential approach over the rolling distance L = λ / ξ_C'(Q) = c (ln(2D/a) + 1/2), c the steady stick
    // half-width: ≈ 21 mm (3 contact widths) at D = R = 460 mm, ≈ 9 mm at D = 20 mm. The datum is physics here:
    // a 2D half-plane has no tangential displacement without one. Measured decay lengths within 15 % of the model.
    let (mut lengths, mut models) = (Vec::new(), Vec::new());
    for (datum, roll, m) in [(20.0, 240.0, 800), (460.0, 360.0, 1200)] {
        let (tr, st) = creep_from_rest(datum, roll, m);
        let (a, b) = (run(&tr), run(&st));
        let y = get(&b.runs, "lemke");
        assert_eq!(y.status, Status::Solved, "{}", y.message);
        let h = hertz(&st, y);
        let q_end = y.resultants.unwrap().tangential;
        let dist = |r: &SolverRun| {
            paired(&r.nodes, &y.nodes).fold(0.0f64, |m, (u, v)| m.max((u.shear - v.shear).abs())) / h.p0
        };
        let along: Vec<f64> = a.steps.iter().map(|st| dist(get(&st.runs, "lemke"))).collect();
        let qs: Vec<f64> = a.steps.iter().map(|st| get(&st.runs, "lemke").resultants.unwrap().tangential).collect();
        // |Q| grows monotonically towards the steady value and never overshoots it.
        for w in qs.windows(2) {
            assert!(w[1].abs() >= w[0].abs() - 1e-9 * h.p0 && w[1].abs() <= q_end.abs() * (1.0 + 1e-9));
        }
        // Decay length fitted on the distance between 1e-2 and 1e-5 of p0 (substeps of 0.3 mm).
        let k1 = along.iter().position(|d| *d < 1e-2).unwrap();
        let k2 = along.iter().position(|d| *d < 1e-5).unwrap();
        let fitted = (k2 - k1) as f64 * 0.3 / (along[k1] / along[k2]).ln();
        let c = h.a * theory::carter_c_over_a(q_end / (0.3 * h.load));
        let model = c * ((2.0 * datum / h.a).ln() + 0.5);
        eprintln!("D = {datum}: decay length {fitted:.2} mm, model {model:.2} mm; end distance {:.2e}", along[m]);
        assert!((fitted / model - 1.0).abs() < 0.15, "D = {datum}: {fitted} vs model {model}");
        lengths.push(fitted);
        models.push(model);
        if datum == 20.0 {
            // 240 mm is 27 decay lengths: the start is forgotten to solver precision.
            assert!(along[m] < 1e-8, "end {:e}", along[m]);
        }
    }
    // The datum's logarithm sets the rate: ratio of the decay lengths against the model's ratio, within 5 %.
    let ratio = models[1] / models[0];
    assert!((lengths[1] / lengths[0] / ratio - 1.0).abs() < 0.05, "{lengths:?} vs models {models:?}");
}

#[test]
fn bad_paths_are_refused_naming_the_field() {
    let base = |body: &str| {
        format!(
            "name = \"bad\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
             model = \"half_plane\"\nprofile = \"parabola\"\n[mesh]\nelement = \"constant\"\n\
             contact_half_width = 9.0\ncontact_elements = 40\n[contact]\nfriction = 0.3\ncoupling = false\n{body}"
        )
    };
    let cases = [
        ("[drive]\nnormal_load = 1.0\n[[steps]]\nnormal_load = 2.0", "steps"),
        ("[[steps]]\ntangential_load = 2.0", "steps[0]"),
        ("[[steps]]\nnormal_load = 2.0\nsubsteps = 0", "steps[0].substeps"),
        ("[[steps]]\nnormal_load = 2.0\n[[steps]]\nnormal_load = 2.0\nroll = -1.0", "steps[1].roll"),
        ("[[steps]]\nnormal_load = 2.0\nroll = 1.0", "rolling"),
        (
            "[rolling]\nmode = \"steady\"\ncreepage = 0.001\ndirection = 1\n[[steps]]\nnormal_load = 2.0\nroll = 1.0",
            "rolling.mode",
        ),
        (
            "[rolling]\nmode = \"transient\"\ndirection = 1\n[[steps]]\nnormal_load = 2.0\nroll = 1.0",
            "rolling.creepage",
        ),
        (
            "[rolling]\nmode = \"transient\"\ncreepage = 0.001\ndirection = 1\n[drive]\nnormal_load = 2.0",
            "rolling.mode",
        ),
    ];
    for (body, field) in cases {
        let text = base(body);
        let err = Scene::from_toml(&text, Path::new("<test>")).expect_err(body).to_string();
        assert!(err.contains(field), "{body}: expected the field `{field}` in: {err}");
    }
}

/// Mindlin–Deresiewicz holds for any β = 0 pair: a steel half-plane wheel on a steel half-plane rail (each body with
/// its own datum; their compliances add) follows the theory's loop as the single half-plane on a rigid flat does.
/// Expected values: `rollbem::report::md_shift` — the 2D theory (tests above derive the datum) summed over the two
/// bodies — at the load and Q of each substep.
#[test]
fn md_loop_of_a_steel_on_steel_pair() {
    let s = md_scene(200, 3000.0, 10, r#"["active_set"]"#)
        .edit(|d| {
            d.counter_body = rollbem::scene::document::CounterBodyTable::HalfPlane {
                youngs_modulus: 210000.0,
                poisson_ratio: 0.3,
                datum_depth: None,
                viscoelastic: None,
            };
            // The pair is twice as compliant: a = 10.08 mm; the zone grows with it at the same element size.
            d.mesh.contact_half_width = Some(13.5);
            d.mesh.contact_elements = 300;
        })
        .unwrap();
    assert_eq!(s.dundurs_beta(), 0.0);
    let (p, q_star) = rollbem::report::md_pattern(&s).expect("a β = 0 pair is of the pattern");
    let delta = rollbem::report::md_shift(&s, p);
    let r = run(&s);
    let span = delta(TangentialPath::Loading, q_star).abs();
    let mut worst: f64 = 0.0;
    assert!(
        r.runs.iter().all(|x| x.status == Status::Solved),
        "{:?}",
        r.runs.iter().map(|x| x.explanation()).collect::<Vec<_>>()
    );
    for st in r.steps.iter().filter(|st| st.step >= 1) {
        let run = &st.runs[0];
        let (q, shift) = (run.resultants.unwrap().tangential, run.rigid_body.unwrap().tangential.unwrap());
        let branch = match st.step {
            1 => TangentialPath::Loading,
            k if k % 2 == 0 => TangentialPath::Unloading { q_star },
            _ => TangentialPath::Reloading { q_star },
        };
        worst = worst.max((shift - delta(branch, q)).abs() / span);
    }
    // The single half-plane's loop agrees to about 1e-3 of its half-span at this mesh (tests above); the pair's
    // compliance is twice the single body's, its discretisation error alike.
    assert!(worst < 5e-3, "largest distance from the theory's loop: {worst:e} of the half-span");
}

/// A path that switches the normal DOF from load to displacement control between steps (found by the `scene` fuzz
/// target, bug 11 in FUZZING.md): the active-set solver reused the previous step's factorisation, which had one more
/// unknown (the load-driven approach), as its preconditioner, and panicked on the size mismatch. Now a factorisation
/// of another layout is not reused. Reference: Lemke on the same path (a peer solver), and for the last step the
/// one-step scene with the same approach; the approach is that of a one-step run at 15 kN/mm.
#[test]
fn a_path_switching_from_load_to_approach_control_is_solved() {
    for (mu, coupling) in [(0.0, false), (0.3, true)] {
        let solvers = r#"["lemke", "active_set"]"#;
        let reference_scene = path_scene(0.3, mu, coupling, 60, "[drive]\nnormal_load = 15000.0", solvers);
        let reference = run(&reference_scene);
        let d = get(&reference.runs, "lemke").rigid_body.unwrap().normal;
        let q = if mu > 0.0 { "tangential_load = 1000.0" } else { "" };
        let body = format!(
            "[[steps]]\nnormal_load = 20000.0\n{q}\n[[steps]]\nnormal_load = 10000.0\n{q}\n\
             [[steps]]\nnormal_approach = {d}\n{q}"
        );
        let path = run(&path_scene(0.3, mu, coupling, 60, &body, solvers));
        assert_eq!(path.steps.len(), 3);
        let one = run(&path_scene(0.3, mu, coupling, 60, &format!("[drive]\nnormal_approach = {d}"), solvers));
        let p0 = hertz(&reference_scene, get(&reference.runs, "lemke")).p0;
        for (k, step) in path.steps.iter().enumerate() {
            let (l, a) = (get(&step.runs, "lemke"), get(&step.runs, "active_set"));
            assert_eq!((l.status, a.status), (Status::Solved, Status::Solved), "μ = {mu}, step {k}");
            for (u, v) in paired(&l.nodes, &a.nodes) {
                assert!((u.pressure - v.pressure).abs() < 1e-8 * p0, "μ = {mu}, step {k}, x = {}", u.x);
                assert!((u.shear - v.shear).abs() < 1e-8 * p0, "μ = {mu}, step {k}, x = {}", u.x);
            }
        }
        // The last step's normal load is that of the one-step approach-driven scene (normal problem only when
        // frictionless; with friction the tangential history changes the shear, not the resultant beyond β's
        // coupling, so only the frictionless case is compared node by node).
        if mu == 0.0 {
            let (x, y) = (get(&path.steps[2].runs, "lemke"), get(&one.runs, "lemke"));
            assert_eq!(y.status, Status::Solved, "{}", y.message);
            for (u, v) in paired(&x.nodes, &y.nodes) {
                assert!((u.pressure - v.pressure).abs() < 1e-10 * p0, "x = {}: {} vs {}", u.x, u.pressure, v.pressure);
            }
        }
    }
}
