//! The report's section on viscoelastic rolling (issue 33): CONTACT's `visc_cylindr` case (two PA6 cylinders,
//! [`crate::viscoelastic`]) swept over the relaxation distance V·τ_C, from instantaneous creep (the elastic body of
//! the relaxed modulus) to frozen creep (that of the glassy modulus): the creepage at the prescribed traction, the
//! peak pressure, the contact's ends, and the rolling resistance, the normal load's moment arm x̄ = Σ x p / Σ p ahead
//! of the contact's centre. Computed afresh by every `rollbem report` (about a second). Falling friction has its own
//! section (`report::veldep`).

use crate::error::Result;
use crate::pipeline::run_scene;
use crate::post::NodeState;
use crate::scene::Scene;
use crate::status::Status;
use std::fmt::Write as _;

/// The creep relaxation times of the sweep (s; V = 1000 mm/s, so V·τ_C in mm is 1000 τ_C): CONTACT's four cases
/// (0, 0.009, 0.045, 2) and points between them.
const CREEP_TIMES: [f64; 10] = [0.0, 0.001, 0.003, 0.006, 0.009, 0.015, 0.025, 0.045, 0.2, 2.0];

/// One row: V·τ_C (mm), creepage, peak pressure, first and last x in contact, pressure centre x̄ (mm).
#[derive(Debug, Clone, Copy)]
struct Row {
    distance: f64,
    creepage: f64,
    pmax: f64,
    ends: (f64, f64),
    centre: f64,
}

/// CONTACT's visc_cylindr.inp on its strip (tests/viscoelastic.rs poses the same), with the creep time `tc`, or
/// elastic with shear modulus `g` when `tc` is `None`.
fn scene(tc: Option<f64>, g: f64) -> Result<Scene> {
    let e = 2.0 * g * 1.4;
    let visc =
        tc.map(|t| format!("viscoelastic = {{ compliance_ratio = 1.0, creep_time = {t:e} }}")).unwrap_or_default();
    let velocity = if tc.is_some() { "velocity = 1000.0" } else { "" };
    let text = format!(
        "name = \"visc-cylindr\"\n[wheel]\nradius = 50\nyoungs_modulus = {e}\npoisson_ratio = 0.4\nmodel = \
         \"half_plane\"\nprofile = \"parabola\"\n{visc}\n[counter_body]\nkind = \"half_plane\"\nyoungs_modulus = \
         {e}\npoisson_ratio = 0.4\n{visc}\n[mesh]\nelement = \"constant\"\ncontact_x = [-8.0, 7.84]\n\
         contact_elements = 99\nstrip_width = 1000\n[contact]\nfriction = 0.3\ncoupling = false\n[drive]\n\
         normal_load = 600\ntangential_load = -108\n[rolling]\nmode = \"steady\"\ndirection = 1\n{velocity}\n\
         [solvers]\nuse = [\"active_set\"]\n"
    );
    Scene::from_toml(&text, std::path::Path::new("<visc-cylindr>"))
}

/// Solve one case; `None` when the run did not solve (the section then says so).
fn row(tc: Option<f64>, g: f64) -> Result<Option<Row>> {
    let report = run_scene(&scene(tc, g)?)?;
    let Some(r) = report.runs.first().filter(|r| r.status == Status::Solved) else { return Ok(None) };
    let contact: Vec<f64> = r.nodes.iter().filter(|n| n.state != NodeState::Separated).map(|n| n.x).collect();
    let (sp, sxp) = r.nodes.iter().fold((0.0, 0.0), |(s, sx), n| (s + n.pressure, sx + n.x * n.pressure));
    Ok(Some(Row {
        distance: tc.map_or(f64::NAN, |t| 1000.0 * t),
        creepage: r.rolling.as_ref().and_then(|x| x.creepage).unwrap_or(f64::NAN),
        pmax: r.nodes.iter().map(|n| n.pressure).fold(0.0, f64::max),
        ends: (contact.first().copied().unwrap_or(f64::NAN), contact.last().copied().unwrap_or(f64::NAN)),
        centre: sxp / sp,
    }))
}

/// The sweep: the elastic body of the relaxed modulus, the viscoelastic rows, the elastic body of the glassy one.
fn rows() -> Result<Vec<(String, Option<Row>)>> {
    let mut out = vec![("elastic, G_r = 571.5".to_string(), row(None, 571.5)?)];
    for tc in CREEP_TIMES {
        out.push((format!("τ_C = {tc} s"), row(Some(tc), 1143.0)?));
    }
    out.push(("elastic, G_g = 1143".to_string(), row(None, 1143.0)?));
    Ok(out)
}

/// Write the section (Markdown) into `md`.
pub(super) fn section(md: &mut String) -> Result<()> {
    let rows = rows()?;
    writeln!(md, "\n## Viscoelastic rolling: rolling resistance against the relaxation distance\n").unwrap();
    writeln!(
        md,
        "CONTACT's `visc_cylindr.inp` (two PA6 cylinders, R = 100 mm each, G_g = 1143 MPa, ν = 0.4, FG = 1, 600 N/mm, \
         Q = −0.6 μP, μ = 0.3, V = 1000 mm/s, its strip of 99 elements), the standard linear solid of Wang & Knothe \
         (`src/viscoelastic.rs`) swept over the creep time τ_C. x̄ is the pressure's centre ahead of the contact's \
         (the normal load's moment arm, the rolling resistance: a resisting moment P·x̄ per unit width). At τ_C = 0 \
         the body is the elastic one of the relaxed modulus, as τ_C grows it tends to the glassy one \
         (tests/viscoelastic.rs checks both limits to 1e-10 and CONTACT's four viscoelastic cases).\n"
    )
    .unwrap();
    writeln!(md, "| case | V·τ_C [mm] | creepage | peak p [MPa] | contact x [mm] | x̄ [mm] | P·x̄ [N·mm/mm] |").unwrap();
    writeln!(md, "|---|---:|---:|---:|---|---:|---:|").unwrap();
    for (name, r) in &rows {
        match r {
            Some(r) => writeln!(
                md,
                "| {name} | {} | {:.4e} | {:.2} | [{:.2}, {:.2}] | {:.4} | {:.1} |",
                if r.distance.is_nan() { "–".to_string() } else { format!("{}", r.distance) },
                r.creepage,
                r.pmax,
                r.ends.0,
                r.ends.1,
                r.centre,
                600.0 * r.centre
            ),
            None => writeln!(md, "| {name} | | not solved | | | | |"),
        }
        .unwrap();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rolling resistance vanishes in both elastic limits (a symmetric pressure: x̄ = 0 to round-off), is
    /// positive between them (the pressure leans towards the leading edge, +x), and peaks at an intermediate
    /// relaxation distance (Hunter's result for the standard linear solid: no dissipation when the material
    /// responds instantly or not at all).
    #[test]
    fn rolling_resistance_peaks_between_the_elastic_limits() {
        let rows = rows().unwrap();
        let x: Vec<f64> = rows.iter().map(|(_, r)| r.unwrap().centre).collect();
        let (first, last) = (x[0], x[x.len() - 1]);
        assert!(first.abs() < 1e-9 && last.abs() < 1e-9, "elastic x̄ {first:e}, {last:e}");
        // τ_C = 0 is the relaxed elastic body: x̄ = 0 too.
        assert!(x[1].abs() < 1e-9, "τ_C = 0: {}", x[1]);
        let visc = &x[2..x.len() - 1];
        assert!(visc.iter().all(|&v| v > 0.0), "{visc:?}");
        let (peak, _) = visc.iter().enumerate().fold((0, 0.0), |(k, m), (i, &v)| if v > m { (i, v) } else { (k, m) });
        assert!(peak > 0 && peak < visc.len() - 1, "peak at the end of the sweep: {visc:?}");
        let mut md = String::new();
        section(&mut md).unwrap();
        assert!(md.contains("| τ_C = 0.009 s | 9 |"), "{md}");
    }
}
