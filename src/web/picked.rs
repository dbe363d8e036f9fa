//! `WebDemo::picked()` and `setPicked()`: the settings of what the pointer picked (the tank's
//! dipper, with the move tool), which the page shows under its controls.

use wasm_bindgen::prelude::*;

use super::tables::{set, spec_object, to_js_number};
use super::{warn, WebDemo};

#[wasm_bindgen]
impl WebDemo {
    /// `{ title, titleId, number, settings: [spec with value] }` (`title` in English, `titleId`
    /// its message in the page's words with `number` to fill in; each spec as in `paramTable()`,
    /// without `shownWhen`, and its `value`), or null when nothing with settings of its own is
    /// picked.
    pub fn picked(&self) -> JsValue {
        let Some(picked) = self.demo.picked() else { return JsValue::NULL };
        let o = js_sys::Object::new();
        set(&o, "title", picked.english_title());
        set(&o, "titleId", picked.title_id);
        set(&o, "number", picked.number);
        let settings = (picked.settings.iter())
            .map(|(spec, value)| {
                let s = spec_object(spec);
                set(&s, "value", to_js_number(*value));
                JsValue::from(s)
            })
            .collect::<js_sys::Array>();
        set(&o, "settings", settings);
        o.into()
    }

    /// Sets the picked thing's setting `name` to `value` (clamped to its range); with nothing
    /// picked, or no such setting, it changes nothing and warns in the console.
    #[wasm_bindgen(js_name = setPicked)]
    pub fn set_picked(&mut self, name: &str, value: f64) {
        if let Err(why) = self.demo.set_picked(name, value as f32) {
            warn(&format!("wavepool: setPicked(\"{name}\", {value}) ignored: {why}"));
        }
    }
}
