//! Drawn frames in the page: their pacing (counted by the page's own counter) and the frame
//! budget's resolution.

use super::*;

/// The counter of drawn frames (tests/pages/frame_counter.js), injected before the page loads.
const FRAME_COUNTER_JS: &str = include_str!("../pages/frame_counter.js");

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
    // Past the start-up (its shaders built, the resolution settled).
    assert!(browser.wait_for("window.demo.stats().framesDrawn >= 40", Duration::from_secs(30)).await);
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
