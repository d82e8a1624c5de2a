//! A contour map being drawn ([`MapCanvas`]): its axes, the labels on contour lines (placed where they overlap
//! nothing), the colour bar and the captions under the map.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;

use super::axis::*;
use super::draw::*;
use super::field::Field;
use super::map_layout::{
    Bands, MapCaptions, MapLayout, CAPTION_SIZE, MAP_LABEL_SIZE, MAP_MARKERS, MAP_MARKER_SIZE, NO_DATA,
};

/// Pixel points of a contour line.
pub(super) type PixelLine = Vec<(i32, i32)>;

/// Colour bar spacing from the map, and width, in pixels.
pub(super) const BAR_GAP: f64 = 18.0;
pub(super) const BAR_WIDTH: f64 = 18.0;

/// A contour map being drawn: the figure, the map's coordinates and its pixel extent.
pub(super) struct MapCanvas<'a, 'b> {
    pub(super) root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    pub(super) coord: Cartesian2d<Axis, Axis>,
    /// Pixel columns of the map.
    pub(super) xr: Range<i32>,
    /// Pixel rows of the map.
    pub(super) yr: Range<i32>,
}

impl MapCanvas<'_, '_> {
    /// The pixel of the point `(x, depth)`.
    pub(super) fn px(&self, p: (f64, f64)) -> (i32, i32) {
        self.coord.translate(&p)
    }

    /// Pixel rectangle of the cells ix0..ix1 of row iz, one pixel larger to the right and below (inside the
    /// map): abutting shapes would otherwise show anti-aliasing seams when the SVG is scaled.
    pub(super) fn cell_run(&self, f: &Field, ix0: usize, ix1: usize, iz: usize) -> [(i32, i32); 2] {
        let (a, b) = (self.px((f.x(ix0), f.depth(iz))), self.px((f.x(ix1), f.depth(iz + 1))));
        [a, ((b.0 + 1).min(self.xr.end), (b.1 + 1).min(self.yr.end))]
    }

    /// Axes, ticks and frame.
    pub(super) fn draw_axes(
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
    pub(super) fn draw_contour_labels(
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
    pub(super) fn draw_colour_bar(&self, layout: &MapLayout, bands: &Bands, levels: &[f64]) -> Result<(), String> {
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
    pub(super) fn draw_captions(&self, layout: &MapLayout, captions: &MapCaptions) -> Result<(), String> {
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
