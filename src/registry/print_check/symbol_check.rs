//! The symbol check of a display's print (issue 37, item 3): run by [`super::check_print`],
//! beside the values, because on the ladder the values cannot tell some points' symbols apart
//! ([`super::twins`]).

use super::Form;
use crate::registry::Equation;

/// The symbol check (issue 37): the display's symbols in our notation (Milne's are his) against
/// the points its section prints ([`crate::print::own_point`]).
pub fn own_points(e: &Equation, chains: &[Vec<Form>]) -> Vec<String> {
    let mut keys = Vec::new();
    for f in chains.iter().flatten().filter(|f| !f.milne) {
        crate::print::own_point::symbol_keys(&f.expr, &mut keys);
    }
    crate::print::symbols::point_rules().check(e.section, e.number, &keys)
}
