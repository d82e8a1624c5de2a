//! The built-in creep engines: FASTSIM ([`Fastsim`]), FaStrip ([`Fastrip`]) and Kalker's linear theory
//! ([`KalkerLinear`]).

use super::{CaseStatus, CreepCase, CreepEngine, CreepResult, EngineEntry, Forces};
use crate::error::ArgumentError;
use crate::fastsim::{self, Bound, Direction, Flexibility, Grid, Options};
use crate::theory::kalker;

/// Kalker's simplified theory by FASTSIM ([`crate::fastsim::solve`]) on `my` strips of `mx` elements (the case's
/// [`super::Resolution`]), with the flexibility and traction bound chosen (default: Kalker's original, one weighted
/// flexibility and the parabolic bound), rolling along +x. Status: [`CaseStatus::GrossSliding`] when every element
/// in contact slips, else [`CaseStatus::Solved`]; Mz is FASTSIM's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fastsim {
    /// The flexibilities.
    pub flexibility: Flexibility,
    /// The traction bound.
    pub bound: Bound,
}

impl Default for Fastsim {
    fn default() -> Fastsim {
        Fastsim { flexibility: Flexibility::Weighted, bound: Bound::Parabolic }
    }
}

impl Fastsim {
    /// The options [`crate::fastsim::solve`] gets for a case.
    pub fn options(&self, case: &CreepCase) -> Options {
        Options {
            bound: self.bound,
            flexibility: self.flexibility,
            direction: Direction::PlusX,
            grid: Grid::Strips { mx: case.resolution.mx, my: case.resolution.my },
        }
    }
}

/// A FASTSIM or FaStrip solution as a table's answer: gross sliding when every element in contact slips.
fn result_of(s: &fastsim::Solution) -> CreepResult {
    let status = if s.n_contact > 0 && s.n_adhesion == 0 { CaseStatus::GrossSliding } else { CaseStatus::Solved };
    CreepResult {
        status,
        forces: Some(Forces { fx: s.fx, fy: s.fy, mz: Some(s.mz) }),
        residual: None,
        contact_elements: Some(s.n_contact),
        slip_elements: Some(s.n_slip),
    }
}

/// The names of the variants in `[options]`.
fn flexibility_name(f: Flexibility) -> &'static str {
    match f {
        Flexibility::Weighted => "weighted",
        Flexibility::Three => "three",
        Flexibility::Blended => "blended",
    }
}

fn bound_name(b: Bound) -> &'static str {
    match b {
        Bound::Parabolic => "parabolic",
        Bound::Elliptic => "elliptic",
    }
}

impl CreepEngine for Fastsim {
    fn name(&self) -> &str {
        "fastsim"
    }

    fn settings(&self) -> String {
        format!("flexibility={} bound={}", flexibility_name(self.flexibility), bound_name(self.bound))
    }

    fn forces(&self, case: &CreepCase) -> Result<CreepResult, ArgumentError> {
        let s = fastsim::solve(&case.contact(), &case.creepages, &self.options(case))?;
        Ok(result_of(&s))
    }
}

/// Builds [`Fastsim`] from `[options]`: `flexibility` (`weighted` | `three` | `blended`), `bound` (`parabolic` |
/// `elliptic`).
fn build_fastsim(options: &toml::Table) -> super::Built {
    let mut engine = Fastsim::default();
    for (key, value) in options {
        let text = value.as_str().ok_or_else(|| (key.clone(), format!("must be a string, is {value}")))?;
        match key.as_str() {
            "flexibility" => engine.flexibility = parse_flexibility(key, text)?,
            "bound" => {
                engine.bound = match text {
                    "parabolic" => Bound::Parabolic,
                    "elliptic" => Bound::Elliptic,
                    _ => return Err((key.clone(), format!("must be parabolic or elliptic, is {text:?}"))),
                }
            }
            _ => return Err((key.clone(), "unknown option of engine fastsim (flexibility, bound)".into())),
        }
    }
    Ok(Box::new(engine))
}

/// FASTSIM's entry in [`super::BUILT_IN`].
pub(super) const FASTSIM_ENTRY: EngineEntry = EngineEntry {
    name: "fastsim",
    describe: "Kalker's FASTSIM (simplified theory); options flexibility = weighted|three|blended, \
               bound = parabolic|elliptic",
    build: build_fastsim,
};

/// FaStrip ([`crate::fastsim::fastrip()`]: FASTSIM, then the strip theory in every strip's adhesion area) on `my`
/// strips of `mx` elements (the case's [`super::Resolution`]), Hertz's pressure as the traction bound, rolling along
/// +x, with the flexibilities chosen (default: CONTACT's blended three, as its M = 5). Status: as [`Fastsim`]'s;
/// Mz is FaStrip's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fastrip {
    /// The flexibilities of the FASTSIM pass.
    pub flexibility: Flexibility,
}

impl Default for Fastrip {
    fn default() -> Fastrip {
        Fastrip { flexibility: Flexibility::Blended }
    }
}

impl CreepEngine for Fastrip {
    fn name(&self) -> &str {
        "fastrip"
    }

    fn settings(&self) -> String {
        format!("flexibility={}", flexibility_name(self.flexibility))
    }

    fn forces(&self, case: &CreepCase) -> Result<CreepResult, ArgumentError> {
        let grid = Grid::Strips { mx: case.resolution.mx, my: case.resolution.my };
        let options =
            Options { bound: Bound::Elliptic, flexibility: self.flexibility, direction: Direction::PlusX, grid };
        let s = fastsim::fastrip(&case.contact(), &case.creepages, &options)?;
        Ok(result_of(&s))
    }
}

/// The flexibility named `text` (`weighted` | `three` | `blended`), or the option's refusal.
fn parse_flexibility(key: &str, text: &str) -> Result<Flexibility, (String, String)> {
    match text {
        "weighted" => Ok(Flexibility::Weighted),
        "three" => Ok(Flexibility::Three),
        "blended" => Ok(Flexibility::Blended),
        _ => Err((key.to_string(), format!("must be weighted, three or blended, is {text:?}"))),
    }
}

/// Builds [`Fastrip`] from `[options]`: `flexibility` (`weighted` | `three` | `blended`).
fn build_fastrip(options: &toml::Table) -> super::Built {
    let mut engine = Fastrip::default();
    for (key, value) in options {
        let text = value.as_str().ok_or_else(|| (key.clone(), format!("must be a string, is {value}")))?;
        match key.as_str() {
            "flexibility" => engine.flexibility = parse_flexibility(key, text)?,
            _ => return Err((key.clone(), "unknown option of engine fastrip (flexibility)".into())),
        }
    }
    Ok(Box::new(engine))
}

/// FaStrip's entry in [`super::BUILT_IN`].
pub(super) const FASTRIP_ENTRY: EngineEntry = EngineEntry {
    name: "fastrip",
    describe: "FaStrip (Sichani et al. 2016: FASTSIM and the strip theory, Hertz's pressure as bound); option \
               flexibility = weighted|three|blended (default blended)",
    build: build_fastrip,
};

/// Kalker's linear theory (no slip; [`crate::theory::kalker`]): `Fx = −G c² C11 ξ`, `Fy = −G c² (C22 η + c C23 φ)`,
/// `Mz = G c³ C23 η` (CONTACT's signs), with C_ij from Table E.3 at the case's a/b and ν. It ignores μ and the
/// grid and never saturates: the reference at vanishing creepage. Mz with spin needs C33, which is not transcribed
/// ([`crate::theory::kalker`]): for φ ≠ 0 Mz is left out. Status: always [`CaseStatus::Solved`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct KalkerLinear;

impl CreepEngine for KalkerLinear {
    fn name(&self) -> &str {
        "kalker_linear"
    }

    fn settings(&self) -> String {
        String::new()
    }

    fn forces(&self, case: &CreepCase) -> Result<CreepResult, ArgumentError> {
        const F: &str = "KalkerLinear::forces";
        for (name, v) in [("shear_modulus", case.shear_modulus), ("a", case.a), ("b", case.b)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(ArgumentError::new(F, name, format!("must be finite and > 0, is {v}")));
            }
        }
        let cr = case.creepages;
        for (name, v) in [("xi", cr.xi), ("eta", cr.eta), ("phi", cr.phi)] {
            if !v.is_finite() {
                return Err(ArgumentError::new(F, name, format!("must be finite, is {v}")));
            }
        }
        let k = kalker::creep_coefficients(case.a, case.b, case.nu)?;
        let (g, c) = (case.shear_modulus, case.size());
        let fx = -g * c * c * k.c11 * cr.xi;
        let fy = -g * c * c * (k.c22 * cr.eta + c * k.c23 * cr.phi);
        let mz = (cr.phi == 0.0).then_some(g * c * c * c * k.c23 * cr.eta);
        Ok(CreepResult {
            status: CaseStatus::Solved,
            forces: Some(Forces { fx, fy, mz }),
            residual: None,
            contact_elements: None,
            slip_elements: None,
        })
    }
}

fn build_kalker_linear(options: &toml::Table) -> super::Built {
    match options.keys().next() {
        Some(key) => Err((key.clone(), "engine kalker_linear takes no options".into())),
        None => Ok(Box::new(KalkerLinear)),
    }
}

/// Kalker's linear theory's entry in [`super::BUILT_IN`].
pub(super) const KALKER_LINEAR_ENTRY: EngineEntry = EngineEntry {
    name: "kalker_linear",
    describe: "Kalker's linear theory (Table E.3 creep coefficients; no slip, no saturation; no Mz with spin)",
    build: build_kalker_linear,
};
