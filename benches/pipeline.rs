//! Criterion benchmarks per pipeline stage, with size sweeps and stable names:
//!
//! - `seed_end_to_end/lemke`: the seed's frictionless scene (56 constant elements), scene to result, Lemke only.
//! - `assembly/{constant,quadratic}/N`: BEM assembly of the rearranged system for N elements.
//! - `condensation/constant/N` and `dense_lu/N`: one LU + the flexibility solves, against a bare faer LU of the
//!   same size (the condensation target is within 2× of it).
//! - `frictionless_solve/{lemke,clarabel}/n`: the frictionless load-driven problem with n contact nodes.
//! - `lemke_frictional/{block,dense}/m`: Lemke on frictional LCPs of m = 3n + 4 unknowns (pivots to stderr).
//! - `formulation_and_normtang/{frictional_lcp,pgs,normtang_qp}/n`: building the frictional LCP, and the two
//!   NORM-TANG solvers, with n contact nodes.
//!
//! Run one group with e.g. `cargo bench --bench pipeline -- assembly --quick`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::condense::{assemble_system, condense, solve_system, Blocks, Model};
use rollbem::formulation::{Frictional, Frictionless};
use rollbem::run::run_scene;
use rollbem::scene::{ElementKind, Scene, SolverName};
use rollbem::solvers::clarabel_qp::{self, QpSettings};
use rollbem::solvers::lemke::{self, LemkeSettings};
use std::hint::black_box;
use std::path::Path;

fn seed_scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/seed-fig6-constant.toml");
    Scene::from_file(&path).expect("seed scene")
}

/// The seed's material on a hub, `n` elements in all with a quarter of them on a 12° candidate arc.
fn scene_with(n: usize, kind: ElementKind) -> Scene {
    let mut s = seed_scene();
    s.wheel.support = rollbem::scene::Support::Hub { radius: 0.2 };
    s.mesh.element = kind;
    s.mesh.contact_arc_deg = 12.0;
    s.mesh.contact_elements = n / 4;
    s.mesh.other_elements = n - n / 4;
    s.drive.normal_load = Some(187.42);
    s
}

fn end_to_end(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut s = seed_scene();
    s.solvers.use_ = vec![SolverName::Lemke];
    let p = Path::new("seed");
    c.bench_function("seed_end_to_end/lemke", |b| b.iter(|| black_box(run_scene(&s, p).unwrap())));
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
            let model = Model::new(&scene_with(n, kind));
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
        let model = Model::new(&scene_with(n, ElementKind::Constant));
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
        let model = Model::new(&s);
        let (flex, _) = condense(&model, Blocks::Normal).unwrap();
        let prob = Frictionless::new(&s, &model, &flex).unwrap();
        let nc = flex.n();
        g.bench_with_input(BenchmarkId::new("lemke", nc), &prob, |b, p| {
            b.iter(|| black_box(lemke::solve(&p.lcp, &LemkeSettings::default())))
        });
        let kcol: Vec<f64> = (0..nc * nc).map(|i| prob.k[(i % nc, i / nc)]).collect();
        let ones = vec![1.0; nc];
        let load = prob.loads[0].load;
        g.bench_with_input(BenchmarkId::new("clarabel", nc), &prob, |b, p| {
            b.iter(|| {
                black_box(clarabel_qp::solve_frictionless(
                    &kcol,
                    nc,
                    &p.q0,
                    Some((&ones, load)),
                    &QpSettings::default(),
                ))
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
        s.wheel.poisson_ratio = 0.3;
        s.wheel.support = rollbem::scene::Support::Hub { radius: 0.25 };
        s.mesh.contact_arc_deg = 12.0;
        s.mesh.contact_elements = n;
        s.mesh.other_elements = 200;
        s.contact.friction = 0.3;
        s.drive.normal_load = Some(187.42);
        s.drive.tangential_load = Some(18.742);
        s.drive.rotation = Some(0.0);
        let model = Model::new(&s);
        let (flex, _) = condense(&model, Blocks::All).unwrap();
        let prob = Frictional::new(&s, &model, &flex);
        let m = prob.lcp.size();
        let probe = lemke::solve(&prob.lcp, &LemkeSettings::default());
        eprintln!("lemke_frictional/block/{m}: {} pivots, {:?}", probe.pivots, probe.status);
        g.bench_with_input(BenchmarkId::new("block", m), &prob, |b, p| {
            b.iter(|| black_box(lemke::solve(&p.lcp, &LemkeSettings::default())))
        });
        if n <= 200 {
            g.bench_with_input(BenchmarkId::new("dense", m), &prob, |b, p| {
                b.iter(|| black_box(lemke::solve_dense(&p.lcp, &LemkeSettings::default())))
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
        s.contact.coupling = true;
        s.wheel.poisson_ratio = 0.45;
        s.mesh.contact_elements = n;
        let model = Model::new(&s);
        let (flex, _) = condense(&model, Blocks::All).unwrap();
        g.bench_with_input(BenchmarkId::new("frictional_lcp", n), &flex, |b, f| {
            b.iter(|| black_box(Frictional::new(&s, &model, f)))
        });
        let split = rollbem::formulation::Split::new(&s, &model, &flex).unwrap();
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

criterion_group!(
    benches,
    end_to_end,
    assembly,
    condensation,
    frictionless_solve,
    lemke_frictional,
    formulation_and_normtang
);
criterion_main!(benches);
