//! The page frame (head, navigation, footer), HTML escaping and the one stylesheet.
//!
//! Pages are polyglot XHTML (every element closed, attributes quoted) so that a plain XML
//! parser can read them back in the tests; MathML is embedded inline, which every current
//! browser draws natively (MathML Core), so the book needs no script and no network.

/// Escape text for HTML content and attribute values.
pub fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// One entry of the navigation bar: (file name, short label).
pub type NavItem = (String, String);

/// A whole page: `depth` is how many directories below the book root the page lives (for the
/// relative path to the stylesheet and the navigation).
pub fn page(title: &str, depth: usize, nav: &[NavItem], current: &str, body: &str) -> String {
    let up = "../".repeat(depth);
    let mut links = String::new();
    for (file, label) in nav {
        let here = if file == current {
            " aria-current=\"page\""
        } else {
            ""
        };
        links.push_str(&format!(
            "<li><a href=\"{up}{}\"{here}>{}</a></li>",
            esc(file),
            esc(label)
        ));
    }
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\" xmlns=\"http://www.w3.org/1999/xhtml\">\n<head>\n\
<meta charset=\"utf-8\" />\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\" />\n\
<title>{} · Torque Analyses of a Sliding Ladder, verified</title>\n\
<link rel=\"stylesheet\" href=\"{up}style.css\" />\n</head>\n<body>\n\
<header><nav aria-label=\"Sections\"><ul>{links}</ul></nav></header>\n<main>\n{body}\n</main>\n\
<footer><p>Written by <code>ladder book</code> from <code>equations/*.md</code> and the checks of \
<code>ladder verify</code> run at build time. Static, no script, works offline.</p></footer>\n\
</body>\n</html>\n",
        esc(title)
    )
}

/// The stylesheet: readable on a phone, printable (no navigation, no backgrounds, displays kept
/// whole). Each display has the column's full width, its number beside it and its checks folded
/// below; an aligned display (`aligned`, which pulldown-latex writes as an `mtable` of class
/// `menv-alignlike`) has its columns right- and left-aligned in turn, so every line meets at its
/// "=" (MathML Core centres table cells by default). The math font is named, so widths are the
/// same wherever the fonts are installed (Debian: fonts-dejavu-extra).
pub const STYLE: &str = r#"
:root { --ink: #1b1b1b; --muted: #555; --rule: #d0d0d0; --ok: #1a7f37; --bad: #b42318;
  --def: #4a5d8a; --err: #9a6700; --bg-aside: #f6f7f9; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); font: 17px/1.55 Georgia, "Times New Roman", serif; }
header { border-bottom: 1px solid var(--rule); background: #fafafa; }
nav ul { list-style: none; margin: 0 auto; padding: .4em 1em; max-width: 60em;
  display: flex; flex-wrap: wrap; gap: .2em 1em; font: 14px/1.4 system-ui, sans-serif; }
nav a[aria-current] { font-weight: bold; text-decoration: none; color: var(--ink); }
main { max-width: 60em; margin: 0 auto; padding: 1em; }
footer { max-width: 60em; margin: 2em auto; padding: 0 1em; color: var(--muted); font-size: 14px; }
h1 { font-size: 1.6em; line-height: 1.25; }
h2 { font-size: 1.3em; margin-top: 1.6em; }
h3 { font-size: 1.1em; margin-top: 1.8em; border-top: 1px solid var(--rule); padding-top: .8em; }
code { font-size: .9em; }
pre { overflow-x: auto; background: #f4f4f4; padding: .6em; }
table { border-collapse: collapse; font: 14px/1.4 system-ui, sans-serif; display: block; overflow-x: auto; }
th, td { border: 1px solid var(--rule); padding: .25em .5em; text-align: left; vertical-align: top; }
img { max-width: 100%; height: auto; }
figure { margin: 1.2em 0; }
figcaption { color: var(--muted); font-size: .95em; }
math { font-size: 1.1em;
  font-family: "DejaVu Math TeX Gyre", "Latin Modern Math", "STIX Two Math", math; }
.eq { margin: .8em 0 1.2em; }
.display { display: flex; align-items: center; gap: 1em; }
.formula { flex: 1 1 auto; min-width: 0; overflow-x: auto; }
.eqno { flex: none; white-space: nowrap; }
mtd { padding: 0; }
mtable.menv-alignlike > mtr > mtd:nth-child(odd) { text-align: right; text-align: -webkit-right; }
mtable.menv-alignlike > mtr > mtd:nth-child(even) { text-align: left; text-align: -webkit-left; }
mtable.menv-align > mtr > mtd:nth-child(2n + 3) { padding-left: 1em; }
.checks { background: var(--bg-aside); border-left: 3px solid var(--rule); margin-top: .3em;
  padding: .2em .8em; font: 13px/1.45 system-ui, sans-serif; }
.checks summary { cursor: pointer; color: var(--muted); }
.checks dl { margin: .3em 0; display: grid; grid-template-columns: max-content 1fr; gap: .15em .6em; }
.checks dt { color: var(--muted); }
.checks dd { margin: 0; overflow-wrap: anywhere; }
.badge { display: inline-block; padding: 0 .5em; border-radius: .6em; color: #fff;
  font: bold 12px/1.6 system-ui, sans-serif; }
.badge.verified, .badge.proved { background: var(--ok); }
.badge.definition { background: var(--def); }
.badge.erratum { background: var(--err); }
.badge.failed { background: var(--bad); }
section.erratum dt { color: var(--muted); font: 14px/1.4 system-ui, sans-serif; margin-top: .5em; }
section.erratum dd { margin: 0 0 0 1em; }
section.erratum math[display="block"] { text-align: left; }
.erratum-forms { border-left: 3px solid var(--err); padding-left: .6em; }
details.solution { border-left: 3px solid var(--def); padding: .2em .8em; margin: .5em 0 1.5em; }
details.solution summary { cursor: pointer; color: var(--def); font: 14px/1.6 system-ui, sans-serif; }
table.derivations td, table.derivations th { width: 14%; }
.source .line { display: block; white-space: pre; }
.source .ln { display: inline-block; width: 4em; color: #999; text-decoration: none; user-select: none; }
.source .line:target { background: #fff3b0; }
@media (max-width: 48em) { body { font-size: 16px; } }
@media print { header, footer { display: none; } main { max-width: none; } .eq, figure, tr { break-inside: avoid; }
  a { color: inherit; text-decoration: none; } .checks { background: none; } }
"#;
