//! Tests of `sliding_ladder::print::unicode` (src/print/unicode.rs).

use sliding_ladder::print::unicode::unicode;

#[test]
fn the_notes_vocabulary_reads() {
    assert_eq!(unicode(r"\frac{4ml^2\ddot{\theta}}{3}"), "4ml²θ̈/3");
    assert_eq!(
        unicode(r"\tau_D - F_{D,x}l\cos\theta"),
        "τ_D − F_D,x l cos θ"
    );
    assert_eq!(unicode(r"2F_f l \sin \theta"), "2F_f l sin θ");
    assert_eq!(unicode(r"\frac{dL_D}{dt}"), "dL_D/dt");
    assert_eq!(unicode(r"x_{\text{cm}} = l \sin \theta"), "x_cm = l sin θ");
    assert_eq!(
        unicode(r"\dot{\theta}^2 = \frac{3g}{2l} (1 - \cos \theta)"),
        "θ̇² = (3g/2l)(1 − cos θ)"
    );
    assert_eq!(unicode(r"\hat{\mathbf{z}}"), "z\u{302}");
    assert_eq!(
        unicode(r"2ml^2\cos^2\theta\ddot{\theta} + 2ml^2\cos\theta\sin\theta\dot{\theta}^2"),
        "2ml² cos² θ θ̈ + 2ml² cos θ sin θ θ̇²"
    );
    assert_eq!(unicode(r"\sum_i m_i \mathbf{x}_i"), "Σᵢmᵢxᵢ");
    assert_eq!(unicode(r"\frac{a + b}{c}"), "(a + b)/c");
    assert_eq!(
        unicode(r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + x"),
        "(ml²θ̇/3) z\u{302} + x"
    );
    assert_eq!(unicode(r"\frac{3g}{4l} \sin \theta"), "(3g/4l) sin θ");
    assert_eq!(unicode(r"-\frac{2ml^2 \dot{\theta}}{3}"), "−2ml²θ̇/3");
    // Every display of the note: tests/note/print/units.rs.
}

/// Every Greek letter the reader knows comes out as its Unicode letter: the lowercase ones
/// from U+03B1 (α) in alphabet order, the capitals from U+0391 (Α). An unknown command stays
/// as written.
#[test]
fn unicode_reads_each_greek_letter_as_its_code_point() {
    let lower = [
        ("alpha", 0x3B1),
        ("beta", 0x3B2),
        ("epsilon", 0x3B5),
        ("theta", 0x3B8),
        ("lambda", 0x3BB),
        ("mu", 0x3BC),
        ("pi", 0x3C0),
        ("rho", 0x3C1),
        ("sigma", 0x3C3),
        ("tau", 0x3C4),
        ("phi", 0x3C6),
        ("psi", 0x3C8),
        ("omega", 0x3C9),
    ];
    let upper = [("Gamma", 0x393), ("Delta", 0x394), ("Omega", 0x3A9)];
    for (name, code) in lower.into_iter().chain(upper) {
        let letter = char::from_u32(code).unwrap().to_string();
        assert_eq!(unicode(&format!("\\{name}")), letter, "\\{name}");
    }
    assert_eq!(unicode(r"\zeta"), r"\zeta");
}

/// Every digit, the minus sign and the index i come out as Unicode's superscript or subscript
/// character (U+2070… and U+2080…, with ¹ ² ³ and ᵢ where Unicode put them); a script with a
/// character Unicode has no script form of stays as `^…` or `_… `.
#[test]
fn script_writes_unicode_superscripts_and_subscripts() {
    let sup = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    for (d, s) in sup.iter().enumerate() {
        assert_eq!(unicode(&format!("x^{{{d}}}")), format!("x{s}"));
    }
    assert_eq!(unicode("x^{-1}"), "x⁻¹");
    assert_eq!(unicode("x^{−2}"), "x⁻²");
    for (d, s) in ['₀', '₁', '₂', '₃'].iter().enumerate() {
        assert_eq!(unicode(&format!("x_{{{d}}}")), format!("x{s}"));
    }
    assert_eq!(unicode("m_i"), "mᵢ");
    assert_eq!(unicode("m_{4} + 1"), "m_4 + 1");
    assert_eq!(unicode("x^{a}"), "x^a");
}

/// `\frac{d}{dt}` is the derivative, written d/dt before what it acts on; a fraction whose
/// numerator is d over anything else is an ordinary fraction.
#[test]
fn fraction_reads_d_over_dt_as_the_derivative_only() {
    assert_eq!(unicode(r"\frac{d}{dt}x"), "d/dt x");
    assert_eq!(unicode(r"\frac{d}{2}"), "d/2");
    assert_eq!(unicode(r"\frac{d}{l}"), "d/l");
}

/// A compound numerator is wrapped in parentheses unless one pair already encloses all of it:
/// 2(a + b) over c reads (2(a + b))/c, not 2(a + b)/c; (a + b)c and (a + b)(c + d) likewise;
/// (a + b) stays as is.
#[test]
fn wrap_parenthesises_a_compound_part_not_already_enclosed() {
    assert_eq!(unicode(r"\frac{2(a + b)}{c}"), "(2(a + b))/c");
    assert_eq!(unicode(r"\frac{(a + b)c}{d}"), "((a + b)c)/d");
    assert_eq!(unicode(r"\frac{(a + b)}{c}"), "(a + b)/c");
    // Two pairs side by side do not enclose the whole.
    assert_eq!(unicode(r"\frac{(a + b)(c + d)}{e}"), "((a + b)(c + d))/e");
}
