//! Tests of `sliding_ladder::show::values` (src/show/values.rs).

use sliding_ladder::show::values::form_values_of;
use sliding_ladder::show::{at::parse_at, state::build};

/// (25) with its last form perturbed in the 13th digit, and with 4 for 5 in its second form:
/// both fail in f64 (the running bound is far tighter) and exactly; the print as printed
/// agrees.
#[test]
fn a_perturbed_form_fails_the_agreement() {
    let e = sliding_ladder::registry::equations()
        .into_iter()
        .find(|e| e.number == 25)
        .unwrap();
    let point = build(&parse_at("m=2, l=3/4, g=10, sin_theta=3/5").unwrap());
    let last = r"&= mgl\sin\theta, \end{aligned}";
    let tiny = r"&= \frac{10000000000001mgl\sin\theta}{10000000000000}, \end{aligned}";
    let agree = |latex: &str| -> Vec<(bool, bool)> {
        form_values_of(&e, latex, &point)
            .unwrap()
            .iter()
            .skip(1)
            .map(|f| (f.agrees.unwrap(), f.exact_agrees.unwrap()))
            .collect()
    };
    assert!(agree(e.latex()).iter().all(|&(a, x)| a && x));
    assert!(e.latex().contains(last));
    let nudged = agree(&e.latex().replace(last, tiny));
    assert_eq!(nudged.last(), Some(&(false, false)));
    assert!(nudged[..nudged.len() - 1].iter().all(|&(a, x)| a && x));
    let four = agree(&e.latex().replacen(r"\frac{4ml^2", r"\frac{5ml^2", 1));
    assert_eq!(four[0], (false, false));
}
