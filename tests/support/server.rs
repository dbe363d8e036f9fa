//! The built page (`dist/`) and the classic's folder served on 127.0.0.1 by a small static
//! server that can count the frames a page draws (the frame counter put in first).
#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};

/// The built page: `$WAVEPOOL_DIST` or `dist/` in the crate.
pub fn dist_dir() -> PathBuf {
    let dir = std::env::var_os("WAVEPOOL_DIST")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("dist"));
    for file in ["index.html", "embed.js", "wavepool.js", "wavepool_bg.wasm"] {
        assert!(
            dir.join(file).is_file(),
            "{} is missing: the browser tests need the built page; run ./scripts/test (it runs \
             `trunk build --release` first)",
            dir.join(file).display()
        );
    }
    dir
}

/// Evan Wallace's WebGL Water, the measuring stick of the browser benchmark: the team's
/// read-only copy next to the crate (`../shared/anchors/webgl-water`). Served as it is, never
/// copied into the project.
pub fn classic_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/anchors/webgl-water");
    assert!(
        dir.join("index.html").is_file(),
        "{} is missing: the benchmark measures our page against the classic WebGL Water, \
         which it expects (unchanged, read-only) in ../shared/anchors/webgl-water beside the crate",
        dir.display()
    );
    dir
}

/// The frame counter (`tests/pages/frame_counter.js`): add it with `Browser::add_init_script`
/// before loading a page, then `window.__frameCounter.reset()` / `.read()` in the page.
pub const FRAME_COUNTER_JS: &str = include_str!("../pages/frame_counter.js");

fn content_type(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript",
        Some("css") => "text/css",
        Some("wasm") => "application/wasm",
        Some("svg") => "image/svg+xml",
        Some("json") => "application/json",
        Some("woff2") => "font/woff2",
        Some("png") => "image/png",
        Some("jpg" | "jpeg") => "image/jpeg",
        _ => "application/octet-stream",
    }
}

/// A static file server for `dist/` at `/` and `tests/pages/` at `/test/` (and, when started
/// with `start_with_classic`, the classic WebGL Water at `/classic/`).
pub struct StaticServer {
    pub port: u16,
    /// Paths requested so far, in order.
    requests: std::sync::Arc<std::sync::Mutex<Vec<String>>>,
}

impl StaticServer {
    pub fn start() -> Self {
        Self::start_serving(None, false, Vec::new())
    }

    /// Also serves each folder under its URL prefix (`("/hosts/", dir)`: `/hosts/a.js` is
    /// `dir/a.js`), ahead of `dist/`.
    pub fn start_with_mounts(mounts: Vec<(&str, PathBuf)>) -> Self {
        let mounts = mounts.into_iter().map(|(prefix, dir)| (prefix.to_owned(), dir)).collect();
        Self::start_serving(None, false, mounts)
    }

    /// Also serves the classic WebGL Water (`classic_dir()`, read-only) at `/classic/`;
    /// panics with a clear message when it is missing. With `count_frames`, every HTML page
    /// served starts with the frame counter ([`FRAME_COUNTER_JS`]) as its first script, so it
    /// runs before the page's own in any engine (the way to inject it where DevTools is not
    /// there: Firefox, WebKit).
    pub fn start_with_classic(count_frames: bool) -> Self {
        Self::start_with_classic_and_mounts(count_frames, Vec::new())
    }

    /// `start_with_classic` and `start_with_mounts` together.
    pub fn start_with_classic_and_mounts(count_frames: bool, mounts: Vec<(&str, PathBuf)>) -> Self {
        let mounts = mounts.into_iter().map(|(prefix, dir)| (prefix.to_owned(), dir)).collect();
        Self::start_serving(Some(classic_dir()), count_frames, mounts)
    }

    fn start_serving(classic: Option<PathBuf>, count_frames: bool, mounts: Vec<(String, PathBuf)>) -> Self {
        let dist = dist_dir();
        let pages = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/pages");
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind the test server");
        let port = listener.local_addr().expect("address").port();
        let requests = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
        let log = requests.clone();
        let served = mounts;
        std::thread::spawn(move || {
            for stream in listener.incoming().flatten() {
                let (dist, pages, classic, log) = (dist.clone(), pages.clone(), classic.clone(), log.clone());
                let mounts = served.clone();
                std::thread::spawn(move || {
                    let folders = Folders { dist: &dist, pages: &pages, classic: classic.as_deref(), mounts: &mounts };
                    if let Some(path) = serve(stream, &folders, count_frames) {
                        log.lock().unwrap_or_else(|e| e.into_inner()).push(path);
                    }
                });
            }
        });
        Self { port, requests }
    }

    /// The paths requested so far (query strings included), in order.
    pub fn requests(&self) -> Vec<String> {
        self.requests.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    pub fn url(&self, path: &str) -> String {
        format!("http://127.0.0.1:{}{path}", self.port)
    }
}

/// `html` with `script` inlined as the first thing of its head (or of the document).
fn with_first_script(html: &[u8], script: &str) -> Vec<u8> {
    let text = String::from_utf8_lossy(html);
    let tag = format!("<script>{script}</script>");
    let at = text.to_ascii_lowercase().find("<head>").map_or(0, |i| i + "<head>".len());
    format!("{}{tag}{}", &text[..at], &text[at..]).into_bytes()
}

/// What the test server serves: `dist/` at `/`, `tests/pages/` at `/test/`, the classic at
/// `/classic/` (when given) and further folders under their prefixes.
struct Folders<'a> {
    dist: &'a Path,
    pages: &'a Path,
    classic: Option<&'a Path>,
    mounts: &'a [(String, PathBuf)],
}

impl Folders<'_> {
    /// The file a request's path names.
    fn file(&self, path: &str) -> PathBuf {
        for (prefix, dir) in self.mounts {
            if let Some(rest) = path.strip_prefix(prefix.as_str()) {
                let file = dir.join(rest);
                return if file.is_dir() { file.join("index.html") } else { file };
            }
        }
        if let (Some(dir), Some(rest)) = (self.classic, path.strip_prefix("/classic/")) {
            return dir.join(if rest.is_empty() { "index.html" } else { rest });
        }
        match path.strip_prefix("/test/") {
            Some(rest) => self.pages.join(rest),
            None if path == "/" => self.dist.join("index.html"),
            None => self.dist.join(path.trim_start_matches('/')),
        }
    }
}

/// Answers one request; returns the path (with its query) it asked for.
fn serve(mut stream: TcpStream, folders: &Folders, count_frames: bool) -> Option<String> {
    let mut reader = BufReader::new(stream.try_clone().expect("clone stream"));
    let mut request = String::new();
    if reader.read_line(&mut request).is_err() {
        return None;
    }
    loop {
        let mut header = String::new();
        if reader.read_line(&mut header).map_or(true, |n| n == 0) || header == "\r\n" {
            break;
        }
    }
    let target = request.split_whitespace().nth(1).unwrap_or("/");
    let path = target.split('?').next().unwrap_or("/");
    let file = folders.file(path);
    let safe = !path.contains("..");
    let response = match std::fs::read(&file) {
        Ok(body) if safe => {
            let html = file.extension().is_some_and(|e| e == "html");
            let body = if count_frames && html { with_first_script(&body, FRAME_COUNTER_JS) } else { body };
            let head = format!(
                "HTTP/1.1 200 OK\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
                content_type(&file),
                body.len()
            );
            [head.into_bytes(), body].concat()
        }
        _ => b"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n".to_vec(),
    };
    let _ = stream.write_all(&response);
    let _ = stream.flush();
    let mut rest = Vec::new();
    let _ = reader.read_to_end(&mut rest);
    Some(target.to_owned())
}
