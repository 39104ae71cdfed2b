//! Predict, observe, explain: the question before the impact, the run played from the
//! start, and the time from which the outcome shows (the view then explains it).

use crate::physics::derived::Regime;
use crate::physics::solution::{EventKind, Solution, Who};
use crate::tui::layer::{Layer, Question};

use super::{App, Prediction, Status, View};

/// When the run shows what the balls do after the first impact: the first thing that
/// ends the left ball's slide (it rolls again or rests, the next impact, a push, the
/// accumulation point), or the impact itself when nothing follows (no friction).
pub fn reveal_time(sol: &Solution) -> f64 {
    sol.events
        .iter()
        .find(|e| {
            e.t > 0.0
                && match e.kind {
                    EventKind::Rolling | EventKind::Rest => e.ball != Who::Right,
                    EventKind::Collision
                    | EventKind::ContactStart
                    | EventKind::ZenoRest
                    | EventKind::ZenoContact => true,
                    _ => false,
                }
        })
        .map_or(0.0, |e| e.t)
}

impl App {
    /// The predict key: the Forces view, paused at the start (a question asked after
    /// the impact would have its answer on screen behind it), and the question.
    pub(super) fn ask_prediction(&mut self) {
        self.layers.main_mut().show(View::Forces);
        self.playing = false;
        self.t = self.lab.solution.t_start;
        self.status = Status::None;
        self.open(Layer::Question(Question));
        // A new round: the last round's answer must not stand beside the question.
        self.prediction = None;
    }

    /// Playback that has just passed the moment a prediction's outcome shows stops
    /// there, so the class sees it beside the prediction; true if it stopped.
    pub(super) fn pause_at_outcome(&mut self, before: f64) -> bool {
        let Some(p) = &self.prediction else {
            return false;
        };
        let crossed = before < p.reveal_at && self.t >= p.reveal_at;
        if !crossed || p.scene != self.lab.scene {
            return false;
        }
        self.t = p.reveal_at;
        self.playing = false;
        self.status = Status::Predicted;
        true
    }

    /// The prediction made (the question's answer): play from the start.
    pub(super) fn predicted(&mut self, guess: Regime) {
        let sol = &self.lab.solution;
        self.prediction = Some(Prediction {
            guess,
            scene: self.lab.scene,
            reveal_at: reveal_time(sol),
        });
        self.t = sol.t_start;
        self.playing = true;
        self.status = Status::Predicted;
    }

    /// The question's `g`: the forces shown as givens until the outcome, or hidden.
    pub(super) fn toggle_givens(&mut self) {
        self.status = Status::Info(
            if self.hide.toggle_forces_givens() {
                "the forces are shown as givens until the outcome (g hides them)"
            } else {
                "the forces are hidden until the outcome (g shows them as givens)"
            }
            .into(),
        );
    }
}
