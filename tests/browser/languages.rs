//! The page in each language (issue 50): every control, group, button and choice shows its
//! catalogue's words (nothing falls back to English, no warning of a missing message), numbers
//! are written as the language writes them, nothing is cut off or overflows at 320 and 1280 px,
//! axe-core finds no violation, switching at run time keeps the water and the view; a
//! pseudo-language 40 % longer than English lays out too; a page whose `lang` is Czech gets
//! Czech with no option.

use std::collections::BTreeMap;

use serde_json::Value;

use crate::catalogues;
use crate::support::{axe_violations, host_packages, serial, Browser, Graphics, StaticServer, READY};

/// Records the page's console warnings in `window.__warnings`.
const WARNINGS_JS: &str = "window.__warnings = []; const warn = console.warn.bind(console);
    console.warn = (...a) => { window.__warnings.push(a.map(String).join(' ')); warn(...a); };";

/// What the controls show: each row's label (by the name its control has), the groups' names,
/// the buttons, each select's options (parameter, choice name, text), wave_speed's value, the
/// controls' lang, the page's intro and lang.
const SHOWN_JS: &str = "const root = document.querySelector('#pool').shadowRoot;
    const specs = new Map(window.demo.params().map((p) => [p.name, p]));
    const name = (id) => id.replace(/^wavepool-\\d+-/, '');
    return {
      labels: [...root.querySelectorAll('.row > label')].map((l) => [name(l.htmlFor), l.textContent]),
      legends: [...root.querySelectorAll('fieldset:not(.picked) > legend')].map((l) => l.textContent),
      buttons: [...root.querySelectorAll('.buttons button')].map((b) => b.textContent),
      options: [...root.querySelectorAll('select[name]')].flatMap((s) => [...s.options].map((o) => {
        const p = specs.get(s.name);
        return [s.name, p.choiceNames[p.choices.indexOf(Number(o.value))] || '', o.textContent, p.unit];
      })),
      speed: root.querySelector('input[name=wave_speed] + output').textContent,
      lang: root.querySelector('details.controls').closest('[lang]').lang,
      intro: document.getElementById('intro') ? document.getElementById('intro').textContent : null,
      pageLang: document.documentElement.lang,
    };";

/// What is cut off in the controls (opened): elements whose text is wider than their box, and
/// selects whose chosen option's text (measured in their font) is wider than their text area;
/// and how far the page is wider than the viewport.
const CUT_JS: &str = "const root = document.querySelector('#pool').shadowRoot;
    root.querySelector('details.controls').open = true;
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const ctx = document.createElement('canvas').getContext('2d');
    const shown = (e) => e.getClientRects().length > 0;
    const cut = [];
    for (const e of root.querySelectorAll('.controls label, .controls legend, .controls button, .controls summary, .controls select')) {
      if (!shown(e)) continue;
      let wide = e.scrollWidth > e.clientWidth + 1;
      if (e.tagName === 'SELECT' && e.selectedOptions[0]) {
        const s = getComputedStyle(e);
        ctx.font = s.font;
        // The text area: the box less its padding and the arrow (about 20 px).
        const room = e.clientWidth - parseFloat(s.paddingLeft) - parseFloat(s.paddingRight) - 20;
        wide = ctx.measureText(e.selectedOptions[0].textContent).width > room + 1;
      }
      if (wide) cut.push(`${e.tagName.toLowerCase()} ${e.name || e.htmlFor || ''}: ${e.textContent.slice(0, 40)}`);
    }
    return { cut, overflow: document.documentElement.scrollWidth - innerWidth };";

/// A pseudo-language of English (PhET's long-string test): each text with accented letters and
/// words added to make it 40 % longer; ids and `{ $variables }` kept.
fn pseudo_catalogue(english: &str) -> String {
    let accent = |c: char| match c {
        'a' => 'á',
        'e' => 'é',
        'i' => 'í',
        'o' => 'ö',
        'u' => 'ü',
        'c' => 'ç',
        'n' => 'ñ',
        'A' => 'Å',
        'E' => 'É',
        'O' => 'Ø',
        _ => c,
    };
    let mut out = String::new();
    for line in english.lines() {
        let Some((head, text)) = line.split_once(" = ").filter(|_| !line.starts_with('#')) else {
            out += line;
            out.push('\n');
            continue;
        };
        let mut long = String::new();
        let mut depth = 0;
        for c in text.chars() {
            depth += (c == '{') as i32 - (c == '}') as i32;
            long.push(if depth == 0 { accent(c) } else { c });
        }
        let length = text.chars().count();
        while long.chars().count() < length * 14 / 10 {
            long += " ẋẋẋ";
        }
        out += &format!("{head} = {long}\n");
    }
    out
}

/// Checks what the controls show against `texts` (the catalogue of `tag`); returns what differs.
fn differences(tag: &str, shown: &Value, texts: &BTreeMap<String, String>) -> Vec<String> {
    let mut wrong = Vec::new();
    let text = |id: &str| texts.get(id).cloned().unwrap_or_else(|| format!("<no {id}>"));
    for pair in shown["labels"].as_array().unwrap() {
        let (name, label) = (pair[0].as_str().unwrap(), pair[1].as_str().unwrap());
        let id = match name {
            "language" | "preset" => name.to_owned(),
            _ => format!("param-{name}"),
        };
        if label != text(&id) {
            wrong.push(format!("{tag} label {name}: {label:?}, the catalogue {:?}", text(&id)));
        }
    }
    let groups: Vec<&String> = texts.iter().filter(|(id, _)| id.starts_with("group-")).map(|(_, t)| t).collect();
    for legend in shown["legends"].as_array().unwrap() {
        if !groups.iter().any(|g| *g == legend) {
            wrong.push(format!("{tag} group {legend} is not one of the catalogue's"));
        }
    }
    let buttons: Vec<String> = ["reset", "defaults", "share-link", "embed-code"].iter().map(|id| text(id)).collect();
    for b in shown["buttons"].as_array().unwrap() {
        if !buttons.iter().any(|t| t == b) {
            wrong.push(format!("{tag} button {b} is not one of the catalogue's"));
        }
    }
    for o in shown["options"].as_array().unwrap() {
        let (param, choice, shown) = (o[0].as_str().unwrap(), o[1].as_str().unwrap(), o[2].as_str().unwrap());
        if let Some(id) = wavepool::param_spec::unit_message_id(o[3].as_str().unwrap()) {
            if choice.is_empty() && !shown.ends_with(&text(&id)) {
                wrong.push(format!("{tag} choice {param}: {shown:?} without the unit's word {:?}", text(&id)));
            }
        }
        if choice.is_empty() || !choice.chars().all(|c| c.is_ascii_lowercase() || c == '_' || c == ',') {
            continue; // numbers and shares ("256", "50%") are not words
        }
        let expected: Vec<String> = choice.split(',').map(|c| text(&format!("param-{param}-{c}"))).collect();
        if shown != expected.join(", ") {
            wrong.push(format!("{tag} choice {param}={choice}: {shown:?}, the catalogue {:?}", expected.join(", ")));
        }
    }
    wrong
}

#[tokio::test]
async fn every_language_shows_its_catalogues_words_fits_at_320_and_1280_px_and_passes_axe() {
    let _g = serial();
    let server = StaticServer::start_with_mounts(vec![("/hosts/", host_packages())]);
    let browser = Browser::open(Graphics::WebGl2Only).await;
    browser.add_init_script(WARNINGS_JS).await;
    browser.set_viewport(1280, 900).await;
    browser.goto(&server.url("/index.html?backend=webgl2&quality=0.5&lang=cs")).await;
    browser.wait_ready("#pool", READY).await;
    browser.js("window.demo.set('damping', 1.25);").await;
    let before = browser.js("return { camera: window.demo.camera(), frames: window.demo.stats().framesDrawn };").await;
    let mut problems = Vec::new();
    for tag in ["cs", "de", "es", "ru", "sr-Latn", "sr-Cyrl", "en"] {
        if tag != "cs" {
            browser.js_async(&format!("await window.demo.setLanguage('{tag}');")).await;
        }
        let shown = browser.js(SHOWN_JS).await;
        let texts = catalogues::texts_of(tag);
        let wrong = differences(tag, &shown, &texts);
        let speed = shown["speed"].as_str().unwrap().to_owned();
        let decimal = if tag == "en" { "0.6" } else { "0,6" };
        println!(
            "{tag}: {} labels, {} groups, {} options; wave speed {speed:?}; {} differ from the catalogue",
            shown["labels"].as_array().unwrap().len(),
            shown["legends"].as_array().unwrap().len(),
            shown["options"].as_array().unwrap().len(),
            wrong.len()
        );
        problems.extend(wrong);
        if !speed.contains(decimal) {
            problems.push(format!("{tag}: wave speed shown as {speed:?}, not with {decimal:?}"));
        }
        if shown["lang"] != tag || shown["pageLang"] != tag || shown["intro"] != texts["page-intro"].as_str() {
            problems.push(format!(
                "{tag}: lang {} / page lang {} / intro {}",
                shown["lang"], shown["pageLang"], shown["intro"]
            ));
        }
        for (width, height) in [(1280, 900), (320, 640)] {
            browser.set_viewport(width, height).await;
            let cut = browser.js_async(CUT_JS).await;
            if std::env::var_os("WAVEPOOL_DUMP_FRAMES").is_some() {
                browser.screenshot().await.dump(&format!("language-{tag}-{width}"));
            }
            println!("  at {width} px: cut off {}, overflow {} px", cut["cut"], cut["overflow"]);
            if !cut["cut"].as_array().unwrap().is_empty() || cut["overflow"].as_f64().unwrap() > 0.0 {
                problems.push(format!("{tag} at {width} px: cut off {}, overflow {}", cut["cut"], cut["overflow"]));
            }
        }
        browser.set_viewport(1280, 900).await;
        let violations = axe_violations(&browser).await;
        if !violations.is_empty() {
            problems.push(format!("{tag}: axe-core {violations:?}"));
        }
    }
    // The pseudo-language, at a phone's width.
    let english = std::fs::read_to_string(catalogues::dir().join("en.ftl")).expect("en.ftl");
    let pseudo = pseudo_catalogue(&english);
    browser
        .js_async(&format!("await window.demo.setLanguage('en-XA', {});", serde_json::to_string(&pseudo).unwrap()))
        .await;
    let shown = browser.js(SHOWN_JS).await;
    problems.extend(differences("en-XA", &shown, &catalogues::texts("en-XA", &pseudo)));
    for (width, height) in [(320, 640), (1280, 900)] {
        browser.set_viewport(width, height).await;
        let cut = browser.js_async(CUT_JS).await;
        println!("en-XA (+40 %) at {width} px: cut off {}, overflow {} px", cut["cut"], cut["overflow"]);
        if !cut["cut"].as_array().unwrap().is_empty() || cut["overflow"].as_f64().unwrap() > 0.0 {
            problems.push(format!("en-XA at {width} px: cut off {}, overflow {}", cut["cut"], cut["overflow"]));
        }
    }
    // Eight languages later: the same view and parameters, the water still running.
    let after = browser.js("return { camera: window.demo.camera(), frames: window.demo.stats().framesDrawn, damping: window.demo.get('damping') };").await;
    println!("before the switches {before}, after {after}");
    assert_eq!(after["camera"], before["camera"], "switching languages moved the camera");
    assert_eq!(after["damping"], 1.25, "switching languages changed a parameter");
    assert!(after["frames"].as_u64() > before["frames"].as_u64(), "the water stopped while the language changed");
    let warnings = browser.js("return window.__warnings;").await;
    println!("console warnings: {warnings}");
    let missing: Vec<&Value> =
        warnings.as_array().unwrap().iter().filter(|w| w.as_str().unwrap().contains("message")).collect();
    assert!(missing.is_empty(), "warnings of missing messages: {missing:?}");
    assert!(problems.is_empty(), "{} problems:\n{}", problems.len(), problems.join("\n"));

    // A Czech course page with a <wave-pool> and no option: Czech, and its share link says nothing of the language.
    browser.goto(&server.url("/test/lang.html")).await;
    browser.wait_ready("#pool", READY).await;
    let page = browser
        .js("const d = document.querySelector('#pool').demo;
             const label = document.querySelector('#pool').shadowRoot.querySelector('label[for$=\"-wave_speed\"]').textContent;
             return { lang: d.language(), label, link: d.shareLink() };")
        .await;
    println!("a page in Czech: {page}");
    assert_eq!(page["lang"], "cs");
    assert_eq!(page["label"].as_str(), catalogues::texts_of("cs").get("param-wave_speed").map(String::as_str));
    assert!(!page["link"].as_str().unwrap().contains("lang="), "the link names the page's own language");
    browser.close().await;
}
