//! A primal–dual active-set method for the contact problem on its physical unknowns (nodal forces f, h and the
//! load-driven rigid motions): a semi-smooth Newton method on the complementarity functions of the contact and
//! friction laws (Hintermüller, Ito & Kunisch 2002 for the normal problem; Hüeber & Wohlmuth 2005 and Hüeber,
//! Stadler & Wohlmuth 2008 for Coulomb friction), each iteration one linear solve of the active block.
//!
//! **Why this method.** Lemke's cost grows with the whole LCP (3n + 2L unknowns, one pivot per node that changes
//! state, each pivot touching every basic column), and the LCP itself costs several n³ to build. The active-set
//! method works on the physical equations directly: it never forms the LCP, each iteration solves one dense system
//! of the size of the *active* block (contact nodes' f, sticking nodes' h, load-driven rigid motions), and from a
//! warm start (the frictionless solution, or the previous load step) it needs a handful of iterations. Block
//! principal pivoting (Júdice–Pires) would work on the LCP and pay for building it; a semi-smooth Newton on the
//! physical unknowns does not.
//!
//! **The iteration.** Each node is separated (f = h = 0), sticking (g = 0, s = 0), or slipping with σ = ±1
//! (g = 0, h = −σμf: friction opposes a slip of sign σ). For given sets the equations — the gap and slip of the
//! problem's flexibility and slip operator, and the equilibrium rows — are linear; their solution updates the
//! sets by the complementarity functions, with the limits c → ∞ of the usual constants (exact, since one of each
//! complementary pair vanishes at every iterate):
//! - a contact node with f < 0 separates; a separated node with g < 0 comes into contact, slipping in the direction
//!   of its current slip (it carries no force yet) or sticking if it does not slip;
//! - a sticking node with |h| > μf slips with σ = −sgn h; a slipping node whose slip reverses (σ s < 0) sticks.
//!
//! When no node changes set, every condition holds and the iterate is the solution (the harness then certifies it by
//! the solver-independent residuals). A set seen before (cycling) or the iteration limit makes it fall back to
//! Lemke, and the message says so.
//!
//! **Start.** From the problem's warm start when it has one; otherwise the normal problem is solved first with the
//! shear fixed at zero (every node starting in contact), then friction starts with every contact node sticking.
//!
//! **Two phases.** Without normal–tangential coupling the normal problem does not depend on the shear: it is solved
//! once, alone, and the stick–slip problem after it with f fixed, its factorisations updated by bordered solves
//! (`src/solvers/active_set/phases.rs`). With coupling the iteration is the joint one above.

use super::lemke::{self, Lemke, LemkeSettings};
use super::{settings_of, Entry, Figures, Outcome, Solver, SolverId, SolverState, Start, Termination, Validate, Work};
use crate::cancel::Cancel;
use crate::formulation::{ContactProblem, ProblemKind, Solution};

mod phases;
use faer::Mat;
use serde::{Deserialize, Serialize};
use std::collections::HashSet;

/// Settings of the active-set method (`[solvers.active_set]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ActiveSetSettings {
    /// Largest number of active-set iterations before falling back to Lemke. Default 100.
    pub max_iterations: usize,
    /// Relative margin of the set updates (of the force, gap and slip scales): values within it of a bound do not
    /// change a node's set (round-off must not make the sets chatter). Default 1e-12.
    pub margin: f64,
}

impl Default for ActiveSetSettings {
    fn default() -> Self {
        ActiveSetSettings { max_iterations: 100, margin: 1e-12 }
    }
}

impl Validate for ActiveSetSettings {
    fn validate(&self) -> Result<(), (&'static str, String)> {
        super::check_count("max_iterations", self.max_iterations)?;
        super::check_tolerance("margin", self.margin)
    }
}

/// The active-set solver.
pub struct ActiveSet {
    /// Its settings.
    pub settings: ActiveSetSettings,
}

/// The active-set method's identity.
pub const ID: SolverId = SolverId::new("active_set");

/// Registry entry.
pub const ENTRY: Entry = Entry::new::<ActiveSetSettings>(
    "active_set",
    "primal–dual active-set (semi-smooth Newton) on the physical unknowns, warm-started, Lemke as fallback; \
     every scene",
    true,
    &["iterations", "factorisations", "gmres", "pivots"],
    |_, s| Box::new(ActiveSet { settings: settings_of::<ActiveSetSettings>(s).copied().unwrap_or_default() }),
    // O(m²) per iteration with the FFT products and bordered solves, a few factorisations of the active block.
    |m| (1e-7 * m * m, 8.0 * m * m),
);

/// What the active-set method keeps between runs on one layout ([`SolverState`]): the joint iteration's last
/// factorisation (a preconditioner for GMRES), or the two phases' factorisations and normal solution, each reused
/// only when the data defining it are equal bit for bit ([`phases`], "Across solves").
enum ActiveSetState {
    Joint(Kept),
    Phases(Box<phases::Kept>),
}

/// The state of a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum NodeSet {
    Separated,
    Stick,
    /// Slipping with slip sign σ (h = −σμf).
    Slip(i8),
}

/// The problem's data the iteration needs (dimensionless).
struct Data<'p> {
    n: usize,
    mu: f64,
    frictional: bool,
    /// Gap matrix on f (K_NN, or the sliding limit's K).
    knn: &'p Mat<f64>,
    /// Gap matrix on h (K_NT with coupling).
    knt: Option<&'p Mat<f64>>,
    /// Slip matrix on f (D K_TN with coupling).
    atn: Option<Mat<f64>>,
    /// Slip matrix on h (D K_TT), formed only for the joint iteration ([`Data::with_att`]); the two phases
    /// ([`phases`]) take its entries from `ktt` and `slip`.
    att: Option<Mat<f64>>,
    /// K_TT (frictional only).
    ktt: Option<&'p Mat<f64>>,
    /// The slip operator D.
    slip: &'p crate::formulation::SlipOperator,
    /// FFT products for K_NN f (when `knn` is the flexibility's Toeplitz K_NN) and D K_TT h (K_TT Toeplitz; D the
    /// two-diagonal slip operator), the iteration's products on a uniform half-plane grid ([`crate::toeplitz`]).
    fast_nn: Option<&'p crate::toeplitz::Toeplitz>,
    fast_tt: Option<&'p crate::toeplitz::Toeplitz>,
    /// Gap and slip with f = h = 0 and the load-driven motions 0.
    g_const: Vec<f64>,
    s_const: Vec<f64>,
    /// Load-driven DOFs.
    loads: Vec<LoadRow>,
}

/// A load-driven DOF: its responses, its equilibrium row and its load.
struct LoadRow {
    /// Gap response per unit motion.
    gap: Vec<f64>,
    /// Slip response per unit motion.
    slip: Vec<f64>,
    /// Equilibrium row on f (with σμ row_t at the sliding limit).
    row_n: Vec<f64>,
    /// Equilibrium row on h.
    row_t: Vec<f64>,
    /// The prescribed resultant.
    load: f64,
}

impl<'p> Data<'p> {
    /// The data of a problem; with `normal_phase`, the normal problem of a frictional one with the shear fixed at
    /// zero (its tangential load DOF dropped).
    fn of(p: &'p ContactProblem, normal_phase: bool) -> Data<'p> {
        let flex = p.flex;
        let n = flex.n();
        let mu = p.law.friction;
        let frictional = p.kind == ProblemKind::Frictional && !normal_phase;
        let given = p.given();
        let smu = p.limit_factor();
        let (knn, g_const, fast_nn) = match &p.normal {
            Some(np) => (&np.k, np.q0.clone(), None),
            None => {
                let g: Vec<f64> = (0..n)
                    .map(|i| flex.g0[i] + p.dofs.iter().zip(&given).map(|(d, v)| d.gap[i] * v).sum::<f64>())
                    .collect();
                (&flex.k_nn, g, flex.toeplitz_nn())
            }
        };
        let coupling = p.law.coupling && frictional;
        let ktt = if frictional { Some(flex.k_tt.as_ref().expect("tangential blocks")) } else { None };
        let (knt, atn, s_const) = if frictional {
            let atn = coupling.then(|| p.slip.apply_mat(flex.k_tn.as_ref().expect("K_TN")));
            let knt = if coupling { flex.k_nt.as_ref() } else { None };
            let mut s: Vec<f64> = p.slip.offset.clone().unwrap_or_else(|| vec![0.0; n]);
            for (d, v) in p.dofs.iter().zip(&given) {
                if let Some(t) = &d.slip {
                    for i in 0..n {
                        s[i] += t[i] * v;
                    }
                }
            }
            (knt, atn, s)
        } else {
            (None, None, vec![0.0; n])
        };
        let loads = p
            .load_dofs()
            .filter(|d| !(normal_phase && d.kind.is_tangential()))
            .map(|d| {
                let row_n: Vec<f64> = (0..n).map(|i| d.row_n[i] + smu * d.row_t[i]).collect();
                let slip = d.slip.clone().unwrap_or_else(|| vec![0.0; n]);
                LoadRow {
                    gap: d.gap.clone(),
                    slip,
                    row_n,
                    row_t: d.row_t.clone(),
                    load: d.drive.load().expect("load-driven"),
                }
            })
            .collect();
        let fast_tt = if frictional { flex.toeplitz_tt() } else { None };
        Data {
            n,
            mu,
            frictional,
            knn,
            knt,
            atn,
            att: None,
            ktt,
            slip: &p.slip,
            fast_nn,
            fast_tt,
            g_const,
            s_const,
            loads,
        }
    }

    /// The same data with D K_TT formed (the joint iteration's reduced systems read it entry by entry).
    fn with_att(mut self) -> Self {
        self.att = self.ktt.map(|k| self.slip.apply_mat(k));
        self
    }

    /// (D K_TT)[i, j].
    fn att_entry(&self, i: usize, j: usize) -> f64 {
        match &self.att {
            Some(a) => a[(i, j)],
            None => self.slip.entry(self.ktt.expect("frictional"), i, j),
        }
    }
}

/// An iterate: forces, load-driven motions, and the gaps and slips they give at every node.
#[derive(Clone)]
struct Iterate {
    f: Vec<f64>,
    h: Vec<f64>,
    rho: Vec<f64>,
    g: Vec<f64>,
    s: Vec<f64>,
}

/// The factor e_j of h_j = e_j f_j at a slipping node (0 elsewhere: a sticking node's h is an unknown).
fn slip_factor(d: &Data, set: NodeSet) -> f64 {
    match set {
        NodeSet::Slip(sg) if d.frictional => -(sg as f64) * d.mu,
        _ => 0.0,
    }
}

/// The system of given sets in the *full* unknowns y = [f (n); h (n, frictional only); ρ (L)]: one normal row per
/// node (f_i = ·, or g_i = ·), one tangential row per node (h_i = ·, s_i = ·, or h_i + σμ f_i = ·), one row per
/// load-driven DOF. The active-set step solves it with right-hand side [−g_const; −s_const; L] on the trivial rows
/// 0; the reduced system ([`Reduced`]) is its non-trivial block.
struct Full<'d, 'p> {
    d: &'d Data<'p>,
    sets: Vec<NodeSet>,
}

impl Full<'_, '_> {
    fn size(&self) -> usize {
        if self.d.frictional {
            2 * self.d.n + self.d.loads.len()
        } else {
            self.d.n + self.d.loads.len()
        }
    }

    /// The right-hand side of the active-set step.
    fn rhs(&self) -> Vec<f64> {
        let d = self.d;
        let n = d.n;
        let mut b = vec![0.0; self.size()];
        for i in 0..n {
            if self.sets[i] != NodeSet::Separated {
                b[i] = -d.g_const[i];
            }
            if d.frictional && self.sets[i] == NodeSet::Stick {
                b[n + i] = -d.s_const[i];
            }
        }
        let base = self.size() - d.loads.len();
        for (l, ld) in d.loads.iter().enumerate() {
            b[base + l] = ld.load;
        }
        b
    }

    /// E(sets) y.
    fn apply(&self, y: &[f64]) -> Vec<f64> {
        let d = self.d;
        let n = d.n;
        let (f, h, rho) = self.split(y);
        let (g, s) = kinematics(d, f, h, rho, false);
        let mut out = vec![0.0; self.size()];
        for i in 0..n {
            out[i] = if self.sets[i] == NodeSet::Separated { f[i] } else { g[i] };
            if d.frictional {
                out[n + i] = match self.sets[i] {
                    NodeSet::Separated => h[i],
                    NodeSet::Stick => s[i],
                    NodeSet::Slip(_) => h[i] - slip_factor(d, self.sets[i]) * f[i],
                };
            }
        }
        let base = self.size() - d.loads.len();
        for (l, ld) in d.loads.iter().enumerate() {
            out[base + l] =
                (0..n).map(|j| ld.row_n[j] * f[j] + if d.frictional { ld.row_t[j] * h[j] } else { 0.0 }).sum();
        }
        out
    }

    fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], &'y [f64], &'y [f64]) {
        let n = self.d.n;
        if self.d.frictional {
            (&y[..n], &y[n..2 * n], &y[2 * n..])
        } else {
            (&y[..n], &y[n..n], &y[n..])
        }
    }
}

/// K v for a column-major K (a contiguous pass per column, through faer's matrix product).
fn matvec(k: &Mat<f64>, v: &[f64]) -> Vec<f64> {
    let x = faer::ColRef::from_slice(v);
    let y = k * x;
    y.iter().copied().collect()
}

/// g and s of forces and load-driven motions; with `constants` the constant parts are included (the physical gap
/// and slip), without them the linear map only.
fn kinematics(d: &Data, f: &[f64], h: &[f64], rho: &[f64], constants: bool) -> (Vec<f64>, Vec<f64>) {
    (gaps(d, f, h, rho, constants), slips(d, f, h, rho, constants))
}

/// The gap part of [`kinematics`].
fn gaps(d: &Data, f: &[f64], h: &[f64], rho: &[f64], constants: bool) -> Vec<f64> {
    let c = if constants { 1.0 } else { 0.0 };
    // The FFT product takes f of the matrix's size, which it always has here; the dense product is the fallback.
    let mut g = match d.fast_nn.and_then(|t| t.apply(f).ok()) {
        Some(g) => g,
        None => matvec(d.knn, f),
    };
    if let Some(k) = d.knt {
        g.iter_mut().zip(matvec(k, h)).for_each(|(a, b)| *a += b);
    }
    for (i, gi) in g.iter_mut().enumerate() {
        *gi += c * d.g_const[i] + d.loads.iter().zip(rho).map(|(ld, r)| ld.gap[i] * r).sum::<f64>();
    }
    g
}

/// The slip part of [`kinematics`] (zeros without friction).
fn slips(d: &Data, f: &[f64], h: &[f64], rho: &[f64], constants: bool) -> Vec<f64> {
    let c = if constants { 1.0 } else { 0.0 };
    let Some(ktt) = d.ktt else { return vec![0.0; d.n] };
    let mut s = match (d.fast_tt.and_then(|t| t.apply(h).ok()), &d.att) {
        (Some(th), _) => d.slip.apply(&th),
        (None, Some(att)) => matvec(att, h),
        (None, None) => d.slip.apply(&matvec(ktt, h)),
    };
    if let Some(k) = &d.atn {
        s.iter_mut().zip(matvec(k, f)).for_each(|(a, b)| *a += b);
    }
    for (i, si) in s.iter_mut().enumerate() {
        *si += c * d.s_const[i] + d.loads.iter().zip(rho).map(|(ld, r)| ld.slip[i] * r).sum::<f64>();
    }
    s
}

/// The non-trivial block of the full system of some sets, factorised: unknowns f_C (contact nodes), h_S (sticking
/// nodes), ρ; rows the contact nodes' gaps, the sticking nodes' slips and the equilibrium rows. Solving the full
/// system for any right-hand side r takes one solve with it ([`Reduced::solve_full`]).
struct Reduced {
    sets: Vec<NodeSet>,
    contact: Vec<usize>,
    stick: Vec<usize>,
    /// The layout it was built for: the number of load-driven DOFs and whether the problem is frictional.
    loads: usize,
    frictional: bool,
    factor: Factor,
}

/// The factorisation of a reduced system.
enum Factor {
    /// Nothing to solve (no contact node, no load-driven motion).
    Empty,
    /// The whole block, LU with partial pivoting.
    Whole(crate::lu::InPlaceLu),
}

impl Factor {
    fn of(a: Mat<f64>) -> Factor {
        if a.nrows() == 0 {
            Factor::Empty
        } else {
            Factor::Whole(crate::lu::InPlaceLu::new(a))
        }
    }

    /// Solve with the factorised system (b: m × 1).
    fn solve(&self, b: &Mat<f64>) -> Mat<f64> {
        match self {
            Factor::Empty => Mat::zeros(0, 1),
            Factor::Whole(lu) => lu.solve(b),
        }
    }
}

impl Reduced {
    fn new(d: &Data, sets: &[NodeSet]) -> Reduced {
        let n = d.n;
        let contact: Vec<usize> = (0..n).filter(|&i| sets[i] != NodeSet::Separated).collect();
        let stick: Vec<usize> =
            if d.frictional { (0..n).filter(|&i| sets[i] == NodeSet::Stick).collect() } else { vec![] };
        let (nc, ns, nl) = (contact.len(), stick.len(), d.loads.len());
        let m = nc + ns + nl;
        let e = |j: usize| slip_factor(d, sets[j]);
        let mut a = Mat::<f64>::zeros(m, m);
        for (c, &j) in contact.iter().enumerate() {
            let ej = e(j);
            for (r, &i) in contact.iter().enumerate() {
                a[(r, c)] = d.knn[(i, j)] + d.knt.map_or(0.0, |k| k[(i, j)] * ej);
            }
            if d.frictional {
                for (r, &i) in stick.iter().enumerate() {
                    a[(nc + r, c)] = d.atn.as_ref().map_or(0.0, |k| k[(i, j)]) + d.att_entry(i, j) * ej;
                }
            }
            for (l, ld) in d.loads.iter().enumerate() {
                a[(nc + ns + l, c)] = ld.row_n[j] + ld.row_t[j] * ej;
            }
        }
        for (c, &j) in stick.iter().enumerate() {
            if let Some(knt) = d.knt {
                for (r, &i) in contact.iter().enumerate() {
                    a[(r, nc + c)] = knt[(i, j)];
                }
            }
            for (r, &i) in stick.iter().enumerate() {
                a[(nc + r, nc + c)] = d.att_entry(i, j);
            }
            for (l, ld) in d.loads.iter().enumerate() {
                a[(nc + ns + l, nc + c)] = ld.row_t[j];
            }
        }
        for (l, ld) in d.loads.iter().enumerate() {
            for (r, &i) in contact.iter().enumerate() {
                a[(r, nc + ns + l)] = ld.gap[i];
            }
            for (r, &i) in stick.iter().enumerate() {
                a[(nc + r, nc + ns + l)] = ld.slip[i];
            }
        }
        let factor = Factor::of(a);
        Reduced { sets: sets.to_vec(), contact, stick, loads: nl, frictional: d.frictional, factor }
    }

    /// Whether this factorisation has the layout of `d`'s full system (nodes, load-driven DOFs, friction). One
    /// kept from an earlier solve on the same flexibility may not: a load path can switch a DOF from load to
    /// displacement control between steps, and its preconditioner would then have the wrong size.
    fn fits(&self, d: &Data) -> bool {
        self.sets.len() == d.n && self.loads == d.loads.len() && self.frictional == d.frictional
    }

    /// Solve the full system of these sets for the right-hand side r (full layout); `None` if singular.
    fn solve_full(&self, d: &Data, r: &[f64]) -> Option<Vec<f64>> {
        if !self.fits(d) {
            return None;
        }
        let n = d.n;
        let full = Full { d, sets: self.sets.clone() };
        let nfull = full.size();
        let base = nfull - d.loads.len();
        // Known values: f and h of separated nodes, the constant part of h at slipping nodes.
        let mut known = vec![0.0; nfull];
        for i in 0..n {
            match self.sets[i] {
                NodeSet::Separated => {
                    known[i] = r[i];
                    if d.frictional {
                        known[n + i] = r[n + i];
                    }
                }
                NodeSet::Slip(_) if d.frictional => known[n + i] = r[n + i],
                _ => {}
            }
        }
        let (f, h, rho) = full.split(&known);
        let (g, s) = kinematics(d, f, h, rho, false);
        let (nc, ns, nl) = (self.contact.len(), self.stick.len(), d.loads.len());
        let mut b = Mat::<f64>::zeros(nc + ns + nl, 1);
        for (k, &i) in self.contact.iter().enumerate() {
            b[(k, 0)] = r[i] - g[i];
        }
        for (k, &i) in self.stick.iter().enumerate() {
            b[(nc + k, 0)] = r[n + i] - s[i];
        }
        for (l, ld) in d.loads.iter().enumerate() {
            let known_row: f64 =
                (0..n).map(|j| ld.row_n[j] * f[j] + if d.frictional { ld.row_t[j] * h[j] } else { 0.0 }).sum();
            b[(nc + ns + l, 0)] = r[base + l] - known_row;
        }
        let y = self.factor.solve(&b);
        if !(0..y.nrows()).all(|k| y[(k, 0)].is_finite()) {
            return None;
        }
        let mut out = known;
        for (k, &j) in self.contact.iter().enumerate() {
            out[j] = y[(k, 0)];
            if d.frictional {
                out[n + j] += slip_factor(d, self.sets[j]) * y[(k, 0)];
            }
        }
        for (k, &j) in self.stick.iter().enumerate() {
            out[n + j] = y[(nc + k, 0)];
        }
        for l in 0..nl {
            out[base + l] = y[(nc + ns + l, 0)];
        }
        Some(out)
    }
}

/// Right-preconditioned restarted GMRES for E y = b from y0, with the preconditioner `prec` (an exact solve of a
/// nearby system); returns the solution and the iterations, or `None` when it does not reach `tol` (relative to
/// ‖b‖) within `max_iter`.
fn gmres(
    e: &dyn Fn(&[f64]) -> Vec<f64>,
    prec: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    b: &[f64],
    y0: &[f64],
    tol: f64,
    max_iter: usize,
) -> Option<(Vec<f64>, usize)> {
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let bnorm = norm(b).max(f64::MIN_POSITIVE);
    let mut y = y0.to_vec();
    let mut total = 0;
    let restart = 60;
    while total < max_iter {
        let ey = e(&y);
        let r: Vec<f64> = b.iter().zip(&ey).map(|(b, v)| b - v).collect();
        let beta = norm(&r);
        if beta <= tol * bnorm {
            return Some((y, total));
        }
        let mut v: Vec<Vec<f64>> = vec![r.iter().map(|x| x / beta).collect()];
        let mut z: Vec<Vec<f64>> = Vec::new();
        let mut hm: Vec<Vec<f64>> = Vec::new(); // columns of the Hessenberg matrix
        let (mut cs, mut sn): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
        let mut gvec = vec![beta];
        let mut k = 0;
        while k < restart && total < max_iter {
            let zk = prec(&v[k])?;
            let mut w = e(&zk);
            z.push(zk);
            let mut col = vec![0.0; k + 2];
            for (i, vi) in v.iter().enumerate() {
                let hij: f64 = w.iter().zip(vi).map(|(a, b)| a * b).sum();
                col[i] = hij;
                for (wj, vj) in w.iter_mut().zip(vi) {
                    *wj -= hij * vj;
                }
            }
            col[k + 1] = norm(&w);
            for i in 0..k {
                let t = cs[i] * col[i] + sn[i] * col[i + 1];
                col[i + 1] = -sn[i] * col[i] + cs[i] * col[i + 1];
                col[i] = t;
            }
            let rr = col[k].hypot(col[k + 1]);
            let (c, s) = if rr == 0.0 { (1.0, 0.0) } else { (col[k] / rr, col[k + 1] / rr) };
            cs.push(c);
            sn.push(s);
            col[k] = rr;
            let hk1 = col[k + 1];
            col[k + 1] = 0.0;
            gvec.push(-s * gvec[k]);
            gvec[k] *= c;
            hm.push(col);
            total += 1;
            k += 1;
            // A NaN or an infinity in the Krylov basis (an operator that overflows) is a failure, not a breakdown:
            // neither `hk1 > 0` nor `hk1 == 0` holds for NaN, and the next step indexed a basis vector that was
            // never pushed (found by the `scene` fuzz target).
            if !(hk1.is_finite() && gvec[k].is_finite()) {
                return None;
            }
            let converged = gvec[k].abs() <= tol * bnorm;
            if !converged && hk1 > 0.0 {
                v.push(w.iter().map(|x| x / hk1).collect());
            }
            if converged || hk1 == 0.0 {
                break;
            }
        }
        // Back substitution for the Krylov coefficients, then y += Z c.
        let mut coef = vec![0.0; k];
        for i in (0..k).rev() {
            let mut t = gvec[i];
            for j in i + 1..k {
                t -= hm[j][i] * coef[j];
            }
            coef[i] = t / hm[i][i];
        }
        for (j, zj) in z.iter().enumerate() {
            for (yi, zi) in y.iter_mut().zip(zj) {
                *yi += coef[j] * zi;
            }
        }
        if !y.iter().all(|v| v.is_finite()) {
            return None;
        }
    }
    let ey = e(&y);
    let rn = norm(&b.iter().zip(&ey).map(|(b, v)| b - v).collect::<Vec<_>>());
    (rn <= tol * bnorm).then_some((y, total))
}

/// One linear step of the iteration: the iterate of given sets.
trait Step {
    /// Solve the system of `sets`, from the previous full solution `y0` when given; with `last`, to round-off.
    /// `None` when the system is singular (or, for a phase, when the sets leave it).
    fn solve(&mut self, d: &Data, sets: &[NodeSet], y0: Option<&[f64]>, last: bool) -> Option<Iterate>;
    /// Whether the last solve was direct (round-off accurate).
    fn last_direct(&self) -> bool;
}

impl Step for Linear {
    fn solve(&mut self, d: &Data, sets: &[NodeSet], y0: Option<&[f64]>, last: bool) -> Option<Iterate> {
        Linear::solve(self, d, sets, y0, last)
    }

    fn last_direct(&self) -> bool {
        self.last_direct
    }
}

/// GMRES's relative residual when it reuses a factorisation to decide the next sets.
const GMRES_TOLERANCE: f64 = 1e-12;

/// The solver of the linear systems of the iteration: a factorisation of some sets' system, reused through GMRES
/// while the sets differ from it in few nodes.
///
/// **Across solves.** On a model solved for many drives (a creep curve), the last factorisation is kept in the
/// solver's state ([`SolverState`], owned by the caller's warm start) and taken up by the next solve only as GMRES's
/// preconditioner (it may belong to another drive: it changes how fast GMRES converges, never the answer); the final
/// solve of every solve is a direct one of its own sets.
struct Linear {
    base: Option<Reduced>,
    /// Whether `base` is this problem's system for its sets (false for one carried over from another solve).
    base_exact: bool,
    /// Factorisations and GMRES iterations so far.
    factorisations: usize,
    gmres_iterations: usize,
    /// Whether the last solve was direct (a factorisation of its own sets: round-off accurate).
    last_direct: bool,
}

/// What the joint iteration keeps between solves ([`Linear`]): its last factorisation.
struct Kept {
    base: Option<Reduced>,
}

impl Linear {
    fn new() -> Linear {
        Linear { base: None, base_exact: false, factorisations: 0, gmres_iterations: 0, last_direct: false }
    }

    /// A solver starting from what the last solve on the same layout kept (for a problem of `n` nodes).
    fn resume(kept: Kept, n: usize) -> Linear {
        let mut l = Linear::new();
        l.base = kept.base.filter(|b| b.sets.len() == n);
        l
    }

    /// What to keep for the next solve.
    fn keep(self) -> Kept {
        Kept { base: self.base }
    }

    /// Solve the system of `sets` (returning the iterate), from the previous full solution `y0` when given; with
    /// `last`, to round-off (the final solve of the converged sets: a factorisation of these sets, or the one it
    /// has when it is of these sets).
    fn solve(&mut self, d: &Data, sets: &[NodeSet], y0: Option<&[f64]>, last: bool) -> Option<Iterate> {
        if self.base.as_ref().is_some_and(|base| !base.fits(d)) {
            self.base = None;
        }
        let full = Full { d, sets: sets.to_vec() };
        let b = full.rhs();
        let changed = self.base.as_ref().map_or(usize::MAX, |r| (0..d.n).filter(|&i| r.sets[i] != sets[i]).count());
        let reuse_limit = (d.n / 100).clamp(8, 40);
        let exact_hit = changed == 0 && self.base_exact;
        let mut y = None;
        if let (Some(base), Some(y0), false) = (&self.base, y0, last || changed > reuse_limit || exact_hit) {
            let e = |v: &[f64]| full.apply(v);
            let prec = |v: &[f64]| base.solve_full(d, v);
            // GMRES converges in about twice the rank of the change.
            if let Some((sol, its)) = gmres(&e, &prec, &b, y0, GMRES_TOLERANCE, 4 * changed + 20) {
                self.gmres_iterations += its;
                y = Some(sol);
            }
        }
        self.last_direct = y.is_none() || exact_hit || last;
        let y = match y {
            Some(y) => y,
            None if exact_hit => self.base.as_ref()?.solve_full(d, &b)?,
            None => {
                // The old factorisation goes before the new one is made (peak memory: two n × n blocks, not three).
                self.base = None;
                let red = Reduced::new(d, sets);
                self.factorisations += 1;
                let sol = red.solve_full(d, &b)?;
                self.base = Some(red);
                self.base_exact = true;
                sol
            }
        };
        let (f, h, rho) = full.split(&y);
        let (f, h, rho) = (f.to_vec(), if d.frictional { h.to_vec() } else { vec![0.0; d.n] }, rho.to_vec());
        let (g, s) = kinematics(d, &f, &h, &rho, true);
        Some(Iterate { f, h, rho, g, s })
    }
}

/// The sets the complementarity functions give for an iterate (module docs), with a relative margin, and for each
/// node that changes set the size of the violation that moves it (relative to the force, gap or slip scale).
fn update(d: &Data, sets: &[NodeSet], it: &Iterate, margin: f64) -> (Vec<NodeSet>, Vec<f64>) {
    let fmax = it.f.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let gmax = d.g_const.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let smax = it.s.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let mut violation = vec![0.0; d.n];
    let next = (0..d.n)
        .map(|i| {
            let (in_contact, v) = match sets[i] {
                NodeSet::Separated => (it.g[i] < -margin * gmax, -it.g[i] / gmax),
                _ => (it.f[i] >= -margin * fmax, -it.f[i] / fmax),
            };
            if !in_contact {
                violation[i] = v;
                return NodeSet::Separated;
            }
            if sets[i] == NodeSet::Separated {
                violation[i] = v;
            }
            if !d.frictional {
                return NodeSet::Stick;
            }
            let limit = d.mu * it.f[i].max(0.0);
            match sets[i] {
                // A node coming into contact carries no force yet: it can only stick if it does not slip.
                NodeSet::Separated if it.s[i].abs() > margin * smax => {
                    NodeSet::Slip(if it.s[i] > 0.0 { 1 } else { -1 })
                }
                NodeSet::Separated => NodeSet::Stick,
                NodeSet::Slip(sg) if (sg as f64) * it.s[i] >= -margin * smax => NodeSet::Slip(sg),
                NodeSet::Slip(sg) => {
                    violation[i] = violation[i].max(-(sg as f64) * it.s[i] / smax);
                    NodeSet::Stick
                }
                _ if it.h[i].abs() <= limit + margin * d.mu * fmax => NodeSet::Stick,
                _ => {
                    violation[i] = violation[i].max((it.h[i].abs() - limit) / (d.mu * fmax));
                    NodeSet::Slip(if it.h[i] > 0.0 { -1 } else { 1 })
                }
            }
        })
        .collect();
    (next, violation)
}

/// Iterate from `sets` until no node changes set; `Err` with the reason (cycle, limit, singular system). All the
/// violated nodes change set at once (the semi-smooth Newton step); when the sets cycle, only the worst half of them
/// do, then the worst quarter, down to one at a time (a damped step), before giving up.
/// What the iteration is run with: the settings and the caller's cancellation token.
struct Control<'a> {
    settings: &'a ActiveSetSettings,
    cancel: &'a Cancel,
}

/// The message of an iteration stopped by the caller's cancellation token.
const CANCELLED: &str = "cancelled";

fn iterate(
    d: &Data,
    mut sets: Vec<NodeSet>,
    start: Option<Vec<f64>>,
    s: &Control,
    count: &mut usize,
    linear: &mut dyn Step,
) -> Result<(Iterate, Vec<NodeSet>), String> {
    let mut seen: HashSet<Vec<NodeSet>> = HashSet::new();
    let mut max_changes = usize::MAX;
    let mut previous: Option<Vec<f64>> = start.filter(|y| y.len() == Full { d, sets: sets.clone() }.size());
    loop {
        *count += 1;
        if *count > s.settings.max_iterations {
            return Err(format!("no convergence in {} iterations", s.settings.max_iterations));
        }
        if s.cancel.is_cancelled() {
            return Err(format!("{CANCELLED} at iteration {count}"));
        }
        let mut it = linear
            .solve(d, &sets, previous.as_deref(), false)
            .ok_or_else(|| format!("singular active-set system at iteration {count}"))?;
        if !linear.last_direct() && update(d, &sets, &it, s.settings.margin).0 == sets {
            // Converged on an iterative solve: confirm with a direct one (round-off accurate).
            it = linear
                .solve(d, &sets, None, true)
                .ok_or_else(|| format!("singular active-set system at iteration {count}"))?;
        }
        previous = Some(if d.frictional {
            it.f.iter().chain(&it.h).chain(&it.rho).copied().collect()
        } else {
            it.f.iter().chain(&it.rho).copied().collect()
        });
        let (next, violation) = update(d, &sets, &it, s.settings.margin);
        let mut changed: Vec<usize> = (0..d.n).filter(|&i| next[i] != sets[i]).collect();
        if changed.is_empty() {
            return Ok((it, sets));
        }
        if !seen.insert(sets.clone()) {
            if max_changes == 1 {
                return Err(format!("the active sets cycle even one change at a time (iteration {count})"));
            }
            max_changes = (changed.len() / 2).clamp(1, max_changes.saturating_sub(1).max(1));
            seen.clear();
            seen.insert(sets.clone());
        }
        if changed.len() > max_changes {
            changed.sort_by(|&a, &b| violation[b].total_cmp(&violation[a]));
            changed.truncate(max_changes);
        }
        for i in changed {
            sets[i] = next[i];
        }
    }
}

/// Problems with more contact nodes than this start from the solution of the same problem on every
/// [`COARSE_STRIDE`]-th node (solved the same way, recursively): its sets, carried to the nearest fine nodes, are
/// right except within a node or two of the edges of the contact and stick zones, so the fine iteration changes
/// few nodes per step and reuses its factorisation.
const COARSE_ABOVE: usize = 400;

/// The coarsening factor of [`COARSE_ABOVE`].
const COARSE_STRIDE: usize = 4;

impl ActiveSet {
    /// The sets of the problem solved on every k-th node (module docs), carried to the nearest fine nodes; `None`
    /// when the problem is small or the coarse solve fails.
    fn coarse_start(&self, p: &ContactProblem, count: &mut usize, cancel: &Cancel) -> Option<Vec<NodeSet>> {
        let n = p.n();
        if n <= COARSE_ABOVE || matches!(p.kind, ProblemKind::GrossSliding { .. }) {
            return None;
        }
        let stride = COARSE_STRIDE;
        let flex = p.flex.coarse(stride);
        let slip = p.slip.coarse(stride, &flex.x);
        let cp = ContactProblem::new(&flex, p.law, p.drive, slip).ok()?;
        let out = self.solve_from(&cp, Start::cancellable(cancel.clone()));
        *count += out.work.get("iterations").unwrap_or(0) as usize;
        let sol = out.solution.filter(|_| out.status == Termination::Solved && out.work.get("pivots").is_none())?;
        let mu = p.law.friction;
        let frictional = p.kind == ProblemKind::Frictional;
        let nk = flex.n();
        Some(
            (0..n)
                .map(|i| {
                    let k = ((i + stride / 2) / stride).min(nk - 1);
                    node_set(sol.f[k], sol.h.as_ref().map_or(0.0, |h| h[k]), frictional, mu)
                })
                .collect(),
        )
    }
}

/// The set of a node carrying forces (f, h) in a solution (a warm start's, a coarse grid's): separated without
/// pressure, sticking inside the friction limit (to a relative 1e-9), slipping against h on it.
fn node_set(f: f64, h: f64, frictional: bool, mu: f64) -> NodeSet {
    if f <= 0.0 {
        NodeSet::Separated
    } else if !frictional || h.abs() < mu * f * (1.0 - 1e-9) {
        NodeSet::Stick
    } else {
        NodeSet::Slip(if h > 0.0 { -1 } else { 1 })
    }
}

/// The sets of a warm start's solution.
fn warm_sets(d: &Data, w: &Solution) -> Vec<NodeSet> {
    (0..d.n).map(|i| node_set(w.f[i], w.h.as_ref().map_or(0.0, |h| h[i]), d.frictional, d.mu)).collect()
}

/// The warm start's unknowns in the full layout [f; h; ρ], GMRES's first guess (`warm` has the problem's shape:
/// [`Start::solution_for`]).
fn warm_unknowns(p: &ContactProblem, d: &Data, warm: Option<&Solution>) -> Option<Vec<f64>> {
    let n = d.n;
    warm.filter(|w| w.f.len() == n && w.rigid.len() == p.dofs.len()).map(|w| {
        let h = w.h.clone().filter(|h| h.len() == n && d.frictional).unwrap_or_else(|| vec![0.0; n]);
        // The data's load-driven DOFs: a normal phase's (`Data::of(p, true)`) leave the tangential one out.
        let rho = p
            .dofs
            .iter()
            .zip(&w.rigid)
            .filter(|(dof, _)| p.is_unknown(dof) && (d.frictional || !dof.kind.is_tangential()))
            .map(|(_, v)| *v);
        let f = w.f.iter().copied();
        if d.frictional {
            f.chain(h).chain(rho).collect::<Vec<f64>>()
        } else {
            f.chain(rho).collect()
        }
    })
}

impl ActiveSet {
    /// The cold start of a coupled problem: the normal problem solved first with the shear fixed at zero (every
    /// node starting in contact), then every contact node sticking.
    fn normal_start(&self, p: &ContactProblem, d: &Data, count: &mut usize, ctl: &Control) -> Vec<NodeSet> {
        let n = d.n;
        if !d.frictional {
            return vec![NodeSet::Stick; n];
        }
        let normal = Data::of(p, true);
        let mut linear = Linear::new();
        match iterate(&normal, vec![NodeSet::Stick; n], None, ctl, count, &mut linear) {
            Ok((it, _)) => it.f.iter().map(|&f| if f > 0.0 { NodeSet::Stick } else { NodeSet::Separated }).collect(),
            Err(_) => vec![NodeSet::Stick; n],
        }
    }
}

impl Solver for ActiveSet {
    fn id(&self) -> SolverId {
        ID
    }

    fn applies(&self, _problem: &ContactProblem) -> Result<(), String> {
        Ok(())
    }

    fn solve_from(&self, p: &ContactProblem, mut start: Start) -> Outcome {
        let d = Data::of(p, false);
        let mut count = 0;
        let state = start.take_state::<ActiveSetState>(ID, p);
        let warm = start.solution_for(p);
        let ctl = Control { settings: &self.settings, cancel: &start.cancel };
        // Start: the warm start's sets, or those of the same problem on a coarse grid, or the normal problem first
        // (every node in contact, no shear).
        let coarse = if warm.is_none() { self.coarse_start(p, &mut count, ctl.cancel) } else { None };
        let warm_sets = warm.map(|w| warm_sets(&d, w));
        let (result, factorisations, gmres_iterations, kept) = if phases::applies(p, &d) {
            let kept = match state {
                Some(ActiveSetState::Phases(k)) => Some(*k),
                _ => None,
            };
            let (run, kept) = phases::solve(&ctl, p, &d, coarse.or(warm_sets), warm, kept, &mut count);
            (run.result, run.factorisations, run.gmres, ActiveSetState::Phases(Box::new(kept)))
        } else {
            let start_sets = match (coarse, warm_sets) {
                (Some(sets), _) | (None, Some(sets)) => sets,
                (None, None) => self.normal_start(p, &d, &mut count, &ctl),
            };
            // What the last run on this layout kept (the caller's warm start; a cold solve has none, so its work
            // does not depend on what ran before it on the model).
            let d = d.with_att();
            let mut linear = match state {
                Some(ActiveSetState::Joint(k)) => Linear::resume(k, d.n),
                _ => Linear::new(),
            };
            let result = iterate(&d, start_sets, warm_unknowns(p, &d, warm), &ctl, &mut count, &mut linear);
            let (factorisations, gmres_iterations) = (linear.factorisations, linear.gmres_iterations);
            (result.map(|(it, _)| it), factorisations, gmres_iterations, ActiveSetState::Joint(linear.keep()))
        };
        if std::env::var_os("ROLLBEM_DEBUG_AS").is_some() {
            eprintln!(
                "active set: {count} iterations, {factorisations} factorisations, {gmres_iterations} GMRES iterations"
            );
        }
        let work = |extra: &[(&str, u64)]| {
            let mut w = vec![("iterations", count as u64)];
            w.extend_from_slice(extra);
            Work::of(&w)
        };
        match result {
            Ok(it) => {
                let mut rigid = p.given();
                let mut l = 0;
                for (k, dof) in p.dofs.iter().enumerate() {
                    if p.is_unknown(dof) {
                        rigid[k] = it.rho[l];
                        l += 1;
                    }
                }
                let h = match p.kind {
                    ProblemKind::Frictional => Some(it.h),
                    ProblemKind::SlidingLimit { .. } => Some(it.f.iter().map(|v| p.limit_factor() * v).collect()),
                    _ => None,
                };
                let tangential_known = !matches!(p.kind, ProblemKind::SlidingLimit { .. });
                Outcome {
                    solution: Some(Solution { f: it.f, h, rigid, tangential_known }),
                    status: Termination::Solved,
                    message: format!(
                        "active sets converged in {count} iterations ({} factorisations and {} GMRES iterations on \
                         the full grid)",
                        factorisations, gmres_iterations
                    ),
                    work: work(&[("factorisations", factorisations as u64), ("gmres", gmres_iterations as u64)]),
                    figures: Figures::default(),
                    state: Some(SolverState::new(ID, p, kept)),
                }
            }
            Err(why) if start.cancel.is_cancelled() => {
                Outcome::failed(Termination::NotConverged, format!("active set: {why}"), work(&[]))
            }
            Err(why) => {
                // Fall back to Lemke on the problem's LCP.
                let lemke =
                    Lemke { id: lemke::ID, settings: LemkeSettings::default(), engine: lemke::solve_cancellable };
                let mut out = lemke.solve_from(p, Start::cancellable(start.cancel.clone()));
                out.message = format!("active set: {why}; fell back to Lemke: {}", out.message);
                let pivots = out.work.get("pivots").unwrap_or(0);
                out.work = work(&[("pivots", pivots)]);
                // Lemke's state is not the active set's: the next run starts without one.
                out.state = None;
                out
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::gmres;

    /// A well-posed system is solved (expected: the exact solution of a diagonal system, x_i = b_i / d_i).
    #[test]
    fn gmres_solves_a_diagonal_system() {
        let d = [1.0, 2.0, 4.0, 8.0];
        let e = |x: &[f64]| x.iter().zip(&d).map(|(x, d)| x * d).collect::<Vec<_>>();
        let b = [1.0, 1.0, 1.0, 1.0];
        let (y, _) = gmres(&e, &|x| Some(x.to_vec()), &b, &[0.0; 4], 1e-14, 50).expect("converges");
        for (y, d) in y.iter().zip(&d) {
            assert!((y - 1.0 / d).abs() <= 1e-13, "{y} against {}", 1.0 / d);
        }
    }

    /// An operator that returns NaN (one that overflowed) makes GMRES fail with `None`; it indexed a Krylov vector
    /// that was never built and panicked before (the `scene` fuzz target's reproducer
    /// fuzz/regressions/active-set-gmres-nan.toml, replayed end to end by tests/fuzz_corpus.rs).
    #[test]
    fn gmres_fails_cleanly_on_a_nan_operator() {
        let e = |x: &[f64]| x.iter().map(|_| f64::NAN).collect::<Vec<_>>();
        assert!(gmres(&e, &|x| Some(x.to_vec()), &[1.0, 2.0], &[0.0, 0.0], 1e-12, 10).is_none());
        let overflow = |x: &[f64]| x.iter().map(|v| v * f64::MAX * 4.0).collect::<Vec<_>>();
        assert!(gmres(&overflow, &|x| Some(x.to_vec()), &[1.0, 2.0], &[1.0, 1.0], 1e-12, 10).is_none());
    }
}
