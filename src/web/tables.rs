//! The core's tables handed to the page's JavaScript as plain objects: the parameters, the
//! creation options, the presets and the Fresnel models' curves (what `mount()` checks options
//! against and the controls are built from).

use wasm_bindgen::prelude::*;

use crate::demo::DemoOptions;
use crate::param_spec::{group_message_id, unit_message_id};
use crate::params::{table, Control};

/// The creation options (`meshSize`, `causticsSize`) as an array of
/// `{ name, label, min, max, default }`, for mount() to check and document them.
#[wasm_bindgen(js_name = optionTable)]
pub fn option_table() -> js_sys::Array {
    DemoOptions::SPECS
        .iter()
        .map(|o| {
            let object = js_sys::Object::new();
            set(&object, "name", o.name);
            set(&object, "label", o.label);
            set(&object, "min", o.min);
            set(&object, "max", o.max);
            set(&object, "default", o.default);
            JsValue::from(object)
        })
        .collect()
}

/// The presets (`src/presets.rs`) as an array of `{ name, label, help, values: [[name,
/// value], ...], camera: [yaw, pitch, distance] | null }`.
#[wasm_bindgen(js_name = presetTable)]
pub fn preset_table() -> js_sys::Array {
    crate::presets::PRESETS
        .iter()
        .map(|p| {
            let object = js_sys::Object::new();
            set(&object, "name", p.name);
            set(&object, "label", p.label);
            set(&object, "help", p.help);
            let values: js_sys::Array = p
                .values
                .iter()
                .map(|&(name, value)| {
                    JsValue::from(
                        [JsValue::from_str(name), JsValue::from(to_js_number(value))].iter().collect::<js_sys::Array>(),
                    )
                })
                .collect();
            set(&object, "values", values);
            let camera = p.camera.map_or(JsValue::NULL, |c| {
                JsValue::from(c.iter().map(|&v| JsValue::from(to_js_number(v))).collect::<js_sys::Array>())
            });
            set(&object, "camera", camera);
            JsValue::from(object)
        })
        .collect()
}

/// The page's own words in English (`page_words.rs`) as an object `{ id: text }`: what the
/// page shows when no catalogue is loaded.
#[wasm_bindgen(js_name = pageWords)]
pub fn page_words() -> js_sys::Object {
    let object = js_sys::Object::new();
    for (id, text) in crate::page_words::PAGE_WORDS {
        set(&object, id, *text);
    }
    object
}

/// Fresnel reflectance of the `fresnel` parameter's model `model` at `samples` incidence
/// angles from 0° to 90°, seen from air or from under the water: the curve the page plots,
/// from the same formulas the surface shader uses (optics.rs).
#[wasm_bindgen(js_name = fresnelCurve)]
pub fn fresnel_curve(model: f32, from_water: bool, samples: u32) -> Vec<f32> {
    crate::optics::reflectance_curve(
        crate::optics::FresnelModel::from(model),
        from_water,
        samples.clamp(2, 1024) as usize,
    )
}

/// Panics on purpose, for the test that a panic shows up in the page.
#[doc(hidden)]
#[wasm_bindgen(js_name = panicForTests)]
pub fn panic_for_tests(message: &str) {
    panic!("{message}");
}

pub(super) fn set(object: &js_sys::Object, key: &str, value: impl Into<JsValue>) {
    let _ = js_sys::Reflect::set(object, &JsValue::from_str(key), &value.into());
}

/// The parameter table (the core's one source of truth) as an array of plain objects:
/// `{ name, label, group, unit, kind: "slider" | "toggle" | "choice", min, max, step,
/// choices, choiceNames, default, help, shownWhen, messageId, groupMessageId, unitMessageId,
/// choiceMessageIds }` (`choices`: the allowed values of a choice, else empty; `choiceNames`:
/// what to show for them, or empty to show the numbers; `shownWhen`: the conditions
/// `{ param, values }` that must all hold for the control to matter: those values of another
/// parameter, e.g. the scene it belongs to; the message ids: where the catalogues hold the
/// label and help, the group's name, a unit's word (null for a symbol) and each choice name's
/// word ("" for a number or a set, shown as its members)).
#[wasm_bindgen(js_name = paramTable)]
pub fn param_table() -> js_sys::Array {
    table()
        .iter()
        .map(|p| {
            let o = spec_object(p);
            let shown_when = crate::scenes::shown_when(p.name)
                .into_iter()
                .map(|(on, values)| {
                    let w = js_sys::Object::new();
                    set(&w, "param", on);
                    set(
                        &w,
                        "values",
                        values.iter().map(|&v| JsValue::from(to_js_number(v))).collect::<js_sys::Array>(),
                    );
                    JsValue::from(w)
                })
                .collect::<js_sys::Array>();
            set(&o, "shownWhen", shown_when);
            JsValue::from(o)
        })
        .collect()
}

/// One spec as the table's plain object, without `shownWhen`.
pub(super) fn spec_object(p: &crate::param_spec::ParamSpec) -> js_sys::Object {
    let o = js_sys::Object::new();
    set(&o, "name", p.name);
    set(&o, "label", p.label);
    set(&o, "group", p.group);
    set(&o, "unit", p.unit);
    let (kind, step, choices, names) = match p.control {
        Control::Slider { step, .. } => ("slider", step, &[][..], &[][..]),
        Control::Toggle => ("toggle", 1.0, &[][..], &[][..]),
        Control::Choice { values, names } => ("choice", 0.0, values, names),
    };
    set(&o, "choices", choices.iter().map(|&v| JsValue::from(to_js_number(v))).collect::<js_sys::Array>());
    set(&o, "choiceNames", names.iter().map(|&n| JsValue::from_str(n)).collect::<js_sys::Array>());
    set(&o, "kind", kind);
    set(&o, "min", to_js_number(p.min()));
    set(&o, "max", to_js_number(p.max()));
    set(&o, "step", to_js_number(step));
    set(&o, "default", to_js_number(p.default));
    set(&o, "help", p.help);
    set(&o, "messageId", p.message_id());
    set(&o, "groupMessageId", group_message_id(p.group));
    set(&o, "unitMessageId", unit_message_id(p.unit).map_or(JsValue::NULL, JsValue::from));
    let word_ids = p.choice_message_ids();
    let choice_ids = names.iter().map(|name| {
        let id = word_ids.iter().find(|(word, _)| word == name).map_or("", |(_, id)| id.as_str());
        JsValue::from_str(id)
    });
    set(&o, "choiceMessageIds", choice_ids.collect::<js_sys::Array>());
    o
}

/// An `f32` as the `f64` with the same shortest decimal form (0.6f32 -> 0.6, not 0.6000000238).
pub(super) fn to_js_number(v: f32) -> f64 {
    v.to_string().parse().unwrap_or(v as f64)
}
