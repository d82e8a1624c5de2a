//! Kalker's creep coefficients C11, C22, C23 (and C32, C33) from rollbem's exact steady rolling in full adhesion
//! (`halfspace::rolling::linear_coefficients`), against Kalker's Table E.3 (`theory::kalker`), as the mesh refines:
//! the convergence table of issue 36. `Fx = −G c² C11 ξ`, `Fy = −G c² C22 η − G c³ C23 φ`,
//! `Mz = −G c³ C32 η − G c⁴ C33 φ` (c = √(ab)).
//!
//! Run: `cargo run --release --example kalker_coefficients -- [a/b ...] [--nu 0.25] [--levels 10,20,40]`
//! (default a/b = 0.2 1 5, ν = 0.25, 10, 20, 40, 80 elements across the smaller semi-axis' diameter).

use rollbem::cancel::Cancel;
use rollbem::halfspace::rolling;
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
            let k = rolling::linear_coefficients(a, b, nu, n, &Cancel::never())?;
            let (c, count, products) = ([k.c11, k.c22, k.c23, k.c32, k.c33], k.elements, k.products);
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
