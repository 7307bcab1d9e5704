//! Each erratum's symbolic difference printed − corrected (`ladder errata`, `difference_latex`)
//! against a difference written by hand from the note's printed and corrected forms.

use sliding_ladder::registry::equations;
use sliding_ladder::registry::prove::erratum_difference;
use sliding_ladder::scalar::{latex, Scalar, Sym};
use sliding_ladder::verify::errata::errata;

fn var(text: &str, tex: &str) -> Sym {
    Sym::var(text, tex)
}

/// The expected differences, from the note by hand (θ, θ̇, θ̈ free; (68) for one particle).
fn expected(number: u32) -> Vec<Sym> {
    let (s, c) = (Sym::sin(), Sym::cos());
    let (m, l) = (var("m", "m"), var("l", "l"));
    let rate = var("θ̇", "\\dot\\theta");
    let accel = var("θ̈", "\\ddot\\theta");
    let one = Sym::int(1);
    let sq = |x: &Sym| x.clone() * x.clone();
    match number {
        // (28) drops F_E,x l cos θ, with F_E,x = −2m ẍ_cm and x_cm = l sin θ (FIGURE.md), so
        // printed − corrected = −F_E,x l cos θ = 2ml² cos θ (cos θ θ̈ − sin θ θ̇²).
        28 => vec![Sym::int(2) * m * sq(&l) * c.clone() * (c * accel - s * sq(&rate))],
        // (49): l²θ̇(cos²θ − sin²θ) printed where m l²θ̇(cos²θ − sin²θ) belongs.
        49 => vec![(one - m) * sq(&l) * rate * (sq(&c) - sq(&s))],
        // (54): θ̇² printed for θ̈ in 4ml²θ̈/3.
        54 => vec![Sym::ratio(4, 3) * m * sq(&l) * (sq(&rate) - accel)],
        // (62): ml where 2ml² belongs, on the θ̈ and θ̇² terms.
        62 => vec![m * l.clone() * (Sym::int(2) * l - one) * (sq(&s) * accel + c * s * sq(&rate))],
        // (68): Σ r ∧ r̈ − Σ r ∧ m r̈ = (1 − m₁) r₁ × r̈₁ for one particle.
        68 => {
            let m1 = var("m_1", "m_{1}");
            let x = [
                var("x_1", "x_{1}"),
                var("y_1", "y_{1}"),
                var("z_1", "z_{1}"),
            ];
            let a = [
                var("ax_1", "a_{x,1}"),
                var("ay_1", "a_{y,1}"),
                var("az_1", "a_{z,1}"),
            ];
            let k = one - m1;
            (0..3)
                .map(|i| {
                    let (j, h) = ((i + 1) % 3, (i + 2) % 3);
                    k.clone() * (x[j].clone() * a[h].clone() - x[h].clone() * a[j].clone())
                })
                .collect()
        }
        n => panic!("no expected difference written for ({n})"),
    }
}

/// The same differences as they should print, factored, written by hand as LaTeX (the ladder's
/// variables s = sin θ, c = cos θ, m, l, θ̇, θ̈; (68) per component of particle 1).
fn expected_latex(number: u32) -> &'static str {
    match number {
        28 => r"2 c m l^{2} \left(c \ddot\theta - s \dot\theta^{2}\right)",
        49 => r"l^{2} \dot\theta \left(1 - m\right) \left(c^{2} - s^{2}\right)",
        54 => r"\frac{4}{3} m l^{2} \left(\dot\theta^{2} - \ddot\theta\right)",
        62 => r"s m l \left(2 l - 1\right) \left(c \dot\theta^{2} + s \ddot\theta\right)",
        68 => concat!(
            // (1 − m₁) r₁ × a₁; the y component reads (m₁ − 1)(x a_z − z a_x), the same thing.
            r"\left(\left(1 - m_{1}\right) \left(y_{1} a_{z,1} - z_{1} a_{y,1}\right),\ ",
            r"\left(m_{1} - 1\right) \left(x_{1} a_{z,1} - z_{1} a_{x,1}\right),\ ",
            r"\left(1 - m_{1}\right) \left(x_{1} a_{y,1} - y_{1} a_{x,1}\right)\right)"
        ),
        n => panic!("no expected LaTeX written for ({n})"),
    }
}

#[test]
fn each_erratum_difference_matches_the_hand_written_one() {
    let reports = errata(&Default::default());
    assert_eq!(reports.len(), 5);
    for e in equations().into_iter().filter(|e| e.erratum.is_some()) {
        let got = e
            .checks
            .iter()
            .map(erratum_difference)
            .find(|d| !d.is_empty())
            .expect("a misprint with its correction");
        let want = expected(e.number);
        assert_eq!(got.len(), want.len(), "({})", e.number);
        for (g, w) in got.iter().zip(&want) {
            assert!(
                !w.is_zero(),
                "({}) an erratum's difference is nonzero",
                e.number
            );
            assert_eq!(g, w, "({}) got {}", e.number, latex(g));
        }
        let report = reports
            .iter()
            .find(|r| r.number == e.number)
            .expect("reported");
        assert_eq!(
            report.difference_latex,
            expected_latex(e.number),
            "({})",
            e.number
        );
    }
}

#[test]
fn a_wrong_expected_difference_is_caught() {
    // The comparison can fail: (54) with the sign of the θ̈ term flipped is not the difference.
    let e54 = equations()
        .into_iter()
        .find(|e| e.number == 54)
        .expect("(54)");
    let got = erratum_difference(&e54.checks[0]);
    let (m, l) = (var("m", "m"), var("l", "l"));
    let rate = var("θ̇", "\\dot\\theta");
    let accel = var("θ̈", "\\ddot\\theta");
    let wrong = Sym::ratio(4, 3) * m * l.clone() * l * (rate.clone() * rate + accel);
    assert_ne!(got[0], wrong);
}

#[test]
fn the_prose_erratum_of_a5_has_its_difference() {
    // −(2/3) m l θ̇ printed where −(2/3) m l² θ̇ belongs: the difference is (2/3) m l θ̇ (l − 1),
    // by hand; and the page reads it in physical terms: the printed term lacks a factor l.
    let c = sliding_ladder::verify::claims::claims()
        .into_iter()
        .find(|c| c.location == "sec. A.5")
        .expect("the A.5 prose erratum");
    let want = r"\frac{2}{3} m l \dot\theta \left(l - 1\right)";
    assert_eq!(c.difference_latex.as_deref(), Some(want));
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/equations/ERRATA.md"))
        .expect("ERRATA.md");
    let reading = r"the printed term $-\frac{2}{3} m l \dot\theta$ lacks a factor $l$";
    assert_eq!(c.reading_latex.as_deref(), Some(reading));
    assert!(page.contains(reading), "ERRATA.md lacks: {reading}");
    // The printed prose form is not L_A (12) symbolically, the corrected one is.
    let (l, s, _) = sliding_ladder::registry::prove::symbolic_ladder(
        sliding_ladder::registry::LadderSample::Kinematic,
    );
    let la = sliding_ladder::ladder::torque::angular_momentum_about_a(&l, &s);
    let printed = -(Sym::ratio(2, 3) * l.m.clone() * l.l.clone() * s.rate.clone());
    assert!(!(printed - la.clone()).is_zero());
    let corrected = -(Sym::ratio(2, 3) * l.m.clone() * l.l.clone() * l.l.clone() * s.rate.clone());
    assert!((corrected - la).is_zero());
}
