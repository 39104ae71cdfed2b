//! The Charts view's own state and keys (issue 26, as helix's components own theirs):
//! which ball the velocity chart shows, velocities, positions or energy, and the time
//! zoom. The app offers each key's action here first and acts on the typed answer
//! ([`Handled`]); the chart is built from this state and the snapshot.

use super::zoom::{self, TimeZoom};
use crate::tui::interact::{Input, Interactive, wheel};
use crate::tui::vocabulary::{Action, ChartBall, Handled};

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
