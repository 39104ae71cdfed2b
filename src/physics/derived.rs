//! Derived quantities, computed in one place for every front end: k, r, D, b*, the
//! regime of the first impact and why, the forces and torque as 3-D vectors in the
//! paper's frame, and the left ball's recovery after the first impact (t', v', x',
//! t_r or t_t). Summaries of a solution (impacts, accumulation, energies) are here too.

use nalgebra::Vector3;
use serde::Serialize;

use crate::physics::closed_form;
use crate::physics::engine::NEGLIGIBLE_SPEED;
use crate::physics::forces::Sliding;
use crate::physics::model::{self, BallState, Rails, slip};
use crate::physics::scene::Scene;
use crate::physics::solution::{EnergySplit, Solution};

/// What the balls do after the first impact (paper, figure 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Regime {
    /// They roll apart (`b < b*`, D > 1).
    Depart,
    /// They stop (`b = b*`, D = 1), or move on at one speed.
    Rest,
    /// They come back and collide again (`b > b*`, D < 1).
    Recollide,
}

impl Regime {
    pub fn name(self) -> &'static str {
        match self {
            Regime::Depart => "depart",
            Regime::Rest => "rest",
            Regime::Recollide => "recollide",
        }
    }
}

/// Forces on one sliding ball, N (torque N m), in the paper's frame: x along the
/// groove, y down (along gravity), z across; contact A at −b/2 in z, B at +b/2.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Forces {
    pub weight: Vector3<f64>,
    pub normal_a: Vector3<f64>,
    pub normal_b: Vector3<f64>,
    pub friction_a: Vector3<f64>,
    pub friction_b: Vector3<f64>,
    pub net: Vector3<f64>,
    /// Net torque about the centre.
    pub torque: Vector3<f64>,
}

/// Forces on a ball of mass `mass` whose slip has sign `slip_sign` (0: rolling freely).
pub fn forces(scene: &Scene, mass: f64, slip_sign: f64) -> Forces {
    let k = scene.k();
    let mg = mass * scene.g;
    let across = mg * scene.width / (4.0 * k * scene.radius);
    let friction = Vector3::new(-slip_sign * scene.mu * mg / (2.0 * k), 0.0, 0.0);
    let normal_a = Vector3::new(0.0, -0.5 * mg, across);
    let normal_b = Vector3::new(0.0, -0.5 * mg, -across);
    let weight = Vector3::new(0.0, mg, 0.0);
    // Lever arms from the centre to the contacts: r e_y ∓ b/2 e_z.
    let r = k * scene.radius;
    let arm_a = Vector3::new(0.0, r, -0.5 * scene.width);
    let arm_b = Vector3::new(0.0, r, 0.5 * scene.width);
    Forces {
        weight,
        normal_a,
        normal_b,
        friction_a: friction,
        friction_b: friction,
        net: weight + normal_a + normal_b + 2.0 * friction,
        torque: arm_a.cross(&friction) + arm_b.cross(&friction),
    }
}

/// How the left ball recovers from the first impact if nothing else interferes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Recovery {
    /// Velocity and spin right after the impact.
    pub after_impact: BallState,
    /// t': time until it rolls again, s (∞ without friction).
    pub t_roll: f64,
    /// v': its rolling speed then, positive toward the other ball, m/s.
    pub v_roll: f64,
    /// x': its place then, from the impact place, m.
    pub x_roll: f64,
    /// t_r: pure gliding (u = 0) on the way, if it happens.
    pub t_pure_gliding: Option<f64>,
    /// t_t: pure slipping (v = 0) on the way, if it happens.
    pub t_pure_slipping: Option<f64>,
    /// Centre acceleration while sliding, m/s².
    pub a_cm: f64,
    /// Tangential acceleration `du/dt` while sliding, m/s².
    pub a_t: f64,
}

/// Everything a front end shows about a scene before any time stepping.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Derived {
    pub k: f64,
    /// Effective radius of the contact circle, m.
    pub r: f64,
    pub b_star: Option<f64>,
    #[serde(rename = "D")]
    pub d: f64,
    pub regime: Regime,
    /// Relative speed of the two balls once both roll again (positive: apart), m/s.
    pub separation_speed: f64,
    /// Release height on the run-up that gives the left ball's v0, m.
    pub release_height: f64,
    pub left_after_impact: Option<Recovery>,
    /// Forces on the left ball while it slides after the first impact.
    pub forces: Forces,
    /// The paper's case: equal balls at equal speeds.
    pub symmetric: bool,
    pub restitution: f64,
    /// Each ball's forces while it slides (the Forces view's chain), left and right.
    #[serde(skip)]
    pub sliding: [Sliding; 2],
}

impl Derived {
    pub fn of(scene: &Scene) -> Derived {
        let k = scene.k();
        let groove = scene.groove();
        let impact = first_impact(scene);
        let recovery = impact
            .filter(|_| scene.mu > 0.0)
            .map(|[left, _]| recovery(&groove, left));
        let separation_speed = separation_speed(&groove, scene, impact);
        let eps = NEGLIGIBLE_SPEED * scene.speed_scale();
        let regime = if separation_speed > eps {
            Regime::Depart
        } else if separation_speed < -eps {
            Regime::Recollide
        } else {
            Regime::Rest
        };
        let slip_sign = impact.map_or(0.0, |[l, _]| {
            let s = slip(l);
            if s.abs() > eps { s.signum() } else { 0.0 }
        });
        Derived {
            k,
            r: k * scene.radius,
            b_star: closed_form::critical_width(scene.radius, scene.restitution),
            d: closed_form::determinant(k),
            regime,
            separation_speed,
            release_height: closed_form::release_height(scene.left.v0, k, scene.g),
            left_after_impact: recovery,
            forces: forces(scene, scene.left.mass, slip_sign),
            symmetric: scene.is_symmetric(),
            restitution: scene.restitution,
            sliding: [
                Sliding::of(scene, scene.left.mass),
                Sliding::of(scene, scene.right.mass),
            ],
        }
    }

    /// One sentence on why the regime happens: for the paper's symmetric scene, D e
    /// against 1 (v' ∝ 2 − 5ek² = 2(1 − D e)); otherwise the relative speed once both
    /// balls roll again.
    pub fn why(&self) -> String {
        if self.left_after_impact.is_none() {
            // No friction (or no impact): the closed forms of D do not apply.
            let w = self.separation_speed;
            return if w > 0.0 {
                format!("without friction nothing turns them back: they separate at {w:.3} m/s")
            } else if w < 0.0 {
                format!("without friction they close at {:.3} m/s", -w)
            } else {
                "no closing speed, or they move on as one: nothing separates them".to_string()
            };
        }
        if !self.symmetric {
            let w = self.separation_speed;
            return if w > 0.0 {
                format!("rolling again they separate at {w:.3} m/s")
            } else if w < 0.0 {
                format!("rolling again they close at {:.3} m/s", -w)
            } else {
                "rolling again they move as one".to_string()
            };
        }
        let de = self.d * self.restitution;
        let shown = product_shown(de);
        // Within the last digit shown, "1.000 > 1" would contradict itself: the
        // difference is shown instead, and the sentence says the margin is slight.
        let barely = (de - 1.0).abs() < 5e-4;
        if de > 1.0 + 1e-12 {
            let how = if barely {
                ", but barely: they depart slowly"
            } else {
                ""
            };
            format!("D e = {shown} > 1: translation reverses first{how}")
        } else if de < 1.0 - 1e-12 {
            let how = if barely {
                ", but barely: they come back slowly"
            } else {
                ""
            };
            format!("D e = {shown} < 1: the spin rolls them back{how}")
        } else {
            "D e = 1: both stop together".to_string()
        }
    }
}

/// D e as the reason shows it: to three decimals, or as `1 + 2e-4` where three
/// decimals would round it to 1.000 (what is true at the precision shown).
fn product_shown(de: f64) -> String {
    let off = de - 1.0;
    if off.abs() >= 5e-4 {
        format!("{de:.3}")
    } else {
        let sign = if off > 0.0 { '+' } else { '-' };
        format!("1 {sign} {:.0e}", off.abs())
    }
}

/// Both balls right after the first impact, or `None` if they meet without closing speed.
pub fn first_impact(scene: &Scene) -> Option<[BallState; 2]> {
    let (vl, vr) = (scene.left.v0, -scene.right.v0);
    (vl > vr).then(|| {
        let (l, r) = model::impact(scene.left.mass, scene.right.mass, vl, vr, scene.restitution);
        [
            BallState {
                x: -scene.radius,
                v: l,
                u: vl,
            },
            BallState {
                x: scene.radius,
                v: r,
                u: vr,
            },
        ]
    })
}

/// Right ball's minus left ball's velocity once each rolls again on its own (or,
/// without friction, right after the impact).
fn separation_speed(groove: &Rails, scene: &Scene, impact: Option<[BallState; 2]>) -> f64 {
    match impact {
        None => 0.0,
        Some([l, r]) if scene.mu > 0.0 => groove.rolling_speed(r) - groove.rolling_speed(l),
        Some([l, r]) => r.v - l.v,
    }
}

/// A ball sliding from `state` until it rolls (single-ball formulas of physics.md);
/// needs friction (μ_k > 0).
pub fn recovery(groove: &Rails, state: BallState) -> Recovery {
    let s = slip(state);
    let (a, du) = groove.sliding_accelerations(s.signum());
    let t_roll = groove.time_to_roll(s);
    let v_roll = groove.rolling_speed(state);
    let x_roll = state.v * t_roll + 0.5 * a * t_roll * t_roll;
    let crossing = |value: f64, rate: f64| {
        let t = -value / rate;
        // At b = b* both cross zero exactly as the ball rolls: that is rest, not a crossing.
        (value * rate < 0.0 && t < t_roll * (1.0 - 1e-12)).then_some(t)
    };
    Recovery {
        after_impact: state,
        t_roll,
        v_roll,
        x_roll,
        t_pure_gliding: crossing(state.u, du),
        t_pure_slipping: crossing(state.v, a),
        a_cm: a,
        a_t: du,
    }
}

/// What a run does after the first impact, as the run bears it out (interface.md):
/// unlike [`Regime`], the paper's criterion, it counts the impacts, the push between
/// the balls and rolling resistance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// One impact (or none), then they move apart for good.
    Depart,
    /// One impact (or none), then both balls stop where they are, neither moving
    /// back nor away once they roll (the paper's b = b*).
    Rest,
    /// One impact (or none), then the pair moves on at one speed without pressing.
    Together,
    /// One impact, then they head back toward each other but stop (rolling
    /// resistance) before they meet again.
    Stopped,
    /// One impact, then friction presses the touching balls together: they never
    /// part and meet again.
    Pressed,
    /// They meet again: two impacts or more (or impacts accumulating at T∞).
    Recollide,
}

impl Outcome {
    pub const ALL: [Outcome; 6] = [
        Outcome::Depart,
        Outcome::Rest,
        Outcome::Together,
        Outcome::Stopped,
        Outcome::Pressed,
        Outcome::Recollide,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Outcome::Depart => "depart",
            Outcome::Rest => "rest",
            Outcome::Together => "together",
            Outcome::Stopped => "stopped",
            Outcome::Pressed => "pressed",
            Outcome::Recollide => "recollide",
        }
    }

    /// The word the paper's criterion would give for this outcome, if one does.
    pub fn regime(self) -> Option<Regime> {
        match self {
            Outcome::Depart => Some(Regime::Depart),
            Outcome::Rest | Outcome::Together => Some(Regime::Rest),
            Outcome::Recollide => Some(Regime::Recollide),
            Outcome::Stopped | Outcome::Pressed => None,
        }
    }

    /// Whether the run bears out the paper's criterion `regime`.
    pub fn agrees_with(self, regime: Regime) -> bool {
        self.regime() == Some(regime)
    }

    /// From the facts of a run: its impacts (`accumulating`: infinitely many), whether
    /// the balls ever pressed on each other after a single impact, and the right minus
    /// left velocity once neither ball slides any more (`settled`), with whether the
    /// pair still moves then, and whether rolling resistance acts (`resisted`). Speeds
    /// within `eps` of zero count as zero.
    pub fn classify(
        (impacts, accumulating, pressed): (usize, bool, bool),
        settled: f64,
        moving: bool,
        resisted: bool,
        eps: f64,
    ) -> Outcome {
        if impacts >= 2 || accumulating {
            Outcome::Recollide
        } else if pressed {
            Outcome::Pressed
        } else if settled > eps {
            Outcome::Depart
        } else if settled < -eps && !resisted {
            // Heading back with nothing to stop them: they meet again, after the
            // run's end (a comparison cut short, a t_end before the second impact).
            Outcome::Recollide
        } else if settled < -eps {
            // Heading back, yet no second impact: rolling resistance stopped them.
            Outcome::Stopped
        } else if moving {
            Outcome::Together
        } else {
            Outcome::Rest
        }
    }

    /// What the exact run `sol` does (the whole motion, whatever span is shown).
    pub fn of(sol: &Solution) -> Outcome {
        use crate::physics::model::Phase;
        let eps = NEGLIGIBLE_SPEED * sol.scene.speed_scale();
        let pressed = sol
            .events
            .iter()
            .any(|e| e.kind == crate::physics::solution::EventKind::ContactStart);
        // The first stretch after the impact in which neither ball slides: there the
        // balls' relative velocity says whether they part, come back or stay; without
        // one (no friction) the last stretch says it.
        let settled = sol
            .segments
            .iter()
            .find(|s| {
                s.t0 >= 0.0
                    && s.phase
                        .iter()
                        .all(|p| matches!(p, Phase::Rolling | Phase::Resting))
            })
            .or(sol.segments.last());
        let (w, moving) = settled.map_or((0.0, false), |s| {
            let [l, r] = s.start;
            (r.v - l.v, l.v.abs() > eps || r.v.abs() > eps)
        });
        let resisted = sol.scene.rolling_resistance > 0.0;
        let facts = (sol.impacts, sol.accumulation.is_some(), pressed);
        Outcome::classify(facts, w, moving, resisted, eps)
    }
}

/// A solution's headline numbers.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// What the run does (whole motion); `derived.regime` is the paper's criterion.
    pub outcome: Outcome,
    pub impacts: usize,
    pub accumulation_time: Option<f64>,
    pub last_event: f64,
    pub energy_start: EnergySplit,
    pub energy_end: EnergySplit,
    pub truncated: bool,
}

impl Summary {
    pub fn of(solution: &Solution) -> Summary {
        // A span that ends before the motion does counts only the impacts it shows (the
        // solver resolved the rest too, and an accumulation point stands for infinitely
        // many, which only a span reaching it shows).
        let whole = solution.t_end >= solution.last_event_time();
        let impacts = if whole {
            solution.impacts
        } else {
            solution
                .visible_events()
                .filter(|e| e.kind == crate::physics::solution::EventKind::Collision)
                .count()
        };
        Summary {
            outcome: Outcome::of(solution),
            impacts,
            accumulation_time: solution.accumulation.filter(|&t| t <= solution.t_end),
            last_event: solution.last_event_time(),
            energy_start: solution.energy_start(),
            energy_end: solution.energy_at(solution.t_end),
            truncated: solution.truncated,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::scene::Ball;
    use proptest::prelude::*;

    /// The scene at the critical width as the screen shows it (b* = 4.26 cm, rounded
    /// from 4.2600…): D e = 1.0002, which three decimals would show as "1.000 > 1".
    #[test]
    fn the_reason_at_the_shown_critical_width_shows_the_difference() {
        let ball = Ball {
            mass: 0.167,
            v0: 0.6,
        };
        let mut sc = Scene {
            width: 0.0426,
            left: ball,
            right: ball,
            ..Scene::default()
        };
        let d = Derived::of(&sc);
        // D = 5k²/2 with k² = 1 − (b/2R)² (physics.md): 1 + 2.1e-4 here.
        let k2 = 1.0 - (0.0426f64 / 0.055).powi(2);
        assert!((d.d - 2.5 * k2).abs() < 1e-12);
        let why = d.why();
        assert_eq!(
            why,
            "D e = 1 + 2e-4 > 1: translation reverses first, but barely: they depart slowly"
        );
        // Just above b*: the other side, said the same way.
        sc.width = 0.042606;
        let why = Derived::of(&sc).why();
        assert!(
            why.starts_with("D e = 1 - ") && why.contains("< 1"),
            "{why}"
        );
        assert!(why.ends_with("but barely: they come back slowly"), "{why}");
        // Far from b*, three decimals as before.
        sc.width = 0.035;
        let why = Derived::of(&sc).why();
        assert_eq!(why, "D e = 1.488 > 1: translation reverses first");
    }

    proptest! {
        /// The 3-D vectors (a cross product here) against the sliding ball's closed
        /// forms in `physics::forces`, to rounding.
        #[test]
        fn forces_agree_with_the_sliding_balls_closed_forms(
            radius in 1e-3..1.0f64,
            half in prop_oneof![Just(0.0), 0.0..0.9999f64, Just(1.0 - 1e-9)],
            mu in prop_oneof![0.001..1.5f64, Just(1e-4)],
            mass in 1e-3..10.0f64,
        ) {
            let ball = Ball { mass: 0.167, v0: 1.0 };
            let sc = Scene {
                radius,
                width: 2.0 * radius * half,
                mu,
                restitution: 0.5,
                left: ball,
                right: ball,
                ..Scene::default()
            };
            let (s, f) = (Sliding::of(&sc, mass), forces(&sc, mass, -1.0));
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
            prop_assert!(close(f.normal_a.norm(), s.normal));
            prop_assert!(close(f.friction_a.x, s.friction));
            prop_assert!(close(f.torque.norm(), s.net_torque));
            prop_assert!(close(f.net.x / mass, s.a_cm));
        }
    }
}
