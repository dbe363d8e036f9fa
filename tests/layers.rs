//! The crate's layers (read from docs/ARCHITECTURE.md, "Layers"): every `crate::` path in `src/` outside
//! test code may only name a module of its own layer or one below, and no modules may import
//! each other round in a cycle. There is no list of exceptions. Reads the sources as text: no build of the modules involved.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The layer table, bottom to top, as docs/ARCHITECTURE.md's "Layers" section writes it (the one
/// place it is kept): each row a layer's name and its modules in backticks. A module may use
/// modules of its own layer (without a cycle) and below.
fn layers() -> &'static [(String, Vec<String>)] {
    static LAYERS: std::sync::OnceLock<Vec<(String, Vec<String>)>> = std::sync::OnceLock::new();
    LAYERS.get_or_init(|| {
        let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/ARCHITECTURE.md"))
            .expect("docs/ARCHITECTURE.md");
        let section = doc.split("\n## Layers\n").nth(1).expect("a Layers section").split("\n## ").next().unwrap();
        let rows: Vec<(String, Vec<String>)> = section
            .lines()
            .filter(|l| l.starts_with("| ") && !l.starts_with("| layer") && !l.starts_with("|---"))
            .map(|l| {
                let cells: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
                let modules = cells[1].split('`').skip(1).step_by(2).map(str::to_owned).collect();
                (cells[0].to_owned(), modules)
            })
            .collect();
        assert!(rows.len() >= 5 && rows.iter().all(|(_, m)| !m.is_empty()), "the Layers table: {rows:?}");
        rows
    })
}

fn layer_of(module: &str) -> Option<usize> {
    layers().iter().position(|(_, modules)| modules.iter().any(|m| m == module))
}

/// Source text with comments, string and char literals blanked (line breaks kept, so line
/// numbers stay true), and every item under `#[cfg(test)]` removed.
fn code_only(source: &str) -> String {
    let chars: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    let blank = |c: char| if c == '\n' { '\n' } else { ' ' };
    while i < chars.len() {
        if chars[i] == '/' && peek(&chars, i + 1) == '/' {
            while i < chars.len() && chars[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if chars[i] == '/' && peek(&chars, i + 1) == '*' {
            while i < chars.len() && !(chars[i] == '*' && peek(&chars, i + 1) == '/') {
                out.push(blank(chars[i]));
                i += 1;
            }
            out.push_str("  ");
            i += 2;
        } else if chars[i] == 'r'
            && (peek(&chars, i + 1) == '#' || peek(&chars, i + 1) == '"')
            && !ident_char(chars.get(i.wrapping_sub(1)))
        {
            let hashes = (1..).take_while(|&n| peek(&chars, i + n) == '#').count();
            if peek(&chars, i + hashes + 1) != '"' {
                out.push(chars[i]);
                i += 1;
                continue;
            }
            i += hashes + 2;
            let closes =
                |at: usize| chars.get(at) == Some(&'"') && (1..=hashes).all(|n| chars.get(at + n) == Some(&'#'));
            while i < chars.len() && !closes(i) {
                out.push(blank(chars[i]));
                i += 1;
            }
            i += hashes + 1;
            out.push_str("\"\"");
        } else if chars[i] == '"' {
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                if chars[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                out.push(blank(chars[i]));
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
        } else if chars[i] == '\''
            && (peek(&chars, i + 2) == '\''
                || (peek(&chars, i + 1) == '\\' && chars[i + 2..].iter().take(10).any(|&c| c == '\'')))
        {
            // A char literal ('x', '\n', '\u{..}'), not a lifetime.
            let end = i + 1 + chars[i + 1..].iter().skip(1).position(|&c| c == '\'').unwrap() + 1;
            out.push_str("' '");
            i = end + 1;
        } else {
            out.push(chars[i]);
            i += 1;
        }
    }
    drop_test_items(&out)
}

fn peek(chars: &[char], at: usize) -> char {
    chars.get(at).copied().unwrap_or('\0')
}

fn ident_char(c: Option<&char>) -> bool {
    c.is_some_and(|c| c.is_alphanumeric() || *c == '_')
}

/// Blanks each item following `#[cfg(test)]`: up to its `;`, or its `{ … }` block.
fn drop_test_items(code: &str) -> String {
    let mut out: Vec<char> = code.chars().collect();
    let marker: Vec<char> = "#[cfg(test)]".chars().collect();
    let mut i = 0;
    while i + marker.len() <= out.len() {
        if out[i..i + marker.len()] != marker[..] {
            i += 1;
            continue;
        }
        let mut j = i;
        let mut depth = 0;
        while j < out.len() {
            match out[j] {
                '{' => depth += 1,
                '}' => depth -= 1,
                ';' if depth == 0 => break,
                _ => {}
            }
            if out[j] == '}' && depth == 0 {
                break;
            }
            j += 1;
        }
        let last = j.min(out.len() - 1);
        for c in &mut out[i..=last] {
            if *c != '\n' {
                *c = ' ';
            }
        }
        i = j;
    }
    out.into_iter().collect()
}

/// The first-level module names a `crate::` path (or group) names, with the byte offset of each
/// (a macro at the crate's root, `crate::name!`, names none).
fn imported_modules(code: &str) -> Vec<(usize, String)> {
    names_after(code, "crate::")
}

/// The names a path starting with `prefix` (`crate::`, `super::`, `crate::render::`) names
/// first, with the byte offset of each; groups `{a::X, b}` give each of theirs.
fn names_after(code: &str, prefix: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (at, _) in code.match_indices(prefix) {
        if prefix == "super::" && code[..at].ends_with("super::") {
            continue; // `super::super::`: above the folder
        }
        let rest = &code[at + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // Names at the group's first level: `crate::{a::X, b::{Y, Z}, c}` gives a, b, c.
            let mut depth = 0;
            let end = group
                .char_indices()
                .find(|&(_, c)| {
                    depth += (c == '{') as i32 - (c == '}') as i32;
                    depth < 0
                })
                .map_or(group.len(), |(i, _)| i);
            let mut depth = 0;
            for segment in group[..end].split(|c| {
                depth += (c == '{') as i32 - (c == '}') as i32;
                c == ',' && depth == 0
            }) {
                found.push((at, leading_name(segment.trim_start())));
            }
        } else {
            let name = leading_name(rest);
            // `crate::wgsl!(..)`: a macro exported at the crate's root (lib.rs), not a module.
            if !rest[name.len()..].starts_with('!') {
                found.push((at, name));
            }
        }
    }
    found.retain(|(_, name)| !name.is_empty() && name != "self");
    found
}

fn leading_name(text: &str) -> String {
    text.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect()
}

fn sources(dir: &Path, into: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, into);
        } else if path.extension().is_some_and(|e| e == "rs") {
            into.push(path);
        }
    }
}

/// One import of a module by another: (from, to) → first place it happens ("src/x.rs:12").
fn module_imports() -> BTreeMap<(String, String), String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    let mut imports = BTreeMap::new();
    for file in files {
        let relative = file.strip_prefix(&src).unwrap();
        let from = relative.iter().next().unwrap().to_string_lossy().trim_end_matches(".rs").to_string();
        if from == "lib" {
            continue;
        }
        let code = code_only(&std::fs::read_to_string(&file).unwrap());
        for (at, to) in imported_modules(&code) {
            if to != from {
                let line = code[..at].matches('\n').count() + 1;
                let place = format!("src/{}:{line}", relative.display());
                imports.entry((from.clone(), to)).or_insert(place);
            }
        }
    }
    imports
}

#[test]
fn every_import_runs_down_the_layer_table_and_no_modules_import_each_other() {
    let imports = module_imports();
    let mut problems = Vec::new();
    for ((from, to), place) in &imports {
        match (layer_of(from), layer_of(to)) {
            (None, _) => problems.push(format!("{place}: module `{from}` is in no layer of the table")),
            (_, None) => problems.push(format!("{place}: `{from}` imports `{to}`, which is in no layer of the table")),
            (Some(a), Some(b)) if b > a => problems.push(format!(
                "{place}: `{from}` ({}) imports `{to}` ({}), a layer above it",
                layers()[a].0,
                layers()[b].0
            )),
            _ => {}
        }
    }
    // Imports within one layer are allowed unless they close a cycle.
    let sideways: Vec<(&str, &str)> = imports
        .keys()
        .map(|(a, b)| (a.as_str(), b.as_str()))
        .filter(|(a, b)| layer_of(a).is_some() && layer_of(a) == layer_of(b))
        .collect();
    for &(from, to) in &sideways {
        let mut reached = vec![to];
        let mut i = 0;
        while i < reached.len() {
            let at = reached[i];
            for &(a, b) in &sideways {
                if a == at && !reached.contains(&b) {
                    reached.push(b);
                }
            }
            i += 1;
        }
        if reached.contains(&from) {
            problems.push(format!(
                "{}: `{from}` imports `{to}`, which leads back to `{from}`",
                imports[&(from.into(), to.into())]
            ));
        }
    }
    println!(
        "{} imports between {} modules checked",
        imports.len(),
        layers().iter().map(|(_, m)| m.len()).sum::<usize>()
    );
    assert!(problems.is_empty(), "layering problems:\n{}", problems.join("\n"));
}

/// The items a folder's root (`mod.rs`, or `render.rs` beside the folder) re-exports from its
/// files (`pub use view::{View, Optics};`): item name → the file it comes from.
fn root_reexports(root: &Path, files: &[String]) -> BTreeMap<String, String> {
    let code = code_only(&std::fs::read_to_string(root).unwrap_or_default());
    let mut found = BTreeMap::new();
    for statement in code.split(';') {
        let Some(at) = statement.find("use ") else { continue };
        if !statement[..at].trim_start().starts_with("pub") {
            continue;
        }
        let path = statement[at + "use ".len()..].trim();
        let Some((file, items)) = path.split_once("::") else { continue };
        if !files.iter().any(|f| f == file) {
            continue;
        }
        for item in items.split(|c: char| !(c.is_alphanumeric() || c == '_')).filter(|i| !i.is_empty() && *i != "self")
        {
            found.insert(item.to_owned(), file.to_owned());
        }
    }
    found
}

/// Imports between the files of one folder (`src/render/flat.rs` naming `super::shaders`,
/// `crate::render::shaders`, or an item the root re-exports from a file, `super::View`):
/// (folder, from, to) → first place. The folder's root is its facade, which its files may use
/// and which names them all: it is left out itself.
fn file_imports() -> BTreeMap<(String, String, String), String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    let mut imports = BTreeMap::new();
    for file in &files {
        let relative = file.strip_prefix(&src).unwrap();
        let parts: Vec<String> =
            relative.iter().map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string()).collect();
        if parts.len() != 2 || parts[1] == "mod" {
            continue;
        }
        let (folder, from) = (&parts[0], &parts[1]);
        let siblings: Vec<String> = files
            .iter()
            .filter(|f| f.parent() == file.parent() && f.file_stem().is_some_and(|s| s != "mod"))
            .map(|f| f.file_stem().unwrap().to_string_lossy().into_owned())
            .collect();
        let folder_dir = file.parent().unwrap();
        let root = if folder_dir.join("mod.rs").is_file() {
            folder_dir.join("mod.rs")
        } else {
            src.join(format!("{folder}.rs"))
        };
        let reexported = root_reexports(&root, &siblings);
        let code = code_only(&std::fs::read_to_string(file).unwrap());
        let named = names_after(&code, "super::").into_iter().chain(names_after(&code, &format!("crate::{folder}::")));
        for (at, name) in named {
            let to = if siblings.contains(&name) { Some(name) } else { reexported.get(&name).cloned() };
            let Some(to) = to else { continue };
            if &to != from {
                let line = code[..at].matches('\n').count() + 1;
                imports
                    .entry((folder.clone(), from.clone(), to))
                    .or_insert(format!("src/{}:{line}", relative.display()));
            }
        }
    }
    imports
}

#[test]
fn no_files_of_one_folder_import_each_other_round_in_a_cycle() {
    let imports = file_imports();
    let mut problems = Vec::new();
    for ((folder, from, to), place) in &imports {
        let mut reached = vec![to.as_str()];
        let mut i = 0;
        while i < reached.len() {
            let at = reached[i];
            for (f, a, b) in imports.keys() {
                if f == folder && a == at && !reached.contains(&b.as_str()) {
                    reached.push(b);
                }
            }
            i += 1;
        }
        if reached.contains(&from.as_str()) {
            problems.push(format!("{place}: `{folder}/{from}` imports `{to}`, which leads back to `{from}`"));
        }
    }
    let folders: std::collections::BTreeSet<&String> = imports.keys().map(|(f, _, _)| f).collect();
    println!("{} imports between the files of {} folders checked", imports.len(), folders.len());
    assert!(problems.is_empty(), "circles within folders:\n{}", problems.join("\n"));
}
