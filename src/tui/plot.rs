//! A small chart widget drawn straight into the buffer: line series on a braille grid
//! (or one ASCII glyph per cell), point markers, labelled vertical event lines, a
//! time cursor, and axes with round ticks and units. ratatui's Chart has no vertical
//! lines, no labels inside the plot and no ASCII mode, hence this.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use super::theme::Theme;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Draw {
    /// Straight segments between consecutive points.
    Line,
    /// One marker cell per point.
    Points,
}

#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    /// The glyph in ASCII mode (lines) or the marker (points, both modes).
    pub glyph: &'static str,
    pub draw: Draw,
}

/// A vertical line at `x`, optionally labelled at the top. Lines closer than two
/// columns are thinned: the higher `priority` stays, else the earlier.
#[derive(Clone, Debug)]
pub struct VLine {
    pub x: f64,
    pub label: Option<String>,
    pub style: Style,
    pub priority: u8,
}

#[derive(Clone, Debug)]
pub struct Plot {
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
    pub x_title: String,
    pub y_title: String,
    pub series: Vec<Series>,
    pub vlines: Vec<VLine>,
    pub cursor: Option<f64>,
    /// Replaces the automatic x ticks (e.g. for log axes): positions and labels.
    pub x_ticks: Option<Vec<(f64, String)>>,
    pub y_ticks: Option<Vec<(f64, String)>>,
}

/// Round tick positions covering `lo..hi` with at most about `max` ticks, and the
/// bounds widened to the outer ticks.
pub fn nice_ticks(lo: f64, hi: f64, max: usize) -> ((f64, f64), Vec<f64>) {
    let (lo, hi) = if !(lo.is_finite() && hi.is_finite()) {
        (0.0, 1.0)
    } else if hi - lo <= f64::EPSILON * lo.abs().max(hi.abs()).max(1e-300) {
        // Zero span: pad so there is something to draw.
        let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        (lo - pad, hi + pad)
    } else {
        (lo, hi)
    };
    let raw = (hi - lo) / max.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let first = (lo / step).floor();
    let last = (hi / step).ceil();
    let ticks: Vec<f64> = (0..=((last - first) as usize))
        .map(|i| (first + i as f64) * step)
        .collect();
    ((first * step, last * step), ticks)
}

/// A tick label with as many decimals as the step needs.
pub fn tick_label(v: f64, step: f64) -> String {
    // Enough decimals to write the step exactly (0.25 needs two).
    let decimals = (0..6)
        .find(|&d| {
            let scaled = step.abs() * 10f64.powi(d);
            (scaled - scaled.round()).abs() < 1e-9 * scaled.max(1.0)
        })
        .unwrap_or(6) as usize;
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

fn ticks_with_labels(ticks: &[f64]) -> Vec<(f64, String)> {
    let step = if ticks.len() > 1 {
        ticks[1] - ticks[0]
    } else {
        1.0
    };
    ticks.iter().map(|&t| (t, tick_label(t, step))).collect()
}

struct Grid {
    cols: usize,
    rows: usize,
    /// Sub-cells per cell: (2, 4) braille, (1, 1) ASCII.
    sub: (usize, usize),
    bits: Vec<u8>,
    style: Vec<Option<(Style, &'static str)>>,
}

impl Grid {
    fn new(cols: usize, rows: usize, ascii: bool) -> Grid {
        Grid {
            cols,
            rows,
            sub: if ascii { (1, 1) } else { (2, 4) },
            bits: vec![0; cols * rows],
            style: vec![None; cols * rows],
        }
    }

    fn dots(&self) -> (usize, usize) {
        (self.cols * self.sub.0, self.rows * self.sub.1)
    }

    fn set(&mut self, dx: i64, dy: i64, style: Style, glyph: &'static str) {
        let (w, h) = self.dots();
        if dx < 0 || dy < 0 || dx as usize >= w || dy as usize >= h {
            return;
        }
        let (dx, dy) = (dx as usize, dy as usize);
        let cell = (dy / self.sub.1) * self.cols + dx / self.sub.0;
        // Braille dot numbering: columns of 1-2-3-7 and 4-5-6-8.
        const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
        self.bits[cell] |= if self.sub.0 == 1 {
            1
        } else {
            BITS[dx % 2][dy % 4]
        };
        self.style[cell] = Some((style, glyph));
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64), style: Style, glyph: &'static str) {
        let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as usize).clamp(1, 4096);
        for i in 0..=steps {
            let f = i as f64 / steps as f64;
            let x = a.0 + (b.0 - a.0) * f;
            let y = a.1 + (b.1 - a.1) * f;
            self.set(x.round() as i64, y.round() as i64, style, glyph);
        }
    }
}

impl Plot {
    pub fn render(&self, area: Rect, buf: &mut Buffer, theme: &Theme) {
        if area.width < 12 || area.height < 4 {
            return;
        }
        let g = theme.glyphs;
        let (x0, x1) = self.x_range;
        let (y0, y1) = self.y_range;
        let y_ticks = self.y_ticks.clone().unwrap_or_else(|| {
            let (_, t) = nice_ticks(y0, y1, (area.height as usize / 2).max(2));
            ticks_with_labels(&t)
        });
        let y_ticks: Vec<_> = y_ticks
            .into_iter()
            .filter(|(v, _)| *v >= y0 && *v <= y1)
            .collect();
        let margin = y_ticks.iter().map(|(_, l)| l.len()).max().unwrap_or(1) as u16;
        // Title and legend: a mark and a name for every named series, on the title row
        // and, if they do not fit there, on more rows (taken from the plot).
        let head = self.y_title.clone();
        let mut legend: Vec<(String, Style)> = Vec::new();
        for s in &self.series {
            if !s.name.is_empty() {
                let mark = match (s.draw, g.ascii) {
                    (Draw::Line, false) => "──",
                    (Draw::Line, true) => "--",
                    (Draw::Points, _) => s.glyph,
                };
                legend.push((format!(" {mark} {}", g.text(&s.name)), s.style));
            }
        }
        buf.set_stringn(area.x, area.y, &head, area.width as usize, theme.dim);
        let first_x = area.x + head.chars().count() as u16 + 2;
        let mut row = 0u16;
        let mut x = first_x;
        // More rows while the plot keeps six at least.
        let max_row = area.height.saturating_sub(9).min(3);
        for (text, style) in legend {
            let w = text.chars().count() as u16;
            if x + w > area.right() && row < max_row {
                row += 1;
                x = area.x + margin;
            }
            if x + w > area.right() {
                break;
            }
            buf.set_string(x, area.y + row, &text, style);
            x += w;
        }
        // Row 0 (and more): y title and legend; last row: x ticks; left: ticks and axis.
        let plot = Rect {
            x: area.x + margin + 1,
            y: area.y + 1 + row,
            width: area.width.saturating_sub(margin + 1),
            height: area.height.saturating_sub(2 + row),
        };
        if plot.width < 4 || plot.height < 2 {
            return;
        }
        let (cols, rows) = (plot.width as usize, plot.height as usize);
        let col_of = |x: f64| ((x - x0) / (x1 - x0) * (cols - 1) as f64).round();
        let row_of = |y: f64| ((y1 - y) / (y1 - y0) * (rows - 1) as f64).round();

        // Axis and y ticks.
        let axis_x = area.x + margin;
        for r in 0..plot.height {
            buf.set_string(axis_x, plot.y + r, g.vline, theme.dim);
        }
        for (v, label) in &y_ticks {
            let r = row_of(*v);
            if r >= 0.0 && (r as usize) < rows {
                let y = plot.y + r as u16;
                let pad = margin as usize - label.len();
                buf.set_string(area.x + pad as u16, y, label, theme.dim);
                buf.set_string(axis_x, y, if g.ascii { "+" } else { "┤" }, theme.dim);
            }
        }
        // x ticks, skipping labels that would collide.
        let x_ticks = self.x_ticks.clone().unwrap_or_else(|| {
            let (_, t) = nice_ticks(x0, x1, (cols / 10).max(2));
            ticks_with_labels(&t)
        });
        let tick_row = plot.bottom();
        let mut free_from = plot.x;
        for (v, label) in x_ticks.iter().filter(|(v, _)| *v >= x0 && *v <= x1) {
            let c = plot.x as i64 + col_of(*v) as i64 - label.len() as i64 / 2;
            let c = c.clamp(
                plot.x as i64,
                (plot.right() as i64 - label.len() as i64).max(0),
            ) as u16;
            if c >= free_from {
                buf.set_string(c, tick_row, label, theme.dim);
                free_from = c + label.len() as u16 + 1;
            }
        }
        let unit = format!(" {}", self.x_title);
        let ux = area.right().saturating_sub(unit.len() as u16);
        if ux >= free_from {
            buf.set_string(ux, tick_row, &unit, theme.dim);
        }

        // Event lines under everything else, thinned to one per two columns; labels
        // at the top where they fit before the next line.
        let mut kept: Vec<(u16, &VLine)> = Vec::new();
        let mut sorted: Vec<&VLine> = self
            .vlines
            .iter()
            .filter(|v| v.x >= x0 && v.x <= x1)
            .collect();
        sorted.sort_by(|a, b| a.x.total_cmp(&b.x));
        for v in sorted {
            let c = plot.x + col_of(v.x) as u16;
            match kept.last_mut() {
                Some(last) if c < last.0 + 2 => {
                    if v.priority > last.1.priority {
                        *last = (c, v);
                    }
                }
                _ => kept.push((c, v)),
            }
        }
        for &(c, v) in &kept {
            for r in 0..plot.height {
                buf.set_string(c, plot.y + r, g.vline, v.style);
            }
        }
        if let Some(t) = self.cursor.filter(|t| *t >= x0 && *t <= x1) {
            let c = plot.x + col_of(t) as u16;
            for r in 0..plot.height {
                buf.set_string(c, plot.y + r, if g.ascii { ":" } else { "┊" }, theme.cursor);
            }
        }

        // Line series on the sub-cell grid.
        let mut grid = Grid::new(cols, rows, g.ascii);
        let (w, h) = grid.dots();
        let to_dot = |(x, y): (f64, f64)| {
            (
                (x - x0) / (x1 - x0) * (w - 1) as f64,
                (y1 - y) / (y1 - y0) * (h - 1) as f64,
            )
        };
        for s in self.series.iter().filter(|s| s.draw == Draw::Line) {
            let finite = s
                .points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite());
            let mut prev: Option<(f64, f64)> = None;
            for &p in finite {
                let d = to_dot(p);
                match prev {
                    Some(a) => grid.line(a, d, s.style, s.glyph),
                    None => grid.set(d.0.round() as i64, d.1.round() as i64, s.style, s.glyph),
                }
                prev = Some(d);
            }
        }
        for r in 0..rows {
            for c in 0..cols {
                let i = r * cols + c;
                if let Some((style, glyph)) = grid.style[i] {
                    let sym = if g.ascii {
                        glyph.to_string()
                    } else {
                        char::from_u32(0x2800 + u32::from(grid.bits[i]))
                            .unwrap_or(' ')
                            .to_string()
                    };
                    buf.set_string(plot.x + c as u16, plot.y + r as u16, sym, style);
                }
            }
        }
        // Point markers on top.
        for s in self.series.iter().filter(|s| s.draw == Draw::Points) {
            for &(x, y) in &s.points {
                if !(x.is_finite() && y.is_finite()) || x < x0 || x > x1 || y < y0 || y > y1 {
                    continue;
                }
                let (c, r) = (col_of(x) as u16, row_of(y) as u16);
                buf.set_string(plot.x + c, plot.y + r, s.glyph, s.style);
            }
        }
        // Labels right of their line if they fit before the next one, else left of it
        // if they fit after the previous line and label.
        let mut taken_until = plot.x;
        for (k, &(c, v)) in kept.iter().enumerate() {
            let Some(label) = &v.label else { continue };
            let next = kept.get(k + 1).map_or(plot.right(), |n| n.0);
            let prev = if k > 0 { kept[k - 1].0 + 1 } else { plot.x };
            let w = label.chars().count() as u16;
            if c + 1 >= taken_until && c + 1 + w < next {
                buf.set_string(c + 1, plot.y, label, v.style);
                taken_until = c + 2 + w;
            } else if c > w && c - w > prev.max(taken_until) {
                buf.set_string(c - w, plot.y, label, v.style);
                taken_until = c + 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_cover_the_range() {
        let ((lo, hi), ticks) = nice_ticks(-0.2, 0.86, 6);
        assert!(lo <= -0.2 && hi >= 0.86);
        assert_eq!(ticks.first().copied(), Some(lo));
        assert!(ticks.len() <= 8);
        let step = ticks[1] - ticks[0];
        assert!((step - 0.2).abs() < 1e-12, "{step}");
        assert_eq!(tick_label(-0.0, 0.2), "0.0");
        assert_eq!(tick_label(0.4, 0.2), "0.4");
        assert_eq!(tick_label(2.25, 0.25), "2.25");
        assert_eq!(tick_label(10.0, 5.0), "10");
    }

    #[test]
    fn zero_span_is_padded() {
        let ((lo, hi), _) = nice_ticks(0.0, 0.0, 4);
        assert!(lo < 0.0 && hi > 0.0);
    }
}
