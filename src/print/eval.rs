//! Evaluating a parsed form in any [`Scalar`], against the project's independent models.
//!
//! Symbols resolve through the symbol table to quantities of the three-particle ladder or of a
//! general particle system ([`super::quantity`]), never to the formula being checked. `d/dt`
//! evaluates its operand on the context lifted along the motion and reads the ε part; ∂/∂θ and
//! ∂/∂θ̇ lift only that variable. A dotted symbol without an entry of its own is the time
//! derivative of the undotted one. No sin or cos is ever taken: `\sin\theta` is the state's
//! carried sin θ.
//!
//! Derivatives nest through the type parameter `D` ([`Depth`]): evaluating in `S` at depth `D`
//! evaluates a derivative's operand in `S::Dual` at `D::Next`. The chain stops at depth 3 with an
//! error, which keeps the instantiation finite (an unbounded `eval::<S>` → `eval::<S::Dual>` would
//! not compile); (4) needs depth 2.
//!
//! An evaluation bar `…\Big|_{\mathbf{x}_P=0}` is a substitution ([`super::condition`]): the
//! form is evaluated in the model changed so that the condition holds at this instant.

use super::ast::Expr;
use super::quantity::{eps, resolve, Lift, Model, Value};
use super::symbols::{lookup, Entry};
use crate::scalar::Scalar;
use crate::vector::Vec3;

/// Where a form is evaluated.
pub struct Ctx<'t, S: Scalar> {
    /// The model the symbols resolve in.
    pub model: std::rc::Rc<Model<S>>,
    /// The section of the display (chooses the meaning of reused symbols).
    pub section: &'t str,
    /// The display's number (for equation-specific symbol entries).
    pub number: u32,
    /// True in Milne's part of the display.
    pub milne: bool,
    /// The particle a Σ is at.
    pub index: Option<usize>,
    /// The symbol table.
    pub table: &'t [Entry],
}

impl<'t, S: Scalar> Ctx<'t, S> {
    fn lifted(&self, how: Lift) -> Result<Ctx<'t, S::Dual>, String> {
        Ok(Ctx {
            model: std::rc::Rc::new(self.model.lifted(how)?),
            section: self.section,
            number: self.number,
            milne: self.milne,
            index: self.index,
            table: self.table,
        })
    }
    fn at(&self, index: usize) -> Ctx<'t, S> {
        Ctx {
            model: self.model.clone(),
            section: self.section,
            number: self.number,
            milne: self.milne,
            index: Some(index),
            table: self.table,
        }
    }
}

/// Derivative depth: evaluates a derivative's operand one dual level up.
pub trait Depth {
    /// How many derivatives deep (0: the instant itself, where a condition can be imposed).
    const LEVEL: u32;
    /// Evaluate `e` in the lifted context and return its ε part.
    fn derive<S: Scalar>(e: &Expr, ctx: &Ctx<S>, how: Lift) -> Result<Value<S>, String>;
}

macro_rules! depth {
    ($d:ident, $next:ident, $level:expr) => {
        /// A derivative depth.
        pub struct $d;
        impl Depth for $d {
            const LEVEL: u32 = $level;
            fn derive<S: Scalar>(e: &Expr, ctx: &Ctx<S>, how: Lift) -> Result<Value<S>, String> {
                let lifted = ctx.lifted(how)?;
                Ok(eps::<S>(eval::<S::Dual, $next>(e, &lifted)?))
            }
        }
    };
}
depth!(D0, D1, 0);
depth!(D1, D2, 1);
depth!(D2, D3, 2);
/// The deepest level: no further derivative.
pub struct D3;
impl Depth for D3 {
    const LEVEL: u32 = 3;
    fn derive<S: Scalar>(_: &Expr, _: &Ctx<S>, _: Lift) -> Result<Value<S>, String> {
        Err("derivatives nested deeper than three".into())
    }
}

/// Evaluate a form at depth 0.
pub fn evaluate<S: Scalar>(e: &Expr, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    eval::<S, D0>(e, ctx)
}

/// Evaluate a form.
pub fn eval<S: Scalar, D: Depth>(e: &Expr, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    use Value::{Scalar as Sc, Vector as Ve};
    let ev = |x: &Expr| eval::<S, D>(x, ctx);
    Ok(match e {
        Expr::Int(n) => Sc(S::int(*n)),
        Expr::Sym(k) => symbol::<S, D>(k, ctx)?,
        Expr::Const => return Err("\\text{const} is only a right side of '='".into()),
        Expr::Neg(a) => ev(a)?.neg(),
        Expr::Add(a, b) => ev(a)?.add(ev(b)?)?,
        Expr::Sub(a, b) => ev(a)?.add(ev(b)?.neg())?,
        Expr::Mul(a, b) => ev(a)?.mul(ev(b)?)?,
        Expr::Div(a, b) => match (ev(a)?, ev(b)?) {
            (Sc(x), Sc(y)) => Sc(x / y),
            (Ve(x), Sc(y)) => Ve(x.div(&y)),
            _ => return Err("division by a vector".into()),
        },
        Expr::Pow(a, n) => match ev(a)? {
            Sc(x) => Sc((1..*n).fold(x.clone(), |acc, _| acc * x.clone())),
            Ve(v) if *n == 2 => Sc(v.dot(&v)),
            Ve(_) => return Err("a vector to a power other than 2".into()),
        },
        Expr::Cross(a, b) => match (ev(a)?, ev(b)?) {
            (Ve(x), Ve(y)) => Ve(x.cross(&y)),
            _ => return Err("× of a scalar".into()),
        },
        Expr::Sin(a) | Expr::Cos(a) => trig(a, matches!(e, Expr::Sin(_)), ctx)?,
        Expr::Tuple(items) => tuple::<S, D>(items, ctx)?,
        Expr::Sum(a) => sum::<S, D>(a, ctx)?,
        // d/dt[…]_{cond}: the rate at the instant where the condition holds.
        Expr::Deriv(a) => match &**a {
            Expr::At(inner, conds) => {
                D::derive(inner, &at_condition::<S, D>(conds, ctx)?, Lift::Motion)?
            }
            _ => D::derive(a, ctx, Lift::Motion)?,
        },
        Expr::Partial(a, wrt) => partial::<S, D>(a, wrt, ctx)?,
        Expr::ZComp(a) => match ev(a)? {
            Ve(v) => Sc(v.z),
            Sc(_) => return Err("|_z of a scalar".into()),
        },
        Expr::At(a, conds) => eval::<S, D>(a, &at_condition::<S, D>(conds, ctx)?)?,
    })
}

/// `\sin\theta` or `\cos\theta`: the state's carried sin θ or cos θ (no sine is ever taken).
fn trig<S: Scalar>(a: &Expr, sin: bool, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    let is_angle = matches!(a, Expr::Sym(k) if quantity_of(k, ctx).as_deref() == Some("theta"));
    if !is_angle {
        return Err("sin/cos of anything but θ".into());
    }
    ctx.model.trig(sin)
}

/// A tuple of two or three scalars: a planar or a 3-vector.
fn tuple<S: Scalar, D: Depth>(items: &[Expr], ctx: &Ctx<S>) -> Result<Value<S>, String> {
    let mut c = Vec::new();
    for it in items {
        match eval::<S, D>(it, ctx)? {
            Value::Scalar(x) => c.push(x),
            Value::Vector(_) => return Err("a vector inside a tuple".into()),
        }
    }
    match c.len() {
        2 => Ok(Value::Vector(Vec3::planar(c[0].clone(), c[1].clone()))),
        3 => Ok(Value::Vector(Vec3::new(
            c[0].clone(),
            c[1].clone(),
            c[2].clone(),
        ))),
        _ => Err("a tuple of other than 2 or 3 components".into()),
    }
}

/// Σ over the particles: the operand at each particle index, added.
fn sum<S: Scalar, D: Depth>(a: &Expr, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    let n = ctx.model.particle_count()?;
    let mut acc: Option<Value<S>> = None;
    for i in 0..n {
        let v = eval::<S, D>(a, &ctx.at(i))?;
        acc = Some(match acc {
            None => v,
            Some(s) => s.add(v)?,
        });
    }
    Ok(acc.ok_or("a sum over no particles")?)
}

/// ∂/∂θ or ∂/∂θ̇ of the operand: the context lifted in that variable alone.
fn partial<S: Scalar, D: Depth>(a: &Expr, wrt: &str, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    let how = match quantity_of(wrt, ctx).as_deref() {
        Some("theta") => Lift::Angle,
        Some("theta_rate") => Lift::Rate,
        _ => return Err(format!("∂/∂{wrt} is not supported")),
    };
    D::derive(a, ctx, how)
}

/// The context with the condition of an evaluation bar imposed ([`super::condition`]): a
/// substitution at the instant, so only at depth 0 (inside a derivative it would also freeze the
/// rates the derivative reads).
fn at_condition<'t, S: Scalar, D: Depth>(
    conds: &[Expr],
    ctx: &Ctx<'t, S>,
) -> Result<Ctx<'t, S>, String> {
    if D::LEVEL > 0 {
        return Err("an evaluation bar inside d/dt (write it on the derivative)".into());
    }
    let model = super::condition::impose(
        &ctx.model,
        conds,
        |k| quantity_of(k, ctx),
        |f| eval::<S, D>(f, ctx),
    )?;
    Ok(Ctx {
        model: std::rc::Rc::new(model),
        section: ctx.section,
        number: ctx.number,
        milne: ctx.milne,
        index: ctx.index,
        table: ctx.table,
    })
}

/// The model of `ctx` with the condition `forms[0] = forms[1] = …` imposed at this instant (an
/// evaluation bar, or a premise of the display): [`super::condition::impose`].
pub fn with_condition<S: Scalar>(forms: &[Expr], ctx: &Ctx<S>) -> Result<Model<S>, String> {
    Ok(std::rc::Rc::unwrap_or_clone(
        at_condition::<S, D0>(forms, ctx)?.model,
    ))
}

fn quantity_of<S: Scalar>(key: &str, ctx: &Ctx<S>) -> Option<String> {
    lookup(ctx.table, key, ctx.section, ctx.number, ctx.milne).map(|e| e.quantity.clone())
}

/// A symbol: its entry's quantity; else, for `\dot{X}` / `\ddot{X}`, the time derivative of X.
fn symbol<S: Scalar, D: Depth>(key: &str, ctx: &Ctx<S>) -> Result<Value<S>, String> {
    if let Some(q) = quantity_of(key, ctx) {
        return resolve(&q, ctx.index, &ctx.model);
    }
    for (accent, inner) in [("\\dot{", 1), ("\\ddot{", 2)] {
        if let Some(rest) = key.strip_prefix(accent) {
            // `\dot{X}_{sub}`: the base is `X_{sub}`.
            if let Some(close) = matching_brace(rest) {
                let base = format!("{}{}", &rest[..close], &rest[close + 1..]);
                let mut e = Expr::Sym(base);
                for _ in 0..inner {
                    e = Expr::Deriv(Box::new(e));
                }
                return eval::<S, D>(&e, ctx);
            }
        }
    }
    Err(format!(
        "symbol {key} is not in the symbol table for sec. {}",
        ctx.section
    ))
}

fn matching_brace(s: &str) -> Option<usize> {
    let mut depth = 1;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}
