//! Tests of the video view's picture: the image protocol switch, the panel's fit,
//! the frame with its tracked balls and the model's rings drawn in, a ball cut at
//! the edge, the kitty encoding.

use super::*;
use crate::vision::thumbs::{BallPixels, Thumbs};

const GREY: u8 = 40;

/// A 64 × 36 video kept whole (its thumbnails are the frames), a flat grey, with
/// one ball tracked at (10, 8) in frame 0 and its mark at (30, 20); no radius, so
/// the band is the whole picture.
fn view() -> VideoView {
    let mut thumbs = Thumbs::sized(64, 36, 1);
    let img = crate::vision::gray::Gray::filled(64, 36, GREY);
    thumbs.push(0, &img);
    assert_eq!((thumbs.width, thumbs.height), (64, 36), "kept whole");
    VideoView {
        thumbs,
        t: vec![0.0],
        px_per_m: 1000.0,
        groove: 0.0,
        origin: (32.0, 18.0),
        radius_px: f64::NAN,
        balls: vec![BallPixels {
            name: "left".into(),
            centre: vec![Some((10.0, 8.0))],
            mark: vec![Some((30.0, 20.0))],
        }],
        levels: [40, 100, 250],
        first_only: None,
    }
}

fn marks(model: Option<[(f64, f64); 2]>) -> Marks {
    Marks {
        model,
        ring: 5.0,
        left: Rgb([0, 0, 255]),
        right: Rgb([255, 0, 0]),
        tracked: Rgb([0, 255, 0]),
    }
}

#[test]
fn the_switch_reads_off_auto_and_a_forced_protocol_and_refuses_the_rest() {
    assert_eq!(Switch::parse(None), Ok(Switch::Auto));
    assert_eq!(Switch::parse(Some("auto")), Ok(Switch::Auto));
    assert_eq!(Switch::parse(Some("off")), Ok(Switch::Off));
    assert_eq!(Switch::parse(Some("0")), Ok(Switch::Off));
    assert_eq!(
        Switch::parse(Some("kitty")),
        Ok(Switch::Force(ProtocolType::Kitty))
    );
    let e = Switch::parse(Some("vga")).unwrap_err().to_string();
    assert!(
        e.contains("GROOVELAB_GRAPHICS=\"vga\"") && e.contains("off"),
        "{e}"
    );
}

#[test]
fn the_protocol_is_the_terminals_unless_switched_off_or_forced() {
    use ProtocolType::*;
    for found in [Sixel, Kitty, Iterm2] {
        assert_eq!(Switch::Auto.choose(found), Some(found));
        assert_eq!(Switch::Off.choose(found), None, "off wins over {found:?}");
    }
    // A terminal without graphics: half-blocks, drawn by the app itself.
    assert_eq!(Switch::Auto.choose(Halfblocks), None);
    assert_eq!(Switch::Force(Sixel).choose(Halfblocks), Some(Sixel));
    assert_eq!(Switch::Force(Kitty).choose(Iterm2), Some(Kitty));
    // Off never asks the terminal; inside tmux only a forced protocol does.
    assert!(detect(Switch::Off).is_none());
    assert!(!Switch::Off.queries(false));
    assert!(Switch::Auto.queries(false));
    assert!(!Switch::Auto.queries(true));
    assert!(Switch::Force(Kitty).queries(true));
}

#[test]
fn the_picture_fills_the_panel_at_the_font_size_with_the_videos_aspect() {
    let v = view();
    // 40 × 10 cells of 10 × 20 px: 400 × 200 px; the 64 × 36 video fits the height.
    let (w, h) = fitted(&v, Rect::new(0, 0, 40, 10), (10, 20));
    assert_eq!(h, 200);
    assert!((f64::from(w) - 200.0 * 64.0 / 36.0).abs() <= 1.0, "{w}");
    // A huge panel is capped: the encoding stays small.
    let (w, h) = fitted(&v, Rect::new(0, 0, 500, 200), (10, 20));
    assert_eq!(w, MAX_SIDE);
    assert!(
        (f64::from(h) - f64::from(MAX_SIDE) * 36.0 / 64.0).abs() <= 1.0,
        "{h}"
    );
}

#[test]
fn the_frame_and_the_tracked_marks_are_in_the_pixels() {
    let v = view();
    // Twice the video's size: video pixel (x, y) is the picture's (2x, 2y).
    let img = picture(&v, 0, (128, 72), &marks(None));
    let green = Rgb([0, 255, 0]);
    assert_eq!(img.get_pixel(100, 60), &Rgb([GREY; 3]), "the frame");
    // The tracked centre (10, 8) → (20, 16), a + (its arms along the axes).
    assert_eq!(img.get_pixel(20, 16), &green);
    assert_eq!(img.get_pixel(22, 16), &green);
    assert_eq!(img.get_pixel(22, 18), &Rgb([GREY; 3]), "not diagonal");
    // The mark (30, 20) → (60, 40), a × (its arms on the diagonals).
    assert_eq!(img.get_pixel(60, 40), &green);
    assert_eq!(img.get_pixel(62, 42), &green);
    assert_eq!(img.get_pixel(62, 40), &Rgb([GREY; 3]), "not along the axes");
}

#[test]
fn the_models_balls_are_rings_of_the_radius_about_their_centres() {
    let v = view();
    // Balls at video (20, 18) and (44, 18), radius 5 px: in the picture at twice
    // that, (40, 36) and (88, 36), radius 10 px, the ring just outside (10.5 … 11.5).
    let img = picture(&v, 0, (128, 72), &marks(Some([(20.0, 18.0), (44.0, 18.0)])));
    let (blue, red) = (Rgb([0, 0, 255]), Rgb([255, 0, 0]));
    for (c, colour) in [((40, 36), blue), ((88, 36), red)] {
        for (dx, dy) in [(10, 0), (-11, 0), (0, 10), (0, -11)] {
            let p = img.get_pixel((c.0 + dx) as u32, (c.1 + dy) as u32);
            assert_eq!(p, &colour, "ring of {c:?} at {dx}, {dy}");
        }
        // Inside the ball: the frame shows through.
        assert_eq!(img.get_pixel(c.0 as u32 + 5, c.1 as u32), &Rgb([GREY; 3]));
        assert_eq!(img.get_pixel(c.0 as u32, c.1 as u32), &Rgb([GREY; 3]));
    }
    // Outside both rings: the frame.
    assert_eq!(img.get_pixel(64, 10), &Rgb([GREY; 3]));
}

#[test]
fn a_ball_partly_outside_the_picture_is_cut_not_a_panic() {
    let v = view();
    let img = picture(&v, 0, (128, 72), &marks(Some([(-3.0, 0.0), (70.0, 40.0)])));
    assert_eq!(img.dimensions(), (128, 72));
}

#[test]
fn a_kitty_picture_is_encoded_without_a_terminal_and_drawn_in_its_cells() {
    let v = view();
    let mut picker = Picker::halfblocks();
    picker.set_protocol_type(ProtocolType::Kitty);
    let img = picture(&v, 0, (128, 72), &marks(None));
    let size = Size::new(20, 6);
    let protocol = picker
        .new_protocol(DynamicImage::ImageRgb8(img), size, Resize::Fit(None))
        .unwrap();
    let area = Rect::new(0, 0, 20, 6);
    let mut buf = Buffer::empty(area);
    Image::new(&protocol).render(area, &mut buf);
    let all: String = buf.content().iter().map(|c| c.symbol()).collect();
    assert!(all.contains("\x1b_G"), "a kitty graphics escape");
}
