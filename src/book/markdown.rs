//! One `equations/*.md` file as the body of a book page, with pulldown-cmark.
//!
//! pulldown-cmark (already the crate's markdown parser, for the doc-as-test harness) gives the
//! math as `DisplayMath`/`InlineMath` events (`Options::ENABLE_MATH`); each becomes MathML
//! ([`super::math`]). The first display after a heading `(N) …` is the numbered display of
//! equation N and gets its number and its panel of checks ([`super::panel`]); links are
//! rewritten from the repository's layout to the book's.

use super::math::mathml;
use pulldown_cmark::{html, CowStr, Event, Options, Parser, Tag, TagEnd};

/// Makes the numbered display of an equation: see [`Hooks::display`].
pub type DisplayHook<'a> = &'a dyn Fn(u32, &str) -> Option<Result<String, String>>;

/// What a page needs from the rest of the book.
pub struct Hooks<'a> {
    /// The numbered display of an equation (by the number of its heading, extensions 1000+k)
    /// with its panel, given the LaTeX of the markdown; `None` when the number is unknown.
    pub display: DisplayHook<'a>,
    /// The book's address for a link of the markdown (`dest`), given the inline code inside
    /// the link, if any (a function path); `None` when it cannot be resolved.
    pub link: &'a dyn Fn(&str, Option<&str>) -> Option<String>,
    /// The book's address of display N (extensions 1000+k), for references "(N)" in the prose
    /// ([`super::refs`]); `None` leaves the reference as text.
    pub equation: &'a dyn Fn(u32) -> Option<String>,
}

/// The number in a heading `(N) Title` or `(PN) Title` (extension: 1000 + N).
pub fn heading_number(text: &str) -> Option<u32> {
    let rest = text.trim_start().strip_prefix('(')?;
    let inner = rest[..rest.find(')')?].trim();
    match inner.strip_prefix('P') {
        Some(k) => k
            .parse::<u32>()
            .ok()
            .map(|k| crate::registry::EXTENSION_BASE + k),
        None => inner.parse().ok(),
    }
}

fn anchor_of(n: u32) -> String {
    match n.checked_sub(crate::registry::EXTENSION_BASE) {
        Some(k) if k > 0 => format!("eq-P{k}"),
        _ => format!("eq-{n}"),
    }
}

/// Text of the heading that starts at `events[i]` and the inline code of a link there.
fn text_until<'e>(
    events: &[Event<'e>],
    i: usize,
    end: fn(&Event) -> bool,
) -> (String, Option<String>) {
    let (mut text, mut code) = (String::new(), None);
    for ev in &events[i + 1..] {
        if end(ev) {
            break;
        }
        match ev {
            Event::Text(t) => text.push_str(t),
            Event::Code(c) => {
                text.push_str(c);
                code.get_or_insert_with(|| c.to_string());
            }
            _ => {}
        }
    }
    (text, code)
}

/// Render `src` (the file `name`) to HTML; returns the HTML and every problem found.
pub fn render(name: &str, src: &str, hooks: &Hooks) -> (String, Vec<String>) {
    let opts = Options::ENABLE_MATH
        | Options::ENABLE_TABLES
        | Options::ENABLE_STRIKETHROUGH
        | Options::ENABLE_HEADING_ATTRIBUTES;
    let events: Vec<Event> = Parser::new_ext(src, opts).collect();
    let mut problems = Vec::new();
    let mut out: Vec<Event> = Vec::with_capacity(events.len());
    let mut pending: Option<u32> = None;
    let bare = display_only_paragraphs(&events);
    for (i, ev) in events.iter().enumerate() {
        if bare.contains(&i) {
            continue;
        }
        let ev = ev.clone();
        match ev {
            Event::Start(Tag::Heading {
                level,
                id,
                classes,
                attrs,
            }) => {
                let (text, _) =
                    text_until(&events, i, |e| matches!(e, Event::End(TagEnd::Heading(_))));
                let number = heading_number(&text);
                pending = number;
                let id = number.map(|n| CowStr::from(anchor_of(n))).or(id);
                out.push(Event::Start(Tag::Heading {
                    level,
                    id,
                    classes,
                    attrs,
                }));
            }
            Event::DisplayMath(latex) => {
                let html = display_html(name, &latex, pending.take(), hooks, &mut problems);
                out.push(Event::Html(format!("{html}\n").into()));
            }
            Event::InlineMath(latex) => match mathml(&latex, false) {
                Ok(m) => out.push(Event::InlineHtml(m.into())),
                Err(e) => {
                    problems.push(format!("{name}: {e}"));
                    out.push(Event::Text("[formula did not typeset]".into()));
                }
            },
            Event::Start(Tag::Link {
                link_type,
                dest_url,
                title,
                id,
            }) => {
                let (_, code) = text_until(&events, i, |e| matches!(e, Event::End(TagEnd::Link)));
                let dest = book_address(name, dest_url, code.as_deref(), hooks, &mut problems);
                out.push(Event::Start(Tag::Link {
                    link_type,
                    dest_url: dest,
                    title,
                    id,
                }));
            }
            Event::Html(h) | Event::InlineHtml(h) => {
                // A comment is a marker for the doc harness (`<!-- worked-example N -->`,
                // [`crate::docs`]): not for the reader. Any other raw HTML is shown, not obeyed.
                if !is_comment(&h) {
                    out.push(Event::Text(h));
                }
            }
            other => out.push(other),
        }
    }
    (linked_html(name, out, hooks), problems)
}

/// The page's events with references "(N)" and the glossary's terms linked, as HTML.
fn linked_html(name: &str, out: Vec<Event>, hooks: &Hooks) -> String {
    let out = super::refs::link_references(out, hooks.equation);
    // The glossary explains these words; it does not link to itself.
    let out = if name.ends_with("glossary.md") {
        out
    } else {
        super::terms::link_terms(out)
    };
    let mut html_out = String::new();
    html::push_html(&mut html_out, out.into_iter());
    html_out
}

/// The HTML of a display: with `number` (a heading `(N)` precedes it) the numbered display and
/// its panel from `hooks.display`, else the display alone in MathML. A display that cannot be
/// typeset is a problem, shown as such on the page.
fn display_html(
    name: &str,
    latex: &str,
    number: Option<u32>,
    hooks: &Hooks,
    problems: &mut Vec<String>,
) -> String {
    match number {
        Some(n) => match (hooks.display)(n, latex) {
            Some(Ok(h)) => h,
            Some(Err(e)) => {
                problems.push(format!("{name}: {e}"));
                "<p class=\"math-error\">[this display did not typeset]</p>".into()
            }
            None => {
                problems.push(format!(
                    "{name}: no verification result for {}",
                    anchor_of(n)
                ));
                "<p class=\"math-error\">[no result for this display]</p>".into()
            }
        },
        None => match mathml(latex, true) {
            Ok(m) => {
                format!("<div class=\"display\"><div class=\"formula\">{m}</div></div>")
            }
            Err(e) => {
                problems.push(format!("{name}: {e}"));
                "<p class=\"math-error\">[this display did not typeset]</p>".into()
            }
        },
    }
}

/// The book's address of the link `dest_url` (with `code`, the inline code inside it); one that
/// does not resolve is kept as written and is a problem.
fn book_address<'a>(
    name: &str,
    dest_url: CowStr<'a>,
    code: Option<&str>,
    hooks: &Hooks,
    problems: &mut Vec<String>,
) -> CowStr<'a> {
    match (hooks.link)(&dest_url, code) {
        Some(d) => CowStr::from(d),
        None => {
            problems.push(format!("{name}: the link to {dest_url} does not resolve"));
            dest_url
        }
    }
}

/// The indices of the `<p>` and `</p>` of each paragraph that holds nothing but display math:
/// a display is a block (`<div>`), which HTML does not allow inside `<p>` (a browser would close
/// the paragraph before it and leave an empty one after).
fn display_only_paragraphs(events: &[Event]) -> Vec<usize> {
    let blank = |e: &Event| match e {
        Event::SoftBreak | Event::HardBreak => true,
        Event::Text(t) => t.trim().is_empty(),
        _ => false,
    };
    let mut out = Vec::new();
    for (i, e) in events.iter().enumerate() {
        if !matches!(e, Event::Start(Tag::Paragraph)) {
            continue;
        }
        let Some(len) = events[i + 1..]
            .iter()
            .position(|e| matches!(e, Event::End(TagEnd::Paragraph)))
        else {
            continue;
        };
        let inner = &events[i + 1..i + 1 + len];
        let displays = inner
            .iter()
            .filter(|e| matches!(e, Event::DisplayMath(_)))
            .count();
        if displays > 0
            && inner
                .iter()
                .all(|e| blank(e) || matches!(e, Event::DisplayMath(_)))
        {
            out.extend([i, i + 1 + len]);
        }
    }
    out
}

/// True when `html` is one whole HTML comment (`<!-- … -->`, surrounding blanks allowed).
pub fn is_comment(html: &str) -> bool {
    let t = html.trim();
    t.starts_with("<!--") && t.ends_with("-->") && !t[4..t.len() - 3].contains("-->")
}

/// The links of a markdown table section (e.g. the contents of `README.md`), in order.
pub fn links_in(src: &str) -> Vec<String> {
    Parser::new_ext(src, Options::ENABLE_TABLES)
        .filter_map(|e| match e {
            Event::Start(Tag::Link { dest_url, .. }) => Some(dest_url.to_string()),
            _ => None,
        })
        .collect()
}

/// A short label for the navigation: the first heading's text, up to the em dash.
pub fn title_of(src: &str) -> String {
    let line = src
        .lines()
        .find(|l| l.starts_with("# "))
        .unwrap_or("# Untitled");
    line.trim_start_matches("# ").trim().to_string()
}
