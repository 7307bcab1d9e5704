//! The dimension an SI unit spells (`N`, `kg m^2/s`, `rad/s^2`), so a stated unit can be held
//! against a computed dimension (the symbol table, `docs/UNITS.md`).
//!
//! The project states units in a small vocabulary: kg, m, s, N, J, rad (a pure number), `1`,
//! factors separated by spaces, each with an optional integer power and one `/` (`kg m^2/s` is
//! kg · m²/s). A unit-parsing crate would bring conversions and prefixes the project never uses.

use super::dimension::Dimension;
use num_rational::Ratio;

impl Dimension {
    /// The dimension of an SI unit in the project's vocabulary; Err names an unknown unit.
    pub fn from_si(unit: &str) -> Result<Dimension, String> {
        let base = |u: &str| {
            Ok(match u {
                "kg" => Dimension::MASS,
                "m" => Dimension::LENGTH,
                "s" => Dimension::TIME,
                "N" => Dimension::new(1, 1, -2),
                "J" => Dimension::new(1, 2, -2),
                "rad" | "1" => Dimension::NONE,
                _ => return Err(format!("unknown SI unit '{u}' in '{unit}'")),
            })
        };
        let power = |f: &str| -> Result<Dimension, String> {
            let (u, e) = f.split_once('^').unwrap_or((f, "1"));
            let e: i32 = e
                .parse()
                .map_err(|_| format!("bad power '{e}' in '{unit}'"))?;
            Ok(base(u)?.pow(Ratio::from_integer(e)))
        };
        let mut d = Dimension::NONE;
        for factor in unit.split_whitespace() {
            let (num, den) = factor.split_once('/').unwrap_or((factor, "1"));
            d = d * power(num)? / power(den)?;
        }
        Ok(d)
    }
}
