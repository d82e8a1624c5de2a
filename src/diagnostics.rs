//! Numerical health of a scene's flexibility: condition estimates of the source's system (when it has one) and of
//! the contact flexibility, its asymmetry, and warnings when a figure exceeds its threshold in
//! [`crate::tolerances`].

use crate::flexibility::Flexibility;
use crate::results::Diagnostics;
use crate::source::SourceInfo;
use crate::tolerances as tol;

/// ‖K − Kᵀ‖_F / ‖K‖_F / √2: the relative asymmetry of a square matrix (0 for a symmetric one, 1 for a skew one).
pub fn asymmetry(k: &faer::Mat<f64>) -> f64 {
    let n = k.nrows();
    let (mut d, mut s) = (0.0, 0.0);
    for j in 0..n {
        for i in 0..n {
            d += (k[(i, j)] - k[(j, i)]).powi(2);
            s += k[(i, j)].powi(2);
        }
    }
    (d / s.max(f64::MIN_POSITIVE)).sqrt() / 2.0_f64.sqrt()
}

/// κ₁(K_NN) and κ₁(K_TT) of a flexibility, computed on its first call (one LU of each, one at a time) and kept.
/// A solve asks for them before its solvers run, so that their two n × n transients come and go while the heap is
/// clean (after a solve they fragment it: the 841-element curve's peak RSS went from 49 to 67 MB).
pub fn conditions(flex: &Flexibility) -> (f64, Option<f64>) {
    let n = flex.n();
    let cond = |k: &faer::Mat<f64>| crate::condition::cond1(k, &crate::lu::InPlaceLu::new(k.clone()));
    flex.derived
        .conditions(|| (if n > 0 { cond(&flex.k_nn) } else { 0.0 }, flex.k_tt.as_ref().filter(|_| n > 0).map(cond)))
}

/// The health figures and warnings of a flexibility; `asymmetry` is that of the normal flexibility
/// ([`crate::pipeline::stages::normal_asymmetry`]).
pub fn diagnose(flex: &Flexibility, info: &SourceInfo, asymmetry: f64) -> Diagnostics {
    let n = flex.n();
    let (flexibility_condition, tangential_condition) = conditions(flex);
    let mut warnings = Vec::new();
    if let Some(k) = info.condition.filter(|k| k.is_nan() || *k > tol::BEM_CONDITION_WARN) {
        warnings.push(format!(
            "the BEM system is poorly conditioned (κ₁ ≈ {:.2e} > {:.0e}): expect fewer than {} correct digits in F",
            k,
            tol::BEM_CONDITION_WARN,
            (16.0 - k.log10()).max(0.0).floor()
        ));
    }
    for (name, k) in [("normal", Some(flexibility_condition)), ("tangential", tangential_condition)] {
        if let Some(k) = k.filter(|k| k.is_nan() || *k > tol::FLEXIBILITY_CONDITION_WARN) {
            warnings.push(format!(
                "the {name} contact flexibility is poorly conditioned (κ₁ ≈ {k:.2e} > {:.0e})",
                tol::FLEXIBILITY_CONDITION_WARN
            ));
        }
    }
    if let Some(i) = (0..n).find(|&i| flex.k_nn[(i, i)].is_nan() || flex.k_nn[(i, i)] <= 0.0) {
        warnings.push(format!(
            "the normal flexibility is not positive definite (non-positive diagonal at contact node {i}): the mesh is \
             too coarse or distorted to represent the wheel; refine other_elements / contact_elements"
        ));
    }
    if asymmetry > tol::ASYMMETRY_WARN {
        // A source without a BEM system is the half-plane: its asymmetry is the datum's rank-one column term (see
        // [`crate::pipeline::stages::normal_asymmetry`]; measured only when the approach is prescribed), which no mesh removes.
        let what = if info.viscoelastic {
            "it is the viscoelastic memory (a load deforms the material that has passed it, not the material ahead: \
             physics, not the mesh); use lemke or active_set, which do not assume symmetry"
        } else if info.system_size.is_none() {
            "it is the half-plane's datum term (displacements relative to a point at depth datum_depth add the datum's \
             motion under each load to every node: physics, not the mesh), which a prescribed load would absorb \
             into the approach; prescribe the load, or use lemke or active_set, which do not assume symmetry"
        } else {
            "refine the mesh"
        };
        warnings.push(format!(
            "the flexibility is far from symmetric (‖K − Kᵀ‖/‖K‖ = {asymmetry:.2e} > {:.0e}): the QP and PGS solvers \
             assume near symmetry; {what}",
            tol::ASYMMETRY_WARN
        ));
    }
    Diagnostics {
        bem_pivot_ratio: info.pivot_ratio,
        bem_condition: info.condition,
        flexibility_condition,
        tangential_condition,
        flexibility_asymmetry: asymmetry,
        warnings,
    }
}
