//! `ladder diagram`: the force diagram of a torque analysis about any point P at any state, as
//! SVG (issue 16, item 2): the five of the book (A-E at the worked example's state, under
//! `equations/figures/`) are `ladder diagram --about A` .. `E`; a point of the ladder or of the
//! lab gives the same picture about it, with the coordinate force −m a_P where P accelerates.

use crate::ladder::analysis::Reference;
use crate::ladder::geometry::Corner;
use crate::report::diagram::diagram;
use crate::report::diagram::svg::draw_svg;
use crate::scalar::{rational_from_float, Rational};
use clap::Args;
use num_traits::{One, ToPrimitive, Zero};
use std::process::ExitCode;

/// The options of `ladder diagram`.
#[derive(Args)]
pub struct DiagramArgs {
    /// The reference point: A, B, C, D, E; `ladder:1/4` (the point of the ladder 1/4 of the way
    /// from C to D); or `lab:0.5,1` (a point fixed in the lab, in units of l).
    #[arg(long, default_value = "A")]
    about: String,
    /// The state, as for `ladder show --at` (default: the book's worked example, 1 kg, 1 m,
    /// 9.81 m/s², θ = 30° from rest upright).
    #[arg(long)]
    at: Option<String>,
    /// Write the SVG to this file instead of stdout.
    #[arg(long)]
    out: Option<std::path::PathBuf>,
}

/// A fraction `p/q` or a decimal, exactly.
fn rational(text: &str) -> Option<Rational> {
    let t = text.trim();
    if let Some((p, q)) = t.split_once('/') {
        let (p, q): (i64, i64) = (p.trim().parse().ok()?, q.trim().parse().ok()?);
        return (q != 0).then(|| Rational::new(p.into(), q.into()));
    }
    let x: f64 = t.parse().ok()?;
    x.is_finite().then(|| rational_from_float(x)).flatten()
}

/// Numerators over a common denominator, all in i64.
fn common(values: &[Rational]) -> Option<(Vec<i64>, i64)> {
    let mut den = Rational::one();
    for v in values {
        let d = Rational::from_integer(v.denom().clone());
        den = Rational::from_integer(num_integer::Integer::lcm(den.numer(), d.numer()));
    }
    let nums = values
        .iter()
        .map(|v| (v * &den).to_integer().to_i64())
        .collect::<Option<Vec<_>>>()?;
    Some((nums, den.to_integer().to_i64()?))
}

/// The point named by `--about`, with its name in the drawing and a description.
pub fn parse_about(text: &str) -> Result<(Reference, String, String), String> {
    let t = text.trim();
    if let Some(k) = Corner::ALL
        .iter()
        .find(|k| k.name().eq_ignore_ascii_case(t))
    {
        return Ok((
            Reference::Corner(*k),
            k.name().to_string(),
            format!("the point {}", k.name()),
        ));
    }
    let bad = || {
        format!("--about: '{text}' is not A-E, ladder:FRACTION (0 = C, 1 = D) or lab:X,Y (in units of l)")
    };
    if let Some(f) = t.strip_prefix("ladder:") {
        let q = rational(f).ok_or_else(bad)?;
        if q < Rational::zero() || q > Rational::one() {
            return Err(format!("--about: '{f}' is not between 0 (C) and 1 (D)"));
        }
        let (n, d) = common(std::slice::from_ref(&q)).ok_or_else(bad)?;
        return Ok((
            Reference::OnLadder(n[0], d),
            "P".into(),
            format!("P: the point of the ladder {q} of the way from C to D"),
        ));
    }
    if let Some(xy) = t.strip_prefix("lab:") {
        let (x, y) = xy.split_once(',').ok_or_else(bad)?;
        let (x, y) = (rational(x).ok_or_else(bad)?, rational(y).ok_or_else(bad)?);
        let (n, d) = common(&[x.clone(), y.clone()]).ok_or_else(bad)?;
        return Ok((
            Reference::Lab(n[0], n[1], d),
            "P".into(),
            format!("P: fixed in the lab at ({x} l, {y} l)"),
        ));
    }
    Err(bad())
}

/// Run `ladder diagram`.
pub fn run(a: DiagramArgs) -> ExitCode {
    let fail = |msg: String| {
        eprintln!("ladder diagram: {msg}");
        ExitCode::from(2)
    };
    let (point, name, description) = match parse_about(&a.about) {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let at = match a.at.as_deref().map(crate::show::at::parse_at) {
        None => crate::show::state::default_at(),
        Some(Ok(at)) => at,
        Some(Err(e)) => return fail(e),
    };
    let (ladder, st) = crate::show::state::build(&at).float;
    let mut d = diagram(&name, &point, &ladder, &st);
    if name == "P" {
        d.description = Some(description);
    }
    let svg = draw_svg(&d);
    match a.out {
        None => {
            print!("{svg}");
            ExitCode::SUCCESS
        }
        Some(path) => match std::fs::write(&path, svg) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => fail(format!("{}: {e}", path.display())),
        },
    }
}
