//! The `scale` group of `ladder stability`: m, l, g at the corners of 1e-30..1e30 (and a few
//! mixed ladders, two with penalty contact), each run against the unit ladder's answers scaled
//! by √(l/g) and m g: the integrators' scale invariance tested, not assumed.

use crate::report::stability::case::{blank, built_in_scene as scene, Case, TOL, UNIT};
use crate::sim::fall;
use crate::sim::rigid::floor_force;

use crate::ladder::Ladder;
use crate::sim::scene::output::Output;
use crate::sim::scene::{ContactModel, End, Scene};
use std::time::Instant;

/// The scaled answers of a scene: (θ_s, t_s/√(l/g), θ̇_s √(l/g), F_f(θ_s)/(m g)).
fn scaled(sc: &Scene) -> Result<([f64; 4], u64, u64), String> {
    let o = fall::run(sc, 1_000_000).map_err(|e| e.to_string())?;
    let s = o.separation.ok_or("no separation")?;
    let l = &sc.ladder;
    let unit = (l.l / l.g).sqrt();
    let f = floor_force(l, s.angle, s.rate) / (l.m * l.g);
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
    let mut unit_penalty = unit_scene.clone();
    penalty(&mut unit_penalty);
    let penalty_reference = scaled(&unit_penalty);
    for (m, l, g, with_penalty) in corners() {
        tick("scale", 1);
        let ladder = Ladder { m, l, g };
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
        judge_scaled(&mut c, reference, &got, with_penalty);
        cases.push(c);
    }
    cases
}

/// The corners of the scale cube m, l, g ∈ {1e-30, 1e30}, then a few mixed scales; the last
/// two with penalty springs (true).
fn corners() -> Vec<(f64, f64, f64, bool)> {
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
    corners
}

/// Give `sc` penalty springs of κ = 1e4.
fn penalty(sc: &mut Scene) {
    let l = sc.ladder;
    // κ = k l/(m g) = 1e4, formed as (1e4 m)(g/l) to stay within range; κ tol = 1e-9
    // keeps an explicit method accurate (see `stability::stiff`).
    sc.contact = ContactModel::Penalty {
        stiffness: 1e4 * l.m * (l.g / l.l),
        damping: 0.0,
    };
}

/// The verdict on a scaled run `got` against the unit-scale `reference`: the largest relative
/// difference of θ_s, t_s, θ̇_s and F_f.
fn judge_scaled(
    c: &mut Case,
    reference: &Result<([f64; 4], u64, u64), String>,
    got: &Result<([f64; 4], u64, u64), String>,
    with_penalty: bool,
) {
    match (reference, got) {
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
}
