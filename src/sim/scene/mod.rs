//! Scene files (TOML) and their validation. Every problem becomes one [`SceneError`] naming the
//! file, the line (from toml's spans) and the field, and saying what is allowed.
//!
//! Schema (DESIGN.md, "Scenes"): `[ladder] mass half_length gravity`, `[start] angle (or
//! angle_from_floor) angular_velocity`, `[contact] model (stiffness damping)`, `[integrator] method
//! tolerance|step (order)`,
//! `[end] at (time)`, `[outputs] want`. Unknown keys are errors.

pub(super) mod checks;
pub mod errors;
pub mod output;
pub mod parts;
pub mod shape;
pub(in crate::sim) mod start;
pub mod work;

use self::output::Output;
use self::start::{check_theta_only, start_angle};
use super::integrators::Control;
pub use super::scene::checks::SOFTEST_CONTACT;
use super::scene::checks::{
    check_contact, check_end, check_integrator, check_outputs, check_penalty,
};
use super::scene::errors::Ctx;
pub use super::scene::errors::SceneError;
pub use super::scene::parts::{ContactModel, End, MAX_END_TIME, MAX_STEP, MIN_STEP, MIN_TOLERANCE};
use super::scene::parts::{Raw, RawLadder};
use super::scene::shape::{check_shape, value_error};
use super::scene::work::check_work;
use super::units::Units;
use crate::ladder::Ladder;
use std::path::Path;

/// A validated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The file it came from.
    pub file: String,
    /// m, l, g.
    pub ladder: Ladder<f64>,
    /// θ0, rad (for a start given as `angle_from_floor`, the nearest f64 below π/2).
    pub theta0: f64,
    /// φ0 = π/2 − θ0, rad, when the scene gave the start as `angle_from_floor` (exact; θ0
    /// cannot hold it near π/2, see `sim::scene::start`).
    pub phi0: Option<f64>,
    /// θ̇0, rad/s.
    pub rate0: f64,
    /// Integrator name (one of [`TABLE`](super::integrators::TABLE) or `exact`).
    pub method: String,
    /// Step or tolerance (None for `exact`).
    pub control: Option<Control>,
    /// The Taylor method's order (`[integrator] order`, method "taylor" only); None: from the
    /// tolerance ([`crate::sim::integrators::taylor::order_for`]).
    pub order: Option<usize>,
    /// Where the run ends.
    pub end: End,
    /// The outputs asked for, in the order given.
    pub outputs: Vec<Output>,
    /// Rigid contacts or penalty springs.
    pub contact: ContactModel,
}

/// Read and validate the scene at `path`.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let file = path.display().to_string();
    let whole = |message: String| SceneError {
        file: file.clone(),
        line: None,
        field: String::new(),
        message,
    };
    if path.is_dir() {
        return Err(whole(
            "a directory; allowed: a scene file (TOML), e.g. scenes/from-rest.toml".into(),
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| {
        whole(format!(
            "cannot read the scene: {e}; allowed: a readable scene file (TOML)"
        ))
    })?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        SceneError {
            line: Some(bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1),
            ..whole(format!(
                "not UTF-8 text (byte 0x{:02x}); allowed: a UTF-8 TOML file",
                bytes[at]
            ))
        }
    })?;
    parse(&file, &text)
}

/// `[ladder]`: m, l and g, each positive.
fn check_ladder(cx: &Ctx, l: &RawLadder) -> Result<Ladder<f64>, SceneError> {
    // Any scale from 1e-30 to 1e30: the simulator is checked to give the same angles, times
    // scaled by √(l/g) and forces by m g over that whole range (`ladder stability`).
    let positive = |x: f64| (1e-30..=1e30).contains(&x);
    Ok(Ladder {
        m: cx.number(
            &l.mass,
            "ladder.mass",
            positive,
            "a number > 0 (kg) in [1e-30, 1e30]",
        )?,
        l: cx.number(
            &l.half_length,
            "ladder.half_length",
            positive,
            "a number > 0 (m) in [1e-30, 1e30]",
        )?,
        g: cx.number(
            &l.gravity,
            "ladder.gravity",
            positive,
            "a number > 0 (m/s²) in [1e-30, 1e30]",
        )?,
    })
}

/// Validate the scene text `text` read from `file`.
pub fn parse(file: &str, text: &str) -> Result<Scene, SceneError> {
    let cx = Ctx { file, text };
    check_shape(&cx)?;
    let raw: Raw = toml::from_str(text).map_err(|e| value_error(&cx, &e))?;
    let ladder = check_ladder(&cx, raw.ladder.get_ref())?;
    let s = raw.start.get_ref();
    let start = start_angle(&cx, s)?;
    let theta0 = start.theta0;
    let rate0 = cx.number(
        &s.angular_velocity,
        "start.angular_velocity",
        |x| x >= 0.0,
        "a number >= 0 (rad/s)",
    )?;
    let big_omega2 = ladder.big_omega2();
    let contact = check_contact(&cx, raw.contact.get_ref(), &ladder)?;
    // At or past the release push the wall would have to pull at the start: a rigid run
    // reports the separation at t = 0 and goes on in the floor phase (`sim::fall::wall_phase`); the
    // penalty model, whose springs would start stretched, is not run there.
    let penalty = matches!(contact, ContactModel::Penalty { .. });
    if penalty && rate0 * rate0 >= big_omega2 * start.cos_theta0() {
        let max = (big_omega2 * start.cos_theta0()).sqrt();
        return Err(cx.err(Some(s.angular_velocity.span()), "start.angular_velocity", format!(
            "{rate0} rad/s is too fast for the penalty model: the wall would have to pull at the start; allowed: below sqrt(3g cos θ0 / 4l) = {max} (model = \"rigid\" reports the separation at t = 0 and goes on in the floor phase)"
        )));
    }
    // The scene's time unit √(l/g): steps and end times are limited in it (see `sim::scaled`).
    let unit = Units::of(&ladder).time;
    let (method, control) = check_integrator(&cx, raw.integrator.get_ref(), unit)?;
    let order = super::scene::checks::check_order(&cx, raw.integrator.get_ref(), &method)?;
    let end = check_end(&cx, raw.end.get_ref(), unit)?;
    // Past √(g/(l cos θ0)) the floor would have to pull at the start of the floor phase too
    // (its force there is m l (g/l − cos θ0 θ̇0²)/(3 sin² θ0 + 1), `sim::fall::floor_phase`): the
    // ladder would fly, which no phase of this model follows.
    let fly = ladder.g / (ladder.l * start.cos_theta0());
    if !penalty && end != End::Separation && rate0 * rate0 >= fly {
        return Err(cx.err(Some(s.angular_velocity.span()), "start.angular_velocity", format!(
            "{rate0} rad/s is too fast: past sqrt(3g cos θ0 / 4l) the top leaves the wall at once, and past sqrt(g / (l cos θ0)) = {} the foot would leave the floor too, which this model does not follow; allowed: below that, or end.at = \"separation\"",
            fly.sqrt()
        )));
    }
    if theta0 == 0.0 && rate0 == 0.0 && !matches!(end, End::Time(_)) {
        return Err(cx.err(Some(start.span.clone()), "start", "θ0 = 0 with θ̇0 = 0 is the equilibrium: the ladder never leaves the wall; allowed: angle > 0 or angular_velocity > 0 (or end.at = \"time\")"));
    }
    let outputs = check_outputs(&cx, raw.outputs.get_ref(), &method, end)?;
    if let ContactModel::Penalty { .. } = contact {
        check_penalty(&cx, &raw, &method, end, &outputs)?;
        check_theta_only(&cx, &start, "the penalty model (integrated in θ)")?;
    }
    if control.is_none() {
        check_theta_only(&cx, &start, "the exact closed form")?;
    }
    let i = raw.integrator.get_ref();
    check_work(
        &cx,
        i,
        &ladder,
        (theta0, rate0),
        &method,
        control,
        end,
        contact,
    )?;
    Ok(Scene {
        file: file.to_string(),
        ladder,
        theta0,
        phi0: start.phi0,
        rate0,
        method,
        control,
        order,
        end,
        outputs,
        contact,
    })
}
