//! What the screen hides while b is hidden (`B`: a class predicts the outcome from the
//! picture alone): one rule, in one place, that every view and status message asks.
//! b's value and the values that give it away are hidden, and so is everything that
//! follows from b (b/R, k, D and what it decides, the outcome's numbers, b's place on
//! the map).

use crate::settings::params::Key;

/// Whether b is hidden, and what that hides.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hide {
    b: bool,
}

impl Hide {
    /// True while b is hidden.
    pub fn b(self) -> bool {
        self.b
    }

    /// Hides b, or shows it again; true if it is hidden now.
    pub fn toggle(&mut self) -> bool {
        self.b = !self.b;
        self.b
    }

    /// Whether `key`'s value is hidden: b's, and the release heights' (they follow
    /// from v0 and k, so from b).
    pub fn value(self, key: Key) -> bool {
        self.b
            && matches!(
                key,
                Key::Width | Key::Height | Key::HeightLeft | Key::HeightRight
            )
    }

    /// Whether a change of the parameter labelled `label` (a pinned run's
    /// comparison) hides its values: it says only that it changed.
    pub fn change(self, label: &str) -> bool {
        self.b && label == Key::Width.param().label
    }

    /// Whether what follows from b is hidden: b/R, k, D and what it decides, the
    /// outcome's numbers, b's place on the map, the reasons that would name them.
    pub fn derived(self) -> bool {
        self.b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn b_and_what_gives_it_away_are_hidden_only_while_b_is() {
        let mut hide = Hide::default();
        assert!(!hide.value(Key::Width) && !hide.derived() && !hide.change("b"));
        assert!(hide.toggle());
        assert!(hide.value(Key::Width) && hide.value(Key::Height));
        assert!(!hide.value(Key::Mu) && !hide.value(Key::Radius));
        assert!(hide.change(Key::Width.param().label) && !hide.change("R"));
        assert!(hide.derived());
    }
}
