//! What the app's own keys do on the main screen (no popup open, no view took the
//! key): selection and nudging, playback, the span, the settings' undo and reset,
//! and opening the popups and prompts. The views' keys are their own
//! ([`crate::tui::layer::main`]).

use crate::lab::{Edit, Groove};
use crate::settings::params::Key;
use crate::settings::spec::SceneError;
use crate::settings::units::{Dimension, show, significant};

use super::{Action, App, Export, Field, SPEEDS, Status};
use crate::tui::layer::{DataTable, Help, Layer, Picker, Prompt};
use crate::tui::vocabulary::TextTarget;

/// What the first `q` says when the scene's changes here are not saved.
pub const UNSAVED: &str =
    "scene changed, not saved: q again quits (s saves a preset, w writes the run)";

impl App {
    /// One fine or coarse step of the selected parameter. A step past a limit stops at
    /// the last value allowed on the way (the limit itself when it is allowed, else the
    /// last fine step before it), and says so; only a step from the limit is refused.
    pub(super) fn nudge(&mut self, key: Key, up: bool, coarse: bool) {
        let p = key.param();
        let Some(steps) = p.steps else { return };
        let step = if coarse { steps.coarse } else { steps.fine };
        let current = self.lab.value(p.key);
        // Snap to the step grid so repeated presses give round numbers.
        let next = ((current / step).round() + if up { 1.0 } else { -1.0 }) * step;
        let refused = match self.lab.set(p.key, next) {
            Ok(()) => return self.applied(p.key),
            Err(e) => e,
        };
        // A refused value changes nothing and costs no solve: trying is cheap. Only a
        // value beyond the current one in the step's direction is a step.
        let beyond = |v: f64| if up { v > current } else { v < current };
        let stopped = limit_candidates(current, next, steps.fine, p.range.lo, p.range.hi)
            .filter(|&v| beyond(v))
            .any(|v| self.lab.set(p.key, v).is_ok());
        // The row's limits, short enough to stay beside the time in the status line
        // (the refused value would give a hidden b away).
        let hidden = self.hidden().value(p.key);
        let why = if hidden {
            String::new()
        } else {
            format!(" ({})", p.range.text)
        };
        if stopped {
            self.applied(p.key);
            if let Status::Info(done) = &self.status {
                self.status = Status::Info(format!("{done}, at the limit{why}"));
            }
        } else if matches!(refused, SceneError::OutOfRange { key, .. } if key == p.key) {
            // Already at the limit: say so, never naming a value nobody typed.
            let value = if hidden {
                String::new()
            } else {
                format!(" ({})", show(current, p.dim))
            };
            self.status = Status::Info(format!("{} is at its limit{value}{why}", p.label));
        } else {
            self.status = Status::Error(format!("not applied: {refused}"));
        }
    }

    /// Whether values set here (typed, stepped, a fit applied) are in force and the
    /// scene is not the one last saved (`s`) or written with its run (`w`).
    fn unsaved(&self) -> bool {
        let set_here = self
            .lab
            .settings()
            .in_force()
            .iter()
            .any(|e| matches!(e, Edit::Values(_) | Edit::Fitted(_)));
        set_here && self.kept != Some(self.lab.scene)
    }

    pub(super) fn apply_normal(&mut self, action: Action) {
        if self.offer(action) {
            return;
        }
        let (t0, t1) = (self.lab.solution.t_start, self.lab.solution.t_end);
        match action {
            // Quitting loses the changes made here: with some not saved, the first
            // press says so and the second quits (a reflex q lost a student's setup).
            Action::Quit if self.unsaved() && !self.quit_asked => {
                self.quit_asked = true;
                self.status = Status::Info(UNSAVED.into());
            }
            Action::Quit | Action::QuitNow => self.quit = true,
            // Esc closes popups and cancels prompts; on the main screen it must not end
            // the session (a reflex Esc lost a student's whole setup), so it says how.
            Action::Cancel => {
                self.status = Status::Info(
                    "q quits (Esc closes popups, cancels typing, leaves a view)".into(),
                )
            }
            Action::Edit | Action::Confirm => self.open(Layer::Prompt(Prompt::new(
                TextTarget::Value,
                Field::default(),
            ))),
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
            Action::NextEvent | Action::PrevEvent => self.jump_to_event(action),
            Action::CycleSpan => self.cycle_span(),
            Action::TogglePin => self.toggle_pin(),
            Action::Start => self.t = t0,
            Action::End => {
                self.playing = false;
                self.t = t1;
            }
            Action::Restart => {
                self.t = t0;
                self.playing = true;
            }
            Action::Presets => self.open_picker(),
            Action::Save => {
                self.status = Status::None;
                let name = Field::suggested(format!("my-{}", self.lab.preset().name));
                self.open(Layer::Prompt(Prompt::new(TextTarget::Name, name)));
            }
            Action::Help => self.open(Layer::Help(Help::default())),
            Action::DataTable => self.open_data_table(),
            Action::Export(kind) => self.ask_export(kind),
            Action::Predict => self.ask_prediction(),
            Action::HideWidth => self.toggle_hide_width(),
            Action::Undo => self.undo(),
            Action::Reset => self.reset(),
            Action::DropData => self.drop_data(),
            Action::ToggleMouse => self.toggle_mouse(),
            // Every other key is a view's or the parameters panel's (offered to them
            // first, see `offer`) or a popup's.
            _ => {}
        }
    }

    /// The next or previous event (`action`), named in the status line.
    fn jump_to_event(&mut self, action: Action) {
        self.playing = false;
        self.status = Status::Info(match self.event_target(action == Action::NextEvent) {
            Some(stop) => {
                self.t = stop.t;
                let name = stop.label;
                match stop.burst {
                    // Short enough to stay whole beside the time on most screens.
                    Some((n, dt)) if n > 0 => format!(
                        "{name} at t = {:.4} s: {n} {} in {}",
                        stop.t,
                        if n == 1 { "impact" } else { "impacts" },
                        if dt < 1.0 {
                            format!(
                                "{}{}",
                                significant(Dimension::Time.to_small(dt), 3),
                                Dimension::Time.small_suffix()
                            )
                        } else {
                            show(dt, Dimension::Time).to_string()
                        }
                    ),
                    _ => format!("{name} at t = {:.4} s", stop.t),
                }
            }
            None if action == Action::NextEvent => "no later event in the span".into(),
            None => "no earlier event in the span".into(),
        });
    }

    /// The span key: auto, ×2, ×½.
    fn cycle_span(&mut self) {
        let next = self.lab.span_end.next();
        match self.lab.set_span_end(next) {
            Ok(()) => {
                let sol = &self.lab.solution;
                self.t = self.t.clamp(sol.t_start, sol.t_end);
                // The span's end would tell a hidden outcome.
                let ends = if self.hidden().derived() {
                    String::new()
                } else {
                    format!(": {:.3} … {:.3} s", sol.t_start, sol.t_end)
                };
                self.status = Status::Info(format!("span {}{ends}", next.describe()));
            }
            Err(e) => self.status = Status::Error(format!("span not changed: {e}")),
        }
    }

    fn toggle_pin(&mut self) {
        let pinned = self.lab.toggle_pin();
        // Unpinning can shorten the span (it reached the pinned run's end).
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        self.status = Status::Info(if pinned {
            "pinned this run: change a parameter to compare (P unpins)".into()
        } else {
            "unpinned".into()
        });
    }

    /// Takes back the last parameter change and says what it was.
    fn undo(&mut self) {
        let Some(edit) = self.lab.undo() else {
            self.status = Status::Info("nothing to undo".into());
            return;
        };
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        if matches!(edit, Edit::Preset(_) | Edit::DropData) {
            // The window was chosen for the data before.
            self.layers.main_mut().data_changed();
        }
        let back = match edit {
            Edit::Values(changes) | Edit::Fitted(changes) => {
                let mut keys: Vec<Key> = changes.iter().map(|(k, _)| *k).collect();
                keys.dedup();
                let shown: Vec<String> = keys
                    .iter()
                    .map(|&k| format!("{} = {}", k.param().screen_label(), self.shown_value(k)))
                    .collect();
                shown.join(", ")
            }
            Edit::SpanEnd(_) => format!("time span {}", self.lab.span_end.describe()),
            Edit::Reset => "the reset: your changes are back".into(),
            Edit::Preset(picked) => format!(
                "preset {}: back to {} as it was",
                picked.name,
                self.lab.preset().name
            ),
            Edit::DropData => match self.lab.own_data() {
                Some(own) => format!("dropping {}", own.name),
                None => "dropping the data".into(),
            },
        };
        let left = self.lab.settings().edits().len();
        self.status = Status::Info(format!("undone: {back} ({left} more to undo)"));
    }

    /// Every parameter back to the preset's (and the command line's) values.
    fn reset(&mut self) {
        if !self.lab.reset() {
            self.status = Status::Info("nothing to reset: the scene is the preset's".into());
            return;
        }
        self.layers.main_mut().data_changed();
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        let flags = self.lab.settings().flags_in_force();
        let flags = if flags.is_some_and(|f| f.given().next().is_some()) {
            " with the command line's values"
        } else {
            ""
        };
        self.status = Status::Info(format!(
            "reset to preset {}{flags} (u undoes it)",
            self.lab.preset().name
        ));
    }

    /// Drops the user's own data (undoable); the preset's are shown only in the
    /// preset's groove, and the status line says which rule applied.
    fn drop_data(&mut self) {
        self.status = Status::Info(match self.lab.drop_data() {
            Some(name) => {
                self.layers.main_mut().data_changed();
                let sol = &self.lab.solution;
                self.t = self.t.clamp(sol.t_start, sol.t_end);
                let preset = self.lab.preset();
                let now = match (self.lab.measured(), &preset.measured) {
                    (Some(_), _) => {
                        format!("{}'s data, measured in this groove, are shown", preset.name)
                    }
                    (None, Some(_)) => match Groove::of_preset(preset) {
                        Some(g) => format!(
                            "no data shown ({}'s were measured at {})",
                            preset.name,
                            g.describe()
                        ),
                        None => "no data shown".into(),
                    },
                    (None, None) => "no data shown".into(),
                };
                format!("dropped {name}: {now}; u undoes")
            }
            None => "no data of your own to drop (--data FILE loads them)".into(),
        });
    }

    /// The preset picker, on the preset the scene came from; on none while b is
    /// hidden or a prediction pends (the status line hides its name for that).
    fn open_picker(&mut self) {
        if self.hidden().derived() {
            self.open(Layer::Picker(Picker::unmarked()));
            return;
        }
        let i = self
            .library
            .presets
            .iter()
            .position(|p| p.name == self.lab.preset().name)
            .unwrap_or(0);
        self.open(Layer::Picker(Picker::on(i)));
    }

    fn open_data_table(&mut self) {
        let unfit = self
            .lab
            .unfit()
            .map(|u| (u.in_file_time.is_some(), u.name.clone()));
        match (self.lab.measured(), unfit) {
            (Some(_), _) | (None, Some((true, _))) => self.open(Layer::Table(DataTable::default())),
            (None, Some((false, name))) => {
                self.status = Status::Error(format!(
                    "no rows to show: {name}'s lengths are in doubt (f says why); groovelab data shows what it holds"
                ))
            }
            (None, None) => {
                self.status = Status::Error(format!(
                    "preset {} has no measured data to show (the paper-b* presets have)",
                    self.lab.preset().name
                ))
            }
        }
    }

    /// The export prompt, with a file name from the scene ([`crate::lab::Lab::scene_name`])
    /// and what is exported; `W`
    /// on a view without a figure says so instead.
    fn ask_export(&mut self, kind: Export) {
        self.status = Status::None;
        let what = match kind {
            Export::Csv if self.hidden().derived() => {
                let e = super::export::NoExport::Hidden("the run");
                self.status = Status::Error(e.to_string());
                return;
            }
            Export::Csv => "run",
            Export::Svg => match self.figure_on_screen() {
                Ok(figure) => figure.name(),
                Err(e) => {
                    self.status = Status::Error(e.to_string());
                    return;
                }
            },
        };
        let name = Field::suggested(format!(
            "{}-{what}.{}",
            super::export::shown_name(&self.lab, self.scene_edited(), self.hidden().derived()),
            kind.extension()
        ));
        self.open(Layer::Prompt(Prompt::new(TextTarget::Export(kind), name)));
    }

    fn toggle_hide_width(&mut self) {
        self.status = Status::Info(
            if self.hide.toggle() {
                "b's value hidden: predict from the picture (B shows it)"
            } else {
                "b's value shown"
            }
            .into(),
        );
    }

    fn toggle_mouse(&mut self) {
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
}

/// Where a step from `current` toward `target` (refused) may stop instead, nearest the
/// target first: the target clamped into the row's range `lo ..= hi`, then the fine grid
/// from the target back toward `current` (a limit that depends on other parameters,
/// b < 2R, is found on it). `current` itself is not one: a step that cannot move is
/// refused.
fn limit_candidates(
    current: f64,
    target: f64,
    fine: f64,
    lo: f64,
    hi: f64,
) -> impl Iterator<Item = f64> {
    let clamped = target.clamp(lo, hi);
    let up = target > current;
    let start = (clamped / fine).round();
    let count = ((clamped - current).abs() / fine).ceil() as i64;
    std::iter::once(clamped)
        .chain((0..=count).map(move |k| {
            let k = k as f64;
            (if up { start - k } else { start + k }) * fine
        }))
        .filter(move |&v| if up { v > current } else { v < current })
}
