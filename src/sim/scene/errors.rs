//! Scene errors: one line `file:line: [section] key: what is wrong; what is allowed`, and the
//! context ([`Ctx`]) that turns a byte span of the scene text into that line.

use std::fmt;
use toml::Spanned;

/// A bad scene: one line for the user.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    /// The scene file as given.
    pub file: String,
    /// 1-based line, where the problem has one.
    pub line: Option<usize>,
    /// The field, as `section.key` (shown as `[section] key`), a section name (`[section]`), a
    /// key outside any section, or empty for the file as a whole.
    pub field: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

/// The sections of a scene, in order.
pub const SECTIONS: [&str; 6] = ["ladder", "start", "contact", "integrator", "end", "outputs"];

impl SceneError {
    /// The field as the user sees it: `[section] key`, `[section]`, or a bare top-level key.
    pub fn place(&self) -> String {
        match self.field.split_once('.') {
            Some((section, key)) => format!("[{section}] {key}"),
            None if SECTIONS.contains(&self.field.as_str()) => format!("[{}]", self.field),
            None => self.field.clone(),
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(l) = self.line {
            write!(f, ":{l}")?;
        }
        let place = self.place();
        if place.is_empty() {
            write!(f, ": {}", self.message)
        } else {
            write!(f, ": {place}: {}", self.message)
        }
    }
}

/// A duration in seconds, the span of its value and the key that gave it.
pub(in crate::sim) type TimeLike<'k> = (f64, std::ops::Range<usize>, &'k str);

/// The scene file being read (its name and text), to place a problem at its line.
pub struct Ctx<'a> {
    /// The file's name, as the problems name it.
    pub file: &'a str,
    /// The file's text.
    pub text: &'a str,
}

impl Ctx<'_> {
    pub(in crate::sim) fn line_of(&self, pos: usize) -> usize {
        self.text[..pos.min(self.text.len())]
            .bytes()
            .filter(|&b| b == b'\n')
            .count()
            + 1
    }
    pub(in crate::sim) fn err(
        &self,
        span: Option<std::ops::Range<usize>>,
        field: &str,
        message: impl Into<String>,
    ) -> SceneError {
        SceneError {
            file: self.file.to_string(),
            line: span.map(|s| self.line_of(s.start)),
            field: field.to_string(),
            message: message.into().replace('\n', " "),
        }
    }
    /// An error on line `line` (1-based).
    pub(in crate::sim) fn err_at_line(
        &self,
        line: usize,
        field: &str,
        message: impl Into<String>,
    ) -> SceneError {
        SceneError {
            line: Some(line),
            ..self.err(None, field, message)
        }
    }
    /// A finite number in the range `ok`, described by `allowed`.
    pub(in crate::sim) fn number(
        &self,
        v: &Spanned<f64>,
        field: &str,
        ok: impl Fn(f64) -> bool,
        allowed: &str,
    ) -> Result<f64, SceneError> {
        let x = *v.get_ref();
        let x_text = if x != 0.0 && (x.abs() < 1e-4 || x.abs() >= 1e6) {
            format!("{x:e}")
        } else {
            format!("{x}")
        };
        if !x.is_finite() {
            return Err(self.err(
                Some(v.span()),
                field,
                format!("{x} is not a finite number; allowed: {allowed}"),
            ));
        }
        if !ok(x) {
            return Err(self.err(
                Some(v.span()),
                field,
                format!("{x_text} is out of range; allowed: {allowed}"),
            ));
        }
        Ok(x)
    }
    /// A duration given either in seconds (`keys.0`) or in units of √(l/g) = `unit` s
    /// (`keys.1`), at most one of them; `ok` judges it in units of √(l/g). Returns it in
    /// seconds with the span of the key that gave it.
    pub(in crate::sim) fn time_like<'k>(
        &self,
        seconds: Option<&Spanned<f64>>,
        scaled: Option<&Spanned<f64>>,
        keys: (&'k str, &'k str),
        unit: f64,
        ok: impl Fn(f64) -> bool,
        allowed: &str,
    ) -> Result<Option<TimeLike<'k>>, SceneError> {
        match (seconds, scaled) {
            (Some(_), Some(b)) => Err(self.err(
                Some(b.span()),
                keys.1,
                format!(
                    "given together with {}; allowed: one of {} (s) or {} (units of √(l/g))",
                    keys.0.split_once('.').map_or(keys.0, |k| k.1),
                    keys.0.split_once('.').map_or(keys.0, |k| k.1),
                    keys.1.split_once('.').map_or(keys.1, |k| k.1)
                ),
            )),
            (Some(v), None) => {
                let x = self.number(v, keys.0, |x| ok(x / unit), allowed)?;
                Ok(Some((x, v.span(), keys.0)))
            }
            (None, Some(v)) => {
                let x = self.number(v, keys.1, &ok, allowed)?;
                Ok(Some((x * unit, v.span(), keys.1)))
            }
            (None, None) => Ok(None),
        }
    }
    /// The `section.key` around byte `pos` (for toml's own errors, which carry a span only).
    pub fn field_at(&self, pos: usize) -> String {
        let mut pos = pos.min(self.text.len());
        while !self.text.is_char_boundary(pos) {
            pos -= 1;
        }
        // The whole line holding `pos` counts as "before" it: the span of a header points into
        // the header's own line, which names the section.
        let line_end = self.text[pos..]
            .find('\n')
            .map_or(self.text.len(), |i| pos + i);
        let before = &self.text[..line_end];
        let section = before
            .lines()
            .rev()
            .find_map(|l| {
                let l = l.trim();
                (l.starts_with('[') && l.ends_with(']'))
                    .then(|| l.trim_matches(|c| c == '[' || c == ']').trim().to_string())
            })
            .unwrap_or_default();
        let line_start = self.text[..pos].rfind('\n').map_or(0, |i| i + 1);
        let line = self.text[line_start..].lines().next().unwrap_or("");
        let key = line.split('=').next().unwrap_or("").trim();
        match (section.is_empty(), key.is_empty() || key.starts_with('[')) {
            (true, _) => key.to_string(),
            (false, true) => section,
            (false, false) => format!("{section}.{key}"),
        }
    }
}
