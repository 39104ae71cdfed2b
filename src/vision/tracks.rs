//! From pixels to metres: the scale from the balls' fitted radius over all frames
//! and the known radius R (or given), the groove's direction from the balls' paths
//! (a straight line through every centre: a tilted phone turns it), and the tracks
//! turned to it, x along the groove toward the right ball, y up, in metres and
//! seconds; then written as a Tracker-style multi-track text file (which
//! `input::data` reads) or as JSON.

use serde::Serialize;

use super::tracker::{FrameFixes, LeftOut, Tracker, median};

/// Why tracked frames give no tracks.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TracksError {
    #[error(
        "no ball found in {frames} frames (a ball is a round blob contrasting with the background, at least {min_radius:.0} px in radius); {TRY}"
    )]
    NoBall { frames: usize, min_radius: f64 },
    #[error(
        "only {frames} frame{}, at least {need} needed: a ball is a blob seen in {need} frames or more",
        if *frames == 1 { "" } else { "s" }
    )]
    TooFewFrames { frames: usize, need: usize },
    #[error(
        "more than two balls in {crowded} of {frames} frames, expected the two colliding balls (or one); {TRY}"
    )]
    TooMany { crowded: usize, frames: usize },
    /// Neither ball found in a third of the frames.
    #[error(
        "tracking unsure: neither ball was found in a third of the frames (at most in {seen} of {frames}), so no tracks are given; {TRY}"
    )]
    Sparse { seen: usize, frames: usize },
    /// The fitted radii disagree: no scale is given from them.
    #[error(
        "tracking unsure: the balls' fitted radii scatter by {:.0} % about {median_px:.1} px (both balls have one radius), so no scale is given; {TRY}",
        100.0 * scatter
    )]
    RadiiDisagree { median_px: f64, scatter: f64 },
    /// A "ball" whose centre swings across the groove's line.
    #[error(
        "tracking unsure: the {name} ball's centre swings {across_px:.1} px (RMS) across the groove's line, {:.0} % of its radius (a ball rolls along it), so no tracks are given; {TRY}",
        100.0 * across_px / radius_px
    )]
    Swings {
        name: &'static str,
        across_px: f64,
        radius_px: f64,
    },
}

/// What to try when the tracker is unsure (every refusal says it).
const TRY: &str = "try --roi X,Y,W,H (pixels) around the groove, --ball-at X,Y on a ball in the first frame, or --scale LENGTH (a pixel's length)";

/// Largest scatter of the fitted radii (robust, a share of their median) that still
/// gives a scale: a sharp ball's radius scatters by under 1 %, a blurred one's by a
/// few; both balls have one radius.
const MAX_RADIUS_SPREAD: f64 = 0.05;

/// A ball must be found in at least one in this many frames for tracks to be given.
const SPARSEST: usize = 3;

/// Fewest frames a ball must be seen in to be one (not a passing blob).
const FEWEST_SEEN: usize = 3;

/// How uncertain the place of a ball's edge is, px, whatever the number of frames:
/// the gradient's peak sits up to ~0.05 px inside the outline where the ball's
/// shading rises steeply at its limb (the project's shaded renders: 0.02 px for a
/// flat ball, 0.06 px for a shaded one), and that carries into the radius and so
/// the scale.
pub const EDGE_SYSTEMATIC: f64 = 0.05;

/// How unsure the balls' edge is, px: the spread of the edge's place by its
/// definitions (the gradient's peak the fit uses, 0, and the half-way crossings of
/// `circle::edge_offsets`, each the median over the frames), at least
/// [`EDGE_SYSTEMATIC`]. Nothing tells which definition is right on a ball whose
/// shading runs into a limb of little contrast, so the whole spread is taken.
fn edge_systematic(offsets: &[[f64; 2]]) -> f64 {
    let at = |i: usize| {
        median(
            &offsets
                .iter()
                .filter_map(|o| o.get(i).copied())
                .collect::<Vec<_>>(),
        )
    };
    let (a, b) = (at(0).unwrap_or(0.0), at(1).unwrap_or(0.0));
    let spread = a.max(b).max(0.0) - a.min(b).min(0.0);
    spread.max(EDGE_SYSTEMATIC)
}

/// How far the two balls' median fitted radii differ, px (0 with one ball).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn between_balls(frames: &[FrameFixes], slots: &[usize]) -> f64 {
    let medians: Vec<f64> = slots
        .iter()
        .filter_map(|&s| {
            let r: Vec<f64> = frames
                .iter()
                .filter_map(|f| f[s].as_ref().ok())
                .map(|fix| fix.outline.circle.r)
                .collect();
            median(&r)
        })
        .collect();
    match medians.as_slice() {
        [a, b] => (a - b).abs(),
        _ => 0.0,
    }
}

/// How pixels become metres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Calibration {
    /// Pixels per metre, and its standard error.
    pub px_per_m: f64,
    pub px_per_m_sigma: f64,
    /// True when given (`--scale`), false when from the fitted radius.
    pub scale_given: bool,
    /// The balls' median fitted radius, px, and its standard error: the median's
    /// own and the edge's systematic (the larger of the edge's definitions' spread,
    /// the single frames' scatter, the two balls' difference, and [`EDGE_SYSTEMATIC`]).
    pub radius_px: f64,
    pub radius_px_sigma: f64,
    /// The radius R the scale comes from, m.
    pub radius_m: f64,
    /// The groove's direction in the picture, degrees (positive: turned clockwise,
    /// the right end lower), and its standard error; 0 when the paths are too short
    /// to tell (`groove_found` false).
    pub groove_deg: f64,
    pub groove_deg_sigma: f64,
    pub groove_found: bool,
    /// The picture's point that is x = y = 0 of the tracks (the mean of every
    /// centre), px: with the scale and the groove's angle it turns metres back into
    /// pixels (the app draws the model over the video). Not in the JSON.
    #[serde(skip)]
    pub origin_px: (f64, f64),
}

/// One ball's tracks, metres (NaN where left out).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BallTrack {
    /// "left" or "right".
    pub name: &'static str,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    /// Standard error of x and of y, m.
    pub sigma: Vec<f64>,
    pub mark_x: Vec<f64>,
    pub mark_y: Vec<f64>,
    pub mark_sigma: Vec<f64>,
    /// Frames left out: not seen, touching the other ball, poor outline.
    pub unseen: usize,
    pub merged: usize,
    pub poor: usize,
    /// Frames with the ball but not its mark (hidden by the rail, too near it, or left out by `mark_check`: not turning with the ball).
    pub mark_missing: usize,
}

/// Both balls' tracks (or one ball's), the times of the frames and the calibration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Tracks {
    pub t: Vec<f64>,
    pub balls: Vec<BallTrack>,
    pub calibration: Calibration,
}

/// The tracks of `tracker`'s frames, shown at `times` (s, one per frame), for balls
/// of radius `radius` (m); `scale` (px/m) overrides the scale from the radius.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1, the two slots' centres; the radii are never empty here (a ball was seen)
pub fn tracks(
    tracker: &Tracker,
    times: Vec<f64>,
    radius: f64,
    scale: Option<f64>,
) -> Result<Tracks, TracksError> {
    let p = &tracker.params;
    let mut frames = super::mark_check::checked(&ordered(&tracker.frames), &p.marks);
    if let Some(r) = median(tracker.radii()) {
        off_the_line(&mut frames, p.off_the_line * r);
    }
    let frames = &frames;
    let mut slots = balls_seen(tracker, frames)?;
    let centres: Vec<Vec<[f64; 2]>> = (0..2).map(|s| centres_of(frames, s)).collect();
    let (angle, angle_se, found) =
        groove(&slots.iter().map(|&s| &centres[s][..]).collect::<Vec<_>>());
    let (u, n) = ((angle.cos(), angle.sin()), (angle.sin(), -angle.cos()));
    let along = |p: &[f64; 2]| p[0] * u.0 + p[1] * u.1;
    let mean_along = |s: usize| centres[s].iter().map(along).sum::<f64>() / centres[s].len() as f64;
    slots.sort_by(|a, b| mean_along(*a).total_cmp(&mean_along(*b)));
    let radii = tracker.radii();
    let r_px = median(radii).unwrap_or(f64::NAN);
    let mut dev: Vec<f64> = radii.iter().map(|r| (r - r_px).abs()).collect();
    dev.sort_by(f64::total_cmp);
    let r_stat = 1.4826 * dev[dev.len() / 2] * 1.2533 / (radii.len() as f64).sqrt();
    // How unsure the edge is beyond the frames' mean: the edge's definitions
    // disagreeing, the single frames' radii scattering (a bias that the shading, a
    // blur or the wall puts into every frame alike does not average out over them:
    // the frames' scatter, not its standard error, bounds it), and the two balls'
    // radii differing (both have one radius).
    let frame_sd = 1.4826 * dev.get(dev.len() / 2).copied().unwrap_or(0.0);
    let systematic = edge_systematic(tracker.edge_offsets())
        .max(frame_sd)
        .max(between_balls(frames, &slots));
    let r_se = r_stat.hypot(systematic);
    // Never a confident wrong scale: radii that disagree are no ball's (the mark, a
    // highlight or clutter taken for one in part of the frames).
    let spread = 1.4826 * dev.get(dev.len() / 2).copied().unwrap_or(0.0) / r_px;
    if scale.is_none() && (spread.is_nan() || spread > MAX_RADIUS_SPREAD) {
        return Err(TracksError::RadiiDisagree {
            median_px: r_px,
            scatter: spread,
        });
    }
    let px_per_m = scale.unwrap_or(r_px / radius);
    // The origin: the mean of every centre, so y is about 0 along the groove.
    let all: Vec<&[f64; 2]> = slots.iter().flat_map(|&s| centres[s].iter()).collect();
    let o = (
        all.iter().map(|p| p[0]).sum::<f64>() / all.len() as f64,
        all.iter().map(|p| p[1]).sum::<f64>() / all.len() as f64,
    );
    let calibration = Calibration {
        px_per_m,
        px_per_m_sigma: if scale.is_some() { 0.0 } else { r_se / radius },
        scale_given: scale.is_some(),
        radius_px: r_px,
        radius_px_sigma: r_se,
        radius_m: radius,
        groove_deg: angle.to_degrees(),
        groove_deg_sigma: angle_se.to_degrees(),
        groove_found: found,
        origin_px: o,
    };
    let to_m = |x: f64, y: f64| {
        let (dx, dy) = (x - o.0, y - o.1);
        (
            (dx * u.0 + dy * u.1) / px_per_m,
            (dx * n.0 + dy * n.1) / px_per_m,
        )
    };
    let names = names_of(&slots, &centres, along);
    for (&s, &name) in slots.iter().zip(&names) {
        let across_px = across_rms(&centres[s], n);
        if across_px > tracker.params.max_across * r_px {
            return Err(TracksError::Swings {
                name,
                across_px,
                radius_px: r_px,
            });
        }
    }
    let balls = slots
        .iter()
        .zip(names)
        .map(|(&s, name)| ball_track(frames, s, name, &to_m, px_per_m))
        .collect();
    Ok(Tracks {
        t: times,
        balls,
        calibration,
    })
}

/// The slots that hold a ball (seen in enough frames), or why the frames give no
/// tracks: crowded, too few, no ball, or the balls found too rarely.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn balls_seen(tracker: &Tracker, frames: &[FrameFixes]) -> Result<Vec<usize>, TracksError> {
    let c = &tracker.counts;
    if c.crowded * 2 > c.frames {
        return Err(TracksError::TooMany {
            crowded: c.crowded,
            frames: c.frames,
        });
    }
    // A slot seen in too few frames is a passing blob, not a ball.
    let seen = |s: usize| frames.iter().filter(|f| f[s].is_ok()).count();
    let enough = (frames.len() / 10).max(FEWEST_SEEN);
    if c.frames < FEWEST_SEEN {
        return Err(TracksError::TooFewFrames {
            frames: c.frames,
            need: FEWEST_SEEN,
        });
    }
    let slots: Vec<usize> = (0..2).filter(|&s| seen(s) >= enough).collect();
    if slots.is_empty() {
        return Err(TracksError::NoBall {
            frames: c.frames,
            min_radius: tracker.params.min_radius,
        });
    }
    // A ball found in few of the frames: what was found may be something else (a
    // mark, a highlight) in the frames where the ball itself was missed.
    let best = slots.iter().map(|&s| seen(s)).max().unwrap_or(0);
    if best * SPARSEST < c.frames {
        return Err(TracksError::Sparse {
            seen: best,
            frames: c.frames,
        });
    }
    Ok(slots)
}

/// Leaves out (as poor outlines) the fits that lie off their ball's line across the
/// groove by more than `within` px (`Params::off_the_line` radii): the line's
/// direction from every fit, each ball's place across it the median of its fits'.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn off_the_line(frames: &mut [FrameFixes], within: f64) {
    let centres: Vec<Vec<[f64; 2]>> = (0..2).map(|s| centres_of(frames, s)).collect();
    let (angle, _, found) = groove(&[&centres[0][..], &centres[1][..]]);
    let angle = if found { angle } else { 0.0 };
    let n = (angle.sin(), -angle.cos());
    for slot in 0..2 {
        let across: Vec<f64> = centres[slot]
            .iter()
            .map(|p| p[0] * n.0 + p[1] * n.1)
            .collect();
        let Some(line) = median(&across) else {
            continue;
        };
        for f in frames.iter_mut() {
            if let Ok(fix) = &f[slot] {
                let c = fix.outline.circle;
                if (c.x * n.0 + c.y * n.1 - line).abs() > within {
                    f[slot] = Err(LeftOut::Poor);
                }
            }
        }
    }
}

/// How far `centres` scatter across the groove (whose normal is `n`), RMS px: a
/// ball rolls along its groove, so a large scatter is no ball's path.
fn across_rms(centres: &[[f64; 2]], n: (f64, f64)) -> f64 {
    let across = |p: &[f64; 2]| p[0] * n.0 + p[1] * n.1;
    let count = centres.len() as f64;
    let mean = centres.iter().map(across).sum::<f64>() / count;
    (centres
        .iter()
        .map(|p| (across(p) - mean).powi(2))
        .sum::<f64>()
        / count)
        .sqrt()
}

/// The names of the balls in `slots` (left to right): with one ball, the side it
/// comes from (it moves away from it at first).
#[allow(clippy::indexing_slicing)] // one slot, seen in at least 3 frames
fn names_of(
    slots: &[usize],
    centres: &[Vec<[f64; 2]>],
    along: impl Fn(&[f64; 2]) -> f64,
) -> Vec<&'static str> {
    if slots.len() == 2 {
        return vec!["left", "right"];
    }
    let c = &centres[slots[0]];
    let n = (c.len() / 4).max(2).min(c.len());
    let moves = along(&c[n - 1]) - along(&c[0]);
    vec![if moves >= 0.0 { "left" } else { "right" }]
}

/// The frames with each ball in its own slot, the left ball in slot 0: two balls in
/// one groove never pass each other, so where both are seen their order in the
/// picture says who is who; a frame with one ball seen gives it to the slot whose
/// ball was nearest in the nearest frame with both seen (a slot kept by the tracker
/// from a first, wrong lock would swap the balls for a stretch of frames).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
pub fn ordered(frames: &[FrameFixes]) -> Vec<FrameFixes> {
    let x = |f: &Result<super::tracker::Fix, LeftOut>| f.as_ref().ok().map(|q| q.outline.circle.x);
    let both: Vec<(usize, f64, f64)> = frames
        .iter()
        .enumerate()
        .filter_map(|(k, f)| Some((k, x(&f[0])?, x(&f[1])?)))
        .collect();
    frames
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let mut f = *f;
            match (x(&f[0]), x(&f[1])) {
                (Some(a), Some(b)) if a > b => f.swap(0, 1),
                (Some(c), None) | (None, Some(c)) => {
                    let near = both.iter().min_by_key(|(j, _, _)| j.abs_diff(k));
                    if let Some(&(_, l, r)) = near {
                        let slot = usize::from((c - r).abs() < (c - l).abs());
                        if f[slot].is_err() {
                            f.swap(0, 1);
                        }
                    }
                }
                _ => {}
            }
            f
        })
        .collect()
}

#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn centres_of(frames: &[FrameFixes], slot: usize) -> Vec<[f64; 2]> {
    frames
        .iter()
        .filter_map(|f| f[slot].as_ref().ok())
        .map(|fix| [fix.outline.circle.x, fix.outline.circle.y])
        .collect()
}

/// The groove's angle (rad, image y down: positive turns the right end down), its
/// standard error, and whether the paths tell it: the principal axis of the centres,
/// each ball's path about its own mean (two balls in one groove run on one line, but
/// a path's own direction is what each tells).
fn groove(paths: &[&[[f64; 2]]]) -> (f64, f64, bool) {
    let (mut sxx, mut sxy, mut syy, mut n) = (0.0, 0.0, 0.0, 0usize);
    for p in paths {
        if p.is_empty() {
            continue;
        }
        let mx = p.iter().map(|q| q[0]).sum::<f64>() / p.len() as f64;
        let my = p.iter().map(|q| q[1]).sum::<f64>() / p.len() as f64;
        for q in p.iter() {
            sxx += (q[0] - mx).powi(2);
            sxy += (q[0] - mx) * (q[1] - my);
            syy += (q[1] - my).powi(2);
        }
        n += p.len();
    }
    let angle = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (c, s) = (angle.cos(), angle.sin());
    let spread = sxx * c * c + 2.0 * sxy * c * s + syy * s * s;
    let across = (sxx * s * s - 2.0 * sxy * c * s + syy * c * c).max(0.0);
    // A path under 5 px long, or no longer than it is wide, tells no direction.
    if n < 3 || spread < 25.0 * n as f64 || spread < 4.0 * across {
        return (0.0, 0.0, false);
    }
    let se = (across / (n as f64 - 2.0).max(1.0) / spread).sqrt();
    (angle, se, true)
}

/// Slot `slot` of `tracker` as a [`BallTrack`] named `name`, through `to_m`.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn ball_track(
    frames: &[FrameFixes],
    slot: usize,
    name: &'static str,
    to_m: &impl Fn(f64, f64) -> (f64, f64),
    px_per_m: f64,
) -> BallTrack {
    let mut b = BallTrack {
        name,
        x: vec![],
        y: vec![],
        sigma: vec![],
        mark_x: vec![],
        mark_y: vec![],
        mark_sigma: vec![],
        unseen: 0,
        merged: 0,
        poor: 0,
        mark_missing: 0,
    };
    let nan = f64::NAN;
    for f in frames {
        let (x, y, s, mx, my, ms) = match &f[slot] {
            Ok(fix) => {
                let c = fix.outline.circle;
                let (x, y) = to_m(c.x, c.y);
                let (mx, my, ms) = match fix.mark {
                    Some(m) => {
                        let (mx, my) = to_m(m.x, m.y);
                        (mx, my, m.sigma / px_per_m)
                    }
                    None => {
                        b.mark_missing += 1;
                        (nan, nan, nan)
                    }
                };
                (x, y, fix.sigma / px_per_m, mx, my, ms)
            }
            Err(why) => {
                match why {
                    LeftOut::Unseen => b.unseen += 1,
                    LeftOut::Merged => b.merged += 1,
                    LeftOut::Poor => b.poor += 1,
                }
                (nan, nan, nan, nan, nan, nan)
            }
        };
        b.x.push(x);
        b.y.push(y);
        b.sigma.push(s);
        b.mark_x.push(mx);
        b.mark_y.push(my);
        b.mark_sigma.push(ms);
    }
    b
}
