//! The browser demo in Debian's headless Chromium: WebGPU, forced WebGL2, automatic fallback,
//! clicks make ripples, controls change parameters, two demos on one page, and a readable
//! message when the browser has no GPU backend at all; the pacing of frames (`pacing.rs`), the
//! optics, ambient and flat-water models (`models.rs`), the sea and the tank (`scenes.rs`).
//! Needs `dist/` (scripts/test builds it).

// Each test holds the one-browser-at-a-time lock for its whole run, awaits included: the
// tests run on separate threads, each with its own runtime, so nothing else waits on it there.
#![allow(clippy::await_holding_lock)]

#[path = "../support/browser.rs"]
mod support;

#[path = "../support/catalogues.rs"]
mod catalogues;
mod languages;
mod models;
mod pacing;
mod scenes;

use std::time::Duration;

use serde_json::Value;
use support::{canvas_rect_js, serial, Browser, Graphics, Rect, StaticServer, MESSAGE_JS, READY};

/// Opens the page, waits for the first frame and checks the backend and that the canvas
/// shows a picture (not a flat fill).
async fn open_demo(graphics: Graphics, query: &str, expected_backend: &str) -> (Browser, StaticServer) {
    let server = StaticServer::start();
    let browser = Browser::open(graphics).await;
    browser.goto(&server.url(&format!("/{}", query.trim_start_matches('/')))).await;
    let took = browser.wait_ready("#pool", READY).await;
    let backend = browser.js("return document.querySelector('#pool').dataset.backend;").await;
    assert_eq!(backend, expected_backend, "data-backend with {graphics:?} {query}");
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    assert!(rect.w >= 300 && rect.h >= 200, "canvas too small: {rect:?}");
    let shot = browser.screenshot().await;
    let spread = shot.luma_spread(rect);
    assert!(spread > 12.0, "canvas looks flat on {expected_backend} (luma spread {spread:.1})");
    eprintln!("{expected_backend} via {graphics:?} {query}: ready in {took:?}, luma spread {spread:.1}");
    (browser, server)
}

#[tokio::test]
async fn webgpu_runs_when_the_browser_has_it() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGpu, "", "webgpu").await;
    let stats = browser.js("return window.demo.stats();").await;
    assert_eq!(stats["backend"], "webgpu");
    assert_eq!(stats["simSize"], 256);
    // The canvas is in the browser's preferred format; the status line names the adapter or
    // says that the browser does not tell it.
    let preferred = browser.js("return navigator.gpu.getPreferredCanvasFormat();").await;
    assert_eq!(stats["canvasFormat"], preferred, "canvas format");
    let status = browser.js("return document.getElementById('status').textContent;").await;
    let status = status.as_str().unwrap_or("");
    let adapter = stats["adapter"].as_str().unwrap_or("");
    let expected =
        if adapter.is_empty() { "the browser does not tell which GPU".to_owned() } else { adapter.to_owned() };
    assert!(status.starts_with("Running on WebGPU") && status.contains(&expected), "status line: {status}");
    println!("canvas {preferred}; {status}");
    browser.close().await;
}

#[tokio::test]
async fn webgl2_can_be_forced_from_the_url() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGpu, "?backend=webgl2", "webgl2").await;
    browser.close().await;
}

#[tokio::test]
async fn falls_back_to_webgl2_without_webgpu() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGl2Only, "", "webgl2").await;
    browser.close().await;
}

/// Both backends draw the same scene: mean colours of the canvas agree (sRGB handled on both).
#[tokio::test]
async fn both_backends_show_the_same_scene() {
    let _g = serial();
    let mut means = Vec::new();
    for backend in ["webgpu", "webgl2"] {
        let (browser, _server) = open_demo(Graphics::WebGpu, &format!("?backend={backend}&paused=1"), backend).await;
        let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
        means.push(browser.screenshot().await.mean(rect));
        browser.close().await;
    }
    for (c, (webgpu, webgl2)) in means[0].iter().zip(&means[1]).enumerate() {
        assert!((webgpu - webgl2).abs() < 6.0, "channel {c}: WebGPU mean {webgpu:.1} vs WebGL2 {webgl2:.1}");
    }
}

/// Page with one demo in a 400x300 element and a lighter mesh: software rendering here
/// draws about one frame a second at this size (see the README's figures).
/// The pool without objects or drops at start, so the water is calm until clicked, and at a fixed resolution, so
/// that only the click changes the picture (automatic resolution redraws it when it steps).
const SMALL: &str =
    "test/sized.html?width=400&height=300&drop_radius=0.1&drop_strength=0.04&objects=none&quality=1&start_drops=0";

/// Page script: watches a 50x50 CSS-pixel square of the demo's canvas around (__X__, __Y__) in every
/// animation frame, right after the demo has drawn it (same task, so both WebGPU and WebGL2
/// canvases can be read). Until a pointerdown on the canvas it keeps refreshing the "before"
/// picture and counts pixels that change anyway (`idleChanged`, the calm water must keep it
/// at 0); after it, it records when the share of changed pixels first reaches 2% (a drop of the
/// test page's size changes about 3% in the first frame, and the calm water 0%).
const CHANGE_WATCH_JS: &str = r#"
const canvas = document.querySelector('#pool').shadowRoot.querySelector('canvas');
const r = canvas.getBoundingClientRect();
const scale = canvas.width / r.width;
const side = Math.round(50 * scale);
const left = Math.round((__X__ - r.left) * scale) - side / 2, top = Math.round((__Y__ - r.top) * scale) - side / 2;
const probe = document.createElement('canvas');
probe.width = probe.height = side;
const g = probe.getContext('2d', { willReadFrequently: true });
const grab = () => { g.drawImage(canvas, left, top, side, side, 0, 0, side, side); return g.getImageData(0, 0, side, side).data; };
const changed = (a, b) => {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 16) n++;
  }
  return n / (a.length / 4);
};
const w = (window.__watch = { clickAt: null, seenAt: null, changed: 0, idleChanged: 0, framesBefore: 0, framesAfter: 0, before: null, log: [] });
canvas.addEventListener('pointerdown', () => { w.clickAt = performance.now(); }, { capture: true });
// A grab that lands outside the canvas's own frame (a WebGPU canvas whose frame this callback
// ran ahead of) reads blank: such a grab says nothing and is skipped.
const blank = (a) => { for (let i = 3; i < a.length; i += 4) if (a[i] !== 0) return false; return true; };
const tick = () => {
  const now = grab();
  if (blank(now)) {
    requestAnimationFrame(tick);
    return;
  }
  if (w.clickAt === null) {
    if (w.before) w.idleChanged = Math.max(w.idleChanged, changed(w.before, now));
    w.before = now;
    w.framesBefore++;
  } else {
    w.framesAfter++;
    w.changed = Math.max(w.changed, changed(w.before, now));
    w.log.push([Math.round(performance.now() - w.clickAt), w.changed]);
    if (w.changed >= 0.02) { w.seenAt = performance.now(); return; }
  }
  requestAnimationFrame(tick);
};
requestAnimationFrame(tick);
return true;
"#;

/// A click on the water changes the picture near the click within a second (timed in the
/// page, from the pointerdown to the frame that shows it) and raises the largest wave height
/// the simulation reports.
async fn click_makes_ripples(graphics: Graphics, backend: &str) {
    click_makes_ripples_with(graphics, backend, "", "gpu").await;
}

async fn click_makes_ripples_with(graphics: Graphics, backend: &str, extra: &str, engine: &str) {
    let (browser, _server) = open_demo(graphics, &format!("{SMALL}&backend={backend}{extra}"), backend).await;
    assert_eq!(browser.js("return window.demo.stats().simEngine;").await, engine, "simulation engine");
    let before = browser.js("return window.demo.stats();").await;
    assert!(before["maxAbsHeight"].as_f64().unwrap() < 1e-4, "water not calm at start: {before}");
    // A point of the water away from the sphere.
    let p = browser.js("return window.demo.project(0.45, 0, -0.35);").await;
    let (x, y) = (p["x"].as_f64().expect("projected x"), p["y"].as_f64().expect("projected y"));
    browser.js(&CHANGE_WATCH_JS.replace("__X__", &x.to_string()).replace("__Y__", &y.to_string())).await;
    // A few frames of calm water first: the watch itself must see no change.
    assert!(browser.wait_for("window.__watch.framesBefore >= 12", Duration::from_secs(20)).await);
    browser.click_at(x, y).await;
    assert!(
        browser.wait_for("window.__watch.seenAt !== null", Duration::from_secs(10)).await,
        "{backend}: pixels near the click did not change: {}",
        browser.js("const w = window.__watch; return { changed: w.changed, frames: w.framesAfter };").await
    );
    let watch = browser
        .js("const w = window.__watch; return { ms: w.seenAt - w.clickAt, changed: w.changed, idle: w.idleChanged, frames: w.framesAfter, log: w.log };")
        .await;
    let (ms, idle) = (watch["ms"].as_f64().unwrap(), watch["idle"].as_f64().unwrap());
    assert!(idle < 0.01, "{backend}: {:.1}% of pixels changed with no click", idle * 100.0);
    assert!(ms < 1000.0, "{backend}: the click showed after {ms:.0} ms: {watch}");
    assert!(
        browser.wait_for("window.demo.stats().maxAbsHeight > 2e-3", Duration::from_secs(20)).await,
        "{backend}: maxAbsHeight did not rise: {}",
        browser.js("return window.demo.stats();").await
    );
    eprintln!("{backend}: click seen after {ms:.0} ms: {watch}");
    browser.close().await;
}

#[tokio::test]
async fn a_click_makes_ripples_on_webgpu() {
    let _g = serial();
    click_makes_ripples(Graphics::WebGpu, "webgpu").await;
}

#[tokio::test]
async fn a_click_makes_ripples_on_webgl2() {
    let _g = serial();
    click_makes_ripples(Graphics::WebGl2Only, "webgl2").await;
}

/// `float=none` takes the path for devices without float render targets (the CPU engine and
/// an 8-bit caustics map); clicks still make ripples within a second.
#[tokio::test]
async fn a_click_makes_ripples_without_float_targets() {
    let _g = serial();
    click_makes_ripples_with(Graphics::WebGl2Only, "webgl2", "&float=none", "cpu").await;
}

/// The controls are generated from the parameter table and drive the core: a slider moved with
/// the keyboard, a checkbox toggled by a click, read back with get(); the shown value has a unit.
#[tokio::test]
async fn controls_change_parameters() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGl2Only, "", "webgl2").await;
    let table = browser.js("return window.demo.params().map((p) => p.name);").await;
    let count = browser
        .js("return document.querySelector('#pool').shadowRoot.querySelectorAll('input[name], select[name]').length;")
        .await;
    assert_eq!(table.as_array().unwrap().len() as u64, count.as_u64().unwrap(), "one input per parameter");
    for name in [
        "wave_speed",
        "damping",
        "drop_radius",
        "drop_strength",
        "sun_azimuth",
        "caustics",
        "objects",
        "duck_density",
        "gravity",
        "paused",
    ] {
        assert!(table.as_array().unwrap().iter().any(|n| n == name), "no control for {name}");
    }
    let before = browser.js("return window.demo.get('wave_speed');").await.as_f64().unwrap();
    browser.js("document.querySelector('#pool').shadowRoot.querySelector('input[name=wave_speed]').focus();").await;
    let slider = browser.client.active_element().await.expect("focused slider");
    slider.send_keys("\u{E014}\u{E014}").await.expect("arrow keys"); // ArrowRight twice
    let after = browser.js("return window.demo.get('wave_speed');").await.as_f64().unwrap();
    assert!((after - before - 0.1).abs() < 1e-3, "wave_speed {before} -> {after} after two steps of 0.05");
    let shown = browser
        .js("return document.querySelector('#pool').shadowRoot.querySelector('input[name=wave_speed] + output').textContent;")
        .await;
    assert!(shown.as_str().unwrap().ends_with("m/s"), "value shown without unit: {shown}");

    browser.js("document.querySelector('#pool').shadowRoot.querySelector('input[name=gravity]').click();").await;
    assert_eq!(browser.js("return window.demo.get('gravity');").await, 0.0, "gravity starts on; a click turns it off");
    // The grid resolution is a choice (a select): changing it resamples the running water.
    browser
        .js("const s = document.querySelector('#pool').shadowRoot.querySelector('select[name=sim_size]'); s.value = '512'; s.dispatchEvent(new Event('change'));")
        .await;
    // On a loaded machine SwiftShader takes its time over the resample (the first full run of
    // the 2026-11-26 version waited out 20 s).
    assert!(
        browser.wait_for("window.demo.stats().simSize === 512", Duration::from_secs(60)).await,
        "sim_size select did not switch the grid: {}",
        browser.js("return window.demo.stats();").await
    );
    // And the API clamps with a warning, and names unknown parameters.
    assert_eq!(browser.js("return window.demo.set('damping', 99);").await, 5.0);
    let err =
        browser.js("try { window.demo.set('nope', 1); return 'no error'; } catch (e) { return e.message; }").await;
    assert!(err.as_str().unwrap().contains("wave_speed"), "unknown name error: {err}");
    browser.close().await;
}

/// Keys reach the demo only when it has focus: space pauses, G toggles gravity.
#[tokio::test]
async fn keys_act_only_with_focus() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGl2Only, "", "webgl2").await;
    let body = browser.client.find(fantoccini::Locator::Css("body")).await.unwrap();
    body.send_keys("g").await.unwrap();
    assert_eq!(browser.js("return window.demo.get('gravity');").await, 1.0, "key acted without focus");
    browser.js("document.querySelector('#pool').shadowRoot.querySelector('canvas').focus();").await;
    let canvas = browser.client.active_element().await.unwrap();
    canvas.send_keys("g ").await.unwrap();
    assert_eq!(browser.js("return window.demo.get('gravity');").await, 0.0);
    assert_eq!(browser.js("return window.demo.get('paused');").await, 1.0);
    browser.close().await;
}

#[tokio::test]
async fn two_instances_run_independently() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGl2Only).await;
    browser.goto(&server.url("/test/two.html")).await;
    browser.wait_ready("#a", READY).await;
    browser.wait_ready("#b", READY).await;
    assert!(browser.wait_for("window.demos.a && window.demos.b", Duration::from_secs(10)).await);
    assert_eq!(
        browser.js("return [window.demos.a.get('wave_speed'), window.demos.b.get('wave_speed')];").await,
        serde_json::json!([0.6, 1.5])
    );
    browser.js("window.demos.a.addDrop(0.3, 0.3, 0.1, 0.03);").await;
    assert!(
        // The readback is a frame or two old and a slow frame takes up to 0.1 s of steps, so
        // the drop's first reading is already spread out (7.5e-3 m, then 6e-3, 4.7e-3, ...).
        browser.wait_for("window.demos.a.stats().maxAbsHeight > 1e-3", Duration::from_secs(20)).await,
        "the drop did not show in a: {}",
        browser.js("return [window.demos.a.stats(), window.demos.b.stats()];").await
    );
    let b = browser.js("return window.demos.b.stats().maxAbsHeight;").await.as_f64().unwrap();
    assert!(b < 1e-4, "a drop in one demo moved the other's water ({b} m)");
    // The host page's canvas rule does not reach into the demo.
    let border = browser
        .js("return getComputedStyle(document.querySelector('#a').shadowRoot.querySelector('canvas')).borderTopWidth;")
        .await;
    assert_eq!(border, "0px");
    browser.close().await;
}

#[tokio::test]
async fn no_gpu_shows_a_message_in_the_page() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::Nothing).await;
    browser.goto(&server.url("/")).await;
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    let message = browser.js(MESSAGE_JS).await;
    assert!(failed, "no error state; message: {message}");
    assert!(message.as_str().unwrap().contains("neither WebGPU nor WebGL2"), "message: {message}");
    // Behind the message, a still picture of the pool (web/no-gpu.webp) instead of an empty box;
    // the single file from disk too (its picture is inline).
    let loaded = "(() => { const i = document.querySelector('#pool').shadowRoot.querySelector('img.fallback');
                  return i && i.complete ? i.naturalWidth : 0; })() > 0";
    assert!(browser.wait_for(loaded, Duration::from_secs(10)).await, "no picture");
    // In German, the message is the German catalogue's (its words for no backend at all).
    browser.goto(&server.url("/?lang=de")).await;
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    let message = browser.js(MESSAGE_JS).await;
    let german = catalogues::texts_of("de");
    println!("in German: {message}");
    assert!(
        failed && message.as_str().unwrap().starts_with(german["error-no-backend"].as_str()),
        "in German: {message}"
    );
    let file = support::dist_dir().join("wavepool-standalone.html");
    browser.goto(&format!("file://{}", file.display())).await;
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    assert!(failed, "the single file: no error state; message: {}", browser.js(MESSAGE_JS).await);
    assert!(browser.wait_for(loaded, Duration::from_secs(10)).await, "the single file: no picture");
    browser.close().await;
}

/// A backend forced from the URL that the browser lacks: the message says it was forced, why
/// it failed, and how to let the page choose (here WebGL2 would have worked).
#[tokio::test]
async fn a_forced_backend_the_browser_lacks_says_so_and_how_to_let_the_page_choose() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGl2Only).await;
    browser.goto(&server.url("/?backend=webgpu")).await;
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    let message = browser.js(MESSAGE_JS).await;
    let message = message.as_str().unwrap_or("").to_owned();
    println!("{message}");
    assert!(failed, "no error state; message: {message}");
    for words in ["asked for WebGPU only (backend=webgpu)", "WebGPU: ", "backend=auto"] {
        assert!(message.contains(words), "the message lacks '{words}': {message}");
    }
    browser.close().await;
}

/// The water keeps up with wall time down to 10 drawn frames/s, and below that runs in slow
/// motion at 0.1 s of water a frame (frames do not take ever more steps): with the frame rate
/// forced by `maxFps`, simulated time over 10 s against the page's clock, and `stats().simSpeed`.
/// (Where steps cost so much that keeping up would push frames under 10 frames/s, fewer are
/// taken: `quality::StepGovernor`, tested on its own.)
#[tokio::test]
async fn simulated_time_keeps_up_down_to_10_frames_per_second_and_slows_gracefully_below() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    for (max_fps, expected) in [(10.0, 1.0), (4.0, 0.4)] {
        // A grid whose steps this machine affords at 10 frames/s (12 steps a frame).
        let page = "test/sized.html?width=200&height=150&objects=none&quality=1&sim_size=128";
        browser.goto(&server.url(&format!("/{page}&maxFps={max_fps}"))).await;
        browser.wait_ready("#pool", READY).await;
        // Past the start-up's first frames, which come as fast as they can.
        assert!(browser.wait_for("window.demo.stats().framesDrawn >= 6", Duration::from_secs(20)).await);
        let clock = "return [performance.now(), window.demo.stats().simTime];";
        let a = browser.js(clock).await;
        tokio::time::sleep(Duration::from_secs(10)).await;
        let b = browser.js(clock).await;
        let stats = browser.js("return window.demo.stats();").await;
        let t = |v: &Value, i: usize| v[i].as_f64().unwrap();
        let speed = (t(&b, 1) - t(&a, 1)) / ((t(&b, 0) - t(&a, 0)) / 1000.0);
        let (fps, reported) = (stats["fps"].as_f64().unwrap(), stats["simSpeed"].as_f64().unwrap());
        println!(
            "maxFps {max_fps}: {fps:.1} frames/s drawn, {speed:.3} simulated s per wall s over 10 s \
             (stats().simSpeed {reported:.3}, frameMs {})",
            stats["frameMs"]
        );
        assert!(fps >= 0.9 * max_fps && fps <= 1.05 * max_fps, "the page drew {fps:.1} frames/s, not {max_fps}");
        assert!((speed - expected).abs() <= 0.05 * expected, "{speed:.3} simulated s per s at {max_fps} frames/s");
        assert!((reported - expected).abs() <= 0.1 * expected, "stats().simSpeed {reported:.3} at {max_fps} frames/s");
    }
    browser.close().await;
}

#[tokio::test]
async fn snapshot_gives_a_png() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGpu, "", "webgpu").await;
    let out = browser
        .js_async(
            "const blob = await window.demo.snapshot();
             const bytes = new Uint8Array(await blob.arrayBuffer());
             return { type: blob.type, size: blob.size, head: Array.from(bytes.slice(1, 4)) };",
        )
        .await;
    assert_eq!(out["type"], "image/png", "{out}");
    assert_eq!(out["head"], serde_json::json!([80, 78, 71]), "not a PNG: {out}"); // "PNG"
    assert!(out["size"].as_u64().unwrap() > 20_000, "snapshot too small to hold the scene: {out}");
    browser.close().await;
}

/// A Rust panic reaches the page: every mounted demo shows the panic's message in its element
/// and marks it `data-error`, instead of freezing on its last frame.
#[tokio::test]
async fn a_panic_shows_in_the_page() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGl2Only, SMALL, "webgl2").await;
    // The same module URL as embed.js imports, so the same wasm instance and panic hook.
    let out = browser
        .js_async("const core = await import('/wavepool.js'); core.panicForTests('deliberate test panic'); return 'returned';")
        .await;
    assert!(out.get("error").is_some(), "the panic did not surface as an exception: {out}");
    let failed = browser.wait_for("document.querySelector('#pool').dataset.error === 'true'", READY).await;
    let message = browser.js(MESSAGE_JS).await;
    assert!(failed, "no error state after a panic; message: {message}");
    assert!(message.as_str().unwrap().contains("deliberate test panic"), "message: {message}");
    browser.close().await;
}

/// A lost GPU device (here destroyed on purpose) is recreated on a fresh canvas: the demo
/// counts one restart, keeps its parameters and draws again.
#[tokio::test]
async fn a_lost_device_is_recreated() {
    let _g = serial();
    let (browser, _server) = open_demo(Graphics::WebGpu, &format!("{SMALL}&backend=webgpu"), "webgpu").await;
    browser.js("window.demo.set('wave_speed', 1.3); window.demo._core.loseDeviceForTests();").await;
    assert!(
        browser
            .wait_for(
                // stats() throws while the new device is being set up
                "(() => { try { const s = window.demo.stats(); return s.restarts === 1 && s.simTime > 0.5; } catch (e) { return false; } })()",
                READY
            )
            .await,
        "no restart after the device was lost: {}",
        browser.js("const m = document.querySelector('#pool').shadowRoot.querySelector('.message'); return m.textContent;").await
    );
    assert_eq!(browser.js("return document.querySelector('#pool').dataset.error || 'none';").await, "none");
    assert!((browser.js("return window.demo.get('wave_speed');").await.as_f64().unwrap() - 1.3).abs() < 1e-6);
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let spread = browser.screenshot().await.luma_spread(rect);
    assert!(spread > 12.0, "canvas flat after the restart (luma spread {spread:.1})");
    eprintln!("restarted after a device loss; luma spread {spread:.1}");
    browser.close().await;
}

/// Options out of range or between the allowed values still give a running demo, with the
/// values clamped or snapped as the core's tables say.
#[tokio::test]
async fn creation_options_are_clamped() {
    let _g = serial();
    let query = format!("{SMALL}&backend=webgl2&sim_size=300&meshSize=2&causticsSize=99999");
    let (browser, _server) = open_demo(Graphics::WebGl2Only, &query, "webgl2").await;
    assert_eq!(browser.js("return window.demo.stats().simSize;").await, 256, "sim_size 300 snaps to 256");
    assert_eq!(browser.js("return window.demo.get('sim_size');").await, 256);
    browser.close().await;
}

/// The sphere and the duck in the browser: the duck is drawn where it floats (duck-yellow
/// pixels around its projection; none there with objects=none), it floats near its waterline,
/// and the `objects` option takes the choice's name.
async fn objects_float(graphics: Graphics, backend: &str) {
    let page = format!("test/sized.html?width=400&height=300&backend={backend}&objects=duck");
    let (browser, _server) = open_demo(graphics, &page, backend).await;
    assert_eq!(browser.js("return window.demo.get('objects');").await, 2.0, "objects=duck by name");
    assert!(
        browser.wait_for("window.demo.stats().simTime > 1", READY).await,
        "{backend}: the water did not run: {}",
        browser.js("return window.demo.stats();").await
    );
    let stats = browser.js("return window.demo.stats();").await;
    let duck = &stats["duckPosition"];
    assert!(stats["spherePosition"].is_null(), "objects=duck shows the sphere: {stats}");
    let y = duck[1].as_f64().expect("duck position");
    assert!(y.abs() < 0.05, "{backend}: the duck is not floating at the surface: {stats}");
    let p = browser.js(&format!("return window.demo.project({}, {}, {});", duck[0], duck[1], duck[2])).await;
    let (x, y) = (p["x"].as_f64().unwrap(), p["y"].as_f64().unwrap());
    let yellow = |shot: &support::Image| {
        shot.region(Rect::around(x, y, 14))
            .iter()
            .filter(|p| p[0] > 180 && p[1] > 115 && p[2] < 90 && p[0] as i32 - p[2] as i32 > 120)
            .count()
    };
    let with_duck = yellow(&browser.screenshot().await);
    browser.js("window.demo.set('objects', 'none');").await;
    browser.wait_frames(3).await;
    let without = yellow(&browser.screenshot().await);
    eprintln!("{backend}: duck at ({x:.0}, {y:.0}): {with_duck} yellow pixels, {without} without");
    assert!(with_duck > 60 && without == 0, "{backend}: duck not seen ({with_duck} yellow pixels, {without} without)");
    // The beach ball, asked for in a set of names: it floats high, drawn in its red and blue
    // gores (no other pixel of the pool is this blue: 0 of the frame without it, natively).
    browser.js("window.demo.set('objects', 'ball,duck');").await;
    assert_eq!(browser.js("return window.demo.get('objects');").await, 6.0, "objects=ball,duck by names");
    browser.wait_sim_time(1.5).await;
    let stats = browser.js("return window.demo.stats();").await;
    let ball = &stats["bodies"]["ball"];
    let height = ball[1].as_f64().expect("ball position");
    let p = browser.js(&format!("return window.demo.project({}, {}, {});", ball[0], ball[1], ball[2])).await;
    let (x, y) = (p["x"].as_f64().unwrap(), p["y"].as_f64().unwrap());
    let gores = browser
        .screenshot()
        .await
        .region(Rect::around(x, y, 20))
        .iter()
        .filter(|p| {
            let red = p[0] > 150 && p[2] < 80 && p[0] as i32 - p[2] as i32 > 100 && p[0] > p[1];
            let blue = p[2] > 170 && p[2] as i32 - p[1] as i32 > 60 && p[0] < 90;
            red || blue
        })
        .count();
    eprintln!("{backend}: ball at {height:.3} m, pixel ({x:.0}, {y:.0}): {gores} red or blue gore pixels");
    assert!(height > 0.08, "{backend}: the ball does not float high: {stats}");
    assert!(gores > 150, "{backend}: ball not seen ({gores} red or blue gore pixels)");
    browser.close().await;
}

#[tokio::test]
async fn objects_float_on_webgpu() {
    let _g = serial();
    objects_float(Graphics::WebGpu, "webgpu").await;
}

#[tokio::test]
async fn objects_float_on_webgl2() {
    let _g = serial();
    objects_float(Graphics::WebGl2Only, "webgl2").await;
}
