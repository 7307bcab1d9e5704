//! No function in `src/` over 80 lines (the project's standard: a function a reader takes in at
//! once; issue 35 split the last 43). Counted on rustfmt's layout: a function runs from the line
//! of its `fn` to the first line that is its indentation and a lone `}`; comments and strings are
//! blanked first, so a `fn` in a doc comment or a string is no function.

use crate::module_graph::scan::code_only;

/// The longest a function may be, its signature and closing brace included.
pub const MAX_LINES: usize = 80;

/// Each function of `text`: (name, line of its `fn`, lines from there to its closing brace). A
/// function on one line counts 1.
pub fn fn_lengths(text: &str) -> Vec<(String, usize, usize)> {
    let code = code_only(text);
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some((indent, name)) = fn_start(line) else {
            continue;
        };
        let close = format!("{indent}}}");
        let end = if line.trim_end().ends_with('}') {
            Some(i)
        } else {
            lines[i + 1..]
                .iter()
                .position(|l| l.trim_end() == close)
                .map(|k| i + 1 + k)
        };
        if let Some(end) = end {
            out.push((name, i + 1, end - i + 1));
        }
    }
    out
}

/// The indentation and name of a line that opens a function (`fn`, after `pub`, `pub(crate)`,
/// `pub(in path)`, `const`, `async` or `unsafe`).
fn fn_start(line: &str) -> Option<(String, String)> {
    let body = line.trim_start();
    let indent = line[..line.len() - body.len()].to_string();
    // A restricted visibility may hold a space (`pub(in crate::sim)`): drop it whole.
    let body = match body.strip_prefix("pub(") {
        Some(rest) => rest.split_once(')').map_or(body, |(_, after)| after),
        None => body,
    };
    let mut words = body.split_whitespace().peekable();
    while let Some(w) = words.peek() {
        if *w == "pub" || ["const", "async", "unsafe"].contains(w) {
            words.next();
        } else {
            break;
        }
    }
    if words.next()? != "fn" {
        return None;
    }
    let name: String = words
        .next()?
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    (!name.is_empty()).then_some((indent, name))
}

#[test]
fn no_function_in_the_library_is_over_80_lines() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let long: Vec<String> = crate::module_graph::modules(&src)
        .values()
        .flat_map(|p| {
            let text = std::fs::read_to_string(p).expect("src is readable");
            fn_lengths(&text)
                .into_iter()
                .filter(|f| f.2 > MAX_LINES)
                .map(move |(name, line, n)| format!("{}:{line} {name} ({n} lines)", p.display()))
        })
        .collect();
    assert!(
        long.is_empty(),
        "split these into functions of one job each: {long:?}"
    );
}

#[test]
fn fn_lengths_counts_a_planted_long_function_and_skips_comments_and_strings() {
    let body = "    let x = 1;\n".repeat(79);
    let text = format!(
        "/// fn in_a_doc() {{\npub(crate) fn long() {{\n{body}}}\nconst S: &str = \"fn in_a_string() {{\";\nimpl T {{\n    pub fn short(&self) -> u8 {{ 1 }}\n    async fn two() {{\n    }}\n    pub(in crate::sim) fn three(\n        x: u8,\n    ) {{\n    }}\n}}\n"
    );
    let found = fn_lengths(&text);
    assert_eq!(
        found,
        vec![
            ("long".to_string(), 2, 81),
            ("short".to_string(), 85, 1),
            ("two".to_string(), 86, 2),
            ("three".to_string(), 88, 4),
        ]
    );
    assert!(
        found[0].2 > MAX_LINES,
        "the planted function is over the limit"
    );
}
