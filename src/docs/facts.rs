//! Figures the book states that come from the code: each is rendered here from the constant it
//! describes and must appear verbatim in its file, so a change of the code that leaves the prose
//! behind is reported as a problem of the book (`file: ...`), not discovered by a reader.

use crate::registry::check::{Config, EXACT_HEIGHT, RATIONAL_POINTS, TOLERANCE_FACTOR};
use crate::scalar::MODULUS;
use std::path::Path;

/// 2 to the power `k` in Unicode: 2⁶⁰.
fn power_of_two(k: u32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits: String = k
        .to_string()
        .bytes()
        .map(|d| SUP[(d - b'0') as usize])
        .collect();
    format!("2{digits}")
}

/// One stated figure: the file (relative to `equations/`) and the exact phrase it must contain.
#[derive(Clone, Debug)]
pub struct Fact {
    /// File name inside the book directory.
    pub file: &'static str,
    /// The phrase, rendered from the code.
    pub phrase: String,
    /// What the figure is, for the message.
    pub what: &'static str,
}

/// Every figure of the book that the code decides.
pub fn facts() -> Vec<Fact> {
    let cfg = Config::default();
    vec![
        Fact {
            file: "README.md",
            phrase: format!("{} random states per check", cfg.float_cases),
            what: "float states per check (Config::default().float_cases)",
        },
        Fact {
            file: "README.md",
            phrase: format!("seed {} by default", cfg.seed),
            what: "the default seed (Config::default().seed)",
        },
        Fact {
            file: "README.md",
            phrase: format!("at {} random points per check", cfg.exact_points),
            what: "exact points per check (Config::default().exact_points)",
        },
        Fact {
            file: "README.md",
            phrase: format!(
                "{} in rational arithmetic, the others modulo the prime p = {} − 1",
                match RATIONAL_POINTS {
                    1 => "the first".to_string(),
                    k => format!("the first {k}"),
                },
                power_of_two((MODULUS + 1).trailing_zeros())
            ),
            what: "which exact points are rational (registry::exact_point::RATIONAL_POINTS = 1) and the prime (scalar::modp::MODULUS)",
        },
        Fact {
            file: "README.md",
            phrase: format!(
                "random integer of magnitude below {}",
                power_of_two(EXACT_HEIGHT.trailing_zeros())
            ),
            what: "the size of the exact coordinates (registry::exact_point::EXACT_HEIGHT)",
        },
        Fact {
            file: "README.md",
            phrase: format!("|a − b| ≤ {}·u·(e_a + e_b)", TOLERANCE_FACTOR),
            what: "the float tolerance factor (registry::check::TOLERANCE_FACTOR)",
        },
    ]
}

/// Check every fact whose file exists in `dir`; problems as `file: message`.
pub fn check_facts(dir: &Path, facts: &[Fact], problems: &mut Vec<String>) {
    for f in facts {
        let path = dir.join(f.file);
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        // Line breaks in the markdown do not matter.
        let flat = crate::docs::normalize_latex(&text);
        if !flat.contains(&crate::docs::normalize_latex(&f.phrase)) {
            problems.push(format!(
                "{}: does not state {} as the code has it: \"{}\"",
                path.display(),
                f.what,
                f.phrase
            ));
        }
    }
}
