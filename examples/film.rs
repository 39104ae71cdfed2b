//! Writes a short synthetic clip of the paper-b4.9 preset as a folder of numbered PNG
//! frames (the test support's synthetic film, what the video tests track), for trying `--data FOLDER`
//! and the app's video view (`V`) without a camera:
//! `cargo run --example film -- /tmp/clip` then
//! `groovelab --data /tmp/clip --fps 100 --radius 2.75cm --width 4.9cm`.

use film::{Film, Look};
use groovelab::input::video::write;
use groovelab::physics::scene::Scene;

// The synthetic film is test support, shared with the tests and the benches.
#[path = "../tests/support/film/mod.rs"]
mod film;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args_os()
        .nth(1)
        .ok_or("usage: film FOLDER (written: frame0001.png …)")?;
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir)?;
    let preset = groovelab::input::preset::load("paper-b4.9")?;
    let lab = groovelab::lab::Lab::of_preset(preset)?;
    let scene: &Scene = &lab.scene;
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
