//! Public functions refuse a value a caller can give instead of panicking (issue 31, item 3): each test hands one a
//! value outside its domain and checks the error names the function and the argument, and that a value inside still
//! works. Before, each of these panicked: an `assert!` (`HalfPlane::new`, `HalfPlane::strip`, the influence blocks,
//! `Toeplitz::from_parts` and `apply`, `InteriorStress::new`, `boundary_stress`, `gauss_legendre`,
//! `lcp_residual::residuals`, `StressEvaluator::evaluate`, `BoundaryResponse::boundary`), an `expect`/`unwrap`/
//! `panic!` (`Mesh::wheel` on an empty contact zone, `ContactProblem::lcp` beyond gross sliding, the frictional LCP of
//! a flexibility without tangential blocks, `Lemke` on a gross-sliding problem) or an index out of bounds (a
//! hand-edited mesh in `assemble_full`, a BEM system of another model, an LCP whose M and q differ in size). The
//! domains are each function's documented ones; the values inside them are checked against an independent answer
//! where there is one.

use rollbem::bem::assemble_full;
use rollbem::bem::kelvin::Kelvin;
use rollbem::bem::quadrature::gauss_legendre;
use rollbem::bem::stress::{boundary_stress, interior_stress, InteriorStress};
use rollbem::error::ArgumentError;
use rollbem::formulation::lcp::frictional_lcp;
use rollbem::formulation::{ContactProblem, DriveIssue, SlipOperator};
use rollbem::halfplane::{pair_blocks_uniform, strip_stress, Block, HalfPlane};
use rollbem::lcp_residual::residuals;
use rollbem::mesh::{Mesh, MeshSpec};
use rollbem::pipeline::stages;
use rollbem::scene::{ContactZone, ElementKind, Scene, Support, ZoneExtent};
use rollbem::solvers::{Lcp, Termination};
use rollbem::source::bem_wheel::{assemble_system, solve_system, Model};
use rollbem::source::{self, Blocks};
use rollbem::stresses::StressEvaluator;
use rollbem::toeplitz::Toeplitz;
use std::path::Path;

/// The function and argument an error names.
fn named(e: ArgumentError) -> (&'static str, &'static str) {
    (e.function, e.argument)
}

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("no_panics.toml")).unwrap()
}

/// A half-plane scene of 40 elements with μ = 0.3 and the given drive lines.
fn half_plane(drive: &str) -> Scene {
    scene(&format!(
        "name = \"hp\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\nmodel = \"half_plane\"\n\
         [mesh]\nelement = \"constant\"\ncontact_half_width = 3.0\ncontact_elements = 40\n[contact]\nfriction = 0.3\n\
         [drive]\n{drive}\n"
    ))
}

#[test]
fn half_plane_refuses_moduli_ratios_depths_and_widths_outside_its_domain() {
    let bad = [
        (0.0, 0.3, 1.0, "e"),
        (-1.0, 0.3, 1.0, "e"),
        (f64::NAN, 0.3, 1.0, "e"),
        (1.0, 0.6, 1.0, "nu"),
        (1.0, -0.1, 1.0, "nu"),
        (1.0, f64::NAN, 1.0, "nu"),
        (1.0, 0.3, 0.0, "datum_depth"),
        (1.0, 0.3, f64::INFINITY, "datum_depth"),
        (1.0, 0.3, f64::NAN, "datum_depth"),
    ];
    for (e, nu, d, argument) in bad {
        let err = HalfPlane::new(e, nu, d).unwrap_err();
        assert_eq!(named(err.clone()), ("HalfPlane::new", argument), "E = {e}, ν = {nu}, D = {d}: {err}");
    }
    // The domain's edges are inside it: a rigid body (E = ∞) and an incompressible one (ν = 0.5), ν = 0.
    for (e, nu) in [(f64::INFINITY, 0.3), (1.0, 0.5), (1.0, 0.0)] {
        assert!(HalfPlane::new(e, nu, 1.0).is_ok(), "E = {e}, ν = {nu}");
    }
    let hp = HalfPlane::new(1.0, 0.3, 1.0).unwrap();
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(named(hp.strip(w).unwrap_err()), ("HalfPlane::strip", "width"), "width {w}");
    }
    assert_eq!(hp.strip(0.5).unwrap().strip_width(), Some(0.5));
}

#[test]
fn influence_blocks_refuse_mismatched_grids_and_impossible_widths() {
    let hp = HalfPlane::new(1.0, 0.3, 1.0).unwrap();
    assert_eq!(named(hp.influence_blocks(&[0.0, 1.0], &[1.0], &[0.5]).unwrap_err()).1, "b");
    for h in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        assert_eq!(named(hp.influence_blocks_uniform(-1.0, h, 4).unwrap_err()).1, "h", "h = {h}");
        assert_eq!(named(hp.influence_block_uniform(-1.0, h, 4, Block::Zz).unwrap_err()).1, "h", "h = {h}");
        assert_eq!(named(pair_blocks_uniform(&hp, &hp, -1.0, h, 4).unwrap_err()).1, "h", "h = {h}");
    }
    // n × n entries that cannot exist: refused before anything is allocated.
    assert_eq!(named(hp.influence_blocks_uniform(0.0, 0.1, usize::MAX).unwrap_err()).1, "n");
    let mut blocks = hp.influence_blocks_uniform(-1.0, 0.5, 4).unwrap();
    // One block computed alone is the same block, bit for bit (the Block names replace the indices 0..4).
    for (which, block) in
        [(Block::Xx, &blocks.cxx), (Block::Xz, &blocks.cxz), (Block::Zx, &blocks.czx), (Block::Zz, &blocks.czz)]
    {
        assert_eq!(&hp.influence_block_uniform(-1.0, 0.5, 4, which).unwrap(), block, "{which:?}");
    }
    assert_eq!(named(blocks.apply(&[0.0; 3], &[0.0; 4]).unwrap_err()), ("InfluenceBlocks::apply", "q"));
    assert_eq!(named(blocks.apply(&[0.0; 4], &[0.0; 5]).unwrap_err()).1, "p");
    let smaller = hp.influence_blocks_uniform(-1.0, 0.5, 3).unwrap();
    let before = blocks.clone();
    assert_eq!(named(blocks.add_blocks(&smaller).unwrap_err()), ("InfluenceBlocks::add_blocks", "other"));
    assert_eq!(blocks, before, "a refused sum leaves the blocks as they were");
    // Blocks whose public vectors were edited to another length than rows × cols.
    blocks.czz.pop();
    assert_eq!(named(blocks.apply(&[0.0; 4], &[0.0; 4]).unwrap_err()).1, "blocks");
}

/// Ends given the other way round integrate the other way: the negative of the strip's value (∫ from b to a is
/// −∫ from a to b). A point outside the body (z < 0) has no stress: NaN, where the closed form used to be evaluated
/// there (and a debug build's assertion fired).
#[test]
fn strip_kernels_take_reversed_ends_and_refuse_points_outside_the_body() {
    let hp = HalfPlane::new(1.0, 0.3, 2.0).unwrap();
    let (forward, reversed) = (
        hp.strip_surface_displacement(-0.5, 0.25, 1.0, 0.3, 0.7),
        hp.strip_surface_displacement(0.25, -0.5, 1.0, 0.3, 0.7),
    );
    assert_eq!((reversed.ux, reversed.uz), (-forward.ux, -forward.uz));
    let (forward, reversed) =
        (strip_stress(-0.5, 0.25, 1.0, 0.3, 0.1, 0.4), strip_stress(0.25, -0.5, 1.0, 0.3, 0.1, 0.4));
    assert_eq!((reversed.sxx, reversed.szz, reversed.txz), (-forward.sxx, -forward.szz, -forward.txz));
    let above = strip_stress(-0.5, 0.25, 1.0, 0.3, 0.1, -0.4);
    assert!(above.sxx.is_nan() && above.szz.is_nan() && above.txz.is_nan(), "{above:?}");
}

#[test]
fn toeplitz_refuses_lengths_it_cannot_have() {
    assert_eq!(named(Toeplitz::from_parts(&[], &[]).unwrap_err()), ("Toeplitz::from_parts", "col"));
    assert_eq!(named(Toeplitz::from_parts(&[1.0, 2.0], &[1.0]).unwrap_err()).1, "row");
    let op = Toeplitz::from_parts(&[2.0, 1.0], &[2.0, 3.0]).unwrap();
    assert_eq!(named(op.apply(&[1.0, 2.0, 3.0]).unwrap_err()), ("Toeplitz::apply", "x"));
    // [[2, 3], [1, 2]] (1, 1) = (5, 3), by hand.
    let y = op.apply(&[1.0, 1.0]).unwrap();
    assert!((y[0] - 5.0).abs() < 1e-14 && (y[1] - 3.0).abs() < 1e-14, "{y:?}");
}

#[test]
fn mesh_wheel_refuses_a_wheel_it_cannot_mesh() {
    let top = Support::TopArc { angle_deg: 30.0 };
    let spec = MeshSpec::arc(ElementKind::Constant, 30.0, 8, 16);
    let zone = |extent, elements| MeshSpec { zone: ContactZone { extent, elements }, ..spec };
    assert!(Mesh::wheel(1.0, top, &spec).is_ok());
    let cases = [
        (0.0, top, spec, "radius"),
        (f64::NAN, top, spec, "radius"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 30.0, 0, 16), "spec.zone.elements"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 30.0, 8, 0), "spec.other_elements"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 30.0, 8, 3), "spec.other_elements"),
        (1.0, top, MeshSpec::arc(ElementKind::Quadratic, 30.0, 3000, 16), "spec"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 200.0, 8, 16), "spec.zone"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 0.0, 8, 16), "spec.zone"),
        (1.0, top, MeshSpec::arc(ElementKind::Constant, 1e-12, 8, 16), "spec.zone"),
        (1.0, top, zone(ZoneExtent::HalfWidth { half_width: 1.5 }, 8), "spec.zone"),
        (1.0, top, zone(ZoneExtent::Span { x_min: -0.1, x_max: 0.2 }, 8), "spec.zone"),
        (1.0, Support::Hub { radius: 1.0 }, spec, "support"),
        (1.0, Support::TopArc { angle_deg: 0.0 }, spec, "support"),
        (1.0, Support::TopArc { angle_deg: 170.0 }, MeshSpec::arc(ElementKind::Constant, 170.0, 8, 16), "support"),
    ];
    for (radius, support, spec, argument) in cases {
        let err = Mesh::wheel(radius, support, &spec).unwrap_err();
        assert_eq!(named(err.clone()), ("Mesh::wheel", argument), "R = {radius}, {support:?}, {spec:?}: {err}");
    }
}

/// A mesh edited by hand so that it no longer holds together is refused by every public reader of meshes (before:
/// an index out of bounds, or an assertion, inside the assembly or the stress evaluation).
#[test]
fn a_mesh_that_does_not_hold_together_is_refused_by_its_readers() {
    let top = Support::TopArc { angle_deg: 30.0 };
    let good = Mesh::wheel(1.0, top, &MeshSpec::arc(ElementKind::Quadratic, 30.0, 4, 8)).unwrap();
    assert_eq!(good.check(), Ok(()));
    let k = Kelvin::new(1.0, 0.3);
    let n = good.n_nodes();
    let zeros = vec![[0.0; 2]; n];
    type Edit = (&'static str, fn(&mut Mesh));
    let edits: [Edit; 5] = [
        ("an element's node count not its shape's", |m| m.elements[0].n_nodes = 1),
        ("nodes beyond the end", |m| {
            m.nodes.pop();
        }),
        ("a node naming another element", |m| m.nodes[0].element = 5),
        ("a contact node missing from contact_nodes", |m| {
            m.contact_nodes.pop();
        }),
        ("contact_nodes naming a node that is not one", |m| m.contact_nodes[0] = m.nodes.len() - 1),
    ];
    for (what, edit) in edits {
        let mut m = good.clone();
        edit(&mut m);
        assert_eq!(named(m.check().unwrap_err()), ("Mesh::check", "mesh"), "{what}");
        assert!(assemble_full(&m, &k).is_err(), "assemble_full: {what}");
        let (u, t) = (vec![[0.0; 2]; m.n_nodes()], vec![[0.0; 2]; m.n_nodes()]);
        assert!(InteriorStress::new(&m, &k, &u, &t).is_err(), "InteriorStress::new: {what}");
        assert!(boundary_stress(&m, &k, &u, &t, 0, 0.0).is_err(), "boundary_stress: {what}");
    }
    assert_eq!(named(InteriorStress::new(&good, &k, &zeros[..n - 1], &zeros).unwrap_err()).1, "u");
    assert_eq!(named(interior_stress(&good, &k, &zeros, &zeros[..1], &[[0.0, 0.0]]).unwrap_err()).1, "t");
    let e = good.elements.len();
    assert_eq!(named(boundary_stress(&good, &k, &zeros, &zeros, e, 0.0).unwrap_err()), ("boundary_stress", "element"));
    // Inside the domain: a traction-free, motionless boundary has no stress anywhere.
    assert_eq!(boundary_stress(&good, &k, &zeros, &zeros, 0, 0.0).unwrap(), Some([0.0; 3]));
    assert_eq!(good.initial_gap(n), None);
    assert!(good.initial_gap(good.contact_nodes[0]).is_some_and(|g| g >= 0.0));
}

#[test]
fn gauss_legendre_refuses_zero_points() {
    assert_eq!(named(gauss_legendre(0).unwrap_err()), ("gauss_legendre", "n"));
    // The 1-point rule: the midpoint, weight 2 (exact for linear functions on [−1, 1]).
    let rule = gauss_legendre(1).unwrap();
    assert_eq!((rule.points.as_slice(), rule.weights.as_slice()), (&[0.0][..], &[2.0][..]));
}

/// A small frictionless BEM wheel (R = 1, 8 contact elements) with a 3 × 3 stress grid well inside it.
fn small_bem(other: usize) -> Scene {
    scene(&format!(
        "name = \"small\"\n[wheel]\nradius = 1.0\nyoungs_modulus = 1000.0\npoisson_ratio = 0.3\n\
         support = {{ kind = \"top_arc\", angle_deg = 30.0 }}\n[mesh]\nelement = \"constant\"\ncontact_arc_deg = 30.0\n\
         contact_elements = 8\nother_elements = {other}\n[contact]\nfriction = 0.0\n[drive]\nnormal_load = 1.0\n\
         [stresses]\nx = [-0.05, 0.05]\ndepth = [0.4, 0.6]\npoints = [3, 3]\n"
    ))
}

#[test]
fn bem_models_responses_and_systems_refuse_what_does_not_fit() {
    let s = small_bem(64);
    let built = source::build(&s, stages::blocks_for(&s)).unwrap();
    let response = built.boundary.as_ref().expect("a scene with [stresses] keeps the boundary response");
    let nc = response.model.mesh.contact_nodes.len();
    let (zeros, short) = (vec![0.0; nc], vec![0.0; nc - 1]);
    assert_eq!(named(response.boundary(&short, &zeros).unwrap_err()), ("BoundaryResponse::boundary", "p"));
    assert_eq!(named(response.boundary(&zeros, &short).unwrap_err()).1, "q");
    // Frictionless: no tangential columns, so a shear cannot be applied.
    assert_eq!(named(response.boundary(&zeros, &vec![1e-3; nc]).unwrap_err()).1, "q");
    let (u, t) = response.boundary(&zeros, &zeros).unwrap();
    assert!(u.iter().chain(&t).all(|v| *v == [0.0; 2]), "no traction, no response");

    let ev = StressEvaluator::new(&s, &built).unwrap().expect("[stresses]");
    assert_eq!(ev.contact_nodes(), nc);
    assert_eq!(named(ev.evaluate(&[]).unwrap_err()), ("StressEvaluator::evaluate", "nodes"));
    assert!(ev.evaluate_counter_body(&[]).unwrap().is_none(), "a rigid flat has no field");

    let spec = MeshSpec::arc(ElementKind::Constant, 30.0, 8, 16);
    let err = Model::new(s.wheel(), Support::TopArc { angle_deg: 0.0 }, &spec).unwrap_err();
    assert_eq!(named(err), ("Mesh::wheel", "support"));
    // A system assembled for one model, solved with another's mesh: refused, naming it.
    let (a, b) = (Model::of_scene(&s).unwrap().unwrap(), Model::of_scene(&small_bem(72)).unwrap().unwrap());
    let sys = assemble_system(&a, Blocks::Normal).unwrap();
    match solve_system(&b, &sys) {
        Err(rollbem::Error::Invalid { field, message, .. }) => assert!(field.contains("sys"), "{field}: {message}"),
        other => panic!("a system of another model: {:?}", other.map(|_| ())),
    }
    assert!(solve_system(&a, &sys).is_ok());
}

#[test]
fn lcps_and_their_residuals_refuse_vectors_of_another_size() {
    use faer::Mat;
    assert_eq!(named(Lcp::new(Mat::zeros(2, 3), vec![0.0; 2]).unwrap_err()), ("Lcp::new", "m"));
    assert_eq!(named(Lcp::new(Mat::zeros(2, 2), vec![0.0; 3]).unwrap_err()).1, "q");
    let lcp = Lcp::new(Mat::from_fn(2, 2, |i, j| if i == j { 2.0 } else { 1.0 }), vec![-5.0, -6.0]).unwrap();
    assert_eq!(named(lcp.w_of(&[1.0]).unwrap_err()), ("Lcp::w_of", "z"));
    // w = M z + q at z = (4/3, 7/3): (8/3 + 7/3 − 5, 4/3 + 14/3 − 6) = (0, 0), by hand.
    let z = [4.0 / 3.0, 7.0 / 3.0];
    let w = lcp.w_of(&z).unwrap();
    assert!(w.iter().all(|v| v.abs() < 1e-14), "{w:?}");
    assert_eq!(named(residuals(&lcp, &z[..1], &w).unwrap_err()), ("residuals", "z"));
    assert_eq!(named(residuals(&lcp, &z, &[0.0; 3]).unwrap_err()).1, "w");
    assert!(residuals(&lcp, &z, &w).unwrap().max < 1e-15);
}

/// A contact problem whose parts do not fit is refused when it is built; beyond gross sliding it has no LCP, and
/// Lemke says so as a status.
#[test]
fn contact_problems_refuse_unfit_parts_and_have_no_lcp_beyond_gross_sliding() {
    let s = half_plane("normal_load = 1000.0\ntangential_load = 100.0");
    // A frictional problem on a flexibility built for the normal problem only: before, the frictional LCP's
    // `expect("K_NT")` (or the active set's `expect("tangential blocks")`) panicked when it was solved.
    let normal_only = source::build(&s, Blocks::Normal).unwrap();
    let drive = *s.drive().unwrap();
    match ContactProblem::new(&normal_only.flex, s.law(), drive, SlipOperator::static_slip()) {
        Err(DriveIssue::Flexibility(why)) => assert!(why.contains("tangential"), "{why}"),
        other => panic!("a frictional problem without tangential blocks: {:?}", other.map(|_| ())),
    }
    assert!(matches!(
        stages::build_problem(&s, &normal_only.flex, drive, SlipOperator::static_slip()),
        Err(rollbem::Error::Unsupported { .. })
    ));
    let full = source::build(&s, stages::blocks_for(&s)).unwrap();
    // A slip operator of another grid (2 nodes, the flexibility has 40).
    let err = ContactProblem::new(&full.flex, s.law(), drive, SlipOperator::steady(&[0.0, 1.0], 1)).unwrap_err();
    assert!(matches!(err, DriveIssue::Flexibility(_)), "{err}");

    let p = ContactProblem::new(&full.flex, s.law(), drive, SlipOperator::static_slip()).unwrap();
    let lcp = p.lcp().expect("a frictional LCP");
    assert_eq!(lcp.size(), p.lcp_size());
    assert!(p.unpack(&vec![0.0; lcp.size() - 1]).is_none(), "a z of another size");
    assert!(p.unpack(&vec![0.0; lcp.size()]).is_some());
    let signs: Vec<f64> = p.load_dofs().map(|d| d.default_sign()).collect();
    assert!(frictional_lcp(&p, &signs[1..]).is_none(), "one sign short");
    assert!(frictional_lcp(&p, &signs).is_some());

    let frictionless = half_plane("normal_load = 1000.0").edit(|d| d.contact.friction = 0.0).unwrap();
    let fb = source::build(&frictionless, stages::blocks_for(&frictionless)).unwrap();
    let pf = stages::scene_problem(&frictionless, &fb.flex).unwrap();
    assert!(frictional_lcp(&pf, &[]).is_none(), "no frictional LCP of a frictionless problem");

    // |Q| = 0.5 P > μP: gross sliding. No LCP (a panic before), and Lemke reports it infeasible.
    let gross = half_plane("normal_load = 1000.0\ntangential_load = 500.0");
    let gb = source::build(&gross, stages::blocks_for(&gross)).unwrap();
    let pg = stages::scene_problem(&gross, &gb.flex).unwrap();
    assert!(pg.lcp().is_none() && pg.unpack(&[]).is_none() && pg.lcp_size() == 0);
    let lemke = rollbem::solvers::build("lemke").unwrap();
    let out = lemke.solve(&pg);
    assert_eq!(out.status, Termination::Infeasible, "{}", out.message);
    assert!(out.message.contains("friction limit"), "{}", out.message);
}

/// Solvers built directly with settings outside the ranges a scene's validation enforces (a settings struct's fields
/// are public) end with a termination, never a panic: zero budgets, tolerances of 0, NaN and ≥ 1, a relaxation
/// outside (0, 2). A guard, not a fix: none of these panicked before either (checked when this test was written).
#[test]
fn solvers_with_settings_outside_their_ranges_end_with_a_termination() {
    use rollbem::solvers::active_set::{ActiveSet, ActiveSetSettings};
    use rollbem::solvers::clarabel_qp::QpSettings;
    use rollbem::solvers::lemke::{self, dense::solve_dense, LemkeSettings};
    use rollbem::solvers::normtang::{NormTangQp, NormTangQpSettings, Pgs, PgsSettings};
    use rollbem::solvers::Solver;
    let s = half_plane("normal_load = 1000.0\ntangential_load = 100.0");
    let built = source::build(&s, stages::blocks_for(&s)).unwrap();
    let p = stages::scene_problem(&s, &built.flex).unwrap();
    let lcp = p.lcp().unwrap();
    for tol in [0.0, f64::NAN, 1.0, 2.0, -1.0] {
        for count in [0, 1] {
            let ls = LemkeSettings {
                max_pivots_per_unknown: count,
                pivot_tolerance: tol,
                tie_tolerance: tol,
                refactor_every: count,
                warm_start: true,
            };
            let what = format!("tolerance {tol}, count {count}");
            let out = lemke::solve(lcp, &ls);
            assert!(!out.message.is_empty() || out.status == Termination::Solved, "lemke, {what}");
            let _ = solve_dense(lcp, &ls);
            let solvers: Vec<Box<dyn Solver>> = vec![
                Box::new(ActiveSet { settings: ActiveSetSettings { max_iterations: count, margin: tol } }),
                Box::new(Pgs {
                    settings: PgsSettings {
                        tolerance: tol,
                        max_sweeps: count,
                        max_outer: count,
                        relaxation: 2.0 + tol,
                    },
                }),
                Box::new(NormTangQp {
                    settings: NormTangQpSettings {
                        tolerance: tol,
                        max_outer: count,
                        qp: QpSettings { tolerance: tol, max_iter: count as u32, ..QpSettings::default() },
                    },
                }),
            ];
            for solver in solvers {
                let out = solver.solve(&p);
                if out.status == Termination::Solved {
                    // A claim the harness checks: the solution has the problem's shape.
                    assert_eq!(out.solution.as_ref().map(|s| s.f.len()), Some(p.n()), "{}, {what}", solver.name());
                }
            }
        }
    }
}

/// A sweep's case by a number beyond its cases: an error naming `case` (a panic before, "a case number below
/// len()"), and no parameters.
#[test]
fn a_sweep_case_beyond_the_sweep_is_refused() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/sweeps/hertz-accuracy.toml");
    let spec = rollbem::sweep::SweepSpec::from_file(&path).unwrap();
    let e = spec.expand(&path, &path).unwrap();
    let n = e.len();
    assert!(n > 0 && e.params(n - 1).is_some() && e.case(n - 1).is_ok());
    assert!(e.params(n).is_none());
    match e.case(n) {
        Err(rollbem::Error::Invalid { field, message, .. }) => assert_eq!(field, "case", "{message}"),
        other => panic!("case {n} of {n}: {:?}", other.map(|c| c.index)),
    }
    assert!(e.check_rows(n, &[]).is_err());
}

/// A solver (a plug-in, say) that claims a solution of another shape than the problem's: the evaluation refuses it
/// and the harness reports the run `numerical_error` with the reason, where it used to index out of bounds.
#[test]
fn a_claimed_solution_of_another_shape_is_refused_by_the_harness() {
    use rollbem::formulation::Solution;
    use rollbem::results::{Setup, Timing};
    use rollbem::solvers::{Outcome, Work};
    use rollbem::status::{Status, VerdictReason};
    let s = half_plane("normal_load = 1000.0\ntangential_load = 100.0");
    let built = source::build(&s, stages::blocks_for(&s)).unwrap();
    let p = stages::scene_problem(&s, &built.flex).unwrap();
    let n = p.n();
    let wrong = Solution {
        f: vec![0.0; n - 1],
        h: Some(vec![0.0; n]),
        rigid: vec![0.0; p.dofs().len()],
        tangential_known: true,
    };
    assert!(!wrong.fits(&p));
    assert_eq!(named(rollbem::post::evaluate(&p, &wrong, None).unwrap_err()), ("evaluate", "sol"));
    let ctx = stages::RunContext {
        scene: &s,
        problem: &p,
        solver: rollbem::solvers::SolverId::new("a_plugin"),
        timing: Timing::of(&built.timing, 0.0, 0.0, Setup::Built),
        refuse: 1e-6,
        rolling: None,
    };
    let outcome = Outcome::new(Some(wrong), Termination::Solved, "done".into(), Work::default());
    let (run, ev) = stages::evaluate_outcome(&ctx, outcome);
    assert!(ev.is_none());
    assert_eq!(run.status, Status::NumericalError);
    let verdict = run.verdict.expect("a verdict saying why");
    assert_eq!(verdict.reason, VerdictReason::ResidualTooLarge);
    assert!(verdict.message.contains("cannot be evaluated"), "{}", verdict.message);
}
