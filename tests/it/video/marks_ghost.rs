//! A "mark" that a compressed clip's frames carry along with the ball (issue 34, the
//! looks table's seed 16: steel balls, 240 frames/s, crf 40): where the drawn mark
//! was behind the rail, a dark spot rode along at one place of the disc in frames
//! whose pictures repeat earlier ones (their fits' centres stale by up to 12 px, left
//! out later as no ball's), and was kept as the mark, 28.6 and 35.6 px off. Two
//! checks of single marks leave such spots out: a lone mark whose neighbours' centres
//! are off (so that each step to them seems fast) is judged by the ball's typical
//! roll about it, and a mark whose only neighbours were left out as no ball's is
//! alone. Numbers as the tracker reported them, no pictures: cheap.

use super::marks_turn::{fix, marks_of};
use groovelab::vision::mark_check::{checked, leave_out_alone};
use groovelab::vision::params::MarkChecks;
use groovelab::vision::tracker::{FrameFixes, LeftOut};

/// The rails' top edge below a ball's centre, in radii (`marks_turn::fix`'s).
const K: f64 = 0.45;
const R: f64 = 45.0;
/// The drawn mark's distance from the centre, in radii.
const D: f64 = 0.5;

/// The ball's centre in frame `k`: rolling right at 5.5 px a frame (a quarter
/// radian of roll a frame).
fn centre(k: usize) -> (f64, f64) {
    (100.0 + 5.5 * k as f64, 400.0)
}

/// The drawn mark's angle from the top in frame `k`, turned by Δx / (kR).
fn angle(k: usize) -> f64 {
    (centre(k).0 - 100.0) / (K * R)
}

/// A point at `D` radii from the centre `c`, at `a` rad from the top.
fn at(c: (f64, f64), a: f64) -> (f64, f64) {
    (c.0 + D * R * a.sin(), c.1 - D * R * a.cos())
}

/// The drawn mark in frame `k` where it is seen (within 60° of the top).
fn drawn(k: usize) -> Option<(f64, f64)> {
    (angle(k).cos() > 0.5).then(|| at(centre(k), angle(k)))
}

/// The spot in frame `k`: at 80° from the top of the disc, where no drawn mark is
/// seen.
fn spot(k: usize) -> (f64, f64) {
    at(centre(k), 1.4)
}

/// The left ball's marks kept, by frame.
fn kept(frames: &[FrameFixes]) -> Vec<(usize, (f64, f64))> {
    marks_of(frames, 0)
}

/// 60 frames of the left ball with its drawn mark where seen.
fn clip() -> Vec<FrameFixes> {
    (0..60)
        .map(|k| {
            let (x, y) = centre(k);
            [fix(x, y, R, drawn(k)), Err(LeftOut::Unseen)]
        })
        .collect()
}

/// The middle of the first stretch of frames where the drawn mark is hidden.
fn hidden_middle() -> usize {
    (0..60)
        .find(|&k| angle(k) >= std::f64::consts::PI)
        .expect("the mark turns behind the rail")
}

/// A spot on the mark's circle where no drawn mark is seen, in frame `g`; the frames next
/// to it fitted with centres off (one stale by two frames' move, one 9 px ahead),
/// without a mark, and the frames beyond them not fitted: each step to a neighbour
/// seems a fast roll, the ball's typical roll about it is slow. The spot is left
/// out; every drawn mark is kept.
#[test]
fn a_lone_spot_between_fits_whose_centres_are_off_is_left_out() {
    let g = hidden_middle();
    let mut frames = clip();
    let (x, y) = centre(g);
    frames[g][0] = fix(x, y, R, Some(spot(g)));
    let stale = centre(g - 3);
    frames[g - 1][0] = fix(stale.0, stale.1, R, None);
    let ahead = centre(g + 1);
    frames[g + 1][0] = fix(ahead.0 + 9.0, ahead.1, R, None);
    frames[g - 2][0] = Err(LeftOut::Unseen);
    frames[g + 2][0] = Err(LeftOut::Unseen);
    let kept = kept(&checked(&frames, &MarkChecks::default()));
    assert!(
        !kept.iter().any(|(k, _)| *k == g),
        "the spot in frame {g} kept: {kept:?}"
    );
    let drawn: Vec<usize> = (0..60)
        .filter(|&k| drawn(k).is_some() && k.abs_diff(g) > 2)
        .collect();
    assert_eq!(kept.iter().map(|m| m.0).collect::<Vec<_>>(), drawn);
}

/// The same spot in frames `g` and `g + 1`, the second a frame whose picture repeats
/// the first's (its centre stale): the checks of single marks take each for the
/// other's confirmation. Once the repeated frame's fit is left out (as `tracks` does
/// with fits off the ball's motion), the spot has no fit of its ball within two frames
/// and is left out; the drawn marks are kept.
#[test]
fn a_mark_confirmed_only_by_a_fit_left_out_later_is_left_out() {
    let g = hidden_middle();
    let mut frames = clip();
    let (x, y) = centre(g);
    frames[g][0] = fix(x, y, R, Some(spot(g)));
    frames[g + 1][0] = fix(x, y, R, Some(spot(g)));
    for k in [g - 2, g - 1, g + 2] {
        frames[k][0] = Err(LeftOut::Unseen);
    }
    let p = MarkChecks::default();
    let mut out = checked(&frames, &p);
    assert!(
        kept(&out).iter().any(|(k, _)| *k == g),
        "the trap: the spot confirmed by its repeat"
    );
    // The repeat left out as no ball's (`tracks`'s odd fits).
    out[g + 1][0] = Err(LeftOut::Repeated);
    leave_out_alone(&mut out, &p);
    let kept = kept(&out);
    assert!(
        !kept.iter().any(|(k, _)| *k == g),
        "the spot in frame {g} kept: {kept:?}"
    );
    let drawn: Vec<usize> = (0..60)
        .filter(|&k| drawn(k).is_some() && (k + 2 < g || k > g + 2))
        .collect();
    assert_eq!(kept.iter().map(|m| m.0).collect::<Vec<_>>(), drawn);
}
