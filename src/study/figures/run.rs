//! A run's chart as the app's chart panel shows it (velocities or positions against
//! time, with its events), for the app's SVG export.

use plotters::prelude::*;

use super::{FigureError, linear_axis};

/// Which chart of a run [`run_chart`] draws: the app's velocity chart of one or both
/// balls, or the positions of both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunChart {
    Velocities { left: bool, right: bool },
    Positions,
}

/// A run's chart, as the app's chart panel shows it: v_cm(t) and v_t(t) of the chosen
/// balls (with the measured left-ball points, if given) or x(t) of both balls, and a
/// dashed line at every labelled event.
pub fn run_chart(
    sol: &crate::physics::solution::Solution,
    which: RunChart,
    measured: Option<&crate::study::measured::series::Measured>,
) -> Result<String, FigureError> {
    use crate::physics::solution::Snapshot;
    let (t0, t1) = (sol.t_start, sol.t_end);
    // About one sample per SVG pixel column; the events add their own.
    let n = 800;
    let samples: Vec<Snapshot> = (0..=n)
        .map(|i| sol.at(t0 + (t1 - t0) * i as f64 / n as f64))
        .chain(sol.visible_events().map(|e| sol.at(e.t)))
        .collect();
    let mut samples = samples;
    samples.sort_by(|a, b| a.t.total_cmp(&b.t));
    type Pick = fn(&Snapshot) -> f64;
    let blue = RGBColor(31, 119, 180);
    let orange = RGBColor(255, 127, 14);
    let purple = RGBColor(148, 103, 189);
    let brown = RGBColor(140, 86, 75);
    let red = RGBColor(214, 39, 40);
    let (curves, y_desc, title): (Vec<(&str, Pick, RGBColor)>, &str, &str) = match which {
        RunChart::Positions => (
            vec![
                ("x left (cm)", |s| s.left.x * 100.0, blue),
                ("x right (cm)", |s| s.right.x * 100.0, purple),
            ],
            "x (cm)",
            "x(t) of both balls",
        ),
        RunChart::Velocities { left, right } => {
            let mut c: Vec<(&str, Pick, RGBColor)> = Vec::new();
            if left {
                c.push(("v_cm left", |s| s.left.v, blue));
                c.push(("v_t left", |s| s.left.u, orange));
            }
            if right {
                c.push(("v_cm right", |s| s.right.v, purple));
                c.push(("v_t right", |s| s.right.u, brown));
            }
            (c, "v (m/s)", "v_cm(t) and v_t(t)")
        }
    };
    let measured = measured.filter(|_| which != RunChart::Positions);
    let values = curves
        .iter()
        .flat_map(|(_, f, _)| samples.iter().map(f))
        .chain(
            measured
                .iter()
                .flat_map(|m| m.v_cm.iter().chain(&m.v_t).copied()),
        )
        .filter(|v| v.is_finite());
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |a, v| {
        (a.0.min(v), a.1.max(v))
    });
    // linear_axis first clamps the range (so the pad is finite), then again after the
    // 5 % pad: no data (an infinite fold), NaN or a flat run still give a drawable axis.
    let (lo, hi) = linear_axis(lo, hi);
    let pad = 0.05 * (hi - lo).max(1e-3);
    let (lo, hi) = linear_axis(lo - pad, hi + pad);
    let (t0, t1) = linear_axis(t0, t1);
    let scene = &sol.scene;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 560)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!(
                    "{title}: b = {:.2} cm, R = {:.2} cm, mu_k = {}, e = {}",
                    scene.width * 100.0,
                    scene.radius * 100.0,
                    scene.mu,
                    scene.restitution
                ),
                ("sans-serif", 18),
            )
            .margin(12)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(t0..t1, lo..hi)?;
        chart
            .configure_mesh()
            .x_desc("t (s)")
            .y_desc(y_desc)
            .draw()?;
        let grey = RGBColor(150, 150, 150);
        for e in sol.visible_events().filter(|e| e.kind.label().is_some()) {
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
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        if let Some(m) = measured {
            let inside = |t: &f64| (t0..=t1).contains(t);
            chart
                .draw_series(
                    m.t.iter()
                        .zip(&m.v_cm)
                        .filter(|(t, v)| inside(t) && v.is_finite())
                        .map(|(t, v)| Cross::new((*t, *v), 4, red)),
                )?
                .label("measured v_cm")
                .legend(move |(x, y)| Cross::new((x + 10, y), 4, red));
            chart
                .draw_series(
                    m.t.iter()
                        .zip(&m.v_t)
                        .filter(|(t, v)| inside(t) && v.is_finite())
                        .map(|(t, v)| Circle::new((*t, *v), 3, red)),
                )?
                .label("measured v_t")
                .legend(move |(x, y)| Circle::new((x + 10, y), 3, red));
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}
