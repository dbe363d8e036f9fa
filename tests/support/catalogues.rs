//! The message catalogues (locales/*.ftl), read with the Fluent project's own parser: each
//! language's messages (and `id.attribute`s) with the variables their texts use, and their
//! texts where they are plain (no placeable): what the page must show.
#![allow(dead_code)]

use std::collections::{BTreeMap, BTreeSet};

use fluent_syntax::ast::{Entry, Expression, InlineExpression, Pattern, PatternElement};

pub type Messages = BTreeMap<String, BTreeSet<String>>;

/// locales/
pub fn dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("locales")
}

fn variables_in_inline(e: &InlineExpression<&str>, out: &mut BTreeSet<String>) {
    match e {
        InlineExpression::VariableReference { id } => {
            out.insert(id.name.to_owned());
        }
        InlineExpression::Placeable { expression } => variables_in(expression, out),
        _ => {}
    }
}

fn variables_in(e: &Expression<&str>, out: &mut BTreeSet<String>) {
    match e {
        Expression::Inline(inline) => variables_in_inline(inline, out),
        Expression::Select { selector, variants } => {
            variables_in_inline(selector, out);
            for v in variants {
                out.extend(variables(&v.value));
            }
        }
    }
}

fn variables(p: &Pattern<&str>) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for element in &p.elements {
        if let PatternElement::Placeable { expression } = element {
            variables_in(expression, &mut out);
        }
    }
    out
}

/// The messages of `source`; a syntax error fails the test, naming the file.
pub fn read(name: &str, source: &str) -> Messages {
    let resource = match fluent_syntax::parser::parse(source) {
        Ok(r) => r,
        Err((_, errors)) => panic!("{name}: {} Fluent syntax errors, the first {:?}", errors.len(), errors[0]),
    };
    let mut out = Messages::new();
    for entry in &resource.body {
        if let Entry::Message(m) = entry {
            let id = m.id.name.to_owned();
            if let Some(value) = &m.value {
                out.insert(id.clone(), variables(value));
            }
            for a in &m.attributes {
                out.insert(format!("{id}.{}", a.id.name), variables(&a.value));
            }
        }
    }
    out
}

/// The plain texts of `source`'s messages and attributes (those with placeables left out).
pub fn texts(name: &str, source: &str) -> BTreeMap<String, String> {
    let resource = fluent_syntax::parser::parse(source).unwrap_or_else(|(_, e)| panic!("{name}: {e:?}"));
    let plain = |p: &Pattern<&str>| {
        let mut text = String::new();
        for element in &p.elements {
            match element {
                PatternElement::TextElement { value } => text += value,
                PatternElement::Placeable { .. } => return None,
            }
        }
        Some(text)
    };
    let mut out = BTreeMap::new();
    for entry in &resource.body {
        if let Entry::Message(m) = entry {
            let id = m.id.name.to_owned();
            if let Some(text) = m.value.as_ref().and_then(plain) {
                out.insert(id.clone(), text);
            }
            for a in &m.attributes {
                if let Some(text) = plain(&a.value) {
                    out.insert(format!("{id}.{}", a.id.name), text);
                }
            }
        }
    }
    out
}

/// The plain texts of locales/<tag>.ftl.
pub fn texts_of(tag: &str) -> BTreeMap<String, String> {
    let name = format!("{tag}.ftl");
    texts(&name, &std::fs::read_to_string(dir().join(&name)).unwrap_or_else(|e| panic!("{name}: {e}")))
}
