//! What every method shares as an interface: the run it is asked to make ([`Run`]),
//! the one signature that makes it ([`Integrator`]), what it reports while it runs
//! ([`Observer`]) and how the run ended ([`RunEnd`], with a typed [`Stall`]).

use super::system::{Model, Settings, Y};
use crate::physics::solution::Event;

/// One run to make: `model` from the state `y0` at `t0` (the rolling run-up is
/// integrated too) to `t1`, stepped as `settings` say.
#[derive(Clone, Copy, Debug)]
pub struct Run<'a> {
    pub model: &'a Model,
    pub y0: Y,
    pub t0: f64,
    pub t1: f64,
    pub settings: &'a Settings,
}

/// A solution method: each method's file holds one, and
/// [`Method::integrator`](super::Method::integrator) names it.
pub trait Integrator: Sync {
    /// Makes `run`, reporting every step and detected event to `obs`.
    fn integrate(&self, run: &Run, obs: &mut dyn Observer) -> RunEnd;
}

/// What a method reports while it runs.
pub trait Observer {
    /// Called after every accepted step (and at the start). Return false to stop.
    fn step(&mut self, t: f64, y: &Y) -> bool;
    /// Called for each event the method detects.
    fn event(&mut self, _event: Event) {}
}

/// Why a run ended before its end time; the sentence is made where it is shown.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum Stall {
    /// A fixed-step run refused before its first step: it needs `needed` steps.
    #[error("{needed} steps needed, budget {budget}")]
    OverBudget { needed: usize, budget: usize },
    /// The adaptive run spent its step budget by `t` (s).
    #[error("step budget of {budget} reached at t = {t:.6} s")]
    StepBudget { budget: usize, t: f64 },
    /// `impacts` impacts by `t` (s): an accumulation the steps cannot follow.
    #[error("{impacts} impacts by t = {t:.9} s: they accumulate faster than steps can follow")]
    Accumulating { impacts: usize, t: f64 },
    /// The step size fell to `h` (s) at `t` (s).
    #[error("step size collapsed to {h:.1e} s at t = {t:.9} s")]
    Collapsed { h: f64, t: f64 },
    /// The exact engine's event budget ended its solution early.
    #[error("the event budget ended the run early")]
    EventBudget,
}

/// How a run ended: where, after how much work, and why if early.
#[derive(Clone, Debug, PartialEq)]
pub struct RunEnd {
    pub steps: usize,
    pub rhs_evals: usize,
    /// Why the run ended early, if it did (step budget, step-size collapse).
    pub stalled: Option<Stall>,
    /// Stopped by the observer (non-finite state, …).
    pub aborted: bool,
    pub t: f64,
    pub y: Y,
}

impl RunEnd {
    /// A run not yet begun: at `t0` in state `y0`, no work done.
    pub fn at_start(t0: f64, y0: Y) -> RunEnd {
        RunEnd {
            steps: 0,
            rhs_evals: 0,
            stalled: None,
            aborted: false,
            t: t0,
            y: y0,
        }
    }
}
