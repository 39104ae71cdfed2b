//! Figures exported as SVG (plotters): the work–precision diagram of the methods.

use plotters::prelude::*;

use crate::methods::Method;
use crate::methods::compare::Row;
use crate::scene::Scene;

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
        let lo_t = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) / 2.0;
        let hi_t = pts.iter().map(|p| p.0).fold(0.0, f64::max) * 2.0;
        let lo_e = pts
            .iter()
            .map(|p| p.1)
            .fold(f64::INFINITY, f64::min)
            .max(1e-16)
            / 3.0;
        let hi_e = pts.iter().map(|p| p.1).fold(0.0, f64::max) * 3.0;
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
        if let Some(exact) = rows.iter().find(|r| r.method == Method::Exact) {
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
            chart.draw_series(mine.iter().filter(|r| r.err_v.is_finite()).map(|r| {
                let p = (r.time_median_s.max(1e-9), r.err_v.max(1e-16));
                let style = if r.status == crate::methods::compare::Status::Ok {
                    c.filled()
                } else {
                    c.stroke_width(1)
                };
                Circle::new(p, 4, style)
            }))?;
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
