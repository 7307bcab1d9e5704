//! The fall animated: an SVG with SMIL animation (no script) of the ladder from release to
//! flat, its wall and floor forces drawn to one scale, the separation marked (issue 39).
//!
//! Every frame is a sample of the simulator's trace (`sim::outcome::Sample`): θ and the centre's
//! abscissa X as integrated (X = l sin θ on the wall, (7)), and the contact forces the run
//! evaluated. The ends follow from the rod's geometry: C = (X − l sin θ, 2l cos θ) and
//! D = (X + l sin θ, 0), the centre B = (X, l cos θ). The forces are arrows at C (F_w, along +x)
//! and D (F_f, along +y), and the weight m g at B, all at [`Animation::metres_per_newton`].
//!
//! The drawing carries its own key for readers and tests: `data-metres-per-newton`,
//! `data-px-per-metre` and the origin of the lab (`data-origin`) on the root element.

use crate::sim::outcome::{Outcome, Sample};
use crate::sim::scene::Scene;
use std::fmt::Write;

/// Width and height of the drawing, px.
const SIZE: (f64, f64) = (760.0, 460.0);
/// The animation runs this many times slower than the fall.
pub const SLOW: f64 = 4.0;
/// Seconds the last frame is held before the animation starts again.
pub const HOLD: f64 = 1.5;
/// Most frames kept (the trace is thinned evenly, keeping the separation and the last sample).
pub const MAX_FRAMES: usize = 240;

/// The frames and scales of an animation.
#[derive(Clone, Debug, PartialEq)]
pub struct Animation {
    /// The samples drawn, from release to flat.
    pub frames: Vec<Sample>,
    /// Index of the first frame after the top left the wall (None: it never did).
    pub separation: Option<usize>,
    /// The simulator's separation event (t_s, θ_s), drawn as the ladder's pose there.
    pub separation_event: Option<(f64, f64)>,
    /// Metres of arrow per newton.
    pub metres_per_newton: f64,
    /// Pixels per metre.
    pub px_per_metre: f64,
    /// Where the corner A (the lab's origin) is drawn, px.
    pub origin: (f64, f64),
}

/// Why there is nothing to animate.
fn refuse(scene: &Scene, why: &str) -> String {
    format!("{}: {why}", scene.file)
}

/// The frames of `o` (a run of `scene` with its trace and forces), thinned to at most
/// [`MAX_FRAMES`], with the scales that fit the whole fall in the drawing.
pub fn frames(scene: &Scene, o: &Outcome) -> Result<Animation, String> {
    let trace = o
        .trace
        .as_ref()
        .ok_or_else(|| refuse(scene, "the run kept no trace"))?;
    let all: Vec<Sample> = trace
        .iter()
        .copied()
        .filter(|s| s.forces.is_some())
        .collect();
    if all.len() < 2 {
        return Err(refuse(
            scene,
            "the run kept fewer than two samples with forces",
        ));
    }
    let first_floor = all.iter().position(|s| s.phase >= 2);
    let stride = all.len().div_ceil(MAX_FRAMES).max(1);
    let mut frames: Vec<Sample> = Vec::new();
    for (k, s) in all.iter().enumerate() {
        let keep = k % stride == 0 || k + 1 == all.len() || Some(k) == first_floor;
        if keep && frames.last().is_none_or(|p| p.t < s.t) {
            frames.push(*s);
        }
    }
    let separation = frames.iter().position(|s| s.phase >= 2);
    let l = scene.ladder.l;
    let weight = scene.ladder.m * scene.ladder.g;
    let biggest = frames
        .iter()
        .filter_map(|s| s.forces)
        .map(|(w, f)| w.abs().max(f.abs()))
        .fold(weight, f64::max);
    // The largest force is drawn l long.
    let metres_per_newton = l / biggest;
    let x_max = frames
        .iter()
        .map(|s| s.centre_x + l * s.theta.sin())
        .fold(2.0 * l, f64::max);
    let (w_m, h_m) = (x_max + 1.6 * l, 2.0 * l + 1.9 * l);
    let px_per_metre = ((SIZE.0 - 40.0) / w_m).min((SIZE.1 - 40.0) / h_m);
    // Below the floor: room for the weight, drawn at most l long from the centre.
    let origin = (
        20.0 + 0.6 * l * px_per_metre,
        SIZE.1 - 30.0 - l * px_per_metre,
    );
    Ok(Animation {
        frames,
        separation,
        separation_event: o.separation.map(|s| (s.time, s.angle)),
        metres_per_newton,
        px_per_metre,
        origin,
    })
}

/// The ends and the centre of the ladder in a sample, metres: (C, D, B).
pub fn ends(s: &Sample, l: f64) -> ((f64, f64), (f64, f64), (f64, f64)) {
    let (sin, cos) = s.theta.sin_cos();
    (
        (s.centre_x - l * sin, 2.0 * l * cos),
        (s.centre_x + l * sin, 0.0),
        (s.centre_x, l * cos),
    )
}

impl Animation {
    /// A point of the lab (metres) in the drawing (px).
    fn px(&self, p: (f64, f64)) -> (f64, f64) {
        (
            self.origin.0 + p.0 * self.px_per_metre,
            self.origin.1 - p.1 * self.px_per_metre,
        )
    }

    /// The animation's length, s.
    fn duration(&self) -> f64 {
        let t_end = self.frames.last().map_or(0.0, |s| s.t);
        SLOW * t_end + HOLD
    }

    /// `keyTimes` of the frames, then 1 (the hold).
    fn key_times(&self) -> String {
        let d = self.duration();
        let mut k: Vec<String> = self
            .frames
            .iter()
            .map(|s| format!("{:.5}", SLOW * s.t / d))
            .collect();
        k.push("1".into());
        k.join(";")
    }

    /// An `<animate>` of `attr` through `value` of each frame (the last held).
    fn animate(&self, attr: &str, value: impl Fn(&Sample) -> String, discrete: bool) -> String {
        let mut v: Vec<String> = self.frames.iter().map(&value).collect();
        if let Some(last) = v.last().cloned() {
            v.push(last);
        }
        format!(
            "<animate attributeName=\"{attr}\" dur=\"{:.3}s\" repeatCount=\"indefinite\" calcMode=\"{}\" keyTimes=\"{}\" values=\"{}\" />",
            self.duration(),
            if discrete { "discrete" } else { "linear" },
            self.key_times(),
            v.join(";")
        )
    }

    /// A line animated between two points of each frame (metres), with its own attributes.
    fn moving_line(
        &self,
        id: &str,
        attrs: &str,
        ends: impl Fn(&Sample) -> ((f64, f64), (f64, f64)),
        visible: impl Fn(&Sample) -> bool,
    ) -> String {
        let ends = &ends;
        let coord = |k: usize| {
            move |s: &Sample| {
                let (a, b) = ends(s);
                let (a, b) = (self.px(a), self.px(b));
                format!("{:.2}", [a.0, a.1, b.0, b.1][k])
            }
        };
        let first = &self.frames[0];
        let (a, b) = ends(first);
        let (a, b) = (self.px(a), self.px(b));
        format!(
            "<line id=\"{id}\" x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" {attrs}>{}{}{}{}{}</line>\n",
            a.0,
            a.1,
            b.0,
            b.1,
            self.animate("x1", coord(0), false),
            self.animate("y1", coord(1), false),
            self.animate("x2", coord(2), false),
            self.animate("y2", coord(3), false),
            self.animate("opacity", |s| if visible(s) { "1".into() } else { "0".into() }, true),
        )
    }
}

/// The animated SVG of the run `o` of `scene` (with trace and forces, to flat).
pub fn svg(scene: &Scene, o: &Outcome) -> Result<String, String> {
    let a = frames(scene, o)?;
    let lad = &scene.ladder;
    let l = lad.l;
    let k = a.metres_per_newton;
    let weight = lad.m * lad.g;
    let shown = |f: f64| f.abs() * k * a.px_per_metre >= 1.0;
    let mut out = String::new();
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {w} {h}\" width=\"{w}\" height=\"{h}\" \
font-family=\"DejaVu Sans, sans-serif\" font-size=\"13\" data-metres-per-newton=\"{k:e}\" \
data-px-per-metre=\"{p:e}\" data-origin=\"{ox:.3},{oy:.3}\" data-half-length=\"{l:e}\">\n\
<title>The ladder's fall from release to flat, simulated ({method}), forces to scale</title>\n\
<defs><marker id=\"head\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\">\
<path d=\"M0,0 L10,5 L0,10 z\" fill=\"context-stroke\" /></marker></defs>\n",
        w = SIZE.0,
        h = SIZE.1,
        p = a.px_per_metre,
        ox = a.origin.0,
        oy = a.origin.1,
        method = scene.method,
    );
    let (wall_top, floor_end) = (a.px((0.0, 2.6 * l)), a.px((SIZE.0 / a.px_per_metre, 0.0)));
    let _ = writeln!(
        out,
        "<line id=\"wall\" x1=\"{ox:.2}\" y1=\"{:.2}\" x2=\"{ox:.2}\" y2=\"{oy:.2}\" stroke=\"#333\" stroke-width=\"2\" />\n\
<line id=\"floor\" x1=\"{ox:.2}\" y1=\"{oy:.2}\" x2=\"{:.2}\" y2=\"{oy:.2}\" stroke=\"#333\" stroke-width=\"2\" />",
        wall_top.1,
        floor_end.0,
        ox = a.origin.0,
        oy = a.origin.1,
    );
    if let Some(ev) = a.separation_event {
        out.push_str(&separation_mark(&a, ev, l));
    }
    out.push_str(&a.moving_line(
        "ladder",
        "stroke=\"#8a5a2b\" stroke-width=\"6\" stroke-linecap=\"round\"",
        |s| {
            let (c, d, _) = ends(s, l);
            (c, d)
        },
        |_| true,
    ));
    out.push_str(&a.moving_line(
        "wall-force",
        "stroke=\"#1f5fbf\" stroke-width=\"3\" marker-end=\"url(#head)\"",
        |s| {
            let (c, _, _) = ends(s, l);
            let f = s.forces.map_or(0.0, |f| f.0);
            (c, (c.0 + f * k, c.1))
        },
        |s| shown(s.forces.map_or(0.0, |f| f.0)),
    ));
    out.push_str(&a.moving_line(
        "floor-force",
        "stroke=\"#1a7f37\" stroke-width=\"3\" marker-end=\"url(#head)\"",
        |s| {
            let (_, d, _) = ends(s, l);
            let f = s.forces.map_or(0.0, |f| f.1);
            (d, (d.0, d.1 + f * k))
        },
        |s| shown(s.forces.map_or(0.0, |f| f.1)),
    ));
    out.push_str(&a.moving_line(
        "weight",
        "stroke=\"#b42318\" stroke-width=\"3\" marker-end=\"url(#head)\"",
        |s| {
            let (_, _, b) = ends(s, l);
            (b, (b.0, b.1 - weight * k))
        },
        |_| true,
    ));
    out.push_str(&legend(&a, weight, o));
    out.push_str("</svg>\n");
    Ok(out)
}

/// The separation: the ladder's pose there dashed, a ring where the top leaves the wall, and
/// a label shown from that moment on.
fn separation_mark(a: &Animation, (t, theta): (f64, f64), l: f64) -> String {
    // On the wall still: the centre at x_cm = l sin θ_s (7).
    let pose = Sample {
        phase: 1,
        t,
        theta,
        rate: 0.0,
        centre_x: l * theta.sin(),
        forces: None,
    };
    let (c, d, _) = ends(&pose, l);
    let (c, d) = (a.px(c), a.px(d));
    let on = a.animate(
        "opacity",
        |f| {
            if f.phase >= 2 {
                "1".into()
            } else {
                "0.25".into()
            }
        },
        true,
    );
    format!(
        "<g id=\"separation\" data-t=\"{t:e}\" data-theta=\"{th:e}\">\
<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"#8a5a2b\" stroke-width=\"2\" stroke-dasharray=\"6 4\" opacity=\"0.6\" />\
<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"7\" fill=\"none\" stroke=\"#9a6700\" stroke-width=\"2\" />\
<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#9a6700\">{on}the top leaves the wall: θ_s = {deg:.2}°, t_s = {t:.3} s</text></g>\n",
        c.0,
        c.1,
        d.0,
        d.1,
        c.0,
        c.1,
        c.0 + 12.0,
        c.1 - 10.0,
        th = theta,
        deg = theta.to_degrees(),
    )
}

/// The key: what each colour is, the scale, and the timing.
fn legend(a: &Animation, weight: f64, o: &Outcome) -> String {
    let x = SIZE.0 - 300.0;
    let scale_px = weight * a.metres_per_newton * a.px_per_metre;
    let flat = o
        .flat
        .map(|f| format!("flat at t = {:.3} s", f.time))
        .unwrap_or_default();
    format!(
        "<g id=\"legend\" font-size=\"12\"><text x=\"{x}\" y=\"24\" fill=\"#1f5fbf\">blue: wall force F_w at C</text>\
<text x=\"{x}\" y=\"40\" fill=\"#1a7f37\">green: floor force F_f at D</text>\
<text x=\"{x}\" y=\"56\" fill=\"#b42318\">red: weight m g = {weight:.3} N at B</text>\
<line x1=\"{x}\" y1=\"70\" x2=\"{:.2}\" y2=\"70\" stroke=\"#b42318\" stroke-width=\"3\" />\
<text x=\"{x}\" y=\"86\">one scale for all three forces (the bar is m g)</text>\
<text x=\"{x}\" y=\"102\">played {SLOW}× slower than the fall; {flat}</text></g>\n",
        x + scale_px,
    )
}

/// Why the animation cannot draw `scene`, naming the field: only the rigid model is drawn, and
/// the exact method has no floor phase.
pub fn unsupported(scene: &Scene) -> Option<String> {
    use crate::sim::scene::ContactModel;
    if scene.contact != ContactModel::Rigid {
        return Some(format!(
            "{}: [contact] model: the animation draws the rigid model only (model = \"rigid\")",
            scene.file
        ));
    }
    (scene.method == "exact").then(|| {
        format!(
            "{}: [integrator] method: \"exact\" stops at separation; the animation needs the floor phase (use e.g. \"dop853\")",
            scene.file
        )
    })
}

/// Run `scene` for the animation: from its start to flat, keeping the trace with the contact
/// forces (whatever outputs or end the scene asks for).
pub fn run(scene: &Scene) -> Result<(Scene, Outcome), String> {
    use crate::sim::scene::output::Output;
    use crate::sim::scene::End;
    if let Some(why) = unsupported(scene) {
        return Err(why);
    }
    let mut s = scene.clone();
    s.end = End::Flat;
    for o in [Output::Trajectory, Output::Forces] {
        if !s.outputs.contains(&o) {
            s.outputs.push(o);
        }
    }
    let o = crate::sim::fall::run(&s, crate::sim::fall::MAX_STEPS)
        .map_err(|e| format!("{}: {e}", s.file))?;
    if o.flat.is_none() {
        return Err(format!("{}: the run did not reach flat", s.file));
    }
    Ok((s, o))
}
