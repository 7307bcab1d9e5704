//! Equation references in the prose as links: "(40)" in a page's text becomes a link to display
//! (40) wherever it lives in the book, "(P3)" to the extension's display (P3). Headings, code,
//! and text already inside a link are left alone, and so is anything that is not exactly a
//! number in parentheses ("(2/3)", "(1 − m)").

use pulldown_cmark::{CowStr, Event, LinkType, Tag, TagEnd};

/// The number of a reference `(N)` or `(PN)` (extension: 1000 + N) starting at `s`, and its
/// length in bytes.
fn reference(s: &str) -> Option<(u32, usize)> {
    let inner = s.strip_prefix('(')?;
    let close = inner.find(')')?;
    let body = &inner[..close];
    let (digits, base) = match body.strip_prefix('P') {
        Some(d) => (d, crate::registry::EXTENSION_BASE),
        None => (body, 0),
    };
    if digits.is_empty() || digits.len() > 3 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((base + digits.parse::<u32>().ok()?, close + 2))
}

/// Keep `depth` as the nesting inside headings, links and code blocks, where text stays text
/// (no link is made there: a heading's own number, a link's words, code).
pub fn track_shield(ev: &Event<'_>, depth: &mut usize) {
    match ev {
        Event::Start(Tag::Heading { .. } | Tag::Link { .. } | Tag::CodeBlock(_)) => *depth += 1,
        Event::End(TagEnd::Heading(_) | TagEnd::Link | TagEnd::CodeBlock) => {
            *depth = depth.saturating_sub(1)
        }
        _ => {}
    }
}

/// `events` with every reference in plain text turned into a link to `target(N)`, when known.
pub fn link_references<'a>(
    events: Vec<Event<'a>>,
    target: &dyn Fn(u32) -> Option<String>,
) -> Vec<Event<'a>> {
    let mut out = Vec::with_capacity(events.len());
    let mut shielded = 0usize;
    for ev in events {
        track_shield(&ev, &mut shielded);
        let Event::Text(text) = &ev else {
            out.push(ev);
            continue;
        };
        if shielded > 0 || !text.contains('(') {
            out.push(ev);
            continue;
        }
        let (mut rest, mut plain) = (text.as_ref(), String::new());
        while let Some(i) = rest.find('(') {
            plain.push_str(&rest[..i]);
            rest = &rest[i..];
            match reference(rest).and_then(|(n, len)| target(n).map(|t| (t, len))) {
                Some((dest, len)) => {
                    if !plain.is_empty() {
                        out.push(Event::Text(CowStr::from(std::mem::take(&mut plain))));
                    }
                    out.push(Event::Start(Tag::Link {
                        link_type: LinkType::Inline,
                        dest_url: CowStr::from(dest),
                        title: CowStr::from(""),
                        id: CowStr::from(""),
                    }));
                    out.push(Event::Text(CowStr::from(rest[..len].to_string())));
                    out.push(Event::End(TagEnd::Link));
                    rest = &rest[len..];
                }
                None => {
                    plain.push('(');
                    rest = &rest[1..];
                }
            }
        }
        plain.push_str(rest);
        if !plain.is_empty() {
            out.push(Event::Text(CowStr::from(plain)));
        }
    }
    out
}
