//! Drawing the open sea (`shaders/sea/sea.wgsl`): the projected grid, which has no vertex buffer
//! (its vertices come from their index, a cell about every [`GRID_CELL_PX`] pixels), and the
//! sky pass behind it. The grid covers the screen from a margin below its bottom edge up to
//! the horizon of [`GRID_FAR`]; the margin is what the largest waves can pull the grid's edge
//! in by, so the moved edge never uncovers the background. The cascades' maps are filled
//! each frame from the GPU's FFT or the CPU's (`lattices.rs`). The sea's passes, its own: the
//! renderer lends it the scene uniforms, the textures, the depth target and the upscaler
//! (`render::scene_parts`).

use glam::{Vec2, Vec3};

mod bodies;
mod foam;
mod island;
mod lattices;

use crate::camera::OrbitCamera;
use crate::gpu::{self, FrameContext, FullscreenPass, FullscreenTarget};
use crate::render::scene_parts::{begin_scene_pass, scene_prelude_in, water_bind_groups, DepthUse, DEPTH_FORMAT};
use crate::render::{Features, Renderer, View};
use crate::sea::{SeaVariant, FOG_HEIGHT, GRID_CELL_PX, GRID_FAR, GRID_MAX_CELLS};
use crate::sim::HeightField;
use foam::{no_map, WhitecapMaps};
use island::{cells_showing, island_map, mesh_pipeline, IslandDrawing, IslandPipelines, MirrorTarget, MIRROR_SCALE};
use lattices::LatticeMaps;
pub use lattices::SeaLattices;

/// Cascades the sea's shader sums (`CASCADES` in shaders/sea/sea.wgsl).
pub const SEA_CASCADES: usize = crate::ambient::cascades::CASCADE_COUNT;
/// The most the grid reaches past the screen's edges (NDC): a camera low over a storm asks
/// about one screen; past that the cells spread thin.
const MAX_GRID_MARGIN: f32 = 1.5;

const WGSL: &str = crate::wgsl!("sea/sea.wgsl");
const ISLAND_WGSL: &str = crate::wgsl!("sea/island.wgsl");
const ISLAND_EDGE_WGSL: &str = crate::wgsl!("sea/island_edge.wgsl");
const LAND_WGSL: &str = crate::wgsl!("sea/land.wgsl");
const FOAM_WGSL: &str = crate::wgsl!("sea/foam.wgsl");
const WAVES_WGSL: &str = crate::wgsl!("sea/waves.wgsl");

/// What a frame of the sea depends on besides the scene's [`View`].
pub struct SeaView<'a> {
    pub camera: &'a OrbitCamera,
    /// The fog's distance at sea level (m); `None`: no fog.
    pub fog_distance: Option<f32>,
    /// The band under the horizon (rad) where the sea takes the sky's haze
    /// (`sea::horizon_haze_band`).
    pub horizon_band: f32,
    /// Choppiness λ the displacement maps are carried by.
    pub choppiness: f32,
    /// About the highest crest above the mean level (m).
    pub crest: f32,
    /// Per cascade: its turn from the world's axes (rad), its tile (m), its slopes' variance.
    pub cascades: [(f32, f32, f32); SEA_CASCADES],
    /// The cascades' lattices at this frame's time, from the GPU's FFT or the CPU's.
    pub lattices: SeaLattices<'a>,
    /// Whether whitecaps and the shore's foam are drawn (off only for tests to compare with).
    pub whitecaps: bool,
    pub shore_foam: bool,
    /// Whether the island stands in the sea, the grid's cells are outlined, the whitecaps kept
    /// (where the device renders into float textures).
    pub variant: SeaVariant,
    /// How much of the kept whitecaps' foam is left after this frame's fixed steps (0-1).
    pub whitecaps_kept: f32,
    /// The patch of simulated water round the target (`sea::PATCH_HALF_WIDTH`), whose
    /// ripples are added to the waves.
    pub patch: &'a HeightField,
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SeaUniforms {
    eye: [f32; 4],
    right: [f32; 4],
    up: [f32; 4],
    forward: [f32; 4],
    grid: [f32; 4],
    cells: [f32; 4],
    waves: [f32; 4],
    foam: [f32; 4],
    mirror: [f32; 4],
    fog: [f32; 4],
    cascades: [[f32; 4]; SEA_CASCADES],
}

/// The sea's pipelines and maps, made the first time the sea is drawn.
pub struct SeaRenderer {
    uniforms: wgpu::Buffer,
    lattices: LatticeMaps,
    group: wgpu::BindGroup,
    /// The feature set (optics models) and the sea's variant the pipelines were built for.
    features: Features,
    variant: SeaVariant,
    grid: wgpu::RenderPipeline,
    /// Per kind of body, its pipelines if the kind is in the sea.
    bodies: Vec<Option<bodies::BodyPipelines>>,
    /// The grid's cells near the bodies, which mirror them, when the variant does: away from
    /// the island and near it.
    near_bodies: Option<[wgpu::RenderPipeline; 2]>,
    /// The island's drawing, when it is in the sea.
    island_drawing: Option<IslandDrawing>,
    /// The whitecaps kept over time, when the variant keeps them.
    whitecaps: Option<WhitecapMaps>,
    /// Group 3, what the frame made for the sea to read: the island's mirror at half the
    /// frame's size (a texel without the island) and each of the whitecap maps (one texel
    /// for both without them).
    frame_layout: wgpu::BindGroupLayout,
    mirror: MirrorTarget,
    no_whitecap_map: wgpu::TextureView,
    frame_groups: [wgpu::BindGroup; 2],
    sky: FullscreenPass,
    /// Group 0 (the scene's uniforms) with the patch's state, one per ping-pong texture.
    patch_groups: [wgpu::BindGroup; 2],
}

impl SeaRenderer {
    /// The sea's pipelines for `key` (each variant's module built here, in the order they
    /// share their parts: hence its length) around `lattices` if kept from before.
    fn new(
        renderer: &Renderer,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        key: (Features, SeaVariant),
        patch: &HeightField,
        lattices: Option<LatticeMaps>,
    ) -> Self {
        let (features, variant) = key;
        let layout = sea_layout(device);
        let uniforms = gpu::uniform_buffer(device, "sea uniforms", &<SeaUniforms as bytemuck::Zeroable>::zeroed());
        // The maps (and the FFT that fills them) outlive the pipelines.
        let lattices = lattices.unwrap_or_else(|| LatticeMaps::new(device));
        let island_map = island_map(device, queue, variant.island.is_some());
        let group = sea_group(device, &layout, &uniforms, &lattices.views(), &island_map);
        let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sea frame layout"),
            entries: &[
                gpu::filtered_texture_entry(0, wgpu::ShaderStages::FRAGMENT),
                gpu::filtered_texture_entry(1, wgpu::ShaderStages::FRAGMENT),
            ],
        });
        let format = renderer.settings().target_format;
        let base = scene_prelude_in(features, format, bodies::WGSL);
        // The plain grid's variant leaves out the island and the bodies' mirror images: the
        // rows that can show them are drawn with variants of their own.
        let prelude = |island: bool, mirrored_bodies| {
            let variant = SeaVariant { island: variant.island.filter(|_| island), mirrored_bodies, ..variant };
            let constants = [crate::sea::wgsl_constants(variant), island::wgsl_constants()];
            [base.clone(), constants.concat()].join("\n")
        };
        let [water_layout, textures_layout] = renderer.scene_layouts();
        let layouts = [water_layout, textures_layout, &layout, &frame_layout];
        let module = |island, bodies| {
            let parts = [
                gpu::wgsl::FULLSCREEN,
                &prelude(island, bodies),
                WAVES_WGSL,
                WGSL,
                ISLAND_WGSL,
                ISLAND_EDGE_WGSL,
                LAND_WGSL,
                FOAM_WGSL,
            ];
            gpu::shader(device, "sea", &parts)
        };
        let (with_frame, without_frame) = (&layouts[..], &layouts[..3]);
        let plain = module(false, false);
        let grid = IslandPipelines { layouts: [with_frame, without_frame], module: &plain, format };
        let grid = mesh_pipeline(
            device,
            &grid,
            "sea grid",
            ["vs_sea", "fs_sea"],
            (format, None, None, DepthUse::TestAndWrite),
        );
        let bodies = bodies::body_pipelines(device, &plain, with_frame, format, features.bodies);
        // The island's pipelines read the shallows and the mirror (ISLAND); the rows of the
        // grid that can show them are drawn with its own (see `IslandDrawing::rows_near`).
        let island_drawing = variant.island.map(|place| {
            let module = module(true, false);
            let pipelines = IslandPipelines { layouts: [with_frame, without_frame], module: &module, format };
            IslandDrawing::new(device, island_map, &pipelines, place)
        });
        // The cells that can show the bodies' mirror images trace them: with the island's
        // shallows and mirror where they are the island's rows as well.
        let near_bodies = |with_island: bool| {
            let module = module(with_island, true);
            let pipelines = IslandPipelines { layouts: [with_frame, without_frame], module: &module, format };
            // Blended: the water's share of a pixel at a body's waterline is its alpha.
            let blend = Some(wgpu::BlendState::ALPHA_BLENDING);
            mesh_pipeline(
                device,
                &pipelines,
                "sea near bodies",
                ["vs_sea", "fs_sea"],
                (format, None, blend, DepthUse::TestAndWrite),
            )
        };
        let near_bodies = variant.mirrored_bodies.then(|| {
            let away = near_bodies(false);
            let near = if variant.island.is_some() { near_bodies(true) } else { away.clone() };
            [away, near]
        });
        let parts = [&prelude(false, false) as &str, WAVES_WGSL, WGSL, ISLAND_WGSL, LAND_WGSL, FOAM_WGSL];
        let whitecaps = variant.whitecap_map.then(|| WhitecapMaps::new(device, &parts, &layouts));
        let sky = FullscreenTarget { format, blend: None, depth: Some(DEPTH_FORMAT) };
        let sky = FullscreenPass::new(device, "sea sky", &parts, "fs_sea_sky", &layouts, sky);
        let patch_groups =
            water_bind_groups(device, water_layout, renderer.uniforms(), patch, renderer.ambient_views());
        let (mirror, no_whitecap_map) = (MirrorTarget::new(device, (1, 1)), no_map(device));
        let frame_groups = frame_groups(device, &frame_layout, &mirror, whitecaps.as_ref(), &no_whitecap_map);
        Self {
            uniforms,
            lattices,
            group,
            features,
            variant,
            grid,
            bodies,
            near_bodies,
            island_drawing,
            whitecaps,
            frame_layout,
            mirror,
            no_whitecap_map,
            frame_groups,
            sky,
            patch_groups,
        }
    }
}

/// The grid's cells (across, up) and which of them take a variant of their own: the rows that
/// can show the island, and the columns and rows that can show the bodies' mirror images.
struct GridRuns {
    cells: (u32, u32),
    island_rows: std::ops::Range<u32>,
    body_columns: std::ops::Range<u32>,
    body_rows: std::ops::Range<u32>,
}

impl SeaRenderer {
    /// Draws the grid row by row up the screen: the bodies' variant on the cells that can show
    /// their mirror images (the columns across them in those rows), else the island's in the
    /// rows that can show the island, else the plain grid's. Six vertices a cell.
    fn draw_grid(&self, pass: &mut wgpu::RenderPass<'_>, runs: GridRuns) {
        let GridRuns { cells, island_rows, body_columns, body_rows } = runs;
        let kind = |r: u32| (body_rows.contains(&r) && !body_columns.is_empty(), island_rows.contains(&r));
        let row = cells.0 * 6;
        let mut start = 0;
        while start < cells.1 {
            let end = (start + 1..cells.1).find(|&r| kind(r) != kind(start)).unwrap_or(cells.1);
            let (near_bodies, near_island) = kind(start);
            match &self.island_drawing {
                Some(island) if near_island => island.set_shallows(pass),
                _ => pass.set_pipeline(&self.grid),
            }
            let (first, last) = (start * row, end * row);
            match &self.near_bodies {
                Some(bodies_pipelines) if near_bodies => {
                    // Each row's cells across the bodies with their variant; between them (the
                    // rest of one row and the start of the next, one run of vertices) the base.
                    let columns = (body_columns.start * 6, body_columns.end * 6);
                    let mut from = first;
                    for r in start..end {
                        pass.draw(from..r * row + columns.0, 0..1);
                        from = r * row + columns.1;
                    }
                    pass.draw(from..last, 0..1);
                    pass.set_pipeline(&bodies_pipelines[usize::from(near_island)]);
                    for r in start..end {
                        pass.draw(r * row + columns.0..r * row + columns.1, 0..1);
                    }
                }
                _ => pass.draw(first..last, 0..1),
            }
            start = end;
        }
    }
}

/// The sea's uniforms for a target of `size` pixels, the grid's layout (its screen rectangle
/// and cells) and the camera's up vector scaled to the field of view.
fn sea_uniforms(sea: &SeaView<'_>, size: (u32, u32)) -> (SeaUniforms, ([f32; 4], (u32, u32)), Vec3) {
    let (rect, cells, angle) = grid_layout(sea.camera, (sea.crest, sea.crest * sea.choppiness), size);
    let (right, up, forward) = camera_basis(sea.camera, size.0 as f32 / size.1.max(1) as f32);
    let uniforms = SeaUniforms {
        eye: sea.camera.eye().extend(1.0).to_array(),
        right: right.extend(0.0).to_array(),
        up: up.extend(0.0).to_array(),
        forward: forward.extend(0.0).to_array(),
        grid: rect,
        cells: [cells.0 as f32, cells.1 as f32, angle, 0.0],
        waves: [sea.choppiness, sea.cascades.iter().map(|c| c.2).sum(), 0.0, 0.0],
        foam: [f32::from(u8::from(sea.whitecaps)), f32::from(u8::from(sea.shore_foam)), sea.crest, sea.whitecaps_kept],
        mirror: [1.0 / size.0.max(1) as f32, 1.0 / size.1.max(1) as f32, 0.0, 0.0],
        fog: [sea.fog_distance.map_or(0.0, |d| 1.0 / d), FOG_HEIGHT, sea.horizon_band, 0.0],
        cascades: sea.cascades.map(|(turn, tile, variance)| [turn.cos(), turn.sin(), tile, variance]),
    };
    (uniforms, (rect, cells), up)
}

/// The layout of the sea's group 2: its uniforms, the cascades' maps, the island's map.
fn sea_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let vis = wgpu::ShaderStages::VERTEX_FRAGMENT;
    let filterable = wgpu::TextureSampleType::Float { filterable: true };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("sea layout"),
        entries: &[
            gpu::uniform_entry(0, vis),
            layers_entry(1),
            layers_entry(2),
            gpu::texture_entry(3, vis, filterable, wgpu::TextureViewDimension::D2),
        ],
    })
}

fn sea_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    views: &[wgpu::TextureView; 2],
    island_map: &wgpu::Texture,
) -> wgpu::BindGroup {
    let island_view = island_map.create_view(&Default::default());
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("sea"),
        layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&views[0]) },
            wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&views[1]) },
            wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(&island_view) },
        ],
    })
}

/// The sea's group 3 reading the mirror and each whitecap map in turn.
fn frame_groups(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    mirror: &MirrorTarget,
    whitecaps: Option<&WhitecapMaps>,
    no_map: &wgpu::TextureView,
) -> [wgpu::BindGroup; 2] {
    [0, 1].map(|i| {
        let map = whitecaps.map_or(no_map, |w| &w.views[i]);
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sea frame"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&mirror.view) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(map) },
            ],
        })
    })
}

/// A filterable array texture binding: the cascades' maps, one layer each.
fn layers_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    let sample_type = wgpu::TextureSampleType::Float { filterable: true };
    gpu::texture_entry(binding, wgpu::ShaderStages::VERTEX_FRAGMENT, sample_type, wgpu::TextureViewDimension::D2Array)
}

/// The least margin (NDC) past the screen's bottom and side edges that keeps the grid's edge off
/// the screen however the waves move it, up to [`MAX_GRID_MARGIN`]: found by halving, each try
/// heaving the edge's nearest points (the bottom's corners, quarters and middle, and the sides
/// a quarter and half way up) by up to `crest` and carrying them up to `carry` (m) each way
/// (27 moves). Near water seen steeply moves the most: there the waves' reach is a large angle.
fn grid_margin(camera: &OrbitCamera, aspect: f32, (crest, carry): (f32, f32)) -> f32 {
    let (right, up, forward) = camera_basis(camera, aspect);
    let (eye, view_proj) = (camera.eye(), camera.view_projection(aspect));
    let moves: Vec<Vec3> = (0..27)
        .map(|i| {
            let across = Vec2::new((i % 3) as f32 - 1.0, (i / 3 % 3) as f32 - 1.0).normalize_or_zero() * carry;
            Vec3::new(across.x, ((i / 9) as f32 - 1.0) * crest, across.y)
        })
        .collect();
    // Whether every moved point of the edge at `margin` stays past it on its own axis.
    let holds = |margin: f32| {
        let edge = 1.0 + margin;
        let points = [-1.0, -0.5, 0.0, 0.5, 1.0].map(|x| (Vec2::new(x * edge, -edge), 1));
        let sides = [-0.5, 0.0].into_iter().flat_map(|y| [-1.0, 1.0].map(|x| (Vec2::new(x * edge, y * edge), 0)));
        points.into_iter().chain(sides).all(|(ndc, axis)| {
            let ray = forward + right * ndc.x + up * ndc.y;
            if ray.y >= 0.0 {
                return true; // no water there
            }
            let point = eye + ray * (eye.y / -ray.y);
            moves.iter().all(|m| {
                let clip = view_proj * (point + *m).extend(1.0);
                clip.w <= 0.0 || [clip.x, clip.y][axis] / clip.w * ndc[axis].signum() >= 1.0
            })
        })
    };
    if !holds(MAX_GRID_MARGIN) {
        return MAX_GRID_MARGIN;
    }
    let (mut least, mut most) = (0.02, MAX_GRID_MARGIN);
    if holds(least) {
        return least;
    }
    for _ in 0..12 {
        let mid = 0.5 * (least + most);
        if holds(mid) {
            most = mid;
        } else {
            least = mid;
        }
    }
    most
}

/// The camera's basis scaled to its field of view: right and up times the tangents of half the
/// field across and down, and forward.
fn camera_basis(camera: &OrbitCamera, aspect: f32) -> (Vec3, Vec3, Vec3) {
    let forward = (camera.target - camera.eye()).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    let tan_y = (camera.fov_y.to_radians() * 0.5).tan();
    (right * tan_y * aspect, up * tan_y, forward)
}

/// The grid's screen rectangle (NDC x from, x to, y from, y to), its cells across and down,
/// and a cell's angle (rad), for a target of `size` pixels. `(crest, carry)`: how far (m) the
/// waves can heave a point of the grid and carry it sideways.
fn grid_layout(camera: &OrbitCamera, (crest, carry): (f32, f32), size: (u32, u32)) -> ([f32; 4], (u32, u32), f32) {
    let aspect = size.0 as f32 / size.1.max(1) as f32;
    let (_, up, forward) = camera_basis(camera, aspect);
    let eye = camera.eye();
    let margin = grid_margin(camera, aspect, (crest, carry));
    // The horizon of the grid's far edge, straight ahead.
    let ahead = Vec2::new(forward.x, forward.z).normalize_or(Vec2::X) * GRID_FAR;
    let far_edge = Vec3::new(ahead.x, -eye.y, ahead.y);
    let horizon = far_edge.dot(up) / up.length_squared() / far_edge.dot(forward);
    let top = (horizon + 0.02).min(1.0 + margin);
    let rect = [-1.0 - margin, 1.0 + margin, -1.0 - margin, top.max(-1.0)];
    let cells_for =
        |span: f32, pixels: u32, most: u32| ((span * 0.5 * pixels as f32 / GRID_CELL_PX).ceil() as u32).clamp(1, most);
    let cells = (
        cells_for(rect[1] - rect[0], size.0, GRID_MAX_CELLS.0),
        cells_for(rect[3] - rect[2], size.1, GRID_MAX_CELLS.1),
    );
    let angle = (rect[3] - rect[2]) / cells.1 as f32 * up.length();
    (rect, cells, angle)
}

/// Draws the sea into `target` (`size` pixels) at the view's render scale with `drawing`, its
/// pipelines and maps (made at the first frame, and again when the view's features or the sea's
/// variant change), after [`Renderer::prepare`] wrote this frame's scene uniforms for `view`
/// (the sea camera's, with its bodies, no caustics or deck).
pub fn encode(
    drawing: &mut Option<SeaRenderer>,
    renderer: &mut Renderer,
    cx: FrameContext<'_>,
    (view, sea): (&View, &SeaView<'_>),
    mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, bool),
) {
    let FrameContext { device, queue, encoder, target, size } = cx;
    let features = view.features();
    let variant =
        SeaVariant { whitecap_map: sea.variant.whitecap_map && renderer.settings().float_targets, ..sea.variant };
    if drawing.as_ref().is_none_or(|s| (s.features, s.variant) != (features, variant)) {
        let lattices = drawing.take().map(|s| s.lattices);
        *drawing = Some(SeaRenderer::new(renderer, device, queue, (features, variant), sea.patch, lattices));
    }
    let drawn = drawing.as_mut().expect("made above");
    let scaled = renderer.scene_size(view, size);
    let bodies = bodies::mirror_boxes(view, sea.crest * sea.choppiness);
    if scaled != size {
        let image = renderer.upscale_image(device, scaled);
        let cx = FrameContext { device, queue, encoder: &mut *encoder, target: &image, size: scaled };
        drawn.draw(renderer, cx, (sea, &bodies), mark);
        renderer.upscale_into(encoder, target);
    } else {
        drawn.draw(renderer, FrameContext { device, queue, encoder, target, size }, (sea, &bodies), mark);
    }
}

impl SeaRenderer {
    /// The sea's grid and sky into the frame's target, after the passes that make the frame's
    /// maps (the island's mirror, the kept whitecaps) and then `mark`; `bodies`: boxes round
    /// the floating bodies and their mirror images.
    fn draw(
        &mut self,
        renderer: &mut Renderer,
        cx: FrameContext<'_>,
        (sea, bodies): (&SeaView<'_>, &[(Vec3, Vec3)]),
        mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, bool),
    ) {
        let FrameContext { device, queue, encoder, target, size } = cx;
        let mirror_size = (size.0.div_ceil(MIRROR_SCALE), size.1.div_ceil(MIRROR_SCALE));
        if self.island_drawing.is_some() && self.mirror.size() != mirror_size {
            self.mirror = MirrorTarget::new(device, mirror_size);
            let whitecaps = self.whitecaps.as_ref();
            self.frame_groups =
                frame_groups(device, &self.frame_layout, &self.mirror, whitecaps, &self.no_whitecap_map);
        }
        let (u, (rect, cells), up) = sea_uniforms(sea, size);
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
        self.lattices.fill(device, queue, encoder, sea.lattices);
        mark(encoder, false);
        let depth = renderer.scene_depth(device, size).clone();
        let scene_groups = [&self.patch_groups[sea.patch.state().current()], renderer.textures_group(), &self.group];
        if let Some(whitecaps) = &mut self.whitecaps {
            whitecaps.update(encoder, scene_groups, &self.frame_groups);
        }
        let frame_group = &self.frame_groups[self.whitecaps.as_ref().map_or(0, WhitecapMaps::current)];
        let [a, b, c] = scene_groups;
        let groups = [a, b, c, frame_group];
        if let Some(island) = &self.island_drawing {
            island.draw_mirrored(encoder, &self.mirror, &groups[..3]);
        }
        mark(encoder, true);
        let mut pass = begin_scene_pass(encoder, "sea", target, &depth, Some(wgpu::Color::BLACK));
        for (i, group) in groups.iter().enumerate() {
            pass.set_bind_group(i as u32, Some(*group), &[]);
        }
        for (pipelines, mesh) in self.bodies.iter().zip(renderer.body_meshes()) {
            if let Some(p) = pipelines {
                pass.set_pipeline(&p.mesh);
                mesh.draw(&mut pass);
            }
        }
        // Which cells can show the island and which the bodies' mirror images.
        let view_proj = sea.camera.view_projection(size.0 as f32 / size.1.max(1) as f32);
        let reach = (sea.crest, up.length());
        let island_rows = self.island_drawing.as_ref().map_or(0..0, |i| i.rows_near(view_proj, rect, cells.1, reach));
        let (body_columns, body_rows) = match self.near_bodies {
            Some(_) => cells_showing(bodies, view_proj, rect, cells, (sea.crest, 0.0)),
            None => (0..0, 0..0),
        };
        self.draw_grid(&mut pass, GridRuns { cells, island_rows, body_columns, body_rows });
        if let Some(island) = &self.island_drawing {
            island.draw_land(&mut pass);
        }
        self.sky.draw(&mut pass, &groups);
        if let Some(island) = &self.island_drawing {
            island.draw_edge(&mut pass);
        }
        // The bodies' outlines last, over the water and the sky behind them.
        if renderer.body_outlines() {
            bodies::draw_outlines(&mut pass, &self.bodies, renderer.body_outline_meshes());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_reaches_below_the_screen_and_up_to_the_horizon() {
        let camera = crate::sea::default_camera();
        let (rect, cells, angle) = grid_layout(&camera, (1.2, 1.2), (800, 600));
        println!("grid {rect:?}, {cells:?} cells, {angle} rad a cell");
        assert!(rect[0] < -1.0 && rect[1] > 1.0 && rect[2] < -1.0, "a margin past the screen's edges");
        // Looking 9° down with a 22.5° half field the horizon is on the screen's upper half.
        assert!(rect[3] > 0.0 && rect[3] < 1.0, "the grid stops at the horizon, {}", rect[3]);
        assert!(cells.0 <= GRID_MAX_CELLS.0 && cells.1 <= GRID_MAX_CELLS.1 && cells.0 >= 100);
    }

    #[test]
    fn the_grids_edges_stay_off_the_screen_however_the_waves_move_them() {
        // A storm (crest 5 m, choppiness 2): each point of the grid's bottom and side edges on
        // the sea plane, heaved up to the crest and carried sideways up to λ crest in any of
        // eight directions, still projects outside the screen, for eyes from over the crests
        // to 600 m away, 2-89 degrees down.
        let (crest, choppiness) = (5.0, 2.0);
        let directions: Vec<Vec3> = (0..27)
            .map(|i| {
                let carry = Vec2::new((i % 3) as f32 - 1.0, (i / 3 % 3) as f32 - 1.0).normalize_or_zero();
                Vec3::new(carry.x * choppiness * crest, ((i / 9) as f32 - 1.0) * crest, carry.y * choppiness * crest)
            })
            .collect();
        let (mut cameras, mut clamped, mut worst) = (0, 0, f32::MIN);
        for pitch in [2.0, 5.0, 10.0, 20.0, 45.0, 89.0] {
            for distance in [3.0, 20.0, 60.0, 200.0, 600.0] {
                let mut camera = crate::sea::default_camera();
                (camera.pitch, camera.distance) = (pitch, distance);
                camera.clamp();
                if camera.eye().y < crest + crate::sea::EYE_OVER_CRESTS {
                    continue; // `SeaScene::follow_params` lifts such a view over the crests
                }
                let (rect, _, _) = grid_layout(&camera, (crest, choppiness * crest), (800, 600));
                if rect[2] <= -1.0 - MAX_GRID_MARGIN {
                    clamped += 1; // past the margin's cap the cells would spread thin
                    continue;
                }
                cameras += 1;
                let view_proj = camera.view_projection(800.0 / 600.0);
                let (right, up, forward) = camera_basis(&camera, 800.0 / 600.0);
                let on_sea = |ndc: Vec2| {
                    let ray = forward + right * ndc.x + up * ndc.y;
                    (ray.y < 0.0).then(|| camera.eye() + ray * (camera.eye().y / -ray.y))
                };
                // Bottom edge (the screen's y below -1), left and right (x beyond -1 and 1).
                for k in 0..=40 {
                    let along = k as f32 / 40.0;
                    let edges = [
                        (Vec2::new(rect[0] + (rect[1] - rect[0]) * along, rect[2]), 1),
                        (Vec2::new(rect[0], rect[2] + (rect[3] - rect[2]) * along), 0),
                        (Vec2::new(rect[1], rect[2] + (rect[3] - rect[2]) * along), 0),
                    ];
                    for (ndc, axis) in edges {
                        let Some(point) = on_sea(ndc) else { continue };
                        for d in &directions {
                            let clip = view_proj * (point + *d).extend(1.0);
                            if clip.w <= 0.0 {
                                continue; // behind the eye: not on the screen either
                            }
                            let moved = [clip.x / clip.w, clip.y / clip.w][axis] * ndc[axis].signum();
                            // How far inside the screen's edge it came (NDC; negative: outside).
                            worst = worst.max(1.0 - moved);
                        }
                    }
                }
            }
        }
        println!(
            "{cameras} views: the grid's edge moved at most {worst:.3} into the screen (NDC); {clamped} past the cap"
        );
        assert!(cameras >= 12 && worst <= 0.0, "the waves pull the grid's edge onto the screen by {worst}");
    }
}
