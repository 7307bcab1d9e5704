//! One case of the stability report ([`crate::report::stability`]) and its verdict: the types every
//! group of cases (stiff, extreme, scale) builds, below the report that gathers them.

use crate::ladder::Ladder;
use crate::sim::integrators::Control;
use crate::sim::scene::output::Output;
use crate::sim::scene::{ContactModel, End, Scene};
use serde::Serialize;

/// `ok` or `fail`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// As theory says, within the bound.
    Ok,
    /// Not: see the reason.
    Fail,
}

/// What theory predicts for a case's verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Expect {
    /// The method must get it right (implicit methods; explicit ones well inside stability).
    Ok,
    /// The method cannot (beyond its stability limit, or κ·tol ≥ 1).
    Fail,
    /// Near a limit: either verdict is plausible.
    Either,
}

impl Expect {
    /// Whether `verdict` contradicts this expectation.
    pub fn surprised_by(self, verdict: Verdict) -> bool {
        matches!(
            (self, verdict),
            (Expect::Ok, Verdict::Fail) | (Expect::Fail, Verdict::Ok)
        )
    }
}

/// One case of the report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Case {
    /// Group: stiff, lagrange, extreme, scale, long.
    pub group: &'static str,
    /// Name (stiff cases contain "penalty").
    pub case: String,
    /// Method (with its tolerance or step).
    pub method: String,
    /// The expected value, in words and number.
    pub expected: String,
    /// What the run gave.
    pub value: String,
    /// The error measure (see `expected`), when there is one.
    pub error: Option<f64>,
    /// The bound the error is held to.
    pub bound: Option<f64>,
    /// Accepted steps.
    pub steps: u64,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Wall-clock seconds of the run.
    pub seconds: f64,
    /// ok / fail.
    pub verdict: Verdict,
    /// Why (for fail: the reason; for ok: a short note).
    pub reason: String,
    /// What theory expects of the verdict.
    pub expect: Expect,
    /// Constraint drift (t, max |g| up to t), for the Lagrange cases.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drift: Option<Vec<(f64, f64)>>,
}

impl Case {
    /// Judge `error` against `bound`: ok when within, fail with the numbers otherwise.
    pub fn judge(&mut self, error: f64, bound: f64) {
        self.error = Some(error);
        self.bound = Some(bound);
        if error.is_finite() && error <= bound {
            self.verdict = Verdict::Ok;
        } else {
            self.verdict = Verdict::Fail;
            self.reason = format!("error {error:.2e} above the bound {bound:.2e}");
        }
    }
}

/// A case with everything but its identity empty (verdict fail until judged).
pub fn blank(group: &'static str, case: String, method: String, expected: String) -> Case {
    Case {
        group,
        case,
        method,
        expected,
        value: String::new(),
        error: None,
        bound: None,
        steps: 0,
        rhs_evals: 0,
        seconds: 0.0,
        verdict: Verdict::Fail,
        reason: String::new(),
        expect: Expect::Ok,
        drift: None,
    }
}

/// Unit roundoff u = 2⁻⁵³.
pub const U: f64 = f64::EPSILON / 2.0;

/// The tolerance of the built-in rigid scenes (dop853).
pub const TOL: f64 = 1e-13;

/// The unit ladder m = l = g = 1.
pub const UNIT: Ladder<f64> = Ladder {
    m: 1.0,
    l: 1.0,
    g: 1.0,
};

/// A built-in rigid scene of the report: dop853 at [`TOL`] from (θ0, θ̇0) to `end`.
pub fn built_in_scene(
    ladder: Ladder<f64>,
    theta0: f64,
    rate0: f64,
    end: End,
    outputs: Vec<Output>,
) -> Scene {
    Scene {
        file: "(built in: stability)".into(),
        ladder,
        theta0,
        phi0: None,
        rate0,
        method: "dop853".into(),
        control: Some(Control::Tolerance(TOL)),
        order: None,
        end,
        outputs,
        contact: ContactModel::Rigid,
    }
}
