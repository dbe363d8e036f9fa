//! The `wavepool` binary as a user runs it: usage errors exit 2 without a panic, a missing
//! adapter exits 1 with a clear message, `render` writes a real PNG, `bench` prints JSON.

use std::process::{Command, Output};

fn wavepool(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_wavepool"))
        .args(args)
        .env("XDG_RUNTIME_DIR", "/tmp")
        .output()
        .expect("run wavepool")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn bad_arguments_give_usage_and_exit_2() {
    let cases: &[(&[&str], &str)] = &[
        (&["--screenshot", "x.png"], "required arguments were not provided"),
        (&["--out", "x.png"], "not --out"),
        (&["fly"], "unrecognized subcommand"),
        (&["render", "--width", "abc", "--out", "x.png"], "not a number"),
        (&["render", "--frames", "0", "--out", "x.png"], "outside"),
        (&["render", "--width"], "a value is required"),
        (&["render", "--bogus", "1"], "unexpected argument"),
        (&["render", "--set", "gravity_well=1", "--out", "x.png"], "unknown parameter"),
        (&["render", "--set", "wave_speed=99", "--out", "x.png"], "outside"),
        (&["bench", "--sim-size", "300"], "is not one of 128, 256, 512, 1024"),
        (&["render", "--set", "render_mode=curved", "--out", "x.png"], "one of raytraced, flat, split"),
        (&["render", "--preset", "stormy", "--out", "x.png"], "is not one of classic"),
        // Ranges come from the tables: the sim_size parameter's choices, the creation options.
        (&["bench", "--sim-size", "2048"], "is not one of 128, 256, 512, 1024"),
        (&["bench", "--surface-grid", "2000"], "outside 16..=512"),
        (&["bench", "--caustics-size", "64"], "outside 128..=2048"),
    ];
    for (args, expected) in cases {
        let out = wavepool(args);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?} exited {:?}: {err}", out.status);
        assert!(err.contains(expected), "{args:?}: expected '{expected}' in: {err}");
        assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    }
}

#[test]
fn help_lists_every_parameter_and_preset_and_exits_0() {
    for args in [&["--help"][..], &["render", "--help"], &["bench", "--help"]] {
        let out = wavepool(args);
        let text = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", stderr(&out));
        for name in ["wave_speed", "sun_elevation", "render_mode", "flat_soft_edge", "classic", "evening"] {
            assert!(text.contains(name), "{args:?}: no '{name}' in the help:\n{text}");
        }
    }
}

#[test]
fn the_parameter_reference_in_docs_is_what_the_table_says_now() {
    let out = wavepool(&["parameters"]);
    assert!(out.status.success(), "wavepool parameters failed: {}", stderr(&out));
    let now = String::from_utf8(out.stdout).expect("UTF-8");
    for p in wavepool::params::table() {
        assert!(now.contains(&format!("| `{}` |", p.name)), "the reference lacks {}", p.name);
    }
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/parameters.md");
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    println!("docs/parameters.md: {} lines, {} parameters", now.lines().count(), wavepool::params::table().len());
    assert!(
        written == now,
        "docs/parameters.md is stale: write it again with `cargo run -- parameters > docs/parameters.md`"
    );
}

#[test]
fn no_adapter_is_a_clear_error_with_exit_1() {
    // Metal does not exist on Linux: the instance finds no adapter at all.
    let out = Command::new(env!("CARGO_BIN_EXE_wavepool"))
        .args(["render", "--out", "never.png"])
        .env("WGPU_BACKEND", "metal")
        .output()
        .expect("run wavepool");
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("no GPU adapter found") && err.contains("mesa-vulkan-drivers"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn render_writes_a_png_of_the_scene() {
    let dir = std::env::temp_dir().join(format!("wavepool-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("frame.png");
    let out = wavepool(&[
        "render",
        "--out",
        path.to_str().unwrap(),
        "--width",
        "160",
        "--height",
        "120",
        "--frames",
        "3",
        "--drops",
        "4",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let (w, h, rgba) = wavepool::headless::read_png(&path).expect("a readable PNG");
    assert_eq!((w, h), (160, 120));
    let distinct: std::collections::HashSet<&[u8]> = rgba.chunks(4).collect();
    assert!(distinct.len() > 200, "only {} distinct colours: not a rendered scene", distinct.len());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bench_prints_one_json_object() {
    let out = wavepool(&["bench", "--width", "160", "--height", "120", "--frames", "4"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8(out.stdout).unwrap();
    let json: serde_json::Value = serde_json::from_str(text.trim()).unwrap_or_else(|e| panic!("{e}: {text}"));
    assert!(json["adapter"].as_str().is_some_and(|s| !s.is_empty()), "{json}");
    assert!(json["backend"].is_string());
    for key in ["median", "p95"] {
        let v = json["frame_ms"][key].as_f64().unwrap_or_else(|| panic!("frame_ms.{key} missing: {json}"));
        assert!(v > 0.0, "{json}");
    }
    for key in ["simulation", "waves", "caustics", "shading"] {
        let v = json["stage_ms"][key].as_f64().unwrap_or_else(|| panic!("stage_ms.{key} missing: {json}"));
        assert!(v >= 0.0, "{json}");
    }
    assert!(json["stage_timing"].is_string());
}

#[test]
fn a_choice_is_set_by_its_name_as_by_its_number_and_a_preset_is_a_starting_point() {
    let dir = std::env::temp_dir().join(format!("wavepool-cli-names-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let frame = |name: &str, extra: &[&str]| {
        let path = dir.join(name);
        let mut args =
            vec!["render", "--out", path.to_str().unwrap(), "--width", "96", "--height", "72", "--frames", "2"];
        args.extend_from_slice(extra);
        let out = wavepool(&args);
        assert!(out.status.success(), "{extra:?}: {}", stderr(&out));
        wavepool::headless::read_png(&path).expect("a readable PNG").2
    };
    let by_name = frame("name.png", &["--set", "render_mode=split", "--set", "caustics=off"]);
    let by_number = frame("number.png", &["--set", "render_mode=2", "--set", "caustics=0"]);
    let traced = frame("traced.png", &["--set", "caustics=0"]);
    // The `flat` preset is the split view; a --set after it wins.
    let preset = frame("preset.png", &["--preset", "flat"]);
    let preset_traced = frame("preset-traced.png", &["--preset", "flat", "--set", "render_mode=raytraced"]);
    let differ = |a: &[u8], b: &[u8]| a.iter().zip(b).filter(|(x, y)| x != y).count() as f64 / a.len() as f64;
    println!(
        "split by name vs by number: {:.4} % of bytes differ; split vs ray-traced {:.1} %; preset flat vs the same \
         with render_mode=raytraced {:.1} %",
        differ(&by_name, &by_number) * 100.0,
        differ(&by_name, &traced) * 100.0,
        differ(&preset, &preset_traced) * 100.0
    );
    assert_eq!(by_name, by_number, "a name sets another value than its number");
    assert!(differ(&by_name, &traced) > 0.01, "render_mode=split changed nothing");
    assert!(differ(&preset, &preset_traced) > 0.01, "--set after --preset did not win");
    std::fs::remove_dir_all(&dir).ok();
}

#[path = "support/catalogues.rs"]
mod catalogues;

#[test]
fn a_language_without_a_catalogue_is_a_usage_error_naming_those_there_are() {
    let out = wavepool(&["--lang", "xx", "--frames", "1"]);
    let err = stderr(&out);
    println!("{err}");
    assert_eq!(out.status.code(), Some(2), "exit status for --lang xx: {:?}", out.status);
    assert!(err.contains("cs") && err.contains("sr-Cyrl"), "the message does not name the languages: {err}");
}

#[test]
fn the_english_catalogue_is_what_the_tables_say_now() {
    let out = wavepool(&["messages"]);
    assert!(out.status.success(), "wavepool messages failed: {}", stderr(&out));
    let now = String::from_utf8(out.stdout).expect("UTF-8");
    let english = catalogues::read("en.ftl", &now);
    // Every parameter's label and help, every choice's words and every preset have a message.
    let mut wanted: Vec<String> = Vec::new();
    for p in wavepool::params::table() {
        wanted.extend([p.message_id(), format!("{}.help", p.message_id())]);
        wanted.extend(p.choice_message_ids().into_iter().map(|(_, id)| id));
        wanted.push(wavepool::param_spec::group_message_id(p.group));
        wanted.extend(wavepool::param_spec::unit_message_id(p.unit));
    }
    wanted.extend(wavepool::presets::PRESETS.iter().map(|p| format!("preset-{}", p.name)));
    wanted.extend(wavepool::page_words::PAGE_WORDS.iter().map(|(id, _)| (*id).to_owned()));
    let missing: Vec<&String> = wanted.iter().filter(|id| !english.contains_key(*id)).collect();
    println!("en.ftl: {} messages and attributes, {} bytes", english.len(), now.len());
    assert!(missing.is_empty(), "the English catalogue lacks {missing:?}");
    let written = std::fs::read_to_string(catalogues::dir().join("en.ftl")).unwrap_or_default();
    assert!(written == now, "locales/en.ftl is stale: write it again with `cargo run -- messages > locales/en.ftl`");
}

/// The English words web/i18n.js holds for the time before the core (which holds English's) has
/// loaded are `page_words.rs`'s.
#[test]
fn the_words_the_page_shows_before_the_core_loads_are_the_english_catalogues() {
    let i18n = std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("web/i18n.js"))
        .expect("web/i18n.js");
    let block = i18n
        .split("const BEFORE_CORE = Object.freeze({")
        .nth(1)
        .and_then(|b| b.split("});").next())
        .expect("BEFORE_CORE");
    let mut count = 0;
    for line in block.lines().filter(|l| l.contains(": ")) {
        let (id, text) = line.trim().trim_end_matches(',').split_once(": ").expect("id: text");
        let (id, text) = (id.trim_matches('"'), text.trim_matches('"'));
        assert_eq!(wavepool::page_words::english(id), Some(text), "web/i18n.js's {id}");
        count += 1;
    }
    println!("{count} words before the core");
    assert!(count >= 2, "BEFORE_CORE read {count} entries");
}

#[test]
fn every_catalogue_has_every_english_message_with_the_same_variables() {
    let read = |name: &str| {
        let text = std::fs::read_to_string(catalogues::dir().join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        (text.len(), catalogues::read(name, &text))
    };
    let (_, english) = read("en.ftl");
    let mut problems = Vec::new();
    for tag in ["cs", "de", "es", "ru", "sr-Latn", "sr-Cyrl"] {
        let name = format!("{tag}.ftl");
        let (bytes, messages) = read(&name);
        let missing: Vec<&String> = english.keys().filter(|id| !messages.contains_key(*id)).collect();
        let extra: Vec<&String> = messages.keys().filter(|id| !english.contains_key(*id)).collect();
        let changed: Vec<&String> =
            english.iter().filter(|(id, v)| messages.get(*id).is_some_and(|w| w != *v)).map(|(id, _)| id).collect();
        println!(
            "{name}: {} messages, {bytes} bytes; missing {missing:?}, extra {extra:?}, other variables {changed:?}",
            messages.len()
        );
        if !(missing.is_empty() && extra.is_empty() && changed.is_empty()) {
            problems.push(name);
        }
    }
    assert!(problems.is_empty(), "catalogues that differ from English's messages: {problems:?}");
}

/// Serbian's two scripts hold one translation: the Latin catalogue is the Cyrillic one with
/// each letter written in Latin (ids, variables and Latin words are already Latin).
#[test]
fn serbian_in_latin_is_the_cyrillic_catalogue_transliterated() {
    let cyrillic = std::fs::read_to_string(catalogues::dir().join("sr-Cyrl.ftl")).expect("sr-Cyrl.ftl");
    let latin = std::fs::read_to_string(catalogues::dir().join("sr-Latn.ftl")).expect("sr-Latn.ftl");
    let out = wavepool(&["messages", "--serbian-latin", "locales/sr-Cyrl.ftl"]);
    assert!(out.status.success(), "wavepool messages --serbian-latin failed: {}", stderr(&out));
    let written = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(written.lines().count() == cyrillic.lines().count(), "the transliteration has other lines");
    let differing = written.lines().zip(latin.lines()).filter(|(a, b)| a != b).count();
    println!("sr-Latn.ftl: {} lines, {differing} differ from sr-Cyrl.ftl transliterated", latin.lines().count());
    assert!(
        written == latin,
        "sr-Latn.ftl is not sr-Cyrl.ftl transliterated ({differing} lines differ): write it with \
         `cargo run -- messages --serbian-latin locales/sr-Cyrl.ftl > locales/sr-Latn.ftl`"
    );
}
