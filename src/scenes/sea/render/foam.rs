//! The sea's whitecaps kept over time (`shaders/sea/foam.wgsl`): a map of foam over the sea
//! plane round the origin (the clicks' patch, the camera's target), [`WHITECAP_MAP_TEXELS`] a
//! side. Each frame one pass writes the other of its two textures: every texel the larger of
//! its foam's cover faded by the frame's fixed steps (e^(-steps dt / lifetime)) and the cover
//! the breaking crests make there now. The sea reads it (group 3, binding 1) beside the foam of the
//! moment, so a broken crest leaves a trail that fades. Past the map only the moment's shows.

use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::sea::WHITECAP_MAP_TEXELS;

/// The map's texels: foam (0-1) in red. A half float keeps a slow fade from sticking at a
/// step of 1/255, which 8 bits would.
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// The two maps and the pass that writes one from the other.
pub(super) struct WhitecapMaps {
    _maps: [wgpu::Texture; 2],
    pub views: [wgpu::TextureView; 2],
    /// The map the last update wrote, which the sea reads.
    current: usize,
    update: FullscreenPass,
}

/// A texture the sea's group 3 binds for the map when there is none (the pass is left out).
pub(super) fn no_map(device: &wgpu::Device) -> wgpu::TextureView {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING;
    gpu::texture_2d(device, "no whitecap map", (1, 1, 1), 1, FORMAT, usage).create_view(&Default::default())
}

impl WhitecapMaps {
    /// `parts`: the sea's WGSL (prelude, sea, island and foam sources); `layouts`: its four
    /// groups'.
    pub(super) fn new(device: &wgpu::Device, parts: &[&str], layouts: &[&wgpu::BindGroupLayout]) -> Self {
        let n = WHITECAP_MAP_TEXELS;
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let maps =
            ["whitecaps a", "whitecaps b"].map(|label| gpu::texture_2d(device, label, (n, n, 1), 1, FORMAT, usage));
        let views = maps.each_ref().map(|m| m.create_view(&Default::default()));
        let target = FullscreenTarget { format: FORMAT, blend: None, depth: None };
        let update = FullscreenPass::new(device, "whitecaps", parts, "fs_whitecaps", layouts, target);
        Self { _maps: maps, views, current: 0, update }
    }

    /// The map the sea reads this frame.
    pub(super) fn current(&self) -> usize {
        self.current
    }

    /// Writes the other map from the current one and makes it current. `groups`: the sea's
    /// groups 0-2; `frame_groups[i]`: its group 3 reading map i.
    pub(super) fn update(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        groups: [&wgpu::BindGroup; 3],
        frame_groups: &[wgpu::BindGroup; 2],
    ) {
        let next = 1 - self.current;
        let [a, b, c] = groups;
        self.update.run(encoder, &self.views[next], &[a, b, c, &frame_groups[self.current]]);
        self.current = next;
    }
}
