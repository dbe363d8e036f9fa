//! The browser demo in Debian's headless Chromium: WebGPU, forced WebGL2, automatic fallback,
//! clicks make ripples, controls change parameters, two demos on one page, and a readable
//! message when the browser has no GPU backend at all. Needs `dist/` (scripts/test builds it).

// Each test holds the one-browser-at-a-time lock for its whole run, awaits included: the
// tests run on separate threads, each with its own runtime, so nothing else waits on it there.
#![allow(clippy::await_holding_lock)]

#[path = "support/browser.rs"]
mod support;

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
/// The pool without objects, so the water is calm until clicked, and at a fixed resolution, so
/// that only the click changes the picture (automatic resolution redraws it when it steps).
const SMALL: &str = "test/sized.html?width=400&height=300&drop_radius=0.1&drop_strength=0.04&objects=none&quality=1";

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
const w = (window.__watch = { clickAt: null, seenAt: null, changed: 0, idleChanged: 0, framesAfter: 0, before: null, log: [] });
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
    assert!(browser.wait_for("window.__watch.before !== null", Duration::from_secs(10)).await);
    tokio::time::sleep(Duration::from_millis(1500)).await;
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
        tokio::time::sleep(Duration::from_secs(2)).await;
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

/// The counter of drawn frames (tests/pages/frame_counter.js), injected before the page loads.
const FRAME_COUNTER_JS: &str = include_str!("pages/frame_counter.js");

/// Opens the 800x600 test page with the frame counter injected and waits for the first frame.
async fn open_counted(backend: &str, extra: &str) -> (Browser, StaticServer) {
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.add_init_script(FRAME_COUNTER_JS).await;
    browser.goto(&server.url(&format!("/test/sized.html?width=800&height=600&backend={backend}{extra}"))).await;
    browser.wait_ready("#pool", READY).await;
    (browser, server)
}

/// Frames are paced on both backends: counted from outside the page (frames that reached the
/// canvas; on WebGPU, frames the GPU finished), over 20 s at most 5 % of the intervals between
/// drawn frames are shorter than half their median (a loop that queues frames ahead of the GPU
/// draws them in bursts, back to back), the page never stalls for a second, and at most two
/// frames ever wait on the GPU. Long intervals are the machine's: here the browser's GPU is the
/// same two cores (SwiftShader) and a frame that takes twice as long now and then is noise, not
/// a pacing fault, so they are printed (95th percentile, longest), not held to the median. stats() agrees
/// with that count: the frames it reports over five 2 s windows (fps x 2 s) sum to the frames
/// the counter saw in them, within 15 %.
async fn frames_are_paced(backend: &str) {
    let _g = serial();
    let (browser, _server) = open_counted(backend, "").await;
    tokio::time::sleep(Duration::from_secs(5)).await;
    let (mut ours, mut counted) = (0.0, 0.0);
    for _ in 0..5 {
        browser.js("window.__frameCounter.reset(); return true;").await;
        tokio::time::sleep(Duration::from_secs(2)).await;
        let both = browser.js("return { c: window.__frameCounter.read(), s: window.demo.stats() };").await;
        ours += both["s"]["fps"].as_f64().unwrap() * both["c"]["seconds"].as_f64().unwrap();
        counted += both["c"]["frames"].as_f64().unwrap();
    }
    browser.js("window.__frameCounter.reset(); return true;").await;
    tokio::time::sleep(Duration::from_secs(20)).await;
    let c = browser.js("return window.__frameCounter.read();").await;
    let stats = browser.js("return window.demo.stats();").await;
    let (fps, median, p5, p95, longest) = (
        c["fps"].as_f64().unwrap(),
        c["medianMs"].as_f64().unwrap(),
        c["p5Ms"].as_f64().unwrap(),
        c["p95Ms"].as_f64().unwrap(),
        c["longestMs"].as_f64().unwrap(),
    );
    let pending = c["pending"].as_f64().unwrap_or(0.0);
    println!(
        "{backend}: {fps:.2} drawn frames/s over 20 s, interval median {median:.0} ms, 5th percentile {p5:.0} ms, 95th {p95:.0} ms, \
         longest {longest:.0} ms, \
         {pending} waiting on the GPU; stats() said {ours:.1} frames where the counter saw {counted} (10 s); \
         stats now: fps {:.2}, frameMs {}, longestFrameMs {}, renderScale {}",
        stats["fps"].as_f64().unwrap(),
        stats["frameMs"],
        stats["longestFrameMs"],
        stats["renderScale"]
    );
    assert!(fps > 0.5, "{backend}: only {fps} frames/s drawn");
    assert!(
        p5 >= 0.5 * median,
        "{backend}: 5 % of the intervals under {p5:.0} ms against a {median:.0} ms median: bursts"
    );
    assert!(longest < 1000.0, "{backend}: the page stalled for {longest:.0} ms");
    assert!(pending <= 2.0, "{backend}: {pending} frames queued on the GPU");
    assert!((ours - counted).abs() <= 0.15 * counted, "{backend}: stats() {ours:.1} frames vs {counted} counted");
    let scale = stats["renderScale"].as_f64().unwrap();
    assert!((0.5..=1.0).contains(&scale), "renderScale {scale}");
    browser.close().await;
}

#[tokio::test]
async fn frames_are_paced_on_webgpu() {
    frames_are_paced("webgpu").await;
}

#[tokio::test]
async fn frames_are_paced_on_webgl2() {
    frames_are_paced("webgl2").await;
}

/// Automatic resolution: with a frame budget no software renderer meets (10 ms) the scene
/// drops to half resolution and the page keeps drawing at the canvas's own size; `quality=1`
/// keeps full resolution whatever the frame time.
#[tokio::test]
async fn a_slow_frame_budget_lowers_the_resolution_and_quality_one_keeps_it() {
    let _g = serial();
    let (browser, server) = open_counted("webgpu", "&frame_budget=10").await;
    assert!(
        browser.wait_for("window.demo.stats().renderScale === 0.5", Duration::from_secs(60)).await,
        "render scale stayed at {}",
        browser.js("return window.demo.stats().renderScale;").await
    );
    browser.js("window.__frameCounter.reset(); return true;").await;
    tokio::time::sleep(Duration::from_secs(4)).await;
    let c = browser.js("return window.__frameCounter.read();").await;
    let s = browser.js("return window.demo.stats();").await;
    println!(
        "budget 10 ms: scale {}, {} frames in 4 s at {}x{}",
        s["renderScale"], c["frames"], s["width"], s["height"]
    );
    assert!(c["frames"].as_f64().unwrap() >= 2.0, "the page stopped drawing: {c}");
    assert_eq!((s["width"].as_u64(), s["height"].as_u64()), (Some(800), Some(600)), "canvas size changed");
    browser.goto(&server.url("/test/sized.html?width=800&height=600&backend=webgpu&quality=1&frame_budget=10")).await;
    browser.wait_ready("#pool", READY).await;
    tokio::time::sleep(Duration::from_secs(6)).await;
    let s = browser.js("return window.demo.stats();").await;
    println!("quality=1: scale {} after 6 s at {} frames/s", s["renderScale"], s["fps"]);
    assert_eq!(s["renderScale"].as_f64(), Some(1.0));
    browser.close().await;
}

/// The Optics group in the page, on both backends: the Fresnel plot draws the chosen model's
/// curve from the core's formulas (its first point is the reflectance at 0° from air: 0.020
/// exact, 0 linear), choosing a model in the select redraws it and changes the water's
/// pixels, and the plot's view mark sits at 90° minus the camera's pitch. Dispersion (a
/// per-channel caustics map, three caustics draws) and in-scattered light run there too,
/// each changing the picture, with no error; ambient waves move the calm pool with no input
/// and stand still while it is paused; with foam on a hard drop leaves white water; every
/// new optics, foam and ambient parameter takes its value from its own control.
async fn fresnel_models_in_the_page(graphics: Graphics, backend: &str) {
    let (browser, _server) =
        open_demo(graphics, &format!("?backend={backend}&quality=1&objects=none&paused=1"), backend).await;
    let plot = "const f = document.querySelector('#pool').shadowRoot.querySelector('.fresnel-plot');
                if (!f) return null;
                const p = f.querySelector('path.model.air').getAttribute('d');
                const m = f.querySelector('line.view');
                return { model: f.dataset.model, start: p.slice(0, p.indexOf('L')), points: p.split('L').length,
                         mark: Number(m.getAttribute('x1')), pitch: window.demo.camera()[1] };";
    let before_plot = browser.js(plot).await;
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let before = browser.screenshot().await;
    browser
        .js("const s = document.querySelector('#pool').shadowRoot.querySelector('select[name=fresnel]');
             s.value = '5'; s.dispatchEvent(new Event('change')); return true;")
        .await;
    browser.wait_frames(3).await;
    let after_plot = browser.js(plot).await;
    let after = browser.screenshot().await;
    let changed = before.changed_fraction(&after, rect, 8);
    println!("{backend}: plot {before_plot} -> {after_plot}; {:.1} % of the canvas changed", changed * 100.0);
    assert_eq!(before_plot["model"], "0");
    // Plot area: x from 30 over 180 units for 0-90°, y from 8 over 100 units for 1-0.
    assert_eq!(before_plot["start"], "M30.0,106.0", "exact at 0°: 0.020");
    assert_eq!(after_plot["model"], "5");
    assert_eq!(after_plot["start"], "M30.0,108.0", "linear at 0°: 0");
    assert_eq!(after_plot["points"], 91);
    assert_eq!(browser.js("return window.demo.get('fresnel');").await, 5.0);
    let expected_mark = 30.0 + (90.0 - before_plot["pitch"].as_f64().unwrap().abs()) / 90.0 * 180.0;
    assert!((before_plot["mark"].as_f64().unwrap() - expected_mark).abs() < 0.2, "view mark {before_plot}");
    assert!(changed > 0.05, "{backend}: the linear model did not change the water ({:.2} %)", changed * 100.0);
    for (name, value) in [("dispersion", 20.0), ("scatter_red", 0.5)] {
        let before = browser.screenshot().await;
        browser.js(&format!("window.demo.set('{name}', {value}); return true;")).await;
        browser.wait_frames(3).await;
        let after = browser.screenshot().await;
        let changed = before.changed_fraction(&after, rect, 8);
        let state = browser
            .js("const e = document.querySelector('#pool'); return { error: e.dataset.error || null, fps: window.demo.stats().fps };")
            .await;
        println!("{backend}: {name} = {value}: {:.1} % of the canvas changed, {state}", changed * 100.0);
        assert!(state["error"].is_null(), "{backend}: {name} stopped the demo: {state}");
        assert!(changed > 0.01, "{backend}: {name} changed {:.2} % of the canvas", changed * 100.0);
    }
    browser.js("window.demo.set('dispersion', 0); window.demo.set('scatter_red', 0); window.demo.set('ambient', 'sines'); window.demo.set('paused', 0); return true;").await;
    browser.wait_frames(3).await;
    let a = browser.screenshot().await;
    browser.wait_sim_time(0.5).await;
    let b = browser.screenshot().await;
    browser.js("window.demo.set('paused', 1); return true;").await;
    browser.wait_frames(3).await;
    let c = browser.screenshot().await;
    browser.wait_frames(3).await;
    let d = browser.screenshot().await;
    let (moving, paused) = (a.changed_fraction(&b, rect, 8), c.changed_fraction(&d, rect, 8));
    println!(
        "{backend}: ambient sines: {:.1} % changed in 0.5 s of water with no input; paused: {:.2} %",
        moving * 100.0,
        paused * 100.0
    );
    assert!(moving > 0.01 && paused == 0.0, "{backend}: ambient waves {moving} moving, {paused} paused");
    // A hard drop with foam, then frozen: the same water drawn with foam and without it.
    browser
        .js("const d = window.demo; d.reset(); d.set('foam', 1); d.set('foam_decay', 5); d.set('paused', 0);
             for (const [x, z] of [[0, 0], [0.4, 0.3], [-0.4, -0.3]]) d.addDrop(x, z, 0.1, 0.045);
             return true;")
        .await;
    tokio::time::sleep(Duration::from_millis(600)).await;
    browser.js("window.demo.set('paused', 1); return true;").await;
    browser.wait_frames(3).await;
    let with_foam = browser.screenshot().await;
    browser.js("window.demo.set('foam', 0); return true;").await;
    browser.wait_frames(3).await;
    let without = browser.screenshot().await;
    let luma = |p: &[u8; 3]| 0.2126 * p[0] as f32 + 0.7152 * p[1] as f32 + 0.0722 * p[2] as f32;
    let whiter = with_foam
        .region(rect)
        .iter()
        .zip(without.region(rect).iter())
        .filter(|(a, b)| luma(a) > luma(b) + 30.0)
        .count();
    println!("{backend}: {whiter} pixels whiter with foam than the same frozen water without");
    assert!(whiter > 100, "{backend}: no foam seen ({whiter} pixels)");
    // Every parameter of this issue's lessons from its own control: sliders to their maximum,
    // toggles clicked, selects to their last choice.
    let set_by_controls = browser
        .js("const root = document.querySelector('#pool').shadowRoot;
             const names = ['sun_size', 'fresnel', 'specular', 'shininess', 'dispersion', 'absorption_red', 'absorption_green',
                            'absorption_blue', 'scatter_red', 'scatter_green', 'scatter_blue', 'view_colour', 'foam', 'foam_decay',
                            'ambient', 'wind_speed', 'wind_direction', 'wave_height', 'wave_spread', 'steepness',
                            'spectrum', 'fft_size', 'choppiness'];
             const out = {};
             for (const name of names) {
               const input = root.querySelector(`[name=${name}]`);
               if (!input) { out[name] = 'no control'; continue; }
               let want;
               if (input.type === 'checkbox') { want = window.demo.get(name) >= 0.5 ? 0 : 1; input.click(); }
               else if (input.tagName === 'SELECT') {
                 input.value = input.options[input.options.length - 1].value; want = Number(input.value);
                 input.dispatchEvent(new Event('change'));
               } else {
                 input.value = input.max; want = Number(input.max); input.dispatchEvent(new Event('input'));
               }
               out[name] = window.demo.get(name) === want ? 'ok' : `got ${window.demo.get(name)}, wanted ${want}`;
             }
             return out;")
        .await;
    browser.wait_frames(3).await;
    let state = browser
        .js("return { error: document.querySelector('#pool').dataset.error || null, fps: window.demo.stats().fps };")
        .await;
    println!("{backend}: set from the controls: {set_by_controls}; then {state}");
    for (name, result) in set_by_controls.as_object().unwrap() {
        assert_eq!(result, "ok", "{backend}: {name} from its control");
    }
    assert!(state["error"].is_null() && state["fps"].as_f64().unwrap() > 0.0, "{backend}: {state}");
    browser.close().await;
}

#[tokio::test]
async fn fresnel_models_switch_in_the_page_with_their_curve_on_webgpu() {
    let _g = serial();
    fresnel_models_in_the_page(Graphics::WebGpu, "webgpu").await;
}

#[tokio::test]
async fn fresnel_models_switch_in_the_page_with_their_curve_on_webgl2() {
    let _g = serial();
    fresnel_models_in_the_page(Graphics::WebGl2Only, "webgl2").await;
}

/// The page's Ambient waves select switches between the five models: each draws its own
/// water (switched while the water is paused, when nothing else moves, so the change is the
/// model's own picture), which moves once running, without an error; and the controls show a
/// model's own settings only while it is chosen (wind with any model, steepness with Gerstner,
/// spectrum, grid and choppiness with the FFT).
async fn ambient_models_in_the_page(graphics: Graphics, backend: &str) {
    let (browser, _server) = open_demo(graphics, &format!("?backend={backend}&quality=1&objects=none"), backend).await;
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let shown = "const root = document.querySelector('#pool').shadowRoot;
                 return ['wind_speed', 'wave_spread', 'steepness', 'spectrum', 'fft_size', 'choppiness']
                   .filter((n) => !root.querySelector(`[name=${n}]`).closest('.row').hidden
                                  && root.querySelector(`[name=${n}]`).offsetParent !== null)
                   .join(' ');";
    let at_start = browser.js(shown).await;
    println!("{backend}: ambient none: settings shown [{}]", at_start.as_str().unwrap());
    assert_eq!(at_start, "", "{backend}: a model's settings show with no model");
    // Paused, the ambient waves stand still (they move in simulated time), so what changes when
    // the model is switched is the model's own picture, not the water's motion.
    browser.js("window.demo.set('paused', 1); return true;").await;
    browser.wait_frames(3).await;
    let mut previous = browser.screenshot().await;
    for (value, name, expected) in [
        (1, "sines", "wind_speed wave_spread"),
        (3, "gerstner", "wind_speed wave_spread steepness"),
        (2, "modes", "wind_speed"),
        (4, "fft", "wind_speed wave_spread spectrum fft_size choppiness"),
    ] {
        browser
            .js(&format!(
                "const s = document.querySelector('#pool').shadowRoot.querySelector('select[name=ambient]');
                 s.value = '{value}'; s.dispatchEvent(new Event('change')); return true;"
            ))
            .await;
        browser.wait_frames(3).await;
        let a = browser.screenshot().await;
        browser.wait_frames(2).await;
        let still = browser.screenshot().await;
        browser.js("window.demo.set('paused', 0); return true;").await;
        browser.wait_sim_time(0.5).await;
        let b = browser.screenshot().await;
        let settings = browser.js(shown).await;
        let state = browser
            .js("return { error: document.querySelector('#pool').dataset.error || null, model: window.demo.get('ambient'),
                          fps: window.demo.stats().fps };")
            .await;
        let vs_previous = previous.changed_fraction(&a, rect, 8);
        let (paused_motion, moving) = (a.changed_fraction(&still, rect, 8), a.changed_fraction(&b, rect, 8));
        println!(
            "{backend}: {name}: {:.1} % of the canvas differs from the model before (both paused; {:.2} % moves \
             while paused), {:.1} % moved in 0.5 s of water; settings shown [{}]; {state}",
            vs_previous * 100.0,
            paused_motion * 100.0,
            moving * 100.0,
            settings.as_str().unwrap()
        );
        assert!(state["error"].is_null() && state["model"] == value as f64, "{backend}: {name}: {state}");
        assert_eq!(settings, expected, "{backend}: {name}: settings shown");
        assert!(paused_motion < 0.002, "{backend}: {name}: the paused water moved ({paused_motion})");
        assert!(vs_previous > 0.01 && moving > 0.01, "{backend}: {name}: {vs_previous} / {moving}");
        browser.js("window.demo.set('paused', 1); return true;").await;
        browser.wait_frames(3).await;
        previous = browser.screenshot().await;
    }
    browser.js("window.demo.set('paused', 0); return true;").await;
    // The finer lattice and the other spectrum run too.
    browser.js("window.demo.set('fft_size', 128); window.demo.set('spectrum', 'jonswap'); return true;").await;
    browser.wait_frames(4).await;
    let after = browser.screenshot().await;
    let state = browser
        .js("return { error: document.querySelector('#pool').dataset.error || null, size: window.demo.get('fft_size'),
                      spectrum: window.demo.get('spectrum') };")
        .await;
    let changed = previous.changed_fraction(&after, rect, 8);
    println!("{backend}: fft 128² JONSWAP: {:.1} % changed; {state}", changed * 100.0);
    assert!(state["error"].is_null() && state["size"] == 128.0 && state["spectrum"] == 1.0, "{backend}: {state}");
    assert!(changed > 0.01);
    // Choppy: the second FFT chain and the fixed-point lookups run too, the water still there.
    let before = after;
    browser.js("window.demo.set('choppiness', 3); return true;").await;
    browser.wait_frames(3).await;
    let choppy = browser.screenshot().await;
    let state = browser.js("return { error: document.querySelector('#pool').dataset.error || null };").await;
    browser.wait_sim_time(0.5).await;
    let later = browser.screenshot().await;
    // A surface lost to NaN shows the bare pool, which does not move.
    let (changed, moving) = (before.changed_fraction(&choppy, rect, 8), choppy.changed_fraction(&later, rect, 8));
    println!(
        "{backend}: choppiness 3: {:.1} % changed, {:.1} % moved in 0.5 s of water; {state}",
        changed * 100.0,
        moving * 100.0
    );
    assert!(
        state["error"].is_null() && changed > 0.01 && moving > 0.01,
        "{backend}: choppy {changed} / {moving}, {state}"
    );
    browser.close().await;
}

#[tokio::test]
async fn the_ambient_select_switches_all_five_models_on_webgpu() {
    let _g = serial();
    ambient_models_in_the_page(Graphics::WebGpu, "webgpu").await;
}

#[tokio::test]
async fn the_ambient_select_switches_all_five_models_on_webgl2() {
    let _g = serial();
    ambient_models_in_the_page(Graphics::WebGl2Only, "webgl2").await;
}

/// Flat water in the page: the split view's halves are the flat and the ray-traced pictures,
/// the divider drags, its control follows, no error. The page starts flat, so the flat
/// picture owes nothing to a ray-traced frame drawn before it.
async fn flat_water_in_the_page(graphics: Graphics, backend: &str) {
    let query = format!("?backend={backend}&quality=1&objects=sphere&paused=1&flat_resolution=1&render_mode=flat");
    let (browser, _server) = open_demo(graphics, &query, backend).await;
    let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let shot = |mode: u32| {
        let browser = &browser;
        async move {
            browser.js(&format!("window.demo.set('render_mode', {mode}); return true;")).await;
            browser.wait_frames(3).await;
            browser.screenshot().await
        }
    };
    let flat = shot(1).await;
    let split = shot(2).await;
    let traced = shot(0).await;
    // Back to the split view, to read its controls and drag its divider.
    let split_again = shot(2).await;
    // Halves, leaving out the divider's grip in the middle.
    let (left, right) = rect.halves(8);
    let (left_diff, right_diff, modes) = (
        split.changed_fraction(&flat, left, 16),
        split.changed_fraction(&traced, right, 16),
        flat.changed_fraction(&traced, rect, 16),
    );
    let history = split_again.changed_fraction(&split, rect, 16);
    let state = browser
        .js("return { error: document.querySelector('#pool').dataset.error || null, note: window.demo.stats().flatNote,
                      splitShown: !document.querySelector('#pool').shadowRoot.querySelector('[name=split]').closest('.row').hidden };")
        .await;
    println!(
        "{backend}: split vs flat on the left {:.2} % of pixels differ, vs ray-traced on the right {:.2} %; flat vs \
         ray-traced {:.1} %; split again after the ray-traced frame vs the first split {:.2} %; {state}",
        left_diff * 100.0,
        right_diff * 100.0,
        modes * 100.0,
        history * 100.0
    );
    assert!(history < 0.02, "{backend}: the split picture depends on the modes drawn before it");
    assert!(state["error"].is_null() && state["note"].is_null() && state["splitShown"] == true, "{backend}: {state}");
    assert!(left_diff < 0.02 && right_diff < 0.02, "{backend}: the split halves are not the two modes");
    assert!(modes > 0.05, "{backend}: flat and ray-traced water look alike ({:.1} %)", modes * 100.0);
    // Drag the divider a quarter of the width to the right.
    let (cx, cy) = (rect.x as f64 + rect.w as f64 / 2.0, rect.y as f64 + rect.h as f64 / 2.0);
    browser.drag((cx, cy), (cx + rect.w as f64 / 4.0, cy), 8).await;
    browser.wait_frames(2).await;
    let after = browser
        .js("const root = document.querySelector('#pool').shadowRoot;
             return { split: window.demo.get('split'), control: Number(root.querySelector('[name=split]').value) };")
        .await;
    println!("{backend}: divider dragged: {after}");
    // Each mode's cost, measured while it was shown: GPU time where WebGPU has timestamps
    // (Chromium here does), frame intervals anyway, written under the mode's control.
    let costs = browser
        .js("return { gpu: window.demo.stats().gpuMs,
                      text: document.querySelector('#pool').shadowRoot.querySelector('.costs').textContent };")
        .await;
    println!("{backend}: costs {costs}");
    let text = costs["text"].as_str().unwrap_or("");
    assert!(text.contains("Between frames: ray-traced") && !text.contains("flat –"), "{backend}: {text}");
    if backend == "webgpu" {
        for mode in ["raytraced", "flat", "split"] {
            assert!(
                costs["gpu"][mode].as_f64().is_some_and(|ms| ms > 0.0),
                "{backend}: no GPU time for {mode}: {costs}"
            );
        }
    } else {
        assert!(costs["gpu"].is_null() && text.contains("does not measure"), "{backend}: {costs}");
    }
    let split_now = after["split"].as_f64().unwrap();
    assert!((split_now - 0.75).abs() < 0.02, "{backend}: the divider is at {split_now}");
    assert!((after["control"].as_f64().unwrap() - split_now).abs() < 0.011, "{backend}: the control did not follow");
    browser.close().await;
}

#[tokio::test]
async fn flat_water_splits_and_the_divider_drags_on_webgpu() {
    let _g = serial();
    flat_water_in_the_page(Graphics::WebGpu, "webgpu").await;
}

#[tokio::test]
async fn flat_water_splits_and_the_divider_drags_on_webgl2() {
    let _g = serial();
    flat_water_in_the_page(Graphics::WebGl2Only, "webgl2").await;
}

/// The open sea in the page on both backends: a picture (sky over darker water), its own
/// controls shown, and back to the pool without a reload or an error; then the ripple tank.
#[tokio::test]
async fn the_sea_and_the_ripple_tank_run_in_the_page_on_both_backends_and_give_the_pool_back() {
    let _g = serial();
    for (graphics, backend) in [(Graphics::WebGpu, "webgpu"), (Graphics::WebGl2Only, "webgl2")] {
        // As a shared link opens it: the scene and the sea camera's view.
        let link = format!("?backend={backend}&scene=sea&quality=1&camera=150,12,60");
        let (browser, _server) = open_demo(graphics, &link, backend).await;
        assert!(browser.wait_for("window.demo.stats().scene === 'sea'", Duration::from_secs(20)).await);
        let view = browser.js("return { camera: window.demo.camera(), link: window.demo.shareLink() };").await;
        let camera: Vec<f64> = view["camera"].as_array().into_iter().flatten().filter_map(Value::as_f64).collect();
        assert!(camera == [150.0, 12.0, 60.0], "{backend}: the link's view is lost: {view}");
        assert!(view["link"].as_str().is_some_and(|l| l.contains("scene=sea") && l.contains("camera=150,12,60")));
        let rect = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
        let shot = browser.screenshot().await;
        shot.dump(&format!("sea-{backend}"));
        let band = |from: u32, to: u32| Rect { y: rect.y + rect.h * from / 10, h: rect.h * (to - from) / 10, ..rect };
        let (sky, sea) = (shot.mean(band(0, 2)), shot.mean(band(7, 10)));
        let controls = browser
            .js("const root = document.querySelector('#pool').shadowRoot;
                 const shown = n => !root.querySelector(`[name=${n}]`).closest('.row').hidden;
                 return { wind: shown('sea_wind'), fog: shown('sea_fog'), sun: shown('sun_elevation'),
                          waveSpeed: shown('wave_speed'), ambient: shown('ambient') };")
            .await;
        println!("{backend}: sky {sky:.0?}, sea {sea:.0?}, sea controls {controls}");
        assert!(sky[2] > sky[0] && sea[2] > sea[0], "{backend}: sky and sea are not blue");
        assert!(sea.iter().sum::<f64>() < sky.iter().sum::<f64>(), "{backend}: the sea is not darker than the sky");
        assert!(controls["wind"] == true && controls["fog"] == true, "{backend}: the sea's controls are hidden");
        assert!(controls["sun"] == true, "{backend}: the sun's controls, which the sea reads, are hidden");
        assert!(
            controls["waveSpeed"] == false && controls["ambient"] == false,
            "{backend}: the pool's controls show in the sea"
        );
        browser.js("window.demo.set('scene', 0); return true;").await;
        assert!(browser.wait_for("window.demo.stats().scene === 'pool'", Duration::from_secs(20)).await);
        let state = browser
            .js("const root = document.querySelector('#pool').shadowRoot;
                 return { error: document.querySelector('#pool').dataset.error || null,
                          wind: !root.querySelector('[name=sea_wind]').closest('.row').hidden,
                          waveSpeed: !root.querySelector('[name=wave_speed]').closest('.row').hidden };")
            .await;
        assert!(
            state["error"].is_null() && state["wind"] == false && state["waveSpeed"] == true,
            "{backend}: back in the pool: {state}"
        );
        // The ripple tank too: its double slit's lines on the screen under the tray, its own
        // controls, and its heights as colour when asked.
        browser
            .js("window.demo.set('scene', 'tank'); window.demo.set('tank_setup', 'double_slit'); return true;")
            .await;
        assert!(browser.wait_for("window.demo.stats().scene === 'tank'", Duration::from_secs(20)).await);
        browser.wait_frames(20).await;
        let screen = browser.screenshot().await;
        screen.dump(&format!("tank-{backend}"));
        let middle = Rect::centred_square(rect.w, rect.h, 0.5);
        let middle = Rect { x: rect.x + middle.x, y: rect.y + middle.y, ..middle };
        browser.js("window.demo.set('tank_view', 'heights'); return true;").await;
        browser.wait_frames(3).await;
        let heights = browser.screenshot().await;
        let tank = browser
            .js("const root = document.querySelector('#pool').shadowRoot;
                 const shown = n => !root.querySelector(`[name=${n}]`).closest('.row').hidden;
                 return { setup: shown('tank_setup'), sun: shown('sun_elevation'), waveSpeed: shown('wave_speed'),
                          error: document.querySelector('#pool').dataset.error || null, stages: window.demo.stats().stageMs };")
            .await;
        let (spread, recoloured) = (screen.luma_spread(middle), screen.changed_fraction(&heights, middle, 24));
        println!(
            "{backend}: the tank's screen, luma spread {spread:.1}; {:.0}% changed for the heights; {tank}",
            recoloured * 100.0
        );
        assert!(tank["error"].is_null() && tank["setup"] == true, "{backend}: the tank's controls: {tank}");
        assert!(tank["sun"] == false && tank["waveSpeed"] == false, "{backend}: other scenes' controls show: {tank}");
        assert!(spread > 10.0 && recoloured > 0.3, "{backend}: the tank's pictures are flat or alike");
        // Its instruments: the probe reads the dipper's frequency, the ruler its length, and
        // what is drawn goes into the share link.
        let sketch = "W-100,-150,100,-120_R-200,-100,100,-100";
        browser
            .js(&format!(
                "window.demo.set('tank_setup', 'dipper'); window.demo.set('tank_probe', 1);
                 window.demo.set('tank_probe_z', 60); window.demo.setSketch('{sketch}'); return true;"
            ))
            .await;
        let probe = "(r => !!r && Math.abs(r.value / 10 - 1) < 0.01)(window.demo.stats().readings['probe frequency'])";
        let read = browser.wait_for(probe, Duration::from_secs(30)).await;
        // The readings under the controls, written twice a second.
        let text = "document.querySelector('#pool').shadowRoot.querySelector('.readings').textContent";
        browser.wait_for(&format!("{text}.includes('Probe frequency')"), Duration::from_secs(5)).await;
        let instruments = browser
            .js("const root = document.querySelector('#pool').shadowRoot;
                 return { readings: window.demo.stats().readings, link: window.demo.shareLink(),
                          shown: root.querySelector('.readings').textContent };")
            .await;
        println!("{backend}: the tank's instruments: {instruments}");
        assert!(read, "{backend}: the probe does not read 10 Hz within 1 %: {instruments}");
        let ruler = instruments["readings"]["ruler"]["value"].as_f64().unwrap_or(0.0);
        assert!((ruler - 300.0).abs() < 1.0, "{backend}: the ruler reads {ruler} mm, not 300");
        let link = instruments["link"].as_str().unwrap_or("");
        assert!(link.contains(&format!("sketch={sketch}")), "{backend}: the drawing is not in the link {link}");
        let shown = instruments["shown"].as_str().unwrap_or("");
        assert!(shown.contains("Probe frequency: ") && shown.contains("Ruler: 300 mm"), "{backend}: shown {shown}");
        // The move tool shows the picked dipper's own settings; its frequency slider goes into the link.
        browser.js("window.demo.set('tank_tool', 'move'); return true;").await;
        let group = "document.querySelector('#pool').shadowRoot.querySelector('fieldset.picked')";
        let shown = browser.wait_for(&format!("!{group}.hidden"), Duration::from_secs(5)).await;
        let own = browser
            .js(&format!(
                "const group = {group}; const input = group.querySelector('[name=frequency]');
                 input.value = '12'; input.dispatchEvent(new Event('input'));
                 return {{ title: group.querySelector('legend').textContent, sketch: window.demo.sketch(),
                          picked: window.demo.picked().settings.map(s => s.value) }};"
            ))
            .await;
        println!("{backend}: the move tool's dipper: {own}");
        assert!(shown && own["title"] == "Dipper 1", "{backend}: the picked dipper's settings: {own}");
        let sketch = own["sketch"].as_str().unwrap_or("");
        assert!(sketch.contains("T0,12,"), "{backend}: the dipper's own frequency is not in the sketch {sketch}");
        // The apparatus beside the screen view: the lab's dim room on the left, the paper on the right.
        browser.js("window.demo.set('tank_look', 'split'); window.demo.set('tank_view', 'screen'); return true;").await;
        browser.wait_frames(3).await;
        let split = browser.screenshot().await;
        split.dump(&format!("tank-split-{backend}"));
        let half = |k: u32| Rect { x: rect.x + k * rect.w / 2, w: rect.w / 2, ..rect };
        let (apparatus, paper) = (split.mean(half(0)), split.mean(half(1)));
        let error = browser.js("return document.querySelector('#pool').dataset.error || null;").await;
        println!("{backend}: split, the apparatus's mean {apparatus:.0?}, the screen view's {paper:.0?}");
        assert!(error.is_null() && apparatus[1] + 20.0 < paper[1], "{backend}: the split: {error}");
        browser.close().await;
    }
}
