//! FASTSIM: Kalker's fast algorithm for the simplified theory of steady rolling contact (J.J. Kalker, "A fast
//! algorithm for the simplified theory of rolling contact", Vehicle System Dynamics 11 (1982) 1–13), for an elliptic
//! contact of semi-axes a (along the rolling direction x) and b (lateral y), with the grid, the variants and the
//! conventions of CONTACT (E.A.H. Vollebregt's program, module 3 with M = 3, T = 3, B = 2 or 3) so that its output
//! can be reproduced (tests/fastsim.rs).
//!
//! # Conventions (CONTACT's)
//!
//! * Units: any consistent set (CONTACT's are mm, N, N/mm²). Creepages ξ, η are dimensionless, the spin φ is in
//!   rad/length.
//! * Creepages are those **of body 1 relative to body 2**: the rigid slip per unit rolled distance is
//!   `w(x, y) = (ξ − φ y, η + φ x)`. Tractions (px, py) and forces act **on body 1**; pn > 0 is compression.
//!   A positive ξ thus gives a negative Fx: `Fx ≈ −G c² C11 ξ` at small creepage (c = √(ab)).
//! * The contact rolls along +x ([`Direction::PlusX`], CONTACT's χ = 0: material enters the contact at its leading
//!   edge x = +a(y) and leaves at −a(y)) or along −x ([`Direction::MinusX`], χ = 180°).
//! * `Mz = Σ (x py − y px) · area` about the ellipse's centre (counter-clockwise seen from +z positive).
//!
//! # The simplified theory and the marching
//!
//! The simplified theory replaces the half-space by independent springs: the displacement difference of a surface
//! particle is `u = L p` (L a flexibility, length³/force). In steady rolling along +x the slip per rolled distance is
//! `s = w − ∂u/∂x`, and Coulomb's law asks `|p| ≤ μ pn`, with `s = 0` where `|p| < μ pn` and `p = −μ pn s/|s|` where
//! the particle slips. Along each row y = const of the grid, FASTSIM marches from the leading edge (where u = 0) to
//! the trailing edge in steps of the element length dx: with p' the traction of the previous element of the row
//! (zero ahead of the contact),
//!
//! ```text
//!   p* = p' − (dx / L) w(x, y)          (adhesion: u − u' = −dx w, i.e. s = 0)
//!   p  = p*                   if |p*| ≤ μ pn   (adhesion)
//!   p  = μ pn p* / |p*|       otherwise        (slip)
//! ```
//!
//! In slip the discrete slip `dx s = u − u' + dx w = L (p − p*)` is anti-parallel to p* and so to p: Coulomb's law
//! holds exactly for one flexibility. The forces are the sums `F = Σ p dx dy` over the elements.
//!
//! # The flexibilities (why they reproduce Kalker's linear theory)
//!
//! At vanishing creepage nothing slips and the marching integrates `u = −∫_x^{a(y)} w dx'`, a(y) = a√(1 − y²/b²).
//! For ξ alone, `px = −ξ (a(y) − x)/L1` and `Fx = −(ξ/L1) ∫ 2a(y)² dy = −8a²b ξ/(3 L1)`; equating it with Kalker's
//! `−G c² C11 ξ` gives `L1 = 8a/(3 C11 G)`, and likewise `L2 = 8a/(3 C22 G)`. For the spin's lateral part
//! `w_y = φ x`: `py = −φ (a(y)² − x²)/(2 L3)`, `Fy = −(2φ/(3 L3)) ∫ a(y)³ dy = −π a³ b φ/(4 L3)`, which equals
//! `−G c³ C23 φ` for `L3 = π a^{3/2} / (4 C23 G √b)` (= π a √(a/b)/(4 C23 G), as CONTACT's `simpflex` writes it).
//! The C_ij are Kalker's Table E.3 ([`crate::theory::kalker`]). The variants ([`Flexibility`]):
//!
//! * [`Flexibility::Weighted`] (Kalker 1982, his original FASTSIM): one flexibility
//!   `L = (|ξ| L1 + |η| L2 + c |φ| L3) / √(ξ² + η² + c² φ²)` (the formula as it is commonly cited from that paper;
//!   the paper itself was not at hand), so the linear theory is reproduced exactly for each creepage alone, and
//!   Coulomb's law holds exactly in the slip area.
//! * [`Flexibility::Three`]: `px = ux/L1`, `py = uy/L2`, the spin entering the rigid slip scaled as
//!   `w = (ξ − (L1/L3) φ y, η + (L2/L3) φ x)` (CONTACT's `set_tang_rhs` for M = 3): Fx and Fy of the linear theory
//!   hold for any combination of creepages (Mz need not: FASTSIM knows no C33), but for L1 ≠ L2 the slip is no
//!   longer exactly opposite to the traction.
//! * [`Flexibility::Blended`]: [`Flexibility::Three`] with the flexibilities moved towards one combined value as the
//!   creepage grows (Vollebregt 2022, CONTACT's default for M = 3 with the creepages prescribed, `simpflex`):
//!   `L_c = (ξ² + η² + (kφ)²) / (ξ²/L1 + η²/L2 + (kφ)²/L3)` with `k = (πa²/4)/(8a/3)`, weight
//!   `f = min(1, r/3)` with `r = √((ξ² + η²)/(χξ² + χη²))`, `χξ = μN/(c² G C11)`, `χη = μN/(c² G C22)`, and
//!   `Li ← (1 − f) Li + f L_c`. This is what CONTACT prints as FLX1–3 for `fastsim.inp`.
//!
//! # The traction bound ([`Bound`])
//!
//! Kalker's original FASTSIM bounds the traction by μ times the **parabolic** pressure
//! `pn = (2N/(πab)) (1 − x²/a² − y²/b²)` ([`Bound::Parabolic`], CONTACT's B = 3), the pressure of the simplified
//! theory itself. [`Bound::Elliptic`] uses Hertz's
//! `pn = (3N/(2πab)) √(1 − x²/a² − y²/b²)` (CONTACT's B = 2, the bound CONTACT advises). Both are evaluated at the
//! element centres as CONTACT does (the discrete Σ pn dx dy is N only in the limit of a fine grid).
//!
//! # The grids ([`Grid`])
//!
//! * [`Grid::Contact`], CONTACT's (IPOTCN = −3): the rectangle `[−s a, s a] × [−s b, s b]` (s ≥ 1) divided into
//!   `mx × my` equal elements; an element is in contact when the pressure at its centre is > 0. Each row is marched
//!   with the step dx = 2sa/mx from its leading element, which starts one whole step from p' = 0; the spin's part of
//!   the rigid slip is evaluated at `x + cos χ · dx · o` with CONTACT's offset o = 1/6 (0 evaluates it at the
//!   centre). These are CONTACT's choices, needed to reproduce its numbers; where a row's leading edge falls between
//!   element centres is not seen, so the error against the continuum is O(dx): about 1.2/mx relative in the linear
//!   regime (tests/fastsim.rs).
//! * [`Grid::Strips`] (the default): `my` strips of width 2b/my, each divided into `mx` equal elements between its
//!   own edges ±a(y); the marching starts at the strip's leading edge, steps half an element to the first centre and
//!   whole elements after, and takes the rigid slip of each step at the step's midpoint. Without slip this
//!   integrates `u = −∫ w` exactly (w is linear in x), so ξ and η alone give Kalker's forces exactly in x and to
//!   O(dy²) across the strips, the spin to O(dx²).
//!
//! Forces are `Σ p · area` over the elements (midpoint rule); `Σ pn · area` → N as the grid refines.
//!
//! FaStrip, the strip theory combined with FASTSIM (Sichani et al. 2016, CONTACT's M = 5), is [`fastrip()`]; its
//! module [`mod@fastrip`] documents the method, its decisions and that its tractions can exceed the traction bound.

use crate::error::ArgumentError;
use crate::theory::kalker::{self, CreepCoefficients};

pub mod fastrip;
pub use fastrip::fastrip;
use std::f64::consts::PI;

/// The elliptic contact and its material: semi-axes, combined shear modulus and Poisson ratio, friction, load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Semi-axis along the rolling direction x (length, > 0).
    pub a: f64,
    /// Lateral semi-axis along y (length, > 0). Kalker's table needs 0.1 ≤ a/b ≤ 10.
    pub b: f64,
    /// Combined modulus of rigidity G = 2/(1/G1 + 1/G2) (force/length², > 0).
    pub shear_modulus: f64,
    /// Combined Poisson ratio ν = G (ν1/G1 + ν2/G2)/2, in [0, 1/2].
    pub nu: f64,
    /// Coefficient of friction μ (≥ 0).
    pub mu: f64,
    /// Normal force N (force, > 0).
    pub normal_force: f64,
}

/// The creepages of body 1 relative to body 2 (CONTACT's CKSI, CETA, CPHI).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creepages {
    /// Longitudinal creepage ξ (dimensionless).
    pub xi: f64,
    /// Lateral creepage η (dimensionless).
    pub eta: f64,
    /// Spin φ (rad/length).
    pub phi: f64,
}

/// The traction bound μ pn: the pressure's shape (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// `pn = (2N/(πab)) (1 − x²/a² − y²/b²)`: Kalker's original FASTSIM (CONTACT's B = 3).
    Parabolic,
    /// Hertz's `pn = (3N/(2πab)) √(1 − x²/a² − y²/b²)` (CONTACT's B = 2).
    Elliptic,
}

/// Which flexibilities the springs have (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flexibility {
    /// One flexibility, Kalker's weighted mean of L1, L2, L3 (his original FASTSIM).
    Weighted,
    /// L1 and L2 for px and py, the spin scaled by L1/L3 and L2/L3 (CONTACT's M = 3 without blending).
    Three,
    /// [`Flexibility::Three`] blended towards one flexibility at large creepage (CONTACT's M = 3 with the
    /// creepages prescribed).
    Blended,
}

/// The rolling direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Rolling along +x (CONTACT's χ = 0): the leading edge is at x = +a.
    PlusX,
    /// Rolling along −x (CONTACT's χ = 180°): the leading edge is at x = −a.
    MinusX,
}

/// The grid (module docs, "The grids").
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Grid {
    /// `my` strips across the ellipse, each divided into `mx` equal elements between its own leading and trailing
    /// edges; the marching starts at the strip's leading edge and the rigid slip of each step is taken at the step's
    /// midpoint (exact for the linear theory's w).
    Strips {
        /// Elements along each strip (≥ 1).
        mx: usize,
        /// Strips (≥ 1).
        my: usize,
    },
    /// CONTACT's rectangular grid (IPOTCN = −3): `mx × my` equal elements over `[−s a, s a] × [−s b, s b]`.
    Contact {
        /// Elements along x (≥ 1).
        mx: usize,
        /// Elements along y (≥ 1).
        my: usize,
        /// The rectangle's half-sides over the semi-axes, s ≥ 1 (CONTACT's SCALE).
        scale: f64,
        /// Where the spin's rigid slip is evaluated, in steps dx ahead of the element centre (CONTACT: 1/6).
        spin_offset: f64,
    },
}

impl Grid {
    /// CONTACT's grid with its spin offset 1/6.
    pub fn contact(mx: usize, my: usize, scale: f64) -> Grid {
        Grid::Contact { mx, my, scale, spin_offset: 1.0 / 6.0 }
    }

    /// Elements along x and y.
    pub fn size(&self) -> (usize, usize) {
        match *self {
            Grid::Strips { mx, my } | Grid::Contact { mx, my, .. } => (mx, my),
        }
    }
}

impl Default for Grid {
    /// 100 strips of 100 elements.
    fn default() -> Grid {
        Grid::Strips { mx: 100, my: 100 }
    }
}

/// The options of [`solve`]: Kalker's original FASTSIM by default (weighted flexibility, parabolic bound, +x) on
/// 100 strips of 100 elements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// The traction bound.
    pub bound: Bound,
    /// The flexibilities.
    pub flexibility: Flexibility,
    /// The rolling direction.
    pub direction: Direction,
    /// The grid.
    pub grid: Grid,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            bound: Bound::Parabolic,
            flexibility: Flexibility::Weighted,
            direction: Direction::PlusX,
            grid: Grid::default(),
        }
    }
}

/// The state of one element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum State {
    /// Outside the contact (pn = 0 at its centre).
    Exterior,
    /// In contact and sticking (|p| < μ pn).
    Adhesion,
    /// In contact and slipping (|p| = μ pn).
    Slip,
}

/// One element of the grid: its centre, pressure, traction on body 1 and state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Element {
    /// Centre x (length).
    pub x: f64,
    /// Centre y (length).
    pub y: f64,
    /// Pressure pn (force/length², the bound's shape).
    pub pn: f64,
    /// Traction px on body 1 (force/length²).
    pub px: f64,
    /// Traction py on body 1 (force/length²).
    pub py: f64,
    /// Adhesion, slip or exterior.
    pub state: State,
    /// The element's weight in the sums F = Σ p · area (length²).
    pub area: f64,
}

impl Element {
    fn new(x: f64, y: f64, pn: f64, area: f64) -> Element {
        let state = if pn > 0.0 { State::Adhesion } else { State::Exterior };
        Element { x, y, pn, px: 0.0, py: 0.0, state, area }
    }
}

/// What [`solve`] returns.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Solution {
    /// Fx on body 1 (force).
    pub fx: f64,
    /// Fy on body 1 (force).
    pub fy: f64,
    /// Mz on body 1 about the ellipse's centre (force·length).
    pub mz: f64,
    /// Σ pn dx dy (force; N only in the limit of a fine grid).
    pub fn_discrete: f64,
    /// Kalker's coefficients used.
    pub coefficients: CreepCoefficients,
    /// The flexibilities L1, L2, L3 used (length³/force; for [`Flexibility::Weighted`] all three are the weighted L).
    pub flexibilities: [f64; 3],
    /// The elements, x fastest: element (ix, iy) is `elements[ix + mx·iy]` (for [`Grid::Strips`] row iy is strip iy,
    /// its elements from −x to +x).
    pub elements: Vec<Element>,
    /// Elements in contact.
    pub n_contact: usize,
    /// Elements in adhesion.
    pub n_adhesion: usize,
    /// Elements in slip.
    pub n_slip: usize,
    /// The largest |p|/(μ pn) over the elements in contact with μ pn > 0 (0 without such elements): at most 1 when
    /// the traction bound holds everywhere, as FASTSIM ensures by construction; FaStrip's strip tractions can exceed
    /// it ([`fastrip`](mod@fastrip)'s module docs: 3.4× in CONTACT's own case 4 of `fastsim.inp`).
    pub bound_ratio: f64,
}

/// The largest grid [`solve`] accepts (elements; about 60 bytes each).
pub const MAX_ELEMENTS: usize = 10_000_000;

/// Kalker's flexibilities `L1 = 8a/(3 C11 G)`, `L2 = 8a/(3 C22 G)`, `L3 = π a^{3/2}/(4 C23 G √b)` (length³/force;
/// module docs), unblended.
pub fn kalker_flexibilities(contact: &Contact, c: &CreepCoefficients) -> [f64; 3] {
    let (a, b, g) = (contact.a, contact.b, contact.shear_modulus);
    [8.0 * a / (3.0 * c.c11 * g), 8.0 * a / (3.0 * c.c22 * g), PI * a * (a / b).sqrt() / (4.0 * c.c23 * g)]
}

/// The flexibilities the variant uses, and the factors (L1/L3, L2/L3) that scale the spin's rigid slip.
fn flexibilities(contact: &Contact, cr: &Creepages, c: &CreepCoefficients, flex: Flexibility) -> ([f64; 3], [f64; 2]) {
    let l = kalker_flexibilities(contact, c);
    let (xi, eta, phi) = (cr.xi, cr.eta, cr.phi);
    match flex {
        Flexibility::Weighted => {
            let cc = (contact.a * contact.b).sqrt();
            let norm = (xi * xi + eta * eta + cc * cc * phi * phi).sqrt();
            let lw =
                if norm > 0.0 { (xi.abs() * l[0] + eta.abs() * l[1] + cc * phi.abs() * l[2]) / norm } else { l[0] };
            ([lw; 3], [1.0, 1.0])
        }
        Flexibility::Three => (l, [l[0] / l[2], l[1] / l[2]]),
        Flexibility::Blended => {
            let (a, b) = (contact.a, contact.b);
            let cc2 = a * b;
            let k = (PI * a * a / 4.0) / (8.0 * a / 3.0);
            let kphi2 = (k * phi).powi(2);
            let num = xi * xi + eta * eta + kphi2;
            let den = (xi * xi / l[0] + eta * eta / l[1] + kphi2 / l[2]).max(1e-14);
            let l_c = num / den;
            let load = contact.mu * contact.normal_force / (cc2 * contact.shear_modulus);
            let (ch_xi, ch_eta) = (load / c.c11, load / c.c22);
            let ratio = ((xi * xi + eta * eta) / (ch_xi * ch_xi + ch_eta * ch_eta)).sqrt().max(1e-10);
            let f = (ratio / 3.0).clamp(0.0, 1.0);
            let lb = l.map(|li| (1.0 - f) * li + f * l_c);
            (lb, [lb[0] / lb[2], lb[1] / lb[2]])
        }
    }
}

fn check(contact: &Contact, cr: &Creepages, opt: &Options) -> Result<(), ArgumentError> {
    const F: &str = "fastsim::solve";
    let positive = [
        ("a", contact.a),
        ("b", contact.b),
        ("shear_modulus", contact.shear_modulus),
        ("normal_force", contact.normal_force),
    ];
    for (name, v) in positive {
        if !(v.is_finite() && v > 0.0) {
            return Err(ArgumentError::new(F, name, format!("must be finite and > 0, is {v}")));
        }
    }
    if !(contact.mu.is_finite() && contact.mu >= 0.0) {
        return Err(ArgumentError::new(F, "mu", format!("must be finite and ≥ 0, is {}", contact.mu)));
    }
    for (name, v) in [("xi", cr.xi), ("eta", cr.eta), ("phi", cr.phi)] {
        if !v.is_finite() {
            return Err(ArgumentError::new(F, name, format!("must be finite, is {v}")));
        }
    }
    let (mx, my) = opt.grid.size();
    if mx == 0 || my == 0 || mx.saturating_mul(my) > MAX_ELEMENTS {
        let msg = format!("mx × my must be ≥ 1 each and at most {MAX_ELEMENTS} elements, is {mx} × {my}");
        return Err(ArgumentError::new(F, "grid", msg));
    }
    if let Grid::Contact { scale, spin_offset, .. } = opt.grid {
        if !(scale.is_finite() && scale >= 1.0) {
            return Err(ArgumentError::new(F, "grid.scale", format!("must be finite and ≥ 1, is {scale}")));
        }
        if !spin_offset.is_finite() {
            return Err(ArgumentError::new(F, "grid.spin_offset", format!("must be finite, is {spin_offset}")));
        }
    }
    Ok(())
}

/// Solves the steady rolling problem by FASTSIM (module docs): the tractions, stick and slip of every element and
/// the creep forces. Errors ([`ArgumentError`] naming the argument): a semi-axis, G or N not finite and > 0, μ < 0
/// or not finite, a creepage not finite, ν or a/b outside Kalker's table (ν ∈ [0, 1/2], a/b ∈ [0.1, 10]), an empty
/// or too large grid, a scale < 1.
pub fn solve(contact: &Contact, creepages: &Creepages, options: &Options) -> Result<Solution, ArgumentError> {
    check(contact, creepages, options)?;
    let coefficients = kalker::creep_coefficients(contact.a, contact.b, contact.nu)?;
    let (l, spin) = flexibilities(contact, creepages, &coefficients, options.flexibility);
    let march = March { creepages, l, spin, mu: contact.mu };
    let pressure = bound_pressure(contact, options.bound);
    let (mx, my) = options.grid.size();
    let mut elements = Vec::with_capacity(mx * my);
    let forward = options.direction == Direction::PlusX;
    match options.grid {
        Grid::Contact { scale, spin_offset, .. } => {
            let (dx, dy) = (2.0 * scale * contact.a / mx as f64, 2.0 * scale * contact.b / my as f64);
            let centre = |i: usize, d: f64, half: f64| -half + (i as f64 + 0.5) * d;
            // The spin's rigid slip at x + cos χ · dx · offset (CONTACT's set_tang_rhs).
            let ahead = if forward { dx * spin_offset } else { -dx * spin_offset };
            for iy in 0..my {
                let y = centre(iy, dy, scale * contact.b);
                let row = elements.len();
                for ix in 0..mx {
                    let x = centre(ix, dx, scale * contact.a);
                    elements.push(Element::new(x, y, pressure(x, y), dx * dy));
                }
                march.row(&mut elements[row..], forward, |e| (dx, e.x + ahead));
            }
        }
        Grid::Strips { .. } => {
            let dy = 2.0 * contact.b / my as f64;
            for iy in 0..my {
                let y = -contact.b + (iy as f64 + 0.5) * dy;
                let half = contact.a * (1.0 - (y / contact.b).powi(2)).max(0.0).sqrt();
                let dx = 2.0 * half / mx as f64;
                let row = elements.len();
                for ix in 0..mx {
                    let x = -half + (ix as f64 + 0.5) * dx;
                    elements.push(Element::new(x, y, pressure(x, y), dx * dy));
                }
                // From the leading edge to the first centre half a step, then whole steps; w at each step's midpoint.
                let lead = if forward { half } else { -half };
                let sign = if forward { 1.0 } else { -1.0 };
                march.row(&mut elements[row..], forward, |e| {
                    if (lead - e.x).abs() < dx {
                        (0.5 * dx, e.x + sign * 0.25 * dx)
                    } else {
                        (dx, e.x + sign * 0.5 * dx)
                    }
                });
            }
        }
    }
    Ok(totals(elements, coefficients, l, contact.mu))
}

/// The forces and counts of the solved elements.
fn totals(elements: Vec<Element>, coefficients: CreepCoefficients, flexibilities: [f64; 3], mu: f64) -> Solution {
    let (mut fx, mut fy, mut mz, mut fn_discrete) = (0.0, 0.0, 0.0, 0.0);
    let (mut n_adhesion, mut n_slip, mut bound_ratio) = (0, 0, 0.0f64);
    for e in &elements {
        if e.state != State::Exterior && mu * e.pn > 0.0 {
            bound_ratio = bound_ratio.max(e.px.hypot(e.py) / (mu * e.pn));
        }
        fx += e.px * e.area;
        fy += e.py * e.area;
        mz += (e.x * e.py - e.y * e.px) * e.area;
        fn_discrete += e.pn * e.area;
        match e.state {
            State::Adhesion => n_adhesion += 1,
            State::Slip => n_slip += 1,
            State::Exterior => {}
        }
    }
    Solution {
        fx,
        fy,
        mz,
        fn_discrete,
        coefficients,
        flexibilities,
        elements,
        n_contact: n_adhesion + n_slip,
        n_adhesion,
        n_slip,
        bound_ratio,
    }
}

/// The creep forces of one steady rolling contact (on body 1, CONTACT's signs: module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct CreepForces {
    /// Longitudinal force Fx on body 1 (force; ≈ −G c² C11 ξ at small ξ, → −μN ξ/|ξ| at large ξ).
    pub fx: f64,
    /// Lateral force Fy on body 1 (force; ≈ −G c² (C22 η + c C23 φ) at small creepage).
    pub fy: f64,
    /// Spin moment Mz on body 1 about the ellipse's centre (force·length).
    pub mz: f64,
}

/// The creep forces by Kalker's original FASTSIM ([`Options::default`]: one weighted flexibility, parabolic traction
/// bound, rolling along +x, 100 strips of 100 elements), for vehicle-dynamics use.
///
/// Units: those of `contact` (e.g. mm, N, N/mm²: forces in N, Mz in N·mm); ξ, η dimensionless, φ in rad/length.
/// Signs (CONTACT's): creepages of body 1 relative to body 2 (rigid slip `(ξ − φ y, η + φ x)`), forces on body 1, so
/// a positive creepage gives a force against it. Accuracy against the simplified theory's continuum: 5e-5 relative
/// in the linear regime (tests/fastsim.rs); against the exact theory, FASTSIM's own approximation (Kalker 1982).
/// Errors: those of [`solve`] (reported with its name).
///
/// ```
/// use rollbem::fastsim::{creep_forces, Contact, Creepages};
/// use rollbem::theory::kalker::creep_coefficients;
/// // A 6 mm × 6 mm steel contact, N = 10 kN, μ = 0.3, a small longitudinal creepage.
/// let contact = Contact { a: 6.0, b: 6.0, shear_modulus: 80_000.0, nu: 0.25, mu: 0.3, normal_force: 10_000.0 };
/// let f = creep_forces(&contact, &Creepages { xi: 1e-7, eta: 0.0, phi: 0.0 }).unwrap();
/// let c11 = creep_coefficients(6.0, 6.0, 0.25).unwrap().c11; // 4.12 (Kalker's Table E.3)
/// let linear = -80_000.0 * 36.0 * c11 * 1e-7; // −G c² C11 ξ
/// assert!((f.fx - linear).abs() < 1e-3 * linear.abs());
/// // Full sliding: the force saturates at μN.
/// let f = creep_forces(&contact, &Creepages { xi: 0.1, eta: 0.0, phi: 0.0 }).unwrap();
/// assert!((f.fx + 0.3 * 10_000.0).abs() < 1e-3 * 3_000.0);
/// ```
pub fn creep_forces(contact: &Contact, creepages: &Creepages) -> Result<CreepForces, ArgumentError> {
    let s = solve(contact, creepages, &Options::default())?;
    Ok(CreepForces { fx: s.fx, fy: s.fy, mz: s.mz })
}

/// The bound's pressure at (x, y) (module docs).
fn bound_pressure(contact: &Contact, bound: Bound) -> impl Fn(f64, f64) -> f64 {
    let (a, b, n) = (contact.a, contact.b, contact.normal_force);
    move |x: f64, y: f64| {
        let f = 1.0 - (x / a).powi(2) - (y / b).powi(2);
        match bound {
            Bound::Parabolic => 2.0 * n / (PI * a * b) * f.max(0.0),
            Bound::Elliptic => 1.5 * n / (PI * a * b) * f.max(0.0).sqrt(),
        }
    }
}

/// The marching of one row (module docs).
struct March<'a> {
    creepages: &'a Creepages,
    l: [f64; 3],
    spin: [f64; 2],
    mu: f64,
}

impl March<'_> {
    /// Marches `row` from its leading element (the last when `forward`, rolling along +x) to its trailing one;
    /// `step(e)` gives the distance from the previous element (or the leading edge) and the x where the rigid
    /// slip of that step is evaluated.
    fn row(&self, row: &mut [Element], forward: bool, step: impl Fn(&Element) -> (f64, f64)) {
        let cr = self.creepages;
        // Displacement differences u = L p of the previous element of the row (zero ahead of the contact).
        let (mut ux, mut uy) = (0.0, 0.0);
        let mut advance = |e: &mut Element| {
            if e.state == State::Exterior {
                (ux, uy) = (0.0, 0.0);
                return;
            }
            let (h, x_w) = step(e);
            let wx = cr.xi - self.spin[0] * cr.phi * e.y;
            let wy = cr.eta + self.spin[1] * cr.phi * x_w;
            ux -= h * wx;
            uy -= h * wy;
            let (mut px, mut py) = (ux / self.l[0], uy / self.l[1]);
            let (p, limit) = (px.hypot(py), self.mu * e.pn);
            e.state = State::Adhesion;
            if p > limit {
                e.state = State::Slip;
                px *= limit / p;
                py *= limit / p;
                (ux, uy) = (self.l[0] * px, self.l[1] * py);
            }
            (e.px, e.py) = (px, py);
        };
        if forward {
            row.iter_mut().rev().for_each(&mut advance);
        } else {
            row.iter_mut().for_each(&mut advance);
        }
    }
}
