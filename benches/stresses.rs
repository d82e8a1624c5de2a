//! Criterion benchmarks of the subsurface stress evaluation ([`rollbem::stresses`]), the field only (the contact is
//! solved once, outside the timing), with stable names:
//!
//! - `stresses/half_plane/100x50`: the half-plane's closed-form strips, 100 contact strips on |x| ≤ 1.25a (the 80
//!   inside the contact loaded, p and q = μp on each: full sliding), on a 100 × 50 grid (|x| ≤ 1.5a, 0 ≤ z ≤ 3a).
//! - `stresses/bem_wheel/100x50`: the BEM wheel (constant elements, 100 on the contact, 200 elsewhere, hub) at
//!   a/R = 0.0025 under the same kind of contact: the boundary solution from the kept response, then the Somigliana
//!   identity at 100 × 50 points (|x| ≤ 1.25a, 0.2a ≤ z ≤ 3a). The issue's target: under 0.5 s.
//!
//! Run with `cargo bench --bench stresses`.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbem::pipeline::run_scene;
use rollbem::pipeline::stages::blocks_for;
use rollbem::scene::Scene;
use rollbem::stresses::StressEvaluator;
use std::hint::black_box;
use std::path::Path;

const R: f64 = 460.0;
const E: f64 = 210000.0;
const NU: f64 = 0.3;

/// The steel wheel at a/R = 0.0025 (a = 1.15 mm) in full sliding (μ = 0.3, Q = μP), as `model`, with 100 contact
/// elements on |x| ≤ 1.25a and a 100 × 50 `[stresses]` grid.
fn scene(model: &str) -> Scene {
    let a = 0.0025 * R;
    let p = rollbem::theory::Hertz2D::from_half_width(a, R, E / (1.0 - NU * NU)).load;
    let (body, other, depth0, half) = if model == "bem" {
        ("support = { kind = \"hub\", radius = 100.0 }", "other_elements = 200", 0.2 * a, 1.25 * a)
    } else {
        ("", "", 0.0, 1.5 * a)
    };
    let text = format!(
        r#"
name = "bench-stresses"
[wheel]
radius = {R}
youngs_modulus = {E}
poisson_ratio = {NU}
model = "{model}"
{body}
[mesh]
element = "constant"
contact_half_width = {hw}
contact_elements = 100
{other}
[contact]
friction = 0.3
coupling = false
[drive]
normal_load = {p}
tangential_load = {q}
[solvers]
use = ["lemke"]
[stresses]
x = [{x0}, {half}]
depth = [{depth0}, {z1}]
points = [100, 50]
"#,
        hw = 1.25 * a,
        q = 0.3 * p,
        x0 = -half,
        z1 = 3.0 * a
    );
    Scene::from_toml(&text, Path::new("bench")).expect("bench scene")
}

fn stresses(c: &mut Criterion) {
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("stresses");
    g.sample_size(20);
    for (name, model) in [("half_plane", "half_plane"), ("bem_wheel", "bem")] {
        let s = scene(model);
        let report = run_scene(&s).expect("bench scene runs");
        assert_eq!(report.runs[0].status, rollbem::solvers::Status::Solved, "{}", report.runs[0].message);
        let nodes = report.runs[0].nodes.clone();
        let built = rollbem::source::build(&s, blocks_for(&s)).expect("source");
        let ev = StressEvaluator::new(&s, &built).expect("grid accepted").expect("[stresses] given");
        g.bench_function(format!("{name}/100x50"), |b| b.iter(|| black_box(ev.evaluate(black_box(&nodes)))));
    }
    g.finish();
}

criterion_group!(benches, stresses);
criterion_main!(benches);
