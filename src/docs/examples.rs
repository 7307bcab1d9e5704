//! Executable examples for the book: functions of plain numbers that a markdown table can call.
//!
//! A table whose first header cell is `` `name` `` calls the example `name` on each row: the
//! first cells are the inputs, then the expected value, then the tolerance (absolute). The
//! expected values in the book come from the note's closed forms, computed by hand (or by a
//! calculator), never from these functions.

use crate::ladder::analysis::{solve_angular_acceleration, AngularMomentum, Reference};
use crate::ladder::forces::wall_force;
use crate::ladder::geometry::Corner;
use crate::ladder::{Ladder, State};

/// An example: name, number of inputs, the function.
pub struct Example {
    /// Name used in the table header.
    pub name: &'static str,
    /// Number of inputs.
    pub inputs: usize,
    /// The function.
    pub run: fn(&[f64]) -> Result<f64, String>,
}

/// Every example the book may call.
pub fn all() -> Vec<Example> {
    vec![
        Example {
            name: "separation_angle",
            inputs: 2,
            run: separation_angle,
        },
        Example {
            name: "analysis_about",
            inputs: 3,
            run: analysis_about,
        },
    ]
}

/// θ at which the wall force (14) on the motion, with θ̈ from (5) and θ̇² from the energy of a
/// start (θ0, θ̇0) (units m = l = 1, g = 4/3 so that Ω² = 3g/4l = 1), changes sign: found by
/// bisection on [θ0, π/2] down to adjacent floats. Inputs: θ0, θ̇0.
pub fn separation_angle(x: &[f64]) -> Result<f64, String> {
    let (theta0, rate0) = (x[0], x[1]);
    if !(0.0..std::f64::consts::FRAC_PI_2).contains(&theta0) || !rate0.is_finite() {
        return Err(format!("θ0 = {theta0} must be in [0, π/2), θ̇0 finite"));
    }
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 4.0 / 3.0,
    };
    let f_w = |th: f64| {
        let (s, c) = th.sin_cos();
        let rate2 = rate0 * rate0 + 2.0 * (theta0.cos() - c);
        let st = State {
            sin: s,
            cos: c,
            rate: rate2.max(0.0).sqrt(),
            accel: s,
            jerk: 0.0,
        };
        wall_force(&ladder, &st)
    };
    let (mut lo, mut hi) = (theta0, std::f64::consts::FRAC_PI_2);
    if f_w(hi) >= 0.0 {
        return Err("the wall force does not change sign before π/2".into());
    }
    if lo > 0.0 && f_w(lo) <= 0.0 {
        return Ok(lo);
    }
    while hi - lo > 0.0 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f_w(mid) > 0.0 {
            lo = mid
        } else {
            hi = mid
        }
    }
    Ok(0.5 * (lo + hi))
}

/// θ̈ solved from the torque analysis about point k = 1..5 (A..E), with L'_P (eq. 40), at angle
/// θ and rate θ̇, for m = l = 1, g = 4/3 (so eq. (5) gives θ̈ = sin θ). Inputs: k, θ, θ̇.
pub fn analysis_about(x: &[f64]) -> Result<f64, String> {
    let k = x[0] as usize;
    let corner = *Corner::ALL
        .get(k.wrapping_sub(1))
        .ok_or(format!("point {k} is not 1..=5 (A..E)"))?;
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 4.0 / 3.0,
    };
    let (s, c) = x[1].sin_cos();
    let st = State {
        sin: s,
        cos: c,
        rate: x[2],
        accel: 0.0,
        jerk: 0.0,
    };
    Ok(solve_angular_acceleration(
        &Reference::Corner(corner),
        AngularMomentum::Relative,
        &ladder,
        &st,
    ))
}

/// Run one example table; returns the number of rows run. Problems go to `problems` as
/// `file:line: ...` (the table's line).
pub fn run_table(at: &str, table: &[Vec<String>], problems: &mut Vec<String>) -> usize {
    let Some(header) = table.first() else {
        return 0;
    };
    let Some(first) = header.first() else {
        return 0;
    };
    let name = first.split('(').next().unwrap_or("").trim();
    let Some(ex) = all().into_iter().find(|e| e.name == name) else {
        return 0; // an ordinary table
    };
    let mut run = 0;
    for (r, row) in table.iter().enumerate().skip(1) {
        let nums: Result<Vec<f64>, _> = row.iter().map(|c| parse_number(c)).collect();
        let nums = match nums {
            Ok(v) if v.len() == ex.inputs + 2 => v,
            Ok(v) => {
                problems.push(format!("{at}: row {r} of `{name}` has {} numbers, expected {} inputs + expected + tolerance", v.len(), ex.inputs));
                continue;
            }
            Err(c) => {
                problems.push(format!("{at}: row {r} of `{name}`: '{c}' is not a number"));
                continue;
            }
        };
        let (inputs, expected, tol) = (&nums[..ex.inputs], nums[ex.inputs], nums[ex.inputs + 1]);
        run += 1;
        match (ex.run)(inputs) {
            Ok(got) if (got - expected).abs() <= tol => {}
            Ok(got) => problems.push(format!("{at}: row {r} of `{name}`{inputs:?}: got {got:.17e}, expected {expected:.17e} ± {tol:e}")),
            Err(e) => problems.push(format!("{at}: row {r} of `{name}`{inputs:?}: {e}")),
        }
    }
    run
}

fn parse_number(cell: &str) -> Result<f64, String> {
    let c = cell.trim().trim_matches('`');
    c.parse::<f64>().map_err(|_| cell.to_string())
}
