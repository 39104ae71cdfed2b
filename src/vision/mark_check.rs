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
    for slot in 0..2 {
        let own = spot.or_else(|| fixed_spot(frames, slot));
        if let Some(h) = own {
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
    }
    out
}

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
