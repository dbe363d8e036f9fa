//! The pool in the course hosts teachers use, in headless Chromium: a reveal.js deck (keys the
//! pool or a focused control uses stay in the pool, others reach the deck; the pool fits its
//! slide whatever the history; it pauses off its slide and resumes with a picture; the canvas
//! follows the slide's scale) and a MkDocs Material site with instant navigation (ready on every
//! visit, contexts given back on leaving); axe-core finds no accessibility violation on the
//! page, the iframe page and the iframe page with controls. reveal.js, axe-core and MkDocs
//! Material are pinned and installed by ./scripts/test. Needs `dist/`.

// One browser at a time, held across awaits: each test runs on its own thread and runtime.
#![allow(clippy::await_holding_lock)]

#[path = "support/browser.rs"]
mod support;

use std::time::Duration;

use fantoccini::actions::{InputSource, KeyAction, KeyActions};
use serde_json::Value;
use support::{axe_violations, canvas_rect_js, host_packages, serial, Browser, Graphics, Rect, StaticServer, READY};

/// WebDriver's codes for the keys the tests press.
const ARROW_RIGHT: char = '\u{E014}';
const ARROW_DOWN: char = '\u{E015}';
const ENTER: char = '\u{E007}';
const ESCAPE: char = '\u{E00C}';

/// Presses and releases one key in the focused element, as a person would.
async fn press(browser: &Browser, key: char) {
    let actions =
        KeyActions::new("keyboard".into()).then(KeyAction::Down { value: key }).then(KeyAction::Up { value: key });
    browser.client.perform_actions(actions).await.expect("press a key");
}

/// Focuses an element of the pool's shadow root (`selector`), opening the drawer first.
async fn focus_in_pool(browser: &Browser, selector: &str) {
    let found = browser
        .js(&format!(
            "const r = document.getElementById('pool').shadowRoot;
             const drawer = r.querySelector('details.controls'); if (drawer) drawer.open = true;
             const e = r.querySelector('{selector}'); if (!e) return false;
             e.focus(); return r.activeElement === e;"
        ))
        .await;
    assert_eq!(found, true, "could not focus {selector} in the pool");
}

/// The deck's slide, whether its overview is open, and the pool's camera yaw, paused flag and
/// the values of the controls the test presses keys in.
const DECK_STATE_JS: &str = "const p = document.getElementById('pool'); const d = p.demo;
    const r = p.shadowRoot; const v = (s) => { const e = r.querySelector(s); return e ? e.value : null; };
    return { slide: Reveal.getIndices().h, overview: Reveal.isOverview(),
             yaw: d && !d._suspended ? d.camera()[0] : null, paused: d ? d.get('paused') : null,
             waveSpeed: v('input[name=wave_speed]'), walls: r.querySelector('input[name=absorbing_walls]')?.checked,
             ambient: v('select[name=ambient]'), preset: v('.preset select'), presetCamera: d ? d.camera()[2] : null };";

/// The pool's boxes against the slide's: element, stage, overlay buttons, canvas (CSS px) and
/// the canvas's backing size.
const FIT_JS: &str = "const p = document.getElementById('pool'); const r = p.shadowRoot;
    const box = (e) => { if (!e) return null; const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
    const c = r.querySelector('canvas:not(.still):not(.print-shot)');
    return { slide: box(document.querySelector('.reveal .slides > section.present')),
             slides: box(document.querySelector('.reveal .slides')), element: box(p),
             stage: box(r.querySelector('.stage')), buttons: [...r.querySelectorAll('.overlay button')].map(box),
             summary: box(r.querySelector('summary')), drawerOpen: !!r.querySelector('details.controls')?.open,
             canvas: box(c), backing: c ? [c.width, c.height] : null };";

fn rect(v: &Value) -> [f64; 4] {
    let a = v.as_array().unwrap_or_else(|| panic!("a box, got {v}"));
    [0, 1, 2, 3].map(|i| a[i].as_f64().unwrap())
}

/// Whether box `inner` lies inside `outer` (1 px of rounding allowed).
fn inside(inner: [f64; 4], outer: [f64; 4]) -> bool {
    inner[0] >= outer[0] - 1.0 && inner[1] >= outer[1] - 1.0 && inner[2] <= outer[2] + 1.0 && inner[3] <= outer[3] + 1.0
}

/// Checks the pool lies inside the deck's slide area, buttons and drawer's summary included;
/// returns the canvas's backing size.
fn assert_fits(fit: &Value, when: &str) -> (u64, u64) {
    println!("{when}: {fit}");
    let slides = rect(&fit["slides"]);
    for part in ["element", "stage", "summary"] {
        if !fit[part].is_null() {
            assert!(
                inside(rect(&fit[part]), slides),
                "{when}: the pool's {part} {} leaves the slide {slides:?}",
                fit[part]
            );
        }
    }
    for button in fit["buttons"].as_array().unwrap() {
        assert!(inside(rect(button), slides), "{when}: an overlay button {button} leaves the slide {slides:?}");
    }
    let backing = &fit["backing"];
    (backing[0].as_u64().unwrap(), backing[1].as_u64().unwrap())
}

/// Keeps a screenshot as `$WAVEPOOL_SHOTS/<name>.png` when that folder is given (to look at).
async fn keep_shot(browser: &Browser, name: &str) {
    if let Ok(dir) = std::env::var("WAVEPOOL_SHOTS") {
        std::fs::write(format!("{dir}/{name}.png"), browser.client.screenshot().await.expect("screenshot")).unwrap();
    }
}

/// Simulated time of the pool (s).
async fn sim_time(browser: &Browser) -> f64 {
    browser.js("return document.getElementById('pool').demo._core.simTime;").await.as_f64().unwrap_or(-1.0)
}

/// A pool on the second slide of a reveal.js deck, on WebGPU: it fits the slide (element,
/// buttons and the drawer's summary inside it) with the same canvas whether the deck was opened
/// on that slide or arrived at it; the keys it uses stay in it (arrows turn the camera, Space
/// pauses; a focused slider, checkbox and select take their keys; the Preset select does not
/// apply while arrowed through, Enter applies it) and the deck still gets the keys it does not
/// use (N moves on, Esc opens the overview); off its slide it holds its simulated time, back on
/// it runs again with a picture; the canvas follows the slide's scale when the window grows; one
/// GPU context at most.
#[tokio::test]
async fn a_pool_on_a_slide_keeps_its_keys_fits_the_slide_and_pauses_off_it() {
    let _g = serial();
    let server = StaticServer::start_with_mounts(vec![("/hosts/", host_packages())]);
    let browser = Browser::open(Graphics::WebGpu).await;

    // Arrived at from the first slide by the deck's own key.
    browser.goto(&server.url("/test/deck.html")).await;
    browser.wait_for("window.Reveal && Reveal.isReady()", READY).await;
    press(&browser, ARROW_RIGHT).await;
    browser.wait_ready("#pool", READY).await;
    let arrived = assert_fits(&browser.js(FIT_JS).await, "arrived at the slide");
    // Opened on the slide.
    browser.goto(&server.url("/test/deck.html#/1")).await;
    browser.wait_ready("#pool", READY).await;
    let opened = assert_fits(&browser.js(FIT_JS).await, "opened on the slide");
    println!("canvas arrived at {arrived:?}, opened on {opened:?}");
    assert!(
        arrived.0.abs_diff(opened.0) <= 2 && arrived.1.abs_diff(opened.1) <= 2,
        "the canvas's size depends on how the slide was reached: {arrived:?} vs {opened:?}"
    );

    // Keys on the focused pool.
    focus_in_pool(&browser, "canvas").await;
    let before = browser.js(DECK_STATE_JS).await;
    press(&browser, ARROW_RIGHT).await;
    let turned = browser.js(DECK_STATE_JS).await;
    println!("ArrowRight on the pool: {before} -> {turned}");
    assert_eq!(turned["slide"], 1, "ArrowRight on the pool changed the slide");
    assert_ne!(turned["yaw"], before["yaw"], "ArrowRight on the pool did not turn the camera");
    press(&browser, ' ').await;
    let paused = browser.js(DECK_STATE_JS).await;
    assert_eq!(paused["slide"], 1, "Space on the pool changed the slide");
    assert_eq!(paused["paused"], 1.0, "Space on the pool did not pause it");
    press(&browser, ' ').await;

    // Keys on focused controls: the control takes them, the deck does not.
    let keyed = [
        ("input[name=wave_speed]", ARROW_RIGHT, "waveSpeed"),
        ("input[name=absorbing_walls]", ' ', "walls"),
        ("select[name=ambient]", ARROW_DOWN, "ambient"),
    ];
    for (selector, key, field) in keyed {
        focus_in_pool(&browser, selector).await;
        let before = browser.js(DECK_STATE_JS).await;
        press(&browser, key).await;
        let after = browser.js(DECK_STATE_JS).await;
        println!("{selector}: {} -> {}, slide {}", before[field], after[field], after["slide"]);
        assert_eq!(after["slide"], 1, "a key in {selector} changed the slide");
        assert_ne!(after[field], before[field], "a key in {selector} left its value unchanged");
    }
    // The Preset select: arrowing through it applies nothing; Enter applies the one shown.
    focus_in_pool(&browser, ".preset select").await;
    let before = browser.js(DECK_STATE_JS).await;
    press(&browser, ARROW_DOWN).await;
    press(&browser, ARROW_DOWN).await;
    let browsed = browser.js(DECK_STATE_JS).await;
    println!("Preset select arrowed: {before} -> {browsed}");
    assert_eq!(browsed["slide"], 1, "arrows in the Preset select changed the slide");
    assert_ne!(browsed["preset"], before["preset"], "arrows did not move the Preset select");
    assert_eq!(browsed["waveSpeed"], before["waveSpeed"], "arrowing through the presets applied one");
    assert_eq!(browsed["ambient"], before["ambient"], "arrowing through the presets applied one");
    press(&browser, ENTER).await;
    let applied = browser
        .js_async(
            "const { presets } = await import('/embed.js');
             const p = document.getElementById('pool'); const name = p.shadowRoot.querySelector('.preset select').value;
             const preset = (await presets()).find((q) => q.name === name);
             const off = preset.values.filter(([n, v]) => Math.abs(p.demo.get(n) - v) > 1e-6).map(([n]) => n);
             return { name, off, matches: off.length === 0, slide: Reveal.getIndices().h };",
        )
        .await;
    println!("Enter in the Preset select: {applied}");
    assert_eq!(applied["slide"], 1, "Enter in the Preset select changed the slide");
    assert_eq!(applied["matches"], true, "Enter did not apply the preset shown");

    // Keys the pool does not use reach the deck: Esc opens the overview, N moves on.
    focus_in_pool(&browser, "canvas").await;
    press(&browser, ESCAPE).await;
    assert!(
        browser.wait_for("Reveal.isOverview()", Duration::from_secs(5)).await,
        "Esc on the pool did not reach the deck"
    );
    browser.js("Reveal.toggleOverview(false);").await;
    focus_in_pool(&browser, "canvas").await;
    press(&browser, 'n').await;
    assert!(
        browser.wait_for("Reveal.getIndices().h === 2", Duration::from_secs(5)).await,
        "N on the pool did not reach the deck"
    );

    // Off its slide it holds its simulated time; back on it, it runs with a picture.
    let t0 = sim_time(&browser).await;
    tokio::time::sleep(Duration::from_millis(700)).await; // a span in which a running pool would advance
    let t1 = sim_time(&browser).await;
    println!("off the slide: simulated time {t0:.3} -> {t1:.3} s");
    assert_eq!(t0, t1, "the pool kept simulating off its slide");
    browser.js("Reveal.prev();").await;
    let resumed = format!("document.getElementById('pool').demo._core.simTime > {t1} + 0.1");
    assert!(browser.wait_for(&resumed, READY).await, "the pool did not run again on its slide");
    let shot = browser.screenshot().await;
    keep_shot(&browser, "deck").await;
    let spread = shot.luma_spread(Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await));
    println!("back on its slide: luma spread of the pool {spread:.1}");
    assert!(spread > 15.0, "the pool shows no picture back on its slide (luma spread {spread:.1})");
    let live = browser.js("return window.__gpuLive();").await;
    println!("GPU contexts live: {live}");
    assert!(live.as_i64().unwrap() <= 1, "more than one GPU context for one pool: {live}");

    // The canvas follows the slide's scale: a larger window, a larger backing store.
    let small = assert_fits(&browser.js(FIT_JS).await, "before the window grew");
    browser.set_viewport(1600, 1200).await;
    let follows = "((c) => Math.abs(c.width - c.getBoundingClientRect().width * devicePixelRatio) <= 2)(
                   document.getElementById('pool').shadowRoot.querySelector('canvas:not(.still)'))";
    // The deck rescales its slides in its own resize handler, after the window has changed.
    let grown = format!(
        "{follows} && document.getElementById('pool').shadowRoot.querySelector('canvas:not(.still)').width > {}",
        small.0
    );
    let followed = browser.wait_for(&grown, Duration::from_secs(20)).await;
    let large = assert_fits(&browser.js(FIT_JS).await, "after the window grew");
    println!("canvas {small:?} -> {large:?} with the window 1100x1000 -> 1600x1200");
    assert!(followed, "the canvas did not grow with the slide's new scale: {small:?} -> {large:?}");
    // ... and the deck's overview, which scales the slides down without a resize.
    browser.js("Reveal.toggleOverview(true); return true;").await;
    let shrunk = format!(
        "{follows} && document.getElementById('pool').shadowRoot.querySelector('canvas:not(.still)').width < {}",
        large.0 / 2
    );
    let followed = browser.wait_for(&shrunk, Duration::from_secs(20)).await;
    let overview = browser.js(FIT_JS).await["backing"].clone();
    println!("canvas in the overview: {overview}");
    assert!(followed, "the canvas did not follow the overview's scale: {overview} (before {large:?})");
    browser.close().await;
}

/// Where each `<wave-pool>` of tests/pages/boxes.html and its box are, and its drawer's state.
const BOXES_JS: &str = "const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
    const parts = (id, holder) => { const p = document.getElementById(id); const r = p.shadowRoot;
      const d = r.querySelector('details.controls');
      return { box: box(holder), element: box(p), stage: box(r.querySelector('.stage')), summary: box(r.querySelector('summary')),
               drawer: d ? box(d) : null, open: d ? d.open : null, buttons: [...r.querySelectorAll('.overlay button')].map(box) }; };
    return { cell: parts('cell', document.getElementById('cell')), panel: parts('panel', document.getElementById('panel-box')) };";

/// A pool stretched to a grid cell of fixed height (it fills the cell) and one under text in a
/// fixed-height panel (it fits what the text leaves): each with its picture, buttons and drawer
/// inside its box, the drawer folded at the start (it would not fit) and, opened, scrolling
/// inside the box.
#[tokio::test]
async fn a_pool_in_a_grid_cell_or_a_fixed_panel_fits_it_with_its_drawer_folded_or_open() {
    let _g = serial();
    let server = StaticServer::start();
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/test/boxes.html")).await;
    browser.wait_ready("#cell", READY).await;
    browser.wait_ready("#panel", READY).await;
    for opened in [false, true] {
        if opened {
            browser
                .js("for (const id of ['cell', 'panel']) document.getElementById(id).shadowRoot.querySelector('details.controls').open = true;
                     return true;")
                .await;
            // Refitted once the drawers' toggle events have come (the assertions below say how, if not).
            let settled = "['cell', 'panel'].every((id) => { const p = document.getElementById(id);
                             const holder = id === 'cell' ? p : document.getElementById('panel-box');
                             return p.shadowRoot.querySelector('details.controls').getBoundingClientRect().bottom
                                    <= holder.getBoundingClientRect().bottom + 1; })";
            browser.wait_for(settled, Duration::from_secs(5)).await;
        }
        let boxes = browser.js(BOXES_JS).await;
        for name in ["cell", "panel"] {
            let b = &boxes[name];
            println!("{name}, drawer {}: {b}", if opened { "opened" } else { "as it starts" });
            assert_eq!(b["open"], opened, "{name}: the drawer should start folded in a box it does not fit");
            let outer = rect(&b["box"]);
            for part in ["element", "stage", "summary", "drawer"] {
                assert!(inside(rect(&b[part]), outer), "{name}: its {part} {} leaves its box {outer:?}", b[part]);
            }
            for button in b["buttons"].as_array().unwrap() {
                assert!(inside(rect(button), outer), "{name}: a button {button} leaves its box {outer:?}");
            }
            // It takes its room: its bottom at the box's (less the panel's 8 px padding and border).
            let unused = outer[3] - rect(&b["element"])[3] - if name == "panel" { 9.0 } else { 0.0 };
            println!("{name}: {unused:.1} px of its box unused");
            assert!((0.0..=6.0).contains(&unused), "{name}: {unused:.1} px of its box unused");
        }
    }
    // ... and keeps it: the same boxes a second later (a fit that crept would show here).
    let before = browser.js(BOXES_JS).await;
    tokio::time::sleep(Duration::from_secs(1)).await; // a span in which a creeping fit would move
    let after = browser.js(BOXES_JS).await;
    assert_eq!(before, after, "the pools' boxes moved with nothing changed");
    browser.close().await;
}

/// Collects, from before the page's own scripts: the layout shifts not caused by input (their
/// sum, at least the page's cumulative layout shift), and the longest main-thread task and the
/// total blocking time (the part of each task over 50 ms).
const LOAD_WATCH_JS: &str = "window.__load = { shift: 0, longest: 0, blocking: 0 };
    new PerformanceObserver((list) => { for (const e of list.getEntries()) if (!e.hadRecentInput) { window.__load.shift += e.value;
        (window.__load.shifts = window.__load.shifts || []).push([Math.round(e.startTime), e.value.toFixed(3), e.sources.map((s) => (s.node ? s.node.nodeName + '.' + (s.node.className || s.node.id || '') : '?') + ' ' + s.previousRect.y + '+' + s.previousRect.height + '->' + s.currentRect.y + '+' + s.currentRect.height).join('; ')]); } })
      .observe({ type: 'layout-shift', buffered: true });
    new PerformanceObserver((list) => { for (const e of list.getEntries()) {
        window.__load.longest = Math.max(window.__load.longest, e.duration); window.__load.blocking += Math.max(0, e.duration - 50); } })
      .observe({ type: 'longtask', buffered: true });";

/// WCAG contrast ratio of two sRGB colours.
fn contrast(a: [u8; 3], b: [u8; 3]) -> f64 {
    let luminance = |c: [u8; 3]| {
        let lin = |v: u8| {
            let v = v as f64 / 255.0;
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
    };
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// The share of points along the middle of the canvas's four edges where the focus ring (its
/// light band 1 px in, its dark band 4 px in, in `focused`) stands out at 3:1 or more from the
/// picture next to it (9 px in, in `plain`, the same frame unfocused).
fn ring_contrast_share(focused: &support::Image, plain: &support::Image, r: &Rect) -> f64 {
    let (x0, y0, x1, y1) = (r.x, r.y, r.x + r.w - 1, r.y + r.h - 1);
    let mut points = Vec::new();
    for i in 1..20 {
        let x = x0 + r.w * i / 20;
        let y = y0 + r.h * i / 20;
        points.push(((x, y0 + 1), (x, y0 + 4), (x, y0 + 9)));
        points.push(((x, y1 - 1), (x, y1 - 4), (x, y1 - 9)));
        points.push(((x0 + 1, y), (x0 + 4, y), (x0 + 9, y)));
        points.push(((x1 - 1, y), (x1 - 4, y), (x1 - 9, y)));
    }
    let good = points
        .iter()
        .filter(|(light, dark, inner)| {
            let picture = plain.pixel(inner.0, inner.1);
            contrast(focused.pixel(light.0, light.1), picture).max(contrast(focused.pixel(dark.0, dark.1), picture))
                >= 3.0
        })
        .count();
    good as f64 / points.len() as f64
}

/// axe-core finds no violation on the page (index.html, its controls open), the iframe page
/// (embed.html) and the iframe page with controls; the focused pool shows a ring standing out
/// at 3:1 from the picture around it; the page does not shift while the pool starts (layout
/// shift ≤ 0.05), and its longest task and total blocking time on start-up are printed.
#[tokio::test]
async fn the_pages_have_no_accessibility_violation_a_visible_focus_ring_and_no_layout_shift() {
    let _g = serial();
    let server = StaticServer::start_with_mounts(vec![("/hosts/", host_packages())]);
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.add_init_script(LOAD_WATCH_JS).await;
    let mut found = Vec::new();
    for page in ["/?quality=0.5", "/embed.html?quality=0.5", "/embed.html?controls=1&quality=0.5"] {
        browser.goto(&server.url(page)).await;
        browser.wait_ready("#pool", READY).await;
        let load = browser.js("return window.__load;").await;
        println!("{page}: shifts {}", load["shifts"]);
        println!(
            "{page}: layout shift {:.3}, longest task {:.0} ms, total blocking time {:.0} ms",
            load["shift"].as_f64().unwrap(),
            load["longest"].as_f64().unwrap(),
            load["blocking"].as_f64().unwrap()
        );
        assert!(
            load["shift"].as_f64().unwrap() <= 0.05,
            "{page}: the page shifted by {} while the pool started",
            load["shift"]
        );
        keep_shot(&browser, &format!("page-{}", page.len())).await;
        if page.starts_with("/?") {
            let open = browser
                .js("return document.querySelector('#pool').shadowRoot.querySelector('details.controls').open;")
                .await;
            assert_eq!(open, true, "the page's controls should be open at 1100 px for the audit to see them");
        }
        let violations = axe_violations(&browser).await;
        println!("{page}: {} axe-core violations", violations.len());
        found.extend(violations.into_iter().map(|(id, n)| format!("{page}: {id} ({n} nodes)")));
    }
    assert!(found.is_empty(), "accessibility violations: {found:?}");

    // The focus ring, on the paused pool (the same frame focused and not).
    browser.goto(&server.url("/embed.html?quality=0.5&paused=1")).await;
    browser.wait_ready("#pool", READY).await;
    let canvas = Rect::from_js(&browser.js(&canvas_rect_js("#pool")).await);
    let plain = browser.screenshot().await;
    browser.js("document.querySelector('#pool').shadowRoot.querySelector('canvas').focus(); return true;").await;
    let focused = browser.screenshot().await;
    keep_shot(&browser, "focus").await;
    let share = ring_contrast_share(&focused, &plain, &canvas);
    println!("focus ring: {:.0} % of the edge points stand out at 3:1 or more", share * 100.0);
    assert!(share >= 0.99, "the focus ring does not stand out from the picture: {:.0} % of points", share * 100.0);
    browser.close().await;

    // On WebGL2 (no WebGPU in the browser): the start-up's shift and tasks.
    let browser = Browser::open(Graphics::WebGl2Only).await;
    browser.add_init_script(LOAD_WATCH_JS).await;
    browser.goto(&server.url("/?quality=0.5")).await;
    browser.wait_ready("#pool", READY).await;
    let load = browser.js("return window.__load;").await;
    println!(
        "/?quality=0.5 on WebGL2: layout shift {:.3}, longest task {:.0} ms, total blocking time {:.0} ms",
        load["shift"].as_f64().unwrap(),
        load["longest"].as_f64().unwrap(),
        load["blocking"].as_f64().unwrap()
    );
    assert!(
        load["shift"].as_f64().unwrap() <= 0.05,
        "WebGL2: the page shifted by {} while the pool started",
        load["shift"]
    );
    browser.close().await;
}

/// Writes a MkDocs Material course site (instant navigation on: `site_url` set to where the
/// test serves it) with the pool on two of its four pages and the built demo in its files, and
/// builds it into `site`.
fn build_course_site(root: &std::path::Path, site_url: &str) -> std::path::PathBuf {
    let docs = root.join("docs");
    let files = docs.join("wavepool");
    std::fs::create_dir_all(&files).unwrap();
    for entry in std::fs::read_dir(support::dist_dir()).unwrap().flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let kept = [".js", ".wasm", ".css", ".webp", ".svg"].iter().any(|e| name.ends_with(e));
        if kept && !name.ends_with(".html") {
            std::fs::copy(entry.path(), files.join(&name)).unwrap();
        }
    }
    let pages = [
        ("index.md", "# Water\n\nA course about water. Next: [the pool](pool.md).\n"),
        ("pool.md", "# The pool\n\nClick the water.\n\n<wave-pool quality=\"0.5\"></wave-pool>\n\nNext: [waves](waves.md).\n"),
        ("waves.md", "# Waves\n\nNo pool on this page. Back to [the pool](pool.md), on to [more](more.md).\n"),
        ("more.md", "# More\n\nAnother pool.\n\n<wave-pool quality=\"0.5\" objects=\"duck\"></wave-pool>\n\nBack to [waves](waves.md).\n"),
    ];
    for (name, text) in pages {
        std::fs::write(docs.join(name), text).unwrap();
    }
    let config = format!(
        "site_name: Water course\nsite_url: {site_url}\ntheme:\n  name: material\n  features:\n    - navigation.instant\n\
         extra_javascript:\n  - path: wavepool/embed.js\n    type: module\n\
         nav:\n  - index.md\n  - pool.md\n  - waves.md\n  - more.md\n"
    );
    std::fs::write(root.join("mkdocs.yml"), config).unwrap();
    let site = root.join("site");
    let out = std::process::Command::new(support::mkdocs())
        .args(["build", "--quiet", "--site-dir"])
        .arg(&site)
        .current_dir(root)
        .output()
        .expect("run mkdocs");
    assert!(out.status.success(), "mkdocs build failed: {}", String::from_utf8_lossy(&out.stderr));
    site
}

/// A MkDocs Material site with instant navigation: four visits to its two pool pages by
/// clicking its links (the page is never reloaded), each pool ready every time, and the GPU
/// contexts back to 0 each time a page with a pool is left.
#[tokio::test]
async fn a_docs_site_with_instant_navigation_starts_the_pool_on_every_visit_and_frees_it_on_leaving() {
    let _g = serial();
    let root = std::env::temp_dir().join(format!("wavepool-mkdocs-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let site_dir = root.join("site");
    let server = StaticServer::start_with_mounts(vec![("/site/", site_dir.clone())]);
    let built = build_course_site(&root, &server.url("/site/"));
    assert_eq!(built, site_dir);
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.add_init_script(include_str!("pages/gpu_contexts.js")).await;
    browser.goto(&server.url("/site/")).await;
    browser.js("window.__sameDocument = true; return true;").await;
    let click = |href: &str| format!("document.querySelector('article a[href$=\"{href}\"]').click(); return true;");
    let route = [("pool/", "waves/"), ("more/", "waves/"), ("pool/", "waves/"), ("more/", "waves/")];
    let mut ready = Vec::new();
    browser.js(&click("pool/")).await;
    for (visit, (page, away)) in route.iter().enumerate() {
        if visit > 0 {
            browser.js(&click(page)).await;
        }
        let path = format!("location.pathname.endsWith('/{page}')");
        assert!(browser.wait_for(&path, Duration::from_secs(20)).await, "visit {}: {page} did not open", visit + 1);
        let took = browser.wait_ready("article wave-pool", READY).await;
        let live = browser.js("return window.__gpuLive();").await;
        println!("visit {} to {page}: ready in {:.1} s, contexts {live}", visit + 1, took.as_secs_f64());
        assert_eq!(live, 1, "visit {}: one pool, {live} contexts", visit + 1);
        ready.push(took);
        keep_shot(&browser, &format!("docs-{}", visit + 1)).await;
        browser.js(&click(away)).await;
        let freed = "window.__gpuLive() === 0 && !document.querySelector('article wave-pool')";
        assert!(
            browser.wait_for(freed, Duration::from_secs(20)).await,
            "leaving {page}: its context was not given back"
        );
    }
    let same = browser.js("return window.__sameDocument === true;").await;
    assert_eq!(same, true, "the site reloaded the page: instant navigation was not used");
    let made = browser.js("return window.__gpu;").await;
    println!("contexts made and given back over the visits: {made}");
    browser.close().await;
    let _ = std::fs::remove_dir_all(&root);
}
