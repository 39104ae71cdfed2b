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
/// Built only by [`Measured::new`] (or [`Measured::velocities`]), which keeps its
/// rules ([`Rule`]): every column has one value per time, the times are finite and
/// strictly increasing, every value is finite or a gap (NaN: a point without that
/// value, e.g. v_t where no rim mark was tracked; never ±∞), and every σ is ≥ 0. An
/// empty series is allowed; each caller asks for the points it needs (the fits
/// refuse too few). Its columns are read through accessors (`t()`, `v_cm()`, …).
///
/// Velocity files fill `t`, `v_cm` and `v_t` only. A series derived from a position
/// track (`study::track`) also carries each derived point's standard uncertainty and
/// the tracked positions; its `v_t` is NaN where no rim mark was tracked.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Measured {
    t: Vec<f64>,
    v_cm: Vec<f64>,
    v_t: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    v_cm_sigma: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    v_t_sigma: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    x: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    angle: Option<Vec<f64>>,
    #[serde(skip)]
    stencils: Option<std::sync::Arc<Stencils>>,
    #[serde(skip)]
    mirrored: bool,
    #[serde(skip)]
    spin_turned: bool,
    #[serde(skip)]
    scale_rel_se: Option<f64>,
    #[serde(skip)]
    x_sigma: Option<Vec<f64>>,
    #[serde(skip)]
    angle_sigma: Option<Vec<f64>>,
}

/// The columns of a [`Measured`] before their rules are checked: what a reader or a
/// derivation fills in, then hands to [`Measured::new`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeasuredParts {
    pub t: Vec<f64>,
    pub v_cm: Vec<f64>,
    pub v_t: Vec<f64>,
    /// Standard uncertainty of each `v_cm`, m/s (from the local fit's residuals).
    pub v_cm_sigma: Option<Vec<f64>>,
    /// Standard uncertainty of each `v_t`, m/s (NaN where `v_t` is).
    pub v_t_sigma: Option<Vec<f64>>,
    /// The tracked centre, m: its displacement from where it was at the first impact,
    /// positive toward the other ball (the model's left ball is at `x − R`).
    pub x: Option<Vec<f64>>,
    /// The rim mark's angle about the centre, rad, from its angle at the first impact,
    /// signed like the spin (`d angle/dt · r = v_t`); NaN where the mark is missing.
    pub angle: Option<Vec<f64>>,
    /// How each derived velocity was made from the tracked frames: neighbouring points
    /// share frames, so their errors are correlated and a fit must not count them as
    /// independent (`study::fit` uses this for its ±).
    pub stencils: Option<std::sync::Arc<Stencils>>,
    /// True when the file was recorded with x pointing away from the other ball (the
    /// ball approaches toward −x) and was read mirrored, x → −x, to match the model.
    pub mirrored: bool,
    /// True when a velocity file's v_t ran opposite to its v_cm while the ball rolled
    /// before the impact (v_t signed the other way round) and was read turned, v_t →
    /// −v_t.
    pub spin_turned: bool,
    /// The relative standard error of the lengths' scale (a video's px per metre from
    /// the balls' fitted radius), where the file states one: every length, and so
    /// μ_k and v0, carries it besides the fit's own ±.
    pub scale_rel_se: Option<f64>,
    /// The standard error of each point's `x`, m, where the track stated its points'
    /// σ (`groovelab track` does): the position fit weights by it.
    pub x_sigma: Option<Vec<f64>>,
    /// The same for each point's `angle`, rad (NaN where the mark is missing).
    pub angle_sigma: Option<Vec<f64>>,
}

/// A rule of a [`Measured`] or a [`Track`] that the values given to its constructor
/// break: which column, which point (1-based), and what is allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Rule {
    #[error("{name} has {len} values for {times} times, expected one value per time")]
    Length {
        name: &'static str,
        len: usize,
        times: usize,
    },
    #[error("t = {value} s (point {point}) is not a finite time, allowed finite seconds")]
    TimeNotFinite { value: f64, point: usize },
    #[error(
        "t = {value} s (point {point}) does not increase (previous {previous} s), allowed strictly increasing times"
    )]
    TimeNotRising {
        value: f64,
        previous: f64,
        point: usize,
    },
    #[error(
        "{name} = {value} (point {point}) is infinite, allowed a finite value or a gap (empty or NaN)"
    )]
    Infinite {
        name: &'static str,
        value: f64,
        point: usize,
    },
    #[error("{name} = {value} (point {point}) is negative, allowed an uncertainty ≥ 0")]
    NegativeSigma {
        name: &'static str,
        value: f64,
        point: usize,
    },
    #[error("the scale's relative standard error {value} is not a finite number ≥ 0")]
    ScaleSe { value: f64 },
}

/// Finite, strictly increasing times.
fn check_times(t: &[f64]) -> Result<(), Rule> {
    if let Some((i, &value)) = t.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(Rule::TimeNotFinite {
            value,
            point: i + 1,
        });
    }
    match t.windows(2).enumerate().find_map(|(i, w)| match *w {
        [a, b] if b <= a => Some((i, a, b)),
        _ => None,
    }) {
        Some((i, previous, value)) => Err(Rule::TimeNotRising {
            value,
            previous,
            point: i + 2,
        }),
        None => Ok(()),
    }
}

/// Column `name` has one value per time, each finite or NaN (a gap); a σ is ≥ 0 too.
fn check_column(name: &'static str, v: &[f64], times: usize, sigma: bool) -> Result<(), Rule> {
    if v.len() != times {
        return Err(Rule::Length {
            name,
            len: v.len(),
            times,
        });
    }
    if let Some((i, &value)) = v.iter().enumerate().find(|(_, v)| v.is_infinite()) {
        return Err(Rule::Infinite {
            name,
            value,
            point: i + 1,
        });
    }
    match v.iter().enumerate().find(|(_, v)| sigma && **v < 0.0) {
        Some((i, &value)) => Err(Rule::NegativeSigma {
            name,
            value,
            point: i + 1,
        }),
        None => Ok(()),
    }
}

/// An optional column, checked like [`check_column`] where present.
fn check_optional(
    name: &'static str,
    v: Option<&[f64]>,
    times: usize,
    sigma: bool,
) -> Result<(), Rule> {
    v.map_or(Ok(()), |v| check_column(name, v, times, sigma))
}

/// A relative standard error, where given, is finite and ≥ 0.
fn check_scale_se(se: Option<f64>) -> Result<(), Rule> {
    match se {
        Some(value) if !(value.is_finite() && value >= 0.0) => Err(Rule::ScaleSe { value }),
        _ => Ok(()),
    }
}

impl Measured {
    /// The series `parts`, if it keeps the rules of [`Measured`]; else the first rule
    /// broken.
    pub fn new(parts: MeasuredParts) -> Result<Measured, Rule> {
        let n = parts.t.len();
        check_times(&parts.t)?;
        check_column("v_cm", &parts.v_cm, n, false)?;
        check_column("v_t", &parts.v_t, n, false)?;
        check_optional("v_cm σ", parts.v_cm_sigma.as_deref(), n, true)?;
        check_optional("v_t σ", parts.v_t_sigma.as_deref(), n, true)?;
        check_optional("x", parts.x.as_deref(), n, false)?;
        check_optional("angle", parts.angle.as_deref(), n, false)?;
        check_optional("x σ", parts.x_sigma.as_deref(), n, true)?;
        check_optional("angle σ", parts.angle_sigma.as_deref(), n, true)?;
        check_scale_se(parts.scale_rel_se)?;
        let MeasuredParts {
            t,
            v_cm,
            v_t,
            v_cm_sigma,
            v_t_sigma,
            x,
            angle,
            stencils,
            mirrored,
            spin_turned,
            scale_rel_se,
            x_sigma,
            angle_sigma,
        } = parts;
        Ok(Measured {
            t,
            v_cm,
            v_t,
            v_cm_sigma,
            v_t_sigma,
            x,
            angle,
            stencils,
            mirrored,
            spin_turned,
            scale_rel_se,
            x_sigma,
            angle_sigma,
        })
    }

    /// A velocity series without uncertainties or positions, if it keeps the rules.
    pub fn velocities(t: Vec<f64>, v_cm: Vec<f64>, v_t: Vec<f64>) -> Result<Measured, Rule> {
        Measured::new(MeasuredParts {
            t,
            v_cm,
            v_t,
            ..MeasuredParts::default()
        })
    }

    /// The series with no points.
    pub fn empty() -> Measured {
        Measured {
            t: Vec::new(),
            v_cm: Vec::new(),
            v_t: Vec::new(),
            v_cm_sigma: None,
            v_t_sigma: None,
            x: None,
            angle: None,
            stencils: None,
            mirrored: false,
            spin_turned: false,
            scale_rel_se: None,
            x_sigma: None,
            angle_sigma: None,
        }
    }

    /// Its columns, to change and check again with [`Measured::new`].
    pub fn into_parts(self) -> MeasuredParts {
        let Measured {
            t,
            v_cm,
            v_t,
            v_cm_sigma,
            v_t_sigma,
            x,
            angle,
            stencils,
            mirrored,
            spin_turned,
            scale_rel_se,
            x_sigma,
            angle_sigma,
        } = self;
        MeasuredParts {
            t,
            v_cm,
            v_t,
            v_cm_sigma,
            v_t_sigma,
            x,
            angle,
            stencils,
            mirrored,
            spin_turned,
            scale_rel_se,
            x_sigma,
            angle_sigma,
        }
    }

    /// A copy of its columns ([`Measured::into_parts`] of a clone).
    pub fn to_parts(&self) -> MeasuredParts {
        self.clone().into_parts()
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// True without points.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Times, s, first impact at 0: finite, strictly increasing.
    pub fn t(&self) -> &[f64] {
        &self.t
    }
    /// The centre's velocity, m/s, one per time (NaN: a gap).
    pub fn v_cm(&self) -> &[f64] {
        &self.v_cm
    }
    /// The rim's velocity, m/s, one per time (NaN where no mark was tracked).
    pub fn v_t(&self) -> &[f64] {
        &self.v_t
    }
    /// Standard uncertainty of each `v_cm`, m/s.
    pub fn v_cm_sigma(&self) -> Option<&[f64]> {
        self.v_cm_sigma.as_deref()
    }
    /// Standard uncertainty of each `v_t`, m/s (NaN where `v_t` is).
    pub fn v_t_sigma(&self) -> Option<&[f64]> {
        self.v_t_sigma.as_deref()
    }
    /// The tracked centre, m, from where it was at the first impact, toward the other
    /// ball.
    pub fn x(&self) -> Option<&[f64]> {
        self.x.as_deref()
    }
    /// The rim mark's angle from the first impact, rad, signed like the spin.
    pub fn angle(&self) -> Option<&[f64]> {
        self.angle.as_deref()
    }
    /// How each derived velocity was made from the tracked frames.
    pub fn stencils(&self) -> Option<&std::sync::Arc<Stencils>> {
        self.stencils.as_ref()
    }
    /// True when the file was read mirrored (x → −x).
    pub fn mirrored(&self) -> bool {
        self.mirrored
    }

    /// True when a velocity file's v_t was read turned (v_t → −v_t).
    pub fn spin_turned(&self) -> bool {
        self.spin_turned
    }
    /// The relative standard error of the lengths' scale, where the file states one.
    pub fn scale_rel_se(&self) -> Option<f64> {
        self.scale_rel_se
    }
    /// The standard error of each point's `x`, m.
    pub fn x_sigma(&self) -> Option<&[f64]> {
        self.x_sigma.as_deref()
    }
    /// The standard error of each point's `angle`, rad.
    pub fn angle_sigma(&self) -> Option<&[f64]> {
        self.angle_sigma.as_deref()
    }

    /// The points whose index `keep` accepts, every column (and the stencils' per-point
    /// lists) cut alike: the rules hold for any subset (times still increase), so no
    /// check is needed.
    pub fn retain_points(&self, keep: impl Fn(usize) -> bool) -> Measured {
        let pick = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .enumerate()
                .filter(|(i, _)| keep(*i))
                .map(|(_, v)| *v)
                .collect()
        };
        let opt = |v: &Option<Vec<f64>>| v.as_deref().map(pick);
        Measured {
            t: pick(&self.t),
            v_cm: pick(&self.v_cm),
            v_t: pick(&self.v_t),
            v_cm_sigma: opt(&self.v_cm_sigma),
            v_t_sigma: opt(&self.v_t_sigma),
            x: opt(&self.x),
            angle: opt(&self.angle),
            // The stencils' frames stay whole: the points left still index them.
            stencils: self.stencils.as_ref().map(|s| {
                let pick = |v: &[Option<Stencil>]| -> Vec<Option<Stencil>> {
                    v.iter()
                        .enumerate()
                        .filter(|(i, _)| keep(*i))
                        .map(|(_, v)| *v)
                        .collect()
                };
                std::sync::Arc::new(Stencils {
                    v_cm: pick(&s.v_cm),
                    v_t: pick(&s.v_t),
                    ..(**s).clone()
                })
            }),
            mirrored: self.mirrored,
            spin_turned: self.spin_turned,
            scale_rel_se: self.scale_rel_se,
            x_sigma: opt(&self.x_sigma),
            angle_sigma: opt(&self.angle_sigma),
        }
    }

    /// The series with v_t (and its σ) times `r`: a spin rate (rad/s) made a rim
    /// speed on the contact radius `r` (m). Finite `r` keeps the rules.
    pub fn v_t_scaled(&self, r: f64) -> Measured {
        let scale = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .map(|w| {
                    let s = w * r;
                    if s.is_finite() { s } else { f64::NAN }
                })
                .collect()
        };
        let sigma = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .map(|w| {
                    let s = w * r.abs();
                    if s.is_finite() { s } else { f64::NAN }
                })
                .collect()
        };
        Measured {
            v_t: scale(&self.v_t),
            v_t_sigma: self.v_t_sigma.as_deref().map(sigma),
            ..self.clone()
        }
    }

    /// The series without its rim mark: v_t all gaps, no angle.
    pub fn without_mark(&self) -> Measured {
        Measured {
            v_t: vec![f64::NAN; self.v_t.len()],
            v_t_sigma: None,
            angle: None,
            angle_sigma: None,
            ..self.clone()
        }
    }

    /// The series with v_t (and its σ) a gap at each point `gap` names: not measured
    /// there, as where the mark was hidden.
    pub fn without_v_t_at(&self, gap: impl Fn(usize) -> bool) -> Measured {
        let cut = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .enumerate()
                .map(|(i, &x)| if gap(i) { f64::NAN } else { x })
                .collect()
        };
        Measured {
            v_t: cut(&self.v_t),
            v_t_sigma: self.v_t_sigma.as_deref().map(cut),
            ..self.clone()
        }
    }

    /// The series with its times moved by `dt` s (finite): they still increase. A
    /// shift that would make a time non-finite or merge two is refused.
    pub fn shifted(&self, dt: f64) -> Result<Measured, Rule> {
        Measured::new(MeasuredParts {
            t: self.t.iter().map(|t| t + dt).collect(),
            ..self.to_parts()
        })
    }
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

    /// Why the line fits' a_t and μ_k,t are not measured, where they are not.
    pub fn why_no_line_v_t(&self) -> NoLineVt {
        if self.has_v_t() {
            NoLineVt::FewInWindow
        } else if self.angle().is_some() {
            NoLineVt::FewInARow
        } else {
            NoLineVt::NoMark
        }
    }
}

/// Why the line fits over a window have no v_t line ([`Measured::why_no_line_v_t`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoLineVt {
    /// The rim mark's v_t is measured, but in fewer than 3 frames of the window.
    FewInWindow,
    /// A mark was tracked, but in too few frames in a row for a v_t anywhere (each
    /// v_t is a local fit over a frame and its neighbours).
    FewInARow,
    /// No mark was tracked.
    NoMark,
}

impl NoLineVt {
    /// The reason in full, as `fit`'s JSON says it.
    pub fn reason(self) -> &'static str {
        match self {
            NoLineVt::FewInWindow => {
                "the rim mark was followed in fewer than 3 frames of the line fits' window: v_t is not measured there"
            }
            NoLineVt::FewInARow => {
                "the rim mark was followed in too few frames in a row for a v_t (a local fit over a frame and its neighbours): v_t is not measured"
            }
            NoLineVt::NoMark => "no rim mark was tracked: v_t is not measured",
        }
    }

    /// The reason in a few words, for a narrow panel.
    pub fn short(self) -> &'static str {
        match self {
            NoLineVt::NoMark => "no rim mark",
            NoLineVt::FewInWindow | NoLineVt::FewInARow => "rim mark in too few frames",
        }
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
/// as the user set them), SI units. Built only by [`Track::new`], which keeps its
/// rules ([`Rule`]): every column (x, y, the mark's, the σs) has one value per time,
/// the times are finite and strictly increasing, and every value is finite or a gap
/// (NaN: a missing cell; never ±∞), every σ ≥ 0. Rows without a time are dropped by
/// the readers. How many frames are enough is the caller's to say (`derive` needs
/// `2 · min_frames`).
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    t: Vec<f64>,
    x: Vec<f64>,
    y: Vec<f64>,
    mark: Option<(Vec<f64>, Vec<f64>)>,
    centre_name: String,
    mark_name: Option<String>,
    format: &'static str,
    scale_rel_se: Option<f64>,
    sigma: Option<Vec<f64>>,
    mark_sigma: Option<Vec<f64>>,
}

/// The columns of a [`Track`] before their rules are checked: what a reader fills in,
/// then hands to [`Track::new`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrackParts {
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

impl Track {
    /// The track `parts`, if it keeps the rules of [`Track`]; else the first rule
    /// broken.
    pub fn new(parts: TrackParts) -> Result<Track, Rule> {
        let n = parts.t.len();
        check_times(&parts.t)?;
        check_column("x", &parts.x, n, false)?;
        check_column("y", &parts.y, n, false)?;
        if let Some((mx, my)) = &parts.mark {
            check_column("mark x", mx, n, false)?;
            check_column("mark y", my, n, false)?;
        }
        check_optional("σ", parts.sigma.as_deref(), n, true)?;
        check_optional("mark σ", parts.mark_sigma.as_deref(), n, true)?;
        check_scale_se(parts.scale_rel_se)?;
        let TrackParts {
            t,
            x,
            y,
            mark,
            centre_name,
            mark_name,
            format,
            scale_rel_se,
            sigma,
            mark_sigma,
        } = parts;
        Ok(Track {
            t,
            x,
            y,
            mark,
            centre_name,
            mark_name,
            format,
            scale_rel_se,
            sigma,
            mark_sigma,
        })
    }

    /// Its columns, to change and check again with [`Track::new`].
    pub fn into_parts(self) -> TrackParts {
        let Track {
            t,
            x,
            y,
            mark,
            centre_name,
            mark_name,
            format,
            scale_rel_se,
            sigma,
            mark_sigma,
        } = self;
        TrackParts {
            t,
            x,
            y,
            mark,
            centre_name,
            mark_name,
            format,
            scale_rel_se,
            sigma,
            mark_sigma,
        }
    }

    /// A copy of its columns ([`Track::into_parts`] of a clone).
    pub fn to_parts(&self) -> TrackParts {
        self.clone().into_parts()
    }

    /// The same track, said to be of format `format` (no rule is about the format).
    pub fn with_format(self, format: &'static str) -> Track {
        Track { format, ..self }
    }

    /// The number of frames.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// True without frames.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Times, s: finite, strictly increasing.
    pub fn t(&self) -> &[f64] {
        &self.t
    }
    /// The ball's centre's x, m, one per time (NaN: a gap).
    pub fn x(&self) -> &[f64] {
        &self.x
    }
    /// The centre's y, m, one per time (all NaN when the file has none).
    pub fn y(&self) -> &[f64] {
        &self.y
    }
    /// The rim mark's x and y, m, one each per time, when the file has a mark.
    pub fn mark(&self) -> Option<(&[f64], &[f64])> {
        self.mark
            .as_ref()
            .map(|(x, y)| (x.as_slice(), y.as_slice()))
    }
    /// Name of the centre's track ("" for a plain `x, y` file).
    pub fn centre_name(&self) -> &str {
        &self.centre_name
    }
    /// Name of the mark's track, when it has one.
    pub fn mark_name(&self) -> Option<&str> {
        self.mark_name.as_deref()
    }
    /// The format found.
    pub fn format(&self) -> &'static str {
        self.format
    }
    /// The relative standard error of the lengths' scale, where the file states one.
    pub fn scale_rel_se(&self) -> Option<f64> {
        self.scale_rel_se
    }
    /// Each frame's standard error of the centre, m, where the file states it.
    pub fn sigma(&self) -> Option<&[f64]> {
        self.sigma.as_deref()
    }
    /// Each frame's standard error of the mark, m, where the file states it.
    pub fn mark_sigma(&self) -> Option<&[f64]> {
        self.mark_sigma.as_deref()
    }
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
