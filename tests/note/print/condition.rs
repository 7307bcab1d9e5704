//! `sliding_ladder::print::condition`: conditions imposed at an instant, and the premise-exact
//! particle samples built on them (issue 37).

use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::print::ast::Expr;
use sliding_ladder::print::condition::impose;
use sliding_ladder::print::quantity::{Model, Value};
use sliding_ladder::registry::sample::{particle_system, ParticleSample, EXTRA, PER_PARTICLE};
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::system::System;
use sliding_ladder::vector::Vec3;

/// Exact particle values: small distinct integers (masses positive), so no coordinate sum is 0.
fn values(n: usize) -> Vec<Rational> {
    (0..n * PER_PARTICLE + EXTRA)
        .map(|i| {
            let k = i as i64;
            if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                Rational::int(k + 2)
            } else {
                Rational::int((k * 7919) % 23 - 11 + i64::from(k % 5 == 0) * 3)
            }
        })
        .collect()
}

fn torques(sys: &System<Rational>) -> Vec<Vec3<Rational>> {
    sys.particles
        .iter()
        .map(|q| q.x.cross(&q.force()))
        .collect()
}

fn is_zero(v: &Vec3<Rational>) -> bool {
    v.components().iter().all(|c| *c == Rational::int(0))
}

#[test]
fn torque_free_states_cancel_in_sum_and_not_each() {
    for n in 2..=4 {
        let (sys, _) = particle_system(ParticleSample::TorqueFree, n, &values(n));
        let each = torques(&sys);
        let total = each.iter().fold(Vec3::zero(), |a, t| a + t.clone());
        assert!(is_zero(&total), "n = {n}: Σ x_i × F_i = {total:?}");
        // The old sampler made every torque vanish; the premise τ = 0 asks only the sum.
        assert!(
            each.iter().any(|t| !is_zero(t)),
            "n = {n}: every torque is zero"
        );
    }
    // The check can fail: a general draw has a torque.
    let (sys, _) = particle_system(ParticleSample::General, 3, &values(3));
    let total = torques(&sys).into_iter().fold(Vec3::zero(), |a, t| a + t);
    assert!(!is_zero(&total));
}

#[test]
fn p_at_cm_is_an_instant_and_a_velocity_not_a_motion() {
    let (sys, p) = particle_system(ParticleSample::PAtCm, 3, &values(3));
    assert_eq!(p.x, sys.centre_of_mass());
    assert_eq!(p.v, sys.cm_velocity());
    // a_P stays free: riding on the centre of mass (a_P = a_cm) is more than (41) assumes.
    assert_ne!(p.a, sys.cm_acceleration());
}

fn cond(forms: &[Expr], model: &Model<Rational>) -> Result<Model<Rational>, String> {
    let quantity = |k: &str| {
        Some(
            match k {
                "xP" => "position:P",
                "vP" => "velocity:P",
                "xcm" => "position:cm",
                "F" => "total_force",
                "tau" => "torque:O",
                _ => return None,
            }
            .to_string(),
        )
    };
    // Any side that is not settable has the value (2, 2, 2).
    let two = || {
        Value::Vector(Vec3::new(
            Rational::int(2),
            Rational::int(2),
            Rational::int(2),
        ))
    };
    impose(model, forms, quantity, |_| Ok(two()))
}

fn sym(k: &str) -> Expr {
    Expr::Sym(k.into())
}

#[test]
fn an_instant_condition_sets_the_position_and_keeps_the_rates() {
    let (sys, p) = particle_system(ParticleSample::General, 3, &values(3));
    let m = Model::particles(sys.clone(), p.clone());
    let Model::Particles(_, q, ..) = cond(&[sym("xP"), Expr::Int(0)], &m).unwrap() else {
        panic!("a particle model")
    };
    assert_eq!(q.x, Vec3::zero());
    assert_eq!((q.v, q.a), (p.v.clone(), p.a.clone()));
    // x_P = x_cm = 0: the centre of mass moved to the origin by a translation, P with it.
    let Model::Particles(s2, q2, ..) = cond(&[sym("xP"), sym("xcm"), Expr::Int(0)], &m).unwrap()
    else {
        panic!("a particle model")
    };
    assert_eq!(s2.centre_of_mass(), Vec3::zero());
    assert_eq!(q2.x, Vec3::zero());
    assert_eq!(s2.cm_velocity(), sys.cm_velocity());
    // F = 0 and τ = 0 hold after imposing them (and did not before).
    for (k, pick) in [("F", 0), ("tau", 1)] {
        let read = |m: &Model<Rational>| {
            let Model::Particles(s, ..) = m else { panic!() };
            if pick == 0 {
                s.total_force()
            } else {
                s.torque_about(&Vec3::zero())
            }
        };
        assert!(!is_zero(&read(&m)));
        assert!(
            is_zero(&read(&cond(&[sym(k), Expr::Int(0)], &m).unwrap())),
            "{k}"
        );
    }
}

#[test]
fn a_condition_the_model_cannot_take_is_an_error_never_ignored() {
    let (sys, p) = particle_system(ParticleSample::General, 2, &values(2));
    let m = Model::particles(sys, p);
    let e = cond(&[sym("unknown"), sym("other")], &m).unwrap_err();
    assert!(e.contains("two sides"), "{e}");
    let e = cond(&[sym("F"), sym("two")], &m).unwrap_err();
    assert!(e.contains("other than = 0"), "{e}");
    // On the ladder the points move as wall and floor make them: no bar can move them.
    let one = Rational::int(1);
    let ladder = Ladder {
        m: one.clone(),
        l: one.clone(),
        g: one.clone(),
    };
    let st = State {
        sin: Rational::ratio(3, 5),
        cos: Rational::ratio(4, 5),
        rate: one.clone(),
        accel: one.clone(),
        jerk: one,
    };
    let e = cond(&[sym("xP"), Expr::Int(0)], &Model::ladder(ladder, st)).unwrap_err();
    assert!(e.contains("ladder"), "{e}");
}
