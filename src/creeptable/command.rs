//! `rollbem fastsim`: one FASTSIM case from the command line (CONTACT's conventions, [`crate::fastsim`]).

use crate::error::{ArgumentError, Error, Result};
use crate::fastsim::{self, Bound, Contact, Creepages, Direction, Flexibility, Grid, Options, State};
use std::path::PathBuf;

/// The arguments of `rollbem fastsim` (units: any consistent set, e.g. mm, N, N/mm²).
#[derive(Debug, Clone, clap::Args)]
pub struct FastsimArgs {
    /// Semi-axis a along the rolling direction x (length, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub a: f64,
    /// Lateral semi-axis b (length, > 0); 0.1 ≤ a/b ≤ 10 (Kalker's Table E.3).
    #[arg(long, allow_hyphen_values = true)]
    pub b: f64,
    /// Combined modulus of rigidity G = 2/(1/G1 + 1/G2) (force/length², > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub shear_modulus: f64,
    /// Combined Poisson ratio ν in [0, 0.5].
    #[arg(long, allow_hyphen_values = true)]
    pub nu: f64,
    /// Coefficient of friction μ (≥ 0).
    #[arg(long, allow_hyphen_values = true)]
    pub mu: f64,
    /// Normal force N (force, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub normal_force: f64,
    /// Longitudinal creepage ξ of body 1 relative to body 2 (CONTACT's CKSI; ξ > 0 gives Fx < 0 on body 1).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub xi: f64,
    /// Lateral creepage η (CONTACT's CETA).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub eta: f64,
    /// Spin φ in rad/length (CONTACT's CPHI): the rigid slip is (ξ − φ y, η + φ x).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub phi: f64,
    /// Flexibilities: weighted (Kalker's original FASTSIM), three, blended (CONTACT's M = 3 default).
    #[arg(long, default_value = "weighted")]
    pub flexibility: String,
    /// Traction bound: parabolic (Kalker's original, CONTACT's B = 3) or elliptic (Hertz, B = 2).
    #[arg(long, default_value = "parabolic")]
    pub bound: String,
    /// Rolling direction: +x (CONTACT's χ = 0: leading edge at x = +a) or -x (χ = 180°).
    #[arg(long, default_value = "+x", allow_hyphen_values = true)]
    pub direction: String,
    /// Elements along each strip (the strip grid), or along x on CONTACT's grid.
    #[arg(long, default_value_t = 100)]
    pub mx: usize,
    /// Strips across the ellipse, or elements along y on CONTACT's grid.
    #[arg(long, default_value_t = 100)]
    pub my: usize,
    /// Use CONTACT's rectangular grid (IPOTCN = −3) of mx × my elements over [−s a, s a] × [−s b, s b] with this
    /// scale s ≥ 1 (CONTACT's SCALE) instead of the strips.
    #[arg(long, allow_hyphen_values = true)]
    pub contact_grid: Option<f64>,
    /// Write {the inputs, fx, fy, mz, counts, flexibilities, coefficients} as JSON here (`-`: standard output).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write one row per element (x, y, pn, px, py, state) as CSV here (`-`: standard output).
    #[arg(long)]
    pub csv: Option<PathBuf>,
}

/// A bad flag value as bad input naming the flag.
fn flag(name: &str, message: impl Into<String>) -> Error {
    Error::Invalid { path: PathBuf::from("<command line>"), field: format!("--{name}"), message: message.into() }
}

/// FASTSIM's refusal as bad input naming the flag it came from.
fn refusal(e: ArgumentError) -> Error {
    let name = match e.argument {
        "grid" | "grid.scale" => "mx".to_string(),
        other => other.replace('_', "-"),
    };
    flag(&name, format!("{} ({})", e.message, e.function))
}

impl FastsimArgs {
    /// Solves the case: its contact, creepages, options and FASTSIM's solution. Errors: bad input naming the flag
    /// (`--a`, `--normal-force`, ...: FASTSIM's and Kalker's refusals mapped to the flag they came from).
    pub fn solve(&self) -> Result<(Contact, Creepages, Options, fastsim::Solution)> {
        let (contact, creepages, options) = self.problem()?;
        let s = fastsim::solve(&contact, &creepages, &options).map_err(refusal)?;
        Ok((contact, creepages, options, s))
    }

    /// The contact, creepages and options of the arguments. Errors: an unknown variant name, naming its flag.
    pub fn problem(&self) -> Result<(Contact, Creepages, Options)> {
        let flexibility = match self.flexibility.as_str() {
            "weighted" => Flexibility::Weighted,
            "three" => Flexibility::Three,
            "blended" => Flexibility::Blended,
            s => return Err(flag("flexibility", format!("must be weighted, three or blended, is {s:?}"))),
        };
        let bound = match self.bound.as_str() {
            "parabolic" => Bound::Parabolic,
            "elliptic" => Bound::Elliptic,
            s => return Err(flag("bound", format!("must be parabolic or elliptic, is {s:?}"))),
        };
        let direction = match self.direction.as_str() {
            "+x" => Direction::PlusX,
            "-x" => Direction::MinusX,
            s => return Err(flag("direction", format!("must be +x or -x, is {s:?}"))),
        };
        let grid = match self.contact_grid {
            Some(scale) => Grid::contact(self.mx, self.my, scale),
            None => Grid::Strips { mx: self.mx, my: self.my },
        };
        let contact = Contact {
            a: self.a,
            b: self.b,
            shear_modulus: self.shear_modulus,
            nu: self.nu,
            mu: self.mu,
            normal_force: self.normal_force,
        };
        Ok((
            contact,
            Creepages { xi: self.xi, eta: self.eta, phi: self.phi },
            Options { bound, flexibility, direction, grid },
        ))
    }
}

/// Runs `rollbem fastsim`: the text it prints, after writing `--json` and `--csv`. Errors: bad input naming the
/// flag (exit 2), an output that cannot be written (exit 3).
pub fn fastsim_command(args: &FastsimArgs) -> Result<String> {
    let (contact, creepages, options, s) = args.solve()?;
    let (mx, my) = options.grid.size();
    let k = s.coefficients;
    let mu_n = contact.mu * contact.normal_force;
    let mut text = format!(
        "fastsim: a = {}, b = {}, G = {}, nu = {}, mu = {}, N = {}; xi = {}, eta = {}, phi = {}\n\
         flexibility {}, bound {}, rolling {}, grid {} {mx} x {my}\n\
         Kalker C11 = {:.4}, C22 = {:.4}, C23 = {:.4}; flexibilities L1 = {:.6e}, L2 = {:.6e}, L3 = {:.6e}\n\
         Fx = {:.6e}, Fy = {:.6e}, Mz = {:.6e} (on body 1, CONTACT's signs)\n",
        contact.a,
        contact.b,
        contact.shear_modulus,
        contact.nu,
        contact.mu,
        contact.normal_force,
        creepages.xi,
        creepages.eta,
        creepages.phi,
        args.flexibility,
        args.bound,
        args.direction,
        if args.contact_grid.is_some() { "CONTACT's rectangle" } else { "strips" },
        k.c11,
        k.c22,
        k.c23,
        s.flexibilities[0],
        s.flexibilities[1],
        s.flexibilities[2],
        s.fx,
        s.fy,
        s.mz,
    );
    if mu_n > 0.0 {
        text += &format!("Fx/(mu N) = {:.6}, Fy/(mu N) = {:.6}\n", s.fx / mu_n, s.fy / mu_n);
    }
    text += &format!(
        "elements: {} in contact, {} adhesion, {} slip; sum pn dA = {:.6e}\n",
        s.n_contact, s.n_adhesion, s.n_slip, s.fn_discrete
    );
    if let Some(path) = &args.json {
        let doc = serde_json::json!({
            "engine": "fastsim",
            "a": contact.a, "b": contact.b, "shear_modulus": contact.shear_modulus, "nu": contact.nu,
            "mu": contact.mu, "normal_force": contact.normal_force,
            "xi": creepages.xi, "eta": creepages.eta, "phi": creepages.phi,
            "flexibility": args.flexibility, "bound": args.bound, "direction": args.direction,
            "mx": mx, "my": my, "contact_grid_scale": args.contact_grid,
            "fx": s.fx, "fy": s.fy, "mz": s.mz, "fn_discrete": s.fn_discrete,
            "n_contact": s.n_contact, "n_adhesion": s.n_adhesion, "n_slip": s.n_slip,
            "flexibilities": s.flexibilities, "coefficients": [k.c11, k.c22, k.c23],
        });
        crate::io::write_output(path, &(doc.to_string() + "\n"))?;
    }
    if let Some(path) = &args.csv {
        let mut csv = String::from("x,y,pn,px,py,state\n");
        for e in &s.elements {
            let state = match e.state {
                State::Exterior => "exterior",
                State::Adhesion => "adhesion",
                State::Slip => "slip",
            };
            csv += &format!("{},{},{},{},{},{state}\n", e.x, e.y, e.pn, e.px, e.py);
        }
        crate::io::write_output(path, &csv)?;
    }
    Ok(text)
}
