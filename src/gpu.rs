//! GPU plumbing shared by every pass: WGSL assembly, the one full-screen pass helper,
//! the one ping-pong texture pair, bind-group layout shorthands and texture readback.

use wgpu::util::DeviceExt;

/// The WGSL parts every kind of pass may use; each feature keeps its own beside its code.
pub mod wgsl {
    /// The full-screen triangle's vertex shader ([`super::FullscreenPass`] adds it).
    pub const FULLSCREEN: &str = crate::wgsl!("fullscreen.wgsl");
    /// Maths and colour helpers without bindings: PI, sRGB conversions, hash and value noise.
    pub const MATH: &str = crate::wgsl!("math.wgsl");
}

/// Compiles a shader module from WGSL parts (constants written by Rust, then sources), joined
/// in order: WGSL has no include, so a pass lists exactly the parts it uses.
pub fn shader(device: &wgpu::Device, label: &str, parts: &[&str]) -> wgpu::ShaderModule {
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(parts.join("\n").into()),
    })
}

pub fn uniform_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

pub fn texture_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    sample_type: wgpu::TextureSampleType,
    view_dimension: wgpu::TextureViewDimension,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Texture { sample_type, view_dimension, multisampled: false },
        count: None,
    }
}

/// A 2D float texture read texel by texel (`textureLoad`; 32-bit floats are not filterable).
pub fn float_texture_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    let sample_type = wgpu::TextureSampleType::Float { filterable: false };
    texture_entry(binding, visibility, sample_type, wgpu::TextureViewDimension::D2)
}

/// A 2D texture read through a filtering sampler.
pub fn filtered_texture_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    let sample_type = wgpu::TextureSampleType::Float { filterable: true };
    texture_entry(binding, visibility, sample_type, wgpu::TextureViewDimension::D2)
}

pub fn sampler_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        count: None,
    }
}

pub fn uniform_buffer<T: bytemuck::Pod>(device: &wgpu::Device, label: &str, value: &T) -> wgpu::Buffer {
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: bytemuck::bytes_of(value),
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
    })
}

pub fn pipeline_layout(device: &wgpu::Device, label: &str, layouts: &[&wgpu::BindGroupLayout]) -> wgpu::PipelineLayout {
    let layouts: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(|l| Some(*l)).collect();
    device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(label),
        bind_group_layouts: &layouts,
        immediate_size: 0,
    })
}

/// What a frame is recorded with: the device and queue, the encoder its drawing goes into and
/// the target it is drawn in, `size` pixels.
pub struct FrameContext<'a> {
    pub device: &'a wgpu::Device,
    pub queue: &'a wgpu::Queue,
    pub encoder: &'a mut wgpu::CommandEncoder,
    pub target: &'a wgpu::TextureView,
    pub size: (u32, u32),
}

/// A 2-D texture of `(width, height, layers)` (6 layers for a cube) and `mips` mip levels.
pub fn texture_2d(
    device: &wgpu::Device,
    label: &str,
    (width, height, layers): (u32, u32, u32),
    mips: u32,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d { width, height, depth_or_array_layers: layers },
        mip_level_count: mips,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

/// A render pass on one colour target and no depth, stored; `load` keeps or clears it first.
/// Copies `data` (rows of texels, top row first, nothing between rows; layer after layer) into
/// the whole of mip level `level` of a 2D texture, every layer of it.
pub fn write_texture_2d(queue: &wgpu::Queue, texture: &wgpu::Texture, level: u32, data: &[u8]) {
    let (width, height) = ((texture.width() >> level).max(1), (texture.height() >> level).max(1));
    let texel = texture.format().block_copy_size(None).expect("colour format");
    queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: level,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        data,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(width * texel), rows_per_image: Some(height) },
        wgpu::Extent3d { width, height, depth_or_array_layers: texture.depth_or_array_layers() },
    );
}

pub fn colour_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    target: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: target,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: None,
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// A pass that shades every pixel of its target with one fragment shader: the simulation
/// steps, the sky background and the sky cubemap faces are all of this kind.
pub struct FullscreenPass {
    pipeline: wgpu::RenderPipeline,
    label: String,
}

/// How a full-screen pass writes its target.
pub struct FullscreenTarget {
    pub format: wgpu::TextureFormat,
    pub blend: Option<wgpu::BlendState>,
    /// Depth format of the render pass it is drawn in, if any. The triangle lies on the far
    /// plane and is depth-tested (less-or-equal, no writes), so it only fills pixels no
    /// geometry covered: draw it last.
    pub depth: Option<wgpu::TextureFormat>,
}

impl FullscreenPass {
    /// `parts` are the WGSL sources besides the shared full-screen vertex shader;
    /// `entry` is the fragment entry point.
    pub fn new(
        device: &wgpu::Device,
        label: &str,
        parts: &[&str],
        entry: &str,
        layouts: &[&wgpu::BindGroupLayout],
        target: FullscreenTarget,
    ) -> Self {
        Self::with_targets(device, label, parts, entry, layouts, &[target])
    }

    /// [`FullscreenPass::new`] writing several targets at once (its fragment entry's
    /// locations 0, 1, …), all in the same depth state (the first's).
    pub fn with_targets(
        device: &wgpu::Device,
        label: &str,
        parts: &[&str],
        entry: &str,
        layouts: &[&wgpu::BindGroupLayout],
        targets: &[FullscreenTarget],
    ) -> Self {
        let mut all = vec![wgsl::FULLSCREEN];
        all.extend_from_slice(parts);
        let module = shader(device, label, &all);
        let layout = pipeline_layout(device, label, layouts);
        let colour_targets: Vec<_> = targets
            .iter()
            .map(|t| {
                Some(wgpu::ColorTargetState { format: t.format, blend: t.blend, write_mask: wgpu::ColorWrites::ALL })
            })
            .collect();
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(label),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_fullscreen"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: targets.first().and_then(|t| t.depth).map(|format| wgpu::DepthStencilState {
                format,
                depth_write_enabled: Some(false),
                depth_compare: Some(wgpu::CompareFunction::LessEqual),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                targets: &colour_targets,
            }),
            multiview_mask: None,
            cache: None,
        });
        Self { pipeline, label: label.to_owned() }
    }

    /// Draws into an already open render pass.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, bind_groups: &[&wgpu::BindGroup]) {
        pass.set_pipeline(&self.pipeline);
        for (i, group) in bind_groups.iter().enumerate() {
            pass.set_bind_group(i as u32, Some(*group), &[]);
        }
        pass.draw(0..3, 0..1);
    }

    /// Draws into the pixels `rect` (x, y, width, height) of `target`, keeping the rest.
    pub fn run_in_rect(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        bind_groups: &[&wgpu::BindGroup],
        rect: [u32; 4],
    ) {
        let mut pass = colour_pass(encoder, &self.label, target, wgpu::LoadOp::Load);
        let [x, y, w, h] = rect;
        pass.set_scissor_rect(x, y, w, h);
        self.draw(&mut pass, bind_groups);
    }

    /// Opens a render pass on `target`, overwriting it, and draws.
    pub fn run(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        bind_groups: &[&wgpu::BindGroup],
    ) {
        self.run_on(encoder, &[target], bind_groups);
    }

    /// [`FullscreenPass::run`] on each of `targets` at once (a pass made
    /// [`FullscreenPass::with_targets`]).
    pub fn run_on(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        targets: &[&wgpu::TextureView],
        bind_groups: &[&wgpu::BindGroup],
    ) {
        let attachments: Vec<_> = targets
            .iter()
            .map(|view| {
                Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })
            })
            .collect();
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(&self.label),
            color_attachments: &attachments,
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        self.draw(&mut pass, bind_groups);
    }
}

/// Two textures of the same size and format: passes read one and write the other, then
/// swap, so no pass reads what it writes.
pub struct PingPong {
    textures: [wgpu::Texture; 2],
    views: [wgpu::TextureView; 2],
    current: usize,
}

impl PingPong {
    /// Two `width` x `height` textures of `format`, to render into (`render_target`) or to
    /// fill from the CPU; either way sampleable and copyable.
    pub fn new(
        device: &wgpu::Device,
        label: &str,
        width: u32,
        height: u32,
        format: wgpu::TextureFormat,
        render_target: bool,
    ) -> Self {
        let target = if render_target { wgpu::TextureUsages::RENDER_ATTACHMENT } else { wgpu::TextureUsages::empty() };
        let make = |i: usize| {
            texture_2d(
                device,
                &format!("{label} {i}"),
                (width, height, 1),
                1,
                format,
                target
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC
                    | wgpu::TextureUsages::COPY_DST,
            )
        };
        let textures = [make(0), make(1)];
        let views = [textures[0].create_view(&Default::default()), textures[1].create_view(&Default::default())];
        Self { textures, views, current: 0 }
    }

    /// Makes texture 0 current: the next pass reads it and writes texture 1. (For a chain of
    /// passes that starts afresh every frame and should end in the same texture.)
    pub fn restart(&mut self) {
        self.current = 0;
    }

    /// Index (0 or 1) of the texture that holds the latest state.
    pub fn current(&self) -> usize {
        self.current
    }

    pub fn current_view(&self) -> &wgpu::TextureView {
        &self.views[self.current]
    }

    pub fn current_texture(&self) -> &wgpu::Texture {
        &self.textures[self.current]
    }

    pub fn textures(&self) -> &[wgpu::Texture; 2] {
        &self.textures
    }

    /// The view of texture `i` (0 or 1).
    pub fn view(&self, i: usize) -> &wgpu::TextureView {
        &self.views[i]
    }

    /// One bind group per texture, built by `make` from that texture's view; pass the
    /// result to [`PingPong::run`], which picks the one that reads the current state.
    pub fn bind_groups(&self, make: impl Fn(&wgpu::TextureView) -> wgpu::BindGroup) -> [wgpu::BindGroup; 2] {
        [make(&self.views[0]), make(&self.views[1])]
    }

    /// Runs `pass` reading the current texture (through `groups[current]`) and writing the
    /// other, then makes the written one current.
    pub fn run(&mut self, encoder: &mut wgpu::CommandEncoder, pass: &FullscreenPass, groups: &[wgpu::BindGroup; 2]) {
        self.run_with(encoder, pass, groups, None);
    }

    /// [`PingPong::run`] with one more bind group (group 1) that does not depend on the side.
    pub fn run_with(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        pass: &FullscreenPass,
        groups: &[wgpu::BindGroup; 2],
        extra: Option<&wgpu::BindGroup>,
    ) {
        let next = 1 - self.current;
        match extra {
            Some(extra) => pass.run(encoder, &self.views[next], &[&groups[self.current], extra]),
            None => pass.run(encoder, &self.views[next], &[&groups[self.current]]),
        }
        self.current = next;
    }

    /// Runs `pass` over the texels `rect` (x, y, width, height) only: it reads the current
    /// texture and writes the other inside `rect`, which is then copied back, so the current
    /// texture stays current and holds the result. Costs in proportion to the rectangle.
    pub fn run_in_place(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        pass: &FullscreenPass,
        groups: &[wgpu::BindGroup; 2],
        extra: Option<&wgpu::BindGroup>,
        rect: [u32; 4],
    ) {
        let next = 1 - self.current;
        let mut bind_groups = vec![&groups[self.current]];
        bind_groups.extend(extra);
        pass.run_in_rect(encoder, &self.views[next], &bind_groups, rect);
        let [x, y, width, height] = rect;
        let at = |texture| wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d { x, y, z: 0 },
            aspect: wgpu::TextureAspect::All,
        };
        encoder.copy_texture_to_texture(
            at(&self.textures[next]),
            at(&self.textures[self.current]),
            wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        );
    }
}

/// A small buffer read back from the GPU without ever waiting: the caller records a copy
/// into it when [`AsyncReadback::is_idle`], calls [`AsyncReadback::after_submit`] once that
/// frame is submitted, and later frames [`AsyncReadback::take`] the bytes once mapping has
/// completed (one to a few frames later). At most one read is in flight.
pub struct AsyncReadback {
    buffer: wgpu::Buffer,
    /// 0 idle, 1 copy recorded, 2 mapping, 3 mapped and ready to read.
    state: std::sync::Arc<std::sync::atomic::AtomicU8>,
}

impl AsyncReadback {
    const IDLE: u8 = 0;
    const RECORDED: u8 = 1;
    const MAPPING: u8 = 2;
    const READY: u8 = 3;

    pub fn new(device: &wgpu::Device, label: &str, size: u64) -> Self {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Self { buffer, state: Default::default() }
    }

    fn state(&self) -> u8 {
        self.state.load(std::sync::atomic::Ordering::Acquire)
    }

    /// The buffer to copy into, when no read is in flight; marks the copy as recorded.
    pub fn record(&self) -> Option<&wgpu::Buffer> {
        (self.state() == Self::IDLE).then(|| {
            self.state.store(Self::RECORDED, std::sync::atomic::Ordering::Release);
            &self.buffer
        })
    }

    /// Starts mapping a copy recorded into a frame that has now been submitted.
    pub fn after_submit(&self) {
        if self.state() == Self::RECORDED {
            self.state.store(Self::MAPPING, std::sync::atomic::Ordering::Release);
            let state = self.state.clone();
            self.buffer.slice(..).map_async(wgpu::MapMode::Read, move |r| {
                let next = if r.is_ok() { Self::READY } else { Self::IDLE };
                state.store(next, std::sync::atomic::Ordering::Release);
            });
        }
    }

    /// The bytes of a completed read (then idle again), or `None` while none has completed.
    pub fn take(&self) -> Option<Vec<u8>> {
        if self.state() != Self::READY {
            return None;
        }
        let bytes = self.buffer.slice(..).get_mapped_range().ok().map(|data| data.to_vec());
        self.buffer.unmap();
        self.state.store(Self::IDLE, std::sync::atomic::Ordering::Release);
        bytes
    }
}

/// Copies a whole 2-D texture (mip 0, layer 0) back to the CPU, rows unpadded.
/// Blocking: for tests, the CLI and benchmarks, never for the frame path.
#[cfg(not(target_arch = "wasm32"))]
#[allow(clippy::disallowed_methods)]
pub fn read_texture(device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture) -> Vec<u8> {
    let width = texture.width();
    let height = texture.height();
    let bytes_per_pixel = texture.format().block_copy_size(None).expect("colour format");
    let row = width * bytes_per_pixel;
    let padded = row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: (padded * height) as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
    );
    queue.submit([encoder.finish()]);
    let slice = buffer.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map readback buffer"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("device poll");
    let data = slice.get_mapped_range().expect("mapped readback range");
    let mut out = Vec::with_capacity((row * height) as usize);
    for y in 0..height as usize {
        let start = y * padded as usize;
        out.extend_from_slice(&data[start..start + row as usize]);
    }
    drop(data);
    buffer.unmap();
    out
}
