//! The optics, ambient-wave and flat-water models switched in the page on both backends.

use super::*;

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
    let foam_from = browser
        .js("const d = window.demo; d.reset(); d.set('foam', 1); d.set('foam_decay', 5); d.set('paused', 0);
             for (const [x, z] of [[0, 0], [0.4, 0.3], [-0.4, -0.3]]) d.addDrop(x, z, 0.1, 0.045);
             return d.stats().simTime;")
        .await;
    // The foam of 0.6 s of simulated time.
    let grown = format!("window.demo.stats().simTime >= {}", foam_from.as_f64().unwrap_or(0.0) + 0.6);
    assert!(browser.wait_for(&grown, Duration::from_secs(20)).await, "{backend}: the water stopped");
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
    // Every parameter of this lessons from its own control: sliders to their maximum,
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
    assert!(text.contains("Between frames: raytraced") && !text.contains("flat –"), "{backend}: {text}");
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
