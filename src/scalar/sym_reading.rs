//! A misprint read in physical terms, from printed − corrected factored ([`super::sym_factor`]):
//! a lost mass reads "the printed term l²θ̇ (c² − s²) lacks a factor m", not
//! "l²θ̇ (1 − m)(c² − s²)", which subtracts a mass from a pure number; a rate put for an
//! acceleration reads "has θ̇² where θ̈ belongs". Two readings, each an exact rewriting of the
//! difference (D = X (1 − f) = X − f X; D = K (u − v) = K u − K v), so neither can misstate it:
//!
//! * a factor of D is c₀ + q M with M a monomial of the model's parameters (m, l, g, a particle's
//!   mᵢ): then D = X (1 − f) with f = −(q / c₀) M, and the printed term X lacks the factor f;
//! * a factor of D is u − v with u, v monomials that differ only in the rates θ̇, θ̈, θ⃛: the
//!   printed form has u where v belongs, in the term K v of the corrected form.

use super::poly::{var_names, Mono, Var};
use super::sym_factor::{factor, Factored};
use super::sym_print::mono_str;
use super::{Coeff, Rational, Sym};
use num_traits::Zero;

/// How printed − corrected reads.
#[derive(Clone, Debug, PartialEq)]
pub enum Reading {
    /// printed − corrected = X (1 − f): the printed term X lacks the factor f.
    MissingFactor {
        /// X, the term as printed.
        term: Factored,
        /// f, the lost factor.
        factor: Factored,
    },
    /// printed − corrected = K (u − v): the printed form has u where v belongs.
    Swapped {
        /// u, as printed.
        has: Mono,
        /// v, as it should be.
        belongs: Mono,
        /// K v, the term of the corrected form.
        term: Factored,
    },
}

impl Reading {
    /// The reading as a phrase; with `latex`, each formula as `$…$` (markdown math).
    pub fn render(&self, latex: bool) -> String {
        let m = |s: String| if latex { format!("${s}$") } else { s };
        match self {
            Reading::MissingFactor { term, factor } => format!(
                "the printed term {} lacks a factor {}",
                m(term.render(latex)),
                m(factor.render(latex))
            ),
            Reading::Swapped { has, belongs, term } => format!(
                "the printed form has {} where {} belongs (the term {} of the corrected form)",
                m(mono_str(has, latex)),
                m(mono_str(belongs, latex)),
                m(term.render(latex))
            ),
        }
    }
    /// The term the reading names (as printed for a lost factor, as corrected for a swap).
    pub fn term(&self, latex: bool) -> String {
        match self {
            Reading::MissingFactor { term, .. } | Reading::Swapped { term, .. } => {
                term.render(latex)
            }
        }
    }
    /// The lost factor or the (printed, right) pair: what every component of a vector must
    /// share; with `latex`, each formula as `$…$`.
    pub fn kind(&self, latex: bool) -> String {
        let m = |s: String| if latex { format!("${s}$") } else { s };
        match self {
            Reading::MissingFactor { factor, .. } => {
                format!("a factor {}", m(factor.render(latex)))
            }
            Reading::Swapped { has, belongs, .. } => format!(
                "{} where {} belongs",
                m(mono_str(has, latex)),
                m(mono_str(belongs, latex))
            ),
        }
    }
}

fn name(v: Var) -> String {
    var_names(v).0
}

/// A parameter of the model: the ladder's m, l, g or a particle's mass mᵢ.
fn is_parameter(v: Var) -> bool {
    let n = name(v);
    matches!(n.as_str(), "m" | "l" | "g") || n.starts_with("m_")
}

fn is_rate(v: Var) -> bool {
    matches!(name(v).as_str(), "θ̇" | "θ̈" | "θ⃛")
}

fn without_rates(m: &Mono) -> Mono {
    m.iter().copied().filter(|&(v, _)| !is_rate(v)).collect()
}

/// `d` (printed − corrected) read in physical terms, when one of the two readings applies.
pub fn reading(d: &Sym) -> Option<Reading> {
    if !(d.den.mono.is_empty() && d.den.factors.is_empty()) {
        return None;
    }
    let f = factor(&d.num)?;
    let others = |k: usize| -> Vec<_> {
        let mut v = f.factors.clone();
        v.remove(k);
        v
    };
    for (k, p) in f.factors.iter().enumerate() {
        let terms: Vec<(&Mono, &Coeff)> = p.terms.iter().collect();
        let [a, b] = terms[..] else { continue };
        // c₀ + q M, M a monomial of parameters: D = X (1 − f).
        let (constant, other) = match (a.0.is_empty(), b.0.is_empty()) {
            (true, false) => (a, b),
            (false, true) => (b, a),
            _ => (a, a),
        };
        if constant.0.is_empty() && other.0.iter().all(|&(v, _)| is_parameter(v)) {
            let c0 = constant.1.to_big();
            let q = other.1.to_big();
            return Some(Reading::MissingFactor {
                term: Factored {
                    coef: f.coef.clone() * c0.clone(),
                    mono: f.mono.clone(),
                    factors: others(k),
                },
                factor: Factored {
                    coef: -(q / c0),
                    mono: other.0.clone(),
                    factors: Vec::new(),
                },
            });
        }
        // u − v, u and v differing in the rates only: D = K u − K v.
        let (qa, qb) = (a.1.to_big(), b.1.to_big());
        let has_rate = |m: &Mono| m.iter().any(|&(v, _)| is_rate(v));
        if (qa.clone() + qb).is_zero()
            && has_rate(a.0)
            && has_rate(b.0)
            && without_rates(a.0) == without_rates(b.0)
        {
            // coef·qa·(a − b) = coef·|qa|·(u − v), u the term with the positive coefficient.
            let (has, belongs) = if qa > Rational::zero() {
                (a.0, b.0)
            } else {
                (b.0, a.0)
            };
            return Some(Reading::Swapped {
                has: has.clone(),
                belongs: belongs.clone(),
                term: Factored {
                    coef: f.coef.clone() * num_traits::Signed::abs(&qa),
                    mono: super::poly::mono_mul(&f.mono, belongs),
                    factors: others(k),
                },
            });
        }
    }
    None
}
