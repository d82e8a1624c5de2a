//! Criterion benchmarks per pipeline stage, with size sweeps and stable names:
//!
//! - `seed_end_to_end/lemke`: the seed's frictionless scene (56 constant elements), scene to result, Lemke only.
//! - `assembly/{constant,quadratic}/N`: BEM assembly of the rearranged system for N elements.
//! - `condensation/constant/N` and `dense_lu/N`: one LU + the flexibility solves, against a bare faer LU of the
//!   same size (the condensation target is within 2× of it).
//! - `frictionless_solve/{lemke,clarabel}/n`: the frictionless load-driven problem with n contact nodes.
//!
//! Run one group with e.g. `cargo bench --bench pipeline -- assembly --quick`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::condense::{assemble_system, condense, solve_system, Blocks, Model};
use rollbem::formulation::Frictionless;
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

criterion_group!(benches, end_to_end, assembly, condensation, frictionless_solve);
criterion_main!(benches);
