//! `[contact] friction_law` (a friction law of the slip velocity, [`crate::veldep`]) and the `[rolling] velocity` it
//! reads: their checks. Every error names the dotted key.
//!
//! A law whose terms are both 0 is a constant, Coulomb's `μ = kinetic`: the scene is then a Coulomb scene (its
//! `friction` is `kinetic`, and nothing of [`crate::veldep`] runs). A falling law (a term not 0) is posed in steady
//! rolling at a prescribed creepage and a given speed, without viscoelastic bodies or a load path; that its pair is
//! uncoupled (the law is solved at the normal problem's pressure) is checked when its model is built
//! (`crate::pipeline`, it needs the flexibility source's rule).

use super::document::{CounterBodyTable, FrictionLawTable, SceneDocument};
use super::RollingMode;
use crate::error::{Error, Result};
use std::path::Path;

impl SceneDocument {
    /// The law's values (finite, μ_kin > 0, each term's coefficient ≥ 0 with its `s_h > 0` when not 0), `friction`
    /// either left out (0) or the law's μ(0), and for a falling law what it is posed with (module docs).
    pub(super) fn validate_friction_law(&self, path: &Path) -> Result<()> {
        let bad =
            |field: &str, message: String| Error::Invalid { path: path.to_path_buf(), field: field.into(), message };
        let Some(t) = self.contact.friction_law else { return Ok(()) };
        check_values(&t).map_err(|(k, m)| bad(&k, m))?;
        let mu0 = t.law().static_coefficient();
        let mu = self.contact.friction;
        if mu != 0.0 && (mu - mu0).abs() > 1e-12 * mu0 {
            return Err(bad(
                "contact.friction",
                format!(
                    "is {mu}, but with `friction_law` the friction is the law's static coefficient μ(0) = {mu0}: leave \
                     `friction` out (or give μ(0))"
                ),
            ));
        }
        if t.is_constant() {
            return Ok(());
        }
        let key = "contact.friction_law";
        let steady = self.rolling.as_ref().filter(|r| r.mode == RollingMode::Steady);
        let Some(rolling) = steady.filter(|_| self.steps.is_empty()) else {
            return Err(bad(
                key,
                "a falling friction law is posed in steady rolling (`[rolling] mode = \"steady\"`, no `[[steps]]`); \
                 transient rolling with it is the library's `rollbem::veldep::transient::roll`"
                    .into(),
            ));
        };
        if rolling.creepage.is_none() || self.drive.tangential_load.is_some() {
            return Err(bad(
                "rolling.creepage",
                "a falling friction law needs the creepage prescribed (`rolling.creepage`, not `drive.tangential_load`): \
                 with friction that falls with the slip velocity a force can belong to several creepages"
                    .into(),
            ));
        }
        match rolling.velocity {
            None => {
                return Err(bad(
                    "rolling.velocity",
                    "missing: a friction law of the slip velocity needs the rolling speed V (length/s); the absolute \
                     slip velocity is V·|s|"
                        .into(),
                ))
            }
            Some(v) if !(v > 0.0 && v.is_finite()) => {
                return Err(bad("rolling.velocity", format!("must be a finite number > 0 (got {v})")))
            }
            Some(_) => {}
        }
        let visco = self.wheel.viscoelastic.is_some()
            || matches!(self.counter_body, CounterBodyTable::HalfPlane { viscoelastic: Some(_), .. });
        if visco {
            return Err(bad(
                key,
                "a falling friction law with a viscoelastic body is not modelled (the law is solved on elastic \
                 bodies)"
                    .into(),
            ));
        }
        Ok(())
    }
}

/// The law's values (errors: the dotted key and why).
fn check_values(t: &FrictionLawTable) -> std::result::Result<(), (String, String)> {
    let key = |k: &str| format!("contact.friction_law.{k}");
    if !(t.kinetic > 0.0 && t.kinetic.is_finite()) {
        return Err((key("kinetic"), format!("must be a finite number > 0 (got {})", t.kinetic)));
    }
    for (name, [c, s]) in [("first", t.first), ("second", t.second)] {
        if !(c >= 0.0 && c.is_finite()) {
            return Err((key(name), format!("its coefficient must be a finite number ≥ 0 (got {c})")));
        }
        if c > 0.0 && !(s > 0.0 && s.is_finite()) {
            return Err((
                key(name),
                format!("its half-value slip velocity must be a finite number > 0 (length/s) (got {s})"),
            ));
        }
        if !s.is_finite() {
            return Err((key(name), format!("its slip velocity must be finite (got {s})")));
        }
    }
    if let Some(m) = t.memory {
        if !(m.distance > 0.0 && m.distance.is_finite()) {
            return Err((key("memory.distance"), format!("must be a finite number > 0 (length) (got {})", m.distance)));
        }
        if !(m.min_velocity >= 0.0 && m.min_velocity.is_finite()) {
            return Err((
                key("memory.min_velocity"),
                format!("must be a finite number ≥ 0 (length/s) (got {})", m.min_velocity),
            ));
        }
    }
    Ok(())
}

/// A friction law's static coefficient μ(0) is the scene's `friction` (what builds the tangential blocks and bounds
/// the shear): filled in as a default; a constant law is thereby Coulomb's μ = kinetic.
pub(super) fn fill_static_coefficient(document: &mut SceneDocument) {
    if let Some(t) = document.contact.friction_law {
        document.contact.friction = t.law().static_coefficient();
    }
}
