//! The wall force's factor at the start, D0 = Ω² cos θ0 − θ̇0², to f64's relative precision
//! from the scene's binary64 inputs (eq. (14) on the motion (5): F_w = m l sin θ (Ω² cos θ −
//! θ̇²), `rigid::separation_factor`).
//!
//! **Why.** Near the release push, θ̇0 → Ω √cos θ0, D0 is a small difference of two numbers of
//! size Ω² cos θ0: formed in f64 it carries an absolute error of about u Ω² cos θ0, a relative
//! error u κ with κ = Ω² cos θ0 / D0 (κ = 2.7e15 one ulp below Ω from upright; the scaling of a
//! scene to its own units, θ̇0 → θ̇0 √(l/g), adds the same again). The separation depends on the
//! start through D0 alone (sin²(θ_s/2) − sin²(θ0/2) = D0/(6Ω²), footnote 4 generalised), so
//! every digit of D0 lost is a digit of θ_s − θ0 and of t_s lost (`sim::near_release`).
//!
//! **How.** g, l and θ̇0 are binary64 numbers, hence exact rationals; cos θ0 (or sin φ0 for a
//! start given as φ0 = π/2 − θ0, as sin φ0 = φ0 · (sin φ0/φ0) so that a tiny φ0 keeps its
//! relative precision) is summed from its Taylor series in fixed point with 2⁻²⁰⁰ resolution,
//! each of its ≤ 60 terms truncated once (so within 2⁻¹⁹⁴ of the true value); then
//! D0 = (3 g C − 4 l θ̇0²)/(4 l) is exact rational arithmetic ([`crate::scalar::Rational`], the
//! exact checks' type), rounded once to f64 (num-rational's `to_f64` keeps 55 bits and rounds).
//! The error left is 2⁻¹⁹⁴ Ω² C plus half an ulp of D0. Hand-written: the crate has exact
//! rationals but no arbitrary-precision cosine (rug and malachite are LGPL with C builds);
//! twenty lines of series. It costs tens of microseconds, paid only near the release push.

use crate::ladder::Ladder;
use crate::scalar::{rational_from_float, Rational};
use num_bigint::BigInt;
use num_traits::{One, ToPrimitive, Zero};

/// Fixed-point resolution of the series: 2⁻ᴮᴵᵀˢ.
const BITS: i64 = 200;

/// The start's angle as a scene gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lean {
    /// θ0, rad (`[start] angle`).
    Theta(f64),
    /// φ0 = π/2 − θ0, rad (`[start] angle_from_floor`, exact where θ0 is not).
    Phi(f64),
}

impl Lean {
    /// cos θ0 in f64 (from φ0 as sin φ0).
    pub fn cos(self) -> f64 {
        match self {
            Lean::Theta(t) => t.cos(),
            Lean::Phi(p) => p.sin(),
        }
    }

    /// sin θ0 in f64 (from φ0 as cos φ0).
    pub fn sin(self) -> f64 {
        match self {
            Lean::Theta(t) => t.sin(),
            Lean::Phi(p) => p.cos(),
        }
    }

    /// cos θ0 (= sin φ0) as an exact rational within 2⁻¹⁹⁴ (relatively, for φ0) of the truth.
    fn cos_exact(self) -> Rational {
        match self {
            Lean::Theta(t) => fixed_series(t, 0),
            Lean::Phi(p) => exact(p) * fixed_series(p, 1),
        }
    }
}

/// x as an exact rational (x finite).
fn exact(x: f64) -> Rational {
    rational_from_float(x).unwrap_or_else(Rational::zero)
}

/// Σ_k (−1)^k x^{2k} / (2k + o)! · o! for o = 0 (cos x) or o = 1 (sin x / x), |x| ≤ 2, in fixed
/// point: each term is the last times −x²/((2k − 1 + o)(2k + o)), truncated to 2⁻ᴮᴵᵀˢ.
pub fn fixed_series(x: f64, o: u64) -> Rational {
    let one = BigInt::one() << BITS as usize;
    // x² in fixed point (x = m 2^e exactly, so x² 2^BITS = m² 2^(2e + BITS), truncated).
    let x2 = {
        let r = exact(x) * exact(x) * Rational::from_integer(one.clone().into());
        r.to_integer().0
    };
    let (mut term, mut sum) = (one.clone(), one.clone());
    let mut k = 1u64;
    while !term.is_zero() && k < 200 {
        term = -((term * &x2) >> BITS as usize) / BigInt::from((2 * k - 1 + o) * (2 * k + o));
        sum += &term;
        k += 1;
    }
    Rational::new(sum.into(), one.into())
}

/// D0 = Ω² cos θ0 − θ̇0² of `ladder` (in its own units, s⁻²) for the start `lean`, `rate0`:
/// exact rationals rounded once (module docs). NaN for a non-finite input.
pub fn start_margin(ladder: &Ladder<f64>, lean: Lean, rate0: f64) -> f64 {
    let (g, l) = (ladder.g, ladder.l);
    let angle = match lean {
        Lean::Theta(t) | Lean::Phi(t) => t,
    };
    if !(g.is_finite() && l.is_finite() && l > 0.0 && angle.is_finite() && rate0.is_finite()) {
        return f64::NAN;
    }
    let three = Rational::from_integer(3.into());
    let four = Rational::from_integer(4.into());
    let numer = three * exact(g) * lean.cos_exact() - four.clone() * exact(l) * exact(rate0).pow(2);
    (numer / (four * exact(l))).to_f64().unwrap_or(f64::NAN)
}

/// The same margin formed in f64, Ω² cos θ0 − θ̇0²: what the run used before (kept for the
/// tests that show its error).
pub fn start_margin_f64(ladder: &Ladder<f64>, lean: Lean, rate0: f64) -> f64 {
    ladder.big_omega2() * lean.cos() - rate0 * rate0
}
