//! The regime map: the regime of every grid point of a sweep, with the analytic
//! critical width drawn over it.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::drawing::{
    Area, FigureError, FigureFrame, SvgChart, draw_legend, line_mark, linear_axis, linear_chart,
    svg, tick,
};
use crate::physics::closed_form;
use crate::physics::derived::Regime;
use crate::physics::scene::Scene;
use crate::settings::params::Key;
use crate::study::sweep::{GridPoint, SweepAxis};

fn regime_colour(r: Regime) -> RGBColor {
    match r {
        Regime::Depart => RGBColor(31, 119, 180),
        Regime::Rest => RGBColor(150, 150, 150),
        Regime::Recollide => RGBColor(255, 127, 14),
    }
}

/// The regime map: one coloured cell per grid point, the analytic critical width
/// b*(e) drawn over it when one axis is the width (a curve against e, else a line),
/// and that axis labelled in b/R too (opposite its labels in m) when R is the scene's.
pub fn regime_map(
    points: &[GridPoint],
    x: &SweepAxis,
    y: Option<&SweepAxis>,
    scene: &Scene,
    preset: &str,
) -> Result<String, FigureError> {
    let (x0, x1, dx) = padded_range(x);
    let (y0, y1, dy, ylabel) = match y {
        Some(y) => {
            let (a, b, s) = padded_range(y);
            (a, b, s, y.key.name().to_string())
        }
        None => (-1.0, 1.0, 2.0, "v'/v0".to_string()),
    };
    let ratio = RatioAxis::of(x, y);
    let caption = format!("Regime map ({preset}): blue depart, grey rest, orange recollide");
    // b/R above the plot goes between the caption and the plot: the caption is then
    // the figure's title, drawn above the chart's frame.
    let on_top = ratio == Some(RatioAxis::Top);
    let frame = FigureFrame {
        caption: (!on_top).then(|| (caption.clone(), 18)),
        margin: 15,
        label_areas: (45, 60),
        room: match ratio {
            Some(RatioAxis::Top) => (30, 0),
            Some(RatioAxis::Right) => (0, 45),
            None => (0, 0),
        },
    };
    let x_desc = format!("{} ({})", x.key.name(), x.key.dimension().si_unit());
    let bounds = ((x0, x1), (y0, y1));
    svg((900, 640), |root| {
        let area = if on_top {
            root.titled(&caption, ("sans-serif", 18))?
        } else {
            root.clone()
        };
        let mut chart = linear_chart(&area, &frame, bounds, (&x_desc, &ylabel), false)?;
        match y {
            Some(_) => draw_cells(&mut chart, points, (dx, dy))?,
            None => draw_speed_ratios(&mut chart, points, (x0, x1))?,
        }
        if x.key == Key::Width {
            draw_critical_width(&mut chart, scene, y, (y0, y1))?;
        }
        if let Some(side) = ratio {
            side.draw(root, &chart, bounds, scene.radius)?;
        }
        Ok(())
    })
}

/// Where the width axis is labelled in b/R as well: above a width across, right of a
/// width up; on no side when the other axis sweeps R (b/R then varies along both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RatioAxis {
    Top,
    Right,
}

impl RatioAxis {
    fn of(x: &SweepAxis, y: Option<&SweepAxis>) -> Option<RatioAxis> {
        let keys = (x.key, y.map(|y| y.key));
        match keys {
            (Key::Width, Some(Key::Radius)) | (Key::Radius, Some(Key::Width)) => None,
            (Key::Width, _) => Some(RatioAxis::Top),
            (_, Some(Key::Width)) => Some(RatioAxis::Right),
            _ => None,
        }
    }

    /// Labels the width axis of `chart` (over `bounds`, m) in b/R for the radius `r`,
    /// on the plot's edge opposite its labels in m: an axis line, ticks at round
    /// values of b/R and their labels, and the axis's name, drawn into the frame's
    /// room on that side.
    fn draw(
        self,
        root: &Area,
        chart: &SvgChart,
        ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
        r: f64,
    ) -> Result<(), FigureError> {
        let (lo, hi) = match self {
            RatioAxis::Top => (x0 / r, x1 / r),
            RatioAxis::Right => (y0 / r, y1 / r),
        };
        // The b/R value's point on the edge, in pixels.
        let at = |v: f64| match self {
            RatioAxis::Top => chart.backend_coord(&(v * r, y1)),
            RatioAxis::Right => chart.backend_coord(&(x1, v * r)),
        };
        let ((ax, ay), (bx, by)) = (at(lo), at(hi));
        root.draw(&PathElement::new(vec![(ax, ay), (bx, by)], BLACK))?;
        let label = ("sans-serif", 12).into_font().color(&BLACK);
        let (tick_to, label_at, anchor) = match self {
            RatioAxis::Top => ((0, -5), (0, -7), Pos::new(HPos::Center, VPos::Bottom)),
            RatioAxis::Right => ((5, 0), (7, 0), Pos::new(HPos::Left, VPos::Center)),
        };
        for v in round_values(lo, hi) {
            let (px, py) = at(v);
            root.draw(&PathElement::new(
                vec![(px, py), (px + tick_to.0, py + tick_to.1)],
                BLACK,
            ))?;
            let text = label.pos(anchor);
            root.draw(&Text::new(
                tick(&v),
                (px + label_at.0, py + label_at.1),
                text,
            ))?;
        }
        // The name: centred above the top labels, or atop the right ones.
        let (name_at, anchor) = match self {
            RatioAxis::Top => (
                ((ax + bx) / 2, ay - 22),
                Pos::new(HPos::Center, VPos::Bottom),
            ),
            RatioAxis::Right => ((bx + 7, by - 12), Pos::new(HPos::Left, VPos::Bottom)),
        };
        root.draw(&Text::new("b/R", name_at, label.pos(anchor)))?;
        Ok(())
    }
}

/// Round values from `lo` to `hi` for ticks: multiples of 1, 2 or 5 times a power of
/// ten, about ten of them; none for a range that is not finite and positive.
fn round_values(lo: f64, hi: f64) -> Vec<f64> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return Vec::new();
    }
    let power = 10f64.powf((span / 10.0).log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|&s| span / s <= 10.0)
        .unwrap_or(10.0 * power);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// An axis's range with half a cell beyond each end, and the cell's width; a
/// one-point or overflowing axis gets a safe range.
fn padded_range(a: &SweepAxis) -> (f64, f64, f64) {
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
    chart: &mut SvgChart,
    points: &[GridPoint],
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
    chart: &mut SvgChart,
    points: &[GridPoint],
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
    chart: &mut SvgChart<'a, 'b>,
    scene: &Scene,
    y: Option<&SweepAxis>,
    (y0, y1): (f64, f64),
) -> Result<(), FigureError> {
    let b_star = |e: f64| closed_form::critical_width(scene.radius, e);
    let legend = line_mark(BLACK.stroke_width(2));
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
    draw_legend(chart, SeriesLabelPosition::MiddleRight)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::figures::drawing::tests::paper;
    use crate::study::sweep::parse_axis;

    /// The text elements of an SVG, trimmed.
    fn texts(svg: &str) -> Vec<&str> {
        svg.split("<text")
            .skip(1)
            .filter_map(|t| Some(t.split_once('>')?.1.split_once("</text>")?.0.trim()))
            .collect()
    }

    fn point(x: f64, y: Option<f64>) -> GridPoint {
        GridPoint {
            x,
            y,
            regime: Regime::Depart,
            v_ratio: Some(-0.4),
            t_roll: None,
            impacts: 1,
            t_accumulation: None,
        }
    }

    /// The map labels its width axis in b/R as well (the app's map is over b/R; the
    /// SVG had only metres): across above a width across, up right of a width up.
    #[test]
    fn a_width_axis_is_labelled_in_b_over_r_too() {
        let (scene, _) = paper();
        let width = parse_axis("width=0..5.5cm", 3).unwrap();
        let e = parse_axis("restitution=0.3..1", 2).unwrap();
        let grid: Vec<GridPoint> = [0.3, 1.0]
            .iter()
            .flat_map(|&y| (0..3).map(move |i| point(width.value(i), Some(y))))
            .collect();
        for (x, y) in [(&width, Some(&e)), (&e, Some(&width)), (&width, None)] {
            let svg = regime_map(&grid, x, y, &scene, "paper-b4.9").unwrap();
            let t = texts(&svg);
            assert!(t.contains(&"b/R"), "{t:?}");
            // R = 2.75 cm: 0 … 5.5 cm is b/R 0 … 2, and half a cell (b/R 0.5)
            // beyond each end: b/R labelled every 0.5, where no other axis has 1.5, 2.0.
            for label in ["1.5", "2.0", "2.5"] {
                assert!(t.contains(&label), "{label}: {t:?}");
            }
        }
        // Against R, b/R varies along both axes: no b/R labels; none without a width.
        let radius = parse_axis("radius=2..3cm", 2).unwrap();
        for (x, y) in [(&width, &radius), (&e, &radius)] {
            let svg = regime_map(&grid, x, Some(y), &scene, "paper-b4.9").unwrap();
            assert!(!texts(&svg).contains(&"b/R"));
        }
    }

    #[test]
    fn round_values_are_about_ten_multiples_of_1_2_or_5() {
        assert_eq!(round_values(0.0, 1.0).len(), 11);
        assert_eq!(round_values(-0.09, 2.09), [0.0, 0.5, 1.0, 1.5, 2.0]);
        let v = round_values(0.0, 1.9);
        assert_eq!(v.len(), 10);
        assert!((v[9] - 1.8).abs() < 1e-12);
        assert!(round_values(1.0, 1.0).is_empty());
        assert!(round_values(0.0, f64::INFINITY).is_empty());
        for (lo, hi) in [(0.0, 3.3e-7), (-5.0, 120.0), (0.13, 0.17)] {
            let n = round_values(lo, hi).len();
            assert!((4..=11).contains(&n), "{lo} {hi}: {n}");
        }
    }
}
