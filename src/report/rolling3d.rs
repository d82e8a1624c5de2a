//! The report's section on 3D steady rolling (issue 36): Kalker's creep coefficients from the exact theory
//! (`halfspace::rolling::linear_coefficients`) against Table E.3 as the mesh refines, and FASTSIM (`crate::fastsim`)
//! against the exact theory on Polach's Eurosprinter creep curve (CONTACT's `tractcurv.inp`): each formulation's
//! error in `F_x/(μF_n)` against the exact theory on a fine grid, and its time per case. Computed afresh by every
//! `rollbem report` (about half a minute, most of it the finest Kalker grids).

use super::{Figs, Result};
use crate::cancel::Cancel;
use crate::creeptable::{self, CreepTable, TableSpec};
use crate::error::ArgumentError;
use crate::fastsim::{self, Bound, Contact, Creepages, Direction, Flexibility, Grid, Options};
use crate::halfspace::normal::{self, Drive, NormalSettings};
use crate::halfspace::rolling::{self, RollingDrive, RollingSettings, RollingStop, SteadyRolling};
use crate::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use crate::plot::{Chart, Series, Style};
use crate::theory::{kalker, Hertz3D};
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

/// The meshes of the Kalker table: elements across the ellipse's smaller diameter.
const ACROSS: [usize; 4] = [20, 40, 80, 160];
/// The ellipses of the Kalker table (a/b) at ν = 0.25, as issue 36 asks.
const RATIOS: [f64; 3] = [0.2, 1.0, 5.0];

/// Append the section to `md`, its figures to `figs`; the creep-force table's spec is read from `reference`'s
/// `creep-tables/` when it is there.
pub(super) fn section(md: &mut String, figs: &mut Figs<'_>, reference: &Path) -> Result<()> {
    writeln!(md, "\n## 3D steady rolling: Kalker's exact theory, FASTSIM and FaStrip\n").unwrap();
    kalker_table(md)?;
    creep_curve(md, figs)?;
    spin_case(md)?;
    // The creep-force table is an input of the reference folder: a folder without it gets no such section.
    let spec = reference.join("creep-tables").join(CREEP_TABLE);
    if spec.is_file() {
        creep_table(md, figs, &spec)?;
    }
    let exact = reference.join("creep-tables").join(EXACT_TABLE);
    if exact.is_file() {
        table_comparison(md, &exact)?;
    }
    Ok(())
}

/// A table's errors |(ΔFx', ΔFy')| against a reference table on the same axes, over the cases both answer.
struct TableErrors {
    /// Cases compared.
    n: usize,
    /// The sum of their errors.
    sum: f64,
    /// The largest error and its case.
    worst: (f64, usize),
    /// Cases with an error above 0.05.
    over: usize,
}

impl TableErrors {
    fn of(reference: &CreepTable, table: &CreepTable) -> TableErrors {
        let mut t = TableErrors { n: 0, sum: 0.0, worst: (0.0, 0), over: 0 };
        for i in 0..reference.status.len().min(table.status.len()) {
            let (e, s) = (&reference.forces[3 * i..3 * i + 2], &table.forces[3 * i..3 * i + 2]);
            if e.iter().chain(s).any(|v| !v.is_finite()) {
                continue;
            }
            let err = (s[0] - e[0]).hypot(s[1] - e[1]);
            t.n += 1;
            t.sum += err;
            t.over += usize::from(err > 0.05);
            if err > t.worst.0 {
                t.worst = (err, i);
            }
        }
        t
    }
}

/// The exact theory's creep-force table, the reference of [`table_comparison`].
const EXACT_TABLE: &str = "exact-usetab.toml";

/// The simplified theories over the exact table's whole grid: each engine's table on the same axes (the spec's
/// engine, options and grid replaced), its error `|ΔF'| = |(ΔFx', ΔFy')|` (in μN) against the exact table, and its
/// time per case.
fn table_comparison(md: &mut String, exact_path: &Path) -> Result<()> {
    let text = std::fs::read_to_string(exact_path)
        .map_err(|source| crate::error::Error::Io { path: exact_path.to_path_buf(), source })?;
    let t0 = Instant::now();
    let (exact, _) = creeptable::compute_spec(&TableSpec::from_toml(&text, exact_path)?, exact_path)?;
    let exact_ms = 1e3 * t0.elapsed().as_secs_f64() / exact.status.len() as f64;
    let spec_of = |engine: &str, options: &str, grid: usize| -> Result<TableSpec> {
        let mut doc: toml::Table = toml::from_str(&text)
            .map_err(|e| crate::error::Error::Parse { path: exact_path.to_path_buf(), message: e.to_string() })?;
        doc.insert("engine".into(), toml::Value::String(engine.into()));
        if engine != "exact" {
            let options: toml::Table = toml::from_str(options).unwrap_or_default();
            doc.insert("options".into(), toml::Value::Table(options));
        }
        let grid: toml::Table = toml::from_str(&format!("mx = {grid}\nmy = {grid}")).unwrap_or_default();
        doc.insert("grid".into(), toml::Value::Table(grid));
        TableSpec::from_toml(&toml::to_string(&doc).unwrap_or_default(), exact_path)
    };
    let engines = [
        ("FASTSIM, Kalker 1982 (one flexibility, parabolic bound)", "fastsim", ""),
        (
            "FASTSIM, CONTACT's blended flexibilities, elliptic bound",
            "fastsim",
            "flexibility = \"blended\"\nbound = \"elliptic\"",
        ),
        ("FaStrip (blended flexibilities)", "fastrip", ""),
    ];
    let shape = exact.axes.shape();
    writeln!(
        md,
        "### The simplified theories over a whole creep-force table\n\n\
         The exact theory's table `reference/creep-tables/{EXACT_TABLE}` ({} cases: ν = {:?}, a/b = {:?}, \
         {} × {} × {} normalised creepages ξ', η', φ'; 32 × 32 elements over 1.1 times the ellipse, {:.1} ms per \
         case on this machine) is the reference; each simplified theory is computed on the same axes on 100 × 100 \
         strips. The error of a case is |(ΔFx', ΔFy')| in units of μN, over the cases both answer. The reference's \
         own grid error at each engine's worst case: the exact theory there on 64 × 64 against 32 × 32.\n\n\
         | engine | cases | largest error | its case (a/b, ξ', η', φ') | exact 64 × 64 − 32 × 32 there | mean error | \
         cases with error > 0.05 | time per case |\n\
         |---|---:|---:|---|---:|---:|---:|---:|",
        exact.status.len(),
        exact.axes.nu,
        exact.axes.a_over_b,
        shape[2],
        shape[3],
        shape[4],
        exact_ms
    )
    .unwrap();
    for (label, engine, options) in engines {
        let spec = spec_of(engine, options, 100)?;
        let t0 = Instant::now();
        let (table, _) = creeptable::compute_spec(&spec, exact_path)?;
        let ms = 1e3 * t0.elapsed().as_secs_f64() / table.status.len() as f64;
        let TableErrors { n, sum, worst, over } = TableErrors::of(&exact, &table);
        let [_, iab, ix, ie, ip] = exact.axes.coords(worst.1);
        let a = &exact.axes;
        // The reference's grid error at this case: the exact theory on a grid twice as fine.
        let fine = spec_of("exact", "", 64)?;
        let (case, norm) = fine.case(worst.1)?;
        let answer = fine.engine(exact_path)?.forces(&case)?;
        let grid_error = match answer.forces.map(|f| norm.forces(&f)) {
            Some((fx, fy, _)) => {
                let e = &exact.forces[3 * worst.1..3 * worst.1 + 2];
                format!("{:.4}", (fx - e[0]).hypot(fy - e[1]))
            }
            None => format!("not solved ({})", answer.status.name()),
        };
        writeln!(
            md,
            "| {label} | {n} | {:.3} | ({}, {}, {}, {}) | {grid_error} | {:.4} | {over} | {ms:.2} ms |",
            worst.0,
            a.a_over_b[iab],
            a.xi[ix],
            a.eta[ie],
            a.phi[ip],
            sum / n.max(1) as f64
        )
        .unwrap();
    }
    md.push('\n');
    Ok(())
}

/// The creep-force table the report computes and draws (README "Creep-force tables").
const CREEP_TABLE: &str = "fastsim-usetab.toml";

/// The creep-force table of `spec` computed in memory, its summary and the surfaces of one ellipse (ν and a/b the
/// table's values nearest 0.28 and 1) beside Kalker's linear theory.
fn creep_table(md: &mut String, figs: &mut Figs<'_>, spec: &Path) -> Result<()> {
    let t0 = Instant::now();
    let (table, engine) = creeptable::compute_table(spec)?;
    let seconds = t0.elapsed().as_secs_f64();
    let nearest =
        |axis: &[f64], v: f64| (0..axis.len()).min_by(|&i, &j| (axis[i] - v).abs().total_cmp(&(axis[j] - v).abs()));
    let ellipse = [nearest(&table.axes.nu, 0.28).unwrap_or(0), nearest(&table.axes.a_over_b, 1.0).unwrap_or(0)];
    let linear = CreepTable::linear(&table.axes);
    let svgs = creeptable::creep_surface_svg(&table, Some(("Kalker's linear theory", &linear)), &engine, ellipse)?;
    let mut links = Vec::new();
    for (svg, which) in svgs.iter().zip(["fx", "fy"]) {
        let file = format!("{}creep-table-{which}.svg", figs.sub);
        crate::io::write_output(&figs.root.join(&file), svg)?;
        let caption = format!(
            "Creep-force table ({engine}): {} against its creepage, ν = {}, a/b = {}",
            if which == "fx" { "Fx/(μN)" } else { "Fy/(μN)" },
            table.axes.nu[ellipse[0]],
            table.axes.a_over_b[ellipse[1]]
        );
        figs.list.push((caption.clone(), file.clone()));
        links.push((caption, file));
    }
    let section = creeptable::markdown_section(&table, &engine, &links);
    // One level below the page's section.
    md.push_str(&section.replacen("## ", "### ", 1));
    writeln!(
        md,
        "The table is `reference/creep-tables/{CREEP_TABLE}`, computed by this report in {seconds:.1} s on this \
         machine (both cores); `rollbem sweep` writes it as CSV and `.npz`, as a SLURM job array too (README \
         \"Creep-force tables\").\n"
    )
    .unwrap();
    Ok(())
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
        pressure_on_grid((self.a, self.b), self.curv, FN, mx, my)
    }
}

/// Steel on steel (G, ν) on CONTACT's grid layout, MX × MY elements over 1.1 times the ellipse of semi-axes `ab`:
/// the influence operator and the pressure of the profile `A x² + B y²` (`curv`) under the normal force `load`.
fn pressure_on_grid(
    ab: (f64, f64),
    curv: (f64, f64),
    load: f64,
    mx: usize,
    my: usize,
) -> Result<(Influence, Vec<f64>)> {
    let (a, b) = ab;
    let (dx, dy) = (2.2 * a / mx as f64, 2.2 * b / my as f64);
    let grid = ContactGrid::new(mx, my, dx, dy, -1.1 * a + 0.5 * dx, -1.1 * b + 0.5 * dy)?;
    let body = HalfSpace::new(2.0 * G * (1.0 + NU), NU)?;
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
    let h = grid.sample(|x, y| curv.0 * x * x + curv.1 * y * y);
    let n = normal::solve(&inf, &h, Drive::Load(load), &NormalSettings::new(1e-10, 10_000), &Cancel::never())?;
    Ok((inf, n.pressure))
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

/// A simplified method on the Eurosprinter contact: FASTSIM's two variants (parabolic bound) or FaStrip (elliptic).
#[derive(Clone, Copy, PartialEq)]
enum Simplified {
    Fastsim(Flexibility, Bound),
    Fastrip,
}

impl Simplified {
    /// Solves one case on CONTACT's grid `mx × my` over 1.1 times the ellipse.
    fn solve(self, contact: &Contact, cr: &Creepages, mx: usize, my: usize) -> Result<fastsim::Solution> {
        let grid = Grid::contact(mx, my, 1.1);
        let direction = Direction::PlusX;
        Ok(match self {
            Simplified::Fastsim(flexibility, bound) => {
                let options = Options { bound, flexibility, direction, grid };
                fastsim::solve(contact, cr, &options)?
            }
            Simplified::Fastrip => {
                let options = Options { bound: Bound::Elliptic, flexibility: Flexibility::Blended, direction, grid };
                fastsim::fastrip(contact, cr, &options)?
            }
        })
    }
}

/// A simplified method on CONTACT's grid of the exact solution's coarse level.
fn simplified_curve(e: &Eurosprinter, method: Simplified, xis: &[f64], name: &'static str) -> Result<Curve> {
    let contact = Contact { a: e.a, b: e.b, shear_modulus: G, nu: NU, mu: MU, normal_force: FN };
    let t0 = Instant::now();
    let mut values = Vec::new();
    for &xi in xis {
        let s = method.solve(&contact, &Creepages { xi, eta: 0.0, phi: 0.0 }, 48, 44)?;
        values.push(s.fx / (MU * FN));
    }
    Ok(Curve { name, values, seconds: t0.elapsed().as_secs_f64() / xis.len() as f64 })
}

/// FASTSIM, FaStrip and the exact theory on the Eurosprinter creep curve: the table and the figure.
fn creep_curve(md: &mut String, figs: &mut Figs<'_>) -> Result<()> {
    let e = Eurosprinter::new()?;
    let xis: Vec<f64> = [1e-5, 2e-4, 4e-4, 8e-4, 1.2e-3, 1.6e-3, 2.4e-3, 3.2e-3, 4.8e-3, 8e-3, 1.6e-2, 5e-2].to_vec();
    let reference = exact_curve(&e, 96, 88, &xis, "exact, 96 × 88 (reference)")?;
    let weighted = Simplified::Fastsim(Flexibility::Weighted, Bound::Parabolic);
    let blended = Simplified::Fastsim(Flexibility::Blended, Bound::Parabolic);
    let curves = [
        exact_curve(&e, 48, 44, &xis, "exact, 48 × 44")?,
        simplified_curve(&e, weighted, &xis, "FASTSIM, Kalker 1982 (one flexibility)")?,
        simplified_curve(&e, blended, &xis, "FASTSIM, CONTACT's blended flexibilities")?,
        simplified_curve(&e, Simplified::Fastrip, &xis, "FaStrip (elliptic bound)")?,
    ];
    writeln!(
        md,
        "### FASTSIM and FaStrip against the exact theory: Polach's Eurosprinter creep curve\n\n\
         CONTACT's `tractcurv.inp` contact: a/b = 0.5 from A = 0.0008/mm, a = {:.3} mm, b = {:.3} mm, FN = 106.7 kN, \
         G = 82 000 N/mm², ν = 0.28, μ = 0.33, η = φ = 0, rolling along +x. The reference is the exact theory on \
         96 × 88 elements over 1.1 times the ellipse; the exact theory on CONTACT's 48 × 44 reproduces \
         `tractcurv.ref_out`'s cases 1–30 to their printed digits (`tests/rolling3d.rs`). FASTSIM (parabolic bound, \
         48 × 44) in its two variants (with ξ alone both use Kalker's L1: the same numbers), and FaStrip \
         (`fastsim::fastrip`, Sichani et al. 2016 as CONTACT's M = 5: the strip theory, here Carter's solution in \
         every strip, with Hertz's pressure as its bound; it reproduces `fastsim.inp`'s cases 4 and 7, \
         `tests/fastsim.rs`). Errors are in units of μFN; times per case on this machine (the exact curves started \
         each case from the last).\n",
        e.a, e.b
    )
    .unwrap();
    let mut head = String::from("| ξ | reference FX/(μFN) |");
    for c in &curves {
        write!(head, " {} |", c.name).unwrap();
    }
    writeln!(md, "{head}\n|---:|---:|{}", "---:|".repeat(curves.len())).unwrap();
    let mut worst = [0.0_f64; 4];
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
    let cells = |f: &dyn Fn(usize) -> String| (0..curves.len()).map(|k| format!(" {} |", f(k))).collect::<String>();
    writeln!(md, "| largest error | |{}", cells(&|k| format!("{:.4}", worst[k]))).unwrap();
    let ms = |k: usize| milliseconds(1e3 * curves[k].seconds);
    writeln!(md, "| time per case | {:.1} ms |{}\n", 1e3 * reference.seconds, cells(&ms)).unwrap();
    let fastest = if curves[1].seconds.min(curves[2].seconds) < curves[0].seconds { "faster" } else { "not faster" };
    writeln!(
        md,
        "FASTSIM is {fastest} than the exact theory on the same grid here ({:.2} and {:.2} ms against {:.1} ms per \
         case) and its largest error on this curve is {:.3} and {:.3} of μFN, against {:.4} for the exact theory on \
         the coarse grid; FaStrip's largest error is {:.3} of μFN at {:.2} ms per case: the trade-off of the \
         simplified theories, measured.\n",
        1e3 * curves[1].seconds,
        1e3 * curves[2].seconds,
        1e3 * curves[0].seconds,
        worst[1],
        worst[2],
        worst[0],
        worst[3],
        1e3 * curves[3].seconds
    )
    .unwrap();
    let title = "Eurosprinter creep curve: exact theory, FASTSIM, FaStrip";
    let mut chart = Chart::new(title, "creepage ξ", "−FX/(μFN)").log_x();
    let line = |c: &Curve| xis.iter().zip(&c.values).map(|(x, v)| (*x, -v)).collect::<Vec<_>>();
    chart = chart.add(Series::new(reference.name, line(&reference), Style::LineMarkers));
    for c in &curves {
        chart = chart.add(Series::new(c.name, line(c), Style::Dashed));
    }
    let file =
        figs.save(&chart, "rolling3d-creep-curve.svg", "Eurosprinter creep curve: exact, FASTSIM, FaStrip".into())?;
    writeln!(md, "![Eurosprinter creep curve: exact theory, FASTSIM and FaStrip]({file})\n\n(−FX/(μFN) against ξ, log axis. With ξ alone both FASTSIM variants use the same flexibility L1 and their \
         curves coincide.)\n").unwrap();
    Ok(())
}

/// One row of the spin case: a method's forces, counts, worst |p|/(μ pn) and time.
struct SpinRow {
    name: String,
    fy: f64,
    mz: f64,
    stick: usize,
    slip: usize,
    ratio: f64,
    seconds: f64,
}

/// The exact theory on `fastsim.inp`'s contact on n × n elements over 1.1 times the ellipse (the tangential solve
/// timed; the normal problem solved once beforehand).
fn spin_exact(n: usize, cr: &Creepages) -> Result<SpinRow> {
    let (a, b) = (SPIN_A, SPIN_B);
    let e_star = G / (1.0 - NU);
    let bad = || ArgumentError::new("report::rolling3d", "hertz", "no Hertz contact");
    let curv = Hertz3D::curvatures_for(a, b, e_star, SPIN_FN).ok_or_else(bad)?;
    let (inf, pressure) = pressure_on_grid((a, b), curv, SPIN_FN, n, n)?;
    let t0 = Instant::now();
    let problem = SteadyRolling::new(&pressure, SPIN_MU, cr.phi, RollingDrive::Creepage(cr.xi, cr.eta));
    let r = rolling::solve(&inf, &problem, &RollingSettings::new(1e-10, 100_000), &Cancel::never())?;
    let seconds = t0.elapsed().as_secs_f64();
    if r.stop != RollingStop::Converged {
        return Err(ArgumentError::new("report::rolling3d", "exact", format!("{n} × {n}: {:?}", r.stop)).into());
    }
    let ratio = pressure
        .iter()
        .enumerate()
        .filter(|(_, &pn)| pn > 0.0)
        .fold(0.0_f64, |m, (i, &pn)| m.max(r.qx[i].hypot(r.qy[i]) / (SPIN_MU * pn)));
    let name = format!("exact, {n} × {n}");
    Ok(SpinRow { name, fy: r.force.1, mz: r.moment, stick: r.stick, slip: r.slip, ratio, seconds })
}

/// `fastsim.inp`'s contact (CONTACT's example): a = 8, b = 4 mm, FN = 82 kN, μ = 0.3 (G and ν as the Eurosprinter's).
const SPIN_A: f64 = 8.0;
const SPIN_B: f64 = 4.0;
const SPIN_FN: f64 = 82_000.0;
const SPIN_MU: f64 = 0.3;

/// The exact theory, FASTSIM (both bounds) and FaStrip on `fastsim.inp`'s lateral creepage with spin.
fn spin_case(md: &mut String) -> Result<()> {
    let cr = Creepages { xi: 0.0, eta: -0.000625, phi: 0.000625 };
    let contact = Contact { a: SPIN_A, b: SPIN_B, shear_modulus: G, nu: NU, mu: SPIN_MU, normal_force: SPIN_FN };
    let reference = spin_exact(220, &cr)?;
    let mut rows = vec![spin_exact(44, &cr)?];
    let methods = [
        (Simplified::Fastsim(Flexibility::Blended, Bound::Parabolic), "FASTSIM, parabolic bound"),
        (Simplified::Fastsim(Flexibility::Blended, Bound::Elliptic), "FASTSIM, elliptic bound"),
        (Simplified::Fastrip, "FaStrip"),
    ];
    for n in [44, 220] {
        for (method, label) in methods {
            let t0 = Instant::now();
            let s = method.solve(&contact, &cr, n, n)?;
            let seconds = t0.elapsed().as_secs_f64();
            let (fy, mz, stick, slip, ratio) = (s.fy, s.mz, s.n_adhesion, s.n_slip, s.bound_ratio);
            rows.push(SpinRow { name: format!("{label}, {n} × {n}"), fy, mz, stick, slip, ratio, seconds });
        }
    }
    writeln!(
        md,
        "### Lateral creepage with spin: CONTACT's `fastsim.inp` contact\n\n\
         a = 8 mm, b = 4 mm (Hertz), FN = 82 kN, G = 82 000 N/mm², ν = 0.28, μ = 0.3, ξ = 0, η = −0.000625, \
         φ = 0.000625 rad/mm, rolling along +x, n × n elements over 1.1 times the ellipse, FASTSIM with CONTACT's \
         blended flexibilities: seven of the eight cases of CONTACT's example (its case 8 is case 5 rolling along \
         −x), whose printed results rollbem reproduces (`tests/fastsim.rs`, `tests/rolling3d.rs`). The reference is \
         the exact theory on 220 × 220 (not one of CONTACT's cases). ΔFY is in units \
         of μFN, ΔMZ relative to the reference's MZ; \"largest |p|/(μpn)\" is the worst ratio of traction to the \
         traction bound over the elements in contact (at most 1 where the friction law holds). Times per case on this \
         machine (the exact theory's: its tangential solve).\n\n\
         | method | FY [N] | ΔFY/(μFN) | MZ [N·mm] | ΔMZ | stick | slip | largest \\|p\\|/(μpn) | time |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|"
    )
    .unwrap();
    let mu_fn = SPIN_MU * SPIN_FN;
    for r in std::iter::once(&reference).chain(&rows) {
        let t = 1e3 * r.seconds;
        writeln!(
            md,
            "| {} | {:.1} | {:+.4} | {:.1} | {:+.1} % | {} | {} | {:.3} | {} |",
            r.name,
            r.fy,
            (r.fy - reference.fy) / mu_fn,
            r.mz,
            100.0 * (r.mz - reference.mz) / reference.mz,
            r.stick,
            r.slip,
            r.ratio,
            milliseconds(t)
        )
        .unwrap();
    }
    let simplified = &rows[1..];
    let best = |f: &dyn Fn(&SpinRow) -> f64| {
        simplified.iter().min_by(|a, b| f(a).total_cmp(&f(b))).map(|r| (r.name.clone(), f(r))).unwrap_or_default()
    };
    let (fy_name, fy_err) = best(&|r| ((r.fy - reference.fy) / mu_fn).abs());
    let (mz_name, mz_err) = best(&|r| (100.0 * (r.mz - reference.mz) / reference.mz).abs());
    let fastrip_worst =
        simplified.iter().filter(|r| r.name.starts_with("FaStrip")).fold(0.0_f64, |m, r| m.max(r.ratio));
    let fastsim_worst =
        simplified.iter().filter(|r| r.name.starts_with("FASTSIM")).fold(0.0_f64, |m, r| m.max(r.ratio));
    let excess = if fastrip_worst > 1.0 + 1e-9 {
        format!(
            "FaStrip's strip tractions exceed the traction bound in its adhesion area by up to {fastrip_worst:.2}× \
             (CONTACT's FaStrip does the same: its strip theory is checked against μ·pmax only, `fastsim::fastrip`'s \
             docs)"
        )
    } else {
        format!("FaStrip's worst ratio is {fastrip_worst:.3}")
    };
    writeln!(
        md,
        "\nOf the simplified methods, {fy_name} has the smallest FY error ({fy_err:.4} μFN) and {mz_name} the smallest MZ \
         error ({mz_err:.1} %). {excess}; FASTSIM's worst ratio is {fastsim_worst:.3} and the exact theory's {:.3}.\n",
        reference.ratio.max(rows[0].ratio)
    )
    .unwrap();
    Ok(())
}

/// A time in milliseconds with two decimals below 1 ms, one above.
fn milliseconds(t: f64) -> String {
    if t < 1.0 {
        format!("{t:.2} ms")
    } else {
        format!("{t:.1} ms")
    }
}
