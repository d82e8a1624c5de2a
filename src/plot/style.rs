//! How a series looks: colours ([`Rgb`], the Okabe–Ito [`PALETTE`]), marker shapes ([`Marker`]), dash patterns
//! ([`Dash`]), their automatic choice per series index ([`Appearance::for_index`]) and the drawing [`Style`].

use plotters::style::RGBColor;

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    pub(super) fn color(self) -> RGBColor {
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
#[non_exhaustive]
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
#[non_exhaustive]
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
    pub(super) fn line_dash(self, style: Style) -> Dash {
        match (style, self.dash) {
            (Style::Dashed, Dash::Solid) => Dash::Dashed,
            (_, d) => d,
        }
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
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
    pub(super) fn has_line(self) -> bool {
        self != Style::Markers
    }

    pub(super) fn has_markers(self) -> bool {
        matches!(self, Style::Markers | Style::LineMarkers)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::test_support::*;
    use crate::plot::{Chart, Series};

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
}
