//! `wavepool parameters`: the reference of every parameter and preset in Markdown, written
//! from the tables themselves (docs/parameters.md is its output; a test fails when it is stale).

use wavepool::params::{self, Control, ParamSpec};
use wavepool::presets;

/// A value as the page and the command line take it: a choice's name where it has one.
fn shown(p: &ParamSpec, v: f32) -> String {
    match p.control {
        Control::Toggle => (if v >= 0.5 { "on" } else { "off" }).to_owned(),
        Control::Choice { values, names } => {
            let i = values.iter().position(|&x| x == v);
            i.and_then(|i| names.get(i)).filter(|n| !n.is_empty()).map_or(format!("{v}"), |n| (*n).to_owned())
        }
        Control::Slider { .. } => format!("{v}"),
    }
}

/// Its range, or its choices by name.
fn range(p: &ParamSpec) -> String {
    match p.control {
        Control::Toggle => "on, off".to_owned(),
        Control::Choice { values, .. } => values.iter().map(|&v| shown(p, v)).collect::<Vec<_>>().join(", "),
        Control::Slider { min, max, .. } => format!("{min} – {max}"),
    }
}

/// Text safe in a Markdown table cell.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// The whole reference.
pub fn markdown() -> String {
    let mut out = String::from(
        "# Parameters\n\n\
         Written by `wavepool parameters` from the parameter table (each feature declares its own\n\
         slice; `src/params.rs` puts them together); a test fails when this file is stale.\n\n\
         Every parameter can be given in the page's URL (`?wave_speed=0.8`), as an attribute of\n\
         `<wave-pool>` in kebab case (`wave-speed=\"0.8\"`), in `mount()`'s options, with the\n\
         handle's `set(name, value)`, and on the command line (`--set wave_speed=0.8`). A choice\n\
         is given by its name or its number; a value out of range is clamped, with a warning.\n",
    );
    let mut groups: Vec<&str> = Vec::new();
    for p in params::table() {
        if !groups.contains(&p.group) {
            groups.push(p.group);
        }
    }
    for group in groups {
        let members: Vec<&ParamSpec> = params::table().iter().filter(|p| p.group == group).map(|p| p.spec).collect();
        out += &format!(
            "\n## {group}\n\n| name | unit | range or choices | default | what it is |\n|---|---|---|---|---|\n"
        );
        for p in &members {
            out += &format!(
                "| `{}` | {} | {} | {} | {} |\n",
                p.name,
                cell(p.unit),
                cell(&range(p)),
                cell(&shown(p, p.default)),
                cell(p.label)
            );
        }
        out += "\n";
        for p in &members {
            out += &format!("- **`{}`**: {}\n", p.name, p.help);
        }
    }
    out += "\n## Presets\n\nNamed starting states: `preset=NAME` in the URL, `preset=\"NAME\"` on the element, \
            `{ preset: \"NAME\" }` in `mount()`, `--preset NAME` on the command line. The page's own \
            options override a preset's values.\n\n| name | what it is |\n|---|---|\n";
    for preset in presets::PRESETS {
        out += &format!("| `{}` | {}: {} |\n", preset.name, cell(preset.label), cell(preset.help));
    }
    out
}
