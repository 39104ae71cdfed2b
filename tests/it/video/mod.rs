//! Videos: tracking balls against truth, random looks, the overlay, and a video given
//! as `--data` everywhere.

pub(crate) mod app;
pub(crate) mod ball_parts;
mod band;
mod black_ball;
mod cast_shadow;
mod colour_edge;
mod colour_settled;
mod coloured_ball;
mod difference;
mod edge_lean;
mod first_locks;
mod follow_gap;
mod follow_once;
pub(crate) mod found_frames;
mod given_scale;
pub(crate) mod impact_follow;
mod inner_lock;
pub(crate) mod looks;
mod mark_highlight;
mod mark_model;
mod mark_place;
mod marks_crowded;
mod marks_ghost;
mod marks_sign;
mod marks_stay;
mod marks_turn;
mod marks_twice;
mod off_the_curve;
mod outer_lock;
pub(crate) mod overlay;
mod ragged_fringe;
mod rail_view;
mod repeated_frames;
pub(crate) mod seed;
mod sharp_arc;
mod stacked;
mod steep;
mod sunk_balls;
mod timestamps;
pub(crate) mod tracker_looks;
pub(crate) mod tracking;
mod unfit;
mod wall_brightness;

/// The random look `seed` of `size` (the looks table's, on the paper's scene) written
/// as its H.264 copy `clip.mp4` into the scratch folder `area`/`size_seed`: the clip
/// and the file (`None` without ffmpeg).
pub(crate) fn h264_look(
    area: &str,
    seed: u64,
    size: crate::film::looks::Size,
) -> Option<(crate::film::looks::Clip, std::path::PathBuf)> {
    h264_first(area, seed, size, None)
}

/// As [`h264_look`], with only the look's `first` frames where given (a test of first
/// locks needs no more, and a clip's frames cost seconds to draw and encode).
pub(crate) fn h264_first(
    area: &str,
    seed: u64,
    size: crate::film::looks::Size,
    first: Option<usize>,
) -> Option<(crate::film::looks::Clip, std::path::PathBuf)> {
    if !tracking::ffmpeg() {
        return None;
    }
    let clip = crate::film::looks::random(&crate::common::paper_scene(), seed, size);
    let (name, frames) = match first {
        Some(n) => (format!("{size:?}_{seed}_first_{n}"), n.min(clip.frames)),
        None => (format!("{size:?}_{seed}"), clip.frames),
    };
    let path = crate::common::scratch_dir(area, &name).join("clip.mp4");
    crate::film::h264::write(&path, &clip.film, frames).unwrap();
    Some((clip, path))
}

/// Checks that the look `seed` of `size` (its `first` frames where given), refused
/// before, is tracked as the command line tracks it (its band first) to a scale
/// within 2 of its ± and `share` of the truth, with a note starting `note` saying how
/// (nothing is checked without ffmpeg).
pub(crate) fn assert_tracked_to_its_scale(
    area: &str,
    look: (u64, crate::film::looks::Size, Option<usize>),
    share: f64,
    note: &str,
) {
    let Some((clip, t)) = tracked_as_the_command_line(area, look) else {
        return;
    };
    assert_scale_within(&clip, &t, 2.0, share);
    assert!(t.notes.iter().any(|n| n.starts_with(note)), "{:?}", t.notes);
}

/// Checks that the scale `t` gives for `clip` lies within `sigmas` of its ± and
/// `share` of the truth.
pub(crate) fn assert_scale_within(
    clip: &crate::film::looks::Clip,
    t: &groovelab::input::video::tracked::Tracked,
    sigmas: f64,
    share: f64,
) {
    let c = &t.tracks.calibration;
    let truth = clip.film.px_per_m();
    let off = c.px_per_m - truth;
    assert!(
        off.abs() <= sigmas * c.px_per_m_sigma && off.abs() < share * truth,
        "scale {:.1} ± {:.1} px/m for {truth:.1}",
        c.px_per_m,
        c.px_per_m_sigma
    );
}

/// The look `seed` of `size` (its `first` frames where given) as H.264 in `area`,
/// tracked as the command line tracks it (its band first, tracked again where
/// refused); panics where it is refused; `None` without ffmpeg.
pub(crate) fn tracked_as_the_command_line(
    area: &str,
    (seed, size, first): (u64, crate::film::looks::Size, Option<usize>),
) -> Option<(
    crate::film::looks::Clip,
    groovelab::input::video::tracked::Tracked,
)> {
    use groovelab::input::video::tracked::{self, Framing, Pictures};
    let (clip, path) = h264_first(area, seed, size, first)?;
    let done = tracked::track_framed(
        &path,
        &look_options(&clip),
        &groovelab::study::Quiet,
        Pictures::Skipped,
        Framing::Band,
    );
    let Ok(Some(t)) = done else {
        panic!("refused: {:?}", done.err().map(|r| r.error.to_string()));
    };
    Some((clip, t))
}

/// The options a user tracks `clip` with: its R (`--radius`) and frame rate, nothing
/// else given.
pub(crate) fn look_options(
    clip: &crate::film::looks::Clip,
) -> groovelab::input::video::tracked::Options {
    groovelab::input::video::tracked::Options {
        radius: clip.film.scene.radius,
        fps: Some(clip.film.look.fps),
        px_per_m: None,
        radius_from: "--radius".into(),
        cache: None,
        roi: None,
        ball_at: None,
    }
}

/// As [`h264_look`], the copy decoded: the clip and its frames.
pub(crate) fn decoded_look(
    area: &str,
    seed: u64,
    size: crate::film::looks::Size,
) -> Option<(crate::film::looks::Clip, Vec<groovelab::vision::Frame>)> {
    h264_first(area, seed, size, None).map(decoded)
}

/// As [`decoded_look`], the look's first `first` frames only.
pub(crate) fn decoded_first(
    area: &str,
    seed: u64,
    size: crate::film::looks::Size,
    first: usize,
) -> Option<(crate::film::looks::Clip, Vec<groovelab::vision::Frame>)> {
    h264_first(area, seed, size, Some(first)).map(decoded)
}

/// The clip's file decoded: the clip and its frames.
fn decoded(
    (clip, path): (crate::film::looks::Clip, std::path::PathBuf),
) -> (crate::film::looks::Clip, Vec<groovelab::vision::Frame>) {
    let limits = groovelab::input::video::Limits::default();
    let (_, frames) = groovelab::input::video::open(&path, &limits).unwrap();
    (clip, frames.map(|f| f.unwrap().1).collect())
}

/// The marks `tracker` keeps of `clip` once checked with `checks`
/// (`mark_check::checked`), each as its distance from the drawn mark (px), its frame
/// and its contrast.
pub(crate) fn marks_against_truth(
    clip: &crate::film::looks::Clip,
    tracker: &groovelab::vision::Tracker,
    checks: &groovelab::vision::params::MarkChecks,
) -> Vec<(f64, usize, f64)> {
    use groovelab::vision::{mark_check, tracks};
    let ordered = tracks::ordered(&tracker.frames);
    let mut kept = Vec::new();
    for (k, fixes) in mark_check::checked(&ordered, checks).iter().enumerate() {
        for fix in fixes.iter().flatten() {
            let Some(m) = fix.mark else { continue };
            let c = fix.outline.circle;
            let t = clip.film.ball_nearest(k, (c.x, c.y));
            kept.push(((m.x - t.mark.0).hypot(m.y - t.mark.1), k, m.contrast));
        }
    }
    kept
}

/// What `vision::tracks` of `clip` is given and held against besides its tracker:
/// R (the paper scene's, m), the true scale (px/m) and the times of its first
/// `frames` frames (s, at its rate).
pub(crate) fn look_truth(clip: &crate::film::looks::Clip, frames: usize) -> (f64, f64, Vec<f64>) {
    let times = (0..frames).map(|k| k as f64 / clip.film.look.fps).collect();
    (
        crate::common::paper_scene().radius,
        clip.film.px_per_m(),
        times,
    )
}

/// The look `seed` of `size` (its `first` frames where given, decoded as
/// [`decoded_first`] in `area`), tracked with the default parameters, has its scale
/// within 2 of its ± of the truth; tracked with `without` (a rule switched off), it
/// is refused: the rule is what tracks it.
pub(crate) fn scaled_with_refused_without(
    area: &str,
    look: (u64, crate::film::looks::Size, Option<usize>),
    without: groovelab::vision::Params,
) {
    if let Some(refused) = scaled_with(area, look, without) {
        assert!(refused, "look {} without the rule: tracked", look.0);
    }
}

/// As [`scaled_with_refused_without`] for each of `looks`, of which at least one is
/// refused without the rule (not all: which look needs the rule can turn on the
/// machine's encoder, its pictures a level apart here and there).
pub(crate) fn scaled_with_one_refused_without(
    area: &str,
    looks: &[(u64, crate::film::looks::Size, Option<usize>)],
    without: groovelab::vision::Params,
) {
    let refused: Option<Vec<bool>> = looks
        .iter()
        .map(|&look| scaled_with(area, look, without))
        .collect();
    let Some(refused) = refused else { return };
    assert!(
        refused.contains(&true),
        "looks {:?} without the rule: all tracked",
        looks.iter().map(|l| l.0).collect::<Vec<_>>()
    );
}

/// The look `seed` of `size` tracked with the default parameters has its scale
/// within 2 of its ± of the truth (asserted); whether it is refused with `without`;
/// `None` without ffmpeg.
fn scaled_with(
    area: &str,
    (seed, size, first): (u64, crate::film::looks::Size, Option<usize>),
    without: groovelab::vision::Params,
) -> Option<bool> {
    use groovelab::vision;
    let (clip, frames) = h264_first(area, seed, size, first).map(decoded)?;
    let (r, truth, times) = look_truth(&clip, frames.len());
    let with = vision::track(&frames, vision::Params::default());
    let tracks = vision::tracks(&with, times.clone(), r, None).unwrap();
    let c = tracks.calibration;
    assert!(
        (c.px_per_m - truth).abs() <= 2.0 * c.px_per_m_sigma,
        "look {seed}: scale {:.1} ± {:.1} px/m for {truth:.1}",
        c.px_per_m,
        c.px_per_m_sigma
    );
    let refused = vision::tracks(&vision::track(&frames, without), times, r, None);
    Some(refused.is_err())
}

/// How much of the pixel drawn at `(px, py)` a disc of radius `r` about `c` covers
/// (0 … 1): the drawn cases' anti-aliasing, over about one pixel of the outline.
pub(crate) fn disc_cover((px, py): (f64, f64), c: (f64, f64), r: f64) -> f64 {
    (0.5 - ((px - c.0).hypot(py - c.1) - r)).clamp(0.0, 1.0)
}

/// A frame `w × h` drawn pixel by pixel for the tracker's drawn cases: `colour(x, y)`
/// (0–255 a channel) plus seeded noise of ±`spread` whole levels, the same on the three
/// channels (so a flat wall has a scatter): `seed`'s xorshift, one step a pixel in
/// row order.
pub(crate) fn drawn_frame(
    (w, h): (u32, u32),
    mut seed: u64,
    spread: u64,
    mut colour: impl FnMut(u32, u32) -> [f64; 3],
) -> groovelab::vision::Frame {
    let mut img = image::RgbImage::new(w, h);
    for y in 0..h {
        for x in 0..w {
            let c = colour(x, y);
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let n = (seed % (2 * spread + 1)) as f64;
            let level = |v: f64| (v + n - spread as f64).round().clamp(0.0, 255.0) as u8;
            img.put_pixel(x, y, image::Rgb(c.map(level)));
        }
    }
    groovelab::vision::Frame::from_rgb(&img)
}

/// A grey picture `w × h` of the scene `level(x, y)` (levels at a point, px): each
/// pixel the mean of 4 × 4 samples over it (edges anti-aliased, as a camera's; pixel
/// `(x, y)` is centred on the point `(x, y)`, as the tracker and the films' renderer
/// take it) plus a fixed pattern of ±2 levels of noise.
pub(crate) fn supersampled(
    (w, h): (usize, usize),
    level: impl Fn(f64, f64) -> f64,
) -> groovelab::vision::gray::Gray {
    let mut img = groovelab::vision::gray::Gray::filled(w, h, 0);
    for y in 0..h {
        for x in 0..w {
            let mut sum = 0.0;
            for sy in 0..4 {
                for sx in 0..4 {
                    sum += level(
                        x as f64 + (sx as f64 + 0.5) / 4.0 - 0.5,
                        y as f64 + (sy as f64 + 0.5) / 4.0 - 0.5,
                    );
                }
            }
            let noise = (((x * 7 + y * 13) % 5) as f64) - 2.0;
            img.data[y * w + x] = (sum / 16.0 + noise).round().clamp(0.0, 255.0) as u8;
        }
    }
    img
}

/// A folder (in the scratch area `area`) of `count` frames of 64×48 px, all one grey
/// and no ball: PNGs, so no ffmpeg is needed.
pub(crate) fn blank_frames(area: &str, count: usize) -> std::path::PathBuf {
    let dir = crate::common::scratch_dir(area, "frames");
    let (w, h) = (64usize, 48usize);
    for k in 1..=count {
        let rgb = vec![90u8; w * h * 3];
        let p = dir.join(format!("frame{k:04}.png"));
        groovelab::input::video::write::png(&p, &rgb, w, h).unwrap();
    }
    dir
}
