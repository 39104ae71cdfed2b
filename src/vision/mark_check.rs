//! Which marks found are a ball's own: a mark is drawn on the ball, so it turns with
//! it; a glossy highlight stays where the light puts it (the same spot of the disc
//! on both balls, frame after frame, however far the ball rolls), and a spot of the
//! wall seen through the search stays where it is in the picture while the ball moves
//! on. Marks of either kind are left out (the centre alone still gives the tracks);
//! a wrong mark is worse than none.

use super::tracker::FrameFixes;

/// Two spots of a disc this near (in radii) are one spot.
const SAME_SPOT: f64 = 0.08;

/// Share of a ball's marks at one spot of its disc that makes the spot a highlight,
/// when the ball moved by at least [`ROLLED`] radii meanwhile (a mark on a ball that
/// rolls one radius turns by one radian, and even a ball sliding after the impact
/// turns by half that over its sliding).
const FIXED_SHARE: f64 = 0.6;
const ROLLED: f64 = 2.0;

/// A mark that moves less than this share of its ball's move between two frames
/// stays put in the picture: a spot of the wall (a mark on a rolling ball moves at
/// a third of the ball's speed or more where it can be seen, above the rail).
const STILL_SHARE: f64 = 0.15;

/// Least move of the ball, px, between two frames for [`STILL_SHARE`] to tell.
const MOVED_PX: f64 = 2.0;

/// The frames (slot 0 the left ball, as `tracks::ordered` gives them) with every
/// mark that is not the ball's own left out.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
pub fn checked(frames: &[FrameFixes]) -> Vec<FrameFixes> {
    let mut out = frames.to_vec();
    let spot = common_spot(frames);
    let staying = staying_spot(frames);
    for slot in 0..2 {
        let own = spot.or_else(|| fixed_spot(frames, slot));
        for h in own.into_iter().chain(staying) {
            for f in out.iter_mut() {
                if let Ok(fix) = &mut f[slot]
                    && offset(fix).is_some_and(|o| near(o, h, 2.0 * SAME_SPOT))
                {
                    fix.mark = None;
                }
            }
        }
        for k in still_marks(&out, slot) {
            if let Some(Ok(fix)) = out.get_mut(k).map(|f| &mut f[slot]) {
                fix.mark = None;
            }
        }
        for k in off_the_circle(&out, slot) {
            if let Some(Ok(fix)) = out.get_mut(k).map(|f| &mut f[slot]) {
                fix.mark = None;
            }
        }
        if !turns_with_the_ball(&out, slot) {
            for f in out.iter_mut() {
                if let Ok(fix) = &mut f[slot] {
                    fix.mark = None;
                }
            }
        }
    }
    out
}

/// How far (in radii) a mark may lie from the circle its ball's marks keep to: a
/// drawn mark stays at one distance from the centre as the ball turns (the fit of
/// the spot's centroid moves it by a few hundredths of a radius).
const ON_CIRCLE: f64 = 0.12;

/// Share of a ball's marks that must keep to one circle about the centre for them
/// to be a drawn mark's (not a highlight here, a wall's spot there, the rail's edge).
const KEPT_SHARE: f64 = 0.6;

/// Fewest marks of a ball from which their circle is told.
const FEWEST_MARKS: usize = 5;

/// The frames whose mark in `slot` lies off the circle (about the centre) that the
/// ball's marks keep to, by more than [`ON_CIRCLE`] radii; every frame's mark when
/// fewer than [`KEPT_SHARE`] of them keep to one circle or that circle lies too near
/// the centre for an angle (a fifth of the radius) — then no mark is the ball's.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn off_the_circle(frames: &[FrameFixes], slot: usize) -> Vec<usize> {
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
    if at.len() < FEWEST_MARKS {
        return all();
    }
    let Some(d) = middle(&at.iter().map(|(_, d)| *d).collect::<Vec<_>>()) else {
        return all();
    };
    let off: Vec<usize> = at
        .iter()
        .filter(|(_, e)| (e - d).abs() > ON_CIRCLE)
        .map(|(k, _)| *k)
        .collect();
    if d < 0.2 || ((at.len() - off.len()) as f64) < KEPT_SHARE * at.len() as f64 {
        return all();
    }
    off
}

/// Largest turn of a drawn mark per radius its ball moves (a rolling ball turns by
/// one radian; 1.6 leaves room for the centroid's and the centre's errors), and
/// the turn allowed whatever the move, rad (noise on a mark at half the radius).
const TURN_PER_RADIUS: f64 = 1.6;
const TURN_SLACK: f64 = 0.35;

/// Share of the steps between a ball's marked frames that may turn faster than
/// rolling allows before its marks are taken for something else (a spot that jumps
/// between the mark, a highlight and the wall).
const JUMPS_SHARE: f64 = 0.2;

/// True when the marks of `slot` turn with the ball: between consecutive frames
/// with a mark, the mark's angle about the centre changes by no more than rolling
/// the ball's move turns it (plus noise), in most steps. A ball turns as it moves;
/// a spot that jumps by more is not one drawn mark.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn turns_with_the_ball(frames: &[FrameFixes], slot: usize) -> bool {
    let marked: Vec<(f64, f64, f64)> = frames
        .iter()
        .filter_map(|f| {
            let fix = f[slot].as_ref().ok()?;
            let o = offset(fix)?;
            let c = fix.outline.circle;
            Some((c.x, c.r, o.1.atan2(o.0)))
        })
        .collect();
    let steps = marked.len().saturating_sub(1);
    if steps < FEWEST_MARKS {
        return true;
    }
    // Per step between marked frames: the mark's turn and the ball's roll, rad.
    let turns: Vec<(f64, f64)> = marked
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let turn = (b.2 - a.2 + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            (turn.abs(), (b.0 - a.0).abs() / a.1.max(1.0))
        })
        .collect();
    let jumps = turns
        .iter()
        .filter(|(turn, roll)| *turn > TURN_PER_RADIUS * roll + TURN_SLACK)
        .count();
    // Over the clip, a drawn mark turns by a good part of what its ball rolled (all
    // of it rolling, less while a struck ball slides); a highlight or the shading's
    // darkest spot stays put in the disc however far the ball goes.
    let turned: f64 = turns.iter().map(|t| t.0).sum();
    let rolled: f64 = turns.iter().map(|t| t.1).sum();
    let stays = rolled >= MIN_ROLL && turned < LEAST_TURN_SHARE * rolled;
    (jumps as f64) <= JUMPS_SHARE * steps as f64 && !stays
}

/// Roll (rad, the ball's move over its radius, summed between marked frames) from
/// which a mark that does not turn is told from one that does …
const MIN_ROLL: f64 = 1.5;
/// … and the least share of that roll a drawn mark turns by (a struck ball slides
/// with its spin growing from none; over a clip with rolling in it, a third or more).
const LEAST_TURN_SHARE: f64 = 0.3;

/// A mark's place in its ball's disc, in radii from the centre.
fn offset(fix: &super::tracker::Fix) -> Option<(f64, f64)> {
    let c = fix.outline.circle;
    fix.mark
        .map(|m| ((m.x - c.x) / c.r.max(1.0), (m.y - c.y) / c.r.max(1.0)))
}

fn near(a: (f64, f64), b: (f64, f64), within: f64) -> bool {
    (a.0 - b.0).hypot(a.1 - b.1) < within
}

/// The spot of the disc where both balls' "marks" sit in most frames with both: a
/// highlight (two marks drawn on two balls meet at one spot of their discs only by
/// chance, and briefly).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn common_spot(frames: &[FrameFixes]) -> Option<(f64, f64)> {
    let pairs: Vec<((f64, f64), (f64, f64))> = frames
        .iter()
        .filter_map(|f| {
            let a = offset(f[0].as_ref().ok()?)?;
            let b = offset(f[1].as_ref().ok()?)?;
            Some((a, b))
        })
        .collect();
    if pairs.len() < 5 {
        return None;
    }
    let same = pairs
        .iter()
        .filter(|(a, b)| near(*a, *b, SAME_SPOT))
        .count();
    if same * 2 < pairs.len() {
        return None;
    }
    let xs: Vec<f64> = pairs.iter().flat_map(|(a, b)| [a.0, b.0]).collect();
    let ys: Vec<f64> = pairs.iter().flat_map(|(a, b)| [a.1, b.1]).collect();
    Some((middle(&xs)?, middle(&ys)?))
}

/// The spot of the disc where the "marks" of either ball sit most often, when they
/// sit there while their ball rolls on by [`ROLLED`] radii or more (summed over the
/// steps between frames with the mark there): a highlight, or the shading's darkest
/// spot, found in part of the frames and the drawn mark in others. A drawn mark
/// passes a spot of the disc as the ball turns, and stays there only while its ball
/// is at rest or slides without turning (a struck ball, briefly).
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn staying_spot(frames: &[FrameFixes]) -> Option<(f64, f64)> {
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
                .filter(|m| m.0 == slot && near(m.4, h, SAME_SPOT))
                .collect();
            let mut start = 0;
            for i in 1..=at.len() {
                let run_ends = i == at.len() || at[i].1 - at[i - 1].1 > 3;
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
    (rolled >= ROLLED).then_some(h)
}

/// The spot of its disc where one ball's "mark" sits in most frames while the ball
/// rolls on by [`ROLLED`] radii or more: a highlight.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn fixed_spot(frames: &[FrameFixes], slot: usize) -> Option<(f64, f64)> {
    let fixes: Vec<&super::tracker::Fix> = frames
        .iter()
        .filter_map(|f| f[slot].as_ref().ok())
        .collect();
    let offs: Vec<(f64, f64)> = fixes.iter().filter_map(|f| offset(f)).collect();
    if offs.len() < 5 {
        return None;
    }
    let xs: Vec<f64> = offs.iter().map(|o| o.0).collect();
    let ys: Vec<f64> = offs.iter().map(|o| o.1).collect();
    let h = (middle(&xs)?, middle(&ys)?);
    let at: Vec<&&super::tracker::Fix> = fixes
        .iter()
        .filter(|f| offset(f).is_some_and(|o| near(o, h, SAME_SPOT)))
        .collect();
    if (at.len() as f64) < FIXED_SHARE * offs.len() as f64 {
        return None;
    }
    let x = at.iter().map(|f| f.outline.circle.x);
    let travel = x.clone().fold(f64::NEG_INFINITY, f64::max) - x.fold(f64::INFINITY, f64::min);
    let r = at.first()?.outline.circle.r;
    (travel >= ROLLED * r).then_some(h)
}

/// The frames whose mark in `slot` stayed put in the picture while its ball moved
/// on, against the ball's previous frame with a mark.
#[allow(clippy::indexing_slicing)] // slots are 0 or 1 of a two-slot frame
fn still_marks(frames: &[FrameFixes], slot: usize) -> Vec<usize> {
    let mut out = Vec::new();
    // The last frame with a mark: its index, the ball's centre and the mark, px.
    type Seen = (usize, (f64, f64), (f64, f64));
    let mut prev: Option<Seen> = None;
    for (k, f) in frames.iter().enumerate() {
        let Ok(fix) = &f[slot] else { continue };
        let Some(m) = fix.mark else { continue };
        let (c, m) = ((fix.outline.circle.x, fix.outline.circle.y), (m.x, m.y));
        if let Some((k0, c0, m0)) = prev {
            let moved = (c.0 - c0.0).hypot(c.1 - c0.1);
            let mark_moved = (m.0 - m0.0).hypot(m.1 - m0.1);
            if moved >= MOVED_PX && mark_moved < STILL_SHARE * moved {
                out.extend([k0, k]);
            }
        }
        prev = Some((k, c, m));
    }
    out.dedup();
    out
}

/// The median of `v`, `None` when empty.
fn middle(v: &[f64]) -> Option<f64> {
    super::tracker::median(v)
}
