//! Jacobi elliptic functions sn, cn, dn of real argument by the arithmetic-geometric mean and
//! the descending Gauss (Landen) transformation, written so that every one of them keeps its
//! *relative* accuracy, also when the modulus k is within 1e-300 of 1.
//!
//! No maintained Rust crate offers Jacobi functions (the `ellip` crate has integrals only), so
//! this is written by hand: some 80 lines.
//!
//! # Method
//! Start the AGM from the complementary modulus, a₀ = 1, b₀ = k', a_{n+1} = (a_n + b_n)/2,
//! b_{n+1} = √(a_n b_n) (DLMF 19.8.1, 22.20.1), until a_N = b_N to working precision; then
//! K(k) = π/(2a_N) (DLMF 19.8.5). Taking k' (not k) as the input is what makes the near-separatrix
//! case work: k' = 1e-12 is an ordinary number, while k = 1 − 5e-25 is not representable.
//!
//! Each AGM step is a descending Landen (Gauss) transformation of the modulus,
//! k_{n+1} = (1 − k'_n)/(1 + k'_n) with 1 + k_{n+1} = a_n/a_{n+1} and 1 − k_{n+1} = b_n/a_{n+1}.
//! DLMF 22.7.2–22.7.4 express the functions of modulus k_n at z through those of modulus
//! k_{n+1} at z a_{n+1}/a_n. Dividing 22.7.3 by 22.7.2 and rewriting 22.7.4 with
//! dn² = 1 − k² sn², sn² = 1/(1 + cs²), one finds, with cs = cn/sn and X_n = a_n cs_n,
//!
//!   X_n = X_{n+1} dn_{n+1},      dn_n = (X_{n+1} cs_{n+1} + b_n) / (X_{n+1} cs_{n+1} + a_n).
//!
//! At the last level k_N = 0 to working precision, so cs_N = cot(a_N u), dn_N = 1
//! (A&S 16.4 and DLMF 22.20(ii) give the same descent in terms of amplitudes; R. Bulirsch,
//! Numer. Math. 7 (1965) 78–90, gives it in this ratio form). Finally sn = ±1/√(1 + cs₀²),
//! cn = cs₀ sn.
//!
//! # Why this form keeps relative accuracy
//! For 0 < u < K every quantity above is positive and only multiplied, divided or *added*, so
//! each level adds a few rounding errors and nothing cancels; dn_n is even damped with respect to
//! errors in X_{n+1}. The amplitude form of DLMF 22.20.1 instead returns cn = cos φ₀ with
//! φ₀ ≈ π/2 when u is near K and k near 1: there cos φ₀ is of size √k' or k' and its relative
//! error u/k' (1e4 ulps for k' = 1e-12 already). The only place where the ratio form can lose
//! digits is cot(a_N u) for a_N u near π/2; callers who know v = K − u (the time left to reach
//! the bottom of the pendulum) pass it instead, and cot(a_N u) = tan(a_N v) is then accurate.
//! Near u = 0 the leading Taylor terms are used, so cot never overflows.
use num_dual::DualNum;
use std::f64::consts::FRAC_PI_2;

/// Enough levels for every k' ≥ 1e-300: the AGM converges quadratically once b/a is not tiny,
/// and b grows like the square root of itself before that (about 11 levels for 1e-300).
const LEVELS: usize = 20;

/// Below this |u| the Taylor polynomials sn = u, cn = 1 − u²/2, dn = 1 − k²u²/2 are exact to
/// half an ulp (the next terms are below u³/6 ≤ 1.7e-28 |u|).
const TAYLOR_BELOW: f64 = 1e-9;

/// The AGM of (1, k') with its whole history: the descending Landen chain of modulus k.
#[derive(Clone, Debug)]
pub struct Agm {
    a: [f64; LEVELS],
    b: [f64; LEVELS],
    /// Index of the last level: a[last] = b[last] to working precision.
    last: usize,
    /// k² = 1 − k'², passed in by the caller, who knows it without cancellation.
    k2: f64,
}

/// sn, cn, dn at one argument, each with its relative accuracy (see the module docs).
/// `D` is f64 or a dual number (derivatives with respect to the argument come along).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jacobi<D = f64> {
    /// sn(u|k).
    pub sn: D,
    /// cn(u|k).
    pub cn: D,
    /// dn(u|k).
    pub dn: D,
    /// cs(u|k) = cn/sn, the quantity the recurrence carries.
    pub cs: D,
}

/// Which argument the caller knows accurately.
#[derive(Clone, Copy, Debug)]
pub enum Arg<D = f64> {
    /// u itself, measured from sn = 0.
    FromZero(D),
    /// v = K − u, measured back from the quarter period where cn = 0.
    FromQuarter(D),
}

impl Agm {
    /// AGM chain for complementary modulus `kc` = k' in (0, 1] and k² = 1 − k'² given
    /// separately (the caller computes it without cancellation).
    pub fn new(kc: f64, k2: f64) -> Agm {
        debug_assert!(kc > 0.0 && kc <= 1.0, "complementary modulus {kc} outside (0, 1]");
        let mut a = [0.0; LEVELS];
        let mut b = [0.0; LEVELS];
        a[0] = 1.0;
        b[0] = kc;
        let mut last = 0;
        // Stop when a and b agree to a couple of ulps: the next level would change nothing.
        while last + 1 < LEVELS && (a[last] - b[last]) > 4.0 * f64::EPSILON * a[last] {
            a[last + 1] = 0.5 * (a[last] + b[last]);
            b[last + 1] = (a[last] * b[last]).sqrt();
            last += 1;
        }
        Agm { a, b, last, k2 }
    }

    /// The arithmetic-geometric mean M(1, k') = π / (2K).
    pub fn mean(&self) -> f64 {
        self.a[self.last]
    }

    /// The complete integral K(k) = π / (2 M(1, k')) (DLMF 19.8.5).
    pub fn quarter_period(&self) -> f64 {
        FRAC_PI_2 / self.mean()
    }

    /// sn, cn, dn of modulus k at the argument `arg` (f64 or a dual number).
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(&self, arg: Arg<D>) -> Jacobi<D> {
        let m = self.mean();
        let one = D::from(1.0);
        // cot(a_N u) and the sign of sin(a_N u), from whichever argument is accurate.
        let (cs_last, sign) = match arg {
            Arg::FromZero(u) if u.re().abs() < TAYLOR_BELOW => {
                let u2 = u * u;
                let (sn, cn, dn) = (u, one - u2 * 0.5, one - u2 * (0.5 * self.k2));
                return Jacobi { sn, cn, dn, cs: cn / sn };
            }
            Arg::FromZero(u) => {
                let (s, c) = (u * m).sin_cos();
                (c / s, s.re().signum())
            }
            Arg::FromQuarter(v) => {
                let (s, c) = (v * m).sin_cos();
                (s / c, c.re().signum())
            }
        };
        let mut cs = cs_last;
        let mut x = cs * m;
        let mut dn = one;
        for n in (0..self.last).rev() {
            let p = x * cs;
            let dn_n = (p + self.b[n]) / (p + self.a[n]);
            x *= dn;
            cs = x / self.a[n];
            dn = dn_n;
        }
        let sn = (one + cs * cs).sqrt().recip() * sign;
        Jacobi { sn, cn: cs * sn, dn, cs }
    }
}
