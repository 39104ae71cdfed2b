//! A video given as `--data` everywhere data are read: `data`, `fit`, `render` and
//! the app, from a folder of frames rendered here (small: no ffmpeg needed) or an mp4
//! (where ffmpeg is installed; CI has it). The app tracks on a worker, shows how far,
//! takes the data in when done and keeps them; `V` draws the frame at the cursor with
//! the tracked points and the model's balls over it.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use groovelab::input::video::write;
use groovelab::physics::scene::Scene;
use groovelab::study::preset::Preset;
use groovelab::study::vision::render::{Film, Look};

fn scene() -> Scene {
    Preset::load("paper-b4.9").unwrap().spec.resolve().unwrap().0
}

/// A small clip: 320×180 at 500 px/m (R = 13.75 px), 100 frames/s, t = −0.15 … 0.34 s.
pub fn look() -> Look {
    Look {
        width: 320,
        height: 180,
        px_per_m: 500.0,
        origin: (160.0, 85.0),
        from: -0.15,
        ..Look::default()
    }
}

pub const FRAMES: usize = 50;

/// The small clip as a folder of PNG frames (made once per test run).
pub fn folder() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let d = std::env::temp_dir().join(format!(
            "groovelab-video-app-{}-frames",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        let look = look();
        let film = Film::new(&scene(), look, 0.4);
        for k in 0..FRAMES {
            let p = d.join(format!("frame{:04}.png", k + 1));
            write::png(&p, &film.rgb(k), look.width, look.height).unwrap();
        }
        d
    })
}

#[test]
#[ignore]
fn make_folder_for_trying() {
    let d = folder();
    let to = Path::new("/tmp/va/frames");
    let _ = std::fs::remove_dir_all(to);
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(d).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
}
