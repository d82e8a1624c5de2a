//! The exact theory as a creep engine ([`Exact`]): Kalker's steady rolling on the half-space grid
//! ([`crate::halfspace::rolling`]).

use super::{CaseStatus, CreepCase, CreepEngine, CreepResult, EngineEntry, Forces};
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::halfspace::rolling::{self, RollingDrive, RollingSettings, RollingStop, SteadyRolling};
use crate::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};

/// Kalker's exact theory of steady rolling ([`crate::halfspace::rolling::solve`]) on a grid of the case's
/// [`super::Resolution`] `mx × my` elements over `[−m a, m a] × [−m b, m b]` (`m` the margin, default 1.1, as CONTACT's
/// Hertzian grids), two identical half-spaces of the case's G and ν (no normal–tangential coupling), Hertz's pressure
/// `p0 √(1 − x²/a² − y²/b²)` at the element centres scaled so that the grid carries the case's normal force exactly,
/// rolling along +x with CONTACT's spin lead (1/6 of an element). Status: [`CaseStatus::Solved`] when the solver
/// converged with some element in stick, [`CaseStatus::GrossSliding`] when every element in contact slips (the force
/// is then μN against the slip), [`CaseStatus::NotConverged`] with the natural residual otherwise (no forces).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exact {
    /// The solver's tolerance ([`RollingSettings::tolerance`]).
    pub tolerance: f64,
    /// The grid's margin `m` around the ellipse (≥ 1).
    pub margin: f64,
}

impl Default for Exact {
    fn default() -> Exact {
        Exact { tolerance: 1e-9, margin: 1.1 }
    }
}

impl CreepEngine for Exact {
    fn name(&self) -> &str {
        "exact"
    }

    fn settings(&self) -> String {
        format!("tolerance={:e} margin={}", self.tolerance, self.margin)
    }

    fn forces(&self, case: &CreepCase) -> Result<CreepResult, ArgumentError> {
        const F: &str = "Exact::forces";
        for (name, v) in [("shear_modulus", case.shear_modulus), ("a", case.a), ("b", case.b)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(ArgumentError::new(F, name, format!("must be finite and > 0, is {v}")));
            }
        }
        let (mx, my) = (case.resolution.mx, case.resolution.my);
        if mx < 2 || my < 2 {
            return Err(ArgumentError::new(F, "resolution", format!("at least 2 × 2 elements, is {mx} × {my}")));
        }
        let (a, b, m) = (case.a, case.b, self.margin);
        let (dx, dy) = (2.0 * m * a / mx as f64, 2.0 * m * b / my as f64);
        let grid = ContactGrid::new(mx, my, dx, dy, -m * a + 0.5 * dx, -m * b + 0.5 * dy)?;
        let body = HalfSpace::new(2.0 * case.shear_modulus * (1.0 + case.nu), case.nu)?;
        let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
        let mut p = grid.sample(|x, y| (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt());
        let sum = grid.area() * p.iter().sum::<f64>();
        if sum <= 0.0 {
            return Err(ArgumentError::new(F, "resolution", "no element centre inside the ellipse".to_string()));
        }
        let scale = case.normal_force() / sum;
        p.iter_mut().for_each(|v| *v *= scale);
        let cr = case.creepages;
        let problem = SteadyRolling::new(&p, case.mu, cr.phi, RollingDrive::Creepage(cr.xi, cr.eta));
        let r = rolling::solve(&inf, &problem, &RollingSettings::new(self.tolerance, 100_000), &Cancel::never())?;
        let counts = (Some(r.stick + r.slip), Some(r.slip));
        if r.stop != RollingStop::Converged {
            return Ok(CreepResult {
                status: CaseStatus::NotConverged { residual: r.residual },
                forces: None,
                residual: Some(r.residual),
                contact_elements: counts.0,
                slip_elements: counts.1,
            });
        }
        let status = if r.stick == 0 && r.slip > 0 { CaseStatus::GrossSliding } else { CaseStatus::Solved };
        Ok(CreepResult {
            status,
            forces: Some(Forces { fx: r.force.0, fy: r.force.1, mz: Some(r.moment) }),
            residual: Some(r.residual),
            contact_elements: counts.0,
            slip_elements: counts.1,
        })
    }
}

/// Builds [`Exact`] from `[options]`: `tolerance` (in (0, 1)), `margin` (≥ 1).
fn build_exact(options: &toml::Table) -> super::Built {
    let mut engine = Exact::default();
    for (key, value) in options {
        let v = value
            .as_float()
            .or_else(|| value.as_integer().map(|i| i as f64))
            .ok_or_else(|| (key.clone(), format!("must be a number, is {value}")))?;
        match key.as_str() {
            "tolerance" if v > 0.0 && v < 1.0 => engine.tolerance = v,
            "tolerance" => return Err((key.clone(), format!("must be in (0, 1), is {v}"))),
            "margin" if (1.0..=10.0).contains(&v) => engine.margin = v,
            "margin" => return Err((key.clone(), format!("must be in [1, 10], is {v}"))),
            _ => return Err((key.clone(), "unknown option of engine exact (tolerance, margin)".into())),
        }
    }
    Ok(Box::new(engine))
}

/// The exact theory's entry in [`super::BUILT_IN`].
pub(super) const EXACT_ENTRY: EngineEntry = EngineEntry {
    name: "exact",
    describe: "Kalker's exact theory of steady rolling on the half-space grid (Hertz's pressure, grid mx × my over \
               margin × the ellipse); options tolerance, margin",
    build: build_exact,
};
