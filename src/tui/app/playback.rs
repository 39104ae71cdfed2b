//! Playback: the time steps, `.`/`,` and `>`/`<`'s targets, the clock's ticks, and
//! playback in words for the status line.

use super::{App, EventStop, FPS, SPEEDS, event_stops};
use crate::settings::units::significant;

impl App {
    pub fn speed_factor(&self) -> f64 {
        SPEEDS[self.speed]
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
                m.t().iter().copied().find(|&x| x > self.t + eps)
            } else {
                m.t().iter().rev().copied().find(|&x| x < self.t - eps)
            }
        });
        let t = frame.unwrap_or(if later {
            self.t + self.frame_step()
        } else {
            self.t - self.frame_step()
        });
        t.clamp(t0, t1)
    }

    /// The next (or previous) stop of `>` (`<`) in the span: see [`event_stops`].
    pub fn event_target(&self, later: bool) -> Option<EventStop> {
        let eps = 1e-9;
        let mut stops = event_stops(&self.lab.solution).into_iter();
        if later {
            stops.find(|s| s.t > self.t + eps)
        } else {
            stops.rev().find(|s| s.t < self.t - eps)
        }
    }

    /// Moves the cursor to `t` (a click on the chart), paused.
    pub fn seek(&mut self, t: f64) {
        let sol = &self.lab.solution;
        self.playing = false;
        self.t = t.clamp(sol.t_start, sol.t_end);
    }

    /// Advances playback by `wall` real seconds; stops at the end. A zoomed chart
    /// follows the cursor.
    pub fn tick(&mut self, wall: f64) {
        if !self.playing {
            return;
        }
        let before = self.t;
        self.t += wall * self.speed_factor();
        if !self.pause_at_outcome(before) && self.t >= self.lab.solution.t_end {
            self.t = self.lab.solution.t_end;
            self.playing = false;
        }
        let span = self.chart_span();
        self.layers.main_mut().moved(self.t, span);
    }

    /// Playback in few words, for a status line that also holds a message: the time,
    /// playing or paused, and the speed if `with_speed`.
    pub fn playback_short(&self, with_speed: bool) -> String {
        let state = if self.playing { "playing" } else { "paused" };
        if with_speed {
            format!("t = {:.3} s  {state}  ×{}", self.t, self.speed_text())
        } else {
            format!("t = {:.3} s  {state}", self.t)
        }
    }

    fn speed_text(&self) -> String {
        let speed = self.speed_factor();
        if speed < 1.0 {
            format!("1/{}", (1.0 / speed).round())
        } else {
            significant(speed, 2)
        }
    }

    /// A one-line summary of playback for the status line (without the span's end
    /// while the outcome is hidden: it would tell it).
    pub fn playback(&self) -> String {
        let speed = self.speed_text();
        let sol = &self.lab.solution;
        if self.hidden().derived() {
            let state = if self.playing { "playing" } else { "paused" };
            return format!("t = {:.3} s   {state}  speed ×{speed}", self.t);
        }
        format!(
            "t = {:.3} s of {:.3} … {:.3} s   {}  speed ×{speed}",
            self.t,
            sol.t_start,
            sol.t_end,
            if self.playing { "playing" } else { "paused" },
        )
    }
}
