//! Which phase of the fall a state of `ladder show --at` belongs to, from the contact forces the
//! two-contact model requires there, (14) and (15): a wall cannot pull (F_w < 0 is past
//! separation, where the top has left the wall) and a floor cannot pull (F_f < 0, the foot would
//! lift). The displays of sec. 2 are identities of the two-contact model, so their forms agree at
//! such a state too; only these signs say that the model no longer describes the fall there.

use crate::ladder::forces::{floor_force, wall_force};
use crate::ladder::{Ladder, State};
use crate::scalar::{Bound, UNIT_ROUNDOFF};
use serde::Serialize;

/// The contact forces at the state and what they say.
#[derive(Clone, Debug, Serialize)]
pub struct Phase {
    /// F_w of (14), N.
    pub wall_force: f64,
    /// F_f of (15), N.
    pub floor_force: f64,
    /// θ0 of the release at rest that passes through the state (on the motion only), rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub released_at: Option<f64>,
    /// Where that release leaves the wall, cos θ = (2/3) cos θ0 (footnote 4), rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<f64>,
    /// The phase, in words.
    pub phase: String,
    /// A warning for each contact force that would have to pull.
    pub warnings: Vec<String>,
}

/// The sign of a force computed with a running error bound: `Some(false)` when it is negative
/// beyond its rounding, `None` when rounding cannot tell it from zero.
fn non_negative(f: Bound) -> Option<bool> {
    if f.v.abs() <= f.e * UNIT_ROUNDOFF {
        None
    } else {
        Some(f.v > 0.0)
    }
}

fn deg(rad: f64) -> String {
    let s = format!("{:.2}", rad.to_degrees());
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The phase of the state `b` (with error bounds; `f` the same in f64). `theta0` is the release
/// angle when θ̇ came from the energy; on the motion, a given θ̇ is traced back to the release
/// at rest that reaches it, cos θ0 = cos θ + (2l/3g) θ̇², when there is one.
pub fn phase(
    f: &(Ladder<f64>, State<f64>),
    b: &(Ladder<Bound>, State<Bound>),
    on_motion: bool,
    theta0: Option<f64>,
) -> Phase {
    let (fl, fs) = f;
    let (fw, ff) = (wall_force(fl, fs), floor_force(fl, fs));
    let released_at = if !on_motion {
        None
    } else {
        theta0.or_else(|| {
            // A release from upright lands on cos θ0 = 1 up to a few roundings.
            let c0 = fs.cos + 2.0 * fl.l / (3.0 * fl.g) * fs.rate * fs.rate;
            (c0 <= 1.0 + 8.0 * UNIT_ROUNDOFF).then(|| c0.min(1.0).acos())
        })
    };
    let separation = released_at.map(|t0| (2.0 / 3.0 * t0.cos()).acos());
    let where_ = |what: &str| {
        match (released_at, separation) {
        (Some(t0), Some(ts)) => format!(
            "{what}: released at rest at θ0 = {}°, the top leaves the wall at cos θ = (2/3) cos θ0, \
θ = {}°",
            deg(t0),
            deg(ts)
        ),
        _ => what.to_string(),
    }
    };
    let (wall, floor) = (
        non_negative(wall_force(&b.0, &b.1)),
        non_negative(floor_force(&b.0, &b.1)),
    );
    let motion = if on_motion {
        "the motion's"
    } else {
        "this state's (θ̈ given)"
    };
    let mut warnings = Vec::new();
    if wall == Some(false) {
        warnings.push(format!(
            "F_w = {fw:.4} N < 0: the wall would have to pull the top to keep {motion} θ̈; past \
separation the top has left the wall, and (5), (14), (15) no longer describe the fall (phase 2: \
the foot alone on the floor). The forms below still agree: they are identities of the \
two-contact model, not of the fall"
        ));
    }
    if floor == Some(false) {
        warnings.push(format!(
            "F_f = {ff:.4} N < 0: the floor would have to pull the foot down to keep {motion} θ̈; \
the foot would lift, which the two-contact model does not describe"
        ));
    }
    let phase = match (wall, floor) {
        (Some(false), _) => where_("past separation (phase 2, the top off the wall)"),
        (_, Some(false)) => "the foot off the floor (no phase of the note)".to_string(),
        (None, _) => where_("at separation (F_w = 0 within rounding)"),
        _ => where_("phase 1, both contacts (F_w ≥ 0, F_f ≥ 0)"),
    };
    Phase {
        wall_force: fw,
        floor_force: ff,
        released_at,
        separation,
        phase,
        warnings,
    }
}
