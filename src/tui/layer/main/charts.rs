//! The Charts view's own state, keys and job (issue 26, as helix's components own
//! theirs; issue 36, the job as a gitui tab holds its own): which ball the velocity
//! chart shows, velocities, positions or energy, the time zoom, and the time-stepping
//! run overlaid on the exact curves. Its keys work from every view (the Fit view shows
//! the charts too; elsewhere the zoom says whose it is); the chart is built from this
//! state and the snapshot.

use super::figure::{Figure, FigureCx, NoFigure};
use super::pane::{Pane, PaneCx};
use super::zoom::{self, TimeZoom};
use crate::lab::jobs::{Job, State};
use crate::lab::{Generation, Lab, OVERLAY_LEVELS, Overlay, analyses};
use crate::methods::Method;
use crate::tui::interact::{Input, Interactive, wheel};
use crate::tui::jobs::{Jobs, Notice};
use crate::tui::vocabulary::{Action, ChartBall, Handled, View};

/// Where the charts' keys act: the cursor's time, the time span the x axis covers
/// unzoomed, whether a chart is on screen (the Charts and Fit views), and for a mouse
/// event the time under the pointer if it is over the chart's plot (the frame laid
/// out tells it).
#[derive(Clone, Copy, Debug)]
pub struct Moment {
    pub t: f64,
    pub span: (f64, f64),
    pub shown: bool,
    pub pointer: Option<f64>,
}

/// What the charts show.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChartState {
    ball: ChartBall,
    positions: bool,
    energy: bool,
    zoom: TimeZoom,
}

impl ChartState {
    /// The ball (or balls) the velocity chart shows.
    pub fn ball(&self) -> ChartBall {
        self.ball
    }

    /// True while the chart shows x(t) of both balls.
    pub fn positions(&self) -> bool {
        self.positions
    }

    /// True while the chart shows the energy.
    pub fn energy(&self) -> bool {
        self.energy
    }

    /// The time zoom.
    pub fn zoom(&self) -> TimeZoom {
        self.zoom
    }

    /// The figure of the chart shown (the energy chart has none yet).
    pub fn figure(&self) -> Result<Figure, NoFigure> {
        if self.energy {
            Err(NoFigure::Energy)
        } else if self.positions {
            Ok(Figure::Positions)
        } else {
            Ok(Figure::Velocities)
        }
    }

    /// What `action` does to the charts: handled (and what the status line says), or
    /// not theirs.
    fn key(&mut self, action: Action, at: Moment) -> Handled {
        match action {
            Action::SwitchBall => {
                self.ball = match self.ball {
                    ChartBall::Left => ChartBall::Right,
                    ChartBall::Right => ChartBall::Both,
                    ChartBall::Both => ChartBall::Left,
                };
                Handled::Consumed
            }
            Action::TogglePositions => {
                self.positions = !self.positions;
                self.energy = false;
                Handled::Consumed
            }
            Action::ToggleEnergy => {
                self.energy = !self.energy;
                self.positions = false;
                Handled::Consumed
            }
            Action::ZoomIn | Action::ZoomOut => {
                // Around the cursor: a window the wheel moved away from it comes back.
                self.zoom.follow(at.t, at.span);
                self.zoom_around(at.t, action == Action::ZoomIn, at)
            }
            Action::ZoomWhole => Handled::Say(if self.zoom.whole() {
                "time zoom off: the whole run".into()
            } else {
                "the charts show the whole run (z zooms in)".into()
            }),
            _ => Handled::Ignored,
        }
    }

    /// Zooms the time axis in (`inward`) or out around `t` (the cursor's time for the
    /// keys, the pointer's for the wheel); what the status line says.
    pub fn zoom_around(&mut self, t: f64, inward: bool, at: Moment) -> Handled {
        if !at.shown {
            return Handled::Say("the time zoom is the charts' (Charts and Fit views)".into());
        }
        let by = if inward { zoom::STEP } else { 1.0 / zoom::STEP };
        let before = self.zoom;
        let factor = self.zoom.zoom(at.span, t, by);
        let (a, b) = self.zoom.range(at.span);
        Handled::Say(match (factor > 1.0, self.zoom == before) {
            (false, _) => "time zoom off: the whole run".into(),
            (true, same) => format!(
                "time zoom ×{}{}: {} (0: the whole run)",
                zoom::text(factor),
                if same { " (the deepest)" } else { "" },
                zoom::window_text(a, b)
            ),
        })
    }

    /// Keeps the cursor at `t` inside a zoomed window (playback, a key that moved it).
    pub fn follow(&mut self, t: f64, span: (f64, f64)) {
        self.zoom.follow(t, span);
    }
}

impl Interactive<Moment> for ChartState {
    /// The charts' keys, and the wheel over the chart's plot: it zooms the time axis
    /// around the pointer's time.
    fn handle(&mut self, input: &Input, at: Moment) -> Handled {
        match (input, wheel(input), at.pointer) {
            (Input::Key(action), ..) => self.key(*action, at),
            (Input::Mouse(..), Some(inward), Some(t)) => self.zoom_around(t, inward, at),
            (Input::Mouse(..), ..) => Handled::Ignored,
        }
    }
}

/// A time-stepping run drawn over the exact curves: which (method, level), if any.
#[derive(Clone, Debug)]
pub struct OverlayRun {
    pub choice: Option<(Method, u8)>,
    /// The overlay's level when one is switched on.
    pub level: u8,
    /// `None` only for a run that was cancelled before it finished.
    run: Job<(Generation, Method, u8), Option<Overlay>>,
}

impl Default for OverlayRun {
    fn default() -> Self {
        OverlayRun {
            choice: None,
            level: 2,
            run: Job::default(),
        }
    }
}

impl OverlayRun {
    /// Asks for the chosen run of this scene (or forgets it).
    pub fn sync(&mut self, lab: &Lab, jobs: &Jobs) {
        let Some((method, level)) = self.choice else {
            self.run.cancel();
            return;
        };
        let key = (lab.generation(), method, level);
        let work = analyses::overlay(lab, method, level);
        self.run.request(jobs, key, Notice::Overlay, work);
    }

    pub fn state(&self) -> State<'_, Overlay> {
        match self.run.state() {
            State::Ready(Some(o)) => State::Ready(o),
            State::Ready(None) | State::Idle => State::Idle,
            State::Computing { done, total } => State::Computing { done, total },
        }
    }

    /// The overlay key: off, then each time-stepping method in turn, then off.
    fn cycle(&mut self) -> Handled {
        let all = Method::TIME_STEPPING;
        let next = match self.choice {
            None => Some(all[0]),
            Some((m, _)) => all
                .iter()
                .position(|x| *x == m)
                .and_then(|i| all.get(i + 1))
                .copied(),
        };
        self.choice = next.map(|m| (m, self.level));
        Handled::Say(match next {
            Some(m) => format!("overlay {}", m.name()),
            None => "overlay off".into(),
        })
    }

    /// A finer or coarser overlay step, kept for the next overlay too.
    fn level_by(&mut self, finer: bool) -> Handled {
        self.level = if finer {
            (self.level + 1).min(OVERLAY_LEVELS - 1)
        } else {
            self.level.saturating_sub(1)
        };
        if let Some((m, _)) = self.choice {
            self.choice = Some((m, self.level));
        }
        Handled::Consumed
    }

    /// The overlay's keys.
    fn key(&mut self, action: Action) -> Handled {
        match action {
            Action::CycleOverlay => self.cycle(),
            Action::OverlayFiner => self.level_by(true),
            Action::OverlayCoarser => self.level_by(false),
            _ => Handled::Ignored,
        }
    }
}

/// The Charts view: what the charts show and the run overlaid on them.
#[derive(Clone, Debug, Default)]
pub struct Charts {
    pub state: ChartState,
    pub overlay: OverlayRun,
}

impl Pane for Charts {
    fn view(&self) -> Option<View> {
        Some(View::Charts)
    }

    fn shows_charts(&self) -> bool {
        true
    }

    fn figure(&self, _: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        Some(self.state.figure())
    }

    fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        let at = Moment {
            t: cx.t,
            span: cx.span,
            shown: cx.charts_shown,
            pointer: cx.pointer.time,
        };
        match self.state.handle(input, at) {
            Handled::Ignored => match input {
                Input::Key(action) => self.overlay.key(*action),
                Input::Mouse(..) => Handled::Ignored,
            },
            answer => answer,
        }
    }

    fn sync(&mut self, cx: &PaneCx<'_>) {
        self.overlay.sync(cx.lab, cx.jobs);
    }

    /// A zoomed chart follows the cursor.
    fn moved(&mut self, t: f64, span: (f64, f64)) {
        self.state.follow(t, span);
    }
}
