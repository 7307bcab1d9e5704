//! The quantity a name denotes (`angular_momentum:A`, without a component), computed in the
//! model: the state's own quantities, those about a reference point, and those of one particle.

use super::{Model, Value};
use crate::ladder::analysis::{Reference, ReferencePoint};
use crate::ladder::geometry::Corner;
use crate::ladder::particles::{
    as_system, external_torque_about, floor_force_from_motion, wall_force_from_motion,
};
use crate::ladder::State;
use crate::print::point::parse_point;
use crate::scalar::Scalar;
use crate::system::{Particle, Point, System};
use crate::vector::Vec3;

/// The value of quantity `id` (`name` or `name:point`, no component) in `model`, at particle
/// `index` (particle 0 outside a Σ).
pub(super) fn whole<S: Scalar>(
    id: &str,
    index: Option<usize>,
    model: &Model<S>,
) -> Result<Value<S>, String> {
    let (name, at) = match id.split_once(':') {
        Some((n, a)) => (n, Some(a)),
        None => (id, None),
    };
    let sys = model.system();
    let m = match model {
        Model::Ladder { ladder, .. } => ladder.m.clone(),
        Model::Particles(sys, ..) => sys.total_mass(),
    };
    if let Some(v) = state_quantity(name, model, sys, &m)? {
        return Ok(v);
    }
    if let Some(v) = particle_quantity(name, at, index, model, sys, id)? {
        return Ok(v);
    }
    point_quantity(name, at, model, sys, m, id)
}

/// A quantity of the state as a whole (θ̇, θ̈, m, l, g, the energies, the contact forces, the
/// momentum, ω), or `None` when `name` is not one.
fn state_quantity<S: Scalar>(
    name: &str,
    model: &Model<S>,
    sys: &System<S>,
    m: &S,
) -> Result<Option<Value<S>>, String> {
    use Value::{Scalar as Sc, Vector as Ve};
    Ok(Some(match name {
        "theta" => return Err("θ appears only under sin and cos".into()),
        "theta_rate" | "theta_accel" => match model {
            Model::Ladder { state: s, .. } => Sc(if name == "theta_rate" {
                s.rate.clone()
            } else {
                s.accel.clone()
            }),
            _ => return Err("θ̇ in a particle system".into()),
        },
        "m" => Sc(m.clone()),
        "l" | "g" => match model {
            Model::Ladder { ladder: l, .. } => Sc(if name == "l" {
                l.l.clone()
            } else {
                l.g.clone()
            }),
            _ => return Err(format!("{name} in a particle system")),
        },
        "kinetic_energy" => Sc(kinetic(sys)),
        "potential_energy" => Sc(potential(model, sys)?),
        "lagrangian" => Sc(kinetic(sys) - potential(model, sys)?),
        "energy" => Sc(kinetic(sys) + potential(model, sys)?),
        "energy_at_rest_upright" => Sc(energy_at_rest_upright(model)?),
        "wall_force" => Sc(wall_force_from_motion(sys)),
        "floor_force" => match model {
            Model::Ladder { ladder: l, .. } => Sc(floor_force_from_motion(l, sys)),
            _ => return Err("F_f in a particle system".into()),
        },
        "total_force" => Ve(sys.total_force()),
        "momentum" => Ve(sys.momentum()),
        "zhat" => Ve(Vec3::along_z(S::int(1))),
        "origin" => Ve(Vec3::zero()),
        "angular_velocity" => {
            Sc(angular_velocity(model, sys)?).mul(Ve(Vec3::along_z(S::int(1))))?
        }
        _ => return Ok(None),
    }))
}

/// A quantity of particle `index` (its mass, motion, force, momentum, and those about a point),
/// or `None` when `name` is not one.
fn particle_quantity<S: Scalar>(
    name: &str,
    at: Option<&str>,
    index: Option<usize>,
    model: &Model<S>,
    sys: &System<S>,
    id: &str,
) -> Result<Option<Value<S>>, String> {
    use Value::{Scalar as Sc, Vector as Ve};
    let particle = || particle_at(sys, index.unwrap_or(0));
    Ok(Some(match name {
        "particle_mass" => Sc(particle()?.m),
        "particle_position" => Ve(particle()?.x),
        "particle_velocity" => Ve(particle()?.v),
        "particle_acceleration" => Ve(particle()?.a),
        "particle_force" => Ve(particle()?.force()),
        "particle_momentum" => Ve(particle()?.momentum()),
        "particle_angular_momentum" => {
            let q = particle()?;
            Ve(q.x.cross(&q.momentum()))
        }
        "particle_torque" => {
            let q = particle()?;
            Ve(q.x.cross(&q.force()))
        }
        "particle_position_from" => Ve(particle()?.x - reference_point(model, sys, at, id)?.x),
        "particle_velocity_from" => Ve(particle()?.v - reference_point(model, sys, at, id)?.v),
        _ => return Ok(None),
    }))
}

/// Particle `i` of the system.
fn particle_at<S: Scalar>(sys: &System<S>, i: usize) -> Result<Particle<S>, String> {
    sys.particles
        .get(i)
        .cloned()
        .ok_or_else(|| format!("no particle {i}"))
}

/// A quantity about the reference point `at` (the moment of inertia, the point's motion, the
/// angular momentum and torque, the coordinate force); an unknown `name` is an error.
fn point_quantity<S: Scalar>(
    name: &str,
    at: Option<&str>,
    model: &Model<S>,
    sys: &System<S>,
    m: S,
    id: &str,
) -> Result<Value<S>, String> {
    use Value::{Scalar as Sc, Vector as Ve};
    let point = |at: Option<&str>| reference_point(model, sys, at, id);
    Ok(match name {
        "moment_of_inertia" => Sc(sys.moment_of_inertia_about(&point(at)?.x)),
        "position" => Ve(point(at)?.x),
        "velocity" => Ve(point(at)?.v),
        "acceleration" => Ve(point(at)?.a),
        "coordinate_force" => Ve(point(at)?.a.scale(&(-m))),
        "angular_momentum" => Ve(sys.angular_momentum_about(&point(at)?)),
        "relative_angular_momentum" => Ve(sys.relative_angular_momentum_about(&point(at)?)),
        "torque" => Ve(match model {
            Model::Ladder { ladder: l, .. } => external_torque_about(l, sys, &point(at)?.x),
            Model::Particles(..) => sys.torque_about(&point(at)?.x),
        }),
        "relative_torque" => {
            let p = point(at)?;
            let tau = match model {
                Model::Ladder { ladder: l, .. } => external_torque_about(l, sys, &p.x),
                Model::Particles(..) => sys.torque_about(&p.x),
            };
            Ve(tau + (sys.centre_of_mass() - p.x.clone()).cross(&p.a.scale(&(-m))))
        }
        "cm_from" => Ve(sys.centre_of_mass() - point(at)?.x),
        "modified_torque" => {
            let (Model::Ladder { ladder: l, .. }, p) = (model, point(at)?) else {
                return Err("the modified torque is the ladder's".into());
            };
            let tau = external_torque_about(l, sys, &p.x);
            Ve(tau + sys.cm_velocity().scale(&m).cross(&p.v))
        }
        _ => return Err(format!("unknown quantity '{id}' (symbols.toml)")),
    })
}

/// The reference point `at`: a corner of the ladder or a point of it or of the lab
/// ([`parse_point`]), P of a particle sample, the centre of mass; "O" the origin, "Cfixed" and
/// "Gnow" the lab points where C and the centre of mass are at this instant (at rest).
fn reference_point<S: Scalar>(
    model: &Model<S>,
    sys: &System<S>,
    at: Option<&str>,
    id: &str,
) -> Result<Point<S>, String> {
    match (model, at) {
        (_, Some("O")) => Ok(Point::fixed(Vec3::zero())),
        (Model::Particles(.., g_now), Some("Gnow")) => Ok(Point::fixed(g_now.clone())),
        (Model::Particles(_, _, cm, _), Some("cm")) => {
            Ok(cm.get_or_init(|| sys.cm_point()).clone())
        }
        (_, Some("cm")) => Ok(sys.cm_point()),
        (Model::Ladder { c_now, .. }, Some("Cfixed")) => Ok(Point::fixed(c_now.clone())),
        (Model::Ladder { ladder, state, .. }, Some(k)) if parse_point(k).is_some() => {
            let r = parse_point(k).ok_or_else(|| format!("no point {k}"))?;
            Ok(r.motion(ladder, state))
        }
        (
            Model::Ladder {
                ladder,
                state,
                corners,
                ..
            },
            Some(k),
        ) => {
            let c = corner(k)?;
            let slot = Corner::ALL.iter().position(|&x| x == c).unwrap_or(0);
            Ok(corners[slot]
                .get_or_init(|| Reference::Corner(c).motion(ladder, state))
                .clone())
        }
        (Model::Particles(_, p, ..), Some("P") | None) => Ok(p.clone()),
        (Model::Ladder { .. }, None) => Err(format!("{id} needs a point on the ladder")),
        (Model::Particles(..), Some(k)) => Err(format!("no point {k} in a particle system")),
    }
}

/// The corner of the ladder a point name denotes (B is the centre of mass).
fn corner(name: &str) -> Result<Corner, String> {
    Ok(match name {
        "A" => Corner::A,
        "B" | "cm" => Corner::B,
        "C" => Corner::C,
        "D" => Corner::D,
        "E" => Corner::E,
        _ => return Err(format!("no point {name} on the ladder")),
    })
}

/// E_0, the energy of the ladder at rest upright (θ = 0, θ̇ = 0).
fn energy_at_rest_upright<S: Scalar>(model: &Model<S>) -> Result<S, String> {
    let Model::Ladder { ladder: l, .. } = model else {
        return Err("E_0 in a particle system".into());
    };
    let z = S::int(0);
    let up = State {
        sin: z.clone(),
        cos: S::int(1),
        rate: z.clone(),
        accel: z.clone(),
        jerk: z,
    };
    let s0 = as_system(l, &up);
    Ok(kinetic(&s0) + potential(model, &s0)?)
}

/// Σ m_i v_i²/2.
fn kinetic<S: Scalar>(sys: &System<S>) -> S {
    sys.particles.iter().fold(S::int(0), |acc, q| {
        acc + q.m.clone() * q.v.dot(&q.v) * S::ratio(1, 2)
    })
}

/// Σ m_i g y_i (the ladder in the floor's gravity).
fn potential<S: Scalar>(model: &Model<S>, sys: &System<S>) -> Result<S, String> {
    let Model::Ladder { ladder: l, .. } = model else {
        return Err("potential energy of a general particle system".into());
    };
    Ok(sys.particles.iter().fold(S::int(0), |acc, q| {
        acc + q.m.clone() * l.g.clone() * q.x.y.clone()
    }))
}

/// The ladder's angular velocity about ẑ from the motion of its ends: (r × ṙ)_z / |r|², r = D − C;
/// for a rigid particle system, its spin.
fn angular_velocity<S: Scalar>(model: &Model<S>, sys: &System<S>) -> Result<S, String> {
    match model {
        Model::Ladder { .. } => {
            let (c, d) = (&sys.particles[0], &sys.particles[2]);
            let r = d.x.clone() - c.x.clone();
            let rv = d.v.clone() - c.v.clone();
            Ok(r.cross(&rv).z / r.dot(&r))
        }
        Model::Particles(sys, ..) => sys
            .spin
            .as_ref()
            .map(|s| s.omega.clone())
            .ok_or_else(|| "ω of a system that is not rigid".to_string()),
    }
}
