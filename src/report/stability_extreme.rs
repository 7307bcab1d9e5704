//! The extreme cases of `ladder stability`: the edges of the start domain, the equilibrium,
//! m, l, g at 1e-30 and 1e30, and a 1e7-step run with nothing stored.
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

use super::stability_case::{blank, Case, Verdict, U};
use crate::sim::complement;
use crate::sim::exact::PhaseOne;
use crate::sim::extreme::{wall_release, WallRelease};
use crate::sim::fall;
use crate::sim::integrators::Control;
use crate::sim::output::Output;
use crate::sim::penalty::{separation, Contact, Law};
use crate::sim::rigid::{floor_force, Ladder};
use crate::sim::scene::{ContactModel, End, Scene};
use std::f64::consts::FRAC_PI_2;
use std::time::Instant;

const TOL: f64 = 1e-13;
const UNIT: Ladder = Ladder {
    mass: 1.0,
    half_length: 1.0,
    gravity: 1.0,
};

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
    let omega = UNIT.big_omega2().sqrt();
    for r in [1e-15, 1e-8, 1e-3, 0.5, 0.999, 1.0, 1.001, 2.0] {
        let name = format!("θ0=0 θ̇0={r:e}·Ω");
        cases.extend(start_rows(&name, 0.0, r * omega, tick));
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

fn scene(ladder: Ladder, theta0: f64, rate0: f64, end: End, outputs: Vec<Output>) -> Scene {
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

/// The scaled answers of a scene: (θ_s, t_s/√(l/g), θ̇_s √(l/g), F_f(θ_s)/(m g)).
fn scaled(sc: &Scene) -> Result<([f64; 4], u64, u64), String> {
    let o = fall::run(sc, 1_000_000).map_err(|e| e.to_string())?;
    let s = o.separation.ok_or("no separation")?;
    let l = &sc.ladder;
    let unit = (l.half_length / l.gravity).sqrt();
    let f = floor_force(l, s.angle, s.rate) / (l.mass * l.gravity);
    let w = o.work.wall;
    Ok((
        [s.angle, s.time / unit, s.rate * unit, f],
        w.steps,
        w.rhs_evals,
    ))
}

/// m, l, g at the corners of 1e-30..1e30: the unit-scale answers, scaled, to 1e-12.
pub fn scale_cases(tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    let (theta0, push) = (0.3, 0.1);
    let outputs = vec![Output::SeparationAngle, Output::SeparationTime];
    let unit_scene = scene(
        UNIT,
        theta0,
        push * UNIT.big_omega2().sqrt(),
        End::Separation,
        outputs.clone(),
    );
    let reference = scaled(&unit_scene);
    let mut cases = Vec::new();
    let (lo, hi) = (1e-30, 1e30);
    let mut corners = Vec::new();
    for m in [lo, hi] {
        for l in [lo, hi] {
            for g in [lo, hi] {
                corners.push((m, l, g, false));
            }
        }
    }
    corners.extend([
        (1.0, hi, lo, false),
        (1.0, lo, hi, false),
        (75.0, 2.0, 9.81, false),
        (hi, 1.0, 1.0, false),
        (lo, hi, lo, true),
        (hi, lo, hi, true),
    ]);
    let penalty = |sc: &mut Scene| {
        let l = sc.ladder;
        // κ = k l/(m g) = 1e4, formed as (1e4 m)(g/l) to stay within range; κ tol = 1e-9
        // keeps an explicit method accurate (see `stability_stiff`).
        sc.contact = ContactModel::Penalty {
            stiffness: 1e4 * l.mass * (l.gravity / l.half_length),
            damping: 0.0,
        };
    };
    let mut unit_penalty = unit_scene.clone();
    penalty(&mut unit_penalty);
    let penalty_reference = scaled(&unit_penalty);
    for (m, l, g, with_penalty) in corners {
        tick("scale", 1);
        let ladder = Ladder {
            mass: m,
            half_length: l,
            gravity: g,
        };
        let mut c = blank(
            "scale",
            format!("m={m:e} l={l:e} g={g:e}"),
            "dop853 tol 1e-13".into(),
            "unit-scale θ_s, t_s·√(l/g), θ̇_s/√(l/g), F_f·m g".into(),
        );
        let rate0 = push * ladder.big_omega2().sqrt();
        let mut sc = scene(ladder, theta0, rate0, End::Separation, outputs.clone());
        let mut reference = &reference;
        if with_penalty {
            penalty(&mut sc);
            reference = &penalty_reference;
            c.case += ", penalty κ=1e4";
        }
        let t = Instant::now();
        let got = scaled(&sc);
        c.seconds = t.elapsed().as_secs_f64();
        match (reference, &got) {
            (Ok((r, ..)), Ok((v, steps, rhs))) => {
                let (steps, rhs) = (*steps, *rhs);
                (c.steps, c.rhs_evals) = (steps, rhs);
                c.value = format!("θ_s = {:.15}, t_s/√(l/g) = {:.15}", v[0], v[1]);
                let err = (0..4)
                    .map(|i| ((v[i] - r[i]) / r[i]).abs())
                    .fold(0.0, f64::max);
                // Rigid: the 1e-12. Penalty: κ = (k/m)(l/g) and θ̇0 √(l/g) are rounded
                // differently at each scale, which changes the adaptive step sequence; both runs
                // then agree to their integration error, 2 × 10 N τ.
                let bound = if with_penalty {
                    (20.0 * steps as f64 * TOL).max(1e-12)
                } else {
                    1e-12
                };
                c.judge(err, bound);
            }
            (Err(e), _) | (_, Err(e)) => c.reason = e.clone(),
        }
        cases.push(c);
    }
    cases
}

/// Peak resident memory of this process (Linux `VmHWM`), kB; None elsewhere.
pub fn peak_rss_kb() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// The scalar-only scene of the memory runs: rk4 at 1e-6 s on a 20 km ladder (its wall phase
/// lasts ~70 s), to `seconds`, asking only for the final state: `seconds`·1e6 steps.
pub fn memory_scene(seconds: f64) -> Scene {
    let mut sc = scene(
        Ladder {
            mass: 1.0,
            half_length: 1e4,
            gravity: 9.81,
        },
        0.3,
        0.0,
        End::Time(seconds),
        vec![Output::FinalState],
    );
    sc.method = "rk4".into();
    sc.control = Some(Control::Fixed(1e-6));
    sc
}

/// 1e7 steps with nothing stored: the angle against the exact reference, the memory flat.
pub fn long_cases(tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    tick("long run 1e7 steps", 2);
    let mut c = blank(
        "long",
        "scalar-only scene, 1e7 steps".into(),
        "rk4 h 1e-6 s".into(),
        "θ(10 s) of the exact reference; peak memory flat".into(),
    );
    let before = peak_rss_kb();
    let t = Instant::now();
    let run = fall::run(&memory_scene(10.0), 20_000_000);
    c.seconds = t.elapsed().as_secs_f64();
    let after = peak_rss_kb();
    match run {
        Err(e) => c.reason = e.to_string(),
        Ok(o) => {
            let sc = memory_scene(10.0);
            c.steps = o.work.wall.steps;
            c.rhs_evals = o.work.wall.rhs_evals;
            let reference = PhaseOne::new(0.3, 0.0, sc.ladder.big_omega2()).map(|p| p.theta(10.0));
            let growth = before.zip(after).map(|(b, a)| a.saturating_sub(b));
            c.value = format!(
                "θ = {:.15}, samples kept {}, peak RSS growth {} kB (from {} kB)",
                o.last.1,
                o.work.stored_samples,
                growth.map_or("n/a".into(), |g| g.to_string()),
                before.map_or("n/a".into(), |b| b.to_string())
            );
            match reference {
                // Rounding: N steps each adding ~u θ, worst case without cancellation; the
                // truncation error h⁵ per step is far below it.
                Ok(r) => c.judge((o.last.1 - r).abs(), 10.0 * c.steps as f64 * U * r),
                Err(e) => c.reason = e,
            }
            // Storing the 1e7 states would take ≥ 80 MB; 1 MB of growth is the budget.
            if growth.is_some_and(|g| g > 1024) || o.work.stored_samples > 0 {
                c.verdict = Verdict::Fail;
                c.reason = "memory grew with the number of steps".into();
            }
        }
    }
    vec![c]
}
