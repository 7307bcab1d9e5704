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
use crate::scalar::{rational_from_float, Bound, Rational, Scalar, UNIT_ROUNDOFF};
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
    let q = |x: f64| rational_from_float(x).unwrap_or_else(Rational::one);
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

/// Complete a user state (missing m, l, g, θ from the worked example) and build it: θ̇ given or
/// from the energy, θ̈ given or from (5), in f64, with error bounds, and exactly when it can be.
pub fn build(at: &At) -> Point {
    let d = default_at();
    let mut how = Vec::new();
    let ladder_q = Ladder {
        m: given_or_example(&at.m, &d.m, "m", &mut how),
        l: given_or_example(&at.l, &d.l, "l", &mut how),
        g: given_or_example(&at.g, &d.g, "g", &mut how),
    };
    let theta = at.theta.clone().unwrap_or_else(|| {
        how.push("θ = 30° from the worked example".into());
        d.theta.clone().unwrap_or(Angle::Radians(0.0))
    });
    let exact_theta = theta.exact();
    let mut why_not = exact_theta.is_none().then(|| {
        "θ has no rational sin and cos (give sin_theta=3/5, cos_theta=…, or tan_half_theta=… for an exact state)"
            .to_string()
    });
    let (s, c, trig_units) = theta.float();
    let (ladder_f, ladder_b) = (float_ladder(&ladder_q), bound_ladder(&ladder_q));
    let (sb, cb) = (Bound::inexact(s, trig_units), Bound::inexact(c, trig_units));
    let rate = rate_of(
        at,
        (&ladder_q, &ladder_b),
        cb,
        &exact_theta,
        &mut why_not,
        &mut how,
    );
    let on_motion = at.accel.is_none();
    how.push(accel_source(at));
    let (accel_f, jerk_f) = (at.accel.as_ref().map(to_f64), at.jerk.as_ref().map(to_f64));
    let float = complete(ladder_f, s, c, rate.float, accel_f, jerk_f);
    let (accel_b, jerk_b) = (
        at.accel.as_ref().map(bound_of),
        at.jerk.as_ref().map(bound_of),
    );
    let bound = complete(ladder_b, sb, cb, rate.bound, accel_b, jerk_b);
    let exact = match (exact_theta, rate.exact) {
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
    let phase = super::phase::phase(&float, &bound, on_motion, rate.theta0);
    let why_not_exact = if exact.is_some() { None } else { why_not };
    let summary = summary(
        &float,
        &theta,
        rate.theta0,
        on_motion,
        how,
        why_not_exact,
        phase,
    );
    Point {
        summary,
        float,
        bound,
        exact,
    }
}

/// A value the user gave, else the worked example's (noted in `how`).
fn given_or_example(
    v: &Option<Rational>,
    example: &Option<Rational>,
    name: &str,
    how: &mut Vec<String>,
) -> Rational {
    v.clone().unwrap_or_else(|| {
        how.push(format!("{name} from the worked example"));
        example.clone().unwrap_or_else(Rational::one)
    })
}

/// m, l, g in f64.
fn float_ladder(q: &Ladder<Rational>) -> Ladder<f64> {
    Ladder {
        m: to_f64(&q.m),
        l: to_f64(&q.l),
        g: to_f64(&q.g),
    }
}

/// m, l, g with their rounding as error bounds.
fn bound_ladder(q: &Ladder<Rational>) -> Ladder<Bound> {
    Ladder {
        m: bound_of(&q.m),
        l: bound_of(&q.l),
        g: bound_of(&q.g),
    }
}

/// A rational input as a `Bound`: a rational that is not a double is rounded once.
fn bound_of(q: &Rational) -> Bound {
    let x = to_f64(q);
    let units = if rational_from_float(x).as_ref() == Some(q) {
        0.0
    } else {
        1.0
    };
    Bound::inexact(x, units)
}

/// θ̇: given, or from the energy of a release at rest at θ0 ([`energy_rate`]).
fn rate_of(
    at: &At,
    ladders: (&Ladder<Rational>, &Ladder<Bound>),
    cb: Bound,
    exact_theta: &Option<(Rational, Rational)>,
    why_not: &mut Option<String>,
    how: &mut Vec<String>,
) -> Rate {
    let Some(r) = &at.rate else {
        return energy_rate(at, ladders, cb, exact_theta, why_not, how);
    };
    how.push("θ̇ given".into());
    Rate {
        float: to_f64(r),
        bound: bound_of(r),
        exact: Some(r.clone()),
        theta0: None,
    }
}

/// θ̇ in every scalar, and θ0 when it comes from the energy.
struct Rate {
    float: f64,
    bound: Bound,
    exact: Option<Rational>,
    theta0: Option<f64>,
}

/// θ̇ from the energy of a release at rest at θ0 (θ0 = 0 unless given):
/// θ̇² = (3g/2l)(cos θ0 − cos θ), which is (10) for θ0 = 0; exact when cos θ0 and cos θ are
/// rational and θ̇² is a rational square (else `why_not` says why, unless it already does).
fn energy_rate(
    at: &At,
    (ladder_q, ladder_b): (&Ladder<Rational>, &Ladder<Bound>),
    cb: Bound,
    exact_theta: &Option<(Rational, Rational)>,
    why_not: &mut Option<String>,
    how: &mut Vec<String>,
) -> Rate {
    let t0 = at.theta0.clone().unwrap_or(Angle::Radians(0.0));
    let (_, c0, u0) = t0.float();
    let q_b = Bound::ratio(3, 2) * ladder_b.g / ladder_b.l * (Bound::inexact(c0, u0) - cb);
    let (rate_f, rate_b) = sqrt_bound(q_b);
    let rate_q = match (t0.exact(), exact_theta) {
        (Some((_, c0q)), Some((_, cq))) => {
            let q = Rational::new(3.into(), 2.into()) * ladder_q.g.clone() / ladder_q.l.clone()
                * (c0q - cq.clone());
            let r = rational_sqrt(&q);
            if r.is_none() && why_not.is_none() {
                *why_not = Some(format!(
                    "θ̇² = (3g/2l)(cos θ0 − cos θ) = {q} is not the square of a rational (give theta_dot for an exact state)"
                ));
            }
            r
        }
        _ => {
            if why_not.is_none() {
                *why_not = Some("θ0 has no rational cos (give cos_theta0=…)".into());
            }
            None
        }
    };
    how.push(format!(
        "θ̇ from the energy, released at rest at θ0 = {}° (θ̇² = (3g/2l)(cos θ0 − cos θ); (10) when θ0 = 0)",
        format!("{:.6}", t0.radians().to_degrees()).trim_end_matches('0').trim_end_matches('.')
    ));
    Rate {
        float: rate_f,
        bound: rate_b,
        exact: rate_q,
        theta0: Some(t0.radians()),
    }
}

/// Where θ̈ and θ⃛ come from, in words: (5) and its d/dt on the motion, else as given.
fn accel_source(at: &At) -> String {
    if at.accel.is_none() {
        "θ̈ from (5), θ⃛ = Ω² cos θ θ̇ (its d/dt): on the motion".into()
    } else {
        format!(
            "θ̈ given (off the motion unless it equals (5)), θ⃛ {}",
            if at.jerk.is_some() { "given" } else { "= 0" }
        )
    }
}

/// The state in words and numbers, from its f64 values.
fn summary(
    float: &(Ladder<f64>, State<f64>),
    theta: &Angle,
    theta0: Option<f64>,
    on_motion: bool,
    how: Vec<String>,
    why_not_exact: Option<String>,
    phase: super::phase::Phase,
) -> Summary {
    let fs = &float.1;
    Summary {
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
        why_not_exact,
        phase,
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
