//! The opening of the index, a student's way in: the problem in words and the figure
//! (`docs/book/problem.md`), then the answer — where the ladder leaves the wall and how it
//! lands — with every number from the simulator's run of `scenes/full-fall.toml` made when the
//! book is built, beside the closed form of footnote 4 (`sim::rigid::separation_cosine`).

use super::pages::esc;
use crate::sim::impact;
use crate::sim::outcome::Outcome;
use crate::sim::rigid::separation_cosine;
use crate::sim::scene::Scene;

/// The answer to the problem, as one run of the simulator found it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Answer {
    /// θ0, rad (the scene's start, from rest).
    pub theta0: f64,
    /// θ_s, rad, where the simulator found F_w = 0.
    pub theta_s: f64,
    /// (2/3) cos θ0, footnote 4's closed form of cos θ_s.
    pub cos_s_closed: f64,
    /// t_s, s.
    pub t_s: f64,
    /// θ̇ at separation, 1/s.
    pub rate_s: f64,
    /// When the ladder lies flat, s.
    pub t_flat: f64,
    /// θ̇ as it lands flat, 1/s.
    pub rate_flat: f64,
    /// (Ẋ, ẏ) of the centre as it lands, m/s.
    pub centre_velocity: (f64, f64),
    /// The kinetic energy the inelastic landing takes, over m g l.
    pub energy_lost: f64,
    /// θ_s from rest upright (θ0 → 0), rad, from the same closed form.
    pub theta_s_upright: f64,
}

/// The answer from a run that reached flat; None when the run stopped short.
pub fn answer(scene: &Scene, o: &Outcome) -> Option<Answer> {
    let (sep, flat) = (o.separation?, o.flat?);
    let w2 = scene.ladder.big_omega2();
    Some(Answer {
        theta0: scene.theta0,
        theta_s: sep.angle,
        cos_s_closed: separation_cosine(w2, scene.theta0, scene.rate0),
        t_s: sep.time,
        rate_s: sep.rate,
        t_flat: flat.time,
        rate_flat: flat.rate,
        centre_velocity: (flat.centre_velocity_x, flat.centre_velocity_y),
        energy_lost: impact::slide(&scene.ladder, &flat, flat.time).energy_lost,
        theta_s_upright: separation_cosine(w2, 0.0, 0.0).acos(),
    })
}

/// The answer as HTML: the separation in words and numbers, then the landing.
pub fn answer_html(a: &Answer, scene: &Scene) -> String {
    let deg = |r: f64| r.to_degrees();
    let l = &scene.ladder;
    format!(
        "<h2 id=\"answer\">The answer</h2>\n\
<p><strong>Where the ladder leaves the wall.</strong> The wall can only push. While the ladder \
is steep the centre of mass speeds up away from the wall and the wall supplies that push; as the \
ladder tilts, the centre would have to slow its outward motion, which needs a pull. So the wall \
force F<sub>w</sub> falls to zero at an angle θ<sub>s</sub> and the top leaves the wall there. \
Energy (10) and F<sub>w</sub> = m a<sub>x</sub> (6) give it in closed form (footnote 4): \
<strong>cos θ<sub>s</sub> = (2/3) cos θ<sub>0</sub></strong> for a start from rest at θ<sub>0</sub>. \
Nudged from upright, cos θ<sub>s</sub> = 2/3: θ<sub>s</sub> = {up:.2}°, whatever m, l or g.</p>\n\
<p>The simulator ({method}, scene <code>{file}</code>: m = {m} kg, l = {hl} m, g = {g} m/s², \
released from rest at θ<sub>0</sub> = {t0:.3} rad = {t0d:.2}°) finds the wall force reach zero at \
t<sub>s</sub> = {ts:.4} s, θ<sub>s</sub> = {ths:.4}° (cos θ<sub>s</sub> = {cs:.12}; the closed form \
(2/3) cos θ<sub>0</sub> = {cc:.12}), turning at θ̇ = {rs:.4} rad/s.</p>\n\
<p><strong>How it lands.</strong> After separation the wall no longer acts and no horizontal \
force is left (P2), so the centre keeps the horizontal speed it had and the foot slides on while \
the ladder falls (the <a href=\"phase2.html\">floor phase</a>, beyond the note). It lies flat at \
t = {tf:.4} s, turning at θ̇ = {rf:.4} rad/s, its centre moving at Ẋ = {vx:.4} m/s along the \
floor and {vy:.4} m/s downwards. The top strikes the floor; without bounce the landing takes \
{el:.4} m g l of kinetic energy, and the ladder slides on, flat, at Ẋ.</p>\n",
        up = deg(a.theta_s_upright),
        method = esc(&scene.method),
        file = esc(&shown_path(&scene.file)),
        m = l.m,
        hl = l.l,
        g = l.g,
        t0 = a.theta0,
        t0d = deg(a.theta0),
        ts = a.t_s,
        ths = deg(a.theta_s),
        cs = a.theta_s.cos(),
        cc = a.cos_s_closed,
        rs = a.rate_s,
        tf = a.t_flat,
        rf = a.rate_flat,
        vx = a.centre_velocity.0,
        vy = -a.centre_velocity.1,
        el = a.energy_lost,
    )
}

/// A scene's path as the reader knows it, from the crate root (`scenes/full-fall.toml`), not
/// the machine's absolute path.
fn shown_path(file: &str) -> String {
    match file.rfind("scenes/") {
        Some(i) => file[i..].to_string(),
        None => file.to_string(),
    }
}

/// Where a reader goes next: the pages for a student and for a teacher.
pub const NEXT: &str = "<h2 id=\"start\">Where to go next</h2>\n<ul>\n\
<li><a href=\"derivations.html\">The six derivations side by side</a>: Lagrange and the torque \
about A, B, C, D, E — what each point needs, where the law of motion enters, what it costs.</li>\n\
<li><a href=\"01-lagrange.html\">The note, display by display</a>, from Lagrange's method (sec. 2.1) \
to Milne (Appendix B); each display with its checks folded below it.</li>\n\
<li><a href=\"problems.html\">Eight problems with checked answers</a>, worked solutions folded.</li>\n\
<li><a href=\"animation.html\">The fall, animated</a>, the contact forces to scale.</li>\n\
<li><a href=\"errata.html\">The note's misprints</a>, in physical terms.</li>\n\
<li><a href=\"glossary.html\">The glossary</a> of the words of the checks, and \
<a href=\"references.html\">the note's references</a>.</li>\n</ul>\n";
