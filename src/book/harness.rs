//! The harness's own fields in a chapter, folded for readers. A display's `*Rust:*` list (the
//! check functions that encode it, with their kind and reference, read by
//! `registry::source`) is data for the checks, and the `*Kind:*` line written just before it
//! (kind, code, how it is checked) repeats what the display's panel shows. On the page both sit
//! in one closed `<details>` under the display, so a student reads the physics first and a
//! developer can still open it.

/// The rendered start of a `*Rust:*` field.
const RUST: &str = "<p><em>Rust:</em></p>";

/// The rendered start of a `*Kind:*` line.
const KIND: &str = "<p><em>Kind:</em>";

/// The summary of the fold.
pub const SUMMARY: &str = "<summary>Kind, code and the checks that encode it</summary>";

/// Take out of `out` the `*Kind:*` paragraph of the current display: the last one after the
/// last heading.
fn take_kind_line(out: &mut String) -> Option<String> {
    let section = out.rfind("<h").unwrap_or(0);
    let start = section + out[section..].rfind(KIND)?;
    let end = start + out[start..].find("</p>")? + "</p>".len();
    let kind = out[start..end].to_string();
    let line_end = end + usize::from(out[end..].starts_with('\n'));
    out.replace_range(start..line_end, "");
    Some(kind)
}

/// Fold a `*Kind:*` paragraph that no `*Rust:*` list took along (a display without one).
fn fold_lone_kind_lines(html: &str) -> String {
    let mut out = String::with_capacity(html.len() + 256);
    let mut rest = html;
    while let Some(i) = rest.find(KIND) {
        let Some(len) = rest[i..].find("</p>").map(|k| k + "</p>".len()) else {
            break;
        };
        out.push_str(&rest[..i]);
        if out.ends_with(&format!("{SUMMARY}\n")) {
            out.push_str(&rest[i..i + len]);
        } else {
            out.push_str("<details class=\"harness\">");
            out.push_str(SUMMARY);
            out.push('\n');
            out.push_str(&rest[i..i + len]);
            out.push_str("</details>");
        }
        rest = &rest[i + len..];
    }
    out.push_str(rest);
    out
}

/// Fold every `*Rust:*` paragraph and the list right after it, with the display's `*Kind:*`
/// line, into a closed `<details>`, and every other `*Kind:*` line into one of its own. A
/// `*Rust:*` paragraph without a list after it is left as it is.
pub fn fold_rust_lists(html: &str) -> String {
    let mut out = String::with_capacity(html.len() + 256);
    let mut rest = html;
    while let Some(i) = rest.find(RUST) {
        out.push_str(&rest[..i]);
        let after = &rest[i + RUST.len()..];
        let list = after.trim_start();
        let end = list
            .starts_with("<ul>")
            .then(|| list.find("</ul>"))
            .flatten();
        match end {
            Some(e) => {
                let e = e + "</ul>".len();
                let kind = take_kind_line(&mut out);
                out.push_str("<details class=\"harness checks\">");
                out.push_str(SUMMARY);
                out.push('\n');
                if let Some(k) = kind {
                    out.push_str(&k);
                    out.push('\n');
                }
                out.push_str(&list[..e]);
                out.push_str("</details>");
                rest = &list[e..];
            }
            None => {
                out.push_str(RUST);
                rest = after;
            }
        }
    }
    out.push_str(rest);
    fold_lone_kind_lines(&out)
}
