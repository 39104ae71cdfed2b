//! The app's UI state and what every action does to it: selection, popups, playback,
//! which view is shown. Everything computed about the scene is asked of the [`Lab`].
//! No terminal here: keys arrive as [`Action`]s, so the whole app is testable without one.

use std::cell::Cell;
use std::path::PathBuf;
use std::sync::LazyLock;

use crate::input::params::{Key, PARAMS, Param};
use crate::input::preset::Preset;
use crate::input::units::{Dimension, parse_typed, show, significant};
use crate::lab::jobs::State;
use crate::lab::{Lab, OVERLAY_LEVELS, SaveError};
use crate::methods::Method;

/// The rows of the parameters panel, top to bottom: the table's rows that have steps.
pub static ROWS: LazyLock<Vec<&'static Param>> =
    LazyLock::new(|| PARAMS.iter().filter(|p| p.steps.is_some()).collect());

/// Which ball the velocity chart shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartBall {
    Left,
    Right,
    Both,
}

/// What the middle of the screen shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    Charts,
    /// Work–precision of the methods instead of the charts.
    Methods,
    /// The regime map and the paper's figure instead of the charts.
    Map,
    /// The charts with the fit lines, and the Fit panel instead of the info panel.
    Fit,
}

/// What `e` and `E` write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Export {
    /// The run sampled as CSV, the columns of `simulate --format csv --sample`.
    Csv,
    /// The chart on screen as SVG.
    Svg,
}

impl Export {
    pub fn extension(self) -> &'static str {
        match self {
            Export::Csv => "csv",
            Export::Svg => "svg",
        }
    }
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
    /// Typing the file name to export to.
    Export(Export, String),
    /// The measured data beside the model's values at those times (scrolls).
    Table,
}

impl Mode {
    /// True for the prompts that take typed text (where `q` is a letter).
    pub fn is_typing(&self) -> bool {
        matches!(
            self,
            Mode::Edit(_) | Mode::SaveName(_) | Mode::ConfirmOverwrite(_) | Mode::Export(..)
        )
    }
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
    /// The energy chart instead of the velocities.
    ToggleEnergy,
    /// The span key: auto, ×2, ×½ (see [`crate::lab::SpanEnd`]).
    CycleSpan,
    NextEvent,
    PrevEvent,
    /// Pin the current run for an A/B comparison, or unpin it.
    TogglePin,
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
    /// Fit view: the fitted values into the scene.
    ApplyFit,
    Export(Export),
    DataTable,
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

/// The presets the picker offers and the folder the app saves to.
#[derive(Clone, Debug, PartialEq)]
pub struct Library {
    pub dir: Option<PathBuf>,
    pub presets: Vec<Preset>,
}

impl Library {
    /// Built-in presets and those in `dir`, where the app also saves.
    pub fn at(dir: Option<PathBuf>) -> Library {
        let presets = Preset::all_in(dir.as_deref()).0;
        Library { dir, presets }
    }

    /// The user's preset folder ([`crate::input::preset::user_dir`]).
    pub fn user() -> Library {
        Library::at(crate::input::preset::user_dir())
    }
}

#[derive(Clone, Debug)]
pub struct App {
    pub lab: Lab,
    /// Simulated time shown, s.
    pub t: f64,
    pub playing: bool,
    pub speed: usize,
    pub selected: usize,
    pub mode: Mode,
    pub chart_ball: ChartBall,
    pub show_positions: bool,
    /// The energy chart (instead of velocities or positions).
    pub show_energy: bool,
    pub mouse: bool,
    pub status: Status,
    pub quit: bool,
    pub library: Library,
    pub view: View,
    /// The overlay's level when one is switched on.
    pub overlay_level: u8,
    /// First line shown of a scrolling popup (help, data table).
    pub scroll: usize,
    /// The largest useful `scroll` at the last drawn size (the popup sets it when it
    /// draws, so a key never scrolls into blank lines).
    pub scroll_max: Cell<usize>,
    /// Where `e`/`E` write a bare file name.
    pub export_dir: PathBuf,
}

impl App {
    pub fn new(lab: Lab, library: Library) -> App {
        App {
            t: lab.solution.t_start,
            lab,
            playing: false,
            speed: DEFAULT_SPEED,
            selected: 1,
            mode: Mode::Normal,
            chart_ball: ChartBall::Left,
            show_positions: false,
            show_energy: false,
            mouse: true,
            status: Status::None,
            quit: false,
            library,
            view: View::Charts,
            overlay_level: 2,
            scroll: 0,
            scroll_max: Cell::new(usize::MAX),
            export_dir: PathBuf::from("."),
        }
    }

    /// True in the Fit view (charts with fit lines, the Fit panel).
    pub fn fit_view(&self) -> bool {
        self.view == View::Fit
    }

    pub fn speed_factor(&self) -> f64 {
        SPEEDS[self.speed]
    }

    /// Sets a parameter if the scene stays valid; otherwise says why in the status line.
    pub fn set_value(&mut self, key: Key, value: f64) {
        match self.lab.set(key, value) {
            Ok(()) => {
                let sol = &self.lab.solution;
                self.t = self.t.clamp(sol.t_start, sol.t_end);
                let label = ROWS
                    .iter()
                    .find(|p| p.key == key)
                    .map_or(key.name(), |p| p.label);
                self.status = Status::Info(format!(
                    "{label} = {}",
                    show(self.lab.value(key), key.dimension())
                ));
                let s = &self.lab.scene;
                if key == Key::V0 && s.left.v0 == s.right.v0 {
                    self.status = Status::Info(format!(
                        "v0 of both balls = {}",
                        show(s.left.v0, Dimension::Speed)
                    ));
                }
            }
            Err(e) => self.status = Status::Error(format!("not applied: {e}")),
        }
    }

    fn nudge(&mut self, up: bool, coarse: bool) {
        let p = ROWS[self.selected];
        let Some(steps) = p.steps else { return };
        let step = if coarse { steps.coarse } else { steps.fine };
        let current = self.lab.value(p.key);
        // Snap to the step grid so repeated presses give round numbers.
        let next = ((current / step).round() + if up { 1.0 } else { -1.0 }) * step;
        self.set_value(p.key, next);
    }

    /// How far one animation frame moves the simulated time.
    pub fn frame_step(&self) -> f64 {
        self.speed_factor() / FPS
    }

    /// The time one `.` (`later`) or `,` moves to: the next or previous measured frame
    /// when the preset carries measured data and there is one, else one animation frame.
    pub fn step_target(&self, later: bool) -> f64 {
        let (t0, t1) = (self.lab.solution.t_start, self.lab.solution.t_end);
        // Times within a nanosecond of the cursor are where it is, not a step away.
        let eps = 1e-9;
        let frame = self.lab.measured().and_then(|m| {
            if later {
                m.t.iter().copied().find(|&x| x > self.t + eps)
            } else {
                m.t.iter().rev().copied().find(|&x| x < self.t - eps)
            }
        });
        let t = frame.unwrap_or(if later {
            self.t + self.frame_step()
        } else {
            self.t - self.frame_step()
        });
        t.clamp(t0, t1)
    }

    /// The next (or previous) marked event's time in the span: impact, rolling, gliding,
    /// slipping, rest, T∞ (what the charts draw as lines).
    pub fn event_target(&self, later: bool) -> Option<f64> {
        let eps = 1e-9;
        let mut times = self
            .lab
            .solution
            .visible_events()
            .filter(|e| e.kind.label().is_some())
            .map(|e| e.t);
        if later {
            times.find(|&x| x > self.t + eps)
        } else {
            times.filter(|&x| x < self.t - eps).last()
        }
    }

    /// Moves the cursor to `t` (a click on the chart), paused.
    pub fn seek(&mut self, t: f64) {
        let sol = &self.lab.solution;
        self.playing = false;
        self.t = t.clamp(sol.t_start, sol.t_end);
    }

    /// Advances playback by `wall` real seconds; stops at the end.
    pub fn tick(&mut self, wall: f64) {
        if !self.playing {
            return;
        }
        self.t += wall * self.speed_factor();
        if self.t >= self.lab.solution.t_end {
            self.t = self.lab.solution.t_end;
            self.playing = false;
        }
    }

    pub fn apply(&mut self, action: Action) {
        if action == Action::Quit {
            // Ctrl-C quits from anywhere; `q` only reaches here from the normal screen
            // (in a popup the key table makes it close the popup, in a prompt it types).
            self.quit = true;
            return;
        }
        match self.mode.clone() {
            Mode::Normal => self.apply_normal(action),
            // Scroll keys scroll the help, any other key closes it.
            Mode::Help | Mode::Table => {
                if !self.scroll_popup(action) {
                    self.mode = Mode::Normal;
                }
            }
            Mode::Picker(i) => self.apply_picker(i, action),
            Mode::Edit(text) => self.apply_text(text, action, TextTarget::Value),
            Mode::SaveName(text) => self.apply_text(text, action, TextTarget::Name),
            Mode::Export(kind, text) => self.apply_text(text, action, TextTarget::Export(kind)),
            Mode::ConfirmOverwrite(name) => {
                self.mode = Mode::Normal;
                match action {
                    Action::Type('y' | 'Y') => self.save(&name, true),
                    _ => self.status = Status::Info("not saved".into()),
                }
            }
        }
    }

    fn apply_normal(&mut self, action: Action) {
        let n = ROWS.len();
        let (t0, t1) = (self.lab.solution.t_start, self.lab.solution.t_end);
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
                if !self.playing && self.t >= t1 {
                    self.t = t0;
                }
                self.playing = !self.playing;
            }
            Action::Faster => self.speed = (self.speed + 1).min(SPEEDS.len() - 1),
            Action::Slower => self.speed = self.speed.saturating_sub(1),
            Action::StepForward | Action::StepBack => {
                self.playing = false;
                self.t = self.step_target(action == Action::StepForward);
            }
            Action::NextEvent | Action::PrevEvent => {
                self.playing = false;
                match self.event_target(action == Action::NextEvent) {
                    Some(t) => {
                        self.t = t;
                        let e = self
                            .lab
                            .solution
                            .visible_events()
                            .find(|e| e.t == t && e.kind.label().is_some());
                        let name = e.and_then(|e| e.kind.label()).unwrap_or("event");
                        self.status = Status::Info(format!("{name} at t = {t:.4} s"));
                    }
                    None => {
                        self.status = Status::Info(
                            if action == Action::NextEvent {
                                "no later event in the span"
                            } else {
                                "no earlier event in the span"
                            }
                            .into(),
                        )
                    }
                }
            }
            Action::CycleSpan => {
                let next = self.lab.span_end.next();
                match self.lab.set_span_end(next) {
                    Ok(()) => {
                        let sol = &self.lab.solution;
                        self.t = self.t.clamp(sol.t_start, sol.t_end);
                        self.status = Status::Info(format!(
                            "span {}: {:.3} … {:.3} s",
                            next.describe(),
                            sol.t_start,
                            sol.t_end
                        ));
                    }
                    Err(e) => self.status = Status::Error(format!("span not changed: {e}")),
                }
            }
            Action::ToggleEnergy => {
                self.show_energy = !self.show_energy;
                self.show_positions = false;
            }
            Action::TogglePin => {
                let pinned = self.lab.toggle_pin();
                self.status = Status::Info(if pinned {
                    "pinned this run: change a parameter to compare (P unpins)".into()
                } else {
                    "unpinned".into()
                });
            }
            Action::Start => self.t = t0,
            Action::End => {
                self.playing = false;
                self.t = t1;
            }
            Action::Restart => {
                self.t = t0;
                self.playing = true;
            }
            Action::Presets => {
                let i = self
                    .library
                    .presets
                    .iter()
                    .position(|p| p.name == self.lab.preset.name)
                    .unwrap_or(0);
                self.mode = Mode::Picker(i);
            }
            Action::Save => {
                self.status = Status::None;
                self.mode = Mode::SaveName(format!("my-{}", self.lab.preset.name));
            }
            Action::Help => self.open_scrolling(Mode::Help),
            Action::DataTable => match self.lab.measured() {
                Some(_) => self.open_scrolling(Mode::Table),
                None => {
                    self.status = Status::Error(format!(
                        "preset {} has no measured data to show (the paper-b* presets have)",
                        self.lab.preset.name
                    ))
                }
            },
            Action::Export(kind) => {
                self.status = Status::None;
                let what = match kind {
                    Export::Csv => "run",
                    Export::Svg => "chart",
                };
                self.mode = Mode::Export(
                    kind,
                    format!("{}-{what}.{}", self.lab.preset.name, kind.extension()),
                );
            }
            Action::ApplyFit => self.apply_fit(),
            Action::SwitchBall => {
                self.chart_ball = match self.chart_ball {
                    ChartBall::Left => ChartBall::Right,
                    ChartBall::Right => ChartBall::Both,
                    ChartBall::Both => ChartBall::Left,
                }
            }
            Action::TogglePositions => {
                self.show_positions = !self.show_positions;
                self.show_energy = false;
            }
            Action::ToggleMethods => self.toggle_view(View::Methods),
            Action::ToggleMap => self.toggle_view(View::Map),
            Action::ToggleFit => {
                self.toggle_view(View::Fit);
                if self.fit_view() && self.lab.measured().is_none() {
                    self.status = Status::Error(format!(
                        "preset {} has no measured data to fit (the paper-b* presets have)",
                        self.lab.preset.name
                    ));
                }
            }
            Action::FitStartEarlier => self.move_window(false, false),
            Action::FitStartLater => self.move_window(false, true),
            Action::FitEndEarlier => self.move_window(true, false),
            Action::FitEndLater => self.move_window(true, true),
            Action::CycleOverlay => {
                let all = Method::TIME_STEPPING;
                let next = match self.lab.overlay_choice() {
                    None => Some(all[0]),
                    Some((m, _)) => all
                        .iter()
                        .position(|x| *x == m)
                        .and_then(|i| all.get(i + 1))
                        .copied(),
                };
                self.lab.set_overlay(next.map(|m| (m, self.overlay_level)));
                self.status = Status::Info(match next {
                    Some(m) => format!("overlay {}", m.name()),
                    None => "overlay off".into(),
                });
            }
            Action::OverlayFiner | Action::OverlayCoarser => {
                self.overlay_level = if action == Action::OverlayFiner {
                    (self.overlay_level + 1).min(OVERLAY_LEVELS - 1)
                } else {
                    self.overlay_level.saturating_sub(1)
                };
                if let Some((m, _)) = self.lab.overlay_choice() {
                    self.lab.set_overlay(Some((m, self.overlay_level)));
                }
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

    /// Shows `view`, or the charts if it is shown already: every view key switches
    /// directly from any view.
    fn toggle_view(&mut self, view: View) {
        self.view = if self.view == view {
            View::Charts
        } else {
            view
        };
        self.lab.want_methods(self.view == View::Methods);
        self.lab.want_fits(self.view == View::Fit);
    }

    fn open_scrolling(&mut self, mode: Mode) {
        self.scroll = 0;
        self.scroll_max.set(usize::MAX);
        self.mode = mode;
    }

    /// Scrolls the open help or table if `action` is a scroll key; false otherwise.
    fn scroll_popup(&mut self, action: Action) -> bool {
        const PAGE: usize = 10;
        // Never beyond what the last frame could show (a press after the end is felt).
        let now = self.scroll.min(self.scroll_max.get());
        self.scroll = match action {
            Action::Up => now.saturating_sub(1),
            Action::Down | Action::NextParam => now + 1,
            Action::IncreaseCoarse => now.saturating_sub(PAGE),
            Action::DecreaseCoarse => now + PAGE,
            Action::Start => 0,
            Action::End => usize::MAX,
            _ => return false,
        }
        .min(self.scroll_max.get());
        true
    }

    /// Fit view: puts the fitted μ_k (and v0, e where the fit freed them) into the scene.
    fn apply_fit(&mut self) {
        if !self.fit_view() {
            self.status = Status::Error("a applies a fit: open the Fit view first (f)".into());
            return;
        }
        let fitted = match self.lab.fits() {
            State::Ready(Ok(f)) => f.model_fit.clone(),
            State::Ready(Err(e)) => {
                self.status = Status::Error(format!("no fit to apply: {e}"));
                return;
            }
            State::Computing { .. } => {
                self.status = Status::Error("the fit is still running: try again".into());
                return;
            }
            State::Idle => {
                self.status = Status::Error("no fit to apply: this preset has no data".into());
                return;
            }
        };
        // μ_k is always fitted; v0 and e only when the fit freed them (they have an
        // uncertainty then).
        let mut changes = vec![(Key::Mu, fitted.mu)];
        if fitted.v0_se.is_some() {
            changes.push((Key::V0, fitted.v0));
        }
        if fitted.restitution_se.is_some() {
            changes.push((Key::Restitution, fitted.restitution));
        }
        let mut applied = Vec::new();
        for (key, value) in changes {
            if let Err(e) = self.lab.set(key, value) {
                self.status = Status::Error(format!("fit not applied: {e}"));
                return;
            }
            applied.push(format!(
                "{} = {}",
                key.param().symbol,
                show(value, key.dimension())
            ));
        }
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        self.status = Status::Info(format!("applied the fit: {}", applied.join(", ")));
    }

    fn move_window(&mut self, end: bool, later: bool) {
        if let Err(e) = self.lab.move_fit_window(end, later) {
            self.status = Status::Error(e);
        }
    }

    fn apply_picker(&mut self, i: usize, action: Action) {
        let n = self.library.presets.len().max(1);
        match action {
            Action::Up => self.mode = Mode::Picker((i + n - 1) % n),
            Action::Down | Action::NextParam => self.mode = Mode::Picker((i + 1) % n),
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                if let Some(p) = self.library.presets.get(i).cloned() {
                    let (name, description) = (p.name.clone(), p.description.clone());
                    match self.lab.load_preset(p) {
                        Ok(()) => {
                            self.t = self.lab.solution.t_start;
                            self.status = Status::Info(description);
                        }
                        Err(e) => self.status = Status::Error(format!("preset {name}: {e}")),
                    }
                }
            }
            Action::Cancel | Action::Presets => self.mode = Mode::Normal,
            _ => {}
        }
    }

    /// Writes the run (CSV) or the chart on screen (SVG) to `name` (in `export_dir`
    /// unless absolute), through a temporary file; says where in the status line.
    fn export(&mut self, kind: Export, name: &str) -> Result<(), String> {
        let name = name.trim();
        if name.is_empty() {
            return Err("give a file name".into());
        }
        let path = self.export_dir.join(name);
        // What can be told at once keeps the prompt open; the writing itself (the SVG
        // takes milliseconds) runs as a job and reports in the status line.
        if let Some(dir) = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty() && !d.is_dir())
        {
            return Err(format!(
                "cannot write {}: no folder {}",
                path.display(),
                dir.display()
            ));
        }
        let sol = std::sync::Arc::clone(&self.lab.solution);
        let work: Box<ExportWork> = match kind {
            Export::Csv => Box::new(move || {
                let dt = export_step(sol.t_end - sol.t_start);
                let samples = sol.sample(dt);
                let text = crate::study::export::run_csv(&sol, Some(&samples))
                    .map_err(|e| e.to_string())?;
                let what = format!(
                    "{} samples every {}",
                    samples.len(),
                    show(dt, Dimension::Time)
                );
                Ok((text.into_bytes(), what))
            }),
            Export::Svg => {
                if self.show_energy {
                    return Err(
                        "the energy chart has no SVG export yet: press e for the velocities, x for positions"
                            .into(),
                    );
                }
                let which = if self.show_positions {
                    crate::study::figures::RunChart::Positions
                } else {
                    crate::study::figures::RunChart::Velocities {
                        left: self.chart_ball != ChartBall::Right,
                        right: self.chart_ball != ChartBall::Left,
                    }
                };
                let measured = self
                    .lab
                    .measured()
                    .filter(|_| self.chart_ball != ChartBall::Right && !self.show_positions)
                    .cloned();
                Box::new(move || {
                    let text = crate::study::figures::run_chart(&sol, which, measured.as_ref())
                        .map_err(|e| format!("cannot draw the chart: {e}"))?;
                    Ok((text.into_bytes(), "the chart".to_string()))
                })
            }
        };
        self.status = Status::Info(format!("writing {}…", path.display()));
        self.lab.start_export(move || {
            let (bytes, what) = work()?;
            crate::output::write_atomically(&path, &bytes).map_err(|e| e.to_string())?;
            Ok(format!("wrote {} ({what})", path.display()))
        });
        Ok(())
    }

    /// Takes in finished analyses and a finished export (its message goes to the
    /// status line); true if anything arrived (the screen needs a redraw).
    pub fn poll(&mut self) -> bool {
        let lab = self.lab.poll();
        let export = self.take_export();
        lab || export
    }

    /// Waits for every running analysis and export (headless output is deterministic).
    pub fn wait(&mut self) {
        self.lab.wait();
        self.take_export();
    }

    fn take_export(&mut self) -> bool {
        match self.lab.take_export() {
            Some(Ok(message)) => self.status = Status::Info(message),
            Some(Err(e)) => self.status = Status::Error(format!("not written: {e}")),
            None => return false,
        }
        true
    }

    fn apply_text(&mut self, mut text: String, action: Action, target: TextTarget) {
        let reopen = |text: String| match target {
            TextTarget::Value => Mode::Edit(text),
            TextTarget::Name => Mode::SaveName(text),
            TextTarget::Export(kind) => Mode::Export(kind, text),
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
                    TextTarget::Export(kind) => {
                        if let Err(e) = self.export(kind, &text) {
                            // Keep the prompt open with the name, and say why.
                            self.status = Status::Error(format!("not written: {e}"));
                            self.mode = Mode::Export(kind, text);
                        }
                    }
                }
            }
            _ => self.mode = reopen(text),
        }
    }

    fn typed_value(&mut self, text: &str) {
        let p = ROWS[self.selected];
        match parse_typed(text, p.dim) {
            Ok(v) => self.set_value(p.key, v),
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.label)),
        }
    }

    /// Saves the scene as a user preset, asking before it replaces a file.
    fn save(&mut self, name: &str, overwrite: bool) {
        match self.lab.save(self.library.dir.as_deref(), name, overwrite) {
            Ok(path) => {
                self.library = Library::at(self.library.dir.clone());
                self.status = Status::Info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(_)) => self.mode = Mode::ConfirmOverwrite(name.trim().into()),
            Err(e @ SaveError::BadName(_)) => {
                // Keep the dialog open with the name as typed, and say why.
                self.status = Status::Error(format!("not saved: {e}"));
                self.mode = Mode::SaveName(name.to_string());
            }
            Err(e) => self.status = Status::Error(format!("not saved: {e}")),
        }
    }

    /// A one-line summary of playback for the status line.
    pub fn playback(&self) -> String {
        let speed = self.speed_factor();
        let speed = if speed < 1.0 {
            format!("1/{}", (1.0 / speed).round())
        } else {
            significant(speed, 2)
        };
        let sol = &self.lab.solution;
        format!(
            "t = {:.3} s of {:.3} … {:.3} s   {}  speed ×{speed}",
            self.t,
            sol.t_start,
            sol.t_end,
            if self.playing { "playing" } else { "paused" },
        )
    }
}

/// The body of an export job: the file's bytes and what they are, or why not.
type ExportWork = dyn FnOnce() -> Result<(Vec<u8>, String), String> + Send;

#[derive(Clone, Copy)]
enum TextTarget {
    Value,
    Name,
    Export(Export),
}

/// The CSV export's sample step for a run `span` seconds long: 1 ms, coarser (1-2-5)
/// for long runs so that a file stays under about 10,000 rows.
pub fn export_step(span: f64) -> f64 {
    let mut dt = 1e-3;
    for factor in [2.0, 2.5, 2.0].iter().cycle() {
        if span / dt <= 10_000.0 || !dt.is_finite() {
            break;
        }
        dt *= factor;
    }
    dt
}

/// The prompt of the typing field for parameter `p`: which unit a bare number is in.
pub fn typing_prompt(p: &Param) -> String {
    let (unit, _) = p.dim.display_unit();
    let example = match p.dim {
        Dimension::Length => "44mm",
        Dimension::Mass => "0.2kg",
        Dimension::Speed => "60cm/s",
        Dimension::Time => "200ms",
        Dimension::Acceleration => "9.81",
        Dimension::Ratio => "",
    };
    let name = p.label;
    if unit.is_empty() {
        format!("{name}: a plain number (e.g. 0.17), Enter applies, Esc cancels")
    } else {
        format!("{name} in {unit} (or with a unit, e.g. {example}), Enter applies, Esc cancels")
    }
}
