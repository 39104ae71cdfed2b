//! Popups over the main screen: help (from the key table), the preset picker, and the
//! save prompts.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph, Widget, Wrap};

use super::block;
use crate::tui::app::{App, Mode};
use crate::tui::keys::TABLE;
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
    let blk = block(format!(" {title} "), theme);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(blk)
        .render(rect, buf);
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    match &app.mode {
        Mode::Normal | Mode::Edit(_) => {}
        Mode::Help => {
            let entries: Vec<(String, &str)> =
                TABLE.iter().map(|b| (b.keys.join(" "), b.help)).collect();
            let mouse = " Mouse: click or scroll a parameter; click or drag on the chart to seek.";
            let one_column = entries.len() as u16 + 3 <= area.height.saturating_sub(2);
            let mut lines: Vec<Line> = if one_column {
                entries
                    .iter()
                    .map(|(keys, help)| {
                        Line::from(vec![
                            Span::styled(format!(" {keys:<16}"), theme.key),
                            Span::styled(*help, theme.text),
                        ])
                    })
                    .collect()
            } else {
                // Short screens: two columns, descriptions cut to fit.
                let half = entries.len().div_ceil(2);
                let col = usize::from(area.width.saturating_sub(6) / 2);
                let cell = |(keys, help): &(String, &str)| {
                    let text: String = format!(" {keys:<12} {help}").chars().take(col).collect();
                    format!("{text:<col$}")
                };
                (0..half)
                    .map(|i| {
                        let right = entries.get(i + half).map(cell).unwrap_or_default();
                        Line::from(Span::styled(
                            format!("{}{right}", cell(&entries[i])),
                            theme.text,
                        ))
                    })
                    .collect()
            };
            lines.push(Line::from(Span::styled(mouse, theme.dim)));
            popup(
                "Keys  (any key closes)",
                lines,
                area,
                if one_column {
                    76
                } else {
                    area.width.saturating_sub(2)
                },
                buf,
                theme,
            );
        }
        Mode::Picker(selected) => {
            let name_width = app
                .library
                .presets
                .iter()
                .map(|p| p.name.len())
                .max()
                .unwrap_or(8);
            let lines: Vec<Line> = app
                .library
                .presets
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    let style = if i == *selected {
                        theme.selected
                    } else {
                        theme.text
                    };
                    let mark = if i == *selected {
                        theme.glyphs.selected
                    } else {
                        " "
                    };
                    // One row per preset: cut the description rather than wrap it.
                    let room = usize::from(area.width.saturating_sub(8));
                    let text: String = format!("{mark}{:<name_width$}  {}", p.name, p.description)
                        .chars()
                        .take(room)
                        .collect();
                    Line::from(Span::styled(text, style))
                })
                .collect();
            popup(
                "Presets  (Enter loads, Esc closes)",
                lines,
                area,
                area.width.saturating_sub(4),
                buf,
                theme,
            );
        }
        Mode::SaveName(text) => {
            let dir = app
                .library
                .dir
                .as_ref()
                .map_or("(no preset folder)".to_string(), |d| {
                    d.display().to_string()
                });
            let lines = vec![
                Line::from(Span::styled(format!(" name: {text}_"), theme.text)),
                Line::from(Span::styled(format!(" saved in {dir}"), theme.dim)),
                Line::from(Span::styled(" Enter saves, Esc cancels", theme.dim)),
            ];
            popup(
                "Save the scene as a user preset",
                lines,
                area,
                70,
                buf,
                theme,
            );
        }
        Mode::ConfirmOverwrite(name) => {
            let lines = vec![Line::from(Span::styled(
                format!(" {name}.toml exists. Overwrite it? y / n"),
                theme.error,
            ))];
            popup("Save", lines, area, 60, buf, theme);
        }
    }
}
