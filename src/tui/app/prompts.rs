//! What the popups ask of the app when they answer ([`Then`]): load the preset
//! picked, take a typed value, save the scene (asking before it replaces a file),
//! write an export, make the prediction. The popups themselves (their keys, their
//! lines) are layers of their own (`crate::tui::layer`).

use crate::input::preset::{PresetFile, SaveError, ToSave};
use crate::settings::units::parse_typed;

use super::{App, Field, Library, NO_FILES, Status};
use crate::tui::layer::{Confirm, Layer, Models, Prompt};
use crate::tui::vocabulary::{TextTarget, Then};

impl App {
    /// Does what a popup asked for when it answered.
    pub(super) fn then(&mut self, then: Then) {
        match then {
            Then::Nothing | Then::Pass => {}
            Then::Say(message) => self.status = Status::Info(message),
            Then::Load(i) => self.load_preset(i),
            Then::Typed(target, field) => self.typed(target, field),
            Then::Overwrite(name) => self.save(&name, true),
            Then::Predict(guess) => self.predicted(guess),
            Then::ToggleGivens => self.toggle_givens(),
            Then::OpenModels => self.open(Layer::Models(Models::default())),
            Then::Step { key, up, coarse } => self.nudge(key, up, coarse),
        }
    }

    /// Loads the library's preset `i` (the picker's choice).
    fn load_preset(&mut self, i: usize) {
        let Some(p) = self.library.presets.get(i).cloned() else {
            return;
        };
        let (name, description) = (p.name.clone(), p.description.clone());
        match self.lab.load_preset(p) {
            Ok(()) => {
                self.layers.main_mut().data_changed();
                self.t = self.lab.solution.t_start;
                self.status = Status::Info(match self.lab.own_data() {
                    // The student's data stay (the status line names them); the
                    // preset is the model.
                    Some(_) => format!("model: preset {name}; your data kept (D drops them)"),
                    None => description,
                });
            }
            Err(e) => self.status = Status::Error(format!("preset {name}: {e}")),
        }
    }

    /// A prompt's line confirmed: into its history, then the value set, the scene
    /// saved or the export written.
    fn typed(&mut self, target: TextTarget, field: Field) {
        let text = field.value().to_string();
        self.histories.of_mut(target).push(&text);
        match target {
            TextTarget::Value => self.typed_value(&text),
            TextTarget::Name => self.save(&text, false),
            TextTarget::Export(kind) => {
                if let Err(e) = self.export(kind, &text) {
                    // Keep the prompt open with the name, and say why.
                    self.status = Status::Error(format!("not written: {e}"));
                    self.open(Layer::Prompt(Prompt::new(target, field)));
                }
            }
        }
    }

    fn typed_value(&mut self, text: &str) {
        let p = self.params().param();
        match parse_typed(text, p.dim) {
            Ok(v) => {
                self.set_value(p.key, v);
                if let (Some(note), Status::Info(done)) = (si_meant(text, p.dim), &self.status) {
                    self.status = Status::Info(format!("{done}; {note}"));
                }
            }
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.screen_label())),
        }
    }

    /// Saves the scene as a user preset, asking before it replaces a file.
    pub(super) fn save(&mut self, name: &str, overwrite: bool) {
        let spec = self.lab.saved_spec();
        let scene = ToSave {
            spec: &spec,
            measured: self.lab.measured(),
            started_from: &self.lab.preset().name,
        };
        let file = PresetFile::new(scene, self.library.dir.as_deref(), name, overwrite);
        let file = match file {
            Ok(file) if !self.writes_files => {
                self.status = Status::Info(format!(
                    "{NO_FILES}: would save preset {} as {}",
                    name.trim(),
                    file.path.display()
                ));
                return;
            }
            other => other.and_then(PresetFile::write),
        };
        match file {
            Ok(path) => {
                self.kept = Some(self.lab.scene);
                self.library = Library::at(self.library.dir.clone());
                self.status = Status::Info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(_)) => self.open(Layer::Confirm(Confirm::new(name.trim()))),
            Err(e @ SaveError::BadName { .. }) => {
                // Keep the dialog open with the name as typed, and say why.
                self.status = Status::Error(format!("not saved: {e}"));
                self.open(Layer::Prompt(Prompt::new(
                    TextTarget::Name,
                    Field::new(name),
                )));
            }
            Err(e) => self.status = Status::Error(format!("not saved: {e}")),
        }
    }
}

/// What a bare number under 1 typed for a length or a mass (shown in cm or g) may
/// have meant: SI, as the command line reads it (`0.05` for b is 0.05 cm here, 5 cm
/// as `--width 0.05`); `None` for a number with a unit, 0, 1 or more, or a quantity
/// shown in its SI unit.
fn si_meant(text: &str, dim: crate::settings::units::Dimension) -> Option<String> {
    let number = text.trim().replace(',', ".");
    let x: f64 = number.parse().ok()?;
    let (shown, shift) = dim.display_unit();
    (shift != 0 && x != 0.0 && x.abs() < 1.0).then(|| {
        format!(
            "a bare number is in {shown} here: for {number} {si} type {number}{si}",
            si = dim.si_unit()
        )
    })
}
