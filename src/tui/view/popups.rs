//! Popups over the main screen: help (from the key table) and the data table, both
//! scrolling; the preset picker; the save and export prompts.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

use super::panel::{block, wrap};
use crate::settings::units::Dimension;
use crate::study::fit::NearImpacts;
use crate::study::preset::Origin;
use crate::tui::app::export::export_step;
use crate::tui::app::{App, Export, Field, Mode, Status};
use crate::tui::keys::TABLE;
use crate::tui::line::caret;
use crate::tui::theme::Theme;

fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let w = width.min(area.width.saturating_sub(2));
    let h = height.min(area.height.saturating_sub(2));
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

fn popup(
    title: &str,
    lines: Vec<Line<'_>>,
    area: Rect,
    width: u16,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let rect = centered(area, width, lines.len() as u16 + 2);
    Clear.render(rect, buf);
    let blk = block(theme.glyphs.text(&format!(" {title} ")), theme);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(blk)
        .render(rect, buf);
}

/// Where a scrolling popup of `width` with `head` fixed lines over `count` scrolling
/// ones goes on a screen of `area`, how many scrolling lines show, and how far it
/// scrolls.
fn scroll_frame(area: Rect, width: u16, head: usize, count: usize) -> (Rect, usize, usize) {
    let rect = centered(
        area,
        width,
        (head + count).min(usize::from(u16::MAX - 2)) as u16 + 2,
    );
    let visible = usize::from(rect.height.saturating_sub(2)).saturating_sub(head);
    (rect, visible, count.saturating_sub(visible))
}

/// How far the open help or data table scrolls on a screen of `area` (a key never
/// scrolls into blank lines); `usize::MAX` for anything else.
pub fn scroll_max(app: &App, area: Rect, theme: &Theme) -> usize {
    match &app.mode {
        Mode::Help => {
            let width = help_width(area);
            let lines = help_lines(usize::from(width.saturating_sub(2)), theme);
            scroll_frame(area, width, 0, lines.len()).2
        }
        Mode::Table => {
            let (head, count, width) = table_layout(app, theme);
            scroll_frame(area, width, head.len(), count).2
        }
        Mode::Normal
        | Mode::Picker(_)
        | Mode::Edit(_)
        | Mode::SaveName(_)
        | Mode::ConfirmOverwrite(_)
        | Mode::Export(..)
        | Mode::Predict => usize::MAX,
    }
}

/// A popup of `width` whose `lines` scroll: as many as fit from `app.scroll`, "more ↓"
/// on the bottom border while lines are below, "↑ more" on the top one while lines
/// are above.
fn scrolling<'a>(
    app: &App,
    title: &str,
    head: Vec<Line<'a>>,
    (count, line): (usize, &dyn Fn(usize) -> Line<'a>),
    (area, width): (Rect, u16),
    buf: &mut Buffer,
    theme: &Theme,
) {
    let g = theme.glyphs;
    let (rect, visible, max) = scroll_frame(area, width, head.len(), count);
    Clear.render(rect, buf);
    let first = app.scroll.min(max);
    let mut blk: Block = block(g.text(&format!(" {title} ")), theme);
    if first + visible < count {
        let more = g.text(&format!(" more ↓ ({} of {count}) ", first + visible));
        blk = blk.title_bottom(Line::from(Span::styled(more, theme.key)).right_aligned());
    }
    if first > 0 {
        blk =
            blk.title_top(Line::from(Span::styled(g.text(" ↑ more "), theme.key)).right_aligned());
    }
    let inner = blk.inner(rect);
    blk.render(rect, buf);
    // Only the rows on screen are made (a data table can have a million).
    let shown: Vec<Line> = head
        .into_iter()
        .chain((first..count.min(first + visible)).map(line))
        .collect();
    super::panel::draw_lines(shown, inner, buf);
}

/// The help's lines at `width`: every binding of the key table, descriptions wrapped
/// under themselves, then the mouse.
fn help_lines(width: usize, theme: &Theme) -> Vec<Line<'static>> {
    let g = theme.glyphs;
    let keys_width = 14;
    let text_width = width.saturating_sub(keys_width + 2).max(10);
    let mut lines = Vec::new();
    for b in TABLE {
        let keys = b.keys.join(" ");
        let rows = wrap(Line::from(g.text(b.help)), text_width);
        for (i, row) in rows.into_iter().enumerate() {
            let lead = if i == 0 {
                format!(" {keys:<keys_width$} ")
            } else {
                " ".repeat(keys_width + 2)
            };
            let mut spans = vec![Span::styled(lead, theme.key)];
            spans.extend(row.spans.into_iter().map(|s| s.style(theme.text)));
            lines.push(Line::from(spans));
        }
    }
    let mouse = "Mouse: click a parameter to select it, scroll on it to change it; click or drag on the chart to seek; click a preset to select it, again to load it.";
    for row in wrap(Line::from(format!(" {mouse}")), width) {
        lines.push(row.style(theme.dim));
    }
    lines
}

/// The data table's rows: t, then v_cm measured, model, measured − model, then the
/// same for v_t, then for x, the left ball's centre (a position track's, where the
/// model's left ball would be: x − R), SI; NaN where the data have no value (x: a
/// velocity file) or the time is outside the run.
pub fn data_rows(app: &App) -> Vec<[f64; 10]> {
    let n = app.lab.measured().map_or(0, |m| m.t.len());
    (0..n).filter_map(|i| data_row(app, i)).collect()
}

/// Row `i` of [`data_rows`].
fn data_row(app: &App, i: usize) -> Option<[f64; 10]> {
    let m = app.lab.measured()?;
    let sol = &app.lab.solution;
    let t = *m.t.get(i)?;
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
        m.v_cm[i],
        model_v,
        m.v_cm[i] - model_v,
        m.v_t[i],
        model_u,
        m.v_t[i] - model_u,
        x,
        model_x,
        x - model_x,
    ])
}

/// The data table's header rows: its groups (x first for a position track, so that
/// a narrow screen still shows it) and their columns.
fn data_head(track: bool, theme: &Theme) -> Vec<Line<'static>> {
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

fn data_table(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let dash = if g.ascii { "-" } else { "–" };
    let cell = |v: f64| {
        if v.is_finite() {
            format!("{v:>+9.3}")
        } else {
            format!("{dash:>9}")
        }
    };
    let track = app.lab.measured().is_some_and(|m| m.x.is_some());
    let (head, count, width) = table_layout(app, theme);
    let times = app.lab.measured().map_or(&[][..], |m| &m.t[..]);
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
    let title = if g.ascii {
        "Data and model  (up/down pgup/pgdn scroll, Esc or q closes)"
    } else {
        "Data and model  (↑↓ PgUp PgDn scroll, Esc or q closes)"
    };
    // Room for the title beside "↑ more".
    let title = g.ellipsize(title, usize::from(area.width.saturating_sub(16)));
    scrolling(app, &title, head, (count, &line), (area, width), buf, theme);
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    match &app.mode {
        Mode::Normal | Mode::Edit(_) => {}
        Mode::Help => help(app, area, buf, theme),
        Mode::Table => data_table(app, area, buf, theme),
        Mode::Predict => super::predict::question(app, area, buf, theme),
        Mode::Picker(selected) => preset_picker(app, *selected, area, buf, theme),
        Mode::SaveName(field) => save_prompt(app, field, area, buf, theme),
        Mode::Export(kind, field) => export_prompt(app, *kind, field, area, buf, theme),
        Mode::ConfirmOverwrite(name) => confirm_overwrite(name, area, buf, theme),
    }
}

/// The data table's fixed lines, its row count and its width.
fn table_layout(app: &App, theme: &Theme) -> (Vec<Line<'static>>, usize, u16) {
    let track = app.lab.measured().is_some_and(|m| m.x.is_some());
    let mut head = data_head(track, theme);
    let times = app.lab.measured().map_or(&[][..], |m| &m.t[..]);
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
    (head, times.len(), if track { 110 } else { 78 })
}

/// The help's width on a screen of `area`.
fn help_width(area: Rect) -> u16 {
    area.width.saturating_sub(2).min(86)
}

/// The keys, scrolling.
fn help(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let width = help_width(area);
    let lines = help_lines(usize::from(width.saturating_sub(2)), theme);
    let title = if theme.glyphs.ascii {
        "Keys  (Esc or q closes, up/down pgup/pgdn scroll)"
    } else {
        "Keys  (Esc or q closes, ↑↓ PgUp PgDn scroll)"
    };
    let line = |i: usize| lines[i].clone();
    let source: (usize, &dyn Fn(usize) -> Line<'static>) = (lines.len(), &line);
    scrolling(app, title, Vec::new(), source, (area, width), buf, theme);
}

/// Where the preset picker is drawn on a screen of `area`, and how many of its rows
/// show.
fn picker_rect(app: &App, area: Rect) -> (Rect, usize) {
    let n = app.library.presets.len();
    let rect = centered(area, area.width.saturating_sub(4), n as u16 + 2);
    (rect, n.min(usize::from(rect.height.saturating_sub(2))))
}

/// The preset under screen cell (`column`, `row`) of the picker on a screen of
/// `area`, if a row of it is there (what a click picks).
pub fn picker_row_at(app: &App, area: Rect, column: u16, row: u16) -> Option<usize> {
    let (rect, shown) = picker_rect(app, area);
    let inside = column > rect.x && column + 1 < rect.right() && row > rect.y;
    let i = usize::from(row.checked_sub(rect.y + 1)?);
    (inside && i < shown).then_some(i)
}

/// The presets to load, one row each with the `selected` one marked.
fn preset_picker(app: &App, selected: usize, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let name_width = app
        .library
        .presets
        .iter()
        .map(|p| p.name.len())
        .max()
        .unwrap_or(8);
    // One row per preset: the description cut with an ellipsis, never wrapped.
    let room = usize::from(area.width.saturating_sub(8));
    let lines: Vec<Line> = app
        .library
        .presets
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let style = if i == selected {
                theme.selected
            } else {
                theme.text
            };
            let mark = if i == selected { g.selected } else { " " };
            // A file of the user's named like a built-in one: both are listed, and
            // this row loads the file (`--preset NAME` finds the built-in).
            let twin = matches!(p.origin, Origin::File(_))
                && app
                    .library
                    .presets
                    .iter()
                    .any(|q| q.origin == Origin::BuiltIn && q.name == p.name);
            let tag = if twin {
                "[your file, named like a built-in] "
            } else {
                ""
            };
            let text = format!("{mark}{:<name_width$}  {tag}{}", p.name, p.description);
            Line::from(Span::styled(g.ellipsize(&text, room), style))
        })
        .collect();
    popup(
        "Presets  (Enter or a second click loads, Esc or q closes)",
        lines,
        area,
        area.width.saturating_sub(4),
        buf,
        theme,
    );
}

/// The name to save the scene under, and where it goes.
fn save_prompt(app: &App, field: &Field, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let dir = app
        .library
        .dir
        .as_ref()
        .map_or("(no preset folder)".to_string(), |d| {
            d.display().to_string()
        });
    prompt(
        app,
        "Save the scene as a user preset",
        (" name: ", field),
        &[
            format!(" saved in {dir}"),
            if app.lab.measured().is_some() {
                " letters, digits, - _ . (the measured data are saved too)".into()
            } else {
                " letters, digits, - _ .".into()
            },
            " Enter saves, Esc cancels".into(),
        ]
        .into_iter()
        .chain(suggestion_note(field))
        .collect::<Vec<_>>(),
        area,
        buf,
        theme,
    );
}

/// The file to export the run (CSV) or the chart (SVG) to, and what it will hold.
fn export_prompt(
    app: &App,
    kind: Export,
    field: &Field,
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let (title, what) = match kind {
        Export::Csv => {
            let sol = &app.lab.solution;
            let dt = export_step(sol.t_end - sol.t_start);
            (
                "Export the run as CSV",
                format!(
                    " its scene, then t, x, v, u, both balls, every {}; --data loads it",
                    crate::settings::units::show(dt, crate::settings::units::Dimension::Time)
                ),
            )
        }
        Export::Svg => (
            "Export the figure on screen as SVG",
            match app.figure_on_screen() {
                Ok(f) => format!(" {}", f.describe()),
                Err(e) => format!(" {e}"),
            },
        ),
    };
    prompt(
        app,
        title,
        (" file: ", field),
        &[
            what,
            if app.export_dir == std::path::Path::new(".") {
                " in the folder groovelab was started in, unless a path is given".into()
            } else {
                format!(" in {} unless a path is given", app.export_dir.display())
            },
            " Enter writes (replacing a file of that name), Esc cancels".into(),
        ]
        .into_iter()
        .chain(suggestion_note(field))
        .collect::<Vec<_>>(),
        area,
        buf,
        theme,
    );
}

/// While a prompt holds its suggested name untouched: how to keep or replace it.
fn suggestion_note(field: &Field) -> Option<String> {
    field
        .is_suggestion()
        .then(|| " typing replaces the suggested name; ← → edit it".into())
}

/// Asks before a save replaces the preset file `name`.
fn confirm_overwrite(name: &str, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let lines = vec![
        Line::from(Span::styled(
            theme.glyphs.ellipsize(
                &format!(" {name}.toml exists. Overwrite it? y / n"),
                usize::from(area.width.saturating_sub(6)),
            ),
            theme.error,
        )),
        Line::from(Span::styled(" (its description is kept)", theme.dim)),
    ];
    popup("Save", lines, area, 60, buf, theme);
}

/// A prompt popup: the field, notes under it, and the error that kept it open.
fn prompt(
    app: &App,
    title: &str,
    (label, field): (&str, &Field),
    notes: &[String],
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let g = theme.glyphs;
    let width = area.width.saturating_sub(4).min(74);
    let room = usize::from(width.saturating_sub(2));
    // The line around its cursor, the cursor's cell reversed.
    let (shown, at) = field.shown(room.saturating_sub(label.chars().count() + 1));
    let piece =
        |from: usize, to: usize| -> String { shown.chars().skip(from).take(to - from).collect() };
    let end = shown.chars().count();
    let mut lines = vec![Line::from(vec![
        Span::styled(label.to_string(), theme.text),
        Span::styled(g.text(&piece(0, at)), theme.text),
        Span::styled(g.text(&piece(at, at + 1)), caret(theme.text)),
        Span::styled(g.text(&piece(at + 1, end)), theme.text),
    ])];
    if let Status::Error(e) = &app.status {
        for row in wrap(Line::from(g.text(&format!(" {e}"))), room) {
            lines.push(row.style(theme.error));
        }
    }
    for n in notes {
        lines.push(Line::from(Span::styled(g.ellipsize(n, room), theme.dim)));
    }
    popup(title, lines, area, width, buf, theme);
}
