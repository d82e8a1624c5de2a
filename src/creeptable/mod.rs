//! Creep-force tables (issue 36, item 4): the creep forces Fx, Fy and the spin moment Mz of a steadily rolling
//! elliptic contact over a grid of creepages (ξ, η, φ), ellipses a/b and Poisson ratios ν, computed by any
//! [`CreepEngine`] — FASTSIM ([`engines::Fastsim`]), Kalker's linear theory ([`engines::KalkerLinear`]) or an exact
//! solver that implements the trait — and written as a CSV table and a compact binary (`.npz`) that a
//! vehicle-dynamics program can read and interpolate.
//!
//! # Cases and engines
//!
//! A [`CreepCase`] is one steady-rolling problem in physical units: the semi-axes a (along the rolling direction x)
//! and b, the combined modulus of rigidity G and Poisson ratio ν, the friction coefficient μ, the normal force N (or
//! Hertz's peak pressure p0 = 3N/(2πab), [`Load`]), the creepages ([`crate::fastsim::Creepages`]: ξ, η
//! dimensionless, φ in rad/length) and a grid resolution ([`Resolution`]) the engine may ignore. Conventions are
//! CONTACT's, as in [`crate::fastsim`]: creepages of body 1 relative to body 2 (the rigid slip is
//! `(ξ − φ y, η + φ x)`), forces and moment on body 1, rolling along +x.
//!
//! An engine answers a case with a [`CreepResult`]: a [`CaseStatus`] (solved, gross sliding, not converged with its
//! residual) and the forces when it has them — never a made-up number: a not-converged case has no forces, and an
//! engine that cannot give Mz (the linear theory with spin: Kalker's C33 is not transcribed) leaves it out. A case
//! the engine cannot take at all (a/b outside its range, say) is an [`ArgumentError`] naming the argument.
//!
//! **Plugging in an engine**: implement [`CreepEngine`] (a name, the settings that change its answers, and
//! `forces`), give it an [`EngineEntry`] (its name as a table spec writes it in `engine = "..."`, a one-line
//! description, and `build`, which reads the spec's `[options]` table and refuses unknown keys naming them), and add
//! the entry to [`BUILT_IN`]. Every table command (`rollbem sweep` of a creep-table spec, its shards, resume and
//! merge, the figure, the readers) then serves it unchanged.
//!
//! # The table: normalised creepages and forces (Kalker's USETAB, CONTACT's `usetab_table`)
//!
//! Creep forces of Hertzian contacts depend on the load, the size and the modulus only through a scaling: with
//! c = √(ab) and Kalker's coefficients C11, C22, C23 at the case's a/b and ν ([`crate::theory::kalker`]), a table
//! holds the **normalised** creepages ξ', η', φ' and forces, related to the physical ones by
//!
//! ```text
//!   ξ = −ξ' · 3μN / (G c² C11),   η = −η' · 3μN / (G c² C22),   φ = −φ' · μN / (G c³ C23)
//!   Fx' = Fx / (μN),              Fy' = Fy / (μN),              Mz' = Mz / (μN c)
//! ```
//!
//! so that the linear theory reads `Fx' = 3ξ'`, `Fy' = 3η' + φ'` and a positive normalised creepage gives a positive
//! normalised force (the minus sign undoes CONTACT's sign convention: a positive ξ of body 1 gives a negative Fx on
//! it), and full sliding is reached near ξ' = 1 for ξ alone in the simplified theory. These are the scalings of
//! Kalker's table of the Hertzian creep-force law (USETAB) as CONTACT's `usetab_table` program computes it (G = 1,
//! N = 1, μ = 1, c = 1). The table here is the same quantity on a grid the spec chooses: every axis is a strictly
//! increasing list (a vehicle-dynamics code interpolates in it), the case index runs over ν (slowest), a/b, ξ', η',
//! φ' (fastest) — `index = iφ + nφ (iη + nη (iξ + nξ (i_ab + n_ab i_ν)))`, USETAB's order with ν outermost.
//!
//! # Files (the layout is checked by this module's tests and `tests/creeptable.rs`)
//!
//! * **CSV** ([`TABLE_COLUMNS`], one row per case, sorted by case, `,`-separated, a header line, numbers in Rust's
//!   shortest round-trip form so a reader gets the same bits; an empty cell is a value the engine did not give):
//!   `case, nu, a_over_b, xi_n, eta_n, phi_n` (the case and its normalised coordinates), `status` (`solved`,
//!   `gross_sliding`, `not_converged`, `refused`), `fx_n, fy_n, mz_n` (the normalised forces), `engine`, then the
//!   physical case `a, b` (the semi-axes), `c11, c22, c23` (Kalker's coefficients that normalise this ellipse),
//!   `xi, eta, phi, fx, fy, mz` (the spec's units), `residual`, `contact_elements`,
//!   `slip_elements`, `case_digest` (a digest of everything the case's answer depends on: the engine and its
//!   settings, the spec's contact, grid and the case's coordinates; merges check it) and `message`.
//! * **NPZ** (NumPy's `.npz`: a ZIP archive of `.npy` arrays, stored uncompressed; `numpy.load` reads it, and each
//!   member is a plain `.npy` a C or Fortran program can read after a 30-byte-plus-name ZIP header): `forces`
//!   (float64, shape (nν, n_ab, nξ, nη, nφ, 3): Fx', Fy', Mz' with NaN where the engine gave none), `status` (int8,
//!   shape (nν, n_ab, nξ, nη, nφ): 0 solved, 1 gross sliding, 2 not converged, 3 refused), the axes `nu`, `a_over_b`,
//!   `xi`, `eta`, `phi` (float64) and `coefficients` (float64, shape (nν, n_ab, 3): the C11, C22, C23 that normalise
//!   each ellipse). Written beside the CSV (`OUT.npz` for `OUT.csv`) for a whole table, never for a shard.
//!   Why `.npz`: one file holding the axes with the data, self-describing (dtype, shape, order in each member's
//!   header), read by NumPy with no extra package and by small readers in every language (cnpy for C++, NPZ.jl);
//!   writing it takes a few dozen lines here (`npz.rs`), no crate. NetCDF or HDF5 would need a C library.
//!
//! The readers: [`CreepTable::read_csv`], [`CreepTable::read_npz`] (Rust) and `rollbem.creeptable` (Python).

mod command;
mod engines;
mod exact;
mod figure;
mod npz;
mod run;
mod section;
mod spec;
mod table;

pub use command::{fastsim_command, FastsimArgs};
pub use engines::{Fastrip, Fastsim, KalkerLinear};
pub use exact::Exact;
pub use figure::{creep_surface_svg, plot_table, write_figure};
pub use run::{
    compute_spec, compute_table, is_table_csv, is_table_spec, merge_tables, run_table, run_table_with, TableOptions,
    TableOutcome,
};
pub use section::markdown_section;
pub use spec::{Axes, Normalisation, TableSpec, MAX_CASES};
pub use table::{CreepTable, TableRow, TABLE_COLUMNS};

use crate::error::ArgumentError;
use crate::fastsim::Creepages;
use std::f64::consts::PI;

/// The normal load of a case: the normal force N, or Hertz's peak pressure p0 (N = 2π a b p0 / 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// The normal force N (force, > 0).
    NormalForce(f64),
    /// Hertz's peak pressure p0 = 3N/(2πab) (force/length², > 0).
    PeakPressure(f64),
}

/// Elements across the contact: `mx` along x (the rolling direction, over 2a) and `my` along y (over 2b). An engine
/// may ignore it (the linear theory) or read it its own way (FASTSIM: `my` strips of `mx` elements).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Resolution {
    /// Elements along x (≥ 1).
    pub mx: usize,
    /// Elements along y (≥ 1).
    pub my: usize,
}

/// One steady-rolling problem of an elliptic contact (module docs; CONTACT's conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CreepCase {
    /// Semi-axis along the rolling direction x (length, > 0).
    pub a: f64,
    /// Lateral semi-axis along y (length, > 0).
    pub b: f64,
    /// Combined Poisson ratio ν, in [0, 1/2].
    pub nu: f64,
    /// Combined modulus of rigidity G (force/length², > 0).
    pub shear_modulus: f64,
    /// Coefficient of friction μ (≥ 0).
    pub mu: f64,
    /// The normal load.
    pub load: Load,
    /// The creepages of body 1 relative to body 2 (ξ, η dimensionless; φ rad/length).
    pub creepages: Creepages,
    /// The grid resolution (the engine may ignore it).
    pub resolution: Resolution,
}

impl CreepCase {
    /// A case from the ellipse's shape a/b and its size c = √(ab): a = c √(a/b), b = c / √(a/b).
    #[allow(clippy::too_many_arguments)]
    pub fn from_shape(
        a_over_b: f64,
        c: f64,
        nu: f64,
        shear_modulus: f64,
        mu: f64,
        load: Load,
        creepages: Creepages,
        resolution: Resolution,
    ) -> CreepCase {
        let r = a_over_b.sqrt();
        CreepCase { a: c * r, b: c / r, nu, shear_modulus, mu, load, creepages, resolution }
    }

    /// The normal force N (force): the load's, or 2π a b p0 / 3.
    pub fn normal_force(&self) -> f64 {
        match self.load {
            Load::NormalForce(n) => n,
            Load::PeakPressure(p0) => 2.0 * PI * self.a * self.b * p0 / 3.0,
        }
    }

    /// The size c = √(ab) (length).
    pub fn size(&self) -> f64 {
        (self.a * self.b).sqrt()
    }

    /// The contact in [`crate::fastsim`]'s terms.
    pub fn contact(&self) -> crate::fastsim::Contact {
        crate::fastsim::Contact {
            a: self.a,
            b: self.b,
            shear_modulus: self.shear_modulus,
            nu: self.nu,
            mu: self.mu,
            normal_force: self.normal_force(),
        }
    }
}

/// How an engine ended on a case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CaseStatus {
    /// Solved (some of the contact adheres, or the engine has no slip at all: the linear theory).
    Solved,
    /// Solved with every element of the contact slipping: the forces are those of full sliding (|F| = μN for
    /// creepages without spin).
    GrossSliding,
    /// The engine's iteration stopped before its tolerance; `residual` is where it stopped (the engine's own
    /// measure). No forces are reported.
    NotConverged {
        /// The engine's residual at the last iterate (dimensionless, as the engine defines it).
        residual: f64,
    },
}

impl CaseStatus {
    /// The status's name in a table (`solved`, `gross_sliding`, `not_converged`).
    pub fn name(&self) -> &'static str {
        match self {
            CaseStatus::Solved => "solved",
            CaseStatus::GrossSliding => "gross_sliding",
            CaseStatus::NotConverged { .. } => "not_converged",
        }
    }
}

/// The forces of a solved case, on body 1 (CONTACT's signs; units of the case).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forces {
    /// Longitudinal force Fx (force).
    pub fx: f64,
    /// Lateral force Fy (force).
    pub fy: f64,
    /// Spin moment Mz about the ellipse's centre (force·length), `None` when the engine cannot give it.
    pub mz: Option<f64>,
}

/// What an engine answers for one case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CreepResult {
    /// How the engine ended.
    pub status: CaseStatus,
    /// The forces: `Some` exactly when the status is solved or gross sliding.
    pub forces: Option<Forces>,
    /// The engine's residual of its converged answer, when it has one (an exact solver's; FASTSIM and the linear
    /// theory have none).
    pub residual: Option<f64>,
    /// Elements in contact, when the engine has elements.
    pub contact_elements: Option<usize>,
    /// Elements slipping, when the engine has elements.
    pub slip_elements: Option<usize>,
}

/// A creep-force engine: FASTSIM, Kalker's linear theory, an exact solver. Shared by the table's worker threads.
pub trait CreepEngine: Send + Sync {
    /// The engine's name, as a table spec writes it (`engine = "..."`).
    fn name(&self) -> &str;
    /// Everything of the engine's settings that changes its answers, as a stable text (it enters each case's
    /// digest, so a table computed with other settings is not merged or resumed into this one).
    fn settings(&self) -> String;
    /// The creep forces of one case. Errors: a case the engine cannot take, naming the argument.
    fn forces(&self, case: &CreepCase) -> Result<CreepResult, ArgumentError>;
}

/// What an engine's `build` returns: the engine, or the `[options]` key it refuses and why.
pub type Built = Result<Box<dyn CreepEngine>, (String, String)>;

/// A registered engine: its name, what it is, and how a table spec's `[options]` table builds it.
#[derive(Clone, Copy)]
pub struct EngineEntry {
    /// The name a spec writes in `engine = "..."`.
    pub name: &'static str,
    /// One line: what the engine computes.
    pub describe: &'static str,
    /// Builds the engine from the spec's `[options]` table (empty when the spec has none). Errors: an unknown or
    /// invalid option, as `(key, message)` with the key relative to `[options]`.
    pub build: fn(&toml::Table) -> Built,
}

/// The engines a table spec can name.
pub const BUILT_IN: &[EngineEntry] =
    &[engines::FASTSIM_ENTRY, engines::FASTRIP_ENTRY, engines::KALKER_LINEAR_ENTRY, exact::EXACT_ENTRY];

/// The registered engine of that name.
pub fn engine_entry(name: &str) -> Option<&'static EngineEntry> {
    BUILT_IN.iter().find(|e| e.name == name)
}
