//! The browser shell: wasm-bindgen bindings that hand the page's JavaScript (`web/embed.js`)
//! a [`WebDemo`] around the platform-free core, drawing into a canvas through WebGPU or
//! WebGL2. Everything about the page (DOM, events, sizing, the frame loop) lives in the JS.

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Arc, Mutex};

use wasm_bindgen::prelude::*;

use crate::demo::{DemoBuild, DemoOptions, FrameContext, Key, SizeCaps, WaterDemo, SOFTWARE_CAPS};
use crate::params::{self, ParamId};
use crate::render::flat::ModeCosts;
use crate::render::RenderMode;
use crate::timing::StageTimer;
use tables::to_js_number;

mod picked;
mod stats;
mod tables;

/// Runs once when the module is instantiated: a panic goes to the console (with a stack)
/// and to the page, as a `wavepool:panic` event whose detail is the message.
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        if let Some(window) = web_sys::window() {
            let init = web_sys::CustomEventInit::new();
            init.set_detail(&JsValue::from_str(&info.to_string()));
            if let Ok(event) = web_sys::CustomEvent::new_with_event_init_dict("wavepool:panic", &init) {
                let _ = window.dispatch_event(&event);
            }
        }
    }));
}

/// Whether the adapter can render into the float formats the GPU simulation and the float
/// caustics map use, and blend the latter (WebGL2 needs EXT_color_buffer_float for it).
fn float_targets(adapter: &wgpu::Adapter) -> bool {
    use wgpu::TextureFormat as F;
    let features = |f: F| adapter.get_texture_format_features(f);
    let renders = |f: F| features(f).allowed_usages.contains(wgpu::TextureUsages::RENDER_ATTACHMENT);
    renders(F::Rgba32Float)
        && renders(F::Rg16Float)
        && features(F::Rg16Float).flags.contains(wgpu::TextureFormatFeatureFlags::BLENDABLE)
}

/// The canvas's colour format. WebGPU: the browser's preferred one (`getPreferredCanvasFormat`,
/// which wgpu lists first), since a browser may composite only that one: Firefox's software
/// compositor aborts the whole browser on an `rgba8unorm` canvas where it prefers `bgra8unorm`.
/// WebGL2: an 8-bit sRGB format if offered. The renderer encodes sRGB itself when the
/// format is not sRGB.
fn canvas_format(backend: &str, offered: &[wgpu::TextureFormat]) -> Option<wgpu::TextureFormat> {
    use wgpu::TextureFormat as F;
    if backend == "webgpu" {
        return offered.first().copied();
    }
    [F::Rgba8UnormSrgb, F::Bgra8UnormSrgb, F::Rgba8Unorm, F::Bgra8Unorm]
        .into_iter()
        .find(|f| offered.contains(f))
        .or_else(|| offered.first().copied())
}

/// A canvas format by its WebGPU name ("bgra8unorm", ...), as `getPreferredCanvasFormat` says it.
fn web_format_name(format: wgpu::TextureFormat) -> String {
    use wgpu::TextureFormat as F;
    match format {
        F::Rgba8Unorm => "rgba8unorm".into(),
        F::Rgba8UnormSrgb => "rgba8unorm-srgb".into(),
        F::Bgra8Unorm => "bgra8unorm".into(),
        F::Bgra8UnormSrgb => "bgra8unorm-srgb".into(),
        F::Rgba16Float => "rgba16float".into(),
        other => format!("{other:?}").to_lowercase(),
    }
}

/// Most frames submitted to the GPU and not yet finished. The page draws the next frame only
/// when fewer are in flight ([`WebDemo::can_draw`]): a slow GPU (software rendering) then gets
/// fewer frames instead of a growing queue of them, and a click shows in the next frame drawn.
pub const MAX_FRAMES_IN_FLIGHT: u32 = 1;
/// Time a piece of the start-up's work may take before the next pipeline waits for a later
/// task (ms): a piece then lasts at most this plus one pipeline (≈ 100 ms on WebGL2 on
/// SwiftShader).
pub const PREPARE_BUDGET_MS: f64 = 40.0;

fn warn(message: &str) {
    web_sys::console::warn_1(&JsValue::from_str(message));
}

/// One running demo on one canvas, with its own device.
#[wasm_bindgen]
pub struct WebDemo {
    demo: WaterDemo,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    device: wgpu::Device,
    queue: wgpu::Queue,
    backend: &'static str,
    adapter: String,
    max_side: u32,
    /// The sRGB view format drawn through, when the canvas format itself is not sRGB.
    srgb_view: Option<wgpu::TextureFormat>,
    lost: Arc<Mutex<Option<String>>>,
    /// Frames submitted whose work the GPU has not finished yet.
    in_flight: Arc<AtomicU32>,
    /// GPU time per stage, where the browser has timestamp queries.
    timer: Option<StageTimer>,
    /// Each render mode's drawing time, from the timer.
    mode_costs: ModeCosts,
    /// The sizes this device is held to (a software rasteriser's), if any.
    caps: Option<SizeCaps>,
    /// What the caps reduced: (option or parameter name, asked, given), for the page to say.
    reduced: Vec<(&'static str, u32, u32)>,
    /// Whether `prepare` has nothing left to do before the first frame.
    prepared: bool,
}

/// The demo, made in `DemoBuild`'s steps with a task of the browser's between them.
async fn build_demo(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    format: wgpu::TextureFormat,
    options: DemoOptions,
) -> WaterDemo {
    let mut build = DemoBuild::new(format, options);
    loop {
        next_task().await;
        if let Some(demo) = build.step(device, queue) {
            return demo;
        }
    }
}

/// Resolves in a later task of the browser's event loop: input and painting run between two
/// steps of work (none of which should hold the thread for long).
async fn next_task() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        let later = web_sys::window().map(|w| w.set_timeout_with_callback(&resolve).is_ok());
        if later != Some(true) {
            let _ = resolve.call0(&JsValue::NULL);
        }
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}

/// The browser's adapter for `surface` and a device on it (with timestamp queries where the
/// browser measures GPU time), or a message a student can act on.
async fn open_device(
    instance: &wgpu::Instance,
    surface: &wgpu::Surface<'_>,
    backend: &str,
) -> Result<(wgpu::Adapter, wgpu::Device, wgpu::Queue), JsError> {
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            compatible_surface: Some(surface),
            ..Default::default()
        })
        .await
        .map_err(|e| {
            warn(&format!("wavepool: {backend} adapter request failed: {e}"));
            JsError::new(match backend {
                "webgpu" => {
                    "the browser gave no WebGPU adapter (WebGPU may be turned off, or not offered for this GPU)"
                }
                _ => "the browser gave no WebGL2 context (graphics acceleration may be turned off)",
            })
        })?;
    let (device, queue) = adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("wavepool"),
            // GPU time per stage where the browser measures it (WebGPU's timestamp-query).
            required_features: adapter.features() & wgpu::Features::TIMESTAMP_QUERY,
            required_limits: wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        })
        .await
        .map_err(|e| JsError::new(&format!("could not open the {backend} device ({e})")))?;
    Ok((adapter, device, queue))
}

#[wasm_bindgen]
impl WebDemo {
    /// Opens `backend` ("webgpu" or "webgl2") on `canvas` and builds the scene. Fails with a
    /// readable message when the browser cannot give that backend; a canvas that failed
    /// must not be reused for the other backend (a canvas keeps its first context type).
    /// `allow_float` false forces the path for devices without float render targets, which
    /// is taken anyway when the device lacks them.
    pub async fn create(
        canvas: web_sys::HtmlCanvasElement,
        backend: String,
        sim_size: u32,
        surface_grid: u32,
        caustics_size: u32,
        allow_float: bool,
    ) -> Result<WebDemo, JsError> {
        let (backends, backend) = match backend.as_str() {
            "webgpu" => (wgpu::Backends::BROWSER_WEBGPU, "webgpu"),
            "webgl2" => (wgpu::Backends::GL, "webgl2"),
            other => return Err(JsError::new(&format!("unknown backend '{other}' (use webgpu or webgl2)"))),
        };
        let (width, height) = (canvas.width().max(1), canvas.height().max(1));
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = backends;
        let instance = wgpu::Instance::new(desc);
        let surface = instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| JsError::new(&format!("the canvas refused a {backend} context ({e})")))?;
        let (adapter, device, queue) = open_device(&instance, &surface, backend).await?;
        let lost = Arc::new(Mutex::new(None));
        let flag = lost.clone();
        device.set_device_lost_callback(move |reason, message| {
            if let Ok(mut slot) = flag.lock() {
                *slot = Some(format!("{reason:?}: {message}"));
            }
        });
        let caps = surface.get_capabilities(&adapter);
        let format =
            canvas_format(backend, &caps.formats).ok_or_else(|| JsError::new("the canvas offers no colour format"))?;
        let alpha_mode = if caps.alpha_modes.contains(&wgpu::CompositeAlphaMode::Opaque) {
            wgpu::CompositeAlphaMode::Opaque
        } else {
            caps.alpha_modes.first().copied().unwrap_or(wgpu::CompositeAlphaMode::Auto)
        };
        // WebGPU canvases are plain UNORM, but may be viewed as sRGB: then the blending
        // hardware encodes, instead of a pow() per pixel in every shader.
        let srgb_view = (backend == "webgpu" && !format.is_srgb()).then(|| format.add_srgb_suffix());
        let max_side = device.limits().max_texture_dimension_2d;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: width.min(max_side),
            height: height.min(max_side),
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode,
            view_formats: srgb_view.into_iter().collect(),
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        surface.configure(&device, &config);
        let mut options = DemoOptions::clamped(sim_size, surface_grid, caustics_size);
        options.caustics_size = options.caustics_size.min(max_side);
        options.float_targets = allow_float && float_targets(&adapter);
        // Without a GPU (the browser's software rasteriser) the largest sizes would take
        // seconds a frame and can get the page given up: held to what software affords.
        let caps = (adapter.get_info().device_type == wgpu::DeviceType::Cpu).then_some(SOFTWARE_CAPS);
        let mut reduced = Vec::new();
        if let Some(caps) = caps {
            (options, reduced) = options.capped(caps);
            for (name, asked, given) in &reduced {
                warn(&format!("wavepool: {name} {asked} reduced to {given}: this device draws without a GPU"));
            }
        }
        let demo = build_demo(&device, &queue, srgb_view.unwrap_or(format), options).await;
        Ok(WebDemo {
            demo,
            surface,
            config,
            srgb_view,
            backend,
            adapter: adapter.get_info().name,
            max_side,
            lost,
            in_flight: Arc::new(AtomicU32::new(0)),
            timer: StageTimer::new(&device, &queue),
            mode_costs: ModeCosts::default(),
            caps,
            reduced,
            prepared: false,
            device,
            queue,
        })
    }

    /// Simulated time since the start (s): fixed steps taken times their length.
    #[wasm_bindgen(getter, js_name = simTime)]
    pub fn sim_time(&self) -> f64 {
        self.demo.sim_time()
    }

    /// "webgpu" or "webgl2".
    #[wasm_bindgen(getter)]
    pub fn backend(&self) -> String {
        self.backend.to_owned()
    }

    /// Advances the water by `dt` seconds and draws a `width` x `height` frame (backing
    /// pixels). Fails when the device was lost.
    pub fn frame(&mut self, dt: f32, width: u32, height: u32) -> Result<(), JsError> {
        if let Some(message) = self.lost.lock().ok().and_then(|m| m.clone()) {
            return Err(JsError::new(&format!("the GPU device was lost ({message})")));
        }
        let (width, height) = (width.clamp(1, self.max_side), height.clamp(1, self.max_side));
        if (width, height) != (self.config.width, self.config.height) {
            self.config.width = width;
            self.config.height = height;
            self.surface.configure(&self.device, &self.config);
        }
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t) | wgpu::CurrentSurfaceTexture::Suboptimal(t) => t,
            wgpu::CurrentSurfaceTexture::Outdated => {
                self.surface.configure(&self.device, &self.config);
                return Ok(());
            }
            wgpu::CurrentSurfaceTexture::Lost => return Err(JsError::new("the canvas surface was lost")),
            _ => return Ok(()),
        };
        let view =
            frame.texture.create_view(&wgpu::TextureViewDescriptor { format: self.srgb_view, ..Default::default() });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        let (size, dt) = ((width, height), dt.clamp(0.0, 1.0));
        match &mut self.timer {
            Some(timer) => {
                self.demo.encode_frame(
                    FrameContext {
                        device: &self.device,
                        queue: &self.queue,
                        encoder: &mut encoder,
                        target: &view,
                        size,
                    },
                    dt,
                    &mut |e, s| timer.mark(e, s as u32),
                );
                timer.finish(&mut encoder);
                // The render modes' costs are the pool's (the sea has none of them).
                if let Some(stages) = timer.latest().filter(|_| self.demo.render_modes_apply()) {
                    self.mode_costs.observe(self.demo.params.choice::<RenderMode>(ParamId::RenderMode), stages);
                }
            }
            None => self.demo.encode_frame(
                FrameContext { device: &self.device, queue: &self.queue, encoder: &mut encoder, target: &view, size },
                dt,
                &mut |_, _| {},
            ),
        }
        self.queue.submit([encoder.finish()]);
        self.demo.after_submit();
        if let Some(timer) = &self.timer {
            timer.after_submit();
        }
        self.queue.present(frame);
        self.count_in_flight();
        let _ = self.device.poll(wgpu::PollType::Poll);
        Ok(())
    }

    /// A piece of the work before the first frame of `width` x `height` pixels; true when
    /// none is left (then `frame` draws without a long pause). Call once per animation frame
    /// until true, not after. A piece builds pipelines the frame will draw with for up to
    /// [`PREPARE_BUDGET_MS`] (one or two on WebGL2, where each waits for its shader's
    /// compilation; most of them on WebGPU, which compiles in the GPU process). On WebGL2 the
    /// last piece draws a frame that is not shown, so that the browser's GL process compiles
    /// what drawing needs while the page goes on (a first frame shown would hold the page's
    /// thread until the GPU had done it all: over a second without a GPU).
    pub fn prepare(&mut self, width: u32, height: u32) -> bool {
        if self.lost.lock().map_or(true, |m| m.is_some()) {
            return true; // the next frame reports the loss
        }
        let size = (width.clamp(1, self.max_side), height.clamp(1, self.max_side));
        let start = js_sys::Date::now();
        while !self.prepared {
            if self.demo.build_ahead(&self.device, size) {
                self.prepared = true;
                if self.backend == "webgl2" {
                    self.draw_unshown(size);
                }
            } else if js_sys::Date::now() - start > PREPARE_BUDGET_MS {
                return false;
            }
        }
        // The first frame waits for the GPU to be done with the unshown one.
        let _ = self.device.poll(wgpu::PollType::Poll);
        self.in_flight.load(Ordering::Acquire) == 0 || self.lost.lock().map_or(true, |m| m.is_some())
    }

    /// Draws a frame of `size` pixels into a texture of its own, not shown.
    fn draw_unshown(&mut self, size: (u32, u32)) {
        let format = self.srgb_view.unwrap_or(self.config.format);
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let target = crate::gpu::texture_2d(&self.device, "unshown frame", (size.0, size.1, 1), 1, format, usage);
        let view = target.create_view(&Default::default());
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.demo.encode_frame(
            FrameContext { device: &self.device, queue: &self.queue, encoder: &mut encoder, target: &view, size },
            1.0 / 60.0,
            &mut |_, _| {},
        );
        self.queue.submit([encoder.finish()]);
        self.demo.after_submit();
        self.count_in_flight();
    }

    /// Counts a submitted frame as in flight until the GPU has done its work.
    fn count_in_flight(&self) {
        self.in_flight.fetch_add(1, Ordering::AcqRel);
        let in_flight = self.in_flight.clone();
        self.queue.on_submitted_work_done(move || {
            in_flight.fetch_sub(1, Ordering::AcqRel);
        });
    }

    /// Whether the GPU has finished enough of the submitted frames to take another (fewer
    /// than [`MAX_FRAMES_IN_FLIGHT`] in flight). Never waits. True once the device is lost,
    /// so that the next `frame` reports it.
    #[wasm_bindgen(js_name = canDraw)]
    pub fn can_draw(&self) -> bool {
        let _ = self.device.poll(wgpu::PollType::Poll);
        self.in_flight.load(Ordering::Acquire) < MAX_FRAMES_IN_FLIGHT || self.lost.lock().map_or(true, |m| m.is_some())
    }

    /// Sets a parameter by name; an out-of-range value is clamped with a console warning.
    /// Returns the value now in effect. Unknown names are an error listing the known ones.
    pub fn set(&mut self, name: &str, value: f64) -> Result<f64, JsError> {
        let sim_name = params::spec(ParamId::SimSize).name;
        let value = match self.caps {
            Some(caps) if name == sim_name => {
                // What `reduced` says of the grid is about this value, whatever came before.
                self.reduced.retain(|r| r.0 != sim_name);
                if value > caps.sim_size as f64 {
                    warn(&format!(
                        "wavepool: {name} {value} reduced to {}: this device draws without a GPU",
                        caps.sim_size
                    ));
                    self.reduced.push((sim_name, value as u32, caps.sim_size));
                }
                value.min(caps.sim_size as f64)
            }
            _ => value,
        };
        let out = self.demo.params.set_by_name(name, value as f32).map_err(|e| JsError::new(&e.to_string()))?;
        if out.clamped {
            let spec = params::find(name).expect("known");
            warn(&format!(
                "wavepool: {name} = {value} is outside [{}, {}]; using {}",
                spec.min(),
                spec.max(),
                out.value
            ));
        }
        Ok(to_js_number(out.value))
    }

    pub fn get(&self, name: &str) -> Result<f64, JsError> {
        self.demo.params.get_by_name(name).map(to_js_number).map_err(|e| JsError::new(&e.to_string()))
    }

    /// A drop at x, z in the shown scene's water (m: the pool's [-1, 1], the sea's patch
    /// [-16, 16]) of `radius` (m) and `strength` (m), as the parameters give them (the sea grows
    /// them with its patch); values are clamped into the water and the parameter ranges (with a
    /// console warning).
    #[wasm_bindgen(js_name = addDrop)]
    pub fn add_drop(&mut self, x: f64, z: f64, radius: f64, strength: f64) {
        for (name, value) in [("drop_radius", radius), ("drop_strength", strength)] {
            let spec = params::find(name).expect("known");
            if spec.sanitise(value as f32) != value as f32 {
                warn(&format!("wavepool: addDrop {name} {value} is outside [{}, {}]", spec.min(), spec.max()));
            }
        }
        let (w, water) = self.demo.drop_area();
        if x.abs() > w as f64 || z.abs() > w as f64 {
            warn(&format!("wavepool: addDrop at ({x}, {z}) is outside {water} [-{w}, {w}]; clamped"));
        }
        // A script's drop is a press of its own (a tool's stroke does not continue).
        self.demo.begin_stroke();
        self.demo.add_drop(x as f32, z as f32, radius as f32, strength as f32);
    }

    /// What was drawn in the shown scene with the pointer (the tank's walls and ruler), as
    /// text for a share link ("" if nothing).
    pub fn sketch(&self) -> String {
        self.demo.sketch()
    }

    /// Puts back what `text` (from `sketch()`) says was drawn; a text that cannot be read
    /// changes nothing and warns in the console.
    #[wasm_bindgen(js_name = setSketch)]
    pub fn set_sketch(&mut self, text: &str) {
        if let Err(why) = self.demo.set_sketch(text) {
            warn(&format!("wavepool: sketch \"{text}\" ignored: {why}"));
        }
    }

    /// Drops the pool with the drops it starts with (the `start_drops` parameter).
    #[wasm_bindgen(js_name = startDrops)]
    pub fn start_drops(&mut self) {
        self.demo.add_start_drops();
    }

    /// Flattens the water and puts the sphere back.
    pub fn reset(&mut self) {
        self.demo.reset(&self.queue);
    }

    #[wasm_bindgen(js_name = pointerDown)]
    pub fn pointer_down(&mut self, x: f32, y: f32) {
        self.demo.pointer_down(x, y);
    }

    /// Whether a press at (x, y) pixels would grab the split view's divider (for the cursor).
    #[wasm_bindgen(js_name = overDivider)]
    pub fn over_divider(&self, x: f32, _y: f32) -> bool {
        self.demo.over_divider(x)
    }

    #[wasm_bindgen(js_name = pointerMove)]
    pub fn pointer_move(&mut self, x: f32, y: f32) {
        self.demo.pointer_move(x, y);
    }

    #[wasm_bindgen(js_name = pointerUp)]
    pub fn pointer_up(&mut self) {
        self.demo.pointer_up();
    }

    /// Positive moves the camera away (one wheel notch is about 1).
    pub fn zoom(&mut self, amount: f32) {
        self.demo.zoom(amount);
    }

    /// Turns the camera by pixel-like amounts (arrow keys).
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.demo.camera_mut().orbit(dx, dy);
    }

    /// A key by its `KeyboardEvent.code`; true when the demo used it.
    pub fn key(&mut self, code: &str) -> bool {
        let key = match code {
            "Space" => Key::Space,
            "KeyG" => Key::G,
            "KeyL" => Key::L,
            _ => return false,
        };
        self.demo.key(key);
        true
    }

    /// The camera as `[yaw, pitch, distance]` (degrees, degrees, m).
    pub fn camera(&self) -> Vec<f32> {
        let c = self.demo.camera();
        vec![c.yaw, c.pitch, c.distance]
    }

    /// Puts the camera at `yaw`, `pitch` (degrees) and `distance` (m); values outside the
    /// camera's ranges are clamped with a console warning.
    #[wasm_bindgen(js_name = setCamera)]
    pub fn set_camera(&mut self, yaw: f32, pitch: f32, distance: f32) {
        self.demo.sync_scene();
        let mut camera = *self.demo.camera();
        let finite = |v: f32, current: f32| if v.is_finite() { v } else { current };
        camera.yaw = finite(yaw, camera.yaw);
        camera.pitch = finite(pitch, camera.pitch);
        camera.distance = finite(distance, camera.distance);
        camera.clamp();
        if !yaw.is_finite() || camera.pitch != pitch || camera.distance != distance {
            let (limits, (y, p, d)) = (camera.limits, (camera.yaw, camera.pitch, camera.distance));
            let ranges = format!("yaw any, pitch {:?}, distance {:?}", limits.pitch, limits.distance);
            warn(&format!("wavepool: camera ({yaw}, {pitch}, {distance}) is outside {ranges}; using ({y}, {p}, {d})"));
        }
        *self.demo.camera_mut() = camera;
    }

    /// Where a point of the pool (x, y, z in m; the water rests at y = 0, the pool spans
    /// -1..1) appears on the canvas, as `[x, y]` in backing pixels; empty when behind the camera.
    pub fn project(&self, x: f32, y: f32, z: f32) -> Vec<f32> {
        let size = glam::Vec2::new(self.config.width as f32, self.config.height as f32);
        self.demo.camera().project(glam::Vec3::new(x, y, z), size).map_or(Vec::new(), |p| vec![p.x, p.y])
    }

    /// Releases the GPU device now (WebGPU: `GPUDevice.destroy()`) instead of whenever the
    /// garbage collector gets to it; call just before `free()`. The page's WebGL context is
    /// released by the page (`WEBGL_lose_context`), which owns the canvas.
    pub fn dispose(&self) {
        self.device.destroy();
    }

    /// Destroys the GPU device the way a driver reset loses it, for the test of the
    /// recovery path: the next `frame` fails with "lost".
    #[doc(hidden)]
    #[wasm_bindgen(js_name = loseDeviceForTests)]
    pub fn lose_device_for_tests(&self) {
        self.device.destroy();
    }
}
