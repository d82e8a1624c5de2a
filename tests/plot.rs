//! The plotting module's public API on realistic figures. Set `ROLLBEM_PLOT_EXAMPLES=/some/dir` to keep the SVGs
//! for a look (e.g. `rsvg-convert -w 1100 dir/map.svg -o map.png`).

use std::path::Path;
use std::process::Command;

use rollbem::plot::{Appearance, Chart, ContourMap, Field, PlotError, Series, Style};

fn keep(name: &str, svg: &str) {
    if let Some(dir) = std::env::var_os("ROLLBEM_PLOT_EXAMPLES") {
        std::fs::write(Path::new(&dir).join(name), svg).unwrap();
    }
}

/// McEwen's closed-form subsurface stresses under a 2D Hertz contact of half-width `a = 1` and peak pressure
/// `p0 = 1` (Johnson, Contact Mechanics, eq. 4.75): returns (σx, σz, τxz) at (x, z), z ≥ 0 downward.
fn mcewen(x: f64, z: f64) -> (f64, f64, f64) {
    let k = 1.0 - x * x + z * z;
    let root = (k * k + 4.0 * x * x * z * z).sqrt();
    let m = (0.5 * (root + k)).max(0.0).sqrt();
    let n = (0.5 * (root - k)).max(0.0).sqrt() * x.signum();
    let mn = m * m + n * n;
    if mn == 0.0 {
        return (0.0, 0.0, 0.0); // the contact edges x = ±a on the surface: the stresses vanish there
    }
    let sx = -(m * (1.0 + (z * z + n * n) / mn) - 2.0 * z);
    let sz = -m * (1.0 - (z * z + n * n) / mn);
    let txz = n * (m * m - z * z) / mn;
    (sx, sz, txz)
}

fn principal_shear(x: f64, z: f64) -> f64 {
    let (sx, sz, txz) = mcewen(x, z);
    (0.25 * (sx - sz).powi(2) + txz * txz).sqrt()
}

/// Half-width a = 0.5 mm and peak pressure p0 = 1000 MPa.
const A_MM: f64 = 0.5;
const P0_MPA: f64 = 1000.0;

fn hertz_shear_map() -> ContourMap {
    let field = Field::from_fn(161, 81, (-2.0 * A_MM, 2.0 * A_MM), (0.0, 2.0 * A_MM), |x, z| {
        P0_MPA * principal_shear(x / A_MM, z / A_MM)
    });
    ContourMap::new("Principal shear stress under a 2D Hertz contact (McEwen), a = 0.5 mm, p₀ = 1 GPa", field)
        .x_axis("x", "mm")
        .depth_axis("depth z", "mm")
        .value_axis("τ₁", "MPa")
        .contours(&[50.0, 100.0, 150.0, 200.0, 250.0, 300.0])
        .mark_max()
        .equal_aspect()
}

#[test]
fn hertz_principal_shear_map_has_its_maximum_at_the_textbook_place() {
    let map = hertz_shear_map();
    let (x, z, v) = map.field.max().unwrap();
    // τ₁,max = 0.300 p0 at z = 0.78 a on the axis (Johnson §4.2); the grid spacing is a / 40.
    assert!(x.abs() < 1e-12 && (z / A_MM - 0.78).abs() < 0.026 && (v / P0_MPA - 0.300).abs() < 0.002, "{x} {z} {v}");
    let svg = map.to_svg().unwrap();
    assert_eq!(svg, hertz_shear_map().to_svg().unwrap());
    assert!(svg.contains("max τ₁ = 300.3 MPa at x = 0 mm, depth z = 0.3875 mm"), "caption");
    keep("map-hertz.svg", &svg);
    // The same map with holes, in cividis, not to scale.
    let mut holes = map.clone().colormap(rollbem::plot::ColorMap::Cividis);
    holes.equal_aspect = false;
    for iz in 30..40 {
        for ix in 100..115 {
            holes.field.values[iz * 161 + ix] = f64::NAN;
        }
    }
    holes.title = "Same field with missing values (cividis, not to scale)".into();
    keep("map-holes.svg", &holes.to_svg().unwrap());
}

#[test]
fn fourteen_series_line_chart() {
    let mut chart = Chart::new("Convergence of 14 configurations", "contact elements", "L2 pressure error")
        .x_unit("1")
        .y_unit("1")
        .log_x()
        .log_y();
    for i in 0..14u32 {
        let c = 0.02 * (1.0 + 0.15 * f64::from(i));
        let order = 1.0 + 0.08 * f64::from(i);
        let pts =
            [10.0, 20.0, 40.0, 80.0, 160.0, 320.0].iter().map(|&n: &f64| (n, c * (10.0 / n).powf(order))).collect();
        let solver =
            ["lemke", "clarabel", "pgs τ=1e-3", "pgs τ=1e-5", "pgs τ=1e-8", "pgs τ=1e-10", "qp"][i as usize % 7];
        let kind = if i < 7 { "constant" } else { "quadratic" };
        chart = chart.add(Series::new(format!("{kind} {solver}"), pts, Style::LineMarkers));
    }
    let svg = chart.to_svg().unwrap();
    // 14 different appearances.
    let looks: Vec<Appearance> = (0..14).map(Appearance::for_index).collect();
    for i in 0..14 {
        assert!(!looks[..i].contains(&looks[i]));
    }
    assert!(chart.axes_without_unit().is_empty());
    keep("lines-14.svg", &svg);
}

#[test]
fn loglog_chart_with_units() {
    let ts: Vec<f64> = (0..12).map(|i| 1e-3 * 2f64.powi(i)).collect();
    let chart = Chart::new("Residual against wall time", "wall time", "max |LCP residual| / p₀")
        .x_unit("s")
        .y_unit("1")
        .log_x()
        .log_y()
        .add(Series::new("Lemke", ts.iter().map(|&t| (t, 1e-2 * (1e-3 / t).powi(2))).collect(), Style::LineMarkers))
        .add(Series::new(
            "clarabel (QP)",
            ts.iter().map(|&t| (1.7 * t, 3e-3 * (1e-3 / t).powf(1.5))).collect(),
            Style::LineMarkers,
        ))
        .add(Series::new("projected Gauss-Seidel", ts.iter().map(|&t| (t, 2e-2 * (1e-3 / t))).collect(), Style::Line))
        .add(Series::new("slope −2", vec![(1e-3, 1e-2), (2e-2, 2.5e-5)], Style::Dashed));
    let svg = chart.to_svg().unwrap();
    assert!(svg.contains("wall time [s]") && svg.contains("max |LCP residual| / p₀ [1]"));
    keep("loglog-units.svg", &svg);
}

#[test]
fn categorical_states_chart_with_overlapping_series() {
    let xs: Vec<f64> = (0..23).map(|i| -0.25 + 0.5 * f64::from(i) / 22.0).collect();
    let state = |x: f64, stick: f64| {
        if x.abs() > 0.1 {
            0.0
        } else if x.abs() > stick {
            1.0
        } else {
            2.0
        }
    };
    let mut chart = Chart::new("Node states (seed Figs. 7–10)", "x", "state").x_unit("m").categories_y(&[
        "separated",
        "slip",
        "stick",
    ]);
    for (label, stick) in [("μ = 0.02", -1.0), ("μ = 0.1", -1.0), ("μ = 0.5", 0.035)] {
        chart = chart.add(Series::new(label, xs.iter().map(|&x| (x, state(x, stick))).collect(), Style::Markers));
    }
    let svg = chart.to_svg().unwrap();
    keep("states.svg", &svg);
    // Empty charts stay errors.
    assert!(matches!(Chart::new("e", "x", "y").to_svg(), Err(PlotError::NoFiniteData { .. })));
}

#[test]
fn edge_case_maps_render() {
    // A constant field with a hole: one band, the colour bar round the constant, the hole captioned.
    let mut values = vec![42.0; 30 * 15];
    values[7 * 30 + 10] = f64::NAN;
    let constant = ContourMap::new("Constant field", Field::new(30, 15, values, (0.0, 3.0), (0.0, 1.5)))
        .x_axis("x", "mm")
        .depth_axis("depth", "mm")
        .value_axis("σ", "MPa")
        .contours(&[42.0])
        .mark_max()
        .equal_aspect();
    let svg = constant.to_svg().unwrap();
    assert!(svg.contains("no value"));
    keep("map-constant.svg", &svg);
    // A coarse grid (6 × 4 nodes): bands and lines follow the same straight pieces per cell.
    let coarse = ContourMap::new(
        "Coarse grid, saddle",
        Field::from_fn(6, 4, (-1.0, 1.0), (0.0, 1.0), |x, z| (3.0 * x).sin() * (4.0 * z).cos()),
    )
    .x_axis("x", "mm")
    .depth_axis("depth", "mm")
    .value_axis("v", "1")
    .contours(&[-0.5, 0.0, 0.5])
    .marker(0.0, 0.5, "probe");
    keep("map-coarse.svg", &coarse.to_svg().unwrap());
    // Many bands: the colour bar labels only every few band edges, at round values.
    let fine = hertz_shear_map().bands(40).size(700, 420);
    keep("map-fine-bands.svg", &fine.to_svg().unwrap());
}

/// Issue 12 item 9: `rollbem plot RESULT.json` draws, per run, the tractions (with Hertz's pressure when the result
/// carries it), the node states on a categorical axis and, for a rolling scene, the slip velocity.
#[test]
fn plot_of_a_result_draws_tractions_with_hertz_states_and_slip_velocity() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let tmp = tempfile::tempdir().unwrap();
    let bin = env!("CARGO_BIN_EXE_rollbem");
    let run = |scene: &str, json: &str| {
        let o = std::process::Command::new(bin)
            .args(["run", "--solver", "lemke"])
            .arg(root.join(scene))
            .arg("--json")
            .arg(tmp.path().join(json))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let o = std::process::Command::new(bin).arg("plot").arg(tmp.path().join(json)).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run("reference/scenes/hertz-hub-fine.toml", "h.json");
    let tr = std::fs::read_to_string(tmp.path().join("h.lemke.tractions.svg")).unwrap();
    assert!(tr.contains("Hertz pressure"));
    // The states chart puts one marker per node on its category's row: the markers' rows must hold as many nodes
    // as the result document calls separated and in contact (the document is the peer of the plot).
    let st = std::fs::read_to_string(tmp.path().join("h.lemke.states.svg")).unwrap();
    assert!(st.contains("separated") && st.contains("stick"));
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(tmp.path().join("h.json")).unwrap()).unwrap();
    let nodes = doc["runs"][0]["nodes"].as_array().unwrap();
    let count = |state: &str| nodes.iter().filter(|n| n["state"] == state).count();
    let mut rows: std::collections::BTreeMap<String, usize> = std::collections::BTreeMap::new();
    for circle in st.split("<circle").skip(1) {
        let cy = circle.split("cy=\"").nth(1).unwrap().split('"').next().unwrap().to_string();
        *rows.entry(cy).or_default() += 1;
    }
    let mut sizes: Vec<usize> = rows.values().copied().filter(|&n| n > 1).collect();
    sizes.sort();
    let mut want = vec![count("separated"), count("contact")];
    want.sort();
    assert!(want[0] > 0 && want[1] > 0);
    assert_eq!(sizes, want, "markers per category row (the legend's one marker aside)");
    assert!(!tmp.path().join("h.lemke.slip_velocity.svg").exists(), "no rolling, no slip-velocity figure");
    run("reference/scenes/seed-fig13-mu03.toml", "r.json");
    assert!(tmp.path().join("r.lemke.slip_velocity.svg").exists());
    assert!(tmp.path().join("r.lemke.states.svg").exists());
}

/// `rollbem plot` on a load path's CSV with its scene draws the loop, the stick zone and the approach, with
/// Mindlin–Deresiewicz beside them; on a sweep's CSV it needs the sweep's analysis (not guessed).
#[test]
fn plot_draws_a_path_csv_with_its_theory_and_refuses_a_sweep_csv_without_its_analysis() {
    let dir = tempfile::tempdir().unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/md-fretting-loop.toml");
    let csv = dir.path().join("md.csv");
    let bin = env!("CARGO_BIN_EXE_rollbem");
    let o = Command::new(bin)
        .args(["run", "--quiet", "--solver", "active_set", "--path-csv"])
        .arg(&csv)
        .arg(&scene)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = Command::new(bin).arg("plot").arg(&csv).arg("--scene").arg(&scene).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for what in ["loop", "stick-zone", "approach"] {
        let svg = std::fs::read_to_string(dir.path().join(format!("md-{what}.svg"))).unwrap();
        assert!(svg.contains("active_set"), "{what}: the solver's series");
        if what != "approach" {
            assert!(svg.contains("Mindlin–Deresiewicz"), "{what}: the theory beside it");
        }
    }
    // Without the scene: the same figures, no theory, and the output says so.
    let o = Command::new(bin).arg("plot").arg(&csv).arg("--out").arg(dir.path().join("bare")).output().unwrap();
    assert!(String::from_utf8_lossy(&o.stdout).contains("skipped theory: no --scene given"));
    // A sweep's CSV without --analysis is bad input naming the flag.
    let sweep = dir.path().join("s.csv");
    let keys = vec!["mesh.contact_elements".to_string()];
    std::fs::write(&sweep, rollbem::sweep::row::header(&keys).join(",") + "\n").unwrap();
    let o = Command::new(bin).arg("plot").arg(&sweep).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--analysis"));
}

/// The texts of an SVG as `(text-anchor, content)`.
fn svg_texts(svg: &str) -> Vec<(String, String)> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let (attrs, rest) = t.split_once('>')?;
            let anchor = attrs.split("text-anchor=\"").nth(1)?.split('"').next()?.to_string();
            Some((anchor, rest.split("</text>").next()?.trim().to_string()))
        })
        .collect()
}

/// Issue 31: `rollbem plot` of a load path's CSV draws, as a result document's path does, the fretting loop less its
/// chord (with the elastic compliance in it the loop of md-fretting-loop is a line: a hysteresis 1.4e-3 mm wide
/// inside ±0.047 mm), and the approach the path holds as the constant it is, with tick labels a person can read (it
/// drew the round-off with labels of 18 characters). Expected values: the loop's width computed here from the CSV
/// (the chord through the tips of the first solver's loop, as the figure's definition says).
#[test]
fn plot_of_a_path_csv_draws_the_loop_less_its_chord_and_readable_ticks() {
    let dir = tempfile::tempdir().unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/scenes/md-fretting-loop.toml");
    let csv = dir.path().join("md.csv");
    let bin = env!("CARGO_BIN_EXE_rollbem");
    let o = Command::new(bin).args(["run", "--quiet", "--path-csv"]).arg(&csv).arg(&scene).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The loop's width less its chord, from the CSV: the first solver's (shift, Q) at every substep.
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let first = rows[0][col("solver")];
    let pts: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r[col("solver")] == first)
        .map(|r| (r[col("shift")].parse().unwrap(), r[col("Q")].parse().unwrap()))
        .collect();
    assert!(pts.len() > 40, "the path's substeps");
    let hi = pts.iter().copied().fold((0.0, f64::NEG_INFINITY), |m, p| if p.1 > m.1 { p } else { m });
    let lo = pts.iter().copied().fold((0.0, f64::INFINITY), |m, p| if p.1 < m.1 { p } else { m });
    let slope = (hi.0 - lo.0) / (hi.1 - lo.1);
    let width = pts.iter().map(|&(d, q)| (d - lo.0 - slope * (q - lo.1)).abs()).fold(0.0, f64::max);
    let span = pts.iter().map(|p| p.0.abs()).fold(0.0, f64::max);
    assert!(width > 0.0 && width < 0.05 * span, "a thin loop: width {width:e} in ±{span:e}");

    for scene_arg in [None, Some(&scene)] {
        let out = dir.path().join(if scene_arg.is_some() { "with-scene" } else { "bare" });
        let mut cmd = Command::new(bin);
        cmd.arg("plot").arg(&csv).arg("--out").arg(&out);
        if let Some(s) = scene_arg {
            cmd.arg("--scene").arg(s);
        }
        let o = cmd.output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let svg = |what: &str| std::fs::read_to_string(out.join(format!("md-{what}.svg"))).unwrap();
        // The loop less its chord: every solver's series, with x ticks on the scale of the loop's width (the loop
        // itself has them on the scale of its span, 30 times wider).
        let opened = svg("loop-opened");
        let texts = svg_texts(&opened);
        assert!(texts.iter().any(|(_, t)| t == "md: loop less its chord"), "{texts:?}");
        for solver in ["lemke", "active_set", "pgs"] {
            assert!(texts.iter().any(|(_, t)| t == solver), "{solver} in the legend: {texts:?}");
        }
        assert_eq!(scene_arg.is_some(), opened.contains("Mindlin–Deresiewicz"), "the theory with --scene only");
        let x_ticks = |texts: &[(String, String)]| -> f64 {
            let v: Vec<f64> = texts.iter().filter(|(a, _)| a == "middle").filter_map(|(_, t)| t.parse().ok()).collect();
            assert!(v.len() >= 3, "x ticks: {texts:?}");
            v.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
        };
        let (opened_ticks, loop_ticks) = (x_ticks(&texts), x_ticks(&svg_texts(&svg("loop"))));
        assert!((0.5 * width..=1.5 * width).contains(&opened_ticks), "ticks to {opened_ticks:e}, width {width:e}");
        assert!(loop_ticks > 0.5 * span, "the loop itself: ticks to {loop_ticks:e}, span {span:e}");
        // Tick labels of bounded length in every figure; the held approach drawn as a constant, and said so.
        for what in ["loop", "loop-opened", "stick-zone", "approach"] {
            for (_, t) in svg_texts(&svg(what)) {
                if t.parse::<f64>().is_ok() {
                    assert!(t.chars().count() <= 8, "{what}: tick label `{t}`");
                }
            }
        }
        let approach = svg_texts(&svg("approach"));
        assert!(approach.iter().any(|(_, t)| t.contains("constant to round-off")), "{approach:?}");
    }
}

/// `rollbem plot` on a 3D half-space sweep's CSV (the report's `reports/sweeps/hertz3d-convergence.csv`, whose spec
/// says `analysis = "table"`): `--analysis table` draws its fronts against time, one figure per error measure the
/// CSV carries (it drew nothing before); a 2D analysis on its 3D rows, or `table` on a 2D sweep's CSV, is bad input
/// naming `--analysis` (exit 2) with nothing written (the accuracy analysis used to fail with exit 3 after writing a
/// figure).
#[test]
fn plot_draws_a_3d_sweep_csv_and_refuses_an_analysis_that_does_not_fit_its_rows() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let csv3d = root.join("reports/sweeps/hertz3d-convergence.csv");
    let csv2d = root.join("reports/sweeps/hertz-accuracy.csv");
    let bin = env!("CARGO_BIN_EXE_rollbem");
    let dir = tempfile::tempdir().unwrap();
    let plot = |csv: &Path, analysis: &str, out: &Path| {
        Command::new(bin).arg("plot").arg(csv).args(["--analysis", analysis, "--out"]).arg(out).output().unwrap()
    };
    // The measures the CSV carries, from its header and rows.
    let text = std::fs::read_to_string(&csv3d).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let carried: Vec<&str> = ["hertz_p0_err", "hertz_approach_err", "cm_transfer_err"]
        .into_iter()
        .filter(|m| {
            let i = header.iter().position(|h| h == m).unwrap();
            text.lines().skip(1).any(|l| l.split(',').nth(i).is_some_and(|c| !c.is_empty()))
        })
        .collect();
    assert!(!carried.is_empty());
    let out = dir.path().join("table");
    let o = plot(&csv3d, "table", &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for m in &carried {
        let svg = std::fs::read_to_string(out.join(format!("hertz3d-convergence-{m}-vs-time.svg"))).unwrap();
        assert!(svg.contains("mx"), "{m}: series labelled by their grids");
    }
    for (csv, analysis, says) in
        [(&csv3d, "accuracy", "`table`"), (&csv3d, "creep_curve", "`table`"), (&csv2d, "table", "no half_space rows")]
    {
        let out = dir.path().join(format!("refused-{analysis}"));
        let o = plot(csv, analysis, &out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{analysis}: {err}");
        assert!(err.contains("--analysis") && err.contains(says), "{analysis}: {err}");
        let written = std::fs::read_dir(&out).map(|d| d.count()).unwrap_or(0);
        assert_eq!(written, 0, "{analysis}: nothing written");
    }
}
