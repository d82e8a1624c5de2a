//! The parts of a contour map fixed before it is drawn: its colour bands, what is captioned under it and where
//! each part goes ([`MapLayout`]), with the map's sizes and markers. `contour.rs` computes them and `canvas.rs`
//! draws with them.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::Axis;
use super::draw::err;
use super::style::Marker;

/// Colour of cells with a non-finite corner.
pub(super) const NO_DATA: RGBColor = RGBColor(190, 190, 190);
/// Nominal font size of contour labels and map captions.
pub(super) const MAP_LABEL_SIZE: f64 = 13.0;
pub(super) const CAPTION_SIZE: f64 = 15.0;
/// Half-size of a map marker, in pixels.
pub(super) const MAP_MARKER_SIZE: f64 = 7.0;
/// Markers used on a map, in order (hollow: a white inside with a black outline shows on any colour).
pub(super) const MAP_MARKERS: [Marker; 5] =
    [Marker::OpenDiamond, Marker::OpenCircle, Marker::OpenSquare, Marker::OpenTriangleUp, Marker::OpenTriangleDown];

/// The colour bands of a contour map.
pub(super) struct Bands {
    /// Band edges, increasing: band `k` spans `edges[k]..edges[k + 1]`.
    pub(super) edges: Vec<f64>,
    /// Colour of each band.
    pub(super) colors: Vec<RGBColor>,
    /// Spacing of the edges.
    pub(super) step: f64,
}

impl Bands {
    pub(super) fn lo(&self) -> f64 {
        self.edges[0]
    }

    pub(super) fn hi(&self) -> f64 {
        self.edges[self.edges.len() - 1]
    }

    /// The largest magnitude of an edge (sets the format of the colour bar's labels).
    pub(super) fn magnitude(&self) -> f64 {
        self.lo().abs().max(self.hi().abs())
    }
}

/// What is captioned under a contour map.
pub(super) struct MapCaptions {
    /// Marked points `(x, depth, caption)`: the maximum (if marked), then the markers.
    pub(super) marks: Vec<(f64, f64, String)>,
    /// Some value is not finite: such cells are grey, with a caption saying so.
    pub(super) has_nan: bool,
}

impl MapCaptions {
    /// Number of caption lines.
    pub(super) fn count(&self) -> usize {
        self.marks.len() + usize::from(self.has_nan)
    }
}

/// Where the parts of a contour map go, in pixels.
pub(super) struct MapLayout {
    /// Axis texts (label and unit) of x, depth and the values.
    pub(super) x_text: String,
    pub(super) d_text: String,
    pub(super) v_text: String,
    /// Size of the figure (its height trimmed to what the map uses).
    pub(super) width: f64,
    pub(super) height: f64,
    /// Height of the x tick labels, of an axis text and of a caption line.
    pub(super) x_tick_h: f64,
    pub(super) desc_h: f64,
    pub(super) caption_h: f64,
    /// Width of the depth tick labels and of the colour bar's tick labels.
    pub(super) d_tick_w: f64,
    pub(super) bar_tick_w: f64,
    /// Top left corner and size of the map.
    pub(super) x0: f64,
    pub(super) y0: f64,
    pub(super) mw: f64,
    pub(super) mh: f64,
}

impl MapLayout {
    /// The chart of the map on `root`: its plotting area the map, with the tick labels left of and below it.
    pub(super) fn chart_on<'a, 'b>(
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
