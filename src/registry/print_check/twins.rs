//! Symbols a display's states cannot tell apart: a printed symbol and another of its section
//! that take the same value at every state the print is checked at (its premises imposed). On the
//! ladder several distinct quantities are equal at every state (I_A = I_C = I_D = I_E; x_P is
//! x_C in A.1, where the note puts P at C), so writing one for the other changes what the note
//! says and no value can see it; `ladder show` lists such pairs so a reader knows where the
//! print check is blind.
//!
//! Two exact points (rationals, fixed seed) decide: distinct rational functions of the draw agree
//! at a random point with probability at most degree/2⁶⁰ (Schwartz-Zippel), so a pair listed is
//! equal on the model, not by chance. A symbol that is zero there is left out (every zero is
//! "equal" to every other).
//!
//! Where the values are blind, the symbols are not: [`super::symbol_check`] holds each display to the
//! points its section prints ([`crate::print::own_point`]), so a swap to another point's symbol
//! (I_C → I_A in sec. 2.4) fails the display even though every value is unchanged.

use super::{print_chains, print_sample, PrintSample};
use crate::print::ast::Expr;
use crate::print::eval::{evaluate, Ctx};
use crate::print::quantity::Model;
use crate::print::symbols::{lookup, Entry};
use crate::registry::sample::{exact_ladder, particle_system};
use crate::registry::Equation;
use crate::scalar::Rational;
use num_traits::Zero;
use rand::SeedableRng;
use std::collections::HashMap;

/// A printed symbol and another symbol of its section that no state of the display tells apart.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Twin {
    /// The printed symbol (canonical LaTeX).
    pub printed: String,
    /// The symbol equal to it at every state.
    pub other: String,
    /// Their quantities (different ids).
    pub quantities: (String, String),
}

/// A symbol's components at each exact state (`None`: it does not evaluate, or is zero there).
type Values = Option<Vec<Vec<Rational>>>;

/// The pairs of symbols the display's states cannot tell apart.
pub fn indistinguishable(e: &Equation) -> Vec<Twin> {
    let (Ok((_, chains)), Some(sample)) = (print_chains(e.number, e.latex()), print_sample(e))
    else {
        return Vec::new();
    };
    let mut keys: Vec<(String, bool)> = Vec::new();
    for f in chains.iter().flatten() {
        symbols(&f.expr, f.milne, &mut keys);
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(37 ^ u64::from(e.number));
    let models: Vec<std::rc::Rc<Model<Rational>>> = (0..2)
        .filter_map(|_| model(e, sample, &mut rng))
        .map(std::rc::Rc::new)
        .collect();
    let mut values = SymbolValues {
        e,
        models,
        table: crate::registry::symbol_table(),
        memo: HashMap::new(),
    };
    let mut out: Vec<Twin> = Vec::new();
    for (key, milne) in &keys {
        let Some(mine) = lookup(values.table, key, e.section, e.number, *milne) else {
            continue;
        };
        let Some(v) = values.of(key, *milne) else {
            continue;
        };
        twins_of(key, *milne, mine, &v, &mut values, &mut out);
    }
    out
}

/// Each symbol's values at the display's exact states, computed once: the pair loop asks for
/// a table entry's values once per printed symbol, and a value at an exact point costs
/// big-integer gcds.
struct SymbolValues<'a> {
    e: &'a Equation,
    models: Vec<std::rc::Rc<Model<Rational>>>,
    table: &'static [Entry],
    memo: HashMap<(String, bool), Values>,
}

impl SymbolValues<'_> {
    /// The components of symbol `key` at each state (`None`: it does not evaluate, or is zero
    /// at every state).
    fn of(&mut self, key: &str, milne: bool) -> Values {
        if let Some(v) = self.memo.get(&(key.to_string(), milne)) {
            return v.clone();
        }
        let vals: Option<Vec<Vec<Rational>>> = self
            .models
            .iter()
            .map(|m| {
                let ctx = Ctx {
                    model: m.clone(),
                    section: self.e.section,
                    number: self.e.number,
                    milne,
                    index: None,
                    table: self.table,
                };
                evaluate(&Expr::Sym(key.to_string()), &ctx)
                    .ok()
                    .map(|v| v.components())
            })
            .collect();
        let vals = vals.filter(|v| v.iter().flatten().any(|x| !x.is_zero()));
        self.memo.insert((key.to_string(), milne), vals.clone());
        vals
    }
}

/// The twins of printed symbol `key` (table entry `mine`, values `v`): every other entry of its
/// section and notation with the same values, each pair listed once.
fn twins_of(
    key: &str,
    milne: bool,
    mine: &Entry,
    v: &[Vec<Rational>],
    values: &mut SymbolValues,
    out: &mut Vec<Twin>,
) {
    let (table, section, number) = (values.table, values.e.section, values.e.number);
    for other in table.iter().filter(|t| t.milne == milne && t.key != key) {
        let Some(theirs) = lookup(table, &other.key, section, number, milne) else {
            continue;
        };
        // Per-particle quantities mean particle 1 outside a Σ: no twin of anything.
        let per_particle = |q: &str| q.starts_with("particle_");
        // The same quantity under another name (x_P for x_C in A.1, where P is C) is a
        // twin too; the entry itself under its own key is not.
        // One quantity printed plain and bold (sec. 2's v_cm, whose square is the speed
        // squared, and the vector v_cm) is one notation of one thing, not a twin.
        let same_in_bold = theirs.quantity == mine.quantity && unbold(key) == unbold(&other.key);
        if theirs.key != other.key
            || same_in_bold
            || per_particle(&theirs.quantity)
            || per_particle(&mine.quantity)
            || out.iter().any(|t| t.printed == other.key && t.other == key)
        {
            continue;
        }
        if values.of(&other.key, milne).as_deref() == Some(v) {
            let twin = Twin {
                printed: key.to_string(),
                other: other.key.clone(),
                quantities: (mine.quantity.clone(), theirs.quantity.clone()),
            };
            if !out.contains(&twin) {
                out.push(twin);
            }
        }
    }
}

/// A symbol's LaTeX with every `\mathbf{…}` replaced by its argument: `\mathbf{v}_{\text{cm}}`
/// reads `v_{\text{cm}}`.
pub fn unbold(latex: &str) -> String {
    let mut out = String::new();
    let mut rest = latex;
    // Depths at which a `\mathbf{` opened: its closing brace is dropped.
    let mut open: Vec<usize> = Vec::new();
    let mut depth = 0usize;
    while let Some(c) = rest.chars().next() {
        if let Some(after) = rest.strip_prefix("\\mathbf{") {
            depth += 1;
            open.push(depth);
            rest = after;
            continue;
        }
        match c {
            '{' => depth += 1,
            '}' => {
                if open.last() == Some(&depth) {
                    open.pop();
                    depth -= 1;
                    rest = &rest[1..];
                    continue;
                }
                depth = depth.saturating_sub(1);
            }
            _ => {}
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// One exact state of the display's print, its premises imposed.
fn model(
    e: &Equation,
    sample: PrintSample,
    rng: &mut rand_chacha::ChaCha8Rng,
) -> Option<Model<Rational>> {
    match sample {
        PrintSample::Ladder(sort) => {
            let (l, s) = exact_ladder(sort, crate::registry::check::exact_ladder_draw(rng));
            Some(Model::ladder(l, s))
        }
        PrintSample::Particles(sort) => {
            let (n, values) = crate::registry::check::exact_particle_draw(rng);
            let (sys, p) = particle_system(sort, n, &values);
            super::premises::premised(e, sys, p).ok()
        }
    }
}

/// Every symbol of a form, with whether it is Milne's.
fn symbols(e: &Expr, milne: bool, out: &mut Vec<(String, bool)>) {
    use Expr::*;
    match e {
        Sym(k) => {
            if !out.iter().any(|(x, m)| x == k && *m == milne) {
                out.push((k.clone(), milne));
            }
        }
        At(a, conds) => {
            symbols(a, milne, out);
            conds.iter().for_each(|c| symbols(c, milne, out));
        }
        Neg(a) | Pow(a, _) | Sin(a) | Cos(a) | Sum(a) | Deriv(a) | Partial(a, _) | ZComp(a) => {
            symbols(a, milne, out)
        }
        Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
            symbols(a, milne, out);
            symbols(b, milne, out);
        }
        Tuple(v) => v.iter().for_each(|x| symbols(x, milne, out)),
        Int(_) | Const => {}
    }
}
