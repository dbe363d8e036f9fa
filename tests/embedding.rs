//! The demo in a course page, in headless Chromium: a strict Content-Security-Policy runs it
//! with no violation and one without 'wasm-unsafe-eval' gets a message naming that directive;
//! with prefers-reduced-motion the demo starts paused and still until play is pressed; the
//! fullscreen button is there only where the page allows fullscreen and fills the screen;
//! Reset returns to the page's own start (parameters and camera), not the table's defaults;
//! Enter on the focused pool makes a drop; twelve demos on a long page start when scrolled to
//! and hold at most 8 GPU contexts. Needs `dist/`.

// One browser at a time, held across awaits: each test runs on its own thread and runtime.
#![allow(clippy::await_holding_lock)]

#[path = "support/browser.rs"]
mod support;

#[path = "support/catalogues.rs"]
mod catalogues;

use std::time::Duration;

use serde_json::{json, Value};
use support::{canvas_rect_js, serial, Browser, Graphics, Rect, StaticServer, MESSAGE_JS, READY};

/// Clicks the centre of an element of the demo's shadow root (real pointer events).
async fn click_in_demo(browser: &Browser, selector: &str) {
    let r = browser
        .js(&format!(
            "const e = document.querySelector('#pool').shadowRoot.querySelector('{selector}');
             if (!e) return null;
             e.scrollIntoView({{ block: 'center' }});
             const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];"
        ))
        .await;
    let (x, y) = (r[0].as_f64().expect("element found"), r[1].as_f64().expect("element found"));
    browser.click_at(x, y).await;
}

#[tokio::test]
async fn a_strict_content_security_policy_runs_the_demo_and_one_without_wasm_says_what_it_needs() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/test/csp.html?quality=1")).await;
    browser.wait_ready("#pool", READY).await;
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let shot = browser.screenshot().await;
    let spread = shot.luma_spread(rect);
    if let Some(dir) = std::env::var_os("WAVEPOOL_DUMP_FRAMES") {
        let path = std::path::Path::new(&dir).join("csp.png");
        let mut encoder = png::Encoder::new(std::fs::File::create(&path).expect("dump"), shot.width, shot.height);
        encoder.set_color(png::ColorType::Rgba);
        encoder.write_header().expect("png").write_image_data(&shot.rgba).expect("png");
        println!("rect {rect:?}, screenshot in {}", path.display());
    }
    let violations = browser.js("return window.__violations;").await;
    println!("strict CSP: luma spread {spread:.1}, violations {violations}");
    assert!(spread > 12.0, "the canvas looks flat under the strict policy");
    assert_eq!(violations, json!([]), "policy violations");

    browser.goto(&server.url("/test/csp-no-wasm.html")).await;
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    let message = browser.js(MESSAGE_JS).await;
    println!("without 'wasm-unsafe-eval': {message}");
    assert!(failed, "no error state: {message}");
    assert!(message.as_str().unwrap_or("").contains("'wasm-unsafe-eval'"), "message: {message}");
    browser.close().await;
}

#[tokio::test]
async fn with_reduced_motion_the_demo_starts_still_until_play_is_pressed() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    let reduce = json!({ "features": [{ "name": "prefers-reduced-motion", "value": "reduce" }] });
    browser.cdp("Emulation.setEmulatedMedia", reduce).await;
    // The default scene (the objects fall in at the start) at a fixed resolution.
    browser.goto(&server.url("/?quality=1")).await;
    browser.wait_ready("#pool", READY).await;
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let first = browser.screenshot().await;
    let before = browser.js("return window.demo.stats();").await;
    tokio::time::sleep(Duration::from_secs(2)).await; // a span in which running water would move
    let second = browser.screenshot().await;
    let after = browser.js("return { s: window.demo.stats(), paused: window.demo.get('paused') };").await;
    let still = first.changed_fraction(&second, rect, 4);
    println!(
        "reduced motion: paused {}, simulated {} s, {:.2}% of the canvas changed over 2 s, sphere {} -> {}",
        after["paused"],
        after["s"]["simTime"],
        still * 100.0,
        before["spherePosition"],
        after["s"]["spherePosition"]
    );
    assert_eq!(after["paused"], 1.0, "not paused at the start");
    assert_eq!(after["s"]["simTime"], 0.0, "the water moved");
    assert_eq!(before["spherePosition"], after["s"]["spherePosition"], "the sphere moved");
    assert!(still < 0.001, "{:.2}% of the canvas changed while still", still * 100.0);
    let label = browser.js("return document.querySelector('#pool').shadowRoot.querySelector('.play').ariaLabel;").await;
    assert_eq!(label, "Play");
    click_in_demo(&browser, ".overlay .play").await;
    let moving = browser.wait_for("window.demo.stats().simTime > 0.5", Duration::from_secs(30)).await;
    let label = browser.js("return document.querySelector('#pool').shadowRoot.querySelector('.play').ariaLabel;").await;
    assert!(moving, "play did not start the water");
    assert_eq!(label, "Pause");
    browser.close().await;
}

#[tokio::test]
async fn fullscreen_is_offered_only_where_the_page_allows_it_and_fills_the_screen() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    // In an iframe whose page does not allow fullscreen (allow="fullscreen 'none'", as for a
    // cross-origin frame without allow="fullscreen"): no button.
    browser
        .goto(&server.url("/test/frame.html?width=640&height=600&allow=fullscreen%20'none'&src=/%3Fquality%3D0.5"))
        .await;
    let framed = "const d = document.getElementById('frame').contentDocument; const h = d && d.querySelector('#pool');
                  if (!h || h.dataset.ready !== 'true') return null;
                  return { enabled: d.fullscreenEnabled, button: !!h.shadowRoot.querySelector('.fullscreen'),
                           play: !!h.shadowRoot.querySelector('.play') };";
    let mut state = Value::Null;
    for _ in 0..600 {
        state = browser.js(framed).await;
        if !state.is_null() {
            break;
        }
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    println!("in a frame without permission: {state}");
    assert_eq!(state, json!({ "enabled": false, "button": false, "play": true }));
    // The page itself: the button is there and a click fills the screen with the pool.
    browser.goto(&server.url("/?quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    click_in_demo(&browser, ".overlay .fullscreen").await;
    let full = browser
        .wait_for("document.fullscreenElement === document.querySelector('#pool')", Duration::from_secs(10))
        .await;
    // The canvas follows the screen's size at its next frame.
    browser
        .wait_for("(c => c.getBoundingClientRect().width >= innerWidth - 1)(document.querySelector('#pool').shadowRoot.querySelector('canvas'))", Duration::from_secs(5))
        .await;
    let sizes =
        browser.js(&canvas_rect_js("#pool").replace("return {", "return { vw: innerWidth, vh: innerHeight,")).await;
    println!("fullscreen: {full}, canvas {sizes}");
    assert!(full, "the pool did not go fullscreen");
    let f = |k: &str| sizes[k].as_f64().unwrap();
    assert!(
        f("width") >= f("vw") - 1.0 && f("height") >= 0.9 * f("vh"),
        "the canvas does not fill the screen: {sizes}"
    );
    browser.close().await;
}

#[tokio::test]
async fn reset_returns_to_the_pages_own_start_and_enter_makes_a_drop() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser
        .goto(&server.url(
            "/?objects=none&quality=1&wave_speed=0.8&camera=30,20,5&drop_radius=0.1&drop_strength=0.04&start_drops=0",
        ))
        .await;
    browser.wait_ready("#pool", READY).await;
    let start = browser.js("return { speed: window.demo.get('wave_speed'), camera: window.demo.camera() };").await;
    assert_eq!(start["speed"], 0.8);
    let camera: Vec<f64> = start["camera"].as_array().expect("camera").iter().filter_map(Value::as_f64).collect();
    assert_eq!(camera, [30.0, 20.0, 5.0], "the camera option");
    // Enter on the focused pool: a drop in the middle.
    browser.js("document.querySelector('#pool').shadowRoot.querySelector('canvas').focus(); return true;").await;
    {
        use fantoccini::actions::{InputSource, KeyAction, KeyActions};
        let enter = KeyActions::new("keyboard".into())
            .then(KeyAction::Down { value: '\u{E007}' })
            .then(KeyAction::Up { value: '\u{E007}' });
        browser.client.perform_actions(enter).await.expect("press Enter");
    }
    let dropped = browser.wait_for("window.demo.stats().maxAbsHeight > 2e-3", Duration::from_secs(20)).await;
    assert!(dropped, "Enter made no drop: {}", browser.js("return window.demo.stats();").await);
    // Change things, then Reset.
    browser.js("window.demo.set('wave_speed', 1.5); window.demo.setCamera(-90, 60, 8); return true;").await;
    click_in_demo(&browser, ".buttons button").await;
    let after = browser.js("return { speed: window.demo.get('wave_speed'), camera: window.demo.camera() };").await;
    let calm = browser.wait_for("window.demo.stats().maxAbsHeight < 1e-4", Duration::from_secs(10)).await;
    println!("start {start}, after Reset {after}, calm again: {calm}");
    assert_eq!(after, start, "Reset did not return to the page's start");
    assert!(calm, "the water is not calm after Reset: {}", browser.js("return window.demo.stats();").await);
    browser.close().await;
}

/// Inserts a `<wave-pool>` with `attributes` into the test page, waits for it to be ready
/// (or fail), and returns whether it drew.
const INSERT_JS: &str = r#"
const attributes = arguments[0];
await customElements.whenDefined('wave-pool');
const el = document.createElement('wave-pool');
for (const [k, v] of Object.entries(attributes)) el.setAttribute(k, v);
el.style.width = '320px';
el.style.height = '240px';
const result = new Promise((resolve) => {
  el.addEventListener('wavepool:ready', (e) => resolve({ ready: true, fps: 0, backend: e.detail.stats().backend }));
  el.addEventListener('wavepool:error', (e) => resolve({ ready: false, error: e.detail }));
});
document.getElementById('host').append(el);
const r = await result;
if (r.ready) {
  await new Promise((done) => setTimeout(done, 300));
  r.simTime = el.demo.stats().simTime;
}
return r;
"#;

/// `<wave-pool>` inserted and removed 20 times on each backend: each insertion runs (reaches
/// its first frame and simulates), each removal gives its GPU context back (WebGL2:
/// `WEBGL_lose_context`, WebGPU: `GPUDevice.destroy`), so the count of live contexts does not
/// grow; attributes are the options and parameters (`wave-speed`, `max-fps`).
#[tokio::test]
async fn the_wave_pool_element_runs_each_time_it_is_inserted_and_frees_its_context_when_removed() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/test/insert.html")).await;
    for backend in ["webgl2", "webgpu"] {
        let attributes = json!({ "backend": backend, "objects": "none", "quality": "0.5", "controls": "false",
                                 "wave-speed": "0.8", "max-fps": "30" });
        let insert = INSERT_JS.replace("arguments[0]", &attributes.to_string());
        let mut most_live = 0;
        for i in 0..20 {
            let r = browser.js_async(&insert).await;
            assert_eq!(r["ready"], true, "{backend}: insertion {i} did not run: {r}");
            assert_eq!(r["backend"], backend, "{backend}: insertion {i}");
            assert!(r["simTime"].as_f64().unwrap_or(0.0) > 0.0, "{backend}: insertion {i} does not simulate: {r}");
            let speed = browser.js("return document.querySelector('wave-pool').demo.get('wave_speed');").await;
            assert_eq!(speed, 0.8, "the wave-speed attribute");
            browser.js("document.querySelector('wave-pool').remove(); return true;").await;
            // Its context goes when the element leaves the page (checked below).
            let gone = match backend {
                "webgl2" => "window.__gpu.webgl2 === window.__gpu.lostWebgl2",
                _ => "window.__gpu.webgpu === window.__gpu.destroyedDevices",
            };
            browser.wait_for(gone, Duration::from_secs(2)).await;
            let gpu = browser.js("return window.__gpu;").await;
            let n = |k: &str| gpu[k].as_i64().unwrap_or(0);
            let live = match backend {
                "webgl2" => n("webgl2") - n("lostWebgl2"),
                _ => n("webgpu") - n("destroyedDevices"),
            };
            most_live = most_live.max(live);
        }
        let gpu = browser.js("return window.__gpu;").await;
        println!("{backend}: 20 insertions ran; GPU contexts {gpu}; at most {most_live} live after a removal");
        assert!(most_live <= 0, "{backend}: {most_live} GPU contexts still live after removals: {gpu}");
    }
    browser.close().await;
}

/// The single file `dist/wavepool-standalone.html` (at most 1.6 MB): opened from disk
/// (`file://`) it reaches its first frame with a picture and fetches nothing (no resource
/// entries), on WebGPU and WebGL2; inside `<iframe sandbox="allow-scripts">` (an opaque
/// origin) it draws, posts `wavepool:ready` to the parent, and the server sees no request but
/// the two pages. Prints its start-up time beside `dist/` over HTTP's, loaded in turn in the
/// same browser (figures for the notes, not held to anything: timing is for benchmarks).
#[tokio::test]
async fn the_single_file_opens_from_disk_and_in_a_sandboxed_frame_without_network_requests() {
    let _g = serial();
    let file = support::dist_dir().join("wavepool-standalone.html");
    let size = std::fs::metadata(&file).map(|m| m.len()).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    assert!(size <= 1_600_000, "{} is {size} bytes", file.display());
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    for backend in ["webgpu", "webgl2"] {
        browser.goto(&format!("file://{}?backend={backend}&quality=1", file.display())).await;
        let took = browser.wait_ready("#pool", READY).await;
        let r = browser
            .js("return { backend: window.demo.stats().backend, firstFrameMs: window.demo.stats().firstFrameMs,
                          resources: performance.getEntriesByType('resource').map((e) => e.name) };")
            .await;
        let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
        let spread = browser.screenshot().await.luma_spread(rect);
        // The open sea is in the single file too.
        browser.js("window.demo.set('scene', 'sea'); return true;").await;
        let at_sea = browser.wait_for("window.demo.stats().scene === 'sea'", Duration::from_secs(30)).await;
        let sea_spread = browser.screenshot().await.luma_spread(rect);
        assert!(
            at_sea && sea_spread > 12.0,
            "the sea did not draw from the single file on {backend} ({sea_spread:.1})"
        );
        // And the ripple tank, its double slit's pattern on the screen under the tray.
        browser
            .js("window.demo.set('scene', 'tank'); window.demo.set('tank_setup', 'double_slit'); return true;")
            .await;
        let in_tank = browser.wait_for("window.demo.stats().scene === 'tank'", Duration::from_secs(30)).await;
        browser.wait_frames(10).await;
        let tank_spread = browser.screenshot().await.luma_spread(rect);
        println!("file:// on {backend}: the tank's luma spread {tank_spread:.1}");
        assert!(
            in_tank && tank_spread > 10.0,
            "the tank did not draw from the single file on {backend} ({tank_spread:.1})"
        );
        if backend == "webgl2" {
            // Its languages: the catalogues and the Fluent runtime are carried inside it.
            let shown = browser
                .js_async("await window.demo.setLanguage('sr-Latn');
                           return { label: document.querySelector('#pool').shadowRoot.querySelector('label[for$=\"-wave_speed\"]').textContent,
                                    resources: performance.getEntriesByType('resource').length };")
                .await;
            println!("file:// in Serbian (Latin): {shown}");
            let texts = catalogues::texts_of("sr-Latn");
            assert_eq!(
                shown["label"].as_str(),
                texts.get("param-wave_speed").map(String::as_str),
                "not the catalogue's words"
            );
            assert_eq!(shown["resources"], 0, "the single file fetched its catalogue");
        }
        browser.goto(&server.url(&format!("/?backend={backend}&quality=1"))).await;
        let took_http = browser.wait_ready("#pool", READY).await;
        let http_first = browser.js("return window.demo.stats().firstFrameMs;").await;
        println!(
            "file:// on {backend}: {size} bytes, ready in {took:?} (first frame {:.0} ms after mount), luma spread {spread:.1}, \
             fetched {}, the sea's luma spread {sea_spread:.1}; dist/ over HTTP: ready in {took_http:?} (first frame {:.0} ms after mount)",
            r["firstFrameMs"].as_f64().unwrap_or(f64::NAN),
            r["resources"],
            http_first.as_f64().unwrap_or(f64::NAN)
        );
        assert_eq!(r["backend"], backend);
        assert_eq!(r["resources"], json!([]), "the single file fetched something");
        assert!(spread > 12.0, "the canvas looks flat from disk on {backend}");
    }
    let before = server.requests().len();
    browser
        .goto(&server.url("/test/sandboxed.html?src=/wavepool-standalone.html%3Fbackend%3Dwebgl2%26quality%3D1"))
        .await;
    let ready = browser.wait_for("window.__messages.some((m) => m && m.type === 'wavepool:ready')", READY).await;
    let messages = browser.js("return window.__messages;").await;
    let rect = Rect::from_js(&browser.js("const r = document.getElementById('frame').getBoundingClientRect(); return { left: r.left, top: r.top, width: r.width, height: 300 };").await);
    // The frame's picture, once the browser has put it on the screen.
    let mut spread = 0.0;
    for _ in 0..40 {
        spread = browser.screenshot().await.luma_spread(Rect { y: rect.y + 60, ..rect });
        if spread > 12.0 {
            break;
        }
    }
    let requests = server.requests()[before..].to_vec();
    println!("sandboxed frame: messages {messages}, luma spread {spread:.1}, requests {requests:?}");
    assert!(ready, "no wavepool:ready from the sandboxed frame: {messages}");
    assert!(spread > 12.0, "the sandboxed frame looks flat");
    assert!(
        requests.iter().all(|p| p.starts_with("/test/sandboxed.html") || p.starts_with("/wavepool-standalone.html")),
        "requests beyond the two pages: {requests:?}"
    );
    browser.close().await;
}

/// Presets, share links and the embed page: `preset=calm` gives the preset's values and view
/// and the page's own options override it; the Preset select starts over from another; a share
/// link made after changes restores the parameters and the camera in a new load, a preset
/// with its scene named too gives its view, and a pool's preset in the sea the sea's; the embed
/// code's page (`embed.html`) fills its frame and posts `wavepool:ready` and its height.
#[tokio::test]
async fn presets_share_links_and_the_embed_page_restore_what_they_hold() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    let state = "const d = window.demo; return { objects: d.get('objects'), damping: d.get('damping'),
                 wave_speed: d.get('wave_speed'), drop_strength: d.get('drop_strength'),
                 camera: d.camera().map((v) => Math.round(v * 10) / 10) };";
    browser.goto(&server.url("/?preset=calm&drop_strength=0.01&quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    let calm = browser.js(state).await;
    println!("preset=calm&drop_strength=0.01: {calm}");
    assert_eq!((calm["objects"].as_f64(), calm["damping"].as_f64()), (Some(0.0), Some(2.0)), "the preset's values");
    assert_eq!(calm["drop_strength"].as_f64(), Some(0.01), "the page's own option over the preset's");
    assert_eq!(calm["camera"], json!([-25, 50, 3.6]), "the preset's view");

    let select = "const s = document.querySelector('#pool').shadowRoot.querySelector('.preset select');
                  s.value = 'busy'; s.dispatchEvent(new Event('change')); return s.value;";
    assert_eq!(browser.js(select).await, "busy");
    let busy = browser.js(state).await;
    println!("Preset select -> busy: {busy}");
    assert_eq!((busy["objects"].as_f64(), busy["wave_speed"].as_f64()), (Some(3.0), Some(0.9)));

    browser.js("window.demo.set('wave_speed', 1.3); window.demo.setCamera(40, 25, 6); return true;").await;
    let changed = browser.js(state).await;
    let link = browser.js("return window.demo.shareLink();").await.as_str().expect("a link").to_owned();
    println!("share link: {link}");
    browser.goto(&link).await;
    browser.wait_ready("#pool", READY).await;
    let restored = browser.js(state).await;
    assert_eq!(restored, changed, "the share link did not restore the demo");

    let code = browser.js("return window.demo.embedCode();").await.as_str().expect("embed code").to_owned();
    let src = code.split("src=\"").nth(1).and_then(|rest| rest.split('"').next()).expect("an iframe src");
    println!("embed code: {code}");
    let encoded: String = src
        .bytes()
        .map(|b| if b.is_ascii_alphanumeric() { (b as char).to_string() } else { format!("%{b:02X}") })
        .collect();
    browser.goto(&server.url(&format!("/test/sandboxed.html?sandbox=none&src={encoded}"))).await;
    let ready = browser.wait_for("window.__messages.some((m) => m && m.type === 'wavepool:ready')", READY).await;
    // The height the frame page asks for once its pool is laid out.
    let tall = "window.__messages.some((m) => m && m.type === 'wavepool:height' && m.height === 600)";
    browser.wait_for(tall, Duration::from_secs(10)).await;
    let messages = browser.js("return window.__messages;").await;
    let inside = browser
        .js("const d = document.getElementById('frame').contentWindow.demo;
             return { camera: d.camera().map((v) => Math.round(v * 10) / 10), wave_speed: d.get('wave_speed'),
                      canvas: d.stats().height, frame: document.getElementById('frame').clientHeight,
                      controls: !!document.getElementById('frame').contentDocument.querySelector('#pool').shadowRoot.querySelector('.controls') };")
        .await;
    println!("embed.html in a frame: messages {messages}, inside {inside}");
    assert!(ready, "embed.html posted no wavepool:ready: {messages}");
    let height = messages.as_array().unwrap().iter().rfind(|m| m["type"] == "wavepool:height").cloned();
    assert_eq!(height.and_then(|m| m["height"].as_f64()), Some(600.0), "wanted height for an 800 px wide frame");
    assert_eq!((inside["camera"].clone(), inside["wave_speed"].as_f64()), (changed["camera"].clone(), Some(1.3)));
    assert_eq!(inside["controls"], false, "embed.html shows the pool alone");
    assert!(
        inside["canvas"].as_f64().unwrap() >= 0.95 * inside["frame"].as_f64().unwrap(),
        "the pool does not fill the frame"
    );
    // A scene named beside a preset: the preset's view in that scene's ranges (it was clamped
    // to the pool's, chosen until the page's own options came).
    browser.goto(&server.url("/?scene=sea&preset=storm&quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    let storm = browser.js("return window.demo.camera().map((v) => Math.round(v * 10) / 10);").await;
    println!("scene=sea&preset=storm: camera {storm}");
    assert_eq!(storm, json!([-30, 12, 80]), "the storm's view with the scene named too");
    // A pool's preset in the sea: its values, but the sea's own view (the preset's is the pool's).
    browser.goto(&server.url("/?scene=sea&preset=calm&quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    let calm_sea = browser.js(state).await;
    println!("scene=sea&preset=calm: {calm_sea}");
    let camera: Vec<f64> = calm_sea["camera"].as_array().expect("a camera").iter().filter_map(Value::as_f64).collect();
    let view = wavepool::sea::DEFAULT_VIEW.map(|v| (v as f64 * 10.0).round() / 10.0);
    assert_eq!(camera, view, "the sea's own view under a pool's preset");
    assert_eq!(calm_sea["damping"].as_f64(), Some(2.0), "the preset's values in the sea");
    browser.close().await;
}

/// Printing: before a print each demo puts a still of its current frame (a 2D canvas, a real
/// picture: luma spread over 12) over its GPU canvas; with print media the GPU canvas and the
/// buttons are hidden and the still shown; after the print the still goes.
#[tokio::test]
async fn printing_swaps_in_a_still_of_the_current_frame() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/?quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    browser.js("window.dispatchEvent(new Event('beforeprint')); return true;").await;
    let still = browser
        .js("const s = document.querySelector('#pool').shadowRoot.querySelector('canvas.print-shot');
             if (!s) return null;
             const px = s.getContext('2d').getImageData(0, 0, s.width, s.height).data;
             let n = 0, sum = 0, sq = 0;
             for (let i = 0; i < px.length; i += 4 * 16) { const l = 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2]; n++; sum += l; sq += l * l; }
             const mean = sum / n; return { width: s.width, height: s.height, spread: Math.sqrt(sq / n - mean * mean) };")
        .await;
    assert!(!still.is_null(), "no still before printing");
    browser.cdp("Emulation.setEmulatedMedia", json!({ "media": "print" })).await;
    let shown = browser
        .js("const r = document.querySelector('#pool').shadowRoot;
             const display = (e) => getComputedStyle(e).display;
             return { gpu: display(r.querySelector('canvas:not(.print-shot)')), still: display(r.querySelector('.print-shot')),
                      buttons: display(r.querySelector('.overlay')) };")
        .await;
    browser.cdp("Emulation.setEmulatedMedia", json!({ "media": "" })).await;
    browser.js("window.dispatchEvent(new Event('afterprint')); return true;").await;
    let gone = browser.js("return !document.querySelector('#pool').shadowRoot.querySelector('.print-shot');").await;
    println!("print: still {still}, with print media {shown}, removed after: {gone}");
    assert!(still["spread"].as_f64().unwrap() > 12.0, "the still is flat: {still}");
    assert_eq!(shown, json!({ "gpu": "none", "still": "block", "buttons": "none" }));
    assert_eq!(gone, true);
    browser.close().await;
}

/// Keyboard: Tab from the top of the page reaches the pool, its buttons and every control shown
/// (a model's own settings are hidden, and skipped, while another model is chosen).
#[tokio::test]
async fn tab_reaches_the_pool_its_buttons_and_every_control() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/?quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    let focusable = browser
        .js("const r = document.querySelector('#pool').shadowRoot;
             return [...r.querySelectorAll('canvas:not(.print-shot), button, input, select, summary')]
               .filter((e) => !e.closest('.row[hidden]')).length;")
        .await
        .as_u64()
        .unwrap();
    let focused = "const a = document.activeElement; const r = a && a.shadowRoot;
                   const e = r ? r.activeElement : null;
                   return e ? e.tagName.toLowerCase() + ':' + (e.name || e.className || e.textContent.trim().slice(0, 20)) : null;";
    let mut reached = std::collections::BTreeSet::new();
    for _ in 0..(focusable + 5) {
        use fantoccini::actions::{InputSource, KeyAction, KeyActions};
        let tab = KeyActions::new("keyboard".into())
            .then(KeyAction::Down { value: '\u{E004}' })
            .then(KeyAction::Up { value: '\u{E004}' });
        browser.client.perform_actions(tab).await.expect("press Tab");
        if let Some(name) = browser.js(focused).await.as_str() {
            reached.insert(name.to_owned());
        }
    }
    println!("Tab reached {} of {focusable} controls: {reached:?}", reached.len());
    assert_eq!(reached.len() as u64, focusable, "Tab did not reach every control");
    assert!(reached.iter().any(|n| n.starts_with("canvas")), "the pool itself is not reachable");
    browser.close().await;
}

/// Luma spread (0-255) of the still shown by the `<wave-pool>` with this id, or null without one.
fn still_spread_js(id: &str) -> String {
    format!(
        "const s = document.getElementById('{id}').shadowRoot.querySelector('canvas.still');
         if (!s) return null;
         const px = s.getContext('2d').getImageData(0, 0, s.width, s.height).data;
         let n = 0, sum = 0, sq = 0;
         for (let i = 0; i < px.length; i += 4 * 16) {{ const l = 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2]; n++; sum += l; sq += l * l; }}
         const mean = sum / n; return Math.sqrt(sq / n - mean * mean);"
    )
}

/// Twelve `<wave-pool>`s on a long page (tests/pages/many.html, a screenful of text between
/// them), on each backend: at load only those near the viewport take a GPU context; scrolled
/// to in turn, each starts (ready, simulating) and never are more than 8 contexts live
/// (counted by wrapping `getContext`, `loseContext` and `GPUDevice.destroy`); those that gave
/// theirs up show their last frame (a still with a picture in it); scrolled back, the first
/// wakes with the parameter value set on it before and its still gives way to the live canvas.
#[tokio::test]
async fn twelve_demos_on_a_long_page_start_when_scrolled_to_and_hold_at_most_eight_gpu_contexts() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    let ready = |i: u32| {
        format!("(() => {{ const e = document.getElementById('pool{i}'); return e.dataset.ready === 'true' && !e.dataset.suspended && !!e.demo; }})()")
    };
    for backend in ["webgl2", "webgpu"] {
        browser.goto(&server.url(&format!("/test/many.html?backend={backend}"))).await;
        assert!(browser.wait_for(&ready(1), READY).await, "{backend}: the first pool did not start");
        tokio::time::sleep(Duration::from_secs(1)).await;
        let at_load = browser
            .js("return { started: [...document.querySelectorAll('wave-pool')].filter((e) => e.dataset.backend).length,
                          live: window.__gpuLive(), last: document.getElementById('pool12').shadowRoot.querySelectorAll('canvas').length };")
            .await;
        browser.js("document.getElementById('pool1').demo.set('wave_speed', 0.7); return true;").await;
        let mut most_live = 0;
        let mut start_ms = Vec::new();
        for i in 2..=12 {
            let t = std::time::Instant::now();
            browser
                .js(&format!("document.getElementById('pool{i}').scrollIntoView({{ block: 'center' }}); return true;"))
                .await;
            assert!(browser.wait_for(&ready(i), READY).await, "{backend}: pool {i} did not start when scrolled to");
            start_ms.push(t.elapsed().as_millis());
            let live = browser.js("return window.__gpuLive();").await.as_i64().unwrap();
            most_live = most_live.max(live);
            assert!(live <= 8, "{backend}: {live} GPU contexts live with pool {i} on screen");
        }
        let runs = "document.getElementById('pool12').demo.stats().simTime > 0";
        browser.wait_for(runs, Duration::from_secs(5)).await;
        let sim_time = browser.js("return document.getElementById('pool12').demo.stats().simTime;").await;
        let suspended: Vec<u32> = {
            let v = browser.js("return [...document.querySelectorAll('wave-pool')].filter((e) => e.dataset.suspended).map((e) => Number(e.id.slice(4)));").await;
            v.as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as u32).collect()
        };
        let mut spreads = Vec::new();
        for &i in &suspended {
            let s = browser.js(&still_spread_js(&format!("pool{i}"))).await;
            spreads.push(s.as_f64().unwrap_or(0.0));
        }
        // Back to the first pool: it wakes where it was.
        browser.js("document.getElementById('pool1').scrollIntoView({ block: 'center' }); return true;").await;
        let woke = browser
            .wait_for(
                "(() => { const e = document.getElementById('pool1'); return !e.dataset.suspended && !e.shadowRoot.querySelector('canvas.still'); })()",
                READY,
            )
            .await;
        let speed = browser.js("return document.getElementById('pool1').demo.get('wave_speed');").await;
        let live_after = browser.js("return window.__gpuLive();").await.as_i64().unwrap();
        let gpu = browser.js("return window.__gpu;").await;
        println!(
            "{backend}: at load {at_load}; starts when scrolled to (ms) {start_ms:?}; at most {most_live} contexts live; \
             suspended {suspended:?} with stills of luma spread {spreads:.1?}; pool 12 simulated {sim_time} s; \
             pool 1 woke: {woke}, wave_speed {speed}, {live_after} live; contexts {gpu}"
        );
        assert!(at_load["started"].as_i64().unwrap() <= 2, "{backend}: far pools started at load: {at_load}");
        assert!(at_load["live"].as_i64().unwrap() <= 2 && at_load["last"] == 0, "{backend}: at load {at_load}");
        assert!(sim_time.as_f64().unwrap_or(0.0) > 0.0, "{backend}: the last pool does not simulate");
        assert!(suspended.len() >= 4 && suspended.contains(&1), "{backend}: suspended {suspended:?}");
        assert!(spreads.iter().all(|&s| s > 12.0), "{backend}: a flat still among {spreads:?}");
        assert!(woke, "{backend}: the first pool did not wake when scrolled back to");
        assert_eq!(speed, 0.7, "{backend}: the first pool's wave_speed after waking");
        assert!(live_after <= 8, "{backend}: {live_after} contexts live after waking the first pool");
    }
    browser.close().await;
}
