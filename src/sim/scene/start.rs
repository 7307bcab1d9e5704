//! The start angle of a scene: `[start] angle = θ0`, or `angle_from_floor = φ0`, the
//! complement φ0 = π/2 − θ0, for starts near the floor.
//!
//! **Why the second key.** f64 spaces its values near π/2 by 2.2e-16, so θ0 = π/2 − 1e-12
//! cannot be written as an `angle`: the nearest f64 is up to 1.1e-16 away, and the separation
//! time moves by about half that relative to ε = π/2 − θ0 (5e-5 at ε = 1e-12). The wall phase
//! near the floor runs in φ (`crate::sim::complement`), which holds 1e-12 to full precision, so a
//! start given as φ0 reaches the integrator exactly. The scene keeps φ0 ([`StartAngle::phi0`])
//! beside its nearest θ0; anything that can only take θ0 (the exact closed form and the
//! penalty model, both in θ) refuses a φ0 that θ0 does not represent exactly
//! ([`check_theta_only`]), rather than silently answering for a different start.

use crate::sim::complement::complement;
use crate::sim::scene::errors::{Ctx, SceneError};
use crate::sim::scene::parts::RawStart;
use std::f64::consts::FRAC_PI_2;
use std::ops::Range;

/// What a scene's start angle keys give.
#[derive(Clone, Debug, PartialEq)]
pub(in crate::sim) struct StartAngle {
    /// θ0, rad: `angle`, or the nearest f64 to π/2 − φ0 (below π/2).
    pub(in crate::sim) theta0: f64,
    /// φ0 = π/2 − θ0, rad, exactly as given by `angle_from_floor`.
    pub(in crate::sim) phi0: Option<f64>,
    /// Where the key that gave it sits in the text.
    pub(in crate::sim) span: Range<usize>,
}

impl StartAngle {
    /// cos θ0, from φ0 when given (cos θ0 = sin φ0 keeps φ0's precision).
    pub(in crate::sim) fn cos_theta0(&self) -> f64 {
        self.phi0.map_or(self.theta0.cos(), f64::sin)
    }
}

const ALLOWED: &str =
    "one of angle (θ0 in [0, π/2) rad) or angle_from_floor (π/2 − θ0 in [2.2e-308, π/2] rad)";

/// The line of the `[start]` header (for an error about the section as a whole).
fn header_line(cx: &Ctx) -> usize {
    cx.text
        .lines()
        .position(|l| l.trim() == "[start]")
        .map_or(1, |i| i + 1)
}

/// The start angle of `s`: exactly one of `angle` and `angle_from_floor`.
pub(in crate::sim) fn start_angle(cx: &Ctx, s: &RawStart) -> Result<StartAngle, SceneError> {
    match (&s.angle, &s.angle_from_floor) {
        (Some(_), Some(b)) => Err(cx.err(
            Some(b.span()),
            "start.angle_from_floor",
            format!("given together with angle; allowed: {ALLOWED}"),
        )),
        (None, None) => Err(cx.err_at_line(
            header_line(cx),
            "start",
            format!("no start angle; allowed: {ALLOWED}"),
        )),
        (Some(a), None) => Ok(StartAngle {
            theta0: cx.number(
                a,
                "start.angle",
                |x| (0.0..FRAC_PI_2).contains(&x),
                "an angle in [0, π/2) rad",
            )?,
            phi0: None,
            span: a.span(),
        }),
        (None, Some(b)) => {
            let phi0 = cx.number(
                b,
                "start.angle_from_floor",
                |x| (f64::MIN_POSITIVE..=FRAC_PI_2).contains(&x),
                "π/2 − θ0 in [2.2250738585072014e-308, π/2] rad (a subnormal φ0 has too few significant bits for the separation at (2/3) φ0), e.g. 1e-12",
            )?;
            // θ0 = π/2 − φ0 (one rounding; π/2's low part included), kept below π/2.
            let theta0 = complement(phi0).min(f64::from_bits(FRAC_PI_2.to_bits() - 1));
            Ok(StartAngle {
                theta0,
                phi0: Some(phi0),
                span: b.span(),
            })
        }
    }
}

/// Refuse a start given as φ0 that θ0 does not carry exactly when the run takes θ0 only
/// (`what` says which: the exact closed form, the penalty model).
pub(in crate::sim) fn check_theta_only(
    cx: &Ctx,
    start: &StartAngle,
    what: &str,
) -> Result<(), SceneError> {
    match start.phi0 {
        Some(phi0) if complement(start.theta0) != phi0 => Err(cx.err(
            Some(start.span.clone()),
            "start.angle_from_floor",
            format!(
                "{phi0:e} rad is not π/2 − θ0 for any f64 θ0 (the nearest, {}, is off by {:.1e} rad), and {what} takes θ0; allowed: an integrator of the rigid model (e.g. dop853), or angle",
                start.theta0,
                (complement(start.theta0) - phi0).abs()
            ),
        )),
        _ => Ok(()),
    }
}
