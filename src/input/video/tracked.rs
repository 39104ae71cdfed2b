//! A video (or a folder of frames) tracked, for `track`, `--data VIDEO` and the app:
//! its frames streamed through the tracker one at a time, small pictures of them
//! kept for the app (`vision::thumbs`), the tracks in metres along the
//! groove, and what was found said in lines for people (the file's comment lines,
//! the JSON's notes). Progress and a stop request go through a `Progress`.

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use super::{Info, Limits, RateSource, VideoError, VideoProblem};
use crate::settings::units::{Dimension, show, show_small, with_uncertainty};
use crate::study::Progress;
use crate::study::measured::track::derivative::scatter as track_scatter;
use crate::vision::band::Band;
use crate::vision::prepared::PreparedLook;
use crate::vision::thumbs::{Thumbs, VideoView};
use crate::vision::tracks::{BallTrack, Tracks};
use crate::vision::{self, Tracker, overlay};

/// What a tracking is asked for: the balls' radius R (m; the scale comes from it),
/// the frame rate given (`--fps`), the scale given (px/m, from `--scale`), where R
/// came from (said in the notes: "--radius", "preset NAME; give --radius"), and the
/// folder its tracks are kept in (`cache::user_folder`; `None`: this process only).
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    pub radius: f64,
    pub fps: Option<f64>,
    pub px_per_m: Option<f64>,
    pub radius_from: String,
    pub cache: Option<std::path::PathBuf>,
    /// Where to look (`--roi X,Y,W,H`, pixels of the frame): `None`, the whole frame.
    pub roi: Option<Roi>,
    /// A point on one ball in the first frame, pixels (`--ball-at X,Y`, or a click on
    /// the ball in the app's video view): the tracker's seed.
    pub ball_at: Option<(f64, f64)>,
}

pub use crate::vision::Roi;

impl Options {
    /// The tracker's parameters these options set (the rest at their defaults).
    pub fn params(&self) -> vision::Params {
        vision::Params {
            roi: self.roi,
            ball_at: self.ball_at,
            ..vision::Params::default()
        }
    }
}

/// A video tracked: what it is, the rate used and why, the tracks, the notes, and
/// the pictures the app draws.
pub struct Tracked {
    pub info: Info,
    pub fps: f64,
    pub source: RateSource,
    pub tracks: Tracks,
    pub notes: Vec<String>,
    pub view: VideoView,
    /// The rows tracked (`vision::band`), or `None`: the whole frame. The tracks,
    /// the view and the fits are in the whole frame's pixels either way.
    pub band: Option<Band>,
}

impl Tracked {
    /// The tracks as the Tracker-style text `--data` reads (the notes as comments).
    pub fn text(&self) -> String {
        vision::write::tracker_text(&self.tracks, &self.notes)
    }
}

/// Tracks the video (or folder) `video` as `options` ask, telling `progress` each
/// frame; `Ok(None)` when `progress` asked to stop.
pub fn track(
    video: &std::path::Path,
    options: &Options,
    progress: &dyn Progress,
) -> Result<Option<Tracked>, VideoError> {
    track_or_found(video, options, progress, Pictures::Made).map_err(|refused| refused.error)
}

/// Whether a tracking makes the app's small pictures of the frames
/// (`Tracked::view`'s thumbs): the command line's `track` writes tracks and draws
/// its overlay from the full frames, and does without them (a box average of every
/// frame, on the reader's thread).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pictures {
    Made,
    Skipped,
}

/// A tracking that gave no tracks: why, and what the tracker found in each frame
/// before it refused (empty when it failed before tracking: an unreadable file).
#[derive(Debug)]
pub struct Refused {
    pub error: VideoError,
    pub found: FitsFound,
    /// The app's view of the first frame, with what the tracker found there and why it
    /// refused (a click on a ball seeds the tracking again); `None` where no pictures
    /// were made or no frame was tracked.
    pub first_frame: Option<VideoView>,
}

/// What the tracker found in each frame, in the video's pixels: each ball's fitted
/// outline (its own radius) and mark, in the order first seen.
pub type FitsFound = Vec<Vec<Option<overlay::Drawn>>>;

/// As [`track`], and when the tracker is unsure (no tracks), what it found in each
/// frame, for `track --overlay` to draw: a student sees where it went wrong and
/// reads `--roi` and `--ball-at` off the picture. `pictures`: whether the app's
/// pictures are made (skipped, `view` holds none). Only the groove's band is
/// tracked where the first frames are sure of it ([`Framing::Band`]).
pub fn track_or_found(
    video: &std::path::Path,
    options: &Options,
    progress: &dyn Progress,
    pictures: Pictures,
) -> Result<Option<Tracked>, Box<Refused>> {
    track_framed(video, options, progress, pictures, Framing::Band)
}

/// Which rows of the frames the tracker looks at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Framing {
    /// The groove's band (`vision::band`) where the clip's first frames are sure of
    /// it, else the whole frame; and the whole frame again when the banded tracking
    /// is refused, or a ball came near the band's edge, or it found one ball (a
    /// band is a speed-up, never a new refusal).
    Band,
    /// The whole frame.
    Whole,
}

/// As [`track_or_found`], its rows chosen by `framing`. A clip refused where its
/// clear outlines agree on a radius the tracker's learned one contradicts
/// (`vision::Tracker::radius_contradicted`: a wrong first lock), or where more of
/// them than fits kept put it elsewhere (`vision::Tracker::radius_doubted`), is
/// tracked once more, their radius known from its first frame; one refused for radii that
/// scatter, its background learned at full resolution, is tracked once more with
/// each outline sought first in the frame's difference from the background
/// (`vision::Params::difference_first`); one in which no ball was found is tracked
/// once more at the lower floor `vision::Params::faint_levels`, and refused so
/// again, a third time with no pixel taken for a shadow ([`unshadowed`]); one in
/// which neither ball was found in a third of the frames, once more with no pixel
/// taken for a shadow; one with more than two balls in most frames, once more with no
/// pixel taken for a shadow (and, its first fits contradicted by its clear outlines,
/// a third time from their radius). Refused again, the first refusal stands.
pub fn track_framed(
    video: &std::path::Path,
    options: &Options,
    progress: &dyn Progress,
    pictures: Pictures,
    framing: Framing,
) -> Result<Option<Tracked>, Box<Refused>> {
    let params = options.params();
    let kept = KeptFrames::default();
    let once =
        |p: &vision::Params| track_once(video, options, p, progress, pictures, framing, &kept);
    match once(&params)? {
        Attempt::Contradicted(first) => {
            let note = format!(
                "tracked twice: the radius learned from the first fits ({:.2} px) was contradicted by the clip's clear outlines, which put it at {:.2} px; tracked again from that radius (the scale is from the second tracking's own fits)",
                first.learned_px, first.radius_px
            );
            retried(
                once(&at_outlines_radius(&params, &first)),
                first.refused,
                note,
            )
        }
        Attempt::Scattered(refused) => {
            let note = difference_note(&refused);
            let again = vision::Params {
                difference_first: true,
                ..params
            };
            retried(once(&again), refused, note)
        }
        Attempt::Unseen(refused) => {
            let faint = vision::Params {
                differ_levels: params.faint_levels,
                ..params
            };
            match retried(once(&faint), refused, faint_note(&params)) {
                Err(first) if no_ball(&first) => {
                    done_or_first(once(&unshadowed(&faint)), first, unshadowed_note(&params))
                }
                other => other,
            }
        }
        Attempt::Crowded(refused) => {
            let plain = unshadowed(&params);
            match once(&plain) {
                // Its balls whole at last, a first lock on a part of one may still
                // set a radius the clear outlines contradict: tracked from theirs.
                Ok(Attempt::Contradicted(second)) => {
                    let note = crowded_note(&refused, Some(&second));
                    done_or_first(once(&at_outlines_radius(&plain, &second)), refused, note)
                }
                other => {
                    let note = crowded_note(&refused, None);
                    done_or_first(other, refused, note)
                }
            }
        }
        Attempt::Sparse(refused) => {
            match done_or_first(once(&unshadowed(&params)), refused, sparse_note()) {
                Err(first) => done_or_first(once(&grey_in_colour(&params)), first, grey_note()),
                other => other,
            }
        }
        Attempt::Done(done) => Ok(*done),
        // `track_once` never gives it.
        Attempt::Again => Ok(None),
    }
}

/// A second tracking's outcome: its tracks with `note` (why the clip was tracked
/// twice) added, or, where it gave none, the first tracking's refusal `first`, but
/// where the second found the balls' line running up the picture: that says what is
/// wrong (a clip shown turned, in which the first found no ball across it).
fn retried(
    second: Result<Attempt, Box<Refused>>,
    first: Box<Refused>,
    note: String,
) -> Result<Option<Tracked>, Box<Refused>> {
    match second {
        Err(steep)
            if matches!(
                steep.error.what.tracks_error(),
                Some(vision::TracksError::Steep { .. })
            ) =>
        {
            Err(steep)
        }
        other => done_or_first(other, first, note),
    }
}

/// A further tracking's tracks with `note` added, or, where it gave none, the first
/// tracking's refusal `first` (whatever the further one said).
fn done_or_first(
    again: Result<Attempt, Box<Refused>>,
    first: Box<Refused>,
    note: String,
) -> Result<Option<Tracked>, Box<Refused>> {
    match again {
        Ok(Attempt::Done(mut done)) => {
            if let Some(t) = done.as_mut().as_mut() {
                t.notes.push(note);
            }
            Ok(*done)
        }
        _ => Err(first),
    }
}

/// `p` with the radius the clear outlines of a tracking `contradicted` agree on known
/// from the first frame (`Params::radius_px`, as a seed's outline sets it).
fn at_outlines_radius(p: &vision::Params, contradicted: &Contradicted) -> vision::Params {
    vision::Params {
        radius_px: Some(contradicted.radius_px),
        ..*p
    }
}

/// `p` with no pixel taken for a shadow (`Params::shadow_darkest` 0): a ball of the
/// wall's own hue, darker than it, or a dark ball's shaded side dims the wall as a
/// shadow would, and the shadow test takes it away.
fn unshadowed(p: &vision::Params) -> vision::Params {
    vision::Params {
        shadow_darkest: 0.0,
        ..*p
    }
}

/// `p` with a grey ball of any brightness sought in colour where its outline in
/// brightness is poor and the wall about it is of one colour
/// (`Params::grey_in_colour`): a steel ball's lit rim of the wall's brightness
/// leaves its outline in brightness inside its edge, and its cast shadow outside.
fn grey_in_colour(p: &vision::Params) -> vision::Params {
    vision::Params {
        grey_in_colour: true,
        ..*p
    }
}

/// The note of a clip tracked again with a grey ball's outline sought in colour,
/// after neither ball was found in a third of its frames (nor with no pixel taken for
/// a shadow).
fn grey_note() -> String {
    "tracked three times: neither ball was found in a third of the frames by its outline in brightness (a grey ball's rim of the wall's brightness, or its shadow beside it), nor with pixels darker than the wall and of its hue taken as the balls'; tracked again with each grey ball's outline sought in colour against the wall's one colour".into()
}

/// The note of a clip tracked again with no pixel taken for a shadow, after neither
/// ball was found in a third of its frames.
fn sparse_note() -> String {
    "tracked twice: neither ball was found in a third of the frames where pixels darker than the wall and of its hue are taken for shadows (a ball of the wall's own hue, or a dark ball's shaded side, is such a pixel); tracked again with them taken as the balls'".into()
}

/// The note of a clip tracked again with no pixel taken for a shadow, after more than
/// two balls were seen in most of its frames (`refused`); and, where that second
/// tracking's first fits were `contradicted` by its clear outlines, a third time
/// from their radius.
fn crowded_note(refused: &Refused, contradicted: Option<&Contradicted>) -> String {
    let why = refused.error.what.to_string();
    let why = why.split(';').next().unwrap_or(&why);
    let again = "tracked again with them taken as the balls'";
    match contradicted {
        None => format!("tracked twice: {why}, {CROWDED_WHY}; {again}"),
        Some(c) => format!(
            "tracked three times: {why}, {CROWDED_WHY}; {again}, and its first fits' radius ({:.2} px) was contradicted by its clear outlines, which agree on {:.2} px; tracked a third time from that radius",
            c.learned_px, c.radius_px
        ),
    }
}

/// Why a dark ball seen as more than two things is tracked again without the shadow
/// test.
const CROWDED_WHY: &str = "where pixels darker than the wall and of its hue are taken for shadows (a dark ball's body on a dark wall is such a pixel, and its highlight and mark are then two things apart)";

/// Whether `refused` is for no ball found at all.
fn no_ball(refused: &Refused) -> bool {
    matches!(
        refused.error.what.tracks_error(),
        Some(vision::TracksError::NoBall { .. })
    )
}

/// The note of a clip tracked a third time, its darker pixels of the wall's hue
/// taken as the balls' rather than as shadows, after no ball was found at
/// `Params::differ_levels` nor at `Params::faint_levels`.
fn unshadowed_note(p: &vision::Params) -> String {
    format!(
        "tracked three times: no ball stood out from the background by {:.0} levels, nor by {:.0}, where pixels darker than the wall and of its hue are taken for shadows (a ball of the wall's own hue, darker than it, is such a pixel); tracked again with them taken as the balls'",
        p.differ_levels, p.faint_levels
    )
}

/// The note of a clip tracked again, its outlines sought first in the frame's
/// difference from the background, after `refused` (its frames' radii scattered).
fn difference_note(refused: &Refused) -> String {
    let why = match &refused.error.what {
        VideoProblem::Tracks { error, .. } => error.to_string(),
        other => other.to_string(),
    };
    let why = why.trim_start_matches("tracking unsure: ");
    format!(
        "tracked twice: {}; tracked again with each ball's outline sought first in the frame's difference from the background (the wall's pattern taken away)",
        why.split(", so").next().unwrap_or(why)
    )
}

/// The note of a clip tracked again at the floor `Params::faint_levels` after no
/// ball was found at `Params::differ_levels`.
fn faint_note(p: &vision::Params) -> String {
    format!(
        "tracked twice: no ball stood out from the background by {:.0} levels (a dark ball on a dark wall shows only its lit part there); tracked again with pixels {:.0} levels off the background taken as the balls'",
        p.differ_levels, p.faint_levels
    )
}

/// A tracking refused whose clear outlines contradict the radius it had learned: the
/// refusal, that radius and the one they agree on (px).
struct Contradicted {
    refused: Box<Refused>,
    learned_px: f64,
    radius_px: f64,
}

/// One tracking at `params` (the band's, else the whole frame's; see [`Framing`]):
/// done (the tracks, or `None` asked to stop), contradicted or scattered, never
/// `Again`.
fn track_once(
    video: &std::path::Path,
    options: &Options,
    params: &vision::Params,
    progress: &dyn Progress,
    pictures: Pictures,
    framing: Framing,
    kept: &KeptFrames,
) -> Result<Attempt, Box<Refused>> {
    let how = HowRead { pictures, kept };
    if framing == Framing::Band {
        match attempt(video, options, params, progress, how, true)? {
            Attempt::Again => {}
            other => return Ok(other),
        }
    }
    match attempt(video, options, params, progress, how, false)? {
        // Never asked again of the whole frame.
        Attempt::Again => Ok(Attempt::Done(Box::new(None))),
        other => Ok(other),
    }
}

/// What one tracking gave: the tracks (`None`: asked to stop), or, banded, a reason
/// to track the whole frame instead, or a refusal of tracks whose clear outlines
/// contradict the radius learned, or of tracks whose radii scatter.
enum Attempt {
    Done(Box<Option<Tracked>>),
    Again,
    Contradicted(Box<Contradicted>),
    /// Refused for radii that scatter, the background learned at full resolution:
    /// to be tracked again with the outlines sought in the frame's difference from
    /// it ([`track_framed`]).
    Scattered(Box<Refused>),
    /// Refused for no ball found at the floor `Params::differ_levels`, over
    /// `Params::faint_levels`: to be tracked again at that ([`track_framed`]).
    Unseen(Box<Refused>),
    /// Refused for neither ball found in a third of the frames, with the shadow
    /// test on: to be tracked again without it ([`track_framed`]).
    Sparse(Box<Refused>),
    /// Refused for more than two balls in most frames, with the shadow test on: to
    /// be tracked again without it ([`track_framed`]).
    Crowded(Box<Refused>),
}

/// How a tracking reads its frames: whether it makes the app's pictures, and the
/// clip's frames kept by an earlier tracking of it.
#[derive(Clone, Copy)]
struct HowRead<'a> {
    pictures: Pictures,
    kept: &'a KeptFrames,
}

/// `video` opened for a tracking: what it is, its frames (those kept by an earlier
/// tracking where there are any, else decoded: `decoded`), and its frame rate.
struct ToTrack {
    info: Info,
    frames: super::Frames,
    rate: (f64, RateSource),
    decoded: bool,
}

/// `video` opened for a tracking as `options` ask ([`ToTrack`]), or why not: probed
/// once, the rate and the options checked before a frame is decoded.
fn opened(
    video: &std::path::Path,
    options: &Options,
    kept: &KeptFrames,
) -> Result<ToTrack, VideoError> {
    let err = |what: VideoProblem| VideoError::new(video, what);
    let mut rate = None;
    let mut accept = |info: &Info| {
        rate = info.rate(options.fps);
        if let Some(what) = off_the_frame(options, (info.width, info.height)) {
            return Err(err(what));
        }
        match rate {
            Some(_) => Ok(()),
            None => Err(err(VideoProblem::NoRate)),
        }
    };
    let from_kept = kept.frames();
    let decoded = from_kept.is_none();
    let (info, frames) = match from_kept {
        // Probed before (the probe is kept in this process): no ffprobe, no ffmpeg.
        Some(frames) => super::check(video, &Limits::default())
            .and_then(|info| accept(&info).map(|()| (info, frames)))?,
        None => super::open_if(video, &Limits::default(), accept)?,
    };
    let rate = rate.ok_or_else(|| err(VideoProblem::NoRate))?;
    Ok(ToTrack {
        info,
        frames,
        rate,
        decoded,
    })
}

/// One tracking of `video`: of its band when `banded` and the first frames give
/// one, else of the whole frame. Its frames are those an earlier tracking kept
/// where there are any, else decoded (and a whole frame's kept for the next).
fn attempt(
    video: &std::path::Path,
    options: &Options,
    params: &vision::Params,
    progress: &dyn Progress,
    how: HowRead<'_>,
    banded: bool,
) -> Result<Attempt, Box<Refused>> {
    let HowRead { pictures, kept } = how;
    let nothing = |error: VideoError| {
        Box::new(Refused {
            error,
            found: Vec::new(),
            first_frame: None,
        })
    };
    let file = video.display().to_string();
    let err = |what: VideoProblem| VideoError::new(video, what);
    let ToTrack {
        info,
        frames,
        rate: (fps, source),
        decoded,
    } = opened(video, options, kept).map_err(nothing)?;
    let framed = if banded {
        // Kept frames are cut in memory: decoding the band anew is ffmpeg's work.
        let anew = decoded.then_some(pictures);
        framed(video, &info, frames, (params, fps), anew).map_err(nothing)?
    } else {
        Framed::whole(frames)
    };
    let band = framed.band;
    // Whole frames decoded are kept for a further tracking of the clip.
    let keep = decoded && band.is_none();
    let Some(Streamed {
        mut tracker,
        numbers,
        thumbs,
        frames,
    }) = stream(framed, &info, params, progress, (pictures, keep)).map_err(nothing)?
    else {
        return Ok(Attempt::Done(Box::new(None)));
    };
    kept.set(frames);
    if let Some(b) = band {
        vision::band::shift(&mut tracker.frames, b.y as f64);
        tracker.params = *params;
    }
    let first = match numbers.as_slice() {
        [first, _, ..] => *first,
        _ => {
            return Err(nothing(err(VideoProblem::TooFewFrames {
                frames: numbers.len(),
            })));
        }
    };
    // A slow-motion clip's capture rate spans more than its duration by design.
    if source == RateSource::Container
        && let Some(what) = numbers.last().and_then(|n| info.rate_in_doubt(n + 1, fps))
    {
        return Err(nothing(err(what)));
    }
    let times: Vec<f64> = numbers.iter().map(|n| (n - first) as f64 / fps).collect();
    let (tracked, stacked) = tracks_or_stacked(&mut tracker, times, options, band.is_none());
    let tracks = match tracked {
        Ok(tracks) => tracks,
        Err(_) if band.is_some() => return Ok(Attempt::Again),
        Err(e) => {
            let what = VideoProblem::Tracks {
                error: e,
                roi: options.roi.is_some(),
                scale: options.px_per_m.is_some(),
                at: options.ball_at,
            };
            return refusal(&tracker, thumbs, pictures, err(what));
        }
    };
    if let Some(b) = band
        && (tracks.balls.len() != 2 || !b.holds(&tracker.frames, tracks.calibration.radius_px))
    {
        return Ok(Attempt::Again);
    }
    let mut notes = notes(&file, &info, fps, &source, &tracks, &options.radius_from);
    notes.extend(seed_note(options.ball_at, tracker.seeded(), &tracks));
    notes.extend(stacked);
    let view = VideoView::new(thumbs, &tracks);
    Ok(Attempt::Done(Box::new(Some(Tracked {
        info,
        fps,
        source,
        tracks,
        notes,
        view,
        band,
    }))))
}

/// The refusal `error` of `tracker`'s tracking, or what to try next: the clip
/// tracked again at the radius its clear outlines agree on where they contradict the
/// one learned, or put it at where they doubt it (`TracksError::RadiusDoubted`)
/// ([`Contradicted`]), or with the outlines sought in the frame's
/// difference from the background where the radii scattered and that background is
/// learned at full resolution ([`Attempt::Scattered`]), or at a lower floor where
/// no ball was found ([`Attempt::Unseen`]), or with no pixel taken for a shadow
/// where neither ball was found in a third of the frames ([`Attempt::Sparse`]) or
/// more than two balls were seen in most frames ([`Attempt::Crowded`]).
fn refusal(
    tracker: &Tracker,
    thumbs: Thumbs,
    pictures: Pictures,
    error: VideoError,
) -> Result<Attempt, Box<Refused>> {
    use vision::TracksError::{NoBall, RadiiDisagree, Sparse, TooMany};
    let params = &tracker.params;
    let why = error.what.tracks_error();
    let scattered = matches!(why, Some(RadiiDisagree { .. }))
        && !params.difference_first
        && tracker.background().is_some_and(|b| b.image.factor == 1);
    let unseen = matches!(why, Some(NoBall { .. })) && params.faint_levels < params.differ_levels;
    let sparse = matches!(why, Some(Sparse { .. })) && params.shadow_darkest > 0.0;
    let crowded = matches!(why, Some(TooMany { .. })) && params.shadow_darkest > 0.0;
    // Outlines that put the radius in doubt (however they scatter) are tried as
    // those that contradict it: tracked again from their radius.
    let doubted = match why {
        Some(vision::TracksError::RadiusDoubted { outlines_px, .. }) => Some(*outlines_px),
        _ => None,
    };
    let refused = refused(tracker, thumbs, pictures, error);
    match (tracker.radius_contradicted().or(doubted), tracker.radius()) {
        (Some(r), Some(learned_px)) if params.radius_px.is_none() => {
            Ok(Attempt::Contradicted(Box::new(Contradicted {
                refused,
                learned_px,
                radius_px: r,
            })))
        }
        _ if scattered => Ok(Attempt::Scattered(refused)),
        _ if unseen => Ok(Attempt::Unseen(refused)),
        _ if sparse => Ok(Attempt::Sparse(refused)),
        _ if crowded => Ok(Attempt::Crowded(refused)),
        _ => Err(refused),
    }
}

/// The tracks of `tracker`'s frames at `times`; where the frames' radii disagree,
/// their edge in colour lies off their outlines (refused, or let through by the
/// pictures with a wide ±) or their radius is over the balls' stacked pictures',
/// and `whole` (the whole frame's tracking: a band refused is tracked whole first),
/// those of its balls' stacked pictures (`vision::Tracker::restacked`, which then
/// replaces `tracker`), with the note saying so. The first outcome stands where the
/// pictures give no tracks.
fn tracks_or_stacked(
    tracker: &mut Tracker,
    times: Vec<f64>,
    options: &Options,
    whole: bool,
) -> (Result<vision::Tracks, vision::TracksError>, Option<String>) {
    let (radius, scale) = (options.radius, options.px_per_m);
    let first = vision::tracks(tracker, times.clone(), radius, scale);
    // Why the stacked pictures are sought; `first` stands where they give no tracks.
    let why = match &first {
        // Radii that scatter, or an edge in colour off the outlines: the frames'
        // outlines are not the ball's, its stacked picture's may be.
        Err(
            e @ (vision::TracksError::RadiiDisagree { .. }
            | vision::TracksError::ColourEdge { .. }
            | vision::TracksError::PictureDisagrees { .. }),
        ) if whole => e.clone(),
        // An edge in colour far inside outlines the pictures confirm: a scale, but
        // with a ± that holds the colour's offset; the pictures' own radius, where
        // they give tracks, is the surer (small look 71: 0.160 ± 0.008 against 0.169
        // ± 0.044 for 0.17). A band's such tracks give way to the whole frame's,
        // which seeks them.
        Ok(vision::Tracks {
            calibration:
                vision::tracks::Calibration {
                    colour_edge_px: Some(offset_px),
                    radius_px,
                    ..
                },
            ..
        }) => {
            let why = vision::TracksError::ColourEdge {
                offset_px: *offset_px,
                radius_px: *radius_px,
            };
            if !whole {
                return (Err(why), None);
            }
            why
        }
        _ => return (first, None),
    };
    let Some((again, radii)) = tracker.restacked() else {
        return (first, None);
    };
    match vision::tracks(&again, times, radius, scale) {
        Ok(tracks) => {
            *tracker = again;
            let why = why.to_string();
            let why = why.trim_start_matches("tracking unsure: ");
            let note = format!(
                "the radius from the balls' stacked pictures: {}; each ball's frames stacked at its centres (the wall behind it averages out), its radius from the outline there ({:.2} and {:.2} px, taken {:.0} % outside the outline: a shaded limb puts it inside), each frame's centre matched to its ball's picture",
                why.split(", so").next().unwrap_or(why),
                radii[0],
                radii[1],
                100.0 * tracker.params.stack_edge
            );
            (Ok(tracks), Some(note))
        }
        Err(_) => (first, None),
    }
}

/// The frames to track and the band they are of: cut by ffmpeg (`cut` false) or
/// to be cut as they are read (`cut` true: a folder, or the app's pictures, which
/// are made of whole frames); `band` `None`, whole frames.
struct Framed {
    frames: super::Frames,
    band: Option<Band>,
    cut: bool,
}

impl Framed {
    fn whole(frames: super::Frames) -> Framed {
        Framed {
            frames,
            band: None,
            cut: false,
        }
    }
}

/// The band of `video`'s frames (`vision::band::find` on its first frames, read
/// from `frames` and kept: the first [`vision::band::LEAST_SPAN`] + 1, else as many
/// as `fps` asks, [`vision::band::first_frames`]), and the frames to track: whole
/// when there is none; a video's band decoded anew by ffmpeg, cut, when only tracks
/// are wanted (`anew`: `frames` decoded, not kept ones, and no pictures made;
/// `frames` ended unread); else `frames` to be cut as they are read.
fn framed(
    video: &std::path::Path,
    info: &Info,
    mut frames: super::Frames,
    (params, fps): (&vision::Params, f64),
    anew: Option<Pictures>,
) -> Result<Framed, VideoError> {
    let mut head = Vec::new();
    // The fewest first frames first: where they show the line (a clip at 60
    // frames/s and below, a slow clip, the balls apart from the background
    // already), no more of them are read whole before the band's own decoding
    // starts again from the first (the bench's clip read 37 whole frames at 240
    // frames/s for a band the first 13 gave). Else the span `fps` asks.
    let mut band = None;
    // The frames ran out (a clip shorter than the span): never asked again.
    let mut ended = false;
    for wanted in [
        vision::band::LEAST_SPAN + 1,
        vision::band::first_frames(fps),
    ] {
        // No new frames (a rate whose span is the 13 already read): nothing to
        // look at again.
        if band.is_some()
            || ended
            || head.len() >= wanted
            || head.last().is_some_and(Result::is_err)
        {
            break;
        }
        while head.len() < wanted {
            let Some(frame) = frames.next() else {
                ended = true;
                break;
            };
            let bad = frame.is_err();
            head.push(frame);
            if bad {
                break;
            }
        }
        let first: Vec<&vision::Frame> = head
            .iter()
            .filter_map(|f| f.as_ref().ok().map(|(_, img)| img))
            .collect();
        band = (first.len() == wanted)
            .then(|| vision::band::find(&first, params))
            .flatten();
    }
    if let Some(b) = band
        && video.is_file()
        && anew == Some(Pictures::Skipped)
    {
        drop(frames);
        return Ok(Framed {
            frames: super::open_band(video, info, &b)?,
            band: Some(b),
            cut: false,
        });
    }
    Ok(Framed {
        frames: Box::new(head.into_iter().chain(frames)),
        band,
        cut: band.is_some(),
    })
}

/// What of `--ball-at` and `--roi` lies off the frames of `size` px, or the point
/// outside the rectangle (checked before a frame is decoded: either would only have
/// the tracker refuse later, or ignore the seed, for a reason it does not name).
fn off_the_frame(options: &Options, size: (usize, usize)) -> Option<VideoProblem> {
    let (w, h) = (size.0 as f64, size.1 as f64);
    if let Some(at) = options.ball_at
        && !(at.0 >= 0.0 && at.0 < w && at.1 >= 0.0 && at.1 < h)
    {
        return Some(VideoProblem::BallAtOutside { at, size });
    }
    if let Some(r) = options.roi
        && !(r.x < w && r.y < h && r.x + r.width > 0.0 && r.y + r.height > 0.0)
    {
        return Some(VideoProblem::RoiOutside {
            roi: (r.x, r.y, r.width, r.height),
            size,
        });
    }
    if let (Some(at), Some(r)) = (options.ball_at, options.roi)
        && !r.contains(at.0, at.1)
    {
        return Some(VideoProblem::BallAtOutsideRoi {
            at,
            roi: (r.x, r.y, r.width, r.height),
        });
    }
    None
}

/// A clip streamed through the tracker ([`stream`]).
struct Streamed {
    tracker: Tracker,
    /// Each frame's number.
    numbers: Vec<u64>,
    /// The app's small pictures.
    thumbs: Thumbs,
    /// The frames read, each with its number, where they were to be kept and fit in
    /// [`KEEP_BYTES`].
    frames: Option<Numbered>,
}

/// The frames streamed through the tracker, read on a thread of their own, and
/// kept where `keep` asks and they fit ([`Streamed`]); `None` when `progress`
/// asked to stop.
fn stream(
    framed: Framed,
    info: &Info,
    params: &vision::Params,
    progress: &dyn Progress,
    (pictures, keep): (Pictures, bool),
) -> Result<Option<Streamed>, VideoError> {
    let Framed { frames, band, cut } = framed;
    let params = band.map_or(*params, |b| b.params(params));
    let mut tracker = Tracker::new(params);
    // One pass, one decode: each frame is learned (reduced) into the background as
    // it comes, and tracked only once `ahead` frames more have been learned, so the
    // background it is tracked against has seen the balls move on. A clip that fits
    // in the look-ahead (most clips) is learned whole before its first frame is
    // tracked, as if read twice.
    // As many frames ahead as of the whole frame, a band or not: which frames the
    // background has learned when a frame is tracked is the tracks' business, not
    // the band's (more, and the speed clip's tracks changed). The reader may run
    // ahead by bytes: more of a band's frames.
    let ahead = lookahead(info.width, info.height);
    let rows = band.map_or(info.height, |b| b.height);
    let total = info.frames.max(1);
    let mut thumbs = Thumbs::sized(info.width, info.height, info.frames);
    let no_thumbs = thumbs.clone();
    // The frames are read (piped from ffmpeg, or decoded from a folder) on a thread
    // of their own, a few ahead, while this one tracks: reading a 1080p frame is a
    // copy of 3 MB. Dropping the receiver (an error, Ctrl-C) ends the reader at its
    // next frame, and the decoder with it. The app's small pictures are made there
    // too (each frame's box averages, in the frames' order: what the tracker is
    // given), off the tracker's thread; and so is each frame's own part of the
    // tracker's look (`PreparedLook`: reduced once for the learner and the look).
    let (sender, received) = std::sync::mpsc::sync_channel(read_ahead(info.width, rows));
    let reader = std::thread::spawn(move || {
        let mut k = 0usize;
        for frame in frames {
            if let (Ok((_, img)), Pictures::Made) = (&frame, pictures) {
                thumbs.push(k, &img.luma);
                k += 1;
            }
            let frame = frame.map(|(n, img)| {
                // The band's rows, for the tracker; the whole frame's pictures made.
                let img = match band.filter(|_| cut) {
                    Some(b) => {
                        let part = b.cut(&img);
                        super::decode::recycle(img);
                        part
                    }
                    None => img,
                };
                let mut prep = PreparedLook::of(&img, &params);
                // The whole frame's pixel noise, not the band's own sample's.
                if let Some(b) = band {
                    prep.noise = b.noise;
                }
                (n, img, prep)
            });
            if sender.send(frame).is_err() {
                break;
            }
        }
        thumbs
    });
    let mut keeping = keep.then(|| Keeping::within(KEEP_BYTES));
    let told = Told {
        ahead,
        total,
        progress,
    };
    let Some(numbers) = learn_and_track(&mut tracker, received, told, keeping.as_mut())? else {
        return Ok(None);
    };
    // The reader is done (the frames ran out); a reader that panicked leaves no
    // pictures, the tracks stand.
    let thumbs = reader.join().unwrap_or(no_thumbs);
    Ok(Some(Streamed {
        tracker,
        numbers,
        thumbs,
        frames: keeping.and_then(Keeping::kept),
    }))
}

/// How far the background learns ahead of the tracker, and whom to tell of how many
/// frames ([`learn_and_track`]).
struct Told<'a> {
    ahead: usize,
    total: u64,
    progress: &'a dyn Progress,
}

/// Each frame of `received` learned into `tracker`'s background as it comes, and
/// tracked once `ahead` frames more have been learned (see [`stream`]), telling
/// `progress` of `total` frames, and given to `keeping` once tracked; the frames'
/// numbers, or `None` asked to stop.
fn learn_and_track(
    tracker: &mut Tracker,
    received: std::sync::mpsc::Receiver<Result<(u64, vision::Frame, PreparedLook), VideoError>>,
    told: Told<'_>,
    mut keeping: Option<&mut Keeping>,
) -> Result<Option<Vec<u64>>, VideoError> {
    let Told {
        ahead,
        total,
        progress,
    } = told;
    let mut numbers = Vec::new();
    let mut waiting: std::collections::VecDeque<(u64, vision::Frame, PreparedLook)> =
        Default::default();
    let mut done = |n: u64, img: vision::Frame| match keeping.as_deref_mut() {
        Some(k) => k.keep(n, img),
        None => super::decode::recycle(img),
    };
    // The work is each frame read (and learned) and each frame tracked: most clips
    // are read whole before their first frame is tracked, and a count of frames
    // read stood at 100 % for the longer half of the work.
    let mut tracked = 0u64;
    let tell = |seen: u64, tracked: u64| {
        let whole = total.max(seen);
        progress.tick(seen + tracked, 2 * whole);
    };
    for frame in received {
        if progress.cancelled() {
            return Ok(None);
        }
        let (n, img, prep) = frame?;
        tracker.learn_prepared(&img, &prep);
        numbers.push(n);
        waiting.push_back((n, img, prep));
        if waiting.len() > ahead
            && let Some((n, first, prep)) = waiting.pop_front()
        {
            tracker.push_prepared(&first, prep);
            done(n, first);
            tracked += 1;
        }
        tell(numbers.len() as u64, tracked);
    }
    for (n, img, prep) in waiting {
        if progress.cancelled() {
            return Ok(None);
        }
        tracker.push_prepared(&img, prep);
        done(n, img);
        tracked += 1;
        tell(numbers.len() as u64, tracked);
    }
    Ok(Some(numbers))
}

/// Most bytes of a clip's frames kept for its further trackings ([`KeptFrames`]): 256 MiB
/// (82 frames of 1080p, 420 of 480p). A longer clip is decoded again for each.
const KEEP_BYTES: usize = 256 << 20;

/// A clip's frames kept as a tracking of its whole frames read them, for the
/// clip's further trackings (a refusal tracked again, a band refused tracked as the
/// whole frame): read from memory, not decoded by ffmpeg (or from a folder's files)
/// once more. The same frames, so the same tracks.
#[derive(Default)]
struct KeptFrames(std::cell::RefCell<Option<std::sync::Arc<Numbered>>>);

/// Frames, each with its number in the clip.
type Numbered = Vec<(u64, vision::Frame)>;

impl KeptFrames {
    /// The kept frames, each a copy (a tracking cuts and recycles its own), in order;
    /// `None` when none were kept.
    fn frames(&self) -> Option<super::Frames> {
        let kept = self.0.borrow().clone()?;
        let copies =
            (0..kept.len()).filter_map(move |i| kept.get(i).map(|(n, f)| Ok((*n, f.clone()))));
        Some(Box::new(copies))
    }

    /// Keeps `frames`, where there are any.
    fn set(&self, frames: Option<Numbered>) {
        if let Some(frames) = frames {
            *self.0.borrow_mut() = Some(std::sync::Arc::new(frames));
        }
    }
}

/// Frames being kept as they are tracked, while they fit in `budget` bytes.
struct Keeping {
    frames: Numbered,
    bytes: usize,
    budget: usize,
    /// More came than fit: none are kept.
    over: bool,
}

impl Keeping {
    fn within(budget: usize) -> Keeping {
        Keeping {
            frames: Vec::new(),
            bytes: 0,
            budget,
            over: false,
        }
    }

    fn keep(&mut self, n: u64, frame: vision::Frame) {
        let bytes = frame.luma.data.len() + frame.u.len() + frame.v.len();
        if self.over || self.bytes + bytes > self.budget {
            self.over = true;
            for (_, f) in self.frames.drain(..) {
                super::decode::recycle(f);
            }
            super::decode::recycle(frame);
            return;
        }
        self.bytes += bytes;
        self.frames.push((n, frame));
    }

    /// The frames kept, `None` where they did not fit.
    fn kept(self) -> Option<Numbered> {
        (!self.over).then_some(self.frames)
    }
}

/// Each frame's fits as the tracker made them, before the tracks' checks.
fn found(tracker: &Tracker) -> FitsFound {
    tracker
        .frames
        .iter()
        .map(|f| {
            f.iter()
                .map(|fix| {
                    let fix = fix.as_ref().ok()?;
                    let c = fix.outline.circle;
                    Some(overlay::Drawn {
                        centre: (c.x, c.y),
                        radius: c.r,
                        mark: fix.mark.map(|m| (m.x, m.y)),
                    })
                })
                .collect()
        })
        .collect()
}

/// Most bytes of frames the reader may decode ahead of the tracker (on top of its
/// look-ahead): 64 MiB (21 frames of 1080p). Room for ffmpeg and the reader to go
/// on while the tracker is busy with one frame or a new background (some 0.1 s of
/// 1080p): four frames' room left the other core idle for most of it.
const READ_BYTES: usize = 64 << 20;

/// Frames of `width × height` the reader may decode ahead: [`READ_BYTES`] of
/// them, at least 4.
fn read_ahead(width: usize, height: usize) -> usize {
    (READ_BYTES / vision::Frame::bytes(width, height).max(1)).max(4)
}

/// Most bytes of decoded frames held at once while the background learns ahead of
/// the tracker: 256 MiB (82 frames of 1080p, 185 of 720p, 420 of 480p).
const AHEAD_BYTES: usize = 256 << 20;

/// How many frames of `width × height` the background learns ahead of the tracker:
/// what fits in [`AHEAD_BYTES`], at least 16.
fn lookahead(width: usize, height: usize) -> usize {
    (AHEAD_BYTES / vision::Frame::bytes(width, height).max(1)).max(16)
}

/// A tracking refused: why, what the tracker found (each frame's fits, unchecked)
/// and, with pictures made, the first frame with them drawn over it.
fn refused(
    tracker: &Tracker,
    thumbs: Thumbs,
    pictures: Pictures,
    error: VideoError,
) -> Box<Refused> {
    let found = found(tracker);
    let first_frame = (pictures == Pictures::Made).then(|| {
        let first: Vec<_> = found
            .first()
            .into_iter()
            .flatten()
            .flatten()
            .copied()
            .collect();
        VideoView::first_frame(thumbs, &first, error.what.to_string())
    });
    Box::new(Refused {
        error,
        found,
        first_frame,
    })
}

/// What became of a `--ball-at` seed where the tracks would not show it: no ball's
/// outline found about the point (`seeded` false), or one found but not among the
/// tracks (one ball tracked, the seed on the other side of it by more than a ball:
/// balls in one groove never pass each other). A seed given is never passed over in
/// silence.
fn seed_note(at: Option<(f64, f64)>, seeded: bool, tracks: &Tracks) -> Option<String> {
    let (x, y) = at?;
    // The point as the refusals say it (`next_try`).
    let point = format!("--ball-at {x},{y}");
    if !seeded {
        return Some(format!(
            "{point}: no ball's outline was found about that point, so the seed was not used (these are the balls found by themselves); give a point inside a ball in the first frame"
        ));
    }
    let [ball] = tracks.balls.as_slice() else {
        return None;
    };
    let c = &tracks.calibration;
    let a = c.groove_deg.to_radians();
    let along = ((x - c.origin_px.0) * a.cos() + (y - c.origin_px.1) * a.sin()) / c.px_per_m;
    let first = ball.x.iter().copied().find(|v| v.is_finite())?;
    let beyond = 2.0 * c.radius_m;
    let other = match ball.name {
        "right" => along < first - beyond,
        _ => along > first + beyond,
    };
    other.then(|| {
        format!(
            "{point}: the ball found there was not followed in enough frames to be tracked; these are the {} ball's tracks alone",
            ball.name
        )
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
    n.push(scale_note(c, radius_from));
    n.push(if c.groove_found {
        let (v, e) = with_uncertainty(c.groove_deg, c.groove_deg_sigma.max(1e-9), 2);
        format!("groove at {v} ± {e}° in the picture (found from the paths; + is the right end lower): the tracks are turned to it")
    } else {
        "groove direction not found (the paths are too short): taken as level in the picture".into()
    });
    if let [b] = tracks.balls.as_slice() {
        n.push(format!(
            "one ball tracked: the {} ball (it moves {} at first); the other was not found in enough frames (out of view, or not told from the wall)",
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
        "x along the groove toward the right, y up, in metres (position scatter ≈ {} frame to frame, as `fit` measures it; the outline fits' own ± {}); each centre set on its ball's line across the groove (the median of its frames'); t in s from the first frame",
        frame_to_frame(tracks),
        show_small(fits_own(tracks), Dimension::Length)
    ));
    n
}

/// The tracks' line on their scale: given (`--scale`), and then whether the radii
/// scatter as they would refuse a scale (the outlines in doubt, which a given scale
/// does not mend); else from the fitted radius, with its ±.
pub fn scale_note(c: &vision::tracks::Calibration, radius_from: &str) -> String {
    if c.scale_given {
        // Radii that would refuse a scale: the outlines, and the centres fitted with
        // them, are in doubt, which the given scale does not mend.
        let doubt = if c.radius_scatter > vision::Params::default().max_radius_spread {
            format!(
                "; the balls' fitted radii scatter by {:.0} % about {:.1} px (both balls have one radius): their outlines, and the centres fitted with them, are in doubt in many frames; check them (--overlay) before trusting μ_k",
                100.0 * c.radius_scatter,
                c.radius_px
            )
        } else {
            String::new()
        };
        format!(
            "scale {} px/m: given (--scale {} a pixel){doubt}{}",
            crate::settings::units::significant(c.px_per_m, 6),
            show_small(1.0 / c.px_per_m, Dimension::Length),
            radius_contradicts(c, radius_from).unwrap_or_default()
        )
    } else {
        let (v, e) = with_uncertainty(c.px_per_m, c.px_per_m_sigma.max(1e-9), 2);
        let (rv, re) = with_uncertainty(c.radius_px, c.radius_px_sigma.max(1e-9), 2);
        // Why the ± is wide where the outlines' edge in colour lies far off them.
        let colour = c.colour_edge_px.map_or(String::new(), |off| {
            format!(
                " (their edge in colour lies {:.1} px inside their outlines in brightness, {:.0} % of the radius, and the balls' stacked pictures, the wall behind them averaged out, agree with the outlines: the colour fades before the ball's edge, a shaded or glossy limb; the ± holds the difference)",
                off.abs(),
                100.0 * off.abs() / c.radius_px
            )
        });
        format!(
            "scale {v} ± {e} px/m (± 1σ, as the radius's): the balls' fitted radius {rv} ± {re} px for R = {} ({radius_from}){colour}; speeds and μ_k from these tracks carry its {:.2} %, which `fit` adds to their own ± (and doubles in its ± 2σ)",
            show(c.radius_m, Dimension::Length),
            100.0 * c.px_per_m_sigma / c.px_per_m
        )
    }
}

/// Where a given scale puts the balls' fitted radius more than
/// [`GIVEN_SCALE_AGREES`] off R: the words that say so (either is off, or the
/// outlines are); `None` where they agree or no radius was fitted.
fn radius_contradicts(c: &vision::tracks::Calibration, radius_from: &str) -> Option<String> {
    let at_scale = c.radius_px / c.px_per_m;
    let off = at_scale / c.radius_m - 1.0;
    (off.is_finite() && off.abs() > GIVEN_SCALE_AGREES).then(|| {
        format!(
            "; {SCALE_OFF_R} the balls' fitted radius {:.1} px is {}, {:.0} % {} R = {} ({radius_from}): the scale, R or the outlines are off (check the outlines with --overlay)",
            c.radius_px,
            show(at_scale, Dimension::Length),
            100.0 * off.abs(),
            if off > 0.0 { "over" } else { "under" },
            show(c.radius_m, Dimension::Length),
        )
    })
}

/// The words that start the scale line's clause on a given scale that puts the
/// fitted radius off R (`data` quotes the clause from a tracks file).
pub const SCALE_OFF_R: &str = "at this scale";

/// How far a given scale may put the fitted radius from R, a share of R, before the
/// note says they disagree: twice the radii's spread that refuses a scale
/// (`Params::max_radius_spread`), which a given scale is often the answer to.
const GIVEN_SCALE_AGREES: f64 = 0.10;

/// Each ball's position scatter frame to frame along the groove, as `fit` and `data`
/// measure a track's (its centres' third differences): "0.51 mm (left), 0.40 mm
/// (right)", or one ball's alone. The outline fits' own ± leaves out what their
/// neighbouring pixels share (a blurred or ghosted edge), so it understates how far
/// the centres stray: quoted alone it read 0.04 mm where `fit` then found 0.14.
fn frame_to_frame(tracks: &Tracks) -> String {
    let each: Vec<String> = tracks
        .balls
        .iter()
        .map(|b| {
            let (ts, xs): (Vec<f64>, Vec<f64>) = tracks
                .t
                .iter()
                .zip(&b.x)
                .filter(|(t, x)| t.is_finite() && x.is_finite())
                .map(|(&t, &x)| (t, x))
                .unzip();
            let s = show_small(track_scatter(&ts, &xs), Dimension::Length);
            format!("{s} ({})", b.name)
        })
        .collect();
    each.join(", ")
}

/// The median of the centres' standard errors from their outline fits, m.
fn fits_own(tracks: &Tracks) -> f64 {
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
    let tracked = frames - b.unseen - b.merged - b.poor - b.repeated;
    let mut out: Vec<String> = Vec::new();
    for (n, why) in [
        (b.unseen, "not seen"),
        (b.merged, "touching the other ball"),
        (b.poor, "outline blurred or too little of it visible"),
        (b.repeated, "repeating another frame's picture"),
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
    let unfound = b.mark_missing.saturating_sub(b.mark_left_out);
    let mut marks = Vec::new();
    if unfound > 0 {
        marks.push(format!(
            "{unfound} not found: hidden by the rail, turned away, or too near the ball's edge or the rail"
        ));
    }
    if b.mark_left_out > 0 {
        marks.push(format!(
            "{} found but left out: not turning with the ball",
            b.mark_left_out
        ));
    }
    let marks = if marks.is_empty() {
        String::new()
    } else {
        format!(" ({})", marks.join("; "))
    };
    format!(
        "{} ball: centre in {tracked} of {frames} frames{left_out}; mark in {}{marks}",
        b.name,
        tracked - b.mark_missing,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball's line says how many marks were never found and how many were found
    /// and left out by the marks' checks, each only where there are some.
    #[test]
    fn a_balls_line_tells_marks_not_found_from_marks_left_out() {
        let ball = |missing: usize, left_out: usize| BallTrack {
            name: "left",
            merged: 1,
            mark_missing: missing,
            mark_left_out: left_out,
            ..BallTrack::default()
        };
        let line = ball_line(&ball(27, 5), 50);
        assert_eq!(
            line,
            "left ball: centre in 49 of 50 frames (left out, not filled in: 1 touching the other ball); mark in 22 (22 not found: hidden by the rail, turned away, or too near the ball's edge or the rail; 5 found but left out: not turning with the ball)"
        );
        assert!(
            ball_line(&ball(3, 3), 50)
                .ends_with("mark in 46 (3 found but left out: not turning with the ball)")
        );
        assert!(ball_line(&ball(0, 0), 50).ends_with("mark in 49"));
    }

    /// Frames are kept while they fit (then given back, in their order, each a copy),
    /// and none once one more would not: a clip is kept whole or not at all.
    #[test]
    fn frames_are_kept_whole_within_their_budget_or_not_at_all() {
        let frame = |level: u8| vision::Frame::from_yuv420p(4, 2, vec![level; 12]).unwrap();
        let budget = 3 * vision::Frame::bytes(4, 2);
        let mut fits = Keeping::within(budget);
        for n in 0..3 {
            fits.keep(n, frame(n as u8));
        }
        let kept = KeptFrames::default();
        kept.set(fits.kept());
        for _ in 0..2 {
            let again: Vec<(u64, vision::Frame)> =
                kept.frames().unwrap().map(Result::unwrap).collect();
            assert_eq!(
                again,
                (0..3).map(|n| (n, frame(n as u8))).collect::<Vec<_>>()
            );
        }
        let mut over = Keeping::within(budget);
        for n in 0..4 {
            over.keep(n, frame(n as u8));
        }
        assert!(over.kept().is_none());
        let none = KeptFrames::default();
        none.set(None);
        assert!(none.frames().is_none());
    }
    use crate::vision::TracksError;

    fn refused(error: TracksError) -> Box<Refused> {
        Box::new(Refused {
            error: VideoError::new(
                std::path::Path::new("clip.mp4"),
                VideoProblem::Tracks {
                    error,
                    roi: false,
                    scale: false,
                    at: None,
                },
            ),
            found: Vec::new(),
            first_frame: None,
        })
    }

    fn said(r: &Refused) -> String {
        r.error.what.to_string()
    }

    fn refusal(r: Result<Option<Tracked>, Box<Refused>>) -> Box<Refused> {
        match r {
            Err(refused) => refused,
            Ok(_) => panic!("tracks from a refusal"),
        }
    }

    /// A second tracking refused again leaves the first refusal standing, but where it
    /// found the balls' line up the picture: a clip shown turned, in which the first
    /// tracking (a line across assumed) found no ball, is refused for its turn.
    #[test]
    fn a_line_up_the_picture_found_the_second_time_is_the_refusal_given() {
        let first = || {
            refused(TracksError::NoBall {
                frames: 25,
                min_radius: 8.0,
            })
        };
        let steep = || refused(TracksError::Steep { groove_deg: -87.8 });
        let given = refusal(retried(Err(steep()), first(), String::new()));
        assert_eq!(said(&given), said(&steep()));
        assert!(said(&given).contains("88° from across"), "{}", said(&given));
        let sparse = refused(TracksError::Sparse {
            seen: 4,
            frames: 25,
        });
        let given = refusal(retried(Err(sparse), first(), String::new()));
        assert_eq!(said(&given), said(&first()));
    }
}
