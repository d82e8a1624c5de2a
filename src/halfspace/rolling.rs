//! # Steady rolling on the half-space grid: creepages, spin, Coulomb's law on the disc (Kalker's exact theory)
//!
//! Two bodies roll over each other at a steady state; in the contact's frame the material flows through the grid
//! against the rolling direction. Given the element pressures `p` (stress), the friction coefficient `μ`, the spin
//! `φ` (rad/length) and either the creepages `(ξ, η)` or the total tangential force `(F_x, F_y)`, find the shears
//! `q_i` (stress, on body 1) whose slip per unit rolled distance (dimensionless, body 1 relative to body 2)
//!
//! ```text
//!   s_i = w_i + [C_tt D q]_i,    w_i = (ξ − φ y_i, η + φ x_i),
//!   (D q)_i = (q_i − q_up(i)) / Δx
//! ```
//!
//! obeys Coulomb's law on the disc `|q_i| ≤ g_i = μ p_i` (`|q_i| < g_i ⇒ s_i = 0`, `s_i ≠ 0 ⇒ q_i = −g_i s_i/|s_i|`).
//! `up(i)` is the element next to `i` against the rolling direction — the one the material at `i` came from —, with
//! `q = 0` beyond the grid; `(x_i, y_i)` are the element centres in the grid's coordinates (the spin turns about
//! the grid's origin). This is Kalker's discretisation of steady rolling and CONTACT's (module 3, `T = 3`, with
//! `DQ = DX`): the displacement difference a particle carries, `u = C_tt q`, changes between neighbouring elements
//! by `u_i − u′_i` with `u′ = C_tt q′` and `q′_i = q_up(i)` the traction one step earlier, so the slip in one step
//! `Δx` is `Δx w_i + u_i − u′_i`. Since `C_tt` is a convolution, `C_tt q − C_tt q′ = C_tt D q · Δx`: one product of
//! the tangential kernels per evaluation (four 2D FFTs), O(N log N). Rolling along `+x` (CONTACT's `χ = 0`) the
//! material enters at the largest `x` and `up(i)` is the element at `ix + 1`; along `−x` (`χ = 180°`) at `ix − 1`.
//!
//! ## The spin
//!
//! The spin's rigid slip `(−φ y, φ x)` varies along the rolling direction across one element; like CONTACT
//! (its `FACPHI`, default 1/6), the lateral part is evaluated at `x_i + f Δx` along the rolling direction
//! ([`SteadyRolling::spin_lead`], `f = 1/6` by default; `f = 0` is the element centre). On CONTACT's
//! `tang_problm_1c` the centre (`f = 0`) moves `F_y` by 1.1 % from CONTACT's printed value; with `f = 1/6` it
//! agrees to its printed digits.
//!
//! ## Signs and the creepage
//!
//! Creepages are those of body 1 relative to body 2, as in [`crate::fastsim`]: a positive `ξ` gives a negative
//! `F_x`, and at vanishing creepage `F_x = −G c² C11 ξ`, `F_y = −G c² C22 η − G c³ C23 φ` (Kalker's linear theory,
//! [`crate::theory::kalker`]; `c = √(ab)`, `G` the combined shear modulus `2/(1/G₁ + 1/G₂)`).
//!
//! ## The method
//!
//! `C_tt D` is not symmetric, so there is no minimum principle to descend on. The equations are solved by a
//! semismooth Newton method on the stick and slip sets with GMRES for each step, preconditioned by the inverse
//! circulants of the shift problem composed with the exact inverse of `D` (`rolling/newton.rs`). With the force
//! prescribed, the creepages `(ξ, η)` are found with the shears (two more unknowns, two more equations).
//!
//! The normal–tangential coupling is left out, as for the shift problem: exact for identical materials (Dundurs'
//! β = 0) and for ν = 0; for a dissimilar pair this is the decoupled approximation.
//!
//! ## Transient rolling
//!
//! [`transient_step`] rolls the contact one element `Δx` on from a previous state (Kalker's "from Cattaneo to
//! Carter", CONTACT's `T = 2` with `DQ = DX`): a shift step ([`super::tangential`]) whose rigid shift is `Δx w_i`
//! and whose previous shears are those each particle carried one element upstream ([`carried`]). Its fixed point,
//! marched from rest, is the steady state above (tested to 1e-12 in `tests/rolling3d.rs`).
//!
//! ## What `converged` certifies
//!
//! The iteration stops when a fresh slip changes neither set and its residual asks for no shear change above
//! `tolerance · max μp`. The answer is then checked from the final shears with a fresh product:
//! [`RollingSolution::residual`] is the natural residual of the disc law, `max_i |q_i − Π_i(q_i − s_i/K_d)| / max μp`
//! (`K_d` the diagonal of `C_tt D`), zero exactly at a solution. A force at or beyond the capacity `μ A Σ p` has no
//! steady solution: [`RollingStop::GrossSliding`] with every element at its bound along the force and the creepages
//! not determined (NaN).

mod linear;
mod newton;

pub use linear::{linear_coefficients, LinearCoefficients};

use super::operator::{ContactGrid, Influence};
use super::tangential::{self, disc_law_residual, ElementState, ShiftStep, TangentialDrive, TangentialSettings};
use crate::cancel::Cancel;
use crate::error::ArgumentError;

/// The direction the contact rolls in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum RollingDirection {
    /// Along `+x` (CONTACT's `χ = 0`): the material enters the grid at its largest `x`.
    PlusX,
    /// Along `−x` (CONTACT's `χ = 180°`): the material enters at its smallest `x`.
    MinusX,
}

/// What is prescribed tangentially besides the spin.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum RollingDrive {
    /// The creepages `(ξ, η)` of body 1 relative to body 2 (dimensionless).
    Creepage(f64, f64),
    /// The total tangential force `(F_x, F_y) = A Σ q` on body 1 (force); the creepages are found.
    Force(f64, f64),
}

/// One steady-rolling problem (module docs).
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct SteadyRolling<'a> {
    /// Pressure per element (stress, ≥ 0), grid order.
    pub pressure: &'a [f64],
    /// Friction coefficient μ (≥ 0).
    pub friction: f64,
    /// The spin creepage φ (rad/length), about the grid's origin.
    pub spin: f64,
    /// What is prescribed.
    pub drive: RollingDrive,
    /// The rolling direction.
    pub direction: RollingDirection,
    /// Shears to start from (`None`: zero), e.g. the answer at a neighbouring creepage; projected onto this
    /// problem's discs.
    pub start: Option<(&'a [f64], &'a [f64])>,
    /// Where the spin's rigid slip is evaluated: at the element centre moved by `spin_lead · Δx` along the rolling
    /// direction (module docs, "The spin"); default 1/6, CONTACT's `FACPHI`.
    pub spin_lead: f64,
}

impl<'a> SteadyRolling<'a> {
    /// Rolling along `+x` from zero shears with spin `spin`.
    pub fn new(pressure: &'a [f64], friction: f64, spin: f64, drive: RollingDrive) -> SteadyRolling<'a> {
        let direction = RollingDirection::PlusX;
        SteadyRolling { pressure, friction, spin, drive, direction, start: None, spin_lead: 1.0 / 6.0 }
    }

    /// The same problem with the spin's rigid slip evaluated `lead · Δx` ahead of the element centres.
    pub fn with_spin_lead(mut self, lead: f64) -> SteadyRolling<'a> {
        self.spin_lead = lead;
        self
    }

    /// The same problem rolling along `direction`.
    pub fn rolling(mut self, direction: RollingDirection) -> SteadyRolling<'a> {
        self.direction = direction;
        self
    }

    /// The same problem started from the shears `(q_x, q_y)`.
    pub fn starting_from(mut self, qx: &'a [f64], qy: &'a [f64]) -> SteadyRolling<'a> {
        self.start = Some((qx, qy));
        self
    }
}

/// Settings of [`solve`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct RollingSettings {
    /// The largest shear change a fresh residual may ask for, relative to `max μp`, in (0, 1).
    pub tolerance: f64,
    /// Largest number of operator products (≥ 1).
    pub max_products: usize,
    /// Largest GMRES dimension in one Newton step (≥ 1).
    pub krylov: usize,
}

impl Default for RollingSettings {
    /// `tolerance` 1e-10, `max_products` 100 000, `krylov` 40.
    fn default() -> Self {
        RollingSettings { tolerance: 1e-10, max_products: 100_000, krylov: 40 }
    }
}

impl RollingSettings {
    /// Settings with a tolerance and a product limit (checked by [`solve`]), the default Krylov dimension.
    pub fn new(tolerance: f64, max_products: usize) -> RollingSettings {
        RollingSettings { tolerance, max_products, ..RollingSettings::default() }
    }
}

/// Why the iteration stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum RollingStop {
    /// A fresh slip changed no set and met the tolerance.
    Converged,
    /// The product limit was reached first.
    IterationLimit,
    /// The caller's [`Cancel`] token was raised.
    Cancelled,
    /// The prescribed force is at or beyond the capacity `μ A Σ p`: no steady solution.
    GrossSliding,
}

/// The answer of [`solve`].
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct RollingSolution {
    /// Shear `q_x` per element (stress, on body 1), grid order.
    pub qx: Vec<f64>,
    /// Shear `q_y` per element.
    pub qy: Vec<f64>,
    /// Slip `s_x` per unit rolled distance per element (dimensionless, body 1 relative to body 2).
    pub sx: Vec<f64>,
    /// Slip `s_y` per element.
    pub sy: Vec<f64>,
    /// Each element's state.
    pub state: Vec<ElementState>,
    /// The creepages `(ξ, η)`: prescribed, or found (NaN under gross sliding).
    pub creepage: (f64, f64),
    /// The total force `(F_x, F_y) = A Σ q` (force).
    pub force: (f64, f64),
    /// The moment `M_z = A Σ (x q_y − y q_x)` about the grid's origin (force × length).
    pub moment: f64,
    /// Elements in stick.
    pub stick: usize,
    /// Elements in slip.
    pub slip: usize,
    /// Operator products (one tangential product each).
    pub products: usize,
    /// Newton steps.
    pub newton_steps: usize,
    /// Why the iteration stopped.
    pub stop: RollingStop,
    /// The natural residual of the disc law relative to `max μp` (module docs), from the final shears.
    pub residual: f64,
}

/// Solve one steady-rolling problem (module docs) with `settings`; `cancel` is checked at every product.
///
/// # Errors
/// An [`ArgumentError`] naming the argument when the operator has no tangential kernels, a vector is not one finite
/// value per element, a pressure is negative, μ, φ or a drive component is not finite (or μ negative), or a setting
/// is out of range.
pub fn solve(
    influence: &Influence,
    problem: &SteadyRolling<'_>,
    settings: &RollingSettings,
    cancel: &Cancel,
) -> Result<RollingSolution, ArgumentError> {
    check(influence, problem, settings)?;
    let grid = influence.grid();
    let n = grid.len();
    let bound: Vec<f64> = problem.pressure.iter().map(|&p| problem.friction * p).collect();
    let rigid = spin_slip(grid, problem);
    let zeros = vec![0.0; n];
    let start = problem.start.unwrap_or((&zeros, &zeros));
    let drive = match problem.drive {
        RollingDrive::Creepage(a, b) => newton::Drive::Creepage(a, b),
        RollingDrive::Force(fx, fy) => {
            let capacity = grid.area() * bound.iter().sum::<f64>();
            if fx.hypot(fy) >= capacity {
                return gross_sliding(influence, &bound, rigid, problem, (fx, fy));
            }
            newton::Drive::Force(fx / grid.area(), fy / grid.area())
        }
    };
    let plus_x = problem.direction == RollingDirection::PlusX;
    let p = newton::Problem { op: influence, bound: &bound, rigid, drive, plus_x, start };
    let out = newton::run(&p, settings.tolerance, settings.max_products, settings.krylov, cancel)?;
    finish(&p, out.q, out.creepage, (out.products, out.steps), out.stop)
}

/// The spin's rigid slip per element, `(−φ y_i, φ (x_i + f Δx))` with the lead `f` along the rolling direction
/// (module docs, "The spin"; dimensionless, per rolled distance).
fn spin_slip(grid: &ContactGrid, problem: &SteadyRolling<'_>) -> (Vec<f64>, Vec<f64>) {
    let phi = problem.spin;
    let sign = if problem.direction == RollingDirection::PlusX { 1.0 } else { -1.0 };
    let lead = problem.spin_lead * grid.dx() * sign;
    let centres = grid.centres();
    (centres.iter().map(|c| -phi * c.1).collect(), centres.iter().map(|c| phi * (c.0 + lead)).collect())
}

/// Every element at its bound along the force: the gross-sliding outcome.
fn gross_sliding(
    op: &Influence,
    bound: &[f64],
    rigid: (Vec<f64>, Vec<f64>),
    problem: &SteadyRolling<'_>,
    f: (f64, f64),
) -> Result<RollingSolution, ArgumentError> {
    let a = f.0.hypot(f.1);
    let (ex, ey) = if a > 0.0 { (f.0 / a, f.1 / a) } else { (0.0, 0.0) };
    let q = (bound.iter().map(|g| g * ex).collect(), bound.iter().map(|g| g * ey).collect());
    let n = bound.len();
    let zeros = vec![0.0; n];
    let plus_x = problem.direction == RollingDirection::PlusX;
    let drive = newton::Drive::Creepage(0.0, 0.0);
    let p = newton::Problem { op, bound, rigid, drive, plus_x, start: (&zeros, &zeros) };
    let mut s = finish(&p, q, (0.0, 0.0), (0, 0), RollingStop::GrossSliding)?;
    s.creepage = (f64::NAN, f64::NAN);
    Ok(s)
}

/// The solution from the final shears with a fresh product (module docs).
fn finish(
    p: &newton::Problem<'_>,
    q: (Vec<f64>, Vec<f64>),
    creepage: (f64, f64),
    (products, newton_steps): (usize, usize),
    stop: RollingStop,
) -> Result<RollingSolution, ArgumentError> {
    let grid = p.op.grid();
    let n = grid.len();
    let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
    let kd = p.diagonal();
    p.slip_of((&q.0, &q.1), creepage, (&mut sx, &mut sy))?;
    let gmax = p.bound.iter().fold(0.0_f64, |m, &g| m.max(g)).max(f64::MIN_POSITIVE);
    let mut residual = 0.0_f64;
    let mut state = Vec::with_capacity(n);
    for i in 0..n {
        let g = p.bound[i];
        residual = residual.max(disc_law_residual((q.0[i], q.1[i]), (sx[i], sy[i]), g, kd) / gmax);
        state.push(if g <= 0.0 {
            ElementState::Exterior
        } else if g - q.0[i].hypot(q.1[i]) <= 1e-9 * g {
            ElementState::Slip
        } else {
            ElementState::Stick
        });
    }
    let count = |s: ElementState| state.iter().filter(|&&e| e == s).count();
    let area = grid.area();
    let force = (area * q.0.iter().sum::<f64>(), area * q.1.iter().sum::<f64>());
    let moment = area * grid.centres().iter().enumerate().map(|(i, c)| c.0 * q.1[i] - c.1 * q.0[i]).sum::<f64>();
    Ok(RollingSolution {
        stick: count(ElementState::Stick),
        slip: count(ElementState::Slip),
        qx: q.0,
        qy: q.1,
        sx,
        sy,
        state,
        creepage,
        force,
        moment,
        products: products + 1,
        newton_steps,
        stop,
        residual,
    })
}

/// The arguments' ranges ([`solve`]).
fn check(op: &Influence, problem: &SteadyRolling<'_>, s: &RollingSettings) -> Result<(), ArgumentError> {
    let bad = |arg: &'static str, msg: String| Err(ArgumentError::new("halfspace::rolling::solve", arg, msg));
    let n = op.grid().len();
    if !op.has_tangential() {
        return bad("influence", "built with Kernels::Normal: no tangential kernels (use Kernels::Full)".into());
    }
    let pressure = problem.pressure;
    if pressure.len() != n {
        return bad("pressure", format!("one value per element ({n}), got {}", pressure.len()));
    }
    if let Some(i) = pressure.iter().position(|p| !(p.is_finite() && *p >= 0.0)) {
        return bad("pressure", format!("pressure[{i}] = {} must be finite and ≥ 0", pressure[i]));
    }
    if !(problem.friction.is_finite() && problem.friction >= 0.0) {
        return bad("friction", format!("a finite coefficient ≥ 0 (got {})", problem.friction));
    }
    if !problem.spin.is_finite() {
        return bad("spin", format!("a finite spin creepage (got {})", problem.spin));
    }
    if !(problem.spin_lead.is_finite() && problem.spin_lead.abs() <= 1.0) {
        return bad("spin_lead", format!("a fraction of the element in [−1, 1] (got {})", problem.spin_lead));
    }
    if let Some((qx, qy)) = problem.start {
        if qx.len() != n || qy.len() != n || !qx.iter().chain(qy).all(|v| v.is_finite()) {
            return bad("start", format!("two vectors of {n} finite values"));
        }
    }
    let (a, b) = match problem.drive {
        RollingDrive::Creepage(a, b) | RollingDrive::Force(a, b) => (a, b),
    };
    if !(a.is_finite() && b.is_finite()) {
        return bad("drive", format!("finite components (got {a}, {b})"));
    }
    if !(s.tolerance > 0.0 && s.tolerance < 1.0) {
        return bad("settings", format!("tolerance in (0, 1) (got {})", s.tolerance));
    }
    if s.max_products == 0 || s.krylov == 0 {
        return bad("settings", "max_products and krylov ≥ 1".into());
    }
    Ok(())
}

/// The shears one element `Δx` downstream: what each particle carried one step earlier, rolling along
/// `direction` (the material moves against it; nothing enters at the leading edge). Grid order.
///
/// # Errors
/// An [`ArgumentError`] when `q` is not one value per element of `grid`.
pub fn carried(grid: &ContactGrid, direction: RollingDirection, q: &[f64]) -> Result<Vec<f64>, ArgumentError> {
    let mx = grid.mx();
    if q.len() != grid.len() {
        let msg = format!("one value per element ({}), got {}", grid.len(), q.len());
        return Err(ArgumentError::new("halfspace::rolling::carried", "q", msg));
    }
    let mut out = vec![0.0; q.len()];
    for (row_in, row_out) in q.chunks(mx).zip(out.chunks_mut(mx)) {
        match direction {
            RollingDirection::PlusX => row_out[..mx - 1].copy_from_slice(&row_in[1..]),
            RollingDirection::MinusX => row_out[1..].copy_from_slice(&row_in[..mx - 1]),
        }
    }
    Ok(out)
}

/// One step of transient rolling (module docs, "Transient rolling"): the pressures of this step, the friction,
/// the spin, the creepages or the force, the direction and the spin lead of `problem` (its `start` is ignored),
/// from the shears `previous` of the step before (`None`: from rest). The answer's `shift` is `Δx (ξ, η)`: prescribed,
/// or found from the force; [`transient_creepage`] divides it out.
///
/// # Errors
/// As [`solve`] and [`super::tangential::solve`].
pub fn transient_step(
    influence: &Influence,
    problem: &SteadyRolling<'_>,
    previous: Option<(&[f64], &[f64])>,
    settings: &TangentialSettings,
    cancel: &Cancel,
) -> Result<tangential::TangentialSolution, ArgumentError> {
    check(influence, problem, &RollingSettings::default())?;
    let grid = influence.grid();
    let h = grid.dx();
    let (mut ox, mut oy) = spin_slip(grid, problem);
    ox.iter_mut().chain(oy.iter_mut()).for_each(|v| *v *= h);
    let drive = match problem.drive {
        RollingDrive::Creepage(xi, eta) => TangentialDrive::Shift(h * xi, h * eta),
        RollingDrive::Force(fx, fy) => TangentialDrive::Force(fx, fy),
    };
    let step = ShiftStep::new(problem.pressure, problem.friction, drive).with_offset(&ox, &oy);
    match previous {
        Some((qx, qy)) => {
            let (px, py) = (carried(grid, problem.direction, qx)?, carried(grid, problem.direction, qy)?);
            tangential::solve(influence, &step.after(&px, &py), settings, cancel)
        }
        None => tangential::solve(influence, &step, settings, cancel),
    }
}

/// The creepages `(ξ, η)` of a [`transient_step`]'s answer on `grid`: its shift over `Δx`.
pub fn transient_creepage(grid: &ContactGrid, step: &tangential::TangentialSolution) -> (f64, f64) {
    (step.shift.0 / grid.dx(), step.shift.1 / grid.dx())
}
