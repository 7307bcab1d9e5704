//! The words of verification in the prose as links to the glossary (`glossary.html`): the first
//! time a page's text says "on-shell", "Schwartz–Zippel", "automatic differentiation", "2⁶¹ − 1",
//! ... it links the entry that explains it. Headings, code and text inside a link are left
//! alone, like [`super::refs`]; the glossary does not link itself.

use pulldown_cmark::{CowStr, Event, LinkType, Tag, TagEnd};

/// (words as they appear in the prose, glossary entry).
pub const TERMS: &[(&str, &str)] = &[
    ("on-shell", "on-shell"),
    ("off the motion", "off-motion"),
    ("Schwartz–Zippel", "schwartz-zippel"),
    ("automatic differentiation", "ad"),
    ("running error bound", "residual"),
    ("2⁶¹ − 1", "modp"),
    ("three-particle", "three-particles"),
    ("coordinate force", "coordinate-force"),
    ("exact points", "exact"),
    ("chains", "forms"),
];

/// `events` with the first plain-text occurrence of each of [`TERMS`] linked to the glossary.
pub fn link_terms(events: Vec<Event<'_>>) -> Vec<Event<'_>> {
    let mut done = vec![false; TERMS.len()];
    let mut out = Vec::with_capacity(events.len());
    let mut shielded = 0usize;
    for ev in events {
        super::refs::track_shield(&ev, &mut shielded);
        let Event::Text(text) = &ev else {
            out.push(ev);
            continue;
        };
        // The first term not yet linked that this text holds, earliest first.
        let hit = TERMS
            .iter()
            .enumerate()
            .filter(|(k, _)| !done[*k])
            .filter_map(|(k, (w, id))| text.find(w).map(|i| (i, k, *w, *id)))
            .min_by_key(|h| h.0);
        let Some((i, k, w, id)) = hit.filter(|_| shielded == 0) else {
            out.push(ev);
            continue;
        };
        done[k] = true;
        let (before, after) = (&text[..i], &text[i + w.len()..]);
        if !before.is_empty() {
            out.push(Event::Text(CowStr::from(before.to_string())));
        }
        out.push(Event::Start(Tag::Link {
            link_type: LinkType::Inline,
            dest_url: CowStr::from(format!("{}#{id}", super::reader::GLOSSARY)),
            title: CowStr::from(""),
            id: CowStr::from(""),
        }));
        out.push(Event::Text(CowStr::from(w.to_string())));
        out.push(Event::End(TagEnd::Link));
        if !after.is_empty() {
            out.push(Event::Text(CowStr::from(after.to_string())));
        }
    }
    out
}
