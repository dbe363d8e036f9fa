//! GPU time per stage of a frame from timestamp queries at five marks (the frame's start, the
//! end of each of its four stages, which the scene names: the pool's simulation, waves, caustics,
//! shading; the sea's maps in place of caustics), read back without waiting (one to a few
//! frames late), for the viewer's readout and the bench.

use crate::gpu::AsyncReadback;

/// The device features stage timing uses; request them where the adapter has them. With only
/// `TIMESTAMP_QUERY` (WebGPU in browsers) each mark is an empty compute pass that writes the
/// timestamp as it begins.
pub const TIMESTAMP_FEATURES: wgpu::Features =
    wgpu::Features::TIMESTAMP_QUERY.union(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS);

/// Marks a frame has: its start and the end of each stage.
const MARKS: u32 = 5;

/// Timestamps at the marks of a frame.
pub struct StageTimer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    readback: AsyncReadback,
    period_ns: f32,
    latest: Option<[f64; 4]>,
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
            count: MARKS,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("stage timestamps"),
            size: 8 * MARKS as u64,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        Some(Self {
            queries,
            resolve,
            readback: AsyncReadback::new(device, "stage timestamps readback", 8 * MARKS as u64),
            period_ns: queue.get_timestamp_period(),
            latest: None,
            inside_encoders: device.features().contains(wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS),
        })
    }

    /// Writes the timestamp of mark `index` (0…4; `WaterDemo::encode_frame`'s stages in order).
    pub fn mark(&self, encoder: &mut wgpu::CommandEncoder, index: u32) {
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
            encoder.resolve_query_set(&self.queries, 0..MARKS, &self.resolve, 0);
            encoder.copy_buffer_to_buffer(&self.resolve, 0, buffer, 0, 8 * MARKS as u64);
        }
    }

    /// Takes a completed read into [`StageTimer::latest`], if there is one.
    pub fn collect(&mut self) {
        if let Some(bytes) = self.readback.take() {
            let ticks: [u64; MARKS as usize] = bytemuck::pod_read_unaligned(&bytes[..8 * MARKS as usize]);
            let ms = |a: usize, b: usize| ticks[b].saturating_sub(ticks[a]) as f64 * self.period_ns as f64 / 1.0e6;
            self.latest = Some([ms(0, 1), ms(1, 2), ms(2, 3), ms(3, 4)]);
        }
    }

    /// Call once the frame recorded with [`StageTimer::finish`] is submitted.
    pub fn after_submit(&self) {
        self.readback.after_submit();
    }

    /// Milliseconds of each of a recent frame's four stages (the scene's `stage_names`).
    pub fn latest(&self) -> Option<[f64; 4]> {
        self.latest
    }
}
