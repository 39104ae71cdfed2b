//! The compositor (issue 26, as helix has it): the main screen at the bottom (its
//! views, [`main`], issue 36) and the popups open over it, a stack of layers. Each layer is a component that owns its state (a scroll, a
//! typed line, a highlighted row) and handles its own keys and mouse; an input goes
//! to the top layer first and falls through the stack when a layer ignores it (the
//! app's view and main keys lie below). A layer that is done closes itself
//! ([`Handled::Close`]) and says what the app should do then.
//!
//! The layers render in `view/` (they read the whole app there); this file and its
//! children know nothing of the app, which holds the stack.

pub mod main;
mod picker;
mod place;
mod prompt;
mod question;
mod scroll;

pub use picker::Picker;
pub use place::centered;
pub use prompt::{Confirm, Histories, Prompt};
pub use question::{Question, answer_at, question_rect};
pub use scroll::{DataTable, Help, Models, Scroll};

use super::interact::{Input, Interactive};
use super::vocabulary::{Handled, Mode, Then};

/// One popup over the main screen.
#[derive(Clone, Debug, PartialEq)]
pub enum Layer {
    /// The keys, scrolling.
    Help(Help),
    /// The measured data beside the model's values at those times, scrolling.
    Table(DataTable),
    /// The Fit view's candidate models by BIC, scrolling.
    Models(Models),
    /// The preset picker.
    Picker(Picker),
    /// Typing a value (on the status line), a save name or an export's file name.
    Prompt(Prompt),
    /// The preset file exists: overwrite it?
    Confirm(Confirm),
    /// Predict, observe, explain: the question before the impact.
    Question(Question),
}

/// What the layers need to know of the app to handle an input.
#[derive(Clone, Copy, Debug)]
pub struct LayerCx<'a> {
    /// How many presets the picker offers.
    pub presets: usize,
    /// The prompts' earlier entries (↑/↓ bring them back).
    pub histories: &'a Histories,
}

impl Layer {
    /// What is open, as plain data (the key table's modes, the tests' view of it).
    pub fn mode(&self) -> Mode {
        match self {
            Layer::Help(_) => Mode::Help,
            Layer::Table(_) => Mode::Table,
            Layer::Models(_) => Mode::Models,
            Layer::Picker(p) => Mode::Picker(p.selected()),
            Layer::Prompt(p) => p.mode(),
            Layer::Confirm(c) => Mode::ConfirmOverwrite(c.name().to_string()),
            Layer::Question(_) => Mode::Predict,
        }
    }

    /// True if the layer is drawn over the panels (the value prompt is typed on the
    /// status line: the screen under it stays whole).
    pub fn covers(&self) -> bool {
        !matches!(self, Layer::Prompt(p) if p.editing_value().is_some())
    }

    /// The scroll of a scrolling layer.
    fn scroll_mut(&mut self) -> Option<&mut Scroll> {
        match self {
            Layer::Help(h) => Some(h.scroll_mut()),
            Layer::Table(t) => Some(t.scroll_mut()),
            Layer::Models(m) => Some(m.scroll_mut()),
            Layer::Picker(_) | Layer::Prompt(_) | Layer::Confirm(_) | Layer::Question(_) => None,
        }
    }
}

impl Interactive<&LayerCx<'_>> for Layer {
    fn handle(&mut self, input: &Input, cx: &LayerCx<'_>) -> Handled {
        match self {
            Layer::Help(h) => h.handle(input, ()),
            Layer::Table(t) => t.handle(input, ()),
            Layer::Models(m) => m.handle(input, ()),
            Layer::Picker(p) => p.handle(input, cx.presets),
            Layer::Prompt(p) => p.handle(input, cx.histories),
            Layer::Confirm(c) => c.handle(input, ()),
            Layer::Question(q) => q.handle(input, ()),
        }
    }
}

/// The stack of layers: the main screen at the bottom, the popups over it, bottom
/// first.
#[derive(Clone, Debug, Default)]
pub struct Compositor {
    main: main::MainScreen,
    layers: Vec<Layer>,
}

impl Compositor {
    /// The bottom layer: the main screen's views.
    pub fn main(&self) -> &main::MainScreen {
        &self.main
    }

    pub fn main_mut(&mut self) -> &mut main::MainScreen {
        &mut self.main
    }

    /// Opens `layer` on top.
    pub fn push(&mut self, layer: Layer) {
        self.layers.push(layer);
    }

    /// The top layer, if any is open.
    pub fn top(&self) -> Option<&Layer> {
        self.layers.last()
    }

    /// The layers, bottom first (the order they are drawn in).
    pub fn iter(&self) -> impl Iterator<Item = &Layer> {
        self.layers.iter()
    }

    /// True while no popup is open (the main screen is always there).
    pub fn is_empty(&self) -> bool {
        self.layers.is_empty()
    }

    /// True if a layer is drawn over the panels.
    pub fn covers(&self) -> bool {
        self.layers.iter().any(Layer::covers)
    }

    /// What the screen laid out for the next frame: how far the top layer scrolls at
    /// this size (a key never scrolls into blank lines).
    pub fn laid_out(&mut self, scroll_max: usize) {
        if let Some(scroll) = self.layers.last_mut().and_then(Layer::scroll_mut) {
            scroll.laid_out(scroll_max);
        }
    }

    /// Offers `input` to the popups, top first, until one takes it; a layer that
    /// closes is taken off the stack (one that closes passing the key on,
    /// [`Then::Pass`], lets it go on down). [`Handled::Ignored`]: no popup took it
    /// (the app offers it to the main screen then, with what the views need).
    pub fn handle(&mut self, input: &Input, cx: &LayerCx<'_>) -> Handled {
        for i in (0..self.layers.len()).rev() {
            match self.layers[i].handle(input, cx) {
                Handled::Ignored => {}
                Handled::Close(Then::Pass) => {
                    self.layers.remove(i);
                }
                closed @ Handled::Close(_) => {
                    self.layers.remove(i);
                    return closed;
                }
                answer => return answer,
            }
        }
        Handled::Ignored
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::vocabulary::Action;

    fn offer(stack: &mut Compositor, action: Action) -> Handled {
        let histories = Histories::default();
        let cx = LayerCx {
            presets: 5,
            histories: &histories,
        };
        stack.handle(&Input::Key(action), &cx)
    }

    #[test]
    fn the_top_layer_takes_a_key_first_and_closes_alone() {
        let mut stack = Compositor::default();
        stack.push(Layer::Help(Help::default()));
        stack.push(Layer::Picker(Picker::on(2)));
        assert_eq!(offer(&mut stack, Action::Down), Handled::Consumed);
        assert_eq!(stack.top(), Some(&Layer::Picker(Picker::on(3))));
        assert_eq!(
            offer(&mut stack, Action::Confirm),
            Handled::Close(Then::Load(3))
        );
        // The picker closed; the help under it is the top again, its scroll untouched.
        assert_eq!(stack.top(), Some(&Layer::Help(Help::default())));
        assert_eq!(stack.iter().count(), 1);
    }

    #[test]
    fn a_key_no_layer_takes_falls_through_the_stack() {
        let mut stack = Compositor::default();
        stack.push(Layer::Table(DataTable::default()));
        stack.push(Layer::Question(Question));
        // Ctrl-C is no popup's key: it reaches the app, which quits.
        assert_eq!(offer(&mut stack, Action::Quit), Handled::Ignored);
        assert_eq!(stack.iter().count(), 2);
        assert_eq!(Compositor::default().top(), None);
        assert_eq!(
            offer(&mut Compositor::default(), Action::Down),
            Handled::Ignored
        );
    }

    #[test]
    fn a_scrolling_layer_stops_at_the_end_the_frame_laid_out() {
        let mut stack = Compositor::default();
        stack.push(Layer::Help(Help::default()));
        stack.laid_out(3);
        for _ in 0..5 {
            offer(&mut stack, Action::Down);
        }
        let Some(Layer::Help(help)) = stack.top() else {
            panic!("the help is open");
        };
        assert_eq!(help.scroll().first(), 3);
        // Any other key closes it and passes on (to the main screen: `p` opens the
        // picker, as in helix); Esc and its own key only close it.
        assert_eq!(offer(&mut stack, Action::Presets), Handled::Ignored);
        assert!(stack.is_empty());
        for closing in [Action::Cancel, Action::Help] {
            stack.push(Layer::Help(Help::default()));
            assert_eq!(offer(&mut stack, closing), Handled::Close(Then::Nothing));
            assert!(stack.is_empty());
        }
    }

    #[test]
    fn the_value_prompt_leaves_the_screen_uncovered() {
        let value = Prompt::new(crate::tui::vocabulary::TextTarget::Value, "4".into());
        let name = Prompt::new(crate::tui::vocabulary::TextTarget::Name, "x".into());
        assert!(!Layer::Prompt(value).covers());
        assert!(Layer::Prompt(name).covers());
        assert_eq!(
            Layer::Confirm(Confirm::new("x")).mode(),
            Mode::ConfirmOverwrite("x".into())
        );
    }
}
