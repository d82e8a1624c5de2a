//! Two phases for a frictional problem without normal–tangential coupling.
//!
//! **Why.** Without coupling (K_NT = 0 and D K_TN = 0), with no tangential load-driven DOF that moves the gaps and
//! no normal one whose equilibrium row carries shear, the normal problem — contact set, normal forces f, normal
//! load-driven motions — does not depend on the shear at all. The joint iteration of the parent module solves it
//! again with every stick–slip step; here it is solved once, alone (the same iteration on the normal unknowns), and
//! then the stick–slip problem with f fixed. The solution is the same (the joint problem's, to round-off); the work
//! is the normal problem once plus a tangential problem of the size of the stick zone. The joint system of a stick
//! set is block lower-triangular in exactly this case ([`super::Split`]).
//!
//! **The tangential system.** For a stick set S the unknowns are h_S and the tangential load-driven motions ρ_T:
//!
//! ```text
//!   A(S) = [ (D K_TT)[S, S]   slip_T[S] ]      rows: the sticking nodes' slips (= 0),
//!          [ row_T[S]ᵀ        0         ]            the tangential equilibrium rows (= Q)
//! ```
//!
//! with the slipping nodes' h = −σμf and everything fixed on the right-hand side. A(S) depends on S only — not on
//! the slip signs, on f, or on the drive's values — so one factorisation of A(S₀) serves every S near S₀: the system
//! of S is the bordered system of S₀ ∪ S with the unknowns of S₀ \ S held at zero by multipliers, solved by the Schur
//! complement of A(S₀) (a k × k matrix for k added and removed nodes; k + 1 solves with the factorisation), then one
//! step of iterative refinement against the problem's own products, and checked: a relative residual above
//! [`BORDER_TOLERANCE`] throws the bordered solve away for a factorisation of A(S). More than [`border_limit`]
//! changes factorise A(S) afresh, which becomes the new A(S₀).
//!
//! **Across solves.** On a model solved for many drives with warm starts (a creep curve, a sweep with
//! `warm_start = true`), what a solve leaves is kept in the solver's state ([`crate::solvers::SolverState`], owned by
//! the caller's warm start, stamped with the flexibility and the problem's layout) and used by the next one only when it
//! is provably the same: the normal phase's result when the normal problem's data (gap constants, load rows, loads,
//! settings) are equal bit for bit, the normal factorisation when its matrix-defining data are, and A(S₀) when D and
//! the tangential load rows are (K_TT is the flexibility's own). A cold solve reads nothing (its work must not depend
//! on what ran before it).

use super::{
    gaps, iterate, slip_factor, slips, warm_unknowns, ActiveSetSettings, Control, Data, Iterate, Linear, NodeSet,
    Reduced, Step,
};
use crate::formulation::{ContactProblem, Solution};
use faer::Mat;

/// The largest relative residual (max-norm, relative to the right-hand side's) a bordered solve may leave before it
/// is replaced by a factorisation.
const BORDER_TOLERANCE: f64 = 1e-12;

/// How many added and removed unknowns a bordered solve takes before A(S) is factorised afresh: the bordered solve
/// costs about k solves with the factorisation (2m² each) against (2/3)m³ for a new one.
fn border_limit(m: usize) -> usize {
    (m / 6).max(16)
}

/// Whether a problem splits into the two phases (module docs).
/// (`d.frictional` means a frictional problem's full data, with K_TT; `d.loads` are `p.load_dofs()` in order.)
pub(super) fn applies(p: &ContactProblem, d: &Data) -> bool {
    d.frictional
        && p.normal.is_none()
        && d.knt.is_none()
        && d.atn.is_none()
        && p.load_dofs().zip(&d.loads).all(|(dof, ld)| {
            if dof.kind.is_tangential() {
                ld.gap.iter().all(|v| *v == 0.0)
            } else {
                ld.row_t.iter().all(|v| *v == 0.0)
            }
        })
}

/// The outcome of a two-phase solve and its work.
pub(super) struct Run {
    pub(super) result: Result<Iterate, String>,
    pub(super) factorisations: usize,
    pub(super) gmres: usize,
}

/// What a solve leaves for the next one on the same flexibility (module docs, "Across solves").
pub(super) struct Kept {
    normal_matrix: Vec<u64>,
    normal_data: Vec<u64>,
    normal_base: Option<Reduced>,
    normal_solution: Option<(Iterate, Vec<NodeSet>)>,
    tangential_matrix: Vec<u64>,
    tangential_base: Option<Base>,
}

/// The bits of some vectors, each preceded by its length.
fn bits(parts: &[&[f64]]) -> Vec<u64> {
    let mut out = Vec::new();
    for p in parts {
        out.push(p.len() as u64);
        out.extend(p.iter().map(|v| v.to_bits()));
    }
    out
}

/// The bits that decide what a solve may take from the last one (module docs, "Across solves"): the normal
/// phase's matrix-defining data, its whole data (matrix, gap constants, loads, settings), and the tangential
/// system's matrix-defining data (D and the tangential load rows; K_TT is the flexibility's own).
fn keys(
    settings: &ActiveSetSettings,
    p: &ContactProblem,
    d: &Data,
    dn: &Data,
    tangential_load: &[bool],
) -> (Vec<u64>, Vec<u64>, Vec<u64>) {
    let n = d.n;
    let mut normal_matrix = vec![n as u64];
    for ld in &dn.loads {
        normal_matrix.extend(bits(&[&ld.gap, &ld.row_n, &ld.row_t, &ld.slip]));
    }
    let loads: Vec<f64> = dn.loads.iter().map(|ld| ld.load).collect();
    let mut normal_data = bits(&[&dn.g_const, &loads, &[settings.margin, settings.max_iterations as f64]]);
    normal_data.extend(&normal_matrix);
    let mut tangential_matrix = vec![n as u64];
    tangential_matrix.extend(p.slip.d_bits());
    for (ld, _) in d.loads.iter().zip(tangential_load).filter(|(_, t)| **t) {
        tangential_matrix.extend(bits(&[&ld.slip, &ld.row_t]));
    }
    (normal_matrix, normal_data, tangential_matrix)
}

/// Solve a problem for which [`applies`] holds from `start` (a warm start's or a coarse grid's sets), with `warm`
/// the warm start's solution and `kept` what the last run on this layout left; returns the run and what it leaves.
pub(super) fn solve(
    ctl: &Control,
    p: &ContactProblem,
    d: &Data,
    start: Option<Vec<NodeSet>>,
    warm: Option<&Solution>,
    kept: Option<Kept>,
    count: &mut usize,
) -> (Run, Kept) {
    let n = d.n;
    let settings = ctl.settings;
    let dn = Data::of(p, true);
    let tangential_load: Vec<bool> = p.load_dofs().map(|dof| dof.kind.is_tangential()).collect();
    let (normal_matrix, normal_data, tangential_matrix) = keys(settings, p, d, &dn, &tangential_load);
    let (mut normal_base, mut normal_solution, mut tangential_base) = (None, None, None);
    let mut normal_exact = false;
    if let Some(k) = kept {
        normal_exact = k.normal_matrix == normal_matrix;
        normal_base = k.normal_base.filter(|b| b.fits(&dn));
        if normal_exact && k.normal_data == normal_data {
            normal_solution = k.normal_solution;
        }
        if k.tangential_matrix == tangential_matrix {
            tangential_base = k.tangential_base;
        }
    }
    let mut run = Run { result: Err(String::new()), factorisations: 0, gmres: 0 };
    // Normal phase.
    let (normal_it, normal_sets) = match normal_solution {
        Some(hit) => hit,
        None => {
            let sets: Vec<NodeSet> = match &start {
                Some(s) => s.iter().map(|v| if *v == NodeSet::Separated { *v } else { NodeSet::Stick }).collect(),
                None => vec![NodeSet::Stick; n],
            };
            let y0 = warm_unknowns(p, &dn, warm);
            let mut linear = Linear::new();
            linear.base = normal_base.take();
            linear.base_exact = normal_exact && linear.base.is_some();
            let out = iterate(&dn, sets, y0, ctl, count, &mut linear);
            run.factorisations += linear.factorisations;
            run.gmres += linear.gmres_iterations;
            normal_base = linear.base;
            match out {
                Ok(v) => v,
                Err(why) => {
                    run.result = Err(format!("normal phase: {why}"));
                    let kept = Kept {
                        normal_matrix,
                        normal_data,
                        normal_base,
                        normal_solution: None,
                        tangential_matrix,
                        tangential_base,
                    };
                    return (run, kept);
                }
            }
        }
    };
    // Tangential phase: f and the normal motions fixed.
    let mut rho_n = vec![0.0; d.loads.len()];
    let mut normal_rho = normal_it.rho.iter();
    for (l, t) in tangential_load.iter().enumerate() {
        if !t {
            rho_n[l] = *normal_rho.next().unwrap_or(&0.0);
        }
    }
    let contact: Vec<bool> = normal_sets.iter().map(|s| *s != NodeSet::Separated).collect();
    let sets: Vec<NodeSet> = (0..n)
        .map(|i| match (contact[i], start.as_ref().map(|s| s[i])) {
            (false, _) => NodeSet::Separated,
            (true, Some(NodeSet::Slip(sg))) => NodeSet::Slip(sg),
            (true, _) => NodeSet::Stick,
        })
        .collect();
    let mut tangential = Tangential {
        f: &normal_it.f,
        g: gaps(d, &normal_it.f, &vec![0.0; n], &rho_n, true),
        contact,
        t_loads: (0..d.loads.len()).filter(|&l| tangential_load[l]).collect(),
        rho_n,
        base: tangential_base,
        factorisations: 0,
    };
    let out = iterate(d, sets, None, ctl, count, &mut tangential);
    run.factorisations += tangential.factorisations;
    let tangential_base = tangential.base.take();
    run.result = out.map(|(it, _)| it).map_err(|why| format!("tangential phase: {why}"));
    let kept = Kept {
        normal_matrix,
        normal_data,
        normal_base,
        normal_solution: Some((normal_it, normal_sets)),
        tangential_matrix,
        tangential_base,
    };
    (run, kept)
}

/// A factorised tangential system A(S₀): its unknowns (nodes i < n, tangential loads n + k) and their positions.
struct Base {
    idx: Vec<usize>,
    /// Position in `idx` of each unknown of the index space (`usize::MAX` when absent).
    pos: Vec<usize>,
    lu: crate::lu::InPlaceLu,
    /// Columns of A(S₀)⁻¹ C already computed, by unknown (an added unknown's column of A, or a removed unknown's
    /// unit vector), and the added unknowns' rows of A on S₀: the border of the next set reuses them.
    w_cols: std::collections::HashMap<usize, Vec<f64>>,
    r_rows: std::collections::HashMap<usize, Vec<f64>>,
}

/// Where an unknown of a nearby set sits in its bordered system.
#[derive(Clone, Copy)]
enum Slot {
    /// At this position of the base.
    Base(usize),
    /// The j-th added unknown (a border column).
    Added(usize),
}

/// The Schur complement of a base for a nearby set (module docs).
struct Border {
    /// For each unknown of the new set, where it sits.
    map: Vec<Slot>,
    /// A(S₀)⁻¹ C (m₀ × k).
    w: Mat<f64>,
    /// The border rows R (k × m₀).
    r: Mat<f64>,
    /// The Schur complement D − R A(S₀)⁻¹ C, factorised (`None` for k = 0).
    schur: Option<crate::lu::InPlaceLu>,
}

/// The tangential phase (module docs): a [`Step`] on the stick–slip sets with f fixed.
struct Tangential<'a> {
    f: &'a [f64],
    /// The gaps, fixed with f (no tangential unknown moves them).
    g: Vec<f64>,
    contact: Vec<bool>,
    /// The tangential load rows (positions in `Data::loads`).
    t_loads: Vec<usize>,
    /// The normal load-driven motions, in `Data::loads` order (0 at tangential ones).
    rho_n: Vec<f64>,
    base: Option<Base>,
    factorisations: usize,
}

impl Tangential<'_> {
    /// Entry (r, c) of the tangential system in the index space (nodes, then tangential loads).
    fn entry(&self, d: &Data, r: usize, c: usize) -> f64 {
        let n = d.n;
        match (r < n, c < n) {
            (true, true) => d.att_entry(r, c),
            (true, false) => d.loads[self.t_loads[c - n]].slip[r],
            (false, true) => d.loads[self.t_loads[r - n]].row_t[c],
            (false, false) => 0.0,
        }
    }

    /// Factorise A(idx) as the new base (a singular A shows as non-finite solutions, which [`Self::solve_sets`]
    /// refuses).
    fn factorise(&mut self, d: &Data, idx: &[usize]) {
        // The old base goes first (peak memory).
        self.base = None;
        let m = idx.len();
        let a = Mat::from_fn(m, m, |i, j| self.entry(d, idx[i], idx[j]));
        let lu = crate::lu::InPlaceLu::new(a);
        self.factorisations += 1;
        let mut pos = vec![usize::MAX; d.n + self.t_loads.len()];
        for (k, &u) in idx.iter().enumerate() {
            pos[u] = k;
        }
        self.base = Some(Base {
            idx: idx.to_vec(),
            pos,
            lu,
            w_cols: std::collections::HashMap::new(),
            r_rows: std::collections::HashMap::new(),
        });
    }

    /// The bordered system of the base for `idx`, or `None` when there is no base or too many changes.
    fn border(&mut self, d: &Data, idx: &[usize]) -> Option<Border> {
        let nu = d.n + self.t_loads.len();
        let m0 = self.base.as_ref()?.idx.len();
        let mut in_new = vec![false; nu];
        let mut added = Vec::new();
        let map: Vec<Slot> = {
            let base = self.base.as_ref()?;
            idx.iter()
                .map(|&u| {
                    in_new[u] = true;
                    if base.pos[u] != usize::MAX {
                        Slot::Base(base.pos[u])
                    } else {
                        added.push(u);
                        Slot::Added(added.len() - 1)
                    }
                })
                .collect()
        };
        let removed: Vec<usize> = {
            let base = self.base.as_ref()?;
            (0..m0).filter(|&k| !in_new[base.idx[k]]).collect()
        };
        let (na, k) = (added.len(), added.len() + removed.len());
        if k > border_limit(idx.len().max(m0)) {
            return None;
        }
        // The border's unknowns: added ones by their index, removed ones by the index they had in the base.
        let unknowns: Vec<usize> = {
            let base = self.base.as_ref()?;
            added.iter().copied().chain(removed.iter().map(|&q| base.idx[q])).collect()
        };
        let missing: Vec<(usize, usize)> = {
            let base = self.base.as_ref()?;
            unknowns.iter().enumerate().filter(|(_, u)| !base.w_cols.contains_key(u)).map(|(j, u)| (j, *u)).collect()
        };
        if !missing.is_empty() {
            let base = self.base.as_ref()?;
            let c = Mat::from_fn(m0, missing.len(), |i, j| {
                let (jj, u) = missing[j];
                if jj < na {
                    self.entry(d, base.idx[i], u)
                } else if removed[jj - na] == i {
                    1.0
                } else {
                    0.0
                }
            });
            let w = base.lu.solve(&c);
            let rows: Vec<(usize, Vec<f64>)> = missing
                .iter()
                .filter(|(jj, _)| *jj < na)
                .map(|&(_, u)| (u, (0..m0).map(|q| self.entry(d, u, base.idx[q])).collect()))
                .collect();
            let base = self.base.as_mut()?;
            for (j, &(_, u)) in missing.iter().enumerate() {
                base.w_cols.insert(u, (0..m0).map(|i| w[(i, j)]).collect());
            }
            base.r_rows.extend(rows);
        }
        let base = self.base.as_ref()?;
        let mut w = Mat::<f64>::zeros(m0, k);
        for (j, u) in unknowns.iter().enumerate() {
            w.col_mut(j).iter_mut().zip(&base.w_cols[u]).for_each(|(a, b)| *a = *b);
        }
        let mut r = Mat::<f64>::zeros(k, m0);
        for (i, u) in added.iter().enumerate() {
            r.row_mut(i).iter_mut().zip(&base.r_rows[u]).for_each(|(a, b)| *a = *b);
        }
        for (q, &pos) in removed.iter().enumerate() {
            r[(na + q, pos)] = 1.0;
        }
        let rw = &r * &w;
        let s = Mat::from_fn(k, k, |i, j| {
            if i < na && j < na {
                self.entry(d, added[i], added[j]) - rw[(i, j)]
            } else {
                -rw[(i, j)]
            }
        });
        let schur = (k > 0).then(|| crate::lu::InPlaceLu::new(s));
        Some(Border { map, w, r, schur })
    }

    /// Solve A(idx) z = b with the base (directly when `border` is `None`).
    fn solve_with(&self, border: Option<&Border>, idx: &[usize], b: &[f64]) -> Option<Vec<f64>> {
        let base = self.base.as_ref()?;
        let m0 = base.idx.len();
        let Some(bd) = border else {
            let rhs = Mat::from_fn(m0, 1, |i, _| b[i]);
            let z = base.lu.solve(&rhs);
            return Some((0..m0).map(|i| z[(i, 0)]).collect());
        };
        let k = bd.w.ncols();
        let mut bt = Mat::<f64>::zeros(m0, 1);
        let mut bs = Mat::<f64>::zeros(k, 1);
        for (j, &slot) in bd.map.iter().enumerate() {
            match slot {
                Slot::Added(a) => bs[(a, 0)] = b[j],
                Slot::Base(q) => bt[(q, 0)] = b[j],
            }
        }
        let u = base.lu.solve(&bt);
        let (x0, ws) = match &bd.schur {
            Some(schur) => {
                let rhs = &bs - &bd.r * &u;
                let ws = schur.solve(&rhs);
                (&u - &bd.w * &ws, ws)
            }
            None => (u, Mat::zeros(0, 1)),
        };
        debug_assert_eq!(idx.len(), bd.map.len());
        Some(
            bd.map
                .iter()
                .map(|&slot| match slot {
                    Slot::Added(a) => ws[(a, 0)],
                    Slot::Base(q) => x0[(q, 0)],
                })
                .collect(),
        )
    }

    /// The residual of the tangential equations at (h, ρ): −s at the sticking nodes, Q − the resultant at the
    /// tangential load rows; and the iterate's slips.
    fn residual(&self, d: &Data, idx: &[usize], h: &[f64], rho: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let n = d.n;
        let s = slips(d, self.f, h, rho, true);
        let r = idx
            .iter()
            .map(|&u| {
                if u < n {
                    -s[u]
                } else {
                    let ld = &d.loads[self.t_loads[u - n]];
                    let q: f64 = (0..n).map(|j| ld.row_n[j] * self.f[j] + ld.row_t[j] * h[j]).sum();
                    ld.load - q
                }
            })
            .collect();
        (r, s)
    }

    /// Solve the sets' system with a border (refined once and checked) or a factorisation; the slips, or `None`
    /// when singular.
    fn solve_sets(&mut self, d: &Data, idx: &[usize], h: &mut [f64], rho: &mut [f64]) -> Option<Vec<f64>> {
        let n = d.n;
        let mut border = self.border(d, idx);
        if border.is_none() {
            self.factorise(d, idx);
        }
        let (h0, rho0) = (h.to_vec(), rho.to_vec());
        let (mut r, _) = self.residual(d, idx, h, rho);
        let scale = r.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
        loop {
            // A factorisation of the sets' own system: one solve; a bordered one: a solve and one refinement.
            let steps = if border.is_some() { 2 } else { 1 };
            let mut s = Vec::new();
            for _ in 0..steps {
                let z = self.solve_with(border.as_ref(), idx, &r)?;
                for (k, &u) in idx.iter().enumerate() {
                    if u < n {
                        h[u] += z[k];
                    } else {
                        rho[self.t_loads[u - n]] += z[k];
                    }
                }
                (r, s) = self.residual(d, idx, h, rho);
            }
            let left = r.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            if !left.is_finite() || !h.iter().chain(rho.iter()).all(|v| v.is_finite()) {
                return None;
            }
            if border.is_none() || left <= BORDER_TOLERANCE * scale {
                return Some(s);
            }
            // The bordered solve was not accurate enough: factorise this set and solve again.
            h.copy_from_slice(&h0);
            rho.copy_from_slice(&rho0);
            (r, _) = self.residual(d, idx, h, rho);
            self.factorise(d, idx);
            border = None;
        }
    }
}

impl Step for Tangential<'_> {
    fn solve(&mut self, d: &Data, sets: &[NodeSet], _y0: Option<&[f64]>, _last: bool) -> Option<Iterate> {
        let n = d.n;
        if (0..n).any(|i| (sets[i] != NodeSet::Separated) != self.contact[i]) {
            return None;
        }
        let mut h: Vec<f64> = (0..n).map(|i| slip_factor(d, sets[i]) * self.f[i]).collect();
        let mut rho = self.rho_n.clone();
        let idx: Vec<usize> =
            (0..n).filter(|&i| sets[i] == NodeSet::Stick).chain((0..self.t_loads.len()).map(|k| n + k)).collect();
        let s =
            if idx.is_empty() { slips(d, self.f, &h, &rho, true) } else { self.solve_sets(d, &idx, &mut h, &mut rho)? };
        Some(Iterate { f: self.f.to_vec(), h, rho, g: self.g.clone(), s })
    }

    fn last_direct(&self) -> bool {
        true
    }
}
