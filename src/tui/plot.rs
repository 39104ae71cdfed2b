//! A small chart widget drawn straight into the buffer: line series on a braille grid
//! (or one ASCII glyph per cell), point markers, labelled vertical event lines, a
//! time cursor, and axes with round ticks and units. ratatui's Chart has no vertical
//! lines, no labels inside the plot and no ASCII mode, hence this.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use super::canvas::Canvas;
use super::theme::{Glyphs, Theme};

mod ticks;
use ticks::ticks_with_labels;
pub use ticks::{nice_ticks, tick_label};

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Draw {
    /// Straight segments between consecutive points.
    Line,
    /// One marker cell per point.
    Points,
    /// One marker cell per point, under the lines (a reference curve that the current
    /// one must not be hidden by).
    PointsUnder,
}

/// A series' points, shared: what does not change from frame to frame (the measured
/// points of a scene) is drawn without being copied.
pub type PlotPoints = std::sync::Arc<[(f64, f64)]>;

#[derive(Clone, Debug)]
pub struct PlotLine {
    pub name: String,
    pub points: PlotPoints,
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
    pub series: Vec<PlotLine>,
    pub vlines: Vec<VLine>,
    pub cursor: Option<f64>,
    /// Replaces the automatic x ticks (e.g. for log axes): positions and labels.
    pub x_ticks: Option<Vec<(f64, String)>>,
    pub y_ticks: Option<Vec<(f64, String)>>,
}

/// The x value drawn in screen column `column` of a plot whose data cells start at
/// `plot_x` and are `plot_width` wide over `x_range` (the inverse of where the plot puts
/// a value: column `i` shows `x0 + i / (width − 1) · (x1 − x0)`); `None` outside.
pub fn time_at_column(
    x_range: (f64, f64),
    plot_x: u16,
    plot_width: u16,
    column: u16,
) -> Option<f64> {
    if plot_width < 2 || column < plot_x || column >= plot_x + plot_width {
        return None;
    }
    let (x0, x1) = x_range;
    let f = f64::from(column - plot_x) / f64::from(plot_width - 1);
    Some(x0 + f * (x1 - x0))
}

impl Plot {
    /// Keeps only what lies at or before `x`: the series' points and the vertical
    /// lines (a chart that must not show what comes later: the outcome, while it is
    /// to be predicted). The axes stay, so the picture does not jump.
    pub fn until(&mut self, x: f64) {
        for s in &mut self.series {
            if s.points.iter().any(|p| p.0 > x) {
                s.points = s.points.iter().copied().filter(|p| p.0 <= x).collect();
            }
        }
        self.vlines.retain(|v| v.x <= x);
    }

    fn y_ticks_in(&self, area: Rect) -> Vec<(f64, String)> {
        let (y0, y1) = self.y_range;
        let y_ticks = self.y_ticks.clone().unwrap_or_else(|| {
            let (_, t) = nice_ticks(y0, y1, (area.height as usize / 2).max(2));
            ticks_with_labels(&t)
        });
        y_ticks
            .into_iter()
            .filter(|(v, _)| *v >= y0 && *v <= y1)
            .collect()
    }

    /// Width of the y tick labels: the plot starts right of them. Labels are short
    /// (scientific beyond 1e6), but a margin never eats more than half the area.
    fn margin(&self, area: Rect) -> u16 {
        self.y_ticks_in(area)
            .iter()
            .map(|(_, l)| l.chars().count())
            .max()
            .unwrap_or(1)
            .min(usize::from(area.width / 2)) as u16
    }

    /// The legend: a mark and a name for every named series, on the title row after
    /// the y title and, if they do not fit there, on up to three more rows (taken from
    /// the plot while it keeps six rows at least). Returns each entry's text, style,
    /// column and row (0 = the title row), and the number of extra rows used.
    /// [`Plot::data_area`] and [`Plot::render`] both use it, so a click maps to the
    /// cells that are drawn.
    #[allow(clippy::type_complexity)]
    fn legend(&self, area: Rect, glyphs: &Glyphs) -> (Vec<(String, Style, u16, u16)>, u16) {
        let margin = self.margin(area);
        let first_x = area.x + self.y_title.chars().count() as u16 + 2;
        let max_row = area.height.saturating_sub(9).min(3);
        let (mut row, mut x) = (0u16, first_x);
        let mut out = Vec::new();
        for s in self.series.iter().filter(|s| !s.name.is_empty()) {
            // ASCII lines are drawn with their glyph: the legend shows it twice.
            let mark = match (s.draw, glyphs.ascii) {
                (Draw::Line, false) => "──".to_string(),
                (Draw::Line, true) => format!("{0}{0}", s.glyph),
                (Draw::Points | Draw::PointsUnder, _) => s.glyph.to_string(),
            };
            let text = format!(" {mark} {}", glyphs.text(&s.name));
            let w = text.chars().count() as u16;
            if x.saturating_add(w) > area.right() && row < max_row {
                row += 1;
                x = area.x + margin;
            }
            if x.saturating_add(w) > area.right() {
                break;
            }
            out.push((text, s.style, x, row));
            x += w;
        }
        (out, row)
    }

    /// The data cells of the plot drawn in `area` with `theme`'s glyphs (right of the
    /// y axis, below the title and legend rows, above the x tick row); `None` if the
    /// area is too small to draw.
    pub fn data_area(&self, area: Rect, theme: &Theme) -> Option<Rect> {
        if area.width < 12 || area.height < 4 {
            return None;
        }
        let margin = self.margin(area);
        let (_, row) = self.legend(area, &theme.glyphs);
        let plot = Rect {
            x: area.x + margin + 1,
            y: area.y + 1 + row,
            width: area.width.saturating_sub(margin + 1),
            height: area.height.saturating_sub(2 + row),
        };
        (plot.width >= 4 && plot.height >= 2).then_some(plot)
    }

    /// The x value under screen cell (`column`, `row`) of the plot drawn in `area`
    /// with `theme`.
    pub fn x_at(&self, area: Rect, theme: &Theme, column: u16, row: u16) -> Option<f64> {
        let plot = self.data_area(area, theme)?;
        if row < plot.y || row >= plot.bottom() {
            return None;
        }
        time_at_column(self.x_range, plot.x, plot.width, column)
    }

    /// Where the plot drawn in `area` with `theme` puts a value: its data cells and
    /// the ranges over them (`None` if the area is too small to draw).
    pub fn cells(&self, area: Rect, theme: &Theme) -> Option<Cells> {
        Some(Cells {
            plot: self.data_area(area, theme)?,
            x_range: self.x_range,
            y_range: self.y_range,
        })
    }

    pub fn render(&self, area: Rect, buf: &mut Buffer, theme: &Theme) {
        let Some(cells) = self.cells(area, theme) else {
            return;
        };
        let plot = cells.plot;
        // Title and legend (the same layout data_area made room for).
        buf.set_stringn(
            area.x,
            area.y,
            &self.y_title,
            area.width as usize,
            theme.dim,
        );
        let (legend, _) = self.legend(area, &theme.glyphs);
        for (text, style, x, row) in legend {
            buf.set_string(x, area.y + row, &text, style);
        }
        // Row 0 (and more): y title and legend; last row: x ticks; left: ticks and axis.
        self.draw_y_axis(area, &cells, buf, theme);
        self.draw_x_ticks(area, &cells, buf, theme);
        // Event lines under everything else, thinned to one per two columns; labels
        // at the top where they fit before the next line.
        let kept = self.event_lines(&cells);
        for &(c, v) in &kept {
            for r in 0..plot.height {
                buf.set_string(c, plot.y + r, theme.glyphs.vline, v.style);
            }
        }
        let (x0, x1) = self.x_range;
        if let Some(t) = self.cursor.filter(|t| *t >= x0 && *t <= x1) {
            let c = plot.x + cells.col_of(t) as u16;
            let mark = if theme.glyphs.ascii { ":" } else { "┊" };
            for r in 0..plot.height {
                buf.set_string(c, plot.y + r, mark, theme.cursor);
            }
        }
        self.draw_series(&cells, buf, theme);
        draw_event_labels(&kept, plot, buf);
    }

    /// The axis line and the y ticks with their labels, right-aligned in the margin.
    fn draw_y_axis(&self, area: Rect, cells: &Cells, buf: &mut Buffer, theme: &Theme) {
        let (g, plot) = (theme.glyphs, cells.plot);
        let margin = plot.x - area.x - 1;
        let axis_x = area.x + margin;
        for r in 0..plot.height {
            buf.set_string(axis_x, plot.y + r, g.vline, theme.dim);
        }
        let rows_apart = |kept: &[(f64, String)]| {
            kept.windows(2)
                .all(|w| cells.row_of(w[0].0) != cells.row_of(w[1].0))
        };
        for (v, label) in &evenly(self.y_ticks_in(area), rows_apart) {
            let r = cells.row_of(*v);
            if r >= 0.0 && (r as usize) < cells.rows() {
                let y = plot.y + r as u16;
                let pad = usize::from(margin).saturating_sub(label.chars().count());
                buf.set_stringn(
                    area.x + pad as u16,
                    y,
                    label,
                    usize::from(margin),
                    theme.dim,
                );
                buf.set_string(axis_x, y, if g.ascii { "+" } else { "┤" }, theme.dim);
            }
        }
    }

    /// The x title (quantity and unit) at the right end of the tick row, and the x
    /// ticks' labels left of it, evenly spaced, skipping those that would collide: the
    /// title has its place first, so the axis always says what it measures (a last
    /// tick label under it once hid it at most sizes).
    fn draw_x_ticks(&self, area: Rect, cells: &Cells, buf: &mut Buffer, theme: &Theme) {
        let plot = cells.plot;
        let (x0, x1) = self.x_range;
        let x_ticks = self.x_ticks.clone().unwrap_or_else(|| {
            let (_, t) = nice_ticks(x0, x1, (cells.cols() / 10).max(2));
            ticks_with_labels(&t)
        });
        let tick_row = plot.bottom();
        // The title (quantity and unit) first, at the right end: the labels end before
        // it (its leading space keeps them apart); a plot too narrow for the title
        // keeps its labels instead.
        let unit = format!(" {}", self.x_title);
        let ux = i64::from(area.right()) - unit.chars().count() as i64;
        let labels_end = if ux >= i64::from(plot.x) {
            buf.set_string(ux as u16, tick_row, &unit, theme.dim);
            ux.min(i64::from(plot.right()))
        } else {
            i64::from(plot.right())
        };
        // Centred under its tick, kept inside the plot; a label wider than the plot
        // starts at its left edge (and is cut by the buffer).
        let column = |v: f64, label: &str| {
            let w = label.chars().count() as i64;
            let left = i64::from(plot.x);
            let c = (left + cells.col_of(v) as i64 - w / 2)
                .min(i64::from(plot.right()) - w)
                .max(left);
            (c, w)
        };
        // Labels that would collide are skipped.
        let placed = |ticks: &[(f64, String)]| {
            let mut free_from = i64::from(plot.x);
            let mut out = Vec::new();
            for (v, label) in ticks {
                let (c, w) = column(*v, label);
                if c >= free_from && c + w <= i64::from(plot.right()) {
                    out.push((c as u16, label.clone()));
                    free_from = c + w + 1;
                }
            }
            out
        };
        // The ticks whose labels end before the title, spaced evenly.
        let inside: Vec<(f64, String)> = x_ticks
            .into_iter()
            .filter(|(v, l)| {
                *v >= x0 && *v <= x1 && column(*v, l).0 + column(*v, l).1 <= labels_end
            })
            .collect();
        for (c, label) in placed(&evenly(inside, |kept| placed(kept).len() == kept.len())) {
            buf.set_string(c, tick_row, &label, theme.dim);
        }
    }

    /// The event lines inside the x range at their columns, one per two columns (the
    /// higher priority kept), left to right.
    fn event_lines(&self, cells: &Cells) -> Vec<(u16, &VLine)> {
        let (x0, x1) = self.x_range;
        let mut kept: Vec<(u16, &VLine)> = Vec::new();
        let mut sorted: Vec<&VLine> = self
            .vlines
            .iter()
            .filter(|v| v.x >= x0 && v.x <= x1)
            .collect();
        sorted.sort_by(|a, b| a.x.total_cmp(&b.x));
        for v in sorted {
            let c = cells.plot.x + cells.col_of(v.x) as u16;
            match kept.last_mut() {
                Some(last) if c < last.0 + 2 => {
                    if v.priority > last.1.priority {
                        *last = (c, v);
                    }
                }
                _ => kept.push((c, v)),
            }
        }
        kept
    }

    /// Markers drawn under the lines, line series on the sub-cell grid, then point
    /// markers on top.
    fn draw_series(&self, cells: &Cells, buf: &mut Buffer, theme: &Theme) {
        self.draw_points(Draw::PointsUnder, cells, buf);
        let plot = cells.plot;
        let ((x0, x1), (y0, y1)) = (self.x_range, self.y_range);
        let mut grid = Canvas::new(cells.cols(), cells.rows(), theme.glyphs.ascii);
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
        grid.write(plot.x, plot.y, buf);
        self.draw_points(Draw::Points, cells, buf);
    }

    /// The marker series drawn as `draw`, one cell per point inside the ranges.
    fn draw_points(&self, draw: Draw, cells: &Cells, buf: &mut Buffer) {
        for s in self.series.iter().filter(|s| s.draw == draw) {
            for (c, r) in s.points.iter().filter_map(|&p| cells.cell_of(p)) {
                let (x, y) = (cells.plot.x + c as u16, cells.plot.y + r as u16);
                buf.set_string(x, y, s.glyph, s.style);
            }
        }
    }
}

/// The plot's data area and the value ranges it shows: where a value goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cells {
    plot: Rect,
    x_range: (f64, f64),
    y_range: (f64, f64),
}

impl Cells {
    /// The cell a marker at `(x, y)` is drawn in (column, row from the data area's
    /// top left), `None` if it is not drawn (not finite, or outside the ranges).
    fn cell_of(&self, (x, y): (f64, f64)) -> Option<(usize, usize)> {
        let ((x0, x1), (y0, y1)) = (self.x_range, self.y_range);
        if !(x.is_finite() && y.is_finite()) || x < x0 || x > x1 || y < y0 || y > y1 {
            return None;
        }
        Some((self.col_of(x) as usize, self.row_of(y) as usize))
    }

    /// One point of `points` for each cell they mark: drawn as markers ([`Draw::Points`])
    /// they fill the same cells with the same glyph as all of them (a series marks a
    /// cell with its one glyph however many of its points fall there), so a million
    /// measured rows draw as at most one point per cell of the plot.
    pub fn thin(&self, points: &[(f64, f64)]) -> Vec<(f64, f64)> {
        let cols = self.cols();
        let mut marked = vec![false; cols * self.rows()];
        let mut out = Vec::new();
        for &p in points {
            if let Some((c, r)) = self.cell_of(p)
                && !std::mem::replace(&mut marked[r * cols + c], true)
            {
                out.push(p);
            }
        }
        out
    }

    fn cols(&self) -> usize {
        self.plot.width as usize
    }

    fn rows(&self) -> usize {
        self.plot.height as usize
    }

    /// The column of `x` (whole, from the data area's left), always one of the plot.
    fn col_of(&self, x: f64) -> f64 {
        let (x0, x1) = self.x_range;
        let last = (self.cols() - 1) as f64;
        (frac(x, x0, x1) * last).round().clamp(0.0, last)
    }

    /// The row of `y` (whole, from the data area's top), always one of the plot.
    fn row_of(&self, y: f64) -> f64 {
        let (y0, y1) = self.y_range;
        let last = (self.rows() - 1) as f64;
        (frac(y, y1, y0) * last).round().clamp(0.0, last)
    }
}

/// Every k-th of `ticks`, k the smallest for which `fits` the labels kept (each on a
/// row of its own, or side by side without colliding), counted from the tick at 0
/// when there is one: evenly spaced labels (1e0, 1e-2, 1e-4), never one here and
/// there where another collided (1e0, 1e-1, 1e-3).
fn evenly(
    ticks: Vec<(f64, String)>,
    fits: impl Fn(&[(f64, String)]) -> bool,
) -> Vec<(f64, String)> {
    let anchor = ticks.iter().position(|(v, _)| *v == 0.0).unwrap_or(0);
    let every = |k: usize| -> Vec<(f64, String)> {
        ticks
            .iter()
            .enumerate()
            .filter(|(i, _)| i.abs_diff(anchor).is_multiple_of(k))
            .map(|(_, t)| t.clone())
            .collect()
    };
    (1..=ticks.len().max(1))
        .map(every)
        .find(|kept| fits(kept))
        .unwrap_or_default()
}

/// Where `v` lies from `a` to `b`, as a fraction. From halves, which cannot overflow
/// for finite bounds (−1e308 … 1e308); NaN for NaN (a cell's `clamp` makes it 0).
fn frac(v: f64, a: f64, b: f64) -> f64 {
    (v / 2.0 - a / 2.0) / (b / 2.0 - a / 2.0)
}

/// The event lines' labels on the top row, the most important first (T∞ before the
/// burst of impacts), then in time order: right of their line if they fit before the
/// next one, else left of it if they fit after the previous one; then, for the labels
/// that found no such room, right or left over the tops of other lines. A label never
/// overlaps another (nor its line) and stays in the plot: dense events (a pinned run's
/// longer span squeezes them) keep their labels rather than lose them.
fn draw_event_labels(kept: &[(u16, &VLine)], plot: Rect, buf: &mut Buffer) {
    // In i64: a long label must not overflow u16 arithmetic.
    let (lo, hi) = (i64::from(plot.x), i64::from(plot.right()));
    let mut order: Vec<usize> = (0..kept.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(kept[k].1.priority));
    // Placed labels as [from, to) columns, each with its line and a gap after it.
    let mut taken: Vec<(i64, i64)> = Vec::new();
    let mut placed = vec![false; kept.len()];
    for over_lines in [false, true] {
        for &k in &order {
            let (c, v) = kept[k];
            let Some(label) = v.label.as_ref().filter(|_| !placed[k]) else {
                continue;
            };
            let (c, w) = (i64::from(c), label.chars().count() as i64);
            let next = kept.get(k + 1).map_or(hi, |n| i64::from(n.0));
            let prev = k.checked_sub(1).map_or(lo - 1, |p| i64::from(kept[p].0));
            let right = (c + 1, (c, c + 2 + w));
            let left = (c - w, (c - w - 1, c + 1));
            let spot = [
                (right, over_lines || c + 1 + w < next),
                (left, over_lines || c - w > prev + 1),
            ]
            .into_iter()
            .find(|&((_, (from, to)), room)| {
                room && from >= lo && to <= hi && taken.iter().all(|&(a, b)| to <= a || from >= b)
            });
            if let Some(((x, interval), _)) = spot {
                buf.set_string(x as u16, plot.y, label, v.style);
                taken.push(interval);
                placed[k] = true;
            }
        }
    }
}

#[cfg(test)]
mod tests;
