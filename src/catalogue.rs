//! The words of the parameter table, the presets and the page in one language, natively: the
//! message catalogues (`locales/*.ftl`, compiled in) read by the Fluent project's crate, for the
//! viewer's panel (`--lang`). English is the tables' own words, as in the page (`web/i18n.js`
//! reads the same catalogues there). Numbers with the decimal mark the language writes.

use std::borrow::Cow;

use fluent_bundle::{FluentArgs, FluentBundle, FluentResource};
use wavepool::page_words;
use wavepool::param_spec::{group_message_id, unit_message_id, ParamSpec};
use wavepool::presets::Preset;

/// The languages there are catalogues for: tag, name in its own words, the catalogue, and
/// whether it writes a decimal comma.
const LANGUAGES: &[(&str, &str, &str, bool)] = &[
    ("en", "English", "", false),
    ("cs", "Čeština", include_str!("../locales/cs.ftl"), true),
    ("de", "Deutsch", include_str!("../locales/de.ftl"), true),
    ("es", "Español", include_str!("../locales/es.ftl"), true),
    ("ru", "Русский", include_str!("../locales/ru.ftl"), true),
    ("sr-Latn", "Srpski (latinica)", include_str!("../locales/sr-Latn.ftl"), true),
    ("sr-Cyrl", "Српски (ћирилица)", include_str!("../locales/sr-Cyrl.ftl"), true),
];

/// Tags and names of the languages, for a language menu.
pub fn languages() -> impl Iterator<Item = (&'static str, &'static str)> {
    LANGUAGES.iter().map(|&(tag, name, _, _)| (tag, name))
}

/// One language's words.
pub struct Catalogue {
    pub tag: &'static str,
    bundle: Option<FluentBundle<FluentResource>>,
    decimal_comma: bool,
}

impl Catalogue {
    /// The catalogue of `tag` ("cs", "sr-Latn", ...; "sr" is Cyrillic, "cs-CZ" is Czech).
    pub fn load(tag: &str) -> Result<Self, String> {
        let lower = tag.to_ascii_lowercase().replace('_', "-");
        let wanted = match lower.split('-').next() {
            Some("sr") if lower.contains("latn") => "sr-latn".to_owned(),
            Some("sr") => "sr-cyrl".to_owned(),
            Some(language) if !LANGUAGES.iter().any(|l| l.0.eq_ignore_ascii_case(&lower)) => language.to_owned(),
            _ => lower.clone(),
        };
        let &(tag, _, source, decimal_comma) =
            LANGUAGES.iter().find(|l| l.0.eq_ignore_ascii_case(&wanted)).ok_or_else(|| {
                format!(
                    "no catalogue for {tag:?}; there are {}",
                    languages().map(|l| l.0).collect::<Vec<_>>().join(", ")
                )
            })?;
        if source.is_empty() {
            return Ok(Self { tag, bundle: None, decimal_comma });
        }
        let resource = FluentResource::try_new(source.to_owned()).map_err(|(_, e)| format!("{tag}.ftl: {e:?}"))?;
        let id = tag.parse().map_err(|e| format!("{tag}: {e}"))?;
        let mut bundle = FluentBundle::new(vec![id]);
        bundle.set_use_isolating(false);
        bundle.add_resource(resource).map_err(|e| format!("{tag}.ftl: {e:?}"))?;
        Ok(Self { tag, bundle: Some(bundle), decimal_comma })
    }

    /// Message `id`'s text (`attribute`: one of its attributes), if the catalogue has it.
    fn lookup(&self, id: &str, attribute: Option<&str>, args: Option<&FluentArgs>) -> Option<String> {
        let bundle = self.bundle.as_ref()?;
        let message = bundle.get_message(id)?;
        let pattern = match attribute {
            Some(a) => message.get_attribute(a)?.value(),
            None => message.value()?,
        };
        let mut errors = Vec::new();
        Some(bundle.format_pattern(pattern, args, &mut errors).into_owned())
    }

    /// The page's and the viewer's own words (`page_words`): "reset", or "reset.title".
    pub fn page(&self, id: &str) -> Cow<'static, str> {
        self.page_with(id, &[])
    }

    /// The same with its `{ $name }`s filled in.
    pub fn page_with(&self, id: &str, args: &[(&str, String)]) -> Cow<'static, str> {
        let (message, attribute) = id.split_once('.').map_or((id, None), |(m, a)| (m, Some(a)));
        let mut fluent = FluentArgs::new();
        for (name, value) in args {
            fluent.set(*name, value.clone());
        }
        if let Some(text) = self.lookup(message, attribute, Some(&fluent)) {
            return Cow::Owned(text);
        }
        if args.is_empty() {
            return Cow::Borrowed(page_words::english(id).unwrap_or(""));
        }
        Cow::Owned(page_words::english_with(id, args))
    }

    /// A scene's stage, named as `Scene::stage_names` names it ("the tank": message stage-the-tank).
    pub fn stage(&self, name: &'static str) -> Cow<'static, str> {
        let id = format!("stage-{}", name.replace(' ', "-"));
        self.lookup(&id, None, None).map_or(Cow::Borrowed(name), Cow::Owned)
    }

    pub fn label(&self, p: &ParamSpec) -> Cow<'static, str> {
        self.lookup(&p.message_id(), None, None).map_or(Cow::Borrowed(p.label), Cow::Owned)
    }

    pub fn help(&self, p: &ParamSpec) -> Cow<'static, str> {
        self.lookup(&p.message_id(), Some("help"), None).map_or(Cow::Borrowed(p.help), Cow::Owned)
    }

    pub fn group(&self, group: &'static str) -> Cow<'static, str> {
        self.lookup(&group_message_id(group), None, None).map_or(Cow::Borrowed(group), Cow::Owned)
    }

    pub fn preset_label(&self, p: &Preset) -> Cow<'static, str> {
        self.lookup(&format!("preset-{}", p.name), None, None).map_or(Cow::Borrowed(p.label), Cow::Owned)
    }

    pub fn preset_help(&self, p: &Preset) -> Cow<'static, str> {
        self.lookup(&format!("preset-{}", p.name), Some("help"), None).map_or(Cow::Borrowed(p.help), Cow::Owned)
    }

    /// A unit after a value: a symbol as it is, a word ("cells") in the language's words.
    pub fn unit(&self, unit: &'static str) -> Cow<'static, str> {
        unit_message_id(unit).and_then(|id| self.lookup(&id, None, None)).map_or(Cow::Borrowed(unit), Cow::Owned)
    }

    /// A choice's value as the controls show it: its name's words (a set by its members'), or
    /// the number and its unit.
    pub fn choice(&self, p: &ParamSpec, value: f32) -> String {
        let ids = p.choice_message_ids();
        let name = wavepool::param_spec::choice_label(p, value);
        if !name.chars().all(|c| c.is_ascii_lowercase() || c == '_' || c == ',') {
            return match p.unit {
                "" => name,
                unit => name.replace(unit, &self.unit(unit)),
            };
        }
        let word = |n: &str| {
            let id = ids.iter().find(|(choice, _)| *choice == n).map(|(_, id)| id.clone());
            id.and_then(|id| self.lookup(&id, None, None)).unwrap_or_else(|| n.to_owned())
        };
        name.split(',').map(word).collect::<Vec<_>>().join(", ")
    }

    /// `v` with `decimals` decimals and the language's decimal mark.
    pub fn number(&self, v: f64, decimals: usize) -> String {
        let text = format!("{v:.decimals$}");
        if self.decimal_comma {
            text.replace('.', ",")
        } else {
            text
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wavepool::params::{table, ParamId};

    /// The words the viewer shows are the catalogue's, and numbers take its decimal mark.
    #[test]
    fn the_viewer_shows_each_catalogues_words_and_decimal_mark() {
        let speed = table()[ParamId::WaveSpeed as usize].spec;
        for (tag, _) in languages() {
            let words = Catalogue::load(tag).expect("a catalogue");
            let label = words.label(speed);
            let source = LANGUAGES.iter().find(|l| l.0 == tag).unwrap().2;
            let line = format!("{} = {label}\n", speed.message_id());
            println!("{tag}: {label:?}, {}", words.number(0.6, 1));
            assert!(tag == "en" || source.contains(&line), "{tag}: {label:?} is not the catalogue's");
            assert_eq!(words.number(0.6, 1), if tag == "en" { "0.6" } else { "0,6" });
        }
        assert_eq!(Catalogue::load("en").unwrap().label(speed), speed.label);
        assert_eq!(Catalogue::load("sr").unwrap().tag, "sr-Cyrl");
        assert_eq!(Catalogue::load("cs-CZ").unwrap().tag, "cs");
        assert!(Catalogue::load("xx").is_err());
    }
}
