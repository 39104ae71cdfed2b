//! The measured series themselves, as plain data in SI units: what a reader makes of a
//! file ([`RawSeries`]: velocities, or a position track in the file's own frame) and
//! the left ball's velocities the fits and views use ([`Measured`]).

/// What a data file holds, as read: nothing here depends on the scene.
#[derive(Clone, Debug, PartialEq)]
pub enum RawSeries {
    /// Velocities (t, v_cm, v_t), impact at t = 0.
    Velocities(Measured),
    /// Positions of the centre (and a rim mark) in the file's frame; the velocities are
    /// derived by `measured::track` (v_t needs the scene's contact radius).
    Positions(Track),
}

/// A measured series of the left ball: time (s, first impact at 0), v_cm and v_t (m/s).
///
/// Velocity files fill `t`, `v_cm` and `v_t` only. A series derived from a position
/// track (`study::track`) also carries each derived point's standard uncertainty and
/// the tracked positions; its `v_t` is NaN where no rim mark was tracked.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Measured {
    pub t: Vec<f64>,
    pub v_cm: Vec<f64>,
    pub v_t: Vec<f64>,
    /// Standard uncertainty of each `v_cm`, m/s (from the local fit's residuals).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub v_cm_sigma: Option<Vec<f64>>,
    /// Standard uncertainty of each `v_t`, m/s (NaN where `v_t` is).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub v_t_sigma: Option<Vec<f64>>,
    /// The tracked centre, m: its displacement from where it was at the first impact,
    /// positive toward the other ball (the model's left ball is at `x − R`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub x: Option<Vec<f64>>,
    /// The rim mark's angle about the centre, rad, from its angle at the first impact,
    /// signed like the spin (`d angle/dt · r = v_t`); NaN where the mark is missing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle: Option<Vec<f64>>,
    /// How each derived velocity was made from the tracked frames: neighbouring points
    /// share frames, so their errors are correlated and a fit must not count them as
    /// independent (`study::fit` uses this for its ±).
    #[serde(skip)]
    pub stencils: Option<std::sync::Arc<Stencils>>,
    /// True when the file was recorded with x pointing away from the other ball (the
    /// ball approaches toward −x) and was read mirrored, x → −x, to match the model.
    #[serde(skip)]
    pub mirrored: bool,
    /// The relative standard error of the lengths' scale (a video's px per metre from
    /// the balls' fitted radius), where the file states one: every length, and so
    /// μ_k and v0, carries it besides the fit's own ±.
    #[serde(skip)]
    pub scale_rel_se: Option<f64>,
    /// The standard error of each point's `x`, m, where the track stated its points'
    /// σ (`groovelab track` does): the position fit weights by it.
    #[serde(skip)]
    pub x_sigma: Option<Vec<f64>>,
    /// The same for each point's `angle`, rad (NaN where the mark is missing).
    #[serde(skip)]
    pub angle_sigma: Option<Vec<f64>>,
}

/// The weights with which a derived velocity was made from tracked frames `lo..=hi`
/// (a local quadratic fit's slope is linear in the positions): frame k counts
/// `c₀ + c₁u + c₂u²` with `u = (t_k − t0)/h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stencil {
    pub lo: usize,
    pub hi: usize,
    pub t0: f64,
    pub h: f64,
    pub c: [f64; 3],
}

impl Stencil {
    /// (frame, weight) over the frames whose times are `times`.
    pub fn weights<'a>(&'a self, times: &'a [f64]) -> impl Iterator<Item = (usize, f64)> + 'a {
        // Frames past the end of `times` have no time, and so no weight.
        (self.lo..=self.hi).filter_map(move |k| {
            let u = (times.get(k)? - self.t0) / self.h;
            Some((k, self.c[0] + self.c[1] * u + self.c[2] * u * u))
        })
    }
}

/// The [`Stencil`] of each point of a series derived from a track, on the frames of
/// the centre (v_cm) and of the mark (v_t, whose frames may be fewer), times from the
/// first impact: how each derived velocity depends on the tracked coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stencils {
    pub centre_times: Vec<f64>,
    /// ±1: v_cm is this times the slope of the file's x.
    pub centre_sign: f64,
    pub v_cm: Vec<Option<Stencil>>,
    pub mark_times: Vec<f64>,
    /// For each mark frame: the centre's frame (index in `centre_times`), and how the
    /// angle v_t is the slope of (signed as v_t) moves with the centre's x and y there;
    /// with the mark's x and y it moves the opposite way.
    pub mark_frames: Vec<(usize, f64, f64)>,
    pub v_t: Vec<Option<Stencil>>,
    /// The scatter of one tracked coordinate, m (the centre's, from its third
    /// differences over the whole track; the mark's taken alike): the σ of each
    /// coordinate's noise that the stencils carry into the derived velocities.
    pub scatter: f64,
}

impl Measured {
    /// A velocity series without uncertainties or positions.
    pub fn velocities(t: Vec<f64>, v_cm: Vec<f64>, v_t: Vec<f64>) -> Measured {
        Measured {
            t,
            v_cm,
            v_t,
            ..Measured::default()
        }
    }

    /// A lab measurement's numbers stay within lab sizes: times within ±1e6 s, speeds
    /// within ±1000 m/s, positions within ±1000 m (NaN marks a missing value). Beyond
    /// them a series is not a measurement of this experiment, and squares of its
    /// numbers (residuals, energies) would overflow.
    pub fn check_magnitudes(&self) -> Result<(), OutOfLabRange> {
        let series: [(&'static str, Option<&[f64]>, f64, &'static str); 5] = [
            ("t", Some(&self.t), 1e6, "1e6 s"),
            ("v_cm", Some(&self.v_cm), 1e3, "1000 m/s"),
            ("v_t", Some(&self.v_t), 1e3, "1000 m/s"),
            ("x", self.x.as_deref(), 1e3, "1000 m"),
            ("angle", self.angle.as_deref(), 1e9, "1e9 rad"),
        ];
        for (name, values, limit, allowed) in series {
            if let Some((i, &value)) = values
                .into_iter()
                .flatten()
                .enumerate()
                .find(|(_, v)| v.abs() > limit)
            {
                return Err(OutOfLabRange {
                    name,
                    value,
                    point: i + 1,
                    allowed,
                });
            }
        }
        Ok(())
    }

    /// True when at least one v_t was measured (a velocity file, or a track with a mark).
    pub fn has_v_t(&self) -> bool {
        self.v_t.iter().any(|v| v.is_finite())
    }
}

/// A measured number beyond lab sizes ([`Measured::check_magnitudes`]): series
/// `name`'s `value` at `point` (1-based), SI, with the largest magnitude allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{name} = {value:e} (point {point}) is out of range, allowed |{name}| ≤ {allowed}")]
pub struct OutOfLabRange {
    pub name: &'static str,
    pub value: f64,
    pub point: usize,
    pub allowed: &'static str,
}

/// A position track in the file's own frame (origin, axis directions and time origin
/// as the user set them), SI units. Rows without a time are dropped; a missing cell
/// is NaN.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Track {
    /// Times, s, strictly increasing.
    pub t: Vec<f64>,
    /// The ball's centre, m.
    pub x: Vec<f64>,
    /// All NaN when the file has no y column for the centre.
    pub y: Vec<f64>,
    /// A mark on the ball's rim (x, y), m, when the file has one.
    pub mark: Option<(Vec<f64>, Vec<f64>)>,
    /// Name of the centre's track ("" for a plain `x, y` file).
    pub centre_name: String,
    pub mark_name: Option<String>,
    /// The format found: "Tracker multi-track", "Tracker single-track" or "CSV".
    pub format: &'static str,
    /// The relative standard error of the lengths' scale, where the file states one
    /// (`# scale = S ± σ px/m`, as `groovelab track` writes it).
    pub scale_rel_se: Option<f64>,
    /// Each frame's standard error of the centre's x and y, m, where the file states
    /// it (`groovelab track`'s `# σ` lines); NaN for a frame without one.
    pub sigma: Option<Vec<f64>>,
    /// The same for the rim mark, m.
    pub mark_sigma: Option<Vec<f64>>,
}

/// Two one-track exports with no frame in common: the centre's and the mark's first
/// and last times, s.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "no frame of the mark's track at a time of the centre's (centre t = {} … {} s, mark t = {} … {} s), expected two tracks of the same video",
    centre.0,
    centre.1,
    mark.0,
    mark.1
)]
pub struct NoCommonFrame {
    pub centre: (f64, f64),
    pub mark: (f64, f64),
}

/// One frame of a [`Track`], its columns read together: NaN where a cell is
/// missing (or the frame is past a column's end).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackFrame {
    pub t: f64,
    pub x: f64,
    pub y: f64,
    /// The rim mark's x and y, m; NaN without a mark.
    pub mark_x: f64,
    pub mark_y: f64,
}

impl TrackFrame {
    /// The mark's offset from the centre (x, y), m; NaN where either is missing.
    pub fn mark_offset(&self) -> (f64, f64) {
        (self.mark_x - self.x, self.mark_y - self.y)
    }
}

impl Track {
    /// Frame `i`, all its columns; a frame or cell the track does not have reads as
    /// NaN (a missing value), so a column shorter than the times is never read past
    /// its end.
    pub fn at(&self, i: usize) -> TrackFrame {
        let cell = |v: &[f64]| v.get(i).copied().unwrap_or(f64::NAN);
        let (mark_x, mark_y) = match &self.mark {
            Some((mx, my)) => (cell(mx), cell(my)),
            None => (f64::NAN, f64::NAN),
        };
        TrackFrame {
            t: cell(&self.t),
            x: cell(&self.x),
            y: cell(&self.y),
            mark_x,
            mark_y,
        }
    }

    /// This track (the ball's centre) with the centre of `other` as its rim mark, the
    /// mark's frames matched to this track's by time (within a quarter of a frame; a
    /// frame without a match is a missing mark). For two one-track exports of the same
    /// video.
    pub fn with_mark(mut self, other: &Track) -> Result<Track, NoCommonFrame> {
        let mut gaps: Vec<f64> = self
            .t
            .windows(2)
            .filter_map(|w| w.last().zip(w.first()).map(|(b, a)| b - a))
            .collect();
        gaps.sort_by(f64::total_cmp);
        let frame = gaps.get(gaps.len() / 2).copied().unwrap_or(f64::INFINITY);
        let (mut mx, mut my) = (Vec::new(), Vec::new());
        let mut matched = 0;
        for &t in &self.t {
            let j = other.t.partition_point(|&s| s < t - 0.25 * frame);
            match other.t.get(j).filter(|&&s| (s - t).abs() <= 0.25 * frame) {
                Some(_) => {
                    matched += 1;
                    let f = other.at(j);
                    mx.push(f.x);
                    my.push(f.y);
                }
                None => {
                    mx.push(f64::NAN);
                    my.push(f64::NAN);
                }
            }
        }
        if matched == 0 {
            let span = |t: &[f64]| {
                let end = |v: Option<&f64>| v.copied().unwrap_or(f64::NAN);
                (end(t.first()), end(t.last()))
            };
            return Err(NoCommonFrame {
                centre: span(&self.t),
                mark: span(&other.t),
            });
        }
        self.mark = Some((mx, my));
        self.mark_name = Some(other.centre_name.clone());
        self.format = match self.format {
            "Tracker single-track" => "two Tracker single-track files",
            _ => "two files",
        };
        Ok(self)
    }
}
