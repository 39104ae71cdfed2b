//! Every colour of each theme against its background, as WCAG 2 measures contrast:
//! text 4.5:1, lines and marks 3:1, with xterm's default RGB of each colour.

use proptest::prelude::*;

use super::*;

/// Each palette with its backgrounds: xterm's own (white, or black with `-rv`) and the
/// least contrasting background a terminal theme of that kind commonly has (grey 235
/// #262626 for dark, grey 255 #eeeeee for light). Contrast falls monotonically as the
/// background moves toward the text's luminance, so these bound every background
/// between them and the extreme.
const CASES: [(Backdrop, [[u8; 3]; 2]); 2] = [
    (Backdrop::Dark, [[0, 0, 0], [38, 38, 38]]),
    (Backdrop::Light, [[255, 255, 255], [238, 238, 238]]),
];

fn themes(background: Backdrop) -> [Theme; 2] {
    [false, true].map(|truecolor| {
        Theme::with(
            Glyphs::UNICODE,
            Colours::Palette {
                background,
                truecolor,
            },
        )
    })
}

fn needed(kind: Use) -> f64 {
    match kind {
        Use::Text => 4.5,
        Use::Line => 3.0,
    }
}

/// The roles whose colour falls short on `bg`, with their contrast.
fn short_of(theme: &Theme, bg: [u8; 3]) -> Vec<(&'static str, f64)> {
    theme
        .roles()
        .into_iter()
        .filter_map(|(name, style, kind)| {
            let fg = style.fg.and_then(xterm_rgb)?;
            let c = contrast(fg, bg);
            (c < needed(kind)).then_some((name, c))
        })
        .collect()
}

#[test]
fn every_colour_of_both_themes_reads_on_its_background() {
    for (background, bgs) in CASES {
        for theme in themes(background) {
            // Only the terminal's own text and the reversed selection go uncoloured.
            let coloured = theme.roles().iter().filter(|r| r.1.fg.is_some()).count();
            assert_eq!(coloured, theme.roles().len() - 2, "{background:?}");
            for bg in bgs {
                let short = short_of(&theme, bg);
                assert!(short.is_empty(), "{background:?} on {bg:?}: {short:?}");
            }
        }
    }
}

#[test]
fn indexed_and_truecolour_are_the_same_colours() {
    for (background, _) in CASES {
        let [indexed, rgb] = themes(background);
        for ((name, a, _), (_, b, _)) in indexed.roles().into_iter().zip(rgb.roles()) {
            assert!(matches!(a.fg, None | Some(Color::Indexed(16..))), "{name}");
            assert!(matches!(b.fg, None | Some(Color::Rgb(..))), "{name}");
            assert_eq!(a.fg.and_then(xterm_rgb), b.fg.and_then(xterm_rgb), "{name}");
        }
    }
}

#[test]
fn the_old_ansi_colours_fail_where_the_issue_measured_them() {
    // The measurement itself: ANSI white (Gray, #e5e5e5) on xterm's white is 1.25:1 and
    // ANSI blue on black 2.2:1 (issue 37), while black on white is 21:1.
    let white = [255, 255, 255];
    let on_white = contrast(xterm_rgb(Color::Gray).unwrap(), white);
    assert!((on_white - 1.25).abs() < 0.01, "{on_white}");
    let blue = contrast(xterm_rgb(Color::Blue).unwrap(), [0, 0, 0]);
    assert!((blue - 2.23).abs() < 0.01, "{blue}");
    assert!((contrast([0, 0, 0], white) - 21.0).abs() < 1e-9);
    assert_eq!(xterm_256(16), [0, 0, 0]);
    assert_eq!(xterm_256(231), [255, 255, 255]);
    assert_eq!(xterm_256(75), [95, 175, 255]);
    assert_eq!(xterm_256(244), [128, 128, 128]);
}

#[test]
fn the_series_of_one_chart_differ_in_colour() {
    for (background, _) in CASES {
        let t = themes(background)[0];
        let series = [
            t.left,
            t.accent,
            t.right,
            t.right_accent,
            t.measured,
            t.overlay,
            t.overlay_t,
            t.event,
        ];
        for (i, a) in series.iter().enumerate() {
            for b in &series[i + 1..] {
                assert_ne!(a.fg, b.fg, "{background:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any background no lighter than grey 235 in each channel (or no darker than grey
    /// 255) keeps every colour of its theme readable: tinted backgrounds too.
    #[test]
    fn any_background_of_its_kind_keeps_the_contrast(rgb in prop::array::uniform3(0u8..=255)) {
        let dark = rgb.map(|c| (u16::from(c) * 38 / 255) as u8);
        let light = rgb.map(|c| 238 + (u16::from(c) * 17 / 255) as u8);
        for (background, bg) in [(Backdrop::Dark, dark), (Backdrop::Light, light)] {
            for theme in themes(background) {
                let short = short_of(&theme, bg);
                prop_assert!(short.is_empty(), "{:?} on {:?}: {:?}", background, bg, short);
            }
        }
    }
}
