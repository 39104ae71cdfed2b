//! The data table popup (key `d`): the measured data beside the model's values at
//! those times, scrolling.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};

use super::popup::scrolling;
use crate::settings::units::Dimension;
use crate::study::fit::NearImpacts;
use crate::study::measured::Measured;
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx};
use crate::tui::layer::DataTable;
use crate::tui::theme::Theme;

/// The data table's rows: t, then v_cm measured, model, measured − model, then the
/// same for v_t, then for x, the left ball's centre (a position track's, where the
/// model's left ball would be: x − R), SI; NaN where the data have no value (x: a
/// velocity file) or the time is outside the run.
pub fn data_rows(app: &App) -> Vec<[f64; 10]> {
    let n = app.lab.measured().map_or(0, |m| m.t().len());
    (0..n).filter_map(|i| data_row(app, i)).collect()
}

/// Row `i` of [`data_rows`].
pub(super) fn data_row(app: &App, i: usize) -> Option<[f64; 10]> {
    let m = app.lab.measured()?;
    let sol = &app.lab.solution;
    let t = *m.t().get(i)?;
    let model = (sol.t_start..=sol.t_end)
        .contains(&t)
        .then(|| sol.at(t).left);
    let (model_v, model_u, model_x) =
        model.map_or((f64::NAN, f64::NAN, f64::NAN), |b| (b.v, b.u, b.x));
    // Aligned by the impact's time and place the position fit profiles out.
    let x = app
        .lab
        .track_x
        .as_ref()
        .and_then(|x| x.get(i).copied())
        .unwrap_or(f64::NAN);
    Some([
        t,
        m.v_cm()[i],
        model_v,
        m.v_cm()[i] - model_v,
        m.v_t()[i],
        model_u,
        m.v_t()[i] - model_u,
        x,
        model_x,
        x - model_x,
    ])
}

/// The data table's header rows: its groups (x first for a position track, so that
/// a narrow screen still shows it) and their columns.
pub(super) fn data_head(track: bool, theme: &Theme) -> Vec<Line<'static>> {
    let g = theme.glyphs;
    let (groups, columns) = if track {
        let unit = POSITION.display_unit().0;
        let x = format!("{:-^28}", format!(" x ({unit}) "));
        (
            format!(
                "          {x}   ---------- v_cm (m/s) ----------  ----------- v_t (m/s) -----------"
            ),
            "   t (s)  measured     model  residual   measured     model  residual    measured     model  residual",
        )
    } else {
        (
            "          ---------- v_cm (m/s) ----------  ----------- v_t (m/s) -----------"
                .to_string(),
            "   t (s)  measured     model  residual    measured     model  residual",
        )
    };
    vec![
        Line::from(Span::styled(g.text(&groups), theme.dim)),
        Line::from(Span::styled(g.text(columns), theme.title)),
    ]
}

/// What the data table shows of a position, in the position chart's unit.
const POSITION: Dimension = Dimension::Length;

fn data_table(app: &App, first: usize, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let dash = if g.ascii { "-" } else { "–" };
    let cell = |v: f64| {
        if v.is_finite() {
            format!("{v:>+9.3}")
        } else {
            format!("{dash:>9}")
        }
    };
    let track = app.lab.measured().is_some_and(|m| m.x().is_some());
    let (head, count, width) = table_layout(app, theme);
    let times = app.lab.measured().map_or(&[][..], |m| m.t());
    let near = NearImpacts::of(times, &app.lab.solution);
    let line = |i: usize| {
        data_row(app, i).map_or_else(Line::default, |r| {
            let at_cursor = (r[0] - app.t).abs() < 1e-9;
            let left_out = near.straddles(r[0]);
            let style = match (at_cursor, left_out) {
                (true, _) => theme.selected,
                (false, true) => theme.dim,
                (false, false) => theme.text,
            };
            let mark = if left_out { '*' } else { ' ' };
            let group = |k: usize, scale: fn(f64) -> f64| {
                let [a, b, c] = [r[k], r[k + 1], r[k + 2]].map(|v| cell(scale(v)));
                format!("{a} {b} {c}")
            };
            let x = if track {
                format!("{}  ", group(7, |v| POSITION.to_display(v)))
            } else {
                String::new()
            };
            let (v_cm, v_t) = (group(1, |v| v), group(4, |v| v));
            Line::from(Span::styled(
                format!("{mark}{:>+7.4} {x}{v_cm}   {v_t}", r[0]),
                style,
            ))
        })
    };
    let title = title("Data and model", area, theme);
    scrolling(
        first,
        &title,
        head,
        (count, &line),
        (area, width),
        buf,
        theme,
    );
}

/// The table's title: `what`, then its keys, cut to leave room beside "↑ more".
fn title(what: &str, area: Rect, theme: &Theme) -> String {
    let g = theme.glyphs;
    let keys = if g.ascii {
        "up/down PgUp/PgDn scroll, Esc or q closes"
    } else {
        "↑↓ PgUp PgDn scroll, Esc or q closes"
    };
    g.ellipsize(
        &format!("{what}  ({keys})"),
        usize::from(area.width.saturating_sub(16)),
    )
    .to_string()
}

/// The data table's fixed lines, its row count and its width.
pub(super) fn table_layout(app: &App, theme: &Theme) -> (Vec<Line<'static>>, usize, u16) {
    if let Some(m) = in_file_time(app) {
        return (unfit_head(theme), m.t().len(), UNFIT_WIDTH);
    }
    let track = app.lab.measured().is_some_and(|m| m.x().is_some());
    let mut head = data_head(track, theme);
    let times = app.lab.measured().map_or(&[][..], |m| m.t());
    // The frames the velocity fit leaves out, marked and said why (a residual there
    // is the jump, not a misfit).
    if NearImpacts::of(times, &app.lab.solution).any_in(times) {
        let why = if track {
            "* left out of the velocity fit: within a frame of an impact, where v jumps (the position fit keeps it)"
        } else {
            "* left out of the fit: within a frame of an impact, where v jumps"
        };
        head.push(Line::from(Span::styled(format!(" {why}"), theme.dim)));
    }
    // While the outcome is hidden the rows end at the cursor, as the charts do: the
    // frames after it (their speeds after the impact) are the answer.
    let count = if app.hidden().derived() {
        let shown = times.iter().take_while(|&&t| t <= app.t + 1e-12).count();
        let note = "rows up to the cursor: the rest shows once the outcome does";
        head.push(Line::from(Span::styled(format!(" {note}"), theme.dim)));
        shown
    } else {
        times.len()
    };
    (head, count, if track { 110 } else { 78 })
}

impl Component for DataTable {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        match in_file_time(cx.app) {
            Some(m) => unfit_table(m, self.scroll().first(), area, buf, cx.theme),
            None => data_table(cx.app, self.scroll().first(), area, buf, cx.theme),
        }
    }
}

/// The user's data without a fit, in the file's own time, where no measured data
/// are in use (`lab::Unfit`).
fn in_file_time(app: &App) -> Option<&Measured> {
    if app.lab.measured().is_some() {
        return None;
    }
    app.lab.unfit()?.in_file_time.as_deref()
}

/// Width of the table of data without a fit.
const UNFIT_WIDTH: u16 = 60;

/// The header of the table of data without a fit: no model column (nothing aligns
/// the file's time with the model's).
fn unfit_head(theme: &Theme) -> Vec<Line<'static>> {
    let unit = POSITION.display_unit().0;
    let columns = format!(
        "   t (s)  {:>10}  {:>10}  {:>10}",
        format!("x ({unit})"),
        "v_cm (m/s)",
        "±1σ (m/s)"
    );
    vec![
        Line::from(Span::styled(
            " the file's own time, x from its first frame; no fit",
            theme.dim,
        )),
        Line::from(Span::styled(theme.glyphs.text(&columns), theme.title)),
    ]
}

/// The rows of the user's data without a fit: t, x, v_cm and its σ.
fn unfit_table(m: &Measured, first: usize, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let dash = if g.ascii { "-" } else { "–" };
    let cell = |v: Option<f64>| match v {
        Some(v) if v.is_finite() => format!("{v:>+10.4}"),
        _ => format!("{dash:>10}"),
    };
    let at = |v: Option<&[f64]>, i: usize| v.and_then(|v| v.get(i).copied());
    let line = |i: usize| {
        let Some(t) = m.t().get(i) else {
            return Line::default();
        };
        let x = at(m.x(), i).map(|x| POSITION.to_display(x));
        Line::from(Span::styled(
            format!(
                "{t:>+8.4}  {}  {}  {}",
                cell(x),
                cell(m.v_cm().get(i).copied()),
                cell(at(m.v_cm_sigma(), i)).replace('+', " ")
            ),
            theme.text,
        ))
    };
    let title = title("Data, no fit", area, theme);
    scrolling(
        first,
        &title,
        unfit_head(theme),
        (m.t().len(), &line),
        (area, UNFIT_WIDTH),
        buf,
        theme,
    );
}
