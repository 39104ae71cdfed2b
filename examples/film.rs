//! Writes a short synthetic clip of the paper-b4.9 preset (the test support's
//! synthetic film, what the video tests track), for trying `--data FOLDER` and the
//! app's video view (`V`) without a camera:
//! `cargo run --example film -- /tmp/clip` writes the default look as a folder of
//! numbered PNG frames, then
//! `groovelab --data /tmp/clip --fps 100 --radius 2.75cm --width 4.9cm`.
//! `cargo run --example film -- /tmp/look7 7` writes random look 7 of the looks table
//! (full size; `7 small` for the small looks of `cargo test`) as `clip.mp4`, and says
//! its rate, the truth's scale and the look in words, to watch the tracker on it
//! (`7 long`: the same full look filmed for 3 s, to time `track` on a clip of the
//! speed target's length):
//! `groovelab track /tmp/look7/clip.mp4 --fps RATE --radius 2.75cm --overlay /tmp/look7/o.png`.
//! With `FILM_TRUTH=1` it also writes each frame's true centres and radius to stderr
//! (`T<frame> (x, y) (x, y) r<R>`, px), to hold the tracker's fits against; with
//! `FILM_FIRST=N`, only its first N frames (a row of the looks table's `LOOKS_FIRST=N`).
//! `cargo run --release --example film -- /tmp/speed speed` writes the speed clip of
//! `benches/video.rs` (3 s of 1080p at 240 frames/s) as `clip.mp4`, to time `track`
//! against ffmpeg's decoding outside criterion (BENCHMARKS.md says how).

use film::looks::{self, Size};
use film::{Film, Look, h264};
use groovelab::input::video::write;
use groovelab::physics::scene::Scene;

// The synthetic film is test support, shared with the tests and the benches.
#[path = "../tests/support/film/mod.rs"]
mod film;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    const USAGE: &str =
        "usage: film FOLDER [SEED [small | long] | speed] (written: frame0001.png … or clip.mp4)";
    let mut args = std::env::args().skip(1);
    // `film --help` prints the usage; it made a folder named `--help`.
    let dir = args.next().filter(|d| !d.starts_with('-')).ok_or(USAGE)?;
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir)?;
    let preset = groovelab::input::preset::load("paper-b4.9")?;
    let lab = groovelab::lab::Lab::of_preset(preset)?;
    let scene: &Scene = &lab.scene;
    let which = args.next();
    if which.as_deref() == Some("speed") {
        let path = dir.join("clip.mp4");
        h264::speed_clip(&path, scene)?;
        println!(
            "{} frames in {} (1920×1080, 240 frames/s)",
            h264::SPEED_CLIP_FRAMES,
            path.display()
        );
        return Ok(());
    }
    if let Some(seed) = which {
        let seed: u64 = seed
            .parse()
            .map_err(|_| format!("error: SEED {seed:?}: a whole number expected"))?;
        let (size, long) = match args.next().as_deref() {
            Some("small") => (Size::Small, false),
            None | Some("full") => (Size::Full, false),
            Some("long") => (Size::Full, true),
            Some(other) => {
                return Err(format!("error: size {other:?}: small, full or long").into());
            }
        };
        let mut clip = looks::random(scene, seed, size);
        if long {
            // The same look filmed for 3 s from its start (the speed target's length).
            let to = clip.film.look.from + 3.0;
            clip.film = Film::new(scene, clip.film.look, to);
            clip.frames = clip.film.frames_to(to);
        }
        // `FILM_FIRST=45`: only the first 45 frames, as the looks table's
        // `LOOKS_FIRST=45` cuts them (to watch a cut clip's row).
        if let Some(k) = std::env::var("FILM_FIRST")
            .ok()
            .and_then(|v| v.parse().ok())
        {
            clip.frames = clip.frames.min(k);
        }
        let path = dir.join("clip.mp4");
        h264::write(&path, &clip.film, clip.frames)?;
        let l = &clip.film.look;
        if std::env::var_os("FILM_TRUTH").is_some() {
            print_truth(&clip.film, clip.frames);
        }
        println!(
            "{} frames in {} ({}×{}, {} frames/s, the first {:.3} s before the impact; truth: {:.2} px/m, R {:.2} px)\n{}",
            clip.frames,
            path.display(),
            l.width,
            l.height,
            l.fps,
            -l.from,
            clip.film.px_per_m(),
            scene.radius * clip.film.px_per_m(),
            clip.name
        );
        return Ok(());
    }
    // 640×360 at 1000 px/m, 100 frames/s from 0.15 s before the impact.
    let look = Look {
        width: 640,
        height: 360,
        px_per_m: 1000.0,
        origin: (320.0, 170.0),
        from: -0.15,
        ..Look::default()
    };
    let film = Film::new(scene, look, 0.35);
    let frames = ((0.35 - look.from) * look.fps).round() as usize;
    for k in 0..frames {
        let path = dir.join(format!("frame{:04}.png", k + 1));
        write::png(&path, &film.rgb(k), look.width, look.height)?;
    }
    println!("{frames} frames in {}", dir.display());
    Ok(())
}

/// Each frame's true centres (left, right) and radius, px, one line a frame on stderr.
fn print_truth(film: &Film, frames: usize) {
    for k in 0..frames {
        let [a, b] = film.truth(k);
        eprintln!(
            "T{k} ({:.1},{:.1}) ({:.1},{:.1}) r{:.2}",
            a.centre.0, a.centre.1, b.centre.0, b.centre.1, a.radius
        );
    }
}
