//! `--at`: a ladder state in the note's own symbols and units, read from one line such as
//! `m=2, l=1.5, g=9.81, theta=40deg, theta0=10deg`.
//!
//! Every number is read exactly, as a rational (`9.81` is 981/100, `3/5`, `1.5e-3`), so the state
//! is exact whenever the angle is: an angle in degrees or radians is exact only at 0 (no other
//! angle of [0, π/2) with a rational number of degrees has rational sin and cos), but
//! `sin_theta=3/5`, `cos_theta=4/5` or `tan_half_theta=1/2` give points of the unit circle with
//! rational sin and cos. Hand-written (a dozen keys, one grammar line) because no crate reads
//! `key=value` lists into exact rationals with the note's units.
//!
//! ```text
//! at     := pair ((',' | ';') pair)*
//! pair   := KEY '=' number [unit]
//! number := decimal ['/' decimal]          decimal := ['+'|'-'] digits ['.' digits] [('e'|'E') ['+'|'-'] digits]
//! ```

use crate::scalar::Rational;
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// How the angle θ (or θ0) was given.
#[derive(Clone, Debug, PartialEq)]
pub enum Angle {
    /// In radians, as a float (from `theta=40deg` or `theta=0.7`); exact only at 0.
    Radians(f64),
    /// By its exact sin and cos (from `sin_theta`, `cos_theta` or `tan_half_theta`).
    Exact {
        /// sin θ.
        sin: Rational,
        /// cos θ.
        cos: Rational,
    },
    /// By sin or cos alone, when the other is irrational: (sin, cos) as floats.
    Float(f64, f64),
}

impl Angle {
    /// (sin, cos) exactly, when known.
    pub fn exact(&self) -> Option<(Rational, Rational)> {
        match self {
            Angle::Exact { sin, cos } => Some((sin.clone(), cos.clone())),
            Angle::Radians(r) if *r == 0.0 => Some((Rational::zero(), Rational::one())),
            _ => None,
        }
    }
    /// (sin, cos) as floats, and their error in roundoffs (libm: within one ulp; a rational:
    /// one rounding).
    pub fn float(&self) -> (f64, f64, f64) {
        match self {
            Angle::Radians(r) => {
                let (s, c) = r.sin_cos();
                (s, c, 2.0)
            }
            Angle::Exact { sin, cos } => (to_f64(sin), to_f64(cos), 1.0),
            Angle::Float(s, c) => (*s, *c, 3.0),
        }
    }
    /// The angle in radians.
    pub fn radians(&self) -> f64 {
        let (s, c, _) = self.float();
        match self {
            Angle::Radians(r) => *r,
            _ => s.atan2(c),
        }
    }
}

/// A state as the user gave it (everything optional: the show fills in the rest).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct At {
    /// m, kg.
    pub m: Option<Rational>,
    /// l, m.
    pub l: Option<Rational>,
    /// g, m/s².
    pub g: Option<Rational>,
    /// θ.
    pub theta: Option<Angle>,
    /// θ0, the angle the ladder was released from at rest.
    pub theta0: Option<Angle>,
    /// θ̇, rad/s.
    pub rate: Option<Rational>,
    /// θ̈, rad/s².
    pub accel: Option<Rational>,
    /// θ⃛, rad/s³.
    pub jerk: Option<Rational>,
}

/// What `--at` accepts, for error messages and `--help`.
pub const ACCEPTED: &str =
    "m (kg), l (m), g (m/s^2), theta or theta0 (with deg or rad; bare = rad), \
sin_theta / cos_theta / tan_half_theta (and the same for theta0) for exact angles, \
theta_dot (rad/s), theta_ddot (rad/s^2), theta_dddot (rad/s^3)";

/// Parse a `--at` line; the error is one line naming the offending pair.
pub fn parse_at(text: &str) -> Result<At, String> {
    let mut at = At::default();
    if text.trim().is_empty() {
        return Err("--at: empty; give pairs like \"m=2, l=1.5, theta=40deg\"".into());
    }
    for pair in text.split([',', ';']) {
        let pair = pair.trim();
        if pair.is_empty() {
            continue;
        }
        let (key, value) = pair
            .split_once('=')
            .ok_or_else(|| format!("--at: '{pair}' is not key=value"))?;
        let (key, value) = (key.trim(), value.trim());
        if value.is_empty() {
            return Err(format!("--at: '{key}' has no value"));
        }
        let err = |e: String| format!("--at: {key}={value}: {e}");
        match key {
            "m" => set(&mut at.m, key, positive(value, &["kg"]).map_err(err)?)?,
            "l" => set(&mut at.l, key, positive(value, &["m"]).map_err(err)?)?,
            "g" => set(
                &mut at.g,
                key,
                positive(value, &["m/s^2", "m/s2", "m/s²"]).map_err(err)?,
            )?,
            "theta" | "θ" => set(&mut at.theta, "theta", angle(value).map_err(err)?)?,
            "theta0" | "θ0" => set(&mut at.theta0, "theta0", angle(value).map_err(err)?)?,
            "sin_theta" | "cos_theta" | "tan_half_theta" => set(
                &mut at.theta,
                "theta",
                exact_angle(key, value).map_err(err)?,
            )?,
            "sin_theta0" | "cos_theta0" | "tan_half_theta0" => set(
                &mut at.theta0,
                "theta0",
                exact_angle(key.trim_end_matches('0'), value).map_err(err)?,
            )?,
            "theta_dot" | "θ̇" => set(
                &mut at.rate,
                key,
                number(value, &["rad/s", "1/s"]).map_err(err)?,
            )?,
            "theta_ddot" | "θ̈" => set(
                &mut at.accel,
                key,
                number(value, &["rad/s^2", "rad/s2"]).map_err(err)?,
            )?,
            "theta_dddot" => set(
                &mut at.jerk,
                key,
                number(value, &["rad/s^3", "rad/s3"]).map_err(err)?,
            )?,
            _ => {
                return Err(format!(
                    "--at: unknown symbol '{key}'; accepted: {ACCEPTED}"
                ))
            }
        }
    }
    if at.rate.is_some() && at.theta0.is_some() {
        return Err(
            "--at: give theta_dot or theta0 (θ̇ then comes from the energy), not both".into(),
        );
    }
    if let (Some(t), Some(t0)) = (&at.theta, &at.theta0) {
        if t0.radians() > t.radians() {
            return Err(format!(
                "--at: theta0 = {:.6} rad is above theta = {:.6} rad: released at rest at θ0, the ladder only falls to larger θ",
                t0.radians(),
                t.radians()
            ));
        }
    }
    Ok(at)
}

fn set<T>(slot: &mut Option<T>, key: &str, v: T) -> Result<(), String> {
    if slot.is_some() {
        return Err(format!("--at: {key} is given twice"));
    }
    *slot = Some(v);
    Ok(())
}

/// A number with an optional unit from `units` (none: the SI unit is understood).
fn number(value: &str, units: &[&str]) -> Result<Rational, String> {
    let mut v = value.trim();
    for u in units {
        if let Some(rest) = v.strip_suffix(u) {
            v = rest.trim_end();
            break;
        }
    }
    let q = match v.split_once('/') {
        Some((n, d)) => {
            let d = decimal(d.trim())?;
            if d.is_zero() {
                return Err("division by zero".into());
            }
            decimal(n.trim())? / d
        }
        None => decimal(v)?,
    };
    // Every value must be a finite f64 too: the float evaluation uses it.
    match q.to_f64() {
        Some(x) if x.is_finite() && (x != 0.0 || q.is_zero()) => Ok(q),
        _ => Err("out of the range of a double".into()),
    }
}

fn positive(value: &str, units: &[&str]) -> Result<Rational, String> {
    let q = number(value, units)?;
    if q.is_positive() {
        Ok(q)
    } else {
        Err("must be positive".into())
    }
}

/// `[+-]digits[.digits][e[+-]digits]`, exactly.
fn decimal(s: &str) -> Result<Rational, String> {
    let bad = || format!("'{s}' is not a number (digits, '.', 'e', or p/q)");
    let (mantissa, exp) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().map_err(|_| bad())?),
        None => (s, 0),
    };
    if !(-400..=400).contains(&exp) {
        return Err("exponent out of range".into());
    }
    let (neg, digits) = match mantissa.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    if int.is_empty() && frac.is_empty()
        || !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit())
    {
        return Err(bad());
    }
    let all: String = format!("{int}{frac}");
    let n: BigInt = all.parse().map_err(|_| bad())?;
    let scale = exp - frac.len() as i32;
    let ten = BigInt::from(10);
    let q = if scale >= 0 {
        Rational::from_integer((n * num_traits::pow(ten, scale as usize)).into())
    } else {
        Rational::new(n.into(), num_traits::pow(ten, (-scale) as usize).into())
    };
    Ok(if neg { -q } else { q })
}

/// θ in degrees (`40deg`, `40°`) or radians (`0.7rad`, `0.7`), in [0, π/2).
fn angle(value: &str) -> Result<Angle, String> {
    let v = value.trim();
    let (num, deg) = if let Some(r) = v.strip_suffix("deg").or_else(|| v.strip_suffix('°')) {
        (r, true)
    } else {
        (v.strip_suffix("rad").unwrap_or(v), false)
    };
    let q = number(num, &[])?;
    let x = to_f64(&q);
    let rad = if deg { x.to_radians() } else { x };
    let limit = if deg { "[0, 90) deg" } else { "[0, π/2) rad" };
    let upper_ok = if deg {
        x < 90.0
    } else {
        rad < std::f64::consts::FRAC_PI_2
    };
    if q.is_negative() || !upper_ok {
        return Err(format!(
            "outside {limit}: the ladder leans between the wall and the floor"
        ));
    }
    Ok(Angle::Radians(rad))
}

/// θ from an exact sin, cos or tan(θ/2), in [0, π/2).
fn exact_angle(key: &str, value: &str) -> Result<Angle, String> {
    let q = number(value, &[])?;
    let one = Rational::one();
    let (sin, cos) = match key {
        "sin_theta" => {
            if q.is_negative() || q >= one {
                return Err("sin θ must be in [0, 1) (θ in [0, π/2))".into());
            }
            let c2 = one - q.clone() * q.clone();
            match rational_sqrt(&c2) {
                Some(c) => (q, c),
                None => return Ok(Angle::Float(to_f64(&q), to_f64(&c2).sqrt())),
            }
        }
        "cos_theta" => {
            if !q.is_positive() || q > one {
                return Err("cos θ must be in (0, 1] (θ in [0, π/2))".into());
            }
            let s2 = one - q.clone() * q.clone();
            match rational_sqrt(&s2) {
                Some(s) => (s, q),
                None => return Ok(Angle::Float(to_f64(&s2).sqrt(), to_f64(&q))),
            }
        }
        _ => {
            // tan(θ/2) = t ∈ [0, 1): sin θ = 2t/(1+t²), cos θ = (1−t²)/(1+t²).
            if q.is_negative() || q >= one {
                return Err("tan(θ/2) must be in [0, 1) (θ in [0, π/2))".into());
            }
            let d = one.clone() + q.clone() * q.clone();
            (
                Rational::from_integer(2.into()) * q.clone() / d.clone(),
                (one - q.clone() * q) / d,
            )
        }
    };
    Ok(Angle::Exact { sin, cos })
}

/// The exact square root of a non-negative rational, when it is rational.
pub fn rational_sqrt(q: &Rational) -> Option<Rational> {
    if q.is_negative() {
        return None;
    }
    let (n, d) = (q.numer(), q.denom());
    let (rn, rd) = (n.sqrt(), d.sqrt());
    (&rn * &rn == n.0 && &rd * &rd == d.0).then(|| Rational::new(rn.into(), rd.into()))
}

/// The nearest f64 (inputs are checked to be in range).
pub fn to_f64(q: &Rational) -> f64 {
    q.to_f64().unwrap_or(f64::NAN)
}
