//! GPU time per stage of a frame (simulation, caustics, scene) from timestamp queries, read
//! back without waiting (one to a few frames late), for the viewer's readout and the bench.

use crate::demo::Stage;
use crate::gpu::AsyncReadback;
use crate::render::flat::RenderMode;

/// The device features stage timing uses; request them where the adapter has them. With only
/// `TIMESTAMP_QUERY` (WebGPU in browsers) each mark is an empty compute pass that writes the
/// timestamp as it begins.
pub const TIMESTAMP_FEATURES: wgpu::Features =
    wgpu::Features::TIMESTAMP_QUERY.union(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS);

/// Timestamps at the [`Stage`] boundaries of a frame.
pub struct StageTimer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    readback: AsyncReadback,
    period_ns: f32,
    latest: Option<[f64; 3]>,
    /// Timestamps may be written between passes (else: by empty compute passes).
    inside_encoders: bool,
}

impl StageTimer {
    /// `None` when the device was made without `TIMESTAMP_QUERY`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let queries = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("stage timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count: 4,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("stage timestamps"),
            size: 32,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        Some(Self {
            queries,
            resolve,
            readback: AsyncReadback::new(device, "stage timestamps readback", 32),
            period_ns: queue.get_timestamp_period(),
            latest: None,
            inside_encoders: device.features().contains(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS),
        })
    }

    /// Writes the timestamp of `stage` (pass as the `mark` of `WaterDemo::encode_frame`).
    pub fn mark(&self, encoder: &mut wgpu::CommandEncoder, stage: Stage) {
        let index = match stage {
            Stage::Start => 0,
            Stage::AfterSimulation => 1,
            Stage::AfterCaustics => 2,
            Stage::AfterScene => 3,
        };
        if self.inside_encoders {
            encoder.write_timestamp(&self.queries, index);
        } else {
            encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("stage timestamp"),
                timestamp_writes: Some(wgpu::ComputePassTimestampWrites {
                    query_set: &self.queries,
                    beginning_of_pass_write_index: Some(index),
                    end_of_pass_write_index: None,
                }),
            });
        }
    }

    /// After the frame's stages: takes a finished read, and copies this frame's timestamps
    /// out when no read is in flight.
    pub fn finish(&mut self, encoder: &mut wgpu::CommandEncoder) {
        self.collect();
        if let Some(buffer) = self.readback.record() {
            encoder.resolve_query_set(&self.queries, 0..4, &self.resolve, 0);
            encoder.copy_buffer_to_buffer(&self.resolve, 0, buffer, 0, 32);
        }
    }

    /// Takes a completed read into [`StageTimer::latest`], if there is one.
    pub fn collect(&mut self) {
        if let Some(bytes) = self.readback.take() {
            let ticks: [u64; 4] = bytemuck::pod_read_unaligned(&bytes[..32]);
            let ms = |a: usize, b: usize| ticks[b].saturating_sub(ticks[a]) as f64 * self.period_ns as f64 / 1.0e6;
            self.latest = Some([ms(0, 1), ms(1, 2), ms(2, 3)]);
        }
    }

    /// Call once the frame recorded with [`StageTimer::finish`] is submitted.
    pub fn after_submit(&self) {
        self.readback.after_submit();
    }

    /// Milliseconds of (simulation, caustics, scene) of a recent frame.
    pub fn latest(&self) -> Option<[f64; 3]> {
        self.latest
    }
}

/// GPU time of drawing the water (the caustics and scene stages) per render mode, smoothed
/// over recent frames and kept after switching away, so the panel can set the modes' costs
/// side by side.
#[derive(Clone, Debug, Default)]
pub struct ModeCosts {
    /// Milliseconds per [`RenderMode`] (ray-traced, flat, split), once measured.
    ms: [Option<f64>; 3],
}

impl ModeCosts {
    /// Takes a frame's stage times ([`StageTimer::latest`]) drawn in `mode`.
    pub fn observe(&mut self, mode: RenderMode, stages: [f64; 3]) {
        let drawing = stages[1] + stages[2];
        let slot = &mut self.ms[mode as usize];
        *slot = Some(slot.map_or(drawing, |old| 0.9 * old + 0.1 * drawing));
    }

    /// The smoothed milliseconds of `mode`, if it was drawn.
    pub fn of(&self, mode: RenderMode) -> Option<f64> {
        self.ms[mode as usize]
    }

    /// "ray-traced 6.2 ms · flat 2.4 ms · split –" (– : not drawn yet).
    pub fn summary(&self) -> String {
        [RenderMode::RayTraced, RenderMode::Flat, RenderMode::Split]
            .iter()
            .zip(["ray-traced", "flat", "split"])
            .map(|(&mode, name)| match self.of(mode) {
                Some(ms) => format!("{name} {ms:.1} ms"),
                None => format!("{name} –"),
            })
            .collect::<Vec<_>>()
            .join(" · ")
    }
}
