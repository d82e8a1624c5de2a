//! Kalker's creep coefficients from the exact theory ([`super::linear_coefficients`]).

use super::{solve, RollingDrive, RollingSettings, RollingStop, SteadyRolling};
use crate::cancel::Cancel;
use crate::error::ArgumentError;
use crate::halfspace::{ContactGrid, HalfSpace, Influence, Kernels};

/// Kalker's creep coefficients of an elliptic contact in full adhesion (dimensionless), from [`linear_coefficients`]:
/// `F_x = −G c² C11 ξ`, `F_y = −G c² C22 η − G c³ C23 φ`, `M_z = −G c³ C32 η − G c⁴ C33 φ`, `c = √(ab)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct LinearCoefficients {
    /// C11.
    pub c11: f64,
    /// C22.
    pub c22: f64,
    /// C23.
    pub c23: f64,
    /// C32 (= −C23 by Betti's reciprocal theorem, up to the solver's tolerance).
    pub c32: f64,
    /// C33.
    pub c33: f64,
    /// Elements in the discretised ellipse.
    pub elements: usize,
    /// Operator products of the three solves.
    pub products: usize,
}

/// Kalker's creep coefficients from the exact steady-rolling solver: an ellipse of semi-axes `a` (rolling direction
/// x) and `b`, Poisson's ratio `nu` on both bodies, `across` elements (square, side `2 min(a, b)/across`) across
/// its smaller diameter; a unit pressure inside the ellipse (element centres inside) with a friction bound far
/// above any shear (μ = 1e4, the creepages of order one: nothing slips — the problem is linear, its answer
/// independent of G and of the pressure's shape), the creepages ξ, η and the spin φ = 1/c one at a time, the spin
/// evaluated at the element centres. The discretisation error falls as `across` grows
/// (`examples/kalker_coefficients.rs`; the report's table).
///
/// # Errors
/// An [`ArgumentError`] naming the argument when a, b are not positive and finite, ν is outside [0, 0.5], or
/// `across` is below 2; or when a solve does not converge or something slips (`"solve"`).
pub fn linear_coefficients(
    a: f64,
    b: f64,
    nu: f64,
    across: usize,
    cancel: &Cancel,
) -> Result<LinearCoefficients, ArgumentError> {
    const F: &str = "halfspace::rolling::linear_coefficients";
    for (name, v) in [("a", a), ("b", b)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(ArgumentError::new(F, name, format!("a positive, finite semi-axis (got {v})")));
        }
    }
    if !(0.0..=0.5).contains(&nu) {
        return Err(ArgumentError::new(F, "nu", format!("Poisson's ratio in [0, 0.5] (got {nu})")));
    }
    if across < 2 {
        return Err(ArgumentError::new(F, "across", format!("at least 2 elements (got {across})")));
    }
    let h = 2.0 * a.min(b) / across as f64;
    let (mx, my) = ((2.0 * a / h).round() as usize + 2, (2.0 * b / h).round() as usize + 2);
    let grid = ContactGrid::new(mx, my, h, h, -0.5 * (mx - 1) as f64 * h, -0.5 * (my - 1) as f64 * h)?;
    let body = HalfSpace::new(2.0 * (1.0 + nu), nu)?;
    let inf = Influence::new(grid, body.pair(&body), Kernels::Full)?;
    let p = grid.sample(|x, y| if (x / a).powi(2) + (y / b).powi(2) < 1.0 { 1.0 } else { 0.0 });
    let c = (a * b).sqrt();
    let settings = RollingSettings::new(1e-12, 100_000);
    let mut products = 0;
    let mut run = |xi: f64, eta: f64, phi: f64| {
        let problem = SteadyRolling::new(&p, 1e4, phi, RollingDrive::Creepage(xi, eta)).with_spin_lead(0.0);
        let r = solve(&inf, &problem, &settings, cancel)?;
        products += r.products;
        if r.stop != RollingStop::Converged || r.slip > 0 {
            let msg = format!("{:?} with {} elements slipping: not the linear theory", r.stop, r.slip);
            return Err(ArgumentError::new(F, "solve", msg));
        }
        Ok(r)
    };
    let (x, y, z) = (run(1.0, 0.0, 0.0)?, run(0.0, 1.0, 0.0)?, run(0.0, 0.0, 1.0 / c)?);
    // G = 1 for the pair (2/(1/G + 1/G) with G = E/(2(1 + ν)) = 1).
    Ok(LinearCoefficients {
        c11: -x.force.0 / (c * c),
        c22: -y.force.1 / (c * c),
        c23: -z.force.1 / (c * c),
        c32: -y.moment / (c * c * c),
        c33: -z.moment / (c * c * c),
        elements: p.iter().filter(|&&v| v > 0.0).count(),
        products,
    })
}
