//! `WebDemo::stats()`: what the page's `demo.stats()` reports from the core (the page adds
//! its frame figures in `web/demo.js`; the fields are declared in `web/embed.d.ts`).

use wasm_bindgen::prelude::*;

use super::tables::set;
use super::{web_format_name, WebDemo};
use crate::bodies::BodyId;
use crate::render::RenderMode;
use crate::sim::SimEngine;
use crate::timing::StageTimer;

#[wasm_bindgen]
impl WebDemo {
    /// `{ backend, adapter, canvasFormat, simSize, simEngine, simTime, meanLevel, maxAbsHeight, width, height,
    /// spherePosition, duckPosition, bodies, submergedVolume, reduced }` (`reduced`: sizes held
    /// to what this device affords, `{ name, asked, given }`); the water statistics are read
    /// back asynchronously and are a frame or two old; positions are [x, y, z] in m or null
    /// when the object is not in the pool (`bodies`: every kind's, by its name).
    pub fn stats(&self) -> js_sys::Object {
        let o = js_sys::Object::new();
        let level = self.demo.water_level().unwrap_or_default();
        set(&o, "backend", self.backend);
        set(&o, "adapter", self.adapter.as_str());
        set(&o, "simSize", self.demo.water().size());
        set(&o, "simEngine", if self.demo.water().engine() == SimEngine::Gpu { "gpu" } else { "cpu" });
        set(&o, "simTime", self.demo.sim_time());
        set(&o, "scene", self.demo.drawn_scene().name());
        // The shown scene's instruments: { name: { value, unit } } (the tank's probe, ruler).
        let readings = js_sys::Object::new();
        for (name, value, unit) in self.demo.readings() {
            let reading = js_sys::Object::new();
            set(&reading, "value", value as f64);
            set(&reading, "unit", unit);
            set(&readings, name, reading);
        }
        set(&o, "readings", readings);
        set(&o, "meanLevel", level.mean as f64);
        set(&o, "maxAbsHeight", level.max_abs as f64);
        set(&o, "width", self.config.width);
        set(&o, "height", self.config.height);
        set(&o, "renderScale", self.demo.render_scale() as f64);
        set(&o, "canvasFormat", web_format_name(self.config.format));
        let position = |p: Option<glam::Vec3>| match p {
            Some(p) => {
                JsValue::from(p.to_array().iter().map(|&v| JsValue::from_f64(v as f64)).collect::<js_sys::Array>())
            }
            None => JsValue::NULL,
        };
        set(&o, "spherePosition", position(self.demo.sphere().map(|s| s.centre)));
        set(&o, "duckPosition", position(self.demo.duck().map(|p| p.position)));
        let bodies = js_sys::Object::new();
        for id in BodyId::all() {
            let shown = self.demo.shows(id).then(|| self.demo.body(id).pose.position);
            set(&bodies, id.kind().name, position(shown));
        }
        set(&o, "bodies", bodies);
        set(&o, "submergedVolume", self.demo.submerged_volume() as f64);
        let costs = js_sys::Object::new();
        for (mode, name) in
            [(RenderMode::RayTraced, "raytraced"), (RenderMode::Flat, "flat"), (RenderMode::Split, "split")]
        {
            set(&costs, name, self.mode_costs.of(mode).map_or(JsValue::NULL, JsValue::from_f64));
        }
        set(&o, "gpuMs", if self.timer.is_some() { JsValue::from(costs) } else { JsValue::NULL });
        // The latest measured frame's GPU time per stage (ms), where the browser measures it.
        let stages = self.timer.as_ref().and_then(StageTimer::latest).map_or(JsValue::NULL, |ms| {
            let o = js_sys::Object::new();
            for (name, v) in self.demo.stage_names().iter().zip(ms) {
                set(&o, name, v);
            }
            JsValue::from(o)
        });
        set(&o, "stageMs", stages);
        let note = self.demo.flat_water_note();
        let text = note.and_then(crate::page_words::english);
        set(&o, "flatNote", text.map_or(JsValue::NULL, JsValue::from_str));
        set(&o, "flatNoteId", note.map_or(JsValue::NULL, JsValue::from_str));
        let reduced: js_sys::Array = self
            .reduced
            .iter()
            .map(|&(name, asked, given)| {
                let r = js_sys::Object::new();
                set(&r, "name", name);
                set(&r, "asked", asked);
                set(&r, "given", given);
                JsValue::from(r)
            })
            .collect();
        set(&o, "reduced", reduced);
        o
    }
}
