//! The report's section on 3D steady rolling (issue 36): Kalker's creep coefficients from the exact theory
//! (`halfspace::rolling::linear_coefficients`) against Table E.3 as the mesh refines, and FASTSIM (`crate::fastsim`)
//! against the exact theory on Polach's Eurosprinter creep curve (CONTACT's `tractcurv.inp`): each formulation's
//! error in `F_x/(μF_n)` against the exact theory on a fine grid, and its time per case. Computed afresh by every
//! `rollbem report` (about half a minute, most of it the finest Kalker grids).

use super::{Figs, Result};
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::fastsim::{self, Bound, Contact, Creepages, Direction, Flexibility, Grid, Options};
use crate::halfspace::normal::{self, Drive, NormalSettings};
use crate::halfspace::rolling::{self, RollingDrive, RollingSettings, RollingStop, SteadyRolling};
use crate::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use crate::plot::{Chart, Series, Style};
use crate::theory::{kalker, Hertz3D};
use std::fmt::Write as _;
use std::time::Instant;

/// The meshes of the Kalker table: elements across the ellipse's smaller diameter.
const ACROSS: [usize; 4] = [20, 40, 80, 160];
/// The ellipses of the Kalker table (a/b) at ν = 0.25, as issue 36 asks.
const RATIOS: [f64; 3] = [0.2, 1.0, 5.0];

/// Append the section to `md`, its figure to `figs`.
pub(super) fn section(md: &mut String, figs: &mut Figs<'_>) -> Result<()> {
    writeln!(md, "\n## 3D steady rolling: Kalker's exact theory and FASTSIM\n").unwrap();
    kalker_table(md)?;
    creep_curve(md, figs)
}

/// Kalker's coefficients from full adhesion against Table E.3, per ellipse and mesh.
fn kalker_table(md: &mut String) -> Result<()> {
    writeln!(
        md,
        "### Kalker's creep coefficients from the exact theory\n\n\
         The exact steady-rolling solver in full adhesion (`halfspace::rolling::linear_coefficients`: an ellipse of \
         semi-axes a along the rolling direction and b, ν = 0.25, the creepages one at a time, nothing slipping) \
         against Kalker's Table E.3 (`theory::kalker`), as the mesh refines (elements across the smaller \
         diameter). Errors are relative; C32/C23 = −1 is Betti's reciprocity.\n\n\
         | a/b | across | elements | C11 | error | C22 | error | C23 | error | C32/C23 | C33 | products | seconds |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    )
    .unwrap();
    let mut finest: f64 = 0.0;
    for ratio in RATIOS {
        let (a, b) = if ratio <= 1.0 { (ratio, 1.0) } else { (1.0, 1.0 / ratio) };
        let t = kalker::creep_coefficients(a, b, 0.25)?;
        for n in ACROSS {
            let t0 = Instant::now();
            let k = rolling::linear_coefficients(a, b, 0.25, n, &Cancel::never())?;
            let secs = t0.elapsed().as_secs_f64();
            let e = [(k.c11 - t.c11) / t.c11, (k.c22 - t.c22) / t.c22, (k.c23 - t.c23) / t.c23];
            if n == ACROSS[ACROSS.len() - 1] {
                finest = e.iter().fold(finest, |m, v| m.max(v.abs()));
            }
            writeln!(
                md,
                "| {ratio} | {n} | {} | {:.4} | {:+.2} % | {:.4} | {:+.2} % | {:.4} | {:+.2} % | {:.6} | {:.4} | {} | {secs:.2} |",
                k.elements,
                k.c11,
                100.0 * e[0],
                k.c22,
                100.0 * e[1],
                k.c23,
                100.0 * e[2],
                k.c32 / k.c23,
                k.c33,
                k.products
            )
            .unwrap();
        }
    }
    let n = ACROSS[ACROSS.len() - 1];
    let verdict = if finest <= 0.01 { "within" } else { "not all within" };
    writeln!(
        md,
        "\nAt {n} elements across, the nine coefficients are {verdict} 1 % of the table (largest {:.2} %). The \
         table's own values carry Kalker's discretisation (CONTACT's exact solver, extrapolated in the mesh, meets \
         them within 0.75 %: `tests/kalker.rs`).\n",
        100.0 * finest
    )
    .unwrap();
    Ok(())
}

/// The Eurosprinter contact (CONTACT's `tractcurv.inp`): a/b = 0.5 from A = 0.0008/mm, FN = 106.7 kN,
/// G = 82 000 N/mm², ν = 0.28, μ = 0.33, rolling along +x.
struct Eurosprinter {
    a: f64,
    b: f64,
    curv: (f64, f64),
}

const G: f64 = 82_000.0;
const NU: f64 = 0.28;
const FN: f64 = 106_700.0;
const MU: f64 = 0.33;

impl Eurosprinter {
    fn new() -> Result<Eurosprinter> {
        let e_star = G / (1.0 - NU);
        let bad = || ArgumentError::new("report::rolling3d", "hertz", "no Hertz contact");
        // B/A for a/b = 0.5 at A = 0.0008 (the scale of B follows A).
        let (ca, cb) = Hertz3D::curvatures_for(0.5, 1.0, e_star, FN).ok_or_else(bad)?;
        let curv = (0.0008, 0.0008 * cb / ca);
        let h = Hertz3D::from_load(curv.0, curv.1, e_star, FN).ok_or_else(bad)?;
        Ok(Eurosprinter { a: h.a_x, b: h.a_y, curv })
    }

    /// The exact pressures on CONTACT's grid layout, MX × MY over 1.1 times the ellipse.
    fn exact_setup(&self, mx: usize, my: usize) -> Result<(Influence, Vec<f64>)> {
        let (dx, dy) = (2.2 * self.a / mx as f64, 2.2 * self.b / my as f64);
        let grid = ContactGrid::new(mx, my, dx, dy, -1.1 * self.a + 0.5 * dx, -1.1 * self.b + 0.5 * dy)?;
        let body = HalfSpace::new(2.0 * G * (1.0 + NU), NU)?;
        let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
        let h = grid.sample(|x, y| self.curv.0 * x * x + self.curv.1 * y * y);
        let n = normal::solve(&inf, &h, Drive::Load(FN), &NormalSettings::new(1e-10, 10_000), &Cancel::never())?;
        Ok((inf, n.pressure))
    }
}

/// One creep curve: `F_x/(μF_n)` per creepage and the seconds per case.
struct Curve {
    name: &'static str,
    values: Vec<f64>,
    seconds: f64,
}

/// The exact theory on MX × MY along the creepages (each case started from the last).
fn exact_curve(e: &Eurosprinter, mx: usize, my: usize, xis: &[f64], name: &'static str) -> Result<Curve> {
    let (inf, p) = e.exact_setup(mx, my)?;
    let t0 = Instant::now();
    let (mut qx, mut qy) = (vec![0.0; p.len()], vec![0.0; p.len()]);
    let mut values = Vec::new();
    for &xi in xis {
        let problem = SteadyRolling::new(&p, MU, 0.0, RollingDrive::Creepage(xi, 0.0)).starting_from(&qx, &qy);
        let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-10, 100_000), &Cancel::never())?;
        if r.stop != RollingStop::Converged {
            let msg = format!("ξ = {xi}: {:?}", r.stop);
            return Err(ArgumentError::new("report::rolling3d", "exact", msg).into());
        }
        values.push(r.force.0 / (MU * FN));
        (qx, qy) = (r.qx, r.qy);
    }
    Ok(Curve { name, values, seconds: t0.elapsed().as_secs_f64() / xis.len() as f64 })
}

/// FASTSIM with `flexibility` on CONTACT's grid of the exact solution's coarse level.
fn fastsim_curve(e: &Eurosprinter, flexibility: Flexibility, xis: &[f64], name: &'static str) -> Result<Curve> {
    let contact = Contact { a: e.a, b: e.b, shear_modulus: G, nu: NU, mu: MU, normal_force: FN };
    let options =
        Options { bound: Bound::Parabolic, flexibility, direction: Direction::PlusX, grid: Grid::contact(48, 44, 1.1) };
    let t0 = Instant::now();
    let mut values = Vec::new();
    for &xi in xis {
        let s = fastsim::solve(&contact, &Creepages { xi, eta: 0.0, phi: 0.0 }, &options)?;
        values.push(s.fx / (MU * FN));
    }
    Ok(Curve { name, values, seconds: t0.elapsed().as_secs_f64() / xis.len() as f64 })
}

/// FASTSIM and the exact theory on the Eurosprinter creep curve: the table and the figure.
fn creep_curve(md: &mut String, figs: &mut Figs<'_>) -> Result<()> {
    let e = Eurosprinter::new()?;
    let xis: Vec<f64> = [1e-5, 2e-4, 4e-4, 8e-4, 1.2e-3, 1.6e-3, 2.4e-3, 3.2e-3, 4.8e-3, 8e-3, 1.6e-2, 5e-2].to_vec();
    let reference = exact_curve(&e, 96, 88, &xis, "exact, 96 × 88 (reference)")?;
    let curves = [
        exact_curve(&e, 48, 44, &xis, "exact, 48 × 44")?,
        fastsim_curve(&e, Flexibility::Weighted, &xis, "FASTSIM, Kalker 1982 (one flexibility)")?,
        fastsim_curve(&e, Flexibility::Blended, &xis, "FASTSIM, CONTACT's blended flexibilities")?,
    ];
    writeln!(
        md,
        "### FASTSIM against the exact theory: Polach's Eurosprinter creep curve\n\n\
         CONTACT's `tractcurv.inp` contact: a/b = 0.5 from A = 0.0008/mm, a = {:.3} mm, b = {:.3} mm, FN = 106.7 kN, \
         G = 82 000 N/mm², ν = 0.28, μ = 0.33, η = φ = 0, rolling along +x. The reference is the exact theory on \
         96 × 88 elements over 1.1 times the ellipse; the exact theory on CONTACT's 48 × 44 reproduces \
         `tractcurv.ref_out`'s cases 1–30 to their printed digits (`tests/rolling3d.rs`). FASTSIM (parabolic bound, \
         48 × 44 strips) in its two variants (with ξ alone both use Kalker's L1: the same numbers). Errors are in units of μFN; times per case on this machine \
         (the exact curves started each case from the last).\n\n\
         | ξ | reference FX/(μFN) | {} | {} | {} |\n|---:|---:|---:|---:|---:|",
        e.a, e.b, curves[0].name, curves[1].name, curves[2].name
    )
    .unwrap();
    let mut worst = [0.0_f64; 3];
    for (i, xi) in xis.iter().enumerate() {
        let r = reference.values[i];
        let mut line = format!("| {xi:.1e} | {r:.5} |");
        for (k, c) in curves.iter().enumerate() {
            let d = c.values[i] - r;
            worst[k] = worst[k].max(d.abs());
            write!(line, " {d:+.4} |").unwrap();
        }
        writeln!(md, "{line}").unwrap();
    }
    writeln!(md, "| largest error | | {:.4} | {:.4} | {:.4} |", worst[0], worst[1], worst[2]).unwrap();
    writeln!(
        md,
        "| time per case | {:.1} ms | {:.1} ms | {:.2} ms | {:.2} ms |\n",
        1e3 * reference.seconds,
        1e3 * curves[0].seconds,
        1e3 * curves[1].seconds,
        1e3 * curves[2].seconds
    )
    .unwrap();
    let fastest = if curves[1].seconds.min(curves[2].seconds) < curves[0].seconds { "faster" } else { "not faster" };
    writeln!(
        md,
        "FASTSIM is {fastest} than the exact theory on the same grid here ({:.2} and {:.2} ms against {:.1} ms per \
         case) and its largest error on this curve is {:.3} and {:.3} of μFN, against {:.4} for the exact theory on \
         the coarse grid: the trade-off of the simplified theory, measured.\n",
        1e3 * curves[1].seconds,
        1e3 * curves[2].seconds,
        1e3 * curves[0].seconds,
        worst[1],
        worst[2],
        worst[0]
    )
    .unwrap();
    let mut chart = Chart::new("Eurosprinter creep curve: exact theory and FASTSIM", "creepage ξ", "−FX/(μFN)").log_x();
    let line = |c: &Curve| xis.iter().zip(&c.values).map(|(x, v)| (*x, -v)).collect::<Vec<_>>();
    chart = chart.add(Series::new(reference.name, line(&reference), Style::LineMarkers));
    for c in &curves {
        chart = chart.add(Series::new(c.name, line(c), Style::Dashed));
    }
    let file = figs.save(&chart, "rolling3d-creep-curve.svg", "Eurosprinter creep curve: exact and FASTSIM".into())?;
    writeln!(md, "![Eurosprinter creep curve: exact theory and FASTSIM]({file})\n\n(−FX/(μFN) against ξ, log axis. With ξ alone both FASTSIM variants use the same flexibility L1 and their \
         curves coincide.)\n").unwrap();
    Ok(())
}
