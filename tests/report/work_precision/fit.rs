//! Rule 2 of the order fit (`report::work_precision::fit`) counts steps per phase: the starting
//! guess and the step cut at the event come once in each phase, so a full fall needs 10 steps
//! in the wall phase and 10 in the floor phase before its error follows the method's order.

use sliding_ladder::report::work_precision::fit::{fit_range, observed_order, Point, MIN_STEPS};

/// A made-up run: (wall steps, floor steps, error); a one-phase run has no floor steps.
#[derive(Debug)]
struct Fall(u64, Option<u64>, f64);

impl Point for Fall {
    fn method(&self) -> &str {
        "dop853"
    }
    fn rhs_evals(&self) -> u64 {
        12 * self.steps()
    }
    fn steps(&self) -> u64 {
        self.0 + self.1.unwrap_or(0)
    }
    fn shortest_phase_steps(&self) -> u64 {
        self.1.map_or(self.0, |f| f.min(self.0))
    }
    fn seconds(&self) -> f64 {
        1e-6 * self.steps() as f64
    }
    fn error(&self) -> f64 {
        self.2
    }
}

/// dop853's whole fall from θ0 = 0.3 at rest (m = l = 1, g = 9.81), tolerances 1e-8 to 1e-16 in
/// half decades (measured 2026-11-24 with `ladder work-precision`'s sweep): wall steps, floor
/// steps and the worse of the separation-angle, separation-time and flat-time errors.
const FULL_FALL: [(u64, u64, f64); 17] = [
    (6, 4, 7.201e-10),
    (6, 4, 2.296e-10),
    (6, 4, 7.277e-11),
    (7, 5, 4.750e-11),
    (7, 5, 3.395e-11),
    (8, 6, 8.142e-12),
    (9, 7, 4.540e-12),
    (11, 7, 3.396e-13),
    (12, 8, 1.525e-13),
    (14, 10, 4.181e-14),
    (15, 11, 3.413e-14),
    (18, 13, 3.754e-15),
    (20, 14, 3.413e-15),
    (23, 16, 6.826e-16),
    (27, 19, 3.783e-16),
    (31, 22, 2.482e-16),
    (35, 25, 0.0),
];

/// Counted per phase, only the runs of 14 + 10 and 15 + 11 steps lie above the rounding floor
/// (4.4e-15, ten times 2 ε), so no order is fitted. The check can fail: the same runs counted as
/// one phase of as many steps are fitted, and give a slope more than 1 from 8 (9.5).
#[test]
fn a_full_fall_needs_ten_steps_in_each_phase() {
    let two_phase: Vec<Fall> = FULL_FALL
        .iter()
        .map(|&(w, f, e)| Fall(w, Some(f), e))
        .collect();
    let kept = fit_range(&two_phase, "dop853");
    assert!(kept.iter().all(|r| r.shortest_phase_steps() >= MIN_STEPS));
    assert_eq!(
        kept.iter().map(|r| (r.0, r.1)).collect::<Vec<_>>(),
        [(14, Some(10)), (15, Some(11))]
    );
    assert!(observed_order(&two_phase, "dop853").is_none());

    let one_phase: Vec<Fall> = FULL_FALL
        .iter()
        .map(|&(w, f, e)| Fall(w + f, None, e))
        .collect();
    let fit = observed_order(&one_phase, "dop853").expect("counted as one phase, it is fitted");
    assert_eq!(fit.steps_range, (14, 26), "{fit:?}");
    assert!((fit.order - 8.0).abs() > 1.0, "{fit:?}");
}

/// A one-phase run's shortest phase is the run, so rule 2 is unchanged for separation scenes:
/// a clean line of order 8 from 10 steps is fitted from its first run.
#[test]
fn one_phase_runs_keep_the_whole_count() {
    let runs: Vec<Fall> = (0..6)
        .map(|k| {
            let n = 10 + 4 * k;
            Fall(n, None, 1e-6 * (10.0 / n as f64).powi(8))
        })
        .collect();
    let fit = observed_order(&runs, "dop853").unwrap();
    assert_eq!(fit.steps_range, (10, 30));
    assert!((fit.order - 8.0).abs() < 1e-9, "{fit:?}");
}
