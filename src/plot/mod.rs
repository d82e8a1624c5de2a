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
//!
//! # Files
//!
//! `chart.rs`: line, marker and state charts; `contour.rs`: contour maps of a `field.rs` field; `legend.rs`: a
//! chart's legend; `axis.rs`: ranges, ticks and number formats; `style.rs`: colours, markers and dashes;
//! `colormap.rs`: viridis and cividis; `draw.rs`: text, dashed lines and markers; `canvas.rs`: the parts of a
//! contour map around the map; `map_layout.rs`: a contour map's bands, captions and layout; `prepared.rs`: a line
//! chart's data ready to draw. Every public item is re-exported here: `rollbem::plot::X` names each of them.

use std::io::Write as _;
use std::path::{Path, PathBuf};

mod axis;
mod canvas;
mod chart;
mod colormap;
mod contour;
mod draw;
mod field;
mod legend;
mod map_layout;
mod prepared;
pub mod space;
mod style;
#[cfg(test)]
mod test_support;

pub use chart::{Chart, Scale, Series};
pub use colormap::ColorMap;
pub use contour::{ContourMap, MapMarker};
pub use field::Field;
pub use style::{Appearance, Dash, Marker, Rgb, Style, PALETTE};

/// Why a chart could not be rendered or written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
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
