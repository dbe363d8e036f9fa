//! What `wavepool bench` times apart in the sea (the median of ten runs each, ms): the GPU's
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

/// The median (ms) of ten runs of `run`, each given a time (s) 0.1 s after the last: the upper
/// of the middle two, as `wavepool bench` takes its medians.
fn median_of_ten(run: &mut dyn FnMut(f64)) -> f64 {
    let mut times: Vec<f64> = (0..10)
        .map(|i| {
            let start = Instant::now();
            run(i as f64 * 0.1);
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The sea's timings apart, named as `wavepool bench` prints them.
pub fn timed_apart(device: &wgpu::Device, queue: &wgpu::Queue, params: &Params) -> Vec<(&'static str, f64)> {
    let waves = SeaWaves::new(&super::sea_settings(params).waves(), SEA_LATTICE);
    let fft_cpu_ms = median_of_ten(&mut |t| {
        std::hint::black_box(waves.layers(t));
    });
    let oceans: Vec<_> = waves.cascades.iter().map(|c| &c.ocean).collect();
    let mut fft = GpuOcean::new(device, SEA_LATTICE as u32, oceans.len() as u32);
    let fft_gpu_ms = median_of_ten(&mut |t| {
        let mut encoder = device.create_command_encoder(&Default::default());
        fft.encode(queue, &mut encoder, &oceans, 1.0 + t);
        queue.submit([encoder.finish()]);
        let _ = device.poll(wgpu::PollType::wait_indefinitely());
    });
    let body_cpu_ms = median_of_ten(&mut |t| {
        for moment in [t, t + 1.0 / 60.0] {
            let now = waves.at(moment);
            let ring = (0..8).map(|i| (i as f32 * 0.785).sin_cos());
            std::hint::black_box(ring.map(|(s, c)| now.height(0.5 * c, 0.5 * s)).sum::<f32>());
        }
    });
    vec![("fft_gpu_ms", fft_gpu_ms), ("fft_cpu_ms", fft_cpu_ms), ("body_cpu_ms", body_cpu_ms)]
}
