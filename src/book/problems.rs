//! The problems page (`equations/problems.md` → `problems.html`): each exercise's answer is a
//! numbered display checked like the note's own, and its worked solution, written under a
//! `#### Solution` heading in the markdown, is folded here into a `<details>` (no script) so a
//! student can try first.

/// The heading that starts a worked solution, as the markdown renderer writes it.
const SOLUTION: &str = "<h4>Solution</h4>";

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_solution_is_folded_up_to_the_next_problem() {
        let html =
            "<h2>P 1</h2><p>q</p><h4>Solution</h4><p>a</p><h2>P 2</h2><h4>Solution</h4><p>b</p>";
        let f = fold_solutions(html);
        assert_eq!(f.matches("<details class=\"solution\">").count(), 2);
        assert!(f.contains("<summary>Worked solution</summary><p>a</p></details>\n<h2>P 2</h2>"));
        assert!(f.ends_with("<p>b</p></details>\n"));
        assert!(!f.contains(SOLUTION));
    }
}
