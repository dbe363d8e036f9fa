//! Look benchmark for issue 27 ("the picture must beat Evan Wallace's classic WebGL Water"):
//! the figures of our default view and the classic's, in the same browser run at the same canvas
//! size (tests/support/picture.rs defines them): colourfulness (Hasler and Süsstrunk), the
//! standard deviation of Rec. 709 luma, the sparkle share (pixels more than 40/255 of luma off
//! their 3x3 median) and the floor's caustic contrast (95th / 50th luma percentile).
//!
//! One headless Chromium with the WebGPU flags (which give WebGL2 too) and an 800x600 viewport
//! loads our `/index.html?backend=B&quality=1&controls=0` for B = webgpu, then webgl2, then the
//! classic `/classic/index.html` (WebGL1; served read-only from ../shared/anchors/webgl-water).
//! Canvas size: the classic's canvas is the window less its help panel, 480x600 at (0, 0) in
//! that viewport; ours is made the same by giving the page's `#pool` element that size at the
//! same place before the demo mounts (an init script pins it: `position: fixed`, 480x600 px;
//! an element with a height of its own is filled by the demo, see web/embed.js), with
//! `quality=1` so the scene is drawn at the canvas's full resolution. Nothing is cropped: both
//! canvases measure 480x600 (checked; a mismatch stops the run). Our play/fullscreen buttons and
//! the stage's rounded corners are hidden before each screenshot, so only the picture counts.
//! Each screenshot is of the viewport, cut to the canvas's rectangle.
//!
//! Four measurements per page, over the whole canvas, each at a simulated time (what a machine
//! drawing 60 frames a second shows then; see `LOAD_SIM`):
//! - `load`: the default view 1 s into the page's water (ours: `stats().simTime`, with the drops
//!   it starts with; the classic: its start, twenty drops on calm water, stepped 60 frames);
//! - `ripples`: then four drops, each the page's own click drop (ours: `demo.addDrop(x, z)` at its
//!   default radius and strength; the classic: `water.addDrop(x, z, 0.03, 0.01)`, what its mouse
//!   makes), at the same pool points, and 1 s later;
//! - `caustics`: the sun overhead, no objects, looking straight down, calm water, then one drop
//!   in the middle and 0.5 s later; also the caustic contrast over the middle 40 % square of
//!   the canvas (the pool's floor through the water). Ours: reloaded with `objects=none`,
//!   `sun_elevation=90` (its maximum) and `camera=0,89,3.8` (pitch at its maximum; the eye
//!   3.5 m above the water, as the classic's, whose distance is fixed, both 45° high), then
//!   `demo.reset()` (calm water). The classic, in place: `angleX = -89.9` (straight down),
//!   `renderer.lightDir = (0, 1, 0)`, the sphere moved to (10, 10, 10) (out of view, shadow and
//!   reflections; `oldCenter` too, so moving it makes no wave), and both water textures cleared
//!   (height, velocity and normal 0: calm).
//! - `under`: the `ripples` water seen from under it, the camera 20° below the level looking
//!   up (`UNDER_PITCH`): ours reloaded in the cut-away setting (`setting=cutaway`, its default
//!   yaw and distance) and taken through the same start and drops; the classic in place, its
//!   `angleX` turned to 20 (measured before its `caustics` view, which calms its water).
//!
//! The classic is paused and stepped by the bench (`CLASSIC_STEP_JS`): it steps once per frame
//! drawn, and in software rendering here (about 4 frames a second) a wall-clock second holds a
//! fifteenth of a second of its waves, younger rings than any student sees. Before 2026-11-29
//! the bench waited in wall time for it and compared its young rings with our older ones.
//!
//! Run: `cargo bench --bench look` after building dist/ (`./scripts/serve` or
//! `trunk build --release`; `WAVEPOOL_DIST` points elsewhere). Settings (environment):
//! - `WAVEPOOL_LOOK_DIR` (`target/look/` in the crate): where the screenshots go, as
//!   `ours-webgpu-load.png`, `ours-webgl2-ripples.png`, `classic-caustics.png`, ...;
//! - `WAVEPOOL_LOOK_PAGES` (`webgpu webgl2 classic`): which pages, space-separated.
//! - `WAVEPOOL_LOOK_QUERY`: extra options for our page, e.g. `&preset=evening` (the load and
//!   ripple views take them; the caustics view too, before its own).
//! - `WAVEPOOL_LOOK_SIZE=page`: each page at its own canvas in a 1000x700 window, as a laptop
//!   shows it (ours with its controls under the pool, not pinned; the classic's canvas is the
//!   window less its panel): the figures where a student meets the pages, not at one size.
//!
//! Prints one JSON line per page and measurement (its figures, the canvas, the PNG's path),
//! then one summary line per measurement with the figures of ours (webgpu), ours (webgl2) and
//! the classic side by side.

#[path = "../tests/support/browser.rs"]
mod support;

use std::path::{Path, PathBuf};
use std::time::Duration;

use serde_json::{json, Value};
use support::picture::{self, Image, PictureStats};
use support::{canvas_rect_js, Browser, Graphics, Rect, StaticServer};

/// The viewport (CSS px) and the canvas size both pages are measured at: the classic's canvas
/// in that viewport.
const VIEWPORT: (u32, u32) = (800, 600);
const CANVAS: (u32, u32) = (480, 600);
/// Longest wait for a page to run (SwiftShader compiles slowly).
const READY_TIMEOUT: Duration = Duration::from_secs(180);
/// Simulated time (s) from the start to the `load` screenshot, from the drops to the `ripples`
/// one, and from the caustics drop to its screenshot, in both pages: what a machine drawing
/// 60 frames a second shows then. Each page's simulation is stepped by its own clock: ours by
/// simulated time (`stats().simTime`; a slow machine's frames take longer to reach it); the
/// classic's by frames (two steps each, 60 a second; it waits for nothing), which the bench
/// steps itself with the classic paused, as on a slow machine its wall-clock seconds would
/// hold a tenth of the waves' travel and show younger rings than a student sees.
const LOAD_SIM: f64 = 1.0;
const RIPPLE_SIM: f64 = 1.0;
const CAUSTIC_SIM: f64 = 0.5;
/// Calm water before the caustics drop (ours: wall time).
const CALM_WAIT: Duration = Duration::from_millis(500);
/// The classic's frames a simulated second (its `update` steps the water twice a frame).
const CLASSIC_FPS: f64 = 60.0;
/// Where the `ripples` drops land (pool coordinates, m; the pool spans -1..1 in both pages).
const DROPS: [(f64, f64); 4] = [(0.0, 0.0), (0.45, 0.3), (-0.5, -0.25), (0.25, -0.55)];
/// Our camera looking down (yaw, pitch, distance): pitch at its maximum, the eye 3.5 m above the
/// water (target 0.3 m below it) like the classic's.
const OUR_TOP_VIEW: (f64, f64, f64) = (0.0, 89.0, 3.8);
/// The floor rectangle of the caustic contrast: this share of the canvas's shorter side, centred.
const FLOOR_SQUARE: f64 = 0.4;
const MEASUREMENTS: [&str; 4] = ["load", "ripples", "caustics", "under"];
/// The `under` view's pitch (degrees): the camera this far below the level, looking up at the
/// water from under it (ours in the cut-away setting, at its default yaw and distance; the
/// classic's `angleX` the same, negated, at its own).
const UNDER_PITCH: f64 = -20.0;

/// Pins our page's `#pool` to the classic canvas's place and size before the demo mounts (run
/// by Chromium before each document's own scripts; the classic is left alone).
const PIN_POOL_JS: &str = "(() => {
  if (location.pathname.startsWith('/classic/')) return;
  const pin = () => {
    const pool = document.getElementById('pool');
    if (!pool) return false;
    Object.assign(pool.style, { position: 'fixed', left: '0', top: '0', margin: '0', width: '480px', height: '600px', zIndex: '1000' });
    return true;
  };
  if (pin()) return;
  const watch = new MutationObserver(() => pin() && watch.disconnect());
  watch.observe(document, { childList: true, subtree: true });
})();";

/// Pauses the classic (its own space bar: nothing steps or draws), then steps its water and
/// its sphere's displacement through `__FRAMES__` frames as its `update` does, its normals and
/// caustics after them (the sphere's shadow where it is now), and draws once (its own L-key path, which draws while paused, with the
/// L key held off so the light stays its own). `__BEFORE__` runs first (drops).
const CLASSIC_STEP_JS: &str = "paused = true;
  __BEFORE__
  for (let f = 0; f < __FRAMES__; f++) {
    water.moveSphere(oldCenter, center, radius);
    oldCenter = center;
    water.stepSimulation();
    water.stepSimulation();
  }
  water.updateNormals();
  renderer.sphereCenter = center;
  renderer.sphereRadius = radius;
  renderer.updateCaustics(water);
  Object.defineProperty(GL.keys, 'L', { get() { return false; }, set(v) {}, configurable: true });
  document.dispatchEvent(new KeyboardEvent('keydown', { keyCode: 76, which: 76 }));
  return true;";

/// The classic's start (its `onload`'s twenty drops, alternately up and down, at its click
/// drop's radius) on calm water, at seeded places (a Park-Miller sequence) so every run
/// measures the same water.
const CLASSIC_START_JS: &str = "const calm = () => { gl.clearColor(0, 0, 0, 0); gl.clear(gl.COLOR_BUFFER_BIT); };
  water.textureA.drawTo(calm);
  water.textureB.drawTo(calm);
  gl.clearColor(0, 0, 0, 1);
  let seed = 2011;
  const next = () => { seed = (seed * 16807) % 2147483647; return seed / 2147483647; };
  for (let i = 0; i < 20; i++) water.addDrop(next() * 2 - 1, next() * 2 - 1, 0.03, (i & 1) ? 0.01 : -0.01);";

/// The classic stepped through `seconds` of simulated time after `before` ran.
fn classic_step_js(before: &str, seconds: f64) -> String {
    let frames = (seconds * CLASSIC_FPS).round() as u32;
    CLASSIC_STEP_JS.replace("__BEFORE__", before).replace("__FRAMES__", &frames.to_string())
}

/// Hides our overlay buttons and the stage's rounded corners (over the canvas); returns our
/// page's own figures.
const TIDY_OURS_JS: &str = "const root = document.querySelector('#pool').shadowRoot;
  root.querySelector('.stage').style.borderRadius = '0';
  const overlay = root.querySelector('.overlay');
  if (overlay) overlay.style.display = 'none';
  const s = window.demo.stats();
  return { backend: s.backend, renderScale: s.renderScale === undefined ? null : s.renderScale,
           fps: s.fps, camera: window.demo.camera(), sunElevation: window.demo.get('sun_elevation'),
           objects: window.demo.get('objects') };";

const CLASSIC_CANVAS_JS: &str = "const c = document.querySelector('canvas'); const r = c.getBoundingClientRect();
  return { left: r.left, top: r.top, width: r.width, height: r.height, size: [c.width, c.height] };";

/// The classic, looking straight down with the sun overhead, the sphere away and calm water.
const CLASSIC_TOP_VIEW_JS: &str = "angleX = -89.9;
  renderer.lightDir = new GL.Vector(0, 1, 0);
  window.center = window.oldCenter = new GL.Vector(10, 10, 10);
  const calm = () => { gl.clearColor(0, 0, 0, 0); gl.clear(gl.COLOR_BUFFER_BIT); };
  water.textureA.drawTo(calm);
  water.textureB.drawTo(calm);
  gl.clearColor(0, 0, 0, 1);
  return { angleX, angleY, lightDir: [renderer.lightDir.x, renderer.lightDir.y, renderer.lightDir.z] };";

/// The pool's opening (the water's rest level, y = 0) and its floor (y = -1), each as the
/// four corners (x, z = ±1, m) where they appear, in CSS px from the viewport's corner: both pages
/// draw a 2 m x 2 m pool 1 m deep. Ours through `demo.project`.
const OUR_POOL_CORNERS_JS: &str = "const out = [];
  for (const y of [0, -1]) for (const [x, z] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) out.push(window.demo.project(x, y, z));
  return out;";

/// The same for the classic: lightgl's `gl.project` with the camera's matrices as its last
/// frame left them, over the canvas's own viewport (y up from its bottom, turned to CSS px down).
const CLASSIC_POOL_CORNERS_JS: &str = "const c = document.querySelector('canvas'); const r = c.getBoundingClientRect();
  const out = [];
  for (const y of [0, -1]) for (const [x, z] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
    const v = gl.project(x, y, z, gl.modelviewMatrix, gl.projectionMatrix, [0, 0, c.width, c.height]);
    out.push({ x: r.left + v.x * r.width / c.width, y: r.top + (c.height - v.y) * r.height / c.height });
  }
  return out;";

/// One page and measurement: its name in the summary and its figures.
struct Row {
    page: String,
    measurement: &'static str,
    stats: PictureStats,
    /// The floor's caustic contrast as the view shows it (`floor_in_view`), for `load` and
    /// `ripples`.
    floor_in_view: Option<f64>,
}

/// Whether the pages are measured at their own canvases in `PAGE_VIEWPORT` (`WAVEPOOL_LOOK_SIZE=page`).
fn at_page_size() -> bool {
    std::env::var("WAVEPOOL_LOOK_SIZE").is_ok_and(|v| v == "page")
}

/// The window of `WAVEPOOL_LOOK_SIZE=page`: a laptop's browser window.
const PAGE_VIEWPORT: (u32, u32) = (1000, 700);

#[tokio::main(flavor = "current_thread")]
async fn main() {
    let dir = std::env::var_os("WAVEPOOL_LOOK_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target/look"));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("create {}: {e}", dir.display()));
    let pages: Vec<String> = std::env::var("WAVEPOOL_LOOK_PAGES")
        .unwrap_or_else(|_| "webgpu webgl2 classic".into())
        .split_whitespace()
        .map(str::to_owned)
        .collect();
    let server = StaticServer::start_with_classic(false);
    let browser = Browser::open(Graphics::WebGpu).await;
    let window = if at_page_size() { PAGE_VIEWPORT } else { VIEWPORT };
    if !at_page_size() {
        browser.add_init_script(PIN_POOL_JS).await;
    }
    let viewport = browser.set_viewport(window.0, window.1).await;
    let agent = browser.js("return navigator.userAgent;").await;
    println!("{}", json!({ "viewport": [viewport.0, viewport.1], "browser": agent, "dir": dir.display().to_string() }));
    let mut rows = Vec::new();
    for page in &pages {
        match page.as_str() {
            "webgpu" | "webgl2" => rows.extend(ours(&browser, &server, page, &dir).await),
            "classic" => rows.extend(classic(&browser, &server, &dir).await),
            other => panic!("WAVEPOOL_LOOK_PAGES: {other:?} is not webgpu, webgl2 or classic"),
        }
    }
    browser.close().await;
    for measurement in MEASUREMENTS {
        let mut line = json!({ "summary": measurement });
        for row in rows.iter().filter(|r| r.measurement == measurement) {
            let s = row.stats.to_json();
            line[&row.page] = json!({ "colourfulness": s["colourfulness"], "luma_std": s["luma_std"],
                                      "sparkle_share": s["sparkle_share"], "caustic_contrast": s["caustic_contrast"],
                                      "floor_in_view": row.floor_in_view.map(|c| (c * 1e4).round() / 1e4) });
        }
        println!("{line}");
    }
}

/// Our page on `backend`: the three measurements.
async fn ours(browser: &Browser, server: &StaticServer, backend: &str, dir: &Path) -> Vec<Row> {
    // Extra options for our page (e.g. `&preset=evening`), named in the page's name too.
    let extra = std::env::var("WAVEPOOL_LOOK_QUERY").unwrap_or_default();
    let name = format!("ours-{backend}{}", extra.replace(['&', '='], "-"));
    let controls = if at_page_size() { "" } else { "&controls=0" };
    let base = format!("/index.html?backend={backend}&quality=1{controls}{extra}");
    let mut rows = Vec::new();

    let info = load_ours(browser, server, &base, backend).await;
    wait_sim(browser, "0", LOAD_SIM).await;
    rows.push(shoot(browser, &name, "load", &base, info, dir).await);

    let drops: Vec<String> = DROPS.iter().map(|(x, z)| format!("d.addDrop({x}, {z});")).collect();
    browser
        .js(&format!("const d = window.demo; window.__dropAt = d.stats().simTime; {} return true;", drops.concat()))
        .await;
    wait_sim(browser, "window.__dropAt", RIPPLE_SIM).await;
    rows.push(shoot(browser, &name, "ripples", &base, Value::Null, dir).await);

    let (yaw, pitch, distance) = OUR_TOP_VIEW;
    let top = format!("{base}&objects=none&sun_elevation=90&camera={yaw},{pitch},{distance}");
    load_ours(browser, server, &top, backend).await;
    browser.js("window.demo.reset(); return true;").await;
    tokio::time::sleep(CALM_WAIT).await;
    browser.js("window.__dropAt = window.demo.stats().simTime; window.demo.addDrop(0, 0); return true;").await;
    wait_sim(browser, "window.__dropAt", CAUSTIC_SIM).await;
    let info = browser.js(TIDY_OURS_JS).await;
    rows.push(shoot(browser, &name, "caustics", &top, info, dir).await);

    let under = format!("{base}&setting=cutaway&camera=-25,{UNDER_PITCH},3");
    let info = load_ours(browser, server, &under, backend).await;
    wait_sim(browser, "0", LOAD_SIM).await;
    browser
        .js(&format!("const d = window.demo; window.__dropAt = d.stats().simTime; {} return true;", drops.concat()))
        .await;
    wait_sim(browser, "window.__dropAt", RIPPLE_SIM).await;
    rows.push(shoot(browser, &name, "under", &under, info, dir).await);
    rows
}

/// Waits until our page's simulated time is `seconds` past `since` (a JS expression).
async fn wait_sim(browser: &Browser, since: &str, seconds: f64) {
    let reached = format!("window.demo.stats().simTime - {since} >= {seconds}");
    assert!(browser.wait_for(&reached, READY_TIMEOUT).await, "our page's water stopped");
}

/// Loads our page at `path`, waits until it runs on `backend`, tidies it (see `TIDY_OURS_JS`)
/// and returns its own figures.
async fn load_ours(browser: &Browser, server: &StaticServer, path: &str, backend: &str) -> Value {
    browser.goto(&server.url(path)).await;
    browser.wait_ready("#pool", READY_TIMEOUT).await;
    assert!(browser.wait_for("window.demo", Duration::from_secs(10)).await, "{path}: no window.demo");
    let info = browser.js(TIDY_OURS_JS).await;
    assert_eq!(info["backend"], backend, "{path}: the page runs on another backend: {info}");
    info
}

/// The classic: the three measurements.
async fn classic(browser: &Browser, server: &StaticServer, dir: &Path) -> Vec<Row> {
    let path = "/classic/index.html";
    let mut rows = Vec::new();
    browser.goto(&server.url(path)).await;
    let running = "document.querySelector('canvas') && document.getElementById('loading').innerHTML === ''";
    assert!(
        browser.wait_for(running, READY_TIMEOUT).await,
        "the classic did not start (is WebGL with float textures there?)"
    );
    browser.js(&classic_step_js(CLASSIC_START_JS, LOAD_SIM)).await;
    rows.push(shoot(browser, "classic", "load", path, Value::Null, dir).await);

    let drops: Vec<String> = DROPS.iter().map(|(x, z)| format!("water.addDrop({x}, {z}, 0.03, 0.01);")).collect();
    browser.js(&classic_step_js(&drops.concat(), RIPPLE_SIM)).await;
    rows.push(shoot(browser, "classic", "ripples", path, Value::Null, dir).await);

    // From under the water, the ripples' state (it draws once, stepping nothing).
    browser.js(&classic_step_js(&format!("angleX = {};", -UNDER_PITCH), 0.0)).await;
    rows.push(shoot(browser, "classic", "under", path, Value::Null, dir).await);

    let info = browser.js(CLASSIC_TOP_VIEW_JS).await;
    browser.js(&classic_step_js("water.addDrop(0, 0, 0.03, 0.01);", CAUSTIC_SIM)).await;
    rows.push(shoot(browser, "classic", "caustics", path, info, dir).await);
    rows
}

/// Screenshots the page's canvas, saves it as `<page>-<measurement>.png`, computes its figures
/// (with the caustic contrast for `caustics`) and prints them as one JSON line.
async fn shoot(browser: &Browser, page: &str, measurement: &'static str, url: &str, info: Value, dir: &Path) -> Row {
    let canvas = if page == "classic" {
        browser.js(CLASSIC_CANVAS_JS).await
    } else {
        let mut v = browser.js(&canvas_rect_js("#pool")).await;
        v["size"] = browser
            .js("const c = document.querySelector('#pool').shadowRoot.querySelector('canvas'); return [c.width, c.height];")
            .await;
        v
    };
    let rect = Rect::from_js(&canvas);
    assert!(
        at_page_size() || (rect.w, rect.h) == CANVAS && canvas["size"] == json!([CANVAS.0, CANVAS.1]),
        "{page}: the canvas is not {}x{} (CSS and backing pixels) as the comparison needs: {canvas}",
        CANVAS.0,
        CANVAS.1
    );
    let shot = browser.screenshot().await;
    let (width, height, rgba) = crop(&shot, rect);
    let file = dir.join(format!("{page}-{measurement}.png"));
    save_png(&file, width, height, &rgba);
    let img = Image::new(width, height, rgba);
    let mut stats = PictureStats::of(&img, img.full());
    let mut floor_in_view = None;
    if measurement == "caustics" {
        stats = stats.with_caustic_contrast(&img, picture::Rect::centred_square(width, height, FLOOR_SQUARE));
    } else if measurement != "under" {
        let corners = browser.js(if page == "classic" { CLASSIC_POOL_CORNERS_JS } else { OUR_POOL_CORNERS_JS }).await;
        // The classic draws no near walls: its floor shows whole, through them or the water.
        floor_in_view = floor_contrast_in_view(&img, &corners, rect, page != "classic");
    }
    println!(
        "{}",
        json!({ "page": page, "measurement": measurement, "url": url, "canvas": [width, height],
                "canvas_at": [rect.x, rect.y], "png": file.display().to_string(), "page_state": info,
                "figures": stats.to_json(), "floor_in_view": floor_in_view })
    );
    Row { page: page.replace('-', "_"), measurement, stats, floor_in_view }
}

/// The floor's caustic contrast as the view shows it: the 95th / 50th luma percentile over the
/// pixels of the pool's floor as projected (`corners`: the opening's four, then the floor's, in
/// CSS px of the viewport; the picture is the canvas cut at `at`), and inside the opening too
/// where the near walls hide the rest (`behind_walls`: ours, sunk in its deck): the pixels that
/// show the floor (or a wall's foot, or a body). None when a corner is behind the camera.
fn floor_contrast_in_view(img: &Image, corners: &Value, at: Rect, behind_walls: bool) -> Option<f64> {
    let points: Vec<(f64, f64)> = corners
        .as_array()?
        .iter()
        .map(|p| Some((p["x"].as_f64()? - at.x as f64, p["y"].as_f64()? - at.y as f64)))
        .collect::<Option<_>>()?;
    let (opening, floor) = points.split_at(4);
    let mut lumas: Vec<f64> = (0..img.height)
        .flat_map(|y| (0..img.width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let p = (x as f64 + 0.5, y as f64 + 0.5);
            inside_convex(floor, p) && (!behind_walls || inside_convex(opening, p))
        })
        .map(|(x, y)| img.luma(x, y))
        .collect();
    if lumas.len() < 100 {
        return None;
    }
    lumas.sort_unstable_by(f64::total_cmp);
    let at_rank = |q: f64| lumas[((lumas.len() - 1) as f64 * q).round() as usize];
    Some(at_rank(0.95) / at_rank(0.5))
}

/// Whether `p` lies inside the convex polygon `poly` (either winding).
fn inside_convex(poly: &[(f64, f64)], p: (f64, f64)) -> bool {
    let sides: Vec<f64> = (0..poly.len())
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
        })
        .collect();
    sides.iter().all(|&s| s >= 0.0) || sides.iter().all(|&s| s <= 0.0)
}

/// The pixels of `r` (clipped to the shot): width, height, RGBA8.
fn crop(shot: &Image, r: Rect) -> (u32, u32, Vec<u8>) {
    let (x, y) = (r.x.min(shot.width), r.y.min(shot.height));
    let (w, h) = (r.w.min(shot.width - x), r.h.min(shot.height - y));
    let mut rgba = Vec::with_capacity(w as usize * h as usize * 4);
    for row in y..y + h {
        let start = (row as usize * shot.width as usize + x as usize) * 4;
        rgba.extend_from_slice(&shot.rgba[start..start + w as usize * 4]);
    }
    (w, h, rgba)
}

fn save_png(path: &Path, width: u32, height: u32, rgba: &[u8]) {
    let file = std::fs::File::create(path).unwrap_or_else(|e| panic!("create {}: {e}", path.display()));
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().expect("PNG header");
    writer.write_image_data(rgba).unwrap_or_else(|e| panic!("write {}: {e}", path.display()));
}
