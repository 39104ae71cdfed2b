//! Exact medians of levels fast: where every value is a whole level (0–255, as a
//! frame's bytes and the colour planes of the coarse frames are), the values
//! counted per level and the middle read off the counts, in one pass and no
//! comparisons; other values by selection. Either way the result is the value a
//! sort by `total_cmp` puts at the middle (`sorted[len / 2]`), bit for bit. The
//! learner takes one median per coarse pixel and plane over its frames (hundreds
//! of thousands per clip), the tracker one over a few thousand pixel differences
//! per frame.

/// Fewer values than this: a plain selection, as fast as counting them.
const FEW: usize = 24;

/// A float that may hold a whole level exactly (f32 and f64: the frames' planes and
/// the tracker's differences).
pub trait Level: Copy {
    /// The level `self` is, when it is exactly one (`+0 … 255`: equal levels are
    /// equal bits).
    fn level(self) -> Option<u8>;
    fn from_level(l: u8) -> Self;
    fn total_cmp(&self, other: &Self) -> std::cmp::Ordering;
}

impl Level for f32 {
    fn level(self) -> Option<u8> {
        let l = self as u8;
        (f32::from(l).to_bits() == self.to_bits()).then_some(l)
    }
    fn from_level(l: u8) -> f32 {
        f32::from(l)
    }
    fn total_cmp(&self, other: &f32) -> std::cmp::Ordering {
        f32::total_cmp(self, other)
    }
}

impl Level for f64 {
    fn level(self) -> Option<u8> {
        let l = self as u8;
        (f64::from(l).to_bits() == self.to_bits()).then_some(l)
    }
    fn from_level(l: u8) -> f64 {
        f64::from(l)
    }
    fn total_cmp(&self, other: &f64) -> std::cmp::Ordering {
        f64::total_cmp(self, other)
    }
}

/// The median of `v` (`v` sorted by `total_cmp`, its element `len / 2`), `v`
/// reordered; `None` when empty.
pub fn median<T: Level>(v: &mut [T]) -> Option<T> {
    let mid = v.len() / 2;
    if v.len() >= FEW
        && let Some(m) = counted(v.iter().map(|&x| x.level()), mid)
    {
        return Some(T::from_level(m));
    }
    (!v.is_empty()).then(|| *v.select_nth_unstable_by(mid, T::total_cmp).1)
}

/// The level at place `mid` of `levels` sorted, by counting them; `None` at the
/// first value that is not a whole level (`None` in `levels`: `+0 … 255` exactly,
/// so equal levels are equal bits) or when there are too many to count in 16 bits.
#[allow(clippy::indexing_slicing)] // a u8 level indexes a 256-array
fn counted(levels: impl ExactSizeIterator<Item = Option<u8>>, mid: usize) -> Option<u8> {
    if levels.len() > usize::from(u16::MAX) {
        return None;
    }
    let mut counts = [0u16; 256];
    for l in levels {
        counts[usize::from(l?)] += 1;
    }
    let mut below = 0usize;
    for (l, &c) in counts.iter().enumerate() {
        below += usize::from(c);
        if below > mid {
            return u8::try_from(l).ok();
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn sorted_middle(v: &[f32]) -> Option<f32> {
        let mut s = v.to_vec();
        s.sort_by(f32::total_cmp);
        s.get(s.len() / 2).copied()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]
        /// Levels, fractions of them, negatives, values past 255, zeros of both
        /// signs, many ties: the same bits as the sort's middle.
        #[test]
        fn the_median_is_the_sorts_middle_bit_for_bit(
            v in prop::collection::vec(
                prop_oneof![
                    (0u8..=255).prop_map(f32::from),
                    (0u32..9181).prop_map(|k| k as f32 * (1.0 / 36.0f32)),
                    -300.0f32..600.0,
                    Just(0.0f32),
                    Just(-0.0f32),
                    Just(f32::INFINITY),
                ],
                0..200,
            )
        ) {
            let want = sorted_middle(&v).map(f32::to_bits);
            let mut w = v.clone();
            prop_assert_eq!(median(&mut w).map(f32::to_bits), want);
            let mut d: Vec<f64> = v.iter().map(|&x| f64::from(x)).collect();
            prop_assert_eq!(median(&mut d).map(|x| x as f32).map(f32::to_bits), want);
        }
    }

    #[test]
    fn nan_falls_back_to_the_plain_selection() {
        let mut v: Vec<f32> = (0..40).map(|i| i as f32).collect();
        v[3] = f32::NAN;
        // total_cmp puts a positive NaN last: the middle of 0..40 without 3, and NaN.
        assert_eq!(median(&mut v), Some(21.0));
        assert_eq!(median::<f32>(&mut []), None);
    }
}
