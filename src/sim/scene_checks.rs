//! The checks of the `[contact]`, `[integrator]` and `[outputs]` sections of a scene.

use super::integrators::{is_adaptive, Control, METHODS};
use super::output::Output;
use super::scene::{
    Ctx, End, RawContact, RawIntegrator, RawOutputs, SceneError, MIN_STEP, MIN_TOLERANCE,
};

pub(super) fn check_contact(cx: &Ctx, c: &RawContact) -> Result<(), SceneError> {
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
                        "only for contact.model = \"penalty\"; remove it for \"rigid\"",
                    ));
                }
            }
            Ok(())
        }
        "penalty" => {
            let Some(k) = &c.stiffness else {
                return Err(cx.err(
                    Some(c.model.span()),
                    "contact.stiffness",
                    "the penalty model needs stiffness (N/m, > 0)",
                ));
            };
            cx.number(k, "contact.stiffness", |x| x > 0.0, "a number > 0 (N/m)")?;
            if let Some(d) = &c.damping {
                cx.number(d, "contact.damping", |x| x >= 0.0, "a number >= 0 (N·s/m)")?;
            }
            Err(cx.err(
                Some(c.model.span()),
                "contact.model",
                "\"penalty\" is not yet implemented; allowed now: \"rigid\"",
            ))
        }
        other => Err(cx.err(
            Some(c.model.span()),
            "contact.model",
            format!("unknown model \"{other}\"; allowed: \"rigid\", \"penalty\""),
        )),
    }
}

pub(super) fn check_integrator(
    cx: &Ctx,
    i: &RawIntegrator,
) -> Result<(String, Option<Control>), SceneError> {
    let method = i.method.get_ref().as_str();
    if method == "exact" {
        if let Some(v) = i.tolerance.as_ref().or(i.step.as_ref()) {
            return Err(cx.err(
                Some(v.span()),
                "integrator",
                "method \"exact\" takes neither tolerance nor step",
            ));
        }
        return Ok((method.into(), None));
    }
    if !METHODS.contains(&method) {
        return Err(cx.err(
            Some(i.method.span()),
            "integrator.method",
            format!(
                "unknown method \"{method}\"; allowed: {}, exact",
                METHODS.join(", ")
            ),
        ));
    }
    let control = if is_adaptive(method) {
        if let Some(s) = &i.step {
            return Err(cx.err(
                Some(s.span()),
                "integrator.step",
                format!("\"{method}\" is adaptive: give tolerance, not step"),
            ));
        }
        let Some(t) = &i.tolerance else {
            return Err(cx.err(
                Some(i.method.span()),
                "integrator.tolerance",
                format!("\"{method}\" needs a tolerance in [1e-16, 0.1]"),
            ));
        };
        Control::Tolerance(cx.number(
            t,
            "integrator.tolerance",
            |x| (MIN_TOLERANCE..=0.1).contains(&x),
            "a tolerance in [1e-16, 0.1]",
        )?)
    } else {
        if let Some(t) = &i.tolerance {
            return Err(cx.err(
                Some(t.span()),
                "integrator.tolerance",
                format!("\"{method}\" has a fixed step: give step, not tolerance"),
            ));
        }
        let Some(s) = &i.step else {
            return Err(cx.err(
                Some(i.method.span()),
                "integrator.step",
                format!("\"{method}\" needs a step in [1e-6, 1] s"),
            ));
        };
        Control::Fixed(cx.number(
            s,
            "integrator.step",
            |x| (MIN_STEP..=1.0).contains(&x),
            "a step in [1e-6, 1] s",
        )?)
    };
    Ok((method.into(), Some(control)))
}

pub(super) fn check_outputs(
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
                format!("\"{name}\" is listed twice"),
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
