//! A display's LaTeX as one line of Unicode for the terminal: `\frac{4ml^2\ddot{\theta}}{3}` reads
//! `4ml²θ̈/3`.
//!
//! Written by hand: the crates that render LaTeX produce MathML or images, and the Unicode
//! converters (unicodeit and the like) are Python; the note uses a small fixed vocabulary (the
//! commands of the displays in `equations/*.md`), each mapped here. Accents become combining
//! characters (θ̇, θ̈, ẑ, r̄), `^2` a superscript, `_i` a subscript where Unicode has one (else
//! `_cm`, as the registry's labels write it), `\frac{a}{b}` `a/b` with parentheses only around
//! a compound part, and layout (`aligned`, `&`, `\\`, `\quad`, `\left`, `\Big`) is dropped.

/// The Unicode reading of a LaTeX fragment.
pub fn unicode(latex: &str) -> String {
    let chars: Vec<char> = latex.chars().collect();
    let mut p = 0;
    let out = convert(&chars, &mut p, None);
    tidy(&out)
}

/// Collapse runs of spaces and trim.
fn tidy(s: &str) -> String {
    let mut out = String::new();
    for w in s.split_whitespace() {
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(w);
    }
    out.replace("( ", "(").replace(" )", ")").replace(" ,", ",")
}

/// Convert until the closing `stop` (a `}`), consuming it.
fn convert(c: &[char], p: &mut usize, stop: Option<char>) -> String {
    let mut out = String::new();
    while *p < c.len() {
        let ch = c[*p];
        if Some(ch) == stop {
            *p += 1;
            return out;
        }
        *p += 1;
        match ch {
            '\\' => out.push_str(&command(c, p)),
            '{' => out.push_str(&convert(c, p, Some('}'))),
            '^' => {
                let arg = argument(c, p);
                out.push_str(&script(&arg, true));
            }
            '_' => {
                let arg = argument(c, p);
                out.push_str(&script(&arg, false));
            }
            '&' => {}
            '=' => out.push_str(" = "),
            '+' => out.push_str(" + "),
            '-' => {
                // Binary minus between operands, a bare sign elsewhere.
                let prev = out.trim_end().chars().last();
                if prev.is_some_and(|x| !matches!(x, '(' | '=' | ',' | '[')) {
                    out.push_str(" − ");
                } else {
                    out.push('−');
                }
            }
            ',' => out.push_str(", "),
            // Source spacing carries nothing; products read like the registry's labels.
            c if c.is_whitespace() => {}
            c => out.push(c),
        }
    }
    out
}

/// The next argument: a `{group}`, a `\command`, or one character.
fn argument(c: &[char], p: &mut usize) -> String {
    while *p < c.len() && c[*p] == ' ' {
        *p += 1;
    }
    match c.get(*p) {
        Some('{') => {
            *p += 1;
            convert(c, p, Some('}'))
        }
        Some('\\') => {
            *p += 1;
            command(c, p)
        }
        Some(&ch) => {
            *p += 1;
            ch.to_string()
        }
        None => String::new(),
    }
}

/// A `\command` (after its backslash) with its arguments, read as Unicode: accents combine,
/// fonts and layout drop, operators and Greek letters become their symbols, an unknown command
/// stays as written.
fn command(c: &[char], p: &mut usize) -> String {
    let start = *p;
    while *p < c.len() && c[*p].is_ascii_alphabetic() {
        *p += 1;
    }
    let word: String = c[start..*p].iter().collect();
    if word.is_empty() {
        // A control symbol: `\\` (row break), `\,` and friends (thin spaces).
        *p += 1;
        return " ".into();
    }
    match word.as_str() {
        "frac" => fraction(c, p),
        "dot" => accent(c, p, '\u{307}'),
        "ddot" => accent(c, p, '\u{308}'),
        "hat" => accent(c, p, '\u{302}'),
        "bar" => accent(c, p, '\u{304}'),
        "tilde" => accent(c, p, '\u{303}'),
        "mathbf" | "boldsymbol" | "text" => {
            let a = argument(c, p);
            if a.trim_end().ends_with(':') {
                format!("{}: ", a.trim_end().trim_end_matches(':').trim_end())
            } else {
                a
            }
        }
        "mathcal" => match argument(c, p).as_str() {
            "L" => "ℒ".into(),
            other => other.into(),
        },
        "begin" | "end" => {
            let _ = argument(c, p);
            " ".into()
        }
        "left" | "right" | "Big" | "big" | "Bigl" | "Bigr" => String::new(),
        "quad" | "qquad" => "   ".into(),
        "sin" | "cos" => trig(c, p, &word),
        "times" => " × ".into(),
        "wedge" => " ∧ ".into(),
        "cdot" => "·".into(),
        "sum" => "Σ".into(),
        "equiv" => " ≡ ".into(),
        "Rightarrow" => " ⇒ ".into(),
        "partial" => "∂".into(),
        "prime" => "′".into(),
        w => greek(w).map_or_else(|| format!("\\{w}"), String::from),
    }
}

/// An accented argument: the argument followed by the combining `mark` (θ̇, ẑ, r̄).
fn accent(c: &[char], p: &mut usize, mark: char) -> String {
    let mut a = argument(c, p);
    a.push(mark);
    a
}

/// `\frac{n}{d}` as `n/d` (parentheses around a compound part), `d/dt` for the derivative;
/// a fraction multiplied by what follows reads `(ml²θ̇/3) ẑ`, not `ml²θ̇/3ẑ`.
fn fraction(c: &[char], p: &mut usize) -> String {
    let (n, d) = (argument(c, p), argument(c, p));
    if n == "d" && d == "dt" {
        return "d/dt ".into();
    }
    let f = format!("{}/{}", wrap(&n), wrap(&d));
    let mut q = *p;
    while c.get(q) == Some(&' ') {
        q += 1;
    }
    if c.get(q)
        .is_some_and(|x| x.is_alphanumeric() || matches!(x, '\\' | '('))
        && !starts_operator(c, q)
    {
        let gap = if c.get(q) == Some(&'(') { "" } else { " " };
        format!("({f}){gap}")
    } else {
        f
    }
}

/// `\sin` or `\cos` with its argument: `\sin^2\theta` reads `sin²θ`; the argument (one
/// symbol) is taken with it, so a factor after it stands apart: `sin θ θ̇²`.
fn trig(c: &[char], p: &mut usize, word: &str) -> String {
    let mut sup = String::new();
    if c.get(*p) == Some(&'^') {
        *p += 1;
        sup = script(&argument(c, p), true);
    }
    format!(" {word}{sup} {} ", argument(c, p))
}

/// True when a command that is not a factor starts at `q` (`\\`, `\end`, `\quad`, `\times`, …).
fn starts_operator(c: &[char], q: usize) -> bool {
    if c.get(q) != Some(&'\\') {
        return false;
    }
    let word: String = c[q + 1..]
        .iter()
        .take_while(|x| x.is_ascii_alphabetic())
        .collect();
    word.is_empty()
        || matches!(
            word.as_str(),
            "end"
                | "quad"
                | "qquad"
                | "times"
                | "wedge"
                | "cdot"
                | "equiv"
                | "Rightarrow"
                | "right"
                | "Big"
                | "text"
        )
}

fn greek(w: &str) -> Option<&'static str> {
    Some(match w {
        "theta" => "θ",
        "tau" => "τ",
        "omega" => "ω",
        "Omega" => "Ω",
        "Gamma" => "Γ",
        "alpha" => "α",
        "beta" => "β",
        "epsilon" => "ε",
        "lambda" => "λ",
        "mu" => "μ",
        "pi" => "π",
        "rho" => "ρ",
        "sigma" => "σ",
        "phi" => "φ",
        "psi" => "ψ",
        "Delta" => "Δ",
        _ => return None,
    })
}

/// Parentheses around a compound numerator or denominator, unless one pair already encloses
/// all of it ((a + b)(c + d) is two pairs, and is wrapped).
fn wrap(s: &str) -> String {
    let t = s.trim();
    let compound = t.contains([' ', '+', '−', '/']) && !enclosed(t);
    if compound {
        format!("({t})")
    } else {
        t.to_string()
    }
}

/// True when the text's first '(' closes at its last character.
fn enclosed(t: &str) -> bool {
    let Some(inner) = t.strip_prefix('(').and_then(|r| r.strip_suffix(')')) else {
        return false;
    };
    let mut depth = 0i32;
    for ch in inner.chars() {
        depth += match ch {
            '(' => 1,
            ')' => -1,
            _ => 0,
        };
        if depth < 0 {
            return false;
        }
    }
    depth == 0
}

/// A superscript or subscript: Unicode's own characters when every character has one.
fn script(arg: &str, sup: bool) -> String {
    let t: String = arg.split_whitespace().collect();
    let t = t.as_str();
    let map = |ch: char| -> Option<char> {
        if sup {
            Some(match ch {
                '0' => '⁰',
                '1' => '¹',
                '2' => '²',
                '3' => '³',
                '4' => '⁴',
                '5' => '⁵',
                '6' => '⁶',
                '7' => '⁷',
                '8' => '⁸',
                '9' => '⁹',
                '−' | '-' => '⁻',
                _ => return None,
            })
        } else {
            Some(match ch {
                '0' => '₀',
                '1' => '₁',
                '2' => '₂',
                '3' => '₃',
                'i' => 'ᵢ',
                _ => return None,
            })
        }
    };
    match t.chars().map(map).collect::<Option<String>>() {
        Some(s) if !s.is_empty() => s,
        _ if sup => format!("^{}", wrap(t)),
        // A space after the subscript, so `F_f l` does not read `F_fl`.
        _ => format!("_{t} "),
    }
}
