//! Axes: ranges (margins, whole decades, categories), tick and grid positions, and the formats of tick, level
//! and caption numbers; axis texts with their units.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::prelude::Ranged;

/// `label [unit]`, unless the label already ends with `[unit]` or there is no unit.
pub(super) fn with_unit(label: &str, unit: Option<&str>) -> String {
    match unit.map(str::trim).filter(|u| !u.is_empty()) {
        None => label.to_string(),
        Some(u) if label.trim_end().ends_with(&format!("[{u}]")) => label.to_string(),
        Some(u) if label.trim().is_empty() => format!("[{u}]"),
        Some(u) => format!("{} [{u}]", label.trim_end()),
    }
}

/// Whether an axis text names a unit: it ends with `[…]`.
pub(super) fn says_unit(text: &str) -> bool {
    let t = text.trim_end();
    t.ends_with(']') && t.contains('[')
}

/// Relative spread of a linear axis's data (over their largest magnitude) up to which they are one value with
/// round-off: such an axis is drawn around that value, with a note saying so ([`Axis::text`]) instead of ticks
/// that spell out the round-off to the last digit. Solvers agree to about 1e-12 and round-off is about 1e-16.
pub(super) const ROUND_OFF: f64 = 1e-9;

/// Significant digits beyond which the tick labels of a linear axis are written from an offset (`d_N − 0.2563705
/// [mm]` with ticks 1e-8, 2e-8, …) rather than in full: a label never needs more than about this many digits.
const MAX_TICK_DIGITS: i32 = 6;

/// One axis in transformed coordinates: range, grid/tick positions and how to label them.
#[derive(Clone)]
pub(super) struct Axis {
    pub(super) lo: f64,
    pub(super) hi: f64,
    /// Labelled ticks with a grid line.
    pub(super) bold: Vec<f64>,
    /// Unlabelled minor grid lines.
    pub(super) light: Vec<f64>,
    /// `None` for log axes (labels are powers of ten), else the tick step (sets the decimals).
    pub(super) step: Option<f64>,
    /// Category names (categorical axis: tick `k` is labelled `names[k]`).
    pub(super) names: Option<Vec<String>>,
    /// Values increase downward (depth).
    pub(super) reversed: bool,
    /// Tick `v` is labelled `v − offset` (0: none), the offset written in the axis text ([`Axis::text`]).
    pub(super) offset: f64,
    /// A remark for the axis text: the data are one value with round-off ([`ROUND_OFF`]), which it names.
    pub(super) note: Option<String>,
}

impl Axis {
    /// A linear axis over data `min..=max` with a 5 % margin (a single value: ±10 % of it). Data that are one value
    /// with round-off ([`ROUND_OFF`]) are drawn as that value, with a note; ticks that would need more than
    /// [`MAX_TICK_DIGITS`] digits are labelled from an offset.
    pub(super) fn linear(min: f64, max: f64, target: usize) -> Axis {
        let magnitude = min.abs().max(max.abs());
        if max > min && max - min <= ROUND_OFF * magnitude {
            let mid = min + 0.5 * (max - min);
            let mut axis = Axis::linear(mid, mid, target);
            axis.note = Some(format!("{}, constant to round-off", fmt_digits(mid, 7)));
            return axis;
        }
        let span = max - min;
        let pad = if span > 0.0 {
            0.05 * span
        } else if min != 0.0 {
            0.1 * min.abs()
        } else {
            1.0
        };
        let (lo, hi) = if (max + pad - (min - pad)).is_finite() { (min - pad, max + pad) } else { (min, max) };
        Axis::exact(lo, hi, target).with_offset()
    }

    /// Label the ticks from an offset when in full they would need more than [`MAX_TICK_DIGITS`] significant
    /// digits: the offset is the round number nearest the middle at the power of ten above the range.
    fn with_offset(mut self) -> Axis {
        let (Some(step), span) = (self.step, self.hi - self.lo) else { return self };
        let magnitude = self.lo.abs().max(self.hi.abs());
        if !(span > 0.0 && magnitude.is_finite()) || magnitude / step < 10f64.powi(MAX_TICK_DIGITS) {
            return self;
        }
        let unit = 10f64.powf(span.log10().ceil());
        let mid = 0.5 * (self.lo + self.hi);
        // A multiple of a power of ten below 1 is formed by dividing by the exact integer 1/unit, so that it is the
        // double nearest its decimal (0.2563705, not 0.25637050000000003).
        self.offset = if unit < 1.0 {
            let inv = (1.0 / unit).round();
            (mid * inv).round() / inv
        } else {
            (mid / unit).round() * unit
        };
        self
    }

    /// The axis text: `label [unit]`, with the offset the ticks are labelled from (`label − 0.2563705 [unit]`) and
    /// the note on data that are one value with round-off.
    pub(super) fn text(&self, label: &str, unit: Option<&str>) -> String {
        let label = if self.offset != 0.0 && !label.trim().is_empty() {
            let unit_step = 10f64.powf((self.hi - self.lo).log10().ceil());
            let sign = if self.offset > 0.0 { '−' } else { '+' };
            format!("{} {sign} {}", label.trim_end(), fmt_linear(self.offset.abs(), unit_step, self.offset.abs()))
        } else {
            label.to_string()
        };
        let text = with_unit(&label, unit);
        match &self.note {
            Some(note) if !text.is_empty() => format!("{text}: {note}"),
            Some(note) => note.clone(),
            None => text,
        }
    }

    /// A linear axis over exactly `lo..hi` with nice ticks inside it.
    pub(super) fn exact(lo: f64, hi: f64, target: usize) -> Axis {
        let step = nice_step((hi - lo) / target as f64);
        // Data near ±f64::MAX can overflow the span: then no ticks rather than an endless list.
        let bold = if (hi - lo) / step <= 1000.0 {
            let eps = 1e-9 * step;
            let (k0, k1) = (((lo - eps) / step).ceil() as i64, ((hi + eps) / step).floor() as i64);
            (k0..=k1).map(|k| k as f64 * step).collect()
        } else {
            Vec::new()
        };
        Axis {
            lo,
            hi,
            bold,
            light: Vec::new(),
            step: Some(step),
            names: None,
            reversed: false,
            offset: 0.0,
            note: None,
        }
    }

    pub(super) fn log(min: f64, max: f64, target: usize) -> Axis {
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
        Axis { lo, hi, bold, light, step: None, names: None, reversed: false, offset: 0.0, note: None }
    }

    /// Categories at 0, 1, …, n−1, half a unit of room either side; ticks only at the categories.
    pub(super) fn categorical(names: &[String]) -> Axis {
        let n = names.len();
        Axis {
            lo: -0.5,
            hi: n as f64 - 0.5,
            bold: (0..n).map(|k| k as f64).collect(),
            light: Vec::new(),
            step: Some(1.0),
            names: Some(names.to_vec()),
            reversed: false,
            offset: 0.0,
            note: None,
        }
    }

    pub(super) fn label(&self, v: f64) -> String {
        if let Some(names) = &self.names {
            let k = v.round();
            return if k >= 0.0 && (k as usize) < names.len() { names[k as usize].clone() } else { String::new() };
        }
        match self.step {
            None => power_of_ten(v.round() as i64),
            Some(step) => {
                let (lo, hi) = (self.lo - self.offset, self.hi - self.offset);
                fmt_linear(v - self.offset, step, lo.abs().max(hi.abs()))
            }
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

pub(super) fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
}

/// A step of 1, 2 or 5 × 10^k, at least `raw`.
pub(super) fn nice_step(raw: f64) -> f64 {
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
pub(super) fn fmt_linear(v: f64, step: f64, magnitude: f64) -> String {
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

/// `v` with `digits` significant digits, trailing zeros of a fixed-notation value dropped; fixed notation for
/// magnitudes in 10⁻³..10⁵, else scientific.
fn fmt_digits(v: f64, digits: i32) -> String {
    if !v.is_finite() || v == 0.0 {
        return fmt_sig(v);
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..5).contains(&e) {
        let decimals = (digits - 1 - e).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.*e}", (digits - 1).max(0) as usize)
    }
}

/// `v` with 4 significant digits: fixed notation for magnitudes in 10⁻³..10⁵, else scientific.
pub(super) fn fmt_sig(v: f64) -> String {
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

/// A contour level's label: as many decimals as the spacing of the levels needs, trailing zeros dropped.
pub(super) fn fmt_level(level: f64, spacing: f64) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

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
    fn round_off_of_a_constant_is_drawn_as_the_constant_and_said() {
        // Expected: data 0.2563705365911895..0.2563705365911900 (a held approach, its last digits round-off) are
        // the value 0.2563705 with a note, and ticks of a few digits around it (the ±10 % of a single value).
        let (lo, hi) = (0.2563705365911895, 0.25637053659119);
        let a = Axis::linear(lo, hi, 6);
        assert!(a.lo < lo && a.hi > hi && a.hi - a.lo > 0.04, "{}..{}", a.lo, a.hi);
        let labels: Vec<String> = a.bold.iter().map(|v| a.label(*v)).collect();
        assert!(labels.iter().all(|l| l.len() <= 5), "{labels:?}");
        assert_eq!(a.text("approach d_N", Some("mm")), "approach d_N [mm]: 0.2563705, constant to round-off");
        // A single value is no round-off: no note.
        assert_eq!(Axis::linear(0.25, 0.25, 6).text("d", None), "d");
    }

    #[test]
    fn ticks_that_would_need_many_digits_are_labelled_from_an_offset() {
        // Expected: a real spread of 4e-8 on 0.25637 (beyond ROUND_OFF) keeps its ticks; they are labelled as
        // differences from the round offset 0.2563705 (a multiple of 1e-7, the power of ten above the range), which
        // the axis text names.
        let (lo, hi) = (0.25637052, 0.25637056);
        let a = Axis::linear(lo, hi, 6);
        assert!(a.note.is_none() && a.offset == 0.2563705, "offset {}", a.offset);
        let labels: Vec<String> = a.bold.iter().map(|v| a.label(*v)).collect();
        assert!(labels.len() >= 3 && labels.iter().all(|l| l.len() <= 8), "{labels:?}");
        assert_eq!(a.text("d_N", Some("mm")), "d_N − 0.2563705 [mm]");
        // Ticks on ordinary data are written in full.
        let b = Axis::linear(0.2, 0.3, 6);
        assert_eq!((b.offset, b.text("d_N", Some("mm"))), (0.0, "d_N [mm]".to_string()));
    }
}
