//! # Viscoelastic bodies in steady rolling: the standard linear solid and its memory integral
//!
//! ## The material (standard linear solid, Wang & Knothe 1993; CONTACT user guide §"Viscoelastic materials")
//!
//! The standard linear solid (SLS, three parameters) in its creep form: under a constant stress `σ₀` applied at
//! `t = 0` the strain follows the creep compliance
//!
//! ```text
//! C(t) = ε(t)/σ₀ = C_g + (C_r − C_g)(1 − e^{−t/τ_C}) = C_g [1 + f (1 − e^{−t/τ_C})]
//! ```
//!
//! with the initial ("glassy") compliance `C_g = 1/E_g`, the final ("rubbery") `C_r = C_g (1 + f)` and the creep
//! relaxation time `τ_C`. These are CONTACT's inputs: `GG = G_g = E_g/(2(1+ν))` (the scene's `youngs_modulus` is
//! `E_g`), `FG = f = C_v/C_g = (C_r − C_g)/C_g = (E_g − E_r)/E_r ≥ 0` and `TC = τ_C ≥ 0` (s). The same solid in its
//! stress-relaxation form, `E(t) = E_r + (E_g − E_r) e^{−t/τ_E}`, has `f = (E_g − E_r)/E_r` and `τ_C = (E_g/E_r)
//! τ_E` (CONTACT's table of the relations, "stress relaxation test" row); [`StandardLinearSolid::from_relaxation`]
//! converts. Poisson's ratio is constant in time, so every compliance of the body (normal, tangential, coupling)
//! follows the same `C(t)/C_g`.
//!
//! ## Steady rolling (the correspondence with the elastic influence)
//!
//! Let `A(x)` be the ELASTIC surface displacement at `x` (contact frame) of a unit traction element (modulus
//! `E_g`). The contact rolls with speed `V` towards `+x` (`direction = +1`): the material passes the contact from
//! `+x` to `−x`, so the material point now at `x` was at `x + Vσ` a time `σ` ago, where the (steady) load gave the
//! elastic field `A(x + Vσ)`. Boltzmann superposition of the creep compliance over that history,
//! `u = ∫ C(t − s) dε_e(s)/C_g`, integrated by parts (the rigid term at `σ → ∞` dropped: it moves every point
//! alike, the approach absorbs it), gives
//!
//! ```text
//! A_v(x) = A(x) + f ∫₀^∞ e^{−η} A(x + L η) dη,      L = direction · V · τ_C  (the relaxation distance)
//! ```
//!
//! — the form CONTACT integrates numerically (`m_visc.f90`, with QUADPACK at relative accuracy 1e-3; Kalker 1990,
//! appendix D). Limits: `L → 0` (instantaneous creep) gives `(1 + f) A`, the elastic body of the relaxed modulus
//! `E_r = E_g/(1 + f)`; `L → ∞` (frozen creep) gives `A` plus a constant per element (the integral of a far-field
//! that no longer depends on `x`), the elastic body of `E_g`. The pressure at the leading edge rises (the material
//! there has not crept yet) and a rolling resistance appears. Only steady rolling has this form; the scene refuses a
//! viscoelastic body in static, transient or load-path problems.
//!
//! ## The memory integral
//!
//! [`memory_integral`] evaluates `∫₀^∞ e^{−η} g(η) dη` for a `g` that is smooth except at given break points, where
//! it may have kinks and `t ln t`-type singular derivatives (an element's edges passing under the observation
//! point): the interval is cut at the break points below η = 40 and at η = 1, 2, 4, …, 32, each finite piece integrated by tanh-sinh and the last, infinite
//! one by exp-sinh (Takahasi & Mori's double-exponential rules, which converge at end-point singularities of this
//! kind at the rate of analytic integrands). Step `1/16`: ≈ 1e-15 relative on the tests' closed forms.

use crate::error::ArgumentError;
use std::f64::consts::FRAC_PI_2;

/// A standard linear solid in CONTACT's parameters: `compliance_ratio = f = FG` and `creep_time = τ_C = TC`
/// (module docs). The elastic modulus of the body (its `youngs_modulus`) is the glassy `E_g`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardLinearSolid {
    compliance_ratio: f64,
    creep_time: f64,
}

impl StandardLinearSolid {
    /// From CONTACT's `FG = f ≥ 0` (ratio of the Kelvin–Voigt spring compliances, dimensionless) and `TC = τ_C ≥ 0`
    /// (creep relaxation time, s; `f64::INFINITY`: creep never starts). Another value (NaN included) is refused.
    pub fn new(compliance_ratio: f64, creep_time: f64) -> Result<Self, ArgumentError> {
        const F: &str = "StandardLinearSolid::new";
        if !(compliance_ratio >= 0.0 && compliance_ratio.is_finite()) {
            return Err(ArgumentError::new(
                F,
                "compliance_ratio",
                format!("must be finite and ≥ 0, got {compliance_ratio}"),
            ));
        }
        if creep_time.is_nan() || creep_time < 0.0 {
            return Err(ArgumentError::new(F, "creep_time", format!("must be ≥ 0, got {creep_time}")));
        }
        Ok(Self { compliance_ratio, creep_time })
    }

    /// From the stress-relaxation form `E(t) = E_r + (E_g − E_r) e^{−t/τ_E}`: `e_glassy = E_g`, `e_relaxed = E_r`
    /// (`0 < E_r ≤ E_g`, stress unit) and `tau_e = τ_E ≥ 0` (s); `f = (E_g − E_r)/E_r`, `τ_C = (E_g/E_r) τ_E`.
    pub fn from_relaxation(e_glassy: f64, e_relaxed: f64, tau_e: f64) -> Result<Self, ArgumentError> {
        const F: &str = "StandardLinearSolid::from_relaxation";
        if !(e_glassy > 0.0 && e_glassy.is_finite()) {
            return Err(ArgumentError::new(F, "e_glassy", format!("must be finite and > 0, got {e_glassy}")));
        }
        if !(e_relaxed > 0.0 && e_relaxed <= e_glassy) {
            return Err(ArgumentError::new(
                F,
                "e_relaxed",
                format!("must lie in (0, E_g = {e_glassy}] (a relaxed modulus above the glassy one), got {e_relaxed}"),
            ));
        }
        Self::new((e_glassy - e_relaxed) / e_relaxed, e_glassy / e_relaxed * tau_e)
            .map_err(|e| ArgumentError::new(F, "tau_e", e.message))
    }

    /// `f = FG = (C_r − C_g)/C_g = (E_g − E_r)/E_r`, dimensionless.
    pub fn compliance_ratio(&self) -> f64 {
        self.compliance_ratio
    }

    /// `τ_C = TC`, the creep relaxation time (s).
    pub fn creep_time(&self) -> f64 {
        self.creep_time
    }

    /// The relaxed (rubbery) modulus `E_r = E_g/(1 + f)` of a body whose glassy modulus is `e_glassy`.
    pub fn relaxed_modulus(&self, e_glassy: f64) -> f64 {
        e_glassy / (1.0 + self.compliance_ratio)
    }

    /// The creep compliance relative to the glassy one, `C(t)/C_g = 1 + f (1 − e^{−t/τ_C})` (`t ≥ 0`, s).
    pub fn creep_compliance_ratio(&self, t: f64) -> f64 {
        let crept = if self.creep_time == 0.0 { 1.0 } else { -(-t / self.creep_time).exp_m1() };
        1.0 + self.compliance_ratio * crept
    }

    /// The memory of this solid rolled at `velocity` (length/s, `> 0`) in `direction` (±1), with lengths divided by
    /// `length_unit`: `L = direction · V · τ_C / length_unit` ([`Memory`]).
    pub fn memory(&self, velocity: f64, direction: i32, length_unit: f64) -> Memory {
        let distance = if self.creep_time.is_infinite() {
            f64::INFINITY * f64::from(direction.signum())
        } else {
            f64::from(direction.signum()) * velocity * self.creep_time / length_unit
        };
        Memory { ratio: self.compliance_ratio, distance }
    }
}

/// The steady-rolling memory of a viscoelastic body (module docs): `A_v(x) = A(x) + ratio ∫₀^∞ e^{−η} A(x +
/// distance·η) dη`. `ratio = f ≥ 0`; `distance = L` is signed (positive when rolling towards `+x`), in the length
/// unit of the coordinates; `0` is instantaneous creep, `±∞` frozen creep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Memory {
    /// `f`, the compliance ratio.
    pub ratio: f64,
    /// `L = direction · V · τ_C`, the signed relaxation distance.
    pub distance: f64,
}

/// Cuts of the memory integral beside the integrand's own break points.
const FIXED_CUTS: [f64; 6] = [1.0, 2.0, 4.0, 8.0, 16.0, 32.0];

/// tanh-sinh / exp-sinh step.
const STEP: f64 = 1.0 / 16.0;

/// `∫_a^b g` (`a < b` finite) by tanh-sinh; `g` receives the abscissa and its distances to both ends (computed
/// without cancellation, for integrands singular there).
fn tanh_sinh<const K: usize>(a: f64, b: f64, g: &impl Fn(f64) -> [f64; K]) -> [f64; K] {
    let half = 0.5 * (b - a);
    let mut sum = [0.0; K];
    let mut add = |x: f64, w: f64| {
        if x > a && x < b {
            let v = g(x);
            sum.iter_mut().zip(v).for_each(|(s, v)| *s += w * v);
        }
    };
    add(a + half, FRAC_PI_2);
    for k in 1..200 {
        let t = k as f64 * STEP;
        let u = FRAC_PI_2 * t.sinh();
        let cu = u.cosh();
        // 1 − tanh(u) = 2/(1 + e^{2u}): the distance to the end, exact near it.
        let gap = 2.0 / (1.0 + (2.0 * u).exp());
        let w = FRAC_PI_2 * t.cosh() / (cu * cu);
        if w < 1e-20 || gap == 0.0 {
            break;
        }
        add(b - half * gap, w);
        add(a + half * gap, w);
    }
    sum.map(|s| s * half * STEP)
}

/// `∫_c^∞ e^{−(η−c)} g(η) dη` by exp-sinh: `η = c + exp((π/2) sinh t)`.
fn exp_sinh<const K: usize>(c: f64, g: &impl Fn(f64) -> [f64; K]) -> [f64; K] {
    let mut sum = [0.0; K];
    for k in -400..400 {
        let t = k as f64 * STEP;
        let s = (FRAC_PI_2 * t.sinh()).exp();
        if s > 745.0 {
            break;
        }
        let w = FRAC_PI_2 * t.cosh() * s * (-s).exp();
        if w < 1e-20 || c + s == c {
            continue;
        }
        let v = g(c + s);
        sum.iter_mut().zip(v).for_each(|(acc, v)| *acc += w * v);
    }
    sum.map(|s| s * STEP)
}

/// `∫₀^∞ e^{−η} g(η) dη` for a `g` smooth between the `breaks` (positive, any order; others are ignored) and at most
/// logarithmically growing at infinity (module docs, "The memory integral").
pub fn memory_integral<const K: usize>(g: impl Fn(f64) -> [f64; K], breaks: &[f64]) -> [f64; K] {
    // Breaks past η = 40 carry a weight below e^{−40} ≈ 4e-18 and are left to the tail; fixed cuts keep every
    // finite piece where e^{−η} matters short (a piece [0, 1e10] would leave the weight near 0 unresolved).
    let mut cuts: Vec<f64> = breaks.iter().copied().filter(|b| *b > 0.0 && *b < 40.0).collect();
    cuts.extend(FIXED_CUTS);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut total = [0.0; K];
    let mut a = 0.0;
    for &b in &cuts {
        let piece = tanh_sinh(a, b, &|x| g(x).map(|v| v * (-x).exp()));
        total.iter_mut().zip(piece).for_each(|(t, p)| *t += p);
        a = b;
    }
    let tail = exp_sinh(a, &g);
    let scale = (-a).exp();
    total.iter_mut().zip(tail).for_each(|(t, p)| *t += scale * p);
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed forms: ∫₀^∞ e^{−η} dη = 1, ∫ η e^{−η} = 1, ∫ ln η e^{−η} = −γ (Euler's constant), and a kink:
    /// ∫ |η − 1| e^{−η} dη = 2/e.
    #[test]
    fn memory_integral_meets_closed_forms() {
        let one = memory_integral(|_| [1.0], &[]);
        assert!((one[0] - 1.0).abs() < 1e-14, "{}", one[0]);
        let eta = memory_integral(|x| [x], &[]);
        assert!((eta[0] - 1.0).abs() < 1e-14, "{}", eta[0]);
        let gamma = 0.577_215_664_901_532_9;
        let ln = memory_integral(|x| [x.ln()], &[]);
        assert!((ln[0] + gamma).abs() < 1e-13, "{}", ln[0]);
        let kink = memory_integral(|x: f64| [(x - 1.0).abs()], &[1.0]);
        assert!((kink[0] - 2.0 / std::f64::consts::E).abs() < 1e-14, "{}", kink[0]);
        // t ln|t| with t = η − 3: ∫ e^{−η} (η−3) ln|η−3| dη, against a 60-digit value (mpmath quad, split at 3).
        let tl = memory_integral(|x: f64| [(x - 3.0) * (x - 3.0).abs().ln()], &[3.0]);
        assert!((tl[0] - TLOG_REF).abs() < 1e-13, "{}", tl[0]);
    }

    /// mpmath: quad(lambda x: exp(-x)*(x-3)*log(abs(x-3)), [0, 3, inf]) (independent of this code).
    const TLOG_REF: f64 = -1.691_800_978_684_860_6;

    #[test]
    fn relaxation_form_is_contacts_table() {
        // E_g = 3200, E_r = 1600, τ_E = 0.0045 s: f = 1, τ_C = 2 τ_E (CONTACT's table, stress-relaxation row).
        let s = StandardLinearSolid::from_relaxation(3200.0, 1600.0, 0.0045).unwrap();
        assert_eq!(s.compliance_ratio(), 1.0);
        assert!((s.creep_time() - 0.009).abs() < 1e-18);
        assert_eq!(s.relaxed_modulus(3200.0), 1600.0);
        assert_eq!(s.creep_compliance_ratio(0.0), 1.0);
        assert!((s.creep_compliance_ratio(1e3) - 2.0).abs() < 1e-15);
        assert!(StandardLinearSolid::from_relaxation(1.0, 2.0, 1.0).is_err());
        assert!(StandardLinearSolid::new(-1.0, 1.0).is_err());
        assert!(StandardLinearSolid::new(1.0, f64::NAN).is_err());
    }
}
