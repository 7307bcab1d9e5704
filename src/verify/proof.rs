//! The proof verdict of one equation: its checks evaluated symbolically ([`crate::registry::prove`])
//! and, for a display of the note, its parsed print too
//! ([`crate::registry::print_check::prove`]): a display is proved only when both are.

use crate::registry::print_check::prove::{prove_print, PrintProof};
use crate::registry::prove::{prove_check, CheckProof};
use crate::registry::{Equation, Kind, EXTENSION_BASE};

/// The proof column of one equation.
#[derive(Clone, Debug)]
pub struct ProofVerdict {
    /// Every check holds symbolically (identities: zero difference; misprints: nonzero).
    pub proved: bool,
    /// `proved`, `erratum`, `definition`, `sampled only: <why>` or `not proved: <side>: <difference>`.
    pub proof: String,
    /// A problem to report (a nonzero difference where an identity should hold).
    pub problem: Option<String>,
    /// Seconds spent on the proofs.
    pub seconds: f64,
    /// The print proved symbolically (every printed form equals its chain for all values of the
    /// variables, every misprint differs); `None` for an extension beyond the note (no print).
    pub print_proved: Option<bool>,
    /// Printed forms of the display (all proved when `print_proved`).
    pub print_forms: usize,
}

/// Prove every check of an equation, and its print.
pub fn prove_equation(e: &Equation) -> (ProofVerdict, Vec<CheckProof>) {
    let proofs: Vec<CheckProof> = e.checks.iter().map(prove_check).collect();
    let print =
        (e.number <= EXTENSION_BASE || e.checks.is_empty()).then(|| prove_print(e, e.latex()));
    (with_print(verdict(e, &proofs), print), proofs)
}

/// Add the proof of the print to a verdict on the checks: a print not proved fails the display.
pub fn with_print(mut v: ProofVerdict, print: Option<PrintProof>) -> ProofVerdict {
    let Some(p) = print else {
        return v;
    };
    v.seconds += p.seconds;
    v.print_proved = Some(p.proved);
    v.print_forms = p.forms;
    if let (true, Some(problem)) = (v.proved, p.problem) {
        v.proved = false;
        v.proof = "not proved".into();
        v.problem = Some(problem);
    }
    v
}

/// Judge an equation from its check proofs.
pub fn verdict(e: &Equation, proofs: &[CheckProof]) -> ProofVerdict {
    let seconds = proofs.iter().map(|p| p.seconds).sum();
    if let Some(p) = proofs.iter().find(|p| p.sampled_only.is_some()) {
        let why = p.sampled_only.clone().unwrap_or_default();
        return ProofVerdict {
            proved: false,
            proof: format!("sampled only: {}: {why}", p.name),
            problem: None,
            seconds,
            print_proved: None,
            print_forms: 0,
        };
    }
    let mut problem = None;
    for p in proofs {
        if let Some((label, diff)) = &p.failure {
            problem = Some(format!(
                "{}: not proved: {label} − first side = {}",
                p.name,
                crate::scalar::text(diff)
            ));
        } else if let Some((label, _)) = p.misprints.iter().find(|m| m.1.is_zero()) {
            problem = Some(format!(
                "{}: the misprint '{label}' is symbolically right",
                p.name
            ));
        } else if p.off_shell_fails == Some(false) {
            problem = Some(format!("{}: holds symbolically off shell too", p.name));
        }
        if problem.is_some() {
            break;
        }
    }
    let proved = problem.is_none();
    let proof = if !proved {
        "not proved".to_string()
    } else if e.erratum.is_some() {
        "erratum".to_string()
    } else if e.kind == Kind::Definition {
        "definition".to_string()
    } else {
        "proved".to_string()
    };
    ProofVerdict {
        proved,
        proof,
        problem,
        seconds,
        print_proved: None,
        print_forms: 0,
    }
}
