//! The extreme cases of `ladder stability`: the edges of the start domain and the equilibrium
//! (the corners of m, l, g are in [`super::stability_corners`], the 1e7-step run in
//! [`super::stability_long`]).
//!
//! **Error measures and models.** Angles are judged by |cos θ_s − cos θ_s,theory| (absolute):
//! well conditioned everywhere, whereas θ_s itself cannot be resolved better than an ulp of
//! π/2 when the ladder starts almost flat. Times are judged against the exact reference
//! (`sim::exact`), relative. An adaptive method with relative tolerance τ on θ (scale
//! max(θ, θ̇/Ω)) taking N steps has an absolute angle error up to 10 N τ max(θ_s, 1), and the
//! time error is that over the angle travelled: 10 N τ max(θ_s, 1) / (θ_s − θ0) relative.
//! Above π/4 the run carries φ = π/2 − θ (`sim::complement`), whose error is relative to φ_s:
//! the time bound is then 10 N τ φ_s / (θ_s − θ0), about 20 N τ, even 1e-9 below flat (where
//! the ladder moves only 3e-10 rad before it leaves; in θ the bound was 5e-3 there).

use super::stability_case::{blank, built_in_scene as scene, Case, Verdict, TOL, U, UNIT};
use crate::sim::complement;
use crate::sim::exact::PhaseOne;
use crate::sim::extreme::{wall_release, WallRelease};
use crate::sim::fall;
use crate::sim::integrators::Control;
use crate::sim::output::Output;
use crate::sim::penalty::{Contact, Law};
use crate::sim::penalty_run::separation;
use crate::sim::rigid::Ladder;
use crate::sim::scene::End;
use std::f64::consts::FRAC_PI_2;
use std::time::Instant;

/// cos θ_s from the energy integral (footnote 4 generalised, see `rigid::separation_cosine`),
/// written out here in the form of the issue: 2/3 cos θ0 + 4 l θ̇0²/(9 g).
fn theory_cosine(ladder: &Ladder, theta0: f64, rate0: f64) -> f64 {
    2.0 / 3.0 * theta0.cos() + 4.0 * ladder.half_length * rate0 * rate0 / (9.0 * ladder.gravity)
}

/// One start of the unit ladder as a small ensemble (issue 17, item 2): the start and its
/// neighbours 1 and 2 ulps away (θ0, or θ̇0 when θ0 = 0), so that a verdict is not a lucky
/// sample. Each row is the ensemble's worst member (largest error over its bound) and states the
/// spread of the errors.
fn start_rows(name: &str, theta0: f64, rate0: f64, tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    tick(name, 2);
    // x ≥ 0 moved by k ulps (k < 0 stops at 0); bit steps, as f64::next_up needs Rust 1.86.
    let ulps = |x: f64, k: i64| f64::from_bits((x.to_bits() as i64 + k).max(0) as u64);
    let members: Vec<(f64, f64)> = [-2, -1, 0, 1, 2]
        .into_iter()
        .map(|k| match theta0 > 0.0 {
            true => (ulps(theta0, k), rate0),
            false => (theta0, ulps(rate0, k).max(0.0)),
        })
        .collect();
    let runs: Vec<Vec<Case>> = members
        .iter()
        .map(|&(th, w)| member_rows(name, th, w))
        .collect();
    // Row by row (matched by name: "leaves at once" members have no time row), the worst.
    let mut rows = Vec::new();
    for row in &runs[2] {
        let same: Vec<&Case> = runs
            .iter()
            .filter_map(|r| r.iter().find(|c| c.case == row.case))
            .collect();
        let ratio = |c: &Case| match (c.error, c.bound) {
            (Some(e), Some(b)) if e.is_finite() && b > 0.0 => e / b,
            (Some(_), Some(_)) => f64::INFINITY,
            _ => 0.0,
        };
        let fails = same.iter().filter(|c| c.verdict == Verdict::Fail).count();
        let worst = same
            .iter()
            .max_by(|a, b| {
                (a.verdict == Verdict::Fail, ratio(a))
                    .partial_cmp(&(b.verdict == Verdict::Fail, ratio(b)))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .copied()
            .unwrap_or(row);
        let mut c = worst.clone();
        let errs: Vec<f64> = same.iter().filter_map(|c| c.error).collect();
        let (lo, hi) = errs
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(l, h), &e| (l.min(e), h.max(e)));
        let moved = if theta0 > 0.0 { "θ0" } else { "θ̇0" };
        let spread = match errs.is_empty() {
            true => "no error to measure".to_string(),
            false => format!("errors {lo:.1e}..{hi:.1e}"),
        };
        c.value = format!(
            "{} [worst of {} with {moved} ± 2 ulp; {spread}]",
            c.value,
            same.len()
        );
        if fails > 0 && c.verdict == Verdict::Fail {
            c.reason = format!("{} ({fails} of {} members fail)", c.reason, same.len());
        }
        (c.steps, c.rhs_evals) = (row.steps, row.rhs_evals);
        c.seconds = same.iter().map(|c| c.seconds).sum();
        rows.push(c);
    }
    rows
}

/// One member of a start's ensemble: an angle row and a time row.
fn member_rows(name: &str, theta0: f64, rate0: f64) -> Vec<Case> {
    let control = Control::Tolerance(TOL);
    let cs = theory_cosine(&UNIT, theta0, rate0);
    // θ_s at or behind θ0 (cos θ_s ≥ cos θ0; for θ0 = 0, cos θ_s ≥ 1): the wall would pull.
    let at_once = cs >= theta0.cos();
    let expected = if at_once {
        format!("cos θ_s = {cs:.6} ≥ cos θ0: leaves at once")
    } else {
        format!("cos θ_s = {cs:.15e}")
    };
    let mut a = blank(
        "extreme",
        format!("{name}: angle"),
        "dop853 tol 1e-13".into(),
        expected,
    );
    let t = Instant::now();
    let r = wall_release(&UNIT, theta0, rate0, "dop853", control, 10_000_000);
    a.seconds = t.elapsed().as_secs_f64();
    let mut rows = Vec::new();
    match r {
        Err(e) => a.reason = e.to_string(),
        Ok((WallRelease::Equilibrium, _)) => a.reason = "called an equilibrium".into(),
        Ok((WallRelease::AtOnce, _)) => {
            a.value = "leaves at once (t_s = 0)".into();
            // Exactly at cos θ_s = 1 rounding decides between "at once" and a separation
            // within an ulp; both are right.
            if cs >= theta0.cos() - 4.0 * U {
                a.verdict = Verdict::Ok;
                a.reason = "the wall would pull at t = 0".into();
            } else {
                a.reason = "left at once although the wall pushes at the start".into();
            }
        }
        Ok((WallRelease::Separated(s), st)) => {
            (a.steps, a.rhs_evals) = (st.steps, st.rhs_evals);
            a.value = format!("θ_s = {:.15}, t_s = {:.6e}", s.angle, s.time);
            let n = st.steps as f64;
            let angle_bound = 10.0 * n * TOL * s.angle.max(1.0) + 4.0 * U;
            a.judge((s.angle.cos() - cs.min(theta0.cos())).abs(), angle_bound);
            // At cos θ_s = 1 (to rounding) the ladder leaves at once: no time to compare.
            if cs < theta0.cos() - 4.0 * U {
                let mut t = blank(
                    "extreme",
                    format!("{name}: time"),
                    "dop853 tol 1e-13".into(),
                    "t_s of the exact reference".into(),
                );
                (t.steps, t.rhs_evals, t.seconds) = (a.steps, a.rhs_evals, a.seconds);
                match PhaseOne::new(theta0, rate0, UNIT.big_omega2()).map(|p| p.separation()) {
                    Ok(Some(x)) => {
                        t.value = format!("t_s = {:.15e} (reference {:.15e})", s.time, x.time);
                        let travel = (s.angle - theta0).abs().max(f64::MIN_POSITIVE);
                        // Near the floor the run carries φ = π/2 − θ: its angle error is
                        // relative to φ_s, not to θ_s (`sim::complement`).
                        let scale = match complement::applies(theta0) {
                            true => complement::complement(s.angle),
                            false => s.angle.max(1.0),
                        };
                        let time_bound = 10.0 * n * TOL * scale / travel + 1e-12;
                        t.judge((s.time - x.time).abs() / x.time, time_bound);
                    }
                    other => t.reason = format!("no reference: {other:?}"),
                }
                rows.push(t);
            }
        }
    }
    rows.insert(0, a);
    rows
}

/// Starts at rest from 1e-12 to π/2 − 1e-9, pushes at θ0 = 0 up to and past Ω, the
/// equilibrium.
pub fn extreme_cases(tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    let mut cases = Vec::new();
    for (label, theta0) in [
        ("1e-12", 1e-12),
        ("1e-6", 1e-6),
        ("0.3", 0.3),
        ("1.0", 1.0),
        ("1.5", 1.5),
        ("π/2−1e-6", FRAC_PI_2 - 1e-6),
        ("π/2−1e-9", FRAC_PI_2 - 1e-9),
    ] {
        cases.extend(start_rows(&format!("rest θ0={label}"), theta0, 0.0, tick));
    }
    let big_omega = UNIT.big_omega2().sqrt();
    for r in [1e-15, 1e-8, 1e-3, 0.5, 0.999, 1.0, 1.001, 2.0] {
        let name = format!("θ0=0 θ̇0={r:e}·Ω");
        cases.extend(start_rows(&name, 0.0, r * big_omega, tick));
    }
    tick("equilibrium", 3);
    let expected = "never separates".to_string();
    let mut e = blank(
        "extreme",
        "equilibrium θ0=θ̇0=0".into(),
        "dop853 tol 1e-13".into(),
        expected.clone(),
    );
    if let Ok((WallRelease::Equilibrium, _)) =
        wall_release(&UNIT, 0.0, 0.0, "dop853", Control::Tolerance(TOL), 1000)
    {
        (e.verdict, e.value) = (Verdict::Ok, expected.clone());
    }
    cases.push(e);
    let mut p = blank(
        "extreme",
        "equilibrium θ0=θ̇0=0, penalty κ=1e6".into(),
        "radau5 tol 1e-10".into(),
        expected.clone(),
    );
    let run = separation(
        Contact {
            kappa: 1e6,
            gamma: 0.0,
        },
        Law::Switched,
        0.0,
        0.0,
        "radau5",
        Control::Tolerance(1e-10),
        1000,
    );
    if let Err(err) = run.result {
        p.value = err.to_string();
        if p.value.contains("equilibrium") {
            p.verdict = Verdict::Ok;
        }
    }
    cases.push(p);
    let mut s = blank(
        "extreme",
        "equilibrium θ0=θ̇0=0, scene to t=100 s".into(),
        "dop853 tol 1e-13".into(),
        "θ = 0 throughout, no separation".into(),
    );
    let mut sc = scene(UNIT, 0.0, 0.0, End::Time(100.0), vec![Output::FinalState]);
    sc.ladder.gravity = 9.81;
    let t = Instant::now();
    match fall::run(&sc, 100_000) {
        Ok(o) => {
            s.seconds = t.elapsed().as_secs_f64();
            s.steps = o.work.wall.steps;
            s.value = format!("θ(100 s) = {}, separation {:?}", o.last.1, o.separation);
            if o.last.1 == 0.0 && o.separation.is_none() && o.last.0 == 100.0 {
                s.verdict = Verdict::Ok;
            }
        }
        Err(err) => s.reason = err.to_string(),
    }
    cases.push(s);
    cases
}
