//! Exact medians of levels (0–255, as the frames' bytes and their means are), fast:
//! the values counted per whole level first, then a selection among the few values
//! of the level that holds the middle. The result is the value a sort by
//! `total_cmp` puts at the middle (`sorted[len / 2]`), bit for bit, whatever the
//! values; only the time depends on their being levels. The learner takes one
//! median per coarse pixel and plane over its frames (hundreds of thousands per
//! clip), the tracker one over a few thousand differences per frame.

use std::cmp::Ordering;

/// Fewer values than this: a plain selection, as fast as counting them.
const FEW: usize = 24;

/// The median of `v` (`v` sorted by `f32::total_cmp`, its element `len / 2`), `v`
/// reordered; `None` when empty.
pub fn median_f32(v: &mut [f32]) -> Option<f32> {
    middle(v, |x| level(f64::from(x)), f32::total_cmp)
}

/// The median of `v` as [`median_f32`], for f64 values.
pub fn median_f64(v: &mut [f64]) -> Option<f64> {
    middle(v, level, f64::total_cmp)
}

/// The whole level `x` lies in, 0 … 255 (below 0: 0, above 255: 255): never
/// decreasing as `x` grows, so the levels sort as the values do. `None` for NaN.
#[inline]
fn level(x: f64) -> Option<usize> {
    if x.is_nan() {
        return None;
    }
    // `as` truncates toward zero: the floor for 0 … 255, the clamp does the rest.
    Some(x.clamp(0.0, 255.0) as usize)
}

/// Element `len / 2` of `v` sorted by `cmp`, where `of` gives each value a level
/// that never decreases along that order (`None`: sorted the plain way).
#[allow(clippy::indexing_slicing)] // levels clamped to 0..=255 of a 256-array; i, n < v.len()
fn middle<T: Copy>(
    v: &mut [T],
    of: impl Fn(T) -> Option<usize>,
    cmp: impl Fn(&T, &T) -> Ordering,
) -> Option<T> {
    if v.is_empty() {
        return None;
    }
    let mid = v.len() / 2;
    let plain = |v: &mut [T]| Some(*v.select_nth_unstable_by(mid, &cmp).1);
    if v.len() < FEW {
        return plain(v);
    }
    let mut counts = [0u32; 256];
    for &x in v.iter() {
        match of(x) {
            Some(l) => counts[l.min(255)] += 1,
            None => return plain(v),
        }
    }
    // The level holding the middle, and how many values lie below it.
    let (mut below, mut at) = (0usize, 255usize);
    for (l, &c) in counts.iter().enumerate() {
        if below + c as usize > mid {
            at = l;
            break;
        }
        below += c as usize;
    }
    // That level's values to the front; the middle is among them, at mid − below.
    let mut n = 0;
    for i in 0..v.len() {
        if of(v[i]).map(|l| l.min(255)) == Some(at) {
            v.swap(n, i);
            n += 1;
        }
    }
    Some(*v[..n].select_nth_unstable_by(mid - below, &cmp).1)
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
            prop_assert_eq!(median_f32(&mut w).map(f32::to_bits), want);
            let mut d: Vec<f64> = v.iter().map(|&x| f64::from(x)).collect();
            prop_assert_eq!(median_f64(&mut d).map(|x| x as f32).map(f32::to_bits), want);
        }
    }

    #[test]
    fn nan_falls_back_to_the_plain_selection() {
        let mut v: Vec<f32> = (0..40).map(|i| i as f32).collect();
        v[3] = f32::NAN;
        // total_cmp puts a positive NaN last: the middle of 0..40 without 3, and NaN.
        assert_eq!(median_f32(&mut v), Some(21.0));
        assert_eq!(median_f32(&mut []), None);
    }
}
