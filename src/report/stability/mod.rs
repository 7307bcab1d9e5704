//! `ladder stability [--json]`: the stiff and the extreme cases, each with its expected value
//! (from theory or the exact reference), the error, the work, the run time and a verdict.
//!
//! Groups (see [`super::stability::stiff`] and [`super::stability::extreme`]):
//! * `stiff`: the penalty model over κ = k l/(m g) = 1e2..1e12 with implicit and explicit
//!   methods, against the rigid separation angle (footnote 4);
//! * `lagrange`: the constrained full-coordinate model (multipliers), its separation angle and
//!   constraint drift against time, with and without Baumgarte stabilisation;
//! * `extreme`: starts from almost upright to almost flat, pushes up to and past the speed at
//!   which the top leaves at once, the equilibrium;
//! * `scale`: m, l, g at 1e-30 and 1e30;
//! * `sweep`: the whole fall to flat at random scales and tolerances, every adaptive method
//!   ([`super::stability::scale`]);
//! * `long`: 1e7 steps with nothing stored, and the peak memory of the process.
//!
//! **Verdicts.** `ok` when the run ends as theory says and its error is within the case's
//! bound; `fail` with the reason otherwise (the run's own error: step limit, step size
//! collapse, non-finite state, Newton failure; a blow-up seen in the energy; an error above
//! the bound). Every bound is an error model stated where the case is built. The exit code is
//! 0 whatever the verdicts: explicit methods are *expected* to fail at high stiffness, and the
//! point of the report is to show that they fail visibly. A case whose verdict contradicts
//! theory's prediction (an implicit method failing, an explicit one passing where theory says it
//! cannot) makes the exit code 1.

pub mod case;
pub mod corners;
pub mod extreme;
pub mod long;
pub mod scale;
pub mod stiff;

pub use super::stability::case::{blank, Case, Expect, Verdict, U};

/// All cases, calling `tick` with a label before each group's runs.
pub fn all_cases(mut tick: impl FnMut(&str, u64)) -> (Vec<Case>, stiff::Convergence) {
    let mut cases = Vec::new();
    let (stiff, conv) = stiff::penalty_cases(&mut tick);
    cases.extend(stiff);
    cases.extend(stiff::lagrange_cases(&mut tick));
    cases.extend(extreme::extreme_cases(&mut tick));
    cases.extend(super::stability::corners::scale_cases(&mut tick));
    cases.extend(super::stability::scale::sweep_cases(&mut tick));
    cases.extend(super::stability::long::long_cases(&mut tick));
    (cases, conv)
}

fn sci(x: Option<f64>) -> String {
    x.map_or("-".into(), |v| format!("{v:.2e}"))
}

/// The human-readable report.
pub fn table(cases: &[Case], conv: &stiff::Convergence) -> String {
    let mut s = String::new();
    let mut group = "";
    for c in cases {
        if c.group != group {
            group = c.group;
            s += &format!(
                "\n[{group}]\n{:<38} {:<24} {:>9} {:>9} {:>9} {:>9} {:>8} {:<5} {}\n",
                "case",
                "method",
                "error",
                "bound",
                "steps",
                "rhs",
                "seconds",
                "",
                "expected / got / reason"
            );
        }
        s += &format!(
            "{:<38} {:<24} {:>9} {:>9} {:>9} {:>9} {:>8.3} {:<5} {} | {} | {}\n",
            c.case,
            c.method,
            sci(c.error),
            sci(c.bound),
            c.steps,
            c.rhs_evals,
            c.seconds,
            if c.verdict == Verdict::Ok {
                "ok"
            } else {
                "FAIL"
            },
            c.expected,
            c.value,
            c.reason
        );
        if let Some(d) = &c.drift {
            let pts: Vec<String> = d.iter().map(|(t, g)| format!("t={t:e}: {g:.1e}")).collect();
            s += &format!("{:<38} constraint drift max|g|: {}\n", "", pts.join(", "));
        }
    }
    s += &format!("\n{conv}\n");
    let n_ok = cases.iter().filter(|c| c.verdict == Verdict::Ok).count();
    let surprises: Vec<&str> = cases
        .iter()
        .filter(|c| c.expect.surprised_by(c.verdict))
        .map(|c| c.case.as_str())
        .collect();
    s += &format!(
        "{} cases: {n_ok} ok, {} fail; verdicts against theory's expectation: {}\n",
        cases.len(),
        cases.len() - n_ok,
        if surprises.is_empty() {
            "all as expected".to_string()
        } else {
            format!("UNEXPECTED {}", surprises.join("; "))
        }
    );
    s
}
