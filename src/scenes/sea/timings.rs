//! What `wavepool bench` times apart in the sea (ten runs each, ms; the bench takes their median): the GPU's
//! FFT of its cascades alone (submitted and waited for), the CPU's FFT that devices without
//! float targets and software rasterisers take instead (`SeaWaves::layers`), and the CPU's sums
//! for a body's probes (the waves at two moments on a ring of eight points).

// A benchmark waits for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

use std::time::Instant;

use crate::ambient::cascades::SeaWaves;
use crate::ambient::gpu_ocean::GpuOcean;
use crate::params::Params;
use crate::sea::SEA_LATTICE;

/// Ten runs of `run` (ms), each given a time (s) 0.1 s after the last.
fn ten_runs(run: &mut dyn FnMut(f64)) -> Vec<f64> {
    (0..10)
        .map(|i| {
            let start = Instant::now();
            run(i as f64 * 0.1);
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect()
}

/// The sea's timings apart, named as `wavepool bench` prints them.
pub fn timed_apart(device: &wgpu::Device, queue: &wgpu::Queue, params: &Params) -> Vec<(&'static str, Vec<f64>)> {
    let waves = SeaWaves::new(&super::sea_settings(params).waves(), SEA_LATTICE);
    let fft_cpu_ms = ten_runs(&mut |t| {
        std::hint::black_box(waves.layers(t));
    });
    let oceans: Vec<_> = waves.cascades.iter().map(|c| &c.ocean).collect();
    let mut fft = GpuOcean::new(device, SEA_LATTICE as u32, oceans.len() as u32);
    let fft_gpu_ms = ten_runs(&mut |t| {
        let mut encoder = device.create_command_encoder(&Default::default());
        fft.encode(queue, &mut encoder, &oceans, 1.0 + t);
        queue.submit([encoder.finish()]);
        let _ = device.poll(wgpu::PollType::wait_indefinitely());
    });
    let body_cpu_ms = ten_runs(&mut |t| {
        for moment in [t, t + 1.0 / 60.0] {
            let now = waves.at(moment);
            let ring = (0..8).map(|i| (i as f32 * 0.785).sin_cos());
            std::hint::black_box(ring.map(|(s, c)| now.height(0.5 * c, 0.5 * s)).sum::<f32>());
        }
    });
    vec![("fft_gpu_ms", fft_gpu_ms), ("fft_cpu_ms", fft_cpu_ms), ("body_cpu_ms", body_cpu_ms)]
}
