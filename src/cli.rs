//! The `wavepool` command line: the desktop viewer's flags, and headless rendering and
//! benchmarks on any wgpu adapter (lavapipe in CI), which need no display. Flags are parsed by
//! clap; every range comes from the table it belongs to (the parameter table, the creation
//! options' specs, the camera's limits), so the command line cannot accept what the demo would
//! clamp.

// Rendering to a file and timing frames wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

mod messages;
mod reference;

use clap::{Args, CommandFactory, Parser, Subcommand};
use wavepool::camera::POOL_LIMITS;
use wavepool::demo::{DemoOptions, OptionSpec, Stage, WaterDemo, STEP_DT};
use wavepool::headless::{write_png, HeadlessGpu, OffscreenTarget, OFFSCREEN_FORMAT};
use wavepool::params::{self, ParamId, ParamSpec};
use wavepool::presets::{self, Preset};
use wavepool::sea::SEA_LIMITS;
use wavepool::tank::TANK_LIMITS;
use wavepool::timing::StageTimer;

/// wavepool: interactive water, a desktop viewer and headless tools.
///
/// With no command it opens the viewer window: the pool and a panel with every parameter.
#[derive(Parser, Debug)]
#[command(name = "wavepool", args_conflicts_with_subcommands = true, after_help = parameter_list())]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    viewer: ViewerArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Simulates N frames of 1/60 s (K seeded random drops at the start) and writes the last
    /// frame as PNG.
    #[command(after_help = parameter_list())]
    Render(RenderArgs),
    /// Renders N frames after a warm-up and prints one JSON object with the adapter, frame
    /// times and per-stage GPU times.
    #[command(after_help = parameter_list())]
    Bench(BenchArgs),
    /// Prints the reference of every parameter and preset in Markdown (docs/parameters.md).
    Parameters,
    /// Prints the English message catalogue (locales/en.ftl): the page's words and those of
    /// every parameter and preset, as Project Fluent messages.
    Messages(MessagesArgs),
}

/// `wavepool messages`'s flags.
#[derive(Args, Debug)]
struct MessagesArgs {
    /// Instead: the Serbian catalogue in Cyrillic at this path written in Latin letters
    /// (locales/sr-Latn.ftl is locales/sr-Cyrl.ftl so written).
    #[arg(long, value_name = "FILE.ftl")]
    serbian_latin: Option<std::path::PathBuf>,
}

/// The viewer's flags (no command).
#[derive(Args, Debug)]
struct ViewerArgs {
    /// Close after N frames (with --screenshot, after saving the window).
    #[arg(long, value_name = "N", value_parser = frames)]
    frames: Option<u32>,
    /// Save a PNG of the window after --frames N frames.
    #[arg(long, value_name = "FILE.png", requires = "frames")]
    screenshot: Option<PathBuf>,
    /// The panel's language: en, cs, de, es, ru, sr-Latn or sr-Cyrl ("sr" is Cyrillic).
    #[arg(long, value_name = "TAG", default_value = "en", value_parser = language)]
    lang: String,
    /// Not for the viewer: `render --out` writes a file.
    #[arg(long, hide = true)]
    out: Option<PathBuf>,
    #[command(flatten)]
    start: StartArgs,
}

/// What every command starts the demo from: creation options, a preset, parameter values.
#[derive(Args, Debug)]
struct StartArgs {
    /// Cells per side of the simulation grid (the `sim_size` parameter's choices).
    #[arg(long, value_name = "N", value_parser = sim_size)]
    sim_size: Option<u32>,
    /// Quads per side of the water surface mesh.
    #[arg(long, value_name = "N", value_parser = |s: &str| option_value(&DemoOptions::SPECS[0], s))]
    surface_grid: Option<u32>,
    /// Texels per side of the caustics map.
    #[arg(long, value_name = "N", value_parser = |s: &str| option_value(&DemoOptions::SPECS[1], s))]
    caustics_size: Option<u32>,
    /// `none` takes the path for devices without float render targets (water simulated on
    /// the CPU, 8-bit caustics map).
    #[arg(long, value_name = "auto|none", value_parser = ["auto", "none"], default_value = "auto")]
    float: String,
    /// Start from a lesson preset (listed below); the --set values come after it.
    #[arg(long, value_name = "NAME", value_parser = preset)]
    preset: Option<&'static Preset>,
    /// Any parameter of the table (listed below), by number or a choice's name, e.g.
    /// --set caustics=off --set render_mode=split.
    #[arg(long = "set", value_name = "NAME=VALUE", value_parser = parameter_value)]
    sets: Vec<(String, f32)>,
    /// What was drawn in the ripple tank with the pointer, as a share link's `sketch` writes it
    /// (walls W, erasures E, the ruler R, in whole mm from the tray's middle), e.g.
    /// W-120,40,-120,200_R-200,0,200,0.
    #[arg(long, value_name = "TEXT")]
    sketch: Option<String>,
}

/// The picture `render` and `bench` draw.
#[derive(Args, Debug)]
struct FrameArgs {
    /// Width of the image (pixels).
    #[arg(long, value_name = "W", default_value = "800", value_parser = image_side)]
    width: u32,
    /// Height of the image (pixels).
    #[arg(long, value_name = "H", default_value = "600", value_parser = image_side)]
    height: u32,
    #[command(flatten)]
    start: StartArgs,
}

#[derive(Args, Debug)]
struct RenderArgs {
    /// Where to write the PNG.
    #[arg(long, value_name = "FILE.png")]
    out: PathBuf,
    /// Frames of 1/60 s to simulate before the picture.
    #[arg(long, value_name = "N", default_value = "60", value_parser = frames)]
    frames: u32,
    /// Seeded random drops at the start.
    #[arg(long, value_name = "K", default_value = "12", value_parser = |s: &str| number(s, 0u32, 100_000))]
    drops: u32,
    /// Seed of the drops.
    #[arg(long, value_name = "S", default_value = "1", value_parser = |s: &str| number(s, 0u64, u64::MAX))]
    seed: u64,
    /// Camera yaw (degrees).
    #[arg(long, value_name = "DEG", allow_negative_numbers = true, value_parser = |s: &str| number(s, -360.0f32, 360.0))]
    yaw: Option<f32>,
    /// Camera pitch (degrees; negative looks up from under the water; the scene's own range
    /// applies: the pool's -89..89, the sea's 2..89).
    #[arg(long, value_name = "DEG", allow_negative_numbers = true, value_parser = |s: &str| number(s, POOL_LIMITS.pitch.0, POOL_LIMITS.pitch.1))]
    pitch: Option<f32>,
    /// Camera distance from its target (m; the scene's own range applies: the pool's
    /// 1.5..12, the sea's 3..600, the tank's 0.2..5).
    #[arg(long, value_name = "M", value_parser = |s: &str| number(s, TANK_LIMITS.distance.0, SEA_LIMITS.distance.1))]
    distance: Option<f32>,
    /// The point the camera orbits (m, "x,y,z"; in the sea y is the water's mean level at 0).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = point)]
    target: Option<glam::Vec3>,
    #[command(flatten)]
    frame: FrameArgs,
}

/// A point "x,y,z" (m), each within 10 km.
fn point(s: &str) -> Result<glam::Vec3, String> {
    let parts: Vec<f32> = s.split(',').map(|p| number(p.trim(), -10_000.0f32, 10_000.0)).collect::<Result<_, _>>()?;
    <[f32; 3]>::try_from(parts).map(glam::Vec3::from).map_err(|_| format!("{s}: three numbers x,y,z"))
}

#[derive(Args, Debug)]
struct BenchArgs {
    /// Frames to time after the warm-up.
    #[arg(long, value_name = "N", default_value = "120", value_parser = frames)]
    frames: u32,
    #[command(flatten)]
    frame: FrameArgs,
}

/// A number within `lo..=hi`, for clap's value parsers.
fn number<T>(text: &str, lo: T, hi: T) -> Result<T, String>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display + Copy,
{
    let v: T = text.parse().map_err(|_| format!("'{text}' is not a number"))?;
    if v < lo || v > hi {
        return Err(format!("{text} is outside {lo}..={hi}"));
    }
    Ok(v)
}

fn frames(text: &str) -> Result<u32, String> {
    number(text, 1, 1_000_000)
}

fn image_side(text: &str) -> Result<u32, String> {
    number(text, 16, 8192)
}

fn option_value(spec: &OptionSpec, text: &str) -> Result<u32, String> {
    number(text, spec.min, spec.max)
}

fn sim_size(text: &str) -> Result<u32, String> {
    let spec = params::spec(ParamId::SimSize);
    let v: f32 = text.parse().map_err(|_| format!("'{text}' is not a number"))?;
    match spec.control {
        params::Control::Choice { values, .. } if !values.contains(&v) => {
            let list: Vec<String> = values.iter().map(|v| v.to_string()).collect();
            Err(format!("{text} is not one of {}", list.join(", ")))
        }
        _ => Ok(v as u32),
    }
}

fn preset(name: &str) -> Result<&'static Preset, String> {
    presets::find(name).ok_or_else(|| {
        let names: Vec<&str> = presets::PRESETS.iter().map(|p| p.name).collect();
        format!("'{name}' is not one of {}", names.join(", "))
    })
}

/// `NAME=VALUE` of the parameter table, checked against the parameter's range or choices.
fn parameter_value(text: &str) -> Result<(String, f32), String> {
    let (name, v) = text.split_once('=').ok_or_else(|| format!("expected NAME=VALUE, got '{text}'"))?;
    let spec = params::find(name).ok_or_else(|| params::ParamError::Unknown(name.to_owned()).to_string())?;
    let value = spec.parse(v).ok_or_else(|| {
        let names = match spec.control {
            params::Control::Choice { names, .. } if !names.is_empty() => format!(" or one of {}", names.join(", ")),
            _ => String::new(),
        };
        format!("{name}: '{v}' is not a number{names}")
    })?;
    if value < spec.min() || value > spec.max() {
        return Err(format!("{name}: {v} is outside {}..={}", spec.min(), spec.max()));
    }
    Ok((name.to_owned(), value))
}

/// One parameter as the help lists it: name, range or choices, default, label.
fn describe(p: &ParamSpec) -> String {
    match p.control {
        params::Control::Toggle => format!("  {:<16} 0 or 1, default {}  {}", p.name, p.default, p.label),
        params::Control::Choice { values, names } => {
            let list: Vec<String> = values
                .iter()
                .enumerate()
                .map(|(i, v)| names.get(i).map_or(v.to_string(), |n| format!("{v}={n}")))
                .collect();
            format!("  {:<16} {} {}, default {}  {}", p.name, list.join("|"), p.unit, p.default, p.label)
        }
        params::Control::Slider { min, max, .. } => {
            format!("  {:<16} {min}..{max} {}, default {}  {}", p.name, p.unit, p.default, p.label)
        }
    }
}

/// The help's tail: every parameter of the table and every preset.
fn parameter_list() -> String {
    let names: Vec<String> = params::table().iter().map(|p| describe(p)).collect();
    let presets: Vec<String> = presets::PRESETS.iter().map(|p| format!("  {:<16} {}", p.name, p.label)).collect();
    format!("Parameters (--set NAME=VALUE):\n{}\n\nPresets (--preset NAME):\n{}", names.join("\n"), presets.join("\n"))
}

impl StartArgs {
    fn demo_options(&self) -> DemoOptions {
        let defaults = DemoOptions::default();
        DemoOptions {
            sim_size: self.sim_size.unwrap_or(defaults.sim_size),
            surface_grid: self.surface_grid.unwrap_or(defaults.surface_grid),
            caustics_size: self.caustics_size.unwrap_or(defaults.caustics_size),
            float_targets: self.float == "auto",
        }
    }

    fn make_demo(&self, gpu: &HeadlessGpu) -> WaterDemo {
        let mut demo = WaterDemo::new(&gpu.device, &gpu.queue, OFFSCREEN_FORMAT, self.demo_options());
        if let Some(preset) = self.preset {
            demo.apply_preset(preset);
        }
        for (name, v) in &self.sets {
            demo.params.set_by_name(name, *v).expect("names checked while parsing");
        }
        // The bodies start where these values put them (a sphere without gravity under the water).
        demo.reset(&gpu.queue);
        if let Some(Err(why)) = self.sketch.as_deref().map(|text| demo.set_sketch(text)) {
            eprintln!("wavepool: --sketch ignored: {why}");
        }
        demo
    }
}

fn render(o: &RenderArgs) -> Result<(), String> {
    let gpu = HeadlessGpu::new()?;
    let mut demo = o.frame.start.make_demo(&gpu);
    demo.sync_scene();
    if let Some(y) = o.yaw {
        demo.camera_mut().yaw = y;
    }
    if let Some(p) = o.pitch {
        demo.camera_mut().pitch = p;
    }
    if let Some(d) = o.distance {
        demo.camera_mut().distance = d;
    }
    if let Some(target) = o.target {
        demo.camera_mut().target = target;
    }
    demo.camera_mut().clamp();
    demo.add_random_drops(o.seed, o.drops);
    let (width, height) = (o.frame.width, o.frame.height);
    let target = OffscreenTarget::new(&gpu.device, width, height);
    for _ in 0..o.frames {
        demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    }
    let rgba = target.read_rgba(&gpu.device, &gpu.queue);
    write_png(&o.out, width, height, &rgba)?;
    eprintln!(
        "wrote {} ({width}x{height}, {} frames, {:.2} s simulated) on {}",
        o.out.display(),
        o.frames,
        demo.sim_time(),
        gpu.describe()
    );
    Ok(())
}

/// What one timed frame gave: its wall-clock time and its stages' times (ms).
struct FrameTimes {
    frame_ms: f64,
    stage_ms: Option<[f64; 4]>,
}

/// Times a frame with GPU timestamps at the stage marks (read once the GPU is idle).
fn time_with_timestamps(
    gpu: &HeadlessGpu,
    demo: &mut WaterDemo,
    target: &OffscreenTarget,
    timer: &mut StageTimer,
) -> FrameTimes {
    let start = Instant::now();
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let dt = 1.0 / 60.0;
    demo.encode_frame(target.frame_context(gpu, &mut encoder), dt, &mut |enc, stage| timer.mark(enc, stage as u32));
    timer.finish(&mut encoder);
    gpu.queue.submit([encoder.finish()]);
    timer.after_submit();
    demo.after_submit();
    let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
    let frame_ms = start.elapsed().as_secs_f64() * 1e3;
    // The frame waited for the GPU, so its timestamps are ready now.
    timer.collect();
    FrameTimes { frame_ms, stage_ms: timer.latest() }
}

/// Times a frame without timestamps: each stage submitted and waited for on its own, timed on
/// the CPU.
fn time_with_cpu_clock(gpu: &HeadlessGpu, demo: &mut WaterDemo, target: &OffscreenTarget) -> FrameTimes {
    let start = Instant::now();
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let mut times = Vec::new();
    let mut last = Instant::now();
    let dt = 1.0 / 60.0;
    demo.encode_frame(target.frame_context(gpu, &mut encoder), dt, &mut |enc, stage| {
        if stage != Stage::Start {
            let done = std::mem::replace(enc, gpu.device.create_command_encoder(&Default::default()));
            gpu.queue.submit([done.finish()]);
            let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
            times.push(last.elapsed().as_secs_f64() * 1e3);
        }
        last = Instant::now();
    });
    gpu.queue.submit([encoder.finish()]);
    demo.after_submit();
    let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
    FrameTimes {
        frame_ms: start.elapsed().as_secs_f64() * 1e3,
        stage_ms: Some([times[0], times[1], times[2], times[3]]),
    }
}

/// The value at fraction `p` of sorted `values`.
fn percentile(values: &[f64], p: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

fn bench(o: &BenchArgs) -> Result<(), String> {
    let gpu = HeadlessGpu::new()?;
    let mut demo = o.frame.start.make_demo(&gpu);
    let target = OffscreenTarget::new(&gpu.device, o.frame.width, o.frame.height);
    let mut timer = StageTimer::new(&gpu.device, &gpu.queue);
    // Warm-up: pipelines compiled, caches filled, sky painted.
    for _ in 0..5 {
        demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    }
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| e.to_string())?;
    let mut frames = Vec::new();
    for i in 0..o.frames {
        if i % 30 == 0 {
            // Keep the water moving during long runs.
            let k = (i / 30) as f32;
            demo.add_drop((k * 0.37).sin() * 0.6, (k * 0.61).cos() * 0.6, 0.04, 0.012);
        }
        frames.push(match &mut timer {
            Some(t) => time_with_timestamps(&gpu, &mut demo, &target, t),
            None => time_with_cpu_clock(&gpu, &mut demo, &target),
        });
    }
    let frame_ms: Vec<f64> = frames.iter().map(|f| f.frame_ms).collect();
    let stage = |k: usize| {
        let v: Vec<f64> = frames.iter().filter_map(|f| f.stage_ms.map(|s| s[k])).collect();
        if v.is_empty() {
            f64::NAN
        } else {
            percentile(&v, 0.5)
        }
    };
    let info = gpu.adapter.get_info();
    let round = |v: f64| (v * 1e3).round() / 1e3;
    let apart: serde_json::Map<_, _> = demo
        .timed_apart(&gpu.device, &gpu.queue)
        .into_iter()
        .map(|(name, ms)| (name.to_string(), serde_json::Value::from(round(percentile(&ms, 0.5)))))
        .collect();
    let report = serde_json::json!({
        "adapter": info.name,
        "backend": format!("{:?}", info.backend),
        "width": o.frame.width,
        "height": o.frame.height,
        "frames": o.frames,
        "sim_size": o.frame.start.demo_options().sim_size,
        "steps_per_frame": (1.0 / 60.0 / STEP_DT).round(),
        "frame_ms": { "median": round(percentile(&frame_ms, 0.5)), "p95": round(percentile(&frame_ms, 0.95)) },
        "stage_ms": demo.stage_names()
            .iter()
            .enumerate()
            .map(|(i, name)| (name.to_string(), serde_json::Value::from(round(stage(i)))))
            .collect::<serde_json::Map<_, _>>(),
        "stage_timing": if timer.is_some() {
            "gpu timestamps between stages"
        } else {
            "cpu wall clock: each stage submitted and waited for separately"
        },
        "frame_timing": "cpu wall clock from encode to GPU idle, one frame in flight",
        "timed_apart": apart,
    });
    println!("{report}");
    Ok(())
}

/// A language there is a catalogue for, as its tag.
fn language(text: &str) -> Result<String, String> {
    crate::catalogue::Catalogue::load(text).map(|c| c.tag.to_owned())
}

fn viewer_options(args: ViewerArgs) -> Result<crate::viewer::ViewerOptions, clap::Error> {
    if args.out.is_some() {
        let message = "the viewer takes --screenshot FILE, not --out (that is for render)";
        return Err(Cli::command().error(clap::error::ErrorKind::ArgumentConflict, message));
    }
    Ok(crate::viewer::ViewerOptions {
        lang: args.lang,
        frames: args.frames,
        screenshot: args.screenshot,
        demo: args.start.demo_options(),
        preset: args.start.preset,
        sets: args.start.sets,
        sketch: args.start.sketch,
    })
}

pub fn main() -> ExitCode {
    // Usage errors print the message and the usage line and exit 2; --help exits 0.
    let cli = Cli::parse();
    let result = match cli.command {
        None => match viewer_options(cli.viewer) {
            Ok(options) => crate::viewer::run(options),
            Err(e) => e.exit(),
        },
        Some(Command::Render(o)) => render(&o),
        Some(Command::Bench(o)) => bench(&o),
        Some(Command::Parameters) => {
            print!("{}", reference::markdown());
            Ok(())
        }
        Some(Command::Messages(a)) => match a.serbian_latin {
            None => {
                print!("{}", messages::english_catalogue());
                Ok(())
            }
            Some(path) => std::fs::read_to_string(&path)
                .map(|cyrillic| print!("{}", messages::serbian_latin(&cyrillic)))
                .map_err(|e| format!("{}: {e}", path.display())),
        },
    };
    match result {
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
        Ok(()) => ExitCode::SUCCESS,
    }
}
