//! Drawing the sea's island (`shaders/sea/island.wgsl`): its heightmap as a texture the sea
//! reads its floor from, its land's mesh (the quads above the water), and the mirror: the land
//! drawn upside down in the sea plane into a texture at half the frame's size, which the sea
//! reads at its own pixel, moved by its waves' slopes, wherever it mirrors the island (a planar
//! reflection).

use glam::{Mat4, Vec3};
use wgpu::util::DeviceExt;

use crate::gpu;
use crate::render::scene_parts::DepthUse;
use crate::render::DEPTH_FORMAT;
use crate::sea::island;

/// The mirror's texels: colours stored as sqrt(c / MIRROR_RANGE) (8 bits hold the land's
/// shade as a gamma would, on every backend), coverage in alpha.
const MIRROR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
pub const MIRROR_RANGE: f32 = 16.0;
/// The mirror's texels a side per the frame's pixels: it is drawn at half the frame's size.
pub const MIRROR_SCALE: u32 = 2;
/// How far (a fraction of the screen per unit of slope) the waves move the mirror's image, and
/// how far up and down its three taps spread per unit of the unresolved rms slope (a tenth of
/// the angle that turns a ray by: three taps further apart show as ghosts).
const MIRROR_WOBBLE: f32 = 0.04;
const MIRROR_BLUR: f32 = 0.05;
/// The most the unresolved waves' rms slope reaches (the storm's far sea): with the wobble and
/// the blur it says how far past the island's image the sea can show it.
const ROUGHEST: f32 = 0.5;

/// The island's WGSL constants for the renderer.
pub fn wgsl_constants() -> String {
    format!(
        "const MIRROR_RANGE: f32 = {MIRROR_RANGE:?};\nconst MIRROR_SCALE: f32 = {:?};\nconst MIRROR_WOBBLE: f32 = {MIRROR_WOBBLE:?};\n\
         const MIRROR_BLUR: f32 = {MIRROR_BLUR:?};\n",
        MIRROR_SCALE as f32
    )
}

/// The island's texture, pipelines and mesh, made with the sea's pipelines when the island is
/// in the sea.
pub(super) struct IslandDrawing {
    _map: wgpu::Texture,
    /// The sea's grid with the shallows and the mirror, the land and its outline, and the land
    /// mirrored and its outline (shaders/sea/island_edge.wgsl).
    shallows: wgpu::RenderPipeline,
    land: wgpu::RenderPipeline,
    edge: wgpu::RenderPipeline,
    mirrored: wgpu::RenderPipeline,
    mirrored_edge: wgpu::RenderPipeline,
    /// The land's index buffer and its length.
    mesh: (wgpu::Buffer, u32),
    /// Boxes (least and most corner, m) round what the sea can show of the island: the water
    /// over floor within [`island::SEE_DEPTH`] (at the sea level), and the land's mirror image.
    shown: [(Vec3, Vec3); 2],
}

/// The mirror's texture at one size (the sea reads it in its group 3, binding 0).
pub(super) struct MirrorTarget {
    size: (u32, u32),
    pub view: wgpu::TextureView,
    depth: wgpu::TextureView,
}

impl MirrorTarget {
    /// A mirror of `size` texels (a texel for a sea without island).
    pub(super) fn new(device: &wgpu::Device, size: (u32, u32)) -> Self {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let colour = gpu::texture_2d(device, "sea mirror", (size.0, size.1, 1), 1, MIRROR_FORMAT, usage);
        let depth = gpu::texture_2d(device, "sea mirror depth", (size.0, size.1, 1), 1, DEPTH_FORMAT, usage);
        Self { size, view: colour.create_view(&Default::default()), depth: depth.create_view(&Default::default()) }
    }

    pub(super) fn size(&self) -> (u32, u32) {
        self.size
    }
}

/// The island's heightmap ([`island::map`]) in half floats, or a texel of sea floor when there
/// is no island.
pub(super) fn island_map(device: &wgpu::Device, queue: &wgpu::Queue, with_island: bool) -> wgpu::Texture {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let n = if with_island { island::MAP_TEXELS } else { 1 };
    let texture = gpu::texture_2d(device, "island", (n, n, 1), 1, wgpu::TextureFormat::Rgba16Float, usage);
    let texels = if with_island { island::map() } else { vec![[-island::FLOOR_DEPTH, 0.0, 0.0, 0.0]] };
    let halves: Vec<[u16; 4]> = texels.iter().map(|t| t.map(super::lattices::f16_bits)).collect();
    gpu::write_texture_2d(queue, &texture, 0, bytemuck::cast_slice(&halves));
    texture
}

/// What the island needs from the sea's pipelines' making: the groups' layouts with the
/// frame's maps (group 3) and without (to draw into the mirror), the module, the frame's format.
pub(super) struct IslandPipelines<'a> {
    pub layouts: [&'a [&'a wgpu::BindGroupLayout]; 2],
    pub module: &'a wgpu::ShaderModule,
    pub format: wgpu::TextureFormat,
}

impl IslandDrawing {
    pub(super) fn new(
        device: &wgpu::Device,
        map: wgpu::Texture,
        p: &IslandPipelines<'_>,
        place: island::Place,
    ) -> Self {
        let indices = island::land_indices();
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("island land"),
            contents: bytemuck::cast_slice(&indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        let (back, front, write) = (Some(wgpu::Face::Back), Some(wgpu::Face::Front), DepthUse::TestAndWrite);
        let shallows = mesh_pipeline(device, p, "sea shallows", ["vs_sea", "fs_sea"], (p.format, None, None, write));
        let land = mesh_pipeline(device, p, "island", ["vs_island", "fs_island"], (p.format, back, None, write));
        // The outline's blend over what is drawn (the mirror's texels are premultiplied).
        let (over, over_mirror) =
            (Some(wgpu::BlendState::ALPHA_BLENDING), Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING));
        let entries = ["vs_island_edge", "fs_island_edge"];
        let edge = mesh_pipeline(device, p, "island edge", entries, (p.format, back, over, DepthUse::Test));
        let into_mirror = IslandPipelines { layouts: [p.layouts[1]; 2], ..*p };
        let entries = ["vs_island_mirrored", "fs_island_mirrored"];
        let mirrored =
            mesh_pipeline(device, &into_mirror, "island mirrored", entries, (MIRROR_FORMAT, front, None, write));
        let entries = ["vs_island_edge_mirrored", "fs_island_edge_mirrored"];
        let mirror_format = (MIRROR_FORMAT, front, over_mirror, DepthUse::Test);
        let mirrored_edge = mesh_pipeline(device, &into_mirror, "island edge mirrored", entries, mirror_format);
        let (least, most, _) = island::extent_above(-island::SEE_DEPTH, place);
        let water = (Vec3::new(least[0], 0.0, least[1]), Vec3::new(most[0], 0.0, most[1]));
        let (least, most, top) = island::extent_above(0.0, place);
        let image = (Vec3::new(least[0], -top, least[1]), Vec3::new(most[0], 0.0, most[1]));
        let mesh = (buffer, indices.len() as u32);
        Self { _map: map, shallows, land, edge, mirrored, mirrored_edge, mesh, shown: [water, image] }
    }

    /// Sets the pipeline drawing the sea's grid with the shallows and the mirror.
    pub(super) fn set_shallows(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_pipeline(&self.shallows);
    }

    /// Draws the land into the sea's pass (after the water: the ground under the surface fails
    /// the depth test unshaded).
    pub(super) fn draw_land(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_pipeline(&self.land);
        self.draw_mesh(pass);
    }

    /// Draws the land's outline blended over what the pass drew (after the sky).
    pub(super) fn draw_edge(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_pipeline(&self.edge);
        self.draw_mesh(pass);
    }

    /// Draws the land mirrored into `mirror`, and its outline, with the sea's groups 0-2.
    pub(super) fn draw_mirrored(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mirror: &MirrorTarget,
        groups: &[&wgpu::BindGroup],
    ) {
        let clear = wgpu::Color::TRANSPARENT;
        let mut pass = crate::render::scene_parts::begin_scene_pass(
            encoder,
            "island mirrored",
            &mirror.view,
            &mirror.depth,
            Some(clear),
        );
        for (i, group) in groups.iter().enumerate() {
            pass.set_bind_group(i as u32, Some(*group), &[]);
        }
        pass.set_pipeline(&self.mirrored);
        self.draw_mesh(&mut pass);
        pass.set_pipeline(&self.mirrored_edge);
        self.draw_mesh(&mut pass);
    }

    fn draw_mesh(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_index_buffer(self.mesh.0.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.mesh.1, 0, 0..1);
    }
}

impl IslandDrawing {
    /// The rows of the sea's grid that can show the island's shallows or its mirror image
    /// ([`cells_showing`] the boxes round them, grown by how far the waves move and smear the
    /// mirror's image; `up`: the tangent of half the field of view).
    pub(super) fn rows_near(
        &self,
        view_proj: Mat4,
        rect: [f32; 4],
        rows: u32,
        (crest, up): (f32, f32),
    ) -> std::ops::Range<u32> {
        // In NDC (twice the texture's units): the wobble's and the blur's reach.
        let smear = 2.0 * (MIRROR_WOBBLE + MIRROR_BLUR * ROUGHEST / up.max(1.0e-3));
        cells_showing(&self.shown, view_proj, rect, (1, rows), (crest, smear)).1
    }
}

/// The columns and rows of the sea's grid (its screen rectangle `rect` in NDC, `cells` across
/// and up it) that can show what lies in `boxes` (least and most corner, m): those across the
/// boxes' screen span, grown by the crests' height and by `smear` (NDC), and two more each way
/// for the waves' sideways carry. None when the boxes lie wholly behind the eye; all of them
/// when one reaches behind it.
pub(super) fn cells_showing(
    boxes: &[(Vec3, Vec3)],
    view_proj: Mat4,
    rect: [f32; 4],
    cells: (u32, u32),
    (crest, smear): (f32, f32),
) -> (std::ops::Range<u32>, std::ops::Range<u32>) {
    let mut span = [f32::INFINITY, f32::NEG_INFINITY, f32::INFINITY, f32::NEG_INFINITY];
    let (mut behind, mut corners) = (0, 0);
    for &(least, most) in boxes {
        let (least, most) = (least - Vec3::Y * crest, most + Vec3::Y * crest);
        for corner in 0..8 {
            let pick = |bit: u32, lo: f32, hi: f32| if corner & bit == 0 { lo } else { hi };
            let p = Vec3::new(pick(1, least.x, most.x), pick(2, least.y, most.y), pick(4, least.z, most.z));
            let clip = view_proj * p.extend(1.0);
            corners += 1;
            if clip.w <= 1.0e-3 {
                behind += 1;
                continue;
            }
            let ndc = clip.truncate() / clip.w;
            span = [span[0].min(ndc.x), span[1].max(ndc.x), span[2].min(ndc.y), span[3].max(ndc.y)];
        }
    }
    match behind {
        _ if corners == 0 => return (0..0, 0..0),
        0 => {}
        b if b == corners => return (0..0, 0..0),
        _ => return (0..cells.0, 0..cells.1),
    }
    let across = |from: f32, to: f32, lo: f32, hi: f32, count: u32| {
        let at = |ndc: f32| (ndc - lo) / (hi - lo) * count as f32;
        let first = (at(from - smear).floor() - 2.0).clamp(0.0, count as f32) as u32;
        let last = (at(to + smear).ceil() + 2.0).clamp(0.0, count as f32) as u32;
        first..last.max(first)
    };
    (across(span[0], span[1], rect[0], rect[1], cells.0), across(span[2], span[3], rect[2], rect[3], cells.1))
}

/// A pipeline drawing triangles from `entries` (vertex, fragment) of the sea's module into
/// `format`, with depth (`depth`: tested, and written or not), no vertex buffers (their
/// vertices come from the index); `cull`: the side of the triangles left out (the land's back
/// faces; mirrored, their fronts).
pub(super) fn mesh_pipeline(
    device: &wgpu::Device,
    p: &IslandPipelines<'_>,
    label: &str,
    entries: [&str; 2],
    (format, cull, blend, depth): (wgpu::TextureFormat, Option<wgpu::Face>, Option<wgpu::BlendState>, DepthUse),
) -> wgpu::RenderPipeline {
    let [vertex_entry, fragment_entry] = entries;
    crate::render::scene_parts::mesh_pipeline(
        device,
        crate::render::scene_parts::MeshPipeline {
            label,
            module: p.module,
            vertex_entry,
            fragment_entry,
            layouts: p.layouts[0],
            attributes: &[],
            stride: 0,
            cull,
            front_face: wgpu::FrontFace::Ccw,
            format,
            blend,
            write_mask: wgpu::ColorWrites::ALL,
            depth,
        },
    )
}
