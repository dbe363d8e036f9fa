//! What a user downloads, used as its users would: the release folder (the npm tarball, the
//! single page, the course zip and their checksums); the package's declarations against the
//! parameter table; a Vite app made here that installs the tarball, imports `mount` in
//! TypeScript, type-checks (and fails on a misspelt option or choice), builds and shows the pool
//! on both backends in headless Chromium; the course zip unpacked under a deep path (its page
//! holding the whole picture in the first screen from 320 to 1280 px wide); the
//! package's files served from two places (`setAssetLocation`). Needs `release/` and
//! `target/npm-package/` (./scripts/test writes them after the web build) and Vite 7.3.8 and
//! TypeScript 5.9.3 in the cache (./scripts/test installs them).

// One browser at a time, held across awaits: each test runs on its own thread and runtime.
#![allow(clippy::await_holding_lock)]

#[path = "support/browser.rs"]
mod support;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use support::{serial, Browser, Graphics, StaticServer, READY};
use wavepool::param_spec::Control;

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

/// The folder ./scripts/test (or ./scripts/release) wrote.
fn release_dir() -> PathBuf {
    let dir = crate_dir().join("release");
    assert!(
        dir.join("SHA256SUMS").is_file(),
        "{} is missing: run ./scripts/test or ./scripts/release, which write it after the web build",
        dir.display()
    );
    dir
}

/// The npm package's folder as the build made it.
fn package_dir() -> PathBuf {
    let dir = crate_dir().join("target/npm-package");
    assert!(dir.join("package.json").is_file(), "{} is missing: run ./scripts/test", dir.display());
    dir
}

/// Where Vite and TypeScript are installed; test apps made inside it find them.
fn package_tools() -> PathBuf {
    let cache = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(std::env::var_os("HOME").expect("HOME")).join(".cache"));
    let dir = cache.join("wavepool/package-tools");
    for tool in ["vite/bin/vite.js", "typescript/bin/tsc"] {
        assert!(
            dir.join("node_modules").join(tool).is_file(),
            "{tool} is missing in {}: run ./scripts/test",
            dir.display()
        );
    }
    dir
}

/// Runs a command in `dir`; returns (success, stdout and stderr).
fn run(dir: &Path, program: &str, args: &[&str]) -> (bool, String) {
    let out =
        Command::new(program).args(args).current_dir(dir).output().unwrap_or_else(|e| panic!("run {program}: {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    (out.status.success(), text)
}

/// The files a tar or zip archive lists (folders left out).
fn archive_files(listing: &str) -> BTreeSet<String> {
    listing.lines().map(str::trim).filter(|l| !l.is_empty() && !l.ends_with('/')).map(str::to_owned).collect()
}

/// The modules `entry` imports, directly or through each other, in `dir`: every `from "./x.js"`,
/// `import "./x.js"` or `import("./x.js")`, with either quote.
fn module_graph(dir: &Path, entry: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    let mut todo = vec![entry.to_owned()];
    while let Some(name) = todo.pop() {
        if !seen.insert(name.clone()) {
            continue;
        }
        let text = std::fs::read_to_string(dir.join(&name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        for quote in ['"', '\''] {
            for (at, _) in text.match_indices(&format!("{quote}./")) {
                // Only an import's specifier: after `from`, `import` or `import(`.
                let before = text[..at].trim_end().trim_end_matches('(').trim_end();
                if !(before.ends_with("from") || before.ends_with("import")) {
                    continue;
                }
                let part = &text[at + 3..];
                let Some(end) = part.find(&format!(".js{quote}")) else { continue };
                let module = &part[..end];
                if module.chars().all(|c| c.is_alphanumeric() || c == '-' || c == '_') {
                    todo.push(format!("{module}.js"));
                }
            }
        }
    }
    seen
}

#[test]
fn the_release_folder_holds_the_tarball_the_single_page_and_the_course_zip_with_their_checksums() {
    let dir = release_dir();
    let tarball = format!("wavepool-{}.tgz", version());
    let zip = format!("wavepool-{}-course.zip", version());
    for name in [tarball.as_str(), "wavepool-standalone.html", zip.as_str()] {
        let bytes = std::fs::metadata(dir.join(name)).unwrap_or_else(|e| panic!("release/{name}: {e}")).len();
        println!("release/{name}: {bytes} bytes");
    }
    let (ok, text) = run(&dir, "sha256sum", &["--check", "SHA256SUMS"]);
    assert!(ok, "the checksums do not match the files:\n{text}");
    assert_eq!(text.matches(": OK").count(), 3, "SHA256SUMS lists the three downloads:\n{text}");

    // The tarball: exactly the modules embed.js loads, the core, its assets, types, licences.
    let (ok, listing) = run(&dir, "tar", &["-tzf", &tarball]);
    assert!(ok, "tar -tzf {tarball}: {listing}");
    let files: BTreeSet<String> = archive_files(&listing)
        .iter()
        .map(|f| f.strip_prefix("package/").expect("npm's package/ folder").to_owned())
        .collect();
    // What the built page's embed.js loads (dist/), so a module the package left out fails here.
    let dist = support::dist_dir();
    let mut wanted = module_graph(&dist, "embed.js");
    wanted.extend(
        [
            "element.js",
            "element.d.ts",
            "embed.d.ts",
            "tables.d.ts",
            "wavepool_bg.wasm",
            "wavepool.css",
            "no-gpu.webp",
            "package.json",
            "README.md",
            "LICENSE-MIT",
            "LICENSE-APACHE",
        ]
        .map(String::from),
    );
    // The message catalogues and the Fluent runtime, fetched for a language other than English.
    for entry in std::fs::read_dir(dist.join("locales")).expect("dist/locales") {
        wanted.insert(format!("locales/{}", entry.expect("entry").file_name().to_string_lossy()));
    }
    println!("the tarball's {} files: {files:?}", files.len());
    assert_eq!(files, wanted, "the tarball holds what the demo needs and nothing else");
    let pkg: serde_json::Value =
        serde_json::from_slice(&std::fs::read(package_dir().join("package.json")).unwrap()).expect("package.json");
    assert_eq!(pkg["version"], version(), "the package's version is the crate's");
    assert_eq!(pkg["type"], "module");
    assert_eq!(pkg["exports"]["."]["types"], "./embed.d.ts");

    // The course zip: the pages and the demo's files in one folder, with its two-line README.
    let (ok, listing) = run(&dir, "python3", &["-m", "zipfile", "-l", &zip]);
    assert!(ok, "python3 -m zipfile -l {zip}: {listing}");
    let names: Vec<&str> = listing.lines().skip(1).filter_map(|l| l.split_whitespace().next()).collect();
    for wanted in [
        "wavepool/index.html",
        "wavepool/embed.html",
        "wavepool/embed.js",
        "wavepool/wavepool_bg.wasm",
        "wavepool/README.txt",
    ] {
        assert!(names.contains(&wanted), "the course zip lacks {wanted}: {names:?}");
    }
    assert!(!names.iter().any(|n| n.ends_with("standalone.html")), "the single page is its own download");
    println!("the course zip: {} files", names.iter().filter(|n| !n.ends_with('/')).count());
}

/// The body of `export interface NAME { … }` in a declaration file.
fn interface<'a>(dts: &'a str, name: &str) -> &'a str {
    let start = dts.find(&format!("export interface {name} ")).unwrap_or_else(|| panic!("no interface {name}"));
    let body = &dts[start..];
    &body[..body.find("\n}").expect("the interface's end")]
}

/// The property names an interface body declares (`name:` or `name?:` at its indent).
fn declared_properties(body: &str) -> BTreeSet<String> {
    body.lines()
        .filter_map(|l| l.strip_prefix("  "))
        .filter(|l| !l.starts_with(' ') && !l.starts_with("/**") && !l.starts_with('*'))
        .filter_map(|l| l.split(':').next())
        .map(|n| n.trim_end_matches('?').trim_matches('"').to_owned())
        .filter(|n| !n.is_empty() && !n.contains(' ') && !n.contains('('))
        .collect()
}

#[test]
fn the_declarations_name_every_parameter_with_its_choices_every_preset_and_every_creation_option() {
    let tables = std::fs::read_to_string(package_dir().join("tables.d.ts")).expect("tables.d.ts");
    let values = interface(&tables, "ParamValues");
    let attributes = interface(&tables, "ParamAttributes");
    let names: BTreeSet<String> = wavepool::params::table().iter().map(|p| p.name.to_owned()).collect();
    assert_eq!(declared_properties(values), names, "ParamValues lists the table's parameters");
    let kebab: BTreeSet<String> = names.iter().map(|n| n.replace('_', "-")).collect();
    assert_eq!(declared_properties(attributes), kebab, "ParamAttributes lists them in kebab case");
    let mut choices = 0;
    for p in wavepool::params::table() {
        let line = values.lines().find(|l| l.starts_with(&format!("  {}: ", p.name))).expect("its line");
        if let Control::Choice { names, values: numbers } = p.control {
            for name in names.iter().filter(|n| !n.is_empty()) {
                assert!(line.contains(&format!("\"{name}\"")), "{}: the choice {name} is not declared: {line}", p.name);
                choices += 1;
            }
            for v in numbers {
                assert!(line.contains(&format!(" {v}")), "{}: the value {v} is not declared: {line}", p.name);
            }
        }
    }
    let presets: Vec<&str> = wavepool::presets::PRESETS.iter().map(|p| p.name).collect();
    for name in &presets {
        assert!(tables.contains(&format!("| \"{name}\"")), "the preset {name} is not in PresetName");
    }
    let creation = declared_properties(interface(&tables, "CreationOptions"));
    let options: BTreeSet<String> = wavepool::demo::DemoOptions::SPECS.iter().map(|o| o.name.to_owned()).collect();
    assert_eq!(creation, options, "CreationOptions lists the creation options' specs");
    let kebab = |name: &str| {
        name.chars()
            .flat_map(|c| if c.is_uppercase() { vec!['-', c.to_ascii_lowercase()] } else { vec![c] })
            .collect::<String>()
    };
    let attributes = declared_properties(interface(&tables, "CreationAttributes"));
    assert_eq!(attributes, options.iter().map(|o| kebab(o)).collect(), "CreationAttributes: the same in kebab case");
    println!(
        "tables.d.ts: {} parameters, {choices} choice names, {} presets, {} creation options ({} bytes)",
        names.len(),
        presets.len(),
        options.len(),
        tables.len()
    );
}

/// A Vite app using the package: `src/main.ts` mounts the pool (backend from the URL),
/// `src/misuse.ts` makes four mistakes the types must catch.
fn make_vite_app(root: &Path) {
    let _ = std::fs::remove_dir_all(root);
    std::fs::create_dir_all(root.join("src")).expect("app folder");
    let write = |name: &str, text: &str| std::fs::write(root.join(name), text).expect("write the app");
    write("package.json", r#"{ "name": "course-page", "private": true, "type": "module" }"#);
    write(
        "index.html",
        r#"<!doctype html><html lang="en"><head><meta charset="utf-8"><title>A course page</title></head>
<body><h1>Waves</h1><div id="pool"></div><script type="module" src="/src/main.ts"></script></body></html>"#,
    );
    write(
        "tsconfig.json",
        r#"{ "compilerOptions": { "target": "ES2022", "module": "ESNext", "moduleResolution": "bundler",
  "strict": true, "noEmit": true, "lib": ["ES2022", "DOM"], "types": [] }, "files": ["src/main.ts"] }"#,
    );
    write("tsconfig.misuse.json", r#"{ "extends": "./tsconfig.json", "files": ["src/misuse.ts"] }"#);
    write(
        "src/main.ts",
        r#"import { mount, type WavePool, type MountOptions } from "wavepool";

const backend = new URLSearchParams(location.search).get("backend") === "webgl2" ? "webgl2" : "webgpu";
const options: MountOptions = { backend, preset: "calm", objects: "duck", wave_speed: 0.8, fresnel: "schlick", lazy: false };
mount(document.getElementById("pool")!, options).then((demo: WavePool) => {
  demo.set("caustics", true);
  demo.set("objects", "ball,duck"); // a set of bodies, in any order
  const s = demo.stats();
  if (!s.suspended) document.title = `${s.backend} ${s.simSize}`;
  (window as unknown as { demo: WavePool }).demo = demo;
});
// The element's type and events come with the package too.
const element = document.createElement("wave-pool");
element.addEventListener("wavepool:ready", (event) => event.detail.pause());
"#,
    );
    write(
        "src/misuse.ts",
        r#"import { mount } from "wavepool";
const el = document.body;
mount(el, { wave_sped: 0.8 });
mount(el, { objects: "dukc" });
mount(el, { preset: "clam" });
mount(el).then((demo) => demo.set("fresnel", "schlik"));
"#,
    );
}

#[tokio::test(flavor = "current_thread")]
async fn a_vite_app_installs_the_tarball_type_checks_builds_and_shows_the_pool_on_both_backends() {
    let _guard = serial();
    let tools = package_tools();
    let tarball = release_dir().join(format!("wavepool-{}.tgz", version()));
    let app = tools.join(format!("apps/course-page-{}", std::process::id()));
    make_vite_app(&app);
    let (ok, text) = run(&app, "npm", &["install", "--offline", "--no-audit", "--no-fund", tarball.to_str().unwrap()]);
    assert!(ok, "npm install of the tarball failed:\n{text}");

    let tsc = tools.join("node_modules/typescript/bin/tsc");
    let (ok, text) = run(&app, "node", &[tsc.to_str().unwrap(), "-p", "tsconfig.json"]);
    assert!(ok, "tsc --noEmit on the app's use of the package failed:\n{text}");
    let (ok, text) = run(&app, "node", &[tsc.to_str().unwrap(), "-p", "tsconfig.misuse.json"]);
    println!("tsc on the misuse file:\n{text}");
    assert!(!ok, "tsc accepted a misspelt option and wrong choice names");
    for (line, what) in [(3, "misspelt option wave_sped"), (4, "choice dukc"), (5, "preset clam"), (6, "choice schlik")]
    {
        assert!(
            text.contains(&format!("src/misuse.ts({line},")),
            "tsc did not catch the {what} (line {line}):\n{text}"
        );
    }

    let vite = tools.join("node_modules/vite/bin/vite.js");
    let (ok, text) = run(&app, "node", &[vite.to_str().unwrap(), "build", "--base", "./"]);
    assert!(ok, "vite build failed:\n{text}");
    println!("vite build:\n{text}");
    let assets: Vec<String> = std::fs::read_dir(app.join("dist/assets"))
        .expect("dist/assets")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    for ext in [".wasm", ".css", ".webp", ".js"] {
        assert!(assets.iter().any(|a| a.ends_with(ext)), "vite's build copied no {ext} file: {assets:?}");
    }

    let stats_declared = declared_properties(interface(
        &std::fs::read_to_string(package_dir().join("embed.d.ts")).expect("embed.d.ts"),
        "Stats",
    ));
    let server = StaticServer::start_with_mounts(vec![("/app/", app.join("dist"))]);
    let browser = Browser::open(Graphics::WebGpu).await;
    for backend in ["webgpu", "webgl2"] {
        browser.goto(&server.url(&format!("/app/index.html?backend={backend}"))).await;
        let took = browser.wait_ready("#pool", READY).await;
        let s = browser.js("return window.demo && window.demo.stats();").await;
        println!(
            "the Vite app on {backend}: ready in {took:?}, {}×{} px, duck at {}",
            s["width"], s["height"], s["duckPosition"]
        );
        assert_eq!(s["backend"], backend, "the Vite app's pool runs on {backend}");
        assert!(s["duckPosition"].is_array(), "the app's option objects=duck reached the demo: {s}");
        let keys: BTreeSet<String> = s.as_object().expect("stats").keys().cloned().collect();
        assert_eq!(keys, stats_declared, "embed.d.ts's Stats declares what stats() returns");
    }
    browser.close().await;
    let _ = std::fs::remove_dir_all(&app);
}

#[tokio::test(flavor = "current_thread")]
async fn the_course_zip_runs_deep_in_a_site_in_the_first_screen_and_the_package_from_two_folders() {
    let _guard = serial();
    let dir = release_dir();
    let work = std::env::temp_dir().join(format!("wavepool-release-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(work.join("course/week-3")).expect("folder");
    let zip = dir.join(format!("wavepool-{}-course.zip", version()));
    let (ok, text) = run(&work.join("course/week-3"), "python3", &["-m", "zipfile", "-e", zip.to_str().unwrap(), "."]);
    assert!(ok, "unzip: {text}");
    let readme = std::fs::read_to_string(work.join("course/week-3/wavepool/README.txt")).expect("README.txt");
    assert_eq!(readme.lines().count(), 2, "the zip's README is two lines: {readme}");

    // The package split in two: its modules in one folder, the wasm, stylesheet and picture in
    // another, which a page names with setAssetLocation().
    let (js, files) = (work.join("js"), work.join("cdn/wavepool-files"));
    std::fs::create_dir_all(&js).expect("folder");
    std::fs::create_dir_all(&files).expect("folder");
    for entry in std::fs::read_dir(package_dir()).expect("package") {
        let path = entry.expect("entry").path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            // The catalogues go with the assets (i18n.js finds them at setAssetLocation()'s).
            std::fs::create_dir_all(files.join(&name)).expect("folder");
            for inner in std::fs::read_dir(&path).expect("folder") {
                let inner = inner.expect("entry").path();
                std::fs::copy(&inner, files.join(&name).join(inner.file_name().unwrap())).expect("copy");
            }
            continue;
        }
        let to = if name.ends_with(".js") { &js } else { &files };
        std::fs::copy(&path, to.join(&name)).expect("copy");
    }
    std::fs::write(
        js.join("page.html"),
        r#"<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Assets elsewhere</title></head>
<body><div id="pool"></div><script type="module">
import { mount, setAssetLocation } from "./embed.js";
setAssetLocation("/cdn/wavepool-files/");
mount(document.getElementById("pool"), { lazy: false });
</script></body></html>"#,
    )
    .expect("page");

    let server = StaticServer::start_with_mounts(vec![
        ("/courses/physics/", work.join("course")),
        ("/js/", js),
        ("/cdn/", work.join("cdn")),
    ]);
    let browser = Browser::open(Graphics::WebGpu).await;
    browser.goto(&server.url("/courses/physics/week-3/wavepool/index.html")).await;
    let took = browser.wait_ready("#pool", READY).await;
    println!("the course zip's page under /courses/physics/week-3/wavepool/: ready in {took:?}");
    // The page's first screen holds the whole picture, from a phone to a laptop.
    for (width, height) in [(320, 568), (800, 600), (1280, 720)] {
        browser.set_viewport(width, height).await;
        let fit = browser
            .js_async(
                "await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
                 const c = document.querySelector('#pool').shadowRoot.querySelector('canvas').getBoundingClientRect();
                 return { top: c.top, bottom: c.bottom, left: c.left, right: c.right, inner: innerHeight, wide: innerWidth,
                          scroll: document.scrollingElement.scrollWidth };",
            )
            .await;
        println!("index.html at {width}×{height}: canvas {fit}");
        let num = |k: &str| fit[k].as_f64().unwrap_or_else(|| panic!("{k} in {fit}"));
        assert!(num("bottom") <= num("inner") + 0.5, "at {width}×{height} the pool runs past the first screen: {fit}");
        assert!(num("right") - num("left") >= 250.0, "at {width}×{height} the pool is small: {fit}");
        assert!(num("scroll") <= num("wide"), "at {width}×{height} the page scrolls sideways: {fit}");
    }
    browser.goto(&server.url("/js/page.html")).await;
    let took = browser.wait_ready("#pool", READY).await;
    let fetched: Vec<String> = server
        .requests()
        .into_iter()
        .filter(|r| r.contains("wavepool_bg.wasm") || r.contains("wavepool.css"))
        .collect();
    println!("the package with its files at /cdn/: ready in {took:?}; fetched {fetched:?}");
    assert!(
        fetched.iter().any(|r| r == "/cdn/wavepool-files/wavepool_bg.wasm")
            && fetched.iter().any(|r| r == "/cdn/wavepool-files/wavepool.css"),
        "the wasm and the stylesheet came from setAssetLocation's folder: {fetched:?}"
    );
    assert!(!fetched.iter().any(|r| r.starts_with("/js/")), "nothing was looked for next to the modules: {fetched:?}");
    browser.close().await;
    let _ = std::fs::remove_dir_all(&work);
}
