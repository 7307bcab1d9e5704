//! The animated fall (`report::animation`, issue 39), read back from the SVG it writes and held
//! against closed forms independent of the simulator and of the drawing code:
//!
//! * an animation with no script: SMIL `<animate>` elements, repeating;
//! * every frame is a ladder of length 2l whose foot D is on the floor, whose top C is on the wall
//!   before the separation and never inside it, and off it at the end;
//! * on the wall, the wall force's arrow is F_w = (3mg/4) sin θ (3 cos θ − 2 cos θ0) long and the
//!   floor force's F_f = mg[1 − (3/4) sin² θ − (3/2) cos θ (cos θ0 − cos θ)] (from (6), (8), (5) and
//!   energy from rest at θ0, (9)), at the drawing's stated scale, θ read off the drawn ladder;
//!   the weight is m g long at every frame;
//! * the separation is marked at θ_s with cos θ_s = (2/3) cos θ0 (footnote 4).
//!
//! Tolerances: coordinates are written to 0.01 px, so a length is within 0.01 px and θ read from
//! the ends (2l px_per_metre apart) within 0.01/(2l ppm) rad; the closed forms change by at most
//! 4 m g per radian, so a force is within 0.01/(k ppm) + 4 m g · 0.01/(2l ppm), doubled.
//! Shown able to fail: the wall force's arrows drawn 10 % long, a frame's top moved off the wall
//! before separation, and the weight's arrow shortened are each reported.

use sliding_ladder::report::animation::{run, svg};
use sliding_ladder::sim::scene::load;
use std::path::Path;

/// The numbers after `attr="` in the first element whose text starts at `from`.
fn attr(text: &str, from: usize, name: &str) -> String {
    let key = format!("{name}=\"");
    let i = text[from..].find(&key).expect(name) + from + key.len();
    let j = text[i..].find('"').unwrap() + i;
    text[i..j].to_string()
}

/// The `values` of the `<animate>` of `attribute` inside the element with `id`.
fn values(svg: &str, id: &str, attribute: &str) -> Vec<f64> {
    let start = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no element {id}"));
    let end = svg[start..].find("</line>").expect("closed") + start;
    let key = format!("attributeName=\"{attribute}\"");
    let at = svg[start..end].find(&key).expect(attribute) + start;
    attr(svg, at, "values")
        .split(';')
        .map(|v| v.parse().expect("a number"))
        .collect()
}

fn number(svg: &str, name: &str) -> f64 {
    attr(svg, 0, name).parse().expect(name)
}

/// Everything wrong with an animation of a fall from rest at `theta0` of a ladder (m, l, g).
fn problems(svg: &str, theta0: f64, (m, l, g): (f64, f64, f64)) -> Vec<String> {
    let mut out = Vec::new();
    if svg.contains("<script") || !svg.contains("<animate") || !svg.contains("repeatCount") {
        out.push("not a SMIL animation without script".into());
    }
    let (k, ppm) = (
        number(svg, "data-metres-per-newton"),
        number(svg, "data-px-per-metre"),
    );
    let origin: Vec<f64> = attr(svg, 0, "data-origin")
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let px = 0.01;
    let theta_tol = 2.0 * px / (2.0 * l * ppm);
    let force_tol = 2.0 * (px / (k * ppm) + 4.0 * m * g * theta_tol);
    let get = |id, a| values(svg, id, a);
    let (cx, cy, dx, dy) = (
        get("ladder", "x1"),
        get("ladder", "y1"),
        get("ladder", "x2"),
        get("ladder", "y2"),
    );
    let (wx1, wx2) = (get("wall-force", "x1"), get("wall-force", "x2"));
    let (fy1, fy2) = (get("floor-force", "y1"), get("floor-force", "y2"));
    let (gy1, gy2) = (get("weight", "y1"), get("weight", "y2"));
    let cos_s = 2.0 / 3.0 * theta0.cos();
    let theta_s: f64 = number(svg, "data-theta");
    if (theta_s.cos() - cos_s).abs() > 1e-9 {
        out.push(format!(
            "separation marked at cos θ = {}, not {cos_s}",
            theta_s.cos()
        ));
    }
    for i in 0..cx.len() {
        // Screen y grows downwards: the top C is above the foot D.
        let (lx, ly) = (dx[i] - cx[i], dy[i] - cy[i]);
        let len = lx.hypot(ly) / ppm;
        if (len - 2.0 * l).abs() > 2.0 * px / ppm {
            out.push(format!("frame {i}: the ladder is {len} m long"));
        }
        if (dy[i] - origin[1]).abs() > px {
            out.push(format!("frame {i}: the foot is off the floor"));
        }
        let theta = lx.atan2(ly);
        let on_wall = theta < theta_s - theta_tol;
        if on_wall && (cx[i] - origin[0]).abs() > px {
            out.push(format!(
                "frame {i}: the top left the wall before the separation"
            ));
        }
        // After it the top moves off the wall from rest (ẋ_C = 0 at t_s), so frame by frame
        // only "never inside the wall" holds; the last frame is checked clear of it below.
        if cx[i] < origin[0] - px {
            out.push(format!("frame {i}: the top is inside the wall"));
        }
        if on_wall {
            let (s, c, c0) = (theta.sin(), theta.cos(), theta0.cos());
            let f_w = 0.75 * m * g * s * (3.0 * c - 2.0 * c0);
            let f_f = m * g * (1.0 - 0.75 * s * s - 1.5 * c * (c0 - c));
            let drawn_w = (wx2[i] - wx1[i]) / (k * ppm);
            let drawn_f = (fy1[i] - fy2[i]) / (k * ppm);
            if (drawn_w - f_w).abs() > force_tol {
                out.push(format!(
                    "frame {i}: F_w drawn {drawn_w} N, closed form {f_w} N"
                ));
            }
            if (drawn_f - f_f).abs() > force_tol {
                out.push(format!(
                    "frame {i}: F_f drawn {drawn_f} N, closed form {f_f} N"
                ));
            }
        }
        let drawn_g = (gy2[i] - gy1[i]) / (k * ppm);
        if (drawn_g - m * g).abs() > force_tol {
            out.push(format!("frame {i}: the weight drawn {drawn_g} N"));
        }
    }
    if cx.last().is_some_and(|x| x - origin[0] < 1.0) {
        out.push("the top never left the wall".into());
    }
    out
}

fn full_fall() -> (String, f64, (f64, f64, f64)) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = load(&root.join("scenes/full-fall.toml")).expect("the scene");
    let (scene, o) = run(&scene).expect("the run reaches flat");
    let lad = scene.ladder;
    assert!(o.separation.is_some() && o.flat.is_some());
    (
        svg(&scene, &o).expect("drawn"),
        scene.theta0,
        (lad.m, lad.l, lad.g),
    )
}

#[test]
fn every_frame_is_the_simulated_ladder_with_its_forces_to_scale_and_the_separation_marked() {
    let (svg, theta0, lad) = full_fall();
    let frames = values(&svg, "ladder", "x1").len();
    assert!(frames >= 50, "only {frames} frames");
    // Not vacuous: frames on the wall and off it.
    let on_wall = values(&svg, "ladder", "x1")
        .iter()
        .filter(|x| (**x - values(&svg, "ladder", "x1")[0]).abs() < 0.01)
        .count();
    assert!(
        on_wall >= 10 && on_wall + 10 <= frames,
        "{on_wall} of {frames} on the wall"
    );
    let p = problems(&svg, theta0, lad);
    assert!(p.is_empty(), "{}", p.join("\n"));
}

/// Replace the `values` of `attribute` of element `id` by `f` of each value.
fn plant(svg: &str, id: &str, attribute: &str, f: impl Fn(usize, f64) -> f64) -> String {
    let start = svg.find(&format!("id=\"{id}\"")).unwrap();
    let key = format!("attributeName=\"{attribute}\"");
    let at = svg[start..].find(&key).unwrap() + start;
    let i = svg[at..].find("values=\"").unwrap() + at + 8;
    let j = svg[i..].find('"').unwrap() + i;
    let new: Vec<String> = svg[i..j]
        .split(';')
        .enumerate()
        .map(|(k, v)| format!("{:.2}", f(k, v.parse().unwrap())))
        .collect();
    format!("{}{}{}", &svg[..i], new.join(";"), &svg[j..])
}

#[test]
fn wrong_forces_a_top_off_the_wall_or_a_short_weight_are_caught() {
    let (svg, theta0, lad) = full_fall();
    let x1 = values(&svg, "wall-force", "x1");
    let long = plant(&svg, "wall-force", "x2", |k, v| x1[k] + 1.1 * (v - x1[k]));
    let off = plant(
        &svg,
        "ladder",
        "x1",
        |k, v| if k == 3 { v + 5.0 } else { v },
    );
    let gy1 = values(&svg, "weight", "y1");
    let short = plant(&svg, "weight", "y2", |k, v| gy1[k] + 0.9 * (v - gy1[k]));
    let has = |s: &str, what: &str| {
        let p = problems(s, theta0, lad);
        assert!(
            p.iter().any(|x| x.contains(what)),
            "{what} not caught: {p:?}"
        );
    };
    has(&long, "F_w drawn");
    has(&off, "frame 3: the top left the wall");
    has(&short, "the weight drawn");
}
