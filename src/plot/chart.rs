//! Line and marker charts ([`Chart`]): series of points on linear, logarithmic or categorical axes (a categorical y
//! axis draws state charts: one named state per row), with a legend.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{min_max, says_unit, with_unit, Axis};
use super::draw::*;
use super::legend::*;
use super::prepared::{Prepared, PreparedSeries};
use super::style::{Appearance, Style};
use super::{write_atomic, PlotError};

/// One data series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    pub label: String,
    /// Data points `(x, y)`, drawn in this order.
    pub points: Vec<(f64, f64)>,
    /// How the series is drawn.
    pub style: Style,
    /// Colour, marker and dash; `None` for the automatic [`Appearance::for_index`] of the series' index.
    pub appearance: Option<Appearance>,
}

impl Series {
    /// A series from a label, its points and a style, with the automatic appearance.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Series {
        Series { label: label.into(), points, style, appearance: None }
    }

    /// Draw this series with the given appearance instead of the automatic one.
    pub fn with_appearance(mut self, appearance: Appearance) -> Series {
        self.appearance = Some(appearance);
        self
    }
}

/// Axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Scale {
    /// Linear axis.
    Linear,
    /// Base-10 logarithmic axis; non-positive values are skipped.
    Log10,
}

/// A 2D chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// Title above the plot.
    pub title: String,
    /// Label under the x axis.
    pub x_label: String,
    /// Label left of the y axis (rotated).
    pub y_label: String,
    /// Unit of x, shown as ` [unit]` after the label.
    pub x_unit: Option<String>,
    /// Unit of y, shown as ` [unit]` after the label.
    pub y_unit: Option<String>,
    /// Scale of the x axis.
    pub x_scale: Scale,
    /// Scale of the y axis (ignored when `y_categories` is set).
    pub y_scale: Scale,
    /// Names of the categories of a categorical y axis, at y = 0, 1, …
    pub y_categories: Option<Vec<String>>,
    /// Series, drawn in order; series `i` gets [`Appearance::for_index`]`(i)` unless it has its own.
    pub series: Vec<Series>,
    /// Width in pixels (at least 200).
    pub width: u32,
    /// Height in pixels (at least 150).
    pub height: u32,
}

impl Chart {
    /// A chart with linear axes, 800 × 500 pixels and no series.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Chart {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_unit: None,
            y_unit: None,
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            y_categories: None,
            series: Vec::new(),
            width: 800,
            height: 500,
        }
    }

    /// Use a base-10 logarithmic x axis.
    pub fn log_x(mut self) -> Self {
        self.x_scale = Scale::Log10;
        self
    }

    /// Use a base-10 logarithmic y axis.
    pub fn log_y(mut self) -> Self {
        self.y_scale = Scale::Log10;
        self
    }

    /// The unit of x, shown as `x label [unit]` (use `"1"` or `"–"` for a dimensionless quantity).
    pub fn x_unit(mut self, unit: impl Into<String>) -> Self {
        self.x_unit = Some(unit.into());
        self
    }

    /// The unit of y, shown as `y label [unit]` (use `"1"` or `"–"` for a dimensionless quantity).
    pub fn y_unit(mut self, unit: impl Into<String>) -> Self {
        self.y_unit = Some(unit.into());
        self
    }

    /// A categorical y axis: category `k` is at y = k and is labelled `names[k]`; the only ticks are these.
    /// Data y values are rounded to the nearest category; points outside `0..names.len()` are skipped. Series are
    /// offset slightly in y from one another so that overlapping series stay visible. Overrides a log y scale.
    pub fn categories_y<S: AsRef<str>>(mut self, names: &[S]) -> Self {
        self.y_categories = Some(names.iter().map(|n| n.as_ref().to_string()).collect());
        self
    }

    /// Set the size in pixels (at least 200 × 150).
    pub fn size(mut self, width: u32, height: u32) -> Self {
        self.width = width;
        self.height = height;
        self
    }

    /// Append a series.
    #[allow(clippy::should_implement_trait)] // a builder step, not `+`
    pub fn add(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }

    /// The x axis text: the label with its unit. The drawn text adds to it, for data that need them, the offset
    /// the ticks are labelled from (`d_N − 0.2563705 [mm]`) or a note that the data are one value with round-off.
    pub fn x_axis_text(&self) -> String {
        with_unit(&self.x_label, self.x_unit.as_deref())
    }

    /// The y axis text: the label with its unit (the drawn text may add to it, as for [`Chart::x_axis_text`]).
    pub fn y_axis_text(&self) -> String {
        with_unit(&self.y_label, self.y_unit.as_deref())
    }

    /// The axes (`"x"`, `"y"`) whose text names no unit (no trailing `[…]`); a categorical axis needs none.
    pub fn axes_without_unit(&self) -> Vec<&'static str> {
        let mut out = Vec::new();
        if !says_unit(&self.x_axis_text()) {
            out.push("x");
        }
        if self.categories().is_none() && !says_unit(&self.y_axis_text()) {
            out.push("y");
        }
        out
    }

    fn categories(&self) -> Option<&[String]> {
        self.y_categories.as_deref().filter(|c| !c.is_empty())
    }

    /// Render to an SVG string (deterministic: same data → byte-identical SVG).
    pub fn to_svg(&self) -> Result<String, PlotError> {
        if self.width < MIN_SIZE.0 || self.height < MIN_SIZE.1 {
            return Err(PlotError::TooSmall { title: self.title.clone(), width: self.width, height: self.height });
        }
        let prepared = self.prepare()?;
        let mut svg = String::new();
        self.draw(&prepared, &mut svg).map_err(|message| PlotError::Render { title: self.title.clone(), message })?;
        Ok(svg)
    }

    /// Write the SVG atomically (temp file in the same folder + rename).
    pub fn write(&self, path: &Path) -> Result<(), PlotError> {
        write_atomic(path, &self.to_svg()?)
    }

    /// Filter and transform the data; compute ranges and ticks.
    fn prepare(&self) -> Result<Prepared, PlotError> {
        let cats = self.categories();
        let xlog = self.x_scale == Scale::Log10;
        let ylog = cats.is_none() && self.y_scale == Scale::Log10;
        let mut any_finite = false;
        let mut lost_series = Vec::new();
        let mut series = Vec::new();
        for (i, s) in self.series.iter().enumerate() {
            let mut segments: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            let mut lost = false;
            for &(x, y) in &s.points {
                let p = if !(x.is_finite() && y.is_finite()) {
                    None
                } else {
                    any_finite = true;
                    let y = match cats {
                        Some(c) => Some(y.round()).filter(|k| *k >= 0.0 && *k < c.len() as f64),
                        None => Some(y).filter(|y| !ylog || *y > 0.0),
                    };
                    let x = Some(x).filter(|x| !xlog || *x > 0.0);
                    lost |= x.is_none() || y.is_none();
                    x.zip(y)
                };
                if let Some((x, y)) = p {
                    let p = (if xlog { x.log10() } else { x }, if ylog { y.log10() } else { y });
                    segments.last_mut().expect("never empty").push(p);
                } else if !segments.last().expect("never empty").is_empty() {
                    segments.push(Vec::new());
                }
            }
            segments.retain(|seg| !seg.is_empty());
            if lost {
                lost_series.push(s.label.clone());
            }
            if !segments.is_empty() {
                series.push(PreparedSeries { index: i, segments });
            }
        }
        if series.is_empty() {
            let title = self.title.clone();
            return Err(match (any_finite, cats.is_some()) {
                (false, _) => PlotError::NoFiniteData { title },
                (true, true) => PlotError::OutsideCategories { title, series: lost_series },
                (true, false) => PlotError::NoPositiveData { title, series: lost_series },
            });
        }
        let pts = || series.iter().flat_map(|s| s.segments.iter().flatten());
        let (xmin, xmax) = min_max(pts().map(|p| p.0));
        let (ymin, ymax) = min_max(pts().map(|p| p.1));
        let x_target = (self.width / 100).clamp(3, 10) as usize;
        let y_target = (self.height / 60).clamp(3, 10) as usize;
        let x = if xlog { Axis::log(xmin, xmax, x_target) } else { Axis::linear(xmin, xmax, x_target) };
        let y = match cats {
            Some(c) => Axis::categorical(c),
            None if ylog => Axis::log(ymin, ymax, y_target),
            None => Axis::linear(ymin, ymax, y_target),
        };
        // Categorical: series k of m is shifted by (k - (m-1)/2)·δ so that coinciding points stay visible.
        let m = series.len();
        let delta = if cats.is_some() { (0.36 / m as f64).min(0.12) } else { 0.0 };
        let offsets = (0..m).map(|k| (k as f64 - (m as f64 - 1.0) / 2.0) * delta).collect();
        Ok(Prepared { series, x, y, offsets })
    }

    /// Draw the prepared data into `svg`: the frame (title, grid, ticks, axis texts), the series over it, then the
    /// legend. The legend is planned first, because a legend beside the plot takes width from it.
    fn draw(&self, prep: &Prepared, svg: &mut String) -> Result<(), String> {
        let (width, height) = (self.width, self.height);
        let root = SVGBackend::with_string(svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let frame = self.frame(prep);
        let items = self.legend_items(prep);
        let est_pw = f64::from(width) - f64::from(MARGIN) - f64::from(frame.y_area) - 30.0;
        let est_ph = f64::from(height) - 2.0 * f64::from(MARGIN) - frame.title_h - f64::from(frame.x_area);
        let legend = plan_legend(&items, prep, est_pw, est_ph, f64::from(width));
        let margin_right = match legend.place {
            LegendPlace::Outside => (legend.w + 25.0).ceil() as u32,
            _ => 30,
        };
        let chart = self.draw_frame(&root, prep, &frame, margin_right)?;
        self.draw_series(&root, &chart, prep)?;
        if !items.is_empty() {
            let (xr, yr) = chart.plotting_area().get_pixel_range();
            draw_legend(&root, &items, &legend, legend.origin(&xr, &yr))?;
        }
        root.present().map_err(|e| err(&e))?;
        Ok(())
    }

    /// The room the frame takes around the plot: tick labels and axis texts, and the title.
    fn frame(&self, prep: &Prepared) -> Frame {
        // The axes' texts as drawn: with the offset their ticks are labelled from and a note on constant data.
        let x_text = prep.x.text(&self.x_label, self.x_unit.as_deref());
        let y_text = if self.categories().is_some() {
            self.y_axis_text()
        } else {
            prep.y.text(&self.y_label, self.y_unit.as_deref())
        };
        let y_tick_w = prep.y.bold.iter().map(|v| text_width(&prep.y.label(*v), TICK_SIZE)).fold(0.0, f64::max) + 14.0;
        let y_desc_w = if y_text.is_empty() { 0.0 } else { DESC_SIZE * 1.5 };
        let y_area = (y_tick_w + y_desc_w).ceil() as u32;
        let x_tick_h = TICK_SIZE * 1.2 + 8.0;
        let x_desc_h = if x_text.is_empty() { 0.0 } else { DESC_SIZE * 1.5 };
        let x_area = (x_tick_h + x_desc_h).ceil() as u32;
        let title_h = if self.title.is_empty() { 0.0 } else { TITLE_SIZE * 1.5 };
        Frame { x_text, y_text, y_area, y_desc_w, x_area, x_tick_h, x_desc_h, title_h }
    }

    /// The legend entries: the drawn series that have a label, in order, with their appearance.
    fn legend_items(&self, prep: &Prepared) -> Vec<LegendItem> {
        prep.series
            .iter()
            .map(|ps| (ps, &self.series[ps.index]))
            .filter(|(_, s)| !s.label.is_empty())
            .map(|(ps, s)| LegendItem {
                label: s.label.clone(),
                appearance: s.appearance.unwrap_or_else(|| Appearance::for_index(ps.index)),
                style: s.style,
            })
            .collect()
    }

    /// Draw the frame: the title, the grid with its tick labels, and the axis texts (`margin_right` leaves room for
    /// a legend beside the plot). Returns the chart's coordinates.
    fn draw_frame<'a, 'b>(
        &self,
        root: &'a DrawingArea<SVGBackend<'b>, Shift>,
        prep: &Prepared,
        frame: &Frame,
        margin_right: u32,
    ) -> Result<ChartCoords<'a, 'b>, String> {
        let width = self.width;
        let x_fmt = |v: &f64| prep.x.label(*v);
        let y_fmt = |v: &f64| prep.y.label(*v);
        let mut builder = ChartBuilder::on(root);
        builder
            .margin(MARGIN)
            .margin_right(margin_right)
            .x_label_area_size(frame.x_area)
            .y_label_area_size(frame.y_area);
        if !self.title.is_empty() {
            // The caption is centred over the area left of a legend placed outside: fit it to that width.
            let avail = f64::from(width) - 2.0 * f64::from(MARGIN) - f64::from(margin_right) + 20.0;
            builder.caption(&self.title, (FONT, fit_font(TITLE_SIZE, &self.title, avail.max(100.0))));
        }
        let mut chart = builder.build_cartesian_2d(prep.x.clone(), prep.y.clone()).map_err(|e| err(&e))?;
        let mut mesh = chart.configure_mesh();
        mesh.bold_line_style(RGBColor(200, 200, 200).stroke_width(1))
            .light_line_style(RGBColor(235, 235, 235).stroke_width(1))
            .axis_style(BLACK.stroke_width(1))
            .label_style((FONT, TICK_SIZE))
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt)
            .draw()
            .map_err(|e| err(&e))?;

        let (xr, yr) = chart.plotting_area().get_pixel_range();
        let (x_text, y_text) = (&frame.x_text, &frame.y_text);
        if !x_text.is_empty() {
            let size = fit_font(DESC_SIZE, x_text, f64::from(xr.end - xr.start));
            let y = f64::from(yr.end) + frame.x_tick_h + frame.x_desc_h / 2.0;
            text(root, x_text, ((xr.start + xr.end) / 2, y.round() as i32), size, Anchor::Center, false)?;
        }
        if !y_text.is_empty() {
            let size = fit_font(DESC_SIZE, y_text, f64::from(yr.end - yr.start));
            let x = f64::from(xr.start) - f64::from(frame.y_area) + frame.y_desc_w / 2.0;
            text(root, y_text, (x.round() as i32, (yr.start + yr.end) / 2), size, Anchor::Center, true)?;
        }
        Ok(chart)
    }

    /// Draw each series: its line (broken where points were skipped, with its dash pattern) and its markers,
    /// offset in y on a categorical axis.
    fn draw_series(
        &self,
        root: &DrawingArea<SVGBackend<'_>, Shift>,
        chart: &ChartCoords<'_, '_>,
        prep: &Prepared,
    ) -> Result<(), String> {
        for (k, ps) in prep.series.iter().enumerate() {
            let s = &self.series[ps.index];
            let app = s.appearance.unwrap_or_else(|| Appearance::for_index(ps.index));
            let off = prep.offsets[k];
            let px = |&(x, y): &(f64, f64)| {
                let p = chart.backend_coord(&(x, y + off));
                (f64::from(p.0), f64::from(p.1))
            };
            if s.style.has_line() {
                let pattern = app.line_dash(s.style).pattern();
                for seg in &ps.segments {
                    let pts: Vec<(f64, f64)> = seg.iter().map(px).collect();
                    draw_dashed(root, &pts, &pattern, app.color.color())?;
                }
            }
            if s.style.has_markers() {
                for p in ps.segments.iter().flatten() {
                    draw_marker(root, px(p), app.marker, app.color.color(), MARKER_SIZE)?;
                }
            }
        }
        Ok(())
    }
}

/// The coordinates of a drawn chart: plotters' chart over the figure, with our axes.
type ChartCoords<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<Axis, Axis>>;

/// The frame of a chart around its plot, in pixels: room for the tick labels and axis texts, and the title.
struct Frame {
    /// The x axis text with its unit.
    pub(super) x_text: String,
    /// The y axis text with its unit.
    pub(super) y_text: String,
    /// Width left of the plot: tick labels and the y axis text.
    pub(super) y_area: u32,
    /// Width of the y axis text's column.
    pub(super) y_desc_w: f64,
    /// Height under the plot: tick labels and the x axis text.
    pub(super) x_area: u32,
    /// Height of the x tick labels' row.
    pub(super) x_tick_h: f64,
    /// Height of the x axis text's row.
    pub(super) x_desc_h: f64,
    /// Height of the title (0 without one).
    pub(super) title_h: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::style::{Dash, Marker, PALETTE};
    use crate::plot::test_support::*;

    #[test]
    fn data_constant_to_round_off_and_data_that_need_an_offset_keep_short_tick_labels() {
        // Expected: a path's held approach (one value, its last digits round-off) is drawn as that value, the y axis
        // saying so; a real spread of 4e-8 on 0.2564 is labelled from the offset the axis names. No tick label is
        // longer than 8 characters either way (the round-off was labelled 0.2563705365911895, …).
        let held: Vec<(f64, f64)> =
            (0..6).map(|k| (f64::from(k), 0.2563705365911895 + f64::from(k % 3) * 5.6e-17)).collect();
        let moving: Vec<(f64, f64)> = (0..6).map(|k| (f64::from(k), 0.25637052 + 8e-9 * f64::from(k))).collect();
        for (points, axis_text) in
            [(held, "approach d_N [mm]: 0.2563705, constant to round-off"), (moving, "approach d_N − 0.2563705 [mm]")]
        {
            let chart = Chart::new("approach", "substep", "approach d_N").x_unit("1").y_unit("mm");
            let svg = chart.add(Series::new("lemke", points, Style::LineMarkers)).to_svg().unwrap();
            let t = texts(&svg);
            assert!(t.iter().any(|x| x == axis_text), "{t:?}");
            let ticks: Vec<&String> = t.iter().filter(|x| x.parse::<f64>().is_ok()).collect();
            assert!(ticks.len() >= 6 && ticks.iter().all(|x| x.len() <= 8), "{ticks:?}");
        }
    }

    fn circles() -> Appearance {
        Appearance { color: PALETTE[2], marker: Marker::Circle, dash: Dash::Solid }
    }

    fn linear_chart() -> Chart {
        let xs: Vec<f64> = (0..=20).map(|i| -1.0 + 0.1 * f64::from(i)).collect();
        Chart::new("Contact pressure", "x / a", "p / p0")
            .add(Series::new("Hertz", xs.iter().map(|&x| (x, (1.0 - x * x).max(0.0).sqrt())).collect(), Style::Dashed))
            .add(
                Series::new(
                    "BEM",
                    xs.iter().step_by(2).map(|&x| (x, 0.98 * (1.0 - x * x).sqrt())).collect(),
                    Style::Markers,
                )
                .with_appearance(circles()),
            )
            .add(Series::new("BEM (line)", vec![(-0.5, 0.5), (0.0, 0.9), (0.5, 0.5)], Style::LineMarkers))
            .add(Series::new("shear <q> & co", vec![(-1.0, 0.0), (1.0, 0.2)], Style::Line))
    }

    fn loglog_chart() -> Chart {
        Chart::new("Error vs time", "time [s]", "relative error")
            .log_x()
            .log_y()
            .add(Series::new("Lemke", vec![(1e-3, 1e-2), (1e-2, 1e-4), (1e-1, 1e-6)], Style::LineMarkers))
            .add(Series::new("clarabel", vec![(2e-3, 5e-3), (3e-2, 5e-5)], Style::Markers))
            .add(Series::new("slope -2", vec![(1e-3, 1e-2), (1e-1, 1e-6)], Style::Dashed))
    }

    #[test]
    fn linear_chart_has_text_markers_and_is_deterministic() {
        let chart = linear_chart();
        let svg = chart.to_svg().unwrap();
        let t = texts(&svg);
        for label in ["Contact pressure", "x / a", "p / p0", "Hertz", "BEM", "BEM (line)", "shear <q> & co"] {
            assert!(t.iter().any(|s| s == label), "missing text {label:?} in {t:?}");
        }
        // Tick labels are text too.
        assert!(t.iter().any(|s| s == "0.0" || s == "0"), "{t:?}");
        // One circle per marker point of "BEM" (11), plus its legend icon.
        assert_eq!(count(&svg, "<circle"), 11 + 1);
        // "BEM (line)" (series 2) has triangles: 3 points plus the legend icon.
        assert_eq!(count(&svg, "<polygon"), 3 + 1);
        assert_eq!(svg, chart.to_svg().unwrap());
        assert_eq!(svg, linear_chart().to_svg().unwrap());
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    }

    #[test]
    fn loglog_chart_has_text_markers_and_is_deterministic() {
        let chart = loglog_chart();
        let svg = chart.to_svg().unwrap();
        let t = texts(&svg);
        for label in ["Error vs time", "time [s]", "relative error", "Lemke", "clarabel", "slope -2"] {
            assert!(t.iter().any(|s| s == label), "missing text {label:?} in {t:?}");
        }
        // Decade labels: x spans 1e-3..1e-1, y spans 1e-6..1e-2.
        for label in ["10⁻³", "10⁻²", "10⁻¹", "10⁻⁶", "10⁻²"] {
            assert!(t.iter().any(|s| s == label), "missing tick {label:?} in {t:?}");
        }
        // Lemke (series 0): circles at 3 points + legend.
        assert_eq!(count(&svg, "<circle"), 3 + 1);
        assert_eq!(svg, chart.to_svg().unwrap());
    }

    #[test]
    fn units_are_appended_once() {
        assert_eq!(with_unit("x", Some("mm")), "x [mm]");
        assert_eq!(with_unit("x [mm]", Some("mm")), "x [mm]");
        assert_eq!(with_unit("x", None), "x");
        assert_eq!(with_unit("", Some("s")), "[s]");
        assert_eq!(with_unit("x", Some(" ")), "x");
        let chart = Chart::new("t", "time", "error").x_unit("s");
        assert_eq!(chart.x_axis_text(), "time [s]");
        assert_eq!(chart.axes_without_unit(), vec!["y"]);
        let chart = chart.y_unit("1");
        assert!(chart.axes_without_unit().is_empty());
        let svg = chart.add(Series::new("s", vec![(1.0, 2.0), (2.0, 3.0)], Style::Line)).to_svg().unwrap();
        let t = texts(&svg);
        assert!(t.iter().any(|s| s == "time [s]") && t.iter().any(|s| s == "error [1]"), "{t:?}");
        // A categorical axis needs no unit.
        assert_eq!(Chart::new("t", "x [m]", "state").categories_y(&["a", "b"]).axes_without_unit(), Vec::<&str>::new());
    }

    #[test]
    fn long_axis_labels_are_shrunk_to_fit() {
        let long = "a very long axis description that would never fit at the normal size of the axis labels [mm]";
        let svg = Chart::new("t", long, long)
            .size(400, 300)
            .add(Series::new("s", vec![(0.0, 0.0), (1.0, 1.0)], Style::Line))
            .to_svg()
            .unwrap();
        // Both descriptions are drawn, in a font smaller than the default 18 (written as 18 / 1.24).
        let sizes: Vec<f64> = svg
            .split("<text")
            .skip(1)
            .filter(|t| t.contains(long))
            .map(|t| {
                let i = t.find("font-size=\"").unwrap() + 11;
                t[i..i + t[i..].find('"').unwrap()].parse().unwrap()
            })
            .collect();
        assert_eq!(sizes.len(), 2);
        assert!(sizes.iter().all(|s| *s < 18.0 / 1.24 - 1.0), "{sizes:?}");
    }

    fn states_chart() -> Chart {
        // x in whole millimetres, so that no x tick is fractional either.
        let xs: Vec<f64> = (0..=20).map(f64::from).collect();
        let state = |x: f64, c: f64| {
            if (x - 10.0).abs() > 8.0 {
                0.0
            } else if (x - 10.0).abs() > c {
                1.0
            } else {
                2.0
            }
        };
        let mut chart = Chart::new("States", "x", "state").x_unit("mm").categories_y(&["separated", "slip", "stick"]);
        for (k, c) in [0.0, 2.0, 4.0].iter().enumerate() {
            chart = chart.add(Series::new(
                format!("μ = {k}"),
                xs.iter().map(|&x| (x, state(x, *c))).collect(),
                Style::Markers,
            ));
        }
        chart
    }

    #[test]
    fn categorical_axis_ticks_only_at_integers() {
        let a = Axis::categorical(&["separated".into(), "slip".into(), "stick".into()]);
        assert_eq!(a.bold, vec![0.0, 1.0, 2.0]);
        assert!(a.light.is_empty());
        assert_eq!((a.lo, a.hi), (-0.5, 2.5));
        assert_eq!(a.label(1.0), "slip");
        let chart = states_chart();
        let prep = chart.prepare().unwrap();
        assert_eq!(prep.y.bold, vec![0.0, 1.0, 2.0]);
        // Every drawn y is an integer category; the series are offset symmetrically by less than half a unit.
        for s in &prep.series {
            assert!(s.segments.iter().flatten().all(|p| p.1.fract() == 0.0));
        }
        assert_eq!(prep.offsets.len(), 3);
        assert!(prep.offsets[0] < 0.0 && prep.offsets[1] == 0.0 && prep.offsets[2] > 0.0);
        assert!(prep.offsets.iter().all(|o| o.abs() < 0.25));
        let svg = chart.to_svg().unwrap();
        let t = texts(&svg);
        for name in ["separated", "slip", "stick"] {
            assert!(t.iter().any(|s| s == name), "{t:?}");
        }
        for frac in ["0.5", "1.5", "2.0", "1.0"] {
            assert!(!t.iter().any(|s| s == frac), "fractional tick {frac} in {t:?}");
        }
        // Codes that were offset by the caller round back to their category; codes outside are skipped.
        let c = Chart::new("t", "x", "s").categories_y(&["a", "b"]).add(Series::new(
            "s",
            vec![(0.0, 1.06), (1.0, 0.12), (2.0, 5.0)],
            Style::Markers,
        ));
        let p = c.prepare().unwrap();
        assert_eq!(p.series[0].segments, vec![vec![(0.0, 1.0), (1.0, 0.0)]]);
        let e = Chart::new("t", "x", "s")
            .categories_y(&["a"])
            .add(Series::new("far", vec![(0.0, 3.0)], Style::Markers))
            .to_svg()
            .unwrap_err();
        assert!(matches!(e, PlotError::OutsideCategories { .. }), "{e}");
        assert_eq!(svg, states_chart().to_svg().unwrap());
    }

    #[test]
    fn extreme_ranges_do_not_hang_or_panic() {
        for pts in [vec![(-1e308, -1e308), (1e308, 1e308)], vec![(1.0, 1.0), (1.0 + 1e-15, 1.0 + 2e-15)]] {
            Chart::new("t", "x", "y").add(Series::new("s", pts, Style::LineMarkers)).to_svg().unwrap();
        }
        let svg = Chart::new("t", "x", "y")
            .log_x()
            .log_y()
            .add(Series::new("s", vec![(1e-300, f64::MIN_POSITIVE), (1e300, f64::MAX)], Style::Line))
            .to_svg()
            .unwrap();
        assert!(texts(&svg).iter().any(|s| s == "10³⁰⁰"));
    }

    #[test]
    fn non_finite_points_are_skipped() {
        let clean = Chart::new("t", "x", "y").add(Series::new("s", vec![(0.0, 1.0), (1.0, 2.0)], Style::Markers));
        let dirty = Chart::new("t", "x", "y").add(Series::new(
            "s",
            vec![(0.0, 1.0), (f64::NAN, 5.0), (1.0, 2.0), (2.0, f64::INFINITY), (f64::NEG_INFINITY, 0.0)],
            Style::Markers,
        ));
        let svg = dirty.to_svg().unwrap();
        assert_eq!(count(&svg, "<circle"), 2 + 1);
        // The skipped points do not stretch the axes: same picture as without them.
        assert_eq!(svg, clean.to_svg().unwrap());
        assert!(!svg.contains("NaN") && !svg.contains("inf"));
    }

    #[test]
    fn line_breaks_at_skipped_points() {
        let chart = Chart::new("t", "x", "y").log_y().add(Series::new(
            "s",
            vec![(0.0, 1.0), (1.0, 2.0), (2.0, 0.0), (3.0, 3.0), (4.0, 4.0)],
            Style::Line,
        ));
        let svg = chart.to_svg().unwrap();
        // Two data polylines plus the legend's sample line.
        let data_lines = count(&svg, "<polyline") - count(&chart_without_series().to_svg().unwrap(), "<polyline");
        assert_eq!(data_lines, 2 + 1);
    }

    fn chart_without_series() -> Chart {
        // Same axes as `line_breaks_at_skipped_points` but an invisible, unlabelled series.
        Chart::new("t", "x", "y").log_y().add(Series::new("", vec![(0.0, 1.0), (4.0, 4.0)], Style::Markers))
    }

    #[test]
    fn log_axis_skips_zero_and_drops_emptied_series_from_legend() {
        let chart = Chart::new("t", "x", "y")
            .log_y()
            .add(Series::new("has zero", vec![(1.0, 0.0), (2.0, 10.0), (3.0, 100.0)], Style::Markers))
            .add(Series::new("all negative", vec![(1.0, -1.0), (2.0, 0.0)], Style::Markers));
        let svg = chart.to_svg().unwrap();
        let t = texts(&svg);
        assert!(t.iter().any(|s| s == "has zero"));
        assert!(!t.iter().any(|s| s == "all negative"));
        assert_eq!(count(&svg, "<circle"), 2 + 1);
    }

    #[test]
    fn empty_charts_are_errors() {
        let e = Chart::new("empty", "x", "y").to_svg().unwrap_err();
        assert!(matches!(e, PlotError::NoFiniteData { .. }), "{e}");
        let e =
            Chart::new("nan", "x", "y").add(Series::new("s", vec![(f64::NAN, 1.0)], Style::Line)).to_svg().unwrap_err();
        assert!(matches!(e, PlotError::NoFiniteData { .. }), "{e}");
        let e = Chart::new("neg", "x", "y")
            .log_x()
            .add(Series::new("gap", vec![(-1.0, 1.0), (0.0, 2.0)], Style::Line))
            .to_svg()
            .unwrap_err();
        assert!(matches!(&e, PlotError::NoPositiveData { series, .. } if series == &["gap".to_string()]), "{e}");
        assert!(e.to_string().contains("\"gap\""), "{e}");
        let mut small = linear_chart();
        small.width = 10;
        assert!(matches!(small.to_svg(), Err(PlotError::TooSmall { .. })));
    }

    #[test]
    fn write_is_atomic_and_leaves_no_temp_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("chart.svg");
        let chart = loglog_chart();
        chart.write(&path).unwrap();
        // Overwrite in place.
        chart.write(&path).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), chart.to_svg().unwrap());
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("chart.svg")]);
        // A missing folder is an I/O error naming the path.
        let bad = dir.path().join("missing").join("c.svg");
        let e = chart.write(&bad).unwrap_err();
        assert!(matches!(e, PlotError::Io { .. }) && e.to_string().contains("missing"), "{e}");
        // An empty chart writes nothing.
        assert!(Chart::new("e", "x", "y").write(&dir.path().join("e.svg")).is_err());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    /// Realistic examples; set `ROLLBEM_PLOT_EXAMPLES=/some/dir` to keep the SVGs for a look.
    #[test]
    fn realistic_examples_render() {
        let ts: Vec<f64> = (0..12).map(|i| 1e-3 * 2f64.powi(i)).collect();
        let errors = Chart::new("Residual vs wall time", "wall time [s]", "max |LCP residual| / p0")
            .y_unit("1")
            .log_x()
            .log_y()
            .add(Series::new("Lemke", ts.iter().map(|&t| (t, 1e-2 * (1e-3 / t).powi(2))).collect(), Style::LineMarkers))
            .add(Series::new(
                "clarabel (QP)",
                ts.iter().map(|&t| (1.7 * t, 3e-3 * (1e-3 / t).powf(1.5))).collect(),
                Style::LineMarkers,
            ))
            .add(Series::new(
                "projected Gauss-Seidel",
                ts.iter().map(|&t| (t, 2e-2 * (1e-3 / t))).collect(),
                Style::Line,
            ));
        let a = 1.0;
        let nodes: Vec<f64> = (0..40).map(|i| -1.4 + 2.8 * (f64::from(i) + 0.5) / 40.0).collect();
        let pressure = Chart::new("Contact pressure, R = 0.5 m, P = 1 kN/mm", "x [mm]", "p [MPa]")
            .add(Series::new(
                "Hertz (analytic)",
                (0..=200)
                    .map(|i| -1.5 + 3.0 * f64::from(i) / 200.0)
                    .map(|x| (x, 120.0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt()))
                    .collect(),
                Style::Dashed,
            ))
            .add(Series::new(
                "BEM, 40 elements",
                nodes.iter().map(|&x| (x, 118.0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt())).collect(),
                Style::Markers,
            ));
        for (name, chart) in [("errors.svg", &errors), ("pressure.svg", &pressure)] {
            let svg = chart.to_svg().unwrap();
            assert!(texts(&svg).iter().any(|s| s == &chart.title));
            assert!(chart.axes_without_unit().is_empty(), "{name}");
            if let Some(dir) = std::env::var_os("ROLLBEM_PLOT_EXAMPLES") {
                chart.write(&Path::new(&dir).join(name)).unwrap();
            }
        }
    }
}
