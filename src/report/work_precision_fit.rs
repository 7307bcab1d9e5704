//! The judgement half of work-precision: the observed order, fitted only where it means
//! something, and the Pareto front. Kept apart from the measuring half so both can be tested on
//! made-up runs.
//!
//! **Fitting rule for the observed order** (stated once, applied to every method and scene):
//! of a method's runs, sorted by rhs evaluations, keep those whose error is
//! 1. above the rounding floor: error ≥ [`FLOOR`] = 1e-13 (about 500 u; the exact reference is
//!    good to 2 ulps, and below ~1e-13 the error of a step sum is rounding, not truncation),
//! 2. in the asymptotic regime: error ≤ [`ASYMPTOTIC`] = 1e-4 (the leading error term dominates;
//!    looser tolerances also meet the event-safe step limit, so work stops following tolerance),
//! 3. bought by more work: rhs evaluations strictly above those of the last kept run (a run that
//!    costs no more than a looser one measured the step limit, not the method);
//!
//! and fit −ln(error) = q ln(rhs evaluations) + c by least squares over at least three such runs.
//! The report gives q with the range used (rhs evaluations and errors, number of runs).

use serde::Serialize;

/// Smallest error used in the order fit.
pub const FLOOR: f64 = 1e-13;
/// Largest error used in the order fit.
pub const ASYMPTOTIC: f64 = 1e-4;

/// A point of a work-precision diagram: work (rhs evaluations), time and error.
pub trait Point {
    /// Method name.
    fn method(&self) -> &str;
    /// Right-hand-side evaluations.
    fn rhs_evals(&self) -> u64;
    /// Median seconds per solve.
    fn seconds(&self) -> f64;
    /// The error judged (the worse of the scene's error measures).
    fn error(&self) -> f64;
}

/// An observed order and the range it was fitted on.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct OrderFit {
    /// The fitted slope q of −ln(error) against ln(rhs evaluations).
    pub order: f64,
    /// Runs used.
    pub runs: usize,
    /// (fewest, most) rhs evaluations of the runs used.
    pub rhs_range: (u64, u64),
    /// (largest, smallest) error of the runs used.
    pub error_range: (f64, f64),
}

/// The runs of `method` that the fitting rule keeps, in order of work.
pub fn fit_range<'a, P: Point>(runs: &'a [P], method: &str) -> Vec<&'a P> {
    let mut mine: Vec<&P> = runs.iter().filter(|r| r.method() == method).collect();
    mine.sort_by_key(|r| r.rhs_evals());
    let mut kept: Vec<&P> = Vec::new();
    for r in mine {
        let e = r.error();
        if !(FLOOR..=ASYMPTOTIC).contains(&e) {
            continue;
        }
        if kept.last().is_some_and(|k| r.rhs_evals() <= k.rhs_evals()) {
            continue;
        }
        kept.push(r);
    }
    kept
}

/// The observed order of `method` by the fitting rule (module docs), or None with fewer than
/// three runs in range.
pub fn observed_order<P: Point>(runs: &[P], method: &str) -> Option<OrderFit> {
    let kept = fit_range(runs, method);
    if kept.len() < 3 {
        return None;
    }
    let pts: Vec<(f64, f64)> = kept
        .iter()
        .map(|r| ((r.rhs_evals() as f64).ln(), -r.error().ln()))
        .collect();
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    (sxx > 0.0).then(|| OrderFit {
        order: sxy / sxx,
        runs: kept.len(),
        rhs_range: (kept[0].rhs_evals(), kept[kept.len() - 1].rhs_evals()),
        error_range: (kept[0].error(), kept[kept.len() - 1].error()),
    })
}

/// Whether `q` dominates `r`: no slower and no less accurate, and better in at least one.
pub fn dominates<P: Point>(q: &P, r: &P) -> bool {
    let (qs, rs, qe, re) = (q.seconds(), r.seconds(), q.error(), r.error());
    qs <= rs && qe <= re && (qs < rs || qe < re)
}

/// The Pareto front of run time against error: every run that no other run dominates (runs
/// equal in both stay, neither dominates the other), fastest first.
pub fn pareto<P: Point>(runs: &[P]) -> Vec<&P> {
    let mut front: Vec<&P> = runs
        .iter()
        .filter(|r| !runs.iter().any(|q| dominates(q, *r)))
        .collect();
    front.sort_by(|a, b| a.seconds().total_cmp(&b.seconds()));
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, PartialEq)]
    struct P(&'static str, u64, f64, f64);
    impl Point for P {
        fn method(&self) -> &str {
            self.0
        }
        fn rhs_evals(&self) -> u64 {
            self.1
        }
        fn seconds(&self) -> f64 {
            self.2
        }
        fn error(&self) -> f64 {
            self.3
        }
    }

    /// A method of order 8 on its asymptotic range, with a floor and a step-limited start.
    fn order_eight() -> Vec<P> {
        let mut v: Vec<P> = (0..6)
            .map(|k| {
                let n = 100.0 * 2f64.powi(k);
                P("m", n as u64, n * 1e-8, 1e-3 * (100.0 / n).powi(8))
            })
            .collect();
        // Rounding floor at tighter tolerances, and loose runs with the same work.
        v.push(P("m", 10_000, 1e-4, 2e-16));
        v.push(P("m", 100, 1e-6, 5e-3));
        v.push(P("m", 90, 1e-6, 2e-2));
        v.push(P("m", 200, 2e-6, 3.9e-6));
        for (n, e) in [
            (5000, 3e-16),
            (7000, 2e-16),
            (14_000, 2e-16),
            (20_000, 3e-16),
        ] {
            v.push(P("m", n, n as f64 * 1e-8, e));
        }
        v
    }

    #[test]
    fn the_order_fit_uses_the_asymptotic_range_only() {
        let runs = order_eight();
        let fit = observed_order(&runs, "m").unwrap();
        assert!((fit.order - 8.0).abs() < 1e-9, "{fit:?}");
        assert!(fit.error_range.1 >= FLOOR && fit.error_range.0 <= ASYMPTOTIC);
        // Without the rule (all runs) the slope is far from 8: the rule matters.
        let all: Vec<(f64, f64)> = runs
            .iter()
            .map(|r| ((r.1 as f64).ln(), -r.3.ln()))
            .collect();
        let n = all.len() as f64;
        let mx = all.iter().map(|p| p.0).sum::<f64>() / n;
        let my = all.iter().map(|p| p.1).sum::<f64>() / n;
        let naive = all.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / all.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        assert!((naive - 8.0).abs() > 1.0, "naive {naive}");
        assert!(observed_order(&runs[..2], "m").is_none());
    }

    #[test]
    fn no_listed_point_is_dominated_and_every_other_is() {
        let runs = vec![
            P("a", 1, 1.0, 1e-4),
            P("a", 1, 1.0, 1e-7), // same time, better: dominates the one above
            P("b", 1, 2.0, 1e-7), // slower, same error: dominated
            P("b", 1, 3.0, 1e-9),
            P("c", 1, 3.0, 1e-9), // an exact tie: both stay
            P("c", 1, 0.5, 1e-3),
            P("d", 1, 4.0, 1e-8), // dominated by (3.0, 1e-9)
        ];
        let front = pareto(&runs);
        for r in &front {
            assert!(!runs.iter().any(|q| dominates(q, *r)), "{r:?} is dominated");
        }
        for r in &runs {
            if !front.contains(&r) {
                assert!(runs.iter().any(|q| dominates(q, r)), "{r:?} left out");
            }
        }
        let listed: Vec<(f64, f64)> = front.iter().map(|r| (r.2, r.3)).collect();
        assert_eq!(listed, [(0.5, 1e-3), (1.0, 1e-7), (3.0, 1e-9), (3.0, 1e-9)]);
        // The old rule (strictly better in both) kept the tied-time point: show it differs.
        let strict: Vec<&P> = runs
            .iter()
            .filter(|r| !runs.iter().any(|q| q.2 < r.2 && q.3 < r.3))
            .collect();
        assert!(strict.len() > front.len());
    }
}
