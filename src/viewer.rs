//! The desktop viewer: an eframe window with the pool next to an egui panel generated from the
//! parameter table. The scene is drawn by the same `WaterDemo` as in the browser, on egui's own
//! wgpu device, into a texture that egui shows as an image; pointer, wheel and keys go through
//! the core's input API. `--frames N --screenshot FILE.png` saves what the window showed after
//! N frames and closes it (used by CI under Xvfb).

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use eframe::egui;

use wavepool::demo::{DemoOptions, FrameContext, Key, WaterDemo};
use wavepool::optics::{self, FresnelModel};
use wavepool::params::{self, table, Control, Param, ParamId};
use wavepool::presets::{Preset, PRESETS};
use wavepool::render::flat::ModeCosts;
use wavepool::render::RenderMode;
use wavepool::timing::{StageTimer, TIMESTAMP_FEATURES};

use crate::catalogue::{self, Catalogue};

/// Format of the texture the scene is drawn into; egui samples it like its own sRGB textures.
const SCENE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// How the viewer runs.
#[derive(Clone, Debug, Default)]
pub struct ViewerOptions {
    /// Close after this many frames (with `screenshot`, after saving it).
    pub frames: Option<u32>,
    /// Where to save a PNG of the window after `frames` frames.
    pub screenshot: Option<PathBuf>,
    /// Starting options of the demo (simulation size, meshes).
    pub demo: DemoOptions,
    /// A lesson preset to start from (before `sets`).
    pub preset: Option<&'static Preset>,
    /// Starting parameter values by name (already checked against the table).
    pub sets: Vec<(String, f32)>,
    /// What was drawn in the tank (a share link's `sketch`), if given.
    pub sketch: Option<String>,
    /// The panel's language (a tag `Catalogue::load` takes; checked by the command line).
    pub lang: String,
}

/// Opens the window and runs until it is closed (or the frame count is reached).
pub fn run(options: ViewerOptions) -> Result<(), String> {
    // egui's usual device, plus timestamp queries where the adapter has them (GPU time per stage).
    let mut setup = egui_wgpu::WgpuSetupCreateNew::without_display_handle();
    let base = setup.device_descriptor.clone();
    setup.device_descriptor = Arc::new(move |adapter| {
        let mut descriptor = base(adapter);
        descriptor.required_features |= adapter.features() & TIMESTAMP_FEATURES;
        descriptor
    });
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default().with_title("wavepool").with_inner_size([1100.0, 680.0]),
        renderer: eframe::Renderer::Wgpu,
        wgpu_options: egui_wgpu::WgpuConfiguration {
            wgpu_setup: egui_wgpu::WgpuSetup::CreateNew(setup),
            ..Default::default()
        },
        ..Default::default()
    };
    let outcome = Arc::new(Mutex::new(None::<Result<(), String>>));
    let app_outcome = outcome.clone();
    eframe::run_native(
        "wavepool",
        native,
        Box::new(move |cc| {
            let state = cc.wgpu_render_state.as_ref().ok_or("eframe started without a wgpu renderer")?;
            Ok(Box::new(Viewer::new(state, options, app_outcome)))
        }),
    )
    .map_err(|e| format!("could not open the viewer window: {e}"))?;
    let result = outcome.lock().map(|o| o.clone()).unwrap_or(None);
    result.unwrap_or(Ok(()))
}

/// The texture the scene is drawn into, and its id for egui.
struct SceneTarget {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    id: egui::TextureId,
}

struct Viewer {
    demo: WaterDemo,
    render_state: egui_wgpu::RenderState,
    /// GPU time per stage, where the device has timestamp queries.
    timer: Option<StageTimer>,
    /// Each render mode's drawing time, from the timer.
    mode_costs: ModeCosts,
    target: Option<SceneTarget>,
    options: ViewerOptions,
    frames: u32,
    last_frame: Option<Instant>,
    /// Smoothed CPU time of recording and submitting a frame (ms) and interval between frames (ms).
    cpu_ms: f32,
    interval_ms: f32,
    /// Whether the primary button went down on the pool and is still held.
    pressing: bool,
    last_pointer: Option<egui::Pos2>,
    /// Set when the screenshot was requested; filled by the callback with the outcome.
    screenshot: Option<Outcome>,
    outcome: Outcome,
    /// The panel's words.
    words: Catalogue,
}

/// Where the screenshot callback leaves its outcome (`None` until it has run).
type Outcome = Arc<Mutex<Option<Result<(), String>>>>;

use eframe::egui_wgpu;

impl Viewer {
    fn new(state: &egui_wgpu::RenderState, options: ViewerOptions, outcome: Outcome) -> Self {
        let mut demo = WaterDemo::new(&state.device, &state.queue, SCENE_FORMAT, options.demo);
        if let Some(preset) = options.preset {
            demo.apply_preset(preset);
        }
        for (name, value) in &options.sets {
            let _ = demo.params.set_by_name(name, *value);
        }
        if let Some(Err(why)) = options.sketch.as_deref().map(|text| demo.set_sketch(text)) {
            eprintln!("wavepool: --sketch ignored: {why}");
        }
        if demo.params.get(ParamId::Paused) == 0.0 {
            demo.add_start_drops();
        }
        let words = Catalogue::load(&options.lang).unwrap_or_else(|e| {
            eprintln!("wavepool: {e}; the panel is in English");
            Catalogue::load("en").expect("English is the tables'")
        });
        Self {
            words,
            demo,
            render_state: state.clone(),
            timer: StageTimer::new(&state.device, &state.queue),
            mode_costs: ModeCosts::default(),
            target: None,
            options,
            frames: 0,
            last_frame: None,
            cpu_ms: 0.0,
            interval_ms: 0.0,
            pressing: false,
            last_pointer: None,
            screenshot: None,
            outcome,
        }
    }

    /// The scene texture at `size` pixels, made (and registered with egui) when the size changes.
    fn target(&mut self, size: (u32, u32)) -> &SceneTarget {
        let stale = self.target.as_ref().is_none_or(|t| (t.texture.width(), t.texture.height()) != size);
        if stale {
            let device = &self.render_state.device;
            let texture = wavepool::gpu::texture_2d(
                device,
                "viewer scene",
                (size.0, size.1, 1),
                1,
                SCENE_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            );
            let view = texture.create_view(&Default::default());
            let mut renderer = self.render_state.renderer.write();
            let id = match &self.target {
                Some(old) => {
                    renderer.update_egui_texture_from_wgpu_texture(device, &view, wgpu::FilterMode::Linear, old.id);
                    old.id
                }
                None => renderer.register_native_texture(device, &view, wgpu::FilterMode::Linear),
            };
            self.target = Some(SceneTarget { texture, view, id });
        }
        self.target.as_ref().expect("target just made")
    }

    /// The parameter panel: one group per table group, a control per parameter with its unit
    /// and a reset-to-default button, then whole-demo buttons and the frame times.
    fn panel(&mut self, ui: &mut egui::Ui) {
        ui.heading("wavepool");
        egui::ScrollArea::vertical().show(ui, |ui| {
            self.language_menu(ui);
            self.preset_menu(ui);
            let mut groups: Vec<&str> = Vec::new();
            for p in table() {
                if !groups.contains(&p.group) {
                    groups.push(p.group);
                }
            }
            // A model's own settings only while that model is chosen, a scene's in that scene;
            // a group with none of them shown not at all.
            let params = &self.demo.params;
            let shown = |spec: &&params::Param| {
                wavepool::scenes::shown_when(spec.name)
                    .iter()
                    .all(|(on, values)| values.contains(&params.get_by_name(on).expect("a parameter of the table")))
            };
            let shown: Vec<&params::Param> = table().iter().filter(shown).collect();
            for group in groups.into_iter().filter(|g| shown.iter().any(|p| p.group == *g)) {
                egui::CollapsingHeader::new(self.words.group(group)).id_salt(group).default_open(true).show(ui, |ui| {
                    for spec in shown.iter().filter(|p| p.group == group) {
                        self.control(ui, spec);
                    }
                    if group == "Optics" {
                        let model: FresnelModel = self.demo.params.choice(ParamId::Fresnel);
                        fresnel_plot(ui, model, 90.0 - self.demo.camera().pitch.abs(), &self.words);
                    }
                });
            }
            if let Some(picked) = self.demo.picked() {
                let title =
                    self.words.page_with(picked.title_id, &[("number", picked.number.to_string())]).into_owned();
                egui::CollapsingHeader::new(title).id_salt("picked").default_open(true).show(ui, |ui| {
                    for (spec, value) in picked.settings {
                        if let Some(value) = picked_slider(ui, spec, value, &self.words) {
                            let _ = self.demo.set_picked(spec.name, value);
                        }
                    }
                });
            }
            ui.separator();
            ui.horizontal(|ui| {
                let words = &self.words;
                let reset = ui.button(words.page("viewer-reset-water"));
                if reset.on_hover_text(words.page("viewer-reset-water.title")).clicked() {
                    self.demo.reset(&self.render_state.queue);
                }
                if ui.button(words.page("defaults")).on_hover_text(words.page("defaults.title")).clicked() {
                    for p in table() {
                        self.demo.params.reset_at(p.index);
                    }
                }
            });
            self.frame_status(ui);
        });
    }

    /// The lessons' presets: a lesson's starting state, its values and view, with calm water
    /// (as the page's select).
    fn preset_menu(&mut self, ui: &mut egui::Ui) {
        let mut chosen: Option<&'static Preset> = None;
        let words = &self.words;
        egui::ComboBox::from_label(words.page("preset"))
            .selected_text(words.page("preset-choose"))
            .show_ui(ui, |ui| {
                for preset in PRESETS {
                    let item = ui.selectable_label(false, words.preset_label(preset));
                    if item.on_hover_text(words.preset_help(preset)).clicked() {
                        chosen = Some(preset);
                    }
                }
            })
            .response
            .on_hover_text(words.page("preset.title"));
        if let Some(preset) = chosen {
            self.demo.apply_preset(preset);
            self.demo.reset(&self.render_state.queue);
        }
    }

    /// Under the panel's controls: the frame's times (CPU, between frames, the GPU's stages and
    /// the render modes' costs), the flat water's note, the water, the adapter and the scene's
    /// readings.
    fn frame_status(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        let w = &self.words;
        let (cpu, between) = (w.number(self.cpu_ms.into(), 1), w.number(self.interval_ms.into(), 1));
        ui.label(w.page_with("viewer-frame", &[("cpu", cpu), ("between", between)]));
        match self.timer.as_ref().and_then(|t| t.latest()) {
            Some(ms) => {
                let names = self.demo.stage_names();
                let stages: Vec<String> =
                    names.iter().zip(ms).map(|(n, v)| format!("{} {} ms", w.stage(n), w.number(v, 1))).collect();
                ui.label(w.page_with("viewer-gpu", &[("stages", stages.join(", "))]))
            }
            None if self.timer.is_none() => ui.label(w.page("viewer-gpu-none")),
            None => ui.label(w.page("viewer-gpu-waiting")),
        };
        let pool = self.demo.render_modes_apply();
        if let Some(stages) = self.timer.as_ref().and_then(|t| t.latest()).filter(|_| pool) {
            let mode = self.demo.params.choice::<RenderMode>(ParamId::RenderMode);
            self.mode_costs.observe(mode, stages);
            let spec = table()[ParamId::RenderMode as usize].spec;
            let costs = self.mode_costs.summary_named(|mode| self.words.choice(spec, mode.value()));
            ui.label(self.words.page_with("viewer-costs", &[("costs", costs)]));
        }
        let w = &self.words;
        if let Some(note) = self.demo.flat_water_note() {
            ui.colored_label(egui::Color32::from_rgb(230, 180, 60), w.page(note));
        }
        let (cells, seconds) = (self.demo.water().size().to_string(), w.number(self.demo.sim_time(), 1));
        ui.label(w.page_with("viewer-water", &[("cells", cells), ("seconds", seconds)]));
        ui.label(w.page_with("viewer-adapter", &[("name", self.render_state.adapter.get_info().name)]));
        for (name, value, unit) in self.demo.readings() {
            ui.label(format!(
                "{}: {} {unit}",
                w.page(&format!("reading-{}", name.replace(' ', "-"))),
                w.number(value.into(), 2)
            ));
        }
        ui.small(w.page("page-intro"));
    }

    /// The panel's language: the catalogues' languages, each named in its own words.
    fn language_menu(&mut self, ui: &mut egui::Ui) {
        let mut chosen = None;
        let shown = catalogue::languages().find(|l| l.0 == self.words.tag).map_or("", |l| l.1);
        egui::ComboBox::from_label(self.words.page("language")).selected_text(shown).show_ui(ui, |ui| {
            for (tag, name) in catalogue::languages() {
                if ui.selectable_label(tag == self.words.tag, name).clicked() {
                    chosen = Some(tag);
                }
            }
        });
        if let Some(words) = chosen.and_then(|tag| Catalogue::load(tag).ok()) {
            self.words = words;
        }
    }

    fn control(&mut self, ui: &mut egui::Ui, spec: &Param) {
        let mut value = self.demo.params.get_at(spec.index);
        let (label, help) = (self.words.label(spec), self.words.help(spec));
        let words = &self.words;
        ui.horizontal(|ui| {
            let changed = match spec.control {
                Control::Slider { min, max, step } => {
                    let suffix =
                        if spec.unit.is_empty() { String::new() } else { format!(" {}", words.unit(spec.unit)) };
                    // In f64 from the table's decimal values, so that egui's snapping to the
                    // step lands on them exactly (f32 -> f64 casts would drift by an ulp).
                    let mut wide = decimal(value);
                    let slider = egui::Slider::new(&mut wide, decimal(min)..=decimal(max)).step_by(decimal(step));
                    let response =
                        ui.add(localised(slider, step, words).suffix(suffix).text(label)).on_hover_text(help);
                    value = wide as f32;
                    response.changed()
                }
                Control::Toggle => {
                    let mut on = value >= 0.5;
                    let r = ui.checkbox(&mut on, label).on_hover_text(help);
                    value = if on { 1.0 } else { 0.0 };
                    r.changed()
                }
                Control::Choice { values, .. } => {
                    let before = value;
                    egui::ComboBox::from_label(label)
                        .selected_text(words.choice(spec, value))
                        .show_ui(ui, |ui| {
                            for &v in values {
                                ui.selectable_value(&mut value, v, words.choice(spec, v));
                            }
                        })
                        .response
                        .on_hover_text(help);
                    value != before
                }
            };
            if changed {
                self.demo.params.set_at(spec.index, value);
            }
            let at_default = self.demo.params.get_at(spec.index) == spec.default;
            if ui
                .add_enabled(!at_default, egui::Button::new(self.words.page("viewer-reset-one")).small())
                .on_hover_text(self.words.page("viewer-reset-one.title"))
                .clicked()
            {
                self.demo.params.reset_at(spec.index);
            }
        });
    }

    /// Pointer, wheel and keys on the pool image, through the core's input API.
    fn input(&mut self, ui: &egui::Ui, response: &egui::Response, pixels_per_point: f32) {
        let to_pixels = |p: egui::Pos2| ((p - response.rect.min) * pixels_per_point).to_pos2();
        let (pressed, down, released, pos, scroll) = ui.input(|i| {
            (
                i.pointer.primary_pressed(),
                i.pointer.primary_down(),
                i.pointer.primary_released(),
                i.pointer.interact_pos(),
                i.smooth_scroll_delta.y,
            )
        });
        if pressed && response.hovered() {
            if let Some(p) = pos.map(to_pixels) {
                self.demo.pointer_down(p.x, p.y);
                self.pressing = true;
                self.last_pointer = Some(p);
            }
        } else if self.pressing && down {
            if let Some(p) = pos.map(to_pixels) {
                if self.last_pointer != Some(p) {
                    self.demo.pointer_move(p.x, p.y);
                    self.last_pointer = Some(p);
                }
            }
        }
        if self.pressing && (released || !down) {
            self.demo.pointer_up();
            self.pressing = false;
        }
        if response.hovered() && scroll != 0.0 {
            self.demo.zoom((-scroll / 40.0).clamp(-3.0, 3.0));
        }
        // Keys reach the pool unless a text field has focus.
        if !ui.ctx().egui_wants_keyboard_input() {
            ui.input(|i| {
                for (key, action) in [(egui::Key::Space, Key::Space), (egui::Key::G, Key::G), (egui::Key::L, Key::L)] {
                    if i.key_pressed(key) {
                        self.demo.key(action);
                    }
                }
                let turn = [
                    (egui::Key::ArrowLeft, (-12.0, 0.0)),
                    (egui::Key::ArrowRight, (12.0, 0.0)),
                    (egui::Key::ArrowUp, (0.0, -12.0)),
                    (egui::Key::ArrowDown, (0.0, 12.0)),
                ];
                for (key, (dx, dy)) in turn {
                    if i.key_pressed(key) {
                        self.demo.camera_mut().orbit(dx, dy);
                    }
                }
                if i.key_pressed(egui::Key::Plus) || i.key_pressed(egui::Key::Equals) {
                    self.demo.zoom(-1.0);
                }
                if i.key_pressed(egui::Key::Minus) {
                    self.demo.zoom(1.0);
                }
            });
        }
    }

    /// After the requested number of frames: a screenshot (if asked), then close.
    fn finish_when_due(&mut self, ctx: &egui::Context) {
        let Some(limit) = self.options.frames else { return };
        if self.frames < limit {
            return;
        }
        match (&self.options.screenshot, &self.screenshot) {
            (Some(path), None) => {
                let slot = Arc::new(Mutex::new(None));
                self.screenshot = Some(slot.clone());
                let path = path.clone();
                ctx.request_screenshot(move |image| {
                    let rgba: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
                    let saved = wavepool::headless::write_png(&path, image.size[0] as u32, image.size[1] as u32, &rgba);
                    if let Ok(mut s) = slot.lock() {
                        *s = Some(saved);
                    }
                });
            }
            (Some(_), Some(slot)) => {
                let done = slot.lock().ok().and_then(|s| s.clone());
                if let Some(saved) = done {
                    if let Ok(mut o) = self.outcome.lock() {
                        *o = Some(saved);
                    }
                    ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                }
            }
            (None, _) => ctx.send_viewport_cmd(egui::ViewportCommand::Close),
        }
    }
}

/// An `f32` as the `f64` with the same shortest decimal form (0.001f32 -> 0.001), so that
/// egui's rounding to the step gives back the table's values exactly.
fn decimal(v: f32) -> f64 {
    v.to_string().parse().unwrap_or(v as f64)
}

impl eframe::App for Viewer {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let now = Instant::now();
        let dt = self.last_frame.map_or(1.0 / 60.0, |t| (now - t).as_secs_f32());
        if let Some(t) = self.last_frame {
            self.interval_ms = 0.9 * self.interval_ms + 0.1 * (now - t).as_secs_f32() * 1000.0;
        }
        self.last_frame = Some(now);

        egui::Panel::left("parameters").resizable(true).default_size(300.0).show(ui, |ui| self.panel(ui));
        egui::CentralPanel::default().frame(egui::Frame::NONE).show(ui, |ui| {
            let pixels_per_point = ui.ctx().pixels_per_point();
            let points = ui.available_size();
            let size = (
                (points.x * pixels_per_point).round().max(1.0) as u32,
                (points.y * pixels_per_point).round().max(1.0) as u32,
            );
            let started = Instant::now();
            let target = self.target(size);
            let (view, id) = (target.view.clone(), target.id);
            let (device, queue) = (&self.render_state.device, &self.render_state.queue);
            let mut encoder = device.create_command_encoder(&Default::default());
            let dt = dt.min(0.25);
            match &mut self.timer {
                Some(timer) => {
                    self.demo.encode_frame(
                        FrameContext { device, queue, encoder: &mut encoder, target: &view, size },
                        dt,
                        &mut |e, s| timer.mark(e, s as u32),
                    );
                    timer.finish(&mut encoder);
                }
                None => self.demo.encode_frame(
                    FrameContext { device, queue, encoder: &mut encoder, target: &view, size },
                    dt,
                    &mut |_, _| {},
                ),
            }
            queue.submit([encoder.finish()]);
            self.demo.after_submit();
            if let Some(timer) = &self.timer {
                timer.after_submit();
            }
            self.cpu_ms = 0.9 * self.cpu_ms + 0.1 * started.elapsed().as_secs_f32() * 1000.0;
            let image = egui::Image::new((id, points)).sense(egui::Sense::click_and_drag());
            let response = ui.add(image);
            self.input(ui, &response, pixels_per_point);
        });
        self.frames += 1;
        self.finish_when_due(ui.ctx());
        ui.ctx().request_repaint();
    }
}

/// Reflectance against the angle of incidence, as the page draws it (web/fresnel-plot.js):
/// `model` (blue) over the exact curve (grey), from air solid and from under the water dashed,
/// and a mark at `view_deg`, the angle at which the view's centre meets the water.
fn fresnel_plot(ui: &mut egui::Ui, model: FresnelModel, view_deg: f32, words: &Catalogue) {
    const SAMPLES: usize = 91;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(220.0, 110.0), egui::Sense::hover());
    let area = rect.shrink2(egui::vec2(8.0, 6.0));
    let painter = ui.painter_at(rect);
    let at = |deg: f32, r: f32| egui::pos2(area.left() + deg / 90.0 * area.width(), area.bottom() - r * area.height());
    let faint = ui.visuals().weak_text_color();
    painter.rect_stroke(area, 0.0, egui::Stroke::new(1.0, faint), egui::StrokeKind::Inside);
    for (from_water, dashed) in [(true, true), (false, false)] {
        for (m, stroke) in [
            (FresnelModel::Exact, egui::Stroke::new(3.0, egui::Color32::from_gray(138))),
            (model, egui::Stroke::new(1.5, egui::Color32::from_rgb(31, 111, 209))),
        ] {
            let curve = optics::reflectance_curve(m, from_water, SAMPLES);
            let points: Vec<egui::Pos2> =
                curve.iter().enumerate().map(|(i, &r)| at(i as f32 * 90.0 / (SAMPLES - 1) as f32, r)).collect();
            if dashed {
                painter.extend(egui::Shape::dashed_line(&points, stroke, 4.0, 3.0));
            } else {
                painter.add(egui::Shape::line(points, stroke));
            }
        }
    }
    let x = at(view_deg.clamp(0.0, 90.0), 0.0).x;
    painter.line_segment(
        [egui::pos2(x, area.top()), egui::pos2(x, area.bottom())],
        egui::Stroke::new(1.5, egui::Color32::from_rgb(209, 70, 31)),
    );
    ui.label(egui::RichText::new(words.page("fresnel-caption")).small());
}

/// A slider whose value is written with the language's decimal mark, to the decimals of its
/// step (as the page writes it), and read with either mark.
fn localised<'a>(slider: egui::Slider<'a>, step: f32, words: &'a Catalogue) -> egui::Slider<'a> {
    let decimals = (-(step as f64).log10().floor()).max(0.0) as usize;
    slider
        .custom_formatter(move |v, _| words.number(v, decimals))
        .custom_parser(|text| text.trim().replace(',', ".").parse().ok())
}

/// A slider for a setting of what the pointer picked (`spec` is a slider's): its new value
/// when moved.
fn picked_slider(
    ui: &mut egui::Ui,
    spec: &wavepool::param_spec::ParamSpec,
    value: f32,
    words: &Catalogue,
) -> Option<f32> {
    let Control::Slider { min, max, step } = spec.control else { return None };
    let mut wide = decimal(value);
    let slider = egui::Slider::new(&mut wide, decimal(min)..=decimal(max)).step_by(decimal(step));
    let slider = localised(slider, step, words);
    let suffix = if spec.unit.is_empty() { String::new() } else { format!(" {}", words.unit(spec.unit)) };
    let response = ui.add(slider.suffix(suffix).text(words.label(spec))).on_hover_text(words.help(spec));
    response.changed().then_some(wide as f32)
}
