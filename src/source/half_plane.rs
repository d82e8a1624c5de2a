//! The elastic half-plane as a flexibility source: the half-space model of the wheel (Hertz, Cattaneo–Mindlin,
//! Carter and Spence are half-plane theories), and the elastic counter-body added to any source.
//!
//! **Geometry.** The half-plane has the wheel's material (E, ν, plane strain) and the wheel's initial gap: the
//! circle of radius R, g₀ = R − √(R² − x²) (default), or Hertz's parabola x²/(2R) (`[wheel] profile`). Its
//! surface is the line y = −R; the body lies above it (z = y + R is the depth into the wheel). The contact grid's
//! strips lie between the x of the BEM wheel's contact vertices ([`crate::mesh::contact_vertex_angles`]), and the
//! collocation points at the strips' midpoints, so one key (`[wheel] model`) switches a scene between the models
//! at the same points. Each strip carries a uniform traction; the influence coefficients are the closed forms of
//! [`crate::halfplane`].
//!
//! **Rigid modes and the datum.** A half-plane's surface displacement under a line load is logarithmic: it is
//! defined only relative to a datum. rollbem's datum is the material point at depth D below the contact centre
//! (`[wheel] datum_depth`, default R: the depth of the wheel's centre); the displacements are relative to it, and
//! the drive prescribes its rigid motion: the shift (every point moves by (1, 0)) and the approach (by (0, −1)).
//! A load is datum-independent (the tractions do not depend on D); an approach is the approach of the datum point.
//! The half-plane has no support, no other boundary and no rotation about a centre: `support`, `other_elements`,
//! `rotation` and `moment` are refused by the scene's validation.
//!
//! **Counter-body** ([`add_counter_body`]): an elastic half-plane below the contact line (E₂, ν₂, datum depth D₂,
//! default R), loaded by the reactions (−q, −p). Its surface displacements add to the wheel's in the relative
//! kinematics of the pair (slip = u_x,wheel − u_x,flat; gap change = the wheel's surface moving away from the flat
//! plus the flat's moving away from the wheel): `K_NN += C′_zz`, `K_TT += C′_xx`, `K_NT −= C′_zx`,
//! `K_TN −= C′_xz` ([`crate::halfplane::InfluenceBlocks::into_counter_body`]). For two identical materials the
//! coupling blocks cancel exactly (Dundurs' β = 0).
//!
//! **Strip of half-spaces** (`[mesh] strip_width`): both bodies' coefficients are then those of a strip of that
//! width on half-spaces, CONTACT's model of its 2D cases ([`crate::halfplane`], "Strip of half-spaces"). They are
//! absolute displacements, so the datum plays no part: a shift and an approach are those of points far away.
//!
//! **Viscoelastic bodies** (`viscoelastic = { ... }` of `[wheel]` or `[counter_body]`, steady rolling at `[rolling]
//! velocity`): each body's coefficients carry its memory, `A(x) + f ∫₀^∞ e^{−η} A(x + Lη) dη` with `L = direction ·
//! V·τ_C / 2R` ([`crate::viscoelastic`], [`HalfPlane::viscoelastic`]); the glassy modulus is the body's
//! `youngs_modulus`. An elastic scene builds exactly the elastic coefficients (no memory, no quadrature).
//!
//! Units: dimensionless as every flexibility ([`crate::flexibility`]): lengths / L0 (L0 = 2R), stresses / E.

use super::{Blocks, Built, SourceInfo, SourceTiming};
use crate::error::{ArgumentError, Result};
use crate::flexibility::{Flexibility, ModeKind, RigidMode, Scales};
use crate::halfplane::{Block, HalfPlane, InfluenceBlocks};
use crate::scene::{Body, CounterBody, ElementKind, Profile, Scene, ZoneExtent};
use faer::Mat;

/// The contact grid of a scene, dimensionless: strip ends and collocation points.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Left ends a_j.
    pub a: Vec<f64>,
    /// Right ends b_j.
    pub b: Vec<f64>,
    /// Collocation points (midpoints).
    pub xc: Vec<f64>,
    /// Uniform spacing and left end (x0, h), when the scene gives `contact_half_width` or `contact_x` (the Toeplitz fast path).
    pub uniform: Option<(f64, f64)>,
}

impl Grid {
    /// The grid of a scene (lengths / L0): uniform in x with `contact_half_width` or `contact_x`, the x-projections of the BEM
    /// wheel's contact chords with `contact_arc_deg`.
    pub fn of(scene: &Scene) -> Grid {
        let l0 = 2.0 * scene.radius();
        let zone = scene.zone();
        let n = zone.elements;
        match zone.extent {
            ZoneExtent::HalfWidth { half_width: w } => {
                let (x0, h) = (-w / l0, 2.0 * w / l0 / n as f64);
                let m = crate::halfplane::uniform_mesh(x0, h, n);
                Grid { a: m.a, b: m.b, xc: m.xc, uniform: Some((x0, h)) }
            }
            ZoneExtent::Span { x_min, x_max } => {
                let (x0, h) = (x_min / l0, (x_max - x_min) / l0 / n as f64);
                let m = crate::halfplane::uniform_mesh(x0, h, n);
                Grid { a: m.a, b: m.b, xc: m.xc, uniform: Some((x0, h)) }
            }
            ZoneExtent::Arc { .. } => {
                let rho = 0.5;
                let x: Vec<f64> =
                    crate::mesh::contact_vertex_angles(rho, &zone.scaled(l0)).iter().map(|t| rho * t.cos()).collect();
                let xc = x.windows(2).map(|v| 0.5 * (v[0] + v[1])).collect();
                Grid { a: x[..n].to_vec(), b: x[1..].to_vec(), xc, uniform: None }
            }
        }
    }

    /// The strips' widths: the spacing h itself on a uniform grid (so that K = C W⁻¹ stays exactly Toeplitz, as
    /// [`crate::toeplitz`] needs; b_j − a_j differs from h in the last bits), b_j − a_j otherwise.
    pub fn widths(&self) -> Vec<f64> {
        match self.uniform {
            Some((_, h)) => vec![h; self.xc.len()],
            None => self.a.iter().zip(&self.b).map(|(a, b)| b - a).collect(),
        }
    }
}

/// The influence blocks of a half-plane on a grid, handed out one at a time (row-major): on a uniform grid each is computed alone when asked for (a flexibility that needs two never holds
/// the other two); on another grid all four are computed on the first request, once.
struct BlockSource<'g> {
    grid: &'g Grid,
    hp: HalfPlane,
    all: Option<InfluenceBlocks>,
}

impl<'g> BlockSource<'g> {
    fn new(grid: &'g Grid, hp: HalfPlane) -> Self {
        BlockSource { grid, hp, all: None }
    }

    fn take(&mut self, which: Block) -> std::result::Result<Vec<f64>, ArgumentError> {
        let g = self.grid;
        if let Some((x0, h)) = g.uniform {
            return self.hp.influence_block_uniform(x0, h, g.xc.len(), which);
        }
        let c = match &mut self.all {
            Some(c) => c,
            all @ None => all.insert(self.hp.influence_blocks(&g.a, &g.b, &g.xc)?),
        };
        Ok(std::mem::take([&mut c.cxx, &mut c.cxz, &mut c.czx, &mut c.czz][which.index()]))
    }
}

/// A row-major block per unit traction → K per unit nodal force (column j divided by the strip width w_j).
fn per_force(block: &[f64], w: &[f64]) -> Mat<f64> {
    let n = w.len();
    Mat::from_fn(n, n, |i, j| block[i * n + j] / w[j])
}

/// Build the half-plane flexibility of a (validated) scene with `model = "half_plane"`.
pub fn build(scene: &Scene, blocks: Blocks) -> Result<Built> {
    let t0 = std::time::Instant::now();
    let w = scene.wheel();
    let Body::HalfPlane { profile, .. } = *scene.body() else {
        unreachable!("half_plane::build is called for the half-plane model only")
    };
    let l0 = 2.0 * w.radius;
    let grid = Grid::of(scene);
    let n = grid.xc.len();
    let rho = 0.5;
    let g0: Vec<f64> = grid
        .xc
        .iter()
        .map(|&x| match profile {
            Profile::Circle => x * x / (rho + (rho * rho - x * x).sqrt()),
            Profile::Parabola => x * x / (2.0 * rho),
        })
        .collect();
    let weights = grid.widths();
    let Some(hp) = wheel_half_plane(scene)? else {
        unreachable!("half_plane::build is called for the half-plane model only")
    };
    let all = blocks != Blocks::Normal;
    let coupled = blocks == Blocks::All;
    let tangential = |v: f64| all.then(|| vec![v; n]);
    // One block at a time, only those the scene needs (peak memory: the 841-element creep curve holds two n × n
    // blocks, not four, and never a second copy of them).
    let mut source = BlockSource::new(&grid, hp);
    let mut k = |which: Block| source.take(which).map(|b| per_force(&b, &weights));
    let k_nn = k(Block::Zz)?;
    let k_nt = if coupled { Some(k(Block::Zx)?) } else { None };
    let k_tn = if coupled { Some(k(Block::Xz)?) } else { None };
    let k_tt = if all { Some(k(Block::Xx)?) } else { None };
    let mut flex = Flexibility {
        k_nn,
        k_nt,
        k_tn,
        k_tt,
        modes: vec![
            RigidMode { kind: ModeKind::Shift, normal: vec![0.0; n], tangential: tangential(1.0) },
            RigidMode { kind: ModeKind::Approach, normal: vec![-1.0; n], tangential: tangential(0.0) },
        ],
        y: g0.iter().map(|g| g - rho).collect(),
        x: grid.xc.clone(),
        g0,
        weights,
        normals: None,
        scales: Scales { length: l0, modulus: w.material.youngs_modulus },
        id: Default::default(),
        derived: Default::default(),
    };
    add_counter_body(&mut flex, scene, &grid)?;
    let assembly = t0.elapsed().as_secs_f64();
    Ok(Built {
        flex,
        info: SourceInfo {
            elements: n,
            nodes: n,
            element: ElementKind::Constant,
            system_size: None,
            pivot_ratio: None,
            condition: None,
            contact_element_length: scene.zone().element_length(w.radius),
            viscoelastic: scene.is_viscoelastic(),
        },
        timing: SourceTiming { assembly, condensation: 0.0 },
        boundary: None,
        pair: None,
    })
}

/// The wheel as a half-plane, dimensionless (E = 1, lengths / 2R), when the scene models it so (`Err` only for values
/// a validated scene does not hold).
fn wheel_half_plane(scene: &Scene) -> std::result::Result<Option<HalfPlane>, ArgumentError> {
    let Body::HalfPlane { datum_depth, .. } = *scene.body() else { return Ok(None) };
    let l0 = 2.0 * scene.radius();
    let hp = in_strip(HalfPlane::new(1.0, scene.wheel().material.poisson_ratio, datum_depth / l0)?, scene, l0)?;
    with_memory(hp, scene.viscoelastic_memories().0).map(Some)
}

/// A half-plane with the viscoelastic memory of its body, if it has one ([`HalfPlane::viscoelastic`]).
fn with_memory(
    hp: HalfPlane,
    memory: Option<crate::viscoelastic::Memory>,
) -> std::result::Result<HalfPlane, ArgumentError> {
    match memory {
        Some(m) => hp.viscoelastic(m),
        None => Ok(hp),
    }
}

/// The elastic counter-body as a half-plane in the wheel's units (E / E_wheel, lengths / 2R), if there is one.
fn counter_half_plane(scene: &Scene) -> std::result::Result<Option<HalfPlane>, ArgumentError> {
    let CounterBody::HalfPlane { material, datum_depth, .. } = *scene.counter_body() else { return Ok(None) };
    let (l0, e) = (2.0 * scene.radius(), scene.wheel().material.youngs_modulus);
    let hp = HalfPlane::new(material.youngs_modulus / e, material.poisson_ratio, datum_depth / l0)?;
    with_memory(in_strip(hp, scene, l0)?, scene.viscoelastic_memories().1).map(Some)
}

/// Whether the scene's normal–tangential cross flexibilities K_NT, K_TN vanish identically, whatever the loads:
/// a half-plane wheel whose cross influence cancels against the counter-body's
/// ([`HalfPlane::cross_influence_cancels`]: the same material and datum depth in plane strain, Dundurs' β = 0 on a
/// strip). A BEM wheel never qualifies: a finite wheel keeps a coupling of order a/R (curvature, bending) even at
/// ν = 0.5. The half-planes are the ones [`build`] and [`add_counter_body`] use.
pub fn cross_blocks_vanish(scene: &Scene) -> bool {
    match (wheel_half_plane(scene), counter_half_plane(scene)) {
        (Ok(Some(w)), Ok(counter)) => w.cross_influence_cancels(counter.as_ref()),
        _ => false,
    }
}

/// A half-plane as the scene poses it: in plane strain, or on the strip of `[mesh] strip_width` (lengths / `l0`).
fn in_strip(hp: HalfPlane, scene: &Scene, l0: f64) -> std::result::Result<HalfPlane, ArgumentError> {
    match *scene.body() {
        Body::HalfPlane { strip_width: Some(w), .. } => hp.strip(w / l0),
        _ => Ok(hp),
    }
}

/// Add the elastic counter-body's flexibility (if the scene has one) on the grid of strips carrying the contact
/// nodes' forces (see the module docs). A rigid counter-body adds nothing.
pub fn add_counter_body(flex: &mut Flexibility, scene: &Scene, grid: &Grid) -> Result<()> {
    let Some(hp) = counter_half_plane(scene)? else { return Ok(()) };
    let w = grid.widths();
    // Only the blocks the flexibility holds, one at a time, with the counter-body's signs
    // ([`crate::halfplane::InfluenceBlocks::into_counter_body`]).
    let mut source = BlockSource::new(grid, hp);
    let mut add = |k: &mut Mat<f64>, which: Block| -> Result<()> {
        let block = source.take(which)?;
        let sign = crate::halfplane::COUNTER_BODY_SIGN[which.index()];
        let n = w.len();
        for j in 0..n {
            for i in 0..n {
                k[(i, j)] += (sign * block[i * n + j]) / w[j];
            }
        }
        Ok(())
    };
    add(&mut flex.k_nn, Block::Zz)?;
    if let Some(k) = flex.k_nt.as_mut() {
        add(k, Block::Zx)?;
    }
    if let Some(k) = flex.k_tn.as_mut() {
        add(k, Block::Xz)?;
    }
    if let Some(k) = flex.k_tt.as_mut() {
        add(k, Block::Xx)?;
    }
    Ok(())
}
