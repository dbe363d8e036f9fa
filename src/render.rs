//! The renderer: caustics map, then one scene pass of sky, pool, sphere and the water
//! surface (from above and from below) into any colour target.

use glam::{Mat4, Vec3};
use wgpu::util::DeviceExt;

use crate::duck;
use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::scene::{self, Sphere};
use crate::sim::HeightField;
use crate::textures::{self, SkyCube};

/// Sun irradiance scale on a surface facing it (linear units; ambient sky light is ~0.35).
pub const SUN_STRENGTH: f32 = 0.8;
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Caustics map: red = light, green = light with the sphere's shadow.
pub const CAUSTICS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;
/// Caustics map where float render targets are missing: 8-bit, holding light / [`CAUSTICS_8BIT_SCALE`].
pub const CAUSTICS_FORMAT_8BIT: wgpu::TextureFormat = wgpu::TextureFormat::Rg8Unorm;
/// Light (relative to a calm surface) that the 8-bit caustics map's 1.0 stands for: focused
/// light up to 4x is kept in 1/255 steps of it, brighter lines are clipped (the tone curve
/// has flattened them by then anyway).
pub const CAUSTICS_8BIT_SCALE: f32 = 4.0;

/// Everything a frame's picture depends on besides the water state.
#[derive(Clone, Copy, Debug)]
pub struct View {
    pub view_proj: Mat4,
    /// Eye position (m).
    pub eye: Vec3,
    /// Unit vector towards the sun.
    pub sun: Vec3,
    pub sphere: Option<Sphere>,
    /// The rubber duck's pose, if it is in the pool.
    pub duck: Option<crate::physics::Pose>,
    pub caustics: bool,
    /// A view of the simulation's textures drawn over the scene, if any.
    pub debug: Option<DebugView>,
}

/// Which inner texture the debug view shows (see `shaders/debug_view.wgsl`), and where.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DebugView {
    pub texture: DebugTexture,
    /// In the lower right corner (a square of 40% of the shorter side) instead of the whole target.
    pub inset: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DebugTexture {
    Height = 1,
    Normals = 2,
    Velocity = 3,
    Caustics = 4,
}

impl DebugTexture {
    /// From the `debug_view` parameter's value (0 = none).
    pub fn from_param(value: f32) -> Option<Self> {
        match value.round() as i32 {
            1 => Some(Self::Height),
            2 => Some(Self::Normals),
            3 => Some(Self::Velocity),
            4 => Some(Self::Caustics),
            _ => None,
        }
    }
}

impl DebugView {
    /// Viewport (x, y, width, height in pixels) of the view in a target of `size` pixels.
    pub fn viewport(&self, size: (u32, u32)) -> [f32; 4] {
        let (w, h) = (size.0 as f32, size.1 as f32);
        if !self.inset {
            // The largest centred square: the pool's square stays square.
            let side = w.min(h);
            return [(w - side) / 2.0, (h - side) / 2.0, side, side];
        }
        let side = (0.4 * w.min(h)).floor();
        let margin = (0.02 * w.min(h)).floor();
        [w - side - margin, h - side - margin, side, side]
    }
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SceneUniforms {
    view_proj: [[f32; 4]; 4],
    inv_view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
    sun: [f32; 4],
    refracted_sun: [f32; 4],
    sphere: [f32; 4],
    pool: [f32; 4],
    water: [f32; 4],
    output: [f32; 4],
    duck_pose: [[f32; 4]; 4],
    duck_bound: [f32; 4],
    duck_parts: [[f32; 4]; 3 * duck::TRACED_PARTS.len()],
}

/// Renderer settings fixed at creation.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    /// Format of the colour targets it will draw into.
    pub target_format: wgpu::TextureFormat,
    /// Side of the caustics map in texels.
    pub caustics_size: u32,
    /// Quads per side of the water surface mesh. The fragment shader reads heights and
    /// normals per pixel, so this only shapes the surface's outline and parallax.
    pub surface_grid: u32,
    /// Whether the device can render (and blend) into float textures; without, the caustics
    /// map is 8-bit ([`CAUSTICS_FORMAT_8BIT`]).
    pub float_targets: bool,
}

impl RenderSettings {
    /// Format and scale (light per unit stored) of the caustics map.
    pub fn caustics_format(&self) -> (wgpu::TextureFormat, f32) {
        if self.float_targets {
            (CAUSTICS_FORMAT, 1.0)
        } else {
            (CAUSTICS_FORMAT_8BIT, CAUSTICS_8BIT_SCALE)
        }
    }
}

/// Quads per side of the mesh projected into the caustics map for a simulation of
/// `sim_size` cells per side: one quad per two cells resolves the shortest waves that make
/// caustics while keeping the triangle count, which software rasterisers pay for, low.
pub fn caustics_grid(sim_size: u32) -> u32 {
    (sim_size / 2).clamp(64, 256)
}

/// A triangle mesh in GPU buffers.
struct Mesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl Mesh {
    fn new<V: bytemuck::Pod>(device: &wgpu::Device, label: &str, vertices: &[V], indices: &[u32]) -> Self {
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let index_count = indices.len() as u32;
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self { vertices, indices, index_count }
    }

    fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }
}

/// Appends triangle (a, b, c), wound counter-clockwise when seen from the side `outward` points to.
fn push_triangle(indices: &mut Vec<u32>, positions: &[Vec3], tri: [u32; 3], outward: Vec3) {
    let [a, b, c] = tri.map(|i| positions[i as usize]);
    if (b - a).cross(c - a).dot(outward) >= 0.0 {
        indices.extend_from_slice(&tri);
    } else {
        indices.extend_from_slice(&[tri[0], tri[2], tri[1]]);
    }
}

/// The water grid: (n + 1)^2 points spanning [-1, 1]^2 in pool units, facing up.
fn water_grid(n: u32) -> (Vec<[f32; 2]>, Vec<u32>) {
    let side = n + 1;
    let vertices: Vec<[f32; 2]> = (0..side * side)
        .map(|i| [(i % side) as f32 / n as f32 * 2.0 - 1.0, (i / side) as f32 / n as f32 * 2.0 - 1.0])
        .collect();
    let positions: Vec<Vec3> = vertices.iter().map(|v| Vec3::new(v[0], 0.0, v[1])).collect();
    let mut indices = Vec::with_capacity((n * n * 6) as usize);
    for j in 0..n {
        for i in 0..n {
            let v00 = j * side + i;
            let (v10, v01, v11) = (v00 + 1, v00 + side, v00 + side + 1);
            push_triangle(&mut indices, &positions, [v00, v01, v10], Vec3::Y);
            push_triangle(&mut indices, &positions, [v10, v01, v11], Vec3::Y);
        }
    }
    (vertices, indices)
}

/// The pool's floor and four walls up to the rim, as (position, inward normal), wound to
/// face inwards so that walls between the eye and the pool are culled.
fn pool_box() -> (Vec<[f32; 6]>, Vec<u32>) {
    let (w, d, r) = (scene::HALF_WIDTH, scene::DEPTH, scene::RIM);
    let faces: [(Vec3, [Vec3; 4]); 5] = [
        (Vec3::Y, [Vec3::new(-w, -d, -w), Vec3::new(w, -d, -w), Vec3::new(w, -d, w), Vec3::new(-w, -d, w)]),
        (Vec3::X, [Vec3::new(-w, -d, -w), Vec3::new(-w, r, -w), Vec3::new(-w, r, w), Vec3::new(-w, -d, w)]),
        (Vec3::NEG_X, [Vec3::new(w, -d, -w), Vec3::new(w, r, -w), Vec3::new(w, r, w), Vec3::new(w, -d, w)]),
        (Vec3::Z, [Vec3::new(-w, -d, -w), Vec3::new(w, -d, -w), Vec3::new(w, r, -w), Vec3::new(-w, r, -w)]),
        (Vec3::NEG_Z, [Vec3::new(-w, -d, w), Vec3::new(w, -d, w), Vec3::new(w, r, w), Vec3::new(-w, r, w)]),
    ];
    let mut positions = Vec::new();
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for (normal, corners) in faces {
        let base = positions.len() as u32;
        for c in corners {
            positions.push(c);
            vertices.push([c.x, c.y, c.z, normal.x, normal.y, normal.z]);
        }
        push_triangle(&mut indices, &positions, [base, base + 1, base + 2], normal);
        push_triangle(&mut indices, &positions, [base, base + 2, base + 3], normal);
    }
    (vertices, indices)
}

/// A unit sphere (latitude-longitude), wound to face outwards.
fn unit_sphere(stacks: u32, slices: u32) -> (Vec<[f32; 3]>, Vec<u32>) {
    let mut positions = Vec::new();
    for i in 0..=stacks {
        let theta = std::f32::consts::PI * i as f32 / stacks as f32;
        for j in 0..=slices {
            let phi = std::f32::consts::TAU * j as f32 / slices as f32;
            positions.push(Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin()));
        }
    }
    let row = slices + 1;
    let mut indices = Vec::new();
    for i in 0..stacks {
        for j in 0..slices {
            let a = i * row + j;
            let (b, c, e) = (a + 1, a + row, a + row + 1);
            for tri in [[a, c, b], [b, c, e]] {
                let centre = tri.iter().map(|&k| positions[k as usize]).sum::<Vec3>();
                let [p, q, s] = tri.map(|k| positions[k as usize]);
                if (q - p).cross(s - p).length_squared() > 1e-12 {
                    push_triangle(&mut indices, &positions, tri, centre);
                }
            }
        }
    }
    (positions.iter().map(|p| p.to_array()).collect(), indices)
}

/// The duck's traced parts as the scene shader takes them: per part its centre and semi-axes
/// in the duck's frame (m), and its colour.
fn duck_parts() -> [[f32; 4]; 3 * duck::TRACED_PARTS.len()] {
    let mut out = [[0.0; 4]; 3 * duck::TRACED_PARTS.len()];
    for (slots, part) in out.chunks_mut(3).zip(&duck::TRACED_PARTS) {
        slots[0] = part.shape.centre.extend(0.0).to_array();
        slots[1] = part.shape.radii.extend(0.0).to_array();
        slots[2] = part.colour.extend(1.0).to_array();
    }
    out
}

/// The caustics map and the pipeline that draws a water grid (see [`caustics_grid`]) into it.
pub struct CausticsPass {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    pipeline: wgpu::RenderPipeline,
    grid: Mesh,
    /// Quads per side of `grid`.
    grid_size: u32,
}

impl CausticsPass {
    fn new(
        device: &wgpu::Device,
        size: u32,
        format: wgpu::TextureFormat,
        sim_size: u32,
        water_layout: &wgpu::BindGroupLayout,
    ) -> Self {
        let texture = gpu::texture_2d(
            device,
            "caustics map",
            size,
            size,
            1,
            1,
            format,
            wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
        );
        let view = texture.create_view(&Default::default());
        let module = gpu::shader(device, "caustics", &[gpu::wgsl::COMMON, gpu::wgsl::SCENE, gpu::wgsl::CAUSTICS]);
        let additive = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let pipeline = mesh_pipeline(
            device,
            MeshPipeline {
                label: "caustics",
                module: &module,
                vertex_entry: "vs_caustics",
                fragment_entry: "fs_caustics",
                layouts: &[water_layout],
                attributes: &wgpu::vertex_attr_array![0 => Float32x2],
                stride: 8,
                cull: None,
                format,
                blend: Some(wgpu::BlendState { color: additive, alpha: additive }),
                depth: false,
            },
        );
        let grid_size = caustics_grid(sim_size);
        let (grid_vertices, grid_indices) = water_grid(grid_size);
        let grid = Mesh::new(device, "caustics grid", &grid_vertices, &grid_indices);
        Self { texture, view, pipeline, grid, grid_size }
    }

    /// The caustics map texture (for tests and debug views).
    pub fn texture(&self) -> &wgpu::Texture {
        &self.texture
    }
}

struct MeshPipeline<'a> {
    label: &'a str,
    module: &'a wgpu::ShaderModule,
    vertex_entry: &'a str,
    fragment_entry: &'a str,
    layouts: &'a [&'a wgpu::BindGroupLayout],
    attributes: &'a [wgpu::VertexAttribute],
    stride: u64,
    cull: Option<wgpu::Face>,
    format: wgpu::TextureFormat,
    blend: Option<wgpu::BlendState>,
    /// Depth-tested and written against [`DEPTH_FORMAT`].
    depth: bool,
}

fn mesh_pipeline(device: &wgpu::Device, p: MeshPipeline<'_>) -> wgpu::RenderPipeline {
    let layout = gpu::pipeline_layout(device, p.label, p.layouts);
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(p.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: p.module,
            entry_point: Some(p.vertex_entry),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: p.stride,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: p.attributes,
            })],
        },
        primitive: wgpu::PrimitiveState { cull_mode: p.cull, ..Default::default() },
        depth_stencil: p.depth.then(|| wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: p.module,
            entry_point: Some(p.fragment_entry),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: p.format,
                blend: p.blend,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

struct DepthBuffer {
    view: wgpu::TextureView,
    size: (u32, u32),
}

/// Draws the pool scene. Holds the pipelines, meshes, textures and bind groups.
pub struct Renderer {
    settings: RenderSettings,
    uniforms: wgpu::Buffer,
    water_layout: wgpu::BindGroupLayout,
    /// Scene uniforms + water state, one per ping-pong texture.
    water_groups: [wgpu::BindGroup; 2],
    textures_group: wgpu::BindGroup,
    caustics: CausticsPass,
    sky_cube: SkyCube,
    sky: FullscreenPass,
    pool: wgpu::RenderPipeline,
    sphere: wgpu::RenderPipeline,
    /// The water surface, both sides in one draw.
    surface: wgpu::RenderPipeline,
    debug: FullscreenPass,
    grid: Mesh,
    pool_mesh: Mesh,
    sphere_mesh: Mesh,
    duck: wgpu::RenderPipeline,
    duck_mesh: Mesh,
    depth: Option<DepthBuffer>,
}

/// The scene uniforms with each of the water's two state textures (group 0 of every scene pass).
fn water_bind_groups(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    water: &HeightField,
) -> [wgpu::BindGroup; 2] {
    water.state().bind_groups(|view| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene + water"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(view) },
            ],
        })
    })
}

impl Renderer {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: RenderSettings, water: &HeightField) -> Self {
        let vis = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let water_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene + water layout"),
            entries: &[
                gpu::uniform_entry(0, vis),
                gpu::texture_entry(
                    1,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: false },
                    wgpu::TextureViewDimension::D2,
                ),
            ],
        });
        let textures_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene textures layout"),
            entries: &[
                gpu::texture_entry(
                    0,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: true },
                    wgpu::TextureViewDimension::D2,
                ),
                gpu::texture_entry(
                    1,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: true },
                    wgpu::TextureViewDimension::D2,
                ),
                gpu::texture_entry(
                    2,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: true },
                    wgpu::TextureViewDimension::Cube,
                ),
                gpu::sampler_entry(3, vis),
                gpu::sampler_entry(4, vis),
            ],
        });
        let uniforms = gpu::uniform_buffer(device, "scene uniforms", &<SceneUniforms as bytemuck::Zeroable>::zeroed());
        let water_groups = water_bind_groups(device, &water_layout, &uniforms, water);
        let caustics = CausticsPass::new(
            device,
            settings.caustics_size,
            settings.caustics_format().0,
            water.size(),
            &water_layout,
        );
        let sky_cube = SkyCube::new(device);
        let tiles = textures::create_tile_texture(device, queue);
        let sampler = |address: wgpu::AddressMode| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                address_mode_u: address,
                address_mode_v: address,
                address_mode_w: address,
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                // Nearest mip level: the level is chosen per pixel already (tile_lod), and
                // trilinear filtering costs software rasterisers twice the texel reads.
                mipmap_filter: wgpu::MipmapFilterMode::Nearest,
                ..Default::default()
            })
        };
        let textures_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene textures"),
            layout: &textures_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&caustics.view) },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&tiles.create_view(&Default::default())),
                },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&sky_cube.view()) },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::Sampler(&sampler(wgpu::AddressMode::ClampToEdge)),
                },
                wgpu::BindGroupEntry {
                    binding: 4,
                    resource: wgpu::BindingResource::Sampler(&sampler(wgpu::AddressMode::Repeat)),
                },
            ],
        });

        let layouts = [&water_layout, &textures_layout];
        let format = settings.target_format;
        let sky = FullscreenPass::new(
            device,
            "sky",
            &[gpu::wgsl::SCENE, gpu::wgsl::SKY],
            "fs_sky",
            &layouts,
            FullscreenTarget { format, blend: None, depth: Some(DEPTH_FORMAT) },
        );
        let debug = FullscreenPass::new(
            device,
            "debug view",
            &[gpu::wgsl::SCENE, gpu::wgsl::DEBUG_VIEW],
            "fs_debug",
            &layouts,
            FullscreenTarget { format, blend: None, depth: None },
        );
        let pool_module = gpu::shader(device, "pool", &[gpu::wgsl::COMMON, gpu::wgsl::SCENE, gpu::wgsl::POOL]);
        let sphere_module = gpu::shader(device, "sphere", &[gpu::wgsl::COMMON, gpu::wgsl::SCENE, gpu::wgsl::SPHERE]);
        let water_module =
            gpu::shader(device, "water surface", &[gpu::wgsl::COMMON, gpu::wgsl::SCENE, gpu::wgsl::WATER]);
        let scene_pipeline = |label, module, vs, fs, attributes: &[wgpu::VertexAttribute], stride, cull| {
            mesh_pipeline(
                device,
                MeshPipeline {
                    label,
                    module,
                    vertex_entry: vs,
                    fragment_entry: fs,
                    layouts: &layouts,
                    attributes,
                    stride,
                    cull,
                    format,
                    blend: None,
                    depth: true,
                },
            )
        };
        let pool = scene_pipeline(
            "pool",
            &pool_module,
            "vs_pool",
            "fs_pool",
            &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
            24,
            Some(wgpu::Face::Back),
        );
        let sphere = scene_pipeline(
            "sphere",
            &sphere_module,
            "vs_sphere",
            "fs_sphere",
            &wgpu::vertex_attr_array![0 => Float32x3],
            12,
            Some(wgpu::Face::Back),
        );
        let duck_module = gpu::shader(device, "duck", &[gpu::wgsl::COMMON, gpu::wgsl::SCENE, gpu::wgsl::DUCK]);
        let duck = scene_pipeline(
            "duck",
            &duck_module,
            "vs_duck",
            "fs_duck",
            &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3],
            36,
            Some(wgpu::Face::Back),
        );
        let grid_attrs = wgpu::vertex_attr_array![0 => Float32x2];
        // Culling off: front faces are the surface seen from above, back faces from below.
        let surface = scene_pipeline("water surface", &water_module, "vs_surface", "fs_surface", &grid_attrs, 8, None);

        let (grid_vertices, grid_indices) = water_grid(settings.surface_grid.clamp(8, 1024));
        let (pool_vertices, pool_indices) = pool_box();
        let (sphere_vertices, sphere_indices) = unit_sphere(24, 48);
        let (duck_vertices, duck_indices) = duck::mesh();
        Self {
            settings,
            uniforms,
            water_layout,
            water_groups,
            textures_group,
            caustics,
            sky_cube,
            sky,
            pool,
            sphere,
            surface,
            debug,
            grid: Mesh::new(device, "water grid", &grid_vertices, &grid_indices),
            pool_mesh: Mesh::new(device, "pool", &pool_vertices, &pool_indices),
            sphere_mesh: Mesh::new(device, "sphere", &sphere_vertices, &sphere_indices),
            duck,
            duck_mesh: Mesh::new(device, "duck", &duck_vertices, &duck_indices),
            depth: None,
        }
    }

    pub fn settings(&self) -> RenderSettings {
        self.settings
    }

    pub fn caustics(&self) -> &CausticsPass {
        &self.caustics
    }

    /// Rebinds the water state textures (after the heightfield was replaced).
    /// Points the renderer at another heightfield (after a change of resolution); the caustics
    /// mesh follows the new simulation size.
    pub fn rebind_water(&mut self, device: &wgpu::Device, water: &HeightField) {
        let grid_size = caustics_grid(water.size());
        if grid_size != self.caustics.grid_size {
            let (vertices, indices) = water_grid(grid_size);
            self.caustics.grid = Mesh::new(device, "caustics grid", &vertices, &indices);
            self.caustics.grid_size = grid_size;
        }
        self.water_groups = water_bind_groups(device, &self.water_layout, &self.uniforms, water);
    }

    /// Writes this frame's uniforms and repaints the sky if the sun moved.
    /// Call once per submission, before [`Renderer::encode_caustics`] and [`Renderer::encode_scene`].
    pub fn prepare(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        let sphere = view.sphere.map_or([0.0; 4], |s| [s.centre.x, s.centre.y, s.centre.z, s.radius]);
        let refracted = scene::refracted_sun(view.sun);
        let n = water.size() as f32;
        let u = SceneUniforms {
            view_proj: view.view_proj.to_cols_array_2d(),
            inv_view_proj: view.view_proj.inverse().to_cols_array_2d(),
            eye: view.eye.extend(1.0).to_array(),
            sun: [view.sun.x, view.sun.y, view.sun.z, SUN_STRENGTH],
            refracted_sun: refracted.extend(0.0).to_array(),
            sphere,
            pool: [scene::HALF_WIDTH, scene::DEPTH, scene::RIM, scene::IOR_WATER],
            water: [n, 1.0 / n, if view.caustics { 1.0 } else { 0.0 }, self.settings.caustics_format().1],
            output: [
                if self.settings.target_format.is_srgb() { 0.0 } else { 1.0 },
                view.debug.map_or(0.0, |d| d.texture as u32 as f32),
                0.0,
                0.0,
            ],
            duck_pose: view
                .duck
                .map_or(Mat4::IDENTITY, |p| Mat4::from_rotation_translation(p.rotation, p.position))
                .to_cols_array_2d(),
            duck_bound: view.duck.map_or([0.0; 4], |p| p.position.extend(duck::bounding_radius()).to_array()),
            duck_parts: duck_parts(),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
        self.sky_cube.update(queue, encoder, view.sun);
    }

    /// Projects the water grid along the refracted sunlight into the caustics map.
    pub fn encode_caustics(&self, encoder: &mut wgpu::CommandEncoder, view: &View, water: &HeightField) {
        if !view.caustics {
            return;
        }
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("caustics"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.caustics.view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&self.caustics.pipeline);
        pass.set_bind_group(0, Some(&self.water_groups[water.state().current()]), &[]);
        self.caustics.grid.draw(&mut pass);
    }

    fn depth_view(&mut self, device: &wgpu::Device, size: (u32, u32)) -> &wgpu::TextureView {
        if self.depth.as_ref().map(|d| d.size) != Some(size) {
            let texture = gpu::texture_2d(
                device,
                "depth",
                size.0.max(1),
                size.1.max(1),
                1,
                1,
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            );
            self.depth = Some(DepthBuffer { view: texture.create_view(&Default::default()), size });
        }
        &self.depth.as_ref().expect("depth buffer just made").view
    }

    /// Draws sky, pool, sphere and water into `target` (of `size` pixels).
    pub fn encode_scene(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        view: &View,
        water: &HeightField,
    ) {
        let depth = self.depth_view(device, size).clone();
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("scene"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::BLACK), store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        // Front to back, so early depth testing skips what the water and sphere hide;
        // the sky last, only where nothing else was drawn.
        let water_group = &self.water_groups[water.state().current()];
        pass.set_bind_group(0, Some(water_group), &[]);
        pass.set_bind_group(1, Some(&self.textures_group), &[]);
        pass.set_pipeline(&self.surface);
        self.grid.draw(&mut pass);
        if view.sphere.is_some() {
            pass.set_pipeline(&self.sphere);
            self.sphere_mesh.draw(&mut pass);
        }
        if view.duck.is_some() {
            pass.set_pipeline(&self.duck);
            self.duck_mesh.draw(&mut pass);
        }
        pass.set_pipeline(&self.pool);
        self.pool_mesh.draw(&mut pass);
        self.sky.draw(&mut pass, &[water_group, &self.textures_group]);
        drop(pass);
        if let Some(debug) = view.debug {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("debug view"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            let [x, y, w, h] = debug.viewport(size);
            pass.set_viewport(x, y, w, h, 0.0, 1.0);
            self.debug.draw(&mut pass, &[water_group, &self.textures_group]);
        }
    }
}
