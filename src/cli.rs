//! The `wavepool` command line: headless rendering and benchmarks on any wgpu adapter
//! (lavapipe in CI). Needs no display.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use wavepool::demo::{DemoOptions, Stage, WaterDemo, STEP_DT};
use wavepool::headless::{write_png, HeadlessGpu, OffscreenTarget, OFFSCREEN_FORMAT};
use wavepool::params::{self, ParamId};
use wavepool::presets;
use wavepool::scene::HALF_WIDTH;
use wavepool::sim::random_drops;
use wavepool::timing::StageTimer;

const USAGE: &str = "\
wavepool: interactive water, a desktop viewer and headless tools

USAGE:
  wavepool [--frames N --screenshot FILE.png] [--sim-size N] [--float auto|none] [--preset NAME] [--set NAME=VALUE]...
  wavepool render --out FILE.png [--width W] [--height H] [--frames N]
                  [--drops K] [--seed S] [--yaw DEG] [--pitch DEG] [--distance M]
                  [--sim-size N] [--surface-grid N] [--caustics-size N] [--float auto|none]
                  [--preset NAME] [--set NAME=VALUE]...
  wavepool bench  [--width W] [--height H] [--frames N] [--sim-size N] [--surface-grid N]
                  [--caustics-size N] [--float auto|none] [--preset NAME] [--set NAME=VALUE]...

(no command) opens the viewer window: the pool and a panel with every parameter. With
        --frames N it closes after N frames, with --screenshot it first saves the window.
render  simulates N frames of 1/60 s (K seeded random drops at the start) and writes the
        last frame as PNG. Defaults: 800x600, 60 frames, 12 drops, seed 1.
bench   renders N frames (default 120) after a warm-up and prints one JSON object with the
        adapter, frame times and per-stage GPU times.

--set takes any parameter of the table, by number or a choice's name, e.g. --set caustics=off
        --set sun_elevation=30 --set render_mode=split. --preset NAME starts from a lesson
        preset (listed last; the --set values come after it).
--float none takes the path for devices without float render targets (water simulated on
the CPU, 8-bit caustics map).
Parameters:";

/// A usage error: message for stderr, exit code 2.
struct UsageError(String);

fn parse_number<T>(flag: &str, value: &str, lo: T, hi: T) -> Result<T, UsageError>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display + Copy,
{
    let v: T = value.parse().map_err(|_| UsageError(format!("{flag}: '{value}' is not a number")))?;
    if v < lo || v > hi {
        return Err(UsageError(format!("{flag}: {value} is outside {lo}..={hi}")));
    }
    Ok(v)
}

#[derive(Debug)]
struct Options {
    width: u32,
    height: u32,
    frames: u32,
    drops: u32,
    seed: u64,
    out: Option<PathBuf>,
    /// The viewer's `--screenshot FILE.png`.
    screenshot: Option<PathBuf>,
    /// Whether `--frames` was given (the viewer runs until closed without it).
    frames_given: bool,
    yaw: Option<f32>,
    pitch: Option<f32>,
    distance: Option<f32>,
    sim_size: u32,
    surface_grid: u32,
    caustics_size: u32,
    /// False with `--float none`: the path for devices without float render targets.
    float_targets: bool,
    /// `--preset NAME`: applied before the `--set` values.
    preset: Option<&'static presets::Preset>,
    sets: Vec<(String, f32)>,
}

fn parse(args: &[String], default_frames: u32) -> Result<Options, UsageError> {
    let mut o = Options {
        width: 800,
        height: 600,
        frames: default_frames,
        drops: 12,
        seed: 1,
        out: None,
        screenshot: None,
        frames_given: false,
        yaw: None,
        pitch: None,
        distance: None,
        sim_size: 256,
        surface_grid: DemoOptions::default().surface_grid,
        caustics_size: DemoOptions::default().caustics_size,
        float_targets: true,
        preset: None,
        sets: Vec::new(),
    };
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let value = it.next().ok_or_else(|| UsageError(format!("{flag} needs a value")))?;
        match flag.as_str() {
            "--width" => o.width = parse_number(flag, value, 16, 8192)?,
            "--height" => o.height = parse_number(flag, value, 16, 8192)?,
            "--frames" => {
                o.frames = parse_number(flag, value, 1, 1_000_000)?;
                o.frames_given = true;
            }
            "--screenshot" => o.screenshot = Some(PathBuf::from(value)),
            "--drops" => o.drops = parse_number(flag, value, 0, 100_000)?,
            "--seed" => o.seed = parse_number(flag, value, 0, u64::MAX)?,
            "--out" => o.out = Some(PathBuf::from(value)),
            "--yaw" => o.yaw = Some(parse_number(flag, value, -360.0, 360.0)?),
            "--pitch" => o.pitch = Some(parse_number(flag, value, -89.0, 89.0)?),
            "--distance" => o.distance = Some(parse_number(flag, value, 1.5, 12.0)?),
            "--sim-size" => {
                o.sim_size = parse_number(flag, value, 16, 2048)?;
                if !o.sim_size.is_power_of_two() {
                    return Err(UsageError(format!("--sim-size: {value} is not a power of two")));
                }
            }
            "--surface-grid" => o.surface_grid = parse_number(flag, value, 8, 1024)?,
            "--caustics-size" => o.caustics_size = parse_number(flag, value, 64, 4096)?,
            "--float" => {
                o.float_targets = match value.as_str() {
                    "auto" => true,
                    "none" => false,
                    _ => return Err(UsageError(format!("--float: expected auto or none, got '{value}'"))),
                }
            }
            "--set" => {
                let (name, v) = value
                    .split_once('=')
                    .ok_or_else(|| UsageError(format!("--set: expected NAME=VALUE, got '{value}'")))?;
                let spec = params::find(name)
                    .ok_or_else(|| UsageError(params::ParamError::Unknown(name.to_owned()).to_string()))?;
                let value = spec.parse(v).ok_or_else(|| {
                    let names = match spec.control {
                        params::Control::Choice { names, .. } if !names.is_empty() => {
                            format!(" or one of {}", names.join(", "))
                        }
                        _ => String::new(),
                    };
                    UsageError(format!("--set {name}: '{v}' is not a number{names}"))
                })?;
                if value < spec.min() || value > spec.max() {
                    return Err(UsageError(format!("--set {name}: {v} is outside {}..={}", spec.min(), spec.max())));
                }
                o.sets.push((name.to_owned(), value));
            }
            "--preset" => {
                let preset = presets::find(value).ok_or_else(|| {
                    let names: Vec<&str> = presets::PRESETS.iter().map(|p| p.name).collect();
                    UsageError(format!("--preset: '{value}' is not one of {}", names.join(", ")))
                })?;
                o.preset = Some(preset);
            }
            other => return Err(UsageError(format!("unknown option '{other}'"))),
        }
    }
    Ok(o)
}

fn make_demo(gpu: &HeadlessGpu, o: &Options) -> WaterDemo {
    let mut demo = WaterDemo::new(
        &gpu.device,
        &gpu.queue,
        OFFSCREEN_FORMAT,
        DemoOptions {
            sim_size: o.sim_size,
            surface_grid: o.surface_grid,
            caustics_size: o.caustics_size,
            float_targets: o.float_targets,
        },
    );
    if let Some(preset) = o.preset {
        preset.apply(&mut demo.params, &mut demo.camera);
    }
    for (name, v) in &o.sets {
        demo.params.set_by_name(name, *v).expect("names checked while parsing");
    }
    if let Some(y) = o.yaw {
        demo.camera.yaw = y;
    }
    if let Some(p) = o.pitch {
        demo.camera.pitch = p;
    }
    if let Some(d) = o.distance {
        demo.camera.distance = d;
    }
    demo.camera.clamp();
    let radius = demo.params.get(ParamId::DropRadius);
    let strength = demo.params.get(ParamId::DropStrength);
    for d in random_drops(o.seed, o.drops, HALF_WIDTH, radius, strength) {
        demo.add_drop(d.x, d.z, d.radius, d.strength);
    }
    demo
}

fn render(o: &Options) -> Result<(), String> {
    let out = o.out.as_ref().ok_or("render needs --out FILE.png")?;
    let gpu = HeadlessGpu::new()?;
    let mut demo = make_demo(&gpu, o);
    let target = OffscreenTarget::new(&gpu.device, o.width, o.height);
    for _ in 0..o.frames {
        demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    }
    let rgba = target.read_rgba(&gpu.device, &gpu.queue);
    write_png(out, o.width, o.height, &rgba)?;
    eprintln!(
        "wrote {} ({}x{}, {} frames, {:.2} s simulated) on {}",
        out.display(),
        o.width,
        o.height,
        o.frames,
        demo.sim_time(),
        gpu.describe()
    );
    Ok(())
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    let i = ((sorted.len() - 1) as f64 * p).round() as usize;
    sorted[i]
}

fn bench(o: &Options) -> Result<(), String> {
    let gpu = HeadlessGpu::new()?;
    let mut demo = make_demo(&gpu, o);
    let target = OffscreenTarget::new(&gpu.device, o.width, o.height);
    let mut timer = StageTimer::new(&gpu.device, &gpu.queue);
    let wait = || gpu.device.poll(wgpu::PollType::wait_indefinitely()).map(|_| ()).map_err(|e| e.to_string());
    // Warm-up: pipelines compiled, caches filled, sky painted.
    for _ in 0..5 {
        demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    }
    wait()?;
    let mut frame_ms = Vec::new();
    let mut stage_ms: Vec<[f64; 3]> = Vec::new();
    for i in 0..o.frames {
        if i % 30 == 0 {
            // Keep the water moving during long runs.
            demo.add_drop(((i / 30) as f32 * 0.37).sin() * 0.6, ((i / 30) as f32 * 0.61).cos() * 0.6, 0.04, 0.012);
        }
        let start = Instant::now();
        match &mut timer {
            Some(t) => {
                let mut encoder = gpu.device.create_command_encoder(&Default::default());
                demo.encode_frame(
                    &gpu.device,
                    &gpu.queue,
                    &mut encoder,
                    &target.view,
                    target.size(),
                    1.0 / 60.0,
                    &mut |enc, stage| t.mark(enc, stage),
                );
                t.finish(&mut encoder);
                gpu.queue.submit([encoder.finish()]);
                t.after_submit();
                wait()?;
                frame_ms.push(start.elapsed().as_secs_f64() * 1e3);
                // The frame waited for the GPU, so its timestamps are ready now.
                t.collect();
                stage_ms.extend(t.latest());
            }
            None => {
                // No timestamps: submit each stage separately and time submit + wait on the CPU.
                let mut encoder = gpu.device.create_command_encoder(&Default::default());
                let mut times = Vec::new();
                let mut last = Instant::now();
                demo.encode_frame(
                    &gpu.device,
                    &gpu.queue,
                    &mut encoder,
                    &target.view,
                    target.size(),
                    1.0 / 60.0,
                    &mut |enc, stage| {
                        if stage != Stage::Start {
                            let done = std::mem::replace(enc, gpu.device.create_command_encoder(&Default::default()));
                            gpu.queue.submit([done.finish()]);
                            let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
                            times.push(last.elapsed().as_secs_f64() * 1e3);
                        }
                        last = Instant::now();
                    },
                );
                gpu.queue.submit([encoder.finish()]);
                wait()?;
                frame_ms.push(start.elapsed().as_secs_f64() * 1e3);
                stage_ms.push([times[0], times[1], times[2]]);
            }
        }
    }
    let mut sorted = frame_ms.clone();
    sorted.sort_by(f64::total_cmp);
    let median_stage = |k: usize| {
        let mut v: Vec<f64> = stage_ms.iter().map(|s| s[k]).collect();
        v.sort_by(f64::total_cmp);
        percentile(&v, 0.5)
    };
    let info = gpu.adapter.get_info();
    let timing = if timer.is_some() {
        "gpu timestamps between stages"
    } else {
        "cpu wall clock: each stage submitted and waited for separately"
    };
    println!(
        "{{\"adapter\":{:?},\"backend\":\"{:?}\",\"width\":{},\"height\":{},\"frames\":{},\"sim_size\":{},\"steps_per_frame\":{},\
\"frame_ms\":{{\"median\":{:.3},\"p95\":{:.3}}},\"stage_ms\":{{\"simulation\":{:.3},\"caustics\":{:.3},\"scene\":{:.3}}},\"stage_timing\":{:?},\
\"frame_timing\":\"cpu wall clock from encode to GPU idle, one frame in flight\"}}",
        info.name,
        info.backend,
        o.width,
        o.height,
        o.frames,
        o.sim_size,
        (1.0 / 60.0 / STEP_DT).round(),
        percentile(&sorted, 0.5),
        percentile(&sorted, 0.95),
        median_stage(0),
        median_stage(1),
        median_stage(2),
        timing
    );
    Ok(())
}

fn usage() -> String {
    let names: Vec<String> = params::PARAMS
        .iter()
        .map(|p| match p.control {
            params::Control::Toggle => format!("  {:<14} 0 or 1, default {}  {}", p.name, p.default, p.label),
            params::Control::Choice { values, names } => {
                let list: Vec<String> = values
                    .iter()
                    .enumerate()
                    .map(|(i, v)| names.get(i).map_or(v.to_string(), |n| format!("{v}={n}")))
                    .collect();
                format!("  {:<14} {} {}, default {}  {}", p.name, list.join("|"), p.unit, p.default, p.label)
            }
            params::Control::Slider { min, max, .. } => {
                format!("  {:<14} {min}..{max} {}, default {}  {}", p.name, p.unit, p.default, p.label)
            }
        })
        .collect();
    let presets: Vec<String> = presets::PRESETS.iter().map(|p| format!("  {:<14} {}", p.name, p.label)).collect();
    format!("{USAGE}\n{}\nPresets:\n{}\n", names.join("\n"), presets.join("\n"))
}

/// Flags of the desktop viewer (no command): `--frames N`, `--screenshot FILE.png`, and the
/// demo options `--sim-size`, `--surface-grid`, `--caustics-size`, `--float`, `--set`.
fn parse_viewer(args: &[String]) -> Result<crate::viewer::ViewerOptions, UsageError> {
    let o = parse(args, 0)?;
    if o.out.is_some() {
        return Err(UsageError("the viewer takes --screenshot FILE, not --out (that is for render)".into()));
    }
    let demo = DemoOptions {
        sim_size: o.sim_size,
        surface_grid: o.surface_grid,
        caustics_size: o.caustics_size,
        float_targets: o.float_targets,
    };
    if o.screenshot.is_some() && !o.frames_given {
        return Err(UsageError("--screenshot needs --frames N".into()));
    }
    Ok(crate::viewer::ViewerOptions {
        frames: o.frames_given.then_some(o.frames),
        screenshot: o.screenshot.clone(),
        demo,
        preset: o.preset,
        sets: o.sets.clone(),
    })
}

pub fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (command, rest) = match args.split_first() {
        Some((c, rest)) if !c.starts_with("--") => (c.as_str(), rest),
        _ => ("view", &args[..]),
    };
    if matches!(command, "-h" | "help") || args.iter().any(|a| a == "--help") {
        print!("{}", usage());
        return ExitCode::SUCCESS;
    }
    let result = match command {
        "view" => parse_viewer(rest).map(crate::viewer::run),
        "render" => parse(rest, 60).map(|o| render(&o)),
        "bench" => parse(rest, 120).map(|o| bench(&o)),
        other => Err(UsageError(format!("unknown command '{other}'"))),
    };
    match result {
        Err(UsageError(msg)) => {
            eprintln!("error: {msg}\n");
            eprint!("{}", usage());
            ExitCode::from(2)
        }
        Ok(Err(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
        Ok(Ok(())) => ExitCode::SUCCESS,
    }
}
