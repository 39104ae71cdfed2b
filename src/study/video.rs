//! Synthetic "videos" for testing the track import against truth: the exact solution's
//! left ball sampled at a frame rate, its centre and a mark on its rim seen from the
//! side, with seeded Gaussian noise, in the user's frame (origin, axis directions and
//! clip start of their choosing), written in every format `input::data` reads.

use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::study::measured::series::{Rule, Track, TrackParts};

mod normal;

/// How the synthetic video is taken and tracked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Video {
    /// Frames per second.
    pub fps: f64,
    /// Standard deviation of each tracked coordinate, m.
    pub noise: f64,
    /// Seed of the noise.
    pub seed: u64,
    /// First and last frame, s from the first impact.
    pub from: f64,
    pub to: f64,
    /// Track the rim mark too.
    pub mark: bool,
    /// The file's x points away from the other ball (the tracked ball comes from the
    /// right of the picture).
    pub flip_x: bool,
    /// The file's y points down (image coordinates).
    pub flip_y: bool,
    /// Where the centre is at the first impact, in the file's frame, m.
    pub origin: (f64, f64),
    /// The file's time of the first impact, s.
    pub t_impact: f64,
}

impl Default for Video {
    fn default() -> Self {
        Video {
            fps: 120.0,
            noise: 3e-4,
            seed: 1,
            from: -0.2,
            to: 0.8,
            mark: true,
            flip_x: false,
            flip_y: false,
            origin: (0.0, 0.0),
            t_impact: 0.2,
        }
    }
}

/// A small seeded Gaussian generator (SplitMix64 and Box–Muller): the same numbers on
/// every platform, so generated files can be committed and checked.
#[derive(Clone, Debug)]
pub struct Noise(u64);

impl Noise {
    pub fn new(seed: u64) -> Noise {
        Noise(seed ^ 0x9E37_79B9_7F4A_7C15)
    }

    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(normal::STEP);
        normal::uniform(self.0)
    }

    /// A standard normal number.
    pub fn gauss(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        normal::box_muller(u, v)
    }

    /// As many numbers as `out` holds, the ones [`Noise::gauss`] called as often
    /// gives, bit for bit, computed side by side in vector registers (a film's
    /// sensor noise, one number per pixel: 11 ns a number with AVX2 where glibc's
    /// `ln` and `cos` took 36).
    pub fn fill_gauss(&mut self, out: &mut [f64]) {
        normal::normals(self.0, out);
        let draws = 2 * out.len() as u64;
        self.0 = self.0.wrapping_add(draws.wrapping_mul(normal::STEP));
    }
}

/// The left ball of `scene` as a tracked video: its centre and (with `video.mark`) a
/// mark on its visible rim, at `x + R sin θ`, `y + R cos θ` with θ the spin angle
/// (on top at the first frame), in the file's frame.
pub fn track(scene: &Scene, video: &Video) -> Result<Track, Rule> {
    let sol = engine::solve(
        scene,
        &Span {
            t_start: video.from.min(-1e-3) - 0.01,
            t_end: Some(video.to + 0.01),
        },
    );
    let mut noise = Noise::new(video.seed);
    let sx = if video.flip_x { -1.0 } else { 1.0 };
    let sy = if video.flip_y { -1.0 } else { 1.0 };
    let r = scene.radius;
    let theta0 = sol.angle_at(video.from)[0];
    let frames = ((video.to - video.from) * video.fps).floor() as usize;
    let mut out = TrackParts {
        centre_name: "mass A".into(),
        mark_name: video.mark.then(|| "mass B".into()),
        format: "synthetic",
        mark: video.mark.then(|| (Vec::new(), Vec::new())),
        ..TrackParts::default()
    };
    for k in 0..=frames {
        let t = video.from + k as f64 / video.fps;
        let x = sol.at(t).left.x + r;
        let theta = sol.angle_at(t)[0] - theta0;
        out.t.push(video.t_impact + t);
        out.x
            .push(video.origin.0 + sx * x + video.noise * noise.gauss());
        out.y.push(video.origin.1 + video.noise * noise.gauss());
        if let Some((mx, my)) = out.mark.as_mut() {
            mx.push(video.origin.0 + sx * (x + r * theta.sin()) + video.noise * noise.gauss());
            my.push(video.origin.1 + sy * r * theta.cos() + video.noise * noise.gauss());
        }
    }
    Track::new(out)
}

/// The file formats `input::data` reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrackFormat {
    /// Tracker's single-track export of the centre (no mark), tab-separated,
    /// scientific notation, metres.
    TrackerSingle,
    /// Tracker's multi-track export, centre "mass A" and mark "mass B", tabs, metres.
    TrackerMulti,
    /// Comma-separated, units in the header: `t (s)`, `x (mm)`.
    CsvComma,
    /// Semicolon-separated with decimal commas, `t/ms`, `x (cm)`.
    CsvSemicolon,
    /// Tab-separated with units as suffixes (`t_s`, `x_m`) and a `rim` track.
    Tsv,
}

impl TrackFormat {
    pub const ALL: [TrackFormat; 5] = [
        TrackFormat::TrackerSingle,
        TrackFormat::TrackerMulti,
        TrackFormat::CsvComma,
        TrackFormat::CsvSemicolon,
        TrackFormat::Tsv,
    ];

    pub fn name(self) -> &'static str {
        match self {
            TrackFormat::TrackerSingle => "Tracker single-track",
            TrackFormat::TrackerMulti => "Tracker multi-track",
            TrackFormat::CsvComma => "CSV (comma)",
            TrackFormat::CsvSemicolon => "CSV (semicolon, decimal comma)",
            TrackFormat::Tsv => "TSV",
        }
    }
}

/// `track` as the text of a file in `format`; NaN becomes an empty cell.
pub fn write(track: &Track, format: TrackFormat) -> String {
    let (head, sep, t_unit, l_unit): (String, &str, f64, f64) = match format {
        TrackFormat::TrackerSingle => (format!("{}\nt\tx\ty", track.centre_name()), "\t", 1.0, 1.0),
        TrackFormat::TrackerMulti => (
            format!(
                "#multi:\n\t{}\t\t{}\t\nt\tx\ty\tx\ty",
                track.centre_name(),
                track.mark_name().unwrap_or("mass B")
            ),
            "\t",
            1.0,
            1.0,
        ),
        TrackFormat::CsvComma => (
            "t (s),x (mm),y (mm),x_mark (mm),y_mark (mm)".into(),
            ",",
            1.0,
            1e-3,
        ),
        TrackFormat::CsvSemicolon => (
            "t/ms;x (cm);y (cm);mark x (cm);mark y (cm)".into(),
            ";",
            1e-3,
            1e-2,
        ),
        TrackFormat::Tsv => ("t_s\tx_m\ty_m\tx rim\ty rim".into(), "\t", 1.0, 1.0),
    };
    let with_mark = format != TrackFormat::TrackerSingle && track.mark().is_some();
    let mut head = head;
    if !with_mark && format != TrackFormat::TrackerSingle {
        // Drop the mark's columns (and, for Tracker, its name).
        head = match format {
            TrackFormat::TrackerMulti => format!("#multi:\n\t{}\t\nt\tx\ty", track.centre_name()),
            _ => head.split(sep).take(3).collect::<Vec<_>>().join(sep),
        };
    }
    let cell = |v: f64, unit: f64| -> String {
        if !v.is_finite() {
            return String::new();
        }
        let v = v / unit;
        match format {
            TrackFormat::TrackerSingle | TrackFormat::TrackerMulti => format!("{v:.9E}"),
            TrackFormat::CsvSemicolon => format!("{v:.5}").replace('.', ","),
            _ => format!("{v:.7}"),
        }
    };
    let mut out = head;
    out.push('\n');
    for i in 0..track.t().len() {
        let mut row = vec![
            cell(track.t()[i], t_unit),
            cell(track.x()[i], l_unit),
            cell(track.y()[i], l_unit),
        ];
        if let (true, Some((mx, my))) = (with_mark, &track.mark()) {
            row.push(cell(mx[i], l_unit));
            row.push(cell(my[i], l_unit));
        }
        out += &row.join(sep);
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::Noise;

    /// A batch is the very numbers one at a time give, bit for bit, over lengths
    /// that end inside, at and past a batch.
    #[test]
    fn a_batch_of_normals_is_the_numbers_one_at_a_time() {
        for len in [0, 1, 63, 64, 65, 1000] {
            let (mut one, mut batch) = (Noise::new(len as u64), Noise::new(len as u64));
            let singly: Vec<u64> = (0..len).map(|_| one.gauss().to_bits()).collect();
            let mut out = vec![0.0; len];
            batch.fill_gauss(&mut out);
            assert_eq!(out.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), singly);
            // Both generators were left at the same place.
            assert_eq!(one.gauss().to_bits(), batch.gauss().to_bits());
        }
    }
}
