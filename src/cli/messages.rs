//! `wavepool messages`: the English catalogue, `locales/en.ftl` (a test fails when it is stale):
//! the page's own words, then the parameter table's and the presets' as Project Fluent
//! messages. Each language's catalogue translates the same ids; the page and the viewer look the
//! table's words up by them (`ParamSpec::message_id`, `group_message_id`).

use wavepool::page_words::PAGE_WORDS;
use wavepool::param_spec::{group_message_id, unit_message_id};
use wavepool::params::{self, ParamSpec};
use wavepool::presets;
use wavepool::tank::tuning::{DIPPER_AMPLITUDE, DIPPER_FREQUENCY, DIPPER_PHASE};

/// What locales/en.ftl says before its messages.
const HEADER: &str = "\
# wavepool's words in English, the source every other catalogue translates (Project Fluent,
# https://projectfluent.org/fluent/guide/). Written by `wavepool messages` from the tables in
# src/ (src/page_words.rs, the parameter table, the presets): edit the English there. A language
# is added by copying this file to locales/<tag>.ftl, translating each message's text (never its
# id or its { $variables }) and registering the tag in web/i18n.js (LANGUAGES). Units' symbols
# (m/s, Hz, °) and proper names stay as they are.

## The page's own words (web/*.js)

";

/// The line in every catalogue after which the table's messages follow.
pub const MARKER: &str = "## The parameter table and the presets";

/// Text as a Fluent pattern: braces start placeables, so they are written as string literals.
fn pattern(text: &str) -> String {
    text.replace('{', "{\"{\"}").replace('}', "{\"}\"}")
}

fn param(p: &ParamSpec) -> String {
    let mut out = format!("{} = {}\n    .help = {}\n", p.message_id(), pattern(p.label), pattern(p.help));
    for (name, id) in p.choice_message_ids() {
        out += &format!("{id} = {}\n", pattern(name));
    }
    out
}

/// The whole English catalogue, locales/en.ftl.
pub fn english_catalogue() -> String {
    let mut out = String::from(HEADER);
    for (id, text) in PAGE_WORDS {
        match id.split_once('.') {
            Some((_, attribute)) => out += &format!("    .{attribute} = {text}\n"),
            None => out += &format!("{id} = {text}\n"),
        }
    }
    out + "\n" + &table_messages()
}

/// The table's and the presets' messages, the marker line first.
fn table_messages() -> String {
    let mut out =
        format!("{MARKER}\n## (written by `wavepool messages` from the tables in src/: edit the English there)\n\n");
    let mut groups: Vec<&str> = Vec::new();
    for p in params::table() {
        if !groups.contains(&p.group) {
            groups.push(p.group);
        }
    }
    for group in &groups {
        out += &format!("{} = {}\n", group_message_id(group), pattern(group));
    }
    let mut units: Vec<&str> =
        params::table().iter().map(|p| p.unit).filter(|u| unit_message_id(u).is_some()).collect();
    units.dedup();
    for unit in units {
        out += &format!("{} = {unit}\n", unit_message_id(unit).expect("a word"));
    }
    for group in groups {
        out += &format!("\n## {group}\n\n");
        for p in params::table().iter().filter(|p| p.group == group) {
            out += &param(p.spec);
        }
    }
    out += "\n## Each dipper's own settings in the tank (the group's title: \"Dipper\" and its number)\n\n";
    for p in [&DIPPER_FREQUENCY, &DIPPER_AMPLITUDE, &DIPPER_PHASE] {
        out += &param(p);
    }
    out += "\n## Presets (the name, and what a student reads)\n\n";
    for preset in presets::PRESETS {
        out += &format!("preset-{} = {}\n    .help = {}\n", preset.name, pattern(preset.label), pattern(preset.help));
    }
    out
}

/// Serbian Cyrillic to Latin, letter by letter (Vuk's alphabet and
/// Gaj's correspond one to one; "љ" is "lj"): the Latin catalogue from the Cyrillic one.
pub fn serbian_latin(text: &str) -> String {
    const PAIRS: [(char, &str); 30] = [
        ('а', "a"),
        ('б', "b"),
        ('в', "v"),
        ('г', "g"),
        ('д', "d"),
        ('ђ', "đ"),
        ('е', "e"),
        ('ж', "ž"),
        ('з', "z"),
        ('и', "i"),
        ('ј', "j"),
        ('к', "k"),
        ('л', "l"),
        ('љ', "lj"),
        ('м', "m"),
        ('н', "n"),
        ('њ', "nj"),
        ('о', "o"),
        ('п', "p"),
        ('р', "r"),
        ('с', "s"),
        ('т', "t"),
        ('ћ', "ć"),
        ('у', "u"),
        ('ф', "f"),
        ('х', "h"),
        ('ц', "c"),
        ('ч', "č"),
        ('џ', "dž"),
        ('ш', "š"),
    ];
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let lower: char = c.to_lowercase().next().unwrap_or(c);
        match PAIRS.iter().find(|(k, _)| *k == lower) {
            None => out.push(c),
            Some((_, latin)) if lower == c => out += latin,
            Some((_, latin)) => {
                // A capital: "Љ" is "Lj" before a small letter, "LJ" in a word of capitals.
                let next_upper = chars.peek().is_some_and(|n| n.is_uppercase());
                let mut letters = latin.chars();
                let first = letters.next().expect("a letter").to_uppercase();
                out.extend(first);
                if next_upper {
                    out.extend(letters.flat_map(char::to_uppercase));
                } else {
                    out.extend(letters);
                }
            }
        }
    }
    out
}
