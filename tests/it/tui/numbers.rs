//! Numbers on screen are never cut and never wrong (issue 11, section 2): in the
//! parameter, Why, Methods runs and Fit panels at 80×24, 120×40 and 200×60, every
//! number read back from the rendered text equals the lab's value to the precision
//! it is printed with.

use groovelab::cli::{self, DataArgs};
use groovelab::lab::jobs::State;
use groovelab::physics::story::{After, after_first_impact};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{App, ROWS};
use groovelab::tui::screen;
use groovelab::tui::theme::{Glyphs, Theme};
use groovelab::tui::{keys, replay, view};
use ratatui::layout::Rect;

use crate::common::{self, scene_of};

const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (200, 60)];

fn app(preset: &str, values: SceneSpec, data: Option<&str>, keys_: &str) -> App {
    let scene = scene_of(preset, values);
    let data = DataArgs {
        data: data.into_iter().map(Into::into).collect(),
        ..DataArgs::default()
    };
    let mut a = App::new(
        cli::lab(&scene, &data).unwrap(),
        common::no_user_presets("numbers"),
    );
    replay(&mut a, &keys::parse_script(keys_).unwrap());
    a.wait();
    a
}

/// The text inside a panel's border, one string per row.
fn panel(app: &App, size: (u16, u16), pick: fn(&view::Panels) -> Rect) -> Vec<String> {
    let theme = Theme::new(Glyphs::new(false), true);
    let text = screen::to_text(app, size.0, size.1, &theme);
    let rows: Vec<Vec<char>> = text.lines().map(|l| l.chars().collect()).collect();
    let r = pick(&view::layout(Rect::new(0, 0, size.0, size.1)).unwrap());
    (r.y + 1..r.bottom() - 1)
        .map(|y| {
            (r.x + 1..r.right() - 1)
                .map(|x| *rows[y as usize].get(x as usize).unwrap_or(&' '))
                .collect()
        })
        .collect()
}

/// A number at the start of `s` and the half unit of its last printed digit.
fn number(s: &str) -> Option<(f64, f64, usize)> {
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits = |i: &mut usize| {
        let start = *i;
        while *i < b.len() && b[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - start
    };
    if digits(&mut i) == 0 {
        return None;
    }
    let mut decimals = 0;
    if i + 1 < b.len() && b[i] == b'.' && b[i + 1].is_ascii_digit() {
        i += 1;
        decimals = digits(&mut i) as i32;
    }
    let mantissa_end = i;
    let mut exp = 0;
    if i < b.len() && b[i] == b'e' {
        let mut j = i + 1;
        if j < b.len() && b[j] == b'-' {
            j += 1;
        }
        let start = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        assert!(j > start, "a cut exponent in '{s}'");
        exp = s[i + 1..j].parse().unwrap();
        i = j;
    }
    // A number running into a letter or digit was cut or glued: not a number here;
    // a percentage is a rounded share, not a value of the lab.
    if i < b.len()
        && ((b[i].is_ascii_alphanumeric() && b[i] != b'm') || b[i] == b'.' || b[i] == b'%')
    {
        return None;
    }
    let v: f64 = s[..mantissa_end].parse::<f64>().ok()? * 10f64.powi(exp);
    Some((v, 0.5 * 10f64.powi(exp - decimals), i))
}

/// Checks every number printed right after `label` (and an optional "= ") in `text`
/// against `want`; returns how many were checked.
fn check(text: &str, label: &str, want: f64, what: &str) -> usize {
    let mut checked = 0;
    for (at, _) in text.match_indices(label) {
        let before = text[..at].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '|') {
            continue;
        }
        let rest = text[at + label.len()..].trim_start();
        let rest = rest.strip_prefix("= ").unwrap_or(rest);
        if let Some((v, half, _)) = number(rest) {
            assert!(
                (v - want).abs() <= half * (1.0 + 1e-9) + 1e-15,
                "{what}: '{label}' shows {v} (±{half}) for {want}\n{text}"
            );
            checked += 1;
        }
    }
    checked
}

fn joined(lines: &[String]) -> String {
    lines.iter().map(|l| l.trim()).collect::<Vec<_>>().join(" ")
}

#[test]
fn the_parameter_panel_shows_every_value_and_note_to_its_precision() {
    let big = SceneSpec::default().with(Key::Radius, 0.30);
    let unequal = SceneSpec::default().with(Key::V0Right, 0.4);
    for (name, values) in [
        ("default", SceneSpec::default()),
        ("R = 30 cm", big),
        ("unequal", unequal),
    ] {
        for size in SIZES {
            let a = app("paper-b4.9", values.clone(), None, "");
            let lines = panel(&a, size, |p| p.params);
            let mut checked = 0;
            for line in &lines {
                let body: String = line.chars().skip(1).collect();
                let Some(row) = ROWS.iter().find(|p| {
                    let label = p.label.replace("mu", "μ");
                    body.starts_with(&label) && body[label.len()..].starts_with("  ")
                }) else {
                    continue;
                };
                let label = row.label.replace("mu", "μ");
                let scale = match row.dim {
                    groovelab::settings::units::Dimension::Length => 100.0,
                    groovelab::settings::units::Dimension::Mass => 1000.0,
                    _ => 1.0,
                };
                let what = format!("{name} {size:?} row {}", row.label);
                checked += check(&body, &label, a.lab.value(row.key) * scale, &what);
                let d = &a.lab.derived;
                if row.key == Key::Width {
                    checked += check(&body, "b* ", d.b_star.unwrap() * 100.0, &what);
                    check(&body, "b/R ", a.lab.scene.width / a.lab.scene.radius, &what);
                    assert!(body.contains("b* "), "{what}: b* is always shown\n{body}");
                }
                if row.key == Key::Radius {
                    check(&body, "k ", d.k, &what);
                }
            }
            assert!(
                checked >= 7,
                "{name} {size:?}: {checked} numbers\n{lines:#?}"
            );
        }
    }
}

#[test]
fn the_why_panel_shows_the_labs_numbers() {
    for (preset, values) in [
        ("paper-b4.9", SceneSpec::default()),
        ("paper-b4.4", SceneSpec::default()),
        (
            "paper-b3.5",
            SceneSpec::default().with(Key::Restitution, 0.2),
        ),
    ] {
        for size in SIZES {
            let a = app(preset, values.clone(), None, "");
            let text = joined(&panel(&a, size, |p| p.info));
            let d = &a.lab.derived;
            let sol = &a.lab.solution;
            let what = format!("{preset} {size:?}");
            let mut checked = 0;
            checked += check(&text, "k ", d.k, &what);
            checked += check(&text, "r ", d.r * 100.0, &what);
            checked += check(&text, "D ", d.d, &what);
            checked += check(&text, "b* ", d.b_star.unwrap_or(f64::NAN) * 100.0, &what);
            // The first "impacts" is the count (the energy line's are shares).
            let count = &text[..text.find(" + impacts").unwrap_or(text.len())];
            checked += check(count, "impacts ", sol.impacts as f64, &what);
            if let Some(t) = sol.accumulation {
                checked += check(&text, "T∞ ", t, &what);
            }
            match after_first_impact(sol, d) {
                Some(After::Recovers(rec)) => {
                    checked += check(&text, "t' ", rec.t_roll, &what);
                    checked += check(&text, "v' ", rec.v_roll, &what);
                    checked += check(&text, "x' ", rec.x_roll * 100.0, &what);
                }
                Some(After::Interrupted(i)) => {
                    checked += check(&text, "t ", i.first.1, &what);
                    if let Some((t, _)) = i.rest_from {
                        checked += check(&text, "at rest from ", t, &what);
                    }
                }
                None => {}
            }
            assert!(checked >= 5, "{what}: {checked} numbers\n{text}");
        }
    }
}

#[test]
fn the_methods_runs_panel_never_cuts_an_error() {
    let a = app("paper-b4.9", SceneSpec::default(), None, "c");
    for size in SIZES {
        let State::Ready(rows) = a.methods().state() else {
            panic!("the rows are computed");
        };
        let lines = panel(&a, size, |p| p.info);
        let mut checked = 0;
        for line in lines.iter().skip(1) {
            let Some(last) = line.split_whitespace().last() else {
                continue;
            };
            let Some(r) = rows.iter().find(|r| {
                let setting = match (r.step, r.tolerance) {
                    (Some(h), _) => format!("h {h:.0e}"),
                    (_, Some(t)) => format!("tol {t:.0e}"),
                    _ => String::new(),
                };
                let name = line.split_whitespace().nth(1).unwrap_or("");
                line.contains(&format!(" {setting} ")) && r.method.name().starts_with(name)
            }) else {
                continue;
            };
            let (v, half, _) =
                number(last).unwrap_or_else(|| panic!("{size:?}: '{last}' in\n{line}"));
            assert!(
                (v - r.err_v).abs() <= half * (1.0 + 1e-9),
                "{size:?}: {} shows {last} for {}",
                r.method.name(),
                r.err_v
            );
            checked += 1;
        }
        assert!(checked >= 6, "{size:?}: {checked} rows\n{lines:#?}");
        // The case: rk45 at tol 1e-8 keeps its whole exponent.
        let tight = rows
            .iter()
            .find(|r| r.tolerance == Some(1e-8))
            .map(|r| r.err_v)
            .unwrap();
        assert!(tight < 1e-6, "{tight}");
        if size.0 >= 120 {
            let text = lines.join("\n");
            assert!(
                text.contains("e-10") || text.contains("e-9") || text.contains("e-11"),
                "{text}"
            );
        }
    }
}

#[test]
fn the_fit_panel_shows_the_fits_numbers() {
    let a = app("paper-b4.9", SceneSpec::default(), None, "f");
    for size in SIZES {
        let State::Ready(Ok(f)) = a.fit().fits() else {
            panic!("the fit is computed");
        };
        let text = joined(&panel(&a, size, |p| p.info));
        // The paper's row holds the paper's constants (checked in tests/it/fit/).
        let text = match (text.find("paper:"), text.find("model fit")) {
            (Some(a), Some(b)) => format!("{}{}", &text[..a], &text[b..]),
            (Some(a), None) => text[..a].to_string(),
            _ => text,
        };
        let (l, m) = (f.line_fit.as_ref().expect("a line fit"), &f.model_fit);
        let what = format!("fit {size:?}");
        let mut checked = 0;
        // μ_k alone has its own line: its numbers are the μ_k row of the models.
        let text = match text.find("μ_k alone") {
            Some(a) => {
                // It ends with its RMS in m/s (the lines are joined by spaces).
                let end = text[a..].find("m/s").map_or(text.len(), |e| a + e + 3);
                let alone = &text[a..end];
                checked += check(alone, "alone: ", f.mu_alone.mu, &what);
                checked += check(alone, "± ", 2.0 * f.mu_alone.mu_se, &what);
                format!("{}{}", &text[..a], &text[end..])
            }
            None => text,
        };
        checked += check(&text, "|a_cm| ", l.a_cm, &what);
        checked += check(&text, "|a_t| ", l.a_t, &what);
        checked += check(&text, "μ_cm ", l.mu_cm, &what);
        checked += check(&text, "μ_t ", l.mu_t, &what);
        checked += check(&text, "|F_net| ", l.f_net, &what);
        checked += check(&text, "μ_k ", m.mu, &what);
        checked += check(&text, "± ", 2.0 * m.mu_se, &what);
        checked += check(&text, "RMS ", m.rms, &what);
        assert!(checked >= 6, "{what}: {checked} numbers\n{text}");
    }
    // A position track: both fits side by side.
    let a = app(
        "paper-b4.9",
        SceneSpec::default(),
        Some("docs/video/paper-b4.9-tracker.txt"),
        "f",
    );
    for size in SIZES {
        let State::Ready(Ok(f)) = a.fit().fits() else {
            panic!("the fits are computed");
        };
        let (v, p) = (f.velocity_fit.as_ref().unwrap(), &f.model_fit);
        let lines = panel(&a, size, |p| p.info);
        let Some(row) = lines.iter().find(|l| l.starts_with("μ_k 2σ")) else {
            assert_eq!(size, (80, 24), "the two fits are shown\n{lines:#?}");
            continue;
        };
        let cells: Vec<&str> = row["μ_k 2σ".len()..].split_whitespace().collect();
        // Two columns where the panel holds them at their printed widths; else the
        // position fit alone, titled so.
        let fits = match cells.len() {
            2 => vec![v, p],
            1 => {
                assert!(
                    lines.iter().any(|l| l.trim_end().ends_with(", positions")),
                    "{size:?}: one column is the position fit's\n{lines:#?}"
                );
                // The velocity fit's μ_k on a line of its own.
                let l = lines
                    .iter()
                    .find(|l| l.starts_with("velocities: "))
                    .unwrap_or_else(|| panic!("{size:?}: the velocity fit's line\n{lines:#?}"));
                let cell = l["velocities: ".len()..].split_whitespace().next().unwrap();
                let (mu, _) = cell.split_once('±').unwrap();
                let (got, half, _) = number(mu).unwrap();
                assert!((got - v.mu).abs() <= half * (1.0 + 1e-9), "{size:?}: {l}");
                vec![p]
            }
            _ => panic!("{size:?}: {row}"),
        };
        for (cell, m) in cells.iter().zip(fits) {
            let (mu, se) = cell.split_once('±').unwrap();
            for (text, want) in [(mu, m.mu), (se, 2.0 * m.mu_se)] {
                let (v, half, _) = number(text).unwrap();
                assert!(
                    (v - want).abs() <= half * (1.0 + 1e-9),
                    "{size:?}: {cell} for {want}"
                );
            }
        }
    }
}
