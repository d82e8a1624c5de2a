//! Criterion benchmark of two finite bodies (issue 34): a 50-point twin-disc creep curve at 400 contact elements
//! per disc — both discs meshed and condensed once (`Model::build`), then the 50 creepages solved on the one
//! model — against the same curve of one BEM wheel on an elastic half-plane at the same element count. The issue
//! asks the twin disc to cost no more than twice the one-wheel curve; that is this benchmark's figure, never a unit
//! test's bound.
//!
//! - `two_bodies_creep_curve/{twin_disc, wheel_on_half_plane}/400`: build + 50 solves (ξ = 0.02 … 1.0 of the
//!   critical creepage μa/R*), constant elements, 96 other elements per body, the active-set solver with warm
//!   starts (`Model::solve_all`), faer sequential. Both at P giving a = 0.01·R₁ = 0.4 mm with R* = 20 mm: the twin
//!   disc of R₁ = R₂ = 40 mm, the one wheel of R = 20 mm on a half-plane of the same steel.
//!
//! Run: `cargo bench --bench two_bodies`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::pipeline::Model;
use rollbem::scene::Scene;
use std::hint::black_box;
use std::path::Path;

const N: usize = 400;

fn twin_disc() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/two_bodies/twin-disc-creep.toml");
    Scene::from_file(&path)
        .unwrap()
        .edit(|d| {
            d.mesh.element = rollbem::scene::ElementKind::Constant;
            d.mesh.contact_elements = N;
            d.solvers = rollbem::scene::document::SolversTable::using(&["active_set"]);
        })
        .unwrap()
}

fn wheel_on_half_plane() -> Scene {
    let text = format!(
        r#"
name = "wheel-on-half-plane"
[wheel]
radius = 20.0
youngs_modulus = 210000.0
poisson_ratio = 0.3
support = {{ kind = "hub", radius = 4.0 }}
[counter_body]
kind = "half_plane"
youngs_modulus = 210000.0
poisson_ratio = 0.3
[mesh]
element = "constant"
contact_arc_deg = 2.8647889756541161
contact_elements = {N}
other_elements = 96
[contact]
friction = 0.3
[drive]
normal_load = 724.982920059183
[rolling]
mode = "steady"
creepage = 1.8e-3
direction = 1
[solvers]
use = ["active_set"]
"#
    );
    Scene::from_toml(&text, Path::new("wheel-on-half-plane.toml")).unwrap()
}

fn creep_curve(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("two_bodies_creep_curve");
    g.sample_size(10);
    let critical = 0.3 * 0.4 / 20.0;
    for (name, base) in [("twin_disc", twin_disc()), ("wheel_on_half_plane", wheel_on_half_plane())] {
        let curve: Vec<Scene> = (1..=50).map(|k| base.with_creepage(critical * 0.02 * k as f64).unwrap()).collect();
        // Every point of the curve solves (checked once, outside the timing).
        let reports = Model::build(&base).unwrap().solve_all(&curve).unwrap();
        let solved = reports.iter().flat_map(|r| &r.runs).all(|r| r.status == rollbem::status::Status::Solved);
        assert!(solved, "{name}: a creep-curve point did not solve");
        g.bench_with_input(BenchmarkId::new(name, N), &N, |b, _| {
            b.iter(|| {
                let model = Model::build(&base).unwrap();
                black_box(model.solve_all(&curve).unwrap())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, creep_curve);
criterion_main!(benches);
