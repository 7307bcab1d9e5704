//! Every printed form of a display evaluated at one state: in f64, with running error bounds
//! (the tolerance of each agreement), exactly when the state is exact, and in dimensions (its SI
//! unit, from [`crate::registry::print_check::units`], as `ladder verify` judges it). The forms are the print's own ([`crate::registry::print_check::print_chains`]), the
//! symbols resolve in the independent models ([`crate::print::quantity`]), and each form is held
//! against the first form of its chain with the registry's own verdicts
//! ([`crate::registry::check::float_residual`], [`crate::registry::check::exact_residual`]).
//!
//! A general display (any system of particles, a point P) is evaluated on the ladder's own three
//! particles, with P the point of the ladder that meets the display's premise (see [`place`]).

use super::state::Point;
use crate::ladder::analysis::{Reference, ReferencePoint};
use crate::ladder::geometry::Corner;
use crate::ladder::particles::as_system;
use crate::ladder::{Ladder, State};
use crate::print::eval::{evaluate, Ctx};
use crate::print::quantity::{Model, Value};
use crate::registry::check::{exact_residual, float_residual, TOLERANCE_FACTOR};
use crate::registry::print_check::units::print_form_units;
use crate::registry::print_check::{print_chains, print_sample, Form, PrintSample};
use crate::registry::symbol_table as table;
use crate::registry::{Equation, ParticleSample, Role, Side};
use crate::scalar::{Bound, Rational, Scalar};
use crate::system::{Point as PPoint, Spin, System};
use serde::Serialize;
use std::rc::Rc;

type Chains<S> = Vec<Vec<Side<S>>>;

/// The error of a form whose f64 value overflows at the state.
pub const NOT_FINITE: &str = "not finite at this state (overflow)";

/// One printed form at the state.
#[derive(Clone, Debug, Serialize)]
pub struct FormValue {
    /// Its place in the print, counted from 1 over every chain (conditions last in their chain).
    pub index: usize,
    /// The chain (statement) it belongs to, from 1.
    pub chain: usize,
    /// The form as printed (LaTeX, spaces dropped).
    pub latex: String,
    /// Its Unicode reading.
    pub unicode: String,
    /// `printed`, `misprint` (recorded erratum: must differ) or `continued` ((57)'s first form,
    /// which is (56)'s last). An evaluation bar is a substitution inside its form, not a form.
    pub role: &'static str,
    /// In Milne's notation.
    pub milne: bool,
    /// Its value in SI units (one number, or x, y, z of a vector).
    pub value: Vec<f64>,
    /// The running error bound of each component of `value`, in SI units: the exact value of
    /// the form at the (rounded) inputs lies within `value ± bound`, to first order.
    pub bound: Vec<f64>,
    /// Its exact value (fractions), when the state is exact.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<Vec<String>>,
    /// Its SI unit (from the dimensions of the symbols), or why it has none.
    pub unit: String,
    /// |this − first form of the chain| in units of the running error bound (pass ≤ 4);
    /// `None` for the first form.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
    /// Agrees with the first form within the error model (f64).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub agrees: Option<bool>,
    /// Equal to the first form exactly (when the state is exact).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_agrees: Option<bool>,
    /// Why the form could not be evaluated here.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// Where a general display is evaluated, and whether its premise holds there.
#[derive(Clone, Debug, Serialize)]
pub struct Place {
    /// The reference point P, in words.
    pub point: String,
    /// When the display's premise does not hold for the ladder, why (its forms need not agree).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub premise_fails: Option<String>,
}

/// Which ladder point plays P for a particle sample, and whether the premise can hold.
pub fn place(sort: ParticleSample) -> Place {
    use ParticleSample::*;
    let (point, fails) = match sort {
        General => ("P = D, the foot (a moving point)", None),
        PAtCm => ("P = B, the centre of mass", None),
        PFixed | PlanarRigid => ("P = A, the corner (at rest)", None),
        PAtOrigin => ("P = A, the corner (at the origin)", None),
        CmAtOriginPAtCm => (
            "origin moved to the centre of mass at this instant, P = B",
            None,
        ),
        RollingAboutP => (
            "P = E, the instantaneous centre (the ladder's point there is at rest)",
            None,
        ),
        ForceFree => (
            "P = D",
            Some("the display assumes no total force; gravity and the contacts act on the ladder"),
        ),
        TorqueFree => (
            "P = D",
            Some("the display assumes no total torque about the origin; the ladder has one"),
        ),
    };
    Place {
        point: point.into(),
        premise_fails: fails.map(String::from),
    }
}

/// The ladder's three particles and the point P for a particle sample, in any scalar.
fn ladder_particles<S: Scalar>(
    sort: ParticleSample,
    l: &Ladder<S>,
    s: &State<S>,
) -> (System<S>, PPoint<S>) {
    use ParticleSample::*;
    let mut sys = as_system(l, s);
    // The rod's spin ω = (r × ṙ)_z/|r|², r = D − C, and ω̇ = (r × r̈)_z/|r|² (|r| is constant).
    let (c, d) = (&sys.particles[0], &sys.particles[2]);
    let r = d.x.clone() - c.x.clone();
    let r2 = r.dot(&r);
    let omega = r.cross(&(d.v.clone() - c.v.clone())).z / r2.clone();
    let omega_dot = r.cross(&(d.a.clone() - c.a.clone())).z / r2;
    let corner = |k| Reference::Corner(k).motion(l, s);
    let p = match sort {
        General | ForceFree | TorqueFree => corner(Corner::D),
        PAtCm => sys.cm_point(),
        PFixed | PAtOrigin => PPoint::fixed(corner(Corner::A).x),
        PlanarRigid => {
            sys.spin = Some(Spin { omega, omega_dot });
            PPoint::fixed(corner(Corner::A).x)
        }
        RollingAboutP => {
            sys.spin = Some(Spin { omega, omega_dot });
            corner(Corner::E)
        }
        CmAtOriginPAtCm => {
            let cm = sys.centre_of_mass();
            for q in &mut sys.particles {
                q.x = q.x.clone() - cm.clone();
            }
            sys.cm_point()
        }
    };
    (sys, p)
}

/// The model a display's forms resolve in, at a ladder state.
fn model<S: Scalar>(e: &Equation, l: &Ladder<S>, s: &State<S>) -> Result<Model<S>, String> {
    match print_sample(e) {
        Some(PrintSample::Ladder(..)) => Ok(Model::ladder(l.clone(), s.clone())),
        Some(PrintSample::Particles(sort)) => {
            let (sys, p) = ladder_particles(sort, l, s);
            // The display's stated and prose premises, imposed as in its print check.
            crate::registry::print_check::premises::premised(e, sys, p)
        }
        None => Err("no model for this display".into()),
    }
}

/// The place a display is evaluated at (`None` for a display of the ladder itself).
pub fn place_of(e: &Equation) -> Option<Place> {
    match print_sample(e) {
        Some(PrintSample::Particles(sort)) => {
            let mut at = place(sort);
            let imposed: Vec<String> = e
                .premises
                .iter()
                .filter(|p| p.source.whole_display())
                .filter_map(|p| p.latex.as_deref().map(crate::print::unicode::unicode))
                .collect();
            if !imposed.is_empty() {
                at.point = format!("{}, then {}", at.point, imposed.join(", "));
            }
            Some(at)
        }
        _ => None,
    }
}

fn eval_form<S: Scalar>(e: &Equation, f: &Form, m: &Rc<Model<S>>) -> Result<Value<S>, String> {
    let ctx = Ctx {
        model: m.clone(),
        section: e.section,
        number: e.number,
        milne: f.milne,
        index: None,
        table: table(),
    };
    evaluate(&f.expr, &ctx)
}

/// An exact evaluation, with a division by an exact zero turned into an error.
fn exact_guarded(
    e: &Equation,
    f: &Form,
    m: &Rc<Model<Rational>>,
) -> Result<Value<Rational>, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| eval_form(e, f, m)))
        .unwrap_or_else(|_| Err("undefined here exactly (a division by zero)".into()))
}

/// Components, a scalar spread over `width` (a literal 0 against a vector).
fn comps<S: Scalar>(v: &Value<S>, width: usize) -> Vec<S> {
    match v {
        Value::Scalar(x) if width == 3 => vec![x.clone(), x.clone(), x.clone()],
        _ => v.components(),
    }
}

fn side<S>(value: S) -> Side<S> {
    Side {
        label: "form",
        value,
        role: Role::Printed,
    }
}

/// Every printed form of `e` at `point`, in print order.
pub fn form_values(e: &Equation, point: &Point) -> Result<Vec<FormValue>, String> {
    form_values_of(e, e.latex(), point)
}

/// [`form_values`] of a given print of `e` (a perturbed copy, in tests).
pub fn form_values_of(e: &Equation, latex: &str, point: &Point) -> Result<Vec<FormValue>, String> {
    let (_, chains) = print_chains(e.number, latex)?;
    let models = Models {
        float: Rc::new(model(e, &point.float.0, &point.float.1)?),
        bound: Rc::new(model(e, &point.bound.0, &point.bound.1)?),
        exact: match &point.exact {
            Some((l, s)) => Some(Rc::new(model(e, l, s)?)),
            None => None,
        },
    };
    // Each form's unit, as `ladder verify` judges it (the same forms in the same order).
    let units: Vec<String> = match print_form_units(e, latex) {
        Ok(u) => u.iter().flatten().map(|f| f.unit()).collect(),
        Err(err) => vec![format!("? ({err})"); chains.iter().map(Vec::len).sum()],
    };
    let mut out = Vec::new();
    for (ci, chain) in chains.iter().enumerate() {
        chain_rows(e, ci, chain, &models, &units, &mut out);
    }
    Ok(out)
}

/// The display's model at the state in each scalar (exact when the state is).
struct Models {
    float: Rc<Model<f64>>,
    bound: Rc<Model<Bound>>,
    exact: Option<Rc<Model<Rational>>>,
}

/// The rows of chain `ci` (from 0): each form's value, bound and exact value, held against the
/// chain's first form that is not a misprint.
fn chain_rows(
    e: &Equation,
    ci: usize,
    chain: &[Form],
    models: &Models,
    units: &[String],
    out: &mut Vec<FormValue>,
) {
    let vf: Vec<_> = chain
        .iter()
        .map(|f| eval_form(e, f, &models.float))
        .collect();
    let vb: Vec<_> = chain
        .iter()
        .map(|f| eval_form(e, f, &models.bound))
        .collect();
    let vq: Vec<Option<Result<Value<Rational>, String>>> = chain
        .iter()
        .map(|f| models.exact.as_ref().map(|m| exact_guarded(e, f, m)))
        .collect();
    let width = vf
        .iter()
        .flatten()
        .map(|v| v.components().len())
        .max()
        .unwrap_or(1);
    let base = chain
        .iter()
        .position(|f| f.role != Role::Misprint)
        .unwrap_or(0);
    for (k, f) in chain.iter().enumerate() {
        let mut row = blank_row(e, ci, k, f, out.len() + 1, units[out.len()].clone());
        match (&vf[k], &vb[k]) {
            (Ok(x), Ok(xb)) => {
                row.value = comps(x, width);
                row.bound = comps(xb, width).iter().map(Bound::abs_error).collect();
                if row.value.iter().any(|v| !v.is_finite()) {
                    row.error = Some(NOT_FINITE.into());
                    row.value = Vec::new();
                    out.push(row);
                    continue;
                }
                if let (true, Ok(b0), Ok(bb0)) = (k != base, &vf[base], &vb[base]) {
                    float_agreement(&mut row, (b0, bb0), (x, xb), width);
                }
            }
            (Err(err), _) | (_, Err(err)) => row.error = Some(err.clone()),
        }
        if let Some(Ok(q)) = &vq[k] {
            row.exact = Some(comps(q, width).iter().map(ToString::to_string).collect());
            if let (true, Some(Ok(q0))) = (k != base, &vq[base]) {
                let chains: Vec<Vec<Side<Rational>>> = comps(q0, width)
                    .into_iter()
                    .zip(comps(q, width))
                    .map(|(a, b)| vec![side(a), side(b)])
                    .collect();
                row.exact_agrees = Some(exact_residual(&chains).0);
            }
        }
        out.push(row);
    }
}

/// Form `k` of chain `ci` before evaluation: its place (`index`, from 1), print, role and unit.
fn blank_row(e: &Equation, ci: usize, k: usize, f: &Form, index: usize, unit: String) -> FormValue {
    let role = if e.continues.is_some() && ci == 0 && k == 0 {
        "continued"
    } else if f.role == Role::Misprint {
        "misprint"
    } else {
        "printed"
    };
    FormValue {
        index,
        chain: ci + 1,
        latex: f.text.clone(),
        unicode: crate::print::unicode::unicode(&f.text),
        role,
        milne: f.milne,
        value: Vec::new(),
        bound: Vec::new(),
        exact: None,
        unit,
        residual: None,
        agrees: None,
        exact_agrees: None,
        error: None,
    }
}

/// A form's f64 agreement with its chain's first form: the residual in units of the running
/// error bounds (the registry's verdict, [`float_residual`]), component by component.
fn float_agreement(
    row: &mut FormValue,
    (b0, bb0): (&Value<f64>, &Value<Bound>),
    (x, xb): (&Value<f64>, &Value<Bound>),
    width: usize,
) {
    let pairs: (Chains<f64>, Chains<Bound>) = comps(b0, width)
        .into_iter()
        .zip(comps(x, width))
        .zip(comps(bb0, width).into_iter().zip(comps(xb, width)))
        .map(|((a, b), (ab, bb))| (vec![side(a), side(b)], vec![side(ab), side(bb)]))
        .unzip();
    let (scaled, _) = float_residual(&pairs.0, &pairs.1);
    row.residual = Some(scaled);
    row.agrees = Some(scaled <= TOLERANCE_FACTOR);
}
