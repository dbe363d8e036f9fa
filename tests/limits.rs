//! The largest options the page allows never crash it, in headless Chromium on both backends
//! with a second browser busy beside it: the sizes a software rasteriser cannot afford are held
//! to what it can (the page says which), frames keep coming and the water keeps running. Needs
//! `dist/`.

// One browser at a time, held across awaits: each test runs on its own thread and runtime.
#![allow(clippy::await_holding_lock)]

#[path = "support/browser.rs"]
mod support;

use std::time::{Duration, Instant};

use support::{serial, Browser, Graphics, StaticServer, READY};

/// The largest values the page's options and controls accept.
const LARGEST: &str = "/?sim_size=1024&causticsSize=2048&meshSize=512&quality=1";
/// How long each load runs.
const RUN: Duration = Duration::from_secs(20);

/// State of the page's demo: simulated time, frames a second, its notice, what was reduced,
/// and whether it shows an error.
const STATE_JS: &str = "const p = document.querySelector('#pool'); const s = window.demo.stats();
    const n = p.shadowRoot.querySelector('.notice');
    return { simTime: s.simTime, fps: s.fps, reduced: s.reduced.map((r) => r.name + ' ' + r.asked + '->' + r.given),
             notice: n && !n.hidden ? n.textContent : null, error: p.dataset.error === 'true', simSize: s.simSize,
             quality: window.demo.get('quality') };";

/// Three loads of the largest options on each backend, each running 20 s beside a browser
/// drawing the default page: no crash (the page answers throughout), no error, the sizes over
/// a software rasteriser's caps reduced with a notice naming them, the water running (simulated
/// time advancing in every 5 s), and where frames still come over a second apart, the page's
/// rescue (automatic resolution, then a smaller grid) under way.
#[tokio::test]
async fn the_largest_options_run_beside_a_busy_browser_without_a_crash() {
    let _g = serial();
    let server = StaticServer::start();
    let busy = Browser::open(Graphics::WebGpu).await;
    busy.goto(&server.url("/?quality=1")).await;
    busy.wait_ready("#pool", READY).await;
    for graphics in [Graphics::WebGpu, Graphics::WebGl2Only] {
        for load in 1..=3 {
            let browser = Browser::open(graphics).await;
            browser.goto(&server.url(LARGEST)).await;
            let took = browser.wait_ready("#pool", READY).await;
            let start = browser.js(STATE_JS).await;
            println!("{graphics:?} load {load}: ready in {:.1} s: {start}", took.as_secs_f64());
            assert_eq!(start["error"], false, "{graphics:?}: the demo failed: {start}");
            let reduced = start["reduced"].as_array().unwrap();
            assert!(!reduced.is_empty(), "{graphics:?}: nothing reduced on a software rasteriser: {start}");
            assert!(
                reduced.iter().any(|r| r == "causticsSize 2048->1024"),
                "{graphics:?}: the caustics map is not held to the caps: {start}"
            );
            // The notice names what was reduced, unless a slow start has already put the
            // rescue's notices in its place (a slow machine, before the page was ready).
            let notice = start["notice"].as_str().unwrap_or_default();
            assert!(
                notice.contains("causticsSize 2048 → 1024") || notice.contains("Frames took over a second"),
                "{graphics:?}: the notice does not say what was reduced: {start}"
            );
            let begun = Instant::now();
            let mut last = start.clone();
            while begun.elapsed() < RUN {
                tokio::time::sleep(Duration::from_secs(5)).await; // the page is watched as it runs
                let now = browser.js(STATE_JS).await; // a crashed page fails here
                assert_eq!(now["error"], false, "{graphics:?}: the demo failed while running: {now}");
                let ran = now["simTime"].as_f64().unwrap() > last["simTime"].as_f64().unwrap();
                assert!(ran, "{graphics:?}: no frame in 5 s: {last} -> {now}");
                last = now;
            }
            let advanced = last["simTime"].as_f64().unwrap() - start["simTime"].as_f64().unwrap();
            println!("{graphics:?} load {load}: after {} s: {last}; simulated {advanced:.1} s", RUN.as_secs());
            // How much water a slow machine simulates depends on its speed (frames two seconds
            // apart simulate 0.1 s each); what the page must do there is rescue itself: its
            // first step makes the resolution automatic (quality 0; the page asked for 1), and
            // it stays so (the notice saying it hides after a while).
            let fps = last["fps"].as_f64().unwrap();
            let rescued = last["quality"].as_f64() == Some(0.0);
            assert!(fps > 1.0 || rescued, "{graphics:?}: frames over a second apart and no rescue: {last}");
            browser.close().await;
        }
    }
    assert_eq!(busy.js("return document.querySelector('#pool').dataset.error || 'none';").await, "none");
    busy.close().await;
}
