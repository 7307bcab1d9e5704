//! The harness's own fields in a chapter, folded for readers. A display's `*Rust:*` list (the
//! check functions that encode it, with their kind and reference, read by
//! `registry::source`) is data for the checks; on the page it sits in a `<details>` under the
//! display's panel, so a student reads the physics first and a developer can still open it.

/// The rendered start of a `*Rust:*` field.
const RUST: &str = "<p><em>Rust:</em></p>";

/// Fold every `*Rust:*` paragraph and the list right after it into a closed `<details>`.
/// A `*Rust:*` paragraph without a list after it is left as it is.
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
                out.push_str(
                    "<details class=\"harness\"><summary>The checks that encode it, in Rust</summary>\n",
                );
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
    out
}
