//! Plots as inline SVG: axes with 1–2–5 ticks, lines or markers, a legend.
//!
//! Text is SVG `<text>` drawn by the browser's own sans-serif font, so no
//! font is embedded and nothing is rasterised. A long series is thinned
//! to its minimum and maximum per pixel column (the envelope a raster
//! plot would show), so a million-sample run still gives a small file.
//! Non-finite values break a line; they are never drawn.

use std::fmt::Write;

/// Plot area size in SVG user units (pixels at 100 % zoom).
const WIDTH: f64 = 720.0;
const HEIGHT: f64 = 360.0;
/// Margins: left (tick labels), right, top (title), bottom (axis label).
const LEFT: f64 = 78.0;
const RIGHT: f64 = 16.0;
const TOP: f64 = 30.0;
const BOTTOM: f64 = 46.0;
/// Series colours (Okabe–Ito, distinguishable with colour blindness).
const COLOURS: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442",
];

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A polyline through the points (broken at non-finite values).
    Line,
    /// A dashed polyline (reference values).
    Dashed,
    /// A marker per point.
    Markers,
}

/// One series of a plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Abscissae.
    pub x: Vec<f64>,
    /// Ordinates (same length as `x`).
    pub y: Vec<f64>,
    /// How it is drawn.
    pub style: Style,
}

impl Series {
    /// A series drawn as a line.
    pub fn line(name: impl Into<String>, x: &[f64], y: &[f64]) -> Self {
        Self::new(name, x, y, Style::Line)
    }

    /// A series drawn with markers.
    pub fn markers(name: impl Into<String>, x: &[f64], y: &[f64]) -> Self {
        Self::new(name, x, y, Style::Markers)
    }

    /// A series with the given style.
    pub fn new(name: impl Into<String>, x: &[f64], y: &[f64], style: Style) -> Self {
        Self {
            name: name.into(),
            x: x.to_vec(),
            y: y.to_vec(),
            style,
        }
    }
}

/// A 2-D plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    /// Title above the plot.
    pub title: String,
    /// Abscissa label with its unit.
    pub x_label: String,
    /// Ordinate label with its unit.
    pub y_label: String,
    /// The series, drawn in order.
    pub series: Vec<Series>,
    /// Same scale on both axes (orbits).
    pub equal_aspect: bool,
    /// A heat map under the series (a spectrogram); its extent sets the
    /// axes.
    pub heat: Option<HeatMap>,
}

/// Values on a grid of cells drawn as coloured rectangles (viridis, from
/// `floor` to 0): a spectrogram's levels in dB below its largest.
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMap {
    /// Cell edges along x (one more than the columns).
    pub x_edges: Vec<f64>,
    /// Cell edges along y (one more than the rows).
    pub y_edges: Vec<f64>,
    /// Column by column, each from the lowest y up: levels ≤ 0.
    pub levels: Vec<f64>,
    /// The level drawn darkest (below it: the same colour).
    pub floor: f64,
    /// The colour bar's label (the levels' unit).
    pub label: String,
}

/// Viridis (van der Walt & Smith, matplotlib's default) at 9 levels.
const VIRIDIS: [(f64, f64, f64); 9] = [
    (68.0, 1.0, 84.0),
    (71.0, 45.0, 123.0),
    (59.0, 82.0, 139.0),
    (44.0, 114.0, 142.0),
    (33.0, 145.0, 140.0),
    (40.0, 174.0, 128.0),
    (94.0, 201.0, 98.0),
    (173.0, 220.0, 48.0),
    (253.0, 231.0, 37.0),
];

/// The viridis colour of `u` in [0, 1] as `#rrggbb`.
fn viridis(u: f64) -> String {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = u * (VIRIDIS.len() - 1) as f64;
    let k = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    let mix = |p: f64, q: f64| (p + f * (q - p)).round() as u8;
    format!(
        "#{:02x}{:02x}{:02x}",
        mix(a.0, b.0),
        mix(a.1, b.1),
        mix(a.2, b.2)
    )
}

impl HeatMap {
    /// The cells as `<rect>`s in `frame`, and a colour bar in the plot's
    /// top-right corner.
    fn to_svg(&self, frame: &Frame, out: &mut String) {
        let rows = self.y_edges.len().saturating_sub(1);
        let _ = write!(out, r#"<g class="heat" shape-rendering="crispEdges">"#);
        for (i, x) in self.x_edges.windows(2).enumerate() {
            for (k, y) in self.y_edges.windows(2).enumerate() {
                let Some(&level) = self.levels.get(i * rows + k) else {
                    continue;
                };
                let (px0, px1) = (frame.px(x[0]), frame.px(x[1]));
                let (py0, py1) = (frame.py(y[1]), frame.py(y[0]));
                let _ = write!(
                    out,
                    r#"<rect x="{px0:.1}" y="{py0:.1}" width="{:.1}" height="{:.1}" fill="{}"/>"#,
                    (px1 - px0).max(0.1),
                    (py1 - py0).max(0.1),
                    viridis(1.0 - level / self.floor)
                );
            }
        }
        out.push_str("</g>");
        // Colour bar: 60 px wide, the floor on the left, 0 on the right.
        let (x0, y0) = (WIDTH - RIGHT - 150.0, TOP + 6.0);
        for k in 0..30 {
            let _ = write!(
                out,
                r#"<rect x="{:.1}" y="{y0:.1}" width="2.1" height="8" fill="{}"/>"#,
                x0 + 2.0 * k as f64,
                viridis(k as f64 / 29.0)
            );
        }
        let _ = write!(
            out,
            r#"<text x="{:.1}" y="{:.1}" class="legend heat-label">{} {}…0</text>"#,
            x0 + 64.0,
            y0 + 8.0,
            escape(&self.label),
            self.floor
        );
    }
}

impl Plot {
    /// An empty plot with its labels.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            equal_aspect: false,
            heat: None,
        }
    }

    /// Adds a heat map under the series.
    pub fn with_heat(mut self, heat: HeatMap) -> Self {
        self.heat = Some(heat);
        self
    }

    /// Adds a series.
    pub fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Whether any series has a finite point to draw, or there is a heat map.
    pub fn has_data(&self) -> bool {
        self.heat.as_ref().is_some_and(|h| !h.levels.is_empty())
            || self.series.iter().any(|s| {
                s.x.iter()
                    .zip(&s.y)
                    .any(|(x, y)| x.is_finite() && y.is_finite())
            })
    }

    /// The plot as an `<svg>` element (well-formed XML).
    pub fn to_svg(&self) -> String {
        let (x_range, y_range) = self.ranges();
        let (x_range, y_range) = if self.equal_aspect {
            equalise(x_range, y_range)
        } else {
            (x_range, y_range)
        };
        let x_ticks = ticks(x_range);
        let y_ticks = ticks(y_range);
        let (x0, x1) = (
            x_ticks.first().copied().unwrap_or(x_range.0),
            x_ticks.last().copied().unwrap_or(x_range.1),
        );
        let (y0, y1) = (
            y_ticks.first().copied().unwrap_or(y_range.0),
            y_ticks.last().copied().unwrap_or(y_range.1),
        );
        let frame = Frame {
            x: (x0, x1),
            y: (y0, y1),
        };
        let mut out = String::new();
        let _ = write!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" class="plot" viewBox="0 0 {WIDTH} {HEIGHT}" width="{WIDTH}" height="{HEIGHT}" role="img" aria-label="{}">"#,
            escape(&self.title)
        );
        let _ = write!(
            out,
            r#"<text x="{}" y="18" text-anchor="middle" class="title">{}</text>"#,
            LEFT + 0.5 * (WIDTH - LEFT - RIGHT),
            escape(&self.title)
        );
        if let Some(heat) = &self.heat {
            heat.to_svg(&frame, &mut out);
        }
        self.axes_to_svg(&frame, &x_ticks, &y_ticks, &mut out);
        self.series_to_svg(&frame, &mut out);
        self.legend_to_svg(&mut out);
        out.push_str("</svg>");
        out
    }

    /// The grid, the tick labels, the frame and the axis labels.
    fn axes_to_svg(&self, frame: &Frame, x_ticks: &[f64], y_ticks: &[f64], out: &mut String) {
        for &t in x_ticks {
            let px = frame.px(t);
            let _ = write!(
                out,
                r#"<line x1="{px:.1}" y1="{TOP}" x2="{px:.1}" y2="{:.1}" class="grid"/><text x="{px:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
                HEIGHT - BOTTOM,
                HEIGHT - BOTTOM + 15.0,
                number(t, x_ticks)
            );
        }
        for &t in y_ticks {
            let py = frame.py(t);
            let _ = write!(
                out,
                r#"<line x1="{LEFT}" y1="{py:.1}" x2="{:.1}" y2="{py:.1}" class="grid"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
                WIDTH - RIGHT,
                LEFT - 5.0,
                py + 4.0,
                number(t, y_ticks)
            );
        }
        let _ = write!(
            out,
            r#"<rect x="{LEFT}" y="{TOP}" width="{:.1}" height="{:.1}" class="frame"/>"#,
            WIDTH - LEFT - RIGHT,
            HEIGHT - TOP - BOTTOM
        );
        let _ = write!(
            out,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
            LEFT + 0.5 * (WIDTH - LEFT - RIGHT),
            HEIGHT - 8.0,
            escape(&self.x_label)
        );
        let _ = write!(
            out,
            r#"<text transform="translate(14 {:.1}) rotate(-90)" text-anchor="middle">{}</text>"#,
            TOP + 0.5 * (HEIGHT - TOP - BOTTOM),
            escape(&self.y_label)
        );
    }

    /// The series: polylines (broken at non-finite points) or markers.
    fn series_to_svg(&self, frame: &Frame, out: &mut String) {
        for (k, s) in self.series.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            match s.style {
                Style::Line | Style::Dashed => {
                    let dash = if s.style == Style::Dashed {
                        r#" stroke-dasharray="6 4""#
                    } else {
                        ""
                    };
                    for run in polylines(&s.x, &s.y, frame) {
                        let _ = write!(
                            out,
                            r#"<polyline class="series" data-series="{}" fill="none" stroke="{colour}" stroke-width="1.4"{dash} points="{run}"/>"#,
                            escape(&s.name)
                        );
                    }
                }
                Style::Markers => {
                    let _ = write!(
                        out,
                        r#"<g class="series" data-series="{}" fill="{colour}">"#,
                        escape(&s.name)
                    );
                    for (x, y) in s.x.iter().zip(&s.y) {
                        if x.is_finite() && y.is_finite() {
                            let _ = write!(
                                out,
                                r#"<circle cx="{:.1}" cy="{:.1}" r="2.6"/>"#,
                                frame.px(*x),
                                frame.py(*y)
                            );
                        }
                    }
                    out.push_str("</g>");
                }
            }
        }
    }

    /// The legend, when there is more than one series.
    fn legend_to_svg(&self, out: &mut String) {
        if self.series.len() > 1 {
            let longest = self.series.iter().map(|s| s.name.chars().count()).max();
            let _ = write!(
                out,
                r#"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" class="legend-box"/>"#,
                LEFT + 5.0,
                TOP + 3.0,
                24.0 + 6.2 * longest.unwrap_or(0) as f64,
                6.0 + 15.0 * self.series.len() as f64
            );
            for (k, s) in self.series.iter().enumerate() {
                let colour = COLOURS[k % COLOURS.len()];
                let y = TOP + 12.0 + 15.0 * k as f64;
                let x = LEFT + 10.0;
                let _ = write!(
                    out,
                    r#"<rect x="{x:.1}" y="{:.1}" width="12" height="4" fill="{colour}"/><text x="{:.1}" y="{:.1}" class="legend">{}</text>"#,
                    y - 4.0,
                    x + 17.0,
                    y + 1.0,
                    escape(&s.name)
                );
            }
        }
    }

    /// Data ranges over the finite points (a unit range around a constant).
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        if let Some(h) = &self.heat {
            let extent = |e: &[f64]| (e.first().copied(), e.last().copied());
            if let ((Some(x0), Some(x1)), (Some(y0), Some(y1))) =
                (extent(&h.x_edges), extent(&h.y_edges))
            {
                return (widen((x0, x1)), widen((y0, y1)));
            }
        }
        let mut x = (f64::INFINITY, f64::NEG_INFINITY);
        let mut y = (f64::INFINITY, f64::NEG_INFINITY);
        for s in &self.series {
            for (a, b) in s.x.iter().zip(&s.y) {
                if a.is_finite() && b.is_finite() {
                    x = (x.0.min(*a), x.1.max(*a));
                    y = (y.0.min(*b), y.1.max(*b));
                }
            }
        }
        (widen(x), widen(y))
    }
}

/// A degenerate or empty range made drawable. A range flat to round-off
/// (narrower than 1e-9 of its values) counts as constant: its ticks would
/// not be distinguishable in print.
fn widen((lo, hi): (f64, f64)) -> (f64, f64) {
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo > 1e-9 * lo.abs().max(hi.abs()) {
        return (lo, hi);
    }
    let (lo, hi) = (0.5 * (lo + hi), 0.5 * (lo + hi));
    let pad = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
    (lo - pad, hi + pad)
}

/// Ranges with the same units per pixel on both axes.
fn equalise(x: (f64, f64), y: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (w, h) = (WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM);
    let scale = ((x.1 - x.0) / w).max((y.1 - y.0) / h);
    let centre = |r: (f64, f64), size: f64| {
        let c = 0.5 * (r.0 + r.1);
        (c - 0.5 * scale * size, c + 0.5 * scale * size)
    };
    (centre(x, w), centre(y, h))
}

/// Plot frame: data ranges mapped onto the plot area.
struct Frame {
    x: (f64, f64),
    y: (f64, f64),
}

impl Frame {
    fn px(&self, x: f64) -> f64 {
        LEFT + (x - self.x.0) / (self.x.1 - self.x.0) * (WIDTH - LEFT - RIGHT)
    }

    fn py(&self, y: f64) -> f64 {
        HEIGHT - BOTTOM - (y - self.y.0) / (self.y.1 - self.y.0) * (HEIGHT - TOP - BOTTOM)
    }
}

/// The `points` attributes of a series' polylines: split at non-finite
/// values; thinned to the first, minimum, maximum and last point of each
/// pixel column when the series is denser than the plot.
fn polylines(x: &[f64], y: &[f64], frame: &Frame) -> Vec<String> {
    let mut runs = Vec::new();
    let mut current = String::new();
    let mut column: Option<(i64, Vec<(f64, f64)>)> = None;
    let flush = |current: &mut String, points: &[(f64, f64)]| {
        // First, then the extremes in the order they occur, then last.
        let (mut lo, mut hi) = (0, 0);
        for (k, p) in points.iter().enumerate() {
            if p.1 < points[lo].1 {
                lo = k;
            }
            if p.1 > points[hi].1 {
                hi = k;
            }
        }
        let mut keep = vec![0, lo, hi, points.len() - 1];
        keep.sort_unstable();
        keep.dedup();
        for k in keep {
            let _ = write!(current, "{:.1},{:.1} ", points[k].0, points[k].1);
        }
    };
    for (a, b) in x.iter().zip(y) {
        if !(a.is_finite() && b.is_finite()) {
            if let Some((_, points)) = column.take() {
                flush(&mut current, &points);
            }
            if !current.is_empty() {
                runs.push(std::mem::take(&mut current).trim_end().to_string());
            }
            continue;
        }
        let (px, py) = (frame.px(*a), frame.py(*b));
        let pixel = px.floor() as i64;
        match &mut column {
            Some((c, points)) if *c == pixel => points.push((px, py)),
            _ => {
                if let Some((_, points)) = column.take() {
                    flush(&mut current, &points);
                }
                column = Some((pixel, vec![(px, py)]));
            }
        }
    }
    if let Some((_, points)) = column.take() {
        flush(&mut current, &points);
    }
    if !current.is_empty() {
        runs.push(current.trim_end().to_string());
    }
    runs
}

/// Tick values: 4–10 steps of 1, 2 or 5 × 10^k covering the range.
pub fn ticks((lo, hi): (f64, f64)) -> Vec<f64> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return vec![lo];
    }
    let raw = span / 6.0;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * magnitude)
        .find(|s| span / s <= 8.0)
        .unwrap_or(10.0 * magnitude);
    let first = (lo / step).floor();
    let last = (hi / step).ceil();
    let count = (last - first) as i64;
    (0..=count)
        .map(|k| {
            let v = (first + k as f64) * step;
            // Exact zero, not 1e-17.
            if v.abs() < 1e-9 * step { 0.0 } else { v }
        })
        .collect()
}

/// A tick label: as few digits as tell the ticks apart; exponent form for
/// very large or small values.
fn number(v: f64, ticks: &[f64]) -> String {
    let step = if ticks.len() > 1 {
        (ticks[1] - ticks[0]).abs()
    } else {
        v.abs().max(1.0)
    };
    let largest = ticks.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    if v == 0.0 {
        return "0".into();
    }
    // Ticks that round-off made equal have no step: print the value as is.
    if !(step > 0.0 && step.is_finite()) {
        return format!("{v:e}");
    }
    if !(1e-3..1e6).contains(&largest) {
        let digits = (largest.log10().floor() - step.log10().floor()).clamp(0.0, 6.0) as usize;
        return format!("{v:.digits$e}");
    }
    let decimals = (-step.log10().floor()).clamp(0.0, 17.0) as usize;
    format!("{v:.decimals$}")
}

/// Text escaped for XML content and attributes.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_cover_the_range_with_round_steps() {
        for (lo, hi) in [(0.0, 1.0), (-3.2, 17.9), (4443.0, 4447.5), (1e-9, 7e-8)] {
            let t = ticks((lo, hi));
            assert!(t[0] <= lo && *t.last().unwrap() >= hi, "{lo} {hi}: {t:?}");
            assert!((4..=10).contains(&t.len()), "{lo} {hi}: {t:?}");
            let step = t[1] - t[0];
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9),
                "{step}"
            );
        }
    }

    #[test]
    fn dense_series_are_thinned_to_their_envelope() {
        let x: Vec<f64> = (0..100_000).map(|k| k as f64).collect();
        let y: Vec<f64> = x.iter().map(|v| (v * 0.37).sin()).collect();
        let plot = Plot::new("t", "x", "y").with(Series::line("s", &x, &y));
        let svg = plot.to_svg();
        // At most 4 points per pixel column of a 626-pixel-wide area.
        let points = svg.matches(',').count();
        assert!(points <= 4 * 630, "{points} points kept");
        // The envelope keeps the extremes: y = ±1 maps to the frame edges.
        let frame = Frame {
            x: (0.0, 1e5),
            y: (-1.0, 1.0),
        };
        assert!(svg.contains(&format!(",{:.1}", frame.py(1.0))));
    }

    #[test]
    fn non_finite_values_break_the_line() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let y = [1.0, 2.0, f64::NAN, 3.0, 4.0];
        let svg = Plot::new("t", "x", "y")
            .with(Series::line("s", &x, &y))
            .to_svg();
        assert_eq!(svg.matches("<polyline").count(), 2);
        assert!(!svg.contains("NaN") && !svg.contains("inf"));
    }

    #[test]
    fn series_flat_to_round_off_draw() {
        // A 6304 run of 0.1 ms has ring displacements flat to 1e-16; a
        // sweep over 1e6 N of axial load has a constant contact angle.
        for (base, wiggle) in [(100.0, 1e-13), (0.0, 1e-300), (1e-20, 1e-36), (-5e5, 1e-10)] {
            let x = [0.0, 1.0, 2.0];
            let y = [base, base + wiggle, base - wiggle];
            let svg = Plot::new("t", "x", "y")
                .with(Series::line("s", &x, &y))
                .to_svg();
            assert!(svg.contains("<polyline"), "{base} {wiggle}");
        }
        for ticks in [vec![7.0, 7.0], vec![0.0, 0.0, 0.0], vec![1e-300, 1e-300]] {
            assert!(!number(ticks[0], &ticks).is_empty());
        }
    }

    #[test]
    fn labels_are_escaped() {
        let svg = Plot::new("a < b & c", "x", "y").to_svg();
        assert!(svg.contains("a &lt; b &amp; c"));
    }
}
