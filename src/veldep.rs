//! # Friction that depends on the slip velocity: CONTACT's laws, and steady rolling with them (library level)
//!
//! ## The laws (CONTACT user guide, §"Velocity dependent friction", its eqs. for L = 2, 3, 4)
//!
//! With `s_a ≥ 0` the magnitude of the absolute slip velocity (length/s), `μ_kin > 0` and the half-value slip
//! velocities `s_h1, s_h2 > 0`:
//!
//! ```text
//! linear      (L = 2): μ(s_a) = μ_kin + μ_lin1 max(0, 1 − s_a/(2 s_h1)) + μ_lin2 max(0, 1 − s_a/(2 s_h2))
//! rational    (L = 3): μ(s_a) = μ_kin + μ_rat1 / (1 + s_a/s_h1)        + μ_rat2 / (1 + (s_a/s_h2)²)
//! exponential (L = 4): μ(s_a) = μ_kin + μ_exp1 exp(−ln 2 · s_a/s_h1)   + μ_exp2 exp(−ln 2 · s_a/s_h2)
//! ```
//!
//! and Coulomb's constant `μ` ([`FrictionLaw::Coulomb`]). A term with a zero coefficient is off. The static
//! coefficient is `μ(0)`.
//!
//! ## Steady rolling with such a law ([`solve_steady`])
//!
//! The steady problem of `crate::formulation::slip`, `s = ξ + D K_TT h` (dimensionless slip velocity), with `μ` a
//! function of the node's own absolute slip velocity `V |s_i|` (V the rolling speed): stick ⇔ `s_i = 0`,
//! `|h_i| ≤ μ(0) f_i`; slip ⇔ `h_i = −μ(V|s_i|) f_i σ_i`, `σ_i = sgn s_i`. Solved by a primal–dual active set with
//! Newton's method inside (the semismooth Newton of the Coulomb solver `active_set`, with the law's slope
//! `μ'(V|s|)` in the slip rows' Jacobian `e_i + f_i V μ' (D K_TT)_i`). With friction that FALLS with the slip
//! velocity the local equation of a slipping node, `t = σa − b f μ(V t)` (`t = |s|`, `s = a + b h` with the other
//! nodes held), can have several roots ([`slip_roots`]), and the steady problem several solutions (Vollebregt &
//! Schuttelaars, J. Sound Vib. 331, 2012). Which one the iteration finds depends on its start ([`Start`]): every
//! contact node sticking (`Below`: the slip grown from zero, CONTACT's INISLP > 0), or every one sliding at the
//! kinetic coefficient (`Above`, INISLP < 0). The outcome names its start; a run that does not converge is a status
//! with its residual ([`SteadyStatus::NotConverged`]), not a solution.
//!
//! A time step of transient rolling is the same problem with another matrix and an offset ([`transient_step`]);
//! [`transient::roll`] rolls many steps in sequence, stopping (with the step's status and residual) at a step that
//! does not converge.
//!
//! ## In scenes
//!
//! `[contact] friction_law` (README, "Scenes") poses a falling law in steady rolling; `crate::pipeline` solves it
//! from both starts ([`solve_both`]) at the normal problem's pressure and reports both ([`BranchReport`]). Only such
//! a scene reaches this module: a Coulomb scene (and a constant law, which is Coulomb's) never does
//! ([`solves_on_this_thread`] counts the solves).
//!
//! Friction memory (CONTACT's MEMDST, MEM_S0): [`Memory`], in steady rolling ([`solve_steady_with`]; a scene's
//! `memory = { ... }`); not in [`transient::roll`]. Tested against CONTACT's `veldep_fric.inp` and its own runs of
//! that problem (tests/veldep.rs).

pub mod transient;

use crate::error::ArgumentError;
use faer::linalg::solvers::Solve;
use faer::Mat;
use std::f64::consts::LN_2;

/// A friction law of the slip velocity (module docs); coefficients dimensionless, slip velocities in length/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// Coulomb: `μ` whatever the slip velocity.
    Coulomb {
        /// The coefficient.
        mu: f64,
    },
    /// CONTACT's L = 2: `μ_kin + c1 max(0, 1 − s/(2 s1)) + c2 max(0, 1 − s/(2 s2))`.
    Linear {
        /// μ_kin (FKIN).
        kinetic: f64,
        /// (μ_lin1, s_h1) (FLIN1, SABSH1).
        first: (f64, f64),
        /// (μ_lin2, s_h2) (FLIN2, SABSH2).
        second: (f64, f64),
    },
    /// CONTACT's L = 3: `μ_kin + c1/(1 + s/s1) + c2/(1 + (s/s2)²)`.
    Rational {
        /// μ_kin (FKIN).
        kinetic: f64,
        /// (μ_rat1, s_h1) (FRAT1, SABSH1).
        first: (f64, f64),
        /// (μ_rat2, s_h2) (FRAT2, SABSH2).
        second: (f64, f64),
    },
    /// CONTACT's L = 4: `μ_kin + c1 exp(−ln2 s/s1) + c2 exp(−ln2 s/s2)`.
    Exponential {
        /// μ_kin (FKIN).
        kinetic: f64,
        /// (μ_exp1, s_h1) (FEXP1, SABSH1).
        first: (f64, f64),
        /// (μ_exp2, s_h2) (FEXP2, SABSH2).
        second: (f64, f64),
    },
}

impl FrictionLaw {
    /// Checks: every coefficient finite, `μ_kin > 0` (Coulomb: `μ ≥ 0`), each term's coefficient `≥ 0` with its
    /// `s_h > 0` when the coefficient is not zero, and `μ(s) ≥ 0` everywhere (true with those). Errors name the part.
    pub fn validated(self) -> Result<Self, ArgumentError> {
        const F: &str = "FrictionLaw::validated";
        let (kinetic, terms) = match self {
            FrictionLaw::Coulomb { mu } => {
                return if mu >= 0.0 && mu.is_finite() {
                    Ok(self)
                } else {
                    Err(ArgumentError::new(F, "mu", format!("must be finite and ≥ 0, got {mu}")))
                }
            }
            FrictionLaw::Linear { kinetic, first, second }
            | FrictionLaw::Rational { kinetic, first, second }
            | FrictionLaw::Exponential { kinetic, first, second } => (kinetic, [first, second]),
        };
        if !(kinetic > 0.0 && kinetic.is_finite()) {
            return Err(ArgumentError::new(F, "kinetic", format!("must be finite and > 0, got {kinetic}")));
        }
        for (name, (c, s)) in ["first", "second"].into_iter().zip(terms) {
            if !(c >= 0.0 && c.is_finite()) || (c > 0.0 && !(s > 0.0 && s.is_finite())) {
                return Err(ArgumentError::new(
                    F,
                    if name == "first" { "first" } else { "second" },
                    format!("needs a coefficient ≥ 0 and, when it is not 0, a slip velocity > 0; got ({c}, {s})"),
                ));
            }
        }
        Ok(self)
    }

    /// `μ(s_a)` at the absolute slip velocity `s_a ≥ 0` (length/s).
    pub fn mu(&self, s_a: f64) -> f64 {
        let term = |(c, s): (f64, f64), f: &dyn Fn(f64) -> f64| if c == 0.0 { 0.0 } else { c * f(s_a / s) };
        match *self {
            FrictionLaw::Coulomb { mu } => mu,
            FrictionLaw::Linear { kinetic, first, second } => {
                let lin = |r: f64| (1.0 - 0.5 * r).max(0.0);
                kinetic + term(first, &lin) + term(second, &lin)
            }
            FrictionLaw::Rational { kinetic, first, second } => {
                kinetic + term(first, &|r| 1.0 / (1.0 + r)) + term(second, &|r| 1.0 / (1.0 + r * r))
            }
            FrictionLaw::Exponential { kinetic, first, second } => {
                let e = |r: f64| (-LN_2 * r).exp();
                kinetic + term(first, &e) + term(second, &e)
            }
        }
    }

    /// The slope `dμ/ds_a` at `s_a ≥ 0` (s/length; the linear law's kink at `2 s_h` takes the right-hand slope).
    pub fn slope(&self, s_a: f64) -> f64 {
        let term = |(c, s): (f64, f64), f: &dyn Fn(f64) -> f64| if c == 0.0 { 0.0 } else { c / s * f(s_a / s) };
        match *self {
            FrictionLaw::Coulomb { .. } => 0.0,
            FrictionLaw::Linear { first, second, .. } => {
                let lin = |r: f64| if r < 2.0 { -0.5 } else { 0.0 };
                term(first, &lin) + term(second, &lin)
            }
            FrictionLaw::Rational { first, second, .. } => {
                term(first, &|r| -1.0 / ((1.0 + r) * (1.0 + r)))
                    + term(second, &|r| -2.0 * r / ((1.0 + r * r) * (1.0 + r * r)))
            }
            FrictionLaw::Exponential { first, second, .. } => {
                let e = |r: f64| -LN_2 * (-LN_2 * r).exp();
                term(first, &e) + term(second, &e)
            }
        }
    }

    /// The kinetic coefficient `μ(∞)` (Coulomb: its `μ`).
    pub fn kinetic_coefficient(&self) -> f64 {
        match *self {
            FrictionLaw::Coulomb { mu } => mu,
            FrictionLaw::Linear { kinetic, .. }
            | FrictionLaw::Rational { kinetic, .. }
            | FrictionLaw::Exponential { kinetic, .. } => kinetic,
        }
    }

    /// The static coefficient `μ(0)`.
    pub fn static_coefficient(&self) -> f64 {
        self.mu(0.0)
    }
}

/// The local equation of a slipping node (module docs): the roots `t > 0` of `t + bf·μ(v t) − c = 0` for `c > bf·μ(0)`
/// (`bf > 0`, `v > 0`), as (smallest, largest, whether there are several), by a scan of `(0, c]` and bisection to
/// round-off. A constant law has one root, `c − bf μ`; a law that falls steeply enough has up to three (the middle
/// one unstable). Where `φ` has no sign change on the scan (it cannot, for `c > bf μ(0)`: `φ(0) < 0 ≤ φ(c)`), `c`.
pub fn slip_roots(law: &FrictionLaw, v: f64, bf: f64, c: f64) -> (f64, f64, bool) {
    let phi = |t: f64| t + bf * law.mu(v * t) - c;
    // φ(0) < 0 and φ(c) = bf μ ≥ 0: the roots lie in (0, c]. A fine logarithmic-then-linear scan finds sign changes.
    let m = 400;
    let mut grid: Vec<f64> = (0..=m).map(|k| c * k as f64 / m as f64).collect();
    grid.extend((1..60).map(|k| c * 1e-12 * 1.6f64.powi(k)).filter(|&t| t < c / m as f64));
    grid.sort_by(f64::total_cmp);
    let bisect = |mut lo: f64, mut hi: f64| {
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if phi(mid) < 0.0 {
                lo = mid
            } else {
                hi = mid
            }
        }
        0.5 * (lo + hi)
    };
    let changes: Vec<(f64, f64)> =
        grid.windows(2).filter(|w| (phi(w[0]) < 0.0) != (phi(w[1]) < 0.0)).map(|w| (w[0], w[1])).collect();
    match (changes.first(), changes.last()) {
        (Some(&(a, b)), Some(&(c2, d))) => (bisect(a, b), bisect(c2, d), changes.len() > 1),
        _ => (c, c, false),
    }
}

/// CONTACT's friction memory (its user guide, "Friction memory"; L = 2, 3, 4 with MEMDST > 0), in steady rolling:
/// the coefficient relaxes towards the law's value along the material's path, `dμ/dt = −max(s_a, s_0)/d_c (μ −
/// μ_s(s_a))`, one backward-Euler step per element: `μ_i = θ_i μ_up + (1 − θ_i) μ_s(s_a,i)`, `θ_i = d_c/(d_c + Δt
/// max(s_a,i, s_0))`, `Δt = Δx/V`, `μ_up` the coefficient of the element upstream (μ(0) ahead of the leading edge),
/// `s_a = 0` in stick and out of contact. A node's coefficient then depends on its upstream neighbours' slip
/// velocities: the problem is solved by the outer iteration alone ([`solve_steady_with`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Memory {
    /// d_c, the memory distance (length, > 0; CONTACT's MEMDST).
    pub distance: f64,
    /// s_0, the least slip velocity of the relaxation (length/s, ≥ 0; MEM_S0).
    pub min_velocity: f64,
    /// Δx, the distance the material travels from one element to the next (length, > 0: the element length).
    pub element: f64,
    /// The rolling direction ±1 (+1: the leading edge is the last node).
    pub direction: i32,
}

impl Memory {
    /// Checks: `distance` finite > 0, `min_velocity` finite ≥ 0, `element` finite > 0, `direction` ±1.
    pub fn validated(self) -> Result<Self, ArgumentError> {
        const F: &str = "veldep::Memory";
        if !(self.distance > 0.0 && self.distance.is_finite()) {
            return Err(ArgumentError::new(F, "distance", format!("must be finite and > 0, got {}", self.distance)));
        }
        if !(self.min_velocity >= 0.0 && self.min_velocity.is_finite()) {
            return Err(ArgumentError::new(
                F,
                "min_velocity",
                format!("must be finite and ≥ 0, got {}", self.min_velocity),
            ));
        }
        if !(self.element > 0.0 && self.element.is_finite()) {
            return Err(ArgumentError::new(F, "element", format!("must be finite and > 0, got {}", self.element)));
        }
        if self.direction.abs() != 1 {
            return Err(ArgumentError::new(F, "direction", format!("must be ±1, got {}", self.direction)));
        }
        Ok(self)
    }

    /// The coefficients of the nodes with slip velocities `s` (dimensionless, 0 where not slipping) at speed `v`.
    fn coefficients(&self, law: &FrictionLaw, v: f64, s: &[f64]) -> Vec<f64> {
        let n = s.len();
        let mut mu = vec![0.0; n];
        let mut upstream = law.static_coefficient();
        let order: Box<dyn Iterator<Item = usize>> =
            if self.direction > 0 { Box::new((0..n).rev()) } else { Box::new(0..n) };
        for i in order {
            let sa = v * s[i].abs();
            let theta = self.distance / (self.distance + self.element / v * sa.max(self.min_velocity));
            mu[i] = theta * upstream + (1.0 - theta) * law.mu(sa);
            upstream = mu[i];
        }
        mu
    }
}

/// Where the iteration starts (module docs): it picks the branch where the steady problem has several solutions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Start {
    /// Every contact node sticking (the slip grown from zero; CONTACT's INISLP > 0).
    #[default]
    Below,
    /// Every contact node sliding at the kinetic coefficient, against the creepage (CONTACT's INISLP < 0).
    Above,
}

/// The steady problem, dimensionless as a [`crate::flexibility::Flexibility`] (lengths / L0, forces / (E L0)).
#[derive(Clone, Debug)]
pub struct SteadyProblem<'a> {
    /// `D K_TT`: the slip velocity per unit tangential nodal force (n × n; `crate::formulation::SlipOperator`'s
    /// steady operator applied to K_TT).
    pub slip_matrix: &'a Mat<f64>,
    /// Normal nodal forces `f_i ≥ 0` (0: out of contact).
    pub normal: &'a [f64],
    /// The creepage ξ (ξ > 0 braking).
    pub creepage: f64,
    /// A per-node offset added to the slip, `s = ξ + c + M h` (`None`: zero). A time step of transient rolling
    /// ([`transient_step`]) is this problem with `M = K_TT/Δq` and `c` from the previous step's displacements.
    pub offset: Option<&'a [f64]>,
    /// The rolling speed V (length/s): the absolute slip velocity is `V |s|`.
    pub velocity: f64,
    /// The friction law.
    pub law: FrictionLaw,
}

/// Converged or not, with the largest residual of the law (module docs of [`solve_steady`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SteadyStatus {
    /// Stick and slip sets settled and the law holds at every node to `residual`.
    Converged {
        /// Active-set iterations taken.
        iterations: usize,
        /// Largest residual of the law.
        residual: f64,
    },
    /// No convergence within the cap: NOT a solution.
    NotConverged {
        /// Iterations taken.
        iterations: usize,
        /// Largest residual of the law at the end.
        residual: f64,
    },
}

/// What [`solve_steady`] found.
#[derive(Clone, Debug)]
pub struct SteadyOutcome {
    /// Converged (with its residual) or not.
    pub status: SteadyStatus,
    /// The start it came from (the branch rule).
    pub start: Start,
    /// Tangential nodal forces `h_i` on the wheel (dimensionless).
    pub tangential: Vec<f64>,
    /// Slip velocities `s_i` (dimensionless; 0 in stick).
    pub slip: Vec<f64>,
    /// Stick flags (in contact and `s_i = 0`).
    pub stick: Vec<bool>,
    /// Outer iterations of CONTACT's scheme it needed before the Newton settled ([`solve_steady`]; 0: none).
    pub fixed_point: usize,
}

/// The law's residual of `(h, s)` with the sets `state` (0 out of contact, 1 stick, ±2 slip with σ = ±1): stick
/// `|s_i|` relative to `|ξ|` and the excess of `|h_i|` over `μ(0) f_i`; slip `|h_i + μ(V|s_i|) f_i σ_i|` and a slip
/// against its sign, relative to `max μ(0) f`.
fn law_residual(p: &SteadyProblem, coef: Coefficients, h: &[f64], s: &[f64], state: &[i8], scale: f64) -> f64 {
    let xi = p.creepage.abs().max(f64::MIN_POSITIVE);
    let mut worst = 0.0f64;
    for i in 0..h.len() {
        let r = match state[i] {
            0 => h[i].abs() / scale,
            1 => (s[i].abs() / xi).max((h[i].abs() - coef.bound(i) * p.normal[i]).max(0.0) / scale),
            st => {
                let sigma = f64::from(st.signum());
                let wrong_way = (-sigma * s[i]).max(0.0) / xi;
                ((h[i] + coef.at(i, p.velocity * s[i].abs()).0 * p.normal[i] * sigma).abs() / scale).max(wrong_way)
            }
        };
        worst = worst.max(r);
    }
    worst
}

/// The slip velocities of the slipping nodes (`state` ±2), 0 elsewhere.
fn slipping(s: &[f64], state: &[i8]) -> Vec<f64> {
    s.iter().zip(state).map(|(&v, &st)| if st.abs() == 2 { v } else { 0.0 }).collect()
}

thread_local! {
    /// Calls of [`solve_steady`] that got past the argument checks, on this thread.
    static SOLVES: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// How many times [`solve_steady`] has started a solve on the calling thread (a time step and each start of
/// [`solve_both`] count one each): the evidence that a Coulomb scene's path never reaches this module (its count
/// does not move; tests/veldep.rs). Per thread, so that tests running side by side do not see each other's solves.
pub fn solves_on_this_thread() -> usize {
    SOLVES.with(std::cell::Cell::get)
}

/// Solve the steady problem (module docs) from `start`; the law's residual must fall below `tolerance`; at most
/// `max_iterations` active-set iterations (each with up to 30 Newton steps). Refused: shapes that differ, a speed
/// that is not finite and > 0, a creepage that is not finite, an invalid law.
///
/// First CONTACT's outer iteration from the start (`fixed_point` below): the coefficients frozen at the previous slip
/// velocities (the start's: μ(0) below, μ_kin above), the per-node Coulomb problem solved, the coefficients
/// updated, until the slip velocities settle. Then the semismooth Newton with the law's slope from the sets and
/// forces it reached, to `tolerance` (the outer iteration alone converges only linearly). Where the problem has
/// several solutions the outer iteration picks CONTACT's (the Newton alone, started from the start's sets, finds
/// other ones in `veldep_fric.inp`'s time steps, and its sets can cycle); where the Newton does not settle from the
/// outer iteration's end, it is started from the start's sets. The outcome's `fixed_point` says how many outer
/// iterations the answer came through (0: the Newton from the start).
pub fn solve_steady(
    p: &SteadyProblem,
    start: Start,
    tolerance: f64,
    max_iterations: usize,
) -> Result<SteadyOutcome, ArgumentError> {
    solve_steady_with(p, None, start, tolerance, max_iterations)
}

/// [`solve_steady`] with CONTACT's friction memory ([`Memory`]; `None`: none, [`solve_steady`]). With memory a
/// node's coefficient depends on the slip upstream, so the outer iteration alone solves it (no Newton after it): to
/// a change of the slip velocities below 1e-13 of their size, then the law's residual with the coefficients of
/// the final slip velocities must be below `tolerance`. Refused as [`solve_steady`], and for an invalid memory.
pub fn solve_steady_with(
    p: &SteadyProblem,
    memory: Option<Memory>,
    start: Start,
    tolerance: f64,
    max_iterations: usize,
) -> Result<SteadyOutcome, ArgumentError> {
    const F: &str = "veldep::solve_steady";
    let n = p.normal.len();
    let m = p.slip_matrix;
    if m.nrows() != n || m.ncols() != n {
        return Err(ArgumentError::new(F, "slip_matrix", format!("must be {n} × {n} (the normal forces' size)")));
    }
    if !(p.velocity > 0.0 && p.velocity.is_finite()) {
        return Err(ArgumentError::new(F, "velocity", format!("must be finite and > 0, got {}", p.velocity)));
    }
    if !p.creepage.is_finite() {
        return Err(ArgumentError::new(F, "creepage", format!("must be finite, got {}", p.creepage)));
    }
    if p.offset.is_some_and(|c| c.len() != n) {
        return Err(ArgumentError::new(F, "offset", format!("must have {n} entries")));
    }
    let law = p.law.validated()?;
    let memory = memory.map(Memory::validated).transpose()?;
    SOLVES.with(|c| c.set(c.get() + 1));
    let scale = p.normal.iter().fold(0.0f64, |a, &f| a.max(law.static_coefficient() * f)).max(f64::MIN_POSITIVE);
    let offset = |i: usize| p.offset.map_or(0.0, |c| c[i]);
    let slip_of = |h: &[f64]| -> Vec<f64> {
        (0..n).map(|i| p.creepage + offset(i) + (0..n).map(|j| m[(i, j)] * h[j]).sum::<f64>()).collect()
    };
    let finish = |state: Vec<i8>, h: Vec<f64>, iterations: usize, fixed_point: usize| {
        let s = slip_of(&h);
        let residual = match &memory {
            None => law_residual(p, Coefficients::Law(&law), &h, &s, &state, scale),
            Some(mem) => {
                let mu = mem.coefficients(&law, p.velocity, &slipping(&s, &state));
                law_residual(p, Coefficients::Frozen(&mu), &h, &s, &state, scale)
            }
        };
        let stick: Vec<bool> = state.iter().map(|&st| st == 1).collect();
        let converged = residual <= tolerance;
        let slip = s.iter().zip(&stick).map(|(&v, &st)| if st && converged { 0.0 } else { v }).collect();
        let status = if converged {
            SteadyStatus::Converged { iterations, residual }
        } else {
            SteadyStatus::NotConverged { iterations, residual }
        };
        SteadyOutcome { status, start, tangential: h, slip, stick, fixed_point }
    };
    let newton_sets = |state: &mut Vec<i8>, h: &mut Vec<f64>| {
        active_set(p, Coefficients::Law(&law), state, h, &slip_of, max_iterations, |st, h| {
            law_residual(p, Coefficients::Law(&law), h, &slip_of(h), st, scale) <= tolerance
        })
    };
    let (mut state, mut h) = initial(p, &law, start);
    let outer = fixed_point(p, &law, memory.as_ref(), start, &mut state, &mut h, &slip_of, max_iterations);
    if memory.is_some() {
        return Ok(finish(state, h, outer, outer));
    }
    if let Some(iterations) = newton_sets(&mut state, &mut h) {
        return Ok(finish(state, h, iterations, outer));
    }
    // The outer iteration led nowhere the Newton settles from: the Newton from the start itself.
    let (mut state, mut h) = initial(p, &law, start);
    let iterations = newton_sets(&mut state, &mut h);
    Ok(finish(state, h, iterations.unwrap_or(max_iterations), 0))
}

/// The sets and forces a start begins from: every contact node sticking with no force (below), or sliding against
/// the creepage at μ_kin (above); out of contact 0.
fn initial(p: &SteadyProblem, law: &FrictionLaw, start: Start) -> (Vec<i8>, Vec<f64>) {
    let sigma0: i8 = if p.creepage < 0.0 { -2 } else { 2 };
    let state: Vec<i8> = p
        .normal
        .iter()
        .map(|&f| match (f <= 0.0, start) {
            (true, _) => 0,
            (false, Start::Below) => 1,
            (false, Start::Above) => sigma0,
        })
        .collect();
    let h = state
        .iter()
        .zip(p.normal)
        .map(|(&st, &f)| if st.abs() == 2 { -law.kinetic_coefficient() * f * f64::from(st.signum()) } else { 0.0 })
        .collect();
    (state, h)
}

/// The coefficient a node's slip row uses at its absolute slip velocity `V t`, `(μ, dμ/ds_a)`, and the bound of a
/// sticking node's force: the law's own (its slope; bound μ(0)), or frozen per node (CONTACT's outer iteration: μ_i
/// fixed, slope 0, bound μ_i).
#[derive(Clone, Copy)]
enum Coefficients<'a> {
    Law(&'a FrictionLaw),
    Frozen(&'a [f64]),
}

impl Coefficients<'_> {
    fn at(&self, i: usize, v_t: f64) -> (f64, f64) {
        match self {
            Coefficients::Law(law) => (law.mu(v_t), law.slope(v_t)),
            Coefficients::Frozen(mu) => (mu[i], 0.0),
        }
    }

    fn bound(&self, i: usize) -> f64 {
        match self {
            Coefficients::Law(law) => law.static_coefficient(),
            Coefficients::Frozen(mu) => mu[i],
        }
    }
}

/// The primal–dual active-set iteration from `state`, `h`: Newton on the sets, then a stick node whose force
/// exceeds its bound slips, a slip node whose slip turns against its sign sticks; `Some(iterations)` once the sets
/// stand and `done` accepts the forces, `None` after `max_iterations`.
fn active_set(
    p: &SteadyProblem,
    coef: Coefficients,
    state: &mut [i8],
    h: &mut [f64],
    slip_of: &dyn Fn(&[f64]) -> Vec<f64>,
    max_iterations: usize,
    done: impl Fn(&[i8], &[f64]) -> bool,
) -> Option<usize> {
    for iteration in 1..=max_iterations {
        newton(p, coef, state, h, slip_of);
        let s = slip_of(h);
        let mut changed = false;
        for i in 0..h.len() {
            let next = match state[i] {
                1 if h[i].abs() > coef.bound(i) * p.normal[i] * (1.0 + 1e-12) => -2 * h[i].signum() as i8,
                st if st.abs() == 2 && f64::from(st.signum()) * s[i] < 0.0 => 1,
                st => st,
            };
            changed |= next != state[i];
            state[i] = next;
        }
        if !changed && done(state, h) {
            return Some(iteration);
        }
    }
    None
}

/// CONTACT's outer iteration for velocity-dependent friction (its user guide, "Velocity dependent friction"; the
/// idea, not its code): coefficients frozen per node at the start's slip velocity (μ(0) below, μ_kin above), the
/// per-node Coulomb problem solved by [`active_set`], the coefficients set to μ(V|s_i|) of the new slip velocities
/// (μ(0) in stick), until the slip velocities change by less than 1e-9 of their size (at most `max_iterations` and
/// 200 times, each inner solve at most `max_iterations` active-set iterations). Leaves
/// the sets and forces it reached; returns the outer iterations taken.
#[allow(clippy::too_many_arguments)]
fn fixed_point(
    p: &SteadyProblem,
    law: &FrictionLaw,
    memory: Option<&Memory>,
    start: Start,
    state: &mut [i8],
    h: &mut [f64],
    slip_of: &dyn Fn(&[f64]) -> Vec<f64>,
    max_iterations: usize,
) -> usize {
    let n = h.len();
    let first = match start {
        Start::Below => law.static_coefficient(),
        Start::Above => law.kinetic_coefficient(),
    };
    let mut mu = vec![first; n];
    let mut previous = vec![0.0; n];
    for outer in 1..=max_iterations.min(200) {
        active_set(p, Coefficients::Frozen(&mu), state, h, slip_of, max_iterations, |_, _| true);
        let s = slipping(&slip_of(h), state);
        let change = s.iter().zip(&previous).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        let size = s.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        mu = match memory {
            Some(m) => m.coefficients(law, p.velocity, &s),
            None => s.iter().map(|v| law.mu(p.velocity * v.abs())).collect(),
        };
        // Without memory the Newton finishes from here; with memory this is the answer, so converged further.
        let settled = if memory.is_some() { 1e-13 } else { 1e-9 };
        if outer > 1 && change <= settled * size {
            return outer;
        }
        previous = s;
    }
    max_iterations.min(200)
}

/// One time step of transient rolling (CONTACT's T = 2 with a shift Δq per step): the slip velocity of node i is
/// `s_i = ξ + (u_i − u_prev(x_i + dir·Δq))/Δq`, the material at `x_i` having been at `x_i + dir·Δq` one step earlier.
/// On a uniform grid with `Δq` = the element length this is node `up(i)` of the previous step, so the step is a
/// [`SteadyProblem`] with `M = K_TT/Δq` and the offset `c_i = −u_prev,up(i)/Δq` (`u_prev = K_TT h_prev`; 0 for the
/// leading-edge node, whose upstream material was outside the grid). Returns `(M, c)`. `k_tt` n × n, `h_prev` of n,
/// `dq > 0`, `direction` ±1; refused otherwise.
pub fn transient_step(
    k_tt: &Mat<f64>,
    h_prev: &[f64],
    dq: f64,
    direction: i32,
) -> Result<(Mat<f64>, Vec<f64>), ArgumentError> {
    const F: &str = "veldep::transient_step";
    let n = h_prev.len();
    if k_tt.nrows() != n || k_tt.ncols() != n {
        return Err(ArgumentError::new(F, "k_tt", format!("must be {n} × {n}")));
    }
    if !(dq > 0.0 && dq.is_finite()) || direction.abs() != 1 {
        return Err(ArgumentError::new(
            F,
            "dq",
            format!("needs dq finite > 0 and direction ±1, got {dq}, {direction}"),
        ));
    }
    let u_prev: Vec<f64> = (0..n).map(|r| (0..n).map(|c| k_tt[(r, c)] * h_prev[c]).sum()).collect();
    let up = |i: usize| if direction > 0 { (i + 1 < n).then_some(i + 1) } else { i.checked_sub(1) };
    let offset = (0..n).map(|i| up(i).map_or(0.0, |j| -u_prev[j] / dq)).collect();
    Ok((Mat::from_fn(n, n, |i, j| k_tt[(i, j)] / dq), offset))
}

/// The steady problem solved from both starts ([`solve_steady`]): the two outcomes, and whether they are two
/// different solutions (both converged, their tangential forces differing by more than `tolerance` relative to
/// max μ(0) f). Where they differ the steady problem has (at least) two solutions, and this says which came from
/// which start; where one did not converge its status says so and nothing is claimed about uniqueness.
#[derive(Clone, Debug)]
pub struct Branches {
    /// From every node sticking.
    pub below: SteadyOutcome,
    /// From every node sliding.
    pub above: SteadyOutcome,
    /// Both converged to different solutions.
    pub distinct: bool,
}

/// [`solve_steady`] from [`Start::Below`] and from [`Start::Above`] ([`Branches`]). Refused as [`solve_steady`].
pub fn solve_both(p: &SteadyProblem, tolerance: f64, max_iterations: usize) -> Result<Branches, ArgumentError> {
    solve_both_with(p, None, tolerance, max_iterations)
}

/// [`solve_both`] with friction memory ([`solve_steady_with`]).
pub fn solve_both_with(
    p: &SteadyProblem,
    memory: Option<Memory>,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Branches, ArgumentError> {
    let below = solve_steady_with(p, memory, Start::Below, tolerance, max_iterations)?;
    let above = solve_steady_with(p, memory, Start::Above, tolerance, max_iterations)?;
    let mu0 = p.law.static_coefficient();
    let scale = p.normal.iter().fold(0.0f64, |a, &f| a.max(mu0 * f)).max(f64::MIN_POSITIVE);
    let converged = |o: &SteadyOutcome| matches!(o.status, SteadyStatus::Converged { .. });
    let gap = below.tangential.iter().zip(&above.tangential).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    let distinct = converged(&below) && converged(&above) && gap > tolerance * scale;
    Ok(Branches { below, above, distinct })
}

/// A scene's friction of the slip velocity (`[contact] friction_law` with `[rolling] velocity`, steady rolling): a
/// law that is not constant, the rolling speed V (length/s) and the start whose solution the runs carry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneFriction {
    /// The law (validated; not constant: a constant law is Coulomb and the scene says so).
    pub law: FrictionLaw,
    /// The rolling speed V (length/s, > 0): the absolute slip velocity is V |s|.
    pub velocity: f64,
    /// The start whose solution the runs carry (both are solved).
    pub start: Start,
    /// Friction memory `(d_c, s_0)` (length, length/s), or none; the pipeline adds the grid's element length and
    /// the rolling direction ([`Memory`]).
    pub memory: Option<(f64, f64)>,
}

/// One start's outcome, as a scene's run reports it (user's units).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BranchFigures {
    /// The start.
    pub start: Start,
    /// Whether it converged (else it is not a solution, and only its residual is reported).
    pub converged: bool,
    /// Active-set iterations taken.
    pub iterations: usize,
    /// The law's largest residual at the end ([`solve_steady`]).
    pub residual: f64,
    /// The tangential force Q = Σ h (force per unit thickness, on the wheel); null when not converged.
    pub tangential: Option<f64>,
    /// Sticking contact nodes (null when not converged).
    pub nodes_stick: Option<usize>,
}

/// Both starts of a scene's steady problem with a falling law, and which one the run carries: where they differ
/// the problem has (at least) two solutions here, and both are reported, never one silently.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BranchReport {
    /// The start whose solution the run's nodes, resultants and status are (`[contact.friction_law] start`).
    pub carried: Start,
    /// From every node sticking.
    pub below: BranchFigures,
    /// From every node sliding.
    pub above: BranchFigures,
    /// Both converged to different solutions ([`Branches::distinct`]).
    pub distinct: bool,
}

impl BranchFigures {
    /// The figures of an outcome; `force` converts a dimensionless force to the user's (E·L0).
    pub fn of(o: &SteadyOutcome, force: f64) -> BranchFigures {
        let (converged, iterations, residual) = match o.status {
            SteadyStatus::Converged { iterations, residual } => (true, iterations, residual),
            SteadyStatus::NotConverged { iterations, residual } => (false, iterations, residual),
        };
        BranchFigures {
            start: o.start,
            converged,
            iterations,
            residual,
            tangential: converged.then(|| o.tangential.iter().sum::<f64>() * force),
            nodes_stick: converged.then(|| o.stick.iter().filter(|&&s| s).count()),
        }
    }

    fn line(&self) -> String {
        let name = match self.start {
            Start::Below => "from below (all stick)",
            Start::Above => "from above (all slide)",
        };
        match (self.tangential, self.nodes_stick) {
            (Some(q), Some(n)) if self.converged => {
                format!("{name}: Q = {q:.6e}, {n} stick, residual {:.1e}", self.residual)
            }
            _ => format!(
                "{name}: not converged in {} iterations, residual {:.3e} (not a solution)",
                self.iterations, self.residual
            ),
        }
    }
}

impl BranchReport {
    /// One line for people: both starts, and whether they found two solutions.
    pub fn describe(&self) -> String {
        let verdict = if self.distinct {
            "two different solutions: the steady problem is not unique here"
        } else if self.below.converged && self.above.converged {
            "the same solution"
        } else {
            "uniqueness not decided (a start did not converge)"
        };
        let carried = match self.carried {
            Start::Below => "below",
            Start::Above => "above",
        };
        format!(
            "slip-velocity friction (run carries the start {carried}): {}; {}; {verdict}",
            self.below.line(),
            self.above.line()
        )
    }
}

/// Newton's method on the equations of fixed sets `state` (out of contact `h_i = 0`, stick `s_i = 0`, slip
/// `h_i + μ(V σ s_i) f_i σ = 0`), up to 30 steps.
fn newton(p: &SteadyProblem, coef: Coefficients, state: &[i8], h: &mut [f64], slip_of: &dyn Fn(&[f64]) -> Vec<f64>) {
    let n = h.len();
    let m = p.slip_matrix;
    for _ in 0..30 {
        let s = slip_of(h);
        let mut j = Mat::<f64>::zeros(n, n);
        let mut r = Mat::<f64>::zeros(n, 1);
        for i in 0..n {
            match state[i] {
                0 => {
                    j[(i, i)] = 1.0;
                    r[(i, 0)] = -h[i];
                }
                1 => {
                    for c in 0..n {
                        j[(i, c)] = m[(i, c)];
                    }
                    r[(i, 0)] = -s[i];
                }
                st => {
                    let sigma = f64::from(st.signum());
                    let t = (sigma * s[i]).max(0.0);
                    let (mu, slope) = coef.at(i, p.velocity * t);
                    let slope = slope * p.velocity * p.normal[i];
                    for c in 0..n {
                        j[(i, c)] = slope * m[(i, c)];
                    }
                    j[(i, i)] += 1.0;
                    r[(i, 0)] = -(h[i] + mu * p.normal[i] * sigma);
                }
            }
        }
        let d = j.partial_piv_lu().solve(&r);
        if (0..n).any(|i| !d[(i, 0)].is_finite()) {
            break;
        }
        // Damped: halve the step until the equations' residual falls (a falling law can throw a full step far).
        let norm = |h: &[f64]| set_residual(p, coef, state, h, &slip_of(h));
        let before = norm(h);
        let mut lambda = 1.0;
        let mut trial: Vec<f64> = (0..n).map(|i| h[i] + d[(i, 0)]).collect();
        for _ in 0..40 {
            if norm(&trial) < before {
                break;
            }
            lambda *= 0.5;
            trial = (0..n).map(|i| h[i] + lambda * d[(i, 0)]).collect();
        }
        let big = (0..n).fold(0.0f64, |a, i| a.max((trial[i] - h[i]).abs()));
        h.copy_from_slice(&trial);
        let hmax = h.iter().fold(0.0f64, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE);
        if big <= 1e-15 * hmax {
            break;
        }
    }
}

/// The sum of squares of the fixed-set equations of [`newton`] at `h` (with its slip `s`).
fn set_residual(p: &SteadyProblem, coef: Coefficients, state: &[i8], h: &[f64], s: &[f64]) -> f64 {
    (0..h.len())
        .map(|i| match state[i] {
            0 => h[i] * h[i],
            1 => {
                // Scaled to a force by the row's diagonal, so that stick and slip rows weigh alike.
                let v = s[i] / p.slip_matrix[(i, i)];
                v * v
            }
            st => {
                let sigma = f64::from(st.signum());
                let t = (sigma * s[i]).max(0.0);
                let v = h[i] + coef.at(i, p.velocity * t).0 * p.normal[i] * sigma;
                v * v
            }
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The laws at chosen points against their formulas (CONTACT's user guide), by hand.
    #[test]
    fn laws_meet_their_formulas() {
        let lin = FrictionLaw::Linear { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
        assert_eq!(lin.mu(0.0), 0.30);
        assert!((lin.mu(100.0) - 0.24).abs() < 1e-15);
        assert_eq!(lin.mu(200.0), 0.18);
        assert_eq!(lin.mu(1e6), 0.18);
        let rat = FrictionLaw::Rational { kinetic: 0.18, first: (0.06, 100.0), second: (0.06, 0.3162) };
        assert!((rat.mu(0.0) - 0.30).abs() < 1e-15);
        assert!((rat.mu(100.0) - (0.18 + 0.03 + 0.06 / (1.0 + (100.0f64 / 0.3162).powi(2)))).abs() < 1e-15);
        let exp = FrictionLaw::Exponential { kinetic: 0.18, first: (0.12, 100.0), second: (0.0, 0.0) };
        assert!((exp.mu(100.0) - 0.24).abs() < 1e-15);
        assert!((exp.mu(200.0) - 0.21).abs() < 1e-15);
        assert_eq!(FrictionLaw::Coulomb { mu: 0.3 }.mu(123.0), 0.3);
        assert!(FrictionLaw::Exponential { kinetic: 0.0, first: (0.1, 1.0), second: (0.0, 0.0) }.validated().is_err());
        assert!(FrictionLaw::Linear { kinetic: 0.1, first: (0.1, 0.0), second: (0.0, 0.0) }.validated().is_err());
    }

    /// Falling friction gives several roots of the local equation t + b f μ(V t) = c; a constant law one. Rational law
    /// with the squared term only, μ = 0.1 + 2/(1 + (t/0.5)²), b f = V = 1, c = 2.12: φ(0) = −0.02, φ rises to
    /// 0.012 at t ≈ 0.066 and falls to about −0.66 near t = 0.8 (worked by hand): three roots.
    #[test]
    fn falling_friction_has_several_local_roots() {
        let falling = FrictionLaw::Rational { kinetic: 0.1, first: (0.0, 0.0), second: (2.0, 0.5) };
        let (lo, hi, several) = slip_roots(&falling, 1.0, 1.0, 2.12);
        assert!(several && lo < 0.066 && hi > 0.8, "{lo} {hi}");
        for t in [lo, hi] {
            assert!((t + falling.mu(t) - 2.12).abs() < 1e-12, "{t}");
        }
        let (lo, hi, several) = slip_roots(&FrictionLaw::Coulomb { mu: 0.3 }, 1.0, 1.0, 0.45);
        assert!(!several && (lo - 0.15).abs() < 1e-12 && lo == hi);
    }
}
