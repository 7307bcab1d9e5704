//! The text summary prints significant digits: a slow ladder (l = 1, g = 1e-26, so √(l/g) =
//! 1e13 s) separates at θ̇ ≈ 7e-14 rad/s, which fixed decimals (`{:.12}`) printed as
//! 0.000000000000. Each number the summary prints for separation, flat and end is read back and
//! held against the outcome it came from, to the digits printed.

use sliding_ladder::report::outcome::summary;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::scene;

/// The number after `key` on the summary line that starts with `line`.
fn field(text: &str, line: &str, key: &str) -> f64 {
    let l = text
        .lines()
        .find(|l| l.trim_start().starts_with(line))
        .unwrap_or_else(|| panic!("no {line} line in\n{text}"));
    let rest = &l[l.find(key).unwrap_or_else(|| panic!("no {key} in {l}")) + key.len()..];
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn a_slow_ladder_prints_its_rates() {
    let text = "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = 1e-26\n[start]\nangle = 0.3\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"dop853\"\ntolerance = 1e-12\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"separation_angle\", \"separation_time\", \"flat_time\"]\n";
    let sc = scene::parse("slow.toml", text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let s = summary(&sc, &o);
    let sep = o.separation.unwrap();
    let flat = o.flat.unwrap();
    // 13 significant digits printed: read back to 1e-12 relative.
    for (got, want) in [
        (field(&s, "separation", "θ̇ = "), sep.rate),
        (field(&s, "separation", "t = "), sep.time),
        (field(&s, "flat", "θ̇ = "), flat.rate),
        (field(&s, "end", "θ̇ = "), o.last.2),
    ] {
        assert!(
            (got - want).abs() <= 1e-12 * want.abs(),
            "{got} against {want}\n{s}"
        );
    }
    // What fixed decimals made of it: the check above fails on that.
    assert!(sep.rate.abs() < 1e-13);
    assert_eq!(format!("{:.12}", sep.rate), "0.000000000000");
}
