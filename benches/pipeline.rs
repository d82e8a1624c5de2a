//! Criterion benchmarks per pipeline stage, with size sweeps and stable names:
//!
//! - `seed_end_to_end/lemke`: the seed's frictionless scene (56 constant elements), scene to result, Lemke only.
//! - `assembly/{constant,quadratic}/N`: BEM assembly of the rearranged system for N elements.
//! - `condensation/constant/N` and `dense_lu/N`: one LU + the flexibility solves, against a bare faer LU of the
//!   same size (the condensation target is within 2× of it).
//! - `frictionless_solve/{lemke,clarabel}/n`: the frictionless load-driven problem with n contact nodes.
//! - `lemke_frictional/{block,dense,warm}/m`: Lemke on frictional LCPs of m = 3n + 4 unknowns (pivots to stderr);
//!   `warm` is the block engine warm-started from the support of the previous load step (Q 10 % lower).
//! - `formulation_and_normtang/{frictional_lcp,pgs,normtang_qp}/n`: building the frictional LCP, and the two
//!   NORM-TANG solvers, with n contact nodes.
//!
//! - `scale/active_set_solve/3300` and `scale/condensation/3300`: the issue-14 size, a frictional LCP of 9904
//!   unknowns (the Cattaneo wheel with coupling on and 3300 contact elements, BEM system 6762×6762): the active-set
//!   solve alone (target under 10 s) and the condensation (one LU of the BEM system and 6603 solves,
//!   ≈ 8.1e11 flops), both with faer's parallelism on. Each sample takes seconds: run it on its own
//!   (`cargo bench --bench pipeline -- scale`).
//!
//! - `creep_curve/{warm,cold_case}/n`: CONTACT's 2D Carter problem (two half-planes G = 82 000, ν = 0.28,
//!   R = 500, μ = 0.3, P = 178.9 per unit length) on n = 111 and 841 elements: `warm` solves the 50-point creep curve
//!   ξ = 1e-5 … 5e-4 on one model, each case from its neighbour (throughput in cases: criterion prints the time per
//!   case); `cold_case` builds the model and solves one case (ξ = 2.5e-4) from nothing, what every case cost before
//!   warm starts.
//!
//! Run one group with e.g. `cargo bench --bench pipeline -- assembly --quick`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::formulation::lcp::frictional_lcp;
use rollbem::pipeline::run_scene;
use rollbem::pipeline::stages::scene_problem;
use rollbem::scene::{ElementKind, Scene};
use rollbem::solvers::clarabel_qp::{self, QpSettings};
use rollbem::solvers::lemke::{self, LemkeSettings};
use rollbem::source::bem_wheel::{assemble_system, condense, solve_system, Model};
use rollbem::source::Blocks;
use std::hint::black_box;
use std::path::Path;

fn seed_scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/seed-fig6-constant.toml");
    Scene::from_file(&path).expect("seed scene")
}

/// The seed's material on a hub, `n` elements in all with a quarter of them on a 12° candidate arc.
fn scene_with(n: usize, kind: ElementKind) -> Scene {
    let mut s = seed_scene();
    s = s
        .edit(|d| {
            d.wheel.support = Some(rollbem::scene::Support::Hub { radius: 0.2 });
            d.mesh.element = kind;
            d.mesh.contact_arc_deg = Some(12.0);
            d.mesh.contact_elements = n / 4;
            d.mesh.other_elements = Some(n - n / 4);
            d.drive.normal_load = Some(187.42);
        })
        .unwrap();
    s
}

fn end_to_end(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut s = seed_scene();
    s = s.edit(|d| d.solvers.use_ = vec!["lemke".into()]).unwrap();
    c.bench_function("seed_end_to_end/lemke", |b| b.iter(|| black_box(run_scene(&s).unwrap())));
}

fn assembly(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("assembly");
    g.sample_size(10);
    for kind in [ElementKind::Constant, ElementKind::Quadratic] {
        for n in [56, 250, 500, 1000, 2000] {
            if kind == ElementKind::Quadratic && n > 1000 {
                continue;
            }
            let model = Model::of_scene(&scene_with(n, kind)).unwrap().unwrap();
            g.bench_with_input(BenchmarkId::new(kind.name(), n), &model, |b, m| {
                b.iter(|| black_box(assemble_system(m, Blocks::Normal).unwrap()))
            });
        }
    }
    g.finish();
}

fn condensation(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("condensation");
    g.sample_size(10);
    for n in [56, 250, 500, 1000, 2000] {
        let model = Model::of_scene(&scene_with(n, ElementKind::Constant)).unwrap().unwrap();
        let sys = assemble_system(&model, Blocks::Normal).unwrap();
        g.bench_with_input(BenchmarkId::new("constant", n), &sys, |b, sys| {
            b.iter(|| black_box(solve_system(&model, sys).unwrap()))
        });
        let a = sys.a.clone();
        g.bench_with_input(BenchmarkId::new("dense_lu", n), &a, |b, a| b.iter(|| black_box(a.partial_piv_lu())));
    }
    g.finish();
}

fn frictionless_solve(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("frictionless_solve");
    g.sample_size(10);
    for n in [56, 250, 1000] {
        let s = scene_with(n, ElementKind::Constant);
        let (flex, _, _) = condense(&Model::of_scene(&s).unwrap().unwrap(), Blocks::Normal).unwrap();
        let prob = scene_problem(&s, &flex).unwrap();
        let nc = flex.n();
        let lcp = prob.lcp().expect("an LCP below gross sliding").clone();
        g.bench_with_input(BenchmarkId::new("lemke", nc), &lcp, |b, l| {
            b.iter(|| black_box(lemke::solve(l, &LemkeSettings::default())))
        });
        let np = prob.normal().unwrap();
        let kcol: Vec<f64> = (0..nc * nc).map(|i| np.k[(i % nc, i / nc)]).collect();
        let ones = vec![1.0; nc];
        let load = prob.load_dofs().next().unwrap().drive.load().unwrap();
        g.bench_with_input(BenchmarkId::new("clarabel", nc), &np.q0, |b, q0| {
            b.iter(|| {
                black_box(clarabel_qp::solve_frictionless(&kcol, nc, q0, Some((&ones, load)), &QpSettings::default()))
            })
        });
    }
    g.finish();
}

/// Frictional LCPs (P and Q prescribed, rotation held, μ = 0.3, ν = 0.3) with n contact nodes: 3n + 4 unknowns.
/// n = 880 gives 2644 unknowns, the size of the 2640-unknown target. Pivot counts go to stderr.
fn lemke_frictional(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("lemke_frictional");
    g.sample_size(10);
    for n in [25usize, 100, 200, 400, 800, 880] {
        let mut s = seed_scene();
        s = s
            .edit(|d| {
                d.wheel.poisson_ratio = 0.3;
                d.wheel.support = Some(rollbem::scene::Support::Hub { radius: 0.25 });
                d.mesh.contact_arc_deg = Some(12.0);
                d.mesh.contact_elements = n;
                d.mesh.other_elements = Some(200);
                d.contact.friction = 0.3;
                d.drive.normal_load = Some(187.42);
                d.drive.tangential_load = Some(18.742);
                d.drive.rotation = Some(0.0);
            })
            .unwrap();
        let (flex, _, _) = condense(&Model::of_scene(&s).unwrap().unwrap(), Blocks::All).unwrap();
        let lcp = scene_problem(&s, &flex).unwrap().lcp().expect("an LCP below gross sliding").clone();
        let m = lcp.size();
        let probe = lemke::solve(&lcp, &LemkeSettings::default());
        eprintln!("lemke_frictional/block/{m}: {} pivots, {:?}", probe.pivots, probe.status);
        g.bench_with_input(BenchmarkId::new("block", m), &lcp, |b, l| {
            b.iter(|| black_box(lemke::solve(l, &LemkeSettings::default())))
        });
        // Warm start from the previous load step (tangential load 10 % lower): its solution's support.
        let mut prev = s.clone();
        prev = prev.edit(|d| d.drive.tangential_load = Some(0.9 * 18.742)).unwrap();
        let prev_lcp = scene_problem(&prev, &flex).unwrap().lcp().expect("an LCP below gross sliding").clone();
        let guess: Vec<bool> = lemke::solve(&prev_lcp, &LemkeSettings::default()).z.iter().map(|&v| v > 0.0).collect();
        let warm = lemke::solve_warm(&lcp, &LemkeSettings::default(), &guess);
        eprintln!("lemke_frictional/warm/{m}: {} pivots, {:?}", warm.pivots, warm.status);
        g.bench_with_input(BenchmarkId::new("warm", m), &lcp, |b, l| {
            b.iter(|| black_box(lemke::solve_warm(l, &LemkeSettings::default(), &guess)))
        });
        if n <= 400 {
            g.bench_with_input(BenchmarkId::new("dense", m), &lcp, |b, l| {
                b.iter(|| black_box(rollbem::solvers::lemke::dense::solve_dense(l, &LemkeSettings::default())))
            });
        }
    }
    g.finish();
}

/// The formulation stage (building the frictional LCP from F: K_TT⁻¹ and the affine elimination) and the
/// NORM-TANG solvers (PGS and clarabel-QP inner) on the Cattaneo scene family, n contact nodes.
fn formulation_and_normtang(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("formulation_and_normtang");
    g.sample_size(10);
    for n in [30usize, 60, 120, 240] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/cattaneo-decoupled.toml");
        let mut s = Scene::from_file(&path).unwrap();
        s = s
            .edit(|d| {
                d.contact.coupling = true;
                d.wheel.poisson_ratio = 0.45;
                d.mesh.contact_elements = n;
            })
            .unwrap();
        let (flex, _, _) = condense(&Model::of_scene(&s).unwrap().unwrap(), Blocks::All).unwrap();
        let prob = scene_problem(&s, &flex).unwrap();
        let signs: Vec<f64> = prob.load_dofs().map(|d| d.default_sign()).collect();
        g.bench_with_input(BenchmarkId::new("frictional_lcp", n), &prob, |b, p| {
            b.iter(|| black_box(frictional_lcp(p, &signs)))
        });
        let split = rollbem::solvers::normtang::Split::from_problem(&prob, None);
        let pgs = rollbem::solvers::normtang::Inner::Pgs(Default::default());
        let qp = rollbem::solvers::normtang::Inner::Qp(Default::default());
        g.bench_with_input(BenchmarkId::new("pgs", n), &split, |b, sp| {
            b.iter(|| black_box(rollbem::solvers::normtang::solve(sp, &pgs)))
        });
        g.bench_with_input(BenchmarkId::new("normtang_qp", n), &split, |b, sp| {
            b.iter(|| black_box(rollbem::solvers::normtang::solve(sp, &qp)))
        });
    }
    g.finish();
}

/// The issue-14 size: 3300 contact nodes on the finite wheel (9904 LCP unknowns).
fn scale(c: &mut Criterion) {
    use rollbem::solvers::active_set::ActiveSet;
    use rollbem::solvers::Solver;
    faer::set_global_parallelism(faer::Par::rayon(0));
    let mut g = c.benchmark_group("scale");
    g.sample_size(10);
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/cattaneo-decoupled.toml");
    let mut s = Scene::from_file(&path).unwrap();
    s = s
        .edit(|d| {
            d.contact.coupling = true;
            d.mesh.contact_elements = 3300;
        })
        .unwrap();
    let model = Model::of_scene(&s).unwrap().unwrap();
    g.bench_function(BenchmarkId::new("condensation", 3300), |b| {
        b.iter(|| black_box(condense(&model, Blocks::All).unwrap()))
    });
    let (flex, _, _) = condense(&model, Blocks::All).unwrap();
    let prob = scene_problem(&s, &flex).unwrap();
    let solver = ActiveSet { settings: Default::default() };
    let first = solver.solve(&prob);
    assert_eq!(first.status, rollbem::solvers::Termination::Solved, "{}", first.message);
    g.bench_with_input(BenchmarkId::new("active_set_solve", 3300), &prob, |b, p| b.iter(|| black_box(solver.solve(p))));
    g.finish();
}

/// CONTACT's 2D Carter scene on `n` elements (see the module docs), on its grid: the first element centred at
/// XC1 = −1.05, width DX = 0.02 (111 elements, carter2d_100) or 0.0025 (841, carter2d_800); `coupling` written out
/// (`"coupling = false\n"`) or left at its default (`""`: the pair's cross flexibilities vanish, so the same path).
fn carter_contact(n: usize, coupling: &str) -> Scene {
    let dx = if n > 200 { 0.0025 } else { 0.02 };
    let text = format!(
        "name = \"carter2d\"\n[wheel]\nradius = 500.0\nyoungs_modulus = 209920.0\npoisson_ratio = 0.28\n\
         model = \"half_plane\"\n[counter_body]\nkind = \"half_plane\"\nyoungs_modulus = 209920.0\n\
         poisson_ratio = 0.28\n[mesh]\nelement = \"constant\"\ncontact_x = [{}, {}]\ncontact_elements = {n}\n\
         [contact]\nfriction = 0.3\n{coupling}[drive]\nnormal_load = 178.9\n[rolling]\nmode = \"steady\"\n\
         creepage = 1e-5\ndirection = 1\n[solvers]\nuse = [\"active_set\"]\n",
        -1.05 - 0.5 * dx,
        -1.05 - 0.5 * dx + dx * n as f64
    );
    Scene::from_toml(&text, Path::new("carter2d.toml")).unwrap()
}

fn creep_curve(c: &mut Criterion) {
    use rollbem::pipeline::Model;
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("creep_curve");
    g.sample_size(10);
    for n in [111usize, 841] {
        let base = carter_contact(n, "coupling = false\n");
        let curve: Vec<Scene> = (1..=50).map(|k| base.with_creepage(1e-5 * k as f64).unwrap()).collect();
        let model = Model::build(&base).unwrap();
        g.throughput(criterion::Throughput::Elements(50));
        g.bench_with_input(BenchmarkId::new("warm", n), &n, |b, _| {
            b.iter(|| black_box(model.solve_all(&curve).unwrap()))
        });
        // The scene as a user writes it, `coupling` at its default: issue 31 asks for the same cost (within 1.2×).
        let default = carter_contact(n, "");
        let curve_default: Vec<Scene> = (1..=50).map(|k| default.with_creepage(1e-5 * k as f64).unwrap()).collect();
        let model_default = Model::build(&default).unwrap();
        g.bench_with_input(BenchmarkId::new("warm_default_coupling", n), &n, |b, _| {
            b.iter(|| black_box(model_default.solve_all(&curve_default).unwrap()))
        });
        g.throughput(criterion::Throughput::Elements(1));
        let one = base.with_creepage(2.5e-4).unwrap();
        g.bench_with_input(BenchmarkId::new("cold_case", n), &n, |b, _| {
            b.iter(|| black_box(Model::build(&one).unwrap().solve(&one).unwrap()))
        });
    }
    g.finish();
}

criterion_group!(
    benches,
    creep_curve,
    end_to_end,
    assembly,
    condensation,
    frictionless_solve,
    lemke_frictional,
    formulation_and_normtang,
    scale
);
criterion_main!(benches);
