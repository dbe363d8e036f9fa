//! Browser benchmark: frames per second of the demo at 800x600 (default quality) in headless
//! Chromium on this machine, on WebGPU and on WebGL2, plus the time to the first frame.
//! Run with `cargo bench --bench browser` after building dist/ (`./scripts/serve`, or `trunk build
//! --release`). Prints one JSON object per backend. WAVEPOOL_BENCH_QUERY adds page options
//! (`&float=none`), WAVEPOOL_BENCH_SECONDS and WAVEPOOL_BENCH_WARMUP set the timing.

#[path = "../tests/support/browser.rs"]
mod support;

use std::time::{Duration, Instant};

use support::{Browser, Graphics, StaticServer};

#[tokio::main(flavor = "current_thread")]
async fn main() {
    let warm_up = Duration::from_secs(env_secs("WAVEPOOL_BENCH_WARMUP", 5));
    let measure = Duration::from_secs(env_secs("WAVEPOOL_BENCH_SECONDS", 20));
    // Extra page options, e.g. WAVEPOOL_BENCH_QUERY='&float=none'.
    let extra = std::env::var("WAVEPOOL_BENCH_QUERY").unwrap_or_default();
    let server = StaticServer::start();
    for backend in ["webgpu", "webgl2"] {
        let browser = Browser::open(Graphics::WebGpu).await;
        let opened = Instant::now();
        browser.goto(&server.url(&format!("/test/sized.html?width=800&height=600&backend={backend}{extra}"))).await;
        let ready = browser.wait_ready("#pool", Duration::from_secs(180)).await;
        let load_to_ready = opened.elapsed();
        tokio::time::sleep(warm_up).await;
        // Frames presented over the measuring window, counted in the page.
        let start = browser.js("return { t: performance.now(), s: window.demo.stats() };").await;
        let count_script = "window.__count = 0; const tick = () => { window.__count++; if (!window.__stop) requestAnimationFrame(tick); }; requestAnimationFrame(tick);";
        browser.js(count_script).await;
        tokio::time::sleep(measure).await;
        let end = browser
            .js("window.__stop = true; return { t: performance.now(), n: window.__count, s: window.demo.stats() };")
            .await;
        let seconds = (end["t"].as_f64().unwrap() - start["t"].as_f64().unwrap()) / 1000.0;
        let fps = end["n"].as_f64().unwrap() / seconds;
        let stats = &end["s"];
        println!(
            "{}",
            serde_json::json!({
                "backend": stats["backend"],
                "sim_engine": stats["simEngine"],
                "adapter": stats["adapter"],
                "canvas": [stats["width"], stats["height"]],
                "fps": (fps * 100.0).round() / 100.0,
                "fps_demo_window": stats["fps"],
                "first_frame_ms_since_mount": stats["firstFrameMs"],
                "page_load_to_ready_ms": load_to_ready.as_millis() as u64,
                "ready_wait_ms": ready.as_millis() as u64,
                "measured_s": seconds,
            })
        );
        browser.close().await;
    }
}

fn env_secs(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}
