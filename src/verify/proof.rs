//! The proof verdict of one equation: its checks evaluated symbolically ([`crate::registry::prove`]).

use crate::registry::prove::{prove_check, CheckProof};
use crate::registry::{Equation, Kind};

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
}

/// Prove every check of an equation.
pub fn prove_equation(e: &Equation) -> (ProofVerdict, Vec<CheckProof>) {
    let proofs: Vec<CheckProof> = e.checks.iter().map(prove_check).collect();
    (verdict(e, &proofs), proofs)
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
    }
}
