//! The work–precision diagram: each time-stepping method's error against its run
//! time, from the rows of `compare`.

use plotters::prelude::*;

use super::drawing::{
    FigureError, FigureFrame, draw_legend, finite_bounds, line_mark, log_axis, svg,
};
use crate::methods::Method;
use crate::physics::scene::Scene;
use crate::settings::units::{Dimension, show};
use crate::study::compare::Row;

fn colour(m: Method) -> RGBColor {
    match m {
        Method::Exact => RGBColor(0, 0, 0),
        Method::Euler => RGBColor(214, 39, 40),
        Method::SymplecticEuler => RGBColor(255, 127, 14),
        Method::Rk4 => RGBColor(44, 160, 44),
        Method::Rk45 => RGBColor(31, 119, 180),
        Method::Moreau => RGBColor(148, 103, 189),
    }
}

/// What the diagram puts across: a run's time (`compare --format svg`), or its steps
/// or right-hand-side evaluations (the Methods view's other work axes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cost {
    Time,
    Steps,
    RhsEvals,
}

impl Cost {
    /// The row's work on this axis, at least the axis' floor (a run refused before its
    /// first step, or a time under a nanosecond, sits there rather than at −∞).
    fn of(self, r: &Row) -> f64 {
        match self {
            Cost::Time => r.time_median_s.max(1e-9),
            Cost::Steps => (r.steps as f64).max(1.0),
            Cost::RhsEvals => (r.rhs_evals as f64).max(1.0),
        }
    }

    fn title(self) -> &'static str {
        match self {
            Cost::Time => "time per run (s, median)",
            Cost::Steps => "steps per run",
            Cost::RhsEvals => "rhs evaluations per run",
        }
    }
}

/// Log error (max |Δv_cm|) against log time, one line per method; runs that are not
/// `ok` are drawn as hollow markers so failures stay visible. The exact engine, with
/// no error, is the vertical line at its time.
pub fn work_precision(rows: &[Row], scene: &Scene) -> Result<String, FigureError> {
    work_precision_against(rows, scene, Cost::Time)
}

/// [`work_precision`] with `work` across.
pub fn work_precision_against(
    rows: &[Row],
    scene: &Scene,
    work: Cost,
) -> Result<String, FigureError> {
    svg((900, 600), |root| draw_diagram(root, rows, scene, work))
}

/// The diagram into `root`.
fn draw_diagram(
    root: &super::drawing::Area,
    rows: &[Row],
    scene: &Scene,
    work: Cost,
) -> Result<(), FigureError> {
    let pts: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.method != Method::Exact || r.err_v > 0.0)
        .map(|r| (work.of(r), r.err_v.max(1e-16)))
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    if pts.is_empty() {
        return Err(FigureError::NothingToDraw(
            "no time-stepping run has a finite error to plot, allowed --methods with at least one of euler, symplectic-euler, rk4, rk45, moreau",
        ));
    }
    let ((lo_t, hi_t), (lo_e, hi_e)) = axis_ranges(rows, &pts, work);
    let frame = FigureFrame {
        caption: Some((caption(scene), 20)),
        margin: 15,
        label_areas: (45, 70),
        room: (0, 0),
    };
    let mut chart = frame
        .builder(root)
        .build_cartesian_2d((lo_t..hi_t).log_scale(), (lo_e..hi_e).log_scale())?;
    chart
        .configure_mesh()
        .x_desc(work.title())
        .y_desc("max |v_cm - exact| (m/s)")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    // The exact engine has no error to plot: a vertical line at its time.
    if let Some(exact) = rows
        .iter()
        .find(|r| r.method == Method::Exact && work.of(r).is_finite())
    {
        let t = work.of(exact);
        chart
            .draw_series(LineSeries::new(
                vec![(t, lo_e), (t, hi_e)],
                BLACK.stroke_width(2),
            ))?
            .label("exact (error 0)")
            .legend(line_mark(BLACK.stroke_width(2)));
    }
    for m in Method::TIME_STEPPING {
        let mine: Vec<&Row> = rows.iter().filter(|r| r.method == m).collect();
        if mine.is_empty() {
            continue;
        }
        let c = colour(m);
        let line: Vec<(f64, f64)> = mine
            .iter()
            .map(|r| (work.of(r), r.err_v.max(1e-16)))
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        chart
            .draw_series(LineSeries::new(line, c.stroke_width(2)))?
            .label(m.name())
            .legend(line_mark(c.stroke_width(2)));
        chart.draw_series(
            mine.iter()
                .filter(|r| r.err_v.is_finite() && work.of(r).is_finite())
                .map(|r| {
                    let p = (work.of(r), r.err_v.max(1e-16));
                    let style = if r.status == crate::study::compare::RunStatus::Ok {
                        c.filled()
                    } else {
                        c.stroke_width(1)
                    };
                    Circle::new(p, 4, style)
                }),
        )?;
    }
    draw_legend(&mut chart, SeriesLabelPosition::LowerRight)
}

/// The work and error axes' ranges: every plotted run with room around it (the exact
/// engine's work on the work axis too), as log axes plotters can draw. `pts` is not
/// empty.
fn axis_ranges(rows: &[Row], pts: &[(f64, f64)], work: Cost) -> ((f64, f64), (f64, f64)) {
    let exact_t = rows
        .iter()
        .filter(|r| r.method == Method::Exact)
        .map(|r| work.of(r));
    let (lo_t, hi_t) =
        finite_bounds(pts.iter().map(|p| p.0).chain(exact_t)).expect("pts is not empty");
    let (lo_e, hi_e) = finite_bounds(pts.iter().map(|p| p.1)).expect("pts is not empty");
    (
        log_axis(lo_t / 2.0, hi_t * 2.0),
        log_axis(lo_e.max(1e-16) / 3.0, hi_e * 3.0),
    )
}

/// The diagram's title: the scene it was run on.
fn caption(scene: &Scene) -> String {
    format!(
        "Work-precision, b = {:.2}, R = {:.2}, μ_k = {}, e = {}",
        show(scene.width, Dimension::Length),
        show(scene.radius, Dimension::Length),
        super::drawing::rounded(scene.mu),
        super::drawing::rounded(scene.restitution)
    )
}

#[cfg(test)]
mod tests {
    use super::super::drawing::tests::{paper, within_30s};
    use super::*;
    use crate::study::compare::RunStatus;

    fn row(method: Method, time: f64, err: f64) -> Row {
        Row {
            method,
            step: None,
            tolerance: None,
            status: RunStatus::Ok,
            err_v: err,
            err_u: err,
            err_t_roll: None,
            err_t_impact: None,
            err_final: err,
            energy_drift: 0.0,
            slip_rolling: 0.0,
            outcome: crate::physics::derived::Outcome::Depart,
            impacts: 1,
            outcome_right: true,
            steps: 1,
            rhs_evals: 1,
            time_min_s: time,
            time_median_s: time,
            cut: None,
            note: None,
        }
    }

    #[test]
    fn a_work_precision_diagram_of_exact_alone_is_an_error_not_a_hang() {
        let (scene, _) = paper();
        let e = within_30s(move || {
            work_precision(&[row(Method::Exact, 5e-6, 0.0)], &scene).map_err(|e| e.to_string())
        })
        .unwrap_err();
        assert!(e.contains("no time-stepping run"), "{e}");
    }

    #[test]
    fn non_finite_rows_are_left_out_of_the_diagram() {
        let (scene, _) = paper();
        let rows = vec![
            row(Method::Exact, f64::INFINITY, 0.0),
            row(Method::Euler, 1e-3, f64::INFINITY),
            row(Method::Euler, f64::NAN, 1e-3),
            row(Method::Rk4, 2e-3, 1e-7),
            row(Method::Rk4, 1e-300, f64::MAX),
        ];
        let svg =
            within_30s(move || work_precision(&rows, &scene).map_err(|e| e.to_string())).unwrap();
        assert!(
            svg.starts_with("<svg") && !svg.contains("NaN"),
            "{}",
            &svg[..200]
        );
    }
}
