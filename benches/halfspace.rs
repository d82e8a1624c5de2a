//! Criterion benchmarks of the 3D half-space solvers on CONTACT's performance inputs `perfc_test/norm_problm_2p` and
//! `tang_problm_2s` (the rail–wheel contact of `examples/halfspace_perfc_series.rs`: 143 × 163 elements of 0.05 mm,
//! G = 82 000 N/mm², ν = 0.28 on both bodies, approach 0.02084 mm; 12 902 elements in contact, 7 243 slipping in the
//! shift), with stable names:
//!
//! - `halfspace/normal/2p`: the normal problem by the preconditioned CG (tolerance 1e-7), the influence operators
//!   built outside the timing (the preconditioner's first build included once, then cached).
//! - `halfspace/shift/2s/cg` and `halfspace/shift/2s/fista`: the shift from rest (μ = 0.3, CONTACT's shift and
//!   rotation) at the solved pressure, by the default preconditioned nonlinear CG and by FISTA, tolerance 1e-7.
//!
//! What CONTACT takes for the same inputs (its MKL build, whole process): `reports/peer-contact3d.md`.
//! Run with `cargo bench --bench halfspace`.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::{self, Drive, NormalSettings};
use rollbem::halfspace::tangential::{self, ShiftStep, TangentialDrive, TangentialMethod, TangentialSettings};
use rollbem::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use std::hint::black_box;

/// The grid, operators and separation of `norm_problm_2p` (profile from `reference/contact3d/`).
fn case() -> (ContactGrid, Influence, Vec<f64>) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/contact3d/norm_problm_1p_profile.csv");
    let mut reader = csv::Reader::from_path(path).expect("the profile CSV");
    let p: Vec<f64> = reader.records().map(|r| r.expect("a row")[2].parse().expect("a number")).collect();
    let profile = |y: f64| {
        let t = ((y + 12.0) / 0.1).clamp(0.0, (p.len() - 1) as f64);
        let k = (t.floor() as usize).min(p.len() - 2);
        p[k] + (t - k as f64) * (p[k + 1] - p[k])
    };
    let d = 0.05;
    let grid = ContactGrid::new(143, 163, d, d, -3.55 + 0.5 * d, -6.15 + 0.5 * d).expect("grid");
    let body = HalfSpace::new(2.0 * 82000.0 * 1.28, 0.28).expect("body");
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full).expect("operators");
    let h = grid.sample(|x, y| profile(y) + x * x / (2.0 * 483.931));
    (grid, inf, h)
}

fn halfspace(c: &mut Criterion) {
    let (grid, inf, h) = case();
    let never = Cancel::never();
    let settings = NormalSettings::new(1e-7, 10_000);
    let mut group = c.benchmark_group("halfspace");
    group.sample_size(10);
    group.bench_function("normal/2p", |b| {
        b.iter(|| normal::solve(&inf, black_box(&h), Drive::Approach(0.02084), &settings, &never).expect("normal"))
    });
    let s = normal::solve(&inf, &h, Drive::Approach(0.02084), &settings, &never).expect("normal");
    assert_eq!(s.in_contact, 12902, "CONTACT's contact count");
    let cphi = 0.0008;
    let ox: Vec<f64> = grid.centres().iter().map(|c| -cphi * c.1).collect();
    let oy: Vec<f64> = grid.centres().iter().map(|c| cphi * c.0).collect();
    let step = ShiftStep::new(&s.pressure, 0.3, TangentialDrive::Shift(0.0005, -0.001)).with_offset(&ox, &oy);
    for (name, method) in
        [("shift/2s/cg", TangentialMethod::ConjugateGradient), ("shift/2s/fista", TangentialMethod::Fista)]
    {
        let set = TangentialSettings::new(1e-7, 100_000).with_method(method);
        let t = tangential::solve(&inf, &step, &set, &never).expect("shift");
        assert_eq!(t.slip, 7243, "CONTACT's slip count ({method:?})");
        group.bench_function(name, |b| {
            b.iter(|| tangential::solve(&inf, black_box(&step), &set, &never).expect("shift"))
        });
    }
    group.finish();
}

criterion_group!(benches, halfspace);
criterion_main!(benches);
