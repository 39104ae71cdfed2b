//! The regime map: the regime of every grid point of a sweep, with the analytic
//! critical width drawn over it.

use plotters::prelude::*;

use super::drawing::{FigureError, linear_axis};
use crate::physics::scene::Scene;

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
) -> Result<String, FigureError> {
    use crate::settings::params::Key;
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
