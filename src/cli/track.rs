//! `groovelab track VIDEO`: both balls (or one) tracked in a video or a folder of
//! numbered frames, written as a Tracker-style multi-track file (which `--data`
//! reads) or as JSON, with how the frame rate, the scale and the groove's direction
//! were found.

use serde::Serialize;

use super::args::{DataArgs, SceneArgs};
use super::error::CliError;
use super::progress::Bar;
use super::track_args::{TrackArgs, TrackOutput};
use crate::input::video::tracked::{self, Options, Pictures, Tracked};
use crate::input::video::{RateSource, overlay};
use crate::settings::params::Key;
use crate::vision::tracks::{BallTrack, Calibration};

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
    /// Always there (`[]` without gaps): scripts read the field the docs list.
    gaps: &'a [[u64; 2]],
    t: &'a [f64],
    balls: &'a [BallTrack],
    notes: &'a [String],
}

/// Runs `track`; of the data options it reads `--scale` (the length one pixel
/// shows), `--fps`, `--roi` and `--ball-at`.
pub fn run(scene: &SceneArgs, data: &DataArgs, args: &TrackArgs) -> Result<String, CliError> {
    if let Some(path) = &args.output {
        crate::output::check_output(path)?;
    }
    // A bad overlay name is refused before the tracking, not after it.
    if let Some(path) = &args.overlay {
        overlay::kind(path)?;
        crate::output::check_output(path)?;
    }
    let options = options(scene, data)?;
    let bar = Bar::new("frames", true);
    // The app's pictures are not wanted here.
    let done = tracked::track_or_found(&args.video, &options, &bar, Pictures::Skipped);
    bar.finish();
    let done: Tracked = match done {
        Ok(done) => done.ok_or(CliError::Interrupted)?,
        Err(refused) => {
            return Err(refused_drawn(
                &args.video,
                *refused,
                args.overlay.as_deref(),
                options.fps,
            ));
        }
    };
    // Tracks that `fit` would refuse for their scale (a ball at 87 m/s: R given as
    // 2.75, metres) are refused here, before anything is written.
    let tracks = done.text();
    tracks_in_a_groove(&args.video.display().to_string(), &tracks)?;
    let drawn = match &args.overlay {
        Some(path) => {
            overlay::write_overlay(&args.video, &overlay::Drawing::tracked(&done), path)?;
            format!("wrote the overlay {}\n", path.display())
        }
        None => String::new(),
    };
    let text = match args.format {
        TrackOutput::Tracker => tracks,
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
        None => {
            // Stdout holds the tracks: the overlay's line goes beside the progress.
            eprint!("{drawn}");
            Ok(text)
        }
        Some(path) => {
            crate::signals::watch();
            crate::output::write_atomically(path, text.as_bytes())?;
            let mut out: String = done.notes.iter().map(|n| format!("{n}\n")).collect();
            out += &drawn;
            out += &format!("wrote {}\n", path.display());
            Ok(out)
        }
    }
}

/// A refused tracking's error; with `--overlay FILE`, what the tracker found before
/// it refused is drawn there over a pixel grid first and the error says so (an
/// overlay that cannot be written leaves the error as it was). `fps`: `--fps`, the
/// rate of a folder's overlay video.
fn refused_drawn(
    video: &std::path::Path,
    refused: tracked::Refused,
    overlay_file: Option<&std::path::Path>,
    fps: Option<f64>,
) -> CliError {
    let (Some(file), false) = (overlay_file, refused.found.is_empty()) else {
        return refused.error.into();
    };
    let drawing = overlay::Drawing::refused(refused.found, fps);
    match overlay::write_overlay(video, &drawing, file) {
        Ok(()) => CliError::RefusedDrawn {
            error: Box::new(refused.error),
            overlay: file.to_path_buf(),
        },
        Err(_) => refused.error.into(),
    }
}

/// What `track` (and `--data VIDEO`) asks of the tracking: R from the scene options,
/// `--fps`, `--scale` (the length a pixel shows, m), `--roi` and `--ball-at` as given.
pub fn options(scene: &SceneArgs, data: &DataArgs) -> Result<Options, CliError> {
    let (fps, scale) = (data.fps, data.scale);
    let (preset, s, _) = scene.resolve()?;
    let radius_from = if scene.values.get(Key::Radius).is_some() {
        "--radius".to_string()
    } else {
        format!("preset {}; give --radius", preset.name)
    };
    Ok(Options {
        radius: s.radius,
        fps,
        px_per_m: scale.map(|l| 1.0 / l),
        radius_from,
        cache: crate::input::video::cache::user_folder(),
        roi: data.roi,
        ball_at: data.ball_at,
    })
}

/// The tracks `text` of the video `file` refused where, read as `--data` reads
/// them, their speeds or frame spacing are of no ball in a groove ([`super::error::video_scale`]:
/// R given in the wrong unit, a wrong `--scale` or `--fps`); any other reason they
/// give no series (no impact in the clip) is `fit`'s to say, not `track`'s.
pub(super) fn tracks_in_a_groove(file: &str, text: &str) -> Result<(), CliError> {
    use crate::input::data::{DataProblem, Reading, load};
    use crate::study::measured::track::Derive;
    match load(text, file, &Reading::default(), &Derive::default()) {
        Err(e) if matches!(e.what, DataProblem::Scale(_)) => {
            Err(super::error::video_scale(e, file, text))
        }
        _ => Ok(()),
    }
}
