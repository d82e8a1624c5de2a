//! Criterion benchmarks of the problems beyond the seed's static one, with stable names:
//!
//! - `half_plane/end_to_end/active_set/1000`: a frictional half-plane scene of 1000 contact elements, scene to
//!   result (influence matrix, problem, solve, post). Target: under 1 s.
//! - `half_plane/influence/N` against `half_plane/n2_write/N`: the closed-form influence blocks (four N×N blocks,
//!   uniform grid: Toeplitz part plus datum column) against a plain write of four N×N vectors (the memory floor).
//! - `rolling/creep_curve/50x200`: a 50-point creep curve (steady rolling, creepage-driven, 200 contact elements),
//!   the points in parallel (rayon). Target: under 2 s.
//! - `rolling/{steady,static}/200`: one steady-rolling solve against the static frictional solve of the same mesh
//!   and load (Lemke). Target: steady ≤ 1.5× static.
//! - `history/{lemke_warm,lemke_cold,pgs}/100x200`: a Mindlin–Deresiewicz path of 100 substeps on 200 contact
//!   elements, Lemke warm-started from the previous substep's basis, Lemke cold, and PGS (warm-started from the
//!   previous substep's tractions). Target: under 1 s.
//!
//! - `toeplitz/{fft,dense}/n`: one K x with a Toeplitz matrix of n rows, by FFT ([`rollbem::toeplitz`]) and by
//!   faer's dense product: the crossover sets `toeplitz::FFT_ABOVE`.
//! - `toeplitz2d/apply/m`: one K v on an m × m grid by 2D FFT ([`rollbem::toeplitz2d`]), the product a 3D
//!   half-space solver iterates on (m² elements: 4 096 to 262 144); `toeplitz2d/build/m` the spectrum's set-up.
//! - `halfspace/kernel_table_100x100`: the closed-form kernel quadrant of a 100 × 100 grid of a dissimilar pair
//!   (10⁴ offsets, six coefficients each; [`rollbem::halfspace::UniformGrid::kernel_table`]).
//!
//! Run one group with e.g. `cargo bench --bench physics -- history --quick`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rayon::prelude::*;
use rollbem::halfplane::HalfPlane;
use rollbem::pipeline::run_scene;
use rollbem::scene::Scene;
use std::hint::black_box;
use std::path::Path;

fn scene(text: &str) -> Scene {
    Scene::from_toml(text, Path::new("<bench>")).expect("bench scene")
}

/// The steel wheel (R = 460 mm, E = 210 GPa, ν = 0.3, P = 20 kN/mm: a = 7.12 mm) as a half-plane, `n` constant
/// elements on |x| ≤ 9 mm, decoupled, μ = 0.3, with the given drive/rolling/path text and solvers.
fn half_plane(n: usize, body: &str, solvers: &str) -> Scene {
    scene(&format!(
        "name = \"bench\"\n[wheel]\nradius = 460.0\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3\n\
         model = \"half_plane\"\nprofile = \"parabola\"\n[mesh]\nelement = \"constant\"\ncontact_half_width = 9.0\n\
         contact_elements = {n}\n[contact]\nfriction = 0.3\ncoupling = false\n{body}\n[solvers]\nuse = {solvers}\n"
    ))
}

fn half_plane_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("half_plane");
    g.sample_size(10);
    let s = half_plane(1000, "[drive]\nnormal_load = 20000.0\ntangential_load = 3000.0", r#"["active_set"]"#);
    g.bench_function(BenchmarkId::new("end_to_end/active_set", 1000), |b| b.iter(|| black_box(run_scene(&s).unwrap())));
    for n in [250usize, 1000] {
        let hp = HalfPlane::new(210000.0, 0.3, 460.0).unwrap();
        let h = 18.0 / n as f64;
        g.bench_with_input(BenchmarkId::new("influence", n), &n, |b, &n| {
            b.iter(|| black_box(hp.influence_blocks_uniform(-9.0, h, n).unwrap()))
        });
        g.bench_with_input(BenchmarkId::new("n2_write", n), &n, |b, &n| {
            // Four row-major n×n blocks written once each, the layout of `InfluenceBlocks`.
            b.iter(|| {
                let m: Vec<Vec<f64>> = (0..4).map(|k| (0..n * n).map(|i| (i + k) as f64).collect()).collect();
                black_box(m)
            })
        });
    }
    g.finish();
}

fn rolling_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("rolling");
    g.sample_size(10);
    // Creepages spanning partial slip up to twice the saturation creepage μa/R = 4.65e-3.
    let scenes: Vec<Scene> = (0..50)
        .map(|k| {
            let xi = 1e-2 * (k as f64 + 0.5) / 50.0;
            half_plane(
                200,
                &format!(
                    "[drive]\nnormal_load = 20000.0\n[rolling]\nmode = \"steady\"\ndirection = 1\ncreepage = {xi}"
                ),
                r#"["lemke"]"#,
            )
        })
        .collect();
    g.bench_function("creep_curve/50x200", |b| {
        b.iter(|| {
            let q: Vec<f64> =
                scenes.par_iter().map(|s| run_scene(s).unwrap().runs[0].resultants.unwrap().tangential).collect();
            black_box(q)
        })
    });
    let load = "[drive]\nnormal_load = 20000.0\ntangential_load = -4107.56";
    let steady = half_plane(200, &format!("{load}\n[rolling]\nmode = \"steady\"\ndirection = 1"), r#"["lemke"]"#);
    let static_ = half_plane(200, load, r#"["lemke"]"#);
    for (name, s) in [("steady", &steady), ("static", &static_)] {
        g.bench_function(BenchmarkId::new(name, 200), |b| b.iter(|| black_box(run_scene(s).unwrap())));
    }
    g.finish();
}

fn history_group(c: &mut Criterion) {
    let mut g = c.benchmark_group("history");
    g.sample_size(10);
    // P, then Q to +Q* (20 substeps), to −Q* (40), back to +Q* (40): 101 substeps.
    let path = "[[steps]]\nnormal_load = 20000.0\n\
                [[steps]]\nnormal_load = 20000.0\ntangential_load = 3000.0\nsubsteps = 20\n\
                [[steps]]\nnormal_load = 20000.0\ntangential_load = -3000.0\nsubsteps = 40\n\
                [[steps]]\nnormal_load = 20000.0\ntangential_load = 3000.0\nsubsteps = 40";
    let cases = [
        ("lemke_warm", half_plane(200, path, r#"["lemke"]"#)),
        ("lemke_cold", half_plane(200, &format!("{path}\n"), "[\"lemke\"]\n[solvers.lemke]\nwarm_start = false")),
        ("pgs", half_plane(200, path, r#"["pgs"]"#)),
    ];
    for (name, s) in &cases {
        let r = run_scene(s).unwrap();
        let work: u64 =
            r.steps.iter().map(|st| st.runs[0].work.get("pivots").or(st.runs[0].work.get("sweeps")).unwrap_or(0)).sum();
        eprintln!("history/{name}/100x200: {} substeps, work {work} (pivots or sweeps)", r.steps.len());
        g.bench_function(BenchmarkId::new(*name, "100x200"), |b| b.iter(|| black_box(run_scene(s).unwrap())));
    }
    g.finish();
}

/// The Toeplitz product by FFT against faer's dense product with the same matrix (a half-plane K_NN on a uniform
/// grid), n contact nodes: where the FFT starts to win decides `toeplitz::FFT_ABOVE`.
fn toeplitz_group(c: &mut Criterion) {
    use rollbem::toeplitz::Toeplitz;
    faer::set_global_parallelism(faer::Par::Seq);
    let mut g = c.benchmark_group("toeplitz");
    for n in [16usize, 32, 48, 64, 96, 128, 192, 256, 512, 841, 1600] {
        let t = |k: i64| -(1.0 + k.unsigned_abs() as f64).ln() + if k >= 0 { 0.3 } else { -0.2 };
        let col: Vec<f64> = (0..n).map(|i| t(i as i64)).collect();
        let row: Vec<f64> = (0..n).map(|j| t(-(j as i64))).collect();
        let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| t(i as i64 - j as i64));
        let op = Toeplitz::from_parts(&col, &row).unwrap();
        let x = faer::Col::<f64>::from_fn(n, |i| (i as f64 * 0.37).sin());
        let xs: Vec<f64> = x.iter().copied().collect();
        g.bench_with_input(BenchmarkId::new("fft", n), &n, |b, _| b.iter(|| black_box(op.apply(&xs))));
        g.bench_with_input(BenchmarkId::new("dense", n), &n, |b, _| b.iter(|| black_box(&dense * &x)));
    }
    g.finish();
}

/// The two-level Toeplitz product by 2D FFT on m × m grids (a half-space-like kernel 1/ρ with its singular offset
/// replaced by a finite value), and the set-up of its spectrum.
fn toeplitz2d_group(c: &mut Criterion) {
    use rollbem::toeplitz2d::{Scratch, Toeplitz2d};
    let mut g = c.benchmark_group("toeplitz2d");
    g.sample_size(10);
    let kernel = |dx: isize, dy: isize| {
        let r = ((dx * dx + dy * dy) as f64).sqrt();
        if r == 0.0 {
            3.5
        } else {
            1.0 / r
        }
    };
    for m in [64usize, 128, 256, 512] {
        g.bench_with_input(BenchmarkId::new("build", m), &m, |b, &m| {
            b.iter(|| black_box(Toeplitz2d::new(m, m, kernel).unwrap()))
        });
        let op = Toeplitz2d::new(m, m, kernel).unwrap();
        let v: Vec<f64> = (0..m * m).map(|k| (k as f64 * 0.37).sin()).collect();
        let (mut out, mut scratch) = (vec![0.0; m * m], Scratch::default());
        g.bench_with_input(BenchmarkId::new("apply", m), &m, |b, _| {
            b.iter(|| op.apply_into(black_box(&v), &mut out, &mut scratch).unwrap())
        });
    }
    g.finish();
}

/// The half-space kernel's set-up (closed forms of every offset of one quadrant).
fn halfspace_group(c: &mut Criterion) {
    use rollbem::halfspace::HalfSpace;
    let mut g = c.benchmark_group("halfspace");
    g.sample_size(20);
    let pair = HalfSpace::new(210e9, 0.3).unwrap().pair(&HalfSpace::new(70e9, 0.33).unwrap());
    let grid = rollbem::halfspace::UniformGrid::new(pair, 100, 100, 1e-4, 1.5e-4).unwrap();
    g.bench_function("kernel_table_100x100", |b| b.iter(|| black_box(black_box(&grid).kernel_table())));
    g.finish();
}

criterion_group!(
    benches,
    half_plane_group,
    rolling_group,
    history_group,
    toeplitz_group,
    toeplitz2d_group,
    halfspace_group
);
criterion_main!(benches);
