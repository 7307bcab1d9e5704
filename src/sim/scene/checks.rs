//! The checks of the `[contact]`, `[integrator]` and `[outputs]` sections of a scene.
//!
//! **Springs too soft to be a contact.** The penalty model accepts κ = k l/(m g) from 1
//! (`penalty::KAPPA_RANGE`), but below a few the springs sink by m g/k ~ l/κ and bounce at
//! ~√κ per √(l/g), as slow as the fall itself: the floor force, m g/4 at the rigid separation
//! (1 − Ω² with θ̇² = Ω² cos θ there), falls to zero first and the foot lifts off, which the
//! model does not follow (the run fails). The reliability campaign found 14 such runs in
//! 10,000 scenes of seed 1 (κ = 1.02..1.55, every method); radau5 at tolerance 1e-10 over
//! 12,000 random starts (θ0 tiny to near π/2, pushes up to the wall's limit, γ = 0 or
//! 1e-3..10 √κ) lifted off up to κ = 2.50 and never above (none in 5,700 runs with
//! κ = 2.5..10). A scene needs κ ≥ [`SOFTEST_CONTACT`] = 5, a margin of 2.

use crate::ladder::Ladder;
use crate::sim::integrators::{card, is_adaptive, names, Control, TABLE};
use crate::sim::penalty::{Contact, KAPPA_RANGE};
use crate::sim::scene::errors::{Ctx, SceneError};
use crate::sim::scene::output::Output;
use crate::sim::scene::parts::{
    ContactModel, End, Raw, RawContact, RawEnd, RawIntegrator, RawOutputs, MAX_END_TIME, MAX_STEP,
    MIN_STEP, MIN_TOLERANCE,
};

/// Least κ = k l/(m g) of a penalty scene (module docs: softer springs lift the foot).
pub const SOFTEST_CONTACT: f64 = 5.0;

pub(in crate::sim) fn check_contact(
    cx: &Ctx,
    c: &RawContact,
    ladder: &Ladder<f64>,
) -> Result<ContactModel, SceneError> {
    match c.model.get_ref().as_str() {
        "rigid" => {
            for (k, v) in [
                ("contact.stiffness", &c.stiffness),
                ("contact.damping", &c.damping),
            ] {
                if let Some(v) = v {
                    return Err(cx.err(
                        Some(v.span()),
                        k,
                        "only for model = \"penalty\"; allowed: no stiffness or damping with model = \"rigid\"",
                    ));
                }
            }
            Ok(ContactModel::Rigid)
        }
        "penalty" => {
            let Some(k) = &c.stiffness else {
                return Err(cx.err(
                    Some(c.model.span()),
                    "contact.stiffness",
                    "missing; the penalty model needs it; allowed: a number > 0 (N/m)",
                ));
            };
            let stiffness = cx.number(k, "contact.stiffness", |x| x > 0.0, "a number > 0 (N/m)")?;
            let damping = match &c.damping {
                Some(d) => {
                    cx.number(d, "contact.damping", |x| x >= 0.0, "a number >= 0 (N·s/m)")?
                }
                None => 0.0,
            };
            let contact = Contact::from_dimensional(ladder, stiffness, damping);
            // The model takes κ from KAPPA_RANGE.0 = 1, a scene from SOFTEST_CONTACT.
            let (lo, hi) = (SOFTEST_CONTACT.max(KAPPA_RANGE.0), KAPPA_RANGE.1);
            if !(KAPPA_RANGE.0..=hi).contains(&contact.kappa) {
                return Err(cx.err(
                    Some(k.span()),
                    "contact.stiffness",
                    format!(
                        "k l/(m g) = {:e} is out of range; allowed: a stiffness with k l/(m g) in [{lo:e}, {hi:e}] (below, the springs are no contact or lift the foot; above, rounding of positions times k swamps the force)",
                        contact.kappa
                    ),
                ));
            }
            if contact.kappa < SOFTEST_CONTACT {
                return Err(cx.err(
                    Some(k.span()),
                    "contact.stiffness",
                    format!(
                        "k l/(m g) = {:e} is too soft: the springs sink by about m g/k = {:.3} l and their bounce lifts the foot off the floor before the wall lets go, which the penalty model does not follow; allowed: k l/(m g) ≥ {SOFTEST_CONTACT} (k ≥ {:.4e} N/m)",
                        contact.kappa,
                        1.0 / contact.kappa,
                        stiffness * (SOFTEST_CONTACT / contact.kappa)
                    ),
                ));
            }
            if !contact.gamma.is_finite() {
                return Err(cx.err(
                    c.damping.as_ref().map(|d| d.span()),
                    "contact.damping",
                    "c √(l/g)/m is not a finite number; allowed: a smaller damping",
                ));
            }
            Ok(ContactModel::Penalty { stiffness, damping })
        }
        other => Err(cx.err(
            Some(c.model.span()),
            "contact.model",
            format!("unknown model \"{other}\"; allowed: \"rigid\", \"penalty\""),
        )),
    }
}

/// What a penalty scene may ask for: the wall phase to separation, by an integrator.
pub(in crate::sim) fn check_penalty(
    cx: &Ctx,
    raw: &Raw,
    method: &str,
    end: End,
    outputs: &[Output],
) -> Result<(), SceneError> {
    let i = raw.integrator.get_ref();
    if method == "exact" {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.method",
            "\"exact\" is the rigid model's reference and the penalty model needs an integrator; allowed: e.g. radau5",
        ));
    }
    if card(method).is_some_and(|c| c.rigid_only) {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.method",
            format!("\"{method}\" has recursions for the rigid phases only; the penalty model needs another integrator (e.g. radau5)"),
        ));
    }
    if end != End::Separation {
        return Err(cx.err(
            Some(raw.end.get_ref().at.span()),
            "end.at",
            "the penalty model runs to separation only; allowed: \"separation\"",
        ));
    }
    for (o, w) in outputs.iter().zip(raw.outputs.get_ref().want.get_ref()) {
        if !PENALTY_OUTPUTS.contains(o) {
            return Err(cx.err(
                Some(w.span()),
                "outputs.want",
                format!(
                    "\"{}\" is not produced by the penalty model; allowed: separation_angle, separation_time, separation_rate, final_state, rhs_evals",
                    o.name()
                ),
            ));
        }
    }
    Ok(())
}

const PENALTY_OUTPUTS: [Output; 5] = [
    Output::SeparationAngle,
    Output::SeparationTime,
    Output::SeparationRate,
    Output::FinalState,
    Output::RhsEvals,
];

pub(in crate::sim) fn check_integrator(
    cx: &Ctx,
    i: &RawIntegrator,
    unit: f64,
) -> Result<(String, Option<Control>), SceneError> {
    let method = i.method.get_ref().as_str();
    if method == "exact" {
        check_exact(cx, i)?;
        return Ok((method.into(), None));
    }
    if card(method).is_none() {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.method",
            format!(
                "unknown method \"{method}\"; allowed: {}, exact",
                names().collect::<Vec<_>>().join(", ")
            ),
        ));
    }
    let control = if is_adaptive(method) {
        adaptive_control(cx, i, method)?
    } else {
        fixed_control(cx, i, method, unit)?
    };
    Ok((method.into(), Some(control)))
}

/// `method = "exact"` alone: the closed form takes neither tolerance nor step.
fn check_exact(cx: &Ctx, i: &RawIntegrator) -> Result<(), SceneError> {
    for (key, v) in [
        ("integrator.tolerance", &i.tolerance),
        ("integrator.step", &i.step),
        ("integrator.scaled_step", &i.scaled_step),
    ] {
        if let Some(v) = v {
            return Err(cx.err(
                Some(v.span()),
                key,
                "method \"exact\" takes neither tolerance nor step; allowed: method = \"exact\" alone",
            ));
        }
    }
    Ok(())
}

/// An adaptive method's control: its tolerance, and no step.
fn adaptive_control(cx: &Ctx, i: &RawIntegrator, method: &str) -> Result<Control, SceneError> {
    if let Some(s) = i.step.as_ref().or(i.scaled_step.as_ref()) {
        return Err(cx.err(
            Some(s.span()),
            "integrator.step",
            format!(
                "\"{method}\" is adaptive and takes no step; allowed: tolerance in [1e-16, 0.1]"
            ),
        ));
    }
    let Some(t) = &i.tolerance else {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.tolerance",
            format!("missing; \"{method}\" needs one; allowed: a tolerance in [1e-16, 0.1]"),
        ));
    };
    Ok(Control::Tolerance(cx.number(
        t,
        "integrator.tolerance",
        |x| (MIN_TOLERANCE..=0.1).contains(&x),
        "a tolerance in [1e-16, 0.1]",
    )?))
}

/// A fixed-step method's control: its step (s, or scaled by `unit` = √(l/g) s), and no
/// tolerance.
fn fixed_control(
    cx: &Ctx,
    i: &RawIntegrator,
    method: &str,
    unit: f64,
) -> Result<Control, SceneError> {
    if let Some(t) = &i.tolerance {
        return Err(cx.err(
            Some(t.span()),
            "integrator.tolerance",
            format!(
                "\"{method}\" has a fixed step and takes no tolerance; allowed: step (s) or scaled_step (units of √(l/g)) in [{MIN_STEP:e}, {MAX_STEP}] √(l/g)"
            ),
        ));
    }
    let allowed = format!(
        "a step in [{MIN_STEP:e}, {MAX_STEP}] √(l/g) = [{:e}, {:e}] s (or scaled_step in [{MIN_STEP:e}, {MAX_STEP}])",
        MIN_STEP * unit,
        MAX_STEP * unit
    );
    let Some((h, _, _)) = cx.time_like(
        i.step.as_ref(),
        i.scaled_step.as_ref(),
        ("integrator.step", "integrator.scaled_step"),
        unit,
        |x| (MIN_STEP..=MAX_STEP).contains(&x),
        &allowed,
    )?
    else {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.step",
            format!("missing; \"{method}\" needs a step; allowed: {allowed}"),
        ));
    };
    Ok(Control::Fixed(h))
}

/// `[integrator] order`: the Taylor method's order, a whole number in
/// [`taylor::MIN_ORDER`, `taylor::MAX_ORDER`], for method "taylor" only.
pub(in crate::sim) fn check_order(
    cx: &Ctx,
    i: &RawIntegrator,
    method: &str,
) -> Result<Option<usize>, SceneError> {
    use crate::sim::integrators::taylor::{MAX_ORDER, MIN_ORDER};
    let Some(o) = &i.order else {
        return Ok(None);
    };
    let allowed = format!("a whole number in [{MIN_ORDER}, {MAX_ORDER}] (default: from the tolerance, the least work per unit time)");
    if card(method).is_some_and(|c| c.order.is_some()) {
        // The methods whose order is chosen per run (their card has no order of its own).
        let takers: Vec<String> = TABLE
            .iter()
            .filter(|c| c.order.is_none())
            .map(|c| format!("method = \"{}\"", c.name))
            .collect();
        return Err(cx.err(
            Some(o.span()),
            "integrator.order",
            format!(
                "\"{method}\" takes no order; allowed: order with {} only",
                takers.join(" or ")
            ),
        ));
    }
    let p = cx.number(
        o,
        "integrator.order",
        |x| x.fract() == 0.0 && (MIN_ORDER as f64..=MAX_ORDER as f64).contains(&x),
        &allowed,
    )?;
    Ok(Some(p as usize))
}

pub(in crate::sim) fn check_outputs(
    cx: &Ctx,
    o: &RawOutputs,
    method: &str,
    end: End,
) -> Result<Vec<Output>, SceneError> {
    if o.want.get_ref().is_empty() {
        return Err(cx.err(
            Some(o.want.span()),
            "outputs.want",
            format!("empty; allowed: {}", Output::names()),
        ));
    }
    let mut out = Vec::new();
    for w in o.want.get_ref() {
        let name = w.get_ref().as_str();
        let Some(x) = Output::from_name(name) else {
            return Err(cx.err(
                Some(w.span()),
                "outputs.want",
                format!("unknown output \"{name}\"; allowed: {}", Output::names()),
            ));
        };
        if out.contains(&x) {
            return Err(cx.err(
                Some(w.span()),
                "outputs.want",
                format!("\"{name}\" is listed twice; allowed: each output once"),
            ));
        }
        if let Err(why) = x.producible(method, end) {
            return Err(cx.err(
                Some(w.span()),
                "outputs.want",
                format!("\"{name}\" cannot be produced: {why}"),
            ));
        }
        out.push(x);
    }
    Ok(out)
}

/// `[end]`: `at` and, for `at = "time"`, `time` (s) or `scaled_time` (units of √(l/g) = `unit` s).
pub(in crate::sim) fn check_end(cx: &Ctx, e: &RawEnd, unit: f64) -> Result<End, SceneError> {
    let allowed = format!(
        "a time in (0, {MAX_END_TIME:e}] √(l/g) = (0, {:e}] s (or scaled_time in (0, {MAX_END_TIME:e}])",
        MAX_END_TIME * unit
    );
    let time = cx.time_like(
        e.time.as_ref(),
        e.scaled_time.as_ref(),
        ("end.time", "end.scaled_time"),
        unit,
        |x| x > 0.0 && x <= MAX_END_TIME,
        &allowed,
    )?;
    match (e.at.get_ref().as_str(), time) {
        ("separation", None) => Ok(End::Separation),
        ("flat", None) => Ok(End::Flat),
        ("time", Some((t, _, _))) => Ok(End::Time(t)),
        ("time", None) => Err(cx.err(
            Some(e.at.span()),
            "end.time",
            format!("missing; at = \"time\" needs it; allowed: {allowed}"),
        )),
        ("separation" | "flat", Some((_, span, key))) => Err(cx.err(
            Some(span),
            key,
            "only for at = \"time\"; allowed: no time with at = \"separation\" or \"flat\"",
        )),
        (other, _) => Err(cx.err(
            Some(e.at.span()),
            "end.at",
            format!("unknown end \"{other}\"; allowed: \"separation\", \"flat\", \"time\""),
        )),
    }
}
