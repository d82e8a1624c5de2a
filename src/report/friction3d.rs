//! The report's section on Coulomb's law in 3D: the disc (exactly: the preconditioned CG and FISTA of
//! `halfspace::tangential`, and clarabel's second-order cones)
//! against the inscribed pyramid of k facets (Lemke), on one small grid — each formulation's error in the total
//! tangential force and in the element tractions against the disc, its time, the pyramid's order in k, and which
//! formulation reaches 1e-3 of μP first. Computed afresh by every `rollbem report` (a second or so).

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::halfspace::dense::{ConeSettings, DenseShift, ShiftDrive, ShiftSolution};
use crate::halfspace::normal::{self, Drive, NormalSettings};
use crate::halfspace::tangential::{self, ShiftStep, TangentialDrive, TangentialMethod, TangentialSettings};
use crate::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};
use crate::solvers::lemke::LemkeSettings;
use crate::theory::Hertz3D;
use std::fmt::Write as _;
use std::time::Instant;

/// The problem: a sphere pair (A = B = 0.05 /mm, E = 210 GPa, ν = 0.3 on both), P = 1 kN, μ = 0.3, on an 11 × 11
/// grid over ±1.2a (`halfspace::dense`'s tests use the same); the force 0.6 μP at 30° (between the vertices of
/// every k-gon measured).
const GRID: usize = 11;
const LOAD: f64 = 1000.0;
const MU: f64 = 0.3;

/// One formulation's figures: name, total-force error and traction max-norm error (relative to μP and μp₀), time.
struct Line {
    name: String,
    force_err: f64,
    traction_err: f64,
    seconds: f64,
}

/// What the section found, for the front page: every formulation as (name, total-force error of μP, seconds), and
/// per target of [`super::accuracy::TARGETS`] the fastest formulation within it ([`fastest_within`], the rule the
/// section's own sentence uses), as an index into `lines`.
pub(super) struct Found {
    /// (name, force error, seconds) per formulation, in the table's order.
    pub lines: Vec<(String, f64, f64)>,
    /// (target, the fastest line within it).
    pub picks: Vec<(f64, Option<usize>)>,
}

/// Append the section to `md`; returns what it found.
pub(super) fn section(md: &mut String) -> Result<Found> {
    let (e, nu, c) = (210e3, 0.3, 0.05);
    let body = HalfSpace::new(e, nu)?;
    let hertz = Hertz3D::from_load(c, c, e / (2.0 * (1.0 - nu * nu)), LOAD).ok_or_else(|| {
        Error::from(crate::error::ArgumentError::new("report::friction3d", "hertz", "no Hertz contact"))
    })?;
    let a = 1.2 * hertz.a_x;
    let grid = ContactGrid::covering(GRID, GRID, -a, a, -a, a)?;
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
    let h = grid.sample(|x, y| c * (x * x + y * y));
    let never = Cancel::never();
    let p = normal::solve(&inf, &h, Drive::Load(LOAD), &NormalSettings::default(), &never)?.pressure;
    let dense = DenseShift::new(&inf, &p, MU, None)?;
    let (fm, t) = (0.6 * MU * LOAD, std::f64::consts::PI / 6.0);
    let f = [fm * t.cos(), fm * t.sin()];
    let reference = dense.disc(ShiftDrive::Force(f), &ConeSettings::default())?;
    let w = ShiftDrive::Shift(reference.shift);
    let p0 = p.iter().fold(0.0_f64, |m, &v| m.max(v));
    let err = |qx: &[f64], qy: &[f64], force: [f64; 2]| {
        let dq = (0..p.len()).fold(0.0_f64, |m, i| m.max((qx[i] - reference.qx[i]).hypot(qy[i] - reference.qy[i])));
        ((force[0] - f[0]).hypot(force[1] - f[1]) / (MU * LOAD), dq / (MU * p0))
    };
    let from = |name: String, s: &ShiftSolution| {
        let (force_err, traction_err) = err(&s.qx, &s.qy, s.force);
        Line { name, force_err, traction_err, seconds: s.seconds }
    };
    let mut lines = Vec::new();
    // The disc by the two scalable solvers, driven by the same shift; each named by the method that ran.
    let step = ShiftStep::new(&p, MU, TangentialDrive::Shift(reference.shift[0], reference.shift[1]));
    for method in [TangentialMethod::ConjugateGradient, TangentialMethod::Fista] {
        let start = Instant::now();
        let s = tangential::solve(&inf, &step, &TangentialSettings::default().with_method(method), &never)?;
        let seconds = start.elapsed().as_secs_f64();
        let (force_err, traction_err) = err(&s.qx, &s.qy, [s.force.0, s.force.1]);
        let name = match s.method {
            TangentialMethod::ConjugateGradient => "disc, preconditioned CG (`halfspace::tangential`, the default)",
            _ => "disc, FISTA (`halfspace::tangential`)",
        };
        lines.push(Line { name: name.into(), force_err, traction_err, seconds });
    }
    let cone = dense.disc(w, &ConeSettings::default())?;
    lines.push(from("disc, clarabel second-order cones (`halfspace::dense`)".into(), &cone));
    for k in [4, 8, 16, 32] {
        let s = dense.pyramid(k, w, &LemkeSettings::default())?;
        if !s.status.is_solved() {
            writeln!(md, "The {k}-facet pyramid was not solved ({}): {}\n", s.status.name(), s.message).unwrap();
            continue;
        }
        lines.push(from(format!("pyramid, k = {k}, Lemke"), &s));
    }
    write_section(md, &lines, dense.contact().len());
    let picks = super::accuracy::TARGETS
        .iter()
        .map(|&t| (t, fastest_within(&lines, t).and_then(|b| lines.iter().position(|l| std::ptr::eq(l, b)))))
        .collect();
    Ok(Found { lines: lines.iter().map(|l| (l.name.clone(), l.force_err, l.seconds)).collect(), picks })
}

/// The fastest formulation whose total force is within `target` of μP.
fn fastest_within(lines: &[Line], target: f64) -> Option<&Line> {
    lines.iter().filter(|l| l.force_err <= target).min_by(|a, b| a.seconds.total_cmp(&b.seconds))
}

/// The table, the pyramid's fitted order and the verdict at 1e-3 of μP.
fn write_section(md: &mut String, lines: &[Line], in_contact: usize) {
    writeln!(md, "\n## Coulomb's law in 3D: the disc against the pyramid\n").unwrap();
    writeln!(
        md,
        "A sphere pair (A = B = 0.05 /mm, E = 210 GPa, ν = 0.3), P = 1 kN, μ = 0.3, on {GRID} × {GRID} elements over \
         ±1.2a ({in_contact} in contact), shifted from rest by the shift that carries 0.6 μP at 30° on the disc. The \
         reference is the disc law solved by clarabel with that force prescribed; every formulation below is driven \
         by the reference's shift, and its total tangential force and element tractions are compared with the \
         reference's (errors relative to μP and to μp₀). Times are the wall clock of one solve in this run.\n"
    )
    .unwrap();
    writeln!(md, "| formulation | force error (of μP) | traction error, max (of μp₀) | time [s] |").unwrap();
    writeln!(md, "|---|---:|---:|---:|").unwrap();
    for l in lines {
        writeln!(md, "| {} | {:.1e} | {:.1e} | {:.1e} |", l.name, l.force_err, l.traction_err, l.seconds).unwrap();
    }
    let pyr: Vec<(f64, f64, f64)> = lines
        .iter()
        .filter_map(|l| {
            let k: f64 = l.name.strip_prefix("pyramid, k = ")?.split(',').next()?.parse().ok()?;
            Some((k, l.force_err, l.traction_err))
        })
        .collect();
    let order = |pick: fn(&(f64, f64, f64)) -> f64| {
        super::table::log_slope(&pyr.iter().map(|r| (r.0, pick(r))).collect::<Vec<_>>()).map(|s| s.0)
    };
    if let (Some(force), Some(traction)) = (order(|r| r.1), order(|r| r.2)) {
        writeln!(
            md,
            "\nThe pyramid's errors fall with its facets as k^{force:.1} (total force) and k^{traction:.1} (element \
             tractions) (least-squares slopes over k = {}).",
            pyr.iter().map(|r| format!("{}", r.0)).collect::<Vec<_>>().join(", ")
        )
        .unwrap();
    }
    let target = 1e-3;
    match fastest_within(lines, target) {
        Some(best) => writeln!(
            md,
            "Of the formulations whose total force is within {target:.0e} of μP, the fastest here is {} ({:.1e} s).\n",
            best.name, best.seconds
        )
        .unwrap(),
        None => writeln!(md, "None of these formulations reaches {target:.0e} of μP in the total force.\n").unwrap(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The verdict and the order are derived from the lines, not written in: synthetic lines with errors `k⁻²`
    /// give the slope −2, the fastest line within 1e-3 is named (not a faster one outside it), and no line within
    /// it gives the sentence that says so.
    #[test]
    fn the_verdict_and_the_order_come_from_the_lines() {
        let line = |name: &str, force_err: f64, seconds: f64| Line {
            name: name.to_string(),
            force_err,
            traction_err: force_err.sqrt(),
            seconds,
        };
        let lines = vec![
            line("slow exact", 1e-9, 2.0),
            line("fast exact", 1e-8, 1.0),
            line("pyramid, k = 4, Lemke", 1.0 / 16.0, 0.1),
            line("pyramid, k = 8, Lemke", 1.0 / 64.0, 0.2),
            line("pyramid, k = 16, Lemke", 1.0 / 256.0, 0.4),
        ];
        let mut md = String::new();
        write_section(&mut md, &lines, 69);
        assert!(md.contains("as k^-2.0 (total force) and k^-1.0 (element tractions)"), "{md}");
        assert!(md.contains("the fastest here is fast exact (1.0e0 s)"), "{md}");
        let mut none = String::new();
        write_section(&mut none, &lines[2..], 69);
        assert!(none.contains("None of these formulations reaches 1e-3 of μP"), "{none}");
    }
}
