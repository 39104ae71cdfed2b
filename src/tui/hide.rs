//! What the screen hides while b is hidden (`B`: a class predicts the outcome from the
//! picture alone): one rule, in one place, that every view and status message asks.
//! b's value and the values that give it away are hidden, and so is everything that
//! follows from b (b/R, k, D and what it decides, the outcome's numbers, b's place on
//! the map).

use crate::settings::params::Key;

/// Whether b is hidden, whether a prediction is pending, and what that hides.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hide {
    b: bool,
    /// A prediction is asked or made and its outcome has not shown yet: b stays shown
    /// (the question states it), what follows from it does not.
    pending: bool,
    /// While a prediction is pending, the forces (|N|, |F|, F_net, the torques at A
    /// and B, r and k) are shown as the exercise's givens; else (the default) they are
    /// hidden too, so that no value on screen gives D away.
    forces_givens: bool,
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

    /// Shows the forces as givens while a prediction is pending, or hides them; true
    /// if they are shown now.
    pub fn toggle_forces_givens(&mut self) -> bool {
        self.forces_givens = !self.forces_givens;
        self.forces_givens
    }

    /// Whether a pending prediction shows the forces as givens (the setting).
    pub fn forces_givens(self) -> bool {
        self.forces_givens
    }

    /// This rule with a prediction pending or not (the app knows which).
    pub fn with_pending(self, pending: bool) -> Hide {
        Hide { pending, ..self }
    }

    /// Whether a prediction is pending.
    pub fn pending(self) -> bool {
        self.pending
    }

    /// Whether the values that follow from b's size are hidden: k, r, |N|, |F|, F_net,
    /// the torques at A and B. With b hidden always; while a prediction is pending
    /// unless the forces are the exercise's givens.
    pub fn forces(self) -> bool {
        self.b || (self.pending && !self.forces_givens)
    }

    /// Whether `key`'s value is hidden: b's, and the release heights' (they follow
    /// from v0 and k, so from b, and give D away with v0: D = v0²/(2gh − v0²)), the
    /// heights as k is ([`Hide::forces`]: also while a prediction is pending).
    pub fn value(self, key: Key) -> bool {
        match key {
            Key::Width => self.b,
            Key::Height | Key::HeightLeft | Key::HeightRight => self.forces(),
            _ => false,
        }
    }

    /// Whether a change of the parameter labelled `label` (a pinned run's
    /// comparison) hides its values: it says only that it changed.
    pub fn change(self, label: &str) -> bool {
        self.b && label == Key::Width.param().label
    }

    /// Whether what follows from b is hidden: b/R, k, D and what it decides, the
    /// outcome's numbers, b's place on the map, the reasons that would name them, the
    /// chart beyond the cursor (its curves and event labels show the outcome), preset
    /// descriptions. With b hidden, and while a prediction is pending.
    pub fn derived(self) -> bool {
        self.b || self.pending
    }
}

/// The time axis the charts show while the outcome is hidden: from `t_start` over the
/// first of 1, 2, 4, … s that reaches the cursor `t`. It depends on nothing but the
/// time played so far: the span's own end would tell the outcome (a pair that comes
/// back runs longer than one that departs).
pub fn neutral_span(t_start: f64, t: f64) -> (f64, f64) {
    let mut length = 1.0;
    while t_start + length < t && length < 1e7 {
        length *= 2.0;
    }
    (t_start, t_start + length)
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
        assert!(hide.derived() && hide.forces());
    }

    #[test]
    fn the_neutral_span_grows_with_the_cursor_only() {
        assert_eq!(neutral_span(-0.2, -0.2), (-0.2, 0.8));
        assert_eq!(neutral_span(-0.2, 0.8), (-0.2, 0.8));
        assert_eq!(neutral_span(-0.2, 0.9), (-0.2, 1.8));
        assert_eq!(neutral_span(0.0, 5.0), (0.0, 8.0));
    }

    #[test]
    fn a_pending_prediction_hides_what_follows_from_b_but_not_b() {
        let hide = Hide::default().with_pending(true);
        assert!(!hide.value(Key::Width) && hide.derived() && hide.forces());
        let mut givens = Hide::default();
        assert!(givens.toggle_forces_givens());
        assert!(!givens.with_pending(true).forces() && givens.with_pending(true).derived());
        assert!(!givens.derived() && !givens.forces());
    }
}
