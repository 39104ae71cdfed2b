//! A mark at the rail's edge (issue 34, the looks table's seed 22: wooden balls with
//! a dark mark, 1080p, 100 frames/s, crf 34). In frame 36 the left ball's mark is low
//! in its disc, its lower part hidden or darkened by the strip above the rail, which
//! the shading's plane fitted on the ring about it does not follow: its centroid was
//! found 3.5 px above the drawn mark, its disc reaching to 1.1 px of the rail's edge.
//! A mark whose disc comes within a tenth of its radius of the rail is not taken
//! (`mark::RAIL_CLEAR`).

use crate::film::looks::Size;
use groovelab::vision::circle::{Circle, Outline};
use groovelab::vision::{Params, mark};

#[test]
fn a_mark_at_the_rails_edge_is_not_taken_high() {
    if !crate::video::tracking::ffmpeg() {
        return;
    }
    // The look's first 44 frames only (of 84), for the test's time.
    let clip = crate::film::looks::random(&crate::common::paper_scene(), 22, Size::Full);
    let path = crate::common::scratch_dir("mark_rail", "Full_22").join("clip.mp4");
    crate::film::h264::write(&path, &clip.film, 44).unwrap();
    let limits = groovelab::input::video::Limits::default();
    let (_, frames) = groovelab::input::video::open(&path, &limits).unwrap();
    let frames: Vec<_> = frames.map(|f| f.unwrap().1).collect();
    let film = &clip.film;
    let p = Params::default();
    let mut found = Vec::new();
    // The left ball's frames as its mark comes down to the rail and goes under it
    // (the frames before, 31 and 32, give marks 3.2 px off on the true outline, which
    // the tracker's checks leave out: not this test's).
    for k in 33..=40 {
        let Some(frame) = frames.get(k) else { break };
        let t = film.truth(k)[0];
        let (cx, cy, r) = (t.centre.0, t.centre.1, t.radius);
        let ball = Outline {
            circle: Circle { x: cx, y: cy, r },
            sigma: [0.05; 3],
            rms: 0.3,
            points: 200,
            coverage: 0.7,
            sectors: 0,
            // The rail's top edge (the look is not tilted).
            lowest: cy + film.scene.k() * r,
            polarity: 1.0,
        };
        let levels = (p.mark_sigmas, p.mark_levels, p.mark_cut);
        if let Some(m) = mark::find(&frame.luma, &ball, 1.5, -1.0, levels).mark {
            found.push((k, (m.x - t.mark.0).hypot(m.y - t.mark.1)));
        }
    }
    let worst = found.iter().map(|f| f.1).fold(0.0, f64::max);
    assert!(worst < 2.5, "a mark over 2.5 px off: {found:?}");
    assert!(found.len() >= 4, "{} marks found: {found:?}", found.len());
}
