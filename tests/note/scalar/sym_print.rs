//! Tests of `sliding_ladder::scalar::sym_print` (src/scalar/sym_print.rs).

use sliding_ladder::scalar::sym_print::{latex, text};
use sliding_ladder::scalar::Scalar;
use sliding_ladder::scalar::Sym;

#[test]
fn prints_text_and_latex() {
    let m = Sym::var("m", "m");
    let rate = Sym::var("θ̇", "\\dot\\theta");
    let v = -Sym::ratio(3, 4) * m.clone() * Sym::sin() * rate.clone() * rate.clone();
    assert_eq!(text(&v), "-3/4 s m θ̇^2");
    assert_eq!(latex(&v), "-\\frac{3}{4} s m \\dot\\theta^{2}");
    let l = Sym::var("l", "l");
    let q = (Sym::cos() - Sym::int(1)) / (l.clone() * (m.clone() + l));
    assert_eq!(text(&q), "(c - 1) / (l (m + l))");
    assert_eq!(text(&Sym::int(0)), "0");
}
