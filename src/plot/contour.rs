//! Filled contour maps of a [`Field`] ([`ContourMap`]): the builder, the layout of map, colour bar and captions,
//! and the drawing of colour bands, missing data, contour lines and markers, in that order.

use std::path::Path;

use plotters::prelude::*;

use super::axis::*;
use super::canvas::*;
use super::colormap::ColorMap;
use super::draw::*;
use super::field::{all_finite, cell_superlevel, Field};
use super::map_layout::*;
use super::{write_atomic, PlotError};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::test_support::*;

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
}
