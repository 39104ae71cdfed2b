//! A run's chart as the app's chart panel shows it (velocities or positions against
//! time, with its events), for the app's SVG export.

use plotters::prelude::*;

use super::drawing::{
    FigureError, FigureFrame, SvgChart, draw_legend, draw_measured_marks, line_mark, linear_axis,
    linear_chart, svg,
};
use crate::physics::solution::{Snapshot, Solution};
use crate::settings::units::Dimension;
use crate::study::measured::series::Measured;

/// Which chart of a run [`run_chart`] draws: the app's velocity chart of one or both
/// balls, or the positions of both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunChart {
    Velocities { left: bool, right: bool },
    Positions,
}

type Pick = fn(&Snapshot) -> f64;

/// A curve of the chart: legend name, what it plots of a state, colour.
type Trace = (String, Pick, RGBColor);

const BLUE: RGBColor = RGBColor(31, 119, 180);
const ORANGE: RGBColor = RGBColor(255, 127, 14);
const PURPLE: RGBColor = RGBColor(148, 103, 189);
const BROWN: RGBColor = RGBColor(140, 86, 75);
const RED: RGBColor = RGBColor(214, 39, 40);
const GREEN: RGBColor = RGBColor(44, 160, 44);

/// About one state per SVG pixel column, and one at each event, in time order.
fn run_samples(sol: &Solution, (t0, t1): (f64, f64)) -> Vec<Snapshot> {
    let n = 800;
    let mut samples: Vec<Snapshot> = (0..=n)
        .map(|i| sol.at(t0 + (t1 - t0) * i as f64 / n as f64))
        .chain(
            sol.visible_events()
                .filter(|e| (t0..=t1).contains(&e.t))
                .map(|e| sol.at(e.t)),
        )
        .collect();
    samples.sort_by(|a, b| a.t.total_cmp(&b.t));
    samples
}

/// The curves of `which`, the y axis's name and the chart's title. Positions are in
/// the display unit of lengths.
fn curves_of(which: RunChart) -> (Vec<Trace>, String, &'static str) {
    match which {
        RunChart::Positions => {
            let unit = Dimension::Length.display_unit().0;
            (
                vec![
                    (
                        format!("x left ({unit})"),
                        |s| Dimension::Length.to_display(s.left.x),
                        BLUE,
                    ),
                    (
                        format!("x right ({unit})"),
                        |s| Dimension::Length.to_display(s.right.x),
                        PURPLE,
                    ),
                ],
                format!("x ({unit})"),
                "x(t) of both balls",
            )
        }
        RunChart::Velocities { left, right } => {
            let mut c: Vec<Trace> = Vec::new();
            if left {
                c.push(("v_cm left".into(), |s| s.left.v, BLUE));
                c.push(("v_t left".into(), |s| s.left.u, ORANGE));
            }
            if right {
                c.push(("v_cm right".into(), |s| s.right.v, PURPLE));
                c.push(("v_t right".into(), |s| s.right.u, BROWN));
            }
            (
                c,
                format!("v ({})", Dimension::Speed.si_unit()),
                "v_cm(t) and v_t(t)",
            )
        }
    }
}

/// The y range that holds every curve and measured value, padded by 5 %.
/// linear_axis first clamps the range (so the pad is finite), then again after the
/// pad: no data (an infinite fold), NaN or a flat run still give a drawable axis.
fn value_range(
    curves: &[Trace],
    samples: &[Snapshot],
    measured: Option<&Measured>,
    (t0, t1): (f64, f64),
) -> (f64, f64) {
    let shown = |m: &'_ Measured| {
        let at = |v: &'_ [f64]| {
            m.t()
                .iter()
                .zip(v.to_vec())
                .filter(|(t, _)| (t0..=t1).contains(*t))
                .map(|(_, v)| v)
                .collect::<Vec<f64>>()
        };
        [at(m.v_cm()), at(m.v_t())].concat()
    };
    let values = curves
        .iter()
        .flat_map(|(_, f, _)| samples.iter().map(f))
        .chain(measured.into_iter().flat_map(shown))
        .filter(|v| v.is_finite());
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |a, v| {
        (a.0.min(v), a.1.max(v))
    });
    let (lo, hi) = linear_axis(lo, hi);
    let pad = 0.05 * (hi - lo).max(1e-3);
    linear_axis(lo - pad, hi + pad)
}

/// The measured left-ball points within the time axis: v_cm as crosses, v_t as circles.
fn draw_measured(
    chart: &mut SvgChart,
    m: &Measured,
    (t0, t1): (f64, f64),
) -> Result<(), FigureError> {
    let inside = |(t, v): &(f64, f64)| (t0..=t1).contains(t) && v.is_finite();
    let points = |v: &[f64]| {
        m.t()
            .iter()
            .zip(v)
            .map(|(t, v)| (*t, *v))
            .filter(inside)
            .collect::<Vec<_>>()
    };
    draw_measured_marks(
        chart,
        points(m.v_cm()).into_iter(),
        points(m.v_t()).into_iter(),
        // Two colours, as the model's v_cm and v_t have two.
        (RED, GREEN),
    )
}

/// The chart's caption: what it shows and the scene (b left out where it is hidden).
fn caption(title: &str, scene: &crate::physics::scene::Scene, b_hidden: bool) -> String {
    let unit = Dimension::Length.display_unit().0;
    let cm = |v: f64| Dimension::Length.to_display(v);
    let b = if b_hidden {
        "b hidden".to_string()
    } else {
        format!("b = {:.2} {unit}", cm(scene.width))
    };
    format!(
        "{title}: {b}, R = {:.2} {unit}, μ_k = {}, e = {}",
        cm(scene.radius),
        super::drawing::rounded(scene.mu),
        super::drawing::rounded(scene.restitution),
    )
}

/// What the app's chart shows beside the run: a pinned run (drawn dashed, labelled
/// with `label`) and a note under the chart (data measured in another groove); and
/// how much of it the screen shows.
#[derive(Clone, Copy, Debug, Default)]
pub struct Beside<'a> {
    pub pinned: Option<(&'a Solution, &'a str)>,
    pub note: Option<&'a str>,
    /// The time axis (the screen's time zoom, or a span that tells no outcome);
    /// `None`: the run's span, reaching a pinned run's end.
    pub range: Option<(f64, f64)>,
    /// Nothing after this time is drawn (the screen hides the outcome): curves,
    /// events and data end there.
    pub until: Option<f64>,
    /// The caption does not state b (the screen hides it).
    pub b_hidden: bool,
}

/// A run's chart, as the app's chart panel shows it: v_cm(t) and v_t(t) of the chosen
/// balls (with the measured left-ball points, if given) or x(t) of both balls, a
/// dashed line at every labelled event, and what is `beside` it on screen.
pub fn run_chart(
    sol: &Solution,
    which: RunChart,
    measured: Option<&Measured>,
    beside: Beside,
) -> Result<String, FigureError> {
    let t_end = beside
        .pinned
        .map_or(sol.t_end, |(p, _)| p.t_end.max(sol.t_end));
    let range = beside.range.unwrap_or((sol.t_start, t_end));
    // What is drawn: the range, up to `until`.
    let drawn = (range.0, range.1.min(beside.until.unwrap_or(f64::INFINITY)));
    let cut = |mut s: Vec<Snapshot>| {
        s.retain(|s| s.t <= drawn.1);
        s
    };
    let samples = cut(run_samples(sol, range));
    let (curves, y_desc, title) = curves_of(which);
    let measured = measured.filter(|_| which != RunChart::Positions);
    let pinned = beside
        .pinned
        .map(|(p, label)| (cut(run_samples(p, range)), label));
    let both: Vec<Snapshot> = samples
        .iter()
        .chain(pinned.iter().flat_map(|(p, _)| p))
        .copied()
        .collect();
    let (lo, hi) = value_range(&curves, &both, measured, drawn);
    let (t0, t1) = linear_axis(range.0, range.1);
    let caption = caption(title, &sol.scene, beside.b_hidden);
    let mut frame = FigureFrame::plain(Some(caption));
    if beside.note.is_some() {
        // Room under the axis for the note.
        frame.label_areas.0 += 22;
    }
    svg((900, 560), |root| {
        if let Some(note) = beside.note {
            root.draw(&Text::new(
                note.to_string(),
                (70, 538),
                ("sans-serif", 14).into_font().color(&RED),
            ))?;
        }
        let mut chart = linear_chart(root, &frame, ((t0, t1), (lo, hi)), ("t (s)", &y_desc), true)?;
        let grey = RGBColor(150, 150, 150);
        let shown = |t: &f64| (drawn.0..=drawn.1).contains(t);
        for e in sol
            .visible_events()
            .filter(|e| e.kind.label().is_some() && shown(&e.t))
        {
            chart.draw_series(DashedLineSeries::new(
                [(e.t, lo), (e.t, hi)],
                4,
                3,
                grey.into(),
            ))?;
        }
        for (name, f, colour) in curves {
            chart
                .draw_series(LineSeries::new(
                    samples.iter().map(|s| (s.t, f(s))),
                    colour.stroke_width(2),
                ))?
                .label(name)
                .legend(line_mark(colour.stroke_width(2)));
        }
        if let Some((pinned, label)) = &pinned {
            for (name, f, colour) in curves_of(which).0 {
                chart
                    .draw_series(DashedLineSeries::new(
                        pinned.iter().map(|s| (s.t, f(s))),
                        6,
                        4,
                        colour.mix(0.6).stroke_width(1),
                    ))?
                    .label(format!("{name}, pinned {label}"))
                    .legend(line_mark(colour.mix(0.6).stroke_width(1)));
            }
        }
        if let Some(m) = measured {
            draw_measured(&mut chart, m, (drawn.0.max(t0), drawn.1.min(t1)))?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperRight)
    })
}
