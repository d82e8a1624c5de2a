//! The legend of a line chart: its entries, where it goes (a data-free corner of the plot or beside it) and how it
//! is drawn.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;

use super::draw::{
    draw_dashed, draw_marker, err, text, text_width, to_px, Anchor, LEGEND_SAMPLE, LEGEND_SIZE, MARKER_SIZE,
};
use super::prepared::Prepared;
use super::style::{Appearance, Style};

/// One legend entry.
pub(super) struct LegendItem {
    pub(super) label: String,
    pub(super) appearance: Appearance,
    pub(super) style: Style,
}

/// A plot corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Corner {
    pub(super) top: bool,
    pub(super) right: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum LegendPlace {
    /// In a plot corner free of data.
    Inside(Corner),
    /// Right of the plot.
    Outside,
}

/// Where the legend goes and its size in pixels.
pub(super) struct LegendPlan {
    pub(super) place: LegendPlace,
    pub(super) font: f64,
    /// Width of the line sample (narrow when no entry has a line).
    pub(super) sample: f64,
    pub(super) rows: usize,
    pub(super) col_w: f64,
    pub(super) row_h: f64,
    pub(super) w: f64,
    pub(super) h: f64,
}

impl LegendPlan {
    /// Top left corner of the legend box, in pixels, for a plot over the pixel ranges `xr`, `yr`: beside the plot,
    /// or 10 pixels inside the chosen corner.
    pub(super) fn origin(&self, xr: &Range<i32>, yr: &Range<i32>) -> (f64, f64) {
        match self.place {
            LegendPlace::Outside => (f64::from(xr.end) + 15.0, f64::from(yr.start)),
            LegendPlace::Inside(c) => {
                let left = if c.right { f64::from(xr.end) - 10.0 - self.w } else { f64::from(xr.start) + 10.0 };
                let top = if c.top { f64::from(yr.start) + 10.0 } else { f64::from(yr.end) - 10.0 - self.h };
                (left, top)
            }
        }
    }
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
pub(super) fn plan_legend(items: &[LegendItem], prep: &Prepared, pw: f64, ph: f64, width: f64) -> LegendPlan {
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

pub(super) fn draw_legend(
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
