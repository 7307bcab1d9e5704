//! Worked examples for the torque-analysis sections, generated from the code.
//!
//! Each torque analysis (16), (19), (22), (25), (28), and those of Appendix A about C, (53)
//! (Jensen's method 1) and (59) (Hu's method), is evaluated at one stated state of the
//! ladder (m = 1 kg, l = 1 m, g = 9.81 m/s², θ = 30°, released from rest upright so that θ̇ comes
//! from (10)), once on the motion (θ̈ from (5)) and once off it (θ̈ = 0, same θ and θ̇). The
//! table shows the two sides of the display's law `=` ([`crate::registry::Law`]): equal on the
//! motion, unequal off it, with the side right of the law unchanged (it holds for any θ̈), and
//! a misprinted form's own value beside them ((28)). The
//! book carries the generated text between `<!-- worked-example N -->` and
//! `<!-- end worked-example -->`; the doc harness regenerates it and reports any difference, so
//! the numbers cannot drift from the code. `LADDER_BLESS_DOCS=1 cargo test --test book docs` rewrites
//! the blocks after a deliberate change.

use crate::ladder::energy::{angular_acceleration, rate_squared};
use crate::ladder::forces::{floor_force, wall_force};
use crate::ladder::{Ladder, State};
use crate::registry::{equations, Eval, Role};

/// The stated example: m (kg), l (m), g (m/s²), θ (degrees).
pub const EXAMPLE: (f64, f64, f64, f64) = (1.0, 1.0, 9.81, 30.0);

/// The example ladder and its state: on the motion (θ̈ from (5)) or off it (θ̈ = 0).
pub fn example_state(on_motion: bool) -> (Ladder<f64>, State<f64>) {
    let (m, l, g, deg) = EXAMPLE;
    let ladder = Ladder { m, l, g };
    let (sin, cos) = deg.to_radians().sin_cos();
    let mut st = State {
        sin,
        cos,
        rate: 0.0,
        accel: 0.0,
        jerk: 0.0,
    };
    st.rate = rate_squared(&ladder, &st).sqrt();
    if on_motion {
        st.accel = angular_acceleration(&ladder, &st);
        // d/dt of (5): Ω² cos θ θ̇ (only derivatives of θ̈-dependent quantities need it).
        st.jerk = ladder.big_omega2() * cos * st.rate;
    }
    (ladder, st)
}

/// The display forms (printed or corrected sides, in order, with labels) of equation `number`'s
/// first on-shell ladder check, in f64 at `st`.
fn forms(
    number: u32,
    ladder: &Ladder<f64>,
    st: &State<f64>,
) -> Result<Vec<(&'static str, f64)>, String> {
    sides(number, ladder, st, &[Role::Printed, Role::Corrected])
}

/// The sides of equation `number`'s first on-shell ladder chain with one of `roles`, in f64.
fn sides(
    number: u32,
    ladder: &Ladder<f64>,
    st: &State<f64>,
    roles: &[Role],
) -> Result<Vec<(&'static str, f64)>, String> {
    let e = equations()
        .into_iter()
        .find(|e| e.number == number)
        .ok_or(format!("({number}) is not registered"))?;
    let f = e
        .checks
        .iter()
        .find_map(|c| match c.eval {
            Eval::Ladder(sort, f) if sort.on_shell() => Some(f),
            _ => None,
        })
        .ok_or(format!("({number}) has no on-shell ladder check"))?;
    let chains = (f.float)(ladder, st);
    Ok(chains
        .first()
        .ok_or(format!("({number}) has no chain"))?
        .iter()
        .filter(|s| roles.contains(&s.role))
        .map(|s| (s.label, s.value))
        .collect())
}

/// Round for display: four decimals (the example's exact values, such as −2ml²θ̈/3 = −2.4525,
/// end in a 5 at the fourth), a true minus sign, and never "−0.0000".
fn num(x: f64) -> String {
    let s = format!("{x:.4}");
    if s == "-0.0000" {
        "0.0000".into()
    } else {
        s.replace('-', "−")
    }
}

/// The worked example of torque analysis `number`, as markdown: the state, a table of the
/// forces (14), (15) and the two sides of the law on and off the motion, the misprints, and
/// what the numbers show.
pub fn worked_example(number: u32) -> Result<String, String> {
    let e = equations()
        .into_iter()
        .find(|e| e.number == number)
        .ok_or(format!("({number}) is not registered"))?;
    let law = e.law.ok_or(format!("({number}) marks no law step"))?;
    let k = law.step as usize;
    let (ladder, on) = example_state(true);
    let (_, off) = example_state(false);
    let (f_on, f_off) = display_forms(number, k, &ladder, &on, &off)?;
    let mut out = opening(law, &on);
    out.push_str("| quantity | on the motion | off the motion (θ̈ = 0) |\n|---|---|---|\n");
    out.push_str(&format!(
        "| F_w, (14) | {} N | {} N |\n| F_f, (15) | {} N | {} N |\n",
        num(wall_force(&ladder, &on)),
        num(wall_force(&ladder, &off)),
        num(floor_force(&ladder, &on)),
        num(floor_force(&ladder, &off)),
    ));
    let last = f_on.len() - 1;
    out.push_str(&law_rows(&f_on, &f_off, k));
    out.push('\n');
    // A misprinted form (kept as printed in the code) agrees with neither side, on the motion
    // or off it: the reader sees the erratum in numbers.
    let (m_on, m_off) = (
        sides(number, &ladder, &on, &[Role::Misprint])?,
        sides(number, &ladder, &off, &[Role::Misprint])?,
    );
    if !m_on.is_empty() {
        out.truncate(out.len() - 1);
        for ((label, v_on), (_, v_off)) in m_on.iter().zip(&m_off) {
            out.push_str(&format!(
                "| misprint ([ERRATA.md](ERRATA.md)): {label} | {} N·m | {} N·m |\n",
                num(*v_on),
                num(*v_off)
            ));
        }
        out.push('\n');
    }
    out.push_str(&closing(!m_on.is_empty(), last > k));
    Ok(out)
}

/// The forms of display `number` on and off the motion, checked to reach the law's `=` no. `k`.
/// A display whose first printed form is dL/dt (as (53): "dL_C/dt = ...") may carry it in the
/// chain as the reference it is checked against (dL_C/dt of the particles, by AD); then that
/// reference is the display's first form.
#[allow(clippy::type_complexity)]
fn display_forms(
    number: u32,
    k: usize,
    ladder: &Ladder<f64>,
    on: &State<f64>,
    off: &State<f64>,
) -> Result<(Vec<(&'static str, f64)>, Vec<(&'static str, f64)>), String> {
    let (mut f_on, mut f_off) = (forms(number, ladder, on)?, forms(number, ladder, off)?);
    if k == f_on.len() {
        let first = |st| sides(number, ladder, st, &[Role::Reference]).map(|r| r.first().copied());
        if let (Some(a), Some(b)) = (first(on)?, first(off)?) {
            f_on.insert(0, a);
            f_off.insert(0, b);
        }
    }
    if k >= f_on.len() {
        return Err(format!("({number}): law step {k} but {} forms", f_on.len()));
    }
    Ok((f_on, f_off))
}

/// The paragraph before the table: the example's state, θ̇ by (10), θ̈ on and off the motion,
/// and which `=` is the law.
fn opening(law: crate::registry::Law, on: &State<f64>) -> String {
    let (m, l, g, deg) = EXAMPLE;
    format!(
        "**Worked example** (generated from the code, `docs::worked`): m = {m} kg, l = {l} m, \
         g = {g} m/s², θ = {deg}°, released from rest upright, so θ̇ = {:.3} s⁻¹ by (10). On the \
         motion θ̈ = {:.3} s⁻² by (5); off it, the same θ and θ̇ with θ̈ = 0. The law is the {} `=` of \
         the display: {}.\n\n",
        on.rate,
        on.accel,
        crate::docs::ordinal(law.step),
        law.statement
    )
}

/// The table's rows for the two sides of the law (`=` no. `k`) and, unless the right of the
/// law is the last form already, the display's last form.
fn law_rows(f_on: &[(&'static str, f64)], f_off: &[(&'static str, f64)], k: usize) -> String {
    let last = f_on.len() - 1;
    let mut out = format!(
        "| left of the law: {} | {} N·m | {} N·m |\n| right of the law: {} | {} N·m | {} N·m |\n",
        f_on[k - 1].0,
        num(f_on[k - 1].1),
        num(f_off[k - 1].1),
        f_on[k].0,
        num(f_on[k].1),
        num(f_off[k].1),
    );
    if last > k {
        out.push_str(&format!(
            "| last form of the display: {} | {} N·m | {} N·m |\n",
            f_on[last].0,
            num(f_on[last].1),
            num(f_off[last].1),
        ));
    }
    out
}

/// The sentence after the table: what agrees on the motion (every form, or all but the
/// misprint) and why the chain breaks off it at the law alone.
fn closing(has_misprint: bool, forms_after_law: bool) -> String {
    let mut out = String::from(if has_misprint {
        "On the motion every form agrees but the misprint. Off it"
    } else {
        "On the motion every form agrees. Off it"
    });
    out.push_str(if forms_after_law {
        " the two sides of the law differ, while the forms \
         right of the law still agree with one another: each `=` among them is algebra with the \
         forces the motion requires, (14) and (15), and holds for any θ̈. The chain breaks at the \
         law alone, which is why the display holds on the motion only.\n"
    } else {
        " the two sides of the law differ: every other `=` \
         is algebra or kinematics, with the forces the motion requires, (14) and (15), and holds \
         for any θ̈. The chain breaks at the law alone, which is why the display holds on the \
         motion only.\n"
    });
    out
}

/// The opening and closing markers of a generated block.
pub fn markers(number: u32) -> (String, &'static str) {
    (
        format!("<!-- worked-example {number} -->"),
        "<!-- end worked-example -->",
    )
}

/// Every generated block of `src` as (number, line of the opening marker, text between markers).
pub fn blocks(src: &str) -> Vec<(u32, usize, String)> {
    let mut out = Vec::new();
    let mut rest = 0;
    while let Some(i) = src[rest..].find("<!-- worked-example ") {
        let start = rest + i;
        let head_end = src[start..]
            .find("-->")
            .map_or(src.len(), |j| start + j + 3);
        let number = src[start + 20..head_end.saturating_sub(3)]
            .trim()
            .parse()
            .unwrap_or(0);
        let body_end = src[head_end..]
            .find("<!-- end worked-example -->")
            .map_or(src.len(), |j| head_end + j);
        let line = src[..start].matches('\n').count() + 1;
        out.push((number, line, src[head_end..body_end].trim().to_string()));
        rest = body_end.min(src.len());
        if rest == start {
            break;
        }
        rest = (rest + 1).min(src.len());
    }
    out
}

/// Replace every generated block of `src` with the current text (for `LADDER_BLESS_DOCS=1`).
pub fn bless(src: &str) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = src;
    while let Some(i) = rest.find("<!-- worked-example ") {
        let head_end = rest[i..].find("-->").ok_or("unclosed marker")? + i + 3;
        let number: u32 = rest[i + 20..head_end - 3]
            .trim()
            .parse()
            .map_err(|_| "bad marker")?;
        let end = rest[head_end..]
            .find("<!-- end worked-example -->")
            .ok_or("no end marker")?
            + head_end;
        out.push_str(&rest[..head_end]);
        out.push_str("\n\n");
        out.push_str(&worked_example(number)?);
        out.push('\n');
        rest = &rest[end..];
    }
    out.push_str(rest);
    Ok(out)
}
