//! The lab's one immutable snapshot of its scene ([`Resolved`]), built by one
//! function from the settings layers, the measured series and the pinned run: the
//! checked scene, its span, the exact solution, the derived values, the run's story
//! and verdict, the measured series derived for this scene (a track's v_t from this
//! r, the rest band, the ghost ball) and its residual, and the measured points the
//! charts draw. An edit builds a new one; views read it and never change it.

use std::sync::Arc;

use crate::physics::derived::{Derived, Summary};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::physics::story::{After, Verdict};
use crate::settings::params::{Key, PARAMS};
use crate::settings::spec::SceneError;
use crate::settings::units::{Dimension, show, show_below};
use crate::study::fit;
use crate::study::measured::{self, InScene, Measured};
use crate::study::story;

use super::data::{Groove, InUse, OtherGroove};
use super::settings::Layers;
use super::span::{SpanEnd, solve_shown};

/// A scene pinned for comparison (A/B): drawn dimmed beside the current one.
#[derive(Clone, Debug)]
pub struct Pinned {
    pub scene: Scene,
    pub solution: Arc<Solution>,
    /// The preset it started from.
    pub label: String,
    /// Where its automatic span ends (the current automatic span reaches it too).
    pub auto_end: f64,
    /// Its closed-form values and headline numbers, made once at pinning.
    pub derived: Derived,
    pub summary: Summary,
}

/// A point of a chart (t, value).
pub type ChartPoint = (f64, f64);

/// Everything about the current scene that changes only when the scene does.
#[derive(Clone, Debug)]
pub struct Resolved {
    pub scene: Scene,
    /// The scene's v0 is the one the user's data measure (their approach), not one
    /// given: a fit then frees it in every model.
    pub v0_measured: bool,
    /// A v0 given that the data in use contradict (said wherever v0 is shown).
    pub contradiction: Option<super::data::Contradiction>,
    /// The span shown: `t_end` is always the shown end (see [`SpanEnd`]).
    pub span: Span,
    pub span_end: SpanEnd,
    pub solution: Arc<Solution>,
    pub derived: Derived,
    /// The solution's headline numbers (outcome, impacts, T∞, energies).
    pub summary: Summary,
    /// The x range (m) the balls (and a pinned run's) cover over the span.
    pub extent: (f64, f64),
    /// The measured series in this scene (`measured::for_scene`).
    pub data: Option<InScene>,
    /// RMS residuals of v_cm and v_t against the measured points
    /// (`None` for v_t when the series has none: a track without a rim mark).
    pub data_rms: Option<(f64, Option<f64>)>,
    /// The measured series' rest band (speeds within it cannot be told from rest).
    pub rest_band: Option<f64>,
    /// The data were measured in another groove than this scene's: said wherever
    /// they are shown.
    pub other_groove: Option<OtherGroove>,
    /// The measured points as the charts draw them.
    pub points: Option<Arc<MeasuredPoints>>,
    /// A position track's centre where the model's left ball would be, per frame (m,
    /// NaN outside the run): [`fit::aligned_track`].
    pub track_x: Option<Arc<[f64]>>,
    /// The run's headline, what follows the first impact, and the verdict.
    pub story: Story,
    /// The pinned run's parameters that differ from the current ones:
    /// `(label, was, now)`.
    pub pinned_changes: Vec<(&'static str, String, String)>,
}

impl Resolved {
    /// The snapshot of `settings`, with the data `in_use` derived for its scene and
    /// the span reaching a pinned run's end: the one way a lab's scene is built.
    pub fn build(
        settings: &Layers,
        in_use: Option<&InUse>,
        pinned: Option<&Pinned>,
    ) -> Result<Resolved, SceneError> {
        let (scene, span, span_end) = settings.settle()?;
        let data = in_use.map(|d| measured::for_scene(&d.series, &scene));
        let m = data.as_ref().map(|d| &*d.measured);
        let solution = solve_shown(&scene, &span, span_end, m, pinned.map(|p| p.auto_end));
        let span = Span {
            t_start: span.t_start,
            t_end: Some(solution.t_end),
        };
        let derived = Derived::of(&scene);
        let rest_band = data.as_ref().map(|d| d.rest_band);
        let mut extent = extent(&solution, scene.radius);
        if let Some(p) = pinned {
            // The pinned balls are drawn too: the scene's scale covers both runs.
            let mut run = (*p.solution).clone();
            (run.t_start, run.t_end) = (solution.t_start, solution.t_end);
            let (lo, hi) = self::extent(&run, p.scene.radius);
            extent = (extent.0.min(lo), extent.1.max(hi));
        }
        let track_x = m
            .and_then(|m| fit::aligned_track(&scene, &solution, m))
            .map(Arc::from);
        Ok(Resolved {
            v0_measured: settings.from_the_data(Key::V0),
            contradiction: super::data::Contradiction::of(
                settings,
                in_use.map(|d| &d.series),
                &scene,
            ),
            data_rms: m.map(|m| data_rms(&solution, m)),
            points: m.map(|m| Arc::new(MeasuredPoints::of(m, track_x.as_deref()))),
            track_x,
            story: Story::of(&solution, &derived, rest_band),
            summary: Summary::of(&solution),
            pinned_changes: pinned
                .map(|p| changes(p, &scene, &span))
                .unwrap_or_default(),
            other_groove: in_use.and_then(|d| OtherGroove::of(d, Groove::of(&scene))),
            scene,
            span,
            span_end,
            solution: Arc::new(solution),
            derived,
            extent,
            data,
            rest_band,
        })
    }

    /// Without measured data in use, the unfitted data's points in the file's own
    /// time (no impact aligns them with the model's).
    pub(super) fn show_in_file_time(&mut self, unfit: Option<&super::data::Unfit>) {
        if self.data.is_some() {
            return;
        }
        self.points = unfit.and_then(|u| u.in_file_time.as_ref()).map(|m| {
            let mut points = MeasuredPoints::of(m, None);
            points.v_t = Arc::from(Vec::new());
            points.v_t_bars = None;
            points.ranges = points.series().map(|s| value_range(s)).collect();
            points.in_file_time = true;
            Arc::new(points)
        });
    }

    /// The measured series in this scene.
    pub fn measured(&self) -> Option<&Measured> {
        self.data.as_ref().map(|d| &*d.measured)
    }

    /// The current value of a parameter, SI (`t_end`: the shown end).
    pub fn value(&self, key: Key) -> f64 {
        key.get(&self.scene, &self.span)
            .expect("the snapshot's span always has its shown end")
    }

    /// Where the measured left ball's centre is at `t`: the tracked position of a
    /// position file, else its v_cm integrated from the impact place at t = 0; `None`
    /// outside the series.
    pub fn ghost_x(&self, t: f64) -> Option<f64> {
        self.data.as_ref()?.ghost_x(t)
    }

    /// The measured left ball's spin angle at `t` for its spoke, rad, on the model's
    /// scale (the model's angle at the first impact plus the mark's turn since then);
    /// `None` without a tracked rim mark or outside the series.
    pub fn ghost_angle(&self, t: f64) -> Option<f64> {
        let turn = self.data.as_ref()?.ghost_turn(t)?;
        Some(self.solution.angle_at(0.0)[0] + turn)
    }
}

/// The measured points as the charts draw them, made once per scene (a series may
/// have a million rows: no frame copies them).
#[derive(Clone, Debug, Default)]
pub struct MeasuredPoints {
    pub v_cm: Arc<[ChartPoint]>,
    pub v_t: Arc<[ChartPoint]>,
    /// Each derived point's ±1σ as a vertical run of points (`None`: no σ given).
    pub v_cm_bars: Option<Arc<[ChartPoint]>>,
    pub v_t_bars: Option<Arc<[ChartPoint]>>,
    /// A position track's centre where the model's left ball would be (x − R, aligned
    /// by [`fit::aligned_track`]), in the display unit of length (the position chart's).
    pub x: Option<Arc<[ChartPoint]>>,
    /// Each series' [`value_range`], in the order of [`MeasuredPoints::series`].
    ranges: Vec<Option<(f64, f64)>>,
    /// The points are in the file's own time, not aligned with the model's (no
    /// impact was found to align them: `super::data::Unfit`).
    pub in_file_time: bool,
}

impl MeasuredPoints {
    fn of(m: &Measured, track_x: Option<&[f64]>) -> MeasuredPoints {
        let pts = |v: &[f64]| m.t().iter().copied().zip(v.iter().copied()).collect();
        let bars = |v: &[f64], s: Option<&[f64]>| s.map(|s| error_bars(m.t(), v, s).into());
        let mut points = MeasuredPoints {
            v_cm: pts(m.v_cm()),
            v_t: pts(m.v_t()),
            v_cm_bars: bars(m.v_cm(), m.v_cm_sigma()),
            v_t_bars: bars(m.v_t(), m.v_t_sigma()),
            x: track_x.map(|x| {
                m.t()
                    .iter()
                    .zip(x)
                    .filter(|(_, x)| x.is_finite())
                    .map(|(t, x)| (*t, Dimension::Length.to_display(*x)))
                    .collect()
            }),
            ranges: Vec::new(),
            in_file_time: false,
        };
        points.ranges = points.series().map(|s| value_range(s)).collect();
        points
    }

    /// Every series above, in a fixed order: v_cm, v_t, their error bars, x.
    pub fn series(&self) -> impl Iterator<Item = &Arc<[ChartPoint]>> {
        [Some(&self.v_cm), Some(&self.v_t)]
            .into_iter()
            .chain([&self.v_cm_bars, &self.v_t_bars, &self.x].map(Option::as_ref))
            .flatten()
    }

    /// The [`value_range`] of `points` if it is one of these series (made once per
    /// scene: a chart's y range takes no pass over a million rows); `None` if not.
    /// Whether `points` are one of the error-bar series: a chart's y range leaves them
    /// out (a derived point beside a gap in a track can carry a σ many times the
    /// speeds; its bar is cut at the chart's edge rather than squeezing the curves).
    pub fn is_bars(&self, points: &Arc<[ChartPoint]>) -> bool {
        [&self.v_cm_bars, &self.v_t_bars]
            .into_iter()
            .flatten()
            .any(|b| Arc::ptr_eq(b, points))
    }

    pub fn range_of(&self, points: &Arc<[ChartPoint]>) -> Option<Option<(f64, f64)>> {
        let i = self.series().position(|s| Arc::ptr_eq(s, points))?;
        self.ranges.get(i).copied()
    }
}

/// The least and the greatest finite value of `points` (`None`: none is finite).
pub fn value_range(points: &[ChartPoint]) -> Option<(f64, f64)> {
    points
        .iter()
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .fold(None, |r, v| {
            Some(r.map_or((v, v), |(lo, hi): (f64, f64)| (lo.min(v), hi.max(v))))
        })
}

/// Points filling `value ± sigma` at each time (12 per bar, enough for a bar a dozen
/// rows tall), for a series drawn as vertical error bars; points without a finite
/// value or uncertainty have none.
fn error_bars(ts: &[f64], values: &[f64], sigma: &[f64]) -> Vec<ChartPoint> {
    const STEPS: usize = 12;
    let mut out = Vec::new();
    for ((&t, &v), &s) in ts.iter().zip(values).zip(sigma) {
        if !(v.is_finite() && s.is_finite() && s > 0.0) {
            continue;
        }
        out.extend((0..=STEPS).map(|k| (t, v - s + 2.0 * s * k as f64 / STEPS as f64)));
    }
    out
}

/// The pinned parameters that differ from the current ones: `(label, was, now)` with
/// the table's label and unit: every value of the scene and the span's start (the
/// shown end follows the runs).
fn changes(p: &Pinned, scene: &Scene, span: &Span) -> Vec<(&'static str, String, String)> {
    let was_span = Span {
        t_start: p.solution.t_start,
        t_end: Some(p.solution.t_end),
    };
    differences((&p.scene, &was_span), (scene, span))
}

/// The parameters of scene `now` that differ from those of `was`: `(label, was,
/// now)` with the table's label and unit, every value of the scene and the span's
/// start (not its end, which follows the runs).
pub fn differences(
    (was, was_span): (&Scene, &Span),
    (scene, span): (&Scene, &Span),
) -> Vec<(&'static str, String, String)> {
    PARAMS
        .iter()
        .filter(|row| row.is_own() && row.replaces.is_none() && row.key != Key::TEnd)
        .filter_map(|row| {
            let x = (row.get)(was, was_span)?;
            let y = (row.get)(scene, span)?;
            let differ = (x - y).abs() > 1e-12 * x.abs().max(y.abs());
            // A width just under 2R keeps the digits that tell it from 2R.
            let shown = |v, sc: &Scene| match row.key {
                Key::Width => show_below(v, 2.0 * sc.radius, row.dim),
                _ => show(v, row.dim).to_string(),
            };
            differ.then(|| (row.label, shown(x, was), shown(y, scene)))
        })
        .collect()
}

/// The x range (m) the balls cover over the span: positions at its ends and at every
/// event (turning points inside a segment, v = 0, are events).
fn extent(sol: &Solution, radius: f64) -> (f64, f64) {
    let times = [sol.t_start, sol.t_end]
        .into_iter()
        .chain(sol.visible_events().map(|e| e.t));
    times.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
        let s = sol.at(t);
        (lo.min(s.left.x - radius), hi.max(s.right.x + radius))
    })
}

/// RMS residuals of the left ball's v_cm and v_t against `m` (the frame that straddles
/// the impact left out; a v_t that was not measured left out, `None` if none was).
fn data_rms(sol: &Solution, m: &Measured) -> (f64, Option<f64>) {
    let (mut sc, mut st, mut n, mut nt) = (0.0, 0.0, 0usize, 0usize);
    for i in (0..m.t().len()).filter(|&i| m.t()[i].abs() >= 0.005) {
        let s = sol.at(m.t()[i]);
        sc += (s.left.v - m.v_cm()[i]).powi(2);
        n += 1;
        if m.v_t()[i].is_finite() {
            st += (s.left.u - m.v_t()[i]).powi(2);
            nt += 1;
        }
    }
    let rms = |sum: f64, n: usize| (sum / n.max(1) as f64).sqrt();
    (rms(sc, n), (nt > 0).then(|| rms(st, nt)))
}

/// The run's story as the panels tell it, once per scene: the headline, what happens
/// after the first impact, and the verdict against the measured series' rest band.
#[derive(Clone, Debug)]
pub struct Story {
    pub headline: String,
    /// The paper's criterion, where the run does otherwise.
    pub criterion_note: Option<String>,
    pub after: Option<After>,
    pub verdict: Verdict,
}

impl Story {
    fn of(sol: &Solution, derived: &Derived, band: Option<f64>) -> Story {
        Story {
            headline: story::headline(sol, derived),
            criterion_note: story::criterion_note(sol, derived),
            after: crate::physics::story::after_first_impact(sol, derived),
            verdict: Verdict::of(sol, derived, band),
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn error_bars_span_one_sigma_and_skip_unknowns() {
        let bars = super::error_bars(
            &[0.0, 1.0, 2.0],
            &[1.0, f64::NAN, 3.0],
            &[0.1, 0.1, f64::NAN],
        );
        assert_eq!(bars.len(), 13);
        assert!(bars.iter().all(|&(t, _)| t == 0.0));
        assert!((bars[0].1 - 0.9).abs() < 1e-12 && (bars[12].1 - 1.1).abs() < 1e-12);
    }
}
