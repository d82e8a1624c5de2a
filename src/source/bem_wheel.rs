//! Condensation of the BEM system to the contact flexibility (seed eqs. 14–24).
//!
//! With the support's displacement prescribed (its rigid motion), the free boundary traction-free and the contact
//! nodes' displacements and tractions both unknown, `H u = G t` is rearranged into `A x = b(t_c, ρ)` with the
//! unknowns `x` = support tractions, free-boundary displacements and contact displacements: A's column for a
//! support degree of freedom is −G's, every other column is H's. One LU factorisation of A then gives, by solves
//! against the contact-traction columns of G, the contact displacements per unit contact traction — the
//! flexibility F — and, by solves against −H·(rigid mode) over the support, the contact displacements caused by
//! each unit rigid motion ρ of the support. No inverse of the whole system is formed.
//!
//! F is expressed in the flat's frame (`DESIGN.md`): N = y (pressure p = t_y, gap change u_y), T = x (shear
//! q = t_x, slip u_x), so `u_N = F_NN p + F_NT q + R_N ρ` and `u_T = F_TN p + F_TT q + R_T ρ`. The seed's per-node
//! rotation C_i (eq. 18) is not applied: the counter-body is a flat, whose frame is the same at every node.
//!
//! Units: everything here is dimensionless, lengths divided by the model's reference length `L0 = 2R` and
//! stresses by Young's modulus (see [`Model`]). The wheel's support offers three rigid modes
//! ([`crate::flexibility::ModeKind`]): the tangential shift (u = (1, 0)), the approach towards the flat
//! (u = (0, −1)) and the counter-clockwise rotation about the wheel centre (u = (−y, x)). The flexibility is handed
//! on per unit nodal force, `K = F W⁻¹` ([`crate::flexibility`]).

use super::{Blocks, SourceTiming};
use crate::bem::{assemble, kelvin::Kelvin, BlockSink};
use crate::error::{ArgumentError, Error, Result};
use crate::flexibility::{Flexibility, ModeKind, RigidMode, Scales};
use crate::mesh::{Bc, Mesh, MeshSpec};
use crate::scene::{Support, Wheel};
use crate::tolerances::BEM_SINGULAR_PIVOT_RATIO;
use faer::linalg::solvers::Solve;
use faer::Mat;

/// The scene's wheel in dimensionless form: mesh in units of `length`, Kelvin kernels with E = 1.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Model {
    /// Boundary mesh, lengths divided by `length`.
    pub mesh: Mesh,
    /// Kernel constants with Young's modulus 1.
    pub kelvin: Kelvin,
    /// Reference length L0 = 2R (user's unit): the wheel's diameter, so every distance in the body is ≤ 1 and the
    /// logarithmic kernel stays clear of the degenerate scales of 2D elastostatics (which lie near radius 1).
    pub length: f64,
    /// Reference stress = Young's modulus E (user's unit).
    pub modulus: f64,
}

impl Model {
    /// The dimensionless model of a scene's BEM wheel (`None` for the half-plane model; `Err` as [`Model::new`], which
    /// a validated scene never gives).
    pub fn of_scene(scene: &crate::scene::Scene) -> std::result::Result<Option<Model>, ArgumentError> {
        crate::mesh::MeshSpec::of_scene(scene)
            .map(|(support, spec)| Model::new(scene.wheel(), support, &spec))
            .transpose()
    }

    /// Build the dimensionless model of a wheel with its support and mesh (lengths in the user's unit). A wheel
    /// [`Mesh::wheel`] cannot mesh is refused, naming the argument.
    pub fn new(wheel: &Wheel, support: Support, spec: &MeshSpec) -> std::result::Result<Model, ArgumentError> {
        let length = 2.0 * wheel.radius;
        let support = match support {
            Support::Hub { radius } => Support::Hub { radius: radius / length },
            s @ Support::TopArc { .. } => s,
        };
        let spec = MeshSpec { zone: spec.zone.scaled(length), ..*spec };
        Ok(Model {
            mesh: Mesh::wheel(wheel.radius / length, support, &spec)?,
            kelvin: Kelvin::new(1.0, wheel.material.poisson_ratio),
            length,
            modulus: wheel.material.youngs_modulus,
        })
    }
}

/// Numerical health of the BEM condensation (what a BEM source adds to the flexibility).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct BemHealth {
    /// Size of the rearranged BEM system (2 × nodes).
    pub system_size: usize,
    /// Ratio of the largest to the smallest |U_ii| of A's LU factors: a cheap lower bound of A's condition number.
    pub pivot_ratio: f64,
    /// Estimated 1-norm condition number of the rearranged BEM system A (`crate::condition`).
    pub system_condition: f64,
}

struct CondSink<'a> {
    a: &'a mut Mat<f64>,
    rhs: &'a mut Mat<f64>,
    mesh: &'a Mesh,
    /// For each node: its contact index, if it is a contact node.
    contact_index: &'a [Option<usize>],
    /// Number of contact-traction right-hand sides per component that are stored (0: none for t_x).
    store_tx: bool,
    n_contact: usize,
}

impl BlockSink for CondSink<'_> {
    fn add_column(&mut self, col: usize, blocks: &[crate::bem::Block]) {
        let node = self.mesh.nodes[col];
        let nr = 2 * blocks.len();
        match node.bc {
            Bc::Support => {
                for (i, (h, g)) in blocks.iter().enumerate() {
                    self.add(i, col, h, g);
                }
            }
            Bc::Free | Bc::Contact => {
                for m in 0..2 {
                    let a = self.a.col_mut(2 * col + m).try_as_col_major_mut().expect("contiguous").as_slice_mut();
                    for (i, (h, _)) in blocks.iter().enumerate() {
                        a[2 * i] += h[0][m];
                        a[2 * i + 1] += h[1][m];
                    }
                }
                if node.bc == Bc::Contact {
                    let c = self.contact_index[col].expect("contact node has an index");
                    let targets = [Some((c, 1usize)), self.store_tx.then_some((self.n_contact + c, 0usize))];
                    for (rc, comp) in targets.into_iter().flatten() {
                        let r = self.rhs.col_mut(rc).try_as_col_major_mut().expect("contiguous").as_slice_mut();
                        debug_assert_eq!(r.len(), nr);
                        for (i, (_, g)) in blocks.iter().enumerate() {
                            r[2 * i] += g[0][comp];
                            r[2 * i + 1] += g[1][comp];
                        }
                    }
                }
            }
        }
    }

    #[inline]
    fn add(&mut self, row: usize, col: usize, h: &[[f64; 2]; 2], g: &[[f64; 2]; 2]) {
        let node = &self.mesh.nodes[col];
        match node.bc {
            Bc::Support => {
                let p = node.pos;
                let modes = [[1.0, 0.0], [0.0, -1.0], [-p[1], p[0]]];
                let base = self.rhs.ncols() - 3;
                for l in 0..2 {
                    for m in 0..2 {
                        self.a[(2 * row + l, 2 * col + m)] -= g[l][m];
                    }
                    for (mi, mode) in modes.iter().enumerate() {
                        self.rhs[(2 * row + l, base + mi)] -= h[l][0] * mode[0] + h[l][1] * mode[1];
                    }
                }
            }
            Bc::Free => {
                for l in 0..2 {
                    for m in 0..2 {
                        self.a[(2 * row + l, 2 * col + m)] += h[l][m];
                    }
                }
            }
            Bc::Contact => {
                let c = self.contact_index[col].expect("contact node has an index");
                for l in 0..2 {
                    for m in 0..2 {
                        self.a[(2 * row + l, 2 * col + m)] += h[l][m];
                    }
                    // Column layout of rhs: t_y columns 0..n, then t_x columns n..2n (if stored), then 3 rigid.
                    self.rhs[(2 * row + l, c)] += g[l][1];
                    if self.store_tx {
                        self.rhs[(2 * row + l, self.n_contact + c)] += g[l][0];
                    }
                }
            }
        }
    }
}

/// The rearranged BEM system `A x = rhs` before factorisation (see the module docs).
#[non_exhaustive]
pub struct System {
    /// A: −G columns for support DOFs, H columns otherwise (2N × 2N).
    pub a: Mat<f64>,
    /// Right-hand sides: t_y columns of the contact nodes, then (with [`Blocks::All`]) their t_x columns, then the
    /// three rigid modes.
    pub rhs: Mat<f64>,
    /// Which blocks the right-hand sides serve.
    pub blocks: Blocks,
}

/// Assemble the rearranged system of `model` (the BEM assembly stage). A mesh that does not hold together
/// ([`Mesh::check`]) is refused.
pub fn assemble_system(model: &Model, blocks: Blocks) -> Result<System> {
    let mesh = &model.mesh;
    mesh.check()?;
    let nn = mesh.n_nodes();
    let nc = mesh.contact_nodes.len();
    let mut contact_index = vec![None; nn];
    for (c, &i) in mesh.contact_nodes.iter().enumerate() {
        contact_index[i] = Some(c);
    }
    let store_tx = blocks != Blocks::Normal;
    let ncols = if store_tx { 2 * nc } else { nc } + 3;
    let mut a = Mat::<f64>::zeros(2 * nn, 2 * nn);
    let mut rhs = Mat::<f64>::zeros(2 * nn, ncols);
    {
        let mut sink =
            CondSink { a: &mut a, rhs: &mut rhs, mesh, contact_index: &contact_index, store_tx, n_contact: nc };
        assemble(mesh, &model.kelvin, &mut sink);
    }
    if !a.col_iter().all(|c| c.iter().all(|v| v.is_finite())) {
        return Err(Error::Numerical { stage: "assembly", message: "the BEM system has non-finite entries".into() });
    }
    Ok(System { a, rhs, blocks })
}

/// Factorise the rearranged system once and solve for the flexibility (the condensation stage).
pub fn solve_system(model: &Model, sys: &System) -> Result<(Flexibility, BemHealth)> {
    solve_system_with_response(model, sys).map(|(flex, health, _)| (flex, health))
}

/// [`solve_system`], also returning the solution of every right-hand side (`A⁻¹ rhs`, 2N × columns of
/// [`System::rhs`]): the whole boundary's response to unit contact tractions, kept for interior stresses
/// ([`BoundaryResponse`]).
///
/// A system of another model (other sizes than `model`'s mesh gives) is refused, as is a mesh that does not hold
/// together ([`Mesh::check`]).
pub fn solve_system_with_response(model: &Model, sys: &System) -> Result<(Flexibility, BemHealth, Mat<f64>)> {
    let mesh = &model.mesh;
    mesh.check()?;
    let nn = mesh.n_nodes();
    let nc = mesh.contact_nodes.len();
    let store_tx = sys.blocks != Blocks::Normal;
    let ncols = sys.rhs.ncols();
    let expected = (2 * nn, if store_tx { 2 * nc } else { nc } + 3);
    if (sys.a.nrows(), sys.a.ncols(), sys.rhs.nrows(), ncols) != (expected.0, expected.0, expected.0, expected.1) {
        return Err(ArgumentError::new(
            "solve_system",
            "sys",
            format!(
                "is {}×{} with {}×{} right-hand sides; the model's mesh gives {}×{} and {}×{}: a system of another \
                 model?",
                sys.a.nrows(),
                sys.a.ncols(),
                sys.rhs.nrows(),
                ncols,
                expected.0,
                expected.0,
                expected.0,
                expected.1
            ),
        )
        .into());
    }
    let lu = sys.a.partial_piv_lu();
    let u = lu.U();
    let (mut umax, mut umin) = (0.0_f64, f64::INFINITY);
    for i in 0..u.nrows() {
        let v = u[(i, i)].abs();
        umax = umax.max(v);
        umin = umin.min(v);
    }
    let pivot_ratio = umax / umin;
    if !pivot_ratio.is_finite() || pivot_ratio > BEM_SINGULAR_PIVOT_RATIO {
        return Err(Error::Numerical {
            stage: "condensation",
            message: format!(
                "the rearranged BEM system is singular (LU pivot ratio {pivot_ratio:.3e}): check the support"
            ),
        });
    }
    let sol = lu.solve(&sys.rhs);
    let system_condition = crate::condition::cond1(&sys.a, &lu);
    let weights: Vec<f64> = mesh.contact_nodes.iter().map(|&i| mesh.nodes[i].weight).collect();
    // Displacement component `comp` of the contact nodes per unit nodal force of right-hand side columns col0..:
    // K = F W⁻¹ (column j divided by node j's tributary length).
    let per_force = |comp: usize, col0: usize| {
        Mat::from_fn(nc, nc, |r, c| sol[(2 * mesh.contact_nodes[r] + comp, col0 + c)] / weights[c])
    };
    let rigid0 = ncols - 3;
    let response = |comp: usize, m: usize| -> Vec<f64> {
        mesh.contact_nodes.iter().map(|&i| sol[(2 * i + comp, rigid0 + m)]).collect()
    };
    // A rigid translation of the support with the contact traction-free moves the whole body rigidly, and the
    // discrete system reproduces it exactly (H's rows sum to zero): the translations' responses are (1, 0) and
    // (0, −1) to round-off, and are set exactly, so that round-off cannot couple a huge rigid shift into the gaps
    // (an unbounded shift must not buy a spurious solution of an infeasible drive). A rigid rotation is reproduced
    // only to the discretisation error (REFERENCES.md), so its responses are the computed ones.
    let nodes = mesh.contact_nodes.len();
    let exact = |v: f64| vec![v; nodes];
    let modes = vec![
        RigidMode { kind: ModeKind::Shift, normal: exact(0.0), tangential: store_tx.then(|| exact(1.0)) },
        RigidMode { kind: ModeKind::Approach, normal: exact(-1.0), tangential: store_tx.then(|| exact(0.0)) },
        RigidMode { kind: ModeKind::Rotation, normal: response(1, 2), tangential: store_tx.then(|| response(0, 2)) },
    ];
    let flex = Flexibility {
        k_nn: per_force(1, 0),
        k_nt: store_tx.then(|| per_force(1, nc)),
        k_tn: store_tx.then(|| per_force(0, 0)),
        k_tt: store_tx.then(|| per_force(0, nc)),
        modes,
        x: mesh.contact_nodes.iter().map(|&i| mesh.nodes[i].pos[0]).collect(),
        y: mesh.contact_nodes.iter().map(|&i| mesh.nodes[i].pos[1]).collect(),
        g0: mesh.contact_nodes.iter().map(|&i| mesh.nodes[i].gap).collect(),
        weights,
        normals: None,
        scales: Scales { length: model.length, modulus: model.modulus },
        id: Default::default(),
        derived: Default::default(),
    };
    Ok((flex, BemHealth { system_size: 2 * nn, pivot_ratio, system_condition }, sol))
}

/// Assemble, factorise and condense the model to the contact flexibility, timing both stages.
pub fn condense(model: &Model, blocks: Blocks) -> Result<(Flexibility, BemHealth, SourceTiming)> {
    condense_with_response(model, blocks).map(|(flex, health, timing, _)| (flex, health, timing))
}

/// [`condense`], also returning the whole boundary's response to unit contact tractions (the solution of every
/// right-hand side of the rearranged system, 2N × columns of [`System::rhs`]; see [`BoundaryResponse`]).
pub fn condense_with_response(
    model: &Model,
    blocks: Blocks,
) -> Result<(Flexibility, BemHealth, SourceTiming, Mat<f64>)> {
    let nn = model.mesh.n_nodes();
    let t0 = std::time::Instant::now();
    let stage = crate::progress::stage(|| format!("assembling the BEM system ({nn} nodes, {0}×{0})", 2 * nn));
    let sys = assemble_system(model, blocks)?;
    drop(stage);
    let t1 = std::time::Instant::now();
    let stage = crate::progress::stage(|| format!("condensing: LU of the {0}×{0} BEM system and its solves", 2 * nn));
    let (flex, health, sol) = solve_system_with_response(model, &sys)?;
    drop(stage);
    let t2 = std::time::Instant::now();
    let timing = SourceTiming { assembly: (t1 - t0).as_secs_f64(), condensation: (t2 - t1).as_secs_f64() };
    Ok((flex, health, timing, sol))
}

/// The wheel's whole boundary solution per unit contact traction, kept after the condensation so that interior
/// stresses can be computed from any solved contact tractions without assembling or factorising again
/// ([`crate::stresses`]). Dimensionless like the [`Model`].
///
/// By linearity, contact tractions (p, q) with the support clamped in place give the boundary unknowns
/// `x = Σ_c p_c X[:, c] + q_c X[:, n + c]` (X = `matrix`, n contact nodes): the support nodes' tractions and the
/// other nodes' displacements. The support's rigid motion is left out: a rigid motion of the whole wheel is
/// stress-free, so the stresses do not depend on it (the translations are reproduced exactly by the discrete
/// system, a rotation only to the discretisation error, which leaving it out avoids).
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct BoundaryResponse {
    /// The model the response belongs to.
    pub model: Model,
    /// `A⁻¹ rhs` ([`solve_system_with_response`]): columns t_y of the contact nodes, then (with [`Blocks::All`])
    /// their t_x, then the three rigid modes.
    pub matrix: Mat<f64>,
    /// Whether the t_x columns are present (the tangential problem was built).
    pub tangential: bool,
}

/// Every node's displacement u and traction t, in node order ([`BoundaryResponse::boundary`]).
pub type BoundarySolution = (Vec<[f64; 2]>, Vec<[f64; 2]>);

impl BoundaryResponse {
    /// Every node's displacement u and traction t (dimensionless, in node order) for contact tractions `p` (= t_y)
    /// and `q` (= t_x) at the contact nodes (in [`Mesh::contact_nodes`] order, dimensionless: stress / E), with the
    /// support clamped in place.
    ///
    /// Refused, naming the argument: `p` or `q` without one value per contact node, a nonzero `q` when the
    /// tangential columns were not built, a matrix of another size than the mesh gives, a mesh that does not hold
    /// together ([`Mesh::check`]).
    pub fn boundary(&self, p: &[f64], q: &[f64]) -> std::result::Result<BoundarySolution, ArgumentError> {
        const F: &str = "BoundaryResponse::boundary";
        let mesh = &self.model.mesh;
        mesh.check()?;
        let nc = mesh.contact_nodes.len();
        for (name, v) in [("p", p), ("q", q)] {
            if v.len() != nc {
                return Err(ArgumentError::new(
                    F,
                    name,
                    format!("has {} values, the mesh {nc} contact nodes", v.len()),
                ));
            }
        }
        if !self.tangential && q.iter().any(|v| *v != 0.0) {
            return Err(ArgumentError::new(
                F,
                "q",
                "is nonzero, but the tangential columns were not built".to_string(),
            ));
        }
        let columns = if self.tangential { 2 * nc } else { nc };
        if self.matrix.nrows() != 2 * mesh.n_nodes() || self.matrix.ncols() < columns {
            return Err(ArgumentError::new(
                F,
                "self.matrix",
                format!(
                    "is {}×{}; the mesh needs {}×{columns} at least",
                    self.matrix.nrows(),
                    self.matrix.ncols(),
                    2 * mesh.n_nodes()
                ),
            ));
        }
        let rows = self.matrix.nrows();
        let mut x = vec![0.0; rows];
        for c in 0..nc {
            let cols = [Some((c, p[c])), self.tangential.then(|| (nc + c, q[c]))];
            for (col, v) in cols.into_iter().flatten().filter(|(_, v)| *v != 0.0) {
                let m = self.matrix.col(col);
                for (xi, mi) in x.iter_mut().zip(m.iter()) {
                    *xi += v * mi;
                }
            }
        }
        let mut contact = vec![None; mesh.n_nodes()];
        for (c, &i) in mesh.contact_nodes.iter().enumerate() {
            contact[i] = Some(c);
        }
        let (mut u, mut t) = (vec![[0.0; 2]; mesh.n_nodes()], vec![[0.0; 2]; mesh.n_nodes()]);
        for (i, node) in mesh.nodes.iter().enumerate() {
            let xi = [x[2 * i], x[2 * i + 1]];
            match node.bc {
                Bc::Support => t[i] = xi,
                Bc::Free => u[i] = xi,
                Bc::Contact => {
                    // Every contact node is listed in contact_nodes (checked above).
                    let c = contact[i].unwrap_or_default();
                    u[i] = xi;
                    t[i] = [q[c], p[c]];
                }
            }
        }
        Ok((u, t))
    }
}
