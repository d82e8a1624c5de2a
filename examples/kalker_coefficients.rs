//! Kalker's creep coefficients C11, C22, C23 (and C32, C33) from rollbem's exact steady rolling
//! (`halfspace::rolling`) in full adhesion, against Kalker's Table E.3 (`theory::kalker`), as the mesh refines:
//! the convergence table of issue 36. An elliptic contact of semi-axes a (rolling direction x) and b, G = 1,
//! the friction bound far above any shear (μ = 1e4 on a unit pressure, creepages of order one: nothing slips), the creepages one at a
//! time. `Fx = −G c² C11 ξ`, `Fy = −G c² C22 η − G c³ C23 φ`, `Mz = −G c³ C32 η − G c⁴ C33 φ` (c = √(ab)).
//!
//! Run: `cargo run --release --example kalker_coefficients -- [a/b ...] [--nu 0.25] [--levels 10,20,40]`
//! (default a/b = 0.2 1 5, ν = 0.25, 10, 20, 40, 80 elements across the smaller semi-axis' diameter).

use rollbem::cancel::Cancel;
use rollbem::halfspace::rolling::{self, RollingDrive, RollingSettings, SteadyRolling};
use rollbem::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use rollbem::theory::kalker;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut ratios = Vec::new();
    let (mut nu, mut levels) = (0.25, vec![10, 20, 40, 80]);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--nu" => nu = it.next().ok_or("--nu needs a value")?.parse()?,
            "--levels" => {
                levels =
                    it.next().ok_or("--levels needs a list")?.split(',').map(|v| v.parse()).collect::<Result<_, _>>()?
            }
            v => ratios.push(v.parse::<f64>()?),
        }
    }
    if ratios.is_empty() {
        ratios = vec![0.2, 1.0, 5.0];
    }
    println!("a/b | nu | elements across 2·min(a,b) | elements in contact | C11 | C22 | C23 | C32 | C33 | C11 err | C22 err | C23 err | products | seconds");
    for &ratio in &ratios {
        let (a, b) = if ratio <= 1.0 { (ratio, 1.0) } else { (1.0, 1.0 / ratio) };
        let table = kalker::creep_coefficients(a, b, nu)?;
        for &n in &levels {
            let t0 = Instant::now();
            let (c, count, products) = coefficients(a, b, nu, n)?;
            let err = |x: f64, r: f64| (x - r) / r;
            println!(
                "{ratio} | {nu} | {n} | {count} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:+.2e} | {:+.2e} | {:+.2e} | {products} | {:.2}",
                c[0],
                c[1],
                c[2],
                c[3],
                c[4],
                err(c[0], table.c11),
                err(c[1], table.c22),
                err(c[2], table.c23),
                t0.elapsed().as_secs_f64()
            );
        }
    }
    Ok(())
}

/// `[C11, C22, C23, C32, C33]`, the elements in contact and the products, with `n` elements across `2 min(a, b)`.
fn coefficients(a: f64, b: f64, nu: f64, n: usize) -> Result<([f64; 5], usize, usize), Box<dyn std::error::Error>> {
    let h = 2.0 * a.min(b) / n as f64;
    let (mx, my) = ((2.0 * a / h).round() as usize + 2, (2.0 * b / h).round() as usize + 2);
    let grid = ContactGrid::new(mx, my, h, h, -0.5 * (mx - 1) as f64 * h, -0.5 * (my - 1) as f64 * h)?;
    let body = HalfSpace::new(2.0 * (1.0 + nu), nu)?; // G = 1 each
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
    let p = grid.sample(|x, y| if (x / a).powi(2) + (y / b).powi(2) < 1.0 { 1.0 } else { 0.0 });
    let count = p.iter().filter(|&&v| v > 0.0).count();
    let g = 1.0; // the pair's combined modulus: 2/(1/G + 1/G) = G = 1
    let c = (a * b).sqrt();
    let settings = RollingSettings::new(1e-12, 100_000);
    let mut out = [0.0; 5];
    let mut products = 0;
    // The problem is linear (nothing slips): creepages of order one and a bound 1e4 times larger keep the stop
    // criterion (relative to max μp) far below the shears.
    let eps = 1.0;
    for (k, (xi, eta, phi)) in [(eps, 0.0, 0.0), (0.0, eps, 0.0), (0.0, 0.0, eps / c)].into_iter().enumerate() {
        let problem = SteadyRolling::new(&p, 1e4, phi, RollingDrive::Creepage(xi, eta)).with_spin_lead(0.0);
        let r = rolling::solve(&inf, &problem, &settings, &Cancel::never())?;
        assert_eq!(r.slip, 0, "full adhesion");
        products += r.products;
        match k {
            0 => out[0] = -r.force.0 / (g * c * c * xi),
            1 => {
                out[1] = -r.force.1 / (g * c * c * eta);
                out[3] = -r.moment / (g * c * c * c * eta);
            }
            _ => {
                out[2] = -r.force.1 / (g * c * c * c * phi);
                out[4] = -r.moment / (g * c * c * c * c * phi);
            }
        }
    }
    Ok((out, count, products))
}
