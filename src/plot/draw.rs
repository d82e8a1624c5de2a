//! Drawing primitives shared by every chart kind: text (with its estimated width and a font that fits), polylines
//! with a dash pattern, markers, and the fonts and sizes of the figures.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontTransform;

use super::style::Marker;

/// Stroke width of lines, in pixels.
const LINE_WIDTH: u32 = 2;
/// Half-size of a series marker, in pixels.
pub(super) const MARKER_SIZE: f64 = 5.0;
/// Length of the line sample in a legend entry, in pixels.
pub(super) const LEGEND_SAMPLE: f64 = 36.0;
/// Smallest accepted chart size, in pixels.
pub(super) const MIN_SIZE: (u32, u32) = (200, 150);
/// Margin around the whole figure, in pixels.
pub(super) const MARGIN: u32 = 15;

pub(super) const FONT: &str = "sans-serif";
pub(super) const TITLE_SIZE: f64 = 24.0;
pub(super) const DESC_SIZE: f64 = 18.0;
pub(super) const TICK_SIZE: f64 = 15.0;
pub(super) const LEGEND_SIZE: f64 = 15.0;
/// Estimated text width per character, in units of the nominal font size (plotters writes `font-size` as the
/// nominal size / 1.24; sans-serif text averages about 0.6 em per character).
const CHAR_WIDTH: f64 = 0.52;

pub(super) fn err(e: &dyn std::fmt::Display) -> String {
    e.to_string()
}

/// Horizontal text anchor.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Anchor {
    Left,
    Center,
}

/// Draw `s` at pixel `pos`, vertically centred; `rotated` turns it to read bottom to top.
pub(super) fn text(
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
pub(super) fn text_width(s: &str, size: f64) -> f64 {
    s.chars().count() as f64 * size * CHAR_WIDTH
}

pub(super) fn to_px(p: (f64, f64)) -> (i32, i32) {
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
pub(super) fn draw_dashed(
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
pub(super) fn draw_marker(
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

/// `size`, shrunk (to no less than 8) so that `text` fits in `avail` pixels at about half an em per character.
pub(super) fn fit_font(size: f64, text: &str, avail: f64) -> f64 {
    let chars = text.chars().count().max(1) as f64;
    size.min((avail / (CHAR_WIDTH * chars)).floor()).max(8.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::Dash;

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
}
