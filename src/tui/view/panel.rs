//! What every panel draws with: its bordered block and title, its lines ranked by
//! priority and word-wrapped to fit, and what it shows while its analysis runs.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Widget};

use crate::lab::jobs::State;
use crate::tui::theme::Theme;

/// A bordered block in the theme's glyph set.
pub(crate) fn block<'a>(title: impl Into<Line<'a>>, theme: &Theme) -> Block<'a> {
    Block::bordered()
        .border_set(theme.glyphs.border)
        .border_style(theme.dim)
        .title(title.into().style(theme.title))
}

/// A panel's frame drawn with the longest of `titles` that fits; the area inside it.
pub(crate) fn framed<S: AsRef<str>>(
    titles: &[S],
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) -> Rect {
    let blk = block(title_of(titles, area, theme), theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    inner
}

/// A block title (` text `) that fits on the border of `area`, cut with an ellipsis.
pub(crate) fn title_within(title: &str, area: Rect, theme: &Theme) -> String {
    let room = usize::from(area.width.saturating_sub(4));
    format!(" {} ", theme.glyphs.ellipsize(title.trim(), room))
}

/// A block's title: the first of `variants` (longest first) that fits on the border
/// of `area`, the last cut with an ellipsis if none does.
pub(crate) fn title_of<S: AsRef<str>>(variants: &[S], area: Rect, theme: &Theme) -> String {
    let texts: Vec<String> = variants
        .iter()
        .map(|t| theme.glyphs.text(t.as_ref()))
        .collect();
    title_within(&fitting(&texts, area.width.saturating_sub(4)), area, theme)
}

/// The first of `variants` that fits in `width` columns, else the last (shortest).
pub(crate) fn fitting(variants: &[String], width: u16) -> String {
    variants
        .iter()
        .find(|v| v.chars().count() <= usize::from(width))
        .or(variants.last())
        .cloned()
        .unwrap_or_default()
}

/// "computing… 40 %" (or without a share when the total is unknown).
pub(crate) fn progress_text(done: usize, total: usize) -> String {
    match (100 * done.min(total)).checked_div(total) {
        Some(percent) => format!("computing… {percent} %"),
        None => "computing…".to_string(),
    }
}

/// What a panel shows while its analysis runs: what is being done and how far.
pub(crate) fn computing<T>(
    state: &State<'_, T>,
    what: &str,
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let text = match state {
        State::Computing { done, total } => format!("{what}: {}", progress_text(*done, *total)),
        _ => String::new(),
    };
    let text = theme.glyphs.text(&text);
    buf.set_stringn(area.x, area.y, text, usize::from(area.width), theme.dim);
}

/// Lines of a panel with a priority each; [`by_priority`] keeps the most important
/// ones that fit.
pub(crate) type Ranked<'a> = Vec<(u8, Line<'a>)>;

/// The lines of `ranked` that fit in `area` once wrapped at its width, in their
/// order: while they do not fit, the lowest priority goes (the last such first). A
/// small screen so shows the important lines whole rather than the first ones.
pub(crate) fn by_priority<'a>(ranked: Ranked<'a>, area: Rect) -> Vec<Line<'a>> {
    let width = usize::from(area.width).max(1);
    let wrapped = ranked
        .into_iter()
        .map(|(p, line)| (p, wrap(line, width)))
        .collect();
    rows_by_priority(wrapped, area.height)
}

/// [`by_priority`] for entries already cut into rows (an entry goes or stays whole):
/// the rows of the entries that fit in `height` rows.
pub(crate) fn rows_by_priority<'a>(
    mut wrapped: Vec<(u8, Vec<Line<'a>>)>,
    height: u16,
) -> Vec<Line<'a>> {
    let rows = |w: &[(u8, Vec<Line>)]| w.iter().map(|(_, l)| l.len()).sum::<usize>();
    while rows(&wrapped) > usize::from(height) && !wrapped.is_empty() {
        let lowest = wrapped.iter().map(|w| w.0).min().unwrap_or(0);
        let i = wrapped.iter().rposition(|w| w.0 == lowest).unwrap_or(0);
        wrapped.remove(i);
    }
    wrapped.into_iter().flat_map(|(_, l)| l).collect()
}

/// Draws `lines` one per row from the top of `area` (already wrapped).
pub(crate) fn draw_lines(lines: Vec<Line<'_>>, area: Rect, buf: &mut Buffer) {
    for (i, line) in lines.into_iter().enumerate().take(usize::from(area.height)) {
        buf.set_line(area.x, area.y + i as u16, &line, area.width);
    }
}

/// A space [`wrap`] never breaks at (between a label and its value, a number and its
/// unit: `b* 4.26 cm` split over two rows read as two values); written as a space.
pub(crate) const NO_BREAK: char = '\u{a0}';

/// `text` with its spaces made [`NO_BREAK`]: one piece for [`wrap`].
pub(crate) fn unbroken(text: &str) -> String {
    text.replace(' ', &NO_BREAK.to_string())
}

/// `line` word-wrapped to `width` columns, styles kept: breaks after spaces (not
/// [`NO_BREAK`]s), a word longer than a row is split, spaces that end a row are
/// dropped.
pub(crate) fn wrap(line: Line<'_>, width: usize) -> Vec<Line<'static>> {
    let mut rows: Vec<Vec<(String, Style)>> = vec![Vec::new()];
    let mut used = 0usize;
    // Words (with the spaces before them) as (text, style) pieces.
    let mut words: Vec<Vec<(String, Style)>> = Vec::new();
    let mut current: Vec<(String, Style)> = Vec::new();
    let mut in_space = false;
    for span in &line.spans {
        for c in span.content.chars() {
            let space = c == ' ';
            if !space && in_space && current.iter().any(|p| p.0.chars().any(|c| c != ' ')) {
                words.push(std::mem::take(&mut current));
            }
            in_space = space;
            match current.last_mut() {
                Some((text, style)) if *style == span.style => text.push(c),
                _ => current.push((c.to_string(), span.style)),
            }
        }
    }
    if !current.is_empty() {
        words.push(current);
    }
    for word in words {
        // A word carries the spaces after it; they never push it to the next row.
        let chars: Vec<(char, Style)> = word
            .iter()
            .flat_map(|(t, s)| t.chars().map(move |c| (c, *s)))
            .collect();
        let len = chars
            .iter()
            .rposition(|(c, _)| *c != ' ')
            .map_or(0, |i| i + 1);
        if used > 0 && used + len > width {
            rows.push(Vec::new());
            used = 0;
        }
        for (c, style) in chars {
            if used == width {
                if c == ' ' {
                    continue;
                }
                rows.push(Vec::new());
                used = 0;
            }
            let row = rows.last_mut().expect("one row at least");
            // A no-break space holds a label to its value: written as a space.
            let c = if c == NO_BREAK { ' ' } else { c };
            match row.last_mut() {
                Some((t, s)) if *s == style => t.push(c),
                _ => row.push((c.to_string(), style)),
            }
            used += 1;
        }
    }
    rows.into_iter()
        .map(|r| {
            Line::from(
                r.into_iter()
                    .map(|(t, s)| Span::styled(t, s))
                    .collect::<Vec<_>>(),
            )
        })
        .collect()
}
