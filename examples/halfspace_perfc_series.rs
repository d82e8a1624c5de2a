//! CONTACT's performance series `perfc_test/norm_problm_1p … 8p` and `tang_problm_1s … 8s` posed to rollbem's
//! half-space solvers: a wheel on a rail, G = 82 000 N/mm², ν = 0.28 on both bodies (identical: no coupling), the
//! approach PEN = 0.02084 mm prescribed, the profile h = p(y) + x²/(2·483.931) with p(y) CONTACT's tabulated
//! rail–wheel profile (271 points from y = −12 mm by 0.1 mm, linearly interpolated;
//! `reference/contact3d/norm_problm_1p_profile.csv`), on the grid [−3.55, 3.55] × [−6.15, …] mm of MX × MY = 71 × 81,
//! 143 × 163, 287 × 323, 575 × 647 elements of 0.1/k mm (k = 1, 2, 4, 8), as CONTACT's inputs give them (see
//! `reference/contact3d/README.md` and `benches/peer/README.md`, "CONTACT in 3D, MKL build").
//!
//! - `kp` (`norm_problm_kp`): the frictionless normal problem, tolerance 1e-7 (CONTACT's EPS).
//! - `ks` (`tang_problm_ks`): the same normal problem, then one shift from zero tractions with μ = 0.3 and CONTACT's
//!   rigid shift W = (CKSI − CPHI·y, CETA + CPHI·x), CKSI = 0.0005 mm, CETA = −0.001 mm, CPHI = 0.0008 rad (a
//!   uniform shift plus a rotation: the rotation enters as the slip offset of each element), tolerance 1e-7.
//!
//! Prints, per case: the elements in contact, stick and slip (CONTACT's slip counts: 1 730, 7 243, 28 260,
//! 111 191; contact 3 148, 12 902, 50 796, 200 980), the forces, the iterations, the residuals and the wall times of
//! the set-up and of each solve. Run: `cargo run --release --example halfspace_perfc_series -- 1p 4p 2s` (cases as
//! arguments; default 1p 2p 4p; `--polonsky-keer` solves the normal problems by the unpreconditioned method).

use rollbem::cancel::Cancel;
use rollbem::halfspace::normal::{self, Drive, NormalMethod, NormalSettings};
use rollbem::halfspace::rolling::{self, RollingDrive, RollingSettings, SteadyRolling};
use rollbem::halfspace::tangential::{self, ShiftStep, TangentialDrive, TangentialSettings};
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
    let mut cases: Vec<(usize, char)> = args
        .iter()
        .filter_map(|a| {
            let (k, kind) = a.split_at(a.len().saturating_sub(1));
            let kind = kind.chars().next()?;
            Some((k.parse().ok()?, kind)).filter(|_| "pscf".contains(kind))
        })
        .collect();
    if cases.is_empty() {
        cases = vec![(1, 'p'), (2, 'p'), (4, 'p')];
    }
    let body = HalfSpace::new(2.0 * 82000.0 * 1.28, 0.28)?;
    // (level, MX, MY, CONTACT's elements in contact, CONTACT's elements in slip for s, c, f)
    let series = [
        (1, 71, 81, 3148, [1730, 1872, 1872]),
        (2, 143, 163, 12902, [7243, 7735, 7757]),
        (4, 287, 323, 50796, [28260, 30181, 30263]),
        (8, 575, 647, 200980, [111191, 0, 0]),
    ];
    println!("case | grid | in contact (CONTACT) | stick | slip (CONTACT) | FN [N] | FX, FY [N] | iterations n, t | residuals n, t | set-up [s] | normal [s] | tangential [s]");
    for (k, kind) in cases {
        let Some(&(_, mx, my, contact, slips)) = series.iter().find(|c| c.0 == k) else {
            eprintln!("level {k}: not one of 1, 2, 4, 8");
            continue;
        };
        let d = 0.1 / k as f64;
        let t0 = Instant::now();
        let grid = ContactGrid::new(mx, my, d, d, -3.55 + 0.5 * d, -6.15 + 0.5 * d)?;
        let kernels = if kind == 'p' { Kernels::Normal } else { Kernels::Full };
        let inf = Influence::new(grid, body.pair(&body), kernels)?;
        let h = grid.sample(|x, y| profile(y) + x * x / (2.0 * 483.931));
        let setup = t0.elapsed().as_secs_f64();
        let settings = NormalSettings::new(1e-7, 10_000).with_method(method);
        let t1 = Instant::now();
        let s = normal::solve(&inf, &h, Drive::Approach(0.02084), &settings, &Cancel::never())?;
        let t_norm = t1.elapsed().as_secs_f64();
        let head = format!("{k}{kind} | {mx} × {my} | {} ({contact})", s.in_contact);
        let t2 = Instant::now();
        let (stick, slip, force, iterations, residual) = match kind {
            'p' => {
                println!(
                    "{head} | | | {:.2} | | {}, | {:.1e}, | {setup:.3} | {t_norm:.3} |",
                    s.load, s.iterations, s.residual
                );
                continue;
            }
            's' => {
                let cphi = 0.0008;
                let ox: Vec<f64> = grid.centres().iter().map(|c| -cphi * c.1).collect();
                let oy: Vec<f64> = grid.centres().iter().map(|c| cphi * c.0).collect();
                let step =
                    ShiftStep::new(&s.pressure, 0.3, TangentialDrive::Shift(0.0005, -0.001)).with_offset(&ox, &oy);
                let t = tangential::solve(&inf, &step, &TangentialSettings::new(1e-7, 100_000), &Cancel::never())?;
                (t.stick, t.slip, t.force, t.iterations, t.residual)
            }
            _ => {
                // CONTACT's tang_problm_kc / kf: CKSI = 0.0005, CETA = 0, CPHI = 0.0003, or FX/(μFN) = −0.573,
                // FY/(μFN) = −0.327 with the same spin; μ = 0.3, rolling along +x.
                let drive = if kind == 'c' {
                    RollingDrive::Creepage(0.0005, 0.0)
                } else {
                    RollingDrive::Force(-0.573 * 0.3 * s.load, -0.327 * 0.3 * s.load)
                };
                let problem = SteadyRolling::new(&s.pressure, 0.3, 0.0003, drive);
                let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-7, 100_000), &Cancel::never())?;
                eprintln!(
                    "{k}{kind}: creepage {:.6e}, {:.6e}, moment {:.1}, Newton steps {}, stop {:?}",
                    r.creepage.0, r.creepage.1, r.moment, r.newton_steps, r.stop
                );
                (r.stick, r.slip, r.force, r.products, r.residual)
            }
        };
        let t_tang = t2.elapsed().as_secs_f64();
        let reference = slips[if kind == 's' {
            0
        } else if kind == 'c' {
            1
        } else {
            2
        }];
        println!(
            "{head} | {stick} | {slip} ({reference}) | {:.2} | {:.1}, {:.1} | {}, {iterations} | {:.1e}, {residual:.1e} | {setup:.3} | {t_norm:.3} | {t_tang:.3}",
            s.load, force.0, force.1, s.iterations, s.residual
        );
    }
    Ok(())
}
