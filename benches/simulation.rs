//! Simulation benchmarks (not tests): the CPU reference step at 256² against a memory
//! bandwidth bound measured on the same machine for the same bytes, and the GPU step at
//! 128² to 1024² on whatever adapter wgpu finds (lavapipe here). Run with
//! `cargo bench --bench simulation`; prints one JSON object per measurement. First, what the
//! floating bodies' ambient-wave probes cost the CPU per frame, two ways.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

use std::hint::black_box;
use std::time::{Duration, Instant};

use wavepool::ambient::{AmbientModel, AmbientSettings, AmbientWaves};
use wavepool::headless::HeadlessGpu;
use wavepool::sim::cpu::CpuHeightField;
use wavepool::sim::{random_drops, HeightField, WaveSettings};

const DT: f32 = 1.0 / 120.0;

/// Runs `f` repeatedly for at least `budget` after one warm-up call; returns seconds per call
/// (the best of three rounds, the least disturbed by other work on a noisy machine).
fn time_per_call(budget: Duration, mut f: impl FnMut()) -> f64 {
    f();
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let start = Instant::now();
        let mut calls = 0u32;
        while start.elapsed() < budget / 3 || calls == 0 {
            f();
            calls += 1;
        }
        best = best.min(start.elapsed().as_secs_f64() / calls as f64);
    }
    best
}

/// The CPU reference's update at 256² (state in cache) and 1024² (state in main memory),
/// each against copying the same bytes between buffers of the same size.
fn cpu_step_against_bandwidth() {
    for n in [256u32, 1024] {
        // Slow waves, so one step is one update (no CFL substeps) at both sizes.
        let settings = WaveSettings::reflecting(0.3, 0.5);
        let mut water = CpuHeightField::new(n, 1.0);
        for d in random_drops(7, 30, 1.0, 0.05, 0.01) {
            water.add_drop(d);
        }
        let steps = if n <= 256 { 200 } else { 40 };
        let per_batch = time_per_call(Duration::from_secs(3), || {
            water.advance(steps, DT, settings);
        });
        let step_s = per_batch / steps as f64;
        // The bytes a step must move at least: read every cell's height and velocity once and
        // write them once (4 planes x 4 B per cell). Bound: copying the two planes' bytes (8 B
        // per cell read, 8 B written) from one buffer to another.
        let cells = (n * n) as usize;
        let bytes = 16 * cells;
        let source = vec![1.0f32; 2 * cells];
        let mut target = vec![0.0f32; 2 * cells];
        let copy_s = time_per_call(Duration::from_secs(2), || {
            target.copy_from_slice(black_box(&source));
            black_box(&mut target);
        });
        println!(
            "{}",
            serde_json::json!({
                "what": "cpu reference step",
                "size": n,
                "steps_per_s": (1.0 / step_s).round(),
                "ns_per_cell": step_s * 1e9 / cells as f64,
                "bytes_per_step": bytes,
                "copy_bound_steps_per_s": (1.0 / copy_s).round(),
                "copy_gb_per_s": bytes as f64 / copy_s / 1e9,
                "ratio_to_bound": step_s / copy_s,
                "note": format!("one wave-equation update per cell (normals and mean once per {steps} steps); bound: copying the same bytes"),
            })
        );
    }
}

fn gpu_steps(gpu: &HeadlessGpu) {
    for n in [128u32, 256, 512, 1024] {
        let mut water = HeightField::new(&gpu.device, n, 1.0);
        for d in random_drops(7, 30, 1.0, 0.05, 0.01) {
            water.add_drop(d);
        }
        // 0.3 m/s keeps one update per step up to 1024² (Courant number below 0.6).
        let settings = WaveSettings::reflecting(0.3, 0.5);
        let steps = (8 * 1024 * 1024 / (n * n)).clamp(8, 256);
        let mut batch = || {
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            water.encode(&gpu.queue, &mut encoder, steps, DT, settings);
            gpu.queue.submit([encoder.finish()]);
            gpu.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
        };
        let per_batch = time_per_call(Duration::from_secs(3), &mut batch);
        let step_s = per_batch / steps as f64;
        println!(
            "{}",
            serde_json::json!({
                "what": "gpu step",
                "adapter": gpu.describe(),
                "size": n,
                "steps_per_batch": steps,
                "ms_per_step": step_s * 1e3,
                "ns_per_cell": step_s * 1e9 / (n * n) as f64,
            })
        );
    }
}

/// What the floating bodies' ambient probes cost a frame (2 bodies x 8 points on the CPU, in
/// wasm the same code): each model's surface summed wave by wave at every point (the
/// reference, `AmbientWaves::sample`) against the surface made once per frame
/// (`AmbientWaves::at`, then `sample` per point), both timed here in the same run.
fn ambient_probes() {
    let points: Vec<(f32, f32)> =
        (0..16).map(|i| (0.4 * (i as f32 * 0.7).cos() - 0.2 * (i / 8) as f32, 0.4 * (i as f32 * 0.7).sin())).collect();
    let cases = [
        ("sines", AmbientSettings::default_for(AmbientModel::Sines)),
        ("gerstner", AmbientSettings::default_for(AmbientModel::Gerstner)),
        ("fft 64", AmbientSettings::default_for(AmbientModel::Fft)),
        ("fft 128", AmbientSettings { fft_size: 128, ..AmbientSettings::default_for(AmbientModel::Fft) }),
        (
            "fft 128 choppiness 2",
            AmbientSettings { fft_size: 128, choppiness: 2.0, ..AmbientSettings::default_for(AmbientModel::Fft) },
        ),
    ];
    for (name, settings) in cases {
        let waves = AmbientWaves::new(&settings);
        let mut t = 3.0f64;
        let per_point = time_per_call(Duration::from_secs(2), || {
            t += 1.0 / 60.0;
            for &(x, z) in &points {
                black_box(waves.sample(x, z, t));
            }
        });
        let once = time_per_call(Duration::from_secs(2), || {
            t += 1.0 / 60.0;
            let now = waves.at(t);
            for &(x, z) in &points {
                black_box(now.sample(x, z));
            }
        });
        println!(
            "{}",
            serde_json::json!({
                "what": "ambient probes per frame (16 points)",
                "model": name,
                "wave_by_wave_ms": per_point * 1e3,
                "made_once_ms": once * 1e3,
                "speed_up": per_point / once,
            })
        );
    }
}

fn main() {
    ambient_probes();
    cpu_step_against_bandwidth();
    match HeadlessGpu::new() {
        Ok(gpu) => gpu_steps(&gpu),
        Err(e) => {
            eprintln!("no GPU adapter for the GPU step benchmark: {e}");
            std::process::exit(1);
        }
    }
}
