//! The contact flexibility: everything a contact formulation needs to know about the elastic bodies, whatever
//! produced it — a boundary-element model of the finite wheel ([`crate::source::bem_wheel`]) today, the closed forms
//! of an elastic half-plane or the sum with an elastic counter-body tomorrow. Nothing here knows about BEM.
//!
//! **Frame and signs** (`DESIGN.md`): the flat's frame at every contact node, N = y (pressure p = t_y ≥ 0 on the
//! wheel, gap change u_N = u_y), T = x (shear q = t_x on the wheel, tangential displacement u_T = u_x of the wheel
//! relative to the counter-body). The contact unknowns are **nodal forces** f = w p, h = w q (w the tributary
//! length of the node), so the blocks here are `K = F W⁻¹`, displacement per unit nodal force, computed once by
//! the source:
//!
//! ```text
//!   u_N = K_NN f + K_NT h + Σ_m r_N,m ρ_m,      u_T = K_TN f + K_TT h + Σ_m r_T,m ρ_m
//! ```
//!
//! where ρ_m are the rigid modes the source offers ([`RigidMode`]). **Units**: dimensionless, every length divided
//! by [`Scales::length`] and every stress by [`Scales::modulus`]; nodal forces are then in units of E·L0.

use faer::Mat;

/// A rigid degree of freedom of the body's support (or datum) relative to the counter-body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ModeKind {
    /// Tangential shift d_T of the support, +x: every point moves by (1, 0) per unit.
    Shift,
    /// Approach d_N of the support towards the flat: every point moves by (0, −1) per unit.
    Approach,
    /// Counter-clockwise rotation φ about the wheel centre: a point (x, y) moves by (−y, x) per unit.
    Rotation,
}

/// The contact nodes' response to one unit rigid mode.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct RigidMode {
    /// Which rigid motion.
    pub kind: ModeKind,
    /// u_N (= u_y) of the contact nodes per unit mode (dimensionless).
    pub normal: Vec<f64>,
    /// u_T (= u_x) per unit mode; `None` when the source built only the normal problem.
    pub tangential: Option<Vec<f64>>,
}

/// The reference scales of the dimensionless flexibility, in the user's units. Every source uses the wheel's
/// diameter as its reference length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// Reference length L0 = 2R, the wheel's diameter.
    pub length: f64,
    /// Reference stress: the wheel's Young's modulus E.
    pub modulus: f64,
}

impl Scales {
    /// The wheel's radius R = L0/2 (user's unit).
    pub fn radius(&self) -> f64 {
        0.5 * self.length
    }

    /// Force per unit thickness of one dimensionless unit: E·L0.
    pub fn force(&self) -> f64 {
        self.modulus * self.length
    }

    /// Moment per unit thickness of one dimensionless unit: E·L0².
    pub fn moment(&self) -> f64 {
        self.modulus * self.length * self.length
    }
}

/// The contact flexibility and the contact nodes' data, dimensionless (see the module docs).
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Flexibility {
    /// K_NN: u_N per unit normal nodal force (n × n).
    pub k_nn: Mat<f64>,
    /// K_NT: u_N per unit tangential nodal force (only when the tangential problem is built).
    pub k_nt: Option<Mat<f64>>,
    /// K_TN: u_T per unit normal nodal force.
    pub k_tn: Option<Mat<f64>>,
    /// K_TT: u_T per unit tangential nodal force.
    pub k_tt: Option<Mat<f64>>,
    /// The rigid modes the source offers, with the contact nodes' responses.
    pub modes: Vec<RigidMode>,
    /// Contact-node x coordinates (increasing).
    pub x: Vec<f64>,
    /// Contact-node y coordinates (undeformed).
    pub y: Vec<f64>,
    /// Initial gaps g₀ to the counter-body.
    pub g0: Vec<f64>,
    /// Tributary lengths w (∫N ds): nodal force = w × traction.
    pub weights: Vec<f64>,
    /// The contact frame at each node when it is not the flat's: the unit vector N_i (global x, y) along which the
    /// pressure acts on the wheel and the gap is measured, with T_i = (N_y, −N_x) (so N = (0, 1) gives T = (1, 0),
    /// the flat's frame). `None`: the flat's frame N = y, T = x at every node (every source but two finite bodies,
    /// [`crate::source::two_body`], whose frame follows the interface of the two curved surfaces).
    pub normals: Option<Vec<[f64; 2]>>,
    /// The scales that make it dimensionless.
    pub scales: Scales,
    /// This flexibility's identity ([`FlexId`]): a solver's state from a solve on it is used only on it.
    pub id: FlexId,
    /// What is derived from the blocks on first use and kept: FFT products, condition numbers, asymmetry ([`Derived`]).
    pub derived: Derived,
}

/// Quantities derived from a flexibility's blocks, computed on first use and kept for every later solve on it (a
/// model solved for many drives computes each once): the FFT products of K_NN and K_TT ([`crate::toeplitz`]; `None`
/// for a block not of that form or too small to gain), their condition numbers and K_NN's asymmetry. A clone of the
/// flexibility computes them again.
#[derive(Default)]
pub struct Derived {
    nn: std::sync::OnceLock<Option<crate::toeplitz::Toeplitz>>,
    tt: std::sync::OnceLock<Option<crate::toeplitz::Toeplitz>>,
    /// κ₁(K_NN), κ₁(K_TT).
    conditions: std::sync::OnceLock<(f64, Option<f64>)>,
    /// ‖K − Kᵀ‖/‖K‖ of K_NN, as is (0) and with a mode projected out (1).
    asymmetry: [std::sync::OnceLock<f64>; 2],
}

impl Derived {
    /// κ₁(K_NN) and κ₁(K_TT) (when built), computed once by `compute`.
    pub fn conditions(&self, compute: impl FnOnce() -> (f64, Option<f64>)) -> (f64, Option<f64>) {
        *self.conditions.get_or_init(compute)
    }

    /// K_NN's asymmetry, as is (`projected` false) or with the approach mode projected out, computed once by
    /// `compute`.
    pub fn asymmetry(&self, projected: bool, compute: impl FnOnce() -> f64) -> f64 {
        *self.asymmetry[usize::from(projected)].get_or_init(compute)
    }
}

impl Clone for Derived {
    fn clone(&self) -> Derived {
        Derived::default()
    }
}

impl std::fmt::Debug for Derived {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Derived")
    }
}

/// The identity of a flexibility: unique in the process, taken when the flexibility is built (a clone, a coarse grid
/// or a deserialised copy gets a new one). A solver's state (a warm start, a kept factorisation:
/// [`crate::solvers::SolverState`]) records the identity of the flexibility it was computed on and is used only on
/// that one: a state from another model is dropped, never trusted.
#[derive(Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FlexId(u64);

impl FlexId {
    /// A new identity, never handed out before in this process.
    pub fn new() -> FlexId {
        static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
        FlexId(NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
    }

    /// The number (for messages and layouts).
    pub fn get(&self) -> u64 {
        self.0
    }
}

impl Default for FlexId {
    fn default() -> FlexId {
        FlexId::new()
    }
}

/// A clone is another flexibility: it gets a new identity.
impl Clone for FlexId {
    fn clone(&self) -> FlexId {
        FlexId::new()
    }
}

impl Flexibility {
    /// Number of contact nodes.
    pub fn n(&self) -> usize {
        self.x.len()
    }

    /// K_NN as a Toeplitz operator, when it is one of FFT size ([`crate::toeplitz::Toeplitz::detect`]).
    pub fn toeplitz_nn(&self) -> Option<&crate::toeplitz::Toeplitz> {
        self.derived.nn.get_or_init(|| crate::toeplitz::Toeplitz::detect(&self.k_nn)).as_ref()
    }

    /// K_TT as a Toeplitz operator, when it is built and is one of FFT size.
    pub fn toeplitz_tt(&self) -> Option<&crate::toeplitz::Toeplitz> {
        self.derived.tt.get_or_init(|| self.k_tt.as_ref().and_then(crate::toeplitz::Toeplitz::detect)).as_ref()
    }

    /// Whether the tangential blocks were built.
    pub fn has_tangential(&self) -> bool {
        self.k_tt.is_some()
    }

    /// The flexibility of every `stride`-th contact node (a coarse model of the same contact: each kept node carries
    /// the force of the `stride` nodes around it, its tributary length their sum), for a cheap first guess.
    pub fn coarse(&self, stride: usize) -> Flexibility {
        let n = self.n();
        let idx: Vec<usize> = (0..n).step_by(stride.max(1)).collect();
        let pick_mat = |m: &Mat<f64>| Mat::from_fn(idx.len(), idx.len(), |i, j| m[(idx[i], idx[j])]);
        let pick = |v: &[f64]| idx.iter().map(|&i| v[i]).collect::<Vec<f64>>();
        let weights = idx
            .iter()
            .map(|&i| {
                let lo = i.saturating_sub(stride / 2);
                let hi = (i + stride - stride / 2).min(n);
                self.weights[lo..hi].iter().sum()
            })
            .collect();
        Flexibility {
            k_nn: pick_mat(&self.k_nn),
            k_nt: self.k_nt.as_ref().map(pick_mat),
            k_tn: self.k_tn.as_ref().map(pick_mat),
            k_tt: self.k_tt.as_ref().map(pick_mat),
            modes: self
                .modes
                .iter()
                .map(|m| RigidMode {
                    kind: m.kind,
                    normal: pick(&m.normal),
                    tangential: m.tangential.as_ref().map(|t| pick(t)),
                })
                .collect(),
            x: pick(&self.x),
            y: pick(&self.y),
            g0: pick(&self.g0),
            normals: self.normals.as_ref().map(|v| idx.iter().map(|&i| v[i]).collect()),
            weights,
            scales: self.scales,
            id: FlexId::new(),
            derived: Derived::default(),
        }
    }

    /// The contact frame (N_i, T_i) of node `i` in global (x, y) components: the flat's ((0, 1), (1, 0)) unless the
    /// source gives per-node frames ([`Flexibility::normals`]).
    pub fn frame(&self, i: usize) -> ([f64; 2], [f64; 2]) {
        match &self.normals {
            Some(v) => (v[i], [v[i][1], -v[i][0]]),
            None => ([0.0, 1.0], [1.0, 0.0]),
        }
    }

    /// The equilibrium rows of a rigid mode's load on the nodal forces (row_n on f, row_t on h): the resultant
    /// conjugate to the mode, by virtual work. Shift: the force on the wheel along +x, Σ (N_x f + T_x h); approach:
    /// the load P pressing the wheel onto the counter-body, Σ (N_y f + T_y h); rotation: the counter-clockwise
    /// moment about the wheel's centre, Σ (x F_y − y F_x). In the flat's frame these are exactly the rows 0/1, 1/0
    /// and x/−y.
    pub fn load_rows(&self, kind: ModeKind) -> (Vec<f64>, Vec<f64>) {
        let n = self.n();
        let Some(normals) = &self.normals else {
            return match kind {
                ModeKind::Shift => (vec![0.0; n], vec![1.0; n]),
                ModeKind::Approach => (vec![1.0; n], vec![0.0; n]),
                ModeKind::Rotation => (self.x.clone(), self.y.iter().map(|y| -y).collect()),
            };
        };
        let row = |c: &dyn Fn(usize, [f64; 2]) -> f64| -> Vec<f64> { (0..n).map(|i| c(i, normals[i])).collect() };
        let (x, y) = (&self.x, &self.y);
        match kind {
            ModeKind::Shift => (row(&|_, nv| nv[0]), row(&|_, nv| nv[1])),
            ModeKind::Approach => (row(&|_, nv| nv[1]), row(&|_, nv| -nv[0])),
            ModeKind::Rotation => {
                (row(&|i, nv| x[i] * nv[1] - y[i] * nv[0]), row(&|i, nv| x[i] * (-nv[0]) - y[i] * nv[1]))
            }
        }
    }

    /// The rigid mode of a kind, if the source offers it.
    pub fn mode(&self, kind: ModeKind) -> Option<&RigidMode> {
        self.modes.iter().find(|m| m.kind == kind)
    }
}
