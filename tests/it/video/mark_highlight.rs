//! The mark is never a glossy highlight (issue 34, looks table seed 3: a black glossy
//! ball with a light mark, mark RMS 10.9 px with centres within 0.04 px). Where the
//! drawn mark turns behind the rail, the brightest spot left in the disc is the
//! highlight, at the mark's own distance from the centre in that look, and it was
//! reported as the mark. A small film of that look, tracked in memory: the spots
//! that stay at one place of both discs are found and no mark is taken there.

use crate::common::preset_scene;
use crate::film::paint::{Finish, Paint, Texture};
use crate::film::{Film, Look};
use groovelab::vision::{self, Params, mark_check, tracks};

/// 480×180, R 16.5 px, 60 frames/s from 0.3 s before the impact to 0.28 s after: black glossy balls
/// with a light mark at 0.47 R (the highlight's distance), on a light plain wall
/// behind a dark rail.
fn look() -> Look {
    Look {
        width: 480,
        height: 180,
        px_per_m: 600.0,
        origin: (240.0, 80.0),
        fps: 60.0,
        from: -0.3,
        mark_at: 0.47,
        mark_size: 0.15,
        paint: Paint {
            ball: [30.0, 30.0, 33.0],
            finish: Finish::Glossy {
                ambient: 0.5,
                strength: 0.8,
            },
            mark: [250.0, 250.0, 245.0],
            wall: ([200.0, 200.0, 195.0], [200.0, 200.0, 195.0]),
            texture: Texture::Plain,
            rail: [60.0, 60.0, 60.0],
            rail_height: 1.5,
            ..Paint::default()
        },
        ..Look::default()
    }
}

#[test]
fn a_highlight_where_the_mark_hides_behind_the_rail_is_not_the_mark() {
    let film = Film::new(&preset_scene("paper-b4.9"), look(), 0.3);
    let n = 36;
    let images: Vec<_> = (0..n).map(|k| film.frame(k)).collect();
    let params = Params::default();
    let tracker = vision::track(&images, params);
    let frames = tracks::ordered(&tracker.frames);
    // Each mark (found, true), before and after the checks.
    let pairs = |frames: &[vision::tracker::FrameFixes]| -> Vec<(f64, usize)> {
        let mut out = Vec::new();
        for (k, fixes) in frames.iter().enumerate() {
            for fix in fixes.iter().flatten() {
                let Some(m) = fix.mark else { continue };
                let c = fix.outline.circle;
                let t = film.ball_nearest(k, (c.x, c.y));
                out.push(((m.x - t.mark.0).hypot(m.y - t.mark.1), k));
            }
        }
        out
    };
    let fits = frames.iter().flatten().filter(|f| f.is_ok()).count();
    assert!(fits >= 2 * n - 4, "{fits} fits of {n} frames");
    // The look has the trap: some spot found is far from the drawn mark (the
    // highlight, where the mark is hidden).
    let raw = pairs(&frames);
    assert!(
        raw.iter().any(|(e, _)| *e > 4.0),
        "no wrong spot to leave out: {raw:?}"
    );
    // Kept: only the drawn mark, to a fraction of a pixel; and in some frames (a
    // check that kept none would pass the first; the mark turns by 1.3 rad a frame
    // and is measured above the rail in about a third of them).
    let kept = pairs(&mark_check::checked(&frames, &params.marks));
    let worst = kept.iter().map(|p| p.0).fold(0.0, f64::max);
    assert!(
        worst < 1.0,
        "a mark {worst:.1} px from the drawn one: {kept:?}"
    );
    assert!(kept.len() >= 6, "{} marks kept of {fits} fits", kept.len());
}
