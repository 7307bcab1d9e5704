//! A readable, factored form of a [`Sym`], for the errata's differences printed − corrected: a
//! missing mass reads `l²θ̇ (1 − m)(c² − s²)`, not `2s²ml²θ̇ − 2s²l²θ̇ − ml²θ̇ + l²θ̇`.
//!
//! Display only: equality never depends on it, and the product is expanded again and compared
//! with the normal form before it is used (any mismatch falls back to the expanded form), so a
//! wrong factoring cannot print. Three cheap steps, not a general factoring algorithm:
//!
//! 1. the rational content and the largest monomial dividing every term are taken out;
//! 2. the rest is split into factors in disjoint sets of variables (s and c count as one, θ):
//!    p = A(X) · B(Y) exactly when p's coefficient matrix, rows the monomials in X and columns
//!    those in Y, has rank one; the smallest such X is split off first, then the rest again;
//! 3. a factor in s and c whose terms all have (s, c)-degrees of one parity is homogenised with
//!    s² + c² = 1 when that has no more terms (1 − s² → c², 1 − 2s² → c² − s²), and the
//!    monomial that then divides it (c in c²θ̈ − scθ̇²) is taken out too.
//!
//! Written by hand: a computer-algebra factoring (multivariate, over Q, modulo s² + c² − 1) is
//! far more than the five errata need, and no crate fits the project's [`Poly`].

use super::poly::{exponent, mono_mul, Mono, Poly, Var, C, S};
use super::sym_print::{factor_ordered, factor_str, mono_str};
use super::{Coeff, Rational, Sym};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;

/// c · m · Π factors, each factor with two or more terms (printed in parentheses).
#[derive(Clone, Debug, PartialEq)]
pub struct Factored {
    /// The rational coefficient.
    pub coef: Rational,
    /// The monomial.
    pub mono: Mono,
    /// The factors (representatives modulo s² + c² = 1, possibly with c²).
    pub factors: Vec<Poly>,
}

impl Factored {
    /// The product, in normal form.
    pub fn expand(&self) -> Poly {
        let mut p = Poly::constant(self.coef.clone().into()).mul_term(&self.mono, &Coeff::one());
        for f in &self.factors {
            p = &p * f;
        }
        p
    }
    /// The factored form as text or LaTeX (`latex`): coefficient, monomial, factors.
    pub fn render(&self, latex: bool) -> String {
        let mut parts = Vec::new();
        let a = self.coef.abs();
        if !a.is_one() {
            parts.push(if a.is_integer() {
                a.numer().to_string()
            } else if latex {
                format!("\\frac{{{}}}{{{}}}", a.numer(), a.denom())
            } else {
                format!("{}/{}", a.numer(), a.denom())
            });
        }
        if !self.mono.is_empty() {
            parts.push(mono_str(&self.mono, latex));
        }
        // A lone factor needs no parentheses, unless a minus sign stands before it.
        let alone = parts.is_empty() && self.factors.len() == 1 && !self.coef.is_negative();
        for f in &self.factors {
            let body = factor_str(f, latex);
            parts.push(if alone {
                body
            } else if latex {
                format!("\\left({body}\\right)")
            } else {
                format!("({body})")
            });
        }
        let body = if parts.is_empty() {
            "1".to_string()
        } else {
            parts.join(" ")
        };
        if self.coef.is_negative() {
            format!("-{body}")
        } else {
            body
        }
    }
}

/// The value factored as text (an expanded [`super::text`] when it has a denominator).
pub fn factored_text(s: &Sym) -> String {
    match polynomial(s).and_then(|p| factor(&p)) {
        Some(f) => f.render(false),
        None => super::text(s),
    }
}

/// The value factored as LaTeX (an expanded [`super::latex`] when it has a denominator).
pub fn factored_latex(s: &Sym) -> String {
    match polynomial(s).and_then(|p| factor(&p)) {
        Some(f) => f.render(true),
        None => super::latex(s),
    }
}

fn polynomial(s: &Sym) -> Option<Poly> {
    (s.den.mono.is_empty() && s.den.factors.is_empty()).then(|| s.num.clone())
}

/// `p` factored, checked against `p` (None when the check fails or `p` is zero).
pub fn factor(p: &Poly) -> Option<Factored> {
    if p.is_zero() {
        return None;
    }
    let (coef, rest) = content(p);
    let mono = rest.mono_content();
    let mut out = Factored {
        coef,
        mono: mono.clone(),
        factors: Vec::new(),
    };
    for f in split(&rest.div_mono(&mono)) {
        let f = homogenised(&f);
        let m = f.mono_content();
        let f = f.div_mono(&m);
        out.mono = mono_mul(&out.mono, &m);
        let (q, f) = content(&f);
        out.coef *= q;
        if f.terms.len() > 1 {
            out.factors.push(f);
        } else if let Some((m, q)) = f.terms.iter().next() {
            out.mono = mono_mul(&out.mono, m);
            out.coef *= q.to_big();
        }
    }
    // Factors in s and c last (as the note writes m l² θ̇ (cos²θ − sin²θ)).
    out.factors
        .sort_by_key(|f| f.terms.keys().flatten().any(|&(v, _)| v == S || v == C));
    // A negative product reads better with one factor's sign turned (printed positive first).
    if out.coef.is_negative() {
        if let Some(f) = out.factors.first_mut() {
            *f = -&*f;
            out.coef = -out.coef.clone();
        }
    }
    (out.expand() == *p).then_some(out)
}

/// (rational content, p / content): integer coprime coefficients, the first term in a factor's
/// print order positive.
fn content(p: &Poly) -> (Rational, Poly) {
    let (mut g, mut l) = (BigInt::zero(), BigInt::one());
    for q in p.terms.values() {
        g = g.gcd(&q.numer());
        l = l.lcm(&q.denom());
    }
    if g.is_zero() {
        return (Rational::one(), p.clone());
    }
    let mut c = Rational::new(g.into(), l.into());
    if factor_ordered(p).first().is_some_and(|t| t.1.is_negative()) {
        c = -c;
    }
    (c.clone(), p.scale(&Coeff::from(Rational::one() / c)))
}

/// The variables of `p` in units that may be split apart (s and c together).
fn units(p: &Poly) -> Vec<Vec<Var>> {
    let mut vars: Vec<Var> = p.terms.keys().flatten().map(|&(v, _)| v).collect();
    vars.sort_unstable();
    vars.dedup();
    let mut out: Vec<Vec<Var>> = Vec::new();
    let trig: Vec<Var> = vars.iter().copied().filter(|&v| v == S || v == C).collect();
    if !trig.is_empty() {
        out.push(trig);
    }
    out.extend(
        vars.into_iter()
            .filter(|&v| v != S && v != C)
            .map(|v| vec![v]),
    );
    out
}

/// Split `p` into factors in disjoint sets of variables, smallest first.
fn split(p: &Poly) -> Vec<Poly> {
    let u = units(p);
    // A display of a few errata: more units than this is left whole.
    if u.len() < 2 || u.len() > 12 {
        return vec![p.clone()];
    }
    let rest = &u[1..];
    let mut subsets: Vec<u32> = (0..(1u32 << rest.len()) - 1).collect();
    subsets.sort_by_key(|m| m.count_ones());
    for mask in subsets {
        let mut group: Vec<Var> = u[0].clone();
        for (i, unit) in rest.iter().enumerate() {
            if mask & (1 << i) != 0 {
                group.extend(unit);
            }
        }
        if let Some((a, b)) = rank_one(p, &group) {
            let mut out = vec![a];
            out.extend(split(&b));
            return out;
        }
    }
    vec![p.clone()]
}

/// p = A(group) · B(rest) when the coefficient matrix has rank one.
fn rank_one(p: &Poly, group: &[Var]) -> Option<(Poly, Poly)> {
    let part = |m: &Mono, inside: bool| -> Mono {
        m.iter()
            .copied()
            .filter(|(v, _)| group.contains(v) == inside)
            .collect()
    };
    let mut matrix: BTreeMap<Mono, BTreeMap<Mono, Coeff>> = BTreeMap::new();
    for (m, q) in &p.terms {
        matrix
            .entry(part(m, true))
            .or_default()
            .insert(part(m, false), q.clone());
    }
    let (_, row0) = matrix.iter().next()?;
    let (y0, c0) = row0.iter().next()?;
    let zero = Coeff::zero();
    let cols: Vec<&Mono> = {
        let mut c: Vec<&Mono> = matrix.values().flat_map(|r| r.keys()).collect();
        c.sort();
        c.dedup();
        c
    };
    for row in matrix.values() {
        let r0 = row.get(y0).unwrap_or(&zero);
        for y in &cols {
            let top = row0.get(*y).unwrap_or(&zero);
            if row.get(*y).unwrap_or(&zero) * c0 != r0 * top {
                return None;
            }
        }
    }
    let a = Poly {
        terms: matrix
            .iter()
            .filter_map(|(x, row)| row.get(y0).map(|q| (x.clone(), q.clone())))
            .collect(),
    };
    let b = Poly {
        terms: row0.iter().map(|(y, q)| (y.clone(), q / c0)).collect(),
    };
    // Both factors have two terms or more: `p` has no monomial content (`factor` divides it out,
    // and a factor of a content-free polynomial has none), and each side holds variables of
    // `p`, so a one-term side would be a monomial dividing `p`.
    Some((a, b))
}

/// `p` homogenised in (s, c) with s² + c² = 1, when all its (s, c)-degrees have one parity and
/// the result has no more terms; else `p`.
fn homogenised(p: &Poly) -> Poly {
    let deg = |m: &Mono| exponent(m, S) + exponent(m, C);
    let degrees: Vec<u32> = p.terms.keys().map(deg).collect();
    let top = degrees.iter().copied().max().unwrap_or(0);
    if top == 0 || degrees.iter().any(|d| (top - d) % 2 != 0) {
        return p.clone();
    }
    let mut out: BTreeMap<Mono, Coeff> = BTreeMap::new();
    for (m, q) in &p.terms {
        // (s² + c²)^k, multiplied out without the rule c² → 1 − s².
        let k = (top - deg(m)) / 2;
        let mut binom = Coeff::one();
        for j in 0..=k {
            let mono = mono_mul(
                m,
                &[(S, 2 * (k - j)), (C, 2 * j)]
                    .into_iter()
                    .filter(|t| t.1 > 0)
                    .collect(),
            );
            let e = out.entry(mono).or_insert_with(Coeff::zero);
            *e += q * &binom;
            binom = binom * Coeff::int(i64::from(k - j)) / Coeff::int(i64::from(j + 1));
        }
    }
    out.retain(|_, q| !q.is_zero());
    let h = Poly { terms: out };
    if h.terms.len() <= p.terms.len() {
        h
    } else {
        p.clone()
    }
}
