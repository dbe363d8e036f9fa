//! What a user-facing parameter is: its machine name, label, group, unit, control (slider,
//! toggle or choice), default and help. Each feature declares its own parameters with these
//! (next to the constants their ranges come from); `params` assembles the one table the page,
//! the viewer, the URL, the command line and the tests read. Values are `f32`; toggles 0 or 1.

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    Slider {
        min: f32,
        max: f32,
        step: f32,
    },
    Toggle,
    /// One of a few values, in increasing order; `names` (empty, or one per value) are what
    /// controls show instead of the numbers.
    Choice {
        values: &'static [f32],
        names: &'static [&'static str],
    },
}

#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    /// Stable machine name used in URLs, `set(name, value)` and the CLI.
    pub name: &'static str,
    pub label: &'static str,
    pub group: &'static str,
    /// Unit symbol shown after the value ("m/s", "1/s", "m", "°"), empty when unitless.
    pub unit: &'static str,
    pub control: Control,
    pub default: f32,
    pub help: &'static str,
}

impl ParamSpec {
    /// The id of its label in the message catalogues (`locales/*.ftl`); its help is the
    /// message's `help` attribute. The page and the viewer look a parameter's words up by it.
    pub fn message_id(&self) -> String {
        format!("param-{}", self.name)
    }

    /// The ids of its choices' names that words stand for (not numbers or shares, "128",
    /// "50%"; not a set such as "sphere,duck", shown as its members' words), with the names.
    pub fn choice_message_ids(&self) -> Vec<(&'static str, String)> {
        let Control::Choice { names, .. } = self.control else { return Vec::new() };
        names
            .iter()
            .filter(|n| {
                n.starts_with(|c: char| c.is_ascii_lowercase()) && n.chars().all(|c| c.is_ascii_lowercase() || c == '_')
            })
            .map(|&n| (n, format!("param-{}-{n}", self.name)))
            .collect()
    }

    pub fn min(&self) -> f32 {
        match self.control {
            Control::Slider { min, .. } => min,
            Control::Toggle => 0.0,
            Control::Choice { values, .. } => values[0],
        }
    }

    pub fn max(&self) -> f32 {
        match self.control {
            Control::Slider { max, .. } => max,
            Control::Toggle => 1.0,
            Control::Choice { values, .. } => values[values.len() - 1],
        }
    }

    /// A value as a user writes it (command line, URL): a number, one of a choice's names
    /// (any case) or several joined by commas (their values added: a set, as `objects`), or
    /// on/off/true/false for a toggle. `None` if it is none of those.
    pub fn parse(&self, text: &str) -> Option<f32> {
        let text = text.trim();
        if let Control::Choice { values, names } = self.control {
            let named = |text: &str| names.iter().position(|n| n.eq_ignore_ascii_case(text.trim())).map(|i| values[i]);
            if let Some(v) = named(text) {
                return Some(v);
            }
            // A set of choices ("sphere,duck") adds their values, if that is a choice too.
            if text.contains(',') {
                let sum = text.split(',').map(named).sum::<Option<f32>>()?;
                return values.contains(&sum).then_some(sum);
            }
        }
        match text.to_ascii_lowercase().as_str() {
            "on" | "true" => Some(1.0),
            "off" | "false" => Some(0.0),
            _ => text.parse().ok(),
        }
    }

    /// The nearest valid value: clamped to the range; toggles snap to 0 or 1, choices to the
    /// nearest value; NaN gives the default.
    pub fn sanitise(&self, value: f32) -> f32 {
        if value.is_nan() {
            return self.default;
        }
        match self.control {
            Control::Slider { min, max, .. } => value.clamp(min, max),
            Control::Toggle => {
                if value >= 0.5 {
                    1.0
                } else {
                    0.0
                }
            }
            Control::Choice { values, .. } => {
                values.iter().copied().min_by(|a, b| (a - value).abs().total_cmp(&(b - value).abs())).unwrap_or(value)
            }
        }
    }
}

/// A slider from `min` to `max` in steps of `step`.
pub const fn slider(min: f32, max: f32, step: f32) -> Control {
    Control::Slider { min, max, step }
}

/// The label a choice parameter shows for `value` (its name, or the number with its unit).
pub fn choice_label(spec: &ParamSpec, value: f32) -> String {
    if let Control::Choice { values, names } = spec.control {
        if let Some(i) = values.iter().position(|&v| v == value) {
            if let Some(name) = names.get(i) {
                return (*name).to_owned();
            }
        }
    }
    if spec.unit.is_empty() {
        format!("{value}")
    } else {
        format!("{value} {}", spec.unit)
    }
}

/// The values 0, 1, …, N − 1 of a choice declared with [`choices!`](crate::choices).
pub const fn option_values<const N: usize>() -> [f32; N] {
    let mut values = [0.0; N];
    let mut i = 0;
    while i < N {
        values[i] = i as f32;
        i += 1;
    }
    values
}

/// A choice parameter's options as an enum, declared in one place: the variants in the order
/// of the parameter's values (0, 1, 2, …) with the names the table, URLs and the command line
/// write, `VALUES` and `NAMES` for its [`Control::Choice`], and `From<f32>`, the option a
/// value stands for (the nearest, clamped; NaN the first). Derives `Clone`, `Copy`, `Debug`,
/// `PartialEq`, `Eq` and `Hash`; more derives (and `#[default]` on a variant) may be given.
#[macro_export]
macro_rules! choices {
    ($(#[$meta:meta])* $vis:vis enum $name:ident { $($(#[$vmeta:meta])* $variant:ident = $label:literal),+ $(,)? }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        $vis enum $name {
            $($(#[$vmeta])* $variant),+
        }

        impl $name {
            /// Every option, in the order of the parameter's values.
            pub const ALL: &'static [$name] = &[$($name::$variant),+];
            /// The options' names, as the parameter table writes them.
            pub const NAMES: &'static [&'static str] = &[$($label),+];
            /// The parameter's values: 0, 1, 2, ….
            pub const VALUES: &'static [f32] = &$crate::param_spec::option_values::<{ [$($label),+].len() }>();

            /// This option's name in the parameter table.
            pub fn name(self) -> &'static str {
                Self::NAMES[self as usize]
            }

            /// The parameter's value for this option.
            pub fn value(self) -> f32 {
                Self::VALUES[self as usize]
            }
        }

        impl From<f32> for $name {
            fn from(value: f32) -> Self {
                let last = (Self::ALL.len() - 1) as f32;
                let i = if value.is_nan() { 0.0 } else { value.round().clamp(0.0, last) };
                Self::ALL[i as usize]
            }
        }
    };
}

/// The id of a unit's word in the message catalogues ("cells": "unit-cells"), for units that
/// are words rather than symbols (lower-case letters only, three or more: not "m", "Hz", "EV").
pub fn unit_message_id(unit: &str) -> Option<String> {
    (unit.len() >= 3 && unit.chars().all(|c| c.is_ascii_lowercase())).then(|| format!("unit-{unit}"))
}

/// The id of a group's name in the message catalogues: "group-" and the name in lower case,
/// spaces as hyphens ("Flat water": "group-flat-water").
pub fn group_message_id(group: &str) -> String {
    format!("group-{}", group.to_lowercase().replace(' ', "-"))
}
