//! Printing a [`Sym`] as plain text (for the terminal) and as LaTeX (for the book and JSON).
//!
//! Terms are ordered by total degree, highest first, then by variable order (s, c, then the
//! order variables were created), so the same value always prints the same way. A denominator is
//! printed in its factored form (monomial times factors).

use super::poly::{var_names, Mono, Poly};
use super::{Coeff, Sym};
use num_traits::One;

/// A monomial as text or LaTeX: its variables with their powers (`s^2 c` / `s^{2} c`).
pub fn mono_str(m: &Mono, latex: bool) -> String {
    m.iter()
        .map(|&(v, e)| {
            let (t, l) = var_names(v);
            let name = if latex { l } else { t };
            match (e, latex) {
                (1, _) => name,
                (_, true) => format!("{name}^{{{e}}}"),
                (_, false) => format!("{name}^{e}"),
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn coef_str(q: &Coeff, latex: bool) -> String {
    if q.is_integer() {
        q.numer().to_string()
    } else if latex {
        format!("\\frac{{{}}}{{{}}}", q.numer(), q.denom())
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

pub(super) fn ordered(p: &Poly) -> Vec<(&Mono, &Coeff)> {
    let mut terms: Vec<_> = p.terms.iter().collect();
    let deg = |m: &Mono| m.iter().map(|x| x.1).sum::<u32>();
    terms.sort_by(|a, b| deg(b.0).cmp(&deg(a.0)).then_with(|| a.0.cmp(b.0)));
    terms
}

/// A polynomial as text or LaTeX.
pub fn poly_str(p: &Poly, latex: bool) -> String {
    terms_str(ordered(p), latex)
}

/// The terms of a factor in print order: by degree, c before s (c² − s², as the note writes
/// cos²θ − sin²θ), then as `ordered` sorts them.
pub fn factor_ordered(p: &Poly) -> Vec<(&Mono, &Coeff)> {
    let mut terms = ordered(p);
    let deg = |m: &Mono| m.iter().map(|x| x.1).sum::<u32>();
    let c = |m: &Mono| super::poly::exponent(m, super::poly::C);
    terms.sort_by(|a, b| deg(b.0).cmp(&deg(a.0)).then_with(|| c(b.0).cmp(&c(a.0))));
    terms
}

/// [`poly_str`] of a factor: [`factor_ordered`], positive terms first (a factor whose sign was
/// turned reads `c θ̈ − s θ̇²`, not `−s θ̇² + c θ̈`).
pub fn factor_str(p: &Poly, latex: bool) -> String {
    let mut terms = factor_ordered(p);
    terms.sort_by_key(|t| t.1.is_negative());
    terms_str(terms, latex)
}

fn terms_str(terms: Vec<(&Mono, &Coeff)>, latex: bool) -> String {
    if terms.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    for (i, (m, q)) in terms.into_iter().enumerate() {
        let neg = q.is_negative();
        let a = q.abs();
        if i == 0 {
            if neg {
                out.push('-');
            }
        } else {
            out.push_str(if neg { " - " } else { " + " });
        }
        let ms = mono_str(m, latex);
        match (a.is_one(), ms.is_empty()) {
            (true, true) => out.push('1'),
            (true, false) => out.push_str(&ms),
            (false, true) => out.push_str(&coef_str(&a, latex)),
            (false, false) => {
                out.push_str(&coef_str(&a, latex));
                out.push(' ');
                out.push_str(&ms);
            }
        }
    }
    out
}

fn den_str(s: &Sym, latex: bool) -> Option<String> {
    let mut parts = Vec::new();
    if !s.den.mono.is_empty() {
        parts.push(mono_str(&s.den.mono, latex));
    }
    for (f, k) in &s.den.factors {
        let body = poly_str(f, latex);
        let (open, close) = if latex {
            ("\\left(", "\\right)")
        } else {
            ("(", ")")
        };
        parts.push(match (k, latex) {
            (1, _) => format!("{open}{body}{close}"),
            (_, true) => format!("{open}{body}{close}^{{{k}}}"),
            (_, false) => format!("({body})^{k}"),
        });
    }
    (!parts.is_empty()).then(|| parts.join(" "))
}

/// The value as plain text, e.g. `-3/4 g l m s θ̇^2` or `(x_1 - x_P)/(m_1 + m_2)`.
pub fn text(s: &Sym) -> String {
    let num = poly_str(&s.num, false);
    match den_str(s, false) {
        None => num,
        Some(d) => {
            let n = if s.num.terms.len() > 1 {
                format!("({num})")
            } else {
                num
            };
            format!("{n} / ({d})")
        }
    }
}

/// The value as LaTeX, e.g. `-\frac{3}{4} g l m s \dot\theta^{2}`.
pub fn latex(s: &Sym) -> String {
    let num = poly_str(&s.num, true);
    match den_str(s, true) {
        None => num,
        Some(d) => format!("\\frac{{{num}}}{{{d}}}"),
    }
}
