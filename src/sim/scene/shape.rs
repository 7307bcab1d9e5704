//! The shape of a scene before its values: TOML syntax, sections, which key lives where, and the
//! type serde found. Each problem is named where it is (`file:line: [section] key: what is
//! wrong; what is allowed`), so that a key in the wrong section says where it belongs and a
//! missing key names its section, not the section before it.
//!
//! The keys of each section are read off the `Raw*` structs themselves (serde hands every
//! struct's field list to the deserializer), so this check cannot drift from the schema.

use crate::sim::scene::errors::{Ctx, SceneError};
use crate::sim::scene::parts::{
    Raw, RawContact, RawEnd, RawIntegrator, RawLadder, RawOutputs, RawStart,
};
use serde::de::{self, Deserialize, Deserializer, Visitor};
use toml::de::{DeTable, DeValue};

/// The field names of the struct `T` deserializes into.
pub fn fields_of<'de, T: Deserialize<'de>>() -> &'static [&'static str] {
    struct Grab<'a>(&'a mut &'static [&'static str]);
    impl<'de> Deserializer<'de> for Grab<'_> {
        type Error = de::value::Error;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Self::Error> {
            Err(de::Error::custom("not a struct"))
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _name: &'static str,
            fields: &'static [&'static str],
            _visitor: V,
        ) -> Result<V::Value, Self::Error> {
            *self.0 = fields;
            Err(de::Error::custom("fields read"))
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes
            byte_buf option unit unit_struct newtype_struct seq tuple tuple_struct map enum
            identifier ignored_any
        }
    }
    let mut fields: &'static [&'static str] = &[];
    let _ = T::deserialize(Grab(&mut fields));
    fields
}

/// Every section with its keys, in the order a scene lists them.
pub(in crate::sim) fn schema() -> Vec<(&'static str, &'static [&'static str])> {
    let sections = fields_of::<Raw>();
    let keys = [
        fields_of::<RawLadder>(),
        fields_of::<RawStart>(),
        fields_of::<RawContact>(),
        fields_of::<RawIntegrator>(),
        fields_of::<RawEnd>(),
        fields_of::<RawOutputs>(),
    ];
    sections.iter().copied().zip(keys).collect()
}

/// The names joined by ", ", each in brackets when `bracket`.
fn list(names: &[&str], bracket: bool) -> String {
    names
        .iter()
        .map(|n| {
            if bracket {
                format!("[{n}]")
            } else {
                (*n).to_string()
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The section a key belongs in, if any.
pub fn home_of(key: &str) -> Option<&'static str> {
    schema()
        .into_iter()
        .find(|(_, keys)| keys.contains(&key))
        .map(|(s, _)| s)
}

/// Syntax, sections and keys of the scene text; the parsed table is thrown away (serde reads
/// the values next).
pub(in crate::sim) fn check_shape(cx: &Ctx) -> Result<(), SceneError> {
    let sections = fields_of::<Raw>();
    if cx.text.trim().is_empty() {
        return Err(cx.err_at_line(
            1,
            "",
            format!(
                "empty file; allowed: a scene with the sections {}",
                list(sections, true)
            ),
        ));
    }
    let doc = DeTable::parse(cx.text).map_err(|e| syntax(cx, &e))?;
    let schema = schema();
    check_sections(cx, doc.get_ref(), &schema, sections)?;
    check_missing_sections(cx, doc.get_ref(), &schema)?;
    Ok(())
}

/// Every section of the scene is one of the schema's, a table, and holds only its own keys;
/// a key of another section says where it belongs.
fn check_sections(
    cx: &Ctx,
    doc: &DeTable,
    schema: &[(&'static str, &'static [&'static str])],
    sections: &[&str],
) -> Result<(), SceneError> {
    for (name, value) in doc.iter() {
        let section = name.get_ref().as_ref();
        let span = Some(name.span());
        let Some((_, keys)) = schema.iter().find(|(s, _)| *s == section) else {
            return Err(match home_of(section) {
                Some(home) => cx.err(
                    span,
                    section,
                    format!("outside any section; allowed: under [{home}]"),
                ),
                None => cx.err(
                    span,
                    &format!("[{section}]"),
                    format!("unknown section; allowed: {}", list(sections, true)),
                ),
            });
        };
        let DeValue::Table(table) = value.get_ref() else {
            return Err(cx.err(
                span,
                section,
                format!(
                    "a value where a section is needed; allowed: a [{section}] section with {}",
                    list(keys, false)
                ),
            ));
        };
        for (key, _) in table.iter() {
            let k = key.get_ref().as_ref();
            if keys.contains(&k) {
                continue;
            }
            let message = match home_of(k) {
                Some(home) => format!(
                    "belongs in [{home}], not [{section}]; allowed in [{section}]: {}",
                    list(keys, false)
                ),
                None => format!("unknown key; allowed in [{section}]: {}", list(keys, false)),
            };
            return Err(cx.err(Some(key.span()), &format!("{section}.{k}"), message));
        }
    }
    Ok(())
}

/// Every section of the schema is present; the first missing one is named where it would go.
fn check_missing_sections(
    cx: &Ctx,
    doc: &DeTable,
    schema: &[(&'static str, &'static [&'static str])],
) -> Result<(), SceneError> {
    let header = |name: &str| {
        doc.iter()
            .find(|(k, _)| k.get_ref().as_ref() == name)
            .map(|(k, _)| cx.line_of(k.span().start))
    };
    for (i, (section, keys)) in schema.iter().enumerate() {
        if header(section).is_some() {
            continue;
        }
        // Where it would go: before the next section present, else at the end.
        let next = schema[i + 1..]
            .iter()
            .find_map(|(s, _)| header(s).map(|l| (*s, l)));
        let (line, place) = match next {
            Some((s, l)) => (l, format!(", expected before [{s}]")),
            None => (cx.line_of(cx.text.len()), String::new()),
        };
        return Err(cx.err_at_line(
            line,
            section,
            format!(
                "missing section{place}; allowed: a [{section}] section with {}",
                list(keys, false)
            ),
        ));
    }
    Ok(())
}

/// A serde error on a scene whose shape is right: a missing key (named in its own section, at
/// that section's header) or a value of the wrong type.
pub(in crate::sim) fn value_error(cx: &Ctx, e: &toml::de::Error) -> SceneError {
    let msg = e.message().trim().replace('\n', " ");
    if let Some(key) = msg
        .strip_prefix("missing field `")
        .and_then(|m| m.split('`').next())
    {
        if let Some(home) = home_of(key) {
            let line = DeTable::parse(cx.text).ok().and_then(|doc| {
                doc.get_ref()
                    .iter()
                    .find(|(k, _)| k.get_ref().as_ref() == home)
                    .map(|(k, _)| cx.line_of(k.span().start))
            });
            let keys = schema()
                .into_iter()
                .find(|(s, _)| *s == home)
                .map_or(String::new(), |(_, k)| list(k, false));
            let e = cx.err(
                None,
                &format!("{home}.{key}"),
                format!("missing key; allowed: a [{home}] section with {keys}"),
            );
            return SceneError { line, ..e };
        }
    }
    let span = e.span();
    let field = span
        .as_ref()
        .map_or_else(String::new, |s| cx.field_at(s.start));
    if let Some((what, expected)) = msg
        .strip_prefix("invalid type: ")
        .and_then(|m| m.rsplit_once(", expected "))
    {
        let allowed = match expected {
            "f64" | "a float" => "a number",
            "a string" => "a string in quotes",
            "a sequence" => "a list of strings, e.g. [\"separation_angle\"]",
            other => other,
        };
        return cx.err(
            span,
            &field,
            format!("wrong type: {what}; allowed: {allowed}"),
        );
    }
    cx.err(
        span,
        &field,
        format!("{msg}; allowed: see the scene format in README.md and docs/simulator.md"),
    )
}

fn syntax(cx: &Ctx, e: &toml::de::Error) -> SceneError {
    let msg = e.message().trim().replace('\n', " ");
    let span = e.span();
    let field = span
        .as_ref()
        .map_or_else(String::new, |s| cx.field_at(s.start));
    let message = if msg.contains("duplicate key") {
        "given twice; allowed: each key and each section once".to_string()
    } else {
        format!("TOML syntax error: {msg}; allowed: `key = value` lines under `[section]` headers")
    };
    cx.err(span, &field, message)
}
