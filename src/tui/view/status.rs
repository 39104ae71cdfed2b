//! The status line and the hint bar under it. The status line: playback (the time
//! and the play state first, always), the last message, and at the right the preset
//! and the data file loaded. A message too long for its row goes on in the hint bar's
//! place, before `? help  q quit`, so that it is read whole at 80 columns.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use crate::settings::params::Param;
use crate::settings::units::Dimension;
use crate::tui::app::{App, ROWS, Status};
use crate::tui::component::{Component, Ctx};
use crate::tui::keys;
use crate::tui::theme::{Glyphs, Theme};

/// Draws the status line in `status` and the hint bar (or the rest of a long message
/// and the help and quit keys) in `hints`.
pub fn render(app: &App, status: Rect, hints: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let width = usize::from(status.width);
    let right = right_text(app, width, &g);
    let right_len = right.chars().count();
    let room = width.saturating_sub(right_len + 1);
    buf.set_string(
        status.right().saturating_sub(right_len as u16),
        status.y,
        &right,
        theme.dim,
    );
    let (message, style) = match (app.editing(), &app.status) {
        (Some(_), _) => {
            let prompt = typing_prompt(ROWS[app.selected()]);
            buf.set_stringn(
                status.x,
                status.y,
                g.ellipsize(&prompt, room),
                room,
                theme.info,
            );
            hint_bar(hints, buf, theme);
            return;
        }
        (_, Status::Error(e)) => (g.text(e), theme.error),
        (_, Status::Info(i)) => (g.text(i), theme.text),
        (_, Status::Predicted | Status::None) => match prediction_text(app, &g) {
            Some(text) => (g.text(&text), theme.info),
            None => (String::new(), theme.text),
        },
    };
    let tail = help_and_quit(g.ascii);
    let second_room = usize::from(hints.width).saturating_sub(tail.chars().count() + 2);
    let (playback, first, rest) = arrange(app, &message, room, second_room, &g);
    let used = playback.chars().count();
    buf.set_stringn(status.x, status.y, &playback, room, theme.text);
    if !first.is_empty() {
        let x = status.x + (used + 3) as u16;
        buf.set_stringn(x, status.y, &first, room.saturating_sub(used + 3), style);
    }
    if rest.is_empty() {
        hint_bar(hints, buf, theme);
    } else {
        buf.set_stringn(hints.x, hints.y, &rest, second_room, style);
        let x = hints.right().saturating_sub(tail.chars().count() as u16);
        let (key, label) = tail.split_once(' ').unwrap_or((&tail, ""));
        let line = Line::from(vec![
            Span::styled(key.to_string(), theme.key),
            Span::styled(format!(" {label}"), theme.dim),
        ]);
        buf.set_line(x, hints.y, &line, hints.width);
    }
}

/// The prediction's line: what was predicted and, once the outcome shows, what was
/// observed and whether they agree ("predicted: move apart, observed: RECOLLIDE ✗"),
/// in every view; before the outcome shows it gives nothing away. `None` without a
/// prediction for this scene, or (the status line empty) before its outcome shows.
fn prediction_text(app: &App, g: &Glyphs) -> Option<String> {
    let p = app.prediction().filter(|p| p.scene == app.lab.scene)?;
    let guess = super::predict::short_answer(p.guess);
    if app.hidden().pending() {
        return matches!(app.status, Status::Predicted)
            .then(|| format!("predicted: {guess}; now watch (space pauses)"));
    }
    let headline = &app.lab.story.headline;
    let observed = headline.split(':').next().unwrap_or(headline);
    let (mark, word) = super::predict::agreement(app.lab.story.verdict.agrees_with(p.guess));
    let mark = if g.ascii {
        format!("({word})")
    } else {
        mark.to_string()
    };
    // Stopped where the outcome shows: how to watch on.
    let more = if !app.playing && app.t == p.reveal_at {
        " (space plays on)"
    } else {
        ""
    };
    Some(format!(
        "predicted: {guess}, observed: {observed} {mark}{more}"
    ))
}

/// Where the scene comes from (the preset, or the data file whose `# scene` lines
/// give it), and the data file loaded (`data: ball.txt`, cut from the left,
/// so at the folders first, when long): what the numbers on screen come from.
fn right_text(app: &App, width: usize, g: &Glyphs) -> String {
    // A preset's name may say b or the outcome (paper-b4.9, critical): hidden with
    // what follows from b.
    let source = if app.hide().b() {
        "preset hidden with b".to_string()
    } else if app.hidden().derived() {
        "preset hidden until the outcome shows".to_string()
    } else {
        app.lab.settings().source()
    };
    let preset = g.ellipsize(&g.text(&source), width / 3);
    let Some(own) = app.lab.own_data() else {
        return preset;
    };
    // A third of the row stays for the time, the play state and a message.
    let room = width.saturating_sub(width / 3 + preset.chars().count() + 2);
    // A file read mirrored says so with its name (the end kept when cut).
    let name = if own.series.mirrored() {
        format!("{} (read mirrored)", own.name)
    } else {
        own.name.clone()
    };
    format!("{preset}  {}", data_label(&name, room, g))
}

/// `data: NAME` in at most `room` columns: NAME's end is kept, from a folder
/// separator where one is in what is kept (`data: …/ball.txt`).
pub(crate) fn data_label(name: &str, room: usize, g: &Glyphs) -> String {
    let name = g.text(name);
    let full = format!("data: {name}");
    if full.chars().count() <= room {
        return full;
    }
    let mark = if g.ascii { "..." } else { "…" };
    let chars: Vec<char> = name.chars().collect();
    let keep = room
        .saturating_sub(6 + mark.chars().count())
        .min(chars.len());
    let mut tail: String = chars[chars.len() - keep..].iter().collect();
    if let Some(i) = tail.find(['/', '\\']).filter(|&i| i > 0) {
        tail = tail[i..].to_string();
    }
    format!("data: {mark}{tail}")
}

/// The playback text and the message's parts: on the status line beside the longest
/// playback that leaves it whole; else on the next row (in `second_room` columns)
/// beside the shortest playback (time and play state), begun on the status line when
/// it is longer than that row, cut after a word, the rest ending in an ellipsis if it
/// still does not fit.
fn arrange(
    app: &App,
    message: &str,
    room: usize,
    second_room: usize,
    g: &Glyphs,
) -> (String, String, String) {
    let len = |s: &str| s.chars().count();
    let shortest = g.text(&app.playback_short(false));
    let playbacks = [app.playback(), app.playback_short(true)].map(|p| g.text(&p));
    if message.is_empty() {
        let playback = playbacks.into_iter().find(|p| len(p) <= room);
        return (
            g.ellipsize(&playback.unwrap_or(shortest), room),
            String::new(),
            String::new(),
        );
    }
    let beside = playbacks
        .into_iter()
        .chain([shortest.clone()])
        .find(|p| len(p) + 3 + len(message) <= room);
    if let Some(playback) = beside {
        return (playback, message.to_string(), String::new());
    }
    let playback = g.ellipsize(&shortest, room);
    // Whole on the next row where it fits there, else begun beside the playback.
    let first_room = if len(message) <= second_room {
        0
    } else {
        room.saturating_sub(len(&playback) + 3)
    };
    let (first, rest) = split_at_word(message, first_room);
    (playback, first, g.ellipsize(&rest, second_room))
}

/// `text` cut after the last whole word that fits in `room` columns, and the rest
/// (all of it on the next row when not even the first word fits).
fn split_at_word(text: &str, room: usize) -> (String, String) {
    let chars: Vec<char> = text.chars().collect();
    if chars.len() <= room {
        return (text.to_string(), String::new());
    }
    match chars[..=room].iter().rposition(|&c| c == ' ') {
        Some(i) if i > 0 => (
            chars[..i].iter().collect::<String>().trim_end().to_string(),
            chars[i + 1..].iter().collect(),
        ),
        _ => (String::new(), text.to_string()),
    }
}

/// The hint bar's last entries (help and quit), as one text: what a long message
/// leaves of the bar.
fn help_and_quit(ascii: bool) -> String {
    keys::hints_within(0, ascii)
        .into_iter()
        .map(|(key, label)| format!("{key} {label}"))
        .collect::<Vec<_>>()
        .join("  ")
}

/// The hint bar: the key table's hints that fit the row.
fn hint_bar(area: Rect, buf: &mut Buffer, theme: &Theme) {
    let mut spans = Vec::new();
    for (key, label) in keys::hints_within(usize::from(area.width), theme.glyphs.ascii) {
        spans.push(Span::styled(key, theme.key));
        spans.push(Span::styled(format!(" {label}  "), theme.dim));
    }
    Paragraph::new(Line::from(spans)).render(area, buf);
}

/// The prompt of the typing field for parameter `p`: which unit a bare number is in.
fn typing_prompt(p: &Param) -> String {
    let (unit, _) = p.dim.display_unit();
    let example = match p.dim {
        Dimension::Length => "44mm",
        Dimension::Mass => "0.2kg",
        Dimension::Speed => "60cm/s",
        Dimension::Time => "200ms",
        Dimension::Acceleration => "9.81",
        Dimension::Ratio => "",
    };
    let name = p.screen_label();
    if unit.is_empty() {
        format!("{name}: a plain number (e.g. 0.17), Enter applies, Esc cancels")
    } else {
        format!("{name} in {unit} (or with a unit, e.g. {example}), Enter applies, Esc cancels")
    }
}

/// The status line (top row of `area`) and hint bar (the row under it) as a component.
pub struct StatusBar;

impl Component for StatusBar {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let [status, hints] =
            ratatui::layout::Layout::vertical([ratatui::layout::Constraint::Length(1); 2])
                .areas(area);
        render(cx.app, status, hints, buf, cx.theme);
    }
}

#[cfg(test)]
mod tests {
    use super::{data_label, split_at_word};
    use crate::tui::theme::Glyphs;

    #[test]
    fn a_long_path_keeps_its_file_name() {
        let g = Glyphs::UNICODE;
        assert_eq!(data_label("ball.txt", 20, &g), "data: ball.txt");
        assert_eq!(
            data_label("docs/video/paper-b4.9-tracker.txt", 30, &g),
            "data: …/paper-b4.9-tracker.txt"
        );
        let cut = data_label("a-very-long-file-name-of-a-track.txt", 20, &Glyphs::ASCII);
        assert_eq!(cut, "data: ...a-track.txt");
        assert!(cut.chars().count() <= 20);
    }

    #[test]
    fn messages_split_after_a_whole_word() {
        assert_eq!(
            split_at_word("one two three", 8),
            ("one two".to_string(), "three".to_string())
        );
        assert_eq!(split_at_word("short", 8), ("short".into(), String::new()));
        assert_eq!(
            split_at_word("unbreakable words", 5),
            (String::new(), "unbreakable words".into())
        );
    }
}
