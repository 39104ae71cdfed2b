//! Which marks found are a ball's own: a mark is drawn on the ball, so it turns with
//! it; a glossy highlight stays where the light puts it (the same spot of the disc
//! on both balls, frame after frame, however far the ball rolls), and a spot of the
//! wall seen through the search stays where it is in the picture while the ball moves
//! on. Marks of either kind are left out (the centre alone still gives the tracks);
//! a wrong mark is worse than none.

use super::params::MarkChecks;
use super::tracker::FrameFixes;

/// The frames (slot 0 the left ball, as `tracks::ordered` gives them) with every
/// mark that is not the ball's own left out.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
pub fn checked(frames: &[FrameFixes], p: &MarkChecks) -> Vec<FrameFixes> {
    // First, the marks no check can judge: the other checks then read none of them.
    let mut judged = frames.to_vec();
    leave_out_alone(&mut judged, p);
    let frames = &judged[..];
    let mut out = frames.to_vec();
    let fixed = fixed_spots(frames, p);
    for f in out.iter_mut() {
        for fix in f.iter_mut().flatten() {
            let at_fixed =
                offset(fix).is_some_and(|o| fixed.iter().any(|h| near(o, *h, p.spot_reach)));
            if at_fixed || rivalled(fix, &fixed, p) {
                fix.mark = None;
            }
        }
    }
    let faint = faint_marks(&out, p);
    for (k, slot) in faint {
        left_out(&mut out, slot, [k]);
    }
    let staying = staying_spot(frames, p);
    for slot in 0..2 {
        let own = fixed_spot(frames, slot, p);
        for h in own.into_iter().chain(staying) {
            for f in out.iter_mut() {
                if let Ok(fix) = &mut f[slot]
                    && offset(fix).is_some_and(|o| near(o, h, 2.0 * p.same_spot))
                {
                    fix.mark = None;
                }
            }
        }
        // Each check reads the marks the one before it left.
        let still = still_marks(&out, slot, p);
        left_out(&mut out, slot, still);
        let off = off_the_circle(&out, slot, p);
        left_out(&mut out, slot, off);
        if !turns_with_the_ball(&out, slot, p) {
            left_out(&mut out, slot, 0..frames.len());
        }
        // Last, single marks that do not behave as a drawn mark's, judged among the
        // marks kept (the checks of the whole track above judge the marks as found:
        // leaving out some first would change their verdict on the others).
        let off = off_the_spin(&out, slot, p);
        left_out(&mut out, slot, off);
        let twice = shown_twice(&out, slot, p);
        left_out(&mut out, slot, twice);
        let stayed = stayed_while_rolling(&out, slot, p);
        left_out(&mut out, slot, stayed);
        let lone = unconfirmed(&out, slot, p);
        left_out(&mut out, slot, lone);
        // Fewer marks than their circle and turning are told from, left after the
        // checks: nothing shows they are the drawn mark's (a lone spot the checks
        // above could not judge, its neighbours without the ball).
        let kept: Vec<usize> = (0..out.len())
            .filter(|&k| out[k][slot].as_ref().is_ok_and(|f| f.mark.is_some()))
            .collect();
        if kept.len() < p.fewest_marks {
            left_out(&mut out, slot, kept);
        }
    }
    out
}

/// The marks of the fits in `frames` with no other fit of their ball within
/// [`MarkChecks::confirm_frames`] left out, judged on the fits kept at last: a mark
/// confirmed by a neighbour whose fit was then left out as no ball's (a compressed
/// clip's frame that repeats an earlier picture, its centre stale and its "mark" a
/// spot that rode along with the ball's blocks) is confirmed by nothing.
pub fn leave_out_alone(frames: &mut [FrameFixes], p: &MarkChecks) {
    for slot in 0..2 {
        let alone = alone_in_time(frames, slot, p);
        left_out(frames, slot, alone);
    }
}

/// The places of the disc (radii from the centre) where a spot stands out in most
/// of each ball's frames (of each ball seen in [`MarkChecks::fewest_marks`] frames
/// or more): a glossy highlight, a feature of the shading or of a metal's
/// reflection, which the light puts at one place of both discs. BallFit as the
/// strongest spot only where the drawn mark is hidden (behind the rail) or weak, it
/// is found as a lesser spot in the other frames ([`super::mark::InDisc::spots`]). A
/// drawn mark turns with its ball and passes any one place of the disc in a few
/// frames only.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn fixed_spots(frames: &[FrameFixes], p: &MarkChecks) -> Vec<(f64, f64)> {
    // Each slot's fits, as the places of their spots in the disc and their signs.
    type Spot = ((f64, f64), f64);
    let per_slot: Vec<Vec<Vec<Spot>>> = (0..2)
        .map(|slot| {
            frames
                .iter()
                .filter_map(|f| f[slot].as_ref().ok())
                .map(|fix| {
                    fix.spots
                        .iter()
                        .flatten()
                        .map(|s| (fix.outline.in_disc((s.0, s.1)), s.2.signum()))
                        .collect()
                })
                .collect()
        })
        .collect();
    let seen: Vec<&Vec<Vec<Spot>>> = per_slot
        .iter()
        .filter(|fits| fits.len() >= p.fewest_marks)
        .collect();
    if seen.is_empty() {
        return Vec::new();
    }
    // The least share, over the balls seen, of the frames with a spot of the sign
    // of `h` within half the reach of it (a highlight's place found in frame after
    // frame to a pixel or two; the wider reach would count a highlight next to the
    // place for it, a second time; a drawn mark that comes back to one place every few frames,
    // at a low rate, keeps to no one place in most).
    let present = |h: Spot| -> f64 {
        seen.iter()
            .map(|fits| {
                let n = fits
                    .iter()
                    .filter(|spots| {
                        spots
                            .iter()
                            .any(|s| s.1 == h.1 && near(s.0, h.0, 0.5 * p.spot_reach))
                    })
                    .count();
                n as f64 / fits.len() as f64
            })
            .fold(1.0, f64::min)
    };
    let mut scored: Vec<((f64, f64), f64)> = seen
        .iter()
        .flat_map(|fits| fits.iter().flatten())
        .map(|&h| (h.0, present(h)))
        .filter(|(_, share)| *share >= p.fixed_present)
        .collect();
    scored.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut out: Vec<(f64, f64)> = Vec::new();
    for (h, _) in scored {
        if !out.iter().any(|o| near(*o, h, p.spot_reach)) {
            out.push(h);
        }
    }
    out
}

/// True when another spot of the disc, of the mark's sign and not at one of the
/// `fixed` places (a highlight), stands out from the ball nearly as much as the
/// mark (over 1 / [`MarkChecks::rival_ratio`] of it), a quarter of a radius or more
/// away from it: two spots alike, and no telling which is the drawn mark (a
/// compressed clip's blocks along a dark limb, a patterned wall's fringe).
fn rivalled(fix: &super::tracker::Fix, fixed: &[(f64, f64)], p: &MarkChecks) -> bool {
    let Some(m) = fix.mark else { return false };
    let sign = m.contrast.signum();
    // The spots of the mark's sign, not at a fixed place: (place in the disc, level).
    let spots: Vec<((f64, f64), f64)> = fix
        .spots
        .iter()
        .flatten()
        .map(|s| (fix.outline.in_disc((s.0, s.1)), s.2 * sign))
        .filter(|(o, d)| *d > 0.0 && !fixed.iter().any(|h| near(*o, *h, p.spot_reach)))
        .collect();
    let at = fix.outline.in_disc((m.x, m.y));
    let own = spots
        .iter()
        .filter(|(o, _)| near(*o, at, p.spot_reach))
        .map(|s| s.1)
        .fold(0.0, f64::max);
    spots
        .iter()
        .any(|(o, d)| !near(*o, at, p.spot_reach) && *d * p.rival_ratio > own)
}

/// The marks (frame, slot) that stand out from their ball by less than
/// [`MarkChecks::faint_share`] of the contrast both balls' marks have (their
/// median): a drawn mark keeps its colour, and so about its contrast, from frame to
/// frame; a spot of the ball's own shading near the limb, or the dark fringe about
/// a highlight, found where the mark is hidden or out of reach, stands out faintly.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn faint_marks(frames: &[FrameFixes], p: &MarkChecks) -> Vec<(usize, usize)> {
    let marks: Vec<(usize, usize, f64)> = frames
        .iter()
        .enumerate()
        .flat_map(|(k, f)| {
            (0..2).filter_map(move |s| Some((k, s, f[s].as_ref().ok()?.mark?.contrast)))
        })
        .collect();
    if marks.len() < p.fewest_marks {
        return Vec::new();
    }
    let Some(typical) = middle(&marks.iter().map(|m| m.2).collect::<Vec<_>>()) else {
        return Vec::new();
    };
    marks
        .into_iter()
        .filter(|m| m.2 * typical.signum() < p.faint_share * typical.abs())
        .map(|m| (m.0, m.1))
        .collect()
}

/// The marks of `slot` in the frames `at` left out.
fn left_out(frames: &mut [FrameFixes], slot: usize, at: impl IntoIterator<Item = usize>) {
    for k in at {
        if let Some(Ok(fix)) = frames.get_mut(k).and_then(|f| f.get_mut(slot)) {
            fix.mark = None;
        }
    }
}

/// The frames whose mark in `slot` lies off the circle (about the centre) that the
/// ball's marks keep to, by more than [`MarkChecks::on_circle`] radii; every frame's mark when
/// fewer than [`MarkChecks::kept_share`] of them keep to one circle or that circle lies too near
/// the centre for an angle (a fifth of the radius) — then no mark is the ball's.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn off_the_circle(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let at: Vec<(usize, f64)> = frames
        .iter()
        .enumerate()
        .filter_map(|(k, f)| {
            let o = offset(f[slot].as_ref().ok()?)?;
            Some((k, o.0.hypot(o.1)))
        })
        .collect();
    if at.is_empty() {
        return Vec::new();
    }
    let all = || at.iter().map(|(k, _)| *k).collect();
    if at.len() < p.fewest_marks {
        return all();
    }
    let Some(d) = middle(&at.iter().map(|(_, d)| *d).collect::<Vec<_>>()) else {
        return all();
    };
    let off: Vec<usize> = at
        .iter()
        .filter(|(_, e)| (e - d).abs() > p.on_circle)
        .map(|(k, _)| *k)
        .collect();
    if d < 0.2 || ((at.len() - off.len()) as f64) < p.kept_share * at.len() as f64 {
        return all();
    }
    off
}

/// True when the marks of `slot` turn with the ball: between consecutive frames
/// with a mark, the mark's angle about the centre changes by no more than rolling
/// the ball's move turns it (plus noise), in most steps. A ball turns as it moves;
/// a spot that jumps by more is not one drawn mark.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn turns_with_the_ball(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> bool {
    let marked: Vec<(f64, f64, f64)> = frames
        .iter()
        .filter_map(|f| {
            let fix = f[slot].as_ref().ok()?;
            let o = offset(fix)?;
            // The ball rolls on the rails' edges, turning by Δx / (kR).
            Some((
                fix.outline.circle.x,
                fix.outline.rolling_radius(),
                o.1.atan2(o.0),
            ))
        })
        .collect();
    // Per step between marked frames: the mark's turn and the ball's roll, rad.
    let turns: Vec<(f64, f64)> = marked
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let turn = turn_between(a.2, b.2);
            (turn.abs(), (b.0 - a.0).abs() / a.1)
        })
        // A turn is measured modulo a whole turn, and the allowed turn grows with
        // the roll: where the ball rolls by a quarter turn or more between two
        // marked frames, the step tells nothing.
        .filter(|(_, roll)| *roll < std::f64::consts::FRAC_PI_2)
        .collect();
    let steps = turns.len();
    if steps < p.fewest_marks {
        return true;
    }
    let jumps = turns
        .iter()
        .filter(|(turn, roll)| *turn > p.turn_per_radius * roll + p.turn_slack)
        .count();
    // Over the clip, a drawn mark turns by a good part of what its ball rolled (all
    // of it rolling, less while a struck ball slides); a highlight or the shading's
    // darkest spot stays put in the disc however far the ball goes.
    let turned: f64 = turns.iter().map(|t| t.0).sum();
    let rolled: f64 = turns.iter().map(|t| t.1).sum();
    let stays = rolled >= p.min_roll && turned < p.least_turn_share * rolled;
    (jumps as f64) <= p.jumps_share * steps as f64 && !stays
}

/// A mark's place in its ball's disc, in radii from the centre.
fn offset(fix: &super::tracker::Fix) -> Option<(f64, f64)> {
    fix.mark.map(|m| fix.outline.in_disc((m.x, m.y)))
}

fn near(a: (f64, f64), b: (f64, f64), within: f64) -> bool {
    super::circle::length(a.0 - b.0, a.1 - b.1) < within
}

/// The spot of the disc where the "marks" of either ball sit most often, when they
/// sit there while their ball rolls on by [`MarkChecks::rolled`] radii or more (summed over the
/// steps between frames with the mark there): a highlight, or the shading's darkest
/// spot, found in part of the frames and the drawn mark in others. A drawn mark
/// passes a spot of the disc as the ball turns, and stays there only while its ball
/// is at rest or slides without turning (a struck ball, briefly).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn staying_spot(frames: &[FrameFixes], p: &MarkChecks) -> Option<(f64, f64)> {
    // Each mark: its slot, frame, ball's x and radius, and its place in the disc.
    type DiscMark = (usize, usize, f64, f64, (f64, f64));
    let marks: Vec<DiscMark> = frames
        .iter()
        .enumerate()
        .flat_map(|(k, f)| {
            (0..2).filter_map(move |s| {
                let fix = f[s].as_ref().ok()?;
                let c = fix.outline.circle;
                Some((s, k, c.x, c.r, offset(fix)?))
            })
        })
        .collect();
    // Each spot where a mark was found, by how far its balls moved while their
    // marks stayed there (net, over each run of frames with the mark there: the
    // centre's jitter does not add up); the spot that stayed longest.
    let rolled_at = |h: (f64, f64)| -> f64 {
        let mut rolled = 0.0;
        for slot in 0..2 {
            let at: Vec<_> = marks
                .iter()
                .filter(|m| m.0 == slot && near(m.4, h, p.same_spot))
                .collect();
            let mut start = 0;
            for i in 1..=at.len() {
                // A highlight is seen in frame after frame; a drawn mark that
                // comes back to one place every third frame (a turn of about 2π/3
                // a frame, at a low rate) is not staying there.
                let run_ends = i == at.len() || at[i].1 - at[i - 1].1 > 2;
                if run_ends {
                    rolled += (at[i - 1].2 - at[start].2).abs() / at[start].3.max(1.0);
                    start = i;
                }
            }
        }
        rolled
    };
    let (h, rolled) = marks
        .iter()
        .map(|m| (m.4, rolled_at(m.4)))
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    (rolled >= p.rolled).then_some(h)
}

/// The spot of its disc where one ball's "mark" sits in most frames while the ball
/// rolls on by [`MarkChecks::rolled`] radii or more, summed over the runs of frames it
/// sits there in: a highlight.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn fixed_spot(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Option<(f64, f64)> {
    // The ball's marks: centre's x, radius and kR (px: it rolls on the rails' edges,
    // kR below its centre), place in the disc.
    let marks: Vec<(f64, f64, f64, (f64, f64))> = frames
        .iter()
        .filter_map(|f| {
            let fix = f[slot].as_ref().ok()?;
            let c = fix.outline.circle;
            Some((c.x, c.r, fix.outline.rolling_radius(), offset(fix)?))
        })
        .collect();
    if marks.len() < 5 {
        return None;
    }
    let xs: Vec<f64> = marks.iter().map(|m| m.3.0).collect();
    let ys: Vec<f64> = marks.iter().map(|m| m.3.1).collect();
    let h = (middle(&xs)?, middle(&ys)?);
    let at: Vec<&(f64, f64, f64, (f64, f64))> =
        marks.iter().filter(|m| near(m.3, h, p.same_spot)).collect();
    if (at.len() as f64) < p.fixed_share * marks.len() as f64 {
        return None;
    }
    // How far the ball moved while the spot was there, over each run of marks at
    // it, each found before the ball rolled half a turn from the one before: a
    // drawn mark cannot come back to its place of the disc in less than a turn, so
    // within a run it stayed there. A drawn mark seen at one place once a turn
    // only (a turn of 2π/3 a frame, the rest of the turn below the centre, at a
    // low rate) stays in no run.
    let mut travel: f64 = 0.0;
    let mut start = 0;
    for i in 1..=at.len() {
        let ends = at
            .get(i)
            .zip(at.get(i - 1))
            .is_none_or(|(b, a)| (b.0 - a.0).abs() / a.2 >= std::f64::consts::PI);
        if ends {
            let x = at[start..i].iter().map(|m| m.0);
            travel += x.clone().fold(f64::NEG_INFINITY, f64::max) - x.fold(f64::INFINITY, f64::min);
            start = i;
        }
    }
    let r = at.first()?.1;
    (travel >= p.rolled * r).then_some(h)
}

/// The frames whose mark in `slot` stayed put in the picture while its ball moved
/// on, against the ball's previous frame with a mark (where it rolled under half a
/// turn meanwhile).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn still_marks(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let mut out = Vec::new();
    // The last frame with a mark: its index, the ball's centre and the mark, px.
    type Seen = (usize, (f64, f64), (f64, f64));
    let mut prev: Option<Seen> = None;
    for (k, f) in frames.iter().enumerate() {
        let Ok(fix) = &f[slot] else { continue };
        let Some(m) = fix.mark else { continue };
        let (c, m) = ((fix.outline.circle.x, fix.outline.circle.y), (m.x, m.y));
        // Only against a frame or two back: a mark seen again after about a whole
        // turn (hidden behind the rail meanwhile) is back near its place.
        if let Some((k0, c0, m0)) = prev.filter(|p| k - p.0 <= 2) {
            let moved = (c.0 - c0.0).hypot(c.1 - c0.1);
            let mark_moved = (m.0 - m0.0).hypot(m.1 - m0.1);
            // A drawn mark above the centre that turns by under half a turn moves
            // forward at least as far as its ball; turned by more, its way back
            // round the disc can cancel the ball's move (a fast ball at 30
            // frames/s, two frames apart), and the step tells nothing. Under half
            // a turn at 1.5 times the roll measured (room for kR's error).
            let judged = 1.5 * moved / fix.outline.rolling_radius() < std::f64::consts::PI;
            if judged && moved >= p.moved_px && mark_moved < p.still_share * moved {
                out.extend([k0, k]);
            }
        }
        prev = Some((k, c, m));
    }
    out.dedup();
    out
}

/// One fit of a ball, for the checks of single marks: its frame, centre (px), kR
/// (px: it rolls on the rails' edges, kR below its centre, the rail's top edge being
/// the outline's lowest point) and its mark's place in the disc (radii).
#[derive(Clone, Copy, Debug)]
struct BallFit {
    k: usize,
    centre: (f64, f64),
    /// The fitted radius, px, and the rolling radius kR.
    r: f64,
    kr: f64,
    mark: Option<(f64, f64)>,
}

impl BallFit {
    /// How far the ball rolled from this fit to `b`: its move over kR, rad.
    fn roll_to(&self, b: &BallFit) -> f64 {
        (b.centre.0 - self.centre.0).hypot(b.centre.1 - self.centre.1) / self.kr
    }

    /// The mark's angle about the centre, rad.
    fn angle(&self) -> Option<f64> {
        self.mark.map(|o| o.1.atan2(o.0))
    }
}

/// Every fit of `slot`, in frame order.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn seen(frames: &[FrameFixes], slot: usize) -> Vec<BallFit> {
    frames
        .iter()
        .enumerate()
        .filter_map(|(k, f)| {
            let fix = f[slot].as_ref().ok()?;
            let c = fix.outline.circle;
            Some(BallFit {
                k,
                centre: (c.x, c.y),
                r: c.r,
                kr: fix.outline.rolling_radius(),
                mark: offset(fix),
            })
        })
        .collect()
}

/// The frames whose mark in `slot` sits at one place of its disc in a run of marks
/// (each found before the ball rolled half a turn from the one before: too little for a
/// drawn mark to come round)
/// while the ball rolled on by [`MarkChecks::stay_roll`] rad or more: a drawn mark
/// turns as its ball rolls; compression blocks on the upper limb, a highlight or the
/// shading's darkest spot stay.
fn stayed_while_rolling(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let fits = seen(frames, slot);
    let marks: Vec<&BallFit> = fits.iter().filter(|f| f.mark.is_some()).collect();
    let mut out = Vec::new();
    for (i, a) in marks.iter().enumerate() {
        let Some(at) = a.mark else { continue };
        let mut run = vec![a.k];
        let mut last = *a;
        for b in marks.iter().skip(i + 1) {
            // A run goes on while the ball rolls under half a turn from its last
            // mark at the spot: a drawn mark needs a whole turn to come back there.
            if last.roll_to(b) >= std::f64::consts::PI {
                break;
            }
            if b.mark.is_some_and(|o| near(o, at, p.stay_within)) {
                run.push(b.k);
                last = b;
                if a.roll_to(b) >= p.stay_roll {
                    out.append(&mut run);
                }
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// The frames whose mark in `slot` agrees with no mark of the ball in the frames
/// around it ([`MarkChecks::confirm_frames`] each way) though some step to them can
/// be judged (the ball rolled by less than a quarter turn): a drawn mark seen in one
/// frame is seen, turned by about what the ball rolled, in the next or the one
/// before unless it turns behind the rail; a lone spot is not confirmed.
fn unconfirmed(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let fits = seen(frames, slot);
    let mut out = Vec::new();
    for a in &fits {
        let Some(ta) = a.angle() else { continue };
        let around: Vec<&BallFit> = fits
            .iter()
            .filter(|b| b.k != a.k && b.k.abs_diff(a.k) <= p.confirm_frames)
            .collect();
        let (mut judged, mut agrees) = (false, false);
        for b in &around {
            let roll = a.roll_to(b);
            // A frame around it without a mark: the mark may be hidden there.
            let Some(tb) = b.angle() else { continue };
            if roll >= std::f64::consts::FRAC_PI_2 {
                continue;
            }
            judged = true;
            let turn = turn_between(ta, tb);
            agrees |= turn.abs() <= p.turn_per_radius * roll + p.turn_slack;
        }
        // Alone: the ball seen before and after it, its mark in none of them (at the
        // clip's ends, or next to frames without the ball, a mark may be alone).
        let lone = around.iter().any(|b| b.k < a.k)
            && around.iter().any(|b| b.k > a.k)
            && around.iter().all(|b| b.mark.is_none());
        // Slow: under a tenth of a turn a frame, so that a drawn mark seen here
        // would be seen in a frame next to it too (it takes several frames to cross
        // the visible part of the disc): the step to a frame next to it, or the
        // ball's typical roll a frame about it (both neighbours' centres a few px
        // off, at a compressed clip's frames that repeat a picture, make each step
        // seem fast).
        let tenth = 0.1 * std::f64::consts::TAU;
        let slow = around
            .iter()
            .any(|b| a.roll_to(b) / (b.k.abs_diff(a.k) as f64) < tenth)
            || typical_roll(&fits, a, 4 * p.confirm_frames).is_some_and(|r| r < tenth);
        if (judged && !agrees) || (lone && slow) {
            out.push(a.k);
        }
    }
    out
}

/// The median roll a frame (rad) of the steps between the fits of its ball within
/// `window` frames of `a`, `None` without such a step.
fn typical_roll(fits: &[BallFit], a: &BallFit, window: usize) -> Option<f64> {
    let near: Vec<&BallFit> = fits
        .iter()
        .filter(|b| b.k.abs_diff(a.k) <= window)
        .collect();
    let rolls: Vec<f64> = near
        .windows(2)
        .filter_map(|w| {
            let [b, c] = w else { return None };
            Some(b.roll_to(c) / (c.k - b.k).max(1) as f64)
        })
        .collect();
    middle(&rolls)
}

/// The frames whose fit of `slot` has no other fit of its ball within
/// [`MarkChecks::confirm_frames`] either way: its mark is no check's to judge (each
/// judges a mark by the marks, or the fits, of the frames about it), and a wrong
/// mark is worse than none. The looks table's seed 24 at 240 frames/s kept a fit 12
/// and 9 frames from its ball's others, its centre 8.75 px off along the groove and
/// its "mark" 38 px from the drawn one: a third of the table's mark error.
fn alone_in_time(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let fits: Vec<usize> = seen(frames, slot).iter().map(|f| f.k).collect();
    fits.iter()
        .enumerate()
        .filter(|&(i, &k)| {
            let near = |j: usize| {
                fits.get(j)
                    .is_some_and(|&q| q.abs_diff(k) <= p.confirm_frames)
            };
            !(i.checked_sub(1).is_some_and(near) || near(i + 1))
        })
        .map(|(_, &k)| k)
        .collect()
}

/// The median of `v`, `None` when empty.
fn middle(v: &[f64]) -> Option<f64> {
    super::tracker::median(v)
}

/// The angle from `a` to `b` turned the short way, rad (−π … π).
fn turn_between(a: f64, b: f64) -> f64 {
    (b - a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

/// Each fit's speed along the picture's x, px a frame, from the fits either side of
/// it (or the one beside it at the ends); 0 for a ball seen once.
fn speeds(fits: &[BallFit]) -> Vec<f64> {
    (0..fits.len())
        .map(|i| {
            let a = fits.get(i.saturating_sub(1)).or(fits.get(i));
            let b = fits.get(i + 1).or(fits.get(i));
            match (a, b) {
                (Some(a), Some(b)) if b.k > a.k => (b.centre.0 - a.centre.0) / (b.k - a.k) as f64,
                _ => 0.0,
            }
        })
        .collect()
}

/// The marked frames of `slot` whose mark lies off where the ball's spin puts it
/// ([`MarkChecks::spin_frames`]): every other pair of marks a frame or two apart whose
/// step is under a quarter turn of roll gives a rate of turning, and carries its
/// nearer mark's angle on at that rate; a mark within reach of such pairs is left out
/// when it agrees with none. The rate may change between them as much as the ball's
/// speed does: by Δv / (kR) while it rolls, by 5 k Δv / (2R) while friction on the
/// rails, kR below the centre, slides it (spin from the same force that slows it).
fn off_the_spin(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let fits = seen(frames, slot);
    // (fit, its mark's angle, its speed along x).
    let marks: Vec<(&BallFit, f64, f64)> = fits
        .iter()
        .zip(speeds(&fits))
        .filter_map(|(f, v)| Some((f, f.angle()?, v)))
        .collect();
    // Each pair's two (frame, angle, speed), and its turn per frame.
    type End = (usize, f64, f64);
    let pairs: Vec<([End; 2], f64)> = marks
        .windows(2)
        .filter_map(|w| {
            let [(b, tb, vb), (c, tc, vc)] = w else {
                return None;
            };
            let apart = c.k - b.k;
            (apart <= 2 && b.roll_to(c) < std::f64::consts::FRAC_PI_2).then(|| {
                let rate = turn_between(*tb, *tc) / apart as f64;
                ([(b.k, *tb, *vb), (c.k, *tc, *vc)], rate)
            })
        })
        .collect();
    let off = |&(a, ta, va): &(&BallFit, f64, f64)| {
        let r = a.r.max(1.0);
        let k = (a.kr / r).clamp(0.2, 1.0);
        // How much the rate may change per px/frame of change in speed.
        let per = (1.0 / k + 2.5 * k) / r;
        let mut verdicts = pairs
            .iter()
            .filter(|([b, c], _)| b.0 != a.k && c.0 != a.k)
            .filter_map(|([b, c], rate)| {
                let near = if b.0.abs_diff(a.k) <= c.0.abs_diff(a.k) {
                    b
                } else {
                    c
                };
                (near.0.abs_diff(a.k) <= p.spin_frames).then(|| {
                    let steps = a.k as f64 - near.0 as f64;
                    let off = turn_between(near.1 + rate * steps, ta).abs();
                    off <= p.spin_slack + (p.spin_drift + per * (near.2 - va).abs()) * steps.abs()
                })
            })
            .peekable();
        verdicts.peek().is_some() && !verdicts.any(|agrees| agrees)
    };
    marks.iter().filter(|m| off(m)).map(|m| m.0.k).collect()
}

/// The marked frames of `slot` whose mark shows the same picture as the next or
/// previous frame's: two marks in consecutive frames whose place in the disc turned
/// by under [`MarkChecks::repeat_share`] of what the ball's spin turns it in a frame
/// (px at the mark's distance from the centre, where that is
/// [`MarkChecks::repeat_px`] or more). The spin is the marks' net turn a frame
/// about them ([`spin_about`]): a picture shown twice, then the next one, turns the
/// mark by none, then by two frames' worth, the same in all. A compressed clip's
/// frame that repeats its neighbour's picture (or blends it in) while the ball
/// spins, even in place after the impact, carries a stale mark a spin's frame or
/// more behind the drawn one's, and its centre too; which of the two is the frame's
/// own is not told, so both are left out.
fn shown_twice(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    let fits = seen(frames, slot);
    let marks: Vec<(usize, f64, (f64, f64))> = fits
        .iter()
        .filter_map(|f| Some((f.k, f.r.max(1.0), f.mark?)))
        .collect();
    let mut out = Vec::new();
    for w in marks.windows(2) {
        let [(ka, r, oa), (kb, _, ob)] = w else {
            continue;
        };
        if *kb != ka + 1 {
            continue;
        }
        let Some(rate) = spin_about(&marks, *ka, p.repeat_frames) else {
            continue;
        };
        // The mark's distance from the centre, and what the spin moves it by, px.
        let rho = 0.5 * (oa.0.hypot(oa.1) + ob.0.hypot(ob.1)) * r;
        let spun = rho * rate.abs();
        let turned = rho * turn_between(oa.1.atan2(oa.0), ob.1.atan2(ob.0)).abs();
        if spun >= p.repeat_px && turned < p.repeat_share * spun {
            out.extend([*ka, *kb]);
        }
    }
    out.dedup();
    out
}

/// The net turn a frame (rad, signed) of the marks `marks` (frame, radius, place in
/// the disc) within `window` frames of the pair of frames `k`, `k + 1`: the sum of the turns between
/// marks at most three frames apart over the frames they span (a step of more is
/// left out: a mark hidden meanwhile may have come round; three, so that a run of
/// pictures shown twice or three times is spanned with the turn after it). `None`
/// over fewer than four frames.
fn spin_about(marks: &[(usize, f64, (f64, f64))], k: usize, window: usize) -> Option<f64> {
    let near: Vec<&(usize, f64, (f64, f64))> = marks
        .iter()
        .filter(|m| m.0.abs_diff(k) <= window + 1)
        .collect();
    let (mut turned, mut spanned) = (0.0, 0usize);
    for w in near.windows(2) {
        let [a, b] = w else { continue };
        if b.0 - a.0 <= 3 {
            turned += turn_between(a.2.1.atan2(a.2.0), b.2.1.atan2(b.2.0));
            spanned += b.0 - a.0;
        }
    }
    (spanned >= 4).then(|| turned / spanned as f64)
}
