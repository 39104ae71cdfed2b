//! Popups over the main screen: help (from the key table) and the data table, both
//! scrolling; the preset picker; the save and export prompts.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};

use super::panel::wrap;
use super::popup::{popup, scroll_frame, scrolling};
use super::table::table_layout;
use crate::study::preset::PresetOrigin;
use crate::tui::app::export::export_step;
use crate::tui::app::{App, Export, Field, Status};
use crate::tui::component::{Component, Ctx};
use crate::tui::keys::TABLE;
use crate::tui::layer::{Confirm, Help, Layer, Picker, Prompt};
use crate::tui::line::caret;
use crate::tui::theme::Theme;
use crate::tui::vocabulary::TextTarget;

/// How far the open help or data table scrolls on a screen of `area` (a key never
/// scrolls into blank lines); `usize::MAX` for anything else.
pub fn scroll_max(app: &App, area: Rect, theme: &Theme) -> usize {
    match app.layers().top() {
        Some(Layer::Help(_)) => {
            let width = help_width(area);
            let lines = help_lines(usize::from(width.saturating_sub(2)), theme, last(app));
            scroll_frame(area, width, 0, lines.len()).2
        }
        Some(Layer::Table(_)) => {
            let (head, count, width) = table_layout(app, theme);
            scroll_frame(area, width, head.len(), count).2
        }
        Some(Layer::Models(_)) => {
            let (lines, width) = super::models::lines(app, theme);
            scroll_frame(area, width, 0, lines.len()).2
        }
        Some(Layer::Picker(_) | Layer::Prompt(_) | Layer::Confirm(_) | Layer::Question(_))
        | None => usize::MAX,
    }
}

/// The status line's message, where one is (an error or a note): the help shows it
/// whole, as a long one is cut on the status line's two rows at 80 columns.
fn last(app: &App) -> Option<(&str, bool)> {
    match &app.status {
        Status::Error(e) => Some((e.as_str(), true)),
        Status::Info(i) => Some((i.as_str(), false)),
        Status::None | Status::Predicted => None,
    }
}

/// The help's lines at `width`: the last message whole (`last`: its text, and
/// whether it is an error), then every binding of the key table, descriptions
/// wrapped under themselves, then the mouse.
fn help_lines(width: usize, theme: &Theme, last: Option<(&str, bool)>) -> Vec<Line<'static>> {
    let g = theme.glyphs;
    let mut lines = Vec::new();
    if let Some((message, error)) = last.filter(|(m, _)| !m.is_empty()) {
        let style = if error { theme.error } else { theme.text };
        let said = g.text(&format!("Last message: {message}"));
        for row in wrap(Line::from(said), width.saturating_sub(2)) {
            let mut spans = vec![Span::raw(" ")];
            spans.extend(row.spans.into_iter().map(|s| s.style(style)));
            lines.push(Line::from(spans));
        }
        lines.push(Line::default());
    }
    // The widest keys' names (Shift-right PgUp in ASCII), 14 columns at least.
    let keys_width = TABLE
        .iter()
        .map(|b| crate::tui::keys::display_keys(b, g.ascii).chars().count())
        .max()
        .unwrap_or(0)
        .max(14);
    // A column kept free on the right, as on the left: a description that fills its
    // row to the border runs into it.
    let text_width = width.saturating_sub(keys_width + 3).max(10);
    for b in TABLE {
        let keys = crate::tui::keys::display_keys(b, g.ascii);
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
    // One line at 200 columns (the whole help then fits 60 rows).
    let mouse = "Mouse: click a parameter to select it, scroll on it to change it; click or drag the chart to seek, scroll to zoom; click a preset twice to load it.";
    // Each wrapped row indented alike, as the keys' descriptions are.
    for row in wrap(Line::from(mouse), width.saturating_sub(2)) {
        let mut spans = vec![Span::raw(" ")];
        spans.extend(row.spans);
        lines.push(Line::from(spans).style(theme.dim));
    }
    lines
}

/// The help's width on a screen of `area`: wide enough on a wide screen (200
/// columns) for every description on one line, so that the whole table fits 60 rows.
fn help_width(area: Rect) -> u16 {
    area.width.saturating_sub(2).min(152)
}

/// The keys, scrolling.
fn help(app: &App, first: usize, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let width = help_width(area);
    let lines = help_lines(usize::from(width.saturating_sub(2)), theme, last(app));
    let title = if theme.glyphs.ascii {
        "Keys  (Esc or q closes, up/down PgUp/PgDn scroll; other keys act)"
    } else {
        "Keys  (Esc or q closes, ↑↓ PgUp PgDn scroll; other keys act)"
    };
    let line = |i: usize| lines[i].clone();
    let source: (usize, &dyn Fn(usize) -> Line<'static>) = (lines.len(), &line);
    scrolling(first, title, Vec::new(), source, (area, width), buf, theme);
}

/// The presets to load, one row each with the `selected` one marked.
fn preset_picker(app: &App, selected: Option<usize>, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let name_width = app
        .library()
        .presets
        .iter()
        .map(|p| p.name.len())
        .max()
        .unwrap_or(8);
    // One row per preset: the description cut with an ellipsis, never wrapped.
    let room = usize::from(area.width.saturating_sub(8));
    let lines: Vec<Line> = app
        .library()
        .presets
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let style = if Some(i) == selected {
                theme.selected
            } else {
                theme.text
            };
            let mark = if Some(i) == selected { g.selected } else { " " };
            // A file of the user's named like a built-in one: both are listed, and
            // this row loads the file (`--preset NAME` finds the built-in).
            let twin = matches!(p.origin, PresetOrigin::File(_))
                && app
                    .library()
                    .presets
                    .iter()
                    .any(|q| q.origin == PresetOrigin::BuiltIn && q.name == p.name);
            let tag = if twin {
                "[your file, named like a built-in] "
            } else {
                ""
            };
            // Descriptions state outcomes: not while b is hidden or a prediction pends.
            let description = if app.hidden().derived() {
                "(description hidden until the outcome shows)"
            } else {
                p.description.as_str()
            };
            let text = format!("{mark}{:<name_width$}  {tag}{description}", p.name);
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
        .library()
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
            if app.export_dir() == std::path::Path::new(".") {
                " in the folder groovelab was started in, unless a path is given".into()
            } else {
                format!(" in {} unless a path is given", app.export_dir().display())
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

impl Component for Help {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        help(cx.app, self.scroll().first(), area, buf, cx.theme);
    }
}

impl Component for Picker {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        preset_picker(cx.app, self.marked(), area, buf, cx.theme);
    }
}

/// The prompts drawn as popups: the name to save under, the file to export to (the
/// value prompt is typed on the status line: the status bar and the parameters
/// panel draw it).
impl Component for Prompt {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let (app, theme, field) = (cx.app, cx.theme, self.field());
        match self.target() {
            TextTarget::Value => {}
            TextTarget::Name => save_prompt(app, field, area, buf, theme),
            TextTarget::Export(kind) => export_prompt(app, kind, field, area, buf, theme),
        }
    }
}

impl Component for Confirm {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        confirm_overwrite(self.name(), area, buf, cx.theme);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::theme::Glyphs;

    /// Every help row, at any width the help takes, leaves its last column free: a
    /// description wrapped to the whole width ran into the popup's border ("…the
    /// cause-and-effect││" at 120 columns).
    #[test]
    fn no_help_row_reaches_the_border() {
        for ascii in [false, true] {
            let theme = Theme::new(Glyphs::new(ascii), true);
            for width in 30..=160 {
                let message = Some((
                    "clip.mp4 not tracked: tracking unsure: neither ball was found in a third of the frames (at most in 3 of 27), so no tracks are given (V: its first frame; click a ball there to seed it)",
                    true,
                ));
                for line in help_lines(width, &theme, None)
                    .into_iter()
                    .chain(help_lines(width, &theme, message))
                {
                    assert!(
                        line.width() < width,
                        "{width} columns, ascii {ascii}: {line:?} is {} wide",
                        line.width()
                    );
                }
            }
        }
    }
}
