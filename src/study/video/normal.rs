//! Box–Muller's standard normal number from two uniform ones, with a logarithm and a
//! cosine of its own: the same bits on every platform (no libm of the system's), and
//! branch-free, so that a batch of them runs in vector registers (a film's sensor
//! noise is one number per pixel, most of the synthetic film's drawing).
//!
//! The logarithm and the cosine's kernels are fdlibm's (within an ulp of the true
//! values), under its notice:
//!
//! Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//! Developed at SunSoft, a Sun Microsystems, Inc. business. Permission to use, copy,
//! modify, and distribute this software is freely granted, provided that this notice
//! is preserved.

use std::f64::consts::{FRAC_2_PI, TAU};

/// `sqrt(-2 ln u) cos(2π v)`: a standard normal number from `u`, `v` uniform in
/// (0, 1).
#[inline(always)]
pub fn box_muller(u: f64, v: f64) -> f64 {
    (-2.0 * ln(u)).sqrt() * cos_of_turns(v)
}

/// SplitMix64's step: its state moves on by this at each draw.
pub const STEP: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's draw at `state` as a uniform number in (0, 1): 53 bits, centred
/// in their interval (never 0, whose logarithm Box–Muller would take).
#[inline(always)]
pub fn uniform(state: u64) -> f64 {
    let mut z = state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// `out[i]`: the normal number of the draws `2i + 1` and `2i + 2` after `state`,
/// each independent of the others (a draw's state is `state + k · STEP`), so they
/// are computed side by side in the widest vector registers the processor has: the
/// same bits in any (each operation rounds as IEEE 754 says; none is fused or
/// reordered).
pub fn normals(state: u64, out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        if has!("avx512f") && has!("avx512dq") && has!("avx512vl") {
            // SAFETY: the processor has these, just asked.
            unsafe { normals_avx512(state, out) };
            return;
        }
        if has!("avx2") {
            // SAFETY: as above.
            unsafe { normals_avx2(state, out) };
            return;
        }
    }
    normals_in(state, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl")]
fn normals_avx512(state: u64, out: &mut [f64]) {
    normals_in(state, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn normals_avx2(state: u64, out: &mut [f64]) {
    normals_in(state, out);
}

#[inline(always)]
fn normals_in(state: u64, out: &mut [f64]) {
    for (i, o) in out.iter_mut().enumerate() {
        let s = state.wrapping_add((2 * i as u64 + 1).wrapping_mul(STEP));
        *o = box_muller(uniform(s), uniform(s.wrapping_add(STEP)));
    }
}

/// 2^52 as a double: a whole number below it put in these bits reads back exactly.
const TWO_52: f64 = 4_503_599_627_370_496.0;

/// ln 2 in two parts: `k · LN2_HI` is exact for the exponents of doubles. (fdlibm's
/// constants are given as its bits, exactly.)
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
/// The Remez polynomial of `(ln(1+s) − ln(1−s) − 2s)/s`, in `s²`.
const LG: [f64; 7] = [
    f64::from_bits(0x3fe5_5555_5555_5593),
    f64::from_bits(0x3fd9_9999_9997_fa04),
    f64::from_bits(0x3fd2_4924_9422_9359),
    f64::from_bits(0x3fcc_71c5_1d8e_78af),
    f64::from_bits(0x3fc7_4664_96cb_03de),
    f64::from_bits(0x3fc3_9a09_d078_c69f),
    f64::from_bits(0x3fc2_f112_df3e_5244),
];

/// The natural logarithm of a positive normal double (what `uniform` gives; no
/// zero, subnormal, infinity or NaN comes here): `x = 2^k (1 + f)` with `1 + f`
/// within √2 of 1, then fdlibm's series in `s = f / (2 + f)`.
#[inline(always)]
fn ln(x: f64) -> f64 {
    let bits = x.to_bits();
    // The high word, moved so that the mantissa's carry past √2 lands in k.
    let high = (bits >> 32).wrapping_add(0x3ff0_0000 - 0x3fe6_a09e) & 0xffff_ffff;
    // k as a double without an integer conversion (none in vector registers).
    let k = f64::from_bits(TWO_52.to_bits() | (high >> 20)) - (TWO_52 + 1023.0);
    let high = (high & 0x000f_ffff) + 0x3fe6_a09e;
    let f = f64::from_bits((high << 32) | (bits & 0xffff_ffff)) - 1.0;
    let hfsq = 0.5 * f * f;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG[1] + w * (LG[3] + w * LG[5]));
    let t2 = z * (LG[0] + w * (LG[2] + w * (LG[4] + w * LG[6])));
    s * (hfsq + t1 + t2) + k * LN2_LO - hfsq + f + k * LN2_HI
}

/// π/2 in two parts: its first 33 bits (`n · PIO2_HI` exact for small `n`) and the rest.
const PIO2_HI: f64 = f64::from_bits(0x3ff9_21fb_5440_0000);
const PIO2_LO: f64 = f64::from_bits(0x3dd0_b461_1a62_6331);
/// 1.5 · 2^52: added to a double below 2^51 it rounds it to a whole number (ties to
/// even), held in the low bits.
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// `cos(2π v)` for `v` in [0, 1), of the rounded product `2π v` as `f64::cos` takes
/// it: reduced by the quarter turns `n` nearest, then fdlibm's kernels of sin and cos
/// on the remainder (|y| ≤ π/4), picked and signed by `n mod 4` with bit masks.
#[inline(always)]
fn cos_of_turns(v: f64) -> f64 {
    let x = TAU * v;
    let rounded = x * FRAC_2_PI + ROUNDER;
    let quarter = rounded.to_bits() & 3;
    let n = rounded - ROUNDER;
    let r = x - n * PIO2_HI;
    let w = n * PIO2_LO;
    let y0 = r - w;
    let y1 = (r - y0) - w;
    let (c, s) = (kernel_cos(y0, y1).to_bits(), kernel_sin(y0, y1).to_bits());
    // Quarters 1 and 3 take the sine; 1 and 2 are negative.
    let sine = 0u64.wrapping_sub(quarter & 1);
    let negative = ((quarter + 1) & 2) << 62;
    f64::from_bits(((c & !sine) | (s & sine)) ^ negative)
}

/// fdlibm's polynomial of `(sin y − y) / y³` in `y²` ([`kernel_sin`]).
const S: [f64; 6] = [
    f64::from_bits(0xbfc5_5555_5555_5549),
    f64::from_bits(0x3f81_1111_1110_f8a6),
    f64::from_bits(0xbf2a_01a0_19c1_61d5),
    f64::from_bits(0x3ec7_1de3_57b1_fe7d),
    f64::from_bits(0xbe5a_e5e6_8a2b_9ceb),
    f64::from_bits(0x3de5_d93a_5acf_d57c),
];
/// fdlibm's polynomial of `(cos y − 1 + y²/2) / y⁴` in `y²` ([`kernel_cos`]).
const C: [f64; 6] = [
    f64::from_bits(0x3fa5_5555_5555_554c),
    f64::from_bits(0xbf56_c16c_16c1_5177),
    f64::from_bits(0x3efa_01a0_19cb_1590),
    f64::from_bits(0xbe92_7e4f_809c_52ad),
    f64::from_bits(0x3e21_ee9e_bdb4_b1c4),
    f64::from_bits(0xbda8_fae9_be88_38d4),
];

/// sin(y0 + y1) for |y0 + y1| ≤ π/4, `y1` the tail of the reduced argument.
#[inline(always)]
fn kernel_sin(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = S[1] + z * (S[2] + z * S[3]) + z * w * (S[4] + z * S[5]);
    let v = z * x;
    x - ((z * (0.5 * y - v * r) - y) - v * S[0])
}

/// cos(y0 + y1) for |y0 + y1| ≤ π/4.
#[inline(always)]
fn kernel_cos(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = z * (C[0] + z * (C[1] + z * C[2])) + w * w * (C[3] + z * (C[4] + z * C[5]));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bits apart: 0 equal, 1 neighbours.
    fn ulps(a: f64, b: f64) -> u64 {
        a.to_bits().abs_diff(b.to_bits())
    }

    /// Evenly spread and edge arguments: within an ulp of the system's `ln` and
    /// `cos` (fdlibm's error bound; the system's is its own half ulp or so), so a
    /// film's noise is the one it was before these (to an ulp: a level rounds
    /// otherwise once in some 10^14 pixels).
    #[test]
    fn ln_and_cos_are_within_an_ulp_of_the_systems() {
        let n = 200_000;
        let edges = [f64::MIN_POSITIVE, 1e-300, 0.5, 1.0 - f64::EPSILON, 1.0];
        let spread = (0..n).map(|i| (i as f64 + 0.5) / n as f64);
        for u in spread.clone().chain(edges) {
            assert!(ulps(ln(u), u.ln()) <= 1, "ln {u}: {} vs {}", ln(u), u.ln());
        }
        let quarters = [
            0.0,
            0.125,
            0.25,
            0.375,
            0.5,
            0.625,
            0.75,
            0.875,
            1.0 - 1e-16,
        ];
        for v in spread.chain(quarters) {
            let (ours, system) = (cos_of_turns(v), (TAU * v).cos());
            // Near the zeros an ulp of the argument is many of the value's.
            assert!(
                ulps(ours, system) <= 1 || (ours - system).abs() <= 1e-16,
                "cos 2π·{v}: {ours} vs {system}"
            );
        }
    }

    /// Each vector path this processor has gives the bits of one draw at a time,
    /// over lengths that end inside and past a vector.
    #[test]
    fn every_vector_path_gives_the_bits_of_one_at_a_time() {
        let state: u64 = 0x1234_5678_9abc_def0;
        for len in [0, 1, 3, 7, 8, 9, 250] {
            let single: Vec<u64> = (0..len as u64)
                .map(|i| {
                    let s = state.wrapping_add((2 * i + 1).wrapping_mul(STEP));
                    box_muller(uniform(s), uniform(s.wrapping_add(STEP))).to_bits()
                })
                .collect();
            let bits = |out: &[f64]| out.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            let mut out = vec![0.0; len];
            normals_in(state, &mut out);
            assert_eq!(bits(&out), single, "baseline, {len}");
            #[cfg(target_arch = "x86_64")]
            {
                use std::arch::is_x86_feature_detected as has;
                if has!("avx2") {
                    // SAFETY: the processor has AVX2, just asked.
                    unsafe { normals_avx2(state, &mut out) };
                    assert_eq!(bits(&out), single, "AVX2, {len}");
                }
                if has!("avx512f") && has!("avx512dq") && has!("avx512vl") {
                    // SAFETY: as above.
                    unsafe { normals_avx512(state, &mut out) };
                    assert_eq!(bits(&out), single, "AVX-512, {len}");
                }
            }
        }
    }

    /// A million numbers: mean 0 and variance 1 within their sampling error
    /// (5σ: 0.005 and 0.007), none beyond the largest `u` allows (√(2·53 ln 2)).
    #[test]
    fn box_muller_is_a_standard_normal() {
        let n = 1_000_000;
        let draws: Vec<f64> = (0..n)
            .map(|i| {
                box_muller(
                    (i as f64 + 0.5) / n as f64,
                    (i as f64 * 0.618_033_988_7).fract(),
                )
            })
            .collect();
        let mean = draws.iter().sum::<f64>() / n as f64;
        let var = draws.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / n as f64;
        assert!(mean.abs() < 0.005, "mean {mean}");
        assert!((var - 1.0).abs() < 0.007, "variance {var}");
        let limit = (2.0 * 53.0 * std::f64::consts::LN_2).sqrt();
        assert!(draws.iter().all(|d| d.abs() <= limit));
    }
}
