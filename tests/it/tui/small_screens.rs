//! What a user sees at small terminals (80×24, 120×40; 200×60 too): the loaded data
//! file named in every view, long status messages read whole, the time axis saying
//! what it measures, the selected parameter kept over a preset pick.

use std::path::PathBuf;

use groovelab::cli::DataArgs;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::Preset;
use groovelab::tui::app::{App, Library, ROWS, Status};

use crate::common::{self, press, scene_of, select, text};

const VELOCITIES: &str = "data/gs-b4.4cm.csv";
const TRACK: &str = "docs/video/paper-b4.9-tracker.txt";
const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (200, 60)];

fn no_user_presets() -> Library {
    common::no_user_presets("small-screens")
}

/// The app as `render` leaves it on `preset` (none: no scene named) with the data
/// `files`, after `keys`.
fn opened(preset: Option<&str>, files: &[&str], at: Option<f64>, keys: Option<&str>) -> App {
    let scene = preset.map_or_else(Default::default, |p| scene_of(p, SceneSpec::default()));
    let data = DataArgs {
        data: files.iter().map(PathBuf::from).collect(),
        ..DataArgs::default()
    };
    common::rendered(&scene, &data, at, keys, no_user_presets())
}

/// The status line and the row under it (the hint bar, or a long message's rest).
fn bottom_rows(screen: &str) -> (String, String) {
    let rows: Vec<&str> = screen.lines().collect();
    let n = rows.len();
    (rows[n - 2].to_string(), rows[n - 1].to_string())
}

#[test]
fn the_loaded_file_is_named_in_every_view_at_every_size() {
    // Once the file was named only in the velocity chart's title, where it fitted
    // beside the key hint (about 200 columns).
    for (file, name) in [
        (VELOCITIES, "data: data/gs-b4.4cm.csv"),
        (TRACK, "paper-b4.9-tracker.txt"),
    ] {
        for keys in ["", "x", "e", "f", "c", "g", "v", "b"] {
            let a = opened(Some("paper-b4.9"), &[file], Some(0.1), Some(keys));
            for size in SIZES {
                for ascii in [false, true] {
                    let (status, _) = bottom_rows(&text(&a, size, ascii));
                    assert!(status.starts_with("t = 0.100 s"), "{status}");
                    assert!(status.contains("preset paper-b4.9  data: "), "{status}");
                    assert!(status.ends_with(name), "{file} {keys:?} {size:?}: {status}");
                }
            }
        }
    }
    // A long path is cut from the left, at a folder: the file's own name stays.
    let dir = crate::common::scratch_dir("tui", "long-path")
        .join("a-class-folder-with-a-long-name/lesson-3/group-b");
    std::fs::create_dir_all(&dir).unwrap();
    let long = dir.join("ball.txt");
    std::fs::copy(TRACK, &long).unwrap();
    let a = opened(Some("paper-b4.9"), &[long.to_str().unwrap()], None, None);
    for ascii in [false, true] {
        let (status, _) = bottom_rows(&text(&a, (80, 24), ascii));
        let mark = if ascii { "..." } else { "…" };
        assert!(
            status.ends_with(&format!("data: {mark}/ball.txt")) || status.contains("group-b/"),
            "{status}"
        );
        assert!(status.starts_with("t = "), "{status}");
    }
    // No file of the user's: no data named (the preset's own series is the preset's).
    let a = opened(Some("paper-b4.9"), &[], None, None);
    let (status, _) = bottom_rows(&text(&a, (80, 24), false));
    assert!(status.ends_with("preset paper-b4.9"), "{status}");
}

#[test]
fn snapshots_with_a_loaded_file() {
    for (name, file) in [("velocities", VELOCITIES), ("track", TRACK)] {
        let a = opened(Some("paper-b4.9"), &[file], Some(0.1), None);
        for (w, h) in [(80, 24), (120, 40)] {
            for ascii in [false, true] {
                let mode = if ascii { "ascii" } else { "unicode" };
                insta::assert_snapshot!(
                    format!("data-{name}-{w}x{h}-{mode}"),
                    text(&a, (w, h), ascii)
                );
            }
        }
    }
}

/// The message of the two bottom rows at 80×24, without the playback before it and
/// the preset, data and keys after it.
fn message_at_80(a: &App) -> String {
    let (status, next) = bottom_rows(&text(a, (80, 24), false));
    let playback = a.playback_short(false);
    let Some(first) = status.strip_prefix(&playback) else {
        panic!("the time and the play state first: {status}")
    };
    let right = first
        .rfind(&format!("preset {}", a.lab.preset().name))
        .unwrap_or_else(|| panic!("{status}"));
    let rest = next
        .strip_suffix("? help  q quit")
        .unwrap_or_else(|| panic!("{next}"));
    format!("{} {}", first[..right].trim(), rest.trim())
        .trim()
        .to_string()
}

#[test]
fn long_messages_are_read_whole_at_80_columns() {
    // A preset picked while the student's data are loaded.
    let a = opened(
        Some("paper-b4.9"),
        &[VELOCITIES],
        None,
        Some("p down enter"),
    );
    let Status::Info(said) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(said.contains("your data kept"), "{said}");
    assert_eq!(message_at_80(&a), *said);
    // Data without a scene: what the model uses, and the ask.
    let a = opened(None, &[TRACK], None, None);
    let Status::Error(said) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(said.contains("R = 2.75 cm, b = 4.9 cm"), "{said}");
    assert_eq!(message_at_80(&a), *said);
    // A preset's description, begun beside the playback and ended on the next row.
    let a = opened(Some("paper-b4.9"), &[], None, Some("p down enter"));
    let Status::Info(said) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(said.chars().count() > 60, "{said}");
    assert_eq!(message_at_80(&a), *said);
    // Longer than both rows: the end is cut with an ellipsis, the keys stay.
    let mut a = a;
    a.status = Status::Error("x ".repeat(100));
    let (status, next) = bottom_rows(&text(&a, (80, 24), false));
    assert!(status.starts_with("t = -0.200 s  paused"), "{status}");
    assert!(
        next.ends_with("…  ? help  q quit") || next.contains("… "),
        "{next}"
    );
    assert!(next.ends_with("? help  q quit"), "{next}");
}

#[test]
fn picking_a_preset_keeps_the_selected_row() {
    for files in [&[][..], &[VELOCITIES][..]] {
        let mut a = opened(Some("paper-b4.9"), files, None, None);
        for key in [Key::Restitution, Key::MassRight, Key::Width] {
            select(&mut a, key);
            let row = a.selected();
            press(&mut a, "p down enter");
            assert_eq!(ROWS[a.selected()].key, key, "{files:?}");
            assert_eq!(a.selected(), row);
            // And on screen: the marker on that row at 80×24 (the list scrolls).
            let screen = text(&a, (80, 24), false);
            let label = ROWS[row].label;
            assert!(
                screen.lines().any(|l| l.starts_with(&format!("│▸{label}"))),
                "{label}\n{screen}"
            );
        }
    }
}

#[test]
fn the_time_axis_says_t_in_seconds_at_every_size() {
    // The last tick label once took the axis title's place at most sizes.
    for p in Preset::built_in() {
        for keys in ["", "x", "e", "f"] {
            let a = opened(Some(&p.name), &[], None, Some(keys));
            for size in [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)] {
                for ascii in [false, true] {
                    let screen = text(&a, size, ascii);
                    // The chart's tick row: just above its bottom border.
                    let row = screen.lines().nth(usize::from(size.1) - 4).unwrap();
                    let border = if ascii { "t (s)||" } else { "t (s)││" };
                    assert!(row.contains(border), "{} {keys:?} {size:?}: {row}", p.name);
                }
            }
        }
    }
}

/// The rows inside the Forces view's chain panel (below its title), right border cut.
fn chain_panel(screen: &str) -> Vec<String> {
    let rows: Vec<Vec<char>> = screen.lines().map(|l| l.chars().collect()).collect();
    let (top, col) = rows
        .iter()
        .enumerate()
        .find_map(|(i, r)| {
            let s: String = r.iter().collect();
            let at = s.find("cause and effect")?;
            // The block's left border: the corner before its title.
            let corner = s[..at].rfind(['├', '╭', '+'])?;
            Some((i, s[..corner].chars().count()))
        })
        .expect("the chain's title");
    rows[top + 1..]
        .iter()
        .take_while(|r| !matches!(r.get(col), Some('╰' | '+')))
        .map(|r| r[col + 1..r.len() - 1].iter().collect::<String>())
        .collect()
}

#[test]
fn the_forces_view_reads_whole_at_80_by_24() {
    // At 80×24 the chain once dropped its units, lost the τ_net and D lines with a run
    // pinned, split a value from its ↑/↓ across rows, and the footers were cut.
    for (preset, keys) in [("paper-b3.5", "v"), ("paper-b4.4", "P right right v")] {
        let a = opened(Some(preset), &[], Some(0.1), Some(keys));
        for size in [(80, 24), (120, 40)] {
            for ascii in [false, true] {
                let screen = text(&a, size, ascii);
                let rows = chain_panel(&screen);
                let chain = rows.join("\n");
                let (arrow, tau, squared) = if ascii {
                    ("->", "tau_net", "m/s^2")
                } else {
                    ("→", "τ_net", "m/s²")
                };
                for want in [" N ", squared, "rad/s", " N m", tau, "D = ", "b "] {
                    assert!(chain.contains(want), "{want} {size:?}:\n{chain}");
                }
                // A chain's row starts with its cause or with an arrow, never with a
                // value's tail or its ↑/↓.
                for row in rows.iter().filter(|r| r.contains(arrow)) {
                    let row = row.trim();
                    let starts = [arrow, "b ", tau, "D "];
                    assert!(
                        starts.iter().any(|s| row.starts_with(s)),
                        "{row:?} {size:?}:\n{chain}"
                    );
                }
                // Every title and footer whole.
                let h = usize::from(size.1);
                let lines: Vec<&str> = screen.lines().collect();
                let ellipsis = if ascii { "..." } else { "…" };
                // The top rows: 9 parameters' rows on a short screen, all 14 on a tall one.
                let top = if h >= 32 { 14 } else { 9 };
                for row in [lines[h - 3], lines[top]] {
                    assert!(!row.contains(ellipsis), "{size:?}: {row}");
                }
            }
        }
    }
}

#[test]
fn every_panel_title_is_whole_at_every_size() {
    // Seen at 80×24: "v_cm(t) and v_t(t), left ball  [b]…"; a title takes the longest
    // of its wordings that fits, never one cut short. (The Methods and Fit views'
    // titles are in their snapshots, which compute their analyses once.)
    for keys in ["", "x", "e", "b b", "g", "v"] {
        let a = opened(Some("paper-b4.9"), &[], Some(0.1), Some(keys));
        for size in SIZES {
            for ascii in [false, true] {
                let screen = text(&a, size, ascii);
                let cut = if ascii { "... -" } else { "… ─" };
                for top in screen.lines().filter(|l| l.contains(['╭', '├']) || ascii) {
                    assert!(!top.contains(cut), "{keys:?} {size:?}: {top}\n{screen}");
                }
            }
        }
    }
}
