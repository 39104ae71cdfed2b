//! What the charts mark beside the curves: the measured series with their error
//! bars, and the line fit's lines and window.

use std::sync::Arc;

use crate::lab::MeasuredPoints;
use crate::study::fit::LineFit;
use crate::tui::plot::{Draw, PlotLine, VLine};
use crate::tui::theme::Theme;

/// The measured v_cm and v_t as marks, with each derived point's ±1σ (a position
/// track's local fits) as a vertical run of dots under the point's own glyph; the
/// points are the snapshot's, shared, not copied per frame.
pub(super) fn measured_velocities(m: &MeasuredPoints, theme: &Theme) -> Vec<PlotLine> {
    let mut series = Vec::new();
    for (n, bars) in [&m.v_cm_bars, &m.v_t_bars].into_iter().enumerate() {
        if let Some(bars) = bars {
            series.push(PlotLine {
                // One legend entry for both series' bars.
                name: if n == 0 {
                    // σ has no ASCII letter: "sd" (standard deviation), not "s".
                    if theme.glyphs.ascii {
                        "+-1 sd"
                    } else {
                        "±1σ"
                    }
                    .to_string()
                } else {
                    String::new()
                },
                points: Arc::clone(bars),
                style: theme.measured,
                // Not ':' or '|': the event lines use those.
                glyph: if theme.glyphs.ascii { "!" } else { "¦" },
                draw: Draw::Points,
            });
        }
    }
    let marks = |name: &str, points, ascii, unicode| PlotLine {
        name: name.into(),
        points,
        style: theme.measured,
        glyph: if theme.glyphs.ascii { ascii } else { unicode },
        draw: Draw::Points,
    };
    // Not aligned with the model's time (no impact found): said in the legend.
    let v_cm = if m.in_file_time {
        "v_cm, file's t"
    } else {
        "measured v_cm"
    };
    series.push(marks(v_cm, Arc::clone(&m.v_cm), "x", "×"));
    // A track without a rim mark measures no v_t: no legend entry claims one.
    if !m.v_t.is_empty() {
        series.push(marks("measured v_t", Arc::clone(&m.v_t), "o", "+"));
    }
    series
}

/// The paper's straight lines over the fit window, and the window's ends.
pub(super) fn line_fit_marks(l: &LineFit, theme: &Theme) -> (Vec<PlotLine>, Vec<VLine>) {
    let lines = l
        .lines
        .iter()
        .zip(["fit lines", ""])
        .map(|(line, name)| PlotLine {
            name: name.to_string(),
            points: [l.from, l.to]
                .iter()
                .map(|&t| (t, line.intercept + line.slope * t))
                .collect(),
            style: theme.cursor,
            glyph: "-",
            draw: Draw::Line,
        })
        .collect();
    let ends = [(l.from, "from"), (l.to, "to")]
        .into_iter()
        .map(|(t, label)| VLine {
            x: t,
            label: Some(label.to_string()),
            style: theme.cursor,
            priority: 2,
        })
        .collect();
    (lines, ends)
}
