//! The reliability campaign (issue 11, item 3): random scenes from the whole domain the README
//! promises (`sliding_ladder::report::campaign` says which), each run as `ladder simulate` runs
//! it (scene text → parse → plan → run → JSON and files, all in memory), counting panics,
//! NaN/inf outputs, runs over the time budget, failed runs (an error, or stopping short of the
//! end asked for: the command exits 1) and results outside their stated tolerance
//! (`sliding_ladder::report::campaign::judge`). Refusals (exit 2, a plan-time error naming the
//! field) are requests the tool says up front it cannot meet: counted apart, by field.
//! Each scene runs under a watchdog (`campaign::judge::Watchdog`): one still running after the
//! budget is counted over budget and named on stderr at once, and the campaign goes on (a hang
//! no step count sees used to stall a whole run: seed 1, scenes 800,000-899,999).
//!
//! Run: `cargo run --release --example campaign -- --scenes 10000 --seed 1` (exit 1 if any of
//! the five counts is nonzero). `--only I` runs scene I alone and prints it; `--out DIR` writes
//! every scene that is not fine to DIR/scene-I.toml, ready for `ladder simulate`;
//! `--work-cap W`, `--work-above W` (the scenes a cap of W leaves out) and `--contact MODEL`
//! narrow the run, counting what they leave out. CI runs
//! `--scenes 10000 --seed 1 --work-cap 1e5 --budget 30` (README says why; both contact models).

use clap::Parser;
use sliding_ladder::report::campaign::judge::{non_finite, out_of_tolerance, Problem, Watchdog};
use sliding_ladder::report::campaign::{busier_steps, draw, selected, work_share, WorkShare};
use sliding_ladder::report::outcome::{files, to_json};
use sliding_ladder::sim::fall;
use sliding_ladder::sim::outcome::unreached_end;
use sliding_ladder::sim::run::RunError;
use sliding_ladder::sim::scene;
use sliding_ladder::sim::scene::output::Output;
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

#[derive(Parser)]
struct Args {
    /// Number of scenes.
    #[arg(long, default_value_t = 10_000)]
    scenes: u64,
    /// Seed of the draw.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Time budget of one scene, seconds of wall time; the watchdog gives up on a scene still
    /// running after it (counted over budget, its index on stderr).
    #[arg(long, default_value_t = 10.0)]
    budget: f64,
    /// Worker threads (default: the machine's cores).
    #[arg(long)]
    jobs: Option<usize>,
    /// Run only scene I and print it with its verdict.
    #[arg(long)]
    only: Option<u64>,
    /// Write every scene that is not fine here, as DIR/scene-I.toml.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Index of the first scene (to run a campaign in chunks).
    #[arg(long, default_value_t = 0)]
    first: u64,
    /// Run only scenes whose phases need at most this many steps by the plan's estimate
    /// (`sim::scene::work::phase_steps`); the others are parsed and planned, and counted apart.
    /// A run past 100 times this in a phase stops and counts as over budget (the estimate
    /// was wrong). Default: every scene the tool accepts (its limit, 1e7 steps a phase).
    #[arg(long, default_value_t = fall::MAX_STEPS as f64)]
    work_cap: f64,
    /// Run only scenes whose busier phase needs more than this many steps by the plan's
    /// estimate: the scenes a run at `--work-cap W` leaves out (counted apart). Default: 0.
    #[arg(long, default_value_t = 0.0)]
    work_above: f64,
    /// Run only the scenes of this contact model (`rigid` or `penalty`); the others are drawn
    /// as usual (scene I stays scene I) and counted as excluded. Default: both.
    #[arg(long, value_parser = ["rigid", "penalty"])]
    contact: Option<String>,
}

/// What became of one scene (the details are printed through `Debug`).
#[allow(dead_code)]
#[derive(Clone, Debug)]
enum Verdict {
    Fine,
    Refused(String),
    Skipped,
    /// At most `--work-above` steps a phase: a capped campaign's share, not run here.
    Light,
    Excluded,
    Panic(String),
    NonFinite(String),
    OverBudget(f64),
    /// Still running when the watchdog gave up on it after the budget (seconds): a hang or a
    /// run far too slow; its thread is left to itself and the campaign goes on.
    Hung(f64),
    /// More than [`OVERRUN`] times the work cap in a phase: the plan's estimate was wrong.
    OverWork(u64),
    Failed(String),
    OutOfTolerance(String),
}

const COUNTS: [&str; 5] = [
    "panics",
    "NaN/inf outputs",
    "over budget",
    "failed runs",
    "out of tolerance",
];

impl Verdict {
    /// Index into [`COUNTS`] for the five that must be zero.
    fn count(&self) -> Option<usize> {
        match self {
            Verdict::Panic(_) => Some(0),
            Verdict::NonFinite(_) => Some(1),
            Verdict::OverBudget(_) | Verdict::Hung(_) | Verdict::OverWork(_) => Some(2),
            Verdict::Failed(_) => Some(3),
            Verdict::OutOfTolerance(_) => Some(4),
            _ => None,
        }
    }
}

/// How far past the work cap a run may go before it counts as over budget: the plan's
/// estimate is a bound up to a constant factor, not a prediction.
const OVERRUN: f64 = 100.0;

/// Scene `text` through the command's path, judged; not run when the plan estimates more
/// than `cap` steps in a phase or its contact model is not `only`.
fn run_scene(text: &str, (above, cap): (f64, f64), only: Option<&str>) -> Verdict {
    let scene = match scene::parse("campaign.toml", text) {
        Ok(s) => s,
        Err(e) => return Verdict::Refused(e.place()),
    };
    if !selected(&scene.contact, only) {
        return Verdict::Excluded;
    }
    let busier = busier_steps(&scene);
    match work_share(busier, cap, above) {
        WorkShare::OverCap => return Verdict::Skipped,
        WorkShare::Light => return Verdict::Light,
        WorkShare::Run => {}
    }
    // A run the plan estimated at most `cap` steps a phase may take OVERRUN times that; one
    // that goes on is over budget in steps, which unlike wall time does not vary with load.
    let limit = (OVERRUN * cap).min(fall::MAX_STEPS as f64) as u64;
    let o = match fall::run(&scene, limit) {
        Ok(o) => o,
        Err(RunError::TooManySteps { limit: l, .. }) if l < fall::MAX_STEPS => {
            return Verdict::OverWork(l)
        }
        Err(e) => return Verdict::Failed(e.to_string()),
    };
    if let Some(why) = unreached_end(&scene, &o) {
        return Verdict::Failed(why);
    }
    let json = serde_json::to_string(&to_json(&scene, &o)).unwrap_or_default();
    if json.is_empty() {
        return Verdict::Failed("the JSON could not be written".into());
    }
    if scene.outputs.contains(&Output::Trajectory) || scene.outputs.contains(&Output::Forces) {
        let _ = files(&scene, &o);
    }
    if let Some(p) = non_finite(&scene, &o).first() {
        return Verdict::NonFinite(format!("{p:?}"));
    }
    match out_of_tolerance(&scene, &o).first() {
        Some(Problem::OutOfTolerance { what, error, bound }) => {
            Verdict::OutOfTolerance(format!("{what}: error {error:e} > bound {bound:e}"))
        }
        Some(p) => Verdict::OutOfTolerance(format!("{p:?}")),
        None => Verdict::Fine,
    }
}

/// Run scene `text` with the panic caught and its wall time measured.
fn judged(text: &str, cap: (f64, f64), only: Option<&str>) -> (Verdict, f64) {
    let t = Instant::now();
    let v = catch_unwind(AssertUnwindSafe(|| run_scene(text, cap, only))).unwrap_or_else(|e| {
        let msg = e
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| e.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Verdict::Panic(msg)
    });
    (v, t.elapsed().as_secs_f64())
}

/// A worker's watchdog (`campaign::judge::Watchdog`): scenes run on a thread of their own.
fn watchdog(a: &Args) -> Watchdog<String, (Verdict, f64)> {
    let (cap, only) = ((a.work_above, a.work_cap), a.contact.clone());
    Watchdog::new(move |text: String| judged(&text, cap, only.as_deref()))
}

/// Scene `i` (`text`) judged under the watchdog: a scene still running after the budget is
/// over budget at once (named on stderr as it happens) and the campaign goes on without it.
fn judge(
    dog: &mut Watchdog<String, (Verdict, f64)>,
    i: u64,
    text: &str,
    a: &Args,
) -> (Verdict, f64) {
    match dog.run(text.to_string(), Duration::from_secs_f64(a.budget)) {
        Some((Verdict::Fine, secs)) if secs > a.budget => (Verdict::OverBudget(secs), secs),
        Some(v) => v,
        None => {
            eprintln!(
                "campaign: scene {i} of seed {} still running after {} s: counted over budget, left on its thread (reproduce: --only {i})",
                a.seed, a.budget
            );
            (Verdict::Hung(a.budget), a.budget)
        }
    }
}

#[derive(Default)]
struct Tally {
    fine: u64,
    skipped: u64,
    light: u64,
    excluded: u64,
    refused: BTreeMap<String, u64>,
    counts: [u64; 5],
    examples: Vec<(u64, Verdict)>,
    slowest: (f64, u64),
    seconds: f64,
    /// Wall seconds and scenes by contact and method.
    by_method: BTreeMap<String, (f64, u64)>,
}

/// `penalty dopri5`, `rigid exact`, … of a scene's text.
fn class(text: &str) -> String {
    let field = |key: &str| {
        text.lines()
            .find_map(|l| l.strip_prefix(key))
            .unwrap_or("?")
            .trim_matches(|c| c == '"' || c == ' ' || c == '=')
            .to_string()
    };
    format!("{} {}", field("model"), field("method"))
}

fn main() -> ExitCode {
    let a = Args::parse();
    std::panic::set_hook(Box::new(|_| {}));
    if let Some(i) = a.only {
        let text = draw(a.seed, i);
        let (v, secs) = judge(&mut watchdog(&a), i, &text, &a);
        println!(
            "{text}\n# scene {i} of seed {}: {v:?} ({secs:.3} s)",
            a.seed
        );
        return ExitCode::from(u8::from(v.count().is_some()));
    }
    let jobs = a
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let next = AtomicU64::new(0);
    let total = Mutex::new(Tally::default());
    let start = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| {
                let mut t = Tally::default();
                let mut dog = watchdog(&a);
                loop {
                    let i = a.first + next.fetch_add(1, Ordering::Relaxed);
                    if i >= a.first + a.scenes {
                        break;
                    }
                    let text = draw(a.seed, i);
                    let (v, secs) = judge(&mut dog, i, &text, &a);
                    t.seconds += secs;
                    let c = t.by_method.entry(class(&text)).or_default();
                    (c.0, c.1) = (c.0 + secs, c.1 + 1);
                    if secs > t.slowest.0 {
                        t.slowest = (secs, i);
                    }
                    match &v {
                        Verdict::Fine => t.fine += 1,
                        Verdict::Skipped => t.skipped += 1,
                        Verdict::Light => t.light += 1,
                        Verdict::Excluded => t.excluded += 1,
                        Verdict::Refused(field) => {
                            *t.refused.entry(field.clone()).or_default() += 1
                        }
                        other => {
                            t.counts[other.count().unwrap_or(3)] += 1;
                            if let Some(dir) = &a.out {
                                let _ = std::fs::create_dir_all(dir);
                                let _ = std::fs::write(dir.join(format!("scene-{i}.toml")), &text);
                            }
                            t.examples.push((i, v));
                        }
                    }
                }
                let mut all = total.lock().unwrap_or_else(|e| e.into_inner());
                all.fine += t.fine;
                all.skipped += t.skipped;
                all.light += t.light;
                all.excluded += t.excluded;
                for (k, n) in t.refused {
                    *all.refused.entry(k).or_default() += n;
                }
                for (x, y) in all.counts.iter_mut().zip(t.counts) {
                    *x += y;
                }
                all.examples.extend(t.examples);
                all.seconds += t.seconds;
                for (k, (secs, n)) in t.by_method {
                    let c = all.by_method.entry(k).or_default();
                    (c.0, c.1) = (c.0 + secs, c.1 + n);
                }
                if t.slowest.0 > all.slowest.0 {
                    all.slowest = t.slowest;
                }
            });
        }
    });
    let wall = start.elapsed().as_secs_f64();
    let t = total.into_inner().unwrap_or_else(|e| e.into_inner());
    let refused: u64 = t.refused.values().sum();
    println!(
        "campaign: {} scenes from {}, seed {}, budget {} s of wall time per scene, {jobs} jobs: {wall:.1} s ({:.0} scenes/s; slowest scene {} took {:.3} s)",
        a.scenes,
        a.first,
        a.seed,
        a.budget,
        a.scenes as f64 / wall,
        t.slowest.1,
        t.slowest.0
    );
    println!("| outcome | scenes |\n|---|---:|");
    println!("| completed within tolerance | {} |", t.fine);
    println!(
        "| not run: more than {:e} steps in a phase by the plan's estimate | {} |",
        a.work_cap, t.skipped
    );
    if a.work_above > 0.0 {
        println!(
            "| not run: at most {:e} steps in every phase (`--work-above`) | {} |",
            a.work_above, t.light
        );
    }
    if let Some(model) = &a.contact {
        println!(
            "| not run: not {model} contact (`--contact {model}`) | {} |",
            t.excluded
        );
    }
    println!("| refused up front (exit 2) | {refused} |");
    for (field, n) in &t.refused {
        println!("| · refused at {field} | {n} |");
    }
    for (name, n) in COUNTS.iter().zip(t.counts) {
        println!("| {name} | {n} |");
    }
    let by: Vec<String> = t
        .by_method
        .iter()
        .map(|(k, (secs, n))| format!("{k} {n} in {secs:.1} s"))
        .collect();
    println!(
        "scenes and seconds by contact and method: {}",
        by.join(", ")
    );
    let mut examples = t.examples;
    examples.sort_by_key(|(i, _)| *i);
    for (i, v) in examples.iter().take(20) {
        println!("scene {i}: {v:?}");
    }
    if !examples.is_empty() {
        println!(
            "reproduce one: cargo run --release --example campaign -- --seed {} --only I",
            a.seed
        );
    }
    // Every scene is in exactly one row: a scene the table does not show is a campaign bug.
    let shown = t.fine + t.skipped + t.light + t.excluded + refused + t.counts.iter().sum::<u64>();
    if shown != a.scenes {
        println!(
            "campaign: the table accounts for {shown} of {} scenes",
            a.scenes
        );
        return ExitCode::from(1);
    }
    ExitCode::from(u8::from(t.counts.iter().any(|&n| n > 0)))
}
