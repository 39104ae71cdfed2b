//! The paper's explanation in numbers (section 2, figures 3–5 and 8): per ball and
//! instant, the forces of the groove (weight, normal and friction forces at the contact
//! points A and B), their torques about the centre, the accelerations they cause, the
//! contact point's velocity with its part relative to the centre, and the motion state
//! the paper names from them. Closed forms for the scene; the instant's phase, push and
//! accelerations are read from the exact solution.
//!
//! Frame (the paper's, figure 4): `x` along the groove toward the right ball, `y` down,
//! `z` across the groove; A at `z = −b/2`, B at `z = +b/2`, both `r` below the centre.
//! Seen from the front (from `+x`), `z` points right, `y` down and `x` out of the
//! picture. `v_t = ω_z r` is positive for the spin that rolls the ball toward `+x`, so
//! rolling ⇔ `v_cm = v_t` for either ball.

use serde::Serialize;

use crate::physics::engine::NEGLIGIBLE_SPEED;
use crate::physics::model::Phase;
use crate::physics::scene::Scene;
use crate::physics::solution::Solution;

/// The magnitudes of one ball's forces while it slides, in one groove (they depend
/// on the scene and the ball's mass only): the numbers of the cause-and-effect chain.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sliding {
    /// `k = r / R`.
    pub k: f64,
    /// Effective radius, centre to the line AB, m.
    pub r: f64,
    /// Weight `G = m g`, N.
    pub weight: f64,
    /// `|N_A| = |N_B| = m g / (2k)`, N.
    pub normal: f64,
    /// Kinetic friction on each rail, `|F_A| = |F_B| = μ_k m g / (2k)`, N.
    pub friction: f64,
    /// `|F_net| = μ_k m g / k`, N.
    pub net_force: f64,
    /// Torque of one rail's friction about the centre, `|τ_A| = |F| R` (its lever arm
    /// from the centre to A is R long), N m.
    pub torque_each: f64,
    /// `|τ_net| = μ_k m g R`: independent of b, N m.
    pub net_torque: f64,
    /// `|a_cm| = μ_k g / k`, m/s².
    pub a_cm: f64,
    /// `|α| = 5 μ_k g / (2R)`: independent of b, 1/s².
    pub alpha: f64,
    /// `|a_t| = r |α| = 5/2 k μ_k g`, m/s².
    pub a_t: f64,
    /// `D = |a_t| / |a_cm| = 5k²/2`.
    pub d: f64,
}

impl Sliding {
    /// The values for a ball of `mass` in `scene`'s groove.
    pub fn of(scene: &Scene, mass: f64) -> Sliding {
        let k = scene.k();
        let (mu, g, radius) = (scene.mu, scene.g, scene.radius);
        let weight = mass * g;
        let friction = mu * weight / (2.0 * k);
        let alpha = 2.5 * mu * g / radius;
        Sliding {
            k,
            r: k * radius,
            weight,
            normal: weight / (2.0 * k),
            friction,
            net_force: 2.0 * friction,
            torque_each: friction * radius,
            net_torque: mu * weight * radius,
            a_cm: mu * g / k,
            alpha,
            a_t: k * radius * alpha,
            d: 2.5 * k * k,
        }
    }
}

/// How a ball moves, as the paper names it (figure 3): from its centre's velocity
/// `v_cm`, the contact points' velocity relative to the centre `v'_A = −v_t` and their
/// velocity `v_A = v_cm + v'_A`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MotionState {
    /// `v_cm = v_t = 0`.
    Rest,
    /// `v_A = 0`: the contact points do not move.
    PureRolling,
    /// `ω = 0`: translation without rotation.
    PureGliding,
    /// `v_cm = 0`: rotation without translation.
    PureSlipping,
    /// Between pure rolling and pure gliding: spin in the rolling sense, slower than
    /// rolling needs (`v_cm`, `v_t` of one sign, `|v_cm| > |v_t|`).
    RollingAndGliding,
    /// Between pure rolling and pure slipping: spin in the rolling sense, faster than
    /// rolling needs (`|v_t| > |v_cm|`).
    RollingAndSlipping,
    /// Spin against the travel (`v_cm`, `v_t` of opposite signs), as right after the
    /// impact: between pure gliding and pure slipping; the paper names no such state.
    GlidingAndSlipping,
}

impl MotionState {
    pub fn name(self) -> &'static str {
        match self {
            MotionState::Rest => "at rest",
            MotionState::PureRolling => "pure rolling",
            MotionState::PureGliding => "pure gliding",
            MotionState::PureSlipping => "pure slipping",
            MotionState::RollingAndGliding => "rolling and gliding",
            MotionState::RollingAndSlipping => "rolling and slipping",
            MotionState::GlidingAndSlipping => "gliding and slipping",
        }
    }

    /// The state of a ball with centre velocity `v` and tangential velocity `u`
    /// (`v_t`); speeds within `eps` of zero (or of each other) count as equal.
    pub fn of(v: f64, u: f64, eps: f64) -> MotionState {
        let zero = |x: f64| x.abs() <= eps;
        if zero(v) && zero(u) {
            MotionState::Rest
        } else if zero(v - u) {
            MotionState::PureRolling
        } else if zero(u) {
            MotionState::PureGliding
        } else if zero(v) {
            MotionState::PureSlipping
        } else if v * u < 0.0 {
            MotionState::GlidingAndSlipping
        } else if v.abs() > u.abs() {
            MotionState::RollingAndGliding
        } else {
            MotionState::RollingAndSlipping
        }
    }
}

/// One ball at one instant: its motion state and velocities, the forces on it and
/// what they do. Signed values are `x` components (`z` for spins and torques about
/// the axis across the groove) in the paper's frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Instant {
    pub state: MotionState,
    /// Inside the short bridge over the last, unresolved impacts before their
    /// accumulation point: the state is interpolated there, not solved.
    pub accumulating: bool,
    /// The balls press on each other (a compressive push `P > 0`).
    pub pressed: bool,
    /// `v_cm`, m/s.
    pub v_cm: f64,
    /// `v_t = ω_z r`, m/s.
    pub v_t: f64,
    /// `ω_z`, rad/s.
    pub omega: f64,
    /// Contact points' velocity `v_A = v_cm − v_t` (the slip), m/s.
    pub v_contact: f64,
    /// Their velocity relative to the centre, `v'_A = −v_t`, m/s.
    pub v_contact_rel: f64,
    /// Normal force on each rail, `m g / (2k)`, N (always).
    pub normal: f64,
    /// Friction on each rail, N: kinetic (`∓μ_k |N|`, against `v_A`) while the ball
    /// slides, else the static friction its spin change needs (0 when rolling freely).
    pub friction: f64,
    /// Whether `friction` is kinetic (the ball slides).
    pub kinetic: bool,
    /// What else pushes the centre along x, N: the other ball's push and rolling
    /// resistance (`m a_cm − 2F`).
    pub other: f64,
    /// `τ_A = (y, z)` components of rail A's friction torque, N m (`τ_B`: y mirrored).
    pub torque_a: (f64, f64),
    /// `τ_net,z = −2 r F`, N m.
    pub net_torque: f64,
    /// `a_cm = dv_cm/dt`, m/s².
    pub a_cm: f64,
    /// `a_t = dv_t/dt = r α_z`, m/s².
    pub a_t: f64,
    /// `α_z`, 1/s².
    pub alpha: f64,
}

/// Ball `ball` (0 left, 1 right) of the run `sol` at time `t` (the state right after
/// `t` where an event happens at `t`, as [`Solution::at`]).
pub fn instant(sol: &Solution, ball: usize, t: f64) -> Instant {
    let scene = &sol.scene;
    let seg = sol.segment_at(t);
    let snap = sol.at(t);
    let s = if ball == 0 { snap.left } else { snap.right };
    let mass = if ball == 0 {
        scene.left.mass
    } else {
        scene.right.mass
    };
    let k = scene.k();
    let r = k * scene.radius;
    let (a, du) = seg.accel[ball];
    let eps = NEGLIGIBLE_SPEED * scene.speed_scale();
    let (state, friction, kinetic) = match seg.phase[ball] {
        Phase::Sliding { sign } => {
            let f = -f64::from(sign) * scene.mu * mass * scene.g / (2.0 * k);
            // A sliding ball is never rolling, even where rounding makes v ≈ u.
            let st = match MotionState::of(s.v, s.u, eps) {
                MotionState::PureRolling => MotionState::of(s.v, s.u, 0.0),
                other => other,
            };
            (st, f, true)
        }
        // Newton's law of rotation: 2 F r = −I α_z with I = 2/5 m R², α_z = du/dt / r,
        // less the share of du/dt that rolling resistance's own couple gives (it takes
        // no friction from the rails: physics.md §4, §9).
        Phase::Rolling => {
            let couple = seg.rolling_share[ball] * scene.groove().rolling_acceleration(s.v);
            (
                MotionState::of(s.v, s.u, eps),
                -0.2 * mass * (du - couple) / (k * k),
                false,
            )
        }
        Phase::Resting => (MotionState::Rest, 0.0, false),
    };
    Instant {
        state,
        accumulating: seg.bridge.is_some(),
        pressed: seg.contact_force > 0.0,
        v_cm: s.v,
        v_t: s.u,
        omega: s.u / r,
        v_contact: s.v - s.u,
        v_contact_rel: -s.u,
        normal: mass * scene.g / (2.0 * k),
        friction,
        kinetic,
        other: mass * a - 2.0 * friction,
        torque_a: (-0.5 * scene.width * friction, -r * friction),
        net_torque: -2.0 * r * friction,
        a_cm: a,
        a_t: du,
        alpha: du / r,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::engine::solve;
    use crate::physics::scene::{Ball, Span};
    use crate::physics::solution::EventKind;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    fn scene(radius: f64, half: f64, mu: f64, e: f64, v0: f64) -> Scene {
        Scene {
            radius,
            width: 2.0 * radius * half,
            mu,
            restitution: e,
            left: Ball { mass: 0.167, v0 },
            right: Ball { mass: 0.167, v0 },
            ..Scene::default()
        }
    }

    #[test]
    fn states_are_named_as_the_paper_does() {
        use MotionState::*;
        let eps = 1e-12;
        assert_eq!(MotionState::of(0.3, 0.3, eps), PureRolling);
        assert_eq!(MotionState::of(-0.3, 0.0, eps), PureGliding);
        assert_eq!(MotionState::of(0.0, 0.3, eps), PureSlipping);
        assert_eq!(MotionState::of(0.0, 0.0, eps), Rest);
        assert_eq!(MotionState::of(-0.3, -0.1, eps), RollingAndGliding);
        assert_eq!(MotionState::of(0.1, 0.3, eps), RollingAndSlipping);
        assert_eq!(MotionState::of(-0.3, 0.3, eps), GlidingAndSlipping);
    }

    #[test]
    fn right_after_the_impact_friction_points_along_x_and_the_torque_along_minus_z() {
        // The paper: v_A(t0) = 2 v_cm(t0) < 0, F_A/B = +μ_k m g/(2k) e_x,
        // τ_net = −R μ_k m g e_z (its equations for F and τ_net).
        let sc = scene(0.0275, 0.7, 0.17, 1.0, 0.6);
        let sol = solve(&sc, &Span::default());
        let i = instant(&sol, 0, 0.0);
        assert_eq!(i.state, MotionState::GlidingAndSlipping);
        assert_relative_eq!(i.v_contact, 2.0 * i.v_cm, max_relative = 1e-15);
        assert!(i.v_contact < 0.0 && i.kinetic);
        let m_g = 0.167 * 9.81;
        assert_relative_eq!(
            i.friction,
            0.17 * m_g / (2.0 * sc.k()),
            max_relative = 1e-14
        );
        assert_relative_eq!(i.net_torque, -0.17 * m_g * 0.0275, max_relative = 1e-14);
        // Before it, the ball rolls: no friction, no torque.
        let before = instant(&sol, 0, -0.1);
        assert_eq!(before.state, MotionState::PureRolling);
        assert_eq!((before.friction, before.net_torque), (0.0, 0.0));
    }

    fn sliding_scenes() -> impl Strategy<Value = Scene> {
        let half = prop_oneof![Just(0.0), 0.0..0.9999f64, Just(1.0 - 1e-9)];
        let mu = prop_oneof![0.001..1.5f64, Just(1e-4)];
        let e = prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64];
        (1e-3..1.0f64, half, mu, e, 0.01..10.0f64)
            .prop_map(|(radius, half, mu, e, v0)| scene(radius, half, mu, e, v0))
    }

    proptest! {
        #[test]
        fn sliding_values_are_the_closed_forms(sc in sliding_scenes(), mass in 1e-3..10.0f64) {
            let s = Sliding::of(&sc, mass);
            let (mg, mu, radius) = (mass * sc.g, sc.mu, sc.radius);
            let k = sc.k();
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
            // r from the geometry of figure 4: R² = r² + (b/2)².
            let r_geometry = ((radius * radius - 0.25 * sc.width * sc.width).max(0.0)).sqrt();
            prop_assert!((s.r - r_geometry).abs() <= 1e-7 * radius, "r {} {}", s.r, r_geometry);
            prop_assert!(close(s.normal, mg / (2.0 * k)));
            prop_assert!(close(s.friction, mu * mg / (2.0 * k)));
            prop_assert!(close(s.net_force, mu * mg / k));
            prop_assert!(close(s.net_torque, mu * mg * radius));
            prop_assert!(close(s.a_cm, mu * sc.g / k));
            prop_assert!(close(s.a_t, 2.5 * k * mu * sc.g));
            prop_assert!(close(s.d, s.a_t / s.a_cm));
            prop_assert!(close(s.d, 2.5 * k * k));
        }

        #[test]
        fn the_instant_after_the_impact_agrees_with_the_closed_forms(sc in sliding_scenes()) {
            let sol = solve(&sc, &Span::default());
            let s = Sliding::of(&sc, sc.left.mass);
            // Half-way to the first event after the impact the left ball still slides.
            let next = sol.events.iter().find(|e| e.t > 0.0).map_or(1.0, |e| e.t);
            let t = 0.5 * next;
            for ball in 0..2 {
                let i = instant(&sol, ball, t);
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
                prop_assert!(i.kinetic);
                prop_assert!(close(i.normal, s.normal));
                prop_assert!(close(i.friction.abs(), s.friction));
                prop_assert!(close(i.net_torque.abs(), s.net_torque));
                prop_assert!(close(i.a_t.abs(), s.a_t));
                prop_assert!(close(i.alpha.abs(), s.alpha));
                // Friction opposes the contact points' velocity.
                prop_assert!(i.friction * i.v_contact < 0.0);
                let push = sol.segment_at(t).contact_force;
                if i.pressed {
                    // Friction presses the balls together (e = 0): the push is the rest.
                    prop_assert!(close(i.other.abs(), push));
                    prop_assert!(i.other * (0.5 - ball as f64) < 0.0, "pushed away from the other");
                } else {
                    prop_assert!(close(i.a_cm.abs(), s.a_cm));
                    prop_assert!(i.other.abs() <= 1e-9 * s.net_force);
                }
                prop_assert!(close(i.v_contact, i.v_cm + i.v_contact_rel));
                // |τ_A| = |F| R: its lever arm is the radius to A.
                let ta = i.torque_a.0.hypot(i.torque_a.1);
                prop_assert!(close(ta, s.torque_each));
            }
        }
    }

    /// The paper's three experiments (its presets paper-b3.5, -b4.4, -b4.9).
    fn paper(width: f64, v0: f64) -> Solution {
        let mut sc = scene(0.0275, 0.5 * width / 0.0275, 0.17, 1.0, v0);
        sc.width = width;
        solve(&sc, &Span::default())
    }

    /// The left ball's state at each of its events and half-way to the next.
    fn states_at_events(sol: &Solution) -> Vec<(EventKind, MotionState, MotionState)> {
        let events: Vec<_> = sol
            .events
            .iter()
            .filter(|e| e.ball != crate::physics::solution::Who::Right)
            .collect();
        events
            .iter()
            .enumerate()
            .map(|(n, e)| {
                let next = events.get(n + 1).map_or(e.t + 0.1, |x| x.t);
                (
                    e.kind,
                    instant(sol, 0, e.t).state,
                    instant(sol, 0, 0.5 * (e.t + next)).state,
                )
            })
            .collect()
    }

    #[test]
    fn the_paper_presets_name_the_states_of_figure_6() {
        use EventKind as E;
        use MotionState::*;
        // b = 3.5 cm < b*: the spin reverses first (pure gliding at t_r), then it rolls apart.
        let b35 = states_at_events(&paper(0.035, 0.6083));
        assert_eq!(
            b35,
            [
                (E::Collision, GlidingAndSlipping, GlidingAndSlipping),
                (E::PureGliding, PureGliding, RollingAndGliding),
                (E::Rolling, PureRolling, PureRolling),
            ]
        );
        // b = 4.4 and 4.9 cm > b*: the translation reverses first (pure slipping at t_t),
        // it rolls back and collides again; the impacts accumulate and the balls rest.
        for (b, v0) in [(0.044, 0.5318), (0.049, 0.7928)] {
            let got = states_at_events(&paper(b, v0));
            assert_eq!(
                got[..4],
                [
                    (E::Collision, GlidingAndSlipping, GlidingAndSlipping),
                    (E::PureSlipping, PureSlipping, RollingAndSlipping),
                    (E::Rolling, PureRolling, PureRolling),
                    (E::Collision, GlidingAndSlipping, GlidingAndSlipping),
                ],
                "b = {b}"
            );
            let last = got.last().unwrap();
            assert_eq!((last.0, last.1), (E::ZenoRest, Rest), "b = {b}");
            // The last impact counted is the accumulation point itself: at rest there.
            let n = got.len();
            assert_eq!(got[n - 2].0, E::Collision);
            assert_eq!(got[n - 2].1, Rest, "b = {b}");
            for (kind, at, _) in got.iter().take(got.len() - 2) {
                let expected = match kind {
                    E::Collision => GlidingAndSlipping,
                    E::PureSlipping => PureSlipping,
                    E::Rolling => PureRolling,
                    _ => Rest,
                };
                assert_eq!(*at, expected, "b = {b}, {kind:?}");
            }
        }
    }

    #[test]
    fn edge_cases_give_finite_values() {
        for (half, mu, v0) in [
            (0.0, 0.2, 0.5),
            (1.0 - 1e-12, 0.2, 0.5),
            (0.5, 0.0, 0.5),
            (0.5, 0.2, 0.0),
        ] {
            let sc = scene(0.02, half, mu, 0.0, v0);
            let sol = solve(&sc, &Span::default());
            let s = Sliding::of(&sc, 0.1);
            assert!(
                [
                    s.k,
                    s.r,
                    s.normal,
                    s.friction,
                    s.net_torque,
                    s.a_cm,
                    s.a_t,
                    s.d
                ]
                .iter()
                .all(|x| x.is_finite())
            );
            for t in [-0.1, 0.0, 0.05, sol.t_end] {
                let i = instant(&sol, 0, t);
                assert!(i.omega.is_finite() && i.friction.is_finite() && i.other.is_finite());
            }
        }
        // Without friction nothing turns: the ball glides and slips on.
        let sol = solve(&scene(0.02, 0.5, 0.0, 1.0, 0.5), &Span::default());
        let i = instant(&sol, 0, 0.1);
        assert_eq!((i.friction, i.net_torque, i.a_cm), (0.0, 0.0, 0.0));
        // v0 = 0: both rest.
        let sol = solve(&scene(0.02, 0.5, 0.2, 1.0, 0.0), &Span::default());
        assert_eq!(instant(&sol, 1, 0.1).state, MotionState::Rest);
    }

    /// Rolling resistance slows a free rolling ball without the rails' friction
    /// (physics.md §4): the view shows none, and its drag c_rr m g as `other`.
    #[test]
    fn a_free_rolling_ball_with_rolling_resistance_needs_no_rail_friction() {
        let sc = Scene {
            rolling_resistance: 0.02,
            ..scene(0.0275, 0.5, 0.2, 1.0, 0.8)
        };
        let sol = solve(&sc, &Span::default());
        let i = instant(&sol, 0, -0.1);
        assert_eq!(i.state, MotionState::PureRolling);
        assert!(i.friction.abs() <= 1e-15, "{}", i.friction);
        assert_relative_eq!(i.other, -0.02 * 0.167 * 9.81, max_relative = 1e-12);
    }
}
