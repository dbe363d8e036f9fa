//! The caustics map: the water grid projected along the refracted sunlight, each
//! triangle adding the light its area gathers (`shaders/caustics.wgsl`), then its mip chain.

use super::caustics_mips::CausticsMips;
use super::meshes::{banded_grid, Mesh};
use super::render_mode::{FlatCaustics, RenderMode};
use super::{flat_shown, Renderer, View};
use crate::gpu;
use crate::param_spec::{Control, ParamSpec};
use crate::sim::HeightField;

/// Caustics map: red = light, green = light with the sphere's shadow.
pub const CAUSTICS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;
/// Caustics map where float render targets are missing: 8-bit, holding light / [`CAUSTICS_8BIT_SCALE`].
pub const CAUSTICS_FORMAT_8BIT: wgpu::TextureFormat = wgpu::TextureFormat::Rg8Unorm;
/// Light (relative to a calm surface) that the 8-bit caustics map's 1.0 stands for: focused
/// light up to 10x is kept in 1/255 steps of it, brighter lines are clipped (the tone curve
/// has flattened them by then anyway).
pub const CAUSTICS_8BIT_SCALE: f32 = 10.0;
/// Quads per side of the mesh projected into the caustics map for a simulation of
/// `sim_size` cells per side: one quad per two cells resolves the shortest waves that make
/// caustics while keeping the triangle count, which software rasterisers pay for, low.
pub fn caustics_grid(sim_size: u32) -> u32 {
    (sim_size / 2).clamp(64, 256)
}

/// The caustics map and the water grid (see [`caustics_grid`]) drawn into it (its pipeline
/// is one of the [`ScenePipelines`]).
pub(super) struct CausticsMap {
    /// The map and its mip chain.
    pub(super) mips: CausticsMips,
    /// Texels per side.
    pub(super) size: u32,
    /// Whether `view` holds light per colour channel (dispersion; an RGBA map).
    pub(super) per_channel: bool,
    pub(super) grid: Mesh,
    /// Quads per side of `grid`.
    pub(super) grid_size: u32,
}

impl CausticsMap {
    pub(super) fn new(device: &wgpu::Device, size: u32, format: wgpu::TextureFormat, sim_size: u32) -> Self {
        let grid_size = caustics_grid(sim_size);
        let (grid_vertices, grid_indices) = banded_grid(grid_size);
        let grid = Mesh::new(device, "caustics grid", &grid_vertices, &grid_indices);
        Self { mips: CausticsMips::new(device, size, format), size, per_channel: false, grid, grid_size }
    }
}

impl Renderer {
    /// Side (texels) of the caustics map for a frame drawn at `render_scale`: the map's texels
    /// follow the screen's pixels, so a frame at half resolution also lights the pool from a
    /// map of half the side (at least 128), a quarter of the work.
    pub fn caustics_size(&self, render_scale: f32) -> u32 {
        let side = (self.settings.caustics_size as f32 * render_scale.clamp(0.25, 1.0)).round() as u32;
        side.clamp(128.min(self.settings.caustics_size), self.settings.caustics_size)
    }

    /// Makes the caustics map `size` texels per side, with light per colour channel or not
    /// (rebinding it), if it is not already.
    pub(super) fn resize_caustics(&mut self, device: &wgpu::Device, size: u32, per_channel: bool) {
        if size != self.caustics.size || per_channel != self.caustics.per_channel {
            self.caustics.mips = CausticsMips::new(device, size, self.settings.caustics_format_for(per_channel).0);
            self.caustics.size = size;
            self.caustics.per_channel = per_channel;
            self.textures_group =
                self.scene_textures.bind_group(device, &self.textures_layout, &self.caustics.mips.view);
        }
    }

    /// Projects the water grid along the refracted sunlight into the caustics map.
    pub fn encode_caustics(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        let features = view.features();
        self.resize_caustics(device, self.caustics_size(view.render_scale), features.dispersion);
        // The ray-traced part reads the map if caustics are on, flat water if it uses the real ones.
        let traced_shown = flat_shown(view).is_none_or(|f| f.mode == RenderMode::Split && f.split < 1.0);
        let flat_reads = flat_shown(view).is_some_and(|f| f.caustics == FlatCaustics::Real);
        if !((view.caustics && traced_shown) || flat_reads) {
            return;
        }
        self.variant(device, features);
        let mut pass = gpu::colour_pass(
            encoder,
            "caustics",
            &self.caustics.mips.target,
            wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
        );
        pass.set_bind_group(0, Some(&self.water_groups[water.state().current()]), &[]);
        // One draw, or with dispersion one per colour channel (each with its own index).
        for pipeline in &self.variants[&features].caustics {
            pass.set_pipeline(pipeline);
            self.caustics.grid.draw(&mut pass);
        }
        drop(pass);
        self.caustics.mips.encode(encoder);
    }
}

/// Caustics on or off. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "caustics",
    label: "Caustics",
    group: "Light",
    unit: "",
    control: Control::Toggle,
    default: 1.0,
    help: "Light focused by the waves onto the floor, walls and sphere.",
}];
