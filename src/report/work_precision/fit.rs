//! The judgement half of work-precision: the observed order, fitted only where it means
//! something, and the Pareto front. Kept apart from the measuring half so both can be tested on
//! made-up runs.
//!
//! **Fitting rule for the observed order** (stated once, applied to every method and scene):
//! of a method's runs, sorted by steps, keep those whose error is
//! 1. above the rounding floor: error ≥ floor = min([`FLOOR`], [`ROUNDING_MARGIN`] × the rounding
//!    level), where the rounding level is the median error of the method's [`ROUNDING_RUNS`]
//!    most accurate runs. [`FLOOR`] = 1e-13 (about 500 u) is the floor a sweep is held to when it
//!    does not show where its rounding lies; a sweep whose tightest runs reach a lower level shows
//!    it, and above ten times that level rounding changes ln(error) by at most ~0.1 (the exact
//!    reference itself is good to 2 ulps). A sweep that never reaches rounding keeps 1e-13.
//! 2. in the asymptotic regime: error ≤ [`ASYMPTOTIC`] = 1e-4 (the leading error term dominates;
//!    looser tolerances also meet the event-safe step limit, so work stops following tolerance),
//!    and at least [`MIN_STEPS`] = 10 steps in every phase: on fewer the error moves with whole
//!    steps, the first step's guess and the last step to the event, and the order of the method
//!    is not visible (dop853 from θ0 = 1 reaches 5e-15 in 9 steps: its five runs above the floor,
//!    of 5 to 9 steps, gave a slope of 12.7 ± 4.3). Those costs come once per phase, so a full
//!    fall needs 10 in each: dop853's first guess from θ0 = 0.3 at 1e-12 is under a seventh of
//!    the settled step, in each phase; over both phases together its runs of 8 + 6 to 15 + 11
//!    steps gave 9.5 ± 1.2 (`tests/report/work_precision/fit.rs`);
//! 3. bought by the tolerance: no other run of the method takes exactly as many steps (several
//!    tolerances with the same work all measured the step limit, not the method: the loosest of
//!    them is as step-limited as the rest), and its steps are strictly above those of the last
//!    kept run;
//! 4. consistent: its error is strictly below that of the last kept run (more steps that buy no
//!    accuracy are not on the asymptotic line: the successive error ratios must all be > 1);
//!
//! and fit −ln(error) = q ln(steps) + c by least squares over such runs ([`observed_order`],
//! from three); the report gives an order only over at least [`MIN_RUNS`] = 5 of them spanning
//! at least [`MIN_DECADES`] = 2 decades of error, else says why not ([`order_fit`]; issue 38:
//! three or four runs over 11-52 steps gave rk4 5.63 ± 0.53 and dopri5 6.26 ± 1.96, and a
//! slope over less than two decades is mostly its end points' noise) (steps,
//! not rhs evaluations: a solve also pays a fixed count for its first step and the event, 27 of
//! dop853's 159 rhs at θ0 = 0.1, which steepens the slope in rhs by 10-40 %; h ∝ 1/steps is
//! what the order speaks of). The report gives q with its standard error and the range used
//! (steps, rhs evaluations and errors, number of runs, floor).

use serde::Serialize;

/// Smallest error used in the order fit.
pub const FLOOR: f64 = 1e-13;
/// Largest error used in the order fit.
pub const ASYMPTOTIC: f64 = 1e-4;
/// Fewest steps of a run used in the order fit.
pub const MIN_STEPS: u64 = 10;
/// How far above the measured rounding level the fit starts.
pub const ROUNDING_MARGIN: f64 = 10.0;
/// How many of the most accurate runs measure the rounding level.
pub const ROUNDING_RUNS: usize = 3;
/// Fewest runs an order (or a tolerance slope) is fitted on.
pub const MIN_RUNS: usize = 5;
/// Fewest decades of error (of tolerance, for the tolerance slope) a fit spans.
pub const MIN_DECADES: f64 = 2.0;

/// A point of a work-precision diagram: work (rhs evaluations), time and error.
pub trait Point {
    /// Method name.
    fn method(&self) -> &str;
    /// Right-hand-side evaluations.
    fn rhs_evals(&self) -> u64;
    /// Steps taken (accepted).
    fn steps(&self) -> u64;
    /// Accepted steps of the run's shortest phase (rule 2); a one-phase run's are all its steps.
    fn shortest_phase_steps(&self) -> u64 {
        self.steps()
    }
    /// Median seconds per solve.
    fn seconds(&self) -> f64;
    /// The tolerance the run was given (NaN where there is none: a fixed step, a made-up run).
    fn tolerance(&self) -> f64 {
        f64::NAN
    }
    /// The error judged (the worse of the scene's error measures).
    fn error(&self) -> f64;
}

/// An observed order and the range it was fitted on.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct OrderFit {
    /// The fitted slope q of −ln(error) against ln(steps).
    pub order: f64,
    /// The slope's standard error from the fit's residuals, √(Σ r² / ((n − 2) Σ (x − x̄)²)).
    pub std_error: f64,
    /// Runs used.
    pub runs: usize,
    /// (fewest, most) steps of the runs used.
    pub steps_range: (u64, u64),
    /// (fewest, most) rhs evaluations of the runs used.
    pub rhs_range: (u64, u64),
    /// (largest, smallest) error of the runs used.
    pub error_range: (f64, f64),
    /// The rounding floor the rule used (rule 1).
    pub floor: f64,
}

/// The rounding floor of rule 1 for `method`'s runs: min(FLOOR, margin × median error of the
/// most accurate runs), that median taken as at least 2 ε (the reference's accuracy).
pub fn rounding_floor<P: Point>(runs: &[P], method: &str) -> f64 {
    let mut errs: Vec<f64> = runs
        .iter()
        .filter(|r| r.method() == method && r.error().is_finite())
        .map(|r| r.error())
        .collect();
    if errs.len() < ROUNDING_RUNS {
        return FLOOR;
    }
    errs.sort_by(f64::total_cmp);
    // An error below the reference's own 2 ulps is a lucky rounding, not a level.
    let level = errs[ROUNDING_RUNS / 2].max(2.0 * f64::EPSILON);
    FLOOR.min(ROUNDING_MARGIN * level)
}

/// The runs of `method` that the fitting rule keeps, in order of steps.
pub fn fit_range<'a, P: Point>(runs: &'a [P], method: &str) -> Vec<&'a P> {
    let floor = rounding_floor(runs, method);
    let mut mine: Vec<&P> = runs.iter().filter(|r| r.method() == method).collect();
    mine.sort_by_key(|r| r.steps());
    let tied = |r: &P| mine.iter().filter(|q| q.steps() == r.steps()).count() > 1;
    let mut kept: Vec<&P> = Vec::new();
    for &r in &mine {
        let e = r.error();
        if !(floor..=ASYMPTOTIC).contains(&e) || r.shortest_phase_steps() < MIN_STEPS || tied(r) {
            continue;
        }
        if kept
            .last()
            .is_some_and(|k| r.steps() <= k.steps() || e >= k.error())
        {
            continue;
        }
        kept.push(r);
    }
    kept
}

/// The least-squares order of `method` over the fitting rule's range (rules 1-4), or None
/// with fewer than three runs there. The report holds it to more ([`order_fit`]).
pub fn observed_order<P: Point>(runs: &[P], method: &str) -> Option<OrderFit> {
    let kept = fit_range(runs, method);
    if kept.len() < 3 {
        return None;
    }
    let (q, sxx, residuals) = log_slope(kept.iter().copied());
    let n = kept.len() as f64;
    let (first, last) = (kept[0], kept[kept.len() - 1]);
    (sxx > 0.0).then(|| OrderFit {
        order: q,
        std_error: (residuals / ((n - 2.0) * sxx)).sqrt(),
        runs: kept.len(),
        steps_range: (first.steps(), last.steps()),
        rhs_range: (first.rhs_evals(), last.rhs_evals()),
        error_range: (first.error(), last.error()),
        floor: rounding_floor(runs, method),
    })
}

/// The observed order the report gives (module docs): [`observed_order`] on at least
/// [`MIN_RUNS`] runs spanning at least [`MIN_DECADES`] of error, or why it is not fitted.
pub fn order_fit<P: Point>(runs: &[P], method: &str) -> Result<OrderFit, String> {
    let n = fit_range(runs, method).len();
    let floor = rounding_floor(runs, method);
    let fit = observed_order(runs, method).filter(|_| n >= MIN_RUNS);
    let Some(fit) = fit else {
        return Err(format!(
            "{n} runs in range (≥ {MIN_STEPS} steps in each phase, error in [{floor:.0e}, {ASYMPTOTIC:.0e}], growing work and falling error), {MIN_RUNS} needed"
        ));
    };
    let decades = (fit.error_range.0 / fit.error_range.1).log10();
    if decades < MIN_DECADES {
        return Err(format!(
            "the {n} runs in range span {decades:.1} decades of error, {MIN_DECADES} needed"
        ));
    }
    Ok(fit)
}

/// How an adaptive method's error follows its tolerance: the least-squares slope of
/// ln(error) against ln(tolerance) over its runs above the rounding floor (rule 1), with the
/// ranges. A method whose error is proportional to its tolerance has slope 1; a flat stretch
/// means something else sets the steps (dop853 from θ0 = 0.1 keeps 8-9 steps and an error of
/// 1e-11 to 6e-11 from tolerance 1e-5 to 1e-9: the event-safe step cap, issue 38).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToleranceSlope {
    /// The slope of ln(error) against ln(tolerance).
    pub slope: f64,
    /// Its standard error.
    pub std_error: f64,
    /// Runs used.
    pub runs: usize,
    /// (loosest, tightest) tolerance of the runs used.
    pub tolerance_range: (f64, f64),
    /// (largest, smallest) error of the runs used.
    pub error_range: (f64, f64),
    /// (fewest, most) steps of the runs used.
    pub steps_range: (u64, u64),
}

/// The tolerance slope of `method` (see [`ToleranceSlope`]), or why it is not fitted: fewer
/// than [`MIN_RUNS`] runs above the rounding floor, or their tolerances spanning less than
/// [`MIN_DECADES`].
pub fn tolerance_slope<P: Point>(runs: &[P], method: &str) -> Result<ToleranceSlope, String> {
    let floor = rounding_floor(runs, method);
    let mut mine: Vec<&P> = runs
        .iter()
        .filter(|r| r.method() == method && r.error() >= floor && r.tolerance() > 0.0)
        .collect();
    mine.sort_by(|a, b| b.tolerance().total_cmp(&a.tolerance()));
    if mine.len() < MIN_RUNS {
        return Err(format!(
            "{} runs above the rounding floor {floor:.0e}, {MIN_RUNS} needed",
            mine.len()
        ));
    }
    let (first, last) = (mine[0], mine[mine.len() - 1]);
    let decades = (first.tolerance() / last.tolerance()).log10();
    if decades < MIN_DECADES {
        return Err(format!(
            "the {} runs above the floor span {decades:.1} decades of tolerance, {MIN_DECADES} needed",
            mine.len()
        ));
    }
    let pts: Vec<(f64, f64)> = mine
        .iter()
        .map(|r| (r.tolerance().ln(), r.error().ln()))
        .collect();
    let (slope, sxx, residuals) = line_fit(&pts);
    let n = pts.len() as f64;
    let steps = mine.iter().map(|r| r.steps());
    Ok(ToleranceSlope {
        slope,
        std_error: (residuals / ((n - 2.0) * sxx)).sqrt(),
        runs: mine.len(),
        tolerance_range: (first.tolerance(), last.tolerance()),
        error_range: (first.error(), last.error()),
        steps_range: (steps.clone().min().unwrap_or(0), steps.max().unwrap_or(0)),
    })
}

/// Least-squares slope of −ln(error) against ln(steps) over `runs`, with the spread of ln(steps)
/// (Σ(x − x̄)²) and the sum of squared residuals, for the slope's standard error.
pub fn log_slope<'a, P: Point + 'a>(runs: impl Iterator<Item = &'a P>) -> (f64, f64, f64) {
    let pts: Vec<(f64, f64)> = runs
        .map(|r| ((r.steps() as f64).ln(), -r.error().ln()))
        .collect();
    line_fit(&pts)
}

/// The least-squares line through `pts` (x, y): its slope, Σ(x − x̄)² and the sum of squared
/// residuals (for the slope's standard error, √(Σ r² / ((n − 2) Σ (x − x̄)²))).
pub fn line_fit(pts: &[(f64, f64)]) -> (f64, f64, f64) {
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let q = sxy / sxx;
    let residuals = pts
        .iter()
        .map(|p| (p.1 - my - q * (p.0 - mx)).powi(2))
        .sum();
    (q, sxx, residuals)
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
