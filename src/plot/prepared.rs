//! A line chart's data ready to draw ([`Prepared`]): what `chart.rs` computes from its series and both
//! `chart.rs` and `legend.rs` (which looks for a plot corner free of data) read.

use super::axis::Axis;

/// Data after filtering and axis transform (log10 for log axes).
pub(super) struct Prepared {
    pub(super) series: Vec<PreparedSeries>,
    pub(super) x: Axis,
    pub(super) y: Axis,
    /// y offset of each prepared series (categorical axes only; else 0).
    pub(super) offsets: Vec<f64>,
}

/// One series ready to draw.
pub(super) struct PreparedSeries {
    /// Index into `Chart::series` (selects the appearance).
    pub(super) index: usize,
    /// Runs of consecutive drawable points, in transformed coordinates.
    pub(super) segments: Vec<Vec<(f64, f64)>>,
}
