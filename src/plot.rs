//! Small, deterministic SVG charts on top of `plotters`: line / marker charts ([`Chart`]) and filled contour maps
//! of a scalar field in a vertical section ([`ContourMap`]).
//!
//! ```no_run
//! use rollbem::plot::{Chart, Series, Style};
//! let chart = Chart::new("Error vs time", "time", "error")
//!     .x_unit("s")
//!     .y_unit("1")
//!     .log_x()
//!     .log_y()
//!     .add(Series::new("Lemke", vec![(1e-3, 1e-2), (1e-2, 1e-5)], Style::LineMarkers))
//!     .add(Series::new("slope 2", vec![(1e-3, 1e-2), (1e-2, 1e-4)], Style::Dashed));
//! chart.write(std::path::Path::new("error.svg")).unwrap();
//! ```
//!
//! **Series styles.** Series `i` is drawn with [`Appearance::for_index`]`(i)`: a colour from [`PALETTE`]
//! (Okabe–Ito, colour-blind safe), a marker shape from [`Marker::ALL`] and a dash pattern ([`Dash`]), chosen so that no
//! two series of a chart look the same, however many there are, and so that markers still differ in shape when
//! printed in grey. The legend shows each series' line (with its dash) and marker. [`Series::with_appearance`]
//! overrides the automatic choice.
//!
//! **Units.** [`Chart::x_unit`] / [`Chart::y_unit`] append ` [unit]` to the axis label (unless the label already
//! ends with it); [`Chart::axes_without_unit`] lists the axes that still say no unit.
//!
//! **Categorical y axis.** [`Chart::categories_y`] labels the y axis with names at the integer positions 0, 1, …
//! (no fractional ticks); y values are rounded to the nearest category, and the series are offset slightly in y
//! so that overlapping series stay visible.
//!
//! **Contour maps.** [`ContourMap`] draws a scalar [`Field`] sampled on a regular grid (x horizontal, depth
//! increasing downward) as filled colour bands (viridis or cividis), with a colour bar, optional contour lines
//! (marching squares), markers such as the location of the maximum, and an optional 1:1 aspect ratio.
//!
//! Text (title, axis labels, tick labels, legend) is emitted as SVG `<text>` elements with
//! `font-family="sans-serif"`: the viewer picks the font, so no font library or system font is needed to render.
//! Layout estimates text widths at about half an em per character and shrinks fonts that would not fit.
//!
//! Axis ranges come from the finite data: linear axes get a 5 % margin, log axes extend to whole decades.
//! Non-finite points are skipped, and so are non-positive ones on a log axis; a line is broken where a point is
//! skipped. A series with nothing left to draw is left out of the legend; only a chart with nothing at all to draw
//! is an error. The legend goes into a plot corner free of data, or beside the plot when no corner is free or
//! the legend is long. All output is deterministic: the same input gives byte-identical SVG.

use std::collections::BTreeMap;
use std::io::Write as _;
use std::ops::Range;
use std::path::{Path, PathBuf};

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontTransform;

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    fn color(self) -> RGBColor {
        RGBColor(self.0, self.1, self.2)
    }
}

/// The series palette, in order: the colour-blind-safe palette of Okabe and Ito ("Color Universal Design", 2008)
/// without its yellow (#F0E442), which is too light on white: blue, vermillion, bluish green, orange, reddish
/// purple, sky blue, black.
pub const PALETTE: [Rgb; 7] = [
    Rgb(0, 114, 178),
    Rgb(213, 94, 0),
    Rgb(0, 158, 115),
    Rgb(230, 159, 0),
    Rgb(204, 121, 167),
    Rgb(86, 180, 233),
    Rgb(0, 0, 0),
];

/// Marker shape drawn at each data point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Marker {
    /// Filled circle.
    Circle,
    /// Filled square.
    Square,
    /// Filled triangle pointing up.
    TriangleUp,
    /// Filled diamond.
    Diamond,
    /// Filled triangle pointing down.
    TriangleDown,
    /// Diagonal cross (×).
    Cross,
    /// Upright cross (+).
    Plus,
    /// Six-armed asterisk (*).
    Asterisk,
    /// Hollow circle.
    OpenCircle,
    /// Hollow square.
    OpenSquare,
    /// Hollow triangle pointing up.
    OpenTriangleUp,
    /// Hollow diamond.
    OpenDiamond,
    /// Hollow triangle pointing down.
    OpenTriangleDown,
}

impl Marker {
    /// Every marker, in the order series use them.
    pub const ALL: [Marker; 13] = [
        Marker::Circle,
        Marker::Square,
        Marker::TriangleUp,
        Marker::Diamond,
        Marker::TriangleDown,
        Marker::Cross,
        Marker::Plus,
        Marker::Asterisk,
        Marker::OpenCircle,
        Marker::OpenSquare,
        Marker::OpenTriangleUp,
        Marker::OpenDiamond,
        Marker::OpenTriangleDown,
    ];
}

/// Dash pattern of a series' line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Dash {
    /// Unbroken line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Dots.
    Dotted,
    /// A dash followed by this many dots, repeated (1: dash-dot, 2: dash-dot-dot, …).
    DashDots(usize),
}

impl Dash {
    /// Alternating on / off lengths in pixels, starting with "on"; empty for a solid line.
    pub fn pattern(self) -> Vec<f64> {
        match self {
            Dash::Solid => Vec::new(),
            Dash::Dashed => vec![9.0, 5.0],
            Dash::Dotted => vec![2.0, 4.0],
            Dash::DashDots(n) => {
                let mut p = vec![10.0, 4.0];
                for _ in 0..n.max(1) {
                    p.extend([2.0, 4.0]);
                }
                p
            }
        }
    }
}

/// Colour, marker and dash pattern of one series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Appearance {
    /// Line and marker colour.
    pub color: Rgb,
    /// Marker shape (for [`Style::Markers`] and [`Style::LineMarkers`]).
    pub marker: Marker,
    /// Dash pattern of the line (for [`Style::Line`] and [`Style::LineMarkers`]; [`Style::Dashed`] is always
    /// broken).
    pub dash: Dash,
}

impl Appearance {
    /// The automatic appearance of series `index`: colour `index mod 7`, marker `index mod 13`, dash pattern
    /// `index / 7` (solid for the first 7 series, then dashed, dotted, dash-dot, dash-dot-dot, …). The first 7
    /// series differ in colour, the first 13 in marker shape, and no two indices give the same triple.
    pub fn for_index(index: usize) -> Appearance {
        let dash = match index / PALETTE.len() {
            0 => Dash::Solid,
            1 => Dash::Dashed,
            2 => Dash::Dotted,
            k => Dash::DashDots(k - 2),
        };
        Appearance { color: PALETTE[index % PALETTE.len()], marker: Marker::ALL[index % Marker::ALL.len()], dash }
    }

    /// The dash pattern actually used for a series drawn in `style`.
    fn line_dash(self, style: Style) -> Dash {
        match (style, self.dash) {
            (Style::Dashed, Dash::Solid) => Dash::Dashed,
            (_, d) => d,
        }
    }
}

/// Stroke width of lines, in pixels.
const LINE_WIDTH: u32 = 2;
/// Half-size of a series marker, in pixels.
const MARKER_SIZE: f64 = 5.0;
/// Length of the line sample in a legend entry, in pixels.
const LEGEND_SAMPLE: f64 = 36.0;
/// Smallest accepted chart size, in pixels.
const MIN_SIZE: (u32, u32) = (200, 150);
/// Margin around the whole figure, in pixels.
const MARGIN: u32 = 15;

const FONT: &str = "sans-serif";
const TITLE_SIZE: f64 = 24.0;
const DESC_SIZE: f64 = 18.0;
const TICK_SIZE: f64 = 15.0;
const LEGEND_SIZE: f64 = 15.0;
/// Estimated text width per character, in units of the nominal font size (plotters writes `font-size` as the
/// nominal size / 1.24; sans-serif text averages about 0.6 em per character).
const CHAR_WIDTH: f64 = 0.52;

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

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A polyline through the points (solid, or the series' dash pattern).
    Line,
    /// A marker at each point.
    Markers,
    /// A polyline with a marker at each point.
    LineMarkers,
    /// A dashed polyline: for analytic reference curves.
    Dashed,
}

impl Style {
    fn has_line(self) -> bool {
        self != Style::Markers
    }

    fn has_markers(self) -> bool {
        matches!(self, Style::Markers | Style::LineMarkers)
    }
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

/// Why a chart could not be rendered or written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// No series has a single finite point (or a field has no finite value).
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
    /// There are finite points, but every one of them lies outside the categories of a categorical y axis.
    #[error("chart {title:?}: nothing to plot: every finite point of {} is outside the y categories", quoted(.series))]
    OutsideCategories {
        /// The chart's title.
        title: String,
        /// Labels of the series that lost points outside the categories.
        series: Vec<String>,
    },
    /// A contour map's field is malformed (grid size, value count or ranges).
    #[error("chart {title:?}: bad field: {reason}")]
    BadField {
        /// The chart's title.
        title: String,
        /// What is wrong.
        reason: String,
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

/// `label [unit]`, unless the label already ends with `[unit]` or there is no unit.
fn with_unit(label: &str, unit: Option<&str>) -> String {
    match unit.map(str::trim).filter(|u| !u.is_empty()) {
        None => label.to_string(),
        Some(u) if label.trim_end().ends_with(&format!("[{u}]")) => label.to_string(),
        Some(u) if label.trim().is_empty() => format!("[{u}]"),
        Some(u) => format!("{} [{u}]", label.trim_end()),
    }
}

/// Whether an axis text names a unit: it ends with `[…]`.
fn says_unit(text: &str) -> bool {
    let t = text.trim_end();
    t.ends_with(']') && t.contains('[')
}

/// Write `svg` to `path` atomically (temp file in the same folder + rename).
fn write_atomic(path: &Path, svg: &str) -> Result<(), PlotError> {
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

    /// The x axis text as drawn: the label with its unit.
    pub fn x_axis_text(&self) -> String {
        with_unit(&self.x_label, self.x_unit.as_deref())
    }

    /// The y axis text as drawn: the label with its unit.
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

    fn draw(&self, prep: &Prepared, svg: &mut String) -> Result<(), String> {
        let (width, height) = (self.width, self.height);
        let root = SVGBackend::with_string(svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;

        let (x_text, y_text) = (self.x_axis_text(), self.y_axis_text());
        let x_fmt = |v: &f64| prep.x.label(*v);
        let y_fmt = |v: &f64| prep.y.label(*v);
        let y_tick_w = prep.y.bold.iter().map(|v| text_width(&prep.y.label(*v), TICK_SIZE)).fold(0.0, f64::max) + 14.0;
        let y_desc_w = if y_text.is_empty() { 0.0 } else { DESC_SIZE * 1.5 };
        let y_area = (y_tick_w + y_desc_w).ceil() as u32;
        let x_tick_h = TICK_SIZE * 1.2 + 8.0;
        let x_desc_h = if x_text.is_empty() { 0.0 } else { DESC_SIZE * 1.5 };
        let x_area = (x_tick_h + x_desc_h).ceil() as u32;
        let title_h = if self.title.is_empty() { 0.0 } else { TITLE_SIZE * 1.5 };

        // Legend: measured before the layout, because a legend beside the plot takes width from it.
        let items: Vec<LegendItem> = prep
            .series
            .iter()
            .map(|ps| (ps, &self.series[ps.index]))
            .filter(|(_, s)| !s.label.is_empty())
            .map(|(ps, s)| LegendItem {
                label: s.label.clone(),
                appearance: s.appearance.unwrap_or_else(|| Appearance::for_index(ps.index)),
                style: s.style,
            })
            .collect();
        let est_pw = f64::from(width) - f64::from(MARGIN) - f64::from(y_area) - 30.0;
        let est_ph = f64::from(height) - 2.0 * f64::from(MARGIN) - title_h - f64::from(x_area);
        let legend = plan_legend(&items, prep, est_pw, est_ph, f64::from(width));
        let margin_right = match legend.place {
            LegendPlace::Outside => (legend.w + 25.0).ceil() as u32,
            _ => 30,
        };

        let mut builder = ChartBuilder::on(&root);
        builder.margin(MARGIN).margin_right(margin_right).x_label_area_size(x_area).y_label_area_size(y_area);
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
        if !x_text.is_empty() {
            let size = fit_font(DESC_SIZE, &x_text, f64::from(xr.end - xr.start));
            let y = f64::from(yr.end) + x_tick_h + x_desc_h / 2.0;
            text(&root, &x_text, ((xr.start + xr.end) / 2, y.round() as i32), size, Anchor::Center, false)?;
        }
        if !y_text.is_empty() {
            let size = fit_font(DESC_SIZE, &y_text, f64::from(yr.end - yr.start));
            let x = f64::from(xr.start) - f64::from(y_area) + y_desc_w / 2.0;
            text(&root, &y_text, (x.round() as i32, (yr.start + yr.end) / 2), size, Anchor::Center, true)?;
        }

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
                    draw_dashed(&root, &pts, &pattern, app.color.color())?;
                }
            }
            if s.style.has_markers() {
                for p in ps.segments.iter().flatten() {
                    draw_marker(&root, px(p), app.marker, app.color.color(), MARKER_SIZE)?;
                }
            }
        }

        if !items.is_empty() {
            let (x0, y0) = match legend.place {
                LegendPlace::Outside => (f64::from(xr.end) + 15.0, f64::from(yr.start)),
                LegendPlace::Inside(c) => {
                    let left = if c.right { f64::from(xr.end) - 10.0 - legend.w } else { f64::from(xr.start) + 10.0 };
                    let top = if c.top { f64::from(yr.start) + 10.0 } else { f64::from(yr.end) - 10.0 - legend.h };
                    (left, top)
                }
            };
            draw_legend(&root, &items, &legend, (x0, y0))?;
        }
        root.present().map_err(|e| err(&e))?;
        Ok(())
    }
}

fn err(e: &dyn std::fmt::Display) -> String {
    e.to_string()
}

/// Horizontal text anchor.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Anchor {
    Left,
    Center,
}

/// Draw `s` at pixel `pos`, vertically centred; `rotated` turns it to read bottom to top.
fn text(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    s: &str,
    pos: (i32, i32),
    size: f64,
    anchor: Anchor,
    rotated: bool,
) -> Result<(), String> {
    let h = match anchor {
        Anchor::Left => HPos::Left,
        Anchor::Center => HPos::Center,
    };
    let mut font = (FONT, size).into_font();
    if rotated {
        font = font.transform(FontTransform::Rotate270);
    }
    let style = TextStyle::from(font).color(&BLACK).pos(Pos::new(h, VPos::Center));
    area.draw_text(s, &style, pos).map_err(|e| err(&e))
}

/// Estimated width in pixels of `s` at nominal font size `size`.
fn text_width(s: &str, size: f64) -> f64 {
    s.chars().count() as f64 * size * CHAR_WIDTH
}

fn to_px(p: (f64, f64)) -> (i32, i32) {
    let c = |v: f64| v.round().clamp(f64::from(i32::MIN / 2), f64::from(i32::MAX / 2)) as i32;
    (c(p.0), c(p.1))
}

/// Split a pixel polyline into the "on" runs of a dash pattern (alternating on / off lengths). An empty pattern
/// (or one of zero total length) gives the whole line.
fn dash_runs(pts: &[(f64, f64)], pattern: &[f64]) -> Vec<Vec<(f64, f64)>> {
    if pts.is_empty() {
        return Vec::new();
    }
    let usable = pattern.iter().all(|v| v.is_finite() && *v >= 0.0) && pattern.iter().sum::<f64>() > 0.0;
    if !usable {
        return vec![pts.to_vec()];
    }
    let mut out = Vec::new();
    let mut cur = vec![pts[0]];
    let mut k = 0;
    let mut left = pattern[0];
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        if !len.is_finite() {
            continue;
        }
        let mut used = 0.0;
        while len - used > left {
            used += left;
            let t = used / len;
            let p = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if k % 2 == 0 {
                cur.push(p);
                out.push(std::mem::take(&mut cur));
            } else {
                cur = vec![p];
            }
            k = (k + 1) % pattern.len();
            left = pattern[k];
        }
        left -= len - used;
        if k % 2 == 0 {
            cur.push(b);
        }
    }
    if k % 2 == 0 && cur.len() >= 2 {
        out.push(cur);
    }
    out
}

/// Draw a pixel polyline with a dash pattern.
fn draw_dashed(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    pts: &[(f64, f64)],
    pattern: &[f64],
    color: RGBColor,
) -> Result<(), String> {
    for run in dash_runs(pts, pattern) {
        let run: Vec<(i32, i32)> = run.into_iter().map(to_px).collect();
        area.draw(&PathElement::new(run, color.stroke_width(LINE_WIDTH))).map_err(|e| err(&e))?;
    }
    Ok(())
}

/// Draw a marker centred at pixel `c`, `s` pixels in half-size. Hollow markers have a white inside.
fn draw_marker(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    c: (f64, f64),
    marker: Marker,
    color: RGBColor,
    s: f64,
) -> Result<(), String> {
    let at = |dx: f64, dy: f64| to_px((c.0 + dx * s, c.1 + dy * s));
    let poly = |pts: &[(f64, f64)]| pts.iter().map(|&(dx, dy)| at(dx, dy)).collect::<Vec<_>>();
    let triangle_up = [(0.0, -1.2), (1.2, 0.8), (-1.2, 0.8)];
    let triangle_down = [(0.0, 1.2), (-1.2, -0.8), (1.2, -0.8)];
    let diamond = [(0.0, -1.25), (1.25, 0.0), (0.0, 1.25), (-1.25, 0.0)];
    let stroke = color.stroke_width(2);
    let r = |f: f64| (f * s).round().max(1.0) as u32;
    let lines = |segs: &[[(f64, f64); 2]]| -> Result<(), String> {
        for [a, b] in segs {
            area.draw(&PathElement::new(vec![at(a.0, a.1), at(b.0, b.1)], stroke)).map_err(|e| err(&e))?;
        }
        Ok(())
    };
    // A closed outline: the first two vertices repeated so that the closing corner is joined, not capped.
    let outline = |pts: &[(f64, f64)]| {
        let mut v = poly(pts);
        v.push(v[0]);
        v.push(v[1]);
        v
    };
    let d = |e: DrawingAreaErrorKind<_>| err(&e);
    match marker {
        Marker::Circle => area.draw(&Circle::new(at(0.0, 0.0), r(1.0), color.filled())).map_err(d),
        Marker::Square => area.draw(&Rectangle::new([at(-0.8, -0.8), at(0.8, 0.8)], color.filled())).map_err(d),
        Marker::TriangleUp => area.draw(&Polygon::new(poly(&triangle_up), color.filled())).map_err(d),
        Marker::TriangleDown => area.draw(&Polygon::new(poly(&triangle_down), color.filled())).map_err(d),
        Marker::Diamond => area.draw(&Polygon::new(poly(&diamond), color.filled())).map_err(d),
        Marker::Cross => lines(&[[(-0.8, -0.8), (0.8, 0.8)], [(-0.8, 0.8), (0.8, -0.8)]]),
        Marker::Plus => lines(&[[(-1.0, 0.0), (1.0, 0.0)], [(0.0, -1.0), (0.0, 1.0)]]),
        Marker::Asterisk => {
            lines(&[[(0.0, -1.0), (0.0, 1.0)], [(-0.87, -0.5), (0.87, 0.5)], [(-0.87, 0.5), (0.87, -0.5)]])
        }
        Marker::OpenCircle => {
            area.draw(&Circle::new(at(0.0, 0.0), r(0.85), WHITE.filled())).map_err(d)?;
            area.draw(&Circle::new(at(0.0, 0.0), r(0.85), stroke)).map_err(d)
        }
        Marker::OpenSquare => {
            let corners = [at(-0.75, -0.75), at(0.75, 0.75)];
            area.draw(&Rectangle::new(corners, WHITE.filled())).map_err(d)?;
            area.draw(&Rectangle::new(corners, stroke)).map_err(d)
        }
        Marker::OpenTriangleUp | Marker::OpenTriangleDown | Marker::OpenDiamond => {
            let shape: &[(f64, f64)] = match marker {
                Marker::OpenTriangleUp => &triangle_up,
                Marker::OpenTriangleDown => &triangle_down,
                _ => &diamond,
            };
            area.draw(&Polygon::new(poly(shape), WHITE.filled())).map_err(d)?;
            area.draw(&PathElement::new(outline(shape), stroke)).map_err(d)
        }
    }
}

/// One legend entry.
struct LegendItem {
    label: String,
    appearance: Appearance,
    style: Style,
}

/// A plot corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Corner {
    top: bool,
    right: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LegendPlace {
    /// In a plot corner free of data.
    Inside(Corner),
    /// Right of the plot.
    Outside,
}

/// Where the legend goes and its size in pixels.
struct LegendPlan {
    place: LegendPlace,
    font: f64,
    /// Width of the line sample (narrow when no entry has a line).
    sample: f64,
    rows: usize,
    col_w: f64,
    row_h: f64,
    w: f64,
    h: f64,
}

/// Legend entries at most drawn inside the plot.
const LEGEND_INSIDE_MAX: usize = 6;

/// Width of the legend's line samples: room for a line and its dashes, or just a marker.
fn legend_sample(items: &[LegendItem]) -> f64 {
    if items.iter().any(|i| i.style.has_line()) {
        LEGEND_SAMPLE
    } else {
        2.0 * MARKER_SIZE + 4.0
    }
}

fn legend_size(items: &[LegendItem], font: f64, columns: usize) -> (usize, f64, f64, f64, f64) {
    let longest = items.iter().map(|i| text_width(&i.label, font)).fold(0.0, f64::max);
    let col_w = 8.0 + legend_sample(items) + 8.0 + longest + 10.0;
    let row_h = (font * 0.8 + 9.0).round();
    let rows = items.len().div_ceil(columns.max(1));
    (rows, col_w, row_h, col_w * columns as f64, rows as f64 * row_h + 10.0)
}

/// Decide where the legend goes: inside a data-free corner when it is short and small, else to the right of the
/// plot (in as many columns as its height needs, the font shrunk if it would take more than 40 % of the width).
fn plan_legend(items: &[LegendItem], prep: &Prepared, pw: f64, ph: f64, width: f64) -> LegendPlan {
    let plan = |place, font: f64, columns: usize| {
        let (rows, col_w, row_h, w, h) = legend_size(items, font, columns);
        LegendPlan { place, font, sample: legend_sample(items), rows, col_w, row_h, w, h }
    };
    if items.is_empty() {
        return plan(LegendPlace::Outside, LEGEND_SIZE, 1);
    }
    let inside = plan(LegendPlace::Outside, LEGEND_SIZE, 1);
    if items.len() <= LEGEND_INSIDE_MAX && inside.w <= 0.45 * pw && inside.h <= 0.5 * ph {
        let (corner, covered) = legend_corner(prep, (inside.w + 20.0) / pw.max(1.0), (inside.h + 20.0) / ph.max(1.0));
        if covered == 0 {
            return LegendPlan { place: LegendPlace::Inside(corner), ..inside };
        }
    }
    let mut font = LEGEND_SIZE;
    loop {
        let rows_fit = (((ph - 10.0) / (font * 0.8 + 9.0).round()).floor() as usize).max(1);
        let columns = items.len().div_ceil(rows_fit);
        let p = plan(LegendPlace::Outside, font, columns);
        if p.w <= 0.4 * width || font <= 9.0 {
            if p.w <= 0.5 * width {
                return p;
            }
            // Too wide even in a small font: draw it in the least covered corner rather than squash the plot.
            let p = plan(LegendPlace::Outside, LEGEND_SIZE.min(12.0), 1);
            let (corner, _) = legend_corner(prep, (p.w + 20.0) / pw.max(1.0), (p.h + 20.0) / ph.max(1.0));
            return LegendPlan { place: LegendPlace::Inside(corner), ..p };
        }
        font -= 1.0;
    }
}

fn draw_legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    items: &[LegendItem],
    plan: &LegendPlan,
    (x0, y0): (f64, f64),
) -> Result<(), String> {
    let corner = |x: f64, y: f64| to_px((x, y));
    area.draw(&Rectangle::new([corner(x0, y0), corner(x0 + plan.w, y0 + plan.h)], WHITE.mix(0.9).filled()))
        .map_err(|e| err(&e))?;
    area.draw(&Rectangle::new([corner(x0, y0), corner(x0 + plan.w, y0 + plan.h)], RGBColor(160, 160, 160)))
        .map_err(|e| err(&e))?;
    for (i, item) in items.iter().enumerate() {
        let (col, row) = (i / plan.rows, i % plan.rows);
        let x = x0 + col as f64 * plan.col_w + 8.0;
        let y = (y0 + 5.0 + (row as f64 + 0.5) * plan.row_h).round();
        let color = item.appearance.color.color();
        if item.style.has_line() {
            let pattern = item.appearance.line_dash(item.style).pattern();
            draw_dashed(area, &[(x, y), (x + plan.sample, y)], &pattern, color)?;
        }
        if item.style.has_markers() {
            draw_marker(area, (x + plan.sample / 2.0, y), item.appearance.marker, color, MARKER_SIZE)?;
        }
        let tx = (x + plan.sample + 8.0).round() as i32;
        text(area, &item.label, (tx, y as i32), plan.font, Anchor::Left, false)?;
    }
    Ok(())
}

/// The plot corner least covered by the data for a legend box of the given size (fractions of the plot), and how
/// many data samples fall into it (0: free).
fn legend_corner(prep: &Prepared, w: f64, h: f64) -> (Corner, usize) {
    let (w, h) = (w.min(1.0), h.min(1.0));
    let nx = |x: f64| (x - prep.x.lo) / (prep.x.hi - prep.x.lo);
    let ny = |y: f64| (y - prep.y.lo) / (prep.y.hi - prep.y.lo);
    // Corner boxes in normalised coordinates (y up): (x0, x1, y0, y1), upper right preferred on ties.
    let corners = [
        (Corner { top: true, right: true }, (1.0 - w, 1.0, 1.0 - h, 1.0)),
        (Corner { top: true, right: false }, (0.0, w, 1.0 - h, 1.0)),
        (Corner { top: false, right: true }, (1.0 - w, 1.0, 0.0, h)),
        (Corner { top: false, right: false }, (0.0, w, 0.0, h)),
    ];
    let mut counts = [0usize; 4];
    for (s, off) in prep.series.iter().zip(&prep.offsets) {
        for seg in &s.segments {
            // Sample along each segment so that long straight lines count too.
            let mut samples = vec![seg[0]];
            for pair in seg.windows(2) {
                for j in 1..=16 {
                    let t = f64::from(j) / 16.0;
                    samples.push((pair[0].0 + t * (pair[1].0 - pair[0].0), pair[0].1 + t * (pair[1].1 - pair[0].1)));
                }
            }
            for (x, y) in samples {
                let (u, v) = (nx(x), ny(y + off));
                for (c, (_, (x0, x1, y0, y1))) in corners.iter().enumerate() {
                    if u >= *x0 && u <= *x1 && v >= *y0 && v <= *y1 {
                        counts[c] += 1;
                    }
                }
            }
        }
    }
    let best = (0..4).min_by_key(|&c| counts[c]).expect("four corners");
    (corners[best].0, counts[best])
}

/// Data after filtering and axis transform (log10 for log axes).
struct Prepared {
    series: Vec<PreparedSeries>,
    x: Axis,
    y: Axis,
    /// y offset of each prepared series (categorical axes only; else 0).
    offsets: Vec<f64>,
}

struct PreparedSeries {
    /// Index into `Chart::series` (selects the appearance).
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
    /// Category names (categorical axis: tick `k` is labelled `names[k]`).
    names: Option<Vec<String>>,
    /// Values increase downward (depth).
    reversed: bool,
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
        Axis::exact(lo, hi, target)
    }

    /// A linear axis over exactly `lo..hi` with nice ticks inside it.
    fn exact(lo: f64, hi: f64, target: usize) -> Axis {
        let step = nice_step((hi - lo) / target as f64);
        // Data near ±f64::MAX can overflow the span: then no ticks rather than an endless list.
        let bold = if (hi - lo) / step <= 1000.0 {
            let eps = 1e-9 * step;
            let (k0, k1) = (((lo - eps) / step).ceil() as i64, ((hi + eps) / step).floor() as i64);
            (k0..=k1).map(|k| k as f64 * step).collect()
        } else {
            Vec::new()
        };
        Axis { lo, hi, bold, light: Vec::new(), step: Some(step), names: None, reversed: false }
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
        Axis { lo, hi, bold, light, step: None, names: None, reversed: false }
    }

    /// Categories at 0, 1, …, n−1, half a unit of room either side; ticks only at the categories.
    fn categorical(names: &[String]) -> Axis {
        let n = names.len();
        Axis {
            lo: -0.5,
            hi: n as f64 - 0.5,
            bold: (0..n).map(|k| k as f64).collect(),
            light: Vec::new(),
            step: Some(1.0),
            names: Some(names.to_vec()),
            reversed: false,
        }
    }

    fn label(&self, v: f64) -> String {
        if let Some(names) = &self.names {
            let k = v.round();
            return if k >= 0.0 && (k as usize) < names.len() { names[k as usize].clone() } else { String::new() };
        }
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
        let mut t = (value - self.lo) / (self.hi - self.lo);
        if self.reversed {
            t = 1.0 - t;
        }
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

/// `v` with 4 significant digits: fixed notation for magnitudes in 10⁻³..10⁵, else scientific.
fn fmt_sig(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".to_string();
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..5).contains(&e) {
        let decimals = (3 - e).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
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
    size.min((avail / (CHAR_WIDTH * chars)).floor()).max(8.0)
}

// ---------------------------------------------------------------------------------------------------------------
// Contour maps
// ---------------------------------------------------------------------------------------------------------------

/// A scalar field sampled at the nodes of a regular grid in a vertical section: x horizontal, depth downward.
///
/// Node `(ix, iz)` is at `x = x_range.0 + ix·(x_range.1 − x_range.0)/(nx − 1)` and
/// `depth = depth_range.0 + iz·(depth_range.1 − depth_range.0)/(nz − 1)`; its value is `values[iz * nx + ix]`
/// (row-major, one row per depth, row 0 the shallowest). Non-finite values mark missing data.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Number of nodes along x (at least 2).
    pub nx: usize,
    /// Number of nodes along depth (at least 2).
    pub nz: usize,
    /// `nx · nz` values, row-major: `values[iz * nx + ix]`.
    pub values: Vec<f64>,
    /// x of the first and last node column (first < last).
    pub x_range: (f64, f64),
    /// Depth of the first and last node row (first < last; depth grows downward on the map).
    pub depth_range: (f64, f64),
}

impl Field {
    /// A field from its values (row-major, `values[iz * nx + ix]`); checked when drawn.
    pub fn new(nx: usize, nz: usize, values: Vec<f64>, x_range: (f64, f64), depth_range: (f64, f64)) -> Field {
        Field { nx, nz, values, x_range, depth_range }
    }

    /// A field sampling `f(x, depth)` at the nodes.
    pub fn from_fn(
        nx: usize,
        nz: usize,
        x_range: (f64, f64),
        depth_range: (f64, f64),
        f: impl Fn(f64, f64) -> f64,
    ) -> Field {
        let mut field = Field::new(nx, nz, Vec::with_capacity(nx.saturating_mul(nz)), x_range, depth_range);
        for iz in 0..nz {
            for ix in 0..nx {
                let v = f(field.x(ix), field.depth(iz));
                field.values.push(v);
            }
        }
        field
    }

    /// x of node column `ix`.
    pub fn x(&self, ix: usize) -> f64 {
        lerp_node(self.x_range, ix, self.nx)
    }

    /// Depth of node row `iz`.
    pub fn depth(&self, iz: usize) -> f64 {
        lerp_node(self.depth_range, iz, self.nz)
    }

    /// Value at node `(ix, iz)`.
    pub fn value(&self, ix: usize, iz: usize) -> f64 {
        self.values[iz * self.nx + ix]
    }

    /// Values at the corners of cell `(ix, iz)`, clockwise on the map from its top left: nodes `(ix, iz)`,
    /// `(ix + 1, iz)`, `(ix + 1, iz + 1)`, `(ix, iz + 1)`.
    fn cell(&self, ix: usize, iz: usize) -> [f64; 4] {
        [self.value(ix, iz), self.value(ix + 1, iz), self.value(ix + 1, iz + 1), self.value(ix, iz + 1)]
    }

    /// Why the field cannot be drawn, if it cannot.
    pub fn check(&self) -> Result<(), String> {
        if self.nx < 2 || self.nz < 2 {
            return Err(format!("grid {}x{} has fewer than 2 nodes along an axis", self.nx, self.nz));
        }
        if self.nx.checked_mul(self.nz) != Some(self.values.len()) {
            return Err(format!("{} values for a {}x{} grid", self.values.len(), self.nx, self.nz));
        }
        for (name, (a, b)) in [("x", self.x_range), ("depth", self.depth_range)] {
            if !(a.is_finite() && b.is_finite() && a < b && (b - a).is_finite()) {
                return Err(format!("{name} range {a}..{b} is not finite and increasing"));
            }
        }
        Ok(())
    }

    /// The largest finite node value and where it is: `(x, depth, value)`; the first in row-major order on ties.
    pub fn max(&self) -> Option<(f64, f64, f64)> {
        let mut best: Option<(usize, f64)> = None;
        for (i, &v) in self.values.iter().enumerate() {
            if v.is_finite() && best.is_none_or(|(_, b)| v > b) {
                best = Some((i, v));
            }
        }
        let (i, v) = best?;
        let nx = self.nx.max(1);
        Some((self.x(i % nx), self.depth(i / nx), v))
    }

    /// Contour lines of `level` by marching squares, as polylines of `(x, depth)` points (closed loops end where
    /// they start). Along a cell edge the crossing is interpolated linearly; a cell with a non-finite corner has no
    /// line; a saddle cell is resolved by the mean of its corners. A node equal to the level counts as above it.
    /// An unusable field (see [`Field::check`]) has no lines.
    pub fn contour_lines(&self, level: f64) -> Vec<Vec<(f64, f64)>> {
        if self.check().is_err() || !level.is_finite() {
            return Vec::new();
        }
        let (nx, nz) = (self.nx, self.nz);
        // Edge ids: horizontal edges (ix, iz)–(ix+1, iz) first, then vertical edges (ix, iz)–(ix, iz+1).
        let h_edges = (nx - 1) * nz;
        let h = |ix: usize, iz: usize| iz * (nx - 1) + ix;
        let v = |ix: usize, iz: usize| h_edges + iz * nx + ix;
        let mut segments: Vec<(usize, usize)> = Vec::new();
        for iz in 0..nz - 1 {
            for ix in 0..nx - 1 {
                let c = self.cell(ix, iz);
                if c.iter().any(|x| !x.is_finite()) {
                    continue;
                }
                let inside = c.map(|x| x >= level);
                // Edges: top (c0–c1), right (c1–c2), bottom (c3–c2), left (c0–c3).
                let e = [h(ix, iz), v(ix + 1, iz), h(ix, iz + 1), v(ix, iz)];
                let crossed =
                    [inside[0] != inside[1], inside[1] != inside[2], inside[2] != inside[3], inside[3] != inside[0]];
                let n = crossed.iter().filter(|&&b| b).count();
                if n == 2 {
                    let mut it = (0..4).filter(|&k| crossed[k]);
                    let (a, b) = (it.next().expect("two"), it.next().expect("two"));
                    segments.push((e[a], e[b]));
                } else if n == 4 {
                    let centre_inside = (c[0] + c[1] + c[2] + c[3]) / 4.0 >= level;
                    if centre_inside == inside[0] {
                        // c0 and c2 joined through the centre: cut off c1 (top, right) and c3 (bottom, left).
                        segments.push((e[0], e[1]));
                        segments.push((e[2], e[3]));
                    } else {
                        // c1 and c3 joined: cut off c0 (left, top) and c2 (right, bottom).
                        segments.push((e[3], e[0]));
                        segments.push((e[1], e[2]));
                    }
                }
            }
        }
        let point = |id: usize| -> (f64, f64) {
            let (a, b) = if id < h_edges {
                let (iz, ix) = (id / (nx - 1), id % (nx - 1));
                ((ix, iz), (ix + 1, iz))
            } else {
                let (iz, ix) = ((id - h_edges) / nx, (id - h_edges) % nx);
                ((ix, iz), (ix, iz + 1))
            };
            let (va, vb) = (self.value(a.0, a.1), self.value(b.0, b.1));
            let t = ((level - va) / (vb - va)).clamp(0.0, 1.0);
            let (pa, pb) = ((self.x(a.0), self.depth(a.1)), (self.x(b.0), self.depth(b.1)));
            (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1))
        };
        chain(&segments).into_iter().map(|ids| ids.into_iter().map(point).collect()).collect()
    }
}

fn lerp_node((a, b): (f64, f64), i: usize, n: usize) -> f64 {
    if n < 2 {
        return a;
    }
    if i + 1 == n {
        return b;
    }
    a + (b - a) * (i as f64 / (n - 1) as f64)
}

/// Join segments (pairs of edge ids) that share an edge into polylines of edge ids, deterministically.
fn chain(segments: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let mut at: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (i, &(a, b)) in segments.iter().enumerate() {
        at.entry(a).or_default().push(i);
        at.entry(b).or_default().push(i);
    }
    let mut used = vec![false; segments.len()];
    let mut out = Vec::new();
    for start in 0..segments.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let mut line = std::collections::VecDeque::from([segments[start].0, segments[start].1]);
        for forward in [true, false] {
            loop {
                let end = if forward { *line.back().expect("two") } else { *line.front().expect("two") };
                let next = at[&end].iter().copied().find(|&s| !used[s]);
                let Some(s) = next else { break };
                used[s] = true;
                let (a, b) = segments[s];
                let other = if a == end { b } else { a };
                if forward {
                    line.push_back(other);
                } else {
                    line.push_front(other);
                }
            }
        }
        out.push(line.into_iter().collect());
    }
    out
}

/// A perceptually uniform colour map (the 256-entry tables of matplotlib).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColorMap {
    /// Viridis (dark blue-violet → green → yellow).
    Viridis,
    /// Cividis (blue → grey → yellow; also uniform for red-green colour-blind readers).
    Cividis,
}

impl ColorMap {
    /// The colour at `t` in 0..1 (clamped; NaN gives the low end).
    pub fn at(self, t: f64) -> Rgb {
        let table = match self {
            ColorMap::Viridis => &VIRIDIS,
            ColorMap::Cividis => &CIVIDIS,
        };
        let i = if t.is_nan() { 0 } else { (t.clamp(0.0, 1.0) * 255.0).round() as usize };
        let [r, g, b] = table[i];
        Rgb(r, g, b)
    }
}

/// A labelled point on a contour map.
#[derive(Debug, Clone, PartialEq)]
pub struct MapMarker {
    /// x of the point.
    pub x: f64,
    /// Depth of the point.
    pub depth: f64,
    /// Caption text under the map.
    pub label: String,
}

/// A filled contour map of a [`Field`]: colour bands (with a colour bar), optional contour lines and markers.
///
/// ```no_run
/// use rollbem::plot::{ContourMap, Field};
/// // A field with its maximum 0.5 below the surface.
/// let field = Field::from_fn(81, 41, (-2.0, 2.0), (0.0, 2.0), |x, z| (-(x * x) - (z - 0.5).powi(2)).exp());
/// ContourMap::new("Bump", field)
///     .x_axis("x", "mm")
///     .depth_axis("depth", "mm")
///     .value_axis("stress", "MPa")
///     .contours(&[0.2, 0.4, 0.6, 0.8])
///     .mark_max()
///     .equal_aspect()
///     .write(std::path::Path::new("bump.svg"))
///     .unwrap();
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ContourMap {
    /// Title above the map.
    pub title: String,
    /// The field drawn.
    pub field: Field,
    /// Label of the horizontal axis.
    pub x_label: String,
    /// Unit of x.
    pub x_unit: Option<String>,
    /// Label of the vertical (depth) axis.
    pub depth_label: String,
    /// Unit of depth.
    pub depth_unit: Option<String>,
    /// Label of the colour bar.
    pub value_label: String,
    /// Unit of the values.
    pub value_unit: Option<String>,
    /// Target number of colour bands (the band edges are round numbers, so the count may differ a little).
    pub bands: usize,
    /// Values at which contour lines are drawn (and marked on the colour bar).
    pub levels: Vec<f64>,
    /// Mark the largest value, with its value and place in a caption.
    pub mark_max: bool,
    /// Further marked points.
    pub markers: Vec<MapMarker>,
    /// Draw x and depth to the same scale (they must be in the same unit); height the map then does not use is
    /// trimmed from the figure.
    pub equal_aspect: bool,
    /// Colour map of the bands.
    pub colormap: ColorMap,
    /// Width in pixels (at least 200).
    pub width: u32,
    /// Height in pixels (at least 150).
    pub height: u32,
}

/// Colour of cells with a non-finite corner.
const NO_DATA: RGBColor = RGBColor(190, 190, 190);
/// Nominal font size of contour labels and map captions.
const MAP_LABEL_SIZE: f64 = 13.0;
const CAPTION_SIZE: f64 = 15.0;
/// Half-size of a map marker, in pixels.
const MAP_MARKER_SIZE: f64 = 7.0;
/// Markers used on a map, in order (hollow: a white inside with a black outline shows on any colour).
const MAP_MARKERS: [Marker; 5] =
    [Marker::OpenDiamond, Marker::OpenCircle, Marker::OpenSquare, Marker::OpenTriangleUp, Marker::OpenTriangleDown];

impl ContourMap {
    /// A map of `field` with axes labelled x, depth and value (no units), about 10 viridis bands, no contour
    /// lines, no markers, 800 × 500 pixels.
    pub fn new(title: impl Into<String>, field: Field) -> ContourMap {
        ContourMap {
            title: title.into(),
            field,
            x_label: "x".into(),
            x_unit: None,
            depth_label: "depth".into(),
            depth_unit: None,
            value_label: "value".into(),
            value_unit: None,
            bands: 10,
            levels: Vec::new(),
            mark_max: false,
            markers: Vec::new(),
            equal_aspect: false,
            colormap: ColorMap::Viridis,
            width: 800,
            height: 500,
        }
    }

    /// Label and unit of the horizontal axis (an empty unit: none).
    pub fn x_axis(mut self, label: impl Into<String>, unit: impl Into<String>) -> Self {
        self.x_label = label.into();
        self.x_unit = Some(unit.into()).filter(|u| !u.is_empty());
        self
    }

    /// Label and unit of the depth axis.
    pub fn depth_axis(mut self, label: impl Into<String>, unit: impl Into<String>) -> Self {
        self.depth_label = label.into();
        self.depth_unit = Some(unit.into()).filter(|u| !u.is_empty());
        self
    }

    /// Label and unit of the values (the colour bar).
    pub fn value_axis(mut self, label: impl Into<String>, unit: impl Into<String>) -> Self {
        self.value_label = label.into();
        self.value_unit = Some(unit.into()).filter(|u| !u.is_empty());
        self
    }

    /// Target number of colour bands (at least 1).
    pub fn bands(mut self, n: usize) -> Self {
        self.bands = n.max(1);
        self
    }

    /// Draw contour lines at these values (non-finite ones are ignored); a few of them are labelled.
    pub fn contours(mut self, levels: &[f64]) -> Self {
        self.levels = levels.to_vec();
        self
    }

    /// Mark the largest value with a marker, and give its value and place in a caption.
    pub fn mark_max(mut self) -> Self {
        self.mark_max = true;
        self
    }

    /// Mark a point, with a caption.
    pub fn marker(mut self, x: f64, depth: f64, label: impl Into<String>) -> Self {
        self.markers.push(MapMarker { x, depth, label: label.into() });
        self
    }

    /// Draw x and depth to the same scale (1:1), so that shapes are not distorted; height the map does not use
    /// is trimmed from the figure.
    pub fn equal_aspect(mut self) -> Self {
        self.equal_aspect = true;
        self
    }

    /// Use another colour map.
    pub fn colormap(mut self, colormap: ColorMap) -> Self {
        self.colormap = colormap;
        self
    }

    /// Set the size in pixels (at least 200 × 150).
    pub fn size(mut self, width: u32, height: u32) -> Self {
        self.width = width;
        self.height = height;
        self
    }

    /// Render to an SVG string (deterministic: same data → byte-identical SVG).
    pub fn to_svg(&self) -> Result<String, PlotError> {
        let title = || self.title.clone();
        if self.width < MIN_SIZE.0 || self.height < MIN_SIZE.1 {
            return Err(PlotError::TooSmall { title: title(), width: self.width, height: self.height });
        }
        self.field.check().map_err(|reason| PlotError::BadField { title: title(), reason })?;
        let (vmin, vmax) = min_max(self.field.values.iter().copied().filter(|v| v.is_finite()));
        if vmin > vmax {
            return Err(PlotError::NoFiniteData { title: title() });
        }
        if !(vmax - vmin).is_finite() {
            return Err(PlotError::BadField { title: title(), reason: "the value range overflows".into() });
        }
        let mut svg = String::new();
        self.draw(vmin, vmax, &mut svg).map_err(|e| match e {
            DrawFail::NoRoom => PlotError::TooSmall { title: title(), width: self.width, height: self.height },
            DrawFail::Render(message) => PlotError::Render { title: title(), message },
        })?;
        Ok(svg)
    }

    /// Write the SVG atomically (temp file in the same folder + rename).
    pub fn write(&self, path: &Path) -> Result<(), PlotError> {
        write_atomic(path, &self.to_svg()?)
    }

    /// Band edges: round numbers covering `vmin..vmax` (a constant field gets a small range around its value).
    fn band_edges(&self, vmin: f64, vmax: f64) -> Vec<f64> {
        let (lo, hi) = if vmax > vmin {
            (vmin, vmax)
        } else {
            let half = if vmin != 0.0 { nice_step(vmin.abs() * 0.1) } else { 1.0 };
            (vmin - half, vmin + half)
        };
        let step = nice_step((hi - lo) / self.bands.max(1) as f64);
        let k0 = (lo / step).floor();
        let k1 = (hi / step).ceil().max(k0 + 1.0);
        let n = ((k1 - k0) as usize).clamp(1, 1000);
        (0..=n).map(|k| (k0 + k as f64) * step).collect()
    }

    /// Draw the map of values `vmin..vmax` into `svg`. The steps paint in this order, each over the ones before.
    fn draw(&self, vmin: f64, vmax: f64, svg: &mut String) -> Result<(), DrawFail> {
        let f = &self.field;
        let bands = self.colour_bands(vmin, vmax);
        let captions = self.captions();
        let layout = self.layout(&bands, captions.count())?;
        let root = SVGBackend::with_string(svg, (self.width, layout.height as u32)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let x_axis = Axis::exact(f.x_range.0, f.x_range.1, (layout.mw / 90.0).max(2.0) as usize);
        let mut d_axis = Axis::exact(f.depth_range.0, f.depth_range.1, (layout.mh / 50.0).max(2.0) as usize);
        d_axis.reversed = true;
        let mut chart = layout.chart_on(&root, &x_axis, &d_axis)?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        let canvas = MapCanvas { root: &root, coord: chart.as_coord_spec().clone(), xr, yr };

        self.draw_bands(&canvas, &bands)?;
        if captions.has_nan {
            self.draw_missing_cells(&canvas)?;
        }
        let levels: Vec<f64> = self.levels.iter().copied().filter(|l| l.is_finite()).collect();
        let lines = self.draw_contour_lines(&canvas, &levels)?;
        canvas.draw_axes(&mut chart, &x_axis, &d_axis)?;
        let mut taken = self.draw_markers(&canvas, &captions.marks)?;
        canvas.draw_contour_labels(&levels, &lines, bands.step, &mut taken)?;
        canvas.draw_colour_bar(&layout, &bands, &levels)?;
        self.draw_titles(&canvas, &layout)?;
        canvas.draw_captions(&layout, &captions)?;
        root.present().map_err(|e| err(&e))?;
        Ok(())
    }

    /// The colour bands for values `vmin..vmax`: round edges (`band_edges`) and a colour for each band.
    fn colour_bands(&self, vmin: f64, vmax: f64) -> Bands {
        let edges = self.band_edges(vmin, vmax);
        let nb = edges.len() - 1;
        let colors = (0..nb).map(|k| self.colormap.at((k as f64 + 0.5) / nb as f64).color()).collect();
        let step = edges[1] - edges[0];
        Bands { edges, colors, step }
    }

    /// Captions under the map: the maximum, the other markers, missing data.
    fn captions(&self) -> MapCaptions {
        let f = &self.field;
        let unit = |u: &Option<String>| match u.as_deref().map(str::trim) {
            None | Some("" | "1" | "-" | "–") => String::new(),
            Some(u) => format!(" {u}"),
        };
        let (xu, du, vu) = (unit(&self.x_unit), unit(&self.depth_unit), unit(&self.value_unit));
        let mut marks: Vec<(f64, f64, String)> = Vec::new();
        if self.mark_max {
            if let Some((x, d, v)) = f.max() {
                let name = if self.value_label.is_empty() { "value" } else { self.value_label.as_str() };
                let text = format!(
                    "max {name} = {}{vu} at {} = {}{xu}, {} = {}{du}",
                    fmt_sig(v),
                    self.x_label,
                    fmt_sig(x),
                    self.depth_label,
                    fmt_sig(d)
                );
                marks.push((x, d, text));
            }
        }
        for m in &self.markers {
            let text = format!(
                "{} at {} = {}{xu}, {} = {}{du}",
                m.label,
                self.x_label,
                fmt_sig(m.x),
                self.depth_label,
                fmt_sig(m.depth)
            );
            marks.push((m.x, m.depth, text));
        }
        MapCaptions { marks, has_nan: f.values.iter().any(|v| !v.is_finite()) }
    }

    /// Layout: room for the title, the tick labels and axis texts, the colour bar and `captions` caption lines
    /// around the map, which gets the rest (to scale if `equal_aspect`).
    fn layout(&self, bands: &Bands, captions: usize) -> Result<MapLayout, DrawFail> {
        let f = &self.field;
        let (width, height) = (f64::from(self.width), f64::from(self.height));
        let x_text = with_unit(&self.x_label, self.x_unit.as_deref());
        let d_text = with_unit(&self.depth_label, self.depth_unit.as_deref());
        let v_text = with_unit(&self.value_label, self.value_unit.as_deref());
        let margin = f64::from(MARGIN);
        let title_h = if self.title.is_empty() { 0.0 } else { TITLE_SIZE * 1.5 };
        let top = margin + title_h;
        let x_tick_h = TICK_SIZE * 1.2 + 8.0;
        let desc_h = DESC_SIZE * 1.5;
        let caption_h = CAPTION_SIZE * 1.6;
        let bottom = margin + x_tick_h + desc_h + captions as f64 * caption_h;
        // Tick labels depend on the axis length; estimate with the axes at their largest.
        let d_axis_est =
            Axis::exact(f.depth_range.0, f.depth_range.1, ((height - top - bottom) / 50.0).max(2.0) as usize);
        let d_tick_w =
            d_axis_est.bold.iter().map(|v| text_width(&d_axis_est.label(*v), TICK_SIZE)).fold(0.0, f64::max) + 14.0;
        let left = margin + desc_h + d_tick_w;
        let bar_tick_w = bands
            .edges
            .iter()
            .map(|v| text_width(&fmt_linear(*v, bands.step, bands.magnitude()), TICK_SIZE))
            .fold(0.0, f64::max);
        let right = BAR_GAP + BAR_WIDTH + 8.0 + bar_tick_w + 8.0 + desc_h + margin;
        let (aw, ah) = (width - left - right, height - top - bottom);
        if aw < 40.0 || ah < 40.0 {
            return Err(DrawFail::NoRoom);
        }
        let (xs, zs) = (f.x_range.1 - f.x_range.0, f.depth_range.1 - f.depth_range.0);
        let (mw, mh) = if self.equal_aspect {
            let s = (aw / xs).min(ah / zs);
            ((s * xs).max(1.0), (s * zs).max(1.0))
        } else {
            (aw, ah)
        };
        // The map with its axes and colour bar centred horizontally; height the map does not use is trimmed from
        // the figure.
        Ok(MapLayout {
            x_text,
            d_text,
            v_text,
            width,
            height: (height - (ah - mh)).round(),
            x_tick_h,
            desc_h,
            caption_h,
            d_tick_w,
            bar_tick_w,
            x0: (left + (aw - mw) / 2.0).round(),
            y0: top.round(),
            mw: mw.round(),
            mh: mh.round(),
        })
    }

    /// Filled bands, painted from the lowest up: layer k covers where the field is ≥ edge k (whole runs of cells
    /// as one rectangle, the cells the edge crosses as polygons).
    fn draw_bands(&self, canvas: &MapCanvas<'_, '_>, bands: &Bands) -> Result<(), String> {
        let f = &self.field;
        for (k, color) in bands.colors.iter().enumerate() {
            let level = bands.edges[k];
            for iz in 0..f.nz - 1 {
                let mut run: Option<usize> = None;
                for ix in 0..f.nx {
                    let c = if ix + 1 < f.nx { Some(f.cell(ix, iz)) } else { None };
                    let full = c.is_some_and(|c| all_finite(&c) && (k == 0 || c.iter().all(|v| *v >= level)));
                    match (full, run) {
                        (true, None) => run = Some(ix),
                        (false, Some(start)) => {
                            let [a, b] = canvas.cell_run(f, start, ix, iz);
                            canvas.root.draw(&Rectangle::new([a, b], color.filled())).map_err(|e| err(&e))?;
                            run = None;
                        }
                        _ => {}
                    }
                    if let Some(c) = c.filter(|c| k > 0 && all_finite(c)) {
                        let (lo, hi) = min_max(c.iter().copied());
                        if lo < level && hi >= level {
                            for poly in cell_superlevel(f, ix, iz, &c, level) {
                                let pts: Vec<(i32, i32)> = poly.into_iter().map(|p| canvas.px(p)).collect();
                                canvas.root.draw(&Polygon::new(pts, color.filled())).map_err(|e| err(&e))?;
                            }
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Cells with a missing corner, in grey (runs of them as one rectangle).
    fn draw_missing_cells(&self, canvas: &MapCanvas<'_, '_>) -> Result<(), String> {
        let f = &self.field;
        for iz in 0..f.nz - 1 {
            let mut run: Option<usize> = None;
            for ix in 0..f.nx {
                let missing = ix + 1 < f.nx && !all_finite(&f.cell(ix, iz));
                match (missing, run) {
                    (true, None) => run = Some(ix),
                    (false, Some(start)) => {
                        let [a, b] = canvas.cell_run(f, start, ix, iz);
                        canvas.root.draw(&Rectangle::new([a, b], NO_DATA.filled())).map_err(|e| err(&e))?;
                        run = None;
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }

    /// Contour lines at `levels`: a white halo under a dark line shows on every colour of the map. Returns the
    /// lines of each level, in pixels.
    fn draw_contour_lines(&self, canvas: &MapCanvas<'_, '_>, levels: &[f64]) -> Result<Vec<Vec<PixelLine>>, String> {
        let lines: Vec<Vec<PixelLine>> = levels
            .iter()
            .map(|&l| {
                let level_lines = self.field.contour_lines(l).into_iter();
                level_lines.map(|line| line.into_iter().map(|p| canvas.px(p)).collect()).collect()
            })
            .collect();
        for pass in [WHITE.mix(0.8).stroke_width(3), RGBColor(20, 20, 20).stroke_width(1)] {
            for line in lines.iter().flatten() {
                canvas.root.draw(&PathElement::new(line.clone(), pass)).map_err(|e| err(&e))?;
            }
        }
        Ok(lines)
    }

    /// Markers at the marked points that lie on the map (the others are only captioned). Returns the pixel boxes
    /// they cover, which contour labels avoid.
    fn draw_markers(&self, canvas: &MapCanvas<'_, '_>, marks: &[(f64, f64, String)]) -> Result<Vec<[f64; 4]>, String> {
        let f = &self.field;
        let inside =
            |(x, d): (f64, f64)| x >= f.x_range.0 && x <= f.x_range.1 && d >= f.depth_range.0 && d <= f.depth_range.1;
        let mut taken: Vec<[f64; 4]> = Vec::new();
        for (i, (x, d, _)) in marks.iter().enumerate() {
            if inside((*x, *d)) {
                let p = canvas.px((*x, *d));
                let p = (f64::from(p.0), f64::from(p.1));
                draw_marker(canvas.root, p, MAP_MARKERS[i % MAP_MARKERS.len()], BLACK, MAP_MARKER_SIZE)?;
                let r = MAP_MARKER_SIZE * 1.6;
                taken.push([p.0 - r, p.1 - r, p.0 + r, p.1 + r]);
            }
        }
        Ok(taken)
    }

    /// Title above the map; axis texts below it and left of it.
    fn draw_titles(&self, canvas: &MapCanvas<'_, '_>, layout: &MapLayout) -> Result<(), String> {
        let (root, xr, yr) = (canvas.root, &canvas.xr, &canvas.yr);
        let (width, margin) = (layout.width, f64::from(MARGIN));
        if !self.title.is_empty() {
            let size = fit_font(TITLE_SIZE, &self.title, width - 20.0);
            text(root, &self.title, to_px((width / 2.0, margin + TITLE_SIZE * 0.6)), size, Anchor::Center, false)?;
        }
        let mid_x = f64::from(xr.start + xr.end) / 2.0;
        let x_text = &layout.x_text;
        if !x_text.is_empty() {
            let size = fit_font(DESC_SIZE, x_text, width - 2.0 * margin);
            let y = f64::from(yr.end) + layout.x_tick_h + layout.desc_h / 2.0;
            text(root, x_text, to_px((mid_x, y)), size, Anchor::Center, false)?;
        }
        let d_text = &layout.d_text;
        if !d_text.is_empty() {
            let (by_top, by_bottom) = (f64::from(yr.start), f64::from(yr.end));
            let size = fit_font(DESC_SIZE, d_text, by_bottom - by_top + 40.0);
            let x = f64::from(xr.start) - layout.d_tick_w - layout.desc_h / 2.0;
            text(root, d_text, to_px((x, (by_top + by_bottom) / 2.0)), size, Anchor::Center, true)?;
        }
        Ok(())
    }
}

/// Pixel points of a contour line.
type PixelLine = Vec<(i32, i32)>;

/// Colour bar spacing from the map, and width, in pixels.
const BAR_GAP: f64 = 18.0;
const BAR_WIDTH: f64 = 18.0;

/// The colour bands of a contour map.
struct Bands {
    /// Band edges, increasing: band `k` spans `edges[k]..edges[k + 1]`.
    edges: Vec<f64>,
    /// Colour of each band.
    colors: Vec<RGBColor>,
    /// Spacing of the edges.
    step: f64,
}

impl Bands {
    fn lo(&self) -> f64 {
        self.edges[0]
    }

    fn hi(&self) -> f64 {
        self.edges[self.edges.len() - 1]
    }

    /// The largest magnitude of an edge (sets the format of the colour bar's labels).
    fn magnitude(&self) -> f64 {
        self.lo().abs().max(self.hi().abs())
    }
}

/// What is captioned under a contour map.
struct MapCaptions {
    /// Marked points `(x, depth, caption)`: the maximum (if marked), then the markers.
    marks: Vec<(f64, f64, String)>,
    /// Some value is not finite: such cells are grey, with a caption saying so.
    has_nan: bool,
}

impl MapCaptions {
    /// Number of caption lines.
    fn count(&self) -> usize {
        self.marks.len() + usize::from(self.has_nan)
    }
}

/// Where the parts of a contour map go, in pixels.
struct MapLayout {
    /// Axis texts (label and unit) of x, depth and the values.
    x_text: String,
    d_text: String,
    v_text: String,
    /// Size of the figure (its height trimmed to what the map uses).
    width: f64,
    height: f64,
    /// Height of the x tick labels, of an axis text and of a caption line.
    x_tick_h: f64,
    desc_h: f64,
    caption_h: f64,
    /// Width of the depth tick labels and of the colour bar's tick labels.
    d_tick_w: f64,
    bar_tick_w: f64,
    /// Top left corner and size of the map.
    x0: f64,
    y0: f64,
    mw: f64,
    mh: f64,
}

impl MapLayout {
    /// The chart of the map on `root`: its plotting area the map, with the tick labels left of and below it.
    fn chart_on<'a, 'b>(
        &self,
        root: &'a DrawingArea<SVGBackend<'b>, Shift>,
        x_axis: &Axis,
        d_axis: &Axis,
    ) -> Result<ChartContext<'a, SVGBackend<'b>, Cartesian2d<Axis, Axis>>, String> {
        let mut builder = ChartBuilder::on(root);
        builder
            .margin_left((self.x0 - self.d_tick_w).max(0.0) as u32)
            .margin_top(self.y0 as u32)
            .margin_right((self.width - self.x0 - self.mw).max(0.0) as u32)
            .margin_bottom((self.height - self.y0 - self.mh - self.x_tick_h).max(0.0) as u32)
            .x_label_area_size(self.x_tick_h as u32)
            .y_label_area_size(self.d_tick_w as u32);
        builder.build_cartesian_2d(x_axis.clone(), d_axis.clone()).map_err(|e| err(&e))
    }
}

/// A contour map being drawn: the figure, the map's coordinates and its pixel extent.
struct MapCanvas<'a, 'b> {
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    coord: Cartesian2d<Axis, Axis>,
    /// Pixel columns of the map.
    xr: Range<i32>,
    /// Pixel rows of the map.
    yr: Range<i32>,
}

impl MapCanvas<'_, '_> {
    /// The pixel of the point `(x, depth)`.
    fn px(&self, p: (f64, f64)) -> (i32, i32) {
        self.coord.translate(&p)
    }

    /// Pixel rectangle of the cells ix0..ix1 of row iz, one pixel larger to the right and below (inside the
    /// map): abutting shapes would otherwise show anti-aliasing seams when the SVG is scaled.
    fn cell_run(&self, f: &Field, ix0: usize, ix1: usize, iz: usize) -> [(i32, i32); 2] {
        let (a, b) = (self.px((f.x(ix0), f.depth(iz))), self.px((f.x(ix1), f.depth(iz + 1))));
        [a, ((b.0 + 1).min(self.xr.end), (b.1 + 1).min(self.yr.end))]
    }

    /// Axes, ticks and frame.
    fn draw_axes(
        &self,
        chart: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<Axis, Axis>>,
        x_axis: &Axis,
        d_axis: &Axis,
    ) -> Result<(), String> {
        let x_fmt = |v: &f64| x_axis.label(*v);
        let d_fmt = |v: &f64| d_axis.label(*v);
        chart
            .configure_mesh()
            .disable_mesh()
            .axis_style(BLACK.stroke_width(1))
            .label_style((FONT, TICK_SIZE))
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&d_fmt)
            .draw()
            .map_err(|e| err(&e))?;
        let (xr, yr) = (&self.xr, &self.yr);
        self.root
            .draw(&Rectangle::new([(xr.start, yr.start), (xr.end, yr.end)], BLACK.stroke_width(1)))
            .map_err(|e| err(&e))
    }

    /// Contour labels: a few of the `levels`, each on its longest line, where the label overlaps neither another
    /// nor a box in `taken` (the labels' boxes are added to it). `bar_step` sets the decimals of a single level.
    fn draw_contour_labels(
        &self,
        levels: &[f64],
        lines: &[Vec<PixelLine>],
        bar_step: f64,
        taken: &mut Vec<[f64; 4]>,
    ) -> Result<(), String> {
        let stride = levels.len().div_ceil(6).max(1);
        let level_step =
            levels.windows(2).map(|w| (w[1] - w[0]).abs()).filter(|d| *d > 0.0).fold(f64::INFINITY, f64::min);
        let level_step = if level_step.is_finite() { level_step } else { bar_step };
        let (xr, yr) = (&self.xr, &self.yr);
        let frame = [f64::from(xr.start), f64::from(yr.start), f64::from(xr.end), f64::from(yr.end)];
        for (k, (&level, level_lines)) in levels.iter().zip(lines).enumerate() {
            if k % stride != 0 {
                continue;
            }
            let label = fmt_level(level, level_step);
            let size = (text_width(&label, MAP_LABEL_SIZE) + 6.0, MAP_LABEL_SIZE + 2.0);
            if let Some((cx, cy, b)) = label_spot(level_lines, size, &frame, taken) {
                taken.push(b);
                self.root
                    .draw(&Rectangle::new([to_px((b[0], b[1])), to_px((b[2], b[3]))], WHITE.mix(0.85).filled()))
                    .map_err(|e| err(&e))?;
                text(self.root, &label, to_px((cx, cy)), MAP_LABEL_SIZE, Anchor::Center, false)?;
            }
        }
        Ok(())
    }

    /// Colour bar right of the map: the bands, ticks at band edges (every few, so labels do not collide), contour
    /// levels, and the value text.
    fn draw_colour_bar(&self, layout: &MapLayout, bands: &Bands, levels: &[f64]) -> Result<(), String> {
        let root = self.root;
        let (nb, e_lo, e_hi, bar_step) = (bands.colors.len(), bands.lo(), bands.hi(), bands.step);
        let bx0 = f64::from(self.xr.end) + BAR_GAP;
        let bx1 = bx0 + BAR_WIDTH;
        let (by_top, by_bottom) = (f64::from(self.yr.start), f64::from(self.yr.end));
        let bar_y = |v: f64| by_bottom - (v - e_lo) / (e_hi - e_lo) * (by_bottom - by_top);
        for (k, color) in bands.colors.iter().enumerate() {
            // One pixel into the next band up (drawn over it next), against anti-aliasing seams.
            let overlap = if k + 1 < nb { 1.0 } else { 0.0 };
            let (a, b) = (to_px((bx0, bar_y(bands.edges[k + 1]) - overlap)), to_px((bx1, bar_y(bands.edges[k]))));
            root.draw(&Rectangle::new([a, b], color.filled())).map_err(|e| err(&e))?;
        }
        for &l in levels.iter().filter(|l| **l >= e_lo && **l <= e_hi) {
            let y = bar_y(l);
            root.draw(&PathElement::new(vec![to_px((bx0, y)), to_px((bx1, y))], RGBColor(20, 20, 20).stroke_width(2)))
                .map_err(|e| err(&e))?;
        }
        root.draw(&Rectangle::new([to_px((bx0, by_top)), to_px((bx1, by_bottom))], BLACK.stroke_width(1)))
            .map_err(|e| err(&e))?;
        let per_label = (TICK_SIZE * 1.3) / ((by_bottom - by_top) / nb as f64);
        let every = nice_stride(per_label.ceil().max(1.0) as usize);
        for &v in &bands.edges {
            // Label round multiples of the stride (0, 0.2, 0.4 rather than 0.1, 0.3, …).
            if ((v / bar_step).round() as i64).rem_euclid(every as i64) != 0 {
                continue;
            }
            let y = bar_y(v);
            root.draw(&PathElement::new(vec![to_px((bx1, y)), to_px((bx1 + 5.0, y))], BLACK.stroke_width(1)))
                .map_err(|e| err(&e))?;
            let label = fmt_linear(v, bar_step * every as f64, bands.magnitude());
            text(root, &label, to_px((bx1 + 8.0, y)), TICK_SIZE, Anchor::Left, false)?;
        }
        let v_text = &layout.v_text;
        if !v_text.is_empty() {
            let x = bx1 + 8.0 + layout.bar_tick_w + 8.0 + layout.desc_h / 2.0;
            let size = fit_font(DESC_SIZE, v_text, by_bottom - by_top + 40.0);
            text(root, v_text, to_px((x, (by_top + by_bottom) / 2.0)), size, Anchor::Center, true)?;
        }
        Ok(())
    }

    /// Captions under the map, each after its marker: the marked points, then missing data.
    fn draw_captions(&self, layout: &MapLayout, captions: &MapCaptions) -> Result<(), String> {
        let (root, width, margin) = (self.root, layout.width, f64::from(MARGIN));
        let mut cy = f64::from(self.yr.end) + layout.x_tick_h + layout.desc_h + layout.caption_h / 2.0;
        let caption_x = margin + 12.0;
        for (i, (_, _, s)) in captions.marks.iter().enumerate() {
            draw_marker(root, (caption_x, cy), MAP_MARKERS[i % MAP_MARKERS.len()], BLACK, MAP_MARKER_SIZE)?;
            let size = fit_font(CAPTION_SIZE, s, width - caption_x - 20.0 - margin);
            text(root, s, to_px((caption_x + 16.0, cy)), size, Anchor::Left, false)?;
            cy += layout.caption_h;
        }
        if captions.has_nan {
            let a = to_px((caption_x - 7.0, cy - 7.0));
            let b = to_px((caption_x + 7.0, cy + 7.0));
            root.draw(&Rectangle::new([a, b], NO_DATA.filled())).map_err(|e| err(&e))?;
            root.draw(&Rectangle::new([a, b], BLACK.stroke_width(1))).map_err(|e| err(&e))?;
            let no_value = "no value (non-finite data)";
            text(root, no_value, to_px((caption_x + 16.0, cy)), CAPTION_SIZE, Anchor::Left, false)?;
        }
        Ok(())
    }
}

/// Where a label of `w` × `h` pixels goes on a contour level's `lines`: at one of a few fractions of the length
/// of one of its three longest lines, 2 pixels inside `frame` and overlapping no box in `taken`. Returns the
/// label's centre and box.
fn label_spot(
    lines: &[PixelLine],
    (w, h): (f64, f64),
    frame: &[f64; 4],
    taken: &[[f64; 4]],
) -> Option<(f64, f64, [f64; 4])> {
    let mut order: Vec<&PixelLine> = lines.iter().filter(|l| l.len() >= 2).collect();
    order.sort_by(|a, b| polyline_length(b).total_cmp(&polyline_length(a)));
    order.iter().take(3).find_map(|line| {
        [0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875].iter().find_map(|&t| {
            let (cx, cy) = point_along(line, t);
            let b = [cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0];
            let within =
                b[0] >= frame[0] + 2.0 && b[2] <= frame[2] - 2.0 && b[1] >= frame[1] + 2.0 && b[3] <= frame[3] - 2.0;
            (within && !taken.iter().any(|o| overlaps(o, &b))).then_some((cx, cy, b))
        })
    })
}

/// All four corner values are finite.
fn all_finite(c: &[f64; 4]) -> bool {
    c.iter().all(|v| v.is_finite())
}

/// Why a contour map could not be drawn.
enum DrawFail {
    /// The size leaves no room for the map beside its axes and colour bar.
    NoRoom,
    /// The plotting library failed.
    Render(String),
}

impl From<String> for DrawFail {
    fn from(message: String) -> DrawFail {
        DrawFail::Render(message)
    }
}

/// 1, 2, 5, 10, 20, 50, … : the smallest such stride ≥ `n`.
fn nice_stride(n: usize) -> usize {
    let mut base = 1;
    loop {
        for m in [1, 2, 5] {
            if m * base >= n {
                return m * base;
            }
        }
        base *= 10;
    }
}

fn overlaps(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

fn polyline_length(line: &[(i32, i32)]) -> f64 {
    line.windows(2).map(|w| f64::from(w[1].0 - w[0].0).hypot(f64::from(w[1].1 - w[0].1))).sum()
}

/// The point at fraction `t` of a pixel polyline's length.
fn point_along(line: &[(i32, i32)], t: f64) -> (f64, f64) {
    let target = t * polyline_length(line);
    let mut acc = 0.0;
    for w in line.windows(2) {
        let (a, b) = ((f64::from(w[0].0), f64::from(w[0].1)), (f64::from(w[1].0), f64::from(w[1].1)));
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        if acc + len >= target && len > 0.0 {
            let s = (target - acc) / len;
            return (a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1));
        }
        acc += len;
    }
    let p = line.last().copied().unwrap_or((0, 0));
    (f64::from(p.0), f64::from(p.1))
}

/// The part of cell `(ix, iz)` where the field is ≥ `level`, as polygons of `(x, depth)` points, bounded by the
/// same straight pieces as [`Field::contour_lines`] draws (crossings interpolated linearly along the edges, saddles
/// resolved by the corners' mean): the cell's boundary is walked keeping the corners above the level and the
/// crossings. A saddle whose centre is below the level gives two pieces, one round each corner above it.
fn cell_superlevel(f: &Field, ix: usize, iz: usize, c: &[f64; 4], level: f64) -> Vec<Vec<(f64, f64)>> {
    let nodes = [(ix, iz), (ix + 1, iz), (ix + 1, iz + 1), (ix, iz + 1)];
    let pos = |k: usize| (f.x(nodes[k].0), f.depth(nodes[k].1));
    let inside = c.map(|v| v >= level);
    // Crossing on the edge from corner k to corner k+1, interpolated from the lower-indexed node as in
    // `contour_lines`, so that the fill and the lines share their points exactly.
    let crossing = |k: usize| {
        let (a, b) = if k < 2 { (k, k + 1) } else { ((k + 1) % 4, k) };
        let t = ((level - c[a]) / (c[b] - c[a])).clamp(0.0, 1.0);
        let (pa, pb) = (pos(a), pos(b));
        (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1))
    };
    let crossed: Vec<usize> = (0..4).filter(|&k| inside[k] != inside[(k + 1) % 4]).collect();
    let centre_inside = (c[0] + c[1] + c[2] + c[3]) / 4.0 >= level;
    if crossed.len() == 4 && centre_inside != inside[0] {
        // Two separate pieces round the two corners above the level.
        return (0..4).filter(|&k| inside[k]).map(|k| vec![crossing((k + 3) % 4), pos(k), crossing(k)]).collect();
    }
    let mut poly = Vec::with_capacity(6);
    for k in 0..4 {
        if inside[k] {
            poly.push(pos(k));
        }
        if inside[k] != inside[(k + 1) % 4] {
            poly.push(crossing(k));
        }
    }
    if poly.len() >= 3 {
        vec![poly]
    } else {
        Vec::new()
    }
}

/// A contour level's label: as many decimals as the spacing of the levels needs, trailing zeros dropped.
fn fmt_level(level: f64, spacing: f64) -> String {
    if level == 0.0 {
        return "0".to_string();
    }
    if !(1e-3..1e5).contains(&level.abs()) {
        return fmt_sig(level);
    }
    // Enough decimals to tell neighbouring levels apart, and to write this level exactly if a few more do.
    let need = if spacing > 0.0 && spacing.is_finite() { (-(spacing.log10().floor()) as i32).max(0) } else { 0 };
    let exact = (0..=8).find(|&d| {
        let p = 10f64.powi(d);
        ((level * p).round() / p - level).abs() <= 1e-9 * level.abs()
    });
    let decimals = exact.unwrap_or(need + 2).max(need).min(12) as usize;
    format!("{level:.decimals$}")
}

/// Matplotlib's viridis colour map (van der Walt & Smith), 256 entries, rounded to 8 bits.
#[rustfmt::skip]
const VIRIDIS: [[u8; 3]; 256] = [
    [68, 1, 84], [68, 2, 86], [69, 4, 87], [69, 5, 89], [70, 7, 90], [70, 8, 92], [70, 10, 93], [70, 11, 94],
    [71, 13, 96], [71, 14, 97], [71, 16, 99], [71, 17, 100], [71, 19, 101], [72, 20, 103], [72, 22, 104], [72, 23, 105],
    [72, 24, 106], [72, 26, 108], [72, 27, 109], [72, 28, 110], [72, 29, 111], [72, 31, 112], [72, 32, 113], [72, 33, 115],
    [72, 35, 116], [72, 36, 117], [72, 37, 118], [72, 38, 119], [72, 40, 120], [72, 41, 121], [71, 42, 122], [71, 44, 122],
    [71, 45, 123], [71, 46, 124], [71, 47, 125], [70, 48, 126], [70, 50, 126], [70, 51, 127], [70, 52, 128], [69, 53, 129],
    [69, 55, 129], [69, 56, 130], [68, 57, 131], [68, 58, 131], [68, 59, 132], [67, 61, 132], [67, 62, 133], [66, 63, 133],
    [66, 64, 134], [66, 65, 134], [65, 66, 135], [65, 68, 135], [64, 69, 136], [64, 70, 136], [63, 71, 136], [63, 72, 137],
    [62, 73, 137], [62, 74, 137], [62, 76, 138], [61, 77, 138], [61, 78, 138], [60, 79, 138], [60, 80, 139], [59, 81, 139],
    [59, 82, 139], [58, 83, 139], [58, 84, 140], [57, 85, 140], [57, 86, 140], [56, 88, 140], [56, 89, 140], [55, 90, 140],
    [55, 91, 141], [54, 92, 141], [54, 93, 141], [53, 94, 141], [53, 95, 141], [52, 96, 141], [52, 97, 141], [51, 98, 141],
    [51, 99, 141], [50, 100, 142], [50, 101, 142], [49, 102, 142], [49, 103, 142], [49, 104, 142], [48, 105, 142], [48, 106, 142],
    [47, 107, 142], [47, 108, 142], [46, 109, 142], [46, 110, 142], [46, 111, 142], [45, 112, 142], [45, 113, 142], [44, 113, 142],
    [44, 114, 142], [44, 115, 142], [43, 116, 142], [43, 117, 142], [42, 118, 142], [42, 119, 142], [42, 120, 142], [41, 121, 142],
    [41, 122, 142], [41, 123, 142], [40, 124, 142], [40, 125, 142], [39, 126, 142], [39, 127, 142], [39, 128, 142], [38, 129, 142],
    [38, 130, 142], [38, 130, 142], [37, 131, 142], [37, 132, 142], [37, 133, 142], [36, 134, 142], [36, 135, 142], [35, 136, 142],
    [35, 137, 142], [35, 138, 141], [34, 139, 141], [34, 140, 141], [34, 141, 141], [33, 142, 141], [33, 143, 141], [33, 144, 141],
    [33, 145, 140], [32, 146, 140], [32, 146, 140], [32, 147, 140], [31, 148, 140], [31, 149, 139], [31, 150, 139], [31, 151, 139],
    [31, 152, 139], [31, 153, 138], [31, 154, 138], [30, 155, 138], [30, 156, 137], [30, 157, 137], [31, 158, 137], [31, 159, 136],
    [31, 160, 136], [31, 161, 136], [31, 161, 135], [31, 162, 135], [32, 163, 134], [32, 164, 134], [33, 165, 133], [33, 166, 133],
    [34, 167, 133], [34, 168, 132], [35, 169, 131], [36, 170, 131], [37, 171, 130], [37, 172, 130], [38, 173, 129], [39, 173, 129],
    [40, 174, 128], [41, 175, 127], [42, 176, 127], [44, 177, 126], [45, 178, 125], [46, 179, 124], [47, 180, 124], [49, 181, 123],
    [50, 182, 122], [52, 182, 121], [53, 183, 121], [55, 184, 120], [56, 185, 119], [58, 186, 118], [59, 187, 117], [61, 188, 116],
    [63, 188, 115], [64, 189, 114], [66, 190, 113], [68, 191, 112], [70, 192, 111], [72, 193, 110], [74, 193, 109], [76, 194, 108],
    [78, 195, 107], [80, 196, 106], [82, 197, 105], [84, 197, 104], [86, 198, 103], [88, 199, 101], [90, 200, 100], [92, 200, 99],
    [94, 201, 98], [96, 202, 96], [99, 203, 95], [101, 203, 94], [103, 204, 92], [105, 205, 91], [108, 205, 90], [110, 206, 88],
    [112, 207, 87], [115, 208, 86], [117, 208, 84], [119, 209, 83], [122, 209, 81], [124, 210, 80], [127, 211, 78], [129, 211, 77],
    [132, 212, 75], [134, 213, 73], [137, 213, 72], [139, 214, 70], [142, 214, 69], [144, 215, 67], [147, 215, 65], [149, 216, 64],
    [152, 216, 62], [155, 217, 60], [157, 217, 59], [160, 218, 57], [162, 218, 55], [165, 219, 54], [168, 219, 52], [170, 220, 50],
    [173, 220, 48], [176, 221, 47], [178, 221, 45], [181, 222, 43], [184, 222, 41], [186, 222, 40], [189, 223, 38], [192, 223, 37],
    [194, 223, 35], [197, 224, 33], [200, 224, 32], [202, 225, 31], [205, 225, 29], [208, 225, 28], [210, 226, 27], [213, 226, 26],
    [216, 226, 25], [218, 227, 25], [221, 227, 24], [223, 227, 24], [226, 228, 24], [229, 228, 25], [231, 228, 25], [234, 229, 26],
    [236, 229, 27], [239, 229, 28], [241, 229, 29], [244, 230, 30], [246, 230, 32], [248, 230, 33], [251, 231, 35], [253, 231, 37],
];

/// Matplotlib's cividis colour map (Nuñez, Anderton & Renslow 2018), 256 entries, rounded to 8 bits.
#[rustfmt::skip]
const CIVIDIS: [[u8; 3]; 256] = [
    [0, 34, 78], [0, 35, 79], [0, 36, 81], [0, 37, 83], [0, 37, 84], [0, 38, 86], [0, 39, 88], [0, 40, 89],
    [0, 40, 91], [0, 41, 93], [0, 42, 95], [0, 42, 97], [0, 43, 98], [0, 44, 100], [0, 44, 102], [0, 45, 104],
    [0, 46, 106], [0, 46, 108], [0, 47, 109], [0, 48, 111], [0, 48, 112], [0, 49, 112], [0, 49, 113], [1, 50, 113],
    [5, 51, 113], [8, 51, 112], [12, 52, 112], [15, 53, 112], [18, 53, 112], [20, 54, 112], [22, 55, 112], [24, 55, 111],
    [26, 56, 111], [28, 57, 111], [30, 58, 111], [32, 58, 111], [33, 59, 110], [35, 60, 110], [36, 60, 110], [38, 61, 110],
    [39, 62, 110], [41, 63, 110], [42, 63, 109], [43, 64, 109], [45, 65, 109], [46, 65, 109], [47, 66, 109], [49, 67, 109],
    [50, 67, 109], [51, 68, 109], [52, 69, 108], [53, 69, 108], [54, 70, 108], [56, 71, 108], [57, 72, 108], [58, 72, 108],
    [59, 73, 108], [60, 74, 108], [61, 74, 108], [62, 75, 108], [63, 76, 108], [64, 76, 108], [65, 77, 108], [66, 78, 108],
    [67, 78, 108], [68, 79, 108], [69, 80, 108], [70, 81, 108], [71, 81, 108], [72, 82, 108], [73, 83, 108], [74, 83, 108],
    [75, 84, 108], [76, 85, 108], [77, 85, 108], [78, 86, 108], [79, 87, 108], [80, 87, 108], [81, 88, 109], [82, 89, 109],
    [83, 90, 109], [84, 90, 109], [85, 91, 109], [85, 92, 109], [86, 92, 109], [87, 93, 109], [88, 94, 109], [89, 94, 110],
    [90, 95, 110], [91, 96, 110], [92, 97, 110], [93, 97, 110], [94, 98, 110], [94, 99, 111], [95, 99, 111], [96, 100, 111],
    [97, 101, 111], [98, 101, 111], [99, 102, 112], [100, 103, 112], [101, 104, 112], [101, 104, 112], [102, 105, 112], [103, 106, 113],
    [104, 106, 113], [105, 107, 113], [106, 108, 113], [107, 109, 114], [108, 109, 114], [108, 110, 114], [109, 111, 114], [110, 111, 115],
    [111, 112, 115], [112, 113, 115], [113, 114, 116], [114, 114, 116], [114, 115, 116], [115, 116, 117], [116, 116, 117], [117, 117, 117],
    [118, 118, 118], [119, 119, 118], [119, 119, 119], [120, 120, 119], [121, 121, 119], [122, 122, 120], [123, 122, 120], [124, 123, 120],
    [125, 124, 120], [126, 124, 120], [126, 125, 120], [127, 126, 120], [128, 127, 120], [129, 127, 120], [130, 128, 121], [131, 129, 121],
    [132, 130, 121], [133, 130, 121], [134, 131, 121], [135, 132, 120], [136, 133, 120], [137, 133, 120], [138, 134, 120], [139, 135, 120],
    [140, 136, 120], [141, 136, 120], [142, 137, 120], [143, 138, 120], [144, 139, 120], [145, 139, 120], [146, 140, 120], [146, 141, 120],
    [147, 142, 120], [148, 142, 119], [149, 143, 119], [150, 144, 119], [151, 145, 119], [152, 146, 119], [153, 146, 119], [154, 147, 118],
    [155, 148, 118], [156, 149, 118], [157, 149, 118], [158, 150, 118], [159, 151, 117], [160, 152, 117], [161, 153, 117], [162, 153, 117],
    [163, 154, 116], [164, 155, 116], [165, 156, 116], [166, 156, 116], [167, 157, 115], [168, 158, 115], [169, 159, 115], [170, 160, 115],
    [171, 160, 114], [172, 161, 114], [173, 162, 114], [174, 163, 113], [175, 164, 113], [176, 165, 113], [177, 165, 112], [179, 166, 112],
    [180, 167, 111], [181, 168, 111], [182, 169, 111], [183, 169, 110], [184, 170, 110], [185, 171, 109], [186, 172, 109], [187, 173, 109],
    [188, 174, 108], [189, 174, 108], [190, 175, 107], [191, 176, 107], [192, 177, 106], [193, 178, 106], [194, 179, 105], [195, 179, 105],
    [196, 180, 104], [197, 181, 104], [198, 182, 103], [199, 183, 103], [200, 184, 102], [201, 185, 101], [203, 185, 101], [204, 186, 100],
    [205, 187, 99], [206, 188, 99], [207, 189, 98], [208, 190, 98], [209, 191, 97], [210, 192, 96], [211, 192, 95], [212, 193, 95],
    [213, 194, 94], [214, 195, 93], [215, 196, 92], [217, 197, 92], [218, 198, 91], [219, 199, 90], [220, 200, 89], [221, 200, 88],
    [222, 201, 88], [223, 202, 87], [224, 203, 86], [225, 204, 85], [226, 205, 84], [228, 206, 83], [229, 207, 82], [230, 208, 81],
    [231, 209, 80], [232, 210, 79], [233, 211, 78], [234, 211, 76], [235, 212, 75], [237, 213, 74], [238, 214, 73], [239, 215, 72],
    [240, 216, 70], [241, 217, 69], [242, 218, 68], [243, 219, 66], [245, 220, 65], [246, 221, 63], [247, 222, 62], [248, 223, 60],
    [249, 224, 58], [251, 225, 56], [252, 226, 54], [253, 227, 52], [254, 228, 52], [254, 229, 53], [254, 230, 54], [254, 232, 56],
];

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
    fn styles_are_distinct_for_many_series() {
        let n = 30;
        let looks: Vec<Appearance> = (0..n).map(Appearance::for_index).collect();
        for i in 0..n {
            for j in 0..i {
                assert_ne!(looks[i], looks[j], "series {i} and {j} look the same");
            }
        }
        // The first 7 differ in colour, the first 13 in shape (grey print), and a series never repeats the
        // colour and marker of another (as long as colour × marker combinations last: 91).
        for i in 0..91 {
            for j in 0..i {
                let (a, b) = (Appearance::for_index(i), Appearance::for_index(j));
                assert!((a.color, a.marker) != (b.color, b.marker), "{i} {j}");
                if i < 7 {
                    assert_ne!(a.color, b.color);
                }
                if i < 13 {
                    assert_ne!(a.marker, b.marker);
                }
            }
        }
        // Far indices stay distinct (the dash pattern index grows without bound) and do not panic.
        assert_ne!(Appearance::for_index(1_000_000), Appearance::for_index(1_000_000 - 7 * 13));
        assert_eq!(Appearance::for_index(7).dash, Dash::Dashed);
        assert_eq!(Appearance::for_index(0).dash, Dash::Solid);
        // A 30-series chart renders, with every label in the legend.
        let mut chart = Chart::new("many", "x", "y").size(1000, 700);
        for i in 0..n {
            let pts = (0..5).map(|k| (f64::from(k), f64::from(k) * (1.0 + i as f64 / 10.0))).collect();
            chart = chart.add(Series::new(format!("series {i}"), pts, Style::LineMarkers));
        }
        let t = texts(&chart.to_svg().unwrap());
        for i in 0..n {
            assert!(t.contains(&format!("series {i}")));
        }
    }

    #[test]
    fn dash_runs_follow_the_pattern() {
        let line = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)];
        let runs = dash_runs(&line, &[4.0, 3.0]);
        // On along the length 0–4, 7–11 (round the corner at 10), 14–18.
        assert_eq!(
            runs,
            vec![
                vec![(0.0, 0.0), (4.0, 0.0)],
                vec![(7.0, 0.0), (10.0, 0.0), (10.0, 1.0)],
                vec![(10.0, 4.0), (10.0, 8.0)],
            ]
        );
        assert_eq!(dash_runs(&line, &[]), vec![line.to_vec()]);
        assert_eq!(dash_runs(&line, &[0.0, 0.0]), vec![line.to_vec()]);
        assert!(dash_runs(&[], &[1.0, 1.0]).is_empty());
        assert!(Dash::DashDots(2).pattern().len() == 6 && Dash::Solid.pattern().is_empty());
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
        assert_eq!(fmt_sig(0.30012), "0.3001");
        assert_eq!(fmt_sig(1234.5), "1234");
        assert_eq!(fmt_sig(2.5e-7), "2.500e-7");
        assert_eq!(fmt_level(0.15, 0.05), "0.15");
        assert_eq!(fmt_level(0.1, 0.05), "0.10");
        assert_eq!(fmt_level(0.5, 0.25), "0.5");
        assert_eq!(fmt_level(1.0 / 3.0, 0.1), "0.333");
        assert_eq!(fmt_level(20.0, 10.0), "20");
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

    // ---- contour maps ----------------------------------------------------------------------------------------

    fn bump(nx: usize, nz: usize) -> Field {
        Field::from_fn(nx, nz, (-2.0, 2.0), (0.0, 2.0), |x, z| (-(x * x) - 2.0 * (z - 0.7).powi(2)).exp())
    }

    fn bump_map() -> ContourMap {
        ContourMap::new("bump", bump(41, 21))
            .x_axis("x", "mm")
            .depth_axis("depth", "mm")
            .value_axis("s", "MPa")
            .contours(&[0.25, 0.5, 0.75])
            .mark_max()
            .equal_aspect()
    }

    #[test]
    fn field_layout_is_row_major_with_depth_rows() {
        let f = Field::from_fn(3, 2, (0.0, 2.0), (0.0, 10.0), |x, z| x + 100.0 * z);
        assert_eq!(f.values, vec![0.0, 1.0, 2.0, 1000.0, 1001.0, 1002.0]);
        assert_eq!((f.x(2), f.depth(1), f.value(1, 1)), (2.0, 10.0, 1001.0));
        assert_eq!(f.max(), Some((2.0, 10.0, 1002.0)));
        assert!(Field::new(3, 2, vec![0.0; 5], (0.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(1, 2, vec![0.0; 2], (0.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(2, 2, vec![0.0; 4], (1.0, 1.0), (0.0, 1.0)).check().is_err());
        assert!(Field::new(2, 2, vec![0.0; 4], (0.0, 1.0), (0.0, f64::NAN)).check().is_err());
        assert_eq!(Field::new(2, 2, vec![f64::NAN; 4], (0.0, 1.0), (0.0, 1.0)).max(), None);
    }

    #[test]
    fn marching_squares_places_levels_on_a_linear_ramp() {
        // v = 3x on x in [0, 1] (10 cells): the level L contour is the vertical line x = L/3 exactly.
        let f = Field::from_fn(11, 6, (0.0, 1.0), (0.0, 0.5), |x, _| 3.0 * x);
        for level in [0.05, 0.37 * 3.0, 1.5, 2.999] {
            let lines = f.contour_lines(level);
            assert_eq!(lines.len(), 1, "level {level}: one line");
            let line = &lines[0];
            // One point per crossed horizontal edge: all 6 depth rows.
            assert_eq!(line.len(), 6);
            for &(x, _) in line {
                assert!((x - level / 3.0).abs() < 1e-12, "level {level}: x = {x}");
            }
            let (d0, d1) = min_max(line.iter().map(|p| p.1));
            assert_eq!((d0, d1), (0.0, 0.5));
        }
        // A ramp along depth: horizontal lines at the predicted depth.
        let g = Field::from_fn(5, 9, (0.0, 1.0), (0.0, 4.0), |_, z| 10.0 - z);
        let lines = g.contour_lines(7.25);
        assert_eq!(lines.len(), 1);
        assert!(lines[0].iter().all(|p| (p.1 - 2.75).abs() < 1e-12));
        // Levels outside the range, or NaN, have no line.
        assert!(f.contour_lines(-1.0).is_empty() && f.contour_lines(4.0).is_empty());
        assert!(f.contour_lines(f64::NAN).is_empty());
    }

    #[test]
    fn marching_squares_closes_loops_around_a_maximum() {
        // v = -(x² + z²) centred in the grid: the level -r² contour is a closed loop of radius r, to within a
        // fraction of a cell (linear interpolation of a quadratic).
        let h = 0.1;
        let f = Field::from_fn(41, 41, (-2.0, 2.0), (-2.0, 2.0), |x, z| -(x * x + z * z));
        let r: f64 = 1.23;
        let lines = f.contour_lines(-r * r);
        assert_eq!(lines.len(), 1);
        let line = &lines[0];
        assert_eq!(line.first(), line.last(), "closed");
        for &(x, z) in line {
            assert!((x.hypot(z) - r).abs() < 0.1 * h, "radius {}", x.hypot(z));
        }
        // NaN cells break lines but never panic.
        let mut g = f.clone();
        g.values[20 * 41 + 32] = f64::NAN;
        let lines = g.contour_lines(-r * r);
        assert!(!lines.is_empty() && lines.iter().all(|l| l.len() >= 2));
    }

    #[test]
    fn superlevel_pieces_cover_the_right_area() {
        // Linear ramp in a unit cell: the part with v ≥ 0.3 of v = x is 0.7 of the cell.
        let f = Field::from_fn(2, 2, (0.0, 1.0), (0.0, 1.0), |x, _| x);
        let c = [0.0, 1.0, 1.0, 0.0];
        let area: f64 = cell_superlevel(&f, 0, 0, &c, 0.3)
            .iter()
            .map(|p| {
                let n = p.len();
                (0..n).map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1).sum::<f64>().abs() / 2.0
            })
            .sum();
        assert!((area - 0.7).abs() < 1e-12, "{area}");
    }

    #[test]
    fn contour_map_renders_deterministically_with_units_and_caption() {
        let map = bump_map();
        let svg = map.to_svg().unwrap();
        assert_eq!(svg, map.to_svg().unwrap());
        assert_eq!(svg, bump_map().to_svg().unwrap());
        let t = texts(&svg);
        for s in ["bump", "x [mm]", "depth [mm]", "s [MPa]"] {
            assert!(t.iter().any(|x| x == s), "missing {s:?} in {t:?}");
        }
        // The maximum (1 at x = 0, depth 0.7) is captioned with its value and place.
        assert!(t.iter().any(|x| x == "max s = 1.000 MPa at x = 0 mm, depth = 0.7000 mm"), "{t:?}");
        // Contour labels.
        for s in ["0.25", "0.5", "0.75"] {
            assert!(t.iter().any(|x| x == s), "missing contour label {s:?} in {t:?}");
        }
        // Depth grows downward: the depth axis's tick "0" is above its tick "2.0" (its labels are the only
        // right-aligned texts).
        let y_of = |label: &str| -> Vec<i32> {
            svg.split("<text")
                .filter(|e| e.contains("text-anchor=\"end\""))
                .filter(|e| e.contains(&format!(">\n{label}\n")) || e.contains(&format!(">{label}<")))
                .map(|e| {
                    let i = e.find(" y=\"").unwrap() + 4;
                    e[i..i + e[i..].find('"').unwrap()].parse().unwrap()
                })
                .collect()
        };
        let (zero, two) = (y_of("0"), y_of("2.0"));
        assert!(zero.len() == 1 && two.len() == 1, "{zero:?} {two:?}");
        assert!(zero[0] < two[0]);
    }

    #[test]
    fn contour_map_equal_aspect_keeps_scales_equal() {
        let svg = bump_map().size(900, 700).to_svg().unwrap();
        // The frame of the map is the first black 1-px rectangle without fill after the bands: find its size.
        let frame = svg
            .split("<rect")
            .skip(1)
            .find(|r| r.contains("fill=\"none\"") && r.contains("stroke=\"#000000\""))
            .unwrap();
        let attr = |name: &str| -> f64 {
            let i = frame.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            frame[i..i + frame[i..].find('"').unwrap()].parse().unwrap()
        };
        // x spans 4 mm and depth 2 mm: the map is twice as wide as tall (to a pixel).
        assert!((attr("width") - 2.0 * attr("height")).abs() <= 2.0, "{frame}");
    }

    #[test]
    fn contour_map_survives_nan_and_constant_fields() {
        // NaN and infinite cells.
        let mut f = bump(21, 11);
        for i in [0, 5, 50, 51, 52, 100, 230] {
            f.values[i] = f64::NAN;
        }
        f.values[77] = f64::INFINITY;
        let svg = ContourMap::new("holes", f.clone()).contours(&[0.3, 0.6]).mark_max().to_svg().unwrap();
        assert!(texts(&svg).iter().any(|s| s.starts_with("no value")));
        assert!(!svg.contains("NaN") && !svg.contains("inf"));
        // Constant fields (with and without holes, zero and not), with a level at the constant.
        for v in [0.0, 3.0, -1e-9, 1e12] {
            let mut c = Field::new(5, 4, vec![v; 20], (0.0, 1.0), (0.0, 1.0));
            ContourMap::new("const", c.clone()).contours(&[v]).mark_max().equal_aspect().to_svg().unwrap();
            c.values[7] = f64::NAN;
            ContourMap::new("const", c).contours(&[v, v + 1.0]).mark_max().to_svg().unwrap();
        }
        // Nothing finite: an error, not a panic. Malformed fields: errors.
        let e = ContourMap::new("nan", Field::new(2, 2, vec![f64::NAN; 4], (0.0, 1.0), (0.0, 1.0))).to_svg();
        assert!(matches!(e, Err(PlotError::NoFiniteData { .. })));
        let e = ContourMap::new("bad", Field::new(3, 3, vec![0.0; 4], (0.0, 1.0), (0.0, 1.0))).to_svg();
        assert!(matches!(e, Err(PlotError::BadField { .. })));
        let e = ContourMap::new("huge", Field::new(2, 2, vec![-f64::MAX, f64::MAX, 0.0, 0.0], (0.0, 1.0), (0.0, 1.0)))
            .to_svg();
        assert!(matches!(e, Err(PlotError::BadField { .. })));
        // Tiny or extreme sizes and shapes.
        assert!(matches!(bump_map().size(100, 100).to_svg(), Err(PlotError::TooSmall { .. })));
        let thin = ContourMap::new("thin", Field::from_fn(200, 2, (0.0, 1000.0), (0.0, 1e-3), |x, z| x + z));
        thin.clone().equal_aspect().to_svg().unwrap();
        assert!(matches!(thin.size(200, 150).to_svg(), Err(PlotError::TooSmall { .. })));
        // A marker off the map is captioned but not drawn; one on it is drawn.
        let svg = bump_map().marker(10.0, 10.0, "far away").marker(1.0, 1.0, "here").to_svg().unwrap();
        let t = texts(&svg);
        assert!(t.iter().any(|s| s.starts_with("far away at x = 10")), "{t:?}");
        assert!(t.iter().any(|s| s.starts_with("here at x = 1")), "{t:?}");
    }

    #[test]
    fn colormaps_are_the_published_tables() {
        assert_eq!(ColorMap::Viridis.at(0.0), Rgb(68, 1, 84));
        assert_eq!(ColorMap::Viridis.at(1.0), Rgb(253, 231, 37));
        assert_eq!(ColorMap::Cividis.at(0.0), Rgb(0, 34, 78));
        assert_eq!(ColorMap::Viridis.at(f64::NAN), ColorMap::Viridis.at(-5.0));
        // Perceptually ordered: luminance rises monotonically along both maps.
        for map in [ColorMap::Viridis, ColorMap::Cividis] {
            let lum = |c: Rgb| 0.2126 * f64::from(c.0) + 0.7152 * f64::from(c.1) + 0.0722 * f64::from(c.2);
            let l: Vec<f64> = (0..=32).map(|i| lum(map.at(f64::from(i) / 32.0))).collect();
            assert!(l.windows(2).all(|w| w[1] > w[0]), "{map:?}");
        }
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
