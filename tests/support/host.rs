//! The machine the browsers run on: its processes (to find and end stray browsers) and the
//! course hosts' tools `./scripts/test` installs.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A process from /proc: its id, its parent's and its command line.
#[derive(Clone, Debug)]
pub struct ProcessInfo {
    pub pid: u32,
    pub ppid: u32,
    pub args: Vec<String>,
}

impl ProcessInfo {
    /// The executable's file name (`chromium`, `chromedriver`, ...).
    pub fn program(&self) -> &str {
        self.args.first().map_or("", |a| a.rsplit('/').next().unwrap_or(a))
    }

    /// Chromium's browser process (not one of its helpers, which have a `--type=`).
    pub fn is_chromium_browser(&self) -> bool {
        self.program() == "chromium" && !self.args.iter().any(|a| a.starts_with("--type="))
    }

    /// For a Chromium started by this support code (profile
    /// `wavepool-chromium-<pid>-<port>/chromium`), the id of the test or benchmark process that
    /// started it.
    fn wavepool_owner(&self) -> Option<u32> {
        let profile = self.args.iter().find_map(|a| a.strip_prefix("--user-data-dir="))?;
        let name = Path::new(profile).parent()?.file_name()?.to_str()?;
        name.strip_prefix("wavepool-chromium-")?.split('-').next()?.parse().ok()
    }

    /// `pid command args...`, shortened, for messages.
    pub fn describe(&self) -> String {
        let line = self.args.join(" ");
        let short: String = line.chars().take(160).collect();
        format!("{} {short}{}", self.pid, if short.len() < line.len() { " ..." } else { "" })
    }
}

/// Every process visible in /proc.
pub fn processes() -> Vec<ProcessInfo> {
    let mut list = Vec::new();
    for entry in std::fs::read_dir("/proc").into_iter().flatten().flatten() {
        let Some(pid) = entry.file_name().to_str().and_then(|n| n.parse::<u32>().ok()) else { continue };
        let (Ok(cmdline), Ok(stat)) =
            (std::fs::read(entry.path().join("cmdline")), std::fs::read_to_string(entry.path().join("stat")))
        else {
            continue;
        };
        // stat: "pid (comm) state ppid ..."; comm may hold spaces and parentheses.
        let ppid = stat.rsplit_once(')').and_then(|(_, rest)| rest.split_whitespace().nth(1)?.parse().ok());
        let args =
            cmdline.split(|&b| b == 0).filter(|a| !a.is_empty()).map(|a| String::from_utf8_lossy(a).into_owned());
        list.push(ProcessInfo { pid, ppid: ppid.unwrap_or(0), args: args.collect() });
    }
    list
}

/// `root` and all its descendants, from a process list.
pub fn process_tree(list: &[ProcessInfo], root: u32) -> Vec<u32> {
    let mut tree = vec![root];
    let mut i = 0;
    while i < tree.len() {
        let parent = tree[i];
        tree.extend(list.iter().filter(|p| p.ppid == parent && p.pid != parent).map(|p| p.pid));
        i += 1;
    }
    tree
}

/// What `end_stray_browsers` found.
pub struct StrayBrowsers {
    /// Leftovers it ended (described).
    pub ended: Vec<String>,
    /// Chromium or chromedriver processes it left running because they are not leftovers:
    /// someone's test or browser that is still running (described).
    pub others: Vec<String>,
}

/// Ends the Chromium processes left over by earlier tests or benchmarks, by process id: a
/// Chromium whose profile (`wavepool-chromium-<pid>-<port>/chromium`) names a process that has ended,
/// with all its helpers, and its chromedriver when that was orphaned too. One such leftover
/// (its GPU process still working through queued frames) makes every figure of a benchmark
/// several times worse. Other Chromium or chromedriver processes are not touched, only listed
/// in `others`: they belong to something still running (a test, another session).
pub fn end_stray_browsers() -> StrayBrowsers {
    let list = processes();
    let alive = |pid: u32| Path::new(&format!("/proc/{pid}")).exists();
    let mut doomed: Vec<u32> = Vec::new();
    let mut ended = Vec::new();
    for p in list.iter().filter(|p| p.is_chromium_browser()) {
        let Some(owner) = p.wavepool_owner() else { continue };
        if alive(owner) {
            continue;
        }
        ended.push(p.describe());
        doomed.extend(process_tree(&list, p.pid));
        if let Some(driver) = list.iter().find(|d| d.pid == p.ppid && d.program() == "chromedriver" && d.ppid == 1) {
            ended.push(driver.describe());
            doomed.extend(process_tree(&list, driver.pid));
        }
    }
    doomed.sort_unstable();
    doomed.dedup();
    for pid in &doomed {
        let _ = Command::new("kill").args(["-KILL", &pid.to_string()]).stderr(Stdio::null()).status();
    }
    let start = Instant::now();
    while doomed.iter().any(|&pid| alive(pid)) && start.elapsed() < Duration::from_secs(5) {
        std::thread::sleep(Duration::from_millis(50));
    }
    let others = processes()
        .iter()
        .filter(|p| !doomed.contains(&p.pid) && (p.is_chromium_browser() || p.program() == "chromedriver"))
        .map(ProcessInfo::describe)
        .collect();
    StrayBrowsers { ended, others }
}

/// Where `./scripts/test` installs the course hosts the tests put the pool in
/// (`ensure_host_tools` in scripts/lib.sh): `$XDG_CACHE_HOME/wavepool` or `~/.cache/wavepool`.
fn host_tools_dir() -> PathBuf {
    std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cache")))
        .expect("HOME or XDG_CACHE_HOME")
        .join("wavepool")
}

/// The npm packages of the host tests (reveal.js and axe-core, pinned in scripts/lib.sh).
pub fn host_packages() -> PathBuf {
    let dir = host_tools_dir().join("hosts/node_modules");
    for package in ["reveal.js/dist/reveal.js", "axe-core/axe.min.js"] {
        assert!(
            dir.join(package).is_file(),
            "{} is missing: the course-host tests need reveal.js and axe-core from npm \
             (./scripts/test installs them)",
            dir.join(package).display()
        );
    }
    dir
}

/// The `mkdocs` command of the MkDocs Material install the host tests build a site with.
pub fn mkdocs() -> PathBuf {
    let bin = host_tools_dir().join("mkdocs/bin/mkdocs");
    assert!(
        bin.is_file(),
        "{} is missing: the course-host tests build a MkDocs Material site (./scripts/test installs it)",
        bin.display()
    );
    bin
}

/// Runs axe-core (from /hosts/) over the page, shadow roots included; the violations' rule
/// ids with their node counts.
pub async fn axe_violations(browser: &super::Browser) -> Vec<(String, u64)> {
    let result = browser
        .js_async(
            "if (!window.axe) await new Promise((done, fail) => { const s = document.createElement('script');
               s.src = '/hosts/axe-core/axe.min.js'; s.onload = done; s.onerror = fail; document.head.append(s); });
             const r = await axe.run(document, { resultTypes: ['violations'] });
             return r.violations.map((v) => [v.id, v.nodes.length, v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')]);",
        )
        .await;
    let list = result.as_array().unwrap_or_else(|| panic!("axe-core did not run: {result}"));
    for v in list {
        println!("  violation {}: {} nodes ({})", v[0], v[1], v[2]);
    }
    list.iter().map(|v| (v[0].as_str().unwrap().to_owned(), v[1].as_u64().unwrap())).collect()
}
