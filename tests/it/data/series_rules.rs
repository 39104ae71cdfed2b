//! The rules a measured series and a position track keep (issue 35): built only by
//! `Measured::new` and `Track::new`, which refuse unequal lengths, times that are not
//! finite or do not increase, infinite values and negative σ, each with its typed
//! [`Rule`]; a good table is accepted and read back unchanged through the accessors;
//! random vectors are either refused or accepted with every rule holding.

use groovelab::study::measured::{Measured, MeasuredParts, Rule, Track, TrackParts};
use proptest::prelude::*;

use crate::common::cases;

/// Four frames of a ball at 100 frames/s, a gap (NaN) in v_t and in the mark.
fn good_parts() -> MeasuredParts {
    MeasuredParts {
        t: vec![-0.02, -0.01, 0.0, 0.01],
        v_cm: vec![0.8, 0.79, 0.3, 0.28],
        v_t: vec![0.8, f64::NAN, -0.1, 0.0],
        v_cm_sigma: Some(vec![0.01; 4]),
        x: Some(vec![-0.016, -0.008, 0.0, 0.003]),
        ..MeasuredParts::default()
    }
}

fn good_track() -> TrackParts {
    TrackParts {
        t: vec![0.0, 0.01, 0.02],
        x: vec![0.1, f64::NAN, 0.12],
        y: vec![0.0; 3],
        mark: Some((vec![0.1, 0.11, f64::NAN], vec![0.03; 3])),
        sigma: Some(vec![1e-4, f64::NAN, 1e-4]),
        centre_name: "ball".into(),
        format: "CSV",
        ..TrackParts::default()
    }
}

#[test]
fn a_good_series_and_track_are_accepted_and_read_back_as_given() {
    let m = Measured::new(good_parts()).unwrap();
    assert_eq!(m.t(), &[-0.02, -0.01, 0.0, 0.01]);
    assert_eq!(m.len(), 4);
    assert!(m.v_t()[1].is_nan(), "a gap stays a gap");
    assert_eq!(m.x().map(<[f64]>::len), Some(4));
    assert_eq!(m.to_parts().t, good_parts().t);
    let t = Track::new(good_track()).unwrap();
    assert_eq!((t.len(), t.centre_name(), t.format()), (3, "ball", "CSV"));
    assert!(t.mark().is_some_and(|(mx, _)| mx[2].is_nan()));
    // An empty series is a series; each caller asks for the points it needs.
    assert!(Measured::new(MeasuredParts::default()).unwrap().is_empty());
}

#[test]
fn each_rule_of_a_series_is_refused_with_its_error() {
    let with = |f: fn(&mut MeasuredParts)| {
        let mut p = good_parts();
        f(&mut p);
        Measured::new(p).unwrap_err()
    };
    assert_eq!(
        with(|p| {
            p.v_cm.pop();
        }),
        Rule::Length {
            name: "v_cm",
            len: 3,
            times: 4
        }
    );
    assert!(matches!(
        with(|p| p.x = Some(vec![0.0; 5])),
        Rule::Length {
            name: "x",
            len: 5,
            ..
        }
    ));
    assert!(matches!(
        with(|p| p.t[2] = f64::NAN),
        Rule::TimeNotFinite { point: 3, .. }
    ));
    assert_eq!(
        with(|p| p.t[2] = -0.01),
        Rule::TimeNotRising {
            value: -0.01,
            previous: -0.01,
            point: 3
        }
    );
    assert!(matches!(
        with(|p| p.v_t[0] = f64::NEG_INFINITY),
        Rule::Infinite {
            name: "v_t",
            point: 1,
            ..
        }
    ));
    assert!(matches!(
        with(|p| p.v_cm_sigma = Some(vec![0.01, -0.01, 0.01, 0.01])),
        Rule::NegativeSigma { point: 2, .. }
    ));
    assert!(matches!(
        with(|p| p.scale_rel_se = Some(f64::INFINITY)),
        Rule::ScaleSe { .. }
    ));
    // One line naming the value and what is allowed.
    let said = with(|p| p.t[3] = -1.0).to_string();
    assert_eq!(
        said,
        "t = -1 s (point 4) does not increase (previous 0 s), allowed strictly increasing times"
    );
    assert!(!said.contains('\n'));
}

#[test]
fn each_rule_of_a_track_is_refused_with_its_error() {
    let with = |f: fn(&mut TrackParts)| {
        let mut p = good_track();
        f(&mut p);
        Track::new(p).unwrap_err()
    };
    assert!(matches!(
        with(|p| p.y = vec![0.0; 2]),
        Rule::Length { name: "y", .. }
    ));
    assert!(matches!(
        with(|p| p.mark = Some((vec![0.0; 3], vec![0.0; 4]))),
        Rule::Length { name: "mark y", .. }
    ));
    assert!(matches!(
        with(|p| p.t[0] = f64::INFINITY),
        Rule::TimeNotFinite { point: 1, .. }
    ));
    assert!(matches!(
        with(|p| p.t[2] = 0.01),
        Rule::TimeNotRising { point: 3, .. }
    ));
    assert!(matches!(
        with(|p| p.x[0] = f64::INFINITY),
        Rule::Infinite { name: "x", .. }
    ));
    assert!(matches!(
        with(|p| p.mark_sigma = Some(vec![-1e-4; 3])),
        Rule::NegativeSigma {
            name: "mark σ", ..
        }
    ));
}

#[test]
fn what_changes_a_series_keeps_its_rules() {
    let m = Measured::new(good_parts()).unwrap();
    // Thinning keeps every other point of every column.
    let thin = m.retain_points(|i| i % 2 == 0);
    assert_eq!(thin.t(), &[-0.02, 0.0]);
    assert_eq!(thin.x(), Some(&[-0.016, 0.0][..]));
    assert!(Measured::new(thin.to_parts()).is_ok());
    // A spin rate made a rim speed: a huge radius overflows to a gap, not to ∞.
    let far = m.v_t_scaled(1e308);
    assert!(far.v_t().iter().all(|v| !v.is_infinite()));
    assert!(m.without_mark().v_t().iter().all(|v| v.is_nan()));
    // A time shift that would merge two times is refused.
    assert!(
        m.shifted(0.5)
            .is_ok_and(|s| (s.t()[0] - 0.48).abs() < 1e-12)
    );
    assert!(matches!(m.shifted(1e300), Err(Rule::TimeNotRising { .. })));
}

/// A value a file or a derivation could hand over: ordinary, a gap, ±∞, huge.
fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -10.0..10.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => prop::num::f64::NORMAL,
    ]
}

/// Mostly rising times (steps of any sign now and then), of lengths near each other.
fn columns() -> impl Strategy<Value = (Vec<f64>, Vec<f64>, Vec<f64>, Option<Vec<f64>>)> {
    (0usize..12).prop_flat_map(|n| {
        let steps = prop::collection::vec(
            prop_oneof![8 => 0.001..0.1f64, 1 => -0.1..0.0f64, 1 => Just(0.0)],
            n,
        );
        let len = move || prop_oneof![8 => Just(n), 1 => 0usize..14];
        (
            steps,
            len().prop_flat_map(|k| prop::collection::vec(value(), k)),
            len().prop_flat_map(|k| prop::collection::vec(value(), k)),
            prop::option::of(len().prop_flat_map(|k| prop::collection::vec(value(), k))),
        )
            .prop_map(|(steps, a, b, c)| {
                let t = steps
                    .iter()
                    .scan(0.0, |acc, s| {
                        *acc += s;
                        Some(*acc)
                    })
                    .collect();
                (t, a, b, c)
            })
    })
}

/// Every guarantee a series' type gives its users.
fn keeps_the_rules(t: &[f64], columns: &[&[f64]]) -> bool {
    t.iter().all(|v| v.is_finite())
        && t.windows(2).all(|w| w.first() < w.last())
        && columns
            .iter()
            .all(|c| c.len() == t.len() && c.iter().all(|v| !v.is_infinite()))
}

proptest! {
    #![proptest_config(cases(256))]

    #[test]
    fn a_series_is_refused_or_keeps_every_rule((t, v_cm, v_t, sigma) in columns()) {
        let parts = MeasuredParts { t, v_cm, v_t, v_cm_sigma: sigma, ..MeasuredParts::default() };
        let broken = !keeps_the_rules(&parts.t, &[&parts.v_cm, &parts.v_t])
            || parts.v_cm_sigma.as_ref().is_some_and(|s| !keeps_the_rules(&parts.t, &[s]) || s.iter().any(|v| *v < 0.0));
        match Measured::new(parts.clone()) {
            Ok(m) => {
                prop_assert!(!broken, "accepted {parts:?}");
                let sigma = m.v_cm_sigma().unwrap_or(m.t());
                prop_assert!(keeps_the_rules(m.t(), &[m.v_cm(), m.v_t(), sigma]));
                prop_assert_eq!(m.len(), parts.t.len());
            }
            Err(e) => {
                prop_assert!(broken, "refused {parts:?}: {e}");
                prop_assert!(!e.to_string().contains('\n'));
            }
        }
    }

    #[test]
    fn a_track_is_refused_or_keeps_every_rule((t, x, y, mark) in columns()) {
        let mark = mark.map(|m| (m.clone(), m));
        let parts = TrackParts { t, x, y, mark, ..TrackParts::default() };
        let mut cols: Vec<&[f64]> = vec![&parts.x, &parts.y];
        if let Some((a, b)) = &parts.mark {
            cols.extend([a.as_slice(), b.as_slice()]);
        }
        let broken = !keeps_the_rules(&parts.t, &cols);
        match Track::new(parts.clone()) {
            Ok(track) => {
                prop_assert!(!broken, "accepted {parts:?}");
                let mut cols = vec![track.x(), track.y()];
                if let Some((a, b)) = track.mark() {
                    cols.extend([a, b]);
                }
                prop_assert!(keeps_the_rules(track.t(), &cols));
                // Every frame reads within the columns.
                for i in 0..track.len() {
                    prop_assert_eq!(track.at(i).t, track.t()[i]);
                }
            }
            Err(e) => prop_assert!(broken, "refused {parts:?}: {e}"),
        }
    }
}
