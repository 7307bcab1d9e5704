//! `Sym`: exact rational functions of the model's variables, for proofs instead of samples.
//!
//! A value is a quotient N / D of polynomials over Q ([`Poly`], reduced modulo s² + c² = 1). The
//! quotient ring Q[s, c, …]/(s² + c² − 1) is an integral domain (s² + c² − 1 is irreducible), so
//! its fractions form a field and N₁/D₁ = N₂/D₂ exactly when N₁D₂ − N₂D₁ reduces to zero: a
//! value is zero exactly when its numerator's normal form is zero. That is the proof: every side
//! of a chain minus the first, reduced to normal form, is the zero polynomial.
//!
//! The denominator is kept factored, D = monomial · Π fᵢ^kᵢ with each fᵢ a non-monomial
//! polynomial scaled so its first term has coefficient 1: sums put fractions over the least
//! common multiple of the two factor lists instead of the product of the denominators, and a
//! numerator is divided by a factor when it divides exactly, so the total mass Σ mᵢ or the
//! 1 + … of a centre of mass do not pile up. (This is simplification for speed only; equality
//! never depends on it.)
//!
//! d/dt needs nothing new: the dual of `Sym` is [`Jet<Sym>`](super::Jet), and lifting a state
//! along the motion (s → s + c θ̇ ε, c → c − s θ̇ ε, θ̇ → θ̇ + θ̈ ε, θ̈ → θ̈ + θ⃛ ε) differentiates
//! symbolically, exactly as it differentiates numbers.

use super::poly::{exponent, mono_mul, var, with_exponent, Mono, Poly, Var};
use super::{Coeff, Jet, Scalar};
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::collections::BTreeMap;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A factored denominator: monomial · Π factor^exponent.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Den {
    /// The monomial part.
    pub mono: Mono,
    /// Non-monomial factors (first coefficient 1) and their exponents.
    pub factors: BTreeMap<Poly, u32>,
}

impl Den {
    fn is_one(&self) -> bool {
        self.mono.is_empty() && self.factors.is_empty()
    }
    /// The denominator as one polynomial.
    pub fn expand(&self) -> Poly {
        let mut p = Poly::constant(Coeff::one()).mul_term(&self.mono, &Coeff::one());
        for (f, k) in &self.factors {
            p = &p * &f.pow(*k);
        }
        p
    }
    fn lcm(&self, o: &Den) -> Den {
        let mut mono = self.mono.clone();
        for &(v, e) in &o.mono {
            if exponent(&mono, v) < e {
                mono = with_exponent(&mono, v, e);
            }
        }
        let mut factors = self.factors.clone();
        for (f, &k) in &o.factors {
            let e = factors.entry(f.clone()).or_insert(0);
            *e = (*e).max(k);
        }
        Den { mono, factors }
    }
    /// `self / part` as a polynomial (`part` divides `self`).
    fn cofactor(&self, part: &Den) -> Poly {
        let mono: Mono = self
            .mono
            .iter()
            .filter_map(|&(v, e)| {
                let e2 = e - exponent(&part.mono, v);
                (e2 > 0).then_some((v, e2))
            })
            .collect();
        let mut p = Poly::constant(Coeff::one()).mul_term(&mono, &Coeff::one());
        for (f, &k) in &self.factors {
            let k2 = k - part.factors.get(f).copied().unwrap_or(0);
            if k2 > 0 {
                p = &p * &f.pow(k2);
            }
        }
        p
    }
    fn mul(&self, o: &Den) -> Den {
        let mut factors = self.factors.clone();
        for (f, &k) in &o.factors {
            *factors.entry(f.clone()).or_insert(0) += k;
        }
        Den {
            mono: mono_mul(&self.mono, &o.mono),
            factors,
        }
    }
}

/// An exact rational function in the model's variables, modulo s² + c² = 1.
#[derive(Clone, Debug)]
pub struct Sym {
    /// The numerator N (normal form).
    pub num: Poly,
    /// The factored denominator D.
    pub den: Den,
}

impl Sym {
    /// The variable with this plain-text name and LaTeX form (e.g. `("θ̇", "\\dot\\theta")`).
    pub fn var(text: &str, latex: &str) -> Self {
        Sym::poly(Poly::var(var(text, latex)))
    }
    /// s = sin θ.
    pub fn sin() -> Self {
        Sym::poly(Poly::var(super::poly::S))
    }
    /// c = cos θ.
    pub fn cos() -> Self {
        Sym::poly(Poly::var(super::poly::C))
    }
    /// A polynomial.
    pub fn poly(p: Poly) -> Self {
        Sym {
            num: p,
            den: Den::default(),
        }
    }
    /// True when the value is zero on the circle s² + c² = 1 (a proof of an identity).
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    /// The index of the variable this value is, if it is one.
    pub fn as_var(&self) -> Option<Var> {
        if !self.den.is_one() || self.num.terms.len() != 1 {
            return None;
        }
        let (m, c) = self.num.terms.iter().next()?;
        (c.is_one() && m.len() == 1 && m[0].1 == 1).then_some(m[0].0)
    }

    /// Divide out common monomials, and factors that divide the numerator exactly.
    fn simplify(mut self) -> Self {
        if self.num.is_zero() {
            self.den = Den::default();
            return self;
        }
        let content = self.num.mono_content();
        let common: Mono = self
            .den
            .mono
            .iter()
            .filter_map(|&(v, e)| {
                let e2 = e.min(exponent(&content, v));
                (e2 > 0).then_some((v, e2))
            })
            .collect();
        if !common.is_empty() {
            self.num = self.num.div_mono(&common);
            self.den.mono = self
                .den
                .mono
                .iter()
                .filter_map(|&(v, e)| {
                    let e2 = e - exponent(&common, v);
                    (e2 > 0).then_some((v, e2))
                })
                .collect();
        }
        let factors: Vec<Poly> = self.den.factors.keys().cloned().collect();
        for f in factors {
            while let Some(q) = exact_div(&self.num, &f) {
                self.num = q;
                let k = self.den.factors.get_mut(&f).expect("factor present");
                *k -= 1;
                if *k == 0 {
                    self.den.factors.remove(&f);
                    break;
                }
            }
        }
        self
    }

    /// `(A, B)` with `self ≡ A + v·B` modulo `v² = r` (`r` free of `v`): the normal form modulo a
    /// quadratic relation such as the energy (10), θ̇² = 3g(1 − c)/(2l). `{1, v}` is a basis of
    /// the field extension when `r` is not a square, so `self` is zero there iff `A = B = 0`.
    pub fn reduce_square(&self, v: Var, r: &Sym) -> (Sym, Sym) {
        let split = |p: &Poly| -> (Sym, Sym) {
            let mut even: BTreeMap<u32, Poly> = BTreeMap::new();
            let mut odd: BTreeMap<u32, Poly> = BTreeMap::new();
            for (m, c) in &p.terms {
                let e = exponent(m, v);
                let rest = with_exponent(m, v, 0);
                let slot = if e % 2 == 0 { &mut even } else { &mut odd };
                let entry = slot.entry(e / 2).or_default();
                *entry = &*entry + &Poly::constant(c.clone()).mul_term(&rest, &Coeff::one());
            }
            let fold = |parts: BTreeMap<u32, Poly>| {
                parts.into_iter().fold(Sym::int(0), |acc, (k, p)| {
                    acc + Sym::poly(p) * (0..k).fold(Sym::int(1), |x, _| x * r.clone())
                })
            };
            (fold(even), fold(odd))
        };
        let (na, nb) = split(&self.num);
        let (da, db) = split(&self.den.expand());
        if db.is_zero() {
            return (na / da.clone(), nb / da);
        }
        // (na + v nb)/(da + v db) = (na + v nb)(da − v db)/(da² − r db²)
        let norm = da.clone() * da.clone() - r.clone() * db.clone() * db.clone();
        let a = (na.clone() * da.clone() - r.clone() * nb.clone() * db.clone()) / norm.clone();
        let b = (nb * da - na * db) / norm;
        (a, b)
    }
}

/// A lex order on monomials (variable 0 first): a true monomial order, for division.
fn lex(a: &Mono, b: &Mono) -> Ordering {
    let (mut i, mut j) = (0, 0);
    loop {
        match (a.get(i), b.get(j)) {
            (None, None) => return Ordering::Equal,
            (Some(_), None) => return Ordering::Greater,
            (None, Some(_)) => return Ordering::Less,
            (Some(x), Some(y)) => match x.0.cmp(&y.0) {
                Ordering::Less => return Ordering::Greater,
                Ordering::Greater => return Ordering::Less,
                Ordering::Equal => match x.1.cmp(&y.1) {
                    Ordering::Equal => {
                        i += 1;
                        j += 1;
                    }
                    o => return o,
                },
            },
        }
    }
}

fn leading(p: &Poly) -> Option<(&Mono, &Coeff)> {
    p.terms.iter().max_by(|a, b| lex(a.0, b.0))
}

/// `p / f` when `f` divides `p` in the polynomial ring (without the circle relation), else None.
fn exact_div(p: &Poly, f: &Poly) -> Option<Poly> {
    let (lf, cf) = leading(f)?;
    let (lf, cf) = (lf.clone(), cf.clone());
    let mut rem = p.clone();
    let mut q = Poly::zero();
    let mut steps = 0usize;
    while let Some((lm, lc)) = leading(&rem) {
        steps += 1;
        if steps > 4 * p.terms.len() + 16 {
            return None;
        }
        let mut qm = Mono::new();
        for &(v, e) in lm {
            let d = e.checked_sub(exponent(&lf, v))?;
            if d > 0 {
                qm.push((v, d));
            }
        }
        if lf.iter().any(|&(v, e)| exponent(lm, v) < e) {
            return None;
        }
        let qc = lc / &cf;
        // Subtract without the circle rewriting: exact division in the plain polynomial ring.
        for (m, c) in &f.terms {
            let mm = mono_mul(m, &qm);
            let v = rem.terms.entry(mm.clone()).or_insert_with(Coeff::zero);
            *v -= c * &qc;
            if v.is_zero() {
                rem.terms.remove(&mm);
            }
        }
        q.terms.insert(qm, qc);
    }
    Some(q)
}

/// Split a nonzero polynomial into (coefficient, monomial content, factor with first coefficient
/// 1) with `p = coefficient · content · factor`.
fn split_factor(p: &Poly) -> (Coeff, Mono, Poly) {
    let content = p.mono_content();
    let f = p.div_mono(&content);
    let lc = f.terms.values().next().cloned().unwrap_or_else(Coeff::one);
    let f = f.scale(&(Coeff::one() / lc.clone()));
    (lc, content, f)
}

impl PartialEq for Sym {
    fn eq(&self, o: &Self) -> bool {
        (self.clone() - o.clone()).is_zero()
    }
}

impl Add for Sym {
    type Output = Sym;
    fn add(self, o: Sym) -> Sym {
        if self.den == o.den {
            return Sym {
                num: &self.num + &o.num,
                den: self.den,
            }
            .simplify();
        }
        let den = self.den.lcm(&o.den);
        let num = &(&self.num * &den.cofactor(&self.den)) + &(&o.num * &den.cofactor(&o.den));
        Sym { num, den }.simplify()
    }
}

impl Neg for Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        Sym {
            num: -&self.num,
            den: self.den,
        }
    }
}

impl Sub for Sym {
    type Output = Sym;
    fn sub(self, o: Sym) -> Sym {
        self + (-o)
    }
}

impl Mul for Sym {
    type Output = Sym;
    fn mul(self, o: Sym) -> Sym {
        Sym {
            num: &self.num * &o.num,
            den: self.den.mul(&o.den),
        }
        .simplify()
    }
}

impl Div for Sym {
    type Output = Sym;
    fn div(self, o: Sym) -> Sym {
        assert!(!o.num.is_zero(), "symbolic division by zero");
        let (lc, content, f) = split_factor(&o.num);
        let num = (&self.num * &o.den.expand()).scale(&(Coeff::one() / lc));
        let mut factors = BTreeMap::new();
        if f.as_constant().is_none() {
            factors.insert(f, 1);
        }
        let den = self.den.mul(&Den {
            mono: content,
            factors,
        });
        Sym { num, den }.simplify()
    }
}

impl Scalar for Sym {
    type Dual = Jet<Sym>;
    fn int(n: i64) -> Self {
        Sym::poly(Poly::constant(Coeff::int(n)))
    }
    fn ratio(n: i64, d: i64) -> Self {
        Sym::poly(Poly::constant(Coeff::ratio(n, d)))
    }
    fn lift(re: Self, eps: Self) -> Jet<Sym> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Sym>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        match (self.den.is_one(), self.num.as_constant()) {
            (true, Some(q)) => q.to_f64(),
            _ => f64::NAN,
        }
    }
}
