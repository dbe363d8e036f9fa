//! The desktop viewer as a user starts it, under a virtual X server (Xvfb) on lavapipe:
//! `wavepool --frames N --screenshot FILE.png` opens the window, draws N frames, saves what
//! the window showed and exits 0. The picture must hold both the parameter panel (egui's
//! flat grey with text) and the pool (the colourful, varied scene to its right). The panel is in
//! Serbian Cyrillic (`--lang`).

use std::process::Command;

#[test]
fn the_viewer_window_shows_the_pool_and_the_panel() {
    let xvfb_run = which("xvfb-run")
        .expect("xvfb-run not found: the viewer test needs Debian's xvfb package (./scripts/test installs it)");
    let dir = std::env::temp_dir().join(format!("wavepool-viewer-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let shot = dir.join("viewer.png");
    let out = Command::new(xvfb_run)
        .args(["-a", "-s", "-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_wavepool"))
        // Its panel in Serbian Cyrillic: a catalogue read natively, letters egui's font must hold.
        .args(["--lang", "sr-Cyrl", "--frames", "20", "--screenshot"])
        .arg(&shot)
        .env("XDG_RUNTIME_DIR", "/tmp")
        .env("WGPU_BACKEND", "vulkan")
        .output()
        .expect("run xvfb-run");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "viewer exited {:?}: {stderr}", out.status);
    let (w, h, rgba) = wavepool::headless::read_png(&shot).expect("screenshot PNG");
    println!("screenshot {w}x{h}");
    assert!(w >= 800 && h >= 500, "window too small: {w}x{h}");
    let stats = |x0: u32, x1: u32| {
        let (mut sum, mut sum2, mut blue, mut n) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for y in 0..h {
            for x in x0..x1 {
                let i = ((y * w + x) * 4) as usize;
                let (r, g, b) = (rgba[i] as f64, rgba[i + 1] as f64, rgba[i + 2] as f64);
                let luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
                sum += luma;
                sum2 += luma * luma;
                blue += b - r;
                n += 1.0;
            }
        }
        let mean = sum / n;
        (mean, (sum2 / n - mean * mean).max(0.0).sqrt(), blue / n)
    };
    // The panel is on the left (300 points wide by default); the scene fills the rest.
    let panel = stats(10, 250);
    let scene = stats(w / 2, w - 10);
    println!(
        "panel luma mean {:.1} std {:.1} blue-red {:.1}; scene luma mean {:.1} std {:.1} blue-red {:.1}",
        panel.0, panel.1, panel.2, scene.0, scene.1, scene.2
    );
    assert!(panel.1 > 3.0, "no text or widgets in the panel (luma std {:.1})", panel.1);
    assert!(scene.1 > 10.0, "the scene looks flat (luma std {:.1})", scene.1);
    // egui's panel is neutral grey; the pool's water is blue against the deck's warm paving.
    assert!((scene.2 - panel.2).abs() > 5.0, "scene and panel look alike: {panel:?} vs {scene:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

fn which(program: &str) -> Option<std::path::PathBuf> {
    std::env::var_os("PATH")?.to_str()?.split(':').map(|d| std::path::Path::new(d).join(program)).find(|p| p.is_file())
}
