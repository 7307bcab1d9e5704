//! Reading one source file: comments, strings and character literals blanked, a token scan,
//! `use` trees unfolded, and every path to this crate resolved to a path from the crate root.

use super::Module;
use std::collections::BTreeSet;

/// The character at `k`, or NUL past the end.
pub fn at(c: &[char], k: usize) -> char {
    c.get(k).copied().unwrap_or('\0')
}

/// The text with comments, strings and character literals blanked (newlines kept, so line
/// numbers stay right).
pub fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |out: &mut String, ch: char| out.push(if ch == '\n' { '\n' } else { ' ' });
    let mut i = 0;
    while i < c.len() {
        if c[i] == '/' && at(&c, i + 1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && at(&c, i + 1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && at(&c, i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(&c, i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
        } else if c[i] == 'r' && raw_start(&c, i) {
            let mut hashes = 0;
            i += 1;
            while at(&c, i) == '#' {
                hashes += 1;
                i += 1;
            }
            i += 1; // the opening quote
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|k| at(&c, i + k) == '#') {
                    i += 1 + hashes;
                    break;
                }
                blank(&mut out, c[i]);
                i += 1;
            }
            out.push(' ');
        } else if c[i] == '"' {
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    blank(&mut out, c[i]);
                    i += 1;
                }
                if i < c.len() {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
            i += 1;
            out.push(' ');
        } else if c[i] == '\'' && (at(&c, i + 1) == '\\' || at(&c, i + 2) == '\'') {
            // a character literal (a lifetime has no closing quote); skip an escaped character
            i += if at(&c, i + 1) == '\\' { 3 } else { 2 };
            while i < c.len() && c[i] != '\'' {
                i += 1;
            }
            i += 1;
            out.push(' ');
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// Whether `c[i]` (an `r`) opens a raw string `r"..."`, `r#"..."#` or `br"..."`, not a raw
/// identifier `r#type` or the end of a name.
pub fn raw_start(c: &[char], i: usize) -> bool {
    let at = |k: usize| at(c, k);
    let name = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut k = i + 1;
    while at(k) == '#' {
        k += 1;
    }
    let starts = i == 0 || !name(at(i - 1)) || (at(i - 1) == 'b' && (i < 2 || !name(at(i - 2))));
    starts && at(k) == '"'
}

#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Ident(String),
    Path, // ::
    Open,
    Close,
    Comma,
    Semi,
    Other,
}

pub fn tokens(code: &str) -> Vec<(Tok, usize)> {
    let c: Vec<char> = code.chars().collect();
    let mut v = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch.is_alphanumeric() || ch == '_' {
            let s = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            v.push((Tok::Ident(c[s..i].iter().collect()), line));
        } else if ch == ':' && c.get(i + 1) == Some(&':') {
            v.push((Tok::Path, line));
            i += 2;
        } else {
            v.push((
                match ch {
                    '{' => Tok::Open,
                    '}' => Tok::Close,
                    ',' => Tok::Comma,
                    ';' => Tok::Semi,
                    _ => Tok::Other,
                },
                line,
            ));
            i += 1;
        }
    }
    v
}

pub fn ident(t: Option<&(Tok, usize)>) -> Option<&str> {
    match t {
        Some((Tok::Ident(s), _)) => Some(s),
        _ => None,
    }
}

/// One path of a `use` tree: its segments and the name it binds (`None` for a glob).
pub type UsePath = (Vec<String>, Option<String>);

/// The paths of a `use` tree starting at token `i` (after `use`).
pub fn use_tree(t: &[(Tok, usize)], i: &mut usize, prefix: &[String], out: &mut Vec<UsePath>) {
    let mut path = prefix.to_vec();
    loop {
        match t.get(*i).map(|x| &x.0) {
            Some(Tok::Ident(s)) if s == "as" => {
                let alias = ident(t.get(*i + 1)).map(str::to_string);
                *i += 2;
                out.push((path, alias));
                return;
            }
            Some(Tok::Ident(s)) => {
                if s != "self" || path.is_empty() {
                    path.push(s.clone());
                }
                *i += 1;
            }
            Some(Tok::Path) => *i += 1,
            Some(Tok::Open) => {
                *i += 1;
                loop {
                    match t.get(*i).map(|x| &x.0) {
                        Some(Tok::Close) => {
                            *i += 1;
                            return;
                        }
                        Some(Tok::Comma) => *i += 1,
                        None => return,
                        _ => use_tree(t, i, &path, out),
                    }
                }
            }
            Some(Tok::Other) => {
                *i += 1; // the glob `*`
                out.push((path, None));
                return;
            }
            _ => {
                let bound = path.last().cloned();
                out.push((path, bound));
                return;
            }
        }
    }
}

/// `segments` written in module `here` (inline modules included) as a path from the crate
/// root, or `None` when it leaves the crate.
pub fn absolute(
    segments: &[String],
    here: &[String],
    known: &BTreeSet<Module>,
    is_main: bool,
) -> Option<Vec<String>> {
    let first = segments.first()?;
    let mut m: Vec<String>;
    let mut rest = &segments[1..];
    match first.as_str() {
        "crate" => m = Vec::new(),
        "sliding_ladder" if is_main => m = Vec::new(),
        "self" => m = here.to_vec(),
        "super" => {
            m = here.to_vec();
            m.pop()?;
            while rest.first().is_some_and(|s| s == "super") {
                m.pop()?;
                rest = &rest[1..];
            }
        }
        _ => {
            // a child module of `here`, named without `self::`
            m = here.to_vec();
            m.push(first.clone());
            if is_main || !known.iter().any(|k| k.starts_with(&m)) {
                return None;
            }
        }
    }
    m.extend(rest.iter().cloned());
    Some(m)
}

/// One path to this crate named in a file.
pub struct Import {
    /// From the crate root.
    pub path: Vec<String>,
    /// Line in the file.
    pub line: usize,
    /// As written.
    pub text: String,
    /// The name a top-level `use` binds in the file's module.
    pub binds: Option<String>,
}

/// The paths to this crate a file names: `use` trees and paths in code.
pub fn imports(
    file_module: &Module,
    text: &str,
    known: &BTreeSet<Module>,
    is_main: bool,
) -> Vec<Import> {
    let t = tokens(&code_only(text));
    let mut out = Vec::new();
    // inline modules (`mod tests { ... }`): their name and the brace depth they opened at
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < t.len() {
        let here: Module = file_module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(n, _)| n.clone()))
            .collect();
        let line = t[i].1;
        let mut push = |p: &[String], binds: Option<String>| {
            if let Some(path) = absolute(p, &here, known, is_main) {
                out.push(Import {
                    path,
                    line,
                    text: p.join("::"),
                    binds,
                });
            }
        };
        match &t[i].0 {
            Tok::Open => depth += 1,
            Tok::Close => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
            }
            Tok::Ident(s) if s == "mod" => {
                if let (Some(n), Some((Tok::Open, _))) = (ident(t.get(i + 1)), t.get(i + 2)) {
                    inline.push((n.to_string(), depth));
                    depth += 1;
                    i += 3;
                    continue;
                }
            }
            Tok::Ident(s) if s == "use" => {
                let mut paths = Vec::new();
                let mut j = i + 1;
                if t.get(j).map(|x| &x.0) == Some(&Tok::Path) {
                    j += 1; // `use ::std::...`
                }
                use_tree(&t, &mut j, &[], &mut paths);
                for (p, bound) in paths {
                    push(&p, bound.filter(|_| depth == 0));
                }
                i = j;
                continue;
            }
            Tok::Ident(s)
                if (s == "crate"
                    || s == "super"
                    || s == "self"
                    || (is_main && s == "sliding_ladder"))
                    && t.get(i + 1).map(|x| &x.0) == Some(&Tok::Path)
                    && (i == 0 || t[i - 1].0 != Tok::Path) =>
            {
                let mut p = vec![s.clone()];
                let mut j = i + 1;
                while t.get(j).map(|x| &x.0) == Some(&Tok::Path) {
                    match ident(t.get(j + 1)) {
                        Some(n) => p.push(n.to_string()),
                        None => break,
                    }
                    j += 2;
                }
                push(&p, None);
                i = j;
                continue;
            }
            // a child module named in code: `child::f()` in a `mod.rs`
            Tok::Ident(s)
                if !is_main
                    && t.get(i + 1).map(|x| &x.0) == Some(&Tok::Path)
                    && (i == 0 || t[i - 1].0 != Tok::Path) =>
            {
                let mut child = here.clone();
                child.push(s.clone());
                if known.contains(&child) {
                    push(std::slice::from_ref(s), None);
                }
            }
            _ => {}
        }
        i += 1;
    }
    out
}
