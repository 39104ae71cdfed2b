//! The regime map: the regime of every grid point of a sweep, with the analytic
//! critical width drawn over it.

use plotters::prelude::*;

use super::drawing::{Chart, FigureError, linear_axis, tick};
use crate::physics::closed_form;
use crate::physics::derived::Regime;
use crate::physics::scene::Scene;
use crate::settings::params::Key;
use crate::study::sweep::{Axis, Point};

fn regime_colour(r: Regime) -> RGBColor {
    match r {
        Regime::Depart => RGBColor(31, 119, 180),
        Regime::Rest => RGBColor(150, 150, 150),
        Regime::Recollide => RGBColor(255, 127, 14),
    }
}

/// The regime map: one coloured cell per grid point, the analytic critical width
/// b*(e) drawn over it when one axis is the width (a curve against e, else a line).
pub fn regime_map(
    points: &[Point],
    x: &Axis,
    y: Option<&Axis>,
    scene: &Scene,
    preset: &str,
) -> Result<String, FigureError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let (x0, x1, dx) = padded_range(x);
        let (y0, y1, dy, ylabel) = match y {
            Some(y) => {
                let (a, b, s) = padded_range(y);
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
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .disable_mesh()
            .draw()?;
        match y {
            Some(_) => draw_cells(&mut chart, points, (dx, dy))?,
            None => draw_speed_ratios(&mut chart, points, (x0, x1))?,
        }
        if x.key == Key::Width {
            draw_critical_width(&mut chart, scene, y, (y0, y1))?;
        }
        root.present()?;
    }
    Ok(svg)
}

/// An axis's range with half a cell beyond each end, and the cell's width; a
/// one-point or overflowing axis gets a safe range.
fn padded_range(a: &Axis) -> (f64, f64, f64) {
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
}

/// A two-axis sweep: one filled cell of the regime's colour per grid point.
fn draw_cells(
    chart: &mut Chart,
    points: &[Point],
    (dx, dy): (f64, f64),
) -> Result<(), FigureError> {
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
    Ok(())
}

/// A one-axis sweep: the rolling speed after the impact over v0 (clamped to ±1) of
/// each point in its regime's colour, and the line v' = 0.
fn draw_speed_ratios(
    chart: &mut Chart,
    points: &[Point],
    (x0, x1): (f64, f64),
) -> Result<(), FigureError> {
    chart.draw_series(points.iter().filter(|p| p.x.is_finite()).map(|p| {
        let ratio = p.v_ratio.filter(|r| r.is_finite()).unwrap_or(0.0);
        Circle::new(
            (p.x, ratio.clamp(-1.0, 1.0)),
            3,
            regime_colour(p.regime).filled(),
        )
    }))?;
    chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], BLACK))?;
    Ok(())
}

/// The analytic boundary b*(e) = 2R sqrt(1 − 2/(5e)) over a width axis: a curve
/// against e when the other axis is e, else a vertical line at the scene's e; with
/// its legend.
fn draw_critical_width<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
    scene: &Scene,
    y: Option<&Axis>,
    (y0, y1): (f64, f64),
) -> Result<(), FigureError> {
    let b_star = |e: f64| closed_form::critical_width(scene.radius, e);
    let legend =
        |(x, y): (i32, i32)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2));
    match y.filter(|y| y.key == Key::Restitution) {
        Some(ya) => {
            let curve: Vec<(f64, f64)> = (0..=400)
                .map(|i| ya.lo + (ya.hi - ya.lo) * i as f64 / 400.0)
                .filter_map(|e| b_star(e).map(|b| (b, e)))
                .collect();
            chart
                .draw_series(LineSeries::new(curve, BLACK.stroke_width(2)))?
                .label("b*(e) = 2R sqrt(1 - 2/(5e))")
                .legend(legend);
        }
        None => {
            if let Some(b) = b_star(scene.restitution) {
                chart
                    .draw_series(LineSeries::new([(b, y0), (b, y1)], BLACK.stroke_width(2)))?
                    .label("b*")
                    .legend(legend);
            }
        }
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .draw()?;
    Ok(())
}
