//! The tank's picture: the lamp's image on the screen below (`shaders/tank/screen.wgsl`, the
//! surface's cells drawn where their light lands, summed) and the view of the tray's plane
//! through the orbit camera (`shaders/tank/show.wgsl`).

use bytemuck::Zeroable;
use glam::Mat4;

use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::scenes::STEP_DT;
use crate::tank::gpu::TankWater;
use crate::tank::{Look, TankSettings, TankView, LINE_WIDTH, MAX_DIPPERS, MAX_LINES, PROBE_SAMPLES, SCREEN_BELOW};

/// Texels along each side of the screen's image.
pub const SCREEN_TEXELS: u32 = 512;
/// Cells between the points of the surface's mesh the screen's image is drawn with: every
/// other cell keeps about seven points to a wavelength at the default 10 Hz, and draws a
/// quarter of the triangles (lavapipe's cost is per triangle: 39 ms a frame with every cell).
pub const SCREEN_MESH_STEP: u32 = 2;
/// How far past the tray's shadow the screen's image reaches (a share of it).
const SCREEN_MARGIN: f32 = 1.1;
/// The tray's frame: its outer edge as a share of the tray's half width (seen from above and
/// in the apparatus alike).
const FRAME_SHARE: f32 = 1.03;
/// The screen's light for flat water at the middle is 1; shown as paper * (1 - exp(-k light))
/// with k this times the exposure, so flat water is a dim grey and the crests' lines bright.
const SCREEN_EXPOSURE: f32 = 0.45;
/// Where the device cannot blend into float textures, light is stored in 8 bits at this scale.
const LOW_PRECISION_SCALE: f32 = 0.25;

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct PictureUniforms {
    inverse_view_proj: [[f32; 4]; 4],
    mesh: [f32; 4],
    tray: [f32; 4],
    screen: [f32; 4],
    view: [f32; 4],
    lines: [f32; 4],
    line_angles: [[f32; 4]; MAX_LINES / 4],
    probe: [f32; 4],
    trace: [f32; 4],
    graph: [f32; 4],
    ruler: [f32; 4],
    apparatus_inverse_view_proj: [[f32; 4]; 4],
    halves: [f32; 4],
    dippers: [[f32; 4]; MAX_DIPPERS],
    bar: [f32; 4],
}

/// What the picture shows beyond the settings: the camera's view-projection, the view and the
/// exposure of the screen's light.
pub struct Shot {
    /// The screen view's camera, and the apparatus's.
    pub view_proj: Mat4,
    pub apparatus_view_proj: Mat4,
    pub look: Look,
    pub view: TankView,
    pub exposure: f32,
    /// The slits' lines to draw: where they start (z, m) and their directions (rad from +z
    /// towards +x), if asked.
    pub lines: Option<(f32, Vec<f32>)>,
    /// The probe, if in: its place (x, z in m) and the swing it reads (m).
    pub probe: Option<((f32, f32), f32)>,
    /// The intensity graph, if drawn: its line's z (m) and the intensity's peak along it (m²).
    pub graph: Option<(f32, f32)>,
    /// The ruler, if laid.
    pub ruler: Option<super::Ruler>,
    /// Where the sources stand, for the apparatus: each dipper's x, z and radius (m), and the
    /// bar's z, half thickness and half length (m), if there is one.
    pub dippers: Vec<[f32; 3]>,
    pub bar: Option<[f32; 3]>,
}

/// The tank's two passes, their uniforms and the screen's image.
pub struct TankPicture {
    uniforms: wgpu::Buffer,
    layout: wgpu::BindGroupLayout,
    screen_pipeline: wgpu::RenderPipeline,
    /// The surface's mesh: a point per cell (its place, -1 to 1), and its triangles' indices.
    mesh: (wgpu::Buffer, wgpu::Buffer, u32),
    screen_image: wgpu::Texture,
    screen_view: wgpu::TextureView,
    image_group: wgpu::BindGroup,
    show: FullscreenPass,
    /// The apparatus in 3D, made when first shown.
    apparatus: Option<FullscreenPass>,
    layouts: [wgpu::BindGroupLayout; 2],
    numbers: String,
    target_format: wgpu::TextureFormat,
    /// What one unit of light is stored as in the screen's image.
    scale: f32,
}

impl TankPicture {
    /// The passes for a target of `target_format` and water of `cells` per side; the screen's
    /// image in half floats where the device renders into float textures (`float_targets`).
    pub fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat, cells: u32, float_targets: bool) -> Self {
        let stage = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("tank picture layout"),
            entries: &[
                gpu::uniform_entry(0, stage),
                gpu::float_texture_entry(1, stage),
                gpu::float_texture_entry(2, stage),
                gpu::float_texture_entry(3, stage),
            ],
        });
        let image_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("tank screen image layout"),
            entries: &[
                gpu::filtered_texture_entry(0, wgpu::ShaderStages::FRAGMENT),
                gpu::sampler_entry(1, wgpu::ShaderStages::FRAGMENT),
            ],
        });
        let (image, screen_view, image_group, scale) = screen_image(device, &image_layout, float_targets);
        let numbers = shader_numbers(target_format);
        let picture = crate::wgsl!("tank/picture.wgsl");
        let format = image.format();
        let screen_pipeline = screen_pipeline(device, &layout, &numbers, format);
        let show = FullscreenPass::new(
            device,
            "tank picture",
            &[
                gpu::wgsl::MATH,
                &numbers,
                picture,
                crate::wgsl!("tank/paper.wgsl"),
                crate::wgsl!("tank/instruments.wgsl"),
                crate::wgsl!("tank/show.wgsl"),
            ],
            "fs_show",
            &[&layout, &image_layout],
            FullscreenTarget { format: target_format, blend: None, depth: None },
        );
        let uniforms = gpu::uniform_buffer(device, "tank picture", &PictureUniforms::zeroed());
        Self {
            uniforms,
            layout: layout.clone(),
            screen_pipeline,
            mesh: surface_mesh(device, cells),
            screen_image: image,
            screen_view,
            image_group,
            show,
            apparatus: None,
            layouts: [layout, image_layout],
            numbers,
            target_format,
            scale,
        }
    }
    /// The screen's image: light per texel (1 for flat water under the lamp) times
    /// [`TankPicture::scale`], the screen's +z side in its first rows; its half extent on the
    /// screen is [`TankPicture::screen_half_extent`].
    pub fn screen_image(&self) -> &wgpu::Texture {
        &self.screen_image
    }

    /// What one unit of light is stored as in the screen's image.
    pub fn scale(&self) -> f32 {
        self.scale
    }

    /// The screen image's half extent on the screen (m) for `settings`.
    pub fn screen_half_extent(settings: &TankSettings) -> f32 {
        settings.half_width() * settings.magnification() * SCREEN_MARGIN
    }

    /// Records the screen's image (in the screen view) into `encoder`; call before
    /// [`TankPicture::encode_show`].
    pub fn encode_screen(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        water: &TankWater,
        settings: &TankSettings,
        shot: &Shot,
    ) -> wgpu::BindGroup {
        let mut uniforms = PictureUniforms {
            inverse_view_proj: shot.view_proj.inverse().to_cols_array_2d(),
            mesh: [(water.cells() / SCREEN_MESH_STEP) as f32, SCREEN_MESH_STEP as f32, 0.0, 0.0],
            tray: [settings.half_width(), settings.depth, settings.lamp_height, SCREEN_BELOW],
            screen: [Self::screen_half_extent(settings), settings.magnification(), water.cells() as f32, self.scale],
            view: [shot.view.value(), settings.amplitude, shot.exposure * SCREEN_EXPOSURE, SCREEN_TEXELS as f32],
            lines: [0.0; 4],
            line_angles: [[0.0; 4]; MAX_LINES / 4],
            probe: [0.0; 4],
            trace: [0.0, 0.0, PROBE_SAMPLES as f32, STEP_DT],
            graph: [0.0; 4],
            ruler: [0.0; 4],
            apparatus_inverse_view_proj: shot.apparatus_view_proj.inverse().to_cols_array_2d(),
            halves: if shot.look == Look::Split { [0.0, 0.5, 0.5, 0.5] } else { [0.0, 1.0, 0.0, 1.0] },
            dippers: [[0.0; 4]; MAX_DIPPERS],
            bar: [0.0; 4],
        };
        for (slot, [x, z, r]) in uniforms.dippers.iter_mut().zip(&shot.dippers) {
            *slot = [*x, *z, *r, 1.0];
        }
        if let Some([z, half_thickness, half_length]) = shot.bar {
            uniforms.bar = [z, half_thickness, half_length, 1.0];
        }
        if let Some(((x, z), swing)) = shot.probe {
            // The graph's half height: the swing read, at least half the dippers' amplitude.
            uniforms.probe = [x, z, 1.0, swing.max(0.5 * settings.amplitude) * 1.1];
            let (newest, held) = water.probe_newest();
            uniforms.trace[..2].copy_from_slice(&[newest as f32, held as f32]);
        }
        if let Some((z, peak)) = shot.graph {
            // At least a hundredth of the dippers' intensity, so still water draws a flat graph.
            uniforms.graph = [z, 1.0, peak.max(0.01 * settings.amplitude.powi(2)), 0.0];
        }
        if let Some((a, b)) = shot.ruler {
            uniforms.graph[3] = 1.0;
            uniforms.ruler = [a.0, a.1, b.0, b.1];
        }
        if let Some((z, angles)) = &shot.lines {
            let count = angles.len().min(MAX_LINES);
            uniforms.lines = [count as f32, *z, 0.0, 0.0];
            for (k, a) in angles.iter().take(count).enumerate() {
                uniforms.line_angles[k / 4][k % 4] = *a;
            }
        }
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("tank picture"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: self.uniforms.as_entire_binding() },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(water.shown_view(settings.strobe > 0.0)),
                },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(water.medium_view()) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(water.probe_view()) },
            ],
        });
        if shot.look != Look::Screen && self.apparatus.is_none() {
            self.apparatus = Some(self.apparatus_pass(device));
        }
        if shot.view == TankView::Screen || shot.look != Look::Screen {
            let mut pass =
                gpu::colour_pass(encoder, "tank screen", &self.screen_view, wgpu::LoadOp::Clear(wgpu::Color::BLACK));
            pass.set_pipeline(&self.screen_pipeline);
            pass.set_bind_group(0, Some(&group), &[]);
            let (points, indices, count) = &self.mesh;
            pass.set_vertex_buffer(0, points.slice(..));
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*count, 0, 0..1);
        }
        group
    }

    /// Draws the picture over the whole of `target` (`size` pixels) with the group
    /// [`TankPicture::encode_screen`] made: the screen view, the apparatus, or the apparatus on
    /// the left and the screen view on the right.
    pub fn encode_show(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        group: &wgpu::BindGroup,
        look: Look,
        (width, height): (u32, u32),
    ) {
        let groups = [group, &self.image_group];
        let apparatus = self.apparatus.as_ref().filter(|_| look != Look::Screen);
        match (look, apparatus) {
            (Look::Apparatus, Some(pass)) => pass.run(encoder, target, &groups),
            (Look::Split, Some(pass)) => {
                let half = width / 2;
                pass.run_in_rect(encoder, target, &groups, [0, 0, half, height]);
                self.show.run_in_rect(encoder, target, &groups, [half, 0, width - half, height]);
            }
            _ => self.show.run(encoder, target, &groups),
        }
    }

    /// The apparatus's pass (`shaders/tank/apparatus.wgsl`).
    fn apparatus_pass(&self, device: &wgpu::Device) -> FullscreenPass {
        let parts = [
            gpu::wgsl::MATH,
            &self.numbers,
            crate::render::COMMON,
            crate::wgsl!("tank/picture.wgsl"),
            crate::wgsl!("tank/paper.wgsl"),
            crate::wgsl!("tank/rays.wgsl"),
            crate::wgsl!("tank/apparatus.wgsl"),
        ];
        let [layout, image_layout] = &self.layouts;
        let target = FullscreenTarget { format: self.target_format, blend: None, depth: None };
        FullscreenPass::new(device, "tank apparatus", &parts, "fs_apparatus", &[layout, image_layout], target)
    }
}

/// The screen pass's pipeline: the surface's mesh (a point: its place, two floats) drawn into
/// the screen's image of `format`, adding up (`numbers`: the picture's WGSL constants).
fn screen_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    numbers: &str,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let parts = [gpu::wgsl::MATH, numbers, crate::wgsl!("tank/picture.wgsl"), crate::wgsl!("tank/screen.wgsl")];
    let module = gpu::shader(device, "tank screen", &parts);
    let additive = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Add,
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("tank screen"),
        layout: Some(&gpu::pipeline_layout(device, "tank screen", &[layout])),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs_screen"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: 8,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x2],
            })],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs_screen"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState { color: additive, alpha: additive }),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// The screen's image (light per texel, in half floats where the device renders into float
/// textures, else 8 bits with the light scaled), its view, the bind group the pictures sample
/// it through (`layout`), and what one unit of light is stored as.
fn screen_image(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    float_targets: bool,
) -> (wgpu::Texture, wgpu::TextureView, wgpu::BindGroup, f32) {
    let (format, scale) = if float_targets {
        (wgpu::TextureFormat::Rgba16Float, 1.0)
    } else {
        (wgpu::TextureFormat::Rgba8Unorm, LOW_PRECISION_SCALE)
    };
    let image = gpu::texture_2d(
        device,
        "tank screen image",
        (SCREEN_TEXELS, SCREEN_TEXELS, 1),
        1,
        format,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC,
    );
    let view = image.create_view(&Default::default());
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        ..Default::default()
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("tank screen image"),
        layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&sampler) },
        ],
    });
    (image, view, group, scale)
}

/// The constants the tank's shaders share, for a target of `target_format`.
fn shader_numbers(target_format: wgpu::TextureFormat) -> String {
    format!(
        "const IOR_WATER: f32 = {:?};\nconst ENCODE_SRGB: bool = {};\nconst LINE_WIDTH: f32 = {LINE_WIDTH:?};\nconst LINE_VECS: u32 = {}u;\nconst FRAME_SHARE: f32 = {FRAME_SHARE:?};\nconst MAX_DIPPERS: u32 = {MAX_DIPPERS}u;\n",
        crate::world::IOR_WATER,
        !target_format.is_srgb(),
        MAX_LINES / 4
    ) + &crate::tank::medium::kind_constants()
}

/// The surface's mesh for water of `cells` per side: a point every [`SCREEN_MESH_STEP`] cells
/// (its place, -1 to 1), and its triangles' indices.
fn surface_mesh(device: &wgpu::Device, cells: u32) -> (wgpu::Buffer, wgpu::Buffer, u32) {
    let (points, indices) = crate::render::scene_parts::banded_grid(cells / SCREEN_MESH_STEP - 1);
    let buffer = |label: &str, contents: &[u8], usage| {
        wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage },
        )
    };
    (
        buffer("tank surface points", bytemuck::cast_slice(&points), wgpu::BufferUsages::VERTEX),
        buffer("tank surface triangles", bytemuck::cast_slice(&indices), wgpu::BufferUsages::INDEX),
        indices.len() as u32,
    )
}
