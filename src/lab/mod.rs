//! One scene under study, for every front end: the preset it came from, its exact
//! solution and derived values, the measured series beside it, and the analyses that
//! take longer than a frame (methods rows, the overlay run, the fits), computed lazily
//! on worker threads and dropped when the scene changes. What the views draw from a
//! solution (curve samples, the regime grid, the ghost ball's track) is cached here
//! per scene and size, never recomputed per frame.

pub mod jobs;

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::Arc;

use crate::input::data::Measured;
use crate::input::params::{Key, SceneError, SceneSpec};
use crate::input::preset::Preset;
use crate::methods::{self, Method, Settings, Y};
use crate::physics::derived::{Derived, Regime};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{EnergySplit, Snapshot, Solution};
use crate::study::compare::{self, Row};
use crate::study::fit::{self, Fits, Free, ModelFit};
use jobs::{Job, State, Ticket};

/// Steps of the overlay and the Methods view: 10 ms … 10 µs (fixed-step methods),
/// tolerances 1e-2 … 1e-8 (rk45).
pub const OVERLAY_LEVELS: u8 = 7;

/// The settings of `method` at `level`.
pub fn level_settings(method: Method, level: u8) -> Settings {
    let level = f64::from(level.min(OVERLAY_LEVELS - 1));
    if method.adaptive() {
        Settings {
            tolerance: 10f64.powf(-2.0 - level),
            step: 1e-3,
            ..Settings::default()
        }
    } else {
        Settings {
            step: 10f64.powf(-2.0 - level / 2.0),
            ..Settings::default()
        }
    }
}

/// The levels the Methods view runs every method at.
pub const METHOD_VIEW_LEVELS: [u8; 4] = [0, 2, 4, 6];

/// A time-stepping run drawn over the exact curves.
#[derive(Clone, Debug)]
pub struct Overlay {
    pub method: Method,
    pub settings: Settings,
    /// Its steps, thinned to a few thousand points.
    pub points: Vec<(f64, Y)>,
    pub row: Row,
}

/// Records a run's steps, keeping at most about `limit` of them; stops the run when
/// the job is cancelled.
struct Thinned<'a> {
    points: Vec<(f64, Y)>,
    every: usize,
    seen: usize,
    total: usize,
    ticket: &'a Ticket,
}

impl methods::Observer for Thinned<'_> {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        if self.seen.is_multiple_of(self.every) {
            self.points.push((t, *y));
            self.ticket.progress(self.seen, self.total);
        }
        self.seen += 1;
        y.iter().all(|v| v.is_finite()) && !self.ticket.cancelled()
    }
}

/// Why a scene could not be saved as a preset.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SaveError {
    #[error("name '{0}', allowed letters, digits, - _ .")]
    BadName(String),
    #[error("no preset folder (set GROOVELAB_PRESETS)")]
    NoFolder,
    #[error("{0} exists")]
    Exists(PathBuf),
    #[error("{0}")]
    Io(String),
}

/// How the end of the shown time span is chosen. The rule, for the README: the span runs
/// to a little past the last event (rest, the accumulation point T∞, the start of the
/// final rolling) and past the last measured point, and is recomputed on every change.
/// An end set explicitly (`--t-end`, or typed in the app) is kept; a preset's `t_end`
/// holds until the first parameter change; the app's span key stretches or shrinks the
/// automatic span, which then still follows the physics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpanEnd {
    /// A little past the last event and the last measured point.
    Auto,
    /// The automatic span times this factor (from `t_start`).
    Scaled(f64),
    /// A fixed end, s. `from_preset`: the preset's `t_end`, which gives way to
    /// [`SpanEnd::Auto`] at the first parameter change.
    Fixed { t_end: f64, from_preset: bool },
}

impl SpanEnd {
    /// The span key's cycle: auto, ×2, ×½, auto; a fixed end goes back to auto.
    pub fn next(self) -> SpanEnd {
        match self {
            SpanEnd::Auto => SpanEnd::Scaled(2.0),
            SpanEnd::Scaled(f) if f > 1.0 => SpanEnd::Scaled(0.5),
            SpanEnd::Scaled(_) | SpanEnd::Fixed { .. } => SpanEnd::Auto,
        }
    }

    /// How the status line names it.
    pub fn describe(self) -> String {
        match self {
            SpanEnd::Auto => "auto (a little past the last event)".into(),
            SpanEnd::Scaled(f) if f > 1.0 => format!("auto ×{f}"),
            SpanEnd::Scaled(f) => format!("auto ×1/{}", (1.0 / f).round()),
            SpanEnd::Fixed {
                from_preset: true, ..
            } => "the preset's t_end".into(),
            SpanEnd::Fixed { .. } => "fixed t_end".into(),
        }
    }
}

/// A scene pinned for comparison (A/B): drawn dimmed beside the current one.
#[derive(Clone, Debug)]
pub struct Pinned {
    pub scene: Scene,
    pub solution: Arc<Solution>,
    /// The preset it started from.
    pub label: String,
    /// Where its automatic span ends (the current automatic span reaches it too).
    pub auto_end: f64,
}

/// A per-scene cache of what the views draw, keyed by size.
type Cached<K, T> = RefCell<Option<(K, Rc<[T]>)>>;

/// One scene under study.
#[derive(Clone, Debug)]
pub struct Lab {
    pub preset: Preset,
    pub scene: Scene,
    /// The span shown: `t_end` is always the shown end (see [`SpanEnd`]).
    pub span: Span,
    pub span_end: SpanEnd,
    /// The run pinned for an A/B comparison.
    pub pinned: Option<Pinned>,
    pub solution: Arc<Solution>,
    pub derived: Derived,
    /// The x range (m) the balls cover over the span.
    pub extent: (f64, f64),
    /// RMS residuals of v_cm and v_t against the measured points.
    pub data_rms: Option<(f64, f64)>,
    /// Where the measured left ball is at each measured time: the tracked centre of a
    /// position file, else its v_cm integrated.
    ghost: Option<Vec<f64>>,
    /// Line-fit window (None: the sliding phase).
    pub fit_window: (Option<f64>, Option<f64>),
    want_methods: bool,
    want_fits: bool,
    overlay_choice: Option<(Method, u8)>,
    methods: Job<Vec<Row>>,
    /// `None` only for a run that was cancelled before it finished.
    overlay: Job<Option<Overlay>>,
    fits: Job<Result<Fits, String>>,
    /// The model fitted to a position track's positions (none for a velocity file).
    position_fit: Job<Result<ModelFit, String>>,
    /// A file the app is writing (run CSV, chart SVG): the status message, or why not.
    export: Job<Result<String, String>>,
    samples: Cached<usize, Snapshot>,
    energies: Cached<usize, (f64, EnergySplit)>,
    pinned_samples: Cached<usize, Snapshot>,
    regimes: Cached<(usize, usize), Regime>,
}

impl Lab {
    /// The lab on `scene`; a `t_end` in `span` counts as the preset's (see [`SpanEnd`];
    /// [`Lab::set_span_end`] makes it explicit).
    pub fn new(preset: Preset, scene: Scene, span: Span) -> Lab {
        let span_end = preset_span_end(&span);
        let solution = Arc::new(solve_shown(
            &scene,
            &span,
            span_end,
            preset.measured.as_ref(),
            None,
        ));
        let span = Span {
            t_start: span.t_start,
            t_end: Some(solution.t_end),
        };
        let mut lab = Lab {
            preset,
            scene,
            span,
            span_end,
            pinned: None,
            derived: Derived::of(&scene),
            solution,
            extent: (0.0, 0.0),
            data_rms: None,
            ghost: None,
            fit_window: (None, None),
            want_methods: false,
            want_fits: false,
            overlay_choice: None,
            methods: Job::Idle,
            overlay: Job::Idle,
            fits: Job::Idle,
            position_fit: Job::Idle,
            export: Job::Idle,
            samples: RefCell::default(),
            energies: RefCell::default(),
            pinned_samples: RefCell::default(),
            regimes: RefCell::default(),
        };
        lab.cache();
        lab
    }

    /// The preset's measured series (kept while parameters change, so a model can be
    /// tuned against it by hand).
    pub fn measured(&self) -> Option<&Measured> {
        self.preset.measured.as_ref()
    }

    /// The current value of a parameter, SI.
    pub fn value(&self, key: Key) -> f64 {
        let s = &self.scene;
        match key {
            Key::Radius => s.radius,
            Key::Width => s.width,
            Key::Mass | Key::MassLeft => s.left.mass,
            Key::MassRight => s.right.mass,
            Key::Mu => s.mu,
            Key::V0 | Key::V0Left => s.left.v0,
            Key::V0Right => s.right.v0,
            Key::Height | Key::HeightLeft => self.derived.release_height,
            Key::HeightRight => crate::physics::closed_form::release_height(s.right.v0, s.k(), s.g),
            Key::Restitution => s.restitution,
            Key::RollingResistance => s.rolling_resistance,
            Key::G => s.g,
            Key::TStart => self.span.t_start,
            Key::TEnd => self.solution.t_end,
        }
    }

    /// Sets a parameter if the scene stays valid. Setting `t_end` fixes the span's end;
    /// any other parameter ends a preset's `t_end` (the span follows the physics again).
    pub fn set(&mut self, key: Key, value: f64) -> Result<(), SceneError> {
        let fixed = match self.span_end {
            SpanEnd::Fixed { t_end, .. } => Some(t_end),
            _ => None,
        };
        let given = Span {
            t_start: self.span.t_start,
            t_end: fixed,
        };
        let spec = SceneSpec::of(&self.scene, &given).with(key, value);
        let (scene, span) = spec.resolve()?;
        self.span_end = match (key, self.span_end) {
            (Key::TEnd, _) => SpanEnd::Fixed {
                t_end: value,
                from_preset: false,
            },
            (Key::TStart, end) => end,
            (
                _,
                SpanEnd::Fixed {
                    from_preset: true, ..
                },
            ) => SpanEnd::Auto,
            (_, end) => end,
        };
        self.load(scene, span);
        Ok(())
    }

    /// Chooses how the span ends (the span key, or `--t-end`), keeping the scene.
    pub fn set_span_end(&mut self, end: SpanEnd) -> Result<(), SceneError> {
        if let SpanEnd::Fixed { t_end, .. } = end
            && !(t_end > self.span.t_start && t_end <= 1e6)
        {
            return Err(SceneError::OutOfRange {
                name: "t_end",
                value: format!("{t_end} s"),
                allowed: format!("t_start = {} s < t_end ≤ 1e6 s", self.span.t_start),
            });
        }
        self.span_end = end;
        self.load(self.scene, self.span);
        Ok(())
    }

    /// Starts over from `preset` (its `t_end`, if any, holds until a parameter changes).
    pub fn load_preset(&mut self, preset: Preset) -> Result<(), SceneError> {
        let (scene, span) = preset.spec.resolve()?;
        self.preset = preset;
        self.fit_window = (None, None);
        self.span_end = preset_span_end(&span);
        self.load(scene, span);
        Ok(())
    }

    /// Pins the current run for an A/B comparison, or unpins it; true if now pinned.
    pub fn toggle_pin(&mut self) -> bool {
        self.pinned = match self.pinned {
            Some(_) => None,
            None => Some(Pinned {
                scene: self.scene,
                solution: self.solution.clone(),
                label: self.preset.name.clone(),
                // Its own automatic end, not the shown one: a scaled span must not
                // compound through the pin.
                auto_end: solve_shown(
                    &self.scene,
                    &self.span,
                    SpanEnd::Auto,
                    self.measured(),
                    None,
                )
                .t_end,
            }),
        };
        // The automatic span covers the pinned run too: re-solve only if that moves it.
        let sol = solve_shown(
            &self.scene,
            &self.span,
            self.span_end,
            self.measured(),
            self.pinned_end(),
        );
        if sol.t_end == self.solution.t_end {
            self.cache();
        } else {
            self.load(self.scene, self.span);
        }
        self.pinned.is_some()
    }

    /// Where the pinned run's span ends (the automatic span reaches it too).
    fn pinned_end(&self) -> Option<f64> {
        self.pinned.as_ref().map(|p| p.auto_end)
    }

    fn load(&mut self, scene: Scene, span: Span) {
        self.scene = scene;
        let solution = solve_shown(
            &scene,
            &span,
            self.span_end,
            self.measured(),
            self.pinned_end(),
        );
        self.span = Span {
            t_start: span.t_start,
            t_end: Some(solution.t_end),
        };
        self.solution = Arc::new(solution);
        self.derived = Derived::of(&scene);
        self.cache();
        self.methods.cancel();
        self.restart();
    }

    /// What the views need from a solve that does not change from frame to frame.
    fn cache(&mut self) {
        self.extent = extent(&self.solution, self.scene.radius);
        if let Some(p) = &self.pinned {
            // The pinned balls are drawn too: the scene's scale covers both runs.
            let mut pinned = (*p.solution).clone();
            (pinned.t_start, pinned.t_end) = (self.solution.t_start, self.solution.t_end);
            let (lo, hi) = extent(&pinned, p.scene.radius);
            self.extent = (self.extent.0.min(lo), self.extent.1.max(hi));
        }
        self.data_rms = self.measured().map(|m| data_rms(&self.solution, m));
        let radius = self.scene.radius;
        self.ghost = self.measured().map(|m| match &m.x {
            // The tracked centre is the displacement from the impact place, where the
            // model's left ball is at −R.
            Some(x) => x.iter().map(|x| x - radius).collect(),
            None => ghost_track(m, radius),
        });
        self.samples.replace(None);
        self.energies.replace(None);
        self.pinned_samples.replace(None);
        self.regimes.replace(None);
    }

    /// (Re)starts every analysis that is wanted and not ready for this scene.
    fn restart(&mut self) {
        if self.want_methods && matches!(self.methods, Job::Idle) {
            let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
            self.methods
                .start(move |ticket| method_rows(&scene, &span, &sol, ticket));
        }
        match self.overlay_choice {
            Some((method, level)) => {
                let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
                self.overlay
                    .start(move |ticket| overlay(method, level, &scene, &span, &sol, ticket));
            }
            None => self.overlay.cancel(),
        }
        self.restart_fits();
    }

    fn restart_fits(&mut self) {
        match self.measured().filter(|_| self.want_fits) {
            Some(m) => {
                let (scene, m, window) = (self.scene, m.clone(), self.fit_window);
                if m.x.is_some() {
                    let m = m.clone();
                    self.position_fit.start(move |ticket| {
                        fit::position_fit(&scene, &m, &[Free::Mu], ticket)
                            .map_err(|e| e.to_string())
                    });
                } else {
                    self.position_fit.cancel();
                }
                self.fits.start(move |ticket| {
                    fit::fit_all(&scene, &m, window, &[Free::Mu], ticket).map_err(|e| e.to_string())
                });
            }
            None => {
                self.fits.cancel();
                self.position_fit.cancel();
            }
        }
    }

    /// Takes in finished analyses; true if any arrived (the screen needs a redraw).
    pub fn poll(&mut self) -> bool {
        let a = self.methods.poll();
        let b = self.overlay.poll();
        let c = self.fits.poll();
        let d = self.position_fit.poll();
        let e = self.export.poll();
        a || b || c || d || e
    }

    /// Waits for every running analysis (headless output is then deterministic).
    pub fn wait(&mut self) {
        self.methods.wait();
        self.overlay.wait();
        self.fits.wait();
        self.position_fit.wait();
        self.export.wait();
    }

    /// Writes a file off the key press (a chart's SVG takes milliseconds): `work`
    /// returns the status message, or why nothing was written. A newer export
    /// supersedes a running one.
    pub fn start_export(&mut self, work: impl FnOnce() -> Result<String, String> + Send + 'static) {
        self.export.start(move |_| work());
    }

    /// The finished export's message, once; `None` while it runs or when there is none.
    pub fn take_export(&mut self) -> Option<Result<String, String>> {
        self.export.poll();
        match std::mem::take(&mut self.export) {
            Job::Ready(r) => Some(r),
            other => {
                self.export = other;
                None
            }
        }
    }

    /// True while an analysis runs.
    pub fn busy(&self) -> bool {
        self.methods.is_running()
            || self.overlay.is_running()
            || self.fits.is_running()
            || self.position_fit.is_running()
            || self.export.is_running()
    }

    /// Asks for (or stops asking for) the Methods view's rows.
    pub fn want_methods(&mut self, on: bool) {
        self.want_methods = on;
        if on {
            self.restart_if_idle();
        }
    }

    fn restart_if_idle(&mut self) {
        if self.want_methods && matches!(self.methods, Job::Idle) {
            let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
            self.methods
                .start(move |ticket| method_rows(&scene, &span, &sol, ticket));
        }
    }

    /// The Methods view's rows: every time-stepping method at four levels, untimed.
    pub fn method_rows(&self) -> State<'_, Vec<Row>> {
        self.methods.state()
    }

    /// Draws `method` at `level` over the exact curves (or nothing).
    pub fn set_overlay(&mut self, choice: Option<(Method, u8)>) {
        self.overlay_choice = choice;
        match choice {
            Some((method, level)) => {
                let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
                self.overlay
                    .start(move |ticket| overlay(method, level, &scene, &span, &sol, ticket));
            }
            None => self.overlay.cancel(),
        }
    }

    pub fn overlay_choice(&self) -> Option<(Method, u8)> {
        self.overlay_choice
    }

    pub fn overlay(&self) -> State<'_, Overlay> {
        match self.overlay.state() {
            State::Ready(Some(o)) => State::Ready(o),
            State::Ready(None) | State::Idle => State::Idle,
            State::Computing { done, total } => State::Computing { done, total },
        }
    }

    /// Asks for (or stops asking for) the fits of the measured series.
    pub fn want_fits(&mut self, on: bool) {
        self.want_fits = on;
        self.restart_fits();
    }

    pub fn fits(&self) -> State<'_, Result<Fits, String>> {
        self.fits.state()
    }

    /// The model fitted directly to a position track (Idle for a velocity file).
    pub fn position_fit(&self) -> State<'_, Result<ModelFit, String>> {
        self.position_fit.state()
    }

    /// Moves one end of the line-fit window by one measured frame.
    pub fn move_fit_window(&mut self, end: bool, later: bool) -> Result<(), String> {
        let Some(m) = self.measured() else {
            return Err("this preset has no measured data to fit".into());
        };
        let current = match self.fits.ready() {
            Some(Ok(f)) => (f.line_fit.from, f.line_fit.to),
            _ => {
                let auto = fit::sliding_window(m).unwrap_or((0.0, 0.0));
                (
                    self.fit_window.0.unwrap_or(auto.0),
                    self.fit_window.1.unwrap_or(auto.1),
                )
            }
        };
        let here = if end { current.1 } else { current.0 };
        let i =
            m.t.iter()
                .position(|&t| (t - here).abs() < 1e-9)
                .unwrap_or(0);
        let j = if later {
            (i + 1).min(m.t.len() - 1)
        } else {
            i.saturating_sub(1)
        };
        let t = m.t[j];
        self.fit_window = if end {
            (Some(current.0), Some(t))
        } else {
            (Some(t), Some(current.1))
        };
        self.restart_fits();
        Ok(())
    }

    /// Where the measured left ball's centre is at `t`: the tracked position of a
    /// position file, else its v_cm integrated (trapezoids) from the impact place at
    /// t = 0; `None` outside the series.
    pub fn ghost_x(&self, t: f64) -> Option<f64> {
        let m = self.measured()?;
        let track = self.ghost.as_ref()?;
        if t < m.t[0] || t > *m.t.last()? {
            return None;
        }
        if m.x.is_some() {
            return interpolate(&m.t, track, t);
        }
        Some(integral_to(m, track, t))
    }

    /// The measured left ball's spin angle at `t` for its spoke, rad, on the model's
    /// scale (the model's angle at the first impact plus the mark's turn since then);
    /// `None` without a tracked rim mark or outside the series.
    pub fn ghost_angle(&self, t: f64) -> Option<f64> {
        let m = self.measured()?;
        let angle = m.angle.as_ref()?;
        if t < m.t[0] || t > *m.t.last()? {
            return None;
        }
        let a = interpolate(&m.t, angle, t)?;
        Some(self.solution.angle_at(0.0)[0] + a)
    }

    /// The exact states at the chart's sample times for a plot `columns` wide: about
    /// four per column plus both sides of every event, computed once per scene and width.
    pub fn samples(&self, columns: usize) -> Rc<[Snapshot]> {
        if let Some((c, s)) = &*self.samples.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let sol = &self.solution;
        let s: Rc<[Snapshot]> = sample_times(sol, columns)
            .into_iter()
            .map(|t| sol.at(t))
            .collect();
        self.samples.replace(Some((columns, s.clone())));
        s
    }

    /// The energy split at the same times as [`Lab::samples`], once per scene and width.
    pub fn energies(&self, columns: usize) -> Rc<[(f64, EnergySplit)]> {
        if let Some((c, s)) = &*self.energies.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let sol = &self.solution;
        let s: Rc<[(f64, EnergySplit)]> = sample_times(sol, columns)
            .into_iter()
            .map(|t| (t, sol.energy_at(t)))
            .collect();
        self.energies.replace(Some((columns, s.clone())));
        s
    }

    /// The pinned run's states over the current span (its own events kept sharp), once
    /// per scene and width; empty when nothing is pinned.
    pub fn pinned_samples(&self, columns: usize) -> Rc<[Snapshot]> {
        let Some(p) = &self.pinned else {
            return Rc::from(Vec::new());
        };
        if let Some((c, s)) = &*self.pinned_samples.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let mut pinned = (*p.solution).clone();
        (pinned.t_start, pinned.t_end) = (self.solution.t_start, self.solution.t_end);
        let s: Rc<[Snapshot]> = sample_times(&pinned, columns)
            .into_iter()
            .map(|t| pinned.at(t))
            .collect();
        self.pinned_samples.replace(Some((columns, s.clone())));
        s
    }

    /// The pinned parameters that differ from the current ones: `(label, was, now)`,
    /// in the units of the parameter panel.
    pub fn pinned_changes(&self) -> Vec<(&'static str, String, String)> {
        let Some(p) = &self.pinned else {
            return Vec::new();
        };
        let (a, b) = (&p.scene, &self.scene);
        let rows: [(&'static str, f64, f64, crate::input::units::Dimension); 11] = {
            use crate::input::units::Dimension as D;
            [
                ("R", a.radius, b.radius, D::Length),
                ("b", a.width, b.width, D::Length),
                ("m left", a.left.mass, b.left.mass, D::Mass),
                ("m right", a.right.mass, b.right.mass, D::Mass),
                ("μ_k", a.mu, b.mu, D::Ratio),
                ("v0 left", a.left.v0, b.left.v0, D::Speed),
                ("v0 right", a.right.v0, b.right.v0, D::Speed),
                ("e", a.restitution, b.restitution, D::Ratio),
                ("c_rr", a.rolling_resistance, b.rolling_resistance, D::Ratio),
                ("g", a.g, b.g, D::Acceleration),
                ("t0", p.solution.t_start, self.solution.t_start, D::Time),
            ]
        };
        rows.into_iter()
            .filter(|(_, x, y, _)| (x - y).abs() > 1e-12 * x.abs().max(y.abs()))
            .map(|(name, x, y, dim)| {
                (
                    name,
                    crate::input::units::show(x, dim).to_string(),
                    crate::input::units::show(y, dim).to_string(),
                )
            })
            .collect()
    }

    /// The regime over groove width (0 … 0.99 · 2R, across) and restitution (1 … 0,
    /// down) for these balls, `cols × rows` cells, row by row; once per scene and size.
    pub fn regime_grid(&self, cols: usize, rows: usize) -> Rc<[Regime]> {
        if let Some((size, g)) = &*self.regimes.borrow()
            && *size == (cols, rows)
        {
            return g.clone();
        }
        let b_max = 2.0 * self.scene.radius * 0.99;
        let g: Rc<[Regime]> = (0..rows)
            .flat_map(|rr| (0..cols).map(move |c| (rr, c)))
            .map(|(rr, c)| {
                let mut scene = self.scene;
                scene.width = b_max * c as f64 / (cols - 1).max(1) as f64;
                scene.restitution = 1.0 - rr as f64 / (rows - 1).max(1) as f64;
                Derived::of(&scene).regime
            })
            .collect();
        self.regimes.replace(Some(((cols, rows), g.clone())));
        g
    }

    /// Saves the scene as a user preset in `dir`; never over an existing file unless
    /// `overwrite`. Returns the path written.
    pub fn save(
        &self,
        dir: Option<&Path>,
        name: &str,
        overwrite: bool,
    ) -> Result<PathBuf, SaveError> {
        let name = name.trim();
        let valid = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.');
        if !valid {
            return Err(SaveError::BadName(name.to_string()));
        }
        let dir = dir.ok_or(SaveError::NoFolder)?;
        let path = dir.join(format!("{name}.toml"));
        if path.exists() && !overwrite {
            return Err(SaveError::Exists(path));
        }
        // Overwriting keeps the description of the file it replaces.
        let kept = path
            .is_file()
            .then(|| Preset::load(&path.display().to_string()).ok())
            .flatten()
            .map(|p| p.description);
        let description = kept
            .unwrap_or_else(|| format!("Saved from groovelab (started from {})", self.preset.name));
        // Only an end that was set (not the automatic one) is saved.
        let t_end = match self.span_end {
            SpanEnd::Fixed { t_end, .. } => Some(t_end),
            _ => None,
        };
        let spec = SceneSpec::of(
            &self.scene,
            &Span {
                t_start: self.span.t_start,
                t_end,
            },
        );
        let text = crate::input::preset::to_toml(name, &description, &spec, self.measured())
            .map_err(SaveError::Io)?;
        // What is written must load again: check before reporting success.
        Preset::parse(&text, name, crate::input::preset::Origin::BuiltIn)
            .map_err(|e| SaveError::Io(format!("the file would not load again: {e}")))?;
        std::fs::create_dir_all(dir).map_err(|e| SaveError::Io(e.to_string()))?;
        crate::output::write_atomically(&path, text.as_bytes())
            .map_err(|e| SaveError::Io(e.to_string()))?;
        Ok(path)
    }
}

/// A `t_end` that came with a preset holds until a parameter changes.
fn preset_span_end(span: &Span) -> SpanEnd {
    match span.t_end {
        Some(t_end) => SpanEnd::Fixed {
            t_end,
            from_preset: true,
        },
        None => SpanEnd::Auto,
    }
}

/// The exact solution with the shown end: the engine always runs to the end of the
/// motion, so only `t_end` depends on the choice. The automatic end also reaches the
/// last measured point and the end of a pinned run, so neither is cut.
fn solve_shown(
    scene: &Scene,
    span: &Span,
    end: SpanEnd,
    measured: Option<&Measured>,
    pinned_end: Option<f64>,
) -> Solution {
    let auto_span = Span {
        t_start: span.t_start,
        t_end: None,
    };
    let mut sol = engine::solve(scene, &auto_span);
    let last_measured = measured.and_then(|m| m.t.last().copied());
    let auto = sol
        .t_end
        .max(last_measured.unwrap_or(f64::NEG_INFINITY))
        .max(pinned_end.unwrap_or(f64::NEG_INFINITY));
    sol.t_end = match end {
        SpanEnd::Auto => auto,
        SpanEnd::Scaled(f) => span.t_start + f * (auto - span.t_start),
        SpanEnd::Fixed { t_end, .. } => t_end,
    };
    sol
}

/// Every time-stepping method at the Methods view's levels, untimed (so the view,
/// like every screen, is the same for the same input).
fn method_rows(scene: &Scene, span: &Span, sol: &Solution, ticket: &Ticket) -> Vec<Row> {
    let runs: Vec<(Method, u8)> = Method::TIME_STEPPING
        .into_iter()
        .flat_map(|m| METHOD_VIEW_LEVELS.map(|l| (m, l)))
        .collect();
    let mut rows = Vec::with_capacity(runs.len());
    for (i, &(method, level)) in runs.iter().enumerate() {
        if ticket.cancelled() {
            break;
        }
        ticket.progress(i, runs.len());
        let settings = level_settings(method, level);
        match compare::measure(method, scene, span, &settings, sol, false, ticket) {
            Ok(row) => rows.push(row),
            // Superseded: the rows are dropped unseen.
            Err(_) => break,
        }
    }
    rows
}

/// One method's run at `level` over the exact curves, thinned, with its row.
fn overlay(
    method: Method,
    level: u8,
    scene: &Scene,
    span: &Span,
    sol: &Solution,
    ticket: &Ticket,
) -> Option<Overlay> {
    let settings = level_settings(method, level);
    let steps = if method.adaptive() {
        1
    } else {
        ((sol.t_end - sol.t_start) / settings.step) as usize
    };
    let mut rec = Thinned {
        points: Vec::new(),
        every: (steps / 4000).max(1),
        seen: 0,
        total: steps,
        ticket,
    };
    let model = methods::Model::of(scene);
    let y0 = methods::start_state(scene, sol.t_start);
    methods::integrate(
        method,
        &model,
        y0,
        sol.t_start,
        sol.t_end,
        &settings,
        &mut rec,
    );
    // A superseded run stops here; its (absent) result is never shown.
    let row = compare::measure(method, scene, span, &settings, sol, false, ticket).ok()?;
    Some(Overlay {
        method,
        settings,
        points: rec.points,
        row,
    })
}

/// Sample times: about four per column, plus both sides of every event so jumps and
/// kinks are drawn where they are.
fn sample_times(sol: &Solution, columns: usize) -> Vec<f64> {
    let n = 4 * columns.max(1);
    let dt = (sol.t_end - sol.t_start) / n as f64;
    let mut ts: Vec<f64> = (0..=n).map(|i| sol.t_start + i as f64 * dt).collect();
    for e in sol.visible_events() {
        ts.push(e.t);
        ts.push(e.t - 1e-12 * (1.0 + e.t.abs()));
    }
    ts.retain(|t| *t >= sol.t_start && *t <= sol.t_end);
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    ts
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
/// the impact left out).
fn data_rms(sol: &Solution, m: &Measured) -> (f64, f64) {
    let (mut sc, mut st, mut n) = (0.0, 0.0, 0usize);
    for i in (0..m.t.len()).filter(|&i| m.t[i].abs() >= 0.005) {
        let s = sol.at(m.t[i]);
        sc += (s.left.v - m.v_cm[i]).powi(2);
        st += (s.left.u - m.v_t[i]).powi(2);
        n += 1;
    }
    let n = n.max(1) as f64;
    ((sc / n).sqrt(), (st / n).sqrt())
}

/// `v_cm` linearly interpolated at `t` inside the series.
fn v_at(m: &Measured, t: f64) -> f64 {
    let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
    let f = (t - m.t[i - 1]) / (m.t[i] - m.t[i - 1]);
    m.v_cm[i - 1] + f * (m.v_cm[i] - m.v_cm[i - 1])
}

/// ∫ v_cm from the first measured time to each measured time (trapezoids: exact for
/// the linearly interpolated series).
fn cumulative(m: &Measured) -> Vec<f64> {
    let mut acc = 0.0;
    std::iter::once(0.0)
        .chain(m.t.windows(2).enumerate().map(|(i, w)| {
            acc += 0.5 * (m.v_cm[i] + m.v_cm[i + 1]) * (w[1] - w[0]);
            acc
        }))
        .collect()
}

/// ∫ v_cm from the first measured time to `t`, from the cumulative table.
fn integral_to(m: &Measured, cum: &[f64], t: f64) -> f64 {
    let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
    let t0 = m.t[i - 1];
    cum[i - 1] + 0.5 * (m.v_cm[i - 1] + v_at(m, t)) * (t - t0)
}

/// The ghost ball's track: the cumulative integral of v_cm at the measured times,
/// shifted so that the ball is at −R (where it meets the other) at t = 0; a frame then
/// only interpolates.
fn ghost_track(m: &Measured, radius: f64) -> Vec<f64> {
    let cum = cumulative(m);
    let at_impact = integral_to(m, &cum, 0.0);
    cum.iter().map(|c| c - at_impact - radius).collect()
}

/// `ys` linearly interpolated at `t` between the neighbouring finite values (a gap in
/// a track is bridged); `None` when there is none on one side.
fn interpolate(ts: &[f64], ys: &[f64], t: f64) -> Option<f64> {
    let i = ts.partition_point(|&x| x <= t);
    let before = (0..i).rev().find(|&j| ys[j].is_finite())?;
    if ts[before] == t {
        return Some(ys[before]);
    }
    let after = (i..ts.len()).find(|&j| ys[j].is_finite())?;
    let f = (t - ts[before]) / (ts[after] - ts[before]);
    Some(ys[before] + f * (ys[after] - ys[before]))
}
