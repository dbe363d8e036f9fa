//! The pool's caustics pass: the water grid ([`caustics_grid`] quads a side) projected along
//! the refracted sunlight into the renderer's caustics map, each triangle adding the light its
//! area gathers (`shaders/pool/caustics.wgsl`), then the map's mip chain.

use super::PoolPasses;
use crate::gpu;
use crate::render::scene_parts::{banded_grid, Mesh};
use crate::render::{flat_shown, FlatCaustics, RenderMode, Renderer, View};
use crate::sim::HeightField;

/// Quads per side of the mesh projected into the caustics map for a simulation of
/// `sim_size` cells per side: one quad per two cells resolves the shortest waves that make
/// caustics while keeping the triangle count, which software rasterisers pay for, low.
pub fn caustics_grid(sim_size: u32) -> u32 {
    (sim_size / 2).clamp(64, 256)
}

/// The grid drawn into the caustics map, and its quads per side.
pub(super) struct CausticsGrid {
    pub(super) mesh: Mesh,
    pub(super) n: u32,
}

impl CausticsGrid {
    /// The grid for a simulation of `sim_size` cells per side.
    pub(super) fn new(device: &wgpu::Device, sim_size: u32) -> Self {
        let n = caustics_grid(sim_size);
        let (vertices, indices) = banded_grid(n);
        Self { mesh: Mesh::new(device, "caustics grid", &vertices, &indices), n }
    }
}

impl PoolPasses {
    /// Projects the water grid along the refracted sunlight into the renderer's caustics map
    /// (sized for the view's render scale first, which rebinds it).
    pub fn encode_caustics(
        &mut self,
        renderer: &mut Renderer,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        let features = view.features();
        renderer.resize_caustics(device, renderer.caustics_size(view.render_scale), features.dispersion);
        // The ray-traced part reads the map if caustics are on, flat water if it uses the real ones.
        let traced_shown = flat_shown(view).is_none_or(|f| f.mode == RenderMode::Split && f.split < 1.0);
        let flat_reads = flat_shown(view).is_some_and(|f| f.caustics == FlatCaustics::Real);
        if !((view.caustics && traced_shown) || flat_reads) {
            return;
        }
        if self.caustics_grid.n != caustics_grid(water.size()) {
            self.caustics_grid = CausticsGrid::new(device, water.size());
        }
        self.variant(renderer, device, features);
        let mut pass = gpu::colour_pass(
            encoder,
            "caustics",
            renderer.caustics_target(),
            wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
        );
        pass.set_bind_group(0, Some(&renderer.water_groups()[water.state().current()]), &[]);
        // One draw, or with dispersion one per colour channel (each with its own index).
        for pipeline in &self.variants[&features].caustics {
            pass.set_pipeline(pipeline);
            self.caustics_grid.mesh.draw(&mut pass);
        }
        drop(pass);
        renderer.encode_caustics_mips(encoder);
    }
}
