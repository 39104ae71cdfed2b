//! The charts' time zoom (issue 28: at b = 4.3 cm the run lasts 13 s and its impact
//! phase fits in two columns): a window of the span the x axis shows, zoomed in and
//! out by a factor around a time (the cursor's for the keys, the pointer's for the
//! wheel), kept in the span, and the whole span again. The axis' ticks, the curves'
//! samples and the event lines all follow the window the chart is built with.

/// A zoom factor as the title and the status line say it: 2, 4, … 4096.
pub fn text(factor: f64) -> String {
    crate::settings::units::significant(factor, 3)
}

/// A zoomed window as the status line says it, `a … b s`, with the decimals that tell
/// its ends apart (at ×4096 a window is a fraction of a millisecond: three decimals
/// would write `0.216 … 0.216 s`).
pub fn window_text(a: f64, b: f64) -> String {
    let width = (b - a).abs();
    let decimals = if width > 0.0 && width.is_finite() {
        ((-width.log10()).ceil() as i64 + 1).clamp(3, 9) as usize
    } else {
        3
    };
    format!("{a:.decimals$} … {b:.decimals$} s")
}

/// How much one zoom key or wheel notch zooms.
pub const STEP: f64 = 2.0;

/// The deepest zoom: the window is never shorter than the span over this.
pub const MAX: f64 = 4096.0;

/// The part of the span the charts show: all of it, or a window of it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TimeZoom {
    window: Option<(f64, f64)>,
}

impl TimeZoom {
    /// The x range shown over `span` (t0, t1): the window inside the span, or the
    /// whole span when nothing is zoomed (or the span changed so that the window no
    /// longer lies in it).
    pub fn range(self, span: (f64, f64)) -> (f64, f64) {
        let Some((a, b)) = self.window else {
            return span;
        };
        let (a, b) = (a.max(span.0), b.min(span.1));
        let least = (span.1 - span.0) / MAX * (1.0 - 1e-9);
        if b - a >= least && b - a < span.1 - span.0 {
            (a, b)
        } else {
            span
        }
    }

    /// How many times the window is shorter than `span` (1: the whole run).
    pub fn factor(self, span: (f64, f64)) -> f64 {
        let (a, b) = self.range(span);
        (span.1 - span.0) / (b - a)
    }

    /// Zooms in (`by` > 1) or out (`by` < 1) around `at`, which keeps its place on the
    /// axis (clamped into what is shown); the window stays in `span` and is never
    /// shorter than the span over [`MAX`]. Returns the new factor.
    pub fn zoom(&mut self, span: (f64, f64), at: f64, by: f64) -> f64 {
        let (a, b) = self.range(span);
        let full = span.1 - span.0;
        if !(full > 0.0 && by > 0.0) {
            return 1.0;
        }
        let width = ((b - a) / by).clamp(full / MAX, full);
        if width >= full * (1.0 - 1e-9) {
            self.window = None;
            return 1.0;
        }
        let at = at.clamp(a, b);
        let share = (at - a) / (b - a);
        let lo = (at - share * width).clamp(span.0, span.1 - width);
        self.window = Some((lo, lo + width));
        full / width
    }

    /// The whole span again; true if a window was shown.
    pub fn whole(&mut self) -> bool {
        self.window.take().is_some()
    }

    /// Keeps `t` (the cursor, moved by playback or a key) in the window: a cursor
    /// that left it is shown at the window's left edge (or as far left as the span
    /// allows), the window's length kept.
    pub fn follow(&mut self, t: f64, span: (f64, f64)) {
        let Some(_) = self.window else { return };
        let (a, b) = self.range(span);
        if t < a || t > b {
            let w = b - a;
            let lo = t.clamp(span.0, span.1 - w);
            self.window = Some((lo, lo + w));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_deepest_window_reads_as_two_times() {
        // Issue 37: ×4096 of a 1 s run said `0.216 … 0.216 s`.
        for (a, span) in [(0.2159, 1.0), (-0.2, 13.0), (0.0, 0.05), (3.9, 2000.0)] {
            let b = a + span / MAX;
            let text = window_text(a, b);
            let (x, y) = text.trim_end_matches(" s").split_once(" … ").unwrap();
            assert_ne!(x, y, "{text}");
            let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
            assert!(
                (x - a).abs() <= 0.1 * (b - a) && (y - b).abs() <= 0.1 * (b - a),
                "{text}"
            );
        }
        assert_eq!(window_text(-0.2, 0.8), "-0.200 … 0.800 s");
    }

    const SPAN: (f64, f64) = (-0.2, 12.8);

    #[test]
    fn zooming_in_keeps_the_time_zoomed_around_in_its_place() {
        let mut z = TimeZoom::default();
        assert_eq!(z.range(SPAN), SPAN);
        let at = 0.1;
        let share = (at - SPAN.0) / (SPAN.1 - SPAN.0);
        assert_eq!(z.zoom(SPAN, at, STEP), 2.0);
        let (a, b) = z.range(SPAN);
        assert!((b - a - 6.5).abs() < 1e-12, "{a} {b}");
        assert!(((at - a) / (b - a) - share).abs() < 1e-12);
        // Out again: the whole run, no window left.
        assert_eq!(z.zoom(SPAN, at, 1.0 / STEP), 1.0);
        assert_eq!(z, TimeZoom::default());
    }

    #[test]
    fn the_window_stays_in_the_span_and_not_below_the_deepest_zoom() {
        let mut z = TimeZoom::default();
        for _ in 0..20 {
            z.zoom(SPAN, 12.8, STEP);
        }
        let (a, b) = z.range(SPAN);
        assert!((z.factor(SPAN) - MAX).abs() < 1e-6 && b <= SPAN.1 && a >= SPAN.0);
        assert!(
            (b - SPAN.1).abs() < 1e-12,
            "the end zoomed around stays the end"
        );
        // A span that shrank past the window shows whole.
        assert_eq!(z.range((-0.2, 1.0)), (-0.2, 1.0));
        assert!(z.whole() && !z.whole());
    }

    #[test]
    fn a_cursor_that_leaves_the_window_takes_it_along() {
        let mut z = TimeZoom::default();
        z.zoom(SPAN, 0.0, 8.0);
        let (a, b) = z.range(SPAN);
        z.follow(b + 0.5, SPAN);
        let (c, d) = z.range(SPAN);
        assert!((c - (b + 0.5)).abs() < 1e-12 && ((d - c) - (b - a)).abs() < 1e-12);
        z.follow(SPAN.1, SPAN);
        assert!((z.range(SPAN).1 - SPAN.1).abs() < 1e-12);
    }
}
