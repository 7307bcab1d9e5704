//! Jacobi elliptic functions sn, cn, dn of real argument by the arithmetic-geometric mean and
//! the descending Gauss (Landen) transformation, written so that every one of them keeps its
//! *relative* accuracy, also when the modulus k is within 1e-300 of 1.
//!
//! No maintained Rust crate offers Jacobi functions (the `ellip` crate has integrals only), so
//! this is written by hand, generic over f64 and dual numbers so that tests can differentiate it.
//!
//! # Method
//! Start the AGM from the complementary modulus, a₀ = 1, b₀ = k', a_{n+1} = (a_n + b_n)/2,
//! b_{n+1} = √(a_n b_n) (DLMF 19.8.1, 22.20.1), until a_N = b_N to working precision; then
//! K(k) = π/(2a_N) (DLMF 19.8.5). Taking k' (not k) as the input is what makes the near-separatrix
//! case work: k' = 1e-12 is an ordinary number, while k = 1 − 5e-25 is not representable. The
//! differences d_n = a_n − b_n = 2c_{n+1} are carried too, from d₀ = k²/(2a₁) and
//! d_{n+1} = d_n²/(8a_{n+2}) (both follow from a_{n+1} − b_{n+1} = (√a_n − √b_n)²/2), so that no
//! difference of nearly equal numbers is ever rounded.
//!
//! Each AGM step is a descending Landen (Gauss) transformation of the modulus,
//! k_{n+1} = (1 − k'_n)/(1 + k'_n) with 1 + k_{n+1} = a_n/a_{n+1} and 1 − k_{n+1} = b_n/a_{n+1}.
//! DLMF 22.7.2–22.7.4 express the functions of modulus k_n at z through those of modulus
//! k_{n+1} at z a_{n+1}/a_n. Dividing 22.7.3 by 22.7.2 and rewriting 22.7.4 with
//! dn² = 1 − k² sn², sn² = 1/(1 + cs²), one finds, with cs = cn/sn and X_n = a_n cs_n,
//!
//!   X_n = X_{n+1} dn_{n+1},   dn_n = (p + b_n)/(p + a_n) = 1 − d_n/(p + a_n),   p = X_{n+1}²/a_{n+1}.
//!
//! At the last level k_N = 0 to working precision, so cs_N = cot(a_N u), dn_N = 1
//! (A&S 16.4 and DLMF 22.20(ii) give the same descent in terms of amplitudes; R. Bulirsch,
//! Numer. Math. 7 (1965) 78–90, gives it in ratio form). Finally sn = ±1/√(1 + cs₀²),
//! cn = cs₀ sn. When |cot(a_N u)| > 1 (u less than halfway to K) the same recurrence is run on
//! Y = 1/X, starting from tan(a_N u)/a_N, so no reciprocal of a small number is ever formed.
//!
//! # Why this form keeps relative accuracy
//! For 0 < u < K every quantity above is positive and only multiplied, divided or *added*: each
//! level adds a few rounding errors and nothing cancels. Of the two equal forms of dn_n the
//! quotient is used while p < a_n (there dn_n may be as small as k'), the form 1 − d_n/(p + a_n)
//! otherwise (there dn_n ≥ 1/2, and the quotient's derivative p'(p + a) − (p + b)p' would cancel
//! for dual numbers); likewise sn and cn are finished from whichever of cs, 1/cs is ≤ 1.
//!
//! The amplitude form of DLMF 22.20.3–4 instead returns cn = cos φ₀ with φ₀ ≈ π/2 when u nears K
//! and k nears 1: there cn is of size √k' to k', and its relative error is u/cn, 1e-4 for
//! k' = 1e-12. The ratio form can lose digits only in cot(a_N u) for a_N u near π/2; callers
//! who know v = K − u (the time left to reach the bottom of the pendulum) pass it instead, and
//! cot(a_N u) = tan(a_N v) is then accurate. Measured against mpmath (tests/sim/exact/reference.rs):
//! within 38u plus the argument's own condition |u f'/f| times 4u, for k' down to 1e-100.
use num_dual::DualNum;
use std::f64::consts::FRAC_PI_2;

/// Enough levels for every k' ≥ 1e-300: the AGM converges quadratically once b/a is not tiny,
/// and b grows like the square root of itself before that (about 11 levels for 1e-300).
const LEVELS: usize = 20;

/// The AGM of (1, k') with its whole history: the descending Landen chain of modulus k.
#[derive(Clone, Debug)]
pub struct Agm {
    a: [f64; LEVELS],
    b: [f64; LEVELS],
    /// a_n − b_n = 2c_{n+1} (DLMF 22.20.1), from d₀ = k²/(2a₁), d_{n+1} = d_n²/(8a_{n+2}):
    /// no difference of nearly equal numbers is ever formed.
    d: [f64; LEVELS],
    /// Index of the last level: a[last] = b[last] to working precision.
    last: usize,
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
        debug_assert!(
            kc > 0.0 && kc <= 1.0,
            "complementary modulus {kc} outside (0, 1]"
        );
        let mut a = [0.0; LEVELS];
        let mut b = [0.0; LEVELS];
        let mut d = [0.0; LEVELS];
        a[0] = 1.0;
        b[0] = kc;
        let mut last = 0;
        // Stop when a and b agree to a couple of ulps: the next level would change nothing.
        while last + 1 < LEVELS && (a[last] - b[last]) > 4.0 * f64::EPSILON * a[last] {
            a[last + 1] = 0.5 * (a[last] + b[last]);
            b[last + 1] = (a[last] * b[last]).sqrt();
            last += 1;
        }
        if last > 0 {
            d[0] = k2 / (2.0 * a[1]);
        }
        for n in 1..last {
            d[n] = d[n - 1] * d[n - 1] / (8.0 * a[n + 1]);
        }
        Agm { a, b, d, last }
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
        // cot(a_N u) as a quotient c/s of a sine and cosine, from whichever argument is accurate,
        // and the sign of sin(a_N u), which is the sign of sn.
        let (num, den, sign) = match arg {
            Arg::FromZero(u) => {
                let (s, c) = (u * m).sin_cos();
                (c, s, s.re().signum())
            }
            Arg::FromQuarter(v) => {
                let (s, c) = (v * m).sin_cos();
                (s, c, c.re().signum())
            }
        };
        if num.re().abs() <= den.re().abs() {
            self.descend_cs(num / den, sign)
        } else {
            self.descend_sc(den / num, sign)
        }
    }

    /// The descent carried in X = a cs, for |cs_N| ≤ 1 (u at least halfway to K).
    fn descend_cs<D: DualNum<Primitive = f64> + Copy>(&self, cs_last: D, sign: f64) -> Jacobi<D> {
        let mut cs = cs_last;
        let mut x = cs * self.mean();
        let mut dn = D::from(1.0);
        for n in (0..self.last).rev() {
            // p = X_{n+1} cs_{n+1} = X_{n+1}²/a_{n+1}.
            let dn_n = self.landen_dn(n, x * cs);
            x *= dn;
            cs = x / self.a[n];
            dn = dn_n;
        }
        finish(cs, None, dn, sign)
    }

    /// The same descent in Y = 1/X = sc/a, for |sc_N| < 1 (u less than halfway to K): no
    /// reciprocal of a small quantity is formed, so values and derivatives stay smooth at u = 0.
    fn descend_sc<D: DualNum<Primitive = f64> + Copy>(&self, sc_last: D, sign: f64) -> Jacobi<D> {
        let mut y = sc_last / self.mean();
        let mut dn = D::from(1.0);
        for n in (0..self.last).rev() {
            // p = 1/(a_{n+1} y²), passed as its reciprocal.
            let dn_n = self.landen_dn_recip(n, y * y * self.a[n + 1]);
            y /= dn;
            dn = dn_n;
        }
        finish(y.recip(), Some(y), dn, sign) // a₀ = 1: sc₀ = Y₀
    }

    /// dn_n = (p + b_n)/(p + a_n), in whichever of two equal forms neither cancels in value
    /// nor (for dual numbers) in the derivative: the quotient while p < a_n, where dn may be
    /// small, else 1 − d_n/(p + a_n), where the quotient's derivative p'(p + a) − (p + b)p'
    /// would cancel.
    fn landen_dn<D: DualNum<Primitive = f64> + Copy>(&self, n: usize, p: D) -> D {
        if p.re() < self.a[n] {
            (p + self.b[n]) / (p + self.a[n])
        } else {
            D::from(1.0) - (p + self.a[n]).recip() * self.d[n]
        }
    }

    /// [`Agm::landen_dn`] given q = 1/p.
    fn landen_dn_recip<D: DualNum<Primitive = f64> + Copy>(&self, n: usize, q: D) -> D {
        let one = D::from(1.0);
        if q.re() * self.a[n] > 1.0 {
            (q * self.b[n] + one) / (q * self.a[n] + one)
        } else {
            one - q * self.d[n] / (q * self.a[n] + one)
        }
    }
}

/// sn = ±1/√(1 + cs²), cn = cs·sn, written through whichever of cs, sc = 1/cs is at most 1 in
/// size so that the derivatives of sn and cn do not cancel to the order of cs² or sc².
fn finish<D: DualNum<Primitive = f64> + Copy>(cs: D, sc: Option<D>, dn: D, sign: f64) -> Jacobi<D> {
    let one = D::from(1.0);
    if cs.re().abs() <= 1.0 {
        let sn = (one + cs * cs).sqrt().recip() * sign;
        Jacobi {
            sn,
            cn: cs * sn,
            dn,
        }
    } else {
        let sc = sc.unwrap_or_else(|| cs.recip());
        let cn = (one + sc * sc).sqrt().recip() * (sign * sc.re().signum());
        Jacobi {
            sn: cn * sc,
            cn,
            dn,
        }
    }
}
