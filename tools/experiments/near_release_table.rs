//! The near-critical push's table (issue 38, item 1): every method's separation angle and
//! time errors, relative to the travel θ_s − θ0 and to t_s, on the pushes of
//! tests/sim/near_release/pushes.rs (mpmath references), through the path `ladder simulate` takes.
//! Only the public scene API is used, so the same file measures any version of the crate.
//!
//! Run: `cargo run --release --example near_release_table` (a lab tool, hence tools/experiments/).
#[path = "../../tests/sim/near_release/pushes.rs"]
mod refs;
use sliding_ladder::sim::{fall, scene};

fn run(p: &[f64; 10], method: &str, control: &str) -> Result<(f64, f64), String> {
    let [g, l, theta0, phi0, rate0, ..] = *p;
    let angle = match phi0 {
        0.0 => format!("angle = {theta0:e}"),
        _ => format!("angle_from_floor = {phi0:e}"),
    };
    let text = format!(
        "[ladder]\nmass = 1.0\nhalf_length = {l:e}\ngravity = {g:e}\n[start]\n{angle}\nangular_velocity = {rate0:e}\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\n{control}\n[end]\nat = \"separation\"\n[outputs]\nwant = [\"separation_angle\", \"separation_time\"]\n"
    );
    let sc = scene::parse("near-release.toml", &text).map_err(|e| e.to_string())?;
    let o = fall::run(&sc, fall::MAX_STEPS).map_err(|e| e.to_string())?;
    let s = o.separation.ok_or("no separation")?;
    let [_, _, _, phi0, _, _, angle_ref, travel, t_ref, _] = *p;
    let theta_ref = match phi0 {
        0.0 => angle_ref,
        _ => std::f64::consts::FRAC_PI_2 - angle_ref,
    };
    // The angle less one ulp of θ_s (the output's own rounding), over the travel.
    let ulp = f64::EPSILON * theta_ref;
    let ea = ((s.angle - theta_ref).abs() - ulp).max(0.0) / travel;
    Ok((ea, (s.time - t_ref).abs() / t_ref))
}

fn main() {
    println!("| push | method | control | angle | time |\n|---|---|---|---:|---:|");
    for (name, p) in refs::PUSHES.iter() {
        let unit = (p[1] / p[0]).sqrt();
        let mut runs: Vec<(&str, String)> = Vec::new();
        for m in ["taylor", "dop853", "dopri5", "radau5"] {
            for tol in [1e-8, 1e-13] {
                runs.push((m, format!("tolerance = {tol:e}")));
            }
        }
        for m in ["rk4", "verlet", "symplectic-euler", "euler"] {
            for h in [1e-3, 1e-4] {
                runs.push((m, format!("step = {:e}", h * unit)));
            }
        }
        for (m, c) in runs {
            match run(p, m, &c) {
                Ok((a, t)) => println!("| {name} | {m} | {c} | {a:.2e} | {t:.2e} |"),
                Err(e) => println!("| {name} | {m} | {c} | {e} | |"),
            }
        }
    }
}
