//! Tokens of the note's display LaTeX.
//!
//! Spacing and layout commands that carry no mathematics (`\quad`, `\,`, `&`, `\begin{aligned}`,
//! `\end{aligned}`, `\left`, `\right`, `\Big` before a delimiter other than `|`) are dropped here;
//! `\\` (a row break) is kept because a row may begin Milne's part of a display.

/// One token.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Tok {
    /// A control word without its backslash: `frac`, `theta`, `mathbf`.
    Cmd(String),
    /// A letter.
    Letter(char),
    /// A run of digits.
    Int(i64),
    /// One of `+ - = ( ) [ ] { } , . ^ _ ' | /`.
    Punct(char),
    /// `\Big|`, the evaluation bar.
    Bar,
    /// `\\`, a row break of an aligned environment.
    RowBreak,
}

/// Split a display into tokens; an unknown character is an error naming it.
pub fn lex(src: &str) -> Result<Vec<Tok>, String> {
    let chars: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() || c == '&' {
            i += 1;
        } else if c == '\\' {
            i += 1;
            let Some(&n) = chars.get(i) else {
                return Err("a lone backslash at the end".into());
            };
            if n == '\\' {
                out.push(Tok::RowBreak);
                i += 1;
            } else if n.is_ascii_alphabetic() {
                let start = i;
                while i < chars.len() && chars[i].is_ascii_alphabetic() {
                    i += 1;
                }
                let word: String = chars[start..i].iter().collect();
                match word.as_str() {
                    "quad" | "qquad" | "left" | "right" | "big" | "Bigl" | "Bigr" => {}
                    "begin" | "end" => {
                        // `{aligned}`: an environment name carries no mathematics.
                        if chars.get(i) == Some(&'{') {
                            while i < chars.len() && chars[i] != '}' {
                                i += 1;
                            }
                            i += 1;
                        }
                    }
                    "Big" => {
                        while chars.get(i).is_some_and(|c| c.is_whitespace()) {
                            i += 1;
                        }
                        if chars.get(i) == Some(&'|') {
                            out.push(Tok::Bar);
                            i += 1;
                        }
                    }
                    _ => out.push(Tok::Cmd(word)),
                }
            } else if matches!(n, ',' | ';' | '!' | ' ') {
                i += 1; // thin spaces
            } else {
                return Err(format!("unknown control symbol \\{n}"));
            }
        } else if c.is_ascii_digit() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            out.push(Tok::Int(s.parse().map_err(|_| format!("number {s}"))?));
        } else if c.is_ascii_alphabetic() {
            out.push(Tok::Letter(c));
            i += 1;
        } else if "+-=()[]{},.^_'|/:".contains(c) {
            out.push(Tok::Punct(c));
            i += 1;
        } else {
            return Err(format!("unexpected character '{c}'"));
        }
    }
    Ok(out)
}
