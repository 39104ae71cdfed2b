//! Frames that repeat another frame's picture: a phone that drops frames repeats the
//! one before to keep its rate, and a heavily compressed clip's B frames that code
//! nothing of their own show the nearest coded frame's picture (blended with the
//! next one's). A moving ball's fit in such a frame stays where its neighbour's is,
//! while the frames about it show the ball moving several pixels a frame: it is the
//! other frame's place, not this frame's time's. Of each run of such fits the one
//! whose place its ball's motion puts at its own frame is kept, the others are left
//! out (`LeftOut::Repeated`). Only a moving ball tells: a ball at rest repeats its
//! place by right, so slow stretches are never judged. Where the ball turns, slows
//! or meets the impact (its motion not one way over the frames either side), a run
//! is judged against the parabola through the fits about it ([`turning`]). So is a
//! fit alone at the place that parabola gives the frame before or after, whose own
//! fit was left out ([`lone_copies`]).

use super::tracker::{FrameFixes, LeftOut, median};

/// When fits repeat their neighbour's place (`Params::repeat_still` and the two
/// after it).
#[derive(Clone, Copy, Debug)]
pub struct RepeatRule {
    /// A step between two frames' fits under this share of the ball's motion a
    /// frame is no step.
    pub still: f64,
    /// The least motion, px a frame, for a ball's steps to be judged.
    pub least_speed: f64,
    /// Frames either side over which the ball's motion a frame is measured (its
    /// displacement over them: repeated fits shorten some steps and lengthen the
    /// next, not the sum).
    pub window: usize,
    /// Where the ball turns or meets the impact: the least step a frame, px, the
    /// parabola through the fits about a run must give each of its steps for the
    /// run to be judged ([`turning`]).
    pub turn_step: f64,
    /// … that parabola through up to this many fits either side.
    pub neighbours: usize,
}

/// Leaves out, as repeats, the fits of each ball at the frames `found` names in its
/// path (its fits as (frame, place along the groove, px)): [`repeated`] while the
/// ball moves one way, [`turning`] where it turns, slows or meets the impact.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
pub fn leave_out(
    frames: &mut [FrameFixes],
    paths: &[Vec<(usize, f64)>; 2],
    found: impl Fn(&[(usize, f64)]) -> Vec<usize>,
) {
    for (slot, path) in paths.iter().enumerate() {
        for k in found(path) {
            if let Some(f) = frames.get_mut(k) {
                f[slot] = Err(LeftOut::Repeated);
            }
        }
    }
}

/// The frames of `path` whose fit repeats a neighbouring frame's place where the
/// motion is no one way over `window` frames (a ball that turns, slows or meets
/// the impact there, which `repeated` does not judge): a run of fits in
/// consecutive frames, on one side of the impact, each within `still` ×
/// `least_speed` px of the one before, is judged against the least-squares
/// parabola (in frames) through up to `neighbours` fits before it and as many
/// after, within `window` frames, on its side of the impact, none within a frame of
/// it (at least one either side, three in all). Where that parabola steps by
/// `turn_step` px or more between each two of the run's frames and each of the
/// run's own steps is under `still` of its step, the run repeats one picture: the
/// fit nearest the parabola at its own frame is kept when it lies within half the
/// least such step of it, the others (or all) left out. (Within a quarter, the
/// looks table's seed 27 lost one more fit and its two fits of μ_k disagreed;
/// within half, seed 11 keeps a fit 4.7 px off, its run's own frame's fit left
/// out: the parabola through a heavily compressed clip's fits is itself a pixel or
/// two off.)
pub fn turning(path: &[(usize, f64)], impact: Option<usize>, rule: RepeatRule) -> Vec<usize> {
    let mut out = Vec::new();
    let mut a = 0;
    while a < path.len() {
        let mut b = a;
        while let (Some(&(ka, sa)), Some(&(kb, sb))) = (path.get(b), path.get(b + 1)) {
            if kb != ka + 1
                || side(impact, ka) * side(impact, kb) < 0
                || (sb - sa).abs() >= rule.still * rule.least_speed
            {
                break;
            }
            b += 1;
        }
        if b > a {
            out.extend(turning_run(path, a, b, impact, rule));
        }
        a = b + 1;
    }
    out
}

/// The frames of `path` whose fit alone shows the frame before's or after's
/// picture: a heavily compressed clip's B frame copies its reference's ball where
/// that frame's own fit was left out (touching the other ball, poor), so no run of
/// fits of one place shows it ([`repeated`], [`turning`] judge runs). Each fit is
/// held against the least-squares parabola (in frames) through up to `neighbours`
/// fits either side within `window` frames on its side of the impact, none within a
/// frame of it (at least one either side, four in all). Where that parabola steps by
/// `turn_step` px a frame or more at the fit and misses its own fits by under
/// `still` of that step (RMS), a fit within `still` of the step of where the
/// parabola puts the frame before or after, and nearer that place than its own
/// frame's, is that other frame's picture. The worst is left out first and the rest
/// judged again.
pub fn lone_copies(path: &[(usize, f64)], impact: Option<usize>, rule: RepeatRule) -> Vec<usize> {
    let mut fits = path.to_vec();
    let mut out = Vec::new();
    loop {
        let worst = (0..fits.len())
            .filter_map(|i| Some((i, copy_of_neighbour(&fits, i, impact, rule)?)))
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let Some((i, _)) = worst else { break };
        if i < fits.len() {
            out.push(fits.remove(i).0);
        }
    }
    out.sort_unstable();
    out
}

/// How far fit `i` of `fits` lies from where the parabola through its neighbours
/// puts its own frame, in steps of the ball a frame, where it is the picture of the
/// frame before or after ([`lone_copies`]); `None` otherwise.
fn copy_of_neighbour(
    fits: &[(usize, f64)],
    i: usize,
    impact: Option<usize>,
    rule: RepeatRule,
) -> Option<f64> {
    let &(k, s) = fits.get(i)?;
    let near_impact = |j: usize| impact.is_some_and(|m| j.abs_diff(m) <= 1);
    if near_impact(k) {
        return None;
    }
    let about = |p: &&(usize, f64)| side(impact, p.0) * side(impact, k) >= 0 && !near_impact(p.0);
    // The fits are in frame order: none beyond the window is looked at.
    let within = |p: &&(usize, f64)| p.0.abs_diff(k) <= rule.window;
    let before = fits.get(..i)?.iter().rev().take_while(within);
    let after = fits.get(i + 1..)?.iter().take_while(within);
    let before = before.filter(about).take(rule.neighbours);
    let after = after.filter(about).take(rule.neighbours);
    let (before, after): (Vec<_>, Vec<_>) = (before.collect(), after.collect());
    if before.is_empty() || after.is_empty() || before.len() + after.len() < 4 {
        return None;
    }
    let pts: Vec<(f64, f64)> = before
        .iter()
        .chain(&after)
        .map(|&&(j, place)| (j as f64 - k as f64, place))
        .collect();
    let (c0, c1, c2) = parabola(&pts)?;
    let at = |u: f64| c0 + c1 * u + c2 * u * u;
    let step = c1.abs();
    let miss =
        (pts.iter().map(|&(u, p)| (p - at(u)).powi(2)).sum::<f64>() / pts.len() as f64).sqrt();
    if step < rule.turn_step || miss >= rule.still * step {
        return None;
    }
    let off = (s - at(0.0)).abs();
    let copy = [-1.0, 1.0]
        .iter()
        .any(|&u| (s - at(u)).abs() <= rule.still * step);
    (copy && off > 0.5 * step).then_some(off / step)
}

/// The frames of the run `a..=b` of `path` that `turning` leaves out.
fn turning_run(
    path: &[(usize, f64)],
    a: usize,
    b: usize,
    impact: Option<usize>,
    rule: RepeatRule,
) -> Vec<usize> {
    let Some(run) = path.get(a..=b) else {
        return Vec::new();
    };
    let (Some(&(ka, _)), Some(&(kb, _))) = (run.first(), run.last()) else {
        return Vec::new();
    };
    let s0 = side(impact, ka) + side(impact, kb);
    let fit_near = |&&(j, _): &&(usize, f64)| {
        side(impact, j) * s0 >= 0 && impact.is_none_or(|i| j.abs_diff(i) > 1)
    };
    let before = path.get(..a).unwrap_or(&[]).iter().rev();
    let before = before.filter(|p| ka - p.0 <= rule.window).filter(fit_near);
    let after = path.get(b + 1..).unwrap_or(&[]).iter();
    let after = after.filter(|p| p.0 - kb <= rule.window).filter(fit_near);
    let before: Vec<(usize, f64)> = before.take(rule.neighbours).copied().collect();
    let after: Vec<(usize, f64)> = after.take(rule.neighbours).copied().collect();
    if before.is_empty() || after.is_empty() || before.len() + after.len() < 3 {
        return Vec::new();
    }
    let pts: Vec<(f64, f64)> = before
        .iter()
        .chain(&after)
        .map(|&(j, s)| (j as f64 - ka as f64, s))
        .collect();
    let Some(curve) = parabola(&pts) else {
        return Vec::new();
    };
    let at = |j: usize| {
        let u = j as f64 - ka as f64;
        curve.0 + curve.1 * u + curve.2 * u * u
    };
    let steps = run.windows(2).map(|w| match w {
        [p, q] => ((at(q.0) - at(p.0)).abs(), (q.1 - p.1).abs()),
        _ => (0.0, f64::INFINITY),
    });
    let mut least = f64::INFINITY;
    for (step, own) in steps {
        if step < rule.turn_step || own >= rule.still * step {
            return Vec::new();
        }
        least = least.min(step);
    }
    let off = |p: &(usize, f64)| (p.1 - at(p.0)).abs();
    let kept = run
        .iter()
        .min_by(|p, q| off(p).total_cmp(&off(q)))
        .filter(|p| off(p) <= 0.5 * least)
        .map(|p| p.0);
    run.iter()
        .map(|p| p.0)
        .filter(|&j| Some(j) != kept)
        .collect()
}

/// The least-squares parabola s = c0 + c1 u + c2 u² through `pts` (u, s); `None`
/// when its normal equations are near singular.
fn parabola(pts: &[(f64, f64)]) -> Option<(f64, f64, f64)> {
    let (m, v) = pts.iter().fold(
        (
            nalgebra::Matrix3::<f64>::zeros(),
            nalgebra::Vector3::<f64>::zeros(),
        ),
        |(m, v), &(u, s)| {
            let row = nalgebra::Vector3::new(1.0, u, u * u);
            (m + row * row.transpose(), v + row * s)
        },
    );
    if m.determinant().abs() <= 1e-9 * m.amax().powi(3) {
        return None;
    }
    let c = m.try_inverse()? * v;
    Some((c.x, c.y, c.z))
}

/// -1 before the impact, +1 after, 0 at it or without one.
fn side(impact: Option<usize>, k: usize) -> i64 {
    impact.map_or(0, |i| (k as i64 - i as i64).signum())
}

/// The ball's motion over frames `lo..=hi` of `path`, px a frame (signed along the
/// groove): its displacement between the farthest fits there on `side_of`'s side of
/// the impact; `None` without two such fits.
fn speed(
    path: &[(usize, f64)],
    (lo, hi): (usize, usize),
    impact: Option<usize>,
    side_of: usize,
) -> Option<f64> {
    let near = |&&(j, _): &&(usize, f64)| {
        (lo..=hi).contains(&j) && side(impact, j) * side(impact, side_of) >= 0
    };
    let first = path.iter().find(near)?;
    let last = path.iter().rev().find(near)?;
    (last.0 > first.0).then(|| (last.1 - first.1) / (last.0 - first.0) as f64)
}

/// The ball's motion about the step from frame `ka` to `kb`, px a frame: the lesser
/// of its motions over `window` frames before and after it, when they go one way
/// (a ball starting or coming to rest there is not judged); 0 otherwise.
fn motion(
    path: &[(usize, f64)],
    ka: usize,
    kb: usize,
    impact: Option<usize>,
    window: usize,
) -> f64 {
    let before = speed(path, (ka.saturating_sub(window), ka), impact, ka);
    let after = speed(path, (kb, kb + window), impact, kb);
    match (before, after) {
        (Some(x), Some(y)) if x * y > 0.0 => x.abs().min(y.abs()) * x.signum(),
        _ => 0.0,
    }
}

/// The frames of `path` whose fit repeats a neighbouring frame's place (each run's
/// kept fit not among them).
pub fn repeated(path: &[(usize, f64)], impact: Option<usize>, rule: RepeatRule) -> Vec<usize> {
    // still[i]: fit i repeats fit i - 1's place (the frame just before).
    let still: Vec<bool> = (0..path.len())
        .map(|i| {
            let (Some(&(ka, sa)), Some(&(kb, sb))) =
                (i.checked_sub(1).and_then(|a| path.get(a)), path.get(i))
            else {
                return false;
            };
            let v = motion(path, ka, kb, impact, rule.window).abs();
            kb == ka + 1
                && side(impact, ka) * side(impact, kb) >= 0
                && v >= rule.least_speed
                && (sb - sa).abs() < rule.still * v
        })
        .collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < path.len() {
        if !still.get(i + 1).copied().unwrap_or(false) {
            i += 1;
            continue;
        }
        // A run: fits a..=b, each the place of the one before.
        let a = i;
        let mut b = a + 1;
        while still.get(b + 1).copied().unwrap_or(false) {
            b += 1;
        }
        let run = kept(path, a, b, impact, rule);
        if run != RepeatRun::Untold {
            out.extend(
                (a..=b)
                    .filter(|&j| run != RepeatRun::Keep(j))
                    .filter_map(|j| path.get(j).map(|p| p.0)),
            );
        }
        i = b + 1;
    }
    out
}

/// What a run of fits that repeat one place is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RepeatRun {
    /// Fit `.0` (an index into the path) shows its own frame's picture; the others
    /// repeat it.
    Keep(usize),
    /// The motion either side names different frames: none is told, all left out.
    Drop,
    /// Too few fits about it to tell its motion: left as it is.
    Untold,
}

/// Which fit of the run `a..=b` of `path` shows its own frame's picture: the one
/// whose frame is nearest the time at which the ball's motion puts it at the run's
/// place, as the fits within `window` frames before the run say it and as those
/// after it say it (each side's a line through its fits, on the run's side of the
/// impact, its slope and offset each the median of theirs, so that another
/// repeated or poor fit among them does not move it). Where the two sides name
/// different frames (a ball turning or slowing there) none is kept; where neither
/// side has two fits, nothing is told.
fn kept(
    path: &[(usize, f64)],
    a: usize,
    b: usize,
    impact: Option<usize>,
    rule: RepeatRule,
) -> RepeatRun {
    let Some(run) = path.get(a..=b) else {
        return RepeatRun::Untold;
    };
    let (Some(&(ka, _)), Some(&(kb, _))) = (run.first(), run.last()) else {
        return RepeatRun::Untold;
    };
    let place = run.iter().map(|p| p.1).sum::<f64>() / run.len() as f64;
    let on_side = |j: usize| {
        side(impact, j) * side(impact, ka) >= 0 && side(impact, j) * side(impact, kb) >= 0
    };
    let fits = |near: &dyn Fn(usize) -> bool| -> Vec<(f64, f64)> {
        path.iter()
            .filter(|&&(j, _)| near(j) && on_side(j))
            .map(|&(j, s)| (j as f64, s))
            .collect()
    };
    let before = fits(&|j| j < ka && ka - j <= rule.window);
    let after = fits(&|j| j > kb && j - kb <= rule.window);
    let nearest = |at: f64| {
        (a..=b).min_by(|&x, &y| {
            let d = |j: usize| {
                path.get(j)
                    .map_or(f64::INFINITY, |p| (p.0 as f64 - at).abs())
            };
            d(x).total_cmp(&d(y))
        })
    };
    let named: Vec<usize> = [before, after]
        .iter()
        .filter_map(|f| nearest(when(f, place)?))
        .collect();
    match named.first() {
        None => RepeatRun::Untold,
        Some(&j) if named.iter().all(|&n| n == j) => RepeatRun::Keep(j),
        Some(_) => RepeatRun::Drop,
    }
}

/// When the line through `fits` (frame, place) puts the ball at `place`, its slope
/// and offset each the median of the fits' (Theil and Sen); `None` with fewer than
/// two fits or no motion.
fn when(fits: &[(f64, f64)], place: f64) -> Option<f64> {
    let slopes: Vec<f64> = fits
        .iter()
        .enumerate()
        .flat_map(|(i, p)| {
            fits.iter()
                .skip(i + 1)
                .map(move |q| (q.1 - p.1) / (q.0 - p.0))
        })
        .collect();
    let v = median(&slopes).filter(|v| v.abs() > 0.0)?;
    let offsets: Vec<f64> = fits.iter().map(|p| p.1 - v * p.0).collect();
    Some((place - median(&offsets)?) / v)
}

#[cfg(test)]
mod tests {
    use super::*;

    const RULE: RepeatRule = RepeatRule {
        still: 0.25,
        least_speed: 2.0,
        window: 8,
        turn_step: 2.0,
        neighbours: 3,
    };

    /// A ball moving 5 px a frame over frames 0..30, frames 10..=12 showing frame
    /// `shown`'s picture.
    fn copying(shown: usize) -> Vec<(usize, f64)> {
        (0..30usize)
            .map(|k| {
                let at = if (10..=12).contains(&k) { shown } else { k };
                (k, 5.0 * at as f64)
            })
            .collect()
    }

    /// Frames 10..=12 showing frame 9's picture: frame 9 kept.
    #[test]
    fn copies_of_the_frame_before_are_left_out_and_it_kept() {
        assert_eq!(repeated(&copying(9), None, RULE), vec![10, 11, 12]);
    }

    /// Frames 10..=12 showing frame 13's picture: frame 13 kept.
    #[test]
    fn copies_of_the_frame_after_are_left_out_and_it_kept() {
        assert_eq!(repeated(&copying(13), None, RULE), vec![10, 11, 12]);
    }

    /// A ball at rest (and one slowing to rest) repeats its place by right.
    #[test]
    fn a_ball_at_rest_is_not_judged() {
        let path: Vec<(usize, f64)> = (0..30).map(|k| (k, 100.0 + 0.01 * k as f64)).collect();
        assert!(repeated(&path, None, RULE).is_empty());
        let stops: Vec<(usize, f64)> = (0..30).map(|k| (k, 5.0 * (k.min(15) as f64))).collect();
        assert!(repeated(&stops, Some(15), RULE).is_empty());
    }

    /// A ball slowing to turn back at frame 15 (s = 100 + (k − 15)²/2): frames 10
    /// and 12 show frame 11's picture. The ball's motion is no one way over the 8
    /// frames after them, so `repeated` does not judge the run; against the
    /// parabola through the fits about it, frames 10 and 12 are left out and 11
    /// kept. Without the copies, and for a ball at rest, nothing is.
    #[test]
    fn copies_where_the_ball_turns_are_left_out() {
        let place = |k: usize| 100.0 + 0.5 * (k as f64 - 15.0).powi(2);
        let turning_ball: Vec<(usize, f64)> = (0..30).map(|k| (k, place(k))).collect();
        let copied: Vec<(usize, f64)> = (0..30)
            .map(|k| (k, place(if (10..=12).contains(&k) { 11 } else { k })))
            .collect();
        assert!(repeated(&copied, None, RULE).is_empty());
        assert_eq!(turning(&copied, None, RULE), vec![10, 12]);
        assert!(turning(&turning_ball, None, RULE).is_empty());
        let rest: Vec<(usize, f64)> = (0..30).map(|k| (k, 100.0 + 0.01 * k as f64)).collect();
        assert!(turning(&rest, None, RULE).is_empty());
    }

    /// A ball leaving an impact at frame 10, slowing from 4 px a frame, its fit at
    /// frame 15 left out (poor) and frame 16 showing frame 15's picture: no run of
    /// one place shows it, so neither `repeated` nor `turning` leaves it out;
    /// `lone_copies` does, and only it. Frame 16 half a step off (a fit's scatter
    /// on a blurred frame, not another frame's place) stays, as does every fit of
    /// the path without the copy, with a scatter of a tenth of a step, and of a
    /// ball under `turn_step` a frame.
    #[test]
    fn a_lone_fit_showing_its_neighbours_picture_is_left_out() {
        let place = |k: usize| 200.0 - 4.0 * (k as f64 - 10.0) + 0.05 * (k as f64 - 10.0).powi(2);
        let path = |shown: &dyn Fn(usize) -> f64| -> Vec<(usize, f64)> {
            (11..30)
                .filter(|&k| k != 15)
                .map(|k| (k, shown(k)))
                .collect()
        };
        let copied = path(&|k| place(if k == 16 { 15 } else { k }));
        assert!(repeated(&copied, Some(10), RULE).is_empty());
        assert!(turning(&copied, Some(10), RULE).is_empty());
        assert_eq!(lone_copies(&copied, Some(10), RULE), vec![16]);
        let half = path(&|k| place(k) + if k == 16 { 2.0 } else { 0.0 });
        assert!(lone_copies(&half, Some(10), RULE).is_empty());
        let scatter = path(&|k| place(k) + if k % 2 == 0 { 0.4 } else { -0.4 });
        assert!(lone_copies(&scatter, Some(10), RULE).is_empty());
        let slow = |k: usize| 200.0 - 1.5 * (k as f64 - 10.0);
        let slow_copied = path(&|k| slow(if k == 16 { 15 } else { k }));
        assert!(lone_copies(&slow_copied, Some(10), RULE).is_empty());
    }
}
