//! The `long` group of `ladder stability`: 1e7 steps of a scene that asks only for its final
//! state, against the exact reference, with the process's peak memory flat.

use crate::ladder::Ladder;
use crate::report::stability::case::{blank, built_in_scene as scene, Case, Verdict, U};
use crate::sim::exact::PhaseOne;
use crate::sim::fall;
use crate::sim::integrators::Control;
use crate::sim::scene::output::Output;
use crate::sim::scene::{End, Scene};
use std::time::Instant;

/// Peak resident memory of this process (Linux `VmHWM`), kB; None elsewhere.
pub fn peak_rss_kb() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// The scalar-only scene of the memory runs: rk4 at 1e-6 s on a 20 km ladder (its wall phase
/// lasts ~70 s), to `seconds`, asking only for the final state: `seconds`·1e6 steps.
pub fn memory_scene(seconds: f64) -> Scene {
    let mut sc = scene(
        Ladder {
            m: 1.0,
            l: 1e4,
            g: 9.81,
        },
        0.3,
        0.0,
        End::Time(seconds),
        vec![Output::FinalState],
    );
    sc.method = "rk4".into();
    sc.control = Some(Control::Fixed(1e-6));
    sc
}

/// 1e7 steps with nothing stored: the angle against the exact reference, the memory flat.
pub fn long_cases(tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    tick("long run 1e7 steps", 2);
    let mut c = blank(
        "long",
        "scalar-only scene, 1e7 steps".into(),
        "rk4 h 1e-6 s".into(),
        "θ(10 s) of the exact reference; peak memory flat".into(),
    );
    let before = peak_rss_kb();
    let t = Instant::now();
    let run = fall::run(&memory_scene(10.0), 20_000_000);
    c.seconds = t.elapsed().as_secs_f64();
    let after = peak_rss_kb();
    match run {
        Err(e) => c.reason = e.to_string(),
        Ok(o) => {
            let sc = memory_scene(10.0);
            c.steps = o.work.wall.steps;
            c.rhs_evals = o.work.wall.rhs_evals;
            let reference = PhaseOne::new(0.3, 0.0, sc.ladder.big_omega2()).map(|p| p.theta(10.0));
            let growth = before.zip(after).map(|(b, a)| a.saturating_sub(b));
            c.value = format!(
                "θ = {:.15}, samples kept {}, peak RSS growth {} kB (from {} kB)",
                o.last.1,
                o.work.stored_samples,
                growth.map_or("n/a".into(), |g| g.to_string()),
                before.map_or("n/a".into(), |b| b.to_string())
            );
            match reference {
                // Rounding: N steps each adding ~u θ, worst case without cancellation; the
                // truncation error h⁵ per step is far below it.
                Ok(r) => c.judge((o.last.1 - r).abs(), 10.0 * c.steps as f64 * U * r),
                Err(e) => c.reason = e,
            }
            // Storing the 1e7 states would take ≥ 80 MB; 1 MB of growth is the budget.
            if growth.is_some_and(|g| g > 1024) || o.work.stored_samples > 0 {
                c.verdict = Verdict::Fail;
                c.reason = "memory grew with the number of steps".into();
            }
        }
    }
    vec![c]
}
