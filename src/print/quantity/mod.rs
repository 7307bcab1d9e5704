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

mod by_name;

use crate::ladder::geometry::corner_position;
use crate::ladder::geometry::Corner;
use crate::ladder::particles::as_system;
use crate::ladder::{Ladder, State};
use crate::scalar::Scalar;
use crate::system::{Point, System};
use crate::vector::Vec3;
use by_name::whole;
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
