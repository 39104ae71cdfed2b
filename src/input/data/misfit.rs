//! Whether a velocity file's numbers fit the units they were read in (stated by the
//! header or an option, or assumed SI): what does not fit, and the unit that does.

use super::notes::UnitNote;
use super::options::Reading;
use super::scales::{
    FASTEST_BALL, FASTEST_SPIN_CHANGE, LONGEST_FRAME, SHORTEST_FRAME, SHORTEST_SPAN, SLOWEST_BALL,
    SPEEDS, TIMES, TYPICAL_SPIN_CHANGE, fitting, frame_spacing, steepest_change, unit_name,
};
use crate::settings::units::significant;

/// The SI factors of a file's columns and who said each (`None`: nobody, the
/// numbers are taken as SI).
pub(super) struct Units {
    pub(super) time: (f64, Option<&'static str>),
    pub(super) v_cm: (f64, Option<&'static str>),
    pub(super) v_t: (f64, Option<&'static str>),
}

/// One unit that does not fit the numbers, what they look like in it and the unit
/// that fits.
#[derive(Clone, Debug, PartialEq)]
pub enum Misfit {
    /// Frames `frame` apart in the file's time unit, `rate` frames per s read as s,
    /// `unit_rate` read as `unit`.
    Times {
        frame: f64,
        rate: f64,
        unit_rate: f64,
        unit: &'static str,
        /// The unit the times were read in.
        read: &'static str,
    },
    /// Speeds up to `fastest` in the file's unit (`beyond`: too fast, else too slow
    /// as m/s), `as_unit` m/s read as `unit`.
    Speeds {
        fastest: f64,
        beyond: bool,
        as_unit: f64,
        unit: &'static str,
    },
    /// v_t changing by up to `steepest` (the file's unit per s), `si` m/s² as read:
    /// beyond any ball's spin; `as_unit` m/s² read as `unit`.
    SpinChange {
        steepest: f64,
        si: f64,
        as_unit: f64,
        unit: &'static str,
    },
}

impl Misfit {
    fn unit(&self) -> &'static str {
        match self {
            Misfit::Times { unit, .. }
            | Misfit::Speeds { unit, .. }
            | Misfit::SpinChange { unit, .. } => unit,
        }
    }

    /// The option that reads the numbers in the unit that fits.
    fn flag(&self) -> String {
        match self {
            Misfit::Times { unit, .. } => format!("--time-unit {unit}"),
            Misfit::Speeds { unit, .. } | Misfit::SpinChange { unit, .. } => {
                format!("--speed-unit {unit}")
            }
        }
    }

    /// The header cells that would state the unit that fits.
    fn header(&self) -> Vec<String> {
        match self {
            Misfit::Times { unit, .. } => vec![format!("t ({unit})")],
            Misfit::Speeds { unit, .. } | Misfit::SpinChange { unit, .. } => {
                vec![format!("v_cm ({unit})"), format!("v_t ({unit})")]
            }
        }
    }

    /// What the numbers look like.
    fn looks(&self) -> String {
        match *self {
            Misfit::Times {
                frame,
                rate,
                unit_rate,
                unit,
                read,
            } => format!(
                "frames {} apart (as {read}: {} frames/s; as {unit}: {} frames/s)",
                significant(frame, 3),
                significant(rate, 2),
                significant(unit_rate, 3),
            ),
            Misfit::Speeds {
                fastest,
                beyond,
                as_unit,
                unit,
            } => format!(
                "speeds up to {} (as m/s {} any ball in a groove; as {unit} {} m/s)",
                significant(fastest, 3),
                if beyond { "beyond" } else { "slower than" },
                significant(as_unit, 3)
            ),
            Misfit::SpinChange {
                steepest,
                si,
                as_unit,
                unit,
            } => format!(
                "v_t changing by up to {} per s (as m/s {} m/s², {}× g, beyond the {:.0}× g at most of any ball in a groove; as {unit} {} m/s²)",
                significant(steepest, 3),
                significant(si, 3),
                significant(si / G, 3),
                FASTEST_SPIN_CHANGE / G,
                significant(as_unit, 3)
            ),
        }
    }
}

/// A velocity file's numbers that are plainly not in the units they were read in:
/// what does not fit, and who stated the units (none: they were assumed SI).
#[derive(Clone, Debug, PartialEq)]
pub struct Implausible {
    pub misfits: Vec<Misfit>,
    pub stated: Vec<&'static str>,
}

impl std::error::Error for Implausible {}

impl std::fmt::Display for Implausible {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let misfits = &self.misfits;
        let units: Vec<&str> = misfits.iter().map(|m| m.unit()).collect();
        let flags: Vec<String> = misfits.iter().map(|m| m.flag()).collect();
        let header: Vec<String> = misfits.iter().flat_map(|m| m.header()).collect();
        let looks: Vec<String> = misfits.iter().map(|m| m.looks()).collect();
        let (units, flags, header) = (units.join(" and "), flags.join(" "), header.join(", "));
        if self.stated.is_empty() {
            return write!(
                f,
                "the header gives no units and the numbers do not look like s and m/s: {}; if they are {units}, give {flags} (or units in the header: {header})",
                looks.join(", ")
            );
        }
        let fix = if self.stated.contains(&"the header") {
            format!("fix the header ({header}) or give {flags}")
        } else {
            format!("give {flags}")
        };
        write!(
            f,
            "the numbers do not fit the units {}: {}; if they are {units}, {fix}",
            stated_text(&self.stated),
            looks.join(", ")
        )
    }
}

impl Units {
    /// The units of t, v_cm and v_t from the header's (`ft`, `fc`, `fv`) and the
    /// options: an option wins over the header, so that a header that states a wrong
    /// unit is set right by the option its error names.
    pub(super) fn decide(
        reading: &Reading,
        ft: Option<f64>,
        fc: Option<f64>,
        fv: Option<f64>,
    ) -> Units {
        let by =
            |option: Option<f64>, flag: &'static str, header: Option<f64>| match (option, header) {
                (Some(f), _) => (f, Some(flag)),
                (None, Some(f)) => (f, Some("the header")),
                (None, None) => (1.0, None),
            };
        Units {
            time: by(reading.time_unit, "--time-unit", ft),
            v_cm: by(reading.speed_unit, "--speed-unit", fc),
            v_t: by(reading.speed_unit, "--speed-unit", fv),
        }
    }

    /// What the file said about its units, for `groovelab data`.
    pub(super) fn notes(&self) -> Vec<UnitNote> {
        vec![
            UnitNote::of("time", &TIMES, self.time.0, self.time.1),
            UnitNote::of("v_cm", &SPEEDS, self.v_cm.0, self.v_cm.1),
            UnitNote::of("v_t", &SPEEDS, self.v_t.0, self.v_t.1),
        ]
    }

    /// Numbers that are plainly not in the units they were read in, whether a unit was
    /// stated or assumed: frames a second or more apart (ms, not s), speeds of 10 m/s
    /// or more (cm/s, not m/s) or all below 1 mm/s (m/s read as mm/s), or a spin that
    /// changes faster than friction can change it (a slow ball's cm/s read as m/s,
    /// [`FASTEST_SPIN_CHANGE`]). The error says
    /// what the numbers look like and names the unit that fits and its option.
    pub(super) fn check_plausible(
        &self,
        t: &[f64],
        v_cm: &[f64],
        v_t: &[f64],
    ) -> Result<(), Implausible> {
        let frame = frame_spacing(t);
        let fastest = v_cm.iter().chain(v_t).fold(0.0_f64, |a, v| a.max(v.abs()));
        let mut misfits = Vec::new();
        let read = unit_name(&TIMES, self.time.0).unwrap_or("s");
        let times = |unit: &'static str| Misfit::Times {
            frame: frame / self.time.0,
            rate: 1.0 / frame,
            unit_rate: 1.0 / (frame / self.time.0 * unit_factor_of(&TIMES, unit)),
            unit,
            read,
        };
        if frame >= LONGEST_FRAME {
            let unit =
                fitting(&TIMES, self.time.0, frame, 0.01, |f| f < LONGEST_FRAME).unwrap_or("ms");
            misfits.push(times(unit));
        } else if frame < SHORTEST_FRAME && span(t) < SHORTEST_SPAN {
            // Seconds under a header that says ms: 0.6 s of frames read as 0.6 ms, at
            // 100 000 frames/s, passed as such (a new user's trial).
            let fits = |f: f64| (SHORTEST_FRAME..LONGEST_FRAME).contains(&f);
            if let Some(unit) = fitting(&TIMES, self.time.0, frame, 0.01, fits) {
                misfits.push(times(unit));
            }
        }
        let plausible = |v: f64| (SLOWEST_BALL..FASTEST_BALL).contains(&v);
        if fastest > 0.0 && !plausible(fastest) {
            let unit = fitting(&SPEEDS, self.v_cm.0, fastest, 0.5, plausible).unwrap_or("cm/s");
            misfits.push(Misfit::Speeds {
                fastest: fastest / self.v_cm.0,
                beyond: fastest >= FASTEST_BALL,
                as_unit: fastest / self.v_cm.0 * unit_factor_of(&SPEEDS, unit),
                unit,
            });
        } else if let Some(misfit) = self.spin_change(t, v_t, fastest) {
            misfits.push(misfit);
        }
        if misfits.is_empty() {
            return Ok(());
        }
        let stated = [self.time.1, self.v_cm.1, self.v_t.1]
            .into_iter()
            .flatten()
            .collect();
        Err(Implausible { misfits, stated })
    }
}

impl Units {
    /// v_t changing faster than any ball's spin can (a stated or assumed speed unit too
    /// large: cm/s read as m/s, which the speeds alone do not show for a ball slower
    /// than 10 cm/s), and the speed unit under which it would not, the speeds
    /// (`fastest`, m/s as read) still of a ball in a groove.
    fn spin_change(&self, t: &[f64], v_t: &[f64], fastest: f64) -> Option<Misfit> {
        let si = steepest_change(t, v_t).filter(|&a| a > FASTEST_SPIN_CHANGE)?;
        let fits = |a: f64| a < FASTEST_SPIN_CHANGE && fastest * a / si >= SLOWEST_BALL;
        let unit = fitting(&SPEEDS, self.v_t.0, si, TYPICAL_SPIN_CHANGE, fits)?;
        Some(Misfit::SpinChange {
            steepest: si / self.v_t.0,
            si,
            as_unit: si / self.v_t.0 * unit_factor_of(&SPEEDS, unit),
            unit,
        })
    }
}

/// How long the times `t` (sorted) span, s.
fn span(t: &[f64]) -> f64 {
    match (t.first(), t.last()) {
        (Some(a), Some(b)) => b - a,
        _ => 0.0,
    }
}

/// Standard gravity (m/s²), the scale a change of speed is told in.
const G: f64 = 9.806_65;

/// The SI factor of `name` among `units`.
fn unit_factor_of(units: &[(&'static str, f64)], name: &str) -> f64 {
    units
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(1.0, |(_, f)| *f)
}

/// Who stated the units, once each: "the header gives", "the header and --time-unit give".
fn stated_text(stated: &[&str]) -> String {
    let mut who: Vec<&str> = Vec::new();
    for s in stated {
        if !who.contains(s) {
            who.push(s);
        }
    }
    format!(
        "{} give{}",
        who.join(" and "),
        if who.len() == 1 { "s" } else { "" }
    )
}
