//! `groovelab data FILE…`: what groovelab reads in each file, before any fit — the
//! format detected, the tracks and which is the centre and which the mark, frames,
//! rate and span, the units and who decided them, missing frames, scatter, approach
//! speed and impacts — and which scene values a fit or the app would take from it
//! (v0 from its approach; the mass assumed, as no data measure it) — as text or JSON.
//! A file that cannot be read is one error line.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;

use super::args::{DataArgs, DataCmdArgs, DataFormat, SceneArgs};
use super::error::CliError;
use super::open::reading_of;
use crate::input::data::{Notes, Report, UnitNote, inspect};
use crate::settings::params::{Key, PARAMS, Param};
use crate::settings::units::{Dimension, show, show_small, significant};
use crate::vision::write::SCALE_COMMENT;

/// Reads each file with the data options and reports it; a video (or a folder of
/// frames) is tracked for the scene's R first, its tracks read as the file.
pub fn run(args: &DataCmdArgs, scene: &SceneArgs, data: &DataArgs) -> Result<String, CliError> {
    let (reading, derive) = reading_of(data)?;
    let mut reports = Vec::new();
    let mut kinds = Vec::new();
    for path in &args.files {
        let video = super::video_data::is_video(path);
        let text = if video {
            super::video_data::text(path, scene, data)?
        } else {
            crate::input::read_user_file(
                path,
                crate::input::FileRole::Data,
                crate::input::MAX_FILE_BYTES,
            )?
        };
        // A video's --scale went into its tracking: its tracks are in metres and
        // seconds, whatever units the other files are read in.
        let reading = crate::input::data::Reading {
            scale: reading.scale.filter(|_| !video),
            length_unit: reading.length_unit.filter(|_| !video),
            time_unit: reading.time_unit.filter(|_| !video),
            ..reading.clone()
        };
        let file = path.display().to_string();
        let mut report = inspect(&text, &file, &reading, &derive)?;
        if video {
            report.notes = video_notes(&text, report.notes);
        }
        // What the lab would take from the file: the same rule as `fit` and the app.
        let series = crate::input::data::load(&text, &file, &reading, &derive).ok();
        let scene_values = series
            .as_ref()
            .map(|series| {
                let values = crate::lab::measured_values(series);
                let rows = values.rows();
                rows.into_iter()
                    .filter_map(|k| values.get(k).map(|v| (k.name(), v)))
                    .collect()
            })
            .unwrap_or_default();
        // The frames whose rim mark is missing, as `fit` says them.
        let mark_missing = series
            .as_ref()
            .and_then(|s| s.found())
            .filter(|f| f.mark_missing > 0)
            .map(|f| MarkMissing {
                frames: f.mark_missing,
                of: f.frames,
                runs: f.mark_gaps.clone(),
                every: f.mark_every,
            });
        // The scene the file says it was taken in (`# scene` lines): `fit` and the app
        // take it under the options, so the report says it too.
        let header: Vec<(Key, f64)> = crate::input::data::scene_of(&text, &file)
            .map(|spec| spec.given().collect())
            .unwrap_or_default();
        let assumed = ["mass_left", "mass_right"]
            .into_iter()
            .filter(|m| !header.iter().any(|(k, _)| k.name() == *m))
            .collect();
        kinds.push((file.clone(), report.holds_velocities()));
        let mark_doubt = scene
            .resolve()
            .ok()
            .and_then(|(_, sc, _)| mark_doubt(&report, sc.radius));
        reports.push(DataReport {
            mark_doubt,
            mark_missing,
            report,
            scene_values,
            header_values: header.iter().map(|(k, v)| (k.name(), *v)).collect(),
            assumed,
        });
    }
    super::open::options_apply(data, &kinds)?;
    Ok(match args.format {
        DataFormat::Json => {
            serde_json::to_string_pretty(&reports).expect("a report serializes") + "\n"
        }
        DataFormat::Table => reports.iter().map(describe).collect::<Vec<_>>().join("\n"),
    })
}

/// What a video's tracks say about themselves (read from the text groovelab wrote for
/// them, not a Tracker file's: "none stated" would be wrong): tracked by groovelab,
/// times from its frame rate, metres from the scale the ball's radius gives in the
/// frames (or `--scale`).
fn video_notes(text: &str, notes: Notes) -> Notes {
    let comment = |start: &str| {
        text.lines()
            .take_while(|l| l.starts_with('#'))
            .find_map(|l| l.strip_prefix('#')?.trim().strip_prefix(start))
            .map(str::trim)
    };
    let rate = comment("frame rate ");
    let radius = comment("scene radius =");
    let scale = comment(SCALE_COMMENT.trim_start_matches('#').trim());
    // A given scale that puts the fitted radius off R (`tracked::scale_note`).
    let contradicted = text
        .lines()
        .take_while(|l| l.starts_with('#'))
        .find_map(|l| {
            l.find(crate::input::video::tracked::SCALE_OFF_R)
                .and_then(|i| l.get(i..))
        });
    let units = notes
        .units
        .into_iter()
        .map(|u| {
            let how = match (u.quantity, rate, radius, scale) {
                ("time", Some(rate), ..) => format!("the video's frames ({rate})"),
                ("length", _, Some(r), Some(s)) => {
                    format!(
                        "the scale from the ball's radius R = {r} in the frames ({})",
                        shown_scale(s)
                    )
                }
                ("length", ..) => match contradicted {
                    Some(why) => format!("the scale given (--scale); {why}"),
                    None => "the scale given (--scale)".into(),
                },
                _ => u.how,
            };
            UnitNote { how, ..u }
        })
        .collect();
    Notes {
        format: "video tracked by groovelab".into(),
        units,
        ..notes
    }
}

/// A scale comment's `S ± σ px/m` to the digits its ± warrants (as written, if not).
fn shown_scale(text: &str) -> String {
    let numbers: Vec<f64> = text
        .trim_end_matches("px/m")
        .split('±')
        .filter_map(|n| n.trim().parse().ok())
        .collect();
    match numbers[..] {
        [s, se] => {
            let (s, se) = crate::settings::units::with_uncertainty(s, se, 2);
            format!("{s} ± {se} px/m")
        }
        _ => text.to_string(),
    }
}

/// One file's report and the scene values it gives.
#[derive(Serialize)]
pub struct DataReport {
    #[serde(flatten)]
    pub report: Report,
    /// The scene values the data measure (by parameter name, SI): what `fit` and the
    /// app take from them where no option or edit sets them (v0: the approach).
    pub scene_values: BTreeMap<&'static str, f64>,
    /// The scene values the file's `# scene` lines give (by parameter name, SI), as
    /// the app's CSV export writes them; absent when it has none.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub header_values: BTreeMap<&'static str, f64>,
    /// The values no data measure that enter F_net, τ_net and the energies: assumed
    /// (the preset's) unless given (here or in the file's header).
    pub assumed: Vec<&'static str>,
    /// Why the track taken for the rim mark cannot be one (it lies farther from the
    /// centre than twice the scene's R, or it is never in a frame with the centre),
    /// naming it; absent when it can.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_missing: Option<MarkMissing>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_doubt: Option<String>,
}

/// A track's frames with a centre but no rim mark: no v_t there (`fit` fills nothing
/// in).
#[derive(Serialize)]
pub struct MarkMissing {
    /// How many frames lack the mark …
    pub frames: usize,
    /// … of those with a centre.
    pub of: usize,
    /// Their runs, `[first, last]` file times, s.
    pub runs: Vec<[f64; 2]>,
    /// k where the mark was followed in every k-th frame only, with v_t in those.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub every: Option<usize>,
}

/// The line that says the frames without the rim mark: missing, or followed in
/// every k-th frame only (v_t in those); empty without any.
fn mark_missing_line(missing: Option<&MarkMissing>) -> String {
    match missing {
        Some(m @ MarkMissing { every: Some(k), .. }) => format!(
            "  rim mark followed in every {} frame only ({} of {} frames): v_t in those\n",
            crate::study::measured::ordinal(*k),
            m.of - m.frames,
            m.of,
        ),
        Some(m) => format!(
            "  rim mark missing in {} of {} frames ({} of the file): no v_t there\n",
            m.frames,
            m.of,
            crate::study::measured::runs_text(&m.runs)
        ),
        None => String::new(),
    }
}

/// Why `report`'s rim mark cannot be one: its median distance from the centre is more
/// than twice the ball's radius `radius` (a second ball, or another run side by side;
/// not judged while the lengths' unit is in doubt),
/// or it has none (never in a frame with the centre: nothing says it is a mark).
fn mark_doubt(report: &Report, radius: f64) -> Option<String> {
    let mark = report.mark.as_ref()?;
    let Some(d) = report.mark_distance else {
        return Some(format!(
            "track {} is not known to be a rim mark: it is never in a frame with the centre, so neither its distance from the centre nor a spin can be measured",
            named(mark)
        ));
    };
    // Distances in a unit not known are not the ball's R apart or not: the lengths'
    // unit is said first (a rim mark in cm read as m lay "276.3 cm" from the centre).
    (d > 2.0 * radius && report.length_unit_doubt.is_none()).then(|| {
        format!(
            "track {} is no rim mark: it lies {} from the centre (median), more than twice the ball's R = {} (a second ball, or another run?); name the mark's track with --track mark=NAME, or give the ball's --radius",
            named(mark),
            show(d, Dimension::Length),
            show(radius, Dimension::Length)
        )
    })
}

/// A track's name as the text says it.
fn named(n: &str) -> String {
    if n.is_empty() {
        "x, y (unnamed)".into()
    } else {
        format!("'{n}'")
    }
}

/// The rim mark as the tracks line names it; a second track never beside the centre
/// is no mark for being the second (its doubt says so below the line).
fn mark_named(r: &Report) -> String {
    match (&r.mark, r.mark_distance) {
        (None, _) => "no rim mark (v_t is not measured)".to_string(),
        (Some(m), Some(_)) => format!("rim mark {}", named(m)),
        (Some(m), None) => format!("second track {}", named(m)),
    }
}

/// One file's report as text for people.
pub fn describe(shown: &DataReport) -> String {
    let r = &shown.report;
    let mut s = format!("{}: {}, {}\n", r.file, r.notes.format, r.kind);
    if let Some(c) = &r.centre {
        let others: Vec<String> = r
            .notes
            .tracks
            .iter()
            .filter(|t| Some(*t) != r.centre.as_ref() && Some(*t) != r.mark.as_ref())
            .map(|t| named(t))
            .collect();
        let _ = writeln!(
            s,
            "  tracks: centre {}, {}{}",
            named(c),
            mark_named(r),
            if others.is_empty() {
                String::new()
            } else {
                format!("; not used: {}", others.join(", "))
            }
        );
    }
    let rate = r
        .frame_rate
        .map_or("no frame rate (too few times)".to_string(), |f| {
            format!("{} frames/s", significant(f, 4))
        });
    // Found frames counted against the span's frames at its rate ("11 of 58 frames
    // at 60 frames/s"), never as a rate of their own.
    let of = if r.frames_spanned > r.frames {
        format!(" of {}", r.frames_spanned)
    } else {
        String::new()
    };
    let _ = writeln!(
        s,
        "  {}{of} frame{} at {rate}, t = {} … {} s",
        r.frames,
        if r.frames == 1 && of.is_empty() {
            ""
        } else {
            "s"
        },
        significant(r.t_first, 4),
        significant(r.t_last, 4)
    );
    if let Some(doubt) = &shown.mark_doubt {
        let _ = writeln!(s, "  {doubt}");
    }
    if let Some(l) = &r.mark_left_out {
        let _ = writeln!(
            s,
            "  rim mark {} left out by the fits: {}; v_t is not measured",
            named(&l.name),
            l.why(r.scatter.unwrap_or(f64::NAN))
        );
    }
    if let Some(line) = r.notes.cut_row {
        let _ = writeln!(
            s,
            "  line {line}, the last, is cut short (no line end, fewer cells than the line before): dropped"
        );
    }
    for u in &r.notes.units {
        let _ = writeln!(s, "  {} in {}: {}", u.quantity, u.unit, u.how);
    }
    s += &missing_line(&r.missing);
    s += &mark_missing_line(shown.mark_missing.as_ref());
    s += &motion_lines(r);
    if let Some(doubt) = &r.length_unit_doubt {
        let _ = writeln!(
            s,
            "  lengths shown in the file's own unit (\"units\"), not known to be metres: {doubt}"
        );
    }
    let _ = writeln!(s, "  {}", r.impact_note);
    let approach = match (r.approach_speed.is_some(), r.length_unit_doubt.is_some()) {
        (false, _) => NoV0::NoApproach,
        (true, true) => NoV0::UnitUnknown,
        (true, false) => NoV0::TooShort,
    };
    s += &scene_line(&shown.scene_values, &shown.header_values, approach);
    s
}

/// The scatter of a position and the approach speed (or the speed between frames), in
/// the file's own length unit where it is in doubt ("units", "units/s").
fn motion_lines(r: &Report) -> String {
    let mut s = String::new();
    let own = r.length_unit_doubt.is_some();
    let speed_unit = if own { "units/s" } else { "m/s" };
    if let Some(sc) = r.scatter {
        let _ = writeln!(
            s,
            "  scatter of a position ≈ {}",
            if own {
                format!("{} units", significant(sc, 3))
            } else {
                show_small(sc, Dimension::Length).to_string()
            }
        );
    }
    match (r.approach_speed, r.approach_speed_se, r.speed) {
        (Some(v), Some(se), _) => {
            let (v, e) = crate::settings::units::with_uncertainty(v, se, 3);
            let _ = writeln!(s, "  approach speed {v} ± {e} {speed_unit}");
        }
        (Some(v), None, _) => {
            let _ = writeln!(s, "  approach speed {} {speed_unit}", significant(v, 3));
        }
        (None, _, Some(v)) if r.kind == "velocities" => {
            let _ = writeln!(s, "  |v_cm| up to {} m/s", significant(v, 3));
        }
        (None, _, Some(v)) => {
            let _ = writeln!(
                s,
                "  speed between frames up to about {} {speed_unit}",
                significant(v, 3)
            );
        }
        _ => {}
    }
    s
}

/// "  no frames missing", or how many and where (the first five runs).
fn missing_line(missing: &[crate::input::data::Gap]) -> String {
    let mut s = String::new();
    if missing.is_empty() {
        s += "  no frames missing\n";
    } else {
        let total: usize = missing.iter().map(|g| g.frames).sum();
        let runs: Vec<String> = missing
            .iter()
            .take(5)
            .map(|g| {
                // A row without a position is one time, not a range from it to
                // itself (a jump in time keeps the frames on either side).
                let at = if g.from == g.to {
                    format!("{:.4}", g.from)
                } else {
                    format!("{:.4} … {:.4}", g.from, g.to)
                };
                format!("{} at t = {at} s ({})", g.frames, g.why)
            })
            .collect();
        let _ = writeln!(
            s,
            "  {total} frame{} missing: {}{}",
            if total == 1 { "" } else { "s" },
            runs.join(", "),
            crate::study::measured::more_runs(missing.len().saturating_sub(5))
        );
    }
    s
}

/// Why the scene would take no v0 from a file ([`scene_line`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum NoV0 {
    /// No approach before an impact.
    NoApproach,
    /// Shown (said above), too short to take v0 from.
    TooShort,
    /// Shown in the file's own length unit, not known to be metres.
    UnitUnknown,
}

/// "  the scene takes from it: v0 = 0.791 m/s (both balls: the approach); R, b, μ_k,
/// e from the preset or the options; m assumed unless given (no data measure it)";
/// what the file's `# scene` lines give is named as its header's; where it takes no
/// v0, why (`approach`).
fn scene_line(
    values: &BTreeMap<&'static str, f64>,
    header: &BTreeMap<&'static str, f64>,
    approach: NoV0,
) -> String {
    // A value is given when the header sets every value it stands for (v0: both balls').
    let given = |k: Key| k.param().sets.iter().all(|s| header.contains_key(s.name()));
    let short = |p: &Param| p.label.replace("mu_k", "μ_k");
    // In the table's order (R, b, m …), as the parameters panel shows them.
    let from_header: Vec<String> = PARAMS
        .iter()
        .filter_map(|p| {
            Some(format!(
                "{} = {}",
                short(p),
                show(*header.get(p.name)?, p.dim)
            ))
        })
        .collect();
    let v0 = values.get("v0").or(values.get("v0_left"));
    let others: Vec<String> = [Key::V0, Key::Radius, Key::Width, Key::Mu, Key::Restitution]
        .into_iter()
        .filter(|&k| !(given(k) || k == Key::V0 && v0.is_some()))
        .map(|k| {
            if k == Key::V0 {
                "v0".into()
            } else {
                short(k.param())
            }
        })
        .collect();
    let mut rest = Vec::new();
    if !from_header.is_empty() {
        rest.push(format!("its header gives {}", from_header.join(", ")));
    }
    if !others.is_empty() {
        rest.push(format!(
            "{} from the preset or the options",
            others.join(", ")
        ));
    }
    if !given(Key::Mass) {
        rest.push("m assumed unless given (no data measure it)".into());
    }
    let rest = rest.join("; ");
    match v0 {
        Some(&v) => format!(
            "  the scene takes from it: v0 = {} (both balls: the approach); {rest}\n",
            show(v, Dimension::Speed)
        ),
        None => match approach {
            NoV0::TooShort => format!(
                "  the scene takes nothing from it (too few frames before the impact to take v0 from, at least {}): {rest}\n",
                crate::study::fit::APPROACH_FRAMES
            ),
            // It said "too few frames" of 7 frames before the impact.
            NoV0::UnitUnknown => format!(
                "  the scene takes nothing from it (its lengths' unit is not known, so neither is the approach speed in m/s: give --length-unit, see above): {rest}\n"
            ),
            NoV0::NoApproach => {
                format!(
                    "  the scene takes nothing from it (no approach before an impact): {rest}\n"
                )
            }
        },
    }
}
