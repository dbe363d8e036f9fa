//! The open sea and the ripple tank in the page on both backends.

use super::*;

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
