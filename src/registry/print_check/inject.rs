//! Typos injected into the print, one at a time, to show the print check catches them.
//!
//! A typo is made on the display's tokens: a numeric coefficient changed (n → n + 1; not a power
//! or an index), a sign flipped (+ ↔ −), sin and cos swapped, or a factor m, l or g dropped. The
//! display is then checked as [`super::check_print`] checks the shipped print. A typo that changes
//! no form's value (a term that cancels identically, or a sign inside a zero) is *neutral*: every
//! form of the edited display equals the same form of the original at an exact random point.

use super::{check_print, evaluate_chains, print_chains};
use crate::print::lexer::{lex, Tok};
use crate::print::parser::render;
use crate::print::quantity::Model;
use crate::registry::check::Config;
use crate::registry::sample::{exact_ladder, particle_system};
use crate::registry::{Equation, Eval};
use crate::scalar::Rational;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The sort of typo.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Typo {
    /// A numeric coefficient n → n + 1.
    Coefficient,
    /// + ↔ −.
    Sign,
    /// sin ↔ cos.
    SinCos,
    /// A factor m, l or g dropped.
    DropFactor,
}

/// One typo in one display.
#[derive(Clone, Debug)]
pub struct Injection {
    /// The display.
    pub number: u32,
    /// The sort of typo.
    pub typo: Typo,
    /// The edited LaTeX.
    pub latex: String,
}

/// What the check made of a typo.
#[derive(Clone, Debug, PartialEq)]
pub enum Detection {
    /// Flagged: the first problem reported (form and residual).
    Caught(String),
    /// No form's value changed: nothing to catch.
    Neutral,
    /// The check passed although a form changed.
    Missed,
}

/// Every typo of the four sorts in a display's print.
pub fn injections(number: u32, latex: &str) -> Vec<Injection> {
    let Ok(toks) = lex(latex) else {
        return Vec::new();
    };
    // Letters inside `\text{…}` (Milne's label, `cm`) are words, not factors.
    let mut in_text = vec![false; toks.len()];
    let (mut depth, mut opening) = (0usize, false);
    for (i, t) in toks.iter().enumerate() {
        if opening || depth > 0 {
            in_text[i] = true;
            match t {
                Tok::Punct('{') => depth += 1,
                Tok::Punct('}') => depth = depth.saturating_sub(1),
                _ => {}
            }
            opening = false;
        } else if matches!(t, Tok::Cmd(w) if w == "text") {
            in_text[i] = true;
            opening = true;
        }
    }
    let mut out = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        if in_text[i] {
            continue;
        }
        let prev = i.checked_sub(1).map(|j| &toks[j]);
        let next = toks.get(i + 1);
        let in_index = matches!(prev, Some(Tok::Punct('_' | '^')));
        let edit = match t {
            Tok::Int(n) if !in_index => Some((Typo::Coefficient, vec![Tok::Int(n + 1)])),
            Tok::Punct('+') => Some((Typo::Sign, vec![Tok::Punct('-')])),
            Tok::Punct('-') => Some((Typo::Sign, vec![Tok::Punct('+')])),
            Tok::Cmd(w) if w == "sin" => Some((Typo::SinCos, vec![Tok::Cmd("cos".into())])),
            Tok::Cmd(w) if w == "cos" => Some((Typo::SinCos, vec![Tok::Cmd("sin".into())])),
            Tok::Letter('m' | 'l' | 'g')
                if !in_index && !matches!(next, Some(Tok::Punct('_' | '^'))) =>
            {
                // Only inside a product: a neighbour that is a factor too.
                let factor = |t: Option<&Tok>| {
                    matches!(t, Some(Tok::Letter(_) | Tok::Int(_) | Tok::Punct(')')))
                        || matches!(t, Some(Tok::Cmd(w)) if !matches!(w.as_str(), "times" | "wedge" | "equiv" | "Rightarrow"))
                };
                (factor(prev) || factor(next)).then(|| (Typo::DropFactor, vec![]))
            }
            _ => None,
        };
        if let Some((typo, with)) = edit {
            let mut edited = toks[..i].to_vec();
            edited.extend(with);
            edited.extend_from_slice(&toks[i + 1..]);
            out.push(Injection {
                number,
                typo,
                latex: render(&edited),
            });
        }
    }
    out
}

/// Check one typo.
pub fn run_injection(e: &Equation, inj: &Injection, cfg: &Config) -> Detection {
    let rep = check_print(e, &inj.latex, cfg);
    // The same three verdicts `verify::judge_print` fails a display on: a chain that breaks, a
    // form that no longer parses, and a Rust form that equals no printed form (the only witness
    // when the typo hits the one printed side of an erratum's chain).
    let code = rep
        .code_mismatches
        .first()
        .map(|c| format!("print vs code: {c}"));
    if let Some(p) = rep
        .problems
        .first()
        .or(rep.unparsed.first())
        .cloned()
        .or(code)
    {
        return Detection::Caught(p);
    }
    if same_values(e, &inj.latex) {
        Detection::Neutral
    } else {
        Detection::Missed
    }
}

/// True when every form of the edited display equals the original's at an exact random point.
fn same_values(e: &Equation, edited: &str) -> bool {
    let (Ok((_, a)), Ok((_, b))) = (
        print_chains(e.number, e.latex()),
        print_chains(e.number, edited),
    ) else {
        return false;
    };
    let Some(check) = e.checks.first() else {
        return false;
    };
    let rng = ChaCha8Rng::seed_from_u64(u64::from(e.number) ^ 0x5eed);
    let eval = |chains| -> Option<Vec<Rational>> {
        let ch = match check.eval {
            Eval::Ladder(sort, _) => {
                let mut r = rng.clone();
                let (l, s) = exact_ladder(sort, crate::registry::check::exact_ladder_draw(&mut r));
                evaluate_chains(e, chains, Model::ladder(l, s), None)
            }
            Eval::Particles(sort, _) => {
                let mut r = rng.clone();
                let (n, v) = crate::registry::check::exact_particle_draw(&mut r);
                let (sys, p) = particle_system(sort, n, &v);
                evaluate_chains(e, chains, Model::particles(sys, p), None)
            }
            Eval::Floor(..) => return None,
        };
        ch.ok()
            .map(|c| c.into_iter().flatten().map(|s| s.value).collect())
    };
    let (va, vb) = (eval(&a), eval(&b));
    matches!((va, vb), (Some(x), Some(y)) if x == y)
}
