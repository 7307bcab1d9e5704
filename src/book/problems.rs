//! The problems page (`equations/problems.md` → `problems.html`): each exercise's answer is a
//! numbered display checked like the note's own, and its worked solution, written under a
//! `#### Solution` heading in the markdown, is folded here into a `<details>` (no script) so a
//! student can try first. The harness's declarations of the answers' points and symbols
//! (`*Points:*`, `*Symbols:*`: quantity ids and dimensions, for the checks) are folded too, under
//! a plain list of what each symbol means ([`fold_declarations`]).

/// The heading that starts a worked solution, as the markdown renderer writes it.
pub const SOLUTION: &str = "<h4>Solution</h4>";

/// Fold every worked solution of the rendered page: from its heading to the next heading of
/// level 1-3 (the next problem) or the end of the page.
pub fn fold_solutions(html: &str) -> String {
    let mut out = String::with_capacity(html.len() + 256);
    let mut rest = html;
    while let Some(i) = rest.find(SOLUTION) {
        out.push_str(&rest[..i]);
        let after = &rest[i + SOLUTION.len()..];
        let end = ["<h1", "<h2", "<h3"]
            .iter()
            .filter_map(|h| after.find(h))
            .min()
            .unwrap_or(after.len());
        out.push_str("<details class=\"solution\"><summary>Worked solution</summary>");
        out.push_str(&after[..end]);
        out.push_str("</details>\n");
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// Where the rendered `*Points:*` paragraph and `*Symbols:*` list begin.
const POINTS: &str = "<p><em>Points:</em>";
const SYMBOLS: &str = "<p><em>Symbols:</em></p>";

/// Fold the harness's declarations (`*Points:*` and the `*Symbols:*` list that follows it) into
/// a `<details>`, and put before it, for a student, each symbol with its meaning alone (the list
/// item's math and the words after its `[dimension]: `).
pub fn fold_declarations(html: &str) -> String {
    let (Some(start), Some(sym)) = (html.find(POINTS), html.find(SYMBOLS)) else {
        return html.to_string();
    };
    let Some(end) = html[sym..].find("</ul>").map(|k| sym + k + "</ul>".len()) else {
        return html.to_string();
    };
    let items: Vec<String> = html[sym..end]
        .split("<li>")
        .skip(1)
        .filter_map(|li| {
            let li = li.split("</li>").next()?;
            let (math, rest) = li.split_once(" = <code>")?;
            let meaning = rest.split_once("]: ").map(|(_, m)| m)?;
            Some(format!("<li>{math}: {meaning}</li>"))
        })
        .collect();
    format!(
        "{}<p>The symbols of the answers:</p>\n<ul>\n{}\n</ul>\n<details class=\"harness\">\
         <summary>How the checks read these symbols</summary>\n{}</details>{}",
        &html[..start],
        items.join("\n"),
        &html[start..end],
        &html[end..]
    )
}
