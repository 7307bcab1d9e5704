//! The model quantities that printed symbols denote, computed from the independent models: the
//! three-particle ladder ([`crate::ladder::particles`]) or a general system of particles with a
//! moving point P ([`crate::system`]). Velocities and accelerations come from automatic
//! differentiation along the motion; contact forces are those the motion requires.
//!
//! A quantity id is a name, optionally `:point` and `.x`/`.y`/`.z` for a component:
//! `angular_momentum:A.z` is the z component of the angular momentum about A. A point is one of
//! the note's (A-E, cm, O; P of a particle sample), a point of the ladder by the fraction of the
//! way from C to D (`ladder:1/4`), or a point fixed in the lab in units of l (`lab:1/2,3/2`)
//! ([`super::point::parse_point`]).

use super::point::parse_point;
use crate::ladder::analysis::{Reference, ReferencePoint};
use crate::ladder::geometry::corner_position;
use crate::ladder::geometry::Corner;
use crate::ladder::particles::{
    as_system, external_torque_about, floor_force_from_motion, wall_force_from_motion,
};
use crate::ladder::{Ladder, State};
use crate::scalar::Scalar;
use crate::system::{Point, System};
use crate::vector::Vec3;
use std::cell::OnceCell;

/// How to lift a context for a derivative.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lift {
    /// Along the motion (d/dt).
    Motion,
    /// θ alone (∂/∂θ).
    Angle,
    /// θ̇ alone (∂/∂θ̇).
    Rate,
}

/// A value: a scalar or a 3-vector.
#[derive(Clone, Debug)]
pub enum Value<S> {
    /// A scalar.
    Scalar(S),
    /// A vector.
    Vector(Vec3<S>),
}

impl<S: Scalar> Value<S> {
    pub(super) fn neg(self) -> Self {
        match self {
            Value::Scalar(x) => Value::Scalar(-x),
            Value::Vector(v) => Value::Vector(v.scale(&S::int(-1))),
        }
    }
    pub(super) fn add(self, o: Self) -> Result<Self, String> {
        match (self, o) {
            (Value::Scalar(a), Value::Scalar(b)) => Ok(Value::Scalar(a + b)),
            (Value::Vector(a), Value::Vector(b)) => Ok(Value::Vector(a + b)),
            _ => Err("a scalar added to a vector".into()),
        }
    }
    pub(super) fn mul(self, o: Self) -> Result<Self, String> {
        match (self, o) {
            (Value::Scalar(a), Value::Scalar(b)) => Ok(Value::Scalar(a * b)),
            (Value::Scalar(a), Value::Vector(v)) | (Value::Vector(v), Value::Scalar(a)) => {
                Ok(Value::Vector(v.scale(&a)))
            }
            _ => Err("an implicit product of two vectors".into()),
        }
    }
    /// The components (one for a scalar, three for a vector).
    pub fn components(&self) -> Vec<S> {
        match self {
            Value::Scalar(x) => vec![x.clone()],
            Value::Vector(v) => v.components().to_vec(),
        }
    }
}

/// The ε part of a lifted value: its derivative.
pub(super) fn eps<S: Scalar>(v: Value<S::Dual>) -> Value<S> {
    match v {
        Value::Scalar(x) => Value::Scalar(S::split(x).1),
        Value::Vector(v) => Value::Vector(Vec3::<S>::derivative_of(&v)),
    }
}

/// The model a form is evaluated in.
#[derive(Clone, Debug)]
pub enum Model<S> {
    /// The ladder of the note (both contacts hold), with its three-particle system (built once)
    /// and the lab point where C is at the instant of evaluation (Hu's fixed point, sec. A.5).
    Ladder {
        /// m, l, g.
        ladder: Ladder<S>,
        /// θ (as sin, cos) and its derivatives.
        state: State<S>,
        /// Where C is at the instant of evaluation (constant under d/dt).
        c_now: Vec3<S>,
        /// The three-particle system, built on first use.
        sys: OnceCell<System<S>>,
        /// The motion of the points A-E, built on first use.
        corners: [OnceCell<Point<S>>; 5],
    },
    /// A system of particles and a reference point P (and the centre of mass's motion, built on
    /// first use), and the lab point where the centre of mass is at the instant of evaluation
    /// (Milne's G′, constant under d/dt).
    Particles(System<S>, Point<S>, OnceCell<Point<S>>, Vec3<S>),
}

impl<S: Scalar> Model<S> {
    /// The ladder model at a state.
    pub fn ladder(ladder: Ladder<S>, state: State<S>) -> Self {
        let c_now = corner_position(Corner::C, &ladder, &state);
        Model::Ladder {
            ladder,
            state,
            c_now,
            sys: OnceCell::new(),
            corners: Default::default(),
        }
    }
    /// A particle system with a reference point.
    pub fn particles(sys: System<S>, p: Point<S>) -> Self {
        let g_now = sys.centre_of_mass();
        Model::Particles(sys, p, OnceCell::new(), g_now)
    }
    pub(super) fn lifted(&self, how: Lift) -> Result<Model<S::Dual>, String> {
        Ok(match (self, how) {
            (
                Model::Ladder {
                    ladder,
                    state,
                    c_now,
                    corners: known,
                    ..
                },
                _,
            ) => {
                let sys = OnceCell::new();
                let corners: [OnceCell<Point<S::Dual>>; 5] = Default::default();
                let state = match how {
                    Lift::Motion => {
                        // The particles' and points' own lift (x → x + v ε, ...): no new
                        // differentiation.
                        let _ = sys.set(self.system().along_motion());
                        for (k, p) in known.iter().enumerate() {
                            if let Some(p) = p.get() {
                                let _ = corners[k].set(p.along_motion());
                            }
                        }
                        state.along_motion()
                    }
                    Lift::Angle => state.vary_angle(),
                    Lift::Rate => state.vary_rate(),
                };
                Model::Ladder {
                    ladder: ladder.constant(),
                    state,
                    c_now: c_now.constant(),
                    sys,
                    corners,
                }
            }
            (Model::Particles(sys, p, cm, g_now), Lift::Motion) => {
                let lifted_cm = OnceCell::new();
                if let Some(c) = cm.get() {
                    let _ = lifted_cm.set(c.along_motion());
                }
                Model::Particles(
                    sys.along_motion(),
                    p.along_motion(),
                    lifted_cm,
                    g_now.constant(),
                )
            }
            _ => return Err("∂/∂θ of a particle system".into()),
        })
    }
    pub(super) fn trig(&self, sin: bool) -> Result<Value<S>, String> {
        match self {
            Model::Ladder { state: s, .. } => Ok(Value::Scalar(if sin {
                s.sin.clone()
            } else {
                s.cos.clone()
            })),
            Model::Particles(..) => Err("θ in a general particle system".into()),
        }
    }
    pub(super) fn particle_count(&self) -> Result<usize, String> {
        Ok(self.system().particles.len())
    }
    fn system(&self) -> &System<S> {
        match self {
            Model::Ladder {
                ladder, state, sys, ..
            } => sys.get_or_init(|| as_system(ladder, state)),
            Model::Particles(sys, ..) => sys,
        }
    }
}

/// Resolve a quantity id in a model (`index`: the particle a Σ is at; particle 0 outside one).
pub fn resolve<S: Scalar>(
    id: &str,
    index: Option<usize>,
    model: &Model<S>,
) -> Result<Value<S>, String> {
    let (base, comp) = match id.rsplit_once('.') {
        Some((b, c)) if matches!(c, "x" | "y" | "z") => (b, Some(c)),
        _ => (id, None),
    };
    let v = whole(base, index, model)?;
    Ok(match (comp, v) {
        (None, v) => v,
        (Some(c), Value::Vector(v)) => Value::Scalar(match c {
            "x" => v.x,
            "y" => v.y,
            _ => v.z,
        }),
        (Some(_), Value::Scalar(_)) => return Err(format!("a component of the scalar {base}")),
    })
}

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

fn whole<S: Scalar>(id: &str, index: Option<usize>, model: &Model<S>) -> Result<Value<S>, String> {
    use Value::{Scalar as Sc, Vector as Ve};
    let (name, at) = match id.split_once(':') {
        Some((n, a)) => (n, Some(a)),
        None => (id, None),
    };
    let sys = model.system();
    let m = match model {
        Model::Ladder { ladder, .. } => ladder.m.clone(),
        Model::Particles(sys, ..) => sys.total_mass(),
    };
    // The reference point: a corner of the ladder, or P of a particle sample; "O" the origin.
    let point = |at: Option<&str>| -> Result<Point<S>, String> {
        match (model, at) {
            (_, Some("O")) => Ok(Point::fixed(Vec3::zero())),
            (Model::Particles(.., g_now), Some("Gnow")) => Ok(Point::fixed(g_now.clone())),
            (Model::Particles(_, _, cm, _), Some("cm")) => {
                Ok(cm.get_or_init(|| sys.cm_point()).clone())
            }
            (_, Some("cm")) => Ok(sys.cm_point()),
            // The lab point where C is at this instant (at rest).
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
    };
    let i = index.unwrap_or(0);
    let particle = || {
        sys.particles
            .get(i)
            .cloned()
            .ok_or_else(|| format!("no particle {i}"))
    };
    Ok(match name {
        "theta" => return Err("θ appears only under sin and cos".into()),
        "theta_rate" | "theta_accel" => match model {
            Model::Ladder { state: s, .. } => Sc(if name == "theta_rate" {
                s.rate.clone()
            } else {
                s.accel.clone()
            }),
            _ => return Err("θ̇ in a particle system".into()),
        },
        "m" => Sc(m),
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
        "energy_at_rest_upright" => match model {
            Model::Ladder { ladder: l, .. } => {
                let z = S::int(0);
                let up = State {
                    sin: z.clone(),
                    cos: S::int(1),
                    rate: z.clone(),
                    accel: z.clone(),
                    jerk: z,
                };
                let s0 = as_system(l, &up);
                Sc(kinetic(&s0) + potential(model, &s0)?)
            }
            _ => return Err("E_0 in a particle system".into()),
        },
        "moment_of_inertia" => Sc(sys.moment_of_inertia_about(&point(at)?.x)),
        "wall_force" => Sc(wall_force_from_motion(sys)),
        "floor_force" => match model {
            Model::Ladder { ladder: l, .. } => Sc(floor_force_from_motion(l, sys)),
            _ => return Err("F_f in a particle system".into()),
        },
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
        "total_force" => Ve(sys.total_force()),
        "momentum" => Ve(sys.momentum()),
        "zhat" => Ve(Vec3::along_z(S::int(1))),
        "origin" => Ve(Vec3::zero()),
        "angular_velocity" => {
            Sc(angular_velocity(model, sys)?).mul(Ve(Vec3::along_z(S::int(1))))?
        }
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
        "particle_position_from" => Ve(particle()?.x - point(at)?.x),
        "particle_velocity_from" => Ve(particle()?.v - point(at)?.v),
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
