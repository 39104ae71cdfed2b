//! The one dot canvas of the TUI: a grid of braille cells (2×4 dots each) or, in
//! ASCII mode, of plain cells (one dot each, drawn with the ink's own glyph). The
//! chart's line series (`plot`) and the balls of the scene view both draw on it.

use ratatui::buffer::Buffer;
use ratatui::style::Style;

/// Dots on a grid of `cols × rows` cells. Each cell remembers the style and ASCII
/// glyph of the last dot set in it.
pub struct Canvas {
    cols: usize,
    rows: usize,
    ascii: bool,
    bits: Vec<u8>,
    ink: Vec<Option<(Style, &'static str)>>,
}

impl Canvas {
    pub fn new(cols: usize, rows: usize, ascii: bool) -> Canvas {
        Canvas {
            cols,
            rows,
            ascii,
            bits: vec![0; cols * rows],
            ink: vec![None; cols * rows],
        }
    }

    /// Dots per cell across and down: (2, 4) braille, (1, 1) ASCII.
    pub fn sub(&self) -> (usize, usize) {
        if self.ascii { (1, 1) } else { (2, 4) }
    }

    /// Dots across and down the whole canvas.
    pub fn dots(&self) -> (usize, usize) {
        let (sx, sy) = self.sub();
        (self.cols * sx, self.rows * sy)
    }

    /// Sets dot (`dx`, `dy`), counted from the top left; dots off the canvas are
    /// ignored.
    pub fn set(&mut self, dx: i64, dy: i64, style: Style, glyph: &'static str) {
        let (w, h) = self.dots();
        if dx < 0 || dy < 0 || dx as usize >= w || dy as usize >= h {
            return;
        }
        let (dx, dy) = (dx as usize, dy as usize);
        let (sx, sy) = self.sub();
        let cell = (dy / sy) * self.cols + dx / sx;
        // Braille dot numbering: columns of 1-2-3-7 and 4-5-6-8.
        const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
        self.bits[cell] |= if self.ascii { 1 } else { BITS[dx % 2][dy % 4] };
        self.ink[cell] = Some((style, glyph));
    }

    /// Sets the dot at (`x`, `y`) with `x` in cell widths across and `y` in dot rows
    /// down (the scene's units: dots are square in braille).
    pub fn dot(&mut self, x: f64, y: f64, style: Style, glyph: &'static str) {
        let sx = self.sub().0 as f64;
        // Float to int casts saturate (NaN → 0), as the bounds check expects.
        self.set((x * sx).floor() as i64, y.floor() as i64, style, glyph);
    }

    /// A straight line of dots from `a` to `b`, in (fractional) dot coordinates.
    pub fn line(&mut self, a: (f64, f64), b: (f64, f64), style: Style, glyph: &'static str) {
        let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as usize).clamp(1, 4096);
        for i in 0..=steps {
            let f = i as f64 / steps as f64;
            let x = a.0 + (b.0 - a.0) * f;
            let y = a.1 + (b.1 - a.1) * f;
            self.set(x.round() as i64, y.round() as i64, style, glyph);
        }
    }

    /// Writes every inked cell into `buf` with its top left at (`x0`, `y0`): the
    /// braille character of its dots, or its glyph in ASCII mode.
    pub fn write(&self, x0: u16, y0: u16, buf: &mut Buffer) {
        for r in 0..self.rows {
            for c in 0..self.cols {
                let i = r * self.cols + c;
                if let Some((style, glyph)) = self.ink[i] {
                    let sym = if self.ascii {
                        glyph.to_string()
                    } else {
                        char::from_u32(0x2800 + u32::from(self.bits[i]))
                            .unwrap_or(' ')
                            .to_string()
                    };
                    buf.set_string(x0 + c as u16, y0 + r as u16, sym, style);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(buf: &Buffer, x: u16, y: u16) -> String {
        buf[(x, y)].symbol().to_string()
    }

    #[test]
    fn dots_combine_into_one_braille_cell() {
        let mut c = Canvas::new(2, 1, false);
        assert_eq!(c.dots(), (4, 4));
        // Top left (dot 1) and bottom right (dot 8) of the first cell.
        c.set(0, 0, Style::default(), "o");
        c.set(1, 3, Style::default(), "o");
        // Off the canvas: ignored, no panic.
        c.set(-1, 0, Style::default(), "o");
        c.set(4, 0, Style::default(), "o");
        c.dot(f64::INFINITY, 0.0, Style::default(), "o");
        let mut buf = Buffer::empty(ratatui::layout::Rect::new(0, 0, 3, 1));
        c.write(1, 0, &mut buf);
        assert_eq!(cell(&buf, 1, 0), "\u{2881}");
        assert_eq!(cell(&buf, 2, 0), " ", "the second cell has no ink");
    }

    #[test]
    fn ascii_cells_show_the_last_glyph() {
        let mut c = Canvas::new(3, 2, true);
        assert_eq!(c.dots(), (3, 2));
        c.line((0.0, 0.0), (2.0, 1.0), Style::default(), "*");
        c.dot(2.4, 1.9, Style::default(), "o");
        let mut buf = Buffer::empty(ratatui::layout::Rect::new(0, 0, 3, 2));
        c.write(0, 0, &mut buf);
        assert_eq!(cell(&buf, 0, 0), "*");
        assert_eq!(cell(&buf, 2, 1), "o");
        assert_eq!(cell(&buf, 0, 1), " ");
    }
}
