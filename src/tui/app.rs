//! The lab's state and what every action does to it. No terminal here: keys arrive as
//! [`Action`]s, so the whole app is testable without one.

use crate::input::data::Measured;
use crate::input::params::{Key, SceneSpec};
use crate::input::preset::Preset;
use crate::input::units::{Dimension, parse_quantity, show, significant};
use crate::methods::{self, Method, Settings, Y};
use crate::physics::derived::Derived;
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::study::compare::{self, Row};

/// An editable row of the parameters panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Param {
    pub key: Key,
    pub label: &'static str,
    /// Step of ←/→ and of Shift+←/→ (PgUp/PgDn), SI.
    pub fine: f64,
    pub coarse: f64,
}

/// The parameters panel, top to bottom.
pub const PARAMS: [Param; 10] = [
    Param {
        key: Key::Radius,
        label: "R",
        fine: 0.0005,
        coarse: 0.005,
    },
    Param {
        key: Key::Width,
        label: "b",
        fine: 0.0005,
        coarse: 0.005,
    },
    Param {
        key: Key::MassLeft,
        label: "m left",
        fine: 0.001,
        coarse: 0.01,
    },
    Param {
        key: Key::MassRight,
        label: "m right",
        fine: 0.001,
        coarse: 0.01,
    },
    Param {
        key: Key::Mu,
        label: "mu_k",
        fine: 0.01,
        coarse: 0.05,
    },
    Param {
        key: Key::V0Left,
        label: "v0 left",
        fine: 0.01,
        coarse: 0.1,
    },
    Param {
        key: Key::V0Right,
        label: "v0 right",
        fine: 0.01,
        coarse: 0.1,
    },
    Param {
        key: Key::Height,
        label: "h (both)",
        fine: 0.002,
        coarse: 0.02,
    },
    Param {
        key: Key::Restitution,
        label: "e",
        fine: 0.01,
        coarse: 0.1,
    },
    Param {
        key: Key::RollingResistance,
        label: "c_rr",
        fine: 0.001,
        coarse: 0.01,
    },
];

/// Which ball the velocity chart shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartBall {
    Left,
    Right,
    Both,
}

/// A popup or prompt over the main screen, which takes the keys while open.
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Normal,
    Help,
    /// Preset picker with the highlighted row.
    Picker(usize),
    /// Typing a value for the selected parameter.
    Edit(String),
    /// Typing a name to save the scene as a user preset.
    SaveName(String),
    /// The file exists: overwrite it?
    ConfirmOverwrite(String),
}

/// Everything a key can do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Quit,
    Up,
    Down,
    NextParam,
    Increase,
    Decrease,
    IncreaseCoarse,
    DecreaseCoarse,
    Edit,
    Confirm,
    Cancel,
    Backspace,
    Type(char),
    PlayPause,
    Faster,
    Slower,
    StepForward,
    StepBack,
    Start,
    End,
    Restart,
    Presets,
    Save,
    Help,
    SwitchBall,
    TogglePositions,
    ToggleMethods,
    ToggleMap,
    ToggleFit,
    FitStartEarlier,
    FitStartLater,
    FitEndEarlier,
    FitEndLater,
    CycleOverlay,
    OverlayFiner,
    OverlayCoarser,
    ToggleMouse,
    Select(usize),
    /// Scroll on parameter row `i`: up increases.
    ScrollParam(usize, bool),
}

/// Playback speeds (simulated seconds per real second); slow motion by default, as
/// the whole event lasts under a second.
pub const SPEEDS: [f64; 7] = [1.0 / 32.0, 1.0 / 16.0, 1.0 / 8.0, 0.25, 0.5, 1.0, 2.0];
const DEFAULT_SPEED: usize = 3;

/// Frames per second while animating.
pub const FPS: f64 = 30.0;

/// Status line contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    None,
    Info(String),
    Error(String),
}

#[derive(Clone, Debug)]
pub struct App {
    pub preset: Preset,
    pub scene: Scene,
    pub span: Span,
    pub solution: Solution,
    pub derived: Derived,
    /// Simulated time shown, s.
    pub t: f64,
    pub playing: bool,
    pub speed: usize,
    pub selected: usize,
    pub mode: Mode,
    pub chart_ball: ChartBall,
    pub show_positions: bool,
    pub mouse: bool,
    pub status: Status,
    pub quit: bool,
    /// Where user presets are saved.
    pub preset_dir: Option<std::path::PathBuf>,
    /// Presets offered by the picker.
    pub presets: Vec<Preset>,
    /// The Methods view (work–precision) instead of the charts.
    pub methods_view: bool,
    /// Rows of the Methods view, computed when it is first shown for a scene.
    pub method_rows: Option<Vec<Row>>,
    /// A time-stepping method drawn over the exact curves, at its level.
    pub overlay_method: Option<Method>,
    pub overlay_level: u8,
    pub overlay: Option<Overlay>,
    /// The Map view (regime map and the paper's figure) instead of the charts.
    pub map_view: bool,
    /// The Fit view instead of the info panel.
    pub fit_view: bool,
    /// Line-fit window (None: the sliding phase).
    pub fit_window: (Option<f64>, Option<f64>),
    pub fits: Option<Result<crate::study::fit::Fits, String>>,
    /// Cached with each solve, not per frame: the x range (m) the balls cover, and the
    /// RMS residuals of v_cm and v_t against the measured points.
    pub extent: (f64, f64),
    pub data_rms: Option<(f64, f64)>,
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

/// A time-stepping run drawn over the exact curves.
#[derive(Clone, Debug)]
pub struct Overlay {
    pub method: Method,
    pub settings: Settings,
    /// Its steps, thinned to a few thousand points.
    pub points: Vec<(f64, Y)>,
    pub row: Row,
}

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

/// Records a run's steps, keeping at most about `limit` of them.
struct Thinned {
    points: Vec<(f64, Y)>,
    every: usize,
    seen: usize,
}

impl methods::Observer for Thinned {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        if self.seen.is_multiple_of(self.every) {
            self.points.push((t, *y));
        }
        self.seen += 1;
        y.iter().all(|v| v.is_finite())
    }
}

impl App {
    pub fn new(preset: Preset, scene: Scene, span: Span) -> App {
        let solution = engine::solve(&scene, &span);
        let derived = Derived::of(&scene);
        let t = solution.t_start;
        App {
            preset,
            scene,
            span,
            solution,
            derived,
            t,
            playing: false,
            speed: DEFAULT_SPEED,
            selected: 1,
            mode: Mode::Normal,
            chart_ball: ChartBall::Left,
            show_positions: false,
            mouse: true,
            status: Status::None,
            quit: false,
            preset_dir: crate::input::preset::user_dir(),
            presets: Preset::all().0,
            methods_view: false,
            method_rows: None,
            overlay_method: None,
            overlay_level: 2,
            overlay: None,
            map_view: false,
            fit_view: false,
            fit_window: (None, None),
            fits: None,
            extent: (0.0, 0.0),
            data_rms: None,
        }
        .with_cached_views()
    }

    fn with_cached_views(mut self) -> App {
        self.cache_views();
        self
    }

    /// What the views need from a solve that does not change from frame to frame.
    fn cache_views(&mut self) {
        self.extent = extent(&self.solution, self.scene.radius);
        self.data_rms = self.measured().map(|m| data_rms(&self.solution, m));
    }

    /// Fits the measured series (if any) with the current scene as the start.
    fn refresh_fits(&mut self) {
        self.fits = if self.fit_view {
            self.measured().map(|m| {
                crate::study::fit::fit_all(
                    &self.scene,
                    m,
                    self.fit_window,
                    &[crate::study::fit::Free::Mu],
                    &crate::study::Quiet,
                )
                .map_err(|e| e.to_string())
            })
        } else {
            None
        };
    }

    /// Moves one end of the line-fit window by one frame.
    fn move_window(&mut self, end: bool, later: bool) {
        let Some(m) = self.measured() else {
            self.status = Status::Error("this preset has no measured data to fit".into());
            return;
        };
        let current = match &self.fits {
            Some(Ok(f)) => (f.line_fit.from, f.line_fit.to),
            _ => crate::study::fit::sliding_window(m).unwrap_or((0.0, 0.0)),
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
        if end {
            self.fit_window = (Some(current.0), Some(t));
        } else {
            self.fit_window = (Some(t), Some(current.1));
        }
        self.refresh_fits();
    }

    /// Runs the overlay method on the current scene (or clears it).
    fn refresh_overlay(&mut self) {
        self.overlay = self.overlay_method.map(|method| {
            let settings = level_settings(method, self.overlay_level);
            let sol = &self.solution;
            let steps = if method.adaptive() {
                1
            } else {
                ((sol.t_end - sol.t_start) / settings.step) as usize
            };
            let mut rec = Thinned {
                points: Vec::new(),
                every: (steps / 4000).max(1),
                seen: 0,
            };
            let model = methods::Model::of(&self.scene);
            let y0 = methods::start_state(&self.scene, sol.t_start);
            methods::integrate(
                method,
                &model,
                y0,
                sol.t_start,
                sol.t_end,
                &settings,
                &mut rec,
            );
            let row = compare::measure(
                method,
                &self.scene,
                &self.span,
                &settings,
                sol,
                false,
                &crate::study::Quiet,
            )
            .expect("Quiet never cancels");
            Overlay {
                method,
                settings,
                points: rec.points,
                row,
            }
        });
    }

    /// The Methods view's rows: every time-stepping method at four levels, untimed
    /// (so the view, like every screen, is the same for the same input).
    pub fn ensure_method_rows(&mut self) {
        if self.method_rows.is_some() {
            return;
        }
        let mut rows = Vec::new();
        for method in Method::TIME_STEPPING {
            for level in [0, 2, 4, 6] {
                let settings = level_settings(method, level);
                rows.push(
                    compare::measure(
                        method,
                        &self.scene,
                        &self.span,
                        &settings,
                        &self.solution,
                        false,
                        &crate::study::Quiet,
                    )
                    .expect("Quiet never cancels"),
                );
            }
        }
        self.method_rows = Some(rows);
    }

    /// The preset's measured series (kept while parameters change, so a model can be
    /// tuned against it by hand).
    pub fn measured(&self) -> Option<&Measured> {
        self.preset.measured.as_ref()
    }

    /// Where the measured left ball is at `t`: its v_cm integrated (trapezoids) from
    /// the impact place at t = 0; `None` outside the series.
    pub fn ghost_x(&self, t: f64) -> Option<f64> {
        let m = self.measured()?;
        if t < m.t[0] || t > *m.t.last()? {
            return None;
        }
        let v_at = |t: f64| {
            let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
            let f = (t - m.t[i - 1]) / (m.t[i] - m.t[i - 1]);
            m.v_cm[i - 1] + f * (m.v_cm[i] - m.v_cm[i - 1])
        };
        let (a, b, sign) = if t >= 0.0 {
            (0.0, t, 1.0)
        } else {
            (t, 0.0, -1.0)
        };
        let mut knots: Vec<f64> = m.t.iter().copied().filter(|&x| x > a && x < b).collect();
        knots.insert(0, a);
        knots.push(b);
        let area: f64 = knots
            .windows(2)
            .map(|w| 0.5 * (v_at(w[0]) + v_at(w[1])) * (w[1] - w[0]))
            .sum();
        Some(-self.scene.radius + sign * area)
    }

    pub fn speed_factor(&self) -> f64 {
        SPEEDS[self.speed]
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
            Key::Height => self.derived.release_height,
            Key::Restitution => s.restitution,
            Key::RollingResistance => s.rolling_resistance,
            Key::G => s.g,
            Key::TStart => self.span.t_start,
            Key::TEnd => self.solution.t_end,
        }
    }

    /// The full settings layer of the current scene.
    fn spec(&self) -> SceneSpec {
        let s = &self.scene;
        SceneSpec {
            radius: Some(s.radius),
            width: Some(s.width),
            mass_left: Some(s.left.mass),
            mass_right: Some(s.right.mass),
            mu: Some(s.mu),
            v0_left: Some(s.left.v0),
            v0_right: Some(s.right.v0),
            height: None,
            restitution: Some(s.restitution),
            rolling_resistance: Some(s.rolling_resistance),
            g: Some(s.g),
            t_start: Some(self.span.t_start),
            t_end: self.span.t_end,
        }
    }

    /// Sets a parameter if the scene stays valid; otherwise says why in the status line.
    pub fn set_value(&mut self, key: Key, value: f64) {
        let mut spec = self.spec();
        if key == Key::Height {
            spec.v0_left = None;
            spec.v0_right = None;
        }
        spec.set(key, value);
        match spec.resolve() {
            Ok((scene, span)) => {
                self.load_scene(scene, span);
                let p = PARAMS.iter().find(|p| p.key == key);
                let label = p.map_or(key.name(), |p| p.label);
                self.status = Status::Info(format!(
                    "{label} = {}",
                    show(self.value(key), key.dimension())
                ));
            }
            Err(e) => self.status = Status::Error(format!("not applied: {e}")),
        }
    }

    fn load_scene(&mut self, scene: Scene, span: Span) {
        self.scene = scene;
        self.span = span;
        self.solution = engine::solve(&scene, &span);
        self.derived = Derived::of(&scene);
        self.t = self.t.clamp(self.solution.t_start, self.solution.t_end);
        self.cache_views();
        self.method_rows = None;
        if self.methods_view {
            self.ensure_method_rows();
        }
        self.refresh_overlay();
        self.refresh_fits();
    }

    fn load_preset(&mut self, preset: Preset) {
        match preset.spec.resolve() {
            Ok((scene, span)) => {
                self.status = Status::Info(preset.description.clone());
                self.preset = preset;
                self.fit_window = (None, None);
                self.load_scene(scene, span);
                self.t = self.solution.t_start;
            }
            Err(e) => self.status = Status::Error(format!("preset {}: {e}", preset.name)),
        }
    }

    fn nudge(&mut self, up: bool, coarse: bool) {
        let p = PARAMS[self.selected];
        let step = if coarse { p.coarse } else { p.fine };
        let current = self.value(p.key);
        // Snap to the step grid so repeated presses give round numbers.
        let next = ((current / step).round() + if up { 1.0 } else { -1.0 }) * step;
        self.set_value(p.key, next);
    }

    /// How far one animation frame moves the simulated time.
    pub fn frame_step(&self) -> f64 {
        self.speed_factor() / FPS
    }

    /// Advances playback by `wall` real seconds; stops at the end.
    pub fn tick(&mut self, wall: f64) {
        if !self.playing {
            return;
        }
        self.t += wall * self.speed_factor();
        if self.t >= self.solution.t_end {
            self.t = self.solution.t_end;
            self.playing = false;
        }
    }

    pub fn apply(&mut self, action: Action) {
        if action == Action::Quit {
            // q (outside typing) and Ctrl-C quit from anywhere.
            self.quit = true;
            return;
        }
        match self.mode.clone() {
            Mode::Normal => self.apply_normal(action),
            // Any key closes the help.
            Mode::Help => self.mode = Mode::Normal,
            Mode::Picker(i) => self.apply_picker(i, action),
            Mode::Edit(text) => self.apply_text(text, action, TextTarget::Value),
            Mode::SaveName(text) => self.apply_text(text, action, TextTarget::Name),
            Mode::ConfirmOverwrite(name) => match action {
                Action::Type('y') | Action::Type('Y') => {
                    self.mode = Mode::Normal;
                    self.save(&name, true);
                }
                _ => {
                    self.mode = Mode::Normal;
                    self.status = Status::Info("not saved".into());
                }
            },
        }
    }

    fn apply_normal(&mut self, action: Action) {
        let n = PARAMS.len();
        match action {
            Action::Quit | Action::Cancel => self.quit = true,
            Action::Up => self.selected = (self.selected + n - 1) % n,
            Action::Down | Action::NextParam => self.selected = (self.selected + 1) % n,
            Action::Increase => self.nudge(true, false),
            Action::Decrease => self.nudge(false, false),
            Action::IncreaseCoarse => self.nudge(true, true),
            Action::DecreaseCoarse => self.nudge(false, true),
            Action::Edit | Action::Confirm => self.mode = Mode::Edit(String::new()),
            Action::PlayPause => {
                if !self.playing && self.t >= self.solution.t_end {
                    self.t = self.solution.t_start;
                }
                self.playing = !self.playing;
            }
            Action::Faster => self.speed = (self.speed + 1).min(SPEEDS.len() - 1),
            Action::Slower => self.speed = self.speed.saturating_sub(1),
            Action::StepForward => {
                self.playing = false;
                self.t = (self.t + self.frame_step()).min(self.solution.t_end);
            }
            Action::StepBack => {
                self.playing = false;
                self.t = (self.t - self.frame_step()).max(self.solution.t_start);
            }
            Action::Start => self.t = self.solution.t_start,
            Action::End => {
                self.playing = false;
                self.t = self.solution.t_end;
            }
            Action::Restart => {
                self.t = self.solution.t_start;
                self.playing = true;
            }
            Action::Presets => {
                let i = self
                    .presets
                    .iter()
                    .position(|p| p.name == self.preset.name)
                    .unwrap_or(0);
                self.mode = Mode::Picker(i);
            }
            Action::Save => self.mode = Mode::SaveName(default_save_name(&self.preset.name)),
            Action::Help => self.mode = Mode::Help,
            Action::SwitchBall => {
                self.chart_ball = match self.chart_ball {
                    ChartBall::Left => ChartBall::Right,
                    ChartBall::Right => ChartBall::Both,
                    ChartBall::Both => ChartBall::Left,
                }
            }
            Action::TogglePositions => self.show_positions = !self.show_positions,
            Action::ToggleMethods => {
                self.methods_view = !self.methods_view;
                self.map_view = false;
                if self.methods_view {
                    self.ensure_method_rows();
                }
            }
            Action::ToggleMap => {
                self.map_view = !self.map_view;
                if self.map_view {
                    self.methods_view = false;
                }
            }
            Action::ToggleFit => {
                self.fit_view = !self.fit_view;
                self.refresh_fits();
                if self.fit_view && self.measured().is_none() {
                    self.status = Status::Error(format!(
                        "preset {} has no measured data to fit (the paper-b* presets have)",
                        self.preset.name
                    ));
                }
            }
            Action::FitStartEarlier => self.move_window(false, false),
            Action::FitStartLater => self.move_window(false, true),
            Action::FitEndEarlier => self.move_window(true, false),
            Action::FitEndLater => self.move_window(true, true),
            Action::CycleOverlay => {
                let all = Method::TIME_STEPPING;
                self.overlay_method = match self.overlay_method {
                    None => Some(all[0]),
                    Some(m) => all
                        .iter()
                        .position(|x| *x == m)
                        .and_then(|i| all.get(i + 1))
                        .copied(),
                };
                self.refresh_overlay();
                self.status = Status::Info(match &self.overlay {
                    Some(o) => format!("overlay {}: {}", o.method.name(), o.row.status.name()),
                    None => "overlay off".into(),
                });
            }
            Action::OverlayFiner | Action::OverlayCoarser => {
                let finer = action == Action::OverlayFiner;
                self.overlay_level = if finer {
                    (self.overlay_level + 1).min(OVERLAY_LEVELS - 1)
                } else {
                    self.overlay_level.saturating_sub(1)
                };
                self.refresh_overlay();
            }
            Action::ToggleMouse => {
                self.mouse = !self.mouse;
                self.status = Status::Info(format!(
                    "mouse {}",
                    if self.mouse {
                        "on"
                    } else {
                        "off (terminal selection works)"
                    }
                ));
            }
            Action::Select(i) if i < n => self.selected = i,
            Action::ScrollParam(i, up) if i < n => {
                self.selected = i;
                self.nudge(up, false);
            }
            Action::Select(_) | Action::ScrollParam(..) | Action::Backspace | Action::Type(_) => {}
        }
    }

    fn apply_picker(&mut self, i: usize, action: Action) {
        let n = self.presets.len().max(1);
        match action {
            Action::Up => self.mode = Mode::Picker((i + n - 1) % n),
            Action::Down | Action::NextParam => self.mode = Mode::Picker((i + 1) % n),
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                if let Some(p) = self.presets.get(i).cloned() {
                    self.load_preset(p);
                }
            }
            Action::Cancel | Action::Presets => self.mode = Mode::Normal,
            _ => {}
        }
    }

    fn apply_text(&mut self, mut text: String, action: Action, target: TextTarget) {
        let reopen = |text: String| match target {
            TextTarget::Value => Mode::Edit(text),
            TextTarget::Name => Mode::SaveName(text),
        };
        match action {
            Action::Type(c) => {
                text.push(c);
                self.mode = reopen(text);
            }
            Action::Backspace => {
                text.pop();
                self.mode = reopen(text);
            }
            Action::Cancel => {
                self.mode = Mode::Normal;
                self.status = Status::Info("cancelled".into());
            }
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                match target {
                    TextTarget::Value => self.typed_value(&text),
                    TextTarget::Name => self.save(&text, false),
                }
            }
            _ => self.mode = reopen(text),
        }
    }

    fn typed_value(&mut self, text: &str) {
        let p = PARAMS[self.selected];
        match parse_quantity(text, p.key.dimension()) {
            Ok(v) => self.set_value(p.key, v),
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.label)),
        }
    }

    /// Saves the scene as a user preset, atomically (temporary file, then rename), and
    /// never over an existing file unless `overwrite`.
    fn save(&mut self, name: &str, overwrite: bool) {
        let name = name.trim();
        let valid = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.');
        if !valid {
            self.status = Status::Error(format!(
                "not saved: name '{name}', allowed letters, digits, - _ ."
            ));
            return;
        }
        let Some(dir) = self.preset_dir.clone() else {
            self.status =
                Status::Error("not saved: no preset folder (set GROOVELAB_PRESETS)".into());
            return;
        };
        let path = dir.join(format!("{name}.toml"));
        if path.exists() && !overwrite {
            self.mode = Mode::ConfirmOverwrite(name.to_string());
            return;
        }
        let text = preset_toml(name, &self.scene, &self.span, &self.preset);
        let result = std::fs::create_dir_all(&dir).and_then(|()| {
            let tmp = dir.join(format!(".{name}.toml.tmp"));
            std::fs::write(&tmp, &text)?;
            std::fs::rename(&tmp, &path)
        });
        self.status = match result {
            Ok(()) => {
                self.presets = Preset::all().0;
                Status::Info(format!("saved {}", path.display()))
            }
            Err(e) => Status::Error(format!("not saved: {}: {e}", path.display())),
        };
    }

    /// A one-line summary of playback for the status line.
    pub fn playback(&self) -> String {
        let speed = self.speed_factor();
        let speed = if speed < 1.0 {
            format!("1/{}", (1.0 / speed).round())
        } else {
            significant(speed, 2)
        };
        format!(
            "t = {:.3} s of {:.3} … {:.3} s   {}  speed ×{speed}",
            self.t,
            self.solution.t_start,
            self.solution.t_end,
            if self.playing { "playing" } else { "paused" },
        )
    }
}

#[derive(Clone, Copy)]
enum TextTarget {
    Value,
    Name,
}

fn default_save_name(preset: &str) -> String {
    format!("my-{preset}")
}

/// The scene as a preset file (SI numbers, with the units in comments).
pub fn preset_toml(name: &str, scene: &Scene, span: &Span, from: &Preset) -> String {
    let mut out = format!(
        "name = \"{name}\"\ndescription = \"Saved from groovelab (started from {})\"\n\n[scene]\n",
        from.name
    );
    let rows: [(&str, f64, Dimension); 11] = [
        ("radius", scene.radius, Dimension::Length),
        ("width", scene.width, Dimension::Length),
        ("mass_left", scene.left.mass, Dimension::Mass),
        ("mass_right", scene.right.mass, Dimension::Mass),
        ("mu", scene.mu, Dimension::Ratio),
        ("v0_left", scene.left.v0, Dimension::Speed),
        ("v0_right", scene.right.v0, Dimension::Speed),
        ("restitution", scene.restitution, Dimension::Ratio),
        (
            "rolling_resistance",
            scene.rolling_resistance,
            Dimension::Ratio,
        ),
        ("g", scene.g, Dimension::Acceleration),
        ("t_start", span.t_start, Dimension::Time),
    ];
    for (key, value, dim) in rows {
        let unit = dim.si_unit();
        let comment = if unit.is_empty() {
            String::new()
        } else {
            format!("  # {unit}")
        };
        out.push_str(&format!("{key} = {value:?}{comment}\n"));
    }
    if let Some(t_end) = span.t_end {
        out.push_str(&format!("t_end = {t_end:?}  # s\n"));
    }
    out
}
