//! Browser benchmark: the frames per second our page DRAWS against Evan Wallace's classic WebGL
//! Water, in the same browser run, counted the same way for both (tests/pages/frame_counter.js,
//! put first in every page served, as /work/shared/notes/measuring.md describes:
//! default-framebuffer draws per animation frame on WebGL, finished frames by
//! `onSubmittedWorkDone` on WebGPU), not `requestAnimationFrame` callbacks, which overstate the
//! rate of a page that queues work.
//!
//! For each engine and backend (Chromium headless with the WebGPU flags on WebGPU and on WebGL2;
//! Firefox ESR under a virtual display on WebGL2 and with WebGPU turned on; WebKitGTK under a
//! virtual display on WebGL2) one browser with an 800x600 viewport loads, alternately
//! (A B A B), our `/index.html?backend=...` and the classic `/classic/index.html` (WebGL1
//! whatever the backend; served read-only from ../shared/anchors/webgl-water). Each page: load,
//! wait until ready, warm up, reset the counter, measure, read it. Before each page the machine
//! is left to settle (CPU mostly idle), so work a previous page queued does not land in the
//! next one's window. Ratios are only between figures of the same browser run.
//!
//! Run: `cargo bench --bench browser` after building dist/ (`./scripts/serve` or
//! `trunk build --release`; `WAVEPOOL_DIST` points elsewhere). Nothing else should run meanwhile:
//! the benchmark ends leftover Chromium processes of earlier tests first and warns about any other.
//! Settings (environment):
//! - `WAVEPOOL_BENCH_ROUNDS` (2): how many A B pairs per backend;
//! - `WAVEPOOL_BENCH_WARMUP` (5) and `WAVEPOOL_BENCH_SECONDS` (20): warm-up and window, s;
//! - `WAVEPOOL_BENCH_QUERY`: extra options for our page, e.g. `&objects=none&quality=1`;
//! - `WAVEPOOL_BENCH_RUNS` (all): which runs, space-separated, of `chromium-webgpu`,
//!   `chromium-webgl2`, `firefox-webgl2`, `firefox-webgpu`, `webkit-webgl2`;
//! - `WAVEPOOL_BENCH_BASELINE`: another build's `dist/` (e.g. an older commit's), served at
//!   `/baseline/` and measured in place of the classic, with the same query as ours: our cost
//!   against an earlier build's in one run;
//! - `WAVEPOOL_BENCH_BASELINE_QUERY`: the baseline's options in place of ours, e.g. one scene of
//!   this build against another (`WAVEPOOL_BENCH_BASELINE=dist WAVEPOOL_BENCH_QUERY=&scene=tank
//!   WAVEPOOL_BENCH_BASELINE_QUERY=`: the tank against the pool);
//! - `WAVEPOOL_BENCH_PAGE` (`index.html`): which of our pages to load (and of the baseline's);
//!   `embed.html` fills the viewport, so two builds whose `index.html` lay out differently
//!   draw canvases of the same size.
//!
//! Prints one JSON line per measurement, then one summary line per run: mean drawn fps of
//! ours and of the classic, their ratio, and the ratio per canvas pixel (fps x backing pixels;
//! and per pixel actually drawn when our page reports its automatic render scale: use
//! `WAVEPOOL_BENCH_QUERY='&quality=1'` to compare at full resolution).

#[path = "../tests/support/browser.rs"]
mod support;

use std::time::{Duration, Instant};

use serde_json::{json, Value};
use support::{end_stray_browsers, process_tree, processes, Browser, Engine, Graphics, StaticServer};

/// The viewport both pages are measured in (CSS px), as in measuring.md.
const VIEWPORT: (u32, u32) = (800, 600);
/// The runs: an engine and the backend our page is told to use there; the classic is measured
/// in each run too (it is WebGL1 in every one).
const RUNS: [(&str, Engine, &str); 5] = [
    ("chromium-webgpu", Engine::Chromium(Graphics::WebGpu), "webgpu"),
    ("chromium-webgl2", Engine::Chromium(Graphics::WebGpu), "webgl2"),
    ("firefox-webgl2", Engine::Firefox, "webgl2"),
    ("firefox-webgpu", Engine::FirefoxWebGpu, "webgpu"),
    ("webkit-webgl2", Engine::WebKit, "webgl2"),
];
/// Longest wait for our page to show its first frame (SwiftShader compiles slowly).
const READY_TIMEOUT: Duration = Duration::from_secs(180);
/// The classic has no ready signal: it is running once its "Loading..." text is gone; it then
/// gets this long before the warm-up starts.
const CLASSIC_SETTLE: Duration = Duration::from_secs(3);
/// Before loading a page, wait (at most `SETTLE_MAX`) until the machine's CPUs are busy less
/// than this fraction of a second: a previous page's queued GPU work must not be measured.
const SETTLE_BUSY: f64 = 0.3;
const SETTLE_MAX: Duration = Duration::from_secs(30);

struct Settings {
    warm_up: Duration,
    window: Duration,
    rounds: u32,
    /// Appended to our page's query string.
    extra_query: String,
    /// The baseline's own options, if not the same as ours.
    baseline_query: Option<String>,
    /// Names of the runs to make (of [`RUNS`]).
    runs: Vec<String>,
    /// Another build of our page to measure in place of the classic.
    baseline: Option<std::path::PathBuf>,
    /// Our page's file name.
    page: String,
}

impl Settings {
    fn from_env() -> Self {
        let number = |name: &str, default: u64| -> u64 {
            std::env::var(name)
                .ok()
                .map_or(default, |v| v.parse().unwrap_or_else(|_| panic!("{name}={v}: not a number")))
        };
        Self {
            warm_up: Duration::from_secs(number("WAVEPOOL_BENCH_WARMUP", 5)),
            window: Duration::from_secs(number("WAVEPOOL_BENCH_SECONDS", 20)),
            rounds: number("WAVEPOOL_BENCH_ROUNDS", 2) as u32,
            extra_query: std::env::var("WAVEPOOL_BENCH_QUERY").unwrap_or_default(),
            baseline_query: std::env::var("WAVEPOOL_BENCH_BASELINE_QUERY").ok(),
            runs: std::env::var("WAVEPOOL_BENCH_RUNS")
                .map(|v| v.split_whitespace().map(str::to_owned).collect())
                .unwrap_or_else(|_| RUNS.iter().map(|r| r.0.to_owned()).collect()),
            baseline: std::env::var_os("WAVEPOOL_BENCH_BASELINE").map(Into::into),
            page: std::env::var("WAVEPOOL_BENCH_PAGE").unwrap_or_else(|_| "index.html".to_owned()),
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Page {
    Ours,
    Classic,
    /// Another build of ours (`WAVEPOOL_BENCH_BASELINE`) at `/baseline/`.
    Baseline,
}

impl Page {
    fn name(self) -> &'static str {
        match self {
            Page::Ours => "wavepool",
            Page::Classic => "classic",
            Page::Baseline => "baseline",
        }
    }

    fn path(self, backend: &str, settings: &Settings) -> String {
        let (page, extra_query) = (&settings.page, &settings.extra_query);
        match self {
            Page::Ours => format!("/{page}?backend={backend}{extra_query}"),
            Page::Classic => "/classic/index.html".to_string(),
            Page::Baseline => {
                let query = settings.baseline_query.as_ref().unwrap_or(extra_query);
                format!("/baseline/{page}?backend={backend}{query}")
            }
        }
    }

    /// JS expression: the page's canvas.
    fn canvas_js(self) -> &'static str {
        match self {
            Page::Ours | Page::Baseline => "document.querySelector('#pool').shadowRoot.querySelector('canvas')",
            Page::Classic => "document.querySelector('canvas')",
        }
    }
}

/// One page measured once: what the summary needs.
struct Measurement {
    page: Page,
    /// The run's name (engine and backend).
    run: &'static str,
    /// Frames drawn per second (the counter's figure).
    fps: f64,
    /// Animation frames per second in which the page's callbacks ran.
    callbacks_fps: f64,
    /// Backing pixels of the canvas.
    pixels: f64,
    /// Our page: the scale its scene is drawn at (`stats().renderScale`, automatic resolution
    /// draws at a fraction of the canvas and scales up); `None` when the build does not say.
    render_scale: Option<f64>,
}

#[tokio::main(flavor = "current_thread")]
async fn main() {
    let settings = Settings::from_env();
    // A leftover Chromium makes every figure several times worse.
    let strays = end_stray_browsers();
    println!("{}", json!({ "strays_ended": strays.ended, "other_browsers": strays.others }));
    if !strays.others.is_empty() {
        eprintln!(
            "warning: other Chromium/chromedriver processes are running (left alone, they belong to \
             something still running); the figures will be lower than they should be:\n  {}",
            strays.others.join("\n  ")
        );
    }
    let server = StaticServer::start_with_classic_and_mounts(
        true,
        settings.baseline.iter().map(|dir| ("/baseline/", dir.clone())).collect(),
    );
    let other = if settings.baseline.is_some() { Page::Baseline } else { Page::Classic };
    let mut results = Vec::new();
    let runs: Vec<_> = RUNS.iter().filter(|r| settings.runs.iter().any(|name| name == r.0)).collect();
    assert!(!runs.is_empty(), "WAVEPOOL_BENCH_RUNS names none of {:?}", RUNS.map(|r| r.0));
    for &&(run, engine, backend) in &runs {
        // Chromium gets the WebGPU flags in both runs: our page is told its backend in the URL.
        let browser = Browser::open_engine(engine).await;
        let (width, height) = browser.set_viewport(VIEWPORT.0, VIEWPORT.1).await;
        let agent = browser.js("return navigator.userAgent;").await;
        println!(
            "{}",
            json!({ "run": run, "backend": backend, "viewport": [width, height], "browser": agent,
                    "warm_up_s": settings.warm_up.as_secs(), "window_s": settings.window.as_secs() })
        );
        for round in 1..=settings.rounds {
            for page in [Page::Ours, other] {
                results.push(measure(&browser, &server, page, run, backend, round, &settings).await);
            }
        }
        browser.close().await;
    }
    for &&(run, _, _) in &runs {
        println!("{}", summary(&results, run, other));
    }
}

/// Loads `page`, waits until it runs, warms up, counts its drawn frames over the window and
/// prints one JSON line.
async fn measure(
    browser: &Browser,
    server: &StaticServer,
    page: Page,
    run: &'static str,
    backend: &'static str,
    round: u32,
    settings: &Settings,
) -> Measurement {
    browser.goto("about:blank").await;
    let settle = settle().await;
    // Other browsers running now (someone's tests): their work lands in our window.
    let list = processes();
    let ours = process_tree(&list, browser.driver_pid());
    let other_browsers = list.iter().filter(|p| p.is_chromium_browser() && !ours.contains(&p.pid)).count();
    if other_browsers > 0 {
        eprintln!("warning: {other_browsers} other Chromium running while measuring {}", page.name());
    }
    let path = page.path(backend, settings);
    let loaded = Instant::now();
    browser.goto(&server.url(&path)).await;
    match page {
        Page::Ours | Page::Baseline => {
            browser.wait_ready("#pool", READY_TIMEOUT).await;
        }
        Page::Classic => {
            let running = "document.querySelector('canvas') && document.getElementById('loading').innerHTML === ''";
            assert!(
                browser.wait_for(running, READY_TIMEOUT).await,
                "the classic did not start (is WebGL with float textures there?)"
            );
            tokio::time::sleep(CLASSIC_SETTLE).await;
        }
    }
    let ready_s = loaded.elapsed().as_secs_f64();
    let viewport = browser.viewport().await;
    tokio::time::sleep(settings.warm_up).await;

    browser.js("window.__frameCounter.reset();").await;
    let cpu_start = CpuSample::take(browser.driver_pid());
    tokio::time::sleep(settings.window).await;
    let counter = browser.js("return window.__frameCounter.read();").await;
    let cpu = CpuSample::take(browser.driver_pid()).since(&cpu_start);

    let canvas = browser
        .js(&format!(
            "const c = {}; const r = c.getBoundingClientRect();
             return {{ size: [c.width, c.height], css: [r.width, r.height] }};",
            page.canvas_js()
        ))
        .await;
    // Our page's own figures, when its handle is on `window` (index.html puts it there).
    let stats = match page {
        Page::Ours | Page::Baseline => {
            browser
                .js("const d = window.demo; if (!d || typeof d.stats !== 'function') return null;
                     const s = d.stats();
                     return { fps: s.fps, backend: s.backend, adapter: s.adapter, simEngine: s.simEngine,
                              renderScale: s.renderScale === undefined ? null : s.renderScale,
                              gpuMs: s.gpuMs === undefined ? null : s.gpuMs,
                              stageMs: s.stageMs === undefined ? null : s.stageMs };")
                .await
        }
        Page::Classic => Value::Null,
    };
    let main = counter["canvases"].get(0).cloned().unwrap_or(Value::Null);
    let pixels = canvas["size"][0].as_f64().unwrap_or(0.0) * canvas["size"][1].as_f64().unwrap_or(0.0);
    let seconds = counter["seconds"].as_f64().unwrap_or(f64::NAN);
    // WebGPU: frames the page began per second (getCurrentTexture), finished or not.
    let started_fps =
        (main["api"] == "webgpu").then(|| main["started"].as_f64().map(|n| round2(n / seconds))).flatten();
    let line = json!({
        "page": page.name(),
        "run": run,
        "backend": backend,
        "round": round,
        "url": path,
        "viewport": [viewport.0, viewport.1],
        "canvas": canvas["size"],
        "canvas_css": canvas["css"],
        "api": counter["api"],
        "drawn_fps": counter["fps"],
        "frames": counter["frames"],
        "seconds": counter["seconds"],
        "median_ms": counter["medianMs"],
        "p95_ms": counter["p95Ms"],
        "longest_ms": counter["longestMs"],
        "pending": counter["pending"],
        "started_fps": started_fps,
        "callbacks_fps": counter["callbacksFps"],
        "canvases_drawing": counter["canvases"].as_array().map_or(0, |c| c.len()),
        "page_stats": stats,
        "ready_s": round2(ready_s),
        "settle": settle,
        "other_browsers": other_browsers,
        "cpu": cpu,
    });
    println!("{line}");
    if counter["frames"] == 0 {
        eprintln!("warning: {} ({backend}) drew no frame in the window", page.name());
    }
    Measurement {
        page,
        run,
        fps: counter["fps"].as_f64().unwrap_or(0.0),
        callbacks_fps: counter["callbacksFps"].as_f64().unwrap_or(0.0),
        pixels,
        render_scale: stats["renderScale"].as_f64(),
    }
}

/// The summary of one run: mean drawn fps of each page, ours / the other (the classic or the
/// baseline build; the figures named after it), and the same per canvas pixel (fps x backing
/// pixels, so a bigger canvas is not a handicap).
fn summary(results: &[Measurement], run: &str, other: Page) -> Value {
    let mean = |page: Page, f: &dyn Fn(&Measurement) -> f64| -> f64 {
        let values: Vec<f64> = results.iter().filter(|m| m.page == page && m.run == run).map(f).collect();
        values.iter().sum::<f64>() / values.len().max(1) as f64
    };
    let (ours, classic) = (mean(Page::Ours, &|m| m.fps), mean(other, &|m| m.fps));
    let ours_pixel_rate = mean(Page::Ours, &|m| m.fps * m.pixels);
    let classic_pixel_rate = mean(other, &|m| m.fps * m.pixels);
    let ratio = |a: f64, b: f64| if b > 0.0 { round3(a / b) } else { f64::NAN };
    // Pixels our scene is actually drawn at (canvas x render scale squared), when every
    // measurement of ours reported its scale.
    let ours_scales: Vec<f64> =
        results.iter().filter(|m| m.page == Page::Ours && m.run == run).filter_map(|m| m.render_scale).collect();
    let scale_known = ours_scales.len() == results.iter().filter(|m| m.page == Page::Ours && m.run == run).count();
    let (ours_scale, ratio_per_rendered_pixel) = if scale_known && !ours_scales.is_empty() {
        let rendered_rate = mean(Page::Ours, &|m| m.fps * m.pixels * m.render_scale.unwrap_or(1.0).powi(2));
        let scale = ours_scales.iter().sum::<f64>() / ours_scales.len() as f64;
        (Some(round3(scale)), Some(ratio(rendered_rate, classic_pixel_rate)))
    } else {
        (None, None)
    };
    let name = |figure: &str| format!("{}_{figure}", other.name());
    json!({
        "summary": run,
        "against": other.name(),
        "rounds": results.iter().filter(|m| m.page == Page::Ours && m.run == run).count(),
        "ours_drawn_fps": round3(ours),
        name("drawn_fps"): round3(classic),
        "ratio": ratio(ours, classic),
        "ours_megapixels_per_s": round3(ours_pixel_rate / 1e6),
        name("megapixels_per_s"): round3(classic_pixel_rate / 1e6),
        "ratio_per_pixel": ratio(ours_pixel_rate, classic_pixel_rate),
        "ours_render_scale": ours_scale,
        "ratio_per_rendered_pixel": ratio_per_rendered_pixel,
        "ours_callbacks_fps": round3(mean(Page::Ours, &|m| m.callbacks_fps)),
        name("callbacks_fps"): round3(mean(other, &|m| m.callbacks_fps)),
    })
}

/// Waits until the machine is mostly idle (see `SETTLE_BUSY`); returns how long that took and
/// how busy the last second was.
async fn settle() -> Value {
    let start = Instant::now();
    loop {
        let before = CpuSample::take(0);
        tokio::time::sleep(Duration::from_secs(1)).await;
        let busy = CpuSample::take(0).since(&before)["busy"].as_f64().unwrap_or(1.0);
        if busy < SETTLE_BUSY || start.elapsed() >= SETTLE_MAX {
            return json!({ "s": round2(start.elapsed().as_secs_f64()), "busy": busy });
        }
    }
}

/// CPU time counters (clock ticks) of the whole machine and of one process tree.
struct CpuSample {
    /// All CPUs: total and idle (idle + iowait) ticks since boot.
    total: u64,
    idle: u64,
    /// User + system ticks of the live processes of the tree (0: none).
    tree: u64,
}

impl CpuSample {
    /// Now; `root` = the tree to follow (the browser: chromedriver and its descendants).
    fn take(root: u32) -> Self {
        let stat = std::fs::read_to_string("/proc/stat").unwrap_or_default();
        let fields: Vec<u64> = stat
            .lines()
            .next()
            .unwrap_or("")
            .split_whitespace()
            .skip(1)
            .take(8)
            .filter_map(|f| f.parse().ok())
            .collect();
        let total = fields.iter().sum();
        let idle = fields.get(3).copied().unwrap_or(0) + fields.get(4).copied().unwrap_or(0);
        let tree = if root == 0 {
            0
        } else {
            process_tree(&processes(), root)
                .iter()
                .filter_map(|pid| {
                    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
                    let rest: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
                    // After "pid (comm)": state is field 0, utime field 11, stime field 12.
                    Some(rest.get(11)?.parse::<u64>().ok()? + rest.get(12)?.parse::<u64>().ok()?)
                })
                .sum()
        };
        Self { total, idle, tree }
    }

    /// Shares of all CPUs' time since `earlier` (1 = every core busy the whole time): busy, by
    /// the followed tree (the browser), and by everything else. Processes of the tree that ended
    /// meanwhile are not counted, so `browser` can be a little low.
    fn since(&self, earlier: &CpuSample) -> Value {
        let total = self.total.saturating_sub(earlier.total).max(1) as f64;
        let busy = 1.0 - self.idle.saturating_sub(earlier.idle) as f64 / total;
        let browser = self.tree.saturating_sub(earlier.tree) as f64 / total;
        json!({ "busy": round3(busy), "browser": round3(browser), "others": round3((busy - browser).max(0.0)) })
    }
}

fn round2(x: f64) -> f64 {
    (x * 100.0).round() / 100.0
}

fn round3(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}
