//! Small, deterministic SVG charts (line / marker plots) on top of `plotters`.
//!
//! ```no_run
//! use rollbem::plot::{Chart, Series, Style};
//! let chart = Chart::new("Error vs time", "t [s]", "error")
//!     .log_x()
//!     .log_y()
//!     .add(Series::new("Lemke", vec![(1e-3, 1e-2), (1e-2, 1e-5)], Style::LineMarkers))
//!     .add(Series::new("slope 2", vec![(1e-3, 1e-2), (1e-2, 1e-4)], Style::Dashed));
//! chart.write(std::path::Path::new("error.svg")).unwrap();
//! ```
//!
//! Text (title, axis labels, tick labels, legend) is emitted as SVG `<text>` elements with
//! `font-family="sans-serif"`: the viewer picks the font, so no font library or system font is needed to render.
//! Layout uses plotters' built-in width estimate (about 0.6 em per character).
//!
//! Axis ranges come from the finite data: linear axes get a 5 % margin, log axes extend to whole decades.
//! Non-finite points are skipped, and so are non-positive ones on a log axis; a line is broken where a point is
//! skipped. A series with nothing left to draw is left out of the legend; only a chart with nothing at all to draw
//! is an error. The legend goes into whichever plot corner is least covered by the data.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

/// Fixed colour palette (Tableau 10), used in series order.
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Radius of a marker circle, in pixels.
const MARKER_RADIUS: i32 = 3;
/// Stroke width of lines, in pixels.
const LINE_WIDTH: u32 = 2;
/// Dash length and gap of [`Style::Dashed`], in pixels.
const DASH: (f64, f64) = (8.0, 5.0);
/// Smallest accepted chart size, in pixels.
const MIN_SIZE: (u32, u32) = (200, 150);

const FONT: &str = "sans-serif";
const TITLE_SIZE: f64 = 24.0;
const DESC_SIZE: f64 = 18.0;
const TICK_SIZE: f64 = 15.0;
const LEGEND_SIZE: f64 = 15.0;

/// One data series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    pub label: String,
    /// Data points `(x, y)`, drawn in this order.
    pub points: Vec<(f64, f64)>,
    /// How the series is drawn.
    pub style: Style,
}

impl Series {
    /// A series from a label, its points and a style.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Series {
        Series { label: label.into(), points, style }
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A solid polyline through the points.
    Line,
    /// A small filled circle at each point.
    Markers,
    /// A solid polyline with a circle at each point.
    LineMarkers,
    /// A dashed polyline: for analytic reference curves.
    Dashed,
}

/// Axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
    /// Scale of the x axis.
    pub x_scale: Scale,
    /// Scale of the y axis.
    pub y_scale: Scale,
    /// Series, drawn in order; series `i` gets palette colour `i mod 10`.
    pub series: Vec<Series>,
    /// Width in pixels (at least 200).
    pub width: u32,
    /// Height in pixels (at least 150).
    pub height: u32,
}

/// Why a chart could not be rendered or written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// No series has a single finite point.
    #[error("chart {title:?}: no finite data to plot")]
    NoFiniteData {
        /// The chart's title.
        title: String,
    },
    /// There are finite points, but every one of them is non-positive on a log axis.
    #[error("chart {title:?}: nothing to plot: every finite point of {} is non-positive on a log axis", quoted(.series))]
    NoPositiveData {
        /// The chart's title.
        title: String,
        /// Labels of the series that lost points to a log axis.
        series: Vec<String>,
    },
    /// Width or height below the minimum of 200 × 150 pixels.
    #[error("chart {title:?}: size {width}x{height} is below the minimum 200x150")]
    TooSmall {
        /// The chart's title.
        title: String,
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// The plotting library reported an error while drawing.
    #[error("chart {title:?}: drawing failed: {message}")]
    Render {
        /// The chart's title.
        title: String,
        /// The library's message.
        message: String,
    },
    /// Writing the SVG file failed.
    #[error("cannot write {}: {source}", .path.display())]
    Io {
        /// The file (or its temporary sibling) being written.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
}

fn quoted(names: &[String]) -> String {
    let names: Vec<String> = names.iter().map(|n| format!("{n:?}")).collect();
    if names.len() == 1 {
        format!("series {}", names[0])
    } else {
        format!("series {}", names.join(", "))
    }
}

impl Chart {
    /// A chart with linear axes, 800 × 500 pixels and no series.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Chart {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
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

    /// Append a series.
    #[allow(clippy::should_implement_trait)] // a builder step, not `+`
    pub fn add(mut self, s: Series) -> Self {
        self.series.push(s);
        self
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
        let svg = self.to_svg()?;
        let name = path.file_name().ok_or_else(|| PlotError::Io {
            path: path.to_path_buf(),
            source: std::io::Error::new(std::io::ErrorKind::InvalidInput, "path has no file name"),
        })?;
        let mut tmp_name = std::ffi::OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".{}.tmp", std::process::id()));
        let tmp = path.with_file_name(tmp_name);
        let result = (|| {
            let mut file = std::fs::File::create(&tmp)?;
            file.write_all(svg.as_bytes())?;
            file.sync_all()?;
            drop(file);
            std::fs::rename(&tmp, path)
        })();
        result.map_err(|source| {
            let _ = std::fs::remove_file(&tmp);
            PlotError::Io { path: path.to_path_buf(), source }
        })
    }

    /// Filter and transform the data; compute ranges and ticks.
    fn prepare(&self) -> Result<Prepared, PlotError> {
        let (xlog, ylog) = (self.x_scale == Scale::Log10, self.y_scale == Scale::Log10);
        let mut any_finite = false;
        let mut lost_to_log = Vec::new();
        let mut series = Vec::new();
        for (i, s) in self.series.iter().enumerate() {
            let mut segments: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            let mut lost = false;
            for &(x, y) in &s.points {
                let ok = if !(x.is_finite() && y.is_finite()) {
                    false
                } else {
                    any_finite = true;
                    let positive = (!xlog || x > 0.0) && (!ylog || y > 0.0);
                    lost |= !positive;
                    positive
                };
                if ok {
                    let p = (if xlog { x.log10() } else { x }, if ylog { y.log10() } else { y });
                    segments.last_mut().expect("never empty").push(p);
                } else if !segments.last().expect("never empty").is_empty() {
                    segments.push(Vec::new());
                }
            }
            segments.retain(|seg| !seg.is_empty());
            if lost {
                lost_to_log.push(s.label.clone());
            }
            if !segments.is_empty() {
                series.push(PreparedSeries { index: i, segments });
            }
        }
        if series.is_empty() {
            return Err(if any_finite {
                PlotError::NoPositiveData { title: self.title.clone(), series: lost_to_log }
            } else {
                PlotError::NoFiniteData { title: self.title.clone() }
            });
        }
        let pts = || series.iter().flat_map(|s| s.segments.iter().flatten());
        let (xmin, xmax) = min_max(pts().map(|p| p.0));
        let (ymin, ymax) = min_max(pts().map(|p| p.1));
        let x_target = (self.width / 100).clamp(3, 10) as usize;
        let y_target = (self.height / 60).clamp(3, 10) as usize;
        let x = if xlog { Axis::log(xmin, xmax, x_target) } else { Axis::linear(xmin, xmax, x_target) };
        let y = if ylog { Axis::log(ymin, ymax, y_target) } else { Axis::linear(ymin, ymax, y_target) };
        Ok(Prepared { series, x, y })
    }

    fn draw(&self, prep: &Prepared, svg: &mut String) -> Result<(), String> {
        let err = |e: &dyn std::fmt::Display| e.to_string();
        let root = SVGBackend::with_string(svg, (self.width, self.height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;

        let x_fmt = |v: &f64| prep.x.label(*v);
        let y_fmt = |v: &f64| prep.y.label(*v);
        let y_tick_chars = prep.y.bold.iter().map(|v| prep.y.label(*v).chars().count()).max().unwrap_or(1);
        let y_area = (y_tick_chars as f64 * TICK_SIZE * 0.6 + 12.0 + DESC_SIZE * 1.6).ceil() as u32;
        let x_area = (TICK_SIZE * 1.2 + 8.0 + DESC_SIZE * 1.3).ceil() as u32;

        let mut builder = ChartBuilder::on(&root);
        builder.margin(15).margin_right(30).x_label_area_size(x_area).y_label_area_size(y_area);
        if !self.title.is_empty() {
            builder.caption(&self.title, (FONT, fit_font(TITLE_SIZE, &self.title, f64::from(self.width) - 20.0)));
        }
        let mut chart = builder.build_cartesian_2d(prep.x.clone(), prep.y.clone()).map_err(|e| err(&e))?;

        let mut mesh = chart.configure_mesh();
        mesh.bold_line_style(RGBColor(200, 200, 200).stroke_width(1))
            .light_line_style(RGBColor(235, 235, 235).stroke_width(1))
            .axis_style(BLACK.stroke_width(1))
            .label_style((FONT, TICK_SIZE))
            .axis_desc_style((FONT, DESC_SIZE))
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt);
        if !self.x_label.is_empty() {
            mesh.x_desc(self.x_label.as_str());
        }
        if !self.y_label.is_empty() {
            mesh.y_desc(self.y_label.as_str());
        }
        mesh.draw().map_err(|e| err(&e))?;

        let mut legend_labels = Vec::new();
        for ps in &prep.series {
            let s = &self.series[ps.index];
            let color = PALETTE[ps.index % PALETTE.len()];
            let line = color.stroke_width(LINE_WIDTH);
            let labelled = !s.label.is_empty();
            if labelled {
                legend_labels.push(s.label.as_str());
            }
            // The legend attaches to the last `draw_series` call: markers are drawn after lines.
            let lines = match s.style {
                Style::Line | Style::LineMarkers => Some(
                    chart
                        .draw_series(ps.segments.iter().map(|seg| PathElement::new(seg.clone(), line)))
                        .map_err(|e| err(&e))?,
                ),
                Style::Dashed => Some(
                    chart
                        .draw_series(
                            ps.segments.iter().map(|seg| DashedPathElement::new(seg.clone(), DASH.0, DASH.1, line)),
                        )
                        .map_err(|e| err(&e))?,
                ),
                Style::Markers => None,
            };
            if let Some(anno) = lines {
                if labelled && s.style != Style::LineMarkers {
                    anno.label(s.label.as_str());
                    if s.style == Style::Dashed {
                        anno.legend(move |(x, y)| DashedPathElement::new(vec![(x, y), (x + 20, y)], 6.0, 3.0, line));
                    } else {
                        anno.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], line));
                    }
                }
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                let anno = chart
                    .draw_series(ps.segments.iter().flatten().map(|&p| Circle::new(p, MARKER_RADIUS, color.filled())))
                    .map_err(|e| err(&e))?;
                if labelled {
                    anno.label(s.label.as_str());
                    if s.style == Style::LineMarkers {
                        anno.legend(move |(x, y)| {
                            EmptyElement::at((x, y))
                                + PathElement::new(vec![(0, 0), (20, 0)], line)
                                + Circle::new((10, 0), MARKER_RADIUS, color.filled())
                        });
                    } else {
                        anno.legend(move |(x, y)| Circle::new((x + 10, y), MARKER_RADIUS, color.filled()));
                    }
                }
            }
        }

        if !legend_labels.is_empty() {
            let (pw, ph) = chart.plotting_area().dim_in_pixel();
            let longest = legend_labels.iter().copied().max_by_key(|l| l.chars().count()).unwrap_or("");
            let legend_size = fit_font(LEGEND_SIZE, longest, f64::from(pw) - 60.0);
            let position = legend_corner(prep, &legend_labels, legend_size, pw, ph);
            chart
                .configure_series_labels()
                .position(position)
                .margin(10)
                .legend_area_size(26)
                .label_font((FONT, legend_size))
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .draw()
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
        Ok(())
    }
}

/// Data after filtering and axis transform (log10 for log axes).
struct Prepared {
    series: Vec<PreparedSeries>,
    x: Axis,
    y: Axis,
}

struct PreparedSeries {
    /// Index into `Chart::series` (selects the colour).
    index: usize,
    /// Runs of consecutive drawable points, in transformed coordinates.
    segments: Vec<Vec<(f64, f64)>>,
}

/// One axis in transformed coordinates: range, grid/tick positions and how to label them.
#[derive(Clone)]
struct Axis {
    lo: f64,
    hi: f64,
    /// Labelled ticks with a grid line.
    bold: Vec<f64>,
    /// Unlabelled minor grid lines.
    light: Vec<f64>,
    /// `None` for log axes (labels are powers of ten), else the tick step (sets the decimals).
    step: Option<f64>,
}

impl Axis {
    fn linear(min: f64, max: f64, target: usize) -> Axis {
        let span = max - min;
        let pad = if span > 0.0 {
            0.05 * span
        } else if min != 0.0 {
            0.1 * min.abs()
        } else {
            1.0
        };
        let (lo, hi) = if (max + pad - (min - pad)).is_finite() { (min - pad, max + pad) } else { (min, max) };
        let step = nice_step((hi - lo) / target as f64);
        // Data near ±f64::MAX can overflow the span: then no ticks rather than an endless list.
        let bold = if (hi - lo) / step <= 1000.0 {
            let (k0, k1) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
            (k0..=k1).map(|k| k as f64 * step).collect()
        } else {
            Vec::new()
        };
        Axis { lo, hi, bold, light: Vec::new(), step: Some(step) }
    }

    fn log(min: f64, max: f64, target: usize) -> Axis {
        let lo = min.floor();
        let mut hi = max.ceil();
        if hi <= lo {
            hi = lo + 1.0;
        }
        let span = (hi - lo) as i64;
        let stride = (nice_step(span as f64 / target as f64).round() as i64).max(1);
        let (k0, k1) = (lo as i64, hi as i64);
        let bold = (k0..=k1).filter(|k| k.rem_euclid(stride) == 0).map(|k| k as f64).collect();
        let mut light: Vec<f64> = if span <= 60 {
            (k0..=k1).filter(|k| k.rem_euclid(stride) != 0).map(|k| k as f64).collect()
        } else {
            Vec::new()
        };
        if stride == 1 && span <= 8 {
            for k in k0..k1 {
                light.extend((2..=9).map(|m| k as f64 + f64::from(m).log10()));
            }
        }
        Axis { lo, hi, bold, light, step: None }
    }

    fn label(&self, v: f64) -> String {
        match self.step {
            None => power_of_ten(v.round() as i64),
            Some(step) => fmt_linear(v, step, self.lo.abs().max(self.hi.abs())),
        }
    }
}

/// A linear coordinate over `lo..hi` whose bold (labelled) and light grid positions are ours.
/// (plotters' `WithKeyPoints<RangedCoordf64>` cannot be used with `configure_mesh`: it has no value formatter.)
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        let px = f64::from(limit.0) + t * f64::from(limit.1 - limit.0);
        px.round().clamp(f64::from(i32::MIN / 2), f64::from(i32::MAX / 2)) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
}

/// A step of 1, 2 or 5 × 10^k, at least `raw`.
fn nice_step(raw: f64) -> f64 {
    let raw = if raw > 0.0 && raw.is_finite() { raw } else { 1.0 };
    let mag = 10f64.powf(raw.log10().floor());
    let f = raw / mag;
    let m = if f <= 1.0 + 1e-9 {
        1.0
    } else if f <= 2.0 + 1e-9 {
        2.0
    } else if f <= 5.0 + 1e-9 {
        5.0
    } else {
        10.0
    };
    m * mag
}

/// Tick label for a linear axis: enough decimals for `step`; scientific notation for very large or small values.
fn fmt_linear(v: f64, step: f64, magnitude: f64) -> String {
    if v.abs() < step * 1e-6 {
        return "0".to_string();
    }
    let step_exp = step.log10().floor() as i32;
    if !(1e-3..1e5).contains(&magnitude) {
        let mag_exp = magnitude.log10().floor() as i32;
        let decimals = (mag_exp - step_exp).max(0) as usize;
        format!("{v:.decimals$e}")
    } else {
        let decimals = (-step_exp).max(0) as usize;
        format!("{v:.decimals$}")
    }
}

/// `10` followed by the exponent in Unicode superscript digits.
fn power_of_ten(k: i64) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        s.push(SUP[c.to_digit(10).expect("decimal digit") as usize]);
    }
    s
}

/// `size`, shrunk (to no less than 8) so that `text` fits in `avail` pixels at about half an em per character.
fn fit_font(size: f64, text: &str, avail: f64) -> f64 {
    let chars = text.chars().count().max(1) as f64;
    size.min((avail / (0.5 * chars)).floor()).max(8.0)
}

/// The plot corner least covered by the data, for a legend of roughly the given size.
fn legend_corner(prep: &Prepared, labels: &[&str], size: f64, pw: u32, ph: u32) -> SeriesLabelPosition {
    let max_chars = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0) as f64;
    let w = ((max_chars * size * 0.6 + 50.0) / f64::from(pw.max(1))).min(1.0);
    let h = ((labels.len() as f64 * (size + 6.0) + 25.0) / f64::from(ph.max(1))).min(1.0);
    let nx = |x: f64| (x - prep.x.lo) / (prep.x.hi - prep.x.lo);
    let ny = |y: f64| (y - prep.y.lo) / (prep.y.hi - prep.y.lo);
    // Corner boxes in normalised coordinates (y up): (x0, x1, y0, y1).
    let corners = [
        (1.0 - w, 1.0, 1.0 - h, 1.0), // upper right (preferred on ties)
        (0.0, w, 1.0 - h, 1.0),       // upper left
        (1.0 - w, 1.0, 0.0, h),       // lower right
        (0.0, w, 0.0, h),             // lower left
    ];
    let mut counts = [0usize; 4];
    for s in &prep.series {
        for seg in &s.segments {
            // Sample along each segment so that long straight lines count too.
            let mut samples = Vec::new();
            samples.push(seg[0]);
            for pair in seg.windows(2) {
                for j in 1..=16 {
                    let t = f64::from(j) / 16.0;
                    samples.push((pair[0].0 + t * (pair[1].0 - pair[0].0), pair[0].1 + t * (pair[1].1 - pair[0].1)));
                }
            }
            for (x, y) in samples {
                let (u, v) = (nx(x), ny(y));
                for (c, (x0, x1, y0, y1)) in corners.iter().enumerate() {
                    if u >= *x0 && u <= *x1 && v >= *y0 && v <= *y1 {
                        counts[c] += 1;
                    }
                }
            }
        }
    }
    let best = (0..4).min_by_key(|&c| counts[c]).expect("four corners");
    match best {
        0 => SeriesLabelPosition::UpperRight,
        1 => SeriesLabelPosition::UpperLeft,
        2 => SeriesLabelPosition::LowerRight,
        _ => SeriesLabelPosition::LowerLeft,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Text content of every `<text>` element, unescaped enough for the tests' labels.
    fn texts(svg: &str) -> Vec<String> {
        let mut out = Vec::new();
        let mut rest = svg;
        while let Some(i) = rest.find("<text") {
            rest = &rest[i..];
            let open_end = rest.find('>').expect("tag end");
            let close = rest.find("</text>").expect("closing tag");
            out.push(rest[open_end + 1..close].trim().replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"));
            rest = &rest[close..];
        }
        out
    }

    fn count(svg: &str, pat: &str) -> usize {
        svg.matches(pat).count()
    }

    fn linear_chart() -> Chart {
        let xs: Vec<f64> = (0..=20).map(|i| -1.0 + 0.1 * f64::from(i)).collect();
        Chart::new("Contact pressure", "x / a", "p / p0")
            .add(Series::new("Hertz", xs.iter().map(|&x| (x, (1.0 - x * x).max(0.0).sqrt())).collect(), Style::Dashed))
            .add(Series::new(
                "BEM",
                xs.iter().step_by(2).map(|&x| (x, 0.98 * (1.0 - x * x).sqrt())).collect(),
                Style::Markers,
            ))
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
        // One circle per marker point (11 + 3), plus one legend icon per marker series (2).
        assert_eq!(count(&svg, "<circle"), 11 + 3 + 2);
        assert_eq!(svg, chart.to_svg().unwrap());
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
        assert_eq!(count(&svg, "<circle"), 3 + 2 + 2);
        assert_eq!(svg, chart.to_svg().unwrap());
    }

    #[test]
    fn log_axis_range_is_whole_decades() {
        let a = Axis::log(2e-3f64.log10(), 5e-1f64.log10(), 8);
        assert_eq!((a.lo, a.hi), (-3.0, 0.0));
        assert_eq!(a.bold, vec![-3.0, -2.0, -1.0, 0.0]);
        let a = Axis::log(0.0, 0.0, 8); // a single value 1.0
        assert_eq!((a.lo, a.hi), (0.0, 1.0));
        let a = Axis::log(-30.0, 0.0, 10); // many decades: label every 5th
        assert_eq!(a.bold, vec![-30.0, -25.0, -20.0, -15.0, -10.0, -5.0, 0.0]);
        assert_eq!(a.light.len(), 31 - 7);
    }

    #[test]
    fn linear_axis_has_margin_and_nice_ticks() {
        let a = Axis::linear(0.0, 10.0, 8);
        assert!(a.lo < 0.0 && a.hi > 10.0);
        assert_eq!(a.bold, vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
        let a = Axis::linear(3.0, 3.0, 8);
        assert!(a.lo < 3.0 && a.hi > 3.0);
        assert_eq!(fmt_linear(0.25, 0.05, 1.0), "0.25");
        assert_eq!(fmt_linear(2e6, 5e5, 3e6), "2.0e6");
        assert_eq!(power_of_ten(-12), "10⁻¹²");
        assert_eq!(power_of_ten(0), "10⁰");
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
            if let Some(dir) = std::env::var_os("ROLLBEM_PLOT_EXAMPLES") {
                chart.write(&Path::new(&dir).join(name)).unwrap();
            }
        }
    }
}
