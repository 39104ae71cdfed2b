//! Figures exported as SVG (plotters): the work–precision diagram of the methods, the
//! fit figure, the regime map, and a run's chart as the app shows it (`run_chart`).
//! Every axis range goes through [`linear_axis`] or
//! [`log_axis`]: plotters loops forever on an infinite, NaN or too thin range.

use plotters::prelude::*;

/// Why a figure cannot be drawn.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct NothingToDraw(pub String);

/// Largest magnitude put on an axis; beyond it spans overflow.
const AXIS_LIMIT: f64 = 1e300;

/// The smallest and largest finite value, if any.
pub fn finite_bounds(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// A linear axis range plotters can draw: finite, within ±1e300, and wider than a
/// millionth of its magnitude (a thinner one is padded by a tenth of it, an empty
/// one at 0 becomes −1 … 1).
pub fn linear_axis(lo: f64, hi: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let (lo, hi) = (
        lo.min(hi).clamp(-AXIS_LIMIT, AXIS_LIMIT),
        hi.max(lo).clamp(-AXIS_LIMIT, AXIS_LIMIT),
    );
    let mag = lo.abs().max(hi.abs());
    if hi - lo >= (mag * 1e-6).max(1e-100) {
        return (lo, hi);
    }
    let pad = if mag < 1e-100 { 1.0 } else { 0.1 * mag };
    (lo - pad, hi + pad)
}

/// A log axis range plotters can draw: positive, finite, within 1e-300 … 1e300, and
/// at least a factor 1.01 wide (else widened tenfold each way).
pub fn log_axis(lo: f64, hi: f64) -> (f64, f64) {
    let ok = |v: f64| v.is_finite() && v > 0.0;
    let (lo, hi) = match (ok(lo), ok(hi)) {
        (true, true) => (lo.min(hi), hi.max(lo)),
        (true, false) => (lo, lo),
        (false, true) => (hi, hi),
        (false, false) => (1.0, 1.0),
    };
    let (lo, hi) = (
        lo.clamp(1.0 / AXIS_LIMIT, AXIS_LIMIT),
        hi.clamp(1.0 / AXIS_LIMIT, AXIS_LIMIT),
    );
    if hi >= lo * 1.01 {
        (lo, hi)
    } else {
        (lo / 10.0, hi * 10.0)
    }
}

use crate::methods::Method;
use crate::physics::scene::Scene;
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

/// Log error (max |Δv_cm|) against log time, one line per method; runs that are not
/// `ok` are drawn as hollow markers so failures stay visible. The exact engine, with
/// no error, is the vertical line at its time.
pub fn work_precision(rows: &[Row], scene: &Scene) -> Result<String, Box<dyn std::error::Error>> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE)?;
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.method != Method::Exact || r.err_v > 0.0)
            .map(|r| (r.time_median_s.max(1e-9), r.err_v.max(1e-16)))
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        if pts.is_empty() {
            return Err(Box::new(NothingToDraw(
                "no time-stepping run has a finite error to plot, allowed --methods with at least one of euler, symplectic-euler, rk4, rk45, moreau".into(),
            )));
        }
        // The exact engine's time is on the time axis too.
        let exact_t = rows
            .iter()
            .filter(|r| r.method == Method::Exact)
            .map(|r| r.time_median_s.max(1e-9));
        let (lo_t, hi_t) =
            finite_bounds(pts.iter().map(|p| p.0).chain(exact_t)).expect("pts is not empty");
        let (lo_t, hi_t) = log_axis(lo_t / 2.0, hi_t * 2.0);
        let (lo_e, hi_e) = finite_bounds(pts.iter().map(|p| p.1)).expect("pts is not empty");
        let (lo_e, hi_e) = log_axis(lo_e.max(1e-16) / 3.0, hi_e * 3.0);
        let title = format!(
            "Work-precision, b = {:.2} cm, R = {:.2} cm, mu = {}, e = {}",
            scene.width * 100.0,
            scene.radius * 100.0,
            scene.mu,
            scene.restitution
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d((lo_t..hi_t).log_scale(), (lo_e..hi_e).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("time per run (s, median)")
            .y_desc("max |v_cm - exact| (m/s)")
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()?;
        // The exact engine has no error to plot: a vertical line at its time.
        if let Some(exact) = rows
            .iter()
            .find(|r| r.method == Method::Exact && r.time_median_s.is_finite())
        {
            let t = exact.time_median_s.max(1e-9);
            chart
                .draw_series(LineSeries::new(
                    vec![(t, lo_e), (t, hi_e)],
                    BLACK.stroke_width(2),
                ))?
                .label("exact (error 0)")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                });
        }
        for m in Method::TIME_STEPPING {
            let mine: Vec<&Row> = rows.iter().filter(|r| r.method == m).collect();
            if mine.is_empty() {
                continue;
            }
            let c = colour(m);
            let line: Vec<(f64, f64)> = mine
                .iter()
                .map(|r| (r.time_median_s.max(1e-9), r.err_v.max(1e-16)))
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .collect();
            chart
                .draw_series(LineSeries::new(line, c.stroke_width(2)))?
                .label(m.name())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
            chart.draw_series(
                mine.iter()
                    .filter(|r| r.err_v.is_finite() && r.time_median_s.is_finite())
                    .map(|r| {
                        let p = (r.time_median_s.max(1e-9), r.err_v.max(1e-16));
                        let style = if r.status == crate::study::compare::RunStatus::Ok {
                            c.filled()
                        } else {
                            c.stroke_width(1)
                        };
                        Circle::new(p, 4, style)
                    }),
            )?;
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}

/// The fit figure: measured v_cm and v_t, the fitted model, the paper's line fits over
/// their window, and the residuals below.
pub fn fit_figure(
    scene: &Scene,
    m: &crate::input::data::Measured,
    fits: &crate::study::fit::Fits,
) -> Result<String, Box<dyn std::error::Error>> {
    let mut fitted = *scene;
    fitted.mu = fits.model_fit.mu;
    fitted.left.v0 = fits.model_fit.v0;
    fitted.right.v0 = fits.model_fit.v0;
    fitted.restitution = fits.model_fit.restitution;
    let Some((t0, t1)) = finite_bounds(m.t.iter().copied()) else {
        return Err(Box::new(NothingToDraw(
            "the measured series has no finite time to plot".into(),
        )));
    };
    let (t0, t1) = linear_axis(t0, t1);
    let sol = crate::physics::engine::solve(
        &fitted,
        &crate::physics::scene::Span {
            t_start: t0.min(-1e-3),
            t_end: Some(t1.max(1e-3)),
        },
    );
    let n = 600;
    let ts: Vec<f64> = (0..=n)
        .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
        .collect();
    let model: Vec<(f64, f64, f64)> = ts
        .iter()
        .map(|&t| {
            let s = sol.at(t);
            (t, s.left.v, s.left.u)
        })
        .collect();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 700)).into_drawing_area();
        root.fill(&WHITE)?;
        let (top, bottom) = root.split_vertically(480);
        let values = m
            .v_cm
            .iter()
            .chain(&m.v_t)
            .copied()
            .chain(model.iter().flat_map(|p| [p.1, p.2]));
        // Non-finite values (a model that overflowed) are left out of the range and
        // the drawing; the range is padded by 0.1 m/s as before.
        let (lo, hi) = finite_bounds(values).unwrap_or((0.0, 0.0));
        let (lo, hi) = linear_axis(lo - 0.1, hi + 0.1);
        let fit = |(t, v): (f64, f64)| (near(t, (t0, t1)), near(v, (lo, hi)));
        let mf = &fits.model_fit;
        let mut chart = ChartBuilder::on(&top)
            .caption(
                format!(
                    "b = {:.2} cm: model fit mu = {:.3} +- {:.3}, line fits mu_cm = {:.3}, mu_t = {:.3}",
                    scene.width * 100.0,
                    mf.mu,
                    2.0 * mf.mu_se,
                    fits.line_fit.mu_cm,
                    fits.line_fit.mu_t
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
            .y_desc("v (m/s)")
            .draw()?;
        let blue = RGBColor(31, 119, 180);
        let orange = RGBColor(255, 127, 14);
        // The model as lines, the data as markers: v_cm (index 1) blue, v_t (2) orange.
        for (j, colour, name) in [(1, blue, "v_cm"), (2, orange, "v_t")] {
            let pick = move |p: &(f64, f64, f64)| (p.0, if j == 1 { p.1 } else { p.2 });
            chart
                .draw_series(LineSeries::new(
                    model.iter().map(pick).filter(|p| finite(*p)).map(fit),
                    colour.stroke_width(2),
                ))?
                .label(format!("model {name}"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        chart
            .draw_series(
                m.t.iter()
                    .zip(&m.v_cm)
                    .map(|(t, v)| (*t, *v))
                    .filter(|p| finite(*p))
                    .map(|p| Cross::new(fit(p), 4, blue)),
            )?
            .label("measured v_cm")
            .legend(move |(x, y)| Cross::new((x + 10, y), 4, blue));
        chart
            .draw_series(
                m.t.iter()
                    .zip(&m.v_t)
                    .map(|(t, v)| (*t, *v))
                    .filter(|p| finite(*p))
                    .map(|p| Circle::new(fit(p), 3, orange)),
            )?
            .label("measured v_t")
            .legend(move |(x, y)| Circle::new((x + 10, y), 3, orange));
        // The line fits over their window.
        let l = &fits.line_fit;
        for (line, colour) in l.lines.iter().zip([blue, orange]) {
            chart.draw_series(LineSeries::new(
                [l.from, l.to]
                    .map(|t| (t, line.intercept + line.slope * t))
                    .into_iter()
                    .filter(|p| finite(*p))
                    .map(fit),
                colour.mix(0.6).stroke_width(1),
            ))?;
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
        // Residuals.
        let res: Vec<(f64, f64, f64)> =
            m.t.iter()
                .enumerate()
                .map(|(i, &t)| {
                    let s = sol.at(t);
                    (t, m.v_cm[i] - s.left.v, m.v_t[i] - s.left.u)
                })
                .collect();
        let rmax = res
            .iter()
            .flat_map(|r| [r.1.abs(), r.2.abs()])
            .filter(|r| r.is_finite())
            .fold(0.01, f64::max)
            .min(1.0);
        let mut rc = ChartBuilder::on(&bottom)
            .margin(12)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(t0..t1, -rmax..rmax)?;
        rc.configure_mesh()
            .x_desc("t (s)")
            .y_desc("data - model (m/s)")
            .draw()?;
        let fit = |(t, r): (f64, f64)| (near(t, (t0, t1)), near(r, (-rmax, rmax)));
        rc.draw_series(
            res.iter()
                .map(|r| (r.0, r.1))
                .filter(|p| finite(*p))
                .map(|p| Cross::new(fit(p), 4, blue)),
        )?;
        rc.draw_series(
            res.iter()
                .map(|r| (r.0, r.2))
                .filter(|p| finite(*p))
                .map(|p| Circle::new(fit(p), 3, orange)),
        )?;
        rc.draw_series(LineSeries::new([(t0, 0.0), (t1, 0.0)], BLACK))?;
        root.present()?;
    }
    Ok(svg)
}

/// Both coordinates finite.
fn finite(p: (f64, f64)) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

/// `v` moved to within one span of the axis `lo … hi`: plotters maps a point into
/// i32 pixels and overflows on one far outside the axis; off the chart is off it.
fn near(v: f64, (lo, hi): (f64, f64)) -> f64 {
    let span = hi - lo;
    v.clamp(lo - span, hi + span)
}

fn regime_colour(r: crate::physics::derived::Regime) -> RGBColor {
    match r {
        crate::physics::derived::Regime::Depart => RGBColor(31, 119, 180),
        crate::physics::derived::Regime::Rest => RGBColor(150, 150, 150),
        crate::physics::derived::Regime::Recollide => RGBColor(255, 127, 14),
    }
}

/// The regime map: one coloured cell per grid point, the analytic critical width
/// b*(e) drawn over it when one axis is the width (a curve against e, else a line).
pub fn regime_map(
    points: &[crate::study::sweep::Point],
    x: &crate::study::sweep::Axis,
    y: Option<&crate::study::sweep::Axis>,
    scene: &Scene,
    preset: &str,
) -> Result<String, Box<dyn std::error::Error>> {
    use crate::input::params::Key;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        // Half a cell beyond each end; a one-point or overflowing axis gets a safe range.
        let pad = |a: &crate::study::sweep::Axis| {
            let step = if a.n > 1 {
                (a.hi - a.lo) / (a.n - 1) as f64
            } else {
                0.0
            };
            let (lo, hi) = linear_axis(a.lo - step / 2.0, a.hi + step / 2.0);
            let step = if step.is_finite() && step > 0.0 {
                step
            } else {
                hi - lo
            };
            (lo, hi, step)
        };
        let (x0, x1, dx) = pad(x);
        let (y0, y1, dy, ylabel) = match y {
            Some(y) => {
                let (a, b, s) = pad(y);
                (a, b, s, y.key.name().to_string())
            }
            None => (-1.0, 1.0, 2.0, "v'/v0".to_string()),
        };
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!("Regime map ({preset}): blue depart, grey rest, orange recollide"),
                ("sans-serif", 18),
            )
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc(format!(
                "{} ({})",
                x.key.name(),
                x.key.dimension().si_unit()
            ))
            .y_desc(ylabel)
            .disable_mesh()
            .draw()?;
        match y {
            Some(_) => {
                chart.draw_series(points.iter().filter(|p| p.x.is_finite()).map(|p| {
                    let (cx, cy) = (p.x, p.y.unwrap_or(0.0));
                    Rectangle::new(
                        [
                            (cx - dx / 2.0, cy - dy / 2.0),
                            (cx + dx / 2.0, cy + dy / 2.0),
                        ],
                        regime_colour(p.regime).filled(),
                    )
                }))?;
            }
            None => {
                chart.draw_series(points.iter().filter(|p| p.x.is_finite()).map(|p| {
                    let ratio = p.v_ratio.filter(|r| r.is_finite()).unwrap_or(0.0);
                    Circle::new(
                        (p.x, ratio.clamp(-1.0, 1.0)),
                        3,
                        regime_colour(p.regime).filled(),
                    )
                }))?;
                chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], BLACK))?;
            }
        }
        // The analytic boundary b*(e) = 2R sqrt(1 − 2/(5e)).
        let b_star = |e: f64| crate::physics::closed_form::critical_width(scene.radius, e);
        let width_axis = |k: Key| k == Key::Width;
        if width_axis(x.key) {
            match y.filter(|y| y.key == Key::Restitution) {
                Some(ya) => {
                    let curve: Vec<(f64, f64)> = (0..=400)
                        .map(|i| ya.lo + (ya.hi - ya.lo) * i as f64 / 400.0)
                        .filter_map(|e| b_star(e).map(|b| (b, e)))
                        .collect();
                    chart
                        .draw_series(LineSeries::new(curve, BLACK.stroke_width(2)))?
                        .label("b*(e) = 2R sqrt(1 - 2/(5e))")
                        .legend(|(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                        });
                }
                None => {
                    if let Some(b) = b_star(scene.restitution) {
                        chart
                            .draw_series(LineSeries::new(
                                [(b, y0), (b, y1)],
                                BLACK.stroke_width(2),
                            ))?
                            .label("b*")
                            .legend(|(x, y)| {
                                PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                            });
                    }
                }
            }
            chart
                .configure_series_labels()
                .border_style(BLACK)
                .background_style(WHITE.mix(0.9))
                .draw()?;
        }
        root.present()?;
    }
    Ok(svg)
}

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
    measured: Option<&crate::input::data::Measured>,
) -> Result<String, Box<dyn std::error::Error>> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::preset::Preset;
    use crate::study::compare::RunStatus;

    /// Runs `f` on a thread and fails if it takes longer than 30 s (a figure once
    /// looped forever on an infinite axis).
    fn within_30s<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send(f());
        });
        rx.recv_timeout(std::time::Duration::from_secs(30))
            .expect("the figure finished")
    }

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
            steps: 1,
            rhs_evals: 1,
            time_min_s: time,
            time_median_s: time,
            note: None,
        }
    }

    fn paper() -> (Scene, crate::input::data::Measured) {
        let p = Preset::load("paper-b4.9").unwrap();
        let (scene, _) = p.spec.resolve().unwrap();
        (scene, p.measured.unwrap())
    }

    #[test]
    fn axes_are_always_finite_and_wide_enough() {
        let cases = [
            (f64::INFINITY, 0.0),
            (f64::NAN, 1.0),
            (0.0, 0.0),
            (1e300, 1e300),
            (-f64::MAX, f64::MAX),
            (1.0, 1.0 + 1e-15),
            (5.0, 2.0),
        ];
        for (lo, hi) in cases {
            let (a, b) = linear_axis(lo, hi);
            assert!(
                a.is_finite() && b.is_finite() && (b - a).is_finite(),
                "{lo} {hi}"
            );
            assert!(b - a >= 1e-6 * a.abs().max(b.abs()), "{lo} {hi}: {a} {b}");
            let (a, b) = log_axis(lo, hi);
            assert!(
                a > 0.0 && b.is_finite() && b >= 1.01 * a,
                "{lo} {hi}: {a} {b}"
            );
        }
        assert_eq!(linear_axis(-0.2, 0.9), (-0.2, 0.9));
        assert_eq!(log_axis(1e-9, 1e-3), (1e-9, 1e-3));
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

    #[test]
    fn a_fit_figure_with_overflowing_values_finishes() {
        let (scene, measured) = paper();
        let fits = crate::study::fit::fit_all(
            &scene,
            &measured,
            (None, None),
            &[crate::study::fit::Free::Mu],
            &crate::study::Quiet,
        )
        .unwrap();
        // A fitted v0 of 1e308 (the model overflows) and inf in the data.
        let mut wild = fits.clone();
        wild.model_fit.v0 = 1e308;
        let mut m = measured.clone();
        m.v_cm[3] = f64::INFINITY;
        m.v_t[4] = f64::NAN;
        let svg =
            within_30s(move || fit_figure(&scene, &m, &wild).map_err(|e| e.to_string())).unwrap();
        assert!(svg.starts_with("<svg"));
        // Huge but finite data give a huge but finite axis.
        let mut big = measured.clone();
        big.v_cm[3] = 1e308;
        big.v_t[3] = -1e308;
        let svg =
            within_30s(move || fit_figure(&scene, &big, &fits).map_err(|e| e.to_string())).unwrap();
        assert!(svg.starts_with("<svg"));
    }
}
