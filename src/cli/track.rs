//! `groovelab track VIDEO`: both balls (or one) tracked in a video or a folder of
//! numbered frames, written as a Tracker-style multi-track file (which `--data`
//! reads) or as JSON, with how the frame rate, the scale and the groove's direction
//! were found.

use serde::Serialize;

use super::args::SceneArgs;
use super::error::CliError;
use super::progress::Bar;
use super::track_args::{TrackArgs, TrackOutput};
use crate::input::data::DataError;
use crate::input::video::{self, Info, Limits, RateSource, VideoError};
use crate::settings::params::Key;
use crate::settings::units::{Dimension, show, show_small, with_uncertainty};
use crate::study::Progress;
use crate::study::vision::tracks::{BallTrack, Calibration};
use crate::study::vision::{self, Tracker, Tracks, write};

#[derive(Serialize)]
struct TrackJson<'a> {
    video: String,
    kind: &'a str,
    width: usize,
    height: usize,
    frames: usize,
    frame_rate: f64,
    frame_rate_source: &'a RateSource,
    #[serde(skip_serializing_if = "Option::is_none")]
    container_frame_rate: Option<f64>,
    calibration: &'a Calibration,
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    gaps: &'a [[u64; 2]],
    t: &'a [f64],
    balls: &'a [BallTrack],
    notes: &'a [String],
}

/// Runs `track`.
/// Runs `track`; `scale` is `--scale`, the length one pixel shows (m).
pub fn run(scene: &SceneArgs, scale: Option<f64>, args: &TrackArgs) -> Result<String, CliError> {
    if let Some(path) = &args.output {
        crate::output::check_output(path)?;
    }
    let done = tracked(&args.video, scene, args.fps, scale)?;
    let text = match args.format {
        TrackOutput::Tracker => write::tracker_text(&done.tracks, &done.notes),
        TrackOutput::Json => {
            let (info, tracks) = (&done.info, &done.tracks);
            let j = TrackJson {
                video: args.video.display().to_string(),
                kind: &info.kind,
                width: info.width,
                height: info.height,
                frames: tracks.t.len(),
                frame_rate: done.fps,
                frame_rate_source: &done.source,
                container_frame_rate: info.container_fps,
                calibration: &tracks.calibration,
                gaps: &info.gaps,
                t: &tracks.t,
                balls: &tracks.balls,
                notes: &done.notes,
            };
            let mut s = serde_json::to_string_pretty(&j).expect("plain data serializes");
            s.push('\n');
            s
        }
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            crate::signals::watch();
            crate::output::write_atomically(path, text.as_bytes())?;
            let mut out: String = done.notes.iter().map(|n| format!("{n}\n")).collect();
            out += &format!("wrote {}\n", path.display());
            Ok(out)
        }
    }
}

/// A video tracked: what it is, the rate used and why, the tracks, the notes.
pub struct Tracked {
    pub info: Info,
    pub fps: f64,
    pub source: RateSource,
    pub tracks: Tracks,
    pub notes: Vec<String>,
}

/// Tracks the video (or folder) `video` for balls of the scene's R, at `fps` when
/// given, with `scale` (the length a pixel shows, m) when given; a progress bar on a
/// terminal, Ctrl-C stops it.
pub fn tracked(
    video: &std::path::Path,
    scene: &SceneArgs,
    fps: Option<f64>,
    scale: Option<f64>,
) -> Result<Tracked, CliError> {
    let (preset, s, _) = scene.resolve()?;
    let radius_given = scene.values.get(Key::Radius).is_some();
    let file = video.display().to_string();
    let data_err = |e: VideoError| DataError {
        file: e.file,
        what: e.what,
    };
    let (info, frames) = video::open(video, &Limits::default()).map_err(data_err)?;
    let Some((fps, source)) = info.rate(fps) else {
        return Err(DataError {
            file,
            what: "a folder of frames says no frame rate; give it with --fps (e.g. --fps 240)"
                .into(),
        }
        .into());
    };
    let bar = Bar::new("frames", true);
    bar.set_total(info.frames);
    let mut tracker = Tracker::new(8.0);
    let mut numbers = Vec::new();
    for (i, frame) in frames.enumerate() {
        if bar.cancelled() {
            return Err(CliError::Interrupted);
        }
        let (n, img) = frame.map_err(data_err)?;
        tracker.push(&img);
        numbers.push(n);
        bar.tick(i as u64 + 1, info.frames);
    }
    bar.finish();
    if numbers.len() < 2 {
        return Err(DataError {
            file,
            what: format!("holds {} frame(s), expected a video", numbers.len()),
        }
        .into());
    }
    let first = numbers[0];
    let times = numbers.iter().map(|n| (n - first) as f64 / fps).collect();
    let tracks =
        vision::tracks(&tracker, times, s.radius, scale.map(|l| 1.0 / l)).map_err(|e| {
            DataError {
                file: file.clone(),
                what: e.to_string(),
            }
        })?;
    let radius_from = if radius_given {
        "--radius".to_string()
    } else {
        format!("preset {}; give --radius", preset.name)
    };
    let notes = notes(&file, &info, fps, &source, &tracks, &radius_from);
    Ok(Tracked {
        info,
        fps,
        source,
        tracks,
        notes,
    })
}

/// What was found, in lines for people (the file's comment lines, the JSON's notes).
fn notes(
    file: &str,
    info: &Info,
    fps: f64,
    source: &RateSource,
    tracks: &Tracks,
    radius_from: &str,
) -> Vec<String> {
    let mut n = vec![format!(
        "groovelab track {file}: {}, {}×{}, {} frames",
        info.kind,
        info.width,
        info.height,
        tracks.t.len()
    )];
    let container = info
        .container_fps
        .map(|f| {
            format!(
                "; the container says {}",
                crate::settings::units::significant(f, 6)
            )
        })
        .unwrap_or_default();
    let rate = crate::settings::units::significant(fps, 6);
    n.push(match source {
        RateSource::Given => format!("frame rate {rate} frames/s: given (--fps){container}"),
        RateSource::Capture(key) => format!(
            "frame rate {rate} frames/s: the slow-motion capture rate in the file's metadata ({key}){container}"
        ),
        RateSource::Container => format!("frame rate {rate} frames/s: the container's"),
    });
    if !info.gaps.is_empty() {
        let g: Vec<String> = info
            .gaps
            .iter()
            .take(5)
            .map(|[a, b]| {
                if a == b {
                    format!("{a}")
                } else {
                    format!("{a}–{b}")
                }
            })
            .collect();
        n.push(format!(
            "frames missing from the folder: {}{} (the times keep the gaps)",
            g.join(", "),
            if info.gaps.len() > 5 { ", …" } else { "" }
        ));
    }
    let c = &tracks.calibration;
    n.push(if c.scale_given {
        format!(
            "scale {} px/m: given (--scale {} a pixel)",
            crate::settings::units::significant(c.px_per_m, 6),
            show_small(1.0 / c.px_per_m, Dimension::Length)
        )
    } else {
        let (v, e) = with_uncertainty(c.px_per_m, c.px_per_m_sigma.max(1e-9), 2);
        let (rv, re) = with_uncertainty(c.radius_px, c.radius_px_sigma.max(1e-9), 2);
        format!(
            "scale {v} ± {e} px/m: the balls' fitted radius {rv} ± {re} px for R = {} ({radius_from}); speeds and μ_k from these tracks carry its {:.2} %, which `fit` adds to their own ±",
            show(c.radius_m, Dimension::Length),
            100.0 * c.px_per_m_sigma / c.px_per_m
        )
    });
    n.push(if c.groove_found {
        let (v, e) = with_uncertainty(c.groove_deg, c.groove_deg_sigma.max(1e-9), 2);
        format!("groove at {v} ± {e}° in the picture (found from the paths; + is the right end lower): the tracks are turned to it")
    } else {
        "groove direction not found (the paths are too short): taken as level in the picture".into()
    });
    if tracks.balls.len() == 1 {
        let b = &tracks.balls[0];
        n.push(format!(
            "one ball in view: tracked as the {} ball (it moves {} at first); no second ball",
            b.name,
            if b.name == "left" {
                "right, coming from the left"
            } else {
                "left, coming from the right"
            }
        ));
    }
    for b in &tracks.balls {
        n.push(ball_line(b, tracks.t.len()));
    }
    n.push(format!(
        "x along the groove toward the right, y up, in metres (position scatter ≈ {}); t in s from the first frame",
        show_small(scatter(tracks), Dimension::Length)
    ));
    n
}

/// The median of the centres' standard errors, m.
fn scatter(tracks: &Tracks) -> f64 {
    let s: Vec<f64> = tracks
        .balls
        .iter()
        .flat_map(|b| b.sigma.iter().copied())
        .filter(|v| v.is_finite())
        .collect();
    vision::tracker::median(&s).unwrap_or(f64::NAN)
}

/// One ball's line: frames tracked, left out and why, marks found.
fn ball_line(b: &BallTrack, frames: usize) -> String {
    let tracked = frames - b.unseen - b.merged - b.poor;
    let mut out: Vec<String> = Vec::new();
    for (n, why) in [
        (b.unseen, "not seen"),
        (b.merged, "touching the other ball"),
        (b.poor, "outline blurred or too little of it visible"),
    ] {
        if n > 0 {
            out.push(format!("{n} {why}"));
        }
    }
    let left_out = if out.is_empty() {
        String::new()
    } else {
        format!(" (left out, not filled in: {})", out.join(", "))
    };
    format!(
        "{} ball: centre in {tracked} of {frames} frames{left_out}; mark in {} ({} hidden by the rail or too near it)",
        b.name,
        tracked - b.mark_missing,
        b.mark_missing
    )
}
