//! The state a display is shown at: the user's `--at` (or the book's worked example), completed
//! on the motion and built in f64, with running error bounds, and exactly when it can be.
//!
//! Unless given, θ̇ comes from the energy of a release at rest at θ0 (θ0 = 0 unless given):
//! (2/3) m l² θ̇² + m g l cos θ = m g l cos θ0, so θ̇² = (3g/2l)(cos θ0 − cos θ), which is (10)
//! for θ0 = 0; θ̈ from the equation of motion (5), and θ⃛ = Ω² cos θ θ̇ (the d/dt of (5)), so
//! the state lies on the motion. A θ̈ given by the user is used as it is (θ⃛ = 0 unless given):
//! an off-motion look, where on-shell displays must break at their law step.

use super::at::{rational_sqrt, to_f64, Angle, At};
use crate::ladder::energy::angular_acceleration;
use crate::ladder::{Ladder, State};
use crate::scalar::{Bound, Rational, Scalar, UNIT_ROUNDOFF};
use num_traits::One;
use serde::Serialize;

/// The state, in every scalar it is evaluated in.
#[derive(Clone, Debug)]
pub struct Point {
    /// In f64.
    pub float: (Ladder<f64>, State<f64>),
    /// The same values with running error bounds (the tolerance of every agreement).
    pub bound: (Ladder<Bound>, State<Bound>),
    /// Exactly, when every input is rational (else `None`, and `why_not_exact` says why).
    pub exact: Option<(Ladder<Rational>, State<Rational>)>,
    /// What the user gave and what was completed, for the report.
    pub summary: Summary,
}

/// The state in words and numbers (the JSON's `state`).
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// m, kg.
    pub m: f64,
    /// l, m.
    pub l: f64,
    /// g, m/s².
    pub g: f64,
    /// θ, rad.
    pub theta: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// θ0 when θ̇ comes from the energy, rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theta0: Option<f64>,
    /// θ̇, rad/s.
    pub theta_dot: f64,
    /// θ̈, rad/s².
    pub theta_ddot: f64,
    /// θ⃛, rad/s³.
    pub theta_dddot: f64,
    /// True when θ̈ comes from (5) (the state is on the motion).
    pub on_motion: bool,
    /// Where each value came from, in words.
    pub how: Vec<String>,
    /// Why the state is not exact, when it is not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why_not_exact: Option<String>,
    /// The contact forces there, the phase of the fall and a warning for a force that would pull.
    pub phase: super::phase::Phase,
}

/// The book's worked example (`docs::worked::EXAMPLE`): m = 1 kg, l = 1 m, g = 9.81 m/s²,
/// θ = 30°, released at rest upright.
pub fn default_at() -> At {
    let (m, l, g, deg) = crate::docs::worked::EXAMPLE;
    let q = |x: f64| Rational::from_float(x).unwrap_or_else(Rational::one);
    At {
        m: Some(q(m)),
        l: Some(q(l)),
        // 9.81 as the decimal it is written as, not its nearest double.
        g: Some(if g == 9.81 {
            Rational::new(981.into(), 100.into())
        } else {
            q(g)
        }),
        theta: Some(Angle::Radians(deg.to_radians())),
        ..At::default()
    }
}

/// Complete a user state (missing m, l, g, θ from the worked example) and build it.
pub fn build(at: &At) -> Point {
    let d = default_at();
    let mut how = Vec::new();
    let mut pick = |v: &Option<Rational>, dv: &Option<Rational>, name: &str| {
        v.clone().unwrap_or_else(|| {
            how.push(format!("{name} from the worked example"));
            dv.clone().unwrap_or_else(Rational::one)
        })
    };
    let (m, l, g) = (
        pick(&at.m, &d.m, "m"),
        pick(&at.l, &d.l, "l"),
        pick(&at.g, &d.g, "g"),
    );
    let theta = at.theta.clone().unwrap_or_else(|| {
        how.push("θ = 30° from the worked example".into());
        d.theta.clone().unwrap_or(Angle::Radians(0.0))
    });
    let mut why_not: Option<String> = None;
    let exact_theta = theta.exact();
    if exact_theta.is_none() {
        why_not = Some(
            "θ has no rational sin and cos (give sin_theta=3/5, cos_theta=…, or tan_half_theta=… for an exact state)"
                .into(),
        );
    }
    let (s, c, trig_units) = theta.float();
    let flt = |q: &Rational| to_f64(q);
    let bnd = |q: &Rational| {
        let x = to_f64(q);
        // A rational that is not a double is rounded once.
        let units = if Rational::from_float(x).as_ref() == Some(q) {
            0.0
        } else {
            1.0
        };
        Bound::inexact(x, units)
    };
    let ladder_f = Ladder {
        m: flt(&m),
        l: flt(&l),
        g: flt(&g),
    };
    let ladder_b = Ladder {
        m: bnd(&m),
        l: bnd(&l),
        g: bnd(&g),
    };
    let ladder_q = Ladder {
        m: m.clone(),
        l: l.clone(),
        g: g.clone(),
    };
    let (sb, cb) = (Bound::inexact(s, trig_units), Bound::inexact(c, trig_units));

    // θ̇: given, or from the energy of a release at rest at θ0.
    let (rate_f, rate_b, rate_q, theta0) = match &at.rate {
        Some(r) => {
            how.push("θ̇ given".into());
            (flt(r), bnd(r), Some(r.clone()), None)
        }
        None => {
            let t0 = at.theta0.clone().unwrap_or(Angle::Radians(0.0));
            let (_, c0, u0) = t0.float();
            let q_b = Bound::ratio(3, 2) * ladder_b.g / ladder_b.l * (Bound::inexact(c0, u0) - cb);
            let (rate_f, rate_b) = sqrt_bound(q_b);
            let rate_q = match (t0.exact(), &exact_theta) {
                (Some((_, c0q)), Some((_, cq))) => {
                    let q = Rational::new(3.into(), 2.into()) * g.clone() / l.clone()
                        * (c0q - cq.clone());
                    let r = rational_sqrt(&q);
                    if r.is_none() && why_not.is_none() {
                        why_not = Some(format!(
                            "θ̇² = (3g/2l)(cos θ0 − cos θ) = {q} is not the square of a rational (give theta_dot for an exact state)"
                        ));
                    }
                    r
                }
                _ => {
                    if why_not.is_none() {
                        why_not = Some("θ0 has no rational cos (give cos_theta0=…)".into());
                    }
                    None
                }
            };
            how.push(format!(
                "θ̇ from the energy, released at rest at θ0 = {}° (θ̇² = (3g/2l)(cos θ0 − cos θ); (10) when θ0 = 0)",
                format!("{:.6}", t0.radians().to_degrees()).trim_end_matches('0').trim_end_matches('.')
            ));
            (rate_f, rate_b, rate_q, Some(t0.radians()))
        }
    };
    let on_motion = at.accel.is_none();
    how.push(if on_motion {
        "θ̈ from (5), θ⃛ = Ω² cos θ θ̇ (its d/dt): on the motion".into()
    } else {
        format!(
            "θ̈ given (off the motion unless it equals (5)), θ⃛ {}",
            if at.jerk.is_some() { "given" } else { "= 0" }
        )
    });
    let float = complete(
        ladder_f,
        s,
        c,
        rate_f,
        at.accel.as_ref().map(flt),
        at.jerk.as_ref().map(flt),
    );
    let bound = complete(
        ladder_b,
        sb,
        cb,
        rate_b,
        at.accel.as_ref().map(bnd),
        at.jerk.as_ref().map(bnd),
    );
    let exact = match (exact_theta, rate_q) {
        (Some((sq, cq)), Some(rq)) => Some(complete(
            ladder_q,
            sq,
            cq,
            rq,
            at.accel.clone(),
            at.jerk.clone(),
        )),
        _ => None,
    };
    let fs = &float.1;
    let phase = super::phase::phase(&float, &bound, on_motion, theta0);
    Point {
        summary: Summary {
            m: float.0.m,
            l: float.0.l,
            g: float.0.g,
            theta: theta.radians(),
            theta_deg: theta.radians().to_degrees(),
            theta0,
            theta_dot: fs.rate,
            theta_ddot: fs.accel,
            theta_dddot: fs.jerk,
            on_motion,
            how,
            why_not_exact: if exact.is_some() { None } else { why_not },
            phase,
        },
        float,
        bound,
        exact,
    }
}

/// θ̈ from (5) and θ⃛ = Ω² cos θ θ̇ unless given (θ⃛ = 0 when only θ̈ is given).
fn complete<S: Scalar>(
    ladder: Ladder<S>,
    sin: S,
    cos: S,
    rate: S,
    accel: Option<S>,
    jerk: Option<S>,
) -> (Ladder<S>, State<S>) {
    let mut st = State {
        sin,
        cos: cos.clone(),
        rate: rate.clone(),
        accel: S::int(0),
        jerk: S::int(0),
    };
    match accel {
        Some(a) => {
            st.accel = a;
            st.jerk = jerk.unwrap_or_else(|| S::int(0));
        }
        None => {
            st.accel = angular_acceleration(&ladder, &st);
            st.jerk = jerk.unwrap_or_else(|| ladder.big_omega2() * cos * rate);
        }
    }
    (ladder, st)
}

/// √q with its error bound: relative error ½ e_q/|q| plus one rounding; at q = 0 computed with
/// error, the root can be as large as √(e_q u).
fn sqrt_bound(q: Bound) -> (f64, Bound) {
    let v = q.v.max(0.0).sqrt();
    let e = if q.v > 0.0 {
        v * (0.5 * q.e / q.v + 1.0)
    } else {
        (q.e * UNIT_ROUNDOFF).sqrt() / UNIT_ROUNDOFF
    };
    (v, Bound { v, e })
}

impl Point {
    /// True when θ̇ and θ̈ are exact, θ rational on the unit circle.
    pub fn is_exact(&self) -> bool {
        self.exact.is_some()
    }
}
