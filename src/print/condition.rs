//! Conditions imposed on a model at an instant. An evaluation bar `…\Big|_{\mathbf{x}_P=0}` and a
//! display's premises (`*Premises:*`) are substitutions, never claims: the model is changed so
//! that the condition holds, and only what the condition names is changed. A condition at an
//! instant sets a position and leaves its rates free (x_P = 0 keeps P's velocity and
//! acceleration); `τ = 0` makes the particles' torques cancel in sum, not each vanish.
//!
//! A condition is a chain of forms `a = b = …`. Each form is a side the model can be made to
//! take (P's position, velocity or acceleration; the centre of mass's position; the total
//! force; the torque about the origin) or a value (`0`, the origin O′, G′ where the centre of
//! mass is now). Every settable side is given the value; with no value, the centre of mass's
//! position is the value (`x_P = x_cm`: P is put on it).

use super::ast::Expr;
use super::quantity::{Model, Value};
use crate::scalar::Scalar;
use crate::system::System;
use crate::vector::Vec3;

/// A side of a condition the model can be made to take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Settable {
    /// x_P (Milne's r₀, O).
    PointPosition,
    /// v_P.
    PointVelocity,
    /// a_P.
    PointAcceleration,
    /// x_cm (Milne's r̄, G): every particle is translated, velocities kept.
    CmPosition,
    /// F = Σ m_i a_i (only `= 0`).
    TotalForce,
    /// τ = Σ x_i × m_i a_i about the origin (only `= 0`).
    Torque,
}

impl Settable {
    /// The side a quantity id names, if the model can be made to take it.
    pub fn of(quantity: &str) -> Option<Settable> {
        Some(match quantity {
            "position:P" => Settable::PointPosition,
            "velocity:P" => Settable::PointVelocity,
            "acceleration:P" => Settable::PointAcceleration,
            "position:cm" => Settable::CmPosition,
            "total_force" => Settable::TotalForce,
            "torque:O" => Settable::Torque,
            _ => return None,
        })
    }
}

/// Impose the condition `forms[0] = forms[1] = …` on `model`. `quantity` names a symbol's
/// quantity; `value` evaluates a form that is not settable, in the model as given.
pub fn impose<S: Scalar>(
    model: &Model<S>,
    forms: &[Expr],
    quantity: impl Fn(&str) -> Option<String>,
    value: impl Fn(&Expr) -> Result<Value<S>, String>,
) -> Result<Model<S>, String> {
    let Model::Particles(sys, p, ..) = model else {
        return Err(
            "a condition on the ladder: its points move as the wall and floor make them".into(),
        );
    };
    let mut sides = Vec::new();
    let mut fixed = Vec::new();
    for f in forms {
        let settable = match f {
            Expr::Sym(k) => quantity(k).as_deref().and_then(Settable::of),
            _ => None,
        };
        match settable {
            Some(s) => sides.push(s),
            None => fixed.push(f),
        }
    }
    if fixed.len() > 1 {
        return Err("a condition with two sides that cannot be set".into());
    }
    let zero_literal = fixed.first().is_some_and(|f| **f == Expr::Int(0));
    let target: Vec3<S> = match fixed.first() {
        Some(Expr::Int(0)) => Vec3::zero(),
        Some(f) => match value(f)? {
            Value::Vector(v) => v,
            Value::Scalar(_) => return Err("a condition setting a vector to a scalar".into()),
        },
        None if sides.contains(&Settable::CmPosition) => {
            sides.retain(|s| *s != Settable::CmPosition);
            sys.centre_of_mass()
        }
        None => return Err("a condition with no value to set".into()),
    };
    let (mut sys, mut p) = (sys.clone(), p.clone());
    // The centre of mass first: a point put on it must see it where it goes.
    sides.sort_by_key(|s| *s != Settable::CmPosition);
    for side in sides {
        match side {
            Settable::CmPosition => {
                let shift = target.clone() - sys.centre_of_mass();
                for q in &mut sys.particles {
                    q.x = q.x.clone() + shift.clone();
                }
            }
            Settable::PointPosition => p.x = target.clone(),
            Settable::PointVelocity => p.v = target.clone(),
            Settable::PointAcceleration => p.a = target.clone(),
            Settable::TotalForce | Settable::Torque if !zero_literal => {
                return Err("a force or torque condition other than = 0".into())
            }
            Settable::TotalForce => force_free(&mut sys),
            Settable::Torque => torque_free(&mut sys),
        }
    }
    Ok(Model::particles(sys, p))
}

/// Σ m_i a_i = 0: every acceleration less the centre of mass's (a general force-free state:
/// any one is reached this way).
pub fn force_free<S: Scalar>(sys: &mut System<S>) {
    let a_cm = sys.cm_acceleration();
    for q in &mut sys.particles {
        q.a = q.a.clone() - a_cm.clone();
    }
}

/// Σ x_i × m_i a_i = 0 with the particles' torques cancelling in sum, not each vanishing: every
/// force is a central force m_i μ_i x_i plus a pair force m_i λ_i (x_i − x_j) along the line to
/// the next particle j (and from the last back to the first), equal and opposite on the two. A
/// pair's two torques, −m_i λ_i x_i × x_j and −m_i λ_i x_j × x_i, cancel; a central force has
/// none. μ_i = a_ix / s_i and λ_i = a_iy / s_i with s_i = x_ix + x_iy + x_iz (rates T⁻² from the
/// draw, so the dimensions hold; the symbolic proof runs on the same states).
/// For two particles these are all the torque-free forces (they must lie in the plane of x_1,
/// x_2); one particle can only have a central force.
pub fn torque_free<S: Scalar>(sys: &mut System<S>) {
    let n = sys.particles.len();
    let x: Vec<Vec3<S>> = sys.particles.iter().map(|q| q.x.clone()).collect();
    // A rate T⁻² from the draw: a component of a_i over the sum of x_i's components (a linear
    // form, so the symbolic proof meets only linear denominators; nonzero on the ladder's
    // particles, which sit on the axes).
    let rate = |q: &crate::system::Particle<S>, k: usize| {
        let a = q.a.components();
        a[k].clone() / (q.x.x.clone() + q.x.y.clone() + q.x.z.clone())
    };
    let mut f: Vec<Vec3<S>> = sys
        .particles
        .iter()
        .map(|q| q.x.scale(&(q.m.clone() * rate(q, 0))))
        .collect();
    let pairs = match n {
        1 => 0,
        2 => 1,
        _ => n,
    };
    for i in 0..pairs {
        let j = (i + 1) % n;
        let q = &sys.particles[i];
        let pull = (x[i].clone() - x[j].clone()).scale(&(q.m.clone() * rate(q, 1)));
        f[i] = f[i].clone() + pull.clone();
        f[j] = f[j].clone() - pull;
    }
    for (q, f) in sys.particles.iter_mut().zip(f) {
        q.a = f.div(&q.m);
    }
}
