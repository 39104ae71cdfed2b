//! Where `>` and `<` stop: each labelled event of the run, the impacts accumulating at
//! T∞ stepped over as one.

use crate::physics::solution::{EventKind, Solution};

/// A time `>` and `<` stop at: an event's, with its label, and for T∞ how many impacts
/// of the burst before it the stop stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventStop {
    pub t: f64,
    pub label: &'static str,
    /// Impacts merged into this stop (T∞ only), and the time they take.
    pub burst: Option<(usize, f64)>,
}

/// The share of the span within which impacts before T∞ are one burst: closer together
/// than a few pixel columns of the chart, so a stop per impact would show nothing new.
const BURST_SHARE: f64 = 0.02;

/// Where `>`/`<` stop in `sol`'s span, in time order, once per time: each labelled event
/// (impact, rolling, gliding, slipping, rest, T∞), except that the impacts accumulating
/// at T∞ (with the slips between them) within [`BURST_SHARE`] of the span before it are
/// stepped over as one, T∞ itself.
pub fn event_stops(sol: &Solution) -> Vec<EventStop> {
    let window = BURST_SHARE * (sol.t_end - sol.t_start);
    let zeno: Vec<f64> = sol
        .visible_events()
        .filter(|e| matches!(e.kind, EventKind::ZenoRest | EventKind::ZenoContact))
        .map(|e| e.t)
        .collect();
    // The T∞ that an event at `t` accumulates toward, if it is inside its burst.
    let in_burst = |t: f64| zeno.iter().any(|&z| t < z && z - t < window);
    let mut stops: Vec<EventStop> = Vec::new();
    for e in sol.visible_events() {
        let Some(label) = e.kind.label() else {
            continue;
        };
        if in_burst(e.t) {
            continue;
        }
        // One stop per time; the last impact falls on T∞ itself, and T∞ names it.
        let zeno_here = zeno.contains(&e.t);
        if stops.last().is_some_and(|s| s.t == e.t) {
            if !zeno_here {
                continue;
            }
            stops.pop();
        }
        let burst = zeno_here.then(|| {
            let impacts: Vec<f64> = sol
                .visible_events()
                .filter(|i| i.kind == EventKind::Collision && i.t <= e.t && e.t - i.t < window)
                .map(|i| i.t)
                .collect();
            (
                impacts.len(),
                impacts.first().map_or(0.0, |first| e.t - first),
            )
        });
        stops.push(EventStop {
            t: e.t,
            label,
            burst,
        });
    }
    stops
}
