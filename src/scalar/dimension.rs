//! `Dim`: a scalar whose value is a physical dimension, not a number (dimensional analysis).
//!
//! Evaluating an equation in `Dim` answers the physicist's first question about it: do its terms
//! have units that can be added at all? A [`Dimension`] is the exponent vector of mass, length and
//! time, M^a L^b T^c, with small rational exponents (so a square root halves them). The scalar
//! rules are those of dimensional analysis:
//!
//! * a product adds exponents, a quotient subtracts them, a power scales them;
//! * a nonzero number is dimensionless; an exact **zero** ([`Dim::Zero`]) has every dimension
//!   (it is the additive identity of each), which is what the "0" side of `τ = 0` and the zero
//!   derivative of a constant mean;
//! * a sum or difference of unlike dimensions is **recorded**, not accepted: the trait's
//!   operators cannot return errors, so the value becomes [`Dim::Inconsistent`], carrying the
//!   first clash met (both dimensions, the operation and, once known, where) and absorbing every
//!   later operation, like a NaN that remembers its cause. Division by an exact zero is recorded
//!   the same way.
//!
//! Time derivatives need nothing special: `Dim`'s dual is the crate's [`Jet`], and lifting a state
//! along the motion (θ̇ → θ̇ + θ̈ ε) puts T⁻¹ · (dimension) in every ε part, so d/dt divides by T by
//! itself. The project never takes sin or cos (sin θ and cos θ are carried in the state), so the
//! only place an angle enters is the state; [`Dim::require_dimensionless`] checks arguments there.
//!
//! Why hand-written: compile-time unit crates (uom, dimensioned) put the dimension in the type,
//! so one generic function cannot be evaluated "in dimensions", and a printed formula parsed at
//! run time has no static type at all. Runtime crates exist (dimensional_analyser: a `Quantity`
//! with a value whose addition returns a `Result`; iridium-units: value plus unit with
//! conversions), but none has a value-less dimension with a dimension-polymorphic zero and an
//! absorbing "inconsistent" state that records the clash, which is what a `Scalar` needs (its
//! `+` must return `Self`); both would need a wrapper doing all of that anyway, over an exponent
//! vector that is three `Ratio<i32>`s (num-rational, already a dependency).

use super::{Jet, Scalar};
use num_rational::Ratio;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exponent of a base dimension: a small rational.
pub type Exponent = Ratio<i32>;

/// A physical dimension M^m L^l T^t.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dimension {
    /// Exponent of mass.
    pub m: Exponent,
    /// Exponent of length.
    pub l: Exponent,
    /// Exponent of time.
    pub t: Exponent,
}

impl Dimension {
    /// A pure number.
    pub const NONE: Dimension = Dimension::new(0, 0, 0);
    /// Mass, M (kg).
    pub const MASS: Dimension = Dimension::new(1, 0, 0);
    /// Length, L (m).
    pub const LENGTH: Dimension = Dimension::new(0, 1, 0);
    /// Time, T (s).
    pub const TIME: Dimension = Dimension::new(0, 0, 1);

    /// M^m L^l T^t with integer exponents.
    pub const fn new(m: i32, l: i32, t: i32) -> Self {
        Dimension {
            m: Ratio::new_raw(m, 1),
            l: Ratio::new_raw(l, 1),
            t: Ratio::new_raw(t, 1),
        }
    }
    /// True for a pure number.
    pub fn is_dimensionless(self) -> bool {
        self == Dimension::NONE
    }
    /// The dimension raised to a rational power p (p = 1/2 for a square root).
    pub fn pow(self, p: Exponent) -> Self {
        Dimension {
            m: self.m * p,
            l: self.l * p,
            t: self.t * p,
        }
    }
    /// Parse "M L^2 T^-1", "M L T^-2", "L^1/2", "1" (dimensionless); factors separated by spaces
    /// or `·`/`*`, a base letter may repeat (exponents add).
    pub fn parse(text: &str) -> Result<Self, String> {
        let mut d = Dimension::NONE;
        let cleaned = text.replace(['·', '*'], " ");
        for factor in cleaned.split_whitespace() {
            if factor == "1" {
                continue;
            }
            let (base, exp) = match factor.split_once('^') {
                Some((b, e)) => (
                    b,
                    e.trim_matches(|c| c == '{' || c == '}' || c == '(' || c == ')'),
                ),
                None => (factor, "1"),
            };
            let exp: Exponent = match exp.split_once('/') {
                Some((n, k)) => {
                    let (n, k) = (n.parse::<i32>(), k.parse::<i32>());
                    match (n, k) {
                        (Ok(n), Ok(k)) if k != 0 => Ratio::new(n, k),
                        _ => return Err(format!("bad exponent in '{factor}'")),
                    }
                }
                None => Ratio::from_integer(
                    exp.parse::<i32>()
                        .map_err(|_| format!("bad exponent in '{factor}'"))?,
                ),
            };
            let unit = match base {
                "M" => Dimension::MASS,
                "L" => Dimension::LENGTH,
                "T" => Dimension::TIME,
                _ => return Err(format!("unknown base dimension '{base}' (M, L or T)")),
            };
            d = d * unit.pow(exp);
        }
        Ok(d)
    }
    /// The SI unit of this dimension, in base units ("kg m^2 s^-1"); "1" for a pure number.
    pub fn si_unit(self) -> String {
        self.render(["kg", "m", "s"], |e| format!("^{e}"))
    }
    fn render(self, names: [&str; 3], exp: impl Fn(Exponent) -> String) -> String {
        let parts: Vec<String> = [self.m, self.l, self.t]
            .iter()
            .zip(names)
            .filter(|(e, _)| **e != Ratio::from_integer(0))
            .map(|(&e, n)| {
                if e == Ratio::from_integer(1) {
                    n.to_string()
                } else {
                    format!("{n}{}", exp(e))
                }
            })
            .collect();
        if parts.is_empty() {
            "1".into()
        } else {
            parts.join(" ")
        }
    }
}

fn superscript(e: Exponent) -> String {
    let digits = |s: String| -> String {
        s.chars()
            .map(|c| match c {
                '-' => '⁻',
                '/' => 'ᐟ',
                d => "⁰¹²³⁴⁵⁶⁷⁸⁹"
                    .chars()
                    .nth(d as usize - '0' as usize)
                    .unwrap_or(d),
            })
            .collect()
    };
    digits(e.to_string())
}

/// "M L² T⁻¹"; "1" for a pure number.
impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(["M", "L", "T"], superscript))
    }
}

impl Mul for Dimension {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Dimension {
            m: self.m + o.m,
            l: self.l + o.l,
            t: self.t + o.t,
        }
    }
}

impl Div for Dimension {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        self * o.pow(Ratio::from_integer(-1))
    }
}

/// What made a value dimensionally inconsistent.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Clash {
    /// `left op right` with unlike dimensions (op is "+" or "−", or "," between the components of
    /// a vector).
    Unlike {
        /// The operation.
        op: &'static str,
        /// Dimension of the left operand.
        left: Dimension,
        /// Dimension of the right operand.
        right: Dimension,
    },
    /// Division by an exact zero.
    DivisionByZero,
    /// Something that must be a pure number (an angle, the argument of sin) is not.
    NotDimensionless {
        /// What it was.
        what: String,
        /// Its dimension.
        dimension: Dimension,
    },
}

/// A clash and where it happened (filled in by whoever knows: a side's label, a printed form).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Inconsistency {
    /// What clashed.
    pub clash: Clash,
    /// Where, when known.
    pub at: Option<String>,
}

impl fmt::Display for Inconsistency {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.clash {
            Clash::Unlike { op, left, right } => write!(f, "{left} {op} {right}")?,
            Clash::DivisionByZero => write!(f, "division by an exact zero")?,
            Clash::NotDimensionless { what, dimension } => {
                write!(f, "{what} has dimension {dimension}, not a pure number")?
            }
        }
        if let Some(at) = &self.at {
            write!(f, " in {at}")?;
        }
        Ok(())
    }
}

/// The dimension of a value, as a scalar: see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub enum Dim {
    /// An exact zero: of every dimension.
    Zero,
    /// A value of one dimension.
    Of(Dimension),
    /// The first clash met; absorbs every later operation.
    Inconsistent(Box<Inconsistency>),
}

impl Dim {
    /// A value of dimension M^m L^l T^t.
    pub fn new(m: i32, l: i32, t: i32) -> Self {
        Dim::Of(Dimension::new(m, l, t))
    }
    /// The inconsistent value for a clash.
    pub fn clash(clash: Clash) -> Self {
        Dim::Inconsistent(Box::new(Inconsistency { clash, at: None }))
    }
    /// The dimension, if the value has one (`None` for zero or inconsistent).
    pub fn dimension(&self) -> Option<Dimension> {
        match self {
            Dim::Of(d) => Some(*d),
            _ => None,
        }
    }
    /// The inconsistency, if any.
    pub fn inconsistency(&self) -> Option<&Inconsistency> {
        match self {
            Dim::Inconsistent(i) => Some(i),
            _ => None,
        }
    }
    /// Say where an inconsistency happened (kept if already known).
    pub fn at(self, place: &str) -> Self {
        match self {
            Dim::Inconsistent(mut i) => {
                i.at.get_or_insert_with(|| place.to_string());
                Dim::Inconsistent(i)
            }
            d => d,
        }
    }
    /// Demand a pure number (an angle, an argument of sin, cos or exp); otherwise inconsistent.
    pub fn require_dimensionless(self, what: &str) -> Self {
        match self {
            Dim::Of(d) if !d.is_dimensionless() => Dim::clash(Clash::NotDimensionless {
                what: what.to_string(),
                dimension: d,
            }),
            d => d,
        }
    }
    /// The value raised to a rational power (a root halves the exponents).
    pub fn pow(self, p: Exponent) -> Self {
        match self {
            Dim::Of(d) => Dim::Of(d.pow(p)),
            d => d,
        }
    }
    fn sum(self, o: Dim, op: &'static str) -> Dim {
        match (self, o) {
            (Dim::Inconsistent(i), _) | (_, Dim::Inconsistent(i)) => Dim::Inconsistent(i),
            (Dim::Zero, d) | (d, Dim::Zero) => d,
            (Dim::Of(a), Dim::Of(b)) if a == b => Dim::Of(a),
            (Dim::Of(left), Dim::Of(right)) => Dim::clash(Clash::Unlike { op, left, right }),
        }
    }
}

impl Add for Dim {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        self.sum(o, "+")
    }
}

impl Sub for Dim {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self.sum(o, "−")
    }
}

impl Mul for Dim {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        match (self, o) {
            (Dim::Inconsistent(i), _) | (_, Dim::Inconsistent(i)) => Dim::Inconsistent(i),
            (Dim::Zero, _) | (_, Dim::Zero) => Dim::Zero,
            (Dim::Of(a), Dim::Of(b)) => Dim::Of(a * b),
        }
    }
}

impl Div for Dim {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        match (self, o) {
            (Dim::Inconsistent(i), _) | (_, Dim::Inconsistent(i)) => Dim::Inconsistent(i),
            (_, Dim::Zero) => Dim::clash(Clash::DivisionByZero),
            (Dim::Zero, _) => Dim::Zero,
            (Dim::Of(a), Dim::Of(b)) => Dim::Of(a / b),
        }
    }
}

impl Neg for Dim {
    type Output = Self;
    fn neg(self) -> Self {
        self
    }
}

impl Scalar for Dim {
    type Dual = Jet<Dim>;
    fn int(n: i64) -> Self {
        if n == 0 {
            Dim::Zero
        } else {
            Dim::Of(Dimension::NONE)
        }
    }
    fn lift(re: Self, eps: Self) -> Jet<Dim> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Dim>) -> (Self, Self) {
        (d.re, d.eps)
    }
    /// A dimension has no numerical value.
    fn to_f64(&self) -> f64 {
        f64::NAN
    }
}
