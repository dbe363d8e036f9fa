//! Drives a browser through WebDriver against the built page (`dist/`), served by a small
//! static server on 127.0.0.1: Debian's headless Chromium through chromedriver, Firefox ESR
//! through geckodriver, WebKitGTK's MiniBrowser through WebKitWebDriver (those two under a
//! virtual X server of their own when they need a display). Shared by the browser tests and
//! the browser benchmark. Nothing is skipped: a missing `dist/`, driver or browser is a failure
//! that says how to get it.
#![allow(dead_code)]

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use fantoccini::{Client, ClientBuilder};
use serde_json::{json, Value};

#[path = "picture.rs"]
pub mod picture;
#[path = "server.rs"]
mod server;
#[allow(unused_imports)]
pub use server::*;
#[path = "host.rs"]
mod host;
// Not every test binary uses each part.
#[allow(unused_imports)]
pub use host::*;
// For the test files (a binary that takes only some of them leaves the others unused).
#[allow(unused_imports)]
pub use picture::{Image, Rect};

pub const CHROMIUM: &str = "/usr/bin/chromium";
pub const CHROMEDRIVER: &str = "/usr/bin/chromedriver";
pub const FIREFOX: &str = "/usr/bin/firefox-esr";
pub const WEBKIT_DRIVER: &str = "/usr/bin/WebKitWebDriver";
pub const WEBKIT_BROWSER: &str = "/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser";

/// geckodriver, which `./scripts/test` installs with cargo (pinned there).
pub fn geckodriver() -> PathBuf {
    let on_path = std::env::var_os("PATH")
        .into_iter()
        .flat_map(|p| std::env::split_paths(&p).collect::<Vec<_>>())
        .map(|dir| dir.join("geckodriver"))
        .find(|p| p.is_file());
    let in_cargo = std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo/bin/geckodriver"));
    on_path.or(in_cargo.filter(|p| p.is_file())).unwrap_or_else(|| {
        panic!("geckodriver is missing: the Firefox tests need it (./scripts/test installs it with cargo install)")
    })
}

/// Longest wait for a demo's first frame (SwiftShader compiles slowly).
pub const READY: Duration = Duration::from_secs(120);

/// One browser at a time in a test binary: two software-rendered browsers on two cores only
/// slow each other. Each test holds the guard for its whole run.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

pub fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// JS: the message shown by the demo in `#pool` ('' when hidden).
pub const MESSAGE_JS: &str = "const m = document.querySelector('#pool').shadowRoot.querySelector('.message');
                              return m && !m.hidden ? m.textContent : '';";

/// What graphics the browser is started with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Graphics {
    /// WebGPU and WebGL2 on SwiftShader (the flags from the team's toolchain notes).
    WebGpu,
    /// No WebGPU flags: `navigator.gpu` gives no adapter, WebGL2 works.
    WebGl2Only,
    /// No GPU process and no software rasteriser: neither WebGPU nor WebGL2.
    Nothing,
}

const BASE_FLAGS: &[&str] = &[
    "--headless=new",
    "--no-sandbox",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
    "--window-size=1100,1000",
    "--force-device-scale-factor=1",
];

const WEBGPU_FLAGS: &[&str] = &[
    "--enable-unsafe-webgpu",
    "--enable-features=Vulkan",
    "--use-vulkan=swiftshader",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
];

const NO_GPU_FLAGS: &[&str] = &["--disable-gpu", "--disable-software-rasterizer"];

/// Which browser engine, and how it is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Headless Chromium with the given graphics.
    Chromium(Graphics),
    /// Firefox ESR with default settings under a virtual X server: WebGL2 on llvmpipe (headless
    /// Firefox has no WebGL here).
    Firefox,
    /// Firefox ESR under a virtual X server with WebGPU turned on (`dom.webgpu.enabled`,
    /// `gfx.webgpu.ignore-blocklist`), composited by its software compositor as without a
    /// usable GPU (where an `rgba8unorm` canvas aborted the whole browser); WebGL2 works too.
    FirefoxWebGpu,
    /// WebKitGTK's MiniBrowser under a virtual X server: WebGL2 (this build has no WebGPU).
    WebKit,
}

impl Engine {
    pub fn name(self) -> &'static str {
        match self {
            Engine::Chromium(_) => "chromium",
            Engine::Firefox => "firefox",
            Engine::FirefoxWebGpu => "firefox-webgpu",
            Engine::WebKit => "webkit",
        }
    }
}

/// A browser session with its own driver, a fresh profile and, for engines that need a
/// display, its own virtual X server; `close` (or drop) ends them all.
pub struct Browser {
    pub client: Client,
    pub engine: Engine,
    driver: Child,
    profile: PathBuf,
    /// The driver's port on 127.0.0.1 (for DevTools commands, see `cdp`).
    driver_port: u16,
    xvfb: Option<VirtualDisplay>,
    /// Where the driver's output goes (Firefox prints the pages' console there).
    log: PathBuf,
}

/// An X server in memory (Xvfb) on a display number of its own, ended on drop.
struct VirtualDisplay {
    process: Child,
    display: String,
}

impl VirtualDisplay {
    fn start() -> Self {
        assert!(
            Path::new("/usr/bin/Xvfb").exists(),
            "Xvfb is missing: the Firefox and WebKit tests run under it (./scripts/test installs xvfb)"
        );
        let number = (100 + std::process::id() % 400..1000)
            .find(|n| !Path::new(&format!("/tmp/.X{n}-lock")).exists())
            .expect("a free X display number");
        let display = format!(":{number}");
        let process = Command::new("/usr/bin/Xvfb")
            .args([display.as_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("start Xvfb");
        let socket = format!("/tmp/.X11-unix/X{number}");
        let start = Instant::now();
        while !Path::new(&socket).exists() {
            assert!(start.elapsed() < Duration::from_secs(20), "Xvfb did not start on {display}");
            std::thread::sleep(Duration::from_millis(50));
        }
        Self { process, display }
    }
}

impl Drop for VirtualDisplay {
    fn drop(&mut self) {
        let _ = self.process.kill();
        let _ = self.process.wait();
    }
}

fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0").and_then(|l| l.local_addr()).expect("free port").port()
}

fn require(tool: &str, what: &str) {
    assert!(Path::new(tool).exists(), "{tool} is missing: the browser tests need {what} (./scripts/test installs it)");
}

impl Browser {
    /// A headless Chromium session.
    pub async fn open(graphics: Graphics) -> Self {
        Self::open_engine(Engine::Chromium(graphics)).await
    }

    pub async fn open_engine(engine: Engine) -> Self {
        let port = free_port();
        let profile = std::env::temp_dir().join(format!("wavepool-{}-{}-{port}", engine.name(), std::process::id()));
        let _ = std::fs::remove_dir_all(&profile);
        std::fs::create_dir_all(&profile).expect("profile folder");
        let log = profile.join("driver.log");
        let xvfb =
            matches!(engine, Engine::Firefox | Engine::FirefoxWebGpu | Engine::WebKit).then(VirtualDisplay::start);
        let mut caps = serde_json::Map::new();
        let mut driver = match engine {
            Engine::Chromium(graphics) => {
                require(CHROMIUM, "Debian's chromium");
                require(CHROMEDRIVER, "Debian's chromium-driver");
                let mut args: Vec<String> = BASE_FLAGS.iter().map(|s| s.to_string()).collect();
                args.push(format!("--user-data-dir={}", profile.join("chromium").display()));
                match graphics {
                    Graphics::WebGpu => args.extend(WEBGPU_FLAGS.iter().map(|s| s.to_string())),
                    Graphics::WebGl2Only => {}
                    Graphics::Nothing => args.extend(NO_GPU_FLAGS.iter().map(|s| s.to_string())),
                }
                caps.insert("goog:chromeOptions".into(), json!({ "binary": CHROMIUM, "args": args }));
                let mut driver = Command::new(CHROMEDRIVER);
                driver.arg(format!("--port={port}"));
                driver
            }
            Engine::Firefox | Engine::FirefoxWebGpu => {
                require(FIREFOX, "Debian's firefox-esr");
                // Pages' console messages go to Firefox's output, which the driver's log keeps.
                let mut prefs = json!({ "devtools.console.stdout.content": true });
                if engine == Engine::FirefoxWebGpu {
                    prefs["dom.webgpu.enabled"] = json!(true);
                    prefs["gfx.webgpu.ignore-blocklist"] = json!(true);
                }
                caps.insert("browserName".into(), json!("firefox"));
                caps.insert("moz:firefoxOptions".into(), json!({ "binary": FIREFOX, "prefs": prefs }));
                let mut driver = Command::new(geckodriver());
                driver.args(["--port", &port.to_string()]);
                driver
            }
            Engine::WebKit => {
                require(WEBKIT_DRIVER, "Debian's webkit2gtk-driver");
                require(WEBKIT_BROWSER, "Debian's webkit2gtk-driver (its MiniBrowser)");
                caps.insert("browserName".into(), json!("MiniBrowser"));
                caps.insert(
                    "webkitgtk:browserOptions".into(),
                    json!({ "binary": WEBKIT_BROWSER, "args": ["--automation"] }),
                );
                let mut driver = Command::new(WEBKIT_DRIVER);
                driver.arg(format!("--port={port}"));
                driver
            }
        };
        if let Some(x) = &xvfb {
            driver.env("DISPLAY", &x.display);
        }
        // Its own process group, so the browser goes with it when a failed test drops the
        // session; HOME in the profile, so crash reports and caches stay out of the user's.
        let output = std::fs::File::create(&log).expect("driver log");
        let mut driver = driver
            .process_group(0)
            .env("HOME", &profile)
            .stdout(output.try_clone().expect("driver log"))
            .stderr(output)
            .spawn()
            .unwrap_or_else(|e| panic!("start the {} driver: {e}", engine.name()));
        let start = Instant::now();
        while TcpStream::connect(("127.0.0.1", port)).is_err() {
            if start.elapsed() > Duration::from_secs(20) {
                let _ = driver.kill();
                panic!("the {} driver did not start", engine.name());
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let client = ClientBuilder::new(hyper_util::client::legacy::connect::HttpConnector::new())
            .capabilities(caps)
            .connect(&format!("http://127.0.0.1:{port}"))
            .await
            .unwrap_or_else(|e| panic!("open a {} session: {e}", engine.name()));
        Self { client, engine, driver, profile, driver_port: port, xvfb, log }
    }

    /// What the driver and the browser printed so far (Firefox: the pages' console too, as
    /// `console.error: "..."` lines and `JavaScript error: <url>, line N: ...`).
    pub fn driver_log(&self) -> String {
        String::from_utf8_lossy(&std::fs::read(&self.log).unwrap_or_default()).into_owned()
    }

    /// Errors the page reported to Firefox's console (from scripts served on 127.0.0.1), and
    /// signs that the browser crashed; empty for other engines, which do not print them.
    pub fn page_errors(&self) -> Vec<String> {
        self.driver_log()
            .lines()
            .filter(|l| {
                l.starts_with("console.error: \"")
                    || l.starts_with("JavaScript error: http://127.0.0.1")
                    || l.contains("MOZ_RELEASE_ASSERT")
                    || l.contains("MOZ_CRASH(")
                    || l.contains("Crash Annotation")
            })
            .map(str::to_owned)
            .collect()
    }

    pub async fn close(self) {
        let _ = self.client.clone().close().await;
        // Drop ends chromedriver and whatever Chromium it started.
    }

    pub async fn goto(&self, url: &str) {
        self.client.goto(url).await.expect("load the page");
    }

    /// Runs `body` (a function body; `return` gives the result) in the page.
    pub async fn js(&self, body: &str) -> Value {
        self.client.execute(body, vec![]).await.unwrap_or_else(|e| panic!("script failed: {e}\n{body}"))
    }

    /// Runs an async function body in the page and waits for its result.
    pub async fn js_async(&self, body: &str) -> Value {
        let script = format!(
            "const done = arguments[arguments.length - 1];
             (async () => {{ {body} }})().then(done, (e) => done({{ error: String(e && e.message || e) }}));"
        );
        self.client.execute_async(&script, vec![]).await.unwrap_or_else(|e| panic!("script failed: {e}\n{body}"))
    }

    /// Waits until the element matching `selector` is ready (`data-ready="true"`); fails early
    /// with the demo's own message when it shows an error.
    pub async fn wait_ready(&self, selector: &str, timeout: Duration) -> Duration {
        let start = Instant::now();
        loop {
            let state = self
                .js(&format!(
                    "const e = document.querySelector('{selector}');
                     if (!e) return {{ missing: true }};
                     const m = e.shadowRoot && e.shadowRoot.querySelector('.message');
                     return {{ ready: e.dataset.ready === 'true', error: e.dataset.error === 'true',
                               message: m ? m.textContent : '' }};"
                ))
                .await;
            if state["ready"] == true {
                return start.elapsed();
            }
            if state["error"] == true {
                panic!("{selector} failed instead of becoming ready: {}", state["message"]);
            }
            if start.elapsed() > timeout {
                panic!("{selector} not ready after {timeout:?}: {state}");
            }
            tokio::time::sleep(Duration::from_millis(200)).await;
        }
    }

    /// Waits until the demo in the page (`window.demo`) has drawn `n` more frames, the first
    /// of them after whatever the test just changed: an event to await instead of a sleep.
    pub async fn wait_frames(&self, n: u32) {
        let got = self
            .js_async(&format!(
                "const d = window.demo, start = d._framesDrawn, until = performance.now() + 60000;
                 while (d._framesDrawn < start + {n} && performance.now() < until) await new Promise((r) => setTimeout(r, 20));
                 return d._framesDrawn - start;"
            ))
            .await;
        assert!(got.as_u64().is_some_and(|k| k >= n as u64), "{n} frames not drawn within 60 s: {got}");
    }

    /// Waits until the water in the page (`window.demo`) has run `seconds` more of simulated
    /// time: what a check of its motion needs, however fast frames come.
    pub async fn wait_sim_time(&self, seconds: f64) {
        let got = self
            .js_async(&format!(
                "const d = window.demo, t0 = d.stats().simTime, f0 = d._framesDrawn, until = performance.now() + 20000;
                 while (d.stats().simTime - t0 < {seconds} - 1e-9 && performance.now() < until) await new Promise((r) => setTimeout(r, 50));
                 const s = d.stats();
                 return {{ ran: s.simTime - t0, frames: d._framesDrawn - f0, paused: d.get('paused'), fps: s.fps, simSpeed: s.simSpeed }};"
            ))
            .await;
        assert!(got["ran"].as_f64().is_some_and(|t| t >= seconds - 1e-9), "{seconds} s of water not run: {got}");
    }

    /// Waits until `condition` (a JS expression) is true.
    pub async fn wait_for(&self, condition: &str, timeout: Duration) -> bool {
        let start = Instant::now();
        while start.elapsed() < timeout {
            if self.js(&format!("return Boolean({condition});")).await == true {
                return true;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        false
    }

    pub async fn screenshot(&self) -> Image {
        Image::decode(&self.client.screenshot().await.expect("screenshot"))
    }

    /// Presses the left mouse button at viewport point (x, y) (CSS pixels) and releases it.
    pub async fn click_at(&self, x: f64, y: f64) {
        use fantoccini::actions::{InputSource, MouseActions, PointerAction, MOUSE_BUTTON_LEFT};
        let mouse = MouseActions::new("mouse".into())
            .then(PointerAction::MoveTo { duration: None, x: x.round(), y: y.round() })
            .then(PointerAction::Down { button: MOUSE_BUTTON_LEFT })
            .then(PointerAction::Pause { duration: Duration::from_millis(50) })
            .then(PointerAction::Up { button: MOUSE_BUTTON_LEFT });
        self.client.perform_actions(mouse).await.expect("click");
    }

    /// Drags the left mouse button from `from` to `to` (viewport CSS px) in `steps` moves.
    pub async fn drag(&self, from: (f64, f64), to: (f64, f64), steps: u32) {
        use fantoccini::actions::{InputSource, MouseActions, PointerAction, MOUSE_BUTTON_LEFT};
        let mut mouse = MouseActions::new("mouse".into())
            .then(PointerAction::MoveTo { duration: None, x: from.0.round(), y: from.1.round() })
            .then(PointerAction::Down { button: MOUSE_BUTTON_LEFT });
        for i in 1..=steps.max(1) {
            let t = i as f64 / steps.max(1) as f64;
            let (x, y) = (from.0 + (to.0 - from.0) * t, from.1 + (to.1 - from.1) * t);
            mouse = mouse.then(PointerAction::MoveTo {
                duration: Some(Duration::from_millis(40)),
                x: x.round(),
                y: y.round(),
            });
        }
        mouse = mouse.then(PointerAction::Up { button: MOUSE_BUTTON_LEFT });
        self.client.perform_actions(mouse).await.expect("drag");
    }
}

/// DevTools commands, init scripts and the viewport: what the browser benchmark needs on top of
/// plain WebDriver.
impl Browser {
    /// chromedriver's process id (Chromium and its helpers are its descendants).
    pub fn driver_pid(&self) -> u32 {
        self.driver.id()
    }

    /// Sends a DevTools command to the current tab through chromedriver's passthrough
    /// (`POST /session/{id}/goog/cdp/execute`) and returns its result.
    pub async fn cdp(&self, method: &str, params: Value) -> Value {
        let session = self.client.session_id().await.expect("session id").expect("an open WebDriver session");
        let path = format!("/session/{session}/goog/cdp/execute");
        let body = json!({ "cmd": method, "params": params }).to_string();
        let port = self.driver_port;
        let reply = tokio::task::spawn_blocking(move || http_post_json(port, &path, &body))
            .await
            .expect("DevTools request thread");
        match reply {
            Ok(reply) => reply["value"].clone(),
            Err(e) => panic!("DevTools command {method} failed: {e}"),
        }
    }

    /// Adds `source` to every document this tab loads from now on (iframes included), run
    /// before the page's own scripts (`Page.addScriptToEvaluateOnNewDocument`). Takes effect
    /// from the next navigation.
    pub async fn add_init_script(&self, source: &str) {
        let reply = self.cdp("Page.addScriptToEvaluateOnNewDocument", json!({ "source": source })).await;
        assert!(reply["identifier"].is_string(), "init script not added: {reply}");
    }

    /// Sizes the window so that the viewport (`innerWidth` x `innerHeight`, CSS px) is
    /// `width` x `height`, and returns the viewport it got. The window is resized through
    /// WebDriver and corrected by what the page reports; only if that cannot reach the size
    /// (a headless screen smaller than the window needs) is the viewport emulated through
    /// DevTools (`Emulation.setDeviceMetricsOverride`, scale factor 1).
    pub async fn set_viewport(&self, width: u32, height: u32) -> (u32, u32) {
        let (mut window_w, mut window_h) = (width, height);
        for _ in 0..4 {
            self.client.set_window_size(window_w, window_h).await.expect("set the window size");
            let (w, h) = self.viewport().await;
            if (w, h) == (width, height) {
                return (w, h);
            }
            window_w = (window_w as i64 + width as i64 - w as i64).max(200) as u32;
            window_h = (window_h as i64 + height as i64 - h as i64).max(200) as u32;
        }
        if !matches!(self.engine, Engine::Chromium(_)) {
            return self.viewport().await;
        }
        let metrics = json!({ "width": width, "height": height, "deviceScaleFactor": 1, "mobile": false });
        self.cdp("Emulation.setDeviceMetricsOverride", metrics).await;
        self.viewport().await
    }

    /// The viewport of the current page: (`innerWidth`, `innerHeight`) in CSS px.
    pub async fn viewport(&self) -> (u32, u32) {
        let v = self.js("return [innerWidth, innerHeight];").await;
        let side = |i: usize| v[i].as_u64().unwrap_or_else(|| panic!("viewport size in {v}")) as u32;
        (side(0), side(1))
    }
}

/// POSTs a JSON body to chromedriver on 127.0.0.1:`port` (plain HTTP/1.1, one connection per
/// request) and returns the JSON reply; an error for a status other than 200.
fn http_post_json(port: u16, path: &str, body: &str) -> Result<Value, String> {
    let mut stream = TcpStream::connect(("127.0.0.1", port)).map_err(|e| format!("connect to chromedriver: {e}"))?;
    stream.set_read_timeout(Some(Duration::from_secs(120))).map_err(|e| e.to_string())?;
    let request = format!(
        "POST {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/json; charset=utf-8\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    stream.write_all(request.as_bytes()).map_err(|e| format!("send: {e}"))?;
    // chromedriver keeps the connection open whatever the request says: read the header, then
    // exactly the body it announces (Content-Length, or chunks up to the last one).
    let mut reply = Vec::new();
    let mut buf = [0u8; 16384];
    let mut receive = |reply: &mut Vec<u8>| -> Result<(), String> {
        let n = stream.read(&mut buf).map_err(|e| format!("receive: {e}"))?;
        if n == 0 {
            return Err("chromedriver closed the connection early".into());
        }
        reply.extend_from_slice(&buf[..n]);
        Ok(())
    };
    let split = loop {
        if let Some(split) = reply.windows(4).position(|w| w == b"\r\n\r\n") {
            break split;
        }
        receive(&mut reply)?;
    };
    let head = String::from_utf8_lossy(&reply[..split]).to_ascii_lowercase();
    let length =
        head.lines().find_map(|l| l.strip_prefix("content-length:")).and_then(|v| v.trim().parse::<usize>().ok());
    let content = match length {
        Some(length) => {
            while reply.len() < split + 4 + length {
                receive(&mut reply)?;
            }
            reply[split + 4..split + 4 + length].to_vec()
        }
        None if head.contains("transfer-encoding: chunked") => {
            while !reply[split + 4..].ends_with(b"0\r\n\r\n") {
                receive(&mut reply)?;
            }
            dechunk(&reply[split + 4..])
        }
        None => return Err(format!("reply of unknown length: {head}")),
    };
    let status = head.split_whitespace().nth(1).unwrap_or("");
    let value: Value = serde_json::from_slice(&content)
        .map_err(|e| format!("HTTP {status}, reply not JSON ({e}): {}", String::from_utf8_lossy(&content)))?;
    if status == "200" {
        Ok(value)
    } else {
        Err(format!("HTTP {status}: {value}"))
    }
}

/// The body of a chunked HTTP/1.1 reply.
fn dechunk(mut data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    while let Some(line_end) = data.windows(2).position(|w| w == b"\r\n") {
        let size = std::str::from_utf8(&data[..line_end])
            .ok()
            .and_then(|s| usize::from_str_radix(s.split(';').next().unwrap_or("").trim(), 16).ok())
            .unwrap_or(0);
        let start = line_end + 2;
        if size == 0 || start + size > data.len() {
            break;
        }
        out.extend_from_slice(&data[start..start + size]);
        data = &data[(start + size + 2).min(data.len())..];
    }
    out
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = Command::new("kill").args(["-KILL", "--", &format!("-{}", self.driver.id())]).status();
        let _ = self.driver.kill();
        let _ = self.driver.wait();
        self.xvfb.take();
        let _ = std::fs::remove_dir_all(&self.profile);
    }
}

/// The canvas rectangle of the demo mounted in `selector`, as JS code.
pub fn canvas_rect_js(selector: &str) -> String {
    format!(
        "const c = document.querySelector('{selector}').shadowRoot.querySelector('canvas');
         const r = c.getBoundingClientRect();
         return {{ left: r.left, top: r.top, width: r.width, height: r.height }};"
    )
}
