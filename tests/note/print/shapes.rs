//! `print_chains` on display shapes the note does not print, generated: up to three statements
//! of ours, each a chain of 2 to 30 forms, then `\text{Milne : }` and up to as many of Milne's,
//! each restating ours in order. The chains must be exactly what the generator wrote: one chain
//! per statement of ours, Milne's k-th joined to our k-th, every form in print order and counted
//! once. (The note's displays have at most one Milne statement and 8 forms; an extender's need
//! not, and mutation shards found the grouping and the labels untested there.)

use proptest::prelude::*;
use sliding_ladder::registry::print_check::print_chains;

/// A shape: the form counts of our statements, and of Milne's (no more of his than ours).
fn shape() -> impl Strategy<Value = (Vec<usize>, Vec<usize>)> {
    prop::collection::vec(2usize..=30, 1..=3).prop_flat_map(|ours| {
        let k = ours.len();
        (Just(ours), prop::collection::vec(1usize..=30, 0..=k))
    })
}

/// The LaTeX of a shape: form j of our statement i is `a_{i j}`, of Milne's statement i
/// `b_{i j}`, so every form names where it was written.
fn latex(ours: &[usize], milne: &[usize]) -> String {
    let chain = |letter: char, i: usize, n: usize| {
        (0..n)
            .map(|j| format!("{letter}_{{{i} {j}}}"))
            .collect::<Vec<_>>()
            .join(" = ")
    };
    let s: Vec<String> = ours
        .iter()
        .enumerate()
        .map(|(i, &n)| chain('a', i, n))
        .collect();
    let theirs: Vec<String> = milne
        .iter()
        .enumerate()
        .map(|(i, &n)| chain('b', i, n))
        .collect();
    let mut out = s.join(r", \quad ");
    if !theirs.is_empty() {
        out.push_str(r", \quad \text{Milne : } ");
        out.push_str(&theirs.join(r", \quad "));
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(64)))]

    #[test]
    fn print_chains_groups_every_generated_shape_as_written((ours, milne) in shape()) {
        let src = latex(&ours, &milne);
        let (count, chains) = print_chains(64, &src).map_err(|e| TestCaseError::fail(format!("{src}: {e}")))?;
        prop_assert_eq!(count, ours.iter().sum::<usize>() + milne.iter().sum::<usize>(), "{}", src);
        prop_assert_eq!(chains.len(), ours.len(), "{}", src);
        for (i, chain) in chains.iter().enumerate() {
            let mut want: Vec<String> = (0..ours[i]).map(|j| format!("a_{{{i} {j}}}")).collect();
            if let Some(&n) = milne.get(i) {
                want.extend((0..n).map(|j| format!("b_{{{i} {j}}}")));
            }
            let got: Vec<String> = chain.iter().map(|f| f.text.replace(' ', "")).collect();
            let want: Vec<String> = want.iter().map(|t| t.replace(' ', "")).collect();
            prop_assert_eq!(got, want, "{}", src);
        }
    }
}
