//! CONTACT's performance series `perfc_test/norm_problm_1p … 8p` posed to rollbem's half-space normal solver:
//! a wheel on a rail, frictionless, approach PEN = 0.02084 mm prescribed, G = 82 000 N/mm², ν = 0.28 on both
//! bodies, the profile h = p(y) + x²/(2·483.931) with p(y) CONTACT's tabulated rail–wheel profile (271 points from
//! y = −12 mm by 0.1 mm, linearly interpolated; `reference/contact3d/norm_problm_1p_profile.csv`), on the grid
//! [−3.55, 3.55] × [−6.15, …] mm of MX × MY = 71 × 81, 143 × 163, 287 × 323, 575 × 647 elements of 0.1/k mm
//! (k = 1, 2, 4, 8: CONTACT's 1p, 2p, 4p, 8p, as its inputs give them; see `reference/contact3d/README.md` and `benches/peer/README.md`, "CONTACT in 3D, MKL build").
//!
//! Prints, per level: the elements in contact (CONTACT's: 3 148, 12 902, 50 796, 200 980), the normal force, the
//! iterations, the residual and the wall time of the set-up and of the solve. Run:
//! `cargo run --release --example halfspace_norm_series -- 1 2 4` (levels as arguments; default 1 2 4; with
//! `--polonsky-keer` the unpreconditioned method instead of the default FFT-preconditioned CG).

use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::{self, Drive, NormalMethod, NormalSettings};
use rollbem::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/contact3d/norm_problm_1p_profile.csv");
    let mut reader = csv::Reader::from_path(path)?;
    let mut p = Vec::new();
    for rec in reader.records() {
        p.push(rec?[2].parse::<f64>()?);
    }
    let profile = |y: f64| {
        let t = ((y + 12.0) / 0.1).clamp(0.0, (p.len() - 1) as f64);
        let k = (t.floor() as usize).min(p.len() - 2);
        p[k] + (t - k as f64) * (p[k + 1] - p[k])
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let method = if args.iter().any(|a| a == "--polonsky-keer") {
        NormalMethod::PolonskyKeer
    } else {
        NormalMethod::PreconditionedCg
    };
    let levels: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let levels = if levels.is_empty() { vec![1, 2, 4] } else { levels };
    let body = HalfSpace::new(2.0 * 82000.0 * 1.28, 0.28)?;
    // (level, MX, MY, CONTACT's elements in contact)
    let series = [(1, 71, 81, 3148), (2, 143, 163, 12902), (4, 287, 323, 50796), (8, 575, 647, 200980)];
    println!("level | grid | in contact (CONTACT) | FN [N] | iterations | residual | set-up [s] | solve [s]");
    for k in levels {
        let Some(&(_, mx, my, theirs)) = series.iter().find(|c| c.0 == k) else {
            eprintln!("level {k}: not one of 1, 2, 4, 8");
            continue;
        };
        let d = 0.1 / k as f64;
        let t0 = Instant::now();
        let grid = ContactGrid::new(mx, my, d, d, -3.55 + 0.5 * d, -6.15 + 0.5 * d)?;
        let inf = Influence::new(grid, body.pair(&body), Kernels::Normal)?;
        let h = grid.sample(|x, y| profile(y) + x * x / (2.0 * 483.931));
        let setup = t0.elapsed().as_secs_f64();
        let settings = NormalSettings::new(1e-7, 10_000).with_method(method);
        let t1 = Instant::now();
        let s = normal::solve(&inf, &h, Drive::Approach(0.02084), &settings, &Cancel::never())?;
        let solve = t1.elapsed().as_secs_f64();
        println!(
            "{k}p | {mx} × {my} | {} ({theirs}) | {:.2} | {} | {:.1e} | {setup:.3} | {solve:.3}",
            s.in_contact, s.load, s.iterations, s.residual
        );
    }
    Ok(())
}
