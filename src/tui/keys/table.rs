//! The key table's rows: each key's names (as `--keys` takes them and the help shows
//! them), its action, its help line and its place in the hint bar. A new view is a row
//! here (`Action::ShowView`).

use crate::tui::vocabulary::{Action, Export, View};

/// One line of the key table.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    /// Key names, as `--keys` takes them and the help shows them.
    pub keys: &'static [&'static str],
    pub action: Action,
    pub help: &'static str,
    /// Short label for the hint bar, if it earns a place there, and its priority: a
    /// narrow hint bar drops the lowest first (`? help` and `q quit` never go).
    pub hint: Option<(&'static str, u8)>,
}

pub const TABLE: &[Binding] = &[
    Binding {
        keys: &["space"],
        action: Action::PlayPause,
        help: "play / pause",
        hint: Some(("play", 8)),
    },
    Binding {
        keys: &["up"],
        action: Action::Up,
        help: "previous parameter",
        hint: None,
    },
    Binding {
        keys: &["down", "tab"],
        action: Action::Down,
        help: "next parameter",
        hint: Some(("select", 7)),
    },
    Binding {
        keys: &["right"],
        action: Action::Increase,
        help: "increase the parameter (fine)",
        hint: None,
    },
    Binding {
        keys: &["left"],
        action: Action::Decrease,
        help: "decrease the parameter (fine)",
        hint: Some(("change", 7)),
    },
    Binding {
        keys: &["S-right", "pgup"],
        action: Action::IncreaseCoarse,
        help: "increase the parameter (coarse)",
        hint: None,
    },
    Binding {
        keys: &["S-left", "pgdn"],
        action: Action::DecreaseCoarse,
        help: "decrease the parameter (coarse)",
        hint: None,
    },
    Binding {
        keys: &["enter"],
        action: Action::Edit,
        help: "type a value: a bare number is in the unit shown (4.4 for b is 4.4 cm), or give a unit (44mm); up/down: earlier values, Ctrl-U clears",
        hint: Some(("type", 6)),
    },
    Binding {
        keys: &["+", "="],
        action: Action::Faster,
        help: "faster playback",
        hint: None,
    },
    Binding {
        keys: &["-"],
        action: Action::Slower,
        help: "slower playback",
        hint: Some(("speed", 2)),
    },
    Binding {
        keys: &["."],
        action: Action::StepForward,
        help: "step one frame forward (the next measured frame when data are shown)",
        hint: None,
    },
    Binding {
        keys: &[","],
        action: Action::StepBack,
        help: "step one frame back (the previous measured frame when data are shown)",
        hint: None,
    },
    Binding {
        keys: &[">"],
        action: Action::NextEvent,
        help: "jump to the next event (impact, rolling, rest, T∞); click the chart to seek",
        hint: None,
    },
    Binding {
        keys: &["<"],
        action: Action::PrevEvent,
        help: "jump to the previous event",
        hint: None,
    },
    Binding {
        keys: &["u"],
        action: Action::Undo,
        help: "undo the last change (again: the one before)",
        hint: None,
    },
    Binding {
        keys: &["R"],
        action: Action::Reset,
        help: "reset all parameters to the preset (and the command line's)",
        hint: None,
    },
    Binding {
        keys: &["t"],
        action: Action::CycleSpan,
        help: "time span: auto (a little past the last event), x2, x1/2",
        hint: None,
    },
    Binding {
        keys: &["z"],
        action: Action::ZoomIn,
        help: "charts: zoom in on time, around the cursor (the mouse wheel over a chart: around the pointer)",
        hint: None,
    },
    Binding {
        keys: &["Z"],
        action: Action::ZoomOut,
        help: "charts: zoom out on time, around the cursor",
        hint: None,
    },
    Binding {
        keys: &["0"],
        action: Action::ZoomWhole,
        help: "charts: the whole run again (no time zoom)",
        hint: None,
    },
    Binding {
        keys: &["home"],
        action: Action::Start,
        help: "go to the start",
        hint: None,
    },
    Binding {
        keys: &["end"],
        action: Action::End,
        help: "go to the end",
        hint: None,
    },
    Binding {
        keys: &["r"],
        action: Action::Restart,
        help: "restart and play",
        hint: None,
    },
    Binding {
        keys: &["b"],
        action: Action::SwitchBall,
        help: "chart: left ball, right ball, both (Forces view: left or right ball)",
        hint: None,
    },
    Binding {
        keys: &["x"],
        action: Action::TogglePositions,
        help: "chart: velocities or positions x(t)",
        hint: None,
    },
    Binding {
        keys: &["e"],
        action: Action::ToggleEnergy,
        help: "chart: energy against time (kinetic parts and what was lost to what)",
        hint: None,
    },
    Binding {
        keys: &["P"],
        action: Action::TogglePin,
        help: "pin this run (A/B): change parameters and compare; P again unpins",
        hint: None,
    },
    Binding {
        keys: &["c"],
        action: Action::ShowView(View::Methods),
        help: "Methods view: error against work of each solution method",
        hint: Some(("methods", 3)),
    },
    Binding {
        keys: &["X"],
        action: Action::CycleWorkAxis,
        help: "Methods view: work axis steps, right-hand-side evaluations, time",
        hint: None,
    },
    Binding {
        keys: &["g"],
        action: Action::ShowView(View::Map),
        help: "Map view: regime over b/R and e, this scene marked, paper's figure",
        hint: Some(("map", 3)),
    },
    Binding {
        keys: &["v"],
        action: Action::ShowView(View::Forces),
        help: "Forces view: the groove's cross-section with forces and torques, motion states, the cause-and-effect chain (b: left or right ball)",
        hint: Some(("forces", 4)),
    },
    Binding {
        keys: &["y"],
        action: Action::Predict,
        help: "predict, observe, explain: predict what the balls do after the impact (1 apart, 2 rest, 3 back), watch, then see why",
        hint: Some(("predict", 3)),
    },
    Binding {
        keys: &["B"],
        action: Action::HideWidth,
        help: "hide or show b's value (a class predicts from the picture alone)",
        hint: None,
    },
    Binding {
        keys: &["f"],
        action: Action::ShowView(View::Fit),
        help: "Fit view: the paper's line fits and a model fit to the measured data",
        hint: Some(("fit", 4)),
    },
    Binding {
        keys: &["("],
        action: Action::FitStartEarlier,
        help: "fit window: start one frame earlier",
        hint: None,
    },
    Binding {
        keys: &[")"],
        action: Action::FitStartLater,
        help: "fit window: start one frame later",
        hint: None,
    },
    Binding {
        keys: &["{"],
        action: Action::FitEndEarlier,
        help: "fit window: end one frame earlier",
        hint: None,
    },
    Binding {
        keys: &["}"],
        action: Action::FitEndLater,
        help: "fit window: end one frame later",
        hint: None,
    },
    Binding {
        keys: &["M"],
        action: Action::ModelsTable,
        help: "Fit view: every model compared, by BIC (scrolls)",
        hint: None,
    },
    Binding {
        keys: &["o"],
        action: Action::CycleOverlay,
        help: "overlay a time-stepping method on the exact curves (cycles, off)",
        hint: Some(("overlay", 1)),
    },
    Binding {
        keys: &["]"],
        action: Action::OverlayFiner,
        help: "overlay: smaller step (tighter tolerance)",
        hint: None,
    },
    Binding {
        keys: &["["],
        action: Action::OverlayCoarser,
        help: "overlay: larger step (looser tolerance)",
        hint: None,
    },
    Binding {
        keys: &["a"],
        action: Action::ApplyFit,
        help: "Fit view: put the fitted μ_k (and v0, e if fitted) into the scene",
        hint: None,
    },
    Binding {
        keys: &["V"],
        action: Action::ToggleVideo,
        help: "Scene panel: the drawn scene or the video (--data VIDEO); a click on a ball in its first frame tracks it from there",
        hint: None,
    },
    Binding {
        keys: &["d"],
        action: Action::DataTable,
        help: "table of the measured data beside the model (scrolls)",
        hint: None,
    },
    Binding {
        keys: &["D"],
        action: Action::DropData,
        help: "drop your own data (--data); a preset picked keeps them",
        hint: None,
    },
    Binding {
        keys: &["w"],
        action: Action::Export(Export::Csv),
        help: "write the run, its scene first, to a CSV file (loads with --data)",
        hint: None,
    },
    Binding {
        keys: &["W"],
        action: Action::Export(Export::Svg),
        help: "write the figure on screen to an SVG file",
        hint: None,
    },
    Binding {
        keys: &["p"],
        action: Action::Presets,
        help: "choose a preset",
        hint: Some(("presets", 5)),
    },
    Binding {
        keys: &["s"],
        action: Action::Save,
        help: "save the scene as a user preset",
        hint: None,
    },
    Binding {
        keys: &["m"],
        action: Action::ToggleMouse,
        help: "mouse on/off (click selects, scroll changes)",
        hint: None,
    },
    Binding {
        keys: &["?"],
        action: Action::Help,
        help: "this help (it scrolls; Esc closes it, another key closes it and acts)",
        hint: Some(("help", 9)),
    },
    Binding {
        keys: &["esc"],
        action: Action::Cancel,
        help: "close a popup, cancel typing, leave a view for the charts (it never quits: q does)",
        hint: None,
    },
    Binding {
        keys: &["q"],
        action: Action::Quit,
        help: "quit (twice where the scene has unsaved changes; in a popup q closes it)",
        hint: Some(("quit", 9)),
    },
    Binding {
        keys: &["C-c"],
        action: Action::QuitNow,
        help: "quit at once, from anywhere (Ctrl-Z suspends)",
        hint: None,
    },
];
