//! Polynomials over Q in named variables, kept in normal form modulo s² + c² = 1.
//!
//! A [`Poly`] is a map from exponent vectors ([`Mono`], sparse and sorted, so equal monomials
//! compare equal whatever variables exist) to nonzero rational coefficients. Every product is
//! reduced by the single rewriting rule c² → 1 − s² (s = sin θ, c = cos θ are the variables
//! [`S`] and [`C`]), so a polynomial in normal form has degree at most one in c.
//!
//! **Why this is a normal form.** The ideal I = (s² + c² − 1) is principal, and the one generator
//! of a principal ideal is a Gröbner basis of it (the only S-polynomial is that of the generator
//! with itself, which is zero). Take a monomial order in which c² leads s² + c² − 1 (lex with c
//! first). Division by a Gröbner basis leaves a unique remainder, and the remainders of division by
//! s² + c² − 1 are exactly the polynomials of c-degree ≤ 1: two polynomials are congruent modulo
//! I exactly when their reduced forms are equal, and p ∈ I exactly when its reduced form is zero.
//! Rewriting c^(2k+r) → (1 − s²)^k c^r term by term computes that remainder.
//!
//! Hand-written (about 200 lines) rather than taken from a crate: feanor-math and the `groebner`
//! crate both keep their polynomials inside a ring object that every operation must be given
//! (`ring.add(a, b)`), which does not fit the project's [`Scalar`](super::Scalar) trait, whose
//! values carry their own `+ − × ÷` so that one generic function serves every number type; and
//! the only ideal needed here has a one-line Gröbner basis. Coefficients are [`Coeff`]: machine
//! words while they fit, `BigRational` beyond (see the `coeff` module).

use super::Coeff;
use num_traits::{One, Zero};
use std::collections::BTreeMap;
use std::sync::Mutex;

/// A variable: an index into the table of names.
pub type Var = u32;
/// s = sin θ.
pub const S: Var = 0;
/// c = cos θ.
pub const C: Var = 1;

/// Names of the variables: (plain text, LaTeX).
static NAMES: Mutex<Vec<(String, String)>> = Mutex::new(Vec::new());

fn with_names<R>(f: impl FnOnce(&mut Vec<(String, String)>) -> R) -> R {
    let mut names = NAMES.lock().unwrap_or_else(|e| e.into_inner());
    if names.is_empty() {
        // The ladder's variables first, in a fixed order, so printing does not depend on which
        // code created a variable first.
        for (t, l) in [
            ("s", "s"),
            ("c", "c"),
            ("m", "m"),
            ("l", "l"),
            ("g", "g"),
            ("θ̇", "\\dot\\theta"),
            ("θ̈", "\\ddot\\theta"),
            ("θ⃛", "\\dddot\\theta"),
        ] {
            names.push((t.into(), l.into()));
        }
    }
    f(&mut names)
}

/// The variable of this plain-text name (created on first use, with its LaTeX form).
pub fn var(text: &str, latex: &str) -> Var {
    with_names(|names| {
        if let Some(i) = names.iter().position(|n| n.0 == text) {
            return i as Var;
        }
        names.push((text.into(), latex.into()));
        (names.len() - 1) as Var
    })
}

/// The (plain text, LaTeX) names of a variable.
pub fn var_names(v: Var) -> (String, String) {
    with_names(|names| names[v as usize].clone())
}

/// A monomial: (variable, exponent) pairs sorted by variable, exponents positive.
pub type Mono = Vec<(Var, u32)>;

/// The product of two monomials.
pub fn mono_mul(a: &Mono, b: &Mono) -> Mono {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Less => {
                out.push(a[i]);
                i += 1;
            }
            std::cmp::Ordering::Greater => {
                out.push(b[j]);
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                out.push((a[i].0, a[i].1 + b[j].1));
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

/// The exponent of `v` in `m`.
pub fn exponent(m: &Mono, v: Var) -> u32 {
    m.iter().find(|p| p.0 == v).map_or(0, |p| p.1)
}

/// `m` with the exponent of `v` set to `e`.
pub fn with_exponent(m: &Mono, v: Var, e: u32) -> Mono {
    let mut out: Mono = m.iter().copied().filter(|p| p.0 != v).collect();
    if e > 0 {
        let at = out.partition_point(|p| p.0 < v);
        out.insert(at, (v, e));
    }
    out
}

/// A polynomial over Q in normal form modulo s² + c² − 1 (c-degree ≤ 1).
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Poly {
    /// Monomial → nonzero coefficient.
    pub terms: BTreeMap<Mono, Coeff>,
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly::default()
    }
    /// A constant.
    pub fn constant(q: Coeff) -> Self {
        let mut p = Poly::zero();
        p.add_term(Vec::new(), q);
        p
    }
    /// A single variable.
    pub fn var(v: Var) -> Self {
        let mut p = Poly::zero();
        p.add_term(vec![(v, 1)], Coeff::one());
        p
    }
    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    /// The value if constant.
    pub fn as_constant(&self) -> Option<Coeff> {
        match self.terms.len() {
            0 => Some(Coeff::zero()),
            1 => self.terms.get(&Vec::new()).cloned(),
            _ => None,
        }
    }
    /// Add `q · m` (m must already be reduced).
    fn add_term(&mut self, m: Mono, q: Coeff) {
        if q.is_zero() {
            return;
        }
        match self.terms.entry(m) {
            std::collections::btree_map::Entry::Vacant(e) => {
                e.insert(q);
            }
            std::collections::btree_map::Entry::Occupied(mut e) => {
                *e.get_mut() += q;
                if e.get().is_zero() {
                    e.remove();
                }
            }
        }
    }
    /// Add `q · m`, reducing c² → 1 − s² first.
    pub fn add_reduced_term(&mut self, m: Mono, q: Coeff) {
        let ec = exponent(&m, C);
        if ec < 2 {
            return self.add_term(m, q);
        }
        // c^(2k+r) = (1 − s²)^k c^r = Σ_j (k choose j) (−1)^j s^(2j) c^r
        let (k, r) = (ec / 2, ec % 2);
        let base = with_exponent(&m, C, r);
        let es = exponent(&base, S);
        let mut binom = Coeff::one();
        for j in 0..=k {
            let sign = if j % 2 == 0 { q.clone() } else { -&q };
            self.add_term(with_exponent(&base, S, es + 2 * j), &sign * &binom);
            binom = binom * Coeff::int(i64::from(k - j)) / Coeff::int(i64::from(j + 1));
        }
    }
    /// `self · q`.
    pub fn scale(&self, q: &Coeff) -> Poly {
        if q.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), c * q)).collect(),
        }
    }
    /// `self · q · m` (m a monomial free of c, or any: reduced).
    pub fn mul_term(&self, m: &Mono, q: &Coeff) -> Poly {
        let mut out = Poly::zero();
        for (mm, c) in &self.terms {
            out.add_reduced_term(mono_mul(mm, m), c * q);
        }
        out
    }
    /// The largest monomial dividing every term (the monomial content).
    pub fn mono_content(&self) -> Mono {
        let mut it = self.terms.keys();
        let Some(first) = it.next() else {
            return Vec::new();
        };
        let mut g = first.clone();
        for m in it {
            g = g
                .into_iter()
                .filter_map(|(v, e)| {
                    let e2 = exponent(m, v).min(e);
                    (e2 > 0).then_some((v, e2))
                })
                .collect();
            if g.is_empty() {
                break;
            }
        }
        g
    }
    /// `self / m` for a monomial dividing every term.
    pub fn div_mono(&self, m: &Mono) -> Poly {
        Poly {
            terms: self
                .terms
                .iter()
                .map(|(mm, c)| {
                    let q = mm
                        .iter()
                        .filter_map(|&(v, e)| {
                            let e2 = e - exponent(m, v);
                            (e2 > 0).then_some((v, e2))
                        })
                        .collect();
                    (q, c.clone())
                })
                .collect(),
        }
    }
    /// `self^k`.
    pub fn pow(&self, k: u32) -> Poly {
        let mut out = Poly::constant(Coeff::one());
        for _ in 0..k {
            out = &out * self;
        }
        out
    }
}

impl std::ops::Add for &Poly {
    type Output = Poly;
    fn add(self, o: &Poly) -> Poly {
        let (big, small) = if self.terms.len() >= o.terms.len() {
            (self, o)
        } else {
            (o, self)
        };
        let mut out = big.clone();
        for (m, c) in &small.terms {
            out.add_term(m.clone(), c.clone());
        }
        out
    }
}

impl std::ops::Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }
}

impl std::ops::Sub for &Poly {
    type Output = Poly;
    fn sub(self, o: &Poly) -> Poly {
        let mut out = self.clone();
        for (m, c) in &o.terms {
            out.add_term(m.clone(), -c);
        }
        out
    }
}

impl std::ops::Mul for &Poly {
    type Output = Poly;
    fn mul(self, o: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &o.terms {
                out.add_reduced_term(mono_mul(ma, mb), ca * cb);
            }
        }
        out
    }
}
