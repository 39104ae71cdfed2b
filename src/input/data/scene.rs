//! The scene a data file says it was taken in: `# scene NAME = VALUE` comment lines,
//! as the app's CSV export writes them (`study::export::scene_comments`).

use super::problem::{DataError, DataProblem};
use crate::settings::params::Key;
use crate::settings::spec::SceneSpec;
use crate::settings::units::parse_quantity;
use crate::study::export::SCENE_COMMENT;

/// The scene values the comment lines of `text` (the file named `file`) give; empty
/// when it has none. A scene line with an unknown name or a bad value is an error
/// naming its line (a typo must not silently leave the scene to a default).
pub fn scene_of(text: &str, file: &str) -> Result<SceneSpec, DataError> {
    let mut spec = SceneSpec::default();
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    for (n, line) in text.lines().enumerate() {
        // `# scene NAME = VALUE` (any blanks after the `#`); `# scenery` is a comment.
        let Some(rest) = line
            .trim()
            .strip_prefix('#')
            .map(str::trim_start)
            .and_then(|l| l.strip_prefix(SCENE_COMMENT[1..].trim()))
            .filter(|r| r.starts_with(char::is_whitespace))
        else {
            continue;
        };
        let err = |what: DataProblem| DataError::new(file, what);
        let (name, value) = rest.split_once('=').ok_or_else(|| {
            err(DataProblem::NotSceneValue {
                line: n + 1,
                text: line.trim().to_string(),
            })
        })?;
        let key = Key::from_name(name.trim())
            .filter(|k| k.param().of_scene())
            .ok_or_else(|| {
                err(DataProblem::NotParameter {
                    line: n + 1,
                    name: name.trim().to_string(),
                })
            })?;
        let v = parse_quantity(value, key.dimension()).map_err(|error| {
            err(DataProblem::SceneValue {
                line: n + 1,
                key,
                value: value.trim().to_string(),
                error: Box::new(error),
            })
        })?;
        spec.set(key, v);
    }
    Ok(spec)
}

/// The relative standard error of the scale a `# scale = S ± σ px/m` comment line of
/// `text` states (`groovelab track` writes it); `None` without one, or with one that
/// does not read as two positive numbers (a comment, then, like any other).
pub fn scale_rel_se(text: &str) -> Option<f64> {
    use crate::vision::write::SCALE_COMMENT;
    let rest = text
        .lines()
        .take_while(|l| l.trim_start().starts_with('#') || l.trim().is_empty())
        .find_map(|l| l.trim().strip_prefix(SCALE_COMMENT))?;
    let (s, e) = rest.trim().trim_end_matches("px/m").split_once('±')?;
    let (s, e): (f64, f64) = (s.trim().parse().ok()?, e.trim().parse().ok()?);
    (s > 0.0 && s.is_finite() && e >= 0.0 && e.is_finite()).then(|| e / s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::scene::Span;

    #[test]
    fn the_scale_comment_gives_its_relative_error() {
        let text = "# groovelab track clip.mp4\n# scale = 1000.000000 ± 2.500000 px/m\n#multi:\n";
        assert!((scale_rel_se(text).unwrap() - 0.0025).abs() < 1e-15);
        assert_eq!(scale_rel_se("# scale = big ± small px/m\nt,x\n"), None);
        assert_eq!(scale_rel_se("t,x\n# scale = 1 ± 1 px/m\n"), None);
    }

    #[test]
    fn the_exported_scene_reads_back_within_its_rounding() {
        let p = crate::input::preset::load("paper-b4.9").unwrap();
        let (scene, _) = p.spec.resolve().unwrap();
        let scene = crate::physics::scene::Scene {
            mu: 0.16667742330550958,
            rolling_resistance: 0.0123456789,
            ..scene
        };
        let span = Span {
            t_start: -0.2,
            t_end: Some(0.75),
        };
        let spec = SceneSpec::of(&scene, &span);
        let text = crate::study::export::scene_comments(&spec) + "t,v_left,u_left\n";
        assert!(text.contains("# scene mu = 0.166677\n"), "{text}");
        let back = scene_of(&text, "run.csv").unwrap();
        let scene_only = || spec.given().filter(|(k, _)| k.param().of_scene());
        let keys: Vec<Key> = scene_only().map(|(k, _)| k).collect();
        assert_eq!(back.given().map(|(k, _)| k).collect::<Vec<_>>(), keys);
        for ((k, a), (_, b)) in scene_only().zip(back.given()) {
            // 6 significant digits: within half a unit of the 6th.
            assert!((a - b).abs() <= 5e-6 * a.abs(), "{k:?}: {a} vs {b}");
        }
    }

    #[test]
    fn a_bad_scene_line_names_its_line() {
        let e = scene_of("# note\n# scene widht = 4 cm\n", "f.csv").unwrap_err();
        assert!(
            e.what.to_string().starts_with(
                "line 2: scene value 'widht' is not a parameter, allowed radius, width"
            ),
            "{e}"
        );
        let e = scene_of("# scene width = 4 kg\n", "f.csv").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("f.csv: line 1: scene width = 4 kg: "),
            "{e}"
        );
        assert!(matches!(
            e.what,
            DataProblem::SceneValue {
                line: 1,
                key: Key::Width,
                ..
            }
        ));
        assert_eq!(
            scene_of("t,x\n# scenery\n", "f").unwrap(),
            SceneSpec::default()
        );
    }
}
