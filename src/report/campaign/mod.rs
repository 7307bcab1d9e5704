//! The reliability campaign (issue 11, item 3): scenes drawn at random from the whole domain
//! the README promises, each run through the path `ladder simulate` takes (scene text → parse →
//! plan → run → outputs) and judged by [`super::campaign::judge`]; `tools/experiments/campaign.rs` is
//! the command.
//!
//! **The domain drawn** (each scene from its own ChaCha8 stream, `seed` and the scene's index,
//! so any one scene can be drawn again alone):
//! * m, l, g each 10^U(−30, 30);
//! * the contact: rigid (3 in 4) or penalty with κ = k l/(m g) = 10^U(0, 12) and a damping
//!   γ = c √(l/g)/m of 0 (half) or 10^U(−3, 1) √κ;
//! * every method (`euler` … `taylor`, and `exact` for rigid scenes), a tolerance
//!   10^U(−16, −1) or a step 10^U(−6, 0) √(l/g), given in seconds or in units of √(l/g)
//!   (Taylor's `order` is not drawn yet: at orders 2-3 and tight tolerances a run takes more
//!   than the 1e7-step limit that the plan does not foresee, e.g. seed 1 scenes 1269, 5128);
//! * every end (`separation`, `flat`, `time` with 10^U(−3, 4) √(l/g), in either unit) and a
//!   random non-empty set of the outputs that end can produce (`Output::producible`);
//! * θ0: 0, subnormal (10^U(−323.3, −308)), tiny (10^U(−300, −2)), anywhere in (0, π/2), near
//!   π/2 (π/2 − 10^U(−15.5, −1)) or the last float below π/2; for a tenth of the rigid scenes,
//!   given from the floor instead (`angle_from_floor` φ0 = 10^U(−300, −1));
//! * θ̇0: 0 (half), a fraction U(0, 1) of the fastest start the wall can hold
//!   (Ω √(cos θ0), Ω² = 3g/4l), or 10^U(−20, 3) √(g/l): past the first a rigid scene
//!   leaves the wall at once, and is refused when it needs the floor phase past √(g/(l cos θ0))
//!   (the foot would fly); a penalty scene is refused past the first.
//!
//! Penalty scenes keep to what that model does (an integrator, the end `separation`, the
//! separation outputs); rigid scenes with `exact` to the separation. Everything else the scene
//! format allows is drawn, so refusals (exit 2) are part of the campaign: they are counted by
//! the field they name.

pub mod judge;
pub mod watchdog;

use crate::sim::integrators::{any_model_names, is_adaptive, names};
use crate::sim::scene::output::Output;
use crate::sim::scene::work::phase_steps;
use crate::sim::scene::{ContactModel, End, Scene};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::FRAC_PI_2;
use std::fmt::Write;

/// Every method a scene may name: the integrators and, for rigid scenes, the closed form.
pub fn methods(penalty: bool) -> Vec<&'static str> {
    match penalty {
        true => any_model_names().collect(),
        false => names().chain(["exact"]).collect(),
    }
}

/// The methods of the table when the campaign's seeds were first run and published (the lab
/// notebook cites scenes by seed and index): a rigid scene drew one of these nine, a penalty
/// scene one of the first seven, uniformly from its own stream. That draw is kept, so those
/// scenes stay as they were.
pub const FIRST_METHODS: [&str; 9] = [
    "euler",
    "symplectic-euler",
    "verlet",
    "rk4",
    "dopri5",
    "dop853",
    "radau5",
    "taylor",
    "exact",
];

/// The method of a seeded scene: `first[pick]` (the draw of the methods first published), unless
/// a method of `current` added since wins it. Weighted rendezvous hashing decides: the first
/// methods together score with weight `first.len()`, each newcomer with weight 1, each score
/// w / −ln u with u from [`unit`]`(seed, index, name)`. A newcomer so takes about its share of
/// the scenes, and adding one moves to it only the scenes it wins: every other scene keeps its
/// method and, since the draw consumes nothing more from the scene's stream, all of its draw.
pub fn pick_method(
    seed: u64,
    index: u64,
    first: &[&'static str],
    pick: usize,
    current: &[&'static str],
) -> &'static str {
    let weighed = |name: &str, w: f64| w / -unit(seed, index, name).ln();
    let mut best = (first[pick], weighed("", first.len() as f64));
    for m in current.iter().copied().filter(|m| !first.contains(m)) {
        let s = weighed(m, 1.0);
        if s > best.1 {
            best = (m, s);
        }
    }
    best.0
}

/// A number in (0, 1) hashed from (seed, index, name): FNV-1a of the name, then SplitMix64's
/// finaliser over the three (well mixed and dependency-free; any fixed hash would do).
fn unit(seed: u64, index: u64, name: &str) -> f64 {
    let fnv = name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    let mut z = seed
        .wrapping_mul(0x9e37_79b9_7f4a_7c15)
        .wrapping_add(index)
        .rotate_left(17)
        ^ fnv;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    // 53 random bits, offset by half a step so that neither 0 nor 1 occurs.
    ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// Every output a scene may ask for.
const OUTPUTS: [&str; 13] = [
    "separation_angle",
    "separation_time",
    "separation_rate",
    "flat_time",
    "flat_state",
    "floor_force_min",
    "top_clearance_min",
    "momentum_error",
    "energy_error",
    "final_state",
    "rhs_evals",
    "trajectory",
    "forces",
];

/// The outputs of the penalty model.
const PENALTY_OUTPUTS: [&str; 5] = [
    "separation_angle",
    "separation_time",
    "separation_rate",
    "final_state",
    "rhs_evals",
];

fn exp10(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    10f64.powf(rng.gen_range(lo..hi))
}

/// A float as TOML reads it back exactly (Rust's shortest round-trip form).
fn num(x: f64) -> String {
    format!("{x:e}")
}

/// The name a scene gives `contact` (`model = "rigid"` or `"penalty"`).
pub fn model_name(contact: &ContactModel) -> &'static str {
    match contact {
        ContactModel::Rigid => "rigid",
        ContactModel::Penalty { .. } => "penalty",
    }
}

/// Whether the campaign runs a scene with `contact` when asked for the model `only` (`None`:
/// every scene); the others are drawn all the same, so that scene I stays scene I.
pub fn selected(contact: &ContactModel, only: Option<&str>) -> bool {
    only.is_none_or(|m| m == model_name(contact))
}

/// Which share of a campaign a scene falls in by the plan's estimate of its busier phase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WorkShare {
    /// Run it.
    Run,
    /// Over `--work-cap`: not run.
    OverCap,
    /// At most `--work-above` (when given, > 0): a capped campaign's share, not run.
    Light,
}

/// The plan's estimate of the steps of `scene`'s busier phase (`sim::scene::work::phase_steps`);
/// 0 for a scene without a control, the closed form (`method = "exact"`), which takes no steps.
/// (Until 2026-11-25 the campaign skipped the estimate for such a scene, so it ran in both
/// shares: about 6,900 closed forms a chunk were counted as heavy.)
pub fn busier_steps(scene: &Scene) -> f64 {
    scene.control.map_or(0.0, |c| {
        let steps = phase_steps(
            &scene.ladder,
            (scene.theta0, scene.rate0),
            &scene.method,
            c,
            scene.end,
            scene.contact,
        );
        steps[0].max(steps[1])
    })
}

/// The share of a scene whose busier phase needs `busier` steps (0 for an adaptive method whose
/// steps follow its tolerance alone), for `--work-cap cap` and `--work-above above`. With
/// `above` = 0 (the default) nothing is light: a plain `busier <= above` once skipped every
/// adaptive rigid scene (commit 5e0da1b, fixed in 8ed692f).
pub fn work_share(busier: f64, cap: f64, above: f64) -> WorkShare {
    if busier > cap {
        WorkShare::OverCap
    } else if above > 0.0 && busier <= above {
        WorkShare::Light
    } else {
        WorkShare::Run
    }
}

/// The start: θ0 as `angle`, or (next to the floor) φ0 = π/2 − θ0 as `angle_from_floor`.
#[derive(Clone, Copy)]
enum Start {
    Angle(f64),
    FromFloor(f64),
}

impl Start {
    /// cos θ0 (= sin φ0 for a start given from the floor).
    fn cos(self) -> f64 {
        match self {
            Start::Angle(theta) => theta.cos(),
            Start::FromFloor(phi) => phi.sin(),
        }
    }
    /// The scene's line.
    fn line(self) -> String {
        match self {
            Start::Angle(theta) => format!("angle = {}", num(theta)),
            Start::FromFloor(phi) => format!("angle_from_floor = {}", num(phi)),
        }
    }
}

/// The start angle θ0.
fn start_angle(rng: &mut ChaCha8Rng) -> f64 {
    match rng.gen_range(0..20) {
        0..=1 => 0.0,
        2..=3 => exp10(rng, -323.3, -308.0),
        4..=7 => exp10(rng, -300.0, -2.0),
        8..=15 => rng.gen_range(0.0..FRAC_PI_2),
        16..=18 => FRAC_PI_2 - exp10(rng, -15.5, -1.0),
        _ => f64::from_bits(FRAC_PI_2.to_bits() - 1),
    }
}

/// Scene `index` of the campaign with `seed`, as TOML text, among today's methods.
pub fn draw(seed: u64, index: u64) -> String {
    draw_among(seed, index, true)
}

/// Scene `index` as it was first drawn and published, among [`FIRST_METHODS`] only: the scene
/// the lab notebook and the regression tests cite by index, whatever methods have been added
/// to the table since (which may win that index in [`draw`]).
pub fn draw_first(seed: u64, index: u64) -> String {
    draw_among(seed, index, false)
}

/// [`draw`], or [`draw_first`] when `newcomers` is false.
fn draw_among(seed: u64, index: u64, newcomers: bool) -> String {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    let rng = &mut rng;
    let (m, l, g) = (
        exp10(rng, -30.0, 30.0),
        exp10(rng, -30.0, 30.0),
        exp10(rng, -30.0, 30.0),
    );
    let unit = (l / g).sqrt();
    // Choices added after the first campaigns (starts given from the floor) come from a stream
    // of their own, so that every other choice of a scene stays as it was
    // (campaign-findings cites scenes by index).
    let mut more = ChaCha8Rng::seed_from_u64(seed);
    more.set_stream(index ^ (1 << 63));
    let theta0 = start_angle(rng);
    let big_omega = (0.75f64).sqrt();
    let push = rng.gen_range(0..4);
    let push_size = match push {
        0 | 1 => 0.0,
        2 => rng.gen_range(0.0..1.0),
        _ => exp10(rng, -20.0, 3.0),
    };
    let penalty = rng.gen_range(0..4) == 0;
    // A rigid start a tenth of the time as φ0 = π/2 − θ0, as close to the floor as f64 goes.
    let start = match !penalty && more.gen_range(0..10) == 0 {
        true => Start::FromFloor(exp10(&mut more, -300.0, -1.0)),
        false => Start::Angle(theta0),
    };
    let rate_scaled = match push {
        2 => push_size * big_omega * start.cos().sqrt(),
        _ => push_size,
    };
    let rate0 = rate_scaled / unit;
    let mut text = String::new();
    let _ = write!(
        text,
        "[ladder]\nmass = {}\nhalf_length = {}\ngravity = {}\n[start]\n{}\nangular_velocity = {}\n[contact]\n",
        num(m),
        num(l),
        num(g),
        start.line(),
        num(rate0)
    );
    let first = &FIRST_METHODS[..if penalty { 7 } else { 9 }];
    let pick = rng.gen_range(0..first.len());
    let current = if newcomers {
        methods(penalty)
    } else {
        first.to_vec()
    };
    let method = pick_method(seed, index, first, pick, &current);
    contact_lines(&mut text, rng, penalty, (m, l, g));
    let _ = write!(text, "[integrator]\nmethod = \"{method}\"\n");
    control_line(&mut text, rng, method, unit);
    let end = end_lines(&mut text, rng, penalty || method == "exact", unit);
    outputs_line(&mut text, rng, penalty, method, end);
    text
}

/// The `[contact]` model of a drawn scene: rigid, or penalty springs with κ = k l/(m g) drawn
/// over 1..1e12 and, half the time, a damping γ √κ with γ drawn over 1e-3..10.
fn contact_lines(
    text: &mut String,
    rng: &mut ChaCha8Rng,
    penalty: bool,
    (m, l, g): (f64, f64, f64),
) {
    let unit = (l / g).sqrt();
    if penalty {
        let kappa = exp10(rng, 0.0, 12.0);
        let gamma = match rng.gen_bool(0.5) {
            true => 0.0,
            false => exp10(rng, -3.0, 1.0) * kappa.sqrt(),
        };
        let _ = write!(
            *text,
            "model = \"penalty\"\nstiffness = {}\ndamping = {}\n",
            num(kappa * (m * (g / l))),
            num(gamma * m / unit)
        );
    } else {
        *text += "model = \"rigid\"\n";
    }
}

/// The integrator's control: none for "exact", a tolerance over 1e-16..0.1 for an adaptive
/// method, else a step over 1e-6..1 √(l/g), given in s or scaled half the time.
fn control_line(text: &mut String, rng: &mut ChaCha8Rng, method: &str, unit: f64) {
    match method {
        "exact" => {}
        _ if is_adaptive(method) => {
            let _ = writeln!(*text, "tolerance = {}", num(exp10(rng, -16.0, -1.0)));
        }
        _ => {
            let h = exp10(rng, -6.0, 0.0);
            let _ = match rng.gen_bool(0.5) {
                true => writeln!(*text, "scaled_step = {}", num(h)),
                false => writeln!(*text, "step = {}", num(h * unit)),
            };
        }
    }
}

/// The `[end]` of a drawn scene: the separation when `separation_only`, else the separation,
/// flat or a time over 1e-3..1e4 √(l/g) (in s or scaled half the time).
fn end_lines(text: &mut String, rng: &mut ChaCha8Rng, separation_only: bool, unit: f64) -> End {
    let end = if separation_only {
        End::Separation
    } else {
        match rng.gen_range(0..3) {
            0 => End::Separation,
            1 => End::Flat,
            _ => End::Time(exp10(rng, -3.0, 4.0)),
        }
    };
    *text += "[end]\n";
    match end {
        End::Separation => *text += "at = \"separation\"\n",
        End::Flat => *text += "at = \"flat\"\n",
        End::Time(t) => {
            let _ = match rng.gen_bool(0.5) {
                true => write!(*text, "at = \"time\"\nscaled_time = {}\n", num(t)),
                false => write!(*text, "at = \"time\"\ntime = {}\n", num(t * unit)),
            };
        }
    }
    end
}

/// The `[outputs]` of a drawn scene: each output the run can produce with probability 0.3,
/// at least one.
fn outputs_line(text: &mut String, rng: &mut ChaCha8Rng, penalty: bool, method: &str, end: End) {
    let candidates: Vec<&str> = OUTPUTS
        .iter()
        .copied()
        .filter(|o| !penalty || PENALTY_OUTPUTS.contains(o))
        .filter(|o| Output::from_name(o).is_some_and(|x| x.producible(method, end).is_ok()))
        .collect();
    let mut want: Vec<&str> = candidates
        .iter()
        .copied()
        .filter(|_| rng.gen_bool(0.3))
        .collect();
    if want.is_empty() {
        want.push(candidates[rng.gen_range(0..candidates.len())]);
    }
    let list: Vec<String> = want.iter().map(|w| format!("\"{w}\"")).collect();
    let _ = writeln!(*text, "[outputs]\nwant = [{}]", list.join(", "));
}
