//! The app's vocabulary: what a key can do ([`Action`]), which popup or prompt is open
//! ([`Mode`]), which view is shown, the status line, playback speeds, and the preset
//! library the picker offers, the prediction's answers. Plain data, no behaviour beyond
//! naming.

use std::path::PathBuf;

use crate::physics::derived::Regime;
use crate::study::preset::Preset;

pub use super::line::Field;

/// Which ball the velocity chart shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ChartBall {
    #[default]
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
    /// The paper's figures of forces, torques and motion states, and the chain.
    Forces,
}

/// What the Methods view puts on its work axis (`X` cycles it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WorkAxis {
    #[default]
    Steps,
    RhsEvals,
    Time,
}

impl WorkAxis {
    pub fn next(self) -> WorkAxis {
        match self {
            WorkAxis::Steps => WorkAxis::RhsEvals,
            WorkAxis::RhsEvals => WorkAxis::Time,
            WorkAxis::Time => WorkAxis::Steps,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            WorkAxis::Steps => "steps",
            WorkAxis::RhsEvals => "right-hand-side evaluations",
            WorkAxis::Time => "time",
        }
    }
}

/// What `w` and `W` write.
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

/// What is open over the main screen, as plain data ([`super::app::App::mode`], made
/// from the top layer): the key table reads a key by it (in a prompt `q` is a letter).
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Normal,
    Help,
    /// Preset picker with the highlighted row.
    Picker(usize),
    /// Typing a value for the selected parameter.
    Edit(Field),
    /// Typing a name to save the scene as a user preset.
    SaveName(Field),
    /// The file exists: overwrite it?
    ConfirmOverwrite(String),
    /// Typing the file name to export to.
    Export(Export, Field),
    /// The measured data beside the model's values at those times (scrolls).
    Table,
    /// The Fit view's candidate models by BIC (scrolls).
    Models,
    /// Predict, observe, explain: the question before the impact (keys 1, 2, 3).
    Predict,
}

/// A prediction of what the balls do after the impact, made before watching.
#[derive(Clone, Debug, PartialEq)]
pub struct Prediction {
    pub guess: Regime,
    /// The scene it was made for (a changed scene makes it stale).
    pub scene: crate::physics::scene::Scene,
    /// From this time on the run shows the outcome, s.
    pub reveal_at: f64,
}

/// The answers the prediction offers, by key.
pub const ANSWERS: [(char, Regime); 3] = [
    ('1', Regime::Depart),
    ('2', Regime::Rest),
    ('3', Regime::Recollide),
];

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
    /// `q`: quits, or first says what quitting loses.
    Quit,
    /// Ctrl-C: quits from anywhere, at once.
    QuitNow,
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
    /// A key typed into the ConfirmOverwrite question or the prediction's question.
    Type(char),
    /// An edit of the open prompt's line (a character, a cursor move, a deletion).
    Line(tui_input::InputRequest),
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
    /// The charts' time zoom: in (twice) around the cursor's time.
    ZoomIn,
    /// The charts' time zoom: out (by half) around the cursor's time.
    ZoomOut,
    /// The charts' time zoom: the whole run again.
    ZoomWhole,
    NextEvent,
    PrevEvent,
    /// Pin the current run for an A/B comparison, or unpin it.
    TogglePin,
    /// Shows a view, or the charts if it is shown already (every view key switches
    /// directly from any view).
    ShowView(View),
    /// Methods view: the next work axis (steps, evaluations, time).
    CycleWorkAxis,
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
    /// Fit view: every candidate model by BIC, in a scrolling popup.
    ModelsTable,
    /// Predict, observe, explain: ask, play, explain.
    Predict,
    /// Hide (or show) b's value, for a prediction from the picture alone.
    HideWidth,
    /// The Scene panel: the drawn scene or the video (`--data VIDEO`).
    ToggleVideo,
    /// Take back the last parameter change.
    Undo,
    /// Every parameter back to the preset (and the command line's values).
    Reset,
    /// Drop the user's own data (`--data`): the preset's are shown again.
    DropData,
}

/// What a component did with an input: not its input (it falls through to what lies
/// below), done, or done with a message for the status line; a popup also closes
/// itself, or asks the app for what only the app can do. The app acts on it.
#[derive(Clone, Debug, PartialEq)]
pub enum Handled {
    Ignored,
    Consumed,
    Say(String),
    /// Not done, and why (an error on the status line).
    Refused(String),
    /// The layer is done: the compositor takes it off, then the app does this.
    Close(Then),
    /// The layer stays open and asks the app for this.
    Ask(Then),
}

/// What a popup asks of the app when it answers (the lab, the files and the
/// playback are the app's, not the popup's).
#[derive(Clone, Debug, PartialEq)]
pub enum Then {
    Nothing,
    /// Nothing of the popup's: the key that closed it acts on what lies below (the
    /// compositor offers it on; the app never sees this).
    Pass,
    /// A message for the status line.
    Say(String),
    /// Load the library's preset of this index.
    Load(usize),
    /// A prompt's line, confirmed with something typed.
    Typed(TextTarget, Field),
    /// Save the scene over the preset file of this name.
    Overwrite(String),
    /// The prediction made: play and watch.
    Predict(Regime),
    /// The forces shown as givens until the outcome, or hidden (predict's `g`).
    ToggleGivens,
    /// Open the Fit view's models (`M`, asked by the Fit view).
    OpenModels,
    /// One step (fine or `coarse`) of the parameter `key`, up or down (asked by the
    /// parameters panel for its row).
    Step {
        key: crate::settings::params::Key,
        up: bool,
        coarse: bool,
    },
}

/// Which prompt text is typed into: a value, a preset's name, an export's file name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextTarget {
    Value,
    Name,
    Export(Export),
}

/// Playback speeds (simulated seconds per real second); slow motion by default, as
/// the whole event lasts under a second.
pub const SPEEDS: [f64; 7] = [1.0 / 32.0, 1.0 / 16.0, 1.0 / 8.0, 0.25, 0.5, 1.0, 2.0];
pub(super) const DEFAULT_SPEED: usize = 3;

/// Frames per second while animating.
pub const FPS: f64 = 30.0;

/// Status line contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    None,
    /// The prediction's line: what was predicted, and once the outcome shows, what
    /// happened beside it (drawn from the prediction, in every view; `Status::None`
    /// shows it too once the outcome shows).
    Predicted,
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
        let presets = crate::input::preset::all_in(dir.as_deref()).0;
        Library { dir, presets }
    }

    /// The user's preset folder ([`crate::input::preset::user_dir`]).
    pub fn user() -> Library {
        Library::at(crate::input::preset::user_dir())
    }
}
