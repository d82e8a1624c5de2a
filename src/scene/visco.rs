//! `viscoelastic = { ... }` of `[wheel]` and `[counter_body]`, and `[rolling] velocity`: their checks and their typed
//! form ([`crate::viscoelastic::StandardLinearSolid`]). A viscoelastic body is posed in steady rolling only (the
//! memory integral of [`crate::viscoelastic`] is the steady state's), on the half-plane model, at a given speed.

use super::document::{CounterBodyTable, SceneDocument, ViscoelasticTable};
use super::{BodyModel, RollingMode};
use crate::error::{Error, Result};
use crate::viscoelastic::StandardLinearSolid;
use std::path::Path;

/// The solid a (checked) table describes with the body's glassy modulus `e_glassy`; `None` without a table (or for
/// an incomplete one, which the checks refuse before).
pub(super) fn solid(table: Option<ViscoelasticTable>, e_glassy: f64) -> Option<StandardLinearSolid> {
    let t = table?;
    match (t.compliance_ratio, t.creep_time, t.relaxed_modulus, t.relaxation_time) {
        (Some(f), Some(tc), None, None) => StandardLinearSolid::new(f, tc).ok(),
        (None, None, Some(er), Some(te)) => StandardLinearSolid::from_relaxation(e_glassy, er, te).ok(),
        _ => None,
    }
}

impl SceneDocument {
    /// The viscoelastic tables and the rolling speed: each table in exactly one parameter set and in range; a
    /// viscoelastic body only on the half-plane model, in steady rolling without a load path, with `[rolling]
    /// velocity`; a velocity only with a viscoelastic body.
    pub(super) fn validate_viscoelastic(&self, path: &Path) -> Result<()> {
        let bad = |field: &str, message: String| Error::Invalid {
            path: path.to_path_buf(),
            field: field.to_string(),
            message,
        };
        let counter = match self.counter_body {
            CounterBodyTable::HalfPlane { viscoelastic, youngs_modulus, .. } => {
                viscoelastic.map(|v| (v, youngs_modulus))
            }
            _ => None,
        };
        let tables = [
            ("wheel.viscoelastic", self.wheel.viscoelastic.map(|v| (v, self.wheel.youngs_modulus))),
            ("counter_body.viscoelastic", counter),
        ];
        let mut any = None;
        for (key, table) in tables {
            let Some((t, e)) = table else { continue };
            check_table(key, &t, e).map_err(|(k, m)| bad(&k, m))?;
            any.get_or_insert(key);
        }
        let velocity = self.rolling.as_ref().and_then(|r| r.velocity);
        let Some(key) = any else {
            return match velocity {
                // A friction law of the slip velocity reads the speed (its checks: super::friction).
                Some(_) if self.contact.friction_law.is_some() => Ok(()),
                Some(_) => Err(bad(
                    "rolling.velocity",
                    "means nothing without a viscoelastic body (`[wheel] viscoelastic` or `[counter_body] \
                     viscoelastic`) or a friction law of the slip velocity (`[contact] friction_law`): an elastic \
                     contact with Coulomb friction does not depend on the speed"
                        .into(),
                )),
                None => Ok(()),
            };
        };
        if self.wheel.model != BodyModel::HalfPlane {
            return Err(bad(
                key,
                "needs wheel.model = \"half_plane\": the viscoelastic memory is built on the half-plane's closed \
                 forms"
                    .into(),
            ));
        }
        let steady = self.rolling.as_ref().is_some_and(|r| r.mode == RollingMode::Steady);
        if !steady || !self.steps.is_empty() {
            return Err(bad(
                key,
                "a viscoelastic body is posed in steady rolling only (`[rolling] mode = \"steady\"`, no `[[steps]]`): \
                 its memory integral is the steady state's"
                    .into(),
            ));
        }
        match velocity {
            None => Err(bad(
                "rolling.velocity",
                "missing: a viscoelastic body rolls at a speed V (length/s), its relaxation distance is V·τ_C".into(),
            )),
            Some(v) if !(v > 0.0 && v.is_finite()) => {
                Err(bad("rolling.velocity", format!("must be a finite number > 0 (got {v})")))
            }
            Some(v) => {
                // Beyond ~1e11 wheel diameters the memory integral's arguments x + Lη lose the element's width to
                // rounding (the kernel turns to noise of its own size); there the creep is frozen to 1e-11.
                let diameter = 2.0 * self.wheel.radius;
                let worst = tables
                    .iter()
                    .filter_map(|(_, t)| *t)
                    .map(|(t, e)| solid(Some(t), e).map_or(0.0, |s| s.creep_time()))
                    .fold(0.0, f64::max);
                if v * worst / diameter > MAX_RELAXATION_DIAMETERS {
                    return Err(bad(
                        "rolling.velocity",
                        format!(
                            "V·τ_C = {:e} is {:.1e} wheel diameters, beyond the {MAX_RELAXATION_DIAMETERS:e} the memory \
                             integral resolves: the creep is frozen, use the elastic body of the glassy modulus \
                             (leave `viscoelastic` out)",
                            v * worst,
                            v * worst / diameter
                        ),
                    ));
                }
                Ok(())
            }
        }
    }
}

/// The largest relaxation distance V·τ_C, in wheel diameters, a scene may pose.
const MAX_RELAXATION_DIAMETERS: f64 = 1e11;

/// One table: exactly one parameter set, each value in range (errors: the dotted key and why).
fn check_table(key: &str, t: &ViscoelasticTable, e_glassy: f64) -> std::result::Result<(), (String, String)> {
    let sub = |k: &str| format!("{key}.{k}");
    let time = |k: &str, v: f64| {
        if v >= 0.0 && v.is_finite() {
            Ok(())
        } else {
            Err((sub(k), format!("must be a finite number ≥ 0 (s) (got {v})")))
        }
    };
    match (t.compliance_ratio, t.creep_time, t.relaxed_modulus, t.relaxation_time) {
        (Some(f), Some(tc), None, None) => {
            if !(f >= 0.0 && f.is_finite()) {
                return Err((sub("compliance_ratio"), format!("must be a finite number ≥ 0 (got {f})")));
            }
            time("creep_time", tc)
        }
        (None, None, Some(er), Some(te)) => {
            if !(er > 0.0 && er <= e_glassy) {
                return Err((
                    sub("relaxed_modulus"),
                    format!(
                        "must lie in (0, E_g], E_g the body's youngs_modulus = {e_glassy} (the glassy modulus) (got \
                         {er})"
                    ),
                ));
            }
            time("relaxation_time", te)
        }
        _ => Err((
            key.to_string(),
            "give exactly one parameter set: `compliance_ratio` and `creep_time` (CONTACT's FG and TC), or \
             `relaxed_modulus` and `relaxation_time` (the stress-relaxation form)"
                .into(),
        )),
    }
}
