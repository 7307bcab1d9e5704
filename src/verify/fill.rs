//! Text that fits a teacher's terminal: the width a string takes in terminal columns, and the
//! filling of long lines (the legend, the law lines, the summary, the errata's reasons) at spaces
//! with a hanging indent. Written by hand because the text mixes formulas with words: a line is
//! never broken just after a binary operator (the operator starts the next line, as in typeset
//! mathematics), and combining marks (the dots of θ̇, θ̈) take no column, which
//! general-purpose wrappers count differently.

/// The width `ladder verify` and `ladder errata` lay out for when stdout is not a terminal (a
/// pipe, a file, a test) and no `--width` is given: a terminal a teacher is likely to have.
pub const DEFAULT_WIDTH: usize = 100;

/// Columns a string takes in a terminal: its characters less the combining marks (the dots of
/// θ̇ and θ̈, the hat of ẑ), which draw on the character before them.
pub fn width(s: &str) -> usize {
    s.chars()
        .filter(|c| !matches!(*c as u32, 0x300..=0x36F | 0x20D0..=0x20FF))
        .count()
}

/// A word that is a binary operator or relation on its own: it is kept with the word after it,
/// so a break falls before it.
fn is_operator(w: &str) -> bool {
    matches!(
        w,
        "−" | "-" | "+" | "=" | "×" | "∧" | "·" | "/" | "≤" | "≥" | "<" | ">" | "≈" | "≠" | "|"
    )
}

/// A word that must stay with the word after it: a lone operator (the break falls before it), a
/// word that ends in one (`(≈`), or a function name (`sin θ`).
fn binds_forward(w: &str) -> bool {
    is_operator(w) || matches!(w, "sin" | "cos" | "tan") || w.ends_with(['≈', '=', '−', '×', '∧'])
}

/// The words of `text`, each word that [`binds_forward`] joined to the word after it by a space
/// that is not a break.
fn words(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut pending: Option<String> = None;
    for w in text.split_whitespace() {
        let joined = match pending.take() {
            Some(p) => format!("{p} {w}"),
            None => w.to_string(),
        };
        if binds_forward(w) {
            pending = Some(joined);
        } else {
            out.push(joined);
        }
    }
    out.extend(pending);
    out
}

/// Break `text` at spaces into lines of at most `width` columns (a longer word stays whole).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    wrap_hanging(text, width, width)
}

/// Break `text` at spaces: the first line at most `first` columns, the others at most `rest`.
fn wrap_hanging(text: &str, first: usize, rest: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for w in words(text) {
        let limit = if lines.len() == 1 { first } else { rest };
        let cur = lines.last_mut().expect("one line");
        if cur.is_empty() {
            cur.push_str(&w);
        } else if self::width(cur) + 1 + self::width(&w) <= limit {
            cur.push(' ');
            cur.push_str(&w);
        } else {
            lines.push(w);
        }
    }
    lines
}

/// Where the text of `line` starts after a label: the character index after a gap of two or
/// more spaces that follows the line's first text within its first 30 columns (a label column,
/// as in the legend's `  residual    worst ...` or the law lines' `(25)  2nd ...`).
fn label_end(line: &str) -> Option<usize> {
    let chars: Vec<char> = line.chars().collect();
    let lead = chars.iter().take_while(|c| **c == ' ').count();
    let mut k = lead;
    while k + 1 < chars.len() && k < 30 {
        if chars[k] == ' ' && chars[k + 1] == ' ' {
            let j = k + chars[k..].iter().take_while(|c| **c == ' ').count();
            return (j < chars.len() && j <= 30).then_some(j);
        }
        k += 1;
    }
    None
}

/// One line filled to `width` columns: unchanged when it fits, else broken at spaces. A line
/// with a label column (`label_end`) keeps its label as it is and continues under its text;
/// any other line continues two columns right of its indent.
pub fn fill_line(line: &str, width: usize) -> String {
    if self::width(line) <= width {
        return line.to_string();
    }
    let lead = line.chars().take_while(|c| *c == ' ').count();
    let (prefix, body, hang): (String, String, usize) = match label_end(line) {
        Some(j) => {
            let prefix: String = line.chars().take(j).collect();
            let hang = self::width(&prefix);
            (prefix, line.chars().skip(j).collect(), hang)
        }
        None => (" ".repeat(lead), line[lead..].to_string(), lead + 2),
    };
    let first = width.saturating_sub(self::width(&prefix)).max(1);
    let rest = width.saturating_sub(hang).max(1);
    let lines = wrap_hanging(&body, first, rest);
    let mut out = format!("{prefix}{}", lines[0]);
    for l in &lines[1..] {
        out.push('\n');
        out.push_str(&" ".repeat(hang));
        out.push_str(l);
    }
    out
}

/// Every line of `text` filled to `width` columns (the trailing newline kept).
pub fn fill(text: &str, width: usize) -> String {
    let mut out: String = text
        .lines()
        .map(|l| fill_line(l, width))
        .collect::<Vec<_>>()
        .join("\n");
    if text.ends_with('\n') {
        out.push('\n');
    }
    out
}

/// The widest line of `text`, in terminal columns.
pub fn widest(text: &str) -> usize {
    text.lines().map(width).max().unwrap_or(0)
}
