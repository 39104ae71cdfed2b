//! The fit figure: the measured series against the fitted model and the paper's line
//! fits, with the residuals below.

use plotters::prelude::*;

use super::drawing::{
    Area, FigureError, FigureFrame, draw_legend, draw_measured_marks, finite_bounds, line_mark,
    linear_axis, linear_chart, svg,
};
use crate::physics::scene::Scene;
use crate::physics::solution::Solution;
use crate::settings::units::Dimension;
use crate::study::fit::Fits;
use crate::study::measured::series::Measured;

const BLUE: RGBColor = RGBColor(31, 119, 180);
const ORANGE: RGBColor = RGBColor(255, 127, 14);

/// The scene with the fitted values.
fn fitted_scene(scene: &Scene, fits: &Fits) -> Scene {
    let mut fitted = *scene;
    fitted.mu = fits.model_fit.mu;
    fitted.left.v0 = fits.model_fit.v0;
    fitted.right.v0 = fits.model_fit.v0;
    fitted.restitution = fits.model_fit.restitution;
    fitted
}

/// The fit figure: measured v_cm and v_t, the fitted model, the paper's line fits over
/// their window, and the residuals below.
pub fn fit_figure(scene: &Scene, m: &Measured, fits: &Fits) -> Result<String, FigureError> {
    let Some((t0, t1)) = finite_bounds(m.t().iter().copied()) else {
        return Err(FigureError::NothingToDraw(
            "the measured series has no finite time to plot",
        ));
    };
    let (t0, t1) = linear_axis(t0, t1);
    let sol = crate::physics::engine::solve(
        &fitted_scene(scene, fits),
        &crate::physics::scene::Span {
            t_start: t0.min(-1e-3),
            t_end: Some(t1.max(1e-3)),
        },
    );
    svg((900, 700), |root| {
        let (top, bottom) = root.split_vertically(480);
        draw_fit(&top, scene, m, fits, &sol, (t0, t1))?;
        draw_residuals(&bottom, m, &sol, (t0, t1))
    })
}

/// A model's name in symbols: `mu+rolling_resistance` → `μ_k + c_rr`.
fn model_symbols(model: &str) -> String {
    model
        .split('+')
        .map(|p| match p {
            "mu" => "μ_k",
            "restitution" => "e",
            "rolling_resistance" => "c_rr",
            other => other,
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The upper chart: the model (600 points over the time axis) as lines, the data as
/// markers (v_cm blue, v_t orange), and the paper's line fits over their window.
fn draw_fit(
    area: &Area,
    scene: &Scene,
    m: &Measured,
    fits: &Fits,
    sol: &Solution,
    (t0, t1): (f64, f64),
) -> Result<(), FigureError> {
    let n = 600;
    let model: Vec<(f64, f64, f64)> = (0..=n)
        .map(|i| {
            let t = t0 + (t1 - t0) * i as f64 / n as f64;
            let s = sol.at(t);
            (t, s.left.v, s.left.u)
        })
        .collect();
    let values = m
        .v_cm()
        .iter()
        .chain(m.v_t())
        .copied()
        .chain(model.iter().flat_map(|p| [p.1, p.2]));
    // Non-finite values (a model that overflowed) are left out of the range and
    // the drawing; the range is padded by 0.1 m/s as before.
    let (lo, hi) = finite_bounds(values).unwrap_or((0.0, 0.0));
    let (lo, hi) = linear_axis(lo - 0.1, hi + 0.1);
    let fit = |(t, v): (f64, f64)| (near(t, (t0, t1)), near(v, (lo, hi)));
    let mf = &fits.model_fit;
    // The headline as `fit` prints it, in its signs: the same model, μ_k and ± 2σ (4
    // places).
    let mu = if mf.undetermined("mu").is_some() {
        "not determined".to_string()
    } else if mf.mu_se.is_finite() {
        let (v, e) = crate::settings::units::with_uncertainty(mf.mu, 2.0 * mf.mu_se, 4);
        format!("{v} ± {e} (2σ)")
    } else {
        super::drawing::rounded(mf.mu)
    };
    let caption = format!(
        "b = {:.2} {}: model {}, μ_k = {mu}; line fits μ_cm = {}, μ_t = {}",
        Dimension::Length.to_display(scene.width),
        Dimension::Length.display_unit().0,
        model_symbols(&mf.model),
        super::drawing::rounded(fits.line_fit.as_ref().map_or(f64::NAN, |l| l.mu_cm)),
        super::drawing::rounded(fits.line_fit.as_ref().map_or(f64::NAN, |l| l.mu_t))
    );
    let mut chart = linear_chart(
        area,
        &FigureFrame::plain(Some(caption)),
        ((t0, t1), (lo, hi)),
        ("t (s)", "v (m/s)"),
        true,
    )?;
    for (j, colour, name) in [(1, BLUE, "v_cm"), (2, ORANGE, "v_t")] {
        let pick = move |p: &(f64, f64, f64)| (p.0, if j == 1 { p.1 } else { p.2 });
        chart
            .draw_series(LineSeries::new(
                model.iter().map(pick).filter(|p| finite(*p)).map(fit),
                colour.stroke_width(2),
            ))?
            .label(format!("model {name}"))
            .legend(line_mark(colour.stroke_width(2)));
    }
    let points = |v: &[f64]| {
        m.t()
            .iter()
            .zip(v)
            .map(|(t, v)| (*t, *v))
            .filter(|p| finite(*p))
            .map(fit)
            .collect::<Vec<_>>()
    };
    draw_measured_marks(
        &mut chart,
        points(m.v_cm()).into_iter(),
        points(m.v_t()).into_iter(),
        (BLUE, ORANGE),
    )?;
    for (l, (line, colour)) in fits
        .line_fit
        .iter()
        .flat_map(|l| l.lines.iter().zip([BLUE, ORANGE]).map(move |lc| (l, lc)))
    {
        chart.draw_series(LineSeries::new(
            [l.from, l.to]
                .map(|t| (t, line.intercept + line.slope * t))
                .into_iter()
                .filter(|p| finite(*p))
                .map(fit),
            colour.mix(0.6).stroke_width(1),
        ))?;
    }
    draw_legend(&mut chart, SeriesLabelPosition::LowerRight)
}

/// The lower chart: data − model at each measured time (v_cm crosses, v_t circles),
/// on a symmetric axis of at least ±0.01 m/s and at most ±1 m/s.
fn draw_residuals(
    area: &Area,
    m: &Measured,
    sol: &Solution,
    (t0, t1): (f64, f64),
) -> Result<(), FigureError> {
    let res: Vec<(f64, f64, f64)> = m
        .t()
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            let s = sol.at(t);
            (t, m.v_cm()[i] - s.left.v, m.v_t()[i] - s.left.u)
        })
        .collect();
    let rmax = res
        .iter()
        .flat_map(|r| [r.1.abs(), r.2.abs()])
        .filter(|r| r.is_finite())
        .fold(0.01, f64::max)
        .min(1.0);
    let mut rc = linear_chart(
        area,
        &FigureFrame::plain(None),
        ((t0, t1), (-rmax, rmax)),
        ("t (s)", "data - model (m/s)"),
        true,
    )?;
    let fit = |(t, r): (f64, f64)| (near(t, (t0, t1)), near(r, (-rmax, rmax)));
    rc.draw_series(
        res.iter()
            .map(|r| (r.0, r.1))
            .filter(|p| finite(*p))
            .map(|p| Cross::new(fit(p), 4, BLUE)),
    )?;
    rc.draw_series(
        res.iter()
            .map(|r| (r.0, r.2))
            .filter(|p| finite(*p))
            .map(|p| Circle::new(fit(p), 3, ORANGE)),
    )?;
    rc.draw_series(LineSeries::new([(t0, 0.0), (t1, 0.0)], BLACK))?;
    Ok(())
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

#[cfg(test)]
mod tests {
    use super::super::drawing::tests::{paper, within_30s};
    use super::*;

    #[test]
    fn a_fit_figure_with_overflowing_values_finishes() {
        let (scene, measured) = paper();
        let fits = crate::study::fit::fit_all(
            &scene,
            &measured,
            &crate::study::fit::Ask::default(),
            &crate::study::Quiet,
        )
        .unwrap();
        // A fitted v0 of 1e308 (the model overflows) and a gap in the data (a series
        // cannot hold ±∞: `Measured::new` refuses it).
        let mut wild = fits.clone();
        wild.model_fit.v0 = 1e308;
        let mut m = measured.to_parts();
        m.v_t[4] = f64::NAN;
        let m = Measured::new(m).unwrap();
        let svg =
            within_30s(move || fit_figure(&scene, &m, &wild).map_err(|e| e.to_string())).unwrap();
        assert!(svg.starts_with("<svg"));
        // Huge but finite data give a huge but finite axis.
        let mut big = measured.to_parts();
        big.v_cm[3] = 1e308;
        big.v_t[3] = -1e308;
        let big = Measured::new(big).unwrap();
        let svg =
            within_30s(move || fit_figure(&scene, &big, &fits).map_err(|e| e.to_string())).unwrap();
        assert!(svg.starts_with("<svg"));
    }
}
